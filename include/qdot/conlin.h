/*
 * qdot/conlin.h - linearization of constrained systems: a model whose
 * equations keep multipliers, with holonomic constraints phi(q, t) = 0,
 * velocity (Pfaffian, nonholonomic) constraints a(q, t) q' + a0 = 0 and
 * `rolls` contacts (which are both), about a point of its state manifold.
 *
 * The state is z = (q, q') (2n).  The motion obeys
 *
 *     [M  -A^T] [q''   ]   [f]
 *     [A    0 ] [lambda] = [b],      z' = F(z) = (q', q''(z)),
 *
 * (qdot/mech.h) and stays on the manifold C(z) = 0, C = (phi_k for the
 * holonomic constraints; A q' + a0 for every constraint), of dimension
 * nx = 2n - nhol - ncon.  Independent states x (nx of the q_j and q'_j) are
 * the caller's or chosen at the point (below); the others, dependent, are
 * solved there by Newton on C = 0 with the independent held (the Whipple
 * bicycle's pitch from its front contact).  About the point z0, on the
 * manifold, z = z0 + T dx + O(dx^2) with T = dz/dx = [I; -C_D^-1 C_I] in
 * the rows of the independent and dependent states, and
 *
 *     dx' = A dx + B du,     A = P (dF/dz) T,   B = P dF/du,
 *
 * P the rows of the independent states.  dF/dz comes from the Jacobians of
 * the compiled M, f, A, b (qdot/tangent.h, forward mode: exact to
 * round-off, never a symbolic expansion), through
 * d(q'', lambda) = K^-1 ([df; db] - dK (q'', lambda)), K the saddle-point
 * matrix above; C's Jacobian the same way.
 *
 * The choice of states, when the caller gives none: the dependent
 * coordinates are the pivots of a column-pivoted Gram-Schmidt of
 * d phi/dq; the dependent velocities are those of the dependent
 * coordinates, then pivots of the velocity constraints' coefficients A,
 * taken first among the velocities of coordinates that occur in neither M
 * nor f (a contact point, a heading, a wheel's angle), then the others,
 * and last those the point gives a value other than 0 or the model's
 * `speeds` define (u2 = q2': a model in speeds keeps them independent):
 * shape velocities
 * (lean and steer rates) and the rates the caller set (a wheel's spin)
 * stay independent where they can.  A dependent state the point gave
 * another value is solved all the same: qd_conlin_print names it.
 *
 * A state no other non-ignorable state's rate depends on (its column of
 * A, in the rows not yet ignorable, below 1e-13 of A's largest entry,
 * repeated until none is left; the contact point, the heading, a wheel's
 * angle) is ignorable: those entries are rounding of exact zeros (the
 * heading's column in the lean row is 5e-15 for the bicycle) and are set to
 * 0, so each ignorable state gives an eigenvalue exactly 0
 * (det(sI - A) = s det of A without that row and column) and the others,
 * the core, decide stability (qd_conlin.stable, .marginal).  The point need
 * not be an equilibrium: an ignorable state may move (the bicycle's run at
 * speed v); x' at the point is reported (qd_statespace.xdot0).
 *
 * Outputs y = h(q, q', u, t) (the model's `outputs`): along the manifold
 * dy = (dh/dz) T dx + (dh/du) du, so C = (dh/dz) T and D = dh/du, from the
 * forward-mode Jacobian of the compiled h (a dependent coordinate as an
 * output moves with the independent ones: the pendulum's height q1 =
 * sqrt(L^2 - q2^2) gives C = -q2/q1 in q2).
 */
#ifndef QDOT_CONLIN_H
#define QDOT_CONLIN_H

