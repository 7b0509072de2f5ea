/*
 * qdot/integrals.h - first integrals of a model (Desloge, Classical
 * Mechanics vol. 2, ch. 56; Goldstein ch. 1-2; Byerly Arts. 16-19):
 *
 *   cyclic coordinates  q_j absent from L: p_j = dL/dq'_j is conserved when
 *                       no generalized force, dissipation or constraint acts
 *                       on q_j (Desloge ch. 56 thm 4);
 *   Jacobi's integral   h = sum_j q'_j dL/dq'_j - L, conserved when L has no
 *                       explicit t and nothing works on the system (ch. 56
 *                       thm 3); it is the energy T + V + U0 only when T is
 *                       homogeneous quadratic in the velocities and U at most
 *                       linear in them;
 *   energy balance      along the motion
 *                         dh/dt = sum_j Q_j q'_j - sum_j q'_j dD/dq'_j
 *                                 - dL/dt|explicit - sum_k lambda_k a0_k,
 *                       the last term the power of the constraint forces
 *                       sum_j q'_j R_j (R_j = sum_k lambda_k A_kj) on the
 *                       constraints A q' + a0 = 0 (0 unless they move);
 *                       sum_j q'_j dD/dq'_j = 2D for a homogeneous quadratic
 *                       D (Goldstein sec. 1.5: 2D is the rate of dissipation).
 *                       It is checked, not assumed: dh/dt is formed with the
 *                       accelerations of the equations of motion;
 *   Noether's theorem   a field q_j -> q_j + eps xi_j(q, t) with
 *                         dL/deps = sum_j dL/dq_j xi_j + dL/dq'_j xi_j'
 *                       equal to 0, or to dF/dt for some F(q, t) (a
 *                       quasi-symmetry, Desloge ch. 56 eq. for C), gives
 *                       I = sum_j p_j xi_j - F, conserved when moreover the
 *                       forces do no work along xi: sum_j xi_j (Q_j - dD/dq'_j) = 0;
 *   proposed integrals  I(q, q', t) is conserved when dI/dt vanishes with the
 *                       accelerations of the equations of motion.
 *
 * Zero tests.  "Vanishes" means qd_simplify gives 0, or, when it does not
 * (the simplifier is incomplete), the expression is below 1e-8 relative to
 * its terms at each of 12 random states (coordinates, velocities, t and every
 * parameter drawn at random), the accelerations computed there from the
 * equations of motion; a state where it clearly does not vanish is a
 * counterexample and wins once ball arithmetic at that state excludes 0
 * (the witness, in `cert`; with solved accelerations qd_zero_test decides
 * directly).  `numeric` flags the verdicts that rest on the random states
 * only; with a negative verdict (not conserved) it means could not decide:
 * no certified counterexample, and too few states where the expression is
 * defined.  Parameters are symbols: a verdict holds for every
 * value of them (substitute values first with qd_integrals_opts.subs to ask
 * about particular ones).
 *
 * Every expression belongs to the context; the arrays are the library's and
 * go with qd_integrals_free.
 */
#ifndef QDOT_INTEGRALS_H
#define QDOT_INTEGRALS_H

#include <stdbool.h>
#include <stddef.h>
#include "certify.h"
#include "expr.h"
#include "mech.h"
#include "model.h"
#include "print.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A cyclic coordinate (absent from L). */
typedef struct qd_int_cyclic {
    size_t coord;               /* index in the eom's coordinates */
    const qd_expr *momentum;    /* p_j = dL/dq'_j, simplified */
    bool conserved;
    const char *obstruction;    /* NULL when conserved, else what acts on q_j */
} qd_int_cyclic;

/* Jacobi's integral and the energy. */
typedef struct qd_int_jacobi {
    const qd_expr *h;           /* sum_j q'_j dL/dq'_j - L, simplified */
    bool explicit_t;            /* L contains t */
    bool conserved;             /* dh/dt vanishes along the motion */
    bool numeric;               /* that verdict rests on random states only */
    qd_zero_result cert;        /* how the verdict on dh/dt is known: NONZERO with the
                                   witness state of a "no", UNKNOWN when undecided */
    int equals_energy;          /* 1 yes, 0 no, -1 unknown (L given without T) */
    const qd_expr *energy;      /* E = T + V + U0 (U0: U at zero velocities), or NULL */
    const qd_expr *h_minus_E;   /* simplified, NULL when energy is */
    const char *reason;         /* why h is (or is not) E: a sentence */
    const char *not_conserved;  /* NULL when conserved, else what spoils it: a sentence */
} qd_int_jacobi;

