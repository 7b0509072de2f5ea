/*
 * qdot/path.h - variational principles as two-point problems (Desloge
 * ch. 82-84, Byerly ch. IV): the stationary paths of Hamilton's action
 * S = integral of L dt between two configurations, their kinetic foci, the
 * paths of given energy (Maupertuis, Jacobi), and the action of a trial path.
 *
 * A path is the motion from q(t0) = q0 with the velocities v0 that reaches
 * q(t1) = q1: found by multiple shooting on the equations of motion (the
 * model's M q'' = f, constraints' multipliers included), Newton's steps
 * taking the Jacobian from the variational equations along each segment.
 *
 * The second variation: the Jacobi (accessory) equation is the equations of
 * motion linearized along the path, delta q'' = (d(q'')/dq) delta q +
 * (d(q'')/dq') delta q'; with delta q(t0) = 0 its solutions span the
 * n x n matrix J(t) = d q(t)/d v0, and a time tc in (t0, t1] where
 * det J(tc) = 0 is a kinetic focus (conjugate point) of t0.  The path is a
 * minimum of S iff there is no focus in (t0, t1] and the Legendre condition
 * holds (M = d^2 L / dq' dq' positive definite along it) (Desloge ch. 84;
 * Gelfand and Fomin ch. 5).
 *
 * The calculus of variations (models with `independent x`): L is then the
 * integrand F(x, y, y') of any functional and t reads x.  An isoperimetric
 * constraint integral G dx = l (qd_model_isoperimetric) adds -lambda G to L
 * with lambda a constant (Desloge App. 32 Thm 5): the constant multipliers
 * are unknowns solved together with v0, the extra conditions being
 * integral G dx = l, each G integrated along the path as a quadrature.  A
 * free end coordinate q_j (free0, free1) is not given: the natural boundary
 * condition p_j = dL/dq'_j = 0 at that end takes the place of q_j = given
 * (Gelfand and Fomin ch. 1 sec. 6; Byerly ch. IV).
 */
#ifndef QDOT_PATH_H
#define QDOT_PATH_H

#include <stdbool.h>
#include <stddef.h>
#include "expr.h"
#include "mech.h"
#include "model.h"
#include "print.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct qd_path_opts {
    double t0, t1;            /* the end times, t1 > t0 */
    const double *q0, *q1;    /* the end configurations, n each */
    /* starting guesses for the initial velocities: nguess rows of n (NULL
     * and 0: the straight line's (q1 - q0)/(t1 - t0)) */
    size_t nguess;
    const double *guess;
    /* all: search for every distinct path (the documented multistart
     * search); else the path found from the first guess that converges */
    bool all;
    size_t segments;          /* multiple-shooting segments; 0: chosen */
    double tol;               /* end-point residual; 0: 1e-10 */
    size_t nsamples;          /* samples of each path; 0: 101 */
    /* free end coordinates (n flags each; NULL: all fixed): free0[j] frees
     * q_j(t0), free1[j] frees q_j(t1), and dL/dq'_j = 0 there instead; the
     * value in q0 / q1 is then only the starting guess.  Not with energy. */
    const bool *free0, *free1;
} qd_path_opts;

typedef struct qd_path {
    size_t n;
    double *v0;               /* n initial velocities */
    double action;            /* S = integral of L dt along the path */
    double residual;          /* |q(t1) - q1| reached */
    size_t nsamples;
    double *t, *q;            /* nsamples times, nsamples*n coordinates */
    size_t nfoci;
    double *foci;             /* the kinetic foci of t0 in (t0, t1], ascending */
    bool legendre;            /* M positive definite along the path */
    bool minimum;             /* legendre and no focus in (t0, t1] */
    /* the second variation was examined (foci, legendre, minimum); not on a
     * constraint manifold, with isoperimetric constraints or free ends,
     * where the fixed-end Jacobi equation does not decide */
    bool examined;
    /* the isoperimetric multipliers lambda (model order: the names are
     * qd_model_isoperimetric_name); with them action is integral F dx, the
     * multiplier terms left out (integral L dx = action - sum lambda l) */
    size_t nmult;
    double *mult;
    size_t *foci_mult;        /* nfoci multiplicities (qd_path_foci_mult), or NULL */
    /* at fixed energy E (qd_path_find_energy): Maupertuis' least action
     * A = integral of p.q' dt = S + E T (T the time taken), the quantity
     * his principle makes stationary (Desloge ch. 83); NaN otherwise */
    double abbreviated;
    /* not isolated: the end t1 is a kinetic focus of t0 (examined paths,
     * not at fixed energy), so a Jacobi field vanishes at both ends and the
     * stationary paths through these ends form (to first order) a family
     * of this dimension, the focus's multiplicity (the great circles
     * between antipodes: 1); this path is one of them, and --all lists a
     * family once.  0: isolated */
    size_t family;
} qd_path;

