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
 * A model given by its Hamiltonian (`momenta ...` and `H = ...`) is taken as
 * it is: Hamilton's equations come from H directly, and the Lagrangian from
 * the inverse Legendre transform (qd_legendre_inverse) when H is regular.
 *
 * The momenta are plain symbols named p_<coordinate>, or as the model's
 * `momenta` line names them.  The energy compared
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
    const qd_expr **q;      /* the coordinates (the eom's, or the model's for an H model) */
    const qd_expr **qd;     /* their velocities q'_j */
    const qd_expr **p;      /* the momenta, symbols p_<q> */
    const qd_expr **pdef;   /* dL/dq'_j in q, q', t (for an H model: p_j solved from
                               q' = dH/dp, NULL entries when H is not regular) */
    const qd_expr **vel;    /* q'_j in q, p, t */
    const qd_expr *H;       /* in q, p, t, simplified */
    const qd_expr **dq;     /* dH/dp_j */
    const qd_expr **dp;     /* -dH/dq_j + extra_j */
    const qd_expr **extra;  /* Q_j - dD/dq'_j in q, p, t (0 when none) */
    const qd_expr *H_minus_E; /* H - (T + V + U0) in q, p, t, simplified; NULL
                                 when the model gives L and no T */
    bool is_energy;         /* H_minus_E simplified to 0 */
    bool conserved;         /* no explicit t in H, every Q_j 0 and no D */
    bool H_given;           /* the model gives H (qd_model_hamiltonian_given) */
    const qd_expr *L_from_H; /* H models: L = sum p q' - H in q, q', t, simplified;
                                NULL when H is not regular (then L_why says why) */
    char L_why[256];
    bool implicit;          /* L is not quadratic in q' and p = dL/dq' has no closed-form
                               inverse: vel_j is q'_j itself, defined by pdef_j = p_j, and
                               H = sum p q' - L, dq, dp are in q, q', p, t (so dq_j = q'_j,
                               dp_j = dL/dq_j + extra_j); qd_ham_velocities_at gives q' */
    /* Hamilton's equations of the second kind (qd_ham2_derive): the fields
     * above read with T in place of L, s for p and K for H.  p are then the
     * symbols s_<q>, pdef s_j = dT/dq'_j, vel q'(q, s, t), H is
     * K = sum s q' - T, dq = dK/ds, dp = ds_j/dt = -dK/dq_j + Q_j, extra the
     * whole generalized force Q_j (the given forces, -dV/dq_j, the
     * generalized potential's d/dt(dU/dq'_j) - dU/dq_j and -dD/dq'_j),
     * H_minus_E K - T (0 when T is homogeneous quadratic in q', Desloge
     * ch. 72 eq. 5) with is_energy K = T, conserved: K free of t and every
     * Q_j 0; s_is_p: s_j = p_j = dL/dq'_j for every j (eq. 6: U = U(q, t)). */
    bool second_kind;
    bool s_is_p;
} qd_ham;

/* The Hamiltonian of model m from its derived equations e (qd_eom_derive).
 * Constraints (or eliminated coordinates) are QD_ERR_ARG, a singular mass
 * matrix QD_ERR_SINGULAR.  An L not quadratic in the velocities is solved
 * in closed form when it is F(q'^T G q') + a.q' + L0 (the relativistic
 * particle in fields: H = sqrt(m^2 c^4 + c^2 (p - e A)^2) + e phi), else
 * kept implicit (h->implicit); L linear in a velocity, or homogeneous of
 * degree 1 in them beyond linear terms, is QD_ERR_SINGULAR naming it.  NULL on failure, reason in the context.
 * For a model given by H, e is not used (it may be NULL): the equations are
 * dq_j/dt = dH/dp_j, dp_j/dt = -dH/dq_j + Q_j - dD/dq'_j (q' = dH/dp), and
 * L_from_H is filled when H is regular; constraints are QD_ERR_ARG. */
QD_API qd_ham *qd_ham_derive(qd_ctx *ctx, const qd_model *m, const qd_eom *e);
QD_API void qd_ham_free(qd_ham *h);