/* dh/dt along the motion. */
typedef struct qd_int_balance {
    const qd_expr *dhdt;        /* computed with the accelerations of the equations of
                                   motion (accelerations left as q'' when they were too
                                   big to solve for), simplified; with constraints, on
                                   them: dh/dt - sum_k lambda_k (A_k q' + a0_k) */
    const qd_expr *expected;    /* sum Q_j q'_j - 2D - dL/dt|explicit - sum_k lambda_k a0_k, with
                                   sum q'_j dD/dq'_j in place of 2D when D is not
                                   homogeneous quadratic */
    const char *formula;        /* that formula in words, e.g. "sum_j Q_j q'_j - 2D" */
    bool D_quadratic;           /* D given and sum q' dD/dq' = 2D */
    bool verified;              /* dhdt - expected vanishes */
    bool numeric;               /* verified at random states only (then dhdt is shown as
                                   expected, and remainder as 0) */
    const qd_expr *remainder;   /* dhdt - expected, simplified (0 when verified symbolically) */
} qd_int_balance;

/* Noether's integral of a field xi. */
typedef struct qd_noether {
    const char *name;           /* as given (not copied), or a static name for found ones */
    const qd_expr **xi;         /* n components (malloc'd copy) */
    const qd_expr *dL;          /* dL/deps, simplified: 0 for a symmetry */
    const qd_expr *F;           /* dL/deps = dF/dt: F(q, t) found, NULL when none needed
                                   or none found */
    bool invariant;             /* dL/deps vanishes, or is dF/dt (then F set) */
    const qd_expr *integral;    /* sum_j p_j xi_j - F (F only when found), simplified */
    const qd_expr *work;        /* sum_j xi_j (Q_j - dD/dq'_j) (+ constraint forces), simplified */
    const qd_expr *remainder;   /* dI/dt along the motion, simplified: 0 when conserved */
    bool conserved;             /* dI/dt vanishes along the motion */
    bool numeric;               /* a verdict rests on random states only */
    qd_zero_result cert;        /* how conserved is known (as in qd_int_jacobi) */
} qd_noether;

/* A proposed integral I(q, q', t). */
typedef struct qd_int_proposed {
    const char *name;           /* as given (not copied) */
    const qd_expr *expr;
    const qd_expr *remainder;   /* dI/dt along the motion, simplified */
    bool conserved;
    bool numeric;
    qd_zero_result cert;        /* how conserved is known (as in qd_int_jacobi) */
} qd_int_proposed;

typedef struct qd_integrals_opts {
    /* Largest solved acceleration (count_ops) substituted symbolically;
     * 0: 4000.  Bigger ones are used only numerically. */
    size_t max_ops;
    /* Look for translations and rotations by coordinate names (see
     * qd_integrals_derive). */
    bool search;
} qd_integrals_opts;

typedef struct qd_integrals {
    size_t n;
    const qd_expr **q, **qd;    /* the eom's */
    const qd_expr *L;           /* simplified, substitutions made */
    size_t ncyclic;
    qd_int_cyclic *cyclic;
    qd_int_jacobi jacobi;
    qd_int_balance balance;
    size_t nfound;              /* symmetries found by the search */
    qd_noether *found;
    size_t ntested;             /* candidates the search tried (found or not) */
    const char **tested;        /* their names (static strings) */
    bool searched;              /* opts->search was set */
    bool constrained;           /* the equations carry constraints (no search then) */
    void *priv;
} qd_integrals;

