/*
 * qdot/stability.h - steady motions (relative equilibria) of systems with
 * cyclic coordinates, and their stability.
 *
 * A steady motion keeps the other ("kept", palpable) coordinates x at rest,
 * x = x0, while each cyclic coordinate c turns at a constant rate c' = w_c.
 * Two situations differ (Britannica 1911 "Dynamics" sec. 6, seed 004; Routh):
 *
 *   free      (--ignore c) the momenta p_c = dL/dc' are constant and
 *             free: the kept coordinates move under the Routhian (qdot/routh.h),
 *             V_eff = V + K = R0 (Goldstein sign: R = sum p c' - L), with the
 *             gyroscopic matrix G from R's part linear in x'.
 *   driven    (--driven "c' = Omega") the rate is imposed by an external agency
 *             (a rheonomic constraint): the kept coordinates move under
 *             L(x, x', c' = Omega), V_eff = V - T0, T0 the part of T free of x'.
 *
 * Both V_eff have the same gradient (dT0/dx = -dK/dx at corresponding p and
 * w), so the steady motions are the same: x0 solves f_k(x0, x' = 0, c' = w) = 0
 * for the kept rows of Lagrange's equations M q'' = f with c'' = 0.  Their
 * Hessians differ, and so do the verdicts: circular orbits under -k r^n are
 * stable for n > -3 with free angular momentum, a bead on a wire driven round
 * at the same rate only for n > 1 (reference seed-goldstein-britannica.md,
 * B08/B09 and pitfall P4).
 *
 * About the steady motion the kept equations linearize to
 *     M0 x'' + (C0 + G0) x' + K0 x = 0          (qdot/modes.h's qd_linear)
 * and two stabilities are reported:
 *   ordinary  the roots of det(M0 s^2 + G0 s + K0) = 0 without dissipation:
 *             stable when every root is a simple imaginary pair (gyroscopic
 *             terms can stabilise a maximum of V_eff: the sleeping top);
 *   secular   Thomson and Tait: with dissipation acting on every kept
 *             coordinate the steady motion is stable iff V_eff is a minimum
 *             (Hessian positive definite); any damping destroys gyroscopic
 *             stabilisation.
 * When the model has a dissipation function (or forces) the roots with C0
 * are also given.  Borderline cases (a zero or a double frequency, a
 * semidefinite Hessian) are flagged as such (-1), never classified.
 */
#ifndef QDOT_STABILITY_H
#define QDOT_STABILITY_H

#include <stdbool.h>
#include <stddef.h>
#include "expr.h"
#include "mech.h"
#include "model.h"
#include "modes.h"
#include "print.h"
#include "routh.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The symbolic side, prepared once per model and choice of cyclic
 * coordinates. */
typedef struct qd_steady {
    bool driven;
    size_t nkeep, ncyc;
    const qd_expr **keep, **keepd;  /* kept coordinates and velocities, model order */
    const qd_expr **cyc, **cycd;    /* cyclic (ignored or driven) coordinates, velocities */
    const qd_expr **beta;           /* free: the momentum symbols p_<c>; driven: NULL */
    const qd_expr **mom;            /* ncyc: p_c = dL/dc' at x' = 0, in x, c', parameters, t */
    const qd_expr **res;            /* nkeep: f_k at x' = 0, c'' = 0: zero at a steady motion,
                                       in x, c', parameters, t */
    const qd_expr *Veff;            /* free: R0 in x and beta; driven: V - T0 in x and c' */
    const qd_expr **M, **f;         /* reduced equations M x'' = f in x, x' and beta (free)
                                       or c' (driven); M nkeep*nkeep row-major */
    qd_routh *routh;                /* free: the reduction used; driven: NULL */
} qd_steady;

/* Prepare the steady-motion analysis of model m (derived as e) with the
 * ncyc coordinates cyc ignored (driven false) or driven (driven true).
 * QD_ERR_ARG (NULL, message naming the coordinate) when one is not a
 * coordinate, is repeated, is not cyclic (appears in L, D, the forces) or
 * when every coordinate is listed, and for models with constraints; the
 * errors of qd_routh_derive for the free case. */
