/*
 * qdot/equilibria.h - configurations of rest.
 *
 * An equilibrium is a configuration q0 where the system stays at rest: with
 * every velocity zero the accelerations vanish, i.e. the generalized forces
 * at rest are zero,
 *
 *     F(q) = f(q, q' = 0) = 0,
 *
 * f the right-hand side of M q'' = f (qdot/mech.h).  For L = T - V this is
 * dV/dq = Q; for rheonomic coordinates T0 enters as a potential -T0 (a
 * relative equilibrium in a rotating frame), and velocity-free terms of U
 * count too.
 *
 * Exact where the kernel can: the equations (parameters replaced by their
 * values) are solved one unknown at a time, taking an equation whose every
 * factor involves one unknown only (a product is zero when a factor is),
 * and substituting each root into the rest:
 *     sin(a q + b) = 0, cos(a q + b) = 0, c1 sin q + c0 = 0, c1 cos q + c0 = 0
 *     and polynomials of degree <= 2 in q.
 * Angles are reported in (-pi, pi].  Every exact root is checked
 * numerically.  Otherwise numerically: damped Newton (Levenberg-Marquardt)
 * from a guess, or a multi-start search over a box (quasi-random starts,
 * plus scans along each coordinate axis through the box centre with
 * sign-change bracketing by bisection, poles rejected) with duplicates merged
 * and every solution verified by its residual.
 *
 * Each equilibrium is classified by the eigenvalues of the symmetric part
 * of K = -dF/dq (the Hessian of V - T0 + U0 for a conservative system).
 */
#ifndef QDOT_EQUILIBRIA_H
#define QDOT_EQUILIBRIA_H

#include <stdbool.h>
#include <stddef.h>
#include "expr.h"
#include "mech.h"
#include "model.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum qd_eq_kind {
    QD_EQ_MINIMUM,    /* K positive definite: stable (without gyroscopic forces) */
    QD_EQ_MAXIMUM,    /* K negative definite */
    QD_EQ_SADDLE,     /* K indefinite */
    QD_EQ_DEGENERATE  /* K singular (a zero eigenvalue): the quadratic test says nothing */
} qd_eq_kind;

QD_API const char *qd_eq_kind_name(qd_eq_kind k); /* "minimum", "maximum", "saddle", "degenerate" */

typedef struct qd_equilibrium {
    double *q;               /* n values */
    const qd_expr **exact;   /* n exact values, or NULL when found numerically */
    double residual;         /* max_j |F_j(q)| (generalized-force units) */
    qd_eq_kind kind;
    size_t npos, nneg, nzero;/* signs of the eigenvalues of sym(K) */
    bool symmetric;          /* K symmetric (forces from a potential) */
} qd_equilibrium;

typedef struct qd_equilibria {
    size_t n;
    size_t count;
    qd_equilibrium *pts;     /* sorted by q (lexicographic) */
    bool exact;              /* every point found exactly: the complete set (angles in
                                (-pi, pi]) */
    bool continuum;          /* some equilibria are not isolated (a singular Jacobian
                                with a null direction along which F stays 0) */
    const char *method;      /* "exact", "newton" or "multistart" */
} qd_equilibria;

typedef struct qd_equilibria_opts {
    const double *near;      /* n: Newton from this guess only (no exact attempt) */
    const double *lo, *hi;   /* n each: the search box; NULL: qd_equilibria_default_box */
    size_t starts;           /* multi-start points; 0: 40 n + 40 */
    bool numeric_only;       /* skip the exact attempt */
} qd_equilibria_opts;

/* Which coordinates are angles (appear inside sin or cos of f at rest, T or
 * V), and the default box: angles [-pi, pi], others [-10, 10]. */
QD_API qd_status qd_equilibria_default_box(qd_ctx *ctx, const qd_eom *e, const qd_model *m, bool *angle,
                                    double *lo, double *hi);

/* Find the equilibria of e (derived from m; no multipliers) with the
 * parameters at syms/vals (as for qd_eom_eval; exact values from the model
 * for the exact attempt).  opts may be NULL.  count may be 0 (QD_OK). */
QD_API qd_status qd_equilibria_find(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t nvals,
                             const qd_expr *const *syms, const double *vals,
                             const qd_equilibria_opts *opts, qd_equilibria *out);
QD_API void qd_equilibria_free(qd_equilibria *r);

#ifdef __cplusplus
}
#endif
#endif