typedef struct qd_path_set {
    size_t count;
    qd_path *paths;           /* distinct paths, by increasing action */
    bool searched;            /* found by the opts->all multistart: more may exist beyond
                               * what its starts aimed at (qd_path_print's note) */
} qd_path_set;

/* The stationary paths of the action between (t0, q0) and (t1, q1) for the
 * equations e of model m (parameters at the model's values).  QD_ERR_NUMERIC
 * when no path converges (the message says so, with the smallest residual
 * reached and each isoperimetric condition's own); QD_ERR_ARG for bad
 * options and for inconsistent isoperimetric data found before solving (a
 * length integral sqrt(1 + y'^2) dx = l shorter than the distance between
 * the ends).  A multiplier declared as a parameter starts from its value,
 * an undeclared one from 0, then from a spread of values.  out is filled on success (count
 * >= 1); free it with qd_path_set_free. */
QD_API qd_status qd_path_find(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                              const qd_path_opts *opts, qd_path_set *out);
QD_API void qd_path_set_free(qd_path_set *s);

/* The kinetic foci of t0 along the motion from (t0, q0, v0) up to t1: the
 * zeros of det d q(t)/d v0 (the Jacobi equation), located to round-off
 * (those of even multiplicity too, each once: qd_path_foci_mult);
 * *foci (malloc'd with the context's allocator: free with qd_path_foci_free)
 * ascending, and whether the Legendre condition holds along the way. */
QD_API qd_status qd_path_foci(qd_ctx *ctx, const qd_model *m, const qd_eom *e, double t0,
                              const double *q0, const double *v0, double t1, double **foci,
                              size_t *nfoci, bool *legendre);
QD_API void qd_path_foci_free(qd_ctx *ctx, double *foci);

/* qd_path_foci with each focus once and its multiplicity: the number of
 * independent Jacobi fields vanishing there, the order of det J's zero
 * (2 at half a period of the isotropic plane oscillator, where det J
 * touches 0 without changing sign).  Models with holonomic constraints
 * too: J is then d q(t)/d v0 for the v0 the velocity constraints admit at
 * q0, and a focus is where it loses rank; QD_ERR_ARG for nonholonomic
 * ones.  *mult (may be NULL: not wanted) is freed with
 * qd_path_foci_mult_free. */
QD_API qd_status qd_path_foci_mult(qd_ctx *ctx, const qd_model *m, const qd_eom *e, double t0,
                                   const double *q0, const double *v0, double t1,
                                   double **foci, size_t **mult, size_t *nfoci, bool *legendre);
QD_API void qd_path_foci_mult_free(qd_ctx *ctx, size_t *mult);

/* Maupertuis / Jacobi: the paths of energy E (the Jacobi integral h) from q0
 * to q1, whatever the time they take: opts.t0 is the start time, opts.t1 is
 * ignored, and each path's t1 (its last sample's time) is the time it takes.
 * Each start's duration is a time at which the motion from q0 at its
 * velocity passes nearest q1 (with all, the first, second and third such
 * pass within 12 chord times, so the way round a sphere is aimed at too);
 * an end beyond the energy's reach, or a start where the speed vanishes
 * (E the energy at rest there), is QD_ERR_NUMERIC before any search.
 * Each path carries both Hamilton's S (action) and Maupertuis' A
 * (abbreviated), ordered by A.
 * For a natural system these are the geodesics of the Jacobi metric
 * (E - V) M.  Otherwise as qd_path_find. */
QD_API qd_status qd_path_find_energy(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                                     double E, const qd_path_opts *opts, qd_path_set *out);

/* The action of a trial path q_j = path[j](t) (expressions in t and the
 * parameters) from t0 to t1, by quadrature, and the size of its first
 * variation: the L2 norm over [t0, t1] of Lagrange's residual
 * d/dt dL/dq' - dL/dq (- Q) along it (0 on a true path). */
QD_API qd_status qd_path_action_of(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                                   const qd_expr *const *path, double t0, double t1,
                                   double *action, double *first_variation);
/* The result of qd_path_action_of as `qdot action-of` prints it, appended
 * to out: text "action: S" and "first_variation: R" lines (12 significant
 * digits, qd_buf_put_result), or (json) one JSON document and a newline
 * with "model" (source, the model's name), "t0", "t1", "action" and
 * "first_variation", every digit.  QD_ERR_NUMERIC (JSON) when a number is
 * not finite; QD_ERR_NOMEM. */