QD_API qd_steady *qd_steady_derive(qd_ctx *ctx, const qd_model *m, const qd_eom *e, size_t ncyc,
                            const qd_expr *const *cyc, bool driven);
QD_API void qd_steady_free(qd_steady *s);

/* A steady motion: kept coordinates x (nkeep), rates w (ncyc, c') and
 * momenta p (ncyc). */
typedef struct qd_steady_point {
    double *x, *w, *p;
} qd_steady_point;

/* Find a steady motion.  On entry pt holds the given values and the starting
 * guesses; xfix[j] keeps x_j, wfix[c] keeps w_c, pfix[c] keeps p_c (at most
 * one of wfix, pfix per c).  The rest are unknowns, solved by Gauss-Newton
 * (Levenberg-Marquardt damped) on the kept residuals and the given momenta:
 * there must be no more unknowns than equations (QD_ERR_ARG, saying what to
 * give).  nvals/syms/vals give the parameters and t (other symbols in syms
 * are ignored).  QD_ERR_NUMERIC when no steady motion is found from the
 * guesses (or the given values are not one: an over-determined residual that
 * does not vanish), QD_ERR_SINGULAR when the equations are not defined there
 * (a coordinate singularity: 0/0).  On success every entry of pt is set and
 * *residual (may be NULL) is the largest final residual, each relative to the
 * size of the terms that make it up (sin and cos counted as 1, their bound:
 * at th = pi a residual whose every term carries sin(pi) = 1.2e-16 is zero).
 * An unknown the search leaves at round-off (|u| <= 1e-10 of its start) is
 * set to an exact 0 when the residual there is no larger. */
QD_API qd_status qd_steady_find(qd_ctx *ctx, const qd_steady *s, size_t nvals,
                         const qd_expr *const *syms, const double *vals, const bool *xfix,
                         const bool *wfix, const bool *pfix, qd_steady_point *pt,
                         double *residual);

/* Every steady motion for the given values, found from the structure of
 * the equations: when one unknown is left free once the given momenta fix
 * the other rates (linearly), the kept residuals along it are
 *   - a polynomial of degree <= 2 when the free unknown is a rate (T is
 *     quadratic in the velocities): its real roots, every one (the fast and
 *     the slow precession of a top);
 *   - a function of the free coordinate otherwise: every sign change over
 *     its range ((-pi, pi] for an angle, else [-10, 10] widened to the
 *     guess), bisected;
 * each polished by the search of qd_steady_find and checked by its relative
 * residual, and again by each row's residual against the size of its own
 * terms and the given momentum (a runaway to a singular point, r -> 0 with a
 * rate -> 1e31, is no steady motion).  The search from the starting values is added too, so nothing
 * qd_steady_find would find is lost.  xfix, wfix, pfix as for
 * qd_steady_find; start holds the given values and the starting guesses;
 * pguess (may be NULL) marks momenta in start->p that are starting values
 * for the rates of those coordinates (converted at the starting point), not
 * held.  The motions come nearest the start first.  Motions where a cyclic
 * coordinate moves nothing (dp_c/dc' = 0: theta = 0 of spherical
 * coordinates) or where qd_stability_analyze cannot linearize (QD_ERR_SINGULAR)
 * are left out and counted; QD_ERR_SINGULAR when only such are
 * found.  QD_ERR_NUMERIC when
 * there is none (the message of the search from the start), QD_ERR_ARG when
 * every value of the free rate is steady (a family: give it). */
typedef struct qd_steady_set {
    size_t count;
    qd_steady_point *pts;     /* count points; x, w, p malloc'd each */
    double *residual;         /* count: each one's largest relative residual */
    bool complete;            /* the structured search applied: every motion is listed
                                 (within the range, for a coordinate that is not an angle) */
    size_t nsingular;         /* motions left out: at a singular point of the coordinates,
                                 where a cyclic coordinate moves nothing (dp_c/dc' = 0) */
} qd_steady_set;

QD_API qd_status qd_steady_find_all(qd_ctx *ctx, const qd_steady *s, size_t nvals,
                                    const qd_expr *const *syms, const double *vals,
                                    const bool *xfix, const bool *wfix, const bool *pfix,
                                    const bool *pguess, const qd_steady_point *start,
                                    qd_steady_set *out);
