/*
 * qdot/modes.h - small oscillations: the linearization of Lagrange's
 * equations about a state and its eigen-analysis.
 *
 * About a point q0 at rest (q' = 0; an equilibrium, or a steady motion
 * written in coordinates where it is at rest), with x = q - q0,
 *
 *     M0 x'' + (C0 + G0) x' + K0 x = 0,
 *
 *   M0 = M(q0)                  the mass matrix (d^2 T2 / dq'_j dq'_k),
 *   C0 = d^2 D / dq'_j dq'_k    symmetric damping, from Rayleigh's D,
 *   G0 = skew part of d/dq'_k (-f_j) at rest: gyroscopic, from T1 and from
 *        the velocity-linear part of U (G0_jk = d(dL1/dq'_j)/dq_k -
 *        d(dL1/dq'_k)/dq_j with L1 the velocity-linear part of L),
 *   K0 = -df_j/dq_k at rest     the Hessian of V - T0 (+ the velocity-free
 *        part of U) minus dQ_j/dq_k.
 *
 * Every entry is an exact symbolic second derivative evaluated at the point:
 * with q' = 0, f_j(q, 0) is the generalized force at rest, so K0 = -df/dq
 * and C0 + G0 = -df/dq' (its symmetric and skew parts).  The symmetric part
 * of -df/dq' is C0 and its skew part G0 (for a Lagrangian system the
 * symmetric part comes only from D, up to a term vanishing at rest).
 */
#ifndef QDOT_MODES_H
#define QDOT_MODES_H

#include <stdbool.h>
#include <stddef.h>
#include "equilibria.h"
#include "expr.h"
#include "mech.h"
#include "model.h"

