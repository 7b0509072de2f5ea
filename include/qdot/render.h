/*
 * qdot/render.h - whole systems printed: the equations M q'' = f of a model
 * (qdot/mech.h) and its equations in generalized speeds (qdot/speeds.h) as
 * text, LaTeX, JSON, SymPy or C, appended to a qd_buf (qdot/print.h).
 *
 * Text is for reading (entries in the model language's syntax); LaTeX is one
 * align environment; JSON is for programs (expressions as strings in the text
 * syntax, numbers as numbers at a state); SymPy is a script that runs as it
 * is and rebuilds M and f (python: exec it, or see docs/python.md); C is one
 * qd_print_c_block, so common subexpressions are shared across M and f.
 * The names a SymPy or C rendering gives its results (M, f, q, qdd, A, b,
 * lam, ...) get a trailing _ for each clash with a name of the model.
 *
 * `qdot eom` is these functions and a few lines of printing.
 */
#ifndef QDOT_RENDER_H
#define QDOT_RENDER_H

#include "mech.h"
#include "model.h"
#include "print.h"
#include "speeds.h"
#include "form.h"
#include "impulse.h"
#include "hamilton.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum qd_render_format {
    QD_RENDER_TEXT,
    QD_RENDER_LATEX,
    QD_RENDER_JSON,
    QD_RENDER_SYMPY,
    QD_RENDER_C
} qd_render_format;

/* "text", "latex", "json", "sympy", "c"; NULL for another value. */
QD_API const char *qd_render_format_name(qd_render_format f);
/* The format of that name; false (and *out unchanged) for another name. */
QD_API bool qd_render_format_parse(const char *name, qd_render_format *out);

/* "holonomic", "integrable" or "nonholonomic". */
QD_API const char *qd_con_kind_name(qd_con_kind k);

typedef struct qd_render_opts {
    /* The model's name in the renderings' headers ("model: NAME", the SymPy
     * and C comments, JSON "model"); NULL: "model". */
    const char *source;
    /* At a state: nstate symbols with their values, as qd_eval takes them
     * (every coordinate, velocity and t, and the parameters when a value
     * other than the model's is wanted; a model with speeds: the speeds
     * instead of the velocities).  The entries of M, f, q'', A, b, the
     * multipliers, R = A^T lambda, T and the model's `reaction` statements
     * (qd_eom_reaction) are then printed as numbers.  nstate 0: the
     * expressions.  Text and JSON only with speeds. */
    size_t nstate;
    const qd_expr *const *syms;
    const double *vals;
    /* With speeds: the multipliers were asked for, so that the rendering
     * says "none" for a model without constraints. */
    bool multipliers;
    /* Where a note goes (a `reaction` whose constraint was eliminated),
     * one line each with its newline; NULL: dropped. */
    qd_buf *notes;
} qd_render_opts;

/* Append e, the equations of m (qd_eom_derive_opts; solved or not), to out
 * in fmt.  o NULL: symbolic, source "model".  At a state, a singular mass
 * matrix is QD_ERR_SINGULAR with the state in the message; another failure
 * to evaluate is its status with "cannot evaluate the equations at this
 * state: ..." (both recorded in ctx). */
QD_API qd_status qd_render_eom(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                               const qd_render_opts *o, qd_render_format fmt, qd_buf *out);

/* The same for the equations in generalized speeds: q' = W u + w, then
 * M_u u' = f_u, the rates u' when solved (qd_speeds_solve), S and the
 * multipliers when derived.  At a state (text and JSON; QD_ERR_ARG for the
 * others): q', u' and the multipliers as numbers (qd_speeds_eval); a number
 * that is not finite is QD_ERR_NUMERIC naming it. */
QD_API qd_status qd_render_speeds(qd_ctx *ctx, const qd_model *m, const qd_speeds_eom *e,
                                  const qd_render_opts *o, qd_render_format fmt, qd_buf *out);

/* Hamel's coefficients gamma_ikm of e (qd_speeds_hamel_coefficients): in
 * text the nonzero ones by index names (a speed, then a constraint), in
 * JSON {"indices": [...], "gamma": [i][k][m]}.  QD_ERR_ARG for another
 * format. */
QD_API qd_status qd_render_hamel(qd_ctx *ctx, const qd_speeds_eom *e, qd_render_format fmt,
                                 qd_buf *out);

/* ---- `qdot eom` as one call (src/render/eom_request.c) ------------------- */

/* What to print of a model's equations: in its speeds when it declares
 * `speeds` (qd_speeds_derive with speeds), else Lagrange's. */