QD_API void qd_steady_set_free(qd_steady_set *set);

/* ---- a problem stated by name (src/linear/steady_given.c) ---------------- */

/* qd_steady_derive for the cyclic coordinates named in text: "phi, psi"
 * (driven false), or the items of the driven rates "phi' = Omega, psi"
 * (driven true: only their coordinates are read here, each once however
 * often named; a bare name leaves its rate to be found).  field names the
 * text in errors (qd_diag.name, "ignore" or "driven"): a name that is not a
 * coordinate, one listed twice, a value in the free list, more than 16, are
 * QD_ERR_ARG located in text; then qd_steady_derive's errors. */
QD_API qd_steady *qd_steady_derive_named(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                                         const char *field, const char *names, bool driven);

/* The values of the search as text, each "NAME = VALUE, ..." (NULL: none),
 * every VALUE a constant expression in the parameters (qd_model_number). */
typedef struct qd_steady_spec {
    const char *rates;       /* held rates "phi' = 2"; driven: the driven list (a bare
                                "phi" holds nothing) */
    const char *rates_field; /* the name of rates in errors: "driven", "omega" (NULL: "rates") */
    const char *momenta;     /* held momenta "p_phi = 3" (free only): field "momentum" */
    const char *guess;       /* starting values, not held: kept coordinates, rates "phi'" or
                                momenta "p_phi" (turned into rates at the start): "guess" */
    const char *at;          /* held kept coordinates "theta = pi/3": field "at" */
} qd_steady_spec;

/* What qd_steady_find_all, qd_stability_analyze and qd_stability_scan take,
 * read from a qd_steady_spec. */
typedef struct qd_steady_given {
    size_t nvals;
    const qd_expr **syms;    /* t, then the parameters */
    double *vals;            /* t = 0, the parameters at their values in the model */
    qd_steady_point start;   /* held values and starting guesses: the model's `initial`
                                values where none is given, else 0 (coordinates), 1 (rates) */
    bool *xfix, *wfix, *pfix; /* nkeep, ncyc, ncyc: held */
    bool *pguess;            /* ncyc: start.p[c] is a starting momentum for the rate */
    bool *wguess;            /* ncyc: start.w[c] was given as a starting value */
    const qd_expr **held;    /* nkeep + 2 ncyc, in the order (x, w, p): the held values'
                                expressions, NULL where none (qd_scan_opts.about) */
} qd_steady_given;

/* Read spec against s (derived from m) into *out: the held values (rates,
 * momenta, at) before the guesses, which may not change one.  QD_ERR_ARG,
 * the error named by its field (qd_diag.name) and located in that field's
 * text (SUBJECT_TEXT: a value's own error, "did you mean", at its place
 * there), for: a name that is not a coordinate, a rate without a prime, a
 * rate of a coordinate that is not cyclic, a momentum that is not p_<q> of
 * a free cyclic coordinate (or any momentum of a driven one), a kept
 * coordinate written as cyclic or the other way round, a value given twice,
 * a guess of a held value, a value that is not a constant.  out is zeroed
 * on an error; qd_steady_given_free releases it. */
QD_API qd_status qd_steady_given_read(qd_ctx *ctx, const qd_steady *s, const qd_model *m,
                                      const qd_steady_spec *spec, qd_steady_given *out);
QD_API void qd_steady_given_free(qd_steady_given *g);

/* The stability of a steady motion. */
typedef struct qd_stability {
    size_t n;                 /* kept coordinates */
    qd_linear lin;            /* M0, C0, G0, K0 about the steady motion */
    double *hessian;          /* n*n: the Hessian of V_eff */
    qd_modes_result ordinary; /* M0 s^2 + G0 s + K0 (no dissipation) */
    qd_modes_result secular;  /* K = Hessian, C = G = 0: omega2's signs are its inertia */
    bool dissipative;         /* C0 != 0: the model's damping acts */
    qd_modes_result damped;   /* M0 s^2 + (C0 + G0) s + K0 when dissipative */
    int ordinary_stable;      /* 1 stable, 0 unstable, -1 borderline */
    int secular_stable;       /* 1 V_eff minimum, 0 not a minimum, -1 semidefinite */
    int damped_stable;        /* as ordinary_stable, for `damped` (when dissipative) */
    size_t nfreq;
    double *freq;             /* ordinary small-oscillation frequencies (> 0), ascending,
                                 each oscillation once (one per imaginary pair) */
    const char *verdict;      /* a sentence (static storage) */
} qd_stability;

