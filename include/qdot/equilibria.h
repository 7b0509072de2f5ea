/*
 * qdot/equilibria.h - configurations of rest.
 *
 * An equilibrium is a configuration q0 where the system stays at rest: with
 * every velocity zero the accelerations vanish, i.e. the generalized forces
 * at rest are zero,
 *
 *     F(q) = f(q, q' = 0) = 0,
 *
 * f the right-hand side of M q'' = f (qdot/mech.h).  For L = T - V this is
 * dV/dq = Q; for rheonomic coordinates T0 enters as a potential -T0 (a
 * relative equilibrium in a rotating frame), and velocity-free terms of U
 * count too.
 *
 * Exact where the kernel can: the equations (parameters replaced by their
 * values) are solved one unknown at a time, taking an equation whose every
 * factor involves one unknown only (a product is zero when a factor is),
 * and substituting each root into the rest:
 *     sin(a q + b) = 0, cos(a q + b) = 0, c1 sin q + c0 = 0, c1 cos q + c0 = 0
 *     and polynomials of degree <= 2 in q.
 * Angles are reported in (-pi, pi].  Every exact root is checked
 * numerically.  Otherwise numerically: damped Newton (Levenberg-Marquardt)
 * from a guess, or a multi-start search over a box (quasi-random starts,
 * plus scans along each coordinate axis through the box centre with
 * sign-change bracketing by bisection, poles rejected) with duplicates merged
 * and every solution verified by its residual.
 *
 * Each equilibrium is classified by the eigenvalues of the symmetric part
 * of K = -dF/dq (the Hessian of V - T0 + U0 for a conservative system).
 */
#ifndef QDOT_EQUILIBRIA_H
#define QDOT_EQUILIBRIA_H

#include <stdbool.h>
#include <stddef.h>
#include "expr.h"
#include "mech.h"
#include "model.h"