/* Cyclic coordinates, Jacobi's integral and the energy balance of model m
 * with equations e (qd_eom_derive; e is solved here for its accelerations
 * when it was not).  With opts->search, candidate symmetries are tried, by
 * the coordinates' names (a heuristic: the model gives no particle
 * positions): a name is a letter x, y or z and a suffix of digits and
 * underscores ("x", "x1", "y_2");
 *   translation along x   every x-named coordinate shifted together;
 *   rotation about z      (x_s, y_s) -> (-y_s, x_s) for every suffix s, when
 *                         every x- and y-named coordinate has its partner
 *                         (about x: (y, z), about y: (z, x));
 * the invariant ones (or quasi-invariant: dL/deps = dF/dt) go to found[],
 * named "linear momentum along x", "angular momentum about z".
 * Models with constraints: cyclic and Jacobi only (Noether and proposed
 * integrals need a state on the constraint manifold: QD_ERR_ARG from those).
 * NULL on failure, reason in ctx. */
QD_API qd_integrals *qd_integrals_derive(qd_ctx *ctx, const qd_model *m, qd_eom *e,
                                  const qd_integrals_opts *opts);
QD_API void qd_integrals_free(qd_integrals *I);

/* Only the cyclic coordinates of m (equations e, not solved here): out has
 * room for e->n entries, *ncyclic receives how many there are.  Cheap: no
 * accelerations are needed (qdot check uses it). */
QD_API qd_status qd_integrals_cyclic(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                              qd_int_cyclic *out, size_t *ncyclic);

/* Noether's integral of the field xi (n components in q and t; NULL entries
 * are 0).  out->xi is malloc'd: qd_noether_clear frees it. */
QD_API qd_status qd_integrals_noether(qd_ctx *ctx, qd_integrals *I, const char *name,
                               const qd_expr *const *xi, qd_noether *out);
QD_API void qd_noether_clear(qd_noether *nt);

/* Is expr (in q, q', t and the parameters) conserved?  QD_ERR_ARG for an
 * expression with accelerations. */
QD_API qd_status qd_integrals_check(qd_ctx *ctx, qd_integrals *I, const char *name,
                             const qd_expr *expr, qd_int_proposed *out);


/* ---- the model's own statements, and the whole written out --------------- */

/* Noether's integral of each `symmetry` statement of m and the check of
 * each `integral` statement (qd_integrals_noether, qd_integrals_check), in
 * the model's order; I derived from m. */
typedef struct qd_integrals_given {
    size_t nnoether;
    qd_noether *noether;
    size_t nproposed;
    qd_int_proposed *proposed;
} qd_integrals_given;
QD_API qd_status qd_integrals_given_derive(qd_ctx *ctx, qd_integrals *I, const qd_model *m,
                                           qd_integrals_given *out);
QD_API void qd_integrals_given_free(qd_integrals_given *g);

/* I and g (may be NULL: none given) written for a reader as text, appended
 * to out: the cyclic coordinates, Jacobi's integral and the energy, the
 * energy balance, the symmetries found (when searched), Noether's integrals
 * of the given symmetries and the proposed integrals; each verdict says
 * whether it rests on random states only.  model_name (may be NULL) heads
 * it.  QD_ERR_NOMEM when out could not grow. */
QD_API qd_status qd_integrals_print(qd_ctx *ctx, const qd_integrals *I,
                                    const qd_integrals_given *g, const char *model_name,
                                    qd_buf *out);
/* The integrals found, as LaTeX for a paper or a notebook (`qdot integrals
 * --format latex`, Python's _repr_latex_): one aligned environment, a row
 * per integral, p_q of each cyclic coordinate, Jacobi's h, the Noether
 * integrals found and given and the proposed ones, each with its verdict
 * in words (conserved, not conserved, could not decide; "numerically" when
 * it rests on random states).  QD_ERR_NOMEM when out could not grow. */
QD_API qd_status qd_integrals_latex(qd_ctx *ctx, const qd_integrals *I,
                                    const qd_integrals_given *g, qd_buf *out);
/* The same as one JSON document and a newline: "model", "coordinates", "L",
 * "cyclic", "jacobi", "energy_balance", "found", "tested", "noether",
 * "proposed" (docs/cli.md shows one). */
QD_API qd_status qd_integrals_json(qd_ctx *ctx, const qd_integrals *I,
                                   const qd_integrals_given *g, const char *model_name,
                                   qd_buf *out);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_integrals_derive (opts); qd_integrals_print
 * (g, model_name); qd_integrals_json (g, model_name). An array
 * whose count is 0 may be NULL. */
#endif