/* Linearize the reduced equations about the steady motion pt and analyse
 * them (qdot/modes.h's qd_modes_solve).  nvals/syms/vals as for
 * qd_steady_find.  QD_ERR_SINGULAR when the equations are not defined there
 * or M0 is not positive definite. */
QD_API qd_status qd_stability_analyze(qd_ctx *ctx, const qd_steady *s, size_t nvals,
                               const qd_expr *const *syms, const double *vals,
                               const qd_steady_point *pt, qd_stability *out);
QD_API void qd_stability_free(qd_stability *st);

/* ---- the whole problem stated by name (src/linear/stability_problem.c) ----
 * What `qdot stability` and Python state: the cyclic coordinates, the values
 * held and the guesses as text (each NULL when not given). */
typedef struct qd_stability_spec {
    const char *ignore;          /* free momenta: the cyclic coordinates "phi, psi" */
    const char *const *driven;   /* or maintained rates: ndriven items "phi' = W", "psi" */
    size_t ndriven;
    const char *momentum;        /* free only: held momenta "p_phi = 3" */
    const char *omega;           /* free only: held rates "phi' = 2" */
    const char *at, *guess;      /* held kept coordinates; starting values (qd_steady_spec) */
} qd_stability_spec;

typedef struct qd_stability_problem {
    qd_steady *s;
    char *driven;                /* the driven items joined, "phi' = W, psi": the text
                                    an error of field "driven" is located in */
    qd_steady_given given;
    qd_steady_set set;           /* qd_stability_problem_solve: every motion ... */
    qd_stability *an;            /* ... and set.count analyses */
} qd_stability_problem;

/* qd_steady_derive_named and qd_steady_given_read of spec for model m
 * derived as e, into *out (overwritten; free it with
 * qd_stability_problem_free, also after a failure).  Their errors, each
 * naming its field (qd_diag.name: "ignore", "driven", "omega", "momentum",
 * "guess", "at") and located in its text; QD_ERR_ARG, not located, when not
 * exactly one of ignore and driven is given, or momentum or omega with
 * driven. */
QD_API qd_status qd_stability_problem_read(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                                           const qd_stability_spec *spec,
                                           qd_stability_problem *out);
/* Every steady motion (qd_steady_find_all) and the analysis of each
 * (qd_stability_analyze) into p->set and p->an; their errors. */
QD_API qd_status qd_stability_problem_solve(qd_ctx *ctx, qd_stability_problem *p);
/* qd_stability_scan of p's motion along param from a to b (steps as
 * qd_scan_opts'), the held values following their expressions. */
QD_API qd_status qd_stability_problem_scan(qd_ctx *ctx, const qd_stability_problem *p,
                                           const qd_model *m, const char *param, double a,
                                           double b, size_t steps, qd_scan *out);
/* A scan sc of p along param printed by qd_scan_print (json: qd_scan_json)
 * with the columns qd_steady_unknown_name and qd_stability_scan_followed's
 * line; their errors (QD_ERR_NOMEM also when out ran out of memory). */
QD_API qd_status qd_stability_scan_write(qd_ctx *ctx, const qd_stability_problem *p,
                                         const char *param, const qd_scan *sc, bool json,
                                         qd_buf *out);
QD_API void qd_stability_problem_free(qd_stability_problem *p);

/* ---- the report (src/linear/stability_print.c) --------------------------- */

/* Every steady motion found and its analysis, for printing. */
typedef struct qd_stability_report {
    const qd_steady *s;
    const qd_steady_given *given; /* which values were held: "(given)" */
    const qd_steady_set *set;     /* count >= 1 motions */
    const qd_stability *an;       /* set->count analyses, in the same order */
    const char *model;            /* the model's name (its file) */
} qd_stability_report;