#ifdef __cplusplus
extern "C" {
#endif

struct qd_speeds_eom; /* qdot/speeds.h */

typedef enum qd_eq_kind {
    QD_EQ_MINIMUM,    /* K positive definite: stable (without gyroscopic forces) */
    QD_EQ_MAXIMUM,    /* K negative definite */
    QD_EQ_SADDLE,     /* K indefinite */
    QD_EQ_DEGENERATE  /* K singular (a zero eigenvalue): the quadratic test says nothing */
} qd_eq_kind;

QD_API const char *qd_eq_kind_name(qd_eq_kind k); /* "minimum", "maximum", "saddle", "degenerate" */

typedef struct qd_equilibrium {
    double *q;               /* n values */
    const qd_expr **exact;   /* n exact values, or NULL when found numerically */
    double residual;         /* max_j |F_j(q)| (generalized-force units) */
    qd_eq_kind kind;
    size_t npos, nneg, nzero;/* signs of the eigenvalues of sym(K) */
    bool symmetric;          /* K symmetric (forces from a potential) */
} qd_equilibrium;

typedef struct qd_equilibria {
    size_t n;
    size_t count;
    qd_equilibrium *pts;     /* sorted by q (lexicographic) */
    bool exact;              /* every point found exactly: the complete set (angles in
                                (-pi, pi]) */
    bool continuum;          /* some equilibria are not isolated (a singular Jacobian
                                with a null direction along which F stays 0) */
    const char *method;      /* "exact", "linear" (affine: one solve), "newton", "multistart", "none" */
} qd_equilibria;

typedef struct qd_equilibria_opts {
    const double *near;      /* n: Newton from this guess only (no exact attempt) */
    const double *lo, *hi;   /* n each: the search box; NULL: qd_equilibria_default_box */
    size_t starts;           /* multi-start points; 0: 40 n + 40 */
    bool numeric_only;       /* skip the exact attempt */
    bool no_search;          /* no multistart: the exact attempt and the solve of affine
                                equations only (method "none" and count 0 when neither
                                applies) */
} qd_equilibria_opts;

/* Which coordinates are angles, and the default box: angles [-pi, pi],
 * others [-10, 10].  An angle is a coordinate the equations f, L, T and V
 * are 2 pi-periodic in: it appears inside sin, cos or tan and only there,
 * each time as k q + (terms free of q) with k a nonzero integer (a pendulum
 * angle that a spring also stretches, V = k/2 (th2 - th1)^2, is not one).
 * QD_ERR_NOMEM when memory runs out. */
QD_API qd_status qd_equilibria_default_box(qd_ctx *ctx, const qd_eom *e, const qd_model *m, bool *angle,
                                    double *lo, double *hi);

/* Find the equilibria of e (derived from m; a model that keeps holonomic
 * constraints goes to qd_constrained_equilibria_find, qdot/constrained.h) with the
 * parameters at syms/vals (as for qd_eom_eval; exact values from the model
 * for the exact attempt).  opts may be NULL.  count may be 0 (QD_OK). */
QD_API qd_status qd_equilibria_find(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t nvals,
                             const qd_expr *const *syms, const double *vals,
                             const qd_equilibria_opts *opts, qd_equilibria *out);
QD_API void qd_equilibria_free(qd_equilibria *r);

struct qd_linpoint; /* qdot/linpoint.h */

/* The search `qdot equilibria --guess ... --box ...` makes, for the
 * equations and state of p (qd_linpoint_init; parameters at their values):
 * guess "q1=VALUE, ..." (qd_linpoint_read_coords, the unnamed coordinates 0)
 * is Newton from there only; box "q1=LOW:HIGH, ..." (qd_linpoint_read_box
 * over qd_equilibria_default_box's ranges) the multi-start search there,
 * numerically only; both NULL the default (the exact attempt, then the
 * default box).  An error in reading guess or box is located in that text
 * and *where (may be NULL) set to it; *where is NULL for every other
 * failure (the search's: QD_ERR_UNSUPPORTED for a constraint the manifold
 * search does not take).  Free out with qd_equilibria_free (also after a
 * failure). */
QD_API qd_status qd_equilibria_find_text(qd_ctx *ctx, const struct qd_linpoint *p,
                                         const char *guess, const char *box, qd_equilibria *out,
                                         const char **where);

/* Which equilibrium to use when the caller names none (small oscillations
 * with no point given).  Newton's method runs from the model's `initial`
 * state first (when it has one).  When that state is itself an equilibrium
 * (Newton stays on it, relative 1e-7) and a minimum of the potential up to
 * rigid motions (no negative stiffness direction; zero ones allowed when
 * some are positive), it is the choice and no search is made (found is
 * qd_equilibria_find with opts.no_search: the exact set when the equations
 * come apart, else empty):
 *   QD_EQ_CHOSEN_INITIAL_STATE        the initial state, an equilibrium.
 * Otherwise, among the equilibria found (qd_equilibria_find with default
 * options) and the point Newton reached from the initial state, a minimum
 * up to rigid motions is preferred:
 *   QD_EQ_CHOSEN_NEAREST_MINIMUM      the minimum nearest the initial state;
 *   QD_EQ_CHOSEN_LOWEST_MINIMUM       no initial state: the minimum of lowest V;
 *   QD_EQ_CHOSEN_NEWTON_FROM_INITIAL  no minimum: where Newton from the
 *                                     initial state went;
 *   QD_EQ_CHOSEN_FIRST_LISTED         no minimum, no initial state: found.pts[0].
 * Ties (relative 1e-12) keep the first listed.  Newton's point is replaced
 * by the listed equilibrium it matches (relative 1e-7), which carries the
 * exact values. */
typedef enum qd_eq_chosen {
    QD_EQ_CHOSEN_NEAREST_MINIMUM,
    QD_EQ_CHOSEN_LOWEST_MINIMUM,
    QD_EQ_CHOSEN_NEWTON_FROM_INITIAL,
    QD_EQ_CHOSEN_FIRST_LISTED,
    QD_EQ_CHOSEN_INITIAL_STATE
} qd_eq_chosen;

typedef struct qd_equilibrium_choice {
    qd_equilibria found;        /* every equilibrium found */
    qd_equilibria from_initial; /* Newton from the initial state (count 0: none or failed) */
    const qd_equilibrium *pt;   /* the choice, into found or from_initial; NULL when both
                                   are empty */
    qd_eq_chosen reason;
    size_t others;              /* how many of found are not pt */
} qd_equilibrium_choice;

/* Find and choose (see qd_equilibrium_choice); syms/vals as for
 * qd_equilibria_find (the initial values are evaluated with them).  QD_OK
 * with pt NULL when there is no equilibrium; a failure of the search is
 * returned.  Free with qd_equilibrium_choice_free (also after a failure). */
QD_API qd_status qd_equilibria_choose(qd_ctx *ctx, const qd_eom *e, const qd_model *m,
                                      size_t nvals, const qd_expr *const *syms,
                                      const double *vals, qd_equilibrium_choice *out);
QD_API void qd_equilibrium_choice_free(qd_equilibrium_choice *c);

/* ---- printed (src/linear/equilibria_print.c) ------------------------------ */

/* What the choice c means, one sentence without a capital or a full stop
 * ("the minimum of the potential nearest the model's initial state"), for a
 * note or a JSON "reason".  Static storage. */
QD_API const char *qd_eq_chosen_name(qd_eq_chosen c);
/* Its machine code, for programs (a JSON "code" next to that "reason"):
 * "nearest_minimum", "lowest_minimum", "newton_from_initial",
 * "first_listed", "initial_state" (the QD_EQ_CHOSEN_ names in lower case);
 * "unknown" outside the enum.  Static storage. */
QD_API const char *qd_eq_chosen_code(qd_eq_chosen c);

/* Coordinate j (below the equilibria's n) of p appended to out: its exact
 * value in the text format (qd_print) when p has one, else the number to
 * 12 significant digits, 0 at or below 1e-12 (qd_buf_put_result, scale 1).
 * QD_ERR_NOMEM when out failed; a failure of qd_print is returned. */
QD_API qd_status qd_equilibrium_put_value(qd_ctx *ctx, const qd_equilibrium *p, size_t j,
                                          qd_buf *out);

/* eq, the equilibria of e (qd_equilibria_find), appended to out: what
 * `qdot equilibria` prints.  Text: "N equilibria (METHOD[: the complete
 * set, angles in (-pi, pi]])", then a numbered line per point with each
 * coordinate (qd_equilibrium_put_value, the number beside an exact value
 * that is not a number in the digit rule of qd_buf_put_result, scale 1)
 * and a line with its kind (qd_eq_kind_name), the Hessian's signs and the
 * residual ("< 1e-14" below it, else 3 digits); a family (eq->continuum)
 * shows its first 10 samples and a note that the points are not isolated.
 * JSON: {"method", "exact", "continuum", "equilibria": [{"equilibrium":
 * {coordinate: value}, "exact": {coordinate: expression} (when found
 * exactly), "kind", "hessian_signs": [positive, negative, zero],
 * "symmetric", "residual"}]}, every digit, ending with a newline.
 * QD_ERR_ARG when eq is not over e's coordinates (eq->n != e->n) or has no
 * method; QD_ERR_NUMERIC (nothing appended) for a JSON number that is not
 * finite; a failure of qd_print; QD_ERR_NOMEM.  Nothing is appended on a
 * failure. */
QD_API qd_status qd_equilibria_print(qd_ctx *ctx, const qd_eom *e, const qd_equilibria *eq,
                                     bool json, qd_buf *out);

/* The automatic choice c said in one line, appended to out: the point,
 * "theta = 0, phi = 1.5" (the names of e's coordinates, each value to 12
 * significant digits, 0 at or below 1e-12: qd_buf_put_result, scale 1),
 * then ", " and what the choice means (qd_eq_chosen_name), then, when
 * others were found, "; 2 other equilibria found" (", not isolated" when
 * some are not).  QD_ERR_ARG when c has no point or e is not of c's size;
 * QD_ERR_NOMEM when out failed. */
QD_API qd_status qd_equilibrium_choice_note(const qd_eom *e, const qd_equilibrium_choice *c,
                                            qd_buf *out);

/* max_j |f_j| at the state syms/vals (as for qd_eom_eval; give the
 * velocities as 0 for a point at rest): how far the point is from an
 * equilibrium, in generalized-force units.  Fails as qd_eom_eval does (a
 * singular M too), *res 0 then. */
QD_API qd_status qd_eom_rest_residual(qd_ctx *ctx, const qd_eom *e, size_t nvals,
                                      const qd_expr *const *syms, const double *vals,
                                      double *res);

/* Is the exact point q0 (n expressions, e.g. an equilibrium's exact
 * values) an equilibrium whatever the parameters' values?  theta = 0 of a
 * bead on a spinning hoop is; cos theta = g/(a w^2) solved at g = 9.81 is
 * not.  Tested numerically: every model parameter in syms is moved off its
 * value in vals and F(q0) must stay 0 (relative 1e-9 against its terms). */
QD_API bool qd_equilibrium_exact_in_parameters(qd_ctx *ctx, const qd_eom *e, const qd_model *m,
                                               size_t nvals, const qd_expr *const *syms,
                                               const double *vals, const qd_expr *const *q0);

/* ---- models in generalized speeds (src/linear/speeds_eq.c) ----------------
 *
 * At rest q' = 0 and u' = 0.  For a scleronomic speed map (q' = W u, no
 * term w free of the speeds; else QD_ERR_UNSUPPORTED) that is u = 0 (W has
 * full column rank) and f_u(q, 0) = 0: m equations in n coordinates, with
 * the holonomic constraints phi(q) = 0 (the speeds keep them only
 * differentiated, so the configuration must be put on them).  With
 * nonholonomic constraints m < n and the equilibria come in families (the
 * rolling disk stands upright anywhere, with any heading): the coordinates
 * no equation at rest involves are free, any value; the others are solved
 * for as qd_equilibria_find does (exact, else numeric).  f_u(q, 0) =
 * W^T f(q, 0), so a holonomic model (W invertible) has the equilibria of
 * Lagrange's equations.  The kinds classify K = -d f_u/dq over the solved
 * coordinates, which is the Hessian of the potential only when the speeds
 * at those coordinates are their velocities. */
typedef struct qd_speeds_equilibria {
    size_t n;                /* e->n */
    size_t nsolved;          /* coordinates the equations at rest involve */
    size_t *solved;          /* nsolved indices into e->q, ascending */
    bool *free_coord;        /* n: in no equation at rest (any value) */
    size_t nrows;            /* equations at rest that are not identically 0 (the
                                holonomic constraints among them) */
    qd_equilibria eq;        /* over the solved coordinates: eq.n = nsolved, each
                                point's q[j] is coordinate solved[j] */
} qd_speeds_equilibria;

/* Find them; syms/vals as for qd_equilibria_find (parameters, t), opts as
 * there with its arrays over all n coordinates of e (the free ones are not
 * read).  With no coordinate to solve for: one point (no values) when no
 * equation at rest is left, every coordinate free, else none. */
QD_API qd_status qd_speeds_equilibria_find(qd_ctx *ctx, const struct qd_speeds_eom *e,
                                           const qd_model *m, size_t nvals,
                                           const qd_expr *const *syms, const double *vals,
                                           const qd_equilibria_opts *opts,
                                           qd_speeds_equilibria *out);
QD_API void qd_speeds_equilibria_free(qd_speeds_equilibria *r);

/* ---- chosen and printed (src/linear/speeds_choose.c, speeds_print.c) ------ */

/* The state to linearize e (derived from m) about when the caller names
 * none: the first equilibrium qd_speeds_equilibria_find lists (default
 * options; syms/vals as there, the parameters' values read from vals), at
 * rest.  Its solved coordinates are written into vals at their symbols'
 * slots in syms and every speed of e that syms holds is set to 0; the free
 * coordinates and every other slot keep their values.  *found false, vals
 * untouched and QD_OK when none is listed; a failure of the search is
 * returned with vals untouched. */
QD_API qd_status qd_speeds_equilibria_choose(qd_ctx *ctx, const struct qd_speeds_eom *e,
                                             const qd_model *m, size_t nvals,
                                             const qd_expr *const *syms, double *vals,
                                             bool *found);

/* s, the equilibria of e (qd_speeds_equilibria_find), appended to out.
 * Text: how many, the method, the speeds (all 0), then each point's solved
 * coordinates (exact values with their number beside them when they are
 * not numbers; numbers in the digit rule of qd_buf_put_result) and
 * residual; a family (s->eq.continuum) shows its first 10 samples and says
 * it is not isolated; then the free coordinates and how many equations at
 * rest were solved.  JSON: "method", "exact", "continuum", "speeds",
 * "free", "equilibria" (each: "equilibrium" {coordinate: value}, "exact"
 * {coordinate: expression} when found exactly, "residual"), every digit,
 * ending with a newline.  QD_ERR_ARG when s is not over e's coordinates,
 * QD_ERR_NUMERIC (nothing appended) for a JSON number that is not finite,
 * QD_ERR_NOMEM. */
QD_API qd_status qd_speeds_equilibria_print(qd_ctx *ctx, const struct qd_speeds_eom *e,
                                            const qd_speeds_equilibria *s, bool json,
                                            qd_buf *out);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_equilibria_find (opts);
 * qd_speeds_equilibria_find (opts, syms, vals). An array whose count is 0
 * may be NULL. */
#endif
