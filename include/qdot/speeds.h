/*
 * qdot/speeds.h - equations of motion in generalized speeds (quasi-velocities):
 * Kane's, Gibbs-Appell's and Boltzmann-Hamel's forms (Desloge ch. 67-70).
 *
 * A model declares m speeds, each linear in the velocities (`speeds`,
 * qdot/model.h):
 *
 *     u_r = sum_j A_rj(q, t) q'_j + b_r(q, t),        r = 1..m,
 *
 * and has its constraints as rows C q' + c0 = 0 (a Pfaffian constraint as
 * given, a holonomic one phi(q, t) = 0 differentiated once: C_kj = dphi/dq_j,
 * c0_k = dphi/dt; the rows of qd_eom's A).  Stacked, the n x n velocity map
 * P = [A; C] must be invertible (m + ncon = n, independent rows: else
 * QD_ERR_SINGULAR, QD_REASON_DEPENDENT_SPEEDS, naming the dependent rows).
 * With [W | Wc] = P^-1 (W the first m columns):
 *
 *     q' = W u + w,     w = -W b - Wc c0                    (kinematics)
 *
 * holds with every constraint satisfied for every u: W_jr = dq'_j/du_r are
 * the partial velocities, and C W = 0 (the constraint forces do no work on
 * them), so no multiplier enters.  The dynamic equations are
 *
 *     M_u u' = f_u,      M_u = W^T M W  (m x m, symmetric positive definite
 *                                         when M is),
 *
 * in q, u, t and the parameters (q' replaced by the kinematics).  Three
 * derivations, equal exactly (the tests show it):
 *
 *   QD_SPEEDS_KANE    Kane's equations F_r + F*_r = 0 in Lagrange's form:
 *                     sum_j W_jr E_j = 0, E_j = d/dt dL/dq'_j - dL/dq_j
 *                     + dD/dq'_j - Q_j, with q' = W u + w and
 *                     q'' = W u' + (d/dt W) u + w' (Kane and Levinson 1985,
 *                     ch. 6; Desloge ch. 69 C12: B^T (M q'' + h) = B^T Q).
 *   QD_SPEEDS_APPELL  Gibbs-Appell: dS/du'_r = Pi_r with the acceleration
 *                     energy S (below) and Pi = W^T G, G the generalized
 *                     forces the kinetic part leaves: Q_j - dD/dq'_j and
 *                     those of V and U (Desloge ch. 69 thm 2, ch. 70).
 *   QD_SPEEDS_HAMEL   Boltzmann-Hamel: with all n quasi-velocities
 *                     v = (u, s), s = C q' + c0 (0 on the motion), and
 *                     L*(q, v, t) = L at q' = W u + Wc s + w,
 *                     d/dt d(L*)/du_r - sum_j W_jr d(L*)/dq_j
 *                       + sum_s d(L*)/dv_s sum_j W_jr (sum_k (dP_sj/dq_k
 *                       - dP_sk/dq_j) q'_k + dP_sj/dt - dp0_s/dq_j)
 *                       = sum_j W_jr (Q_j - dD/dq'_j),
 *                     p0 = (b, c0), every derivative at fixed v, then
 *                     s = 0 (Desloge ch. 68; his gamma_ikm are the
 *                     dP/dq terms: seed-desloge-C.md pitfall 2).
 *
 * The Gibbs-Appell function (acceleration energy) is
 *
 *     S = sum_particles m/2 |r''|^2
 *       + sum_bodies (M/2 |c''|^2 + 1/2 a.I a + a.(w x I w))
 *       + the part of any `T = ...` (or `L = ...`) term: 1/2 q''^T M q'' + h^T q''
 *
 * (w, a = w' the body-axis angular velocity and acceleration, I the
 * body-axis inertia about the centre of mass c; h the part of Lagrange's
 * expression free of accelerations), with q'' and q' in terms of u', u, q
 * as above: the constraints are substituted first (Desloge ch. 69 thm 2,
 * seed pitfall 13), and the terms free of u' are dropped:
 *
 *     S = 1/2 u'^T M_u u' + g^T u',   f_u = Pi - g.
 *
 * With `L = ...` given, S is built from L's own Lagrange expression (its
 * potential terms then sit in g rather than in Pi; dS/du' = Pi holds).
 *
 * Multipliers (opts.multipliers): the constraint forces are not needed for
 * the motion, but recovered as lambda = Wc^T E, E Lagrange's residual
 * M q'' - f at the motion (C Wc = I, so this solves E = C^T lambda): the
 * same lambda_k, sign and scale as qd_eom's (M q'' = f + A^T lambda), as
 * expressions in q, u, u', t.
 */