typedef struct qd_eom_request {
    qd_render_format fmt;
    const char *source;      /* the model's name (qd_render_opts.source) */
    const char *at;          /* the numbers at a state "q=..., q'=..., t=..." (with speeds
                                qd_speeds_state_read's), or NULL: the expressions */
    bool solve;              /* without at: q'' (u') solved symbolically; a solution larger
                                than max_ops operations an entry leaves M and f, with a note */
    size_t max_ops;
    bool eliminate;          /* coordinates: qd_eom_opts.eliminate */
    qd_speeds_opts speeds;   /* speeds: the method, S and the multipliers */
    bool hamel;              /* speeds: Hamel's coefficients (qd_render_hamel) instead */
} qd_eom_request;

/* The step of qd_eom_request_render that failed. */
typedef enum qd_eom_step {
    QD_EOM_STEP_NONE,
    QD_EOM_STEP_DERIVE,      /* the derivation (the model's fault: its errors) */
    QD_EOM_STEP_AT,          /* the state read: located in rq->at */
    QD_EOM_STEP_SOLVE,       /* solving for q'' or u' */
    QD_EOM_STEP_RENDER
} qd_eom_step;

/* Derive m's equations as rq says and append their rendering to out, the
 * notes (one line each with its newline: a solution too large, the
 * renderer's) to notes.  *failed (may be NULL) names the step that failed,
 * QD_EOM_STEP_NONE on success; the errors are that step's. */
QD_API qd_status qd_eom_request_render(qd_ctx *ctx, const qd_model *m, const qd_eom_request *rq,
                                       qd_buf *out, qd_buf *notes, qd_eom_step *failed);

/* The verdict of `qdot check` from the model's numbers (qd_eom_audit at
 * the parameters' values and the initial state): ok, or a certified "no"
 * with its witness.  reason is a machine code next to the English message:
 * "mass_not_positive_definite" (witness: the pivot of the mass matrix for
 * coordinate `about`) or "constraint_not_real" (witness: the smallest
 * residual the constraint `about` reaches near the initial state).
 * statement: where the model says it, for qd_model_where ("T", "L", a
 * coordinate, "constraint:NAME"); hint: what to look at.  off_constraint:
 * the initial state is off a constraint (by residual, over 1e-4), which a
 * run projects away: a note, not a "no".  No numbers to judge by (a
 * parameter without a value) is ok, with judged false. */
typedef struct qd_check_verdict {
    bool ok, judged;
    const char *reason; /* the machine code ("mass_not_positive_definite",
                         * "constraint_not_real"; JSON "code"), NULL when ok */
    char message[320];
    const char *about;  /* a coordinate or a constraint name */
    double witness;
    char statement[160];
    const char *hint;
    bool off_constraint;
    double residual;
    const char *residual_con;
} qd_check_verdict;

/* The verdict of e, the equations of m, into *v; QD_OK (also for a "no"),
 * QD_ERR_NOMEM. */
QD_API qd_status qd_check_verdict_of(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                                     qd_check_verdict *v);

/* The summary `qdot check` prints of a model whose verdict is v: in text
 * the coordinates, degrees of freedom, parameters, what T, V, U, D and L
 * depend on, forces, constraints and their kinds, impulsive statements,
 * cyclic coordinates, time dependence and the energy integral, the size of
 * the equations (nothing when v says "no": the caller shows the message at
 * its statement); in JSON the same as data with "ok", and "code" (v->reason),
 * "reason" (its English), "message" and "witness" for a "no".  QD_ERR_ARG for another format. */
QD_API qd_status qd_render_check(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                                 const qd_render_opts *o, const qd_check_verdict *v,
                                 qd_render_format fmt, qd_buf *out);

/* The reduction f of the quadratic form phi (qd_qform_reduce): in text the
 * form, its symmetric matrix, Lagrange's sum of squares c_k y_k^2, the rank
 * and Sylvester's inertia (or "undecided"); in JSON "variables", "form",
 * "matrix", "coefficients", "linear_forms", "sum_of_squares", "paired",
 * "rank", "inertia" ({"positive", "negative", "zero"} or null) and "kind".
 * QD_ERR_ARG for another format. */
QD_API qd_status qd_render_qform(qd_ctx *ctx, const qd_expr *phi, const qd_qform *f,
                                 qd_render_format fmt, qd_buf *out);

/* The homogeneity h of a function in the n variables x (qd_homogeneity,
 * qdot/form.h; Desloge App. 20): in text "homogeneity in x, y (...)", f,
 * sum x_i df/dx_i and the verdict: "homogeneous of degree N: ..." (with
 * qd_zero_result_note when verified numerically), "f is 0: homogeneous of
 * every degree", "not homogeneous: ..." with the witness line
 * (qd_zero_result_print), or "could not decide: ..."; in JSON
 * "variables", "f", "euler", "verdict" (qd_homog_verdict_name),
 * "homogeneous" (null when undecided), "degree" (null unless homogeneous
 * of one degree) and qd_zero_result_json's "certainty", "witness",
 * "points", "bits".  QD_ERR_ARG for another format. */
