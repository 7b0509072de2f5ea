/*
 * qdot/mech.h - equations of motion from a model.
 *
 * Lagrange's equations, for each coordinate q_j,
 *
 *     d/dt(dL/dq'_j) - dL/dq_j + dD/dq'_j = Q_j,
 *
 * are linear in the accelerations and are written M(q, q', t) q'' = f(q, q', t):
 * M_jk = d^2 L / dq'_j dq'_k (the mass matrix, symmetric), and f the rest
 * moved to the right-hand side.  Every entry is simplified.
 */
#ifndef QDOT_MECH_H
#define QDOT_MECH_H

#include <stddef.h>
#include "expr.h"
#include "model.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct qd_eom {
    size_t n;                    /* degrees of freedom */
    const qd_expr **q;           /* coordinates q_j */
    const qd_expr **qd;          /* velocities q'_j */
    const qd_expr **qdd;         /* accelerations q''_j */
    const qd_expr **M;           /* n*n, row-major */
    const qd_expr **f;           /* n */
    const qd_expr *L;            /* the Lagrangian used */
    /* The kinetic energy split by degree in the velocities, T = T2 + T1 + T0
     * (T1, T0 not zero for rheonomic coordinates); NULL when L was given
     * without T. */
    const qd_expr *T2, *T1, *T0;
    const qd_expr **acc;         /* n symbolic accelerations after qd_eom_solve, else NULL */
    void *priv;                  /* the library's: the compiled numeric program */
} qd_eom;

/* Derive the equations of a model.  Parameters stay symbolic.  A mass matrix
 * that is singular (identically: det M simplifies to 0) is QD_ERR_SINGULAR.
 * NULL on failure, reason in the context. */
qd_eom *qd_eom_derive(qd_ctx *ctx, const qd_model *m);
void qd_eom_free(qd_eom *e);

/* Solve M q'' = f symbolically for q'' (fraction-free elimination, each entry
 * simplified).  QD_ERR_TOOBIG when the result would exceed max_ops operations
 * (count_ops) in some entry: the caller then keeps M and f. */
qd_status qd_eom_solve(qd_ctx *ctx, qd_eom *e, size_t max_ops);

/* Numbers: M, f and q'' at one state.  vals gives the value of each symbol in
 * syms (coordinates, velocities, t, parameters); symbols not given are 0.
 * M is n*n row-major; M, f or qdd may be NULL when not wanted.
 * QD_ERR_SINGULAR when M is singular at that state (M and f are still
 * filled).  M and f are compiled on the first call and kept in e, so one
 * qd_eom must not be evaluated on two threads at once. */
qd_status qd_eom_eval(qd_ctx *ctx, const qd_eom *e, size_t nvals, const qd_expr *const *syms,
                      const double *vals, double *M, double *f, double *qdd);

#ifdef __cplusplus
}
#endif
#endif