#include <stdbool.h>
#include <stddef.h>
#include "equilibria.h"
#include "linpoint.h"
#include "mech.h"
#include "model.h"
#include "statespace.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct qd_conlin {
    size_t n, nhol, ncon;   /* e's coordinates, holonomic constraints, all constraints */
    size_t nx;              /* 2n - nhol - ncon independent states */
    size_t *indep;          /* nx indices into z = (q, q'), ascending */
    size_t *dep;            /* nhol + ncon indices into z, ascending */
    const qd_expr **zsym;   /* 2n: the states' symbols, q_j then q'_j */
    double *z;              /* 2n: the point, on the manifold */
    double *given;          /* 2n: the point as given, before Newton */
    double moved;           /* max |z - z_given| over the dependent states */
    double residual;        /* max |C(z)| after Newton */
    bool *ignorable;        /* nx */
    size_t ncore;           /* the states not ignorable */
    double *core_re, *core_im; /* ncore: the core's eigenvalues, sorted as ss's */
    double *lambda;         /* ncon: the multipliers at the point (e->con's order) */
    const qd_expr **lambda_sym; /* ncon: their symbols (lambda_NAME) */
    double margin;          /* the core's largest Re s (-inf without a core) */
    double tol;             /* QD_CONLIN_MARGIN_TOL times the core's largest |s| (and 1) */
    bool steady;            /* x' vanishes in every core state (to 1e-9 of the point's
                               scale): a steady motion, which the verdict is about */
    bool stable;            /* steady and margin <= tol: no core eigenvalue has Re s > 0 */
    bool marginal;          /* stable with margin >= -tol: eigenvalues on the imaginary
                               axis (a conservative core, a family of steady motions) */
    qd_statespace ss;       /* A, B over the independent states (ss.states: q_j, q'_j),
                               C, D of m's outputs (dy/dz T, dy/du), their eigenvalues,
                               controllability and observability */
} qd_conlin;

/* Round-off puts the imaginary pairs of a conservative core at Re s ~ 1e-16:
 * a core eigenvalue counts as unstable above this fraction of the core's
 * largest |s| (the verdict, the scan's crossings). */
#define QD_CONLIN_MARGIN_TOL 1e-10

/* The linearization of e (derived from m, with constraints) about the
 * point pt->st (its coordinates and velocities; t, the parameters at their
 * values; m's inputs at 0).  independent: "x, q2, q5'" (coordinates and
 * velocities of e, n - nhol and n - ncon of them, by commas or spaces; or
 * the n - nhol coordinates alone, the velocities then chosen), or NULL to
 * choose.  QD_ERR_ARG, located in independent, for a name that is
 * no coordinate or velocity of e, a count other than those, or a choice
 * whose dependent states the constraints do not determine there (the
 * message says which); QD_ERR_ARG when Newton does not reach the manifold
 * (the residual named); QD_ERR_UNSUPPORTED for a model without
 * constraints (qd_linearize);
 * QD_ERR_SINGULAR when K is singular at the point; QD_ERR_NUMERIC for a
 * value that is not finite there.  Free with qd_conlin_free (also after a
 * failure). */
QD_API qd_status qd_conlin_about(qd_ctx *ctx, const qd_eom *e, const qd_model *m,
                                 const qd_linpoint *pt, const char *independent,
                                 qd_conlin *out);
QD_API void qd_conlin_free(qd_conlin *c);

/* c->ss replaced by the state-space form over the core states alone (A's
 * rows and columns and B's rows of the states not ignorable), analysed
 * again: what an LQR design takes, the ignorable states' zero modes being
 * out of every input's reach and acting on nothing (`linearize --lqr`).
 * The notes (qd_conlin_print) still name every state.  QD_ERR_NOMEM, the
 * errors of the analysis (c unchanged then). */
QD_API qd_status qd_conlin_keep_core(qd_ctx *ctx, qd_conlin *c);

/* pt->st's coordinates and velocities from m's `initial` (a speed defined
 * as one velocity, `speeds u3 = q3'`, gives that velocity its initial
 * value), then from about ("q=V, q'=V", NULL: none; qd_state_read, errors
 * located in about).  QD_ERR_ARG for about naming t, a parameter or an
 * input; QD_ERR_UNSUPPORTED, without about, for a speed with an initial
 * value that is not one velocity (u = r*pr': give the velocities). */
