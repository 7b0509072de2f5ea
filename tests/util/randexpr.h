/*
 * tests/util/randexpr.h - random expressions for property tests.
 *
 * The generator only builds expressions that are defined and smooth at every
 * point with all symbols in [-1, 1]: logarithms, square roots and quotients
 * are taken of (c + e^2) with c >= 1/2, inverse sines of sin(e)/2, so a
 * derivative compared against finite differences never crosses a pole.
 */
#ifndef QT_RANDEXPR_H
#define QT_RANDEXPR_H

#include <stdint.h>
#include "qdot/qdot.h"

typedef struct qt_rng {
    uint64_t s;
} qt_rng;

uint64_t qt_rand(qt_rng *r);                          /* splitmix64 */
double qt_uniform(qt_rng *r, double lo, double hi);
unsigned qt_below(qt_rng *r, unsigned n);             /* 0 .. n-1 */

enum {
    QT_POLY = 1,   /* + * and small integer powers of symbols and rationals */
    QT_TRIG = 2,   /* sin and cos */
    QT_FUNCS = 4,  /* every built-in function, in domains where it is smooth */
    QT_DIV = 8,    /* quotients and negative powers (of positive expressions) */
    QT_FLOAT = 16, /* float coefficients */
    QT_ALL = 31
};

/* A random expression of at most the given depth over syms. */
const qd_expr *qt_random_expr(qd_ctx *ctx, qt_rng *r, const qd_expr *const *syms,
                              size_t nsyms, int depth, unsigned flags);

#endif