#ifndef QDOT_SPEEDS_H
#define QDOT_SPEEDS_H

#include <stdbool.h>
#include <stddef.h>
#include "expr.h"
#include "mech.h"
#include "model.h"
#include "state.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum qd_speeds_method {
    QD_SPEEDS_KANE,
    QD_SPEEDS_APPELL,
    QD_SPEEDS_HAMEL,
    QD_SPEEDS_METHOD_COUNT
} qd_speeds_method;

QD_API const char *qd_speeds_method_name(qd_speeds_method m);          /* "kane" */
QD_API bool qd_speeds_method_from_name(const char *name, qd_speeds_method *m);

typedef struct qd_speeds_opts {
    qd_speeds_method method;
    bool appell;       /* compute S (qd_speeds_eom.S) whatever the method */
    bool multipliers;  /* the constraints' multipliers (qd_speeds_eom.mult) */
} qd_speeds_opts;

typedef struct qd_speeds_eom {
    size_t n;                 /* coordinates */
    size_t m;                 /* speeds */
    size_t ncon;              /* constraints (the rows C) */
    const qd_expr **q, **qd;  /* n: coordinates and their velocities */
    const qd_expr **u, **ud;  /* m: the speeds (qd_model_speed) and u' */
    const qd_expr **def;      /* m: u_r as the model defines it (q, q', t) */
    const qd_expr **W;        /* n*m, row-major: dq'_j/du_r */
    const qd_expr **w;        /* n */
    const qd_expr **kin;      /* n: q'_j = sum_r W_jr u_r + w_j, simplified */
    const qd_expr **M;        /* m*m, row-major */
    const qd_expr **f;        /* m */
    const qd_expr *T;         /* T*(q, u, t): the kinetic energy (NULL when L was given) */
    const qd_expr *S;         /* the Gibbs-Appell function (u'-free terms dropped),
                                 when opts.appell or the method is appell; else NULL */
    qd_con *con;              /* ncon: the constraints, classified as in qd_eom */
    const qd_expr **mult;     /* ncon multipliers in q, u, u', t (opts.multipliers), else NULL */
    qd_speeds_method method;
    void *priv;               /* the library's: the compiled numeric program */
    const qd_expr **acc;      /* m: u' explicit after qd_speeds_solve, else NULL */
} qd_speeds_eom;

/* Derive the equations in speeds of a model with `speeds` (QD_ERR_ARG when
 * it has none; a model given by H is refused too).  opts may be NULL: Kane,
 * no S, no multipliers.  QD_ERR_SINGULAR when P is singular (the error is
 * about the speed or constraint that depends on the others, with
 * QD_REASON_DEPENDENT_SPEEDS, locatable with qd_model_locate) or M_u is.
 * NULL on failure, reason in ctx. */
QD_API qd_speeds_eom *qd_speeds_derive(qd_ctx *ctx, const qd_model *m, const qd_speeds_opts *opts);
QD_API void qd_speeds_eom_free(qd_speeds_eom *e);

