/*
 * qdot/statespace.h - a model with inputs linearized into state-space form
 * about an operating point, and its controllability and observability.
 *
 * With x = (q, q') (state order: the coordinates, then their velocities,
 * both in declaration order), u the model's inputs (`inputs F, ...`) and y
 * its outputs (`outputs y1 = EXPR, ...`), about a point (x0, u0):
 *
 *     dx' = A dx + B du,     dy = C dx + D du,     dx = x - x0, du = u - u0
 *
 * and x' = xdot0 + A dx + B du, xdot0 = (q'0, q''0) the affine term (zero
 * only at an equilibrium).  From M(q, q') q'' = f(q, q', u, t):
 *
 *     A = [0 I; dq''/dq  dq''/dq'],   B = [0; dq''/du],
 *     dq''/dz = M^-1 (df/dz - dM/dz q''0)        (z = q_k, q'_k or u_k),
 *
 * every derivative exact (symbolic) and evaluated at the point; C = dy/dx,
 * D = dy/du.  The numbers solve with M at the point (LAPACK dgesv); the
 * symbolic A, B, C, D (expressions in the parameters, the point put in
 * exactly) solve by fraction-free elimination and are NULL when that grows
 * beyond QD_SS_MAX_OPS operations per entry.
 *
 * Models whose equations keep multipliers (constraints) are refused
 * (QD_ERR_ARG): qd_conlin_about (qdot/conlin.h) gives A, B, C, D over
 * the independent states on their state manifold.
 */
#ifndef QDOT_STATESPACE_H
#define QDOT_STATESPACE_H

#include <stdbool.h>
#include <stddef.h>
#include "expr.h"
#include "mech.h"
#include "model.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The largest symbolic entry kept, in operations (qd_count_ops). */
#define QD_SS_MAX_OPS 4000
/* Rank tolerance of the Kalman matrices: a singular value counts when it
 * exceeds QD_SS_RANK_TOL times the largest.  A mode is unreachable by B
 * (PBH) when |w^H B| <= QD_SS_RANK_TOL |w| |B| for its left eigenvector w
 * (and unseen by C when |C v| <= QD_SS_RANK_TOL |C| |v|). */
#define QD_SS_RANK_TOL 1e-9

typedef struct qd_statespace {
    size_t n;                    /* coordinates */
    size_t nx, nu, ny;           /* 2n states, inputs, outputs */
    const qd_expr **states;      /* nx: q_j then q'_j (kernel symbols) */
    const qd_expr **inputs;      /* nu (the model's) */
    const char **outputs;        /* ny (the model's names) */
    /* numbers, row-major: A nx*nx, B nx*nu, C ny*nx, D ny*nu */
    double *A, *B, *C, *D;
    double *xdot0;               /* nx: x' at the point */
    double *y0;                  /* ny: the outputs at the point */
    /* the same as expressions in the parameters (each simplified), or all
     * NULL when the elimination grew too large */
    const qd_expr **Asym, **Bsym, **Csym, **Dsym;
    /* eigenvalues of A (dgeev), sorted by real part descending then
     * imaginary part; right eigenvectors by column (vec_re[i*nx + j]:
     * component i of vector j), scaled to largest component 1 */
    double *eig_re, *eig_im, *vec_re, *vec_im;
    /* ranks of [B AB ... A^(nx-1) B] and [C; CA; ...; C A^(nx-1)] */
    size_t rank_ctrb, rank_obsv;
    bool controllable, observable; /* full rank (observable false when ny = 0) */
    /* PBH: the eigenvalues (indices into eig_*) whose modes B does not
     * reach and C does not see */
    size_t nuncontrollable, nunobservable;
    size_t *uncontrollable, *unobservable;
} qd_statespace;

/* Linearize e (qd_eom_derive of m) about the point syms = vals: vals are
 * exact expressions (0, pi, 1/2) for coordinates, velocities (qd_jet order
 * 1), inputs and t; symbols not given are 0; the parameters take their
 * values in m (apply --set to m first).  QD_ERR_ARG for a model with
 * multipliers or a symbol of the point that is none of these;
 * QD_ERR_SINGULAR when M is singular at the point; QD_ERR_NUMERIC when an
 * entry is not finite there or LAPACK fails.  Free with
 * qd_statespace_free (also after a failure). */
