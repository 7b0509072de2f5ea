/*
 * qdot/control.h - linear-quadratic regulation: the continuous algebraic
 * Riccati equation and the LQR gain.
 *
 * For x' = A x + B u and the cost  J = integral of x^T Q x + u^T R u dt,
 * the stabilizing solution X of
 *
 *     A^T X + X A - X B R^-1 B^T X + Q = 0
 *
 * gives the optimal feedback u = -K x with K = R^-1 B^T X, and every
 * eigenvalue of A - B K in the open left half plane.  It exists (and is
 * unique, symmetric, positive semidefinite) when R is symmetric positive
 * definite, Q symmetric positive semidefinite, (A, B) stabilizable and no
 * mode of A on the imaginary axis is unseen by Q.
 *
 * Method (Laub 1979, "A Schur method for solving algebraic Riccati
 * equations", IEEE TAC 24): the Hamiltonian matrix
 *     H = [A, -B R^-1 B^T; -Q, -A^T]
 * has eigenvalues in pairs s, -s; LAPACK dgees orders its real Schur form
 * with the n stable ones first, whose Schur vectors [U11; U21] span the
 * stable invariant subspace, and X = U21 U11^-1, then refined by Newton
 * (Kleinman) steps while they shrink the residual (docs/design.md, "The
 * Riccati equation").
 *
 * Matrices are row-major: A[i*n + j] is row i, column j; A n*n, B n*m,
 * Q n*n, R m*m; X n*n and K m*n.  The result's arrays are malloc'd from the
 * context's allocator; qd_care_result_free releases them.
 */
#ifndef QDOT_CONTROL_H
#define QDOT_CONTROL_H

#include <stddef.h>
#include "expr.h"
#include "json.h"
#include "print.h"
#include "statespace.h"
#include "status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Why qd_care_solve failed, so a caller need not read the message. */
typedef enum qd_care_failure {
    QD_CARE_OK,
    QD_CARE_R_NOT_PD,         /* R not symmetric positive definite (dpotrf fails) */
    QD_CARE_Q_NOT_PSD,        /* Q not symmetric positive semidefinite */
    QD_CARE_NOT_STABILIZABLE, /* a mode with Re s >= 0 that B does not reach: (A, B) */
    QD_CARE_NOT_DETECTABLE,   /* a mode on the imaginary axis that Q does not see: (Q, A) */
    QD_CARE_IMAGINARY_AXIS,   /* H has eigenvalues on the imaginary axis (fewer than n
                               * stable), though neither test above fired */
    QD_CARE_ILL_CONDITIONED,  /* U11 numerically singular: no reliable X */
    QD_CARE_NOT_STABILIZING   /* A - B K came out with an eigenvalue of Re s >= 0 */
} qd_care_failure;

/* The stabilizing solution and what it gives. */
typedef struct qd_care_result {
    size_t n, m;
    double *X;             /* n*n, symmetric */
    double *K;             /* m*n, the gain: u = -K x */
    double *eig_re, *eig_im; /* n eigenvalues of A - B K (dgeev), by Re descending */
    /* ||A^T X + X A - X G X + Q||_F / (||Q||_F + 2 ||A^T X||_F + ||X G X||_F),
     * G = B R^-1 B^T: the residual relative to the size of its terms, after
     * the Newton steps that refine the Schur solution */
    double residual;
    double rcond;          /* reciprocal condition number of U11 (1-norm, dgecon) */
    qd_care_failure failure; /* QD_CARE_OK on success; says why otherwise */
    double mode_re, mode_im; /* the offending eigenvalue (NOT_STABILIZABLE, NOT_DETECTABLE) */
} qd_care_result;

/* Below this reciprocal condition number U11 counts as singular. */
#define QD_CARE_RCOND_MIN 1e-12

/* Solve the Riccati equation for the stabilizing X, the gain K and the
 * closed-loop eigenvalues.  QD_ERR_ARG for n or m zero, a NULL or
 * non-finite entry, and for data with no stabilizing solution (R not
 * positive definite, Q not positive semidefinite, not stabilizable, not
 * detectable on the imaginary axis: out->failure says which, the message
 * names the mode); QD_ERR_NUMERIC when LAPACK fails or U11 is
 * ill-conditioned; QD_ERR_NOMEM.  out is zeroed first and holds arrays
 * only on QD_OK, but out->failure is set either way. */
QD_API qd_status qd_care_solve(qd_ctx *ctx, size_t n, size_t m, const double *A,
                               const double *B, const double *Q, const double *R,
                               qd_care_result *out);
QD_API void qd_care_result_free(qd_care_result *r); /* NULL is fine */

/* ---- weights and matrices from text (src/linear/lqr_read.c) ------------- */

