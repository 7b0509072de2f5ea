/*
 * qdot/action.h - action-angle variables of a separable bounded motion
 * (Desloge ch. 79; Goldstein sec. 10.6-10.8).
 *
 * For a motion separated in its coordinates (qdot/hj.h: each p_k^2 a
 * function of q_k and the separation constants alpha), the action of each
 * coordinate is
 *
 *     J_k = oint p_k dq_k                       (no 1/(2 pi): the seeds')
 *
 * over one cycle of q_k: twice the integral of sqrt(p_k^2) between the two
 * turning points (a libration), or the integral over one period 2 pi of an
 * angle whose p_k^2 stays positive (a rotation).  J_k >= 0: the sense of a
 * rotation is not in it.  The frequencies follow from the Jacobian
 *
 *     A_kj = dJ_k/dalpha_j = oint (dp_k^2/dalpha_j) / (2 p_k) dq_k
 *
 * (differentiated under the integral: the end points add nothing, p_k
 * vanishes there), as omega_k = 2 pi dH/dJ_k = 2 pi (A^-1)_{E,k}, in rad/s,
 * E the energy constant; the angle variables at the state are
 * 2 pi dW/dJ_k = 2 pi (A^-T beta)_k, beta_j = dW/dalpha_j along the cycles.  Every integral is a tanh-sinh quadrature
 * (src/num/quad.c) whose end points are the turning points themselves.
 *
 * Ownership: a qd_action holds its own arrays, freed by qd_action_free;
 * its expressions belong to the context.
 */
#ifndef QDOT_ACTION_H
#define QDOT_ACTION_H

#include <stdbool.h>
#include <stddef.h>
#include "expr.h"
#include "hj.h"
#include "model.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum qd_act_kind {
    QD_ACT_LIBRATION, /* q_k oscillates between two turning points */
    QD_ACT_ROTATION   /* an angle that goes round: p_k^2 > 0 over a whole period */
} qd_act_kind;

/* Why there is no action, when qd_action_at fails on the motion itself
 * rather than on its input. */
typedef enum qd_act_fail {
    QD_ACT_OK,
    QD_ACT_UNBOUNDED,     /* a coordinate with no second turning point (no cycle) */
    QD_ACT_SEPARATRIX,    /* a double root of p_k^2: the period (dJ/dE) diverges
                             logarithmically */
    QD_ACT_AT_REST,       /* p_k^2 <= 0 all round the state: J_k = 0, rest at an equilibrium */
    QD_ACT_NOT_SEPARABLE, /* the Hamilton-Jacobi equation does not separate */
    QD_ACT_SINGULAR       /* an end of the motion where p_k^2 does not vanish (infinite:
                             a collision, or a singular point of the coordinates such as
                             the axis of parabolic ones; or the edge of its domain): no
                             turning point, so no cycle; the coordinate's lo = hi = there */
} qd_act_fail;

typedef struct qd_act_coord {
    const qd_expr *q;
    const qd_expr *constant;   /* its separation constant */
    double value;              /* the constant's value at the state */
    qd_act_kind kind;
    double lo, hi;             /* the turning points, or the period [q - pi, q + pi] */
    double J;                  /* oint p dq (>= 0) */
    double omega;              /* 2 pi dH/dJ, rad/s */
    /* the angle variable at the state, 2 pi dW/dJ in [0, 2 pi): 0 at the
     * lower turning point (for a rotation at q = 0 mod 2 pi), advancing at
     * omega in the motion */
    double angle;
} qd_act_coord;

/* Two commensurate frequencies: omega_i : omega_j = num : den. */
typedef struct qd_act_ratio {
    size_t i, j;
    long num, den;
} qd_act_ratio;

typedef enum qd_act_closed {
    QD_ACT_H_NONE,     /* no closed form recognised */
    QD_ACT_H_LINEAR,   /* H = sum_k omega_k J_k / (2 pi): oscillators */
    QD_ACT_H_KEPLER    /* H = -c / (J_1 + ... + J_n)^2, c = 2 pi^2 m k^2 */
} qd_act_closed;

