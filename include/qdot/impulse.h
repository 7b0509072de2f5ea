/*
 * qdot/impulse.h - impulsive motion: blows, sudden constraints, collisions
 * (Desloge ch. 57 thm 1, Byerly ch. III arts. 26-37, the Britannica's
 * "Dynamics" sec. "impulsive motion").
 *
 * Across an impulse the configuration q is frozen and only the velocities
 * jump.  Integrating Lagrange's equations over the vanishing duration of
 * the impulse leaves
 *
 *     M(q) (q'+ - q'-) = Qhat + A^T Lambda,
 *
 * M the mass matrix (d^2 T / dq' dq'), Qhat the generalized impulses of the
 * model's blows (qd_model_blow), A the rows of the constraints that act
 * through the impulse and Lambda their impulsive multipliers.  The rows are
 * the velocity forms c(q') = a . q' + a0 of
 *
 *   - the ordinary constraints, which keep holding:       c(q'+) = 0,
 *   - the sudden ones (`impact constraint`, Newton's law): c(q'+) = -E c(q'-),
 *   - the prescriptions (`prescribe`, Thomson's problem):  c(q'+) = 0,
 *
 * a holonomic constraint phi(q, t) = 0 giving c = dphi/dq . q' + dphi/dt.
 * The system is solved numerically always, and in closed form (in the
 * parameters and the state as given) when asked and small enough.
 */
#ifndef QDOT_IMPULSE_H
#define QDOT_IMPULSE_H

#include <stdbool.h>
#include <stddef.h>
#include "expr.h"
#include "model.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct qd_impulse_opts {
    /* The state just before: n coordinates and n velocities, expressions
     * in the parameters (numbers, pi/6, al, v); t NULL for 0.  Evaluated at
     * the model's parameter values for the numbers. */
    const qd_expr *const *q;
    const qd_expr *const *qd;
    const qd_expr *t;
    bool exact;        /* also solve in closed form */
    size_t max_ops;    /* exact: give up when an entry exceeds this many
                          operations (0: 4000); exact is then false */
} qd_impulse_opts;

/* A theorem of impulsive motion checked on the case at hand.
 *
 *   Carnot's: a sudden constraint (E = 0, no blows, constraints homogeneous
 *     in the velocities) loses the kinetic energy of the velocity change:
 *     a = energy lost, b = T(q'+ - q'-).
 *   Bertrand's: with the same blows, the sudden constraints and
 *     prescriptions lower the kinetic energy after, by the energy of the
 *     difference of the two motions: a = T after without them, b = T after
 *     with them, c = T(difference); holds when a >= b and a - b = c.
 *   Thomson's (Kelvin's): among the motions in which the struck points have
 *     the velocities (along each blow) that the blows give them, the actual
 *     velocity change has the least energy: a = T(q'+ - q'-), b = the least
 *     such energy, found by minimization; holds when a = b.
 *
 * applies: the theorem's hypotheses hold here; holds: it was verified
 * numerically, to 1e-9 relative. */
typedef struct qd_impulse_check {
    bool applies, holds;
    double a, b, c;
} qd_impulse_check;

/* Two bodies (particles or rigid bodies, the model's only two) meeting
 * (Desloge ch. 61): the centre-of-mass velocity w is conserved; velocities
 * are of the centres of mass; angles are measured from the relative
 * velocity before, u = v1 - v2, in [0, pi] (0 when a velocity is zero).
 * Filled when the model has exactly two mass elements (particles, then
 * bodies: body 1 is the first), its sudden constraints are all gaps that
 * close (holonomic `impact constraint`s; none prescribed), and the
 * impulses are internal: the total momentum is the same after (to 1e-9 of
 * the speeds) and the bodies met (u before is not 0).  A contact with the
 * ground, a pivot, a blow from outside, a sudden rolling (velocity)
 * constraint or prescribed velocities are not a collision. */