QD_API qd_status qd_conlin_point(qd_ctx *ctx, const qd_model *m, qd_linpoint *pt,
                                 const char *about);

/* The point a command linearizes about (src/linear/conlin_start.c):
 * qd_conlin_point's, except that without about, for equations that keep
 * holonomic constraints alone (qd_conlin_needed false: a system at rest on
 * them, like a pendulum in x and y), the equilibrium on the constraints
 * qd_equilibria_choose takes from that state (the velocities 0): what
 * `qdot modes` takes, so both agree.  choice is filled then (choice->pt
 * the point; say which with qd_equilibrium_choice_note), else left empty.
 * QD_ERR_NUMERIC when no equilibrium is found ("give a point with
 * --about"), and the errors of qd_conlin_point and of the search.  Free
 * choice with qd_equilibrium_choice_free (also after a failure). */
QD_API qd_status qd_conlin_start(qd_ctx *ctx, const qd_eom *e, const qd_model *m,
                                 qd_linpoint *pt, const char *about,
                                 qd_equilibrium_choice *choice);

/* `qdot stability --ignore q1, x, y` on the manifold: each coordinate
 * named (commas or spaces) is independent and ignorable in c, its
 * steady motion's cyclic coordinate (src/linear/conlin_start.c).
 * QD_ERR_ARG located at the first that is no coordinate of the
 * equations, a dependent one, or not ignorable (another rate depends on
 * it), and for a list of none. */
QD_API qd_status qd_conlin_require_ignorable(qd_ctx *ctx, const qd_conlin *c,
                                             const char *names);

/* ---- along a parameter (src/linear/conlin_scan.c) ------------------------ */

typedef struct qd_conlin_cross {
    double at;              /* the parameter's value */
    double omega;           /* |Im s| of the eigenvalues that cross there (0: a real one) */
    bool to_stable;         /* no core eigenvalue has Re s > 0 above it */
    bool marginal;          /* on the stable side the largest Re s is 0 (to the tolerance):
                               eigenvalues on the imaginary axis (a conservative core) */
} qd_conlin_cross;

typedef struct qd_conlin_scan {
    size_t nsamples, nx;
    double *p;              /* nsamples: the parameter's values */
    double *re, *im;        /* nsamples * nx: the eigenvalues at each (as qd_conlin's ss) */
    double *margin;         /* nsamples: the largest Re s of the core */
    bool *unstable;         /* nsamples: margin above 1e-10 of the core's largest |s| */
    size_t ncross;
    qd_conlin_cross *cross; /* where margin changes sign, in order of p */
    bool nudged;            /* the parameter is assumed positive and the range starts at 0:
                               the first sample is at a + 1e-6 (b - a) instead */
} qd_conlin_scan;

/* The linearization at steps + 1 values of the parameter name from a to b
 * (m's parameter set each time with qd_model_set_param, so the `initial`
 * point follows it; about and independent as for qd_conlin_point and
 * qd_conlin_about, pt refilled), and each value between two samples where
 * the core turns unstable or back (its margin through 1e-10 of its
 * largest |s|), bisected to 1e-10 of the samples' spacing (on the sign of
 * the margin itself when the stable side is inside the left half-plane).  A parameter the
 * model assumes positive (qd_symbol_is_positive: its value was when the
 * model was read) starts just above a = 0 (out->nudged) and refuses a < 0.  m's parameter is
 * given back its value.  QD_ERR_ARG for an unknown parameter, a >= b,
 * steps 0 or above 100000, and the errors of qd_conlin_about at a sample
 * (the message says at which value).  Free with qd_conlin_scan_free. */
QD_API qd_status qd_conlin_scan_run(qd_ctx *ctx, const qd_eom *e, qd_model *m,
                                    qd_linpoint *pt, const char *about,
                                    const char *independent, const char *name, double a,
                                    double b, size_t steps, qd_conlin_scan *out);
