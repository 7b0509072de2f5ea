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

/* A constraint of the model, classified.
 *
 *   holonomic       phi(q, t) = 0, no velocities.  a_j = dphi/dq_j, a0 = dphi/dt,
 *                   so that phi' = sum_j a_j q'_j + a0.
 *   Pfaffian        sum_j a_j(q, t) q'_j + a0(q, t) = 0: integrable when it is
 *                   exact after multiplying by an integrating factor (then
 *                   `integral` = const along the motion and `factor` is that
 *                   factor, 1 when exact), otherwise nonholonomic.
 *   nonlinear       velocities enter nonlinearly: not supported (an error).
 */
typedef enum qd_con_kind {
    QD_CON_HOLONOMIC,
    QD_CON_INTEGRABLE,     /* Pfaffian, integrable */
    QD_CON_NONHOLONOMIC    /* Pfaffian, not integrable */
} qd_con_kind;

typedef struct qd_con {
    const char *name;            /* the model's name for it (owned by the model) */
    qd_con_kind kind;
    const qd_expr *expr;         /* as the model gives it (= 0) */
    const qd_expr **a;           /* n coefficients of the velocities */
    const qd_expr *a0;           /* the velocity-free part */
    const qd_expr *integral;     /* QD_CON_INTEGRABLE: phi(q, t), constant along the motion;
                                    NULL when integrable but not found in closed form */
    const qd_expr *factor;       /* the integrating factor used, or NULL */
    const qd_expr *lambda;       /* the multiplier, a plain symbol lambda_<name> */
} qd_con;

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
    /* Constraints: M q'' = f + A^T lambda, closed by A q'' = b (each
     * holonomic constraint differentiated twice, each Pfaffian once).
     * A is ncon*n row-major (A_kj = con[k].a[j]); b is ncon. */
    size_t ncon;
    qd_con *con;
    const qd_expr **A, **b;
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
