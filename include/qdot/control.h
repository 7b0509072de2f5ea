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

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. No pointer argument here accepts
 * NULL otherwise. An array whose count is 0 may be NULL. */
#endif