QD_API qd_status qd_render_homog(qd_ctx *ctx, const qd_homog *h, size_t n,
                                 const qd_expr *const *x, qd_render_format fmt, qd_buf *out);

/* The fundamental period system p (qd_periods_reduce, qdot/form.h; Desloge
 * App. 31) of the vectors w (p->g * p->r) in the variables x, with f (NULL:
 * none tested): in text each w_j and, when tested, "a period of f" or "not
 * a period of f" with its witness line, the fundamental periods e_k and each
 * w_j as an integer combination of them; in JSON "variables", "f",
 * "periods", "tests" ({"is_period", and qd_zero_result_json's keys} per
 * vector, [] when not tested), "unit", "rank", "fundamental" and
 * "coordinates" (g rows of rank integers).  QD_ERR_ARG for another format. */
QD_API qd_status qd_render_periods(qd_ctx *ctx, const qd_expr *f, const qd_periods *p,
                                   const qd_expr *const *x, const qd_expr *const *w,
                                   qd_render_format fmt, qd_buf *out);

/* The Gram-Schmidt orthogonalization g (qd_gram_schmidt, qdot/form.h;
 * Desloge App. 21) under T (n * n, or NULL for the identity), the
 * components named by x (n, or NULL): in text T, the a's, each b(r) as
 * a(r) less its components along the b's before it with its norm
 * b(r)^T T b(r), and the check of eq. 4; in JSON "variables" ([] without
 * x), "euclidean", "metric" (T's rows, null when euclidean), "vectors",
 * "orthogonal", "norms", "coefficients" (s rows of s: a(r)'s along b(j),
 * j < r) and "certainty" ("proven" or "numeric").  QD_ERR_ARG for another
 * format. */
QD_API qd_status qd_render_gram(qd_ctx *ctx, const qd_gram *g, const qd_expr *const *x,
                                const qd_expr *const *T, qd_render_format fmt, qd_buf *out);

/* The change of variables c (qd_change_vars, qdot/form.h; Desloge App. 19):
 * in text the map x = x(y), the Jacobian matrix, J(x/y), J(y/x), J's sign,
 * |J|, f and f(x(y)) |J| when f was given, and where J = 0; in JSON
 * "variables", "new_variables", "map" (by old variable), "jacobian" (rows
 * dx_i/dy_j), "jacobian_det", "inverse_det", "sign" ("nonnegative",
 * "nonpositive", "unknown"), "abs_det", "f", "integrand" (null without f)
 * and "singular" ({"lhs", "rhs", "period"}, as qdot metric's chart).
 * QD_ERR_ARG for another format. */
QD_API qd_status qd_render_change(qd_ctx *ctx, const qd_change *c, qd_render_format fmt,
                                  qd_buf *out);

/* The Fourier series f of fx in the variables x (qd_fourier_series,
 * qdot/form.h; Desloge App. 31): in text each harmonic's wave vector k and
 * its cos and sin coefficients (the constant term alone for k = 0), and the
 * check; in JSON "variables", "f", "harmonics" ({"k", "argument", "cos",
 * "sin"} each) and "certainty".  QD_ERR_ARG for another format. */
QD_API qd_status qd_render_fourier(qd_ctx *ctx, const qd_fourier *f, const qd_expr *fx,
                                   const qd_expr *const *x, qd_render_format fmt, qd_buf *out);

/* ---- impulsive motion (qdot/impulse.h) ----------------------------------- */

/* Append r, the answer of qd_impulse_solve on m, to out: text (the
 * velocities before and after with their closed forms, the blows'
 * generalized impulses, the multipliers, redundant rows and reactions, the
 * energies, the theorems that apply and, for a collision, the lab and
 * centre-of-mass description), JSON (the same for programs) or LaTeX (one
 * align of the closed forms).  QD_ERR_ARG for another format; QD_ERR_NOMEM
 * when out ran out. */
QD_API qd_status qd_render_impulse(qd_ctx *ctx, const qd_model *m, const qd_impulse *r,
                                   qd_render_format fmt, qd_buf *out);

/* ---- the Hamiltonian (qdot/hamilton.h) ------------------------------------ */

/* H and Hamilton's equations of h (qd_ham_derive) at one point (q, p, t):
 * numbers, computed by qd_ham_point_eval, for qd_render_hamiltonian and any
 * caller (arrays of n entries each, the library's: qd_ham_point_free). */