QD_API qd_status qd_path_action_of_print(qd_ctx *ctx, const char *source, double t0, double t1,
                                         double action, double first_variation, bool json,
                                         qd_buf *out);


/* One end of a path as the command line and Python give it, "x=0, y=free,
 * t=2": for each coordinate of e named, its value into q[j] (e->n entries;
 * the others untouched), or `free` (is_free[j] set, q[j] untouched: a free
 * end, qd_path_opts.free0/free1); the time (t, or the model's independent
 * name) into *t, untouched when the text does not give it.  Values are
 * constant expressions in pi, e and the parameters, read by qd_state_read;
 * a velocity, a parameter or another slot is refused, and so is `free` on
 * a name that is not a coordinate.  QD_ERR_ARG (or the reader's error)
 * with the error record located in text; QD_ERR_NOMEM. */
QD_API qd_status qd_path_end_read(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                                  const char *text, double *q, double *t, bool *is_free);

/* The arrays of a problem read by qd_path_ends_read (free with
 * qd_path_ends_free; q1, guess and free1 lie in q0's and free0's blocks). */
typedef struct qd_path_ends {
    double *q0, *q1;      /* n each */
    double *guess;        /* nguess rows of n initial velocities */
    bool *free0, *free1;  /* n each */
} qd_path_ends;

/* The ends and guesses of qd_path_find's problem from text, as `qdot path`
 * and Python's Model.path take them: from and to as qd_path_end_read reads
 * them (t = 0 at the start when not given; the end's time is required
 * unless energy, the problem of qd_path_find_energy, which takes no free
 * ends), nguess texts "q'=VALUE, ..." each a row of starting velocities (a
 * velocity not named 0).  A free coordinate starts from the other end's
 * value (0 when free at both).  Fills *ends and opts' t0, t1, q0, q1,
 * free0, free1 (NULL when none is free), nguess and guess; the rest of
 * opts is left as given.  QD_OK; else QD_ERR_ARG (or the reader's error)
 * with the error record naming the field "from", "to", "energy" or
 * "guess" (qd_diag.name; for a guess, index is which), located in that
 * text when the error is in it; QD_ERR_NOMEM.  *ends is the caller's to
 * free, also after an error. */
QD_API qd_status qd_path_ends_read(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                                   const char *from, const char *to, size_t nguess,
                                   const char *const *guess, bool energy, qd_path_ends *ends,
                                   qd_path_opts *opts);
QD_API void qd_path_ends_free(qd_path_ends *ends); /* NULL is fine */

/* A trial path for qd_path_action_of, "x = EXPR, y = EXPR": every
 * coordinate of m once (q has qd_model_ncoords(m) entries, in m's order),
 * each an expression in t, the parameters and other names m knows.  A name
 * that is not a coordinate, a coordinate given twice or left out, and the
 * expression reader's errors are QD_ERR_ARG / QD_ERR_PARSE with the error
 * record located in text (the last one is not located: it names the
 * coordinate). */
QD_API qd_status qd_path_trial_read(qd_ctx *ctx, const qd_model *m, const char *text,
                                    const qd_expr **q);

/* ps (found for m and e with opts: its free ends are said so; may be NULL)
 * written for a reader, appended to out: with opts->all a note that more
 * stationary paths may exist beyond what the starts aimed at, and how to
 * ask for them; per path the action, the initial
 * velocities, the multipliers, at fixed energy the least action and the
 * time, the kinetic foci and whether it is a minimum (or why not
 * examined), and every tenth sample.  Numbers have 12 significant digits.
 * QD_ERR_NOMEM when out could not grow. */
QD_API qd_status qd_path_print(qd_ctx *ctx, const qd_path_set *ps, const qd_model *m,
                               const qd_eom *e, const qd_path_opts *opts, qd_buf *out);
/* The same as one JSON document and a newline, every digit and every
 * sample: "count", "paths" (each "action", at fixed energy "least_action"
 * and "time", "initial_velocities", "multipliers", "residual", "samples"
 * as [t, q...] rows, "kinetic_foci", "kinetic_foci_multiplicity",
 * "minimum", "examined"), and for a searched set "search": the text's note
 * as data, {"code": "more_paths_may_exist", "covered": what the starts
 * aimed at, "ask": the options that ask for more}.  QD_ERR_NUMERIC for a
 * non-finite number. */
QD_API qd_status qd_path_json(qd_ctx *ctx, const qd_path_set *ps, const qd_model *m,
                              const qd_eom *e, qd_buf *out);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_path_foci (legendre);
 * qd_path_foci_free (ctx, foci); qd_path_foci_mult (legendre, mult);
 * qd_path_foci_mult_free (ctx); qd_path_print (opts). An array whose count is 0 may be NULL. */
#endif
