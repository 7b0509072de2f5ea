/*
 * src/sym/node.h - the expression node and the kernel's internal interface.
 *
 * Only src/sym/ and the modules built on it include this; everyone else sees
 * the opaque qd_expr of include/qdot/expr.h.
 *
 * Node layout: a fixed header (hash, kind, a small per-kind tag, argument
 * count), a per-kind payload, and the arguments inline after it.  Nodes are
 * allocated from the context's arena and interned in its unique table
 * (intern.c), so a node is never copied and never freed alone.
 *
 * Canonical forms, enforced by the constructors in add.c, mul.c, pow.c and
 * func.c (docs/design.md has them with examples):
 *   ADD  args = [c?] t1 ... tn   n >= 1, c a nonzero number first when
 *        present; n + (c?) >= 2; no ti is a number or an ADD; ti sorted by
 *        term key (the factors of ti without its numeric coefficient);
 *        no two ti have the same key.
 *   MUL  args = [c?] f1 ... fn   n >= 1, c a number != 1 first when present;
 *        no fi is a number, a MUL; fi sorted by base, no two with one base;
 *        never c * (single ADD) with c rational (that is distributed).
 *   POW  args = b, e with e != 0, 1; b != 1; b != 0 unless e is not a
 *        number (0^x stays); not (rational b, integer e
 *        with |e| <= QD_MAX_FOLD_EXP: larger powers are not worked out);
 *        not (MUL b, integer e); not (POW b, integer e); not (abs(x) b, even
 *        integer e); for a fraction e: not (POW b with an even integer
 *        exponent or a base known >= 0); not (MUL b with a rational
 *        coefficient whose |c|^e is rational, or with such a POW factor,
 *        unless what would stay under the root is -1).
 *   FUNC sin, cos, tan: the argument is not K*pi with K outside [0, 1/2]
 *        nor with a known value (K*6 or K*4 an integer); a sum's pi term
 *        K*pi has 0 <= K < 1/2.  abs: the argument is not known >= 0.
 *        Odd and even functions: the argument has no leading minus.
 */
#ifndef QD_SYM_NODE_H
#define QD_SYM_NODE_H

#include <gmp.h>
#include <stdarg.h>
#include "qdot/expr.h"
#include "../base/arena.h"
#include "../base/ptrmap.h"
#include "../base/mem.h"
#include "../base/ctx.h"

struct qd_expr {
    uint64_t hash;
    uint8_t kind;       /* qd_kind */
    uint8_t tag;        /* QD_FUNC: qd_func; QD_SYMBOL: qd_role; QD_CONSTANT: qd_constant */
    uint16_t order;     /* QD_SYMBOL with role COORD: jet order */
    uint32_t nargs;
    union {
        mpq_t q;        /* QD_RATIONAL */
        double f;       /* QD_FLOAT */
        struct {        /* QD_SYMBOL */
            const char *name;
            const qd_expr *coord;      /* order-0 coordinate, or the symbol itself */
            const qd_expr *next;       /* the next jet symbol once made, else NULL */
            bool positive;             /* qd_symbol_positive; not part of its identity */
        } sym;
        struct {        /* QD_UFUNC, QD_UDERIV */
            const char *name;
            const unsigned *slots;     /* QD_UDERIV: sorted slot list */
            uint32_t nslots;
        } fn;
        /* QD_ADD, QD_MUL, QD_POW, QD_FUNC: qd_count_ops + 1 once counted,
         * else 0.  A memo, not part of the node's identity: the simplifier
         * compares the sizes of candidates that share most subterms. */
        size_t ops_memo;
    } u;
    const qd_expr *args[];
};

typedef struct qd__symtab_entry {
    const char *name;
    const qd_expr *sym;
} qd__symtab_entry;

/* The kernel's part of a context (base/ctx.h's ctx->sym), attached by
 * qd_ctx_new_with and released by qd_ctx_free through ctx->detach. */
typedef struct qd__sym_state qd__sym_state;
struct qd__sym_state {
    /* unique table: open addressing over (hash, node) slots, the hash kept
     * beside the pointer so that a probe reads the node only on a match */
    struct qd__slot { uint64_t hash; const qd_expr *e; } *table;
    size_t table_cap, table_len;
    /* symbols by name */
    qd__ptrmap symtab;            /* interned name -> its symbol */
    const char **names;          /* interned names, open addressing */
    size_t names_cap, names_len;
    /* rational nodes, for mpq_clear at the end */
    qd_expr **rationals;
    size_t nrat, rat_cap;
    /* a few nodes every operation uses */
    const qd_expr *zero, *one, *minus_one, *half, *t;
    const char *tname;           /* how t prints (qd_print_set_time_name); NULL: "t" */
};

/* ---- intern.c --------------------------------------------------------- */
/* Intern a node of the given kind/tag with args; the payload is compared and
 * hashed by the kind's rules.  proto carries the payload (only the union and
 * tag/order are read). */
/* e in ball arithmetic (certify.c, 128 bits) at syms[i] = at[i], not
 * simplified first: false where e is undefined there or not computable
 * (a user function); else *mid and *rad (a bound of the ball's radius). */
bool qd__ball_eval(qd_ctx *ctx, const qd_expr *e, size_t n, const qd_expr *const *syms,
                   const double *at, double *mid, double *rad);

const qd_expr *qd__intern(qd_ctx *ctx, const qd_expr *proto, size_t nargs,
                          const qd_expr *const *args);
