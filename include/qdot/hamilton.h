/*
 * qdot/hamilton.h - the Legendre transform of a model and Hamilton's
 * equations.
 *
 * From Lagrange's equations of an unconstrained model (qd_eom):
 *
 *     p_j = dL/dq'_j = sum_k M_jk q'_k + b_j      (L is quadratic in q')
 *     q'  = M^-1 (p - b)                           (solved exactly)
 *     H(q, p, t) = sum_j p_j q'_j - L              (q' substituted)
 *     dq_j/dt = dH/dp_j
 *     dp_j/dt = -dH/dq_j + Q_j - dD/dq'_j          (the last two: extra_j)
 *
 * The momenta are plain symbols named p_<coordinate>.  The energy compared
 * with H is E = T + V + U0, U0 the velocity-free part of the generalized
 * potential U (q phi for a charge): H = E unless the kinetic energy has
 * parts T1, T0 linear in or free of the velocities (rheonomic coordinates).
 */
#ifndef QDOT_HAMILTON_H
#define QDOT_HAMILTON_H

#include <stdbool.h>
#include <stddef.h>
#include "expr.h"
#include "mech.h"
#include "model.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct qd_ham {
    size_t n;
    const qd_expr **q;      /* the coordinates (the eom's) */
    const qd_expr **p;      /* the momenta, symbols p_<q> */
    const qd_expr **pdef;   /* dL/dq'_j in q, q', t */
    const qd_expr **vel;    /* q'_j in q, p, t */
    const qd_expr *H;       /* in q, p, t, simplified */
    const qd_expr **dq;     /* dH/dp_j */
    const qd_expr **dp;     /* -dH/dq_j + extra_j */
    const qd_expr **extra;  /* Q_j - dD/dq'_j in q, p, t (0 when none) */
    const qd_expr *H_minus_E; /* H - (T + V + U0) in q, p, t, simplified; NULL
                                 when the model gives L and no T */
    bool is_energy;         /* H_minus_E simplified to 0 */
    bool conserved;         /* no explicit t in H, every Q_j 0 and no D */
} qd_ham;

/* The Hamiltonian of model m from its derived equations e (qd_eom_derive).
 * Constraints (or eliminated coordinates) are QD_ERR_ARG, momenta that are
 * not linear in the velocities QD_ERR_NONLINEAR, a singular mass matrix
 * QD_ERR_SINGULAR.  NULL on failure, reason in the context. */
qd_ham *qd_ham_derive(qd_ctx *ctx, const qd_model *m, const qd_eom *e);
void qd_ham_free(qd_ham *h);

#ifdef __cplusplus
}
#endif
#endif