typedef struct qd_action {
    size_t n;
    qd_act_coord *c;           /* n, in coordinate order */
    double energy;             /* the energy constant's value */
    double *dJ;                /* n * n, A_kj = dJ_k/dalpha_j (constants in hj order) */
    const char *form;          /* the separation used ("one degree of freedom", hj's form) */
    size_t nratio;
    qd_act_ratio *ratio;       /* the commensurate pairs (degeneracies) */
    qd_act_closed closed;
    double closed_c;           /* c of QD_ACT_H_KEPLER */
    qd_act_fail fail;          /* set when the call failed on the motion */
    size_t fail_coord;         /* the coordinate it failed at */
} qd_action;

/* The separation constants one motion may have. */
#define QD_ACT_MAX_CONST 16

typedef struct qd_action_opts {
    const char *energy_name;   /* NULL: "E" */
    double degeneracy_tol;     /* |omega_i/omega_j - num/den| relative; 0: 1e-9 */
    long max_den;              /* the largest num, den tried; 0: 12 */
    /* coordinates taken as angles (period 2 pi) besides those found inside
     * sin, cos or tan: a cyclic angle of a model given by H appears nowhere
     * (Kepler's H in r, theta) and would be read as unbounded */
    size_t nangles;
    const qd_expr *const *angles;
} qd_action_opts;

/* The actions and frequencies of model m at the state syms/vals (every
 * coordinate, velocity and parameter with a value; a momentum among them
 * is taken as given, the others come from p = dL/dq', or for a model
 * given by H from q' = dH/dp inverted; opts->angles adds angles).  One degree of freedom
 * is separated here (H = E solved for p^2); more go through qd_hj_derive.
 * On failure the reason is in ctx, and out->fail says which failure of the
 * motion it is (out->fail_coord where).  opts may be NULL. */
QD_API qd_status qd_action_at(qd_ctx *ctx, const qd_model *m, size_t nvals,
                              const qd_expr *const *syms, const double *vals,
                              const qd_action_opts *opts, qd_action *out);

struct qd_state; /* qdot/state.h */

/* The state `qdot action --at` and Python's Model.action(at=) take the
 * actions at, into *st (overwritten; free it with qd_state_free, also after
 * a failure): m's state at its `initial` values (qd_state_init,
 * qd_state_initial), at (NULL: none) read over it (qd_state_read, its
 * errors located in at), and for a model given by H the momenta at names
 * (after the parameters; those it does not name are left out, so that
 * qd_action_at takes the velocities instead). */
QD_API qd_status qd_action_state_read(qd_ctx *ctx, const qd_model *m, const char *at,
                                      struct qd_state *st);

/* The same from a separation already made (h->separable): angle[k] marks
 * the coordinates that are angles (period 2 pi); the constants take their
 * values from the integrals evaluated at syms/vals, which must give every
 * symbol those contain. */
QD_API qd_status qd_action_of_sep(qd_ctx *ctx, const qd_hj *h, const bool *angle, size_t nvals,
                                  const qd_expr *const *syms, const double *vals,
                                  const qd_action_opts *opts, qd_action *out);

QD_API void qd_action_free(qd_action *a);

/* a, the result of qd_action_at or qd_action_of_sep, appended to out.
 * Text: "separation: ...", "energy: ...", then for each coordinate its
 * kind with the turning points (a libration) or the period's range (a
 * rotation) and its separation constant's value, J_q, omega_q (rad/s) with
 * the period 2 pi/omega, angle_q; the commensurate pairs ("degenerate:
 * omega_x : omega_y = 1 : 2 ..."), and H(J) when recognised.  Numbers to 12
 * significant digits, 0 at and below 1e-12 in size (qd_buf_put_result,
 * scale 1).  JSON: one object and a newline, "separation", "energy",
 * "coordinates" (each "coordinate", "constant", "value", "kind",
 * "turning_points" or "range", "J", "omega", "angle"), "actions",
 * "frequencies" and "angles" (coordinate name to number), "degeneracies"
 * (each "coordinates" and "ratio" [num, den]) and "H_of_J" (null, or
 * "form" and for Kepler's "c"), numbers to 17 digits.  QD_ERR_ARG for an
 * inconsistent a, QD_ERR_NUMERIC (nothing appended) for a JSON number that
 * is not finite, QD_ERR_NOMEM when out could not grow. */
QD_API qd_status qd_action_print(qd_ctx *ctx, const qd_action *a, bool json, qd_buf *out);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_action_at (opts); qd_action_of_sep
 * (opts). An array whose count is 0 may be NULL. */
#endif