QD_API void qd_conlin_scan_free(qd_conlin_scan *s);

/* ---- printed (src/linear/conlin_print.c) --------------------------------- */

/* What precedes the state-space form on the manifold: text "on the
 * manifold of N constraints (K holonomic): independent ...; dependent
 * ...", "point: NAME = V, ..." (every coordinate and velocity, the
 * dependent ones solved), "solved from the constraints: NAME = V (was W),
 * ..." for the dependent states Newton changed (when any), "ignorable:
 * ..." (or none), the core's eigenvalues and "multipliers: lambda_NAME =
 * V, ..." (with constraints), each a line;
 * JSON one object: "independent", "dependent", "ignorable" (names),
 * "point" (object), "core_eigenvalues" ([re, im] pairs), "multipliers"
 * ({lambda_NAME: V}), "stable", "marginal" (c's) and "verdict" ("stable",
 * "marginally stable", "unstable").  QD_ERR_NUMERIC for a number JSON
 * cannot hold, QD_ERR_NOMEM (out unchanged). */
QD_API qd_status qd_conlin_print(const qd_conlin *c, bool json, qd_buf *out);

/* c's notes (above) and its state-space form (qd_statespace_render of
 * c->ss, with the design lqr or NULL) in format fmt: text, the notes'
 * lines, the form's, then the verdict line (qd_conlin_modes_print's); JSON
 * one object with the notes' members and the form's (the keys of
 * `linearize` without constraints: "states", "A", "B", "C", "D",
 * "eigenvalues", ...); C, SymPy and Octave the form's alone.  The errors of
 * qd_statespace_render (out unchanged). */
QD_API qd_status qd_conlin_render(qd_ctx *ctx, const qd_conlin *c,
                                  const struct qd_care_result *lqr, qd_ss_format fmt,
                                  qd_buf *out);

/* `qdot modes` on the manifold: the notes of qd_conlin_print, then (text)
 * the eigenvalues of A a line each ("s = RE +- IM i", with w = Im s for
 * Im s > 0) and the verdict line, the same as qd_conlin_render's: "verdict:
 * stable", "marginally stable" (the core's largest Re s within c->tol of
 * 0: the linearization does not decide) or "unstable", with that Re s;
 * JSON one object: the notes' members (their "stable", "marginal",
 * "verdict"), "states" and "eigenvalues" ([re, im] pairs, as in
 * qd_statespace_render), then a newline.  QD_ERR_NUMERIC for a number JSON
 * cannot hold, QD_ERR_NOMEM (out unchanged; recorded in ctx). */
QD_API qd_status qd_conlin_modes_print(qd_ctx *ctx, const qd_conlin *c, bool json,
                                       qd_buf *out);

/* Whether e needs qd_conlin_about rather than the holonomic reduction of
 * qdot/constrained.h: it keeps a velocity constraint (Pfaffian,
 * nonholonomic, or a `rolls` contact). */
QD_API bool qd_conlin_needed(const qd_eom *e);

/* The scan: text, a table "NAME  max Re s (core)  eigenvalues" a sample a
 * line, then a line per crossing ("NAME = V: stable above; a complex
 * pair crosses the imaginary axis at s = +-W i", "... a real eigenvalue
 * crosses 0", or, marginally stable above, "a real pair meets at s = 0 and
 * turns imaginary");
 * JSON {"parameter", "starts_above_zero", "samples": [{"value", "margin",
 * "eigenvalues"}], "crossings": [{"value", "omega", "to_stable",
 * "marginal"}]}.  QD_ERR_NUMERIC for a
 * number JSON cannot hold, QD_ERR_NOMEM (out unchanged). */
QD_API qd_status qd_conlin_scan_print(const qd_conlin_scan *s, const char *name, bool json,
                                      qd_buf *out);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_conlin_about (independent);
 * qd_conlin_point (about); qd_conlin_scan_run (about, independent);
 * qd_conlin_render (lqr). An
 * array whose count is 0 may be NULL. */
#endif