/* Hamilton's equations of the second kind (Desloge ch. 72 Thm 1): the
 * Legendre transform of the kinetic energy T(q, q', t) instead of L,
 *
 *     s_j = dT/dq'_j,   K = sum_j s_j q'_j - T   (in q, s, t),
 *     dq_j/dt = dK/ds_j,   ds_j/dt = -dK/dq_j + Q_j,
 *
 * where Q_j is every force not in T: the given forces (Q[q], force ... at),
 * -dV/dq_j, the generalized potential's d/dt(dU/dq'_j) - dU/dq_j and the
 * dissipation's -dD/dq'_j (Desloge ch. 72 eq. 1), so that dissipative
 * forces need no potential.  The result is a qd_ham with second_kind set
 * (its fields read as the comment there says); free it with qd_ham_free.
 * e is m's qd_eom_derive (NULL only for a model given by H, which is
 * refused).  A model that gives L or H instead of T is QD_ERR_ARG ("built
 * from T"), as are constraints; a U whose force holds
 * accelerations (U not linear in the velocities) is QD_ERR_NONLINEAR; a
 * singular d^2T/dq'dq' QD_ERR_SINGULAR.  NULL on failure, reason in the
 * context. */
QD_API qd_ham *qd_ham2_derive(qd_ctx *ctx, const qd_model *m, const qd_eom *e);

/* The inverse Legendre transform of a model given by H (Desloge ch. 71,
 * Appendix 22): q' = dH/dp solved for p, L = sum p q' - H, simplified, in
 * q, q', t.  H quadratic in the momenta gives a linear system; otherwise
 * QD_ERR_NONLINEAR.  A singular d^2H/dp^2 (H = p_x) is QD_ERR_SINGULAR
 * naming the momentum that q' does not determine; a model not given by H is
 * QD_ERR_ARG.  NULL on failure, reason in the context.  pdef (n entries, may
 * be NULL) receives p_j(q, q', t). */
QD_API const qd_expr *qd_legendre_inverse(qd_ctx *ctx, const qd_model *m);
QD_API qd_status qd_legendre_inverse_p(qd_ctx *ctx, const qd_model *m, const qd_expr **pdef,
                                const qd_expr **L);

/* Before qd_eom_derive, for a model whose L is not quadratic in the
 * velocities: QD_ERR_SINGULAR, the message naming the coordinate, when its
 * Hessian d^2L/dq'dq' is singular for a reason that can be named (L linear
 * in a velocity: "L is linear in x': ..."; L homogeneous of degree 1 in them
 * beyond linear terms, so H = sum p q' - L does not depend on p: Desloge
 * Appendix 20).  QD_OK otherwise, which does not prove the Hessian regular;
 * quadratic L and models given by H are always QD_OK (their own checks
 * speak for them). */
QD_API qd_status qd_ham_regular(qd_ctx *ctx, const qd_model *m);

/* The velocities at a point for h->implicit (and any h): Newton's method on
 * p = dL/dq' (pdef), the Jacobian d^2L/dq'dq'.  syms/vals (nsyms) give the
 * coordinates, momenta, t and parameters; values given for the velocities
 * are the first guess (else 0).  qd_out receives h->n velocities.
 * QD_ERR_NUMERIC when it does not converge, QD_ERR_SINGULAR when the
 * Hessian is singular on the way, message in the context. */
QD_API qd_status qd_ham_velocities_at(qd_ctx *ctx, const qd_ham *h, size_t nsyms,
                                      const qd_expr *const *syms, const double *vals,
                                      double *qd_out);

/* Whether h gives H in closed form, for a computation (what, a sentence
 * subject: "the Hamilton-Jacobi equation") that needs it: QD_OK when it
 * does, QD_ERR_NONLINEAR with a message saying what needs it when
 * h->implicit (p = dL/dq' has no closed-form solution for q'). */
QD_API qd_status qd_ham_require_closed(qd_ctx *ctx, const qd_ham *h, const char *what);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_ham_derive (e); qd_legendre_inverse_p
 * (pdef). An array whose count is 0 may be NULL. */
#endif