/* Read text into Q (n*n) and R (m*m), row-major arrays the caller owns.
 * text is "Q = W, R = W" in either order, each given once, where W is
 *   a number c              c times the identity,
 *   diag(d1, ..., dk)       k = the size,
 *   [[a11, a12, ...], ...]  the full matrix, row by row.
 * QD_ERR_PARSE for text that does not read so, the error located at its
 * place in text (qd_ctx_diag: offset, line, col), its message what was
 * expected there.  Symmetry and definiteness are left to qd_care_solve,
 * which names what is wrong with them. */
QD_API qd_status qd_lqr_weights_read(qd_ctx *ctx, const char *text, size_t n, size_t m,
                                     double *Q, double *R);

/* A matrix of numbers, row-major: a[i*cols + j]. */
typedef struct qd_matrix {
    size_t rows, cols;
    double *a;
} qd_matrix;

/* A matrix "[[a11, a12, ...], [a21, ...], ...]" of any shape (rows of equal
 * length, at most 4096 of them) into *out; QD_ERR_PARSE located as above
 * (out zeroed).  qd_matrix_free releases it. */
QD_API qd_status qd_matrix_read(qd_ctx *ctx, const char *text, qd_matrix *out);
QD_API void qd_matrix_free(qd_matrix *m); /* NULL is fine */

/* ---- a system given as text (src/linear/lqr_system.c) ------------------- */

/* x' = A x + B u and its LQR weights, as `qdot lqr` takes them. */
typedef struct qd_lqr_system {
    qd_matrix A, B;          /* n*n, n*m */
    double *Q, *R;           /* n*n, m*m */
} qd_lqr_system;

/* A and B by qd_matrix_read, the weights by qd_lqr_weights_read, into *out
 * (overwritten; qd_lqr_system_free, also after a failure).  Each error
 * names its text (qd_diag.name "A", "B" or "weights"): the readers'
 * QD_ERR_PARSE located in it, QD_ERR_ARG for an A that is not square or a
 * B without one row per state. */
QD_API qd_status qd_lqr_system_read(qd_ctx *ctx, const char *A, const char *B,
                                    const char *weights, qd_lqr_system *out);
QD_API void qd_lqr_system_free(qd_lqr_system *s);

/* ---- LQR on a model (src/linear/lqr_model.c) ----------------------------- */

/* The LQR design on s (qd_linearize of a model about a point) for the
 * weights text (as qd_lqr_weights_read: Q on the states dx, R on the inputs
 * du): out as qd_care_solve's.  QD_ERR_ARG (diag name "lqr") when s has no
 * inputs to feed back; the reader's QD_ERR_PARSE; qd_care_solve's errors. */
QD_API qd_status qd_lqr_design(qd_ctx *ctx, const qd_statespace *s, const char *weights,
                               qd_care_result *out);

/* The feedback of input k (0 <= k < s->nu) as an expression in the states:
 *     u_k = u0_k - sum_j K[k][j] (x_j - x0_j)
 * about the point s was linearized at, given as for qd_linearize (npt
 * symbols syms with exact values vals; a state or input not given is 0),
 * so the point's values stay exact.  NULL on an error (QD_ERR_ARG for k out
 * of range or r not a design on s; QD_ERR_NOMEM). */
QD_API const qd_expr *qd_lqr_feedback(qd_ctx *ctx, const qd_statespace *s,
                                      const qd_care_result *r, size_t npt,
                                      const qd_expr *const *syms, const qd_expr *const *vals,
                                      size_t k);

/* ---- the design printed (src/linear/lqr_print.c) ------------------------- */

typedef enum qd_lqr_format {
    QD_LQR_TEXT, /* K with the states and inputs named, X, the closed loop, 10 digits */
    QD_LQR_JSON, /* "states", "inputs", "K", "X", "closed_loop_eigenvalues", "residual",
                    "rcond": every digit */
    QD_LQR_C     /* K as a static const double array, every digit, the names in a comment */
} qd_lqr_format;

/* The design r appended to out in format fmt (JSON ends with a newline).
 * The states and inputs are named from s (the linearization r was designed
 * on) or, for s NULL, x1..xn and u1..um.  QD_ERR_NOMEM when out failed,
 * QD_ERR_NUMERIC (nothing appended) when a number of r is not finite. */
QD_API qd_status qd_lqr_print(const qd_statespace *s, const qd_care_result *r,
                              qd_lqr_format fmt, qd_buf *out);
/* The design's JSON object (the keys above) into j, for a caller that nests
 * it in its own document; s as for qd_lqr_print. */
QD_API void qd_lqr_json(qd_json *j, const qd_statespace *s, const qd_care_result *r);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_lqr_feedback (syms, vals);
 * qd_lqr_print (s); qd_lqr_json (s). An array whose count is 0 may be NULL. */
#endif