typedef struct qd_ham_point {
    size_t n;        /* h->n */
    double *q, *p;   /* the point's coordinates h->q and momenta h->p */
    double t;
    double *qd;      /* the velocities there: h->vel evaluated, or for h->implicit
                        Newton's solution of p = dL/dq' (qd_ham_velocities_at) */
    double H;
    double *dq, *dp; /* dq_j/dt and dp_j/dt */
    bool solved;     /* qd came from Newton's method (h->implicit) */
} qd_ham_point;

/* Evaluate h at the state syms/vals (nvals: every coordinate h->q, every
 * momentum h->p, t and the parameters, as qd_eval takes them; for
 * h->implicit the velocities given are Newton's first guess, else 0) into
 * *out.  H, dq and dp are evaluated in that order with the velocities of
 * the point (for h->implicit, Newton's); out->qd after them.  QD_ERR_ARG
 * naming it when a coordinate, momentum or t has no value in syms; an
 * evaluation's or Newton's status with its message (QD_ERR_NUMERIC "not a
 * finite number: ..." for a value that is not finite).  *out is
 * overwritten; free it with qd_ham_point_free (also after a failure). */
QD_API qd_status qd_ham_point_eval(qd_ctx *ctx, const qd_ham *h, size_t nvals,
                                   const qd_expr *const *syms, const double *vals,
                                   qd_ham_point *out);
QD_API void qd_ham_point_free(qd_ham_point *pt);
/* h evaluated where `qdot hamiltonian --at` and Python's
 * Model.hamiltonian(at=) ask: the state of m with every coordinate,
 * velocity and t 0 and the parameters at their values (qd_state_init, not
 * the model's `initial`), h's momenta after it at 0, and the values at
 * names read into it (qd_state_read: "x=0.5, p_x=2", the momenta named as
 * printed); then qd_ham_point_eval.  The reader's errors located in at;
 * qd_ham_point_eval's.  Free out with qd_ham_point_free (also after a
 * failure). */
QD_API qd_status qd_ham_point_at(qd_ctx *ctx, const qd_model *m, const qd_ham *h, const char *at,
                                 qd_ham_point *out);

/* Append h, the Hamiltonian of m (qd_ham_derive), to out in fmt; source
 * names the model in the headers (NULL: "model"); at (NULL: symbolic) is h
 * evaluated at a point (qd_ham_point_eval), whose H, Hamilton's equations
 * and (h->implicit) velocities are then printed as numbers.
 *   Text and LaTeX: "qdot hamiltonian SOURCE", the momenta p_j = dL/dq'_j
 *     and the velocities q'_j(q, p, t) (at a point the velocities only for
 *     h->implicit, Newton's), H, for a model given by H the inverse
 *     Legendre transform L (or why there is none), Hamilton's equations and
 *     the verdicts "H = T + V" and "H conserved"; LaTeX rows end in \\ and
 *     the other lines are % comments.
 *   JSON: "model", "coordinates", "momenta", "definitions" (pdef, null
 *     entries when there is none), "velocities", "implicit" (only when
 *     true), "at" {q..., t, p...} at a point, "H", "dq_dt", "dp_dt" (each
 *     an expression string, a number at the point), "H_is_energy" (null
 *     when unknown), "H_minus_energy", "conserved", "H_given", and for a
 *     model given by H without a point "L" and "L_error"; a newline ends it.
 *   SymPy: a script defining the symbols, momenta, pdef (None when there
 *     are none), velocities, implicit (when true), H, L (a model given by
 *     H), dq_dt and dp_dt, each name with a _ appended while it clashes
 *     with a name of m, the verdicts as comments.
 * For h->second_kind (qd_ham2_derive) the same with s, K and T in place of
 * p, H and L: the header "qdot hamiltonian --second-kind SOURCE", a section
 * "generalized forces" (Q_<q> = h->extra), "Hamilton's equations of the
 * second kind" and the verdicts "K = T", "s = p", "K conserved"; JSON
 * "kind": "second" after "model", "K", "forces", "dq_dt", "ds_dt", "K_is_T",
 * "K_minus_T", "s_is_p", "conserved" (no H keys); SymPy K, forces, ds_dt.
 * QD_ERR_ARG for QD_RENDER_C or an at not of h (another n); QD_ERR_NUMERIC
 * for a JSON number that is not finite; QD_ERR_NOMEM.  Nothing is appended
 * on an error. */
QD_API qd_status qd_render_hamiltonian(qd_ctx *ctx, const qd_model *m, const qd_ham *h,
                                       const char *source, const qd_ham_point *at,
                                       qd_render_format fmt, qd_buf *out);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it. NULL is an
 * accepted value, as documented at the function, for: qd_render_eom (o),
 * qd_render_speeds (o), qd_render_check (o), qd_render_periods (f), qd_render_gram (x, T),
 * qd_render_hamiltonian (source,
 * at); qd_ham_point_free accepts NULL. Exception:
 * qd_render_format_parse(NULL, out) is false. */
#endif