/* r appended to out.  Text: how many motions (and how many left out), then
 * each: its kept coordinates, rates and momenta, V_eff, M0, C0 (with
 * dissipation), G0, K0, the Hessian of V_eff, the frequencies, the roots s
 * and the verdicts, numbers by the digit rule of qd_result_format (12
 * digits; at or below 1e-12 a 0; a real or imaginary part at or below 1e-12
 * of the largest |s| a 0: gyroscopic roots are imaginary exactly).  JSON: "model", "kind" ("free" or "driven"), the
 * first motion's "steady" (name to value), "residual", "Veff",
 * "mass_matrix", "damping_matrix", "gyroscopic_matrix", "stiffness_matrix",
 * "hessian", "frequencies", "eigenvalues" ([re, im] pairs), "stable" and
 * "secular" (true, false, or null when borderline), "dissipation" (with
 * dissipation: "eigenvalues", "stable", "max_re"), "verdict"; then
 * "steady_motions" (each: "steady", "residual", "frequencies",
 * "eigenvalues", "stable", "secular", "verdict") and "complete".
 * QD_ERR_ARG for no motion, QD_ERR_NUMERIC (nothing appended) for a JSON
 * number that is not finite, QD_ERR_NOMEM. */
QD_API qd_status qd_stability_print(qd_ctx *ctx, const qd_stability_report *r, bool json,
                                    qd_buf *out);

/* Follow a steady motion as the parameter named param goes from a to b and
 * report where its stability changes: ordinary_stable, or damped_stable when
 * the model has dissipation (the motion with its own damping: the rotating
 * bowl with friction fails at omega = sqrt(g/a)).  The scan of
 * qd_modes_scan (qdot/modes.h; opts->start is not used), with the point
 * u = (x, w, p) of kept coordinates, rates and momenta (out->n =
 * nkeep + 2 ncyc, in that order).  At a the motion is the first
 * qd_steady_find_all lists from start (xfix, wfix, pfix, pguess and start as
 * there); then each step holds the given values (xfix, wfix, pfix) and
 * solves for the rest by qd_steady_find from the previous motion.  A held
 * value follows its expression in opts->about (nkeep + 2 ncyc entries in
 * the order of u, NULL entries allowed: a rate driven at a parameter,
 * phi' = W, as W is scanned); without one it keeps its number in start.
 * out->margin: the smallest w^2 (no gyroscopic or damping terms) or the
 * largest Re s of the roots judged.  Errors as qd_modes_scan's;
 * QD_ERR_NUMERIC when no steady motion is found at a, or it is lost. */
QD_API qd_status qd_stability_scan(qd_ctx *ctx, const qd_steady *s, const qd_model *m,
                                   const char *param, double a, double b, const bool *xfix,
                                   const bool *wfix, const bool *pfix, const bool *pguess,
                                   const qd_steady_point *start, const qd_scan_opts *opts,
                                   qd_scan *out);


/* The name of unknown k of the point u = (x, w, p) of qd_stability_scan
 * (k < nkeep + 2 ncyc): a kept coordinate's name, then "Q'" for each cyclic
 * coordinate Q, then "p_Q": the columns of a scan's table.  Written as
 * snprintf writes (at most cap - 1 characters and a NUL into out; out may
 * be NULL when cap is 0); returns the length of the whole name, or 0 for k
 * out of range or s NULL. */
QD_API size_t qd_steady_unknown_name(const qd_steady *s, size_t k, char *out, size_t cap);

/* What a scan of s follows, one line for its table: "the steady motion
 * (momenta free: Routhian); ordinary stability", with "rates maintained:
 * V - T0" for driven rates and "with the model's damping" when the scan
 * judged damped stability (qd_scan's damped).  Appended to out; QD_ERR_NOMEM
 * when out ran out of memory. */
QD_API qd_status qd_stability_scan_followed(const qd_steady *s, bool damped, qd_buf *out);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_steady_find (residual);
 * qd_steady_find_all (pguess); qd_stability_scan (opts, pguess). An array
 * whose count is 0 may be NULL. */
#endif