QD_API qd_status qd_linearize(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t npt,
                              const qd_expr *const *syms, const qd_expr *const *vals,
                              qd_statespace *out);
QD_API void qd_statespace_free(qd_statespace *s);
/* qd_linearize about a point written "q=V, q'=V, F=V, ..." (about NULL:
 * every value 0): coordinates, velocities, m's inputs and t, each value
 * kept exact (qd_state_read's exact values: pi/6 stays pi/6).  The reader's
 * errors located in about; then qd_linearize's (a parameter named is its
 * QD_ERR_ARG).  Free out with qd_statespace_free (also after a failure). */
QD_API qd_status qd_linearize_about(qd_ctx *ctx, const qd_eom *e, const qd_model *m,
                                    const char *about, qd_statespace *out);

/* ---- the state-space form printed (src/linear/statespace_print.c) -------- */

/* The formats of qd_statespace_render (qd_render_format has no Octave, and
 * the ranks of linear lie below render). */
typedef enum qd_ss_format {
    QD_SS_TEXT,   /* for a reader */
    QD_SS_JSON,   /* for programs */
    QD_SS_C,      /* static const double arrays */
    QD_SS_SYMPY,  /* SymPy Matrix assignments */
    QD_SS_OCTAVE  /* Octave / MATLAB matrix assignments */
} qd_ss_format;

/* The LQR design of qdot/control.h (qd_lqr_design on s). */
struct qd_care_result;

/* s, the answer of qd_linearize, appended to out in format fmt, followed by
 * the LQR design lqr found on s (NULL: none).
 *
 * Text: the lines "states:", "inputs:", "outputs:" (the names, or "none");
 * A, B, C and D as bracketed rows (a matrix with no entries left out), each
 * number shortest round-trip (qd_double_format) right-aligned to the widest;
 * x' at the point when it is not an equilibrium; the nonzero exact entries
 * of the acceleration rows, "A[rate, state] = EXPR" and "B[rate, input] =
 * EXPR", when the exact form was kept; the eigenvalues of A ("re +- im i");
 * "controllable:" and, with outputs, "observable:" with the Kalman rank and
 * QD_SS_RANK_TOL, each followed by the modes B does not reach (C does not
 * see), each named by its eigenvalue and the states its eigenvector moves
 * (a component above 1e-6 of the largest); then lqr as qd_lqr_print's text.
 *
 * JSON (one object, then a newline): "states", "inputs", "outputs" (names),
 * "A", "B", "C", "D", "xdot0" (row arrays of numbers), "A_exact",
 * "B_exact" (row arrays of expressions as text, or null), "eigenvalues"
 * ([re, im] pairs), "rank_tolerance", "controllable",
 * "controllability_rank", "uncontrollable_modes", "observable",
 * "observability_rank", "unobservable_modes" (each mode {"eigenvalue":
 * [re, im], "states": [...]}), and with lqr, "lqr": qd_lqr_json's object.
 *
 * C, SymPy, Octave: a comment naming x and u, then A, B and, with outputs,
 * C and D as assignments in that language, the exact entries where they
 * were kept (printed by qd_print in C or SymPy syntax), else the numbers
 * (every digit; the comment says so); in C lqr follows as qd_lqr_print's C.
 *
 * out is unchanged on failure.  QD_ERR_ARG for a format not in
 * qd_ss_format and for lqr with SymPy or Octave (a design prints as text,
 * JSON or C); QD_ERR_NUMERIC for a number JSON cannot hold (not finite) or
 * a design that is not finite; QD_ERR_NOMEM.  Each is recorded in ctx. */
QD_API qd_status qd_statespace_render(qd_ctx *ctx, const qd_statespace *s,
                                      const struct qd_care_result *lqr, qd_ss_format fmt,
                                      qd_buf *out);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_linearize (syms, vals); qd_linearize_about (about);
 * qd_statespace_render (lqr). An array whose
 * count is 0 may be NULL. */
#endif