#ifdef __cplusplus
extern "C" {
#endif

struct qd_speeds_eom;    /* qdot/speeds.h */
struct qd_symmetry;      /* qdot/symmetry.h */
struct qd_cyclic_modes;  /* qdot/symmetry.h */
struct qd_linpoint;      /* qdot/linpoint.h */

/* The linearization about a state: M q'' + (C + G) q' + K q = 0 (n*n
 * row-major numbers each, malloc'd; qd_linear_free). */
typedef struct qd_linear {
    size_t n;
    double *M, *C, *G, *K;
} qd_linear;

/* The eigen-analysis of a qd_linear.
 *
 * Conservative (C = 0 and G = 0, to 1e-12 relative): K a = w^2 M a solved by
 * LAPACK dsygvd; omega2 ascending, shapes column j = mode j with
 * a^T M a = 1.  w^2 < 0 is an unstable direction.
 *
 * Otherwise the 2n eigenvalues s of the state-space system
 *     [0 I; -M^-1 K  -M^-1 (C + G)]
 * (dgeev; dggev on the pencil when M is ill-conditioned).  omega2 and shapes
 * are NULL then.  The state-space eigenvalues are filled in both cases
 * (conservative: s = +-i w for w^2 >= 0, +-sqrt(-w^2) for w^2 < 0).
 *
 * stable: 1 when every motion stays bounded (conservative: every w^2 > 0;
 * otherwise every Re s < 0, or Re s = 0 only on simple purely imaginary
 * pairs of an undamped gyroscopic system), 0 when some motion grows
 * exponentially (w^2 < 0, Re s > 0), -1 borderline: zero-frequency modes
 * (w^2 = 0: the linear motion may drift), or repeated roots on the
 * imaginary axis of a non-conservative system. */
typedef struct qd_modes_result {
    size_t n;
    bool conservative;     /* C = 0, G = 0 and K symmetric */
    double *omega2;        /* n, ascending (conservative case), w^2 < 0 unstable */
    double *shapes;        /* n*n, column j = mode j, a^T M a = 1 (row-major: shapes[i*n+j]) */
    size_t neig;           /* 2n */
    double *eig_re, *eig_im; /* state-space eigenvalues, sorted by Re descending then Im */
    int stable;            /* 1 stable, 0 unstable, -1 borderline */
} qd_modes_result;

/* Relative size under which a w^2 (against the largest |w^2|) or a real
 * part (against the largest |s|) counts as zero. */
#define QD_MODES_ZERO_TOL 1e-9

/* Linearize e (from qd_eom_derive on m) about the state syms/vals (as for
 * qd_eom_eval: coordinates, t and parameters; velocities are taken as 0
 * whatever vals says).  Models with constraints (multipliers) are
 * QD_ERR_ARG here: qd_constrained_linear_about (qdot/constrained.h) reduces
 * them onto the constraint manifold.
 * The symbolic derivatives are computed once per e and kept in a cache
 * private to this call (each call recomputes them: cheap for small n). */
QD_API qd_status qd_linear_about(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t nvals,
                          const qd_expr *const *syms, const double *vals, qd_linear *out);

/* Eigen-analysis of lin (see qd_modes_result).  QD_ERR_SINGULAR when M is
 * not positive definite, QD_ERR_NUMERIC when LAPACK fails. */
QD_API qd_status qd_modes_solve(qd_ctx *ctx, const qd_linear *lin, qd_modes_result *out);

QD_API void qd_linear_free(qd_linear *l);
QD_API void qd_modes_result_free(qd_modes_result *r);

/* Relative distance (against the largest |w^2|) under which two w^2 of a
 * conservative result are one repeated eigenvalue: LAPACK's symmetric
 * solver returns a k-fold w^2 as k values that differ by round-off (the
 * ring of three masses: 3k/2m twice, 0 three times). */
#define QD_MODES_REPEAT_TOL 1e-7

/* The multiplicity of mode j's w^2: how many of r->omega2 (j included)
 * are the same eigenvalue; their shapes span its eigenspace (one
 * M-orthonormal basis of it, not unique).  0 for j out of range or a
 * result that is not conservative. */
QD_API size_t qd_modes_multiplicity(const qd_modes_result *r, size_t j);

/* The symbolic stiffness and mass matrices at a point given symbolically:
 * K_jk = -df_j/dq_k and M_jk with q = q0[j] (expressions, e.g. 0 or pi) and
 * q' = 0, each simplified; parameters stay symbols.  Kout, Mout: n*n. */
QD_API qd_status qd_linear_symbolic(qd_ctx *ctx, const qd_eom *e, const qd_expr *const *q0,
                             const qd_expr **Kout, const qd_expr **Mout);

/* For n = 1 or 2: the roots w^2 of det(K - w^2 M) = 0 as expressions in
 * the parameters (n = 2: the quadratic's two roots, the one with the minus
 * sign of the square root first), simplified.  QD_ERR_ARG for n > 2. */
QD_API qd_status qd_modes_symbolic_omega2(qd_ctx *ctx, size_t n, const qd_expr *const *K,
                                   const qd_expr *const *M, const qd_expr **w2);

/* The exact w^2 of the n = 1 or 2 modes about an exact point q0 (an
 * equilibrium's exact values): in the parameters (*in_params true) when q0
 * is an equilibrium whatever their values
 * (qd_equilibrium_exact_in_parameters), else exact numbers with every
 * parameter at its exact value.  syms/vals: the parameters' values, for
 * that test.  QD_ERR_ARG for n > 2 or q0 NULL. */
/* The normal coordinates of the state q, q' (n each) about q0 for a
 * conservative result r of lin: Q_j = a_j^T M0 (q - q0) and
 * Q_j' = a_j^T M0 q', so that q = q0 + sum_j a_j Q_j with each
 * Q_j'' + w_j^2 Q_j = 0.  QD_ERR_ARG when r is not conservative. */
QD_API qd_status qd_modes_normal_coords(const qd_linear *lin, const qd_modes_result *r,
                                        const double *q0, const double *q, const double *qd,
                                        double *Q, double *Qd);

/* The frequencies, ascending, into w (room for r->neig): w = sqrt(w^2) of
 * every mode with w^2 >= 0 (conservative), else the positive imaginary
 * parts of the state-space eigenvalues.  Returns how many. */
QD_API size_t qd_modes_frequencies(const qd_modes_result *r, double *w);

QD_API qd_status qd_modes_exact_omega2(qd_ctx *ctx, const qd_eom *e, const qd_model *m,
                                       size_t nvals, const qd_expr *const *syms,
                                       const double *vals, const qd_expr *const *q0,
                                       const qd_expr **w2, bool *in_params);

/* ---- the modes about a point, as `qdot modes` takes them (src/linear/modes_at.c)
 * Step 1 chooses the point, step 2 linearizes and solves there; a model that
 * keeps constraints takes step 1 only (its modes are on the manifold:
 * qdot/constrained.h).  syms/vals: the model's state at rest (coordinates,
 * velocities 0, t, parameters at their values), as for qd_linear_about. */
typedef struct qd_modes_at {
    double *q0;                   /* e->n: the point */
    const qd_equilibrium *pt;     /* the equilibrium q0 is (in choice), or NULL: given */
    bool chosen;                  /* pt is qd_equilibria_choose's (choice.reason) */
    qd_equilibrium_choice choice; /* the automatic choice, or the list (at_equilibrium) */
    double residual;              /* qd_eom_rest_residual at q0 (step 2) */
    qd_linear lin;                /* the linearization at q0 (step 2) */
    qd_modes_result res;          /* qd_modes_solve of lin (step 2) */
    const qd_expr *w2exact[2];    /* exact w^2 with 1 or 2 degrees of freedom about an
                                     exact equilibrium (have_exact) */
    bool have_exact, exact_in_params;
} qd_modes_at;

/* Step 1: q0 is given (e->n values, copied), else equilibrium number
 * at_equilibrium (1-based) of qd_equilibria_find's list, else (0) the one
 * qd_equilibria_choose takes.  QD_ERR_NUMERIC "no equilibrium found" when
 * there is none to take; QD_ERR_ARG for at_equilibrium past the list.  Free
 * with qd_modes_at_free (also after a failure). */
QD_API qd_status qd_modes_at_point(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t nvals,
                                   const qd_expr *const *syms, const double *vals,
                                   const double *given, size_t at_equilibrium, qd_modes_at *out);
/* Step 2: at the point of step 1 (its coordinates put into a copy of vals),
 * the residual, qd_linear_about, qd_modes_solve, and the exact w^2 when the
 * point is an exact equilibrium of 1 or 2 degrees of freedom and the modes
 * are conservative. */
QD_API qd_status qd_modes_at_solve(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t nvals,
                                   const qd_expr *const *syms, const double *vals,
                                   qd_modes_at *at);
QD_API void qd_modes_at_free(qd_modes_at *at); /* NULL is fine */
/* Step 1 from text, as `qdot modes` takes it: about "q1=VALUE, ..." (the
 * unnamed coordinates 0; qd_linpoint_read_coords, its errors located in
 * about), or NULL: qd_modes_at_point at_equilibrium with p's state. */
QD_API qd_status qd_modes_at_choose(qd_ctx *ctx, const struct qd_linpoint *p, const char *about,
                                    size_t at_equilibrium, qd_modes_at *out);
/* After step 2, the motion from initial values: the state read from text
 * "q1=VALUE, q1'=VALUE, ..." (qd_linpoint_read, its errors located in text;
 * the unnamed coordinates at at->q0, velocities 0) in the normal
 * coordinates Q, Qd (e->n each, qd_modes_normal_coords).  QD_ERR_ARG, not
 * located, when at's modes are not conservative. */
QD_API qd_status qd_modes_at_initial(qd_ctx *ctx, const struct qd_linpoint *p,
                                     const qd_modes_at *at, const char *text, double *Q,
                                     double *Qd);

/* ---- the modes printed (src/linear/modes_print.c) ------------------------- */

/* The largest generalized force at rest (qd_eom_rest_residual) a point may
 * leave and still be taken for an equilibrium. */
#define QD_MODES_REST_TOL 1e-8

/* The note on a point that is not an equilibrium, the one `qdot modes`
 * prints and Python's Model.modes warns with: true when residual (the
 * generalized forces at rest there, qd_modes_at.residual) is above
 * QD_MODES_REST_TOL, and then, unless out is NULL, "not an equilibrium: the
 * generalized forces at rest are R there; the linearization drops them"
 * appended to out (no newline).  false, out untouched, otherwise (NaN
 * included: no residual was measured). */
QD_API bool qd_modes_rest_note(double residual, qd_buf *out);

/* The small oscillations about one point, for printing: what `qdot modes`
 * computes.  e, q0, lin and res are required; every other pointer may be
 * NULL (not there). */
typedef struct qd_modes_report {
    const qd_eom *e;                      /* the equations: the coordinates' names */
    const double *q0;                     /* e->n: the point */
    const qd_equilibrium *pt;             /* the equilibrium q0 is (its exact values and
                                             kind), or NULL: a point given */
    const qd_equilibrium_choice *choice;  /* the automatic choice that gave pt, or NULL */
    double residual;                      /* qd_eom_rest_residual at q0 */
    const qd_linear *lin;                 /* the linearization at q0 (n = e->n) */
    const qd_modes_result *res;           /* qd_modes_solve of lin */
    const qd_expr *const *w2exact;        /* res->n exact w^2 (qd_modes_exact_omega2), or
                                             NULL */
    bool w2exact_in_params;               /* ... in the parameters (else exact numbers) */
    const double *Q, *Qd;                 /* n: the normal coordinates at t = 0
                                             (qd_modes_normal_coords), or NULL */
    const struct qd_symmetry *sym;        /* reduced (qd_symmetry_reduce): the labelled
                                             modes replace the plain ones; or NULL */
    const struct qd_cyclic_modes *cyc;    /* the cyclic fast path's modes instead (cyc->n
                                             > 0), or NULL */
} qd_modes_report;

/* r appended to out, as text or (json) as one JSON document with a final
 * newline.
 *
 * Text: "equilibrium: q1 = VALUE, ... (KIND of the potential)" (exact values
 * where pt has them; "about: " and numbers for a point given), a note when
 * qd_modes_rest_note (not an equilibrium), M0, C0 and G0 (when not zero) and
 * K0; then the symmetry's text (qd_symmetry_print / qd_cyclic_print) when
 * sym or cyc is given, else the conservative modes (w^2, w, period,
 * multiplicity, shape; the exact w^2) or the state-space eigenvalues; the
 * motion from the initial values (Q); the verdict "stable", "unstable" or
 * "borderline" with why.  Numbers to 12 significant digits by
 * qd_buf_put_result: matrix entries and w^2 0 at or below 1e-12 (scale 1),
 * a shape's components at or below 1e-12 of its largest (a shape is small
 * as a whole when M0 is large); w, periods and eigenvalues to 10 digits.
 *
 * JSON: "equilibrium" (name to value), "residual", "choice" (with choice:
 * "reason", qd_eq_chosen_name, and "others"), "conservative",
 * "mass_matrix", "damping_matrix", "gyroscopic_matrix", "stiffness_matrix",
 * "symmetry" (with sym or cyc: qd_symmetry_json / qd_cyclic_json),
 * "frequencies" (qd_modes_frequencies), "modes" (conservative: each with
 * "omega2", "omega", "period", "multiplicity", "shape" and, when given,
 * "omega2_exact", "omega2_exact_in_parameters", "Q0", "Q0_dot"; with sym or
 * cyc their labelled modes), "eigenvalues" ([re, im] pairs), "stable" (true,
 * false, null when borderline) and "verdict"; every digit.
 *
 * QD_ERR_ARG when a required field is NULL or lin, res and e disagree on n;
 * QD_ERR_NUMERIC (nothing appended) when a JSON number is not finite;
 * QD_ERR_NOMEM. */
QD_API qd_status qd_modes_print(qd_ctx *ctx, const qd_modes_report *r, bool json, qd_buf *out);

/* ---- scans along a parameter (src/linear/scan.c) ---------------------------
 *
 * Follow an equilibrium as one parameter P goes from a to b and report every
 * value where its stability (qd_modes_result.stable) changes.  The parameter
 * must be one the model reads as a number (not fixed by qd_model_opts, not
 * defined from other parameters); the parameters defined from it follow
 * their definitions at each value.  The equilibrium is found by damped
 * Newton at each of steps + 1 evenly spaced values, continued from the
 * previous one; when `about` is given (n expressions in the parameters, such
 * as x = 1/2 - mu for L4 of the restricted three-body problem) the start is
 * about(a) and each step is predicted by about(P) - about(P_prev).  A step
 * whose Newton iteration fails is halved, down to 1e-6 of the interval,
 * before the equilibrium counts as lost (QD_ERR_NUMERIC, with the last value
 * reached and the one that failed).  Between two samples whose verdicts
 * differ the change is located by bisection on the verdict itself (each
 * midpoint's equilibrium by Newton, its eigenvalues by qd_modes_solve) to a
 * bracket of width tol.  Two changes between the same two samples are not
 * seen: more steps separate them. */
typedef struct qd_scan_opts {
    size_t steps;                 /* intervals between samples; 0 gives 200 */
    double tol;                   /* bracket width of each transition; 0 gives
                                     1e-13 max(1, |a|, |b|) */
    const qd_expr *const *about;  /* n expressions in the parameters, or NULL */
    const double *start;          /* n: the equilibrium's guess at a when about
                                     is NULL; both NULL: qd_equilibria_choose at a */
} qd_scan_opts;

typedef struct qd_scan_transition {
    double value;                 /* the middle of the final bracket */
    double lo, hi;                /* the bracket: verdict `from` at lo, `to` at hi */
    int from, to;                 /* 1 stable, 0 unstable, -1 borderline */
} qd_scan_transition;

typedef struct qd_scan {
    size_t n;                     /* numbers per point: the coordinates (e->n), or
                                     for a steady motion (qd_stability_scan) kept
                                     coordinates, rates and momenta */
    size_t count;                 /* samples */
    double *value;                /* count: the parameter, a to b */
    double *q;                    /* count * n: the point at each value */
    int *stable;                  /* count: qd_modes_result.stable there */
    double *margin;               /* count: the smallest w^2 (conservative) or the
                                     largest Re s: its sign is the verdict's */
    bool *conservative;           /* count */
    bool damped;                  /* qd_stability_scan: the roots judged were the damped
                                     ones (the model's dissipation acts) at some sample */
    size_t ntrans;
    qd_scan_transition *trans;    /* ntrans, in the order of P */
} qd_scan;

/* Scan e (derived from m, no multipliers) along the parameter named param
 * from a to b (a < b).  QD_ERR_ARG (message naming it) for an unknown
 * parameter, a fixed one, one defined from others, a >= b, a range that
 * leaves a parameter assumed positive (its value positive when the model
 * was read); QD_ERR_NUMERIC when no equilibrium is found at a or it is lost
 * on the way.  Free with qd_scan_free (also after a failure). */
QD_API qd_status qd_modes_scan(qd_ctx *ctx, const qd_eom *e, const qd_model *m,
                               const char *param, double a, double b,
                               const qd_scan_opts *opts, qd_scan *out);
QD_API void qd_scan_free(qd_scan *s);

/* How a scan is written (qd_scan_print, qd_scan_json): the parameter's
 * name, a name for each number of a point (sc->n), what was followed (a
 * phrase for the text's head: "the equilibrium from x = 1/2 - mu") and the
 * JSON key of a point ("equilibrium", "steady_motion"). */
typedef struct qd_scan_view {
    const char *param;
    const char *const *names;
    const char *followed;
    const char *key;
} qd_scan_view;
/* sc (count >= 1) appended to out for a reader: a head, a table of the
 * parameter, the point and the margin ("min w^2" when every sample is
 * conservative, else "max Re s") with the verdict, and each transition
 * ("transition: mu = 0.0385208965, stable -> unstable"), computed results by
 * qd_result_format; or as one JSON document and a newline: "parameter",
 * "range", "steps", "samples" (each {PARAM, KEY: {name: value},
 * "min_omega2" or "max_re_s", "stable" (true, false, null for borderline),
 * "verdict"}), "transitions" (each {PARAM, "from", "to", "bracket"}).
 * QD_ERR_NOMEM when out could not grow, QD_ERR_ARG for a number JSON cannot
 * hold or an empty scan. */
QD_API qd_status qd_scan_print(const qd_scan_view *v, const qd_scan *sc, qd_buf *out);
QD_API qd_status qd_scan_json(const qd_scan_view *v, const qd_scan *sc, qd_buf *out);

/* What `qdot modes --scan NAME=A:B [--about ...] [--steps N]` writes, for
 * the equations and state of p (qdot/linpoint.h): range "NAME=A:B" read by
 * qd_state_named_range, about (NULL: the equilibrium qd_equilibria_choose
 * takes at A) by qd_linpoint_read_exact (kept in the parameters, evaluated
 * at each value), steps as qd_scan_opts.steps; then qd_modes_scan and the
 * scan appended to out (qd_scan_print, or qd_scan_json when json).  An
 * error in reading range or about is located in that text and *where (may
 * be NULL) set to it, else *where is NULL (the scan's errors: QD_ERR_ARG
 * for the parameter, QD_ERR_NUMERIC for an equilibrium lost). */
QD_API qd_status qd_modes_scan_text(qd_ctx *ctx, const struct qd_linpoint *p, const char *range,
                                    const char *about, size_t steps, bool json, qd_buf *out,
                                    const char **where);

/* ---- models in generalized speeds (src/linear/speeds_lin.c) ----------------
 *
 * The first-order system y = (q, u) of qd_speeds_derive, q' = kin(q, u, t),
 * M_u u' = f_u, linearized about a state: y' = rate + A (y - y0).  Only the
 * coordinates the dynamics needs are kept: q_j is kept when f_u or M_u
 * involves it, or the kinematic row of another kept coordinate does; the
 * others (ignorable: the contact point and heading of a rolling disk) do
 * not act back, so the kept coordinates and the speeds are a closed
 * reduced system and a steady motion of the full one (the disk rolling
 * upright along a line) is a stationary point of it: rate = 0.  The
 * derivatives are exact (symbolic), evaluated at the state. */
typedef struct qd_speeds_linear {
    size_t n, m;          /* coordinates of e, speeds */
    size_t nkept;         /* coordinates in the reduced system */
    size_t *kept;         /* nkept indices into e->q, ascending */
    bool *ignorable;      /* n: dropped */
    size_t dim;           /* nkept + m: y = (q[kept], u) */
    double *A;            /* dim*dim row-major: d(q'[kept], u')/d(q[kept], u) */
    double *rate;         /* dim: (q'[kept], u') at the state, 0 when stationary */
} qd_speeds_linear;

/* Linearize e about the state syms/vals (coordinates, speeds, t,
 * parameters; symbols not given are 0).  QD_ERR_SINGULAR when M_u is
 * singular there. */
QD_API qd_status qd_speeds_linear_about(qd_ctx *ctx, const struct qd_speeds_eom *e, size_t nvals,
                                        const qd_expr *const *syms, const double *vals,
                                        qd_speeds_linear *out);
QD_API void qd_speeds_linear_free(qd_speeds_linear *l);

/* The eigenvalues s of lin->A (dgeev) into out: n = neig = lin->dim,
 * sorted as for qd_modes_solve, conservative false, omega2 and shapes NULL.
 * stable: 0 when some Re s > 0 (relative QD_MODES_ZERO_TOL); 1 when every
 * Re s <= 0, the zero eigenvalues are semisimple (as many null vectors of A
 * as zeros: neighbouring steady motions, which a nonholonomic system has in
 * families, do not drift apart linearly) and no purely imaginary root
 * repeats; -1 otherwise (borderline). */
QD_API qd_status qd_speeds_modes_solve(qd_ctx *ctx, const qd_speeds_linear *lin,
                                       qd_modes_result *out);

/* Follow the verdict of qd_speeds_modes_solve as one value of the state
 * syms/vals goes from a to b (a < b), the others fixed: a parameter (the
 * gravity under a rolling disk), or a speed or coordinate of a family of
 * steady motions (the disk's spin).  opts: steps and tol as for
 * qd_modes_scan (about and start are not read).  out: n = 0 (no point is
 * followed), margin the largest Re s, conservative false; transitions
 * bisected on the verdict to a bracket of width tol.  QD_ERR_ARG when what
 * is not among syms or a >= b.  Free with qd_scan_free (also after a
 * failure). */
QD_API qd_status qd_speeds_modes_scan(qd_ctx *ctx, const struct qd_speeds_eom *e, size_t nvals,
                                      const qd_expr *const *syms, const double *vals,
                                      const qd_expr *what, double a, double b,
                                      const qd_scan_opts *opts, qd_scan *out);

/* What `qdot modes --scan NAME=A:B` writes for a model with `speeds`, at
 * the state syms/vals (the model's, its speeds appended, with --about's
 * values or at the first equilibrium): range "NAME=A:B" read by
 * qd_state_named_range, NAME a parameter, coordinate or speed among syms
 * (not t; QD_ERR_ARG naming it otherwise); qd_speeds_modes_scan with steps;
 * the scan appended to out (qd_scan_print, or qd_scan_json when json), its
 * head naming about (the text the state was given by, or NULL: the first
 * equilibrium).  An error about range has *where (may be NULL) set to it
 * (located in it when the reader's), else NULL. */
QD_API qd_status qd_speeds_modes_scan_text(qd_ctx *ctx, const struct qd_speeds_eom *e,
                                           size_t nvals, const qd_expr *const *syms,
                                           const double *vals, const char *range,
                                           const char *about, size_t steps, bool json,
                                           qd_buf *out, const char **where);

/* ---- printed (src/linear/speeds_print.c) --------------------------------- */

/* The modes of e about the state syms/vals (the one lin was linearized
 * about: qd_speeds_linear_about, qd_speeds_modes_solve gave res) appended
 * to out.  Text: the state (every coordinate and speed of e, in the digit
 * rule of qd_buf_put_result; a value syms lacks is nan), the reduced
 * system and the ignorable coordinates dropped, a note when the state is
 * not stationary (|y'| > 1e-8), the eigenvalues s to 10 digits (a part
 * below 1e-12 of the largest |s| as 0) with the frequency of each Im s > 0,
 * and the verdict in words.  JSON: "state" {name: value}, "kept",
 * "ignorable", "eigenvalues" ([re, im] pairs, every digit), "verdict"
 * ("stable", "unstable" or "borderline") and "stable" (true, false, or null
 * when borderline), ending with a newline.  QD_ERR_ARG when lin is not of
 * e, QD_ERR_NUMERIC (nothing appended) for a JSON number that is not
 * finite (a state value missing), QD_ERR_NOMEM. */
QD_API qd_status qd_speeds_modes_print(qd_ctx *ctx, const struct qd_speeds_eom *e, size_t nvals,
                                       const qd_expr *const *syms, const double *vals,
                                       const qd_speeds_linear *lin, const qd_modes_result *res,
                                       bool json, qd_buf *out);

/* ---- the mode shapes drawn (src/linear/modes_plot.c) ----------------------
 *
 * A conservative result's modes as a picture.  A model with particles (at
 * most QD_MODES_PLOT_MAXP of them, and at most QD_MODES_PLOT_MAXPANELS
 * modes): a panel per mode (at most 3 to a row, 2 x 2 for four), each with
 * the particles at the equilibrium ("equilibrium") and at q0 + s a_j ("mode
 * shape"), headed "mode J: omega = W rad/s" or "mode J: unstable, omega^2 =
 * W2" (4 significant digits),
 * s scaling the linear displacement so its largest component (along x, y or
 * z, over the particles) is a fifth of the configuration's size (its
 * largest extent along x, y or z; 1 when all particles are at one point;
 * the displacement per unit s is a forward difference of the positions
 * with a step 1e-6 of the size along a_j), drawn in the plane of the two
 * axes along which the positions, at rest and moved, spread most, with
 * equal axes, with the springs and rods that join them (qd_modes_link),
 * drawn moved, an arrow from each particle's place at rest to its place in
 * the mode, and a pivot at the origin where a rod reaches it; one legend
 * under the title for the whole picture.  When they all lie on one line (spread across it below 1e-9
 * of the spread along it: a chain of masses and springs), each particle's
 * displacement along the line is drawn against its place at rest ("x" and
 * "displacement along x").  Otherwise (no particles, or too many): one
 * panel with each mode's coordinates a_ij, scaled to a largest |a_ij| of 1,
 * against the coordinate number i.
 */
struct qd_plot;            /* qdot/plot.h */

#define QD_MODES_PLOT_MAXP 64       /* particles drawn at most */
#define QD_MODES_PLOT_MAXPANELS 24  /* modes drawn as particles at most */

#define QD_MODES_PLOT_MAXLINKS 256   /* springs and rods drawn at most */
#define QD_MODES_PLOT_MAXWALLS 16    /* springs to walls drawn at most */

/* What joins two particles in the picture (src/linear/modes_links.c): a
 * spring where V couples a coordinate that moves only particle a with one
 * that moves only b (K0's entry not 0: a distance term of V, such as
 * k/2 (|ra - rb| - L)^2); a rod where their distance is not 0 and no
 * coordinate changes it to first order (a pendulum's links); a to the
 * origin (b == np) is a rod of constant length from a pivot there, or a
 * spring from there where a term of V holds a by its distance from the
 * origin alone (k/2 (r - l0)^2 of a spring pendulum; in a plane).  K0 here
 * is that of V's terms that are not linear in the positions (gravity,
 * m g y, holds a pendulum's bob but is drawn as nothing).  A rod to a
 * pivot elsewhere (b > np, wall_axis 3: the point the particle's own
 * coordinate swings it about, at a distance every coordinate keeps: the
 * second of two pendulums hung side by side).  A
 * spring to a wall (b > np: wall b - np - 1 of the picture's walls) where
 * the configuration can be moved rigidly along an axis by each particle's
 * own coordinates and K0 does not let it (K0 T != 0 on a's coordinate
 * along the axis: something fixed holds a, such as k/2 x1^2 in V); the
 * wall is drawn on a's side of the configuration's middle along the axis,
 * the nearest two particles' distance from a (the configuration's size for
 * one particle): where the wall is the model does not say, only that it is
 * fixed. */
typedef enum qd_modes_link { QD_MODES_SPRING, QD_MODES_ROD } qd_modes_link;
typedef struct qd_modes_link_of {
    size_t a, b;            /* particles, b == np: the pivot at the origin */
    qd_modes_link kind;
} qd_modes_link_of;

/* The numbers of the particle picture. */
typedef struct qd_modes_picture {
    size_t np;          /* particles drawn; 0: the picture shows coordinates */
    size_t nmode;       /* modes (res->n) */
    double *rest;       /* np*3: x, y, z of particle i at the equilibrium (0 where the model
                         * gives fewer); NULL when np is 0 */
    double *moved;      /* nmode*np*3: particle i in mode j at moved[(j*np + i)*3 + k] */
    unsigned ax, ay;    /* the plane's axes (0 x, 1 y, 2 z; ax < ay), or ay = 3: the
                         * particles are on the line of axis ax */
    size_t nlinks;      /* the springs and rods found (at most QD_MODES_PLOT_MAXLINKS) */
    qd_modes_link_of links[QD_MODES_PLOT_MAXLINKS];
    bool pivot;         /* a rod reaches the origin: a fixed support drawn there */
    size_t nwalls;      /* the walls springs reach (at most QD_MODES_PLOT_MAXWALLS) */
    double wall[3 * QD_MODES_PLOT_MAXWALLS];  /* wall w's point: x, y, z at 3w */
    unsigned wall_axis[QD_MODES_PLOT_MAXWALLS]; /* its axis (0 x, 1 y, 2 z): the wall is
                                                 * across it; 3: a pivot at the point */
} qd_modes_picture;

/* The particles of m at the equilibrium and moved along each mode of res,
 * and the plane to draw them in (see above), into *out (zeroed first;
 * qd_modes_picture_free).  e: the equations of m whose linearization
 * (qd_linear_about) res solved; syms/vals: the state it was linearized
 * about (coordinates of e at the equilibrium q0, t and parameters, as
 * qd_linear_about takes; velocities are taken as 0).  out->np is 0, with
 * nothing computed, for a model without particles or with more than the
 * picture draws.  QD_ERR_ARG for a result that is not conservative (no
 * real shapes: damping or gyroscopic terms) or whose n is not e->n,
 * QD_ERR_NOMEM, or the failure of compiling the particles' positions; the
 * reason in ctx. */
QD_API qd_status qd_modes_picture_make(qd_ctx *ctx, const qd_eom *e, const qd_model *m,
                                       size_t nvals, const qd_expr *const *syms,
                                       const double *vals, const qd_modes_result *res,
                                       qd_modes_picture *out);
QD_API void qd_modes_picture_free(qd_modes_picture *pic);

/* The picture of the modes of res (see above) with title title, as a new
 * plot in *out (qd_plot_write writes it; qd_plot_free).  Arguments as
 * qd_modes_picture_make's; *out is NULL after a failure: those of
 * qd_modes_picture_make, and of the plot's construction. */
QD_API qd_status qd_modes_plot(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t nvals,
                               const qd_expr *const *syms, const double *vals,
                               const qd_modes_result *res, const char *title,
                               struct qd_plot **out);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_modes_scan (opts); qd_modes_at_choose (about);
 * qd_speeds_modes_scan (opts). An array whose count is 0 may be NULL. */
#endif