/* Hamel's three-index symbols of a velocity map (Desloge ch. 68, ch. 69;
 * seed-desloge-C.md T1 and pitfall 2): with quasi-velocities
 * pid_i = sum_j a_ij(q) q'_j and b = a^-1,
 *
 *     gamma_ikm = sum_{j,l} (d a_kj/d q_l - d a_kl/d q_j) b_ji b_lm,
 *
 * placed as + sum_{k,m} gamma_ikm (dTs/d pid_k) pid_m (Ts = T*) in the Boltzmann-Hamel
 * equations; gamma_ikm = -gamma_imk.  a is n*n row-major in the coordinates
 * q; out receives n^3 simplified entries, gamma_ikm at (i*n + k)*n + m.
 * QD_ERR_SINGULAR when a is singular.  (Polar r, th with pid = (r',
 * r^2 th'/2): gamma_122 = -2/r, gamma_221 = 2/r, the rest 0.) */
QD_API qd_status qd_hamel_coefficients(qd_ctx *ctx, size_t n, const qd_expr *const *q,
                                       const qd_expr *const *a, const qd_expr **out);

/* The same for the speeds of e: a is the speeds' rows A (u = A q' + b)
 * stacked on the constraints' rows C (the P of the head comment); a
 * rheonomic or affine part (dA/dt, b, c0) is left out, as Desloge ch. 68
 * does.  out receives n^3 entries indexed as above, the indices i, k, m
 * running over the m speeds first, then the constraints. */
QD_API qd_status qd_speeds_hamel_coefficients(qd_ctx *ctx, const qd_speeds_eom *e,
                                              const qd_expr **out);

/* Solve M_u u' = f_u symbolically for u' (the fraction-free elimination of
 * qd_eom_solve, each entry simplified) into e->acc.  QD_ERR_TOOBIG when an
 * entry would exceed max_ops operations (count_ops): the caller keeps M_u
 * and f_u; QD_ERR_SINGULAR when det M_u simplifies to 0. */
QD_API qd_status qd_speeds_solve(qd_ctx *ctx, qd_speeds_eom *e, size_t max_ops);

/* Numbers at one state.  vals gives the value of each symbol in syms
 * (coordinates, speeds, t, parameters; symbols not given are 0).  Any
 * output may be NULL: qd (n) the velocities from the kinematics, ud (m) the
 * speeds' rates (M_u u' = f_u solved), lambda (ncon, needs e->mult: else
 * QD_ERR_ARG) the multipliers at that u'.  QD_ERR_SINGULAR when M_u is
 * singular there.  Compiled on the first call and kept in e (one thread). */
QD_API qd_status qd_speeds_eval(qd_ctx *ctx, const qd_speeds_eom *e, size_t nvals,
                                const qd_expr *const *syms, const double *vals, double *qd,
                                double *ud, double *lambda);

/* The speeds at (q, q', t): u = A q' + b (the definitions), m of them; vals
 * as for qd_speeds_eval but with the velocities qd_jet(q, 1) given. */
QD_API qd_status qd_speeds_from_velocities(qd_ctx *ctx, const qd_speeds_eom *e, size_t nvals,
                                           const qd_expr *const *syms, const double *vals,
                                           double *u);
/* A state of m (derived into e) read from text as qd_state_read reads it:
 * *st is made (qd_state_init: q, q' and t at 0, the parameters at their
 * values) with e's speeds appended at 0 (qd_state_append), so that text
 * names q, t, the parameters and the speeds ("x=1, u1=0.3").  A velocity
 * of e's coordinates named in text is refused, whatever its value: with
 * speeds the velocities follow from them (QD_ERR_ARG, located under its name in text, the hint
 * naming the speeds).  Other errors as qd_state_read's, located in text
 * (qd_ctx_diag).  Free *st with qd_state_free, also after a failure. */
QD_API qd_status qd_speeds_state_read(qd_ctx *ctx, const qd_model *m, const qd_speeds_eom *e,
                                      const char *text, qd_state *st);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_speeds_derive (opts); qd_speeds_eval
 * (lambda, qd, ud). An array whose count is 0 may be NULL. */
#endif