typedef struct qd_collision {
    double m1, m2;
    double w[3];                     /* centre-of-mass velocity */
    double v1[2][3], v2[2][3];       /* lab velocities, before [0] and after [1] */
    double u[2][3];                  /* relative velocity v1 - v2 */
    double eps[2];                   /* relative kinetic energy m1 m2 |u|^2 / (2 (m1 + m2)) */
    double T_cm;                     /* (m1 + m2) |w|^2 / 2: the lab energy of translation
                                        is T_cm + eps, before and after (Koenig) */
    double s[2];                     /* body 1's speed in the CM frame, before (s) and after
                                        (s*): s*^2 = s^2 (1 + (eps[1] - eps[0])/eps[0])
                                        (Desloge ch. 61, masses unchanged) */
    double theta_cm;                 /* deflection of u (CM angle of body 1), radians */
    double theta_lab1, theta_lab2;   /* angles of v1 and v2 after from u before */
    double gamma;                    /* |w| / s*, s* body 1's speed in the CM frame after;
                                        tan theta_lab1 = sin theta / (cos theta + gamma)
                                        when body 2 is at rest before (Desloge ch. 61);
                                        0 when s* = 0 (the bodies move together after) */
} qd_collision;

typedef struct qd_impulse {
    size_t n;
    const qd_expr *const *q;         /* the model's coordinates */
    double *qd_before, *qd_after;    /* n */
    double *Qhat;                    /* n: the blows' generalized impulses */
    /* The impulsive multipliers: ordinary constraints, then sudden ones,
     * then prescriptions, each named "Lambda_NAME" (owned by the result). */
    size_t nmult;
    const char **mult_name;
    double *mult;
    double *R;                       /* n: A^T Lambda, the constraints' generalized impulses */
    /* Impulsive reactions at the points of the model's `reaction`
     * statements (on any kind of constraint): Cartesian impulses. */
    size_t nreact;
    const char **react_name;         /* the reaction's name (owned by the model) */
    double (*react)[3];
    /* energy_lost = T_before - T_after, T = T2 + T1 + T0 at the frozen
     * configuration (a model given by L: L's T2 + T1, its T0 being
     * indistinguishable from -V; differences are unaffected). */
    double T_before, T_after, energy_lost;
    /* Closed forms (exact true): in the parameters and the state as given,
     * the same saddle system solved by fraction-free elimination
     * (qd_eom_solve) and simplified; mult_exact is NULL without rows.
     * exact stays false, with no error, when an entry exceeds max_ops or
     * the symbolic system is singular for every parameter value. */
    bool exact;
    const qd_expr **qd_after_exact;  /* n */
    const qd_expr **mult_exact;      /* nmult */
    const qd_expr *energy_lost_exact;
    qd_impulse_check carnot, bertrand, thomson;
    bool collision;                  /* col is filled */
    qd_collision col;
    /* nmult flags: a row that depends on the others at the impact and is
     * consistent with them (two points' full velocity vectors prescribed on
     * one rigid body): reduced by rank, its multiplier set to 0 (the
     * multipliers are not unique; the velocities after are).  Truly
     * inconsistent rows are QD_ERR_SINGULAR. */
    bool *redundant;
    size_t nredundant;
} qd_impulse;

/* Solve the impulse equations of m at the state in opts.  Errors:
 * QD_ERR_ARG for a restitution outside [0, 1] (naming the constraint), a
 * prescription or sudden constraint not linear in the velocities, a model
 * with neither blows nor sudden constraints nor prescriptions;
 * QD_ERR_SINGULAR when M is singular there or the rows are dependent or
 * inconsistent (naming the constraints); QD_ERR_NONLINEAR when T is not
 * quadratic in the velocities.  *out is zeroed on failure.  A NULL opts,
 * or a NULL q, qd or entry of them, takes the model's `initial` value as
 * written (qd_model_initial_definition); none there is QD_ERR_ARG. */
QD_API qd_status qd_impulse_solve(qd_ctx *ctx, const qd_model *m, const qd_impulse_opts *opts,
                                  qd_impulse *out);
QD_API void qd_impulse_free(qd_impulse *r);

/* The state just before, for qd_impulse_opts, as `qdot impulse --at`
 * takes it: each coordinate and velocity the model's `initial` as written
 * (qd_model_initial_definition, exact in the parameters), overridden by the
 * items of at ("q=V, q'=V, t=V", read by qd_state_read and kept exact;
 * parameters refused; at may be NULL), 0 where neither names it; *t the
 * time at gives, else NULL.  q and qd have qd_model_ncoords(m) entries
 * each; the expressions are the context's.  QD_OK; else the reader's error
 * located in at; QD_ERR_NOMEM. */
QD_API qd_status qd_impulse_state_read(qd_ctx *ctx, const qd_model *m, const char *at,
                                       const qd_expr **q, const qd_expr **qd,
                                       const qd_expr **t);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_impulse_solve (opts);
 * qd_impulse_state_read (at). An array whose count is 0 may be NULL. */
#endif