const char *qd__intern_name(qd_ctx *ctx, const char *name);
const char *qd__find_name(const qd_ctx *ctx, const char *name); /* NULL if never interned */
uint64_t qd__hash_mix(uint64_t h, uint64_t v);
/* The forms listed at the top of this file (canon.c); qd__intern asserts it
 * on every new node unless NDEBUG is defined. */
bool qd__is_canonical(const qd_expr *proto, size_t nargs, const qd_expr *const *args);

/* ---- number.c --------------------------------------------------------- */
#define QD_MAX_FOLD_EXP 100000UL /* a rational to a larger integer power stays a power */
/* ... and so does one whose numerator or denominator would exceed this many
 * bits (2^26: 8 MiB), so GMP is never asked for more. */
#define QD_MAX_FOLD_BITS (1UL << 26)
const qd_expr *qd__rat_mpq(qd_ctx *ctx, const mpq_t q);
const qd_expr *qd__number_add(qd_ctx *ctx, const qd_expr *a, const qd_expr *b);
const qd_expr *qd__number_mul(qd_ctx *ctx, const qd_expr *a, const qd_expr *b);
/* a^e for numbers; NULL result with *exact=false when it does not fold. */
const qd_expr *qd__number_pow(qd_ctx *ctx, const qd_expr *a, const qd_expr *e, bool *folded);
int qd__number_cmp(const qd_expr *a, const qd_expr *b);
/* Whether number e is a finite double; else QD_ERR_NUMERIC recorded, naming
 * its size ("the number 10^100000 overflows a double"). */
bool qd__number_finite(qd_ctx *ctx, const qd_expr *e);
bool qd__is_rational(const qd_expr *e);
bool qd__is_float(const qd_expr *e);

/* ---- gmpmem.c: GMP's and FLINT's allocations ---------------------------
 * qd__gmp_install (called by qd_ctx_new_with) hooks GMP's and FLINT's
 * allocation functions once per process.  Between qd__gmp_enter(ctx) and
 * qd__gmp_leave(ctx, outer) each of their requests of at least
 * QD_GMP_PROBE_MIN bytes on this thread is first asked of ctx's allocator;
 * it is served either way, and leave returns false, with QD_ERR_NOMEM
 * recorded, when one was refused: the caller then drops what it computed.
 * Sections nest. */
#define QD_GMP_PROBE_MIN 1024
typedef struct qd__gmp_section {
    qd_ctx *ctx;
    bool refused;
} qd__gmp_section;
void qd__gmp_install(void);
qd__gmp_section qd__gmp_enter(qd_ctx *ctx);
bool qd__gmp_leave(qd_ctx *ctx, qd__gmp_section outer);

/* ---- cmp.c --------------------------------------------------------------- */
/* Natural-order comparison of names: theta2 < theta10. */
int qd__name_cmp(const char *a, const char *b);
/* Compare two factor sequences (term keys of sums). */
int qd__seq_cmp(const qd_expr *const *a, size_t na, const qd_expr *const *b, size_t nb);

/* ---- add.c / mul.c ------------------------------------------------------ */
/* Split a term of a sum into numeric coefficient and the factors after it. */
const qd_expr *qd__term_coeff(qd_ctx *ctx, const qd_expr *t, const qd_expr *const **rest,
                              size_t *nrest);
/* Intern a product from an already canonical factor list (trusted: no checks);
 * coeff NULL for none. */
const qd_expr *qd__mul_raw(qd_ctx *ctx, const qd_expr *coeff, size_t n,
                           const qd_expr *const *factors);
/* Could -e be written more simply than e (negative coefficient leading)? */
bool qd__has_minus(const qd_expr *e);

/* ---- map.c / evaltree.c --------------------------------------------------- */
/* Rebuild e with new arguments through the constructor of its kind. */
const qd_expr *qd__rebuild(qd_ctx *ctx, const qd_expr *e, const qd_expr *const *args);
double qd__func_value(qd_func f, double a, double b);  /* b: atan2's x */
double qd__step_value(double x);                       /* step(x), 1/2 at 0 */

/* ---- map.c ---------------------------------------------------------------- */
/* Rewrite e bottom-up (map.c has the contract); post may be NULL. */
typedef const qd_expr *(*qd__post_fn)(qd_ctx *ctx, const qd_expr *e, void *data);
const qd_expr *qd__map(qd_ctx *ctx, const qd_expr *e, qd__ptrmap *memo, qd__post_fn post,
                       void *data);
double qd__pow_value(double b, double e);

/* ---- pow.c ----------------------------------------------------------------- */
/* Known to be >= 0 wherever it is defined (every symbol is real)? */
bool qd__nonneg(const qd_expr *e);

/* ---- trigeven.c ------------------------------------------------------------ */
/* The sum with even powers of sin and cos reduced modulo sin^2 + cos^2 = 1
 * where that is shorter; the sum itself otherwise, NULL on error. */
const qd_expr *qd__trig_even(qd_ctx *ctx, const qd_expr *sum);

/* ---- rewrite.c -------------------------------------------------------------- */
/* e with tan = sin/cos, exp(a) exp(b) = exp(a + b), exp(a)^k = exp(k a) and
 * sqrt(a) sqrt(b) = sqrt(a b) applied (qd_simplify's second path); e itself
 * when none applies, NULL on error. */
const qd_expr *qd__rewrite_identities(qd_ctx *ctx, const qd_expr *e);

/* ---- small helpers used across the kernel ------------------------------- */
static inline bool qd__is_num(const qd_expr *e) {
    return e->kind == QD_RATIONAL || e->kind == QD_FLOAT;
}

#endif
