/*
 * src/linear/care.c - the continuous algebraic Riccati equation and the LQR
 * gain by the Schur method on the Hamiltonian matrix (qdot/control.h).
 *
 * Laub, "A Schur method for solving algebraic Riccati equations", IEEE
 * Trans. Automatic Control 24 (1979) 913-921: the n stable eigenvalues of
 *     H = [A, -G; -Q, -A^T],   G = B R^-1 B^T,
 * ordered first in H's real Schur form (dgees with a select function) give
 * Schur vectors [U11; U21] spanning the stable invariant subspace, and the
 * stabilizing solution is X = U21 U11^-1.  Before that the data are checked
 * so that a failure names its cause rather than surfacing as a singular
 * U11: R by Cholesky, Q by its eigenvalues, stabilizability and
 * detectability on the imaginary axis by the Popov-Belevitch-Hautus test
 * (rank [A - sI, B] = n at each eigenvalue s of A with Re s >= 0).
 *
 * LAPACK works column-major; the public arrays are row-major, so every
 * matrix is copied in transposed and the results copied out.
 */
#include "qdot/control.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* LAPACK (Fortran, column-major); one-character lengths not passed, as is
 * usual from C for length 1 (src/linear/eigen.c). */
typedef int (*care_select)(const double *wr, const double *wi);
extern void dpotrf_(const char *uplo, const int *n, double *a, const int *lda, int *info);
extern void dpotrs_(const char *uplo, const int *n, const int *nrhs, const double *a,
                    const int *lda, double *b, const int *ldb, int *info);
extern void dsyev_(const char *jobz, const char *uplo, const int *n, double *a, const int *lda,
                   double *w, double *work, const int *lwork, int *info);
extern void dgeev_(const char *jobvl, const char *jobvr, const int *n, double *a, const int *lda,
                   double *wr, double *wi, double *vl, const int *ldvl, double *vr,
                   const int *ldvr, double *work, const int *lwork, int *info);
extern void dgesvd_(const char *jobu, const char *jobvt, const int *m, const int *n, double *a,
                    const int *lda, double *s, double *u, const int *ldu, double *vt,
                    const int *ldvt, double *work, const int *lwork, int *info);
extern void dgees_(const char *jobvs, const char *sort, care_select select, const int *n,
                   double *a, const int *lda, int *sdim, double *wr, double *wi, double *vs,
                   const int *ldvs, double *work, const int *lwork, int *bwork, int *info);
extern void dtrsyl_(const char *trana, const char *tranb, const int *isgn, const int *m,
                    const int *n, const double *a, const int *lda, const double *b,
                    const int *ldb, double *c, const int *ldc, double *scale, int *info);
extern void dgetrf_(const int *m, const int *n, double *a, const int *lda, int *ipiv, int *info);
extern void dgecon_(const char *norm, const int *n, const double *a, const int *lda,
                    const double *anorm, double *rcond, double *work, int *iwork, int *info);
extern void dgetrs_(const char *trans, const int *n, const int *nrhs, const double *a,
                    const int *lda, const int *ipiv, double *b, const int *ldb, int *info);

/* Relative sizes under which a symmetry defect, an eigenvalue's real part or
 * a PBH singular value counts as zero.  Eigenvalues of A carry errors of
 * eps ||A|| (more at a defective one), so 1e-9 leaves room above them. */
#define CARE_SYM_TOL 1e-12
#define CARE_ZERO_TOL 1e-9

/* Everything one solve holds, column-major, so cleanup is one function. */
typedef struct care_work {
    qd_ctx *ctx;
    int n, m;
    double *A, *B, *Q, *Rc; /* Rc: R's Cholesky factor (upper) */
    double *G, *Y;          /* G = B R^-1 B^T (n*n); Y = R^-1 B^T (m*n) */
    double *X;              /* n*n */
    double normA, normB, normQ, normG;
} care_work;

static void work_free(care_work *w) {
    qd__free(w->A);
    qd__free(w->B);
    qd__free(w->Q);
    qd__free(w->Rc);
    qd__free(w->G);
    qd__free(w->Y);
    qd__free(w->X);
}

static double *col_major(qd_ctx *ctx, size_t rows, size_t cols, const double *rm) {
    double *c = qd__malloc(ctx, (rows * cols > 0 ? rows * cols : 1) * sizeof *c);
    if (c)
        for (size_t i = 0; i < rows; i++)
            for (size_t j = 0; j < cols; j++)
                c[i + j * rows] = rm[i * cols + j];
    return c;
}

static double frob(size_t len, const double *a) {
    double s = 0;
    for (size_t i = 0; i < len; i++)
        s += a[i] * a[i];
    return sqrt(s);
}

static bool all_finite(size_t len, const double *a) {
    for (size_t i = 0; i < len; i++)
        if (!isfinite(a[i]))
            return false;
    return true;
}

/* The largest |a_ij - a_ji| against the largest |a_ij|: symmetric enough? */
static bool symmetric(int n, const double *a) {
    double big = 0, off = 0;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            big = fmax(big, fabs(a[i + j * n]));
            off = fmax(off, fabs(a[i + j * n] - a[j + i * n]));
        }
    return off <= CARE_SYM_TOL * big;
}

static qd_status fail(qd_care_result *out, qd_care_failure why, qd_status st) {
    out->failure = why;
    return st;
}

/* R symmetric positive definite: its Cholesky factor, kept for R^-1 B^T. */
static qd_status check_r(care_work *w, const double *R, qd_care_result *out) {
    int info = 0;
    if (!(w->Rc = col_major(w->ctx, (size_t)w->m, (size_t)w->m, R)))
        return QD_ERR_NOMEM;
    if (!symmetric(w->m, w->Rc)) {
        qd_ctx_error(w->ctx, QD_ERR_ARG, "R is not symmetric");
        return fail(out, QD_CARE_R_NOT_PD, QD_ERR_ARG);
    }
    dpotrf_("U", &w->m, w->Rc, &w->m, &info);
    if (info != 0) {
        qd_ctx_error(w->ctx, QD_ERR_ARG,
                     "R is not positive definite (its leading minor of order %d is not positive)",
                     info);
        return fail(out, QD_CARE_R_NOT_PD, QD_ERR_ARG);
    }
    return QD_OK;
}

/* The eigenvalues of a symmetric matrix (ascending), by dsyev. */
static bool sym_eigvals(qd_ctx *ctx, int n, const double *a, double *eig) {
    int info = 0, lwork = 3 * n + 8;
    double *c = qd__malloc(ctx, (size_t)n * (size_t)n * sizeof *c);
    double *work = qd__malloc(ctx, (size_t)lwork * sizeof *work);
    if (c && work) {
        memcpy(c, a, (size_t)n * (size_t)n * sizeof *c);
        dsyev_("N", "U", &n, c, &n, eig, work, &lwork, &info);
    }
    bool ok = c && work && info == 0;
    qd__free(c);
    qd__free(work);
    return ok;
}

/* Q symmetric positive semidefinite, to rounding: its smallest eigenvalue
 * no more negative than CARE_ZERO_TOL times its largest. */
static qd_status check_q(care_work *w, qd_care_result *out) {
    if (!symmetric(w->n, w->Q)) {
        qd_ctx_error(w->ctx, QD_ERR_ARG, "Q is not symmetric");
        return fail(out, QD_CARE_Q_NOT_PSD, QD_ERR_ARG);
    }
    double *eig = qd__malloc(w->ctx, (size_t)w->n * sizeof *eig);
    if (!eig)
        return QD_ERR_NOMEM;
    qd_status st = QD_OK;
    if (!sym_eigvals(w->ctx, w->n, w->Q, eig)) {
        st = qd__ctx_nomem(w->ctx) ? QD_ERR_NOMEM : QD_ERR_NUMERIC;
        qd_ctx_error(w->ctx, st, "the eigenvalues of Q (dsyev) failed");
    } else if (eig[0] < -CARE_ZERO_TOL * fmax(fabs(eig[w->n - 1]), fabs(eig[0]))) {
        qd_ctx_error(w->ctx, QD_ERR_ARG,
                     "Q is not positive semidefinite (it has the eigenvalue %.6g)", eig[0]);
        st = fail(out, QD_CARE_Q_NOT_PSD, QD_ERR_ARG);
    }
    qd__free(eig);
    return st;
}

/* Y = R^-1 B^T (m*n) from R's Cholesky factor, then G = B Y (n*n). */
static qd_status weight_inputs(care_work *w) {
    int n = w->n, m = w->m, info = 0;
    w->Y = qd__malloc(w->ctx, (size_t)m * (size_t)n * sizeof *w->Y);
    w->G = qd__calloc(w->ctx, (size_t)n * (size_t)n, sizeof *w->G);
    if (!w->Y || !w->G)
        return QD_ERR_NOMEM;
    for (int i = 0; i < m; i++)
        for (int j = 0; j < n; j++)
            w->Y[i + j * m] = w->B[j + i * n];
    dpotrs_("U", &m, &n, w->Rc, &m, w->Y, &m, &info);
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            for (int k = 0; k < m; k++)
                w->G[i + j * n] += w->B[i + k * n] * w->Y[k + j * m];
    w->normG = frob((size_t)n * (size_t)n, w->G);
    return QD_OK;
}

/* The eigenvalues of a general n*n column-major matrix (a is kept). */
static bool gen_eigvals(qd_ctx *ctx, int n, const double *a, double *wr, double *wi) {
    int info = 0, one = 1, lwork = 8 * n + 16;
    double *c = qd__malloc(ctx, (size_t)n * (size_t)n * sizeof *c), dummy = 0;
    double *work = qd__malloc(ctx, (size_t)lwork * sizeof *work);
    if (c && work) {
        memcpy(c, a, (size_t)n * (size_t)n * sizeof *c);
        dgeev_("N", "N", &n, c, &n, wr, wi, &dummy, &one, &dummy, &one, work, &lwork, &info);
    }
    bool ok = c && work && info == 0;
    qd__free(c);
    qd__free(work);
    return ok;
}

/* The smallest singular value of the complex rows*cols matrix re + i im,
 * through its real embedding [re, -im; im, re], whose singular values are
 * the complex ones twice over: what PBH asks for, with LAPACK's real SVD. */
static bool sigma_min(qd_ctx *ctx, int rows, int cols, const double *re, const double *im,
                      double *out) {
    int r2 = 2 * rows, c2 = 2 * cols, info = 0, one = 1;
    int k = r2 < c2 ? r2 : c2, lwork = 5 * (r2 + c2) + 64;
    double *e = qd__malloc(ctx, (size_t)r2 * (size_t)c2 * sizeof *e), dummy = 0;
    double *s = qd__malloc(ctx, (size_t)k * sizeof *s);
    double *work = qd__malloc(ctx, (size_t)lwork * sizeof *work);
    if (e && s && work) {
        for (int j = 0; j < cols; j++)
            for (int i = 0; i < rows; i++) {
                double a = re[i + j * rows], b = im[i + j * rows];
                e[i + j * r2] = a;
                e[i + rows + j * r2] = b;
                e[i + (j + cols) * r2] = -b;
                e[i + rows + (j + cols) * r2] = a;
            }
        dgesvd_("N", "N", &r2, &c2, e, &r2, s, &dummy, &one, &dummy, &one, work, &lwork, &info);
    }
    bool ok = e && s && work && info == 0;
    if (ok)
        *out = s[k - 1];
    qd__free(e);
    qd__free(s);
    qd__free(work);
    return ok;
}

/* PBH at the eigenvalue s of A: the smallest singular value of
 * [A - sI, B] (beside: controllability) or [A - sI; Q] (observability). */
static bool pbh(care_work *w, double sre, double sim, bool beside, double *out) {
    int n = w->n, extra = beside ? w->m : n;
    int rows = beside ? n : 2 * n, cols = beside ? n + w->m : n;
    const double *E = beside ? w->B : w->Q;
    double *re = qd__calloc(w->ctx, (size_t)rows * (size_t)cols, sizeof *re);
    double *im = qd__calloc(w->ctx, (size_t)rows * (size_t)cols, sizeof *im);
    bool ok = re && im;
    for (int i = 0; ok && i < n; i++) {
        for (int j = 0; j < n; j++)
            re[i + j * rows] = w->A[i + j * n] - (i == j ? sre : 0);
        im[i + i * rows] = -sim;
        for (int k = 0; k < extra; k++) {
            if (beside)
                re[i + (n + k) * rows] = E[i + k * n];
            else
                re[n + i + k * rows] = E[i + k * n];
        }
    }
    ok = ok && sigma_min(w->ctx, rows, cols, re, im, out);
    qd__free(re);
    qd__free(im);
    return ok;
}

/* "1", "0.5 +- 2i": an eigenvalue as a message shows it. */
static void mode_text(char *buf, size_t len, double re, double im) {
    if (im == 0)
        snprintf(buf, len, "%.6g", re);
    else
        snprintf(buf, len, "%.6g +- %.6gi", re, fabs(im));
}

static qd_status mode_error(care_work *w, qd_care_result *out, double re, double im, bool ctrl) {
    char s[64];
    mode_text(s, sizeof s, re, im);
    if (ctrl)
        qd_ctx_error(w->ctx, QD_ERR_ARG,
                     "(A, B) is not stabilizable: the mode s = %s of A (Re s >= 0) is not "
                     "reached by the inputs", s);
    else
        qd_ctx_error(w->ctx, QD_ERR_ARG,
                     "(Q, A) is not detectable: the mode s = %s of A, on the imaginary axis, is "
                     "not seen by Q", s);
    out->mode_re = re;
    out->mode_im = im;
    return fail(out, ctrl ? QD_CARE_NOT_STABILIZABLE : QD_CARE_NOT_DETECTABLE, QD_ERR_ARG);
}

/* PBH on every eigenvalue of A that could matter: Re s >= 0 must be
 * reached by B (stabilizable); Re s = 0 must be seen by Q (else H has that
 * eigenvalue on the imaginary axis and no stabilizing X exists). */
static qd_status check_modes(care_work *w, qd_care_result *out) {
    int n = w->n;
    double *wr = qd__malloc(w->ctx, (size_t)n * sizeof *wr);
    double *wi = qd__malloc(w->ctx, (size_t)n * sizeof *wi);
    qd_status st = wr && wi ? QD_OK : QD_ERR_NOMEM;
    if (st == QD_OK && !gen_eigvals(w->ctx, n, w->A, wr, wi)) {
        st = qd__ctx_nomem(w->ctx) ? QD_ERR_NOMEM : QD_ERR_NUMERIC;
        qd_ctx_error(w->ctx, st, "the eigenvalues of A (dgeev) failed");
    }
    double axis = CARE_ZERO_TOL * fmax(w->normA, 1e-300);
    double ctrl_tol = CARE_ZERO_TOL * fmax(fmax(w->normA, w->normB), 1e-300);
    double obs_tol = CARE_ZERO_TOL * fmax(fmax(w->normA, w->normQ), 1e-300);
    for (int k = 0; st == QD_OK && k < n; k++) {
        double sig = 0;
        if (wi[k] < 0 || wr[k] < -axis) /* a conjugate is tested once; stable modes pass */
            continue;
        if (!pbh(w, wr[k], wi[k], true, &sig))
            st = QD_ERR_NOMEM;
        else if (sig <= ctrl_tol)
            st = mode_error(w, out, wr[k], wi[k], true);
        else if (fabs(wr[k]) <= axis && !pbh(w, wr[k], wi[k], false, &sig))
            st = QD_ERR_NOMEM;
        else if (fabs(wr[k]) <= axis && sig <= obs_tol)
            st = mode_error(w, out, wr[k], wi[k], false);
    }
    qd__free(wr);
    qd__free(wi);
    return st;
}

static int stable_first(const double *wr, const double *wi) {
    (void)wi;
    return *wr < 0;
}

/* H's real Schur form with the stable eigenvalues first: the Schur
 * vectors (2n*2n, column-major) in vs.  Fewer than n stable eigenvalues
 * means some on the imaginary axis. */
static qd_status schur_stable(care_work *w, double *vs, qd_care_result *out) {
    int n = w->n, N = 2 * n, sdim = 0, info = 0, lwork = 8 * N + 64;
    double *H = qd__malloc(w->ctx, (size_t)N * (size_t)N * sizeof *H);
    double *wr = qd__malloc(w->ctx, 2 * (size_t)N * sizeof *wr);
    double *work = qd__malloc(w->ctx, (size_t)lwork * sizeof *work);
    int *bwork = qd__malloc(w->ctx, (size_t)N * sizeof *bwork);
    qd_status st = H && wr && work && bwork ? QD_OK : QD_ERR_NOMEM;
    for (int i = 0; st == QD_OK && i < n; i++)
        for (int j = 0; j < n; j++) {
            H[i + j * N] = w->A[i + j * n];
            H[i + (j + n) * N] = -w->G[i + j * n];
            H[i + n + j * N] = -w->Q[i + j * n];
            H[i + n + (j + n) * N] = -w->A[j + i * n];
        }
    if (st == QD_OK)
        dgees_("V", "S", stable_first, &N, H, &N, &sdim, wr, wr + N, vs, &N, work, &lwork, bwork,
               &info);
    if (st == QD_OK && info != 0 && info != N + 2) {
        qd_ctx_error(w->ctx, QD_ERR_NUMERIC,
                     "the Schur form of the Hamiltonian matrix (dgees) failed: info %d", info);
        st = QD_ERR_NUMERIC;
    } else if (st == QD_OK && sdim != n) {
        qd_ctx_error(w->ctx, QD_ERR_ARG,
                     "the Hamiltonian matrix has %d stable eigenvalues, not %d: some lie on the "
                     "imaginary axis, so (A, B) is not stabilizable or (Q, A) not detectable",
                     sdim, n);
        st = fail(out, QD_CARE_IMAGINARY_AXIS, QD_ERR_ARG);
    }
    qd__free(H);
    qd__free(wr);
    qd__free(work);
    qd__free(bwork);
    return st;
}

/* X U11 = U21, i.e. U11^T X^T = U21^T, by LU with U11's condition checked
 * first; X symmetrized (it is symmetric in exact arithmetic). */
static qd_status solve_x(care_work *w, const double *vs, qd_care_result *out) {
    int n = w->n, N = 2 * n, info = 0;
    double *u = qd__malloc(w->ctx, (size_t)n * (size_t)n * sizeof *u);
    double *work = qd__malloc(w->ctx, 4 * (size_t)n * sizeof *work), anorm = 0;
    int *ipiv = qd__malloc(w->ctx, 2 * (size_t)n * sizeof *ipiv);
    w->X = qd__malloc(w->ctx, (size_t)n * (size_t)n * sizeof *w->X);
    if (!u || !work || !ipiv || !w->X) {
        qd__free(u), qd__free(work), qd__free(ipiv);
        return QD_ERR_NOMEM;
    }
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            u[i + j * n] = vs[j + i * N];         /* U11^T */
            w->X[i + j * n] = vs[n + j + i * N]; /* U21^T */
        }
    for (int j = 0; j < n; j++) {
        double col = 0;
        for (int i = 0; i < n; i++)
            col += fabs(u[i + j * n]);
        anorm = fmax(anorm, col);
    }
    dgetrf_(&n, &n, u, &n, ipiv, &info);
    out->rcond = 0;
    if (info == 0)
        dgecon_("1", &n, u, &n, &anorm, &out->rcond, work, ipiv + n, &info);
    qd_status st = QD_OK;
    if (info != 0 || !(out->rcond >= QD_CARE_RCOND_MIN)) {
        qd_ctx_error(w->ctx, QD_ERR_NUMERIC,
                     "U11 of the stable Schur vectors is ill-conditioned (reciprocal condition "
                     "%.3g < %g): no reliable solution X; (A, B) is close to unstabilizable or the "
                     "weights are badly scaled", out->rcond, QD_CARE_RCOND_MIN);
        st = fail(out, QD_CARE_ILL_CONDITIONED, QD_ERR_NUMERIC);
    } else {
        dgetrs_("N", &n, &n, u, &n, ipiv, w->X, &n, &info);
        for (int i = 0; i < n; i++)
            for (int j = 0; j < i; j++)
                w->X[i + j * n] = w->X[j + i * n] = (w->X[i + j * n] + w->X[j + i * n]) / 2;
    }
    qd__free(u);
    qd__free(work);
    qd__free(ipiv);
    return st;
}

/* c = op(a) op(b), n*n column-major; t: transposed. */
static void mat_mul(int n, const double *a, bool ta, const double *b, bool tb, double *c) {
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            double s = 0;
            for (int k = 0; k < n; k++)
                s += (ta ? a[k + i * n] : a[i + k * n]) * (tb ? b[j + k * n] : b[k + j * n]);
            c[i + j * n] = s;
        }
}

/* res = A^T X + X A - X G X + Q, and its size relative to its terms:
 * ||res||_F / (||Q||_F + 2 ||A^T X||_F + ||X G X||_F) (control.h).
 * t is n*n scratch. */
static double riccati_residual(const care_work *w, const double *X, double *res, double *t) {
    int n = w->n;
    size_t nn = (size_t)n * (size_t)n;
    mat_mul(n, w->G, false, X, false, t);   /* G X */
    mat_mul(n, X, false, t, false, res);    /* X G X */
    double quad = frob(nn, res);
    mat_mul(n, w->A, true, X, false, t);    /* A^T X; X A is its transpose */
    double lin = frob(nn, t);
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            res[i + j * n] = t[i + j * n] + t[j + i * n] - res[i + j * n] + w->Q[i + j * n];
    double scale = w->normQ + 2 * lin + quad;
    return scale > 0 ? frob(nn, res) / scale : frob(nn, res);
}

/* One Newton (Kleinman) step from the Schur solution: with Ac = A - G X,
 * Ac^T E + E Ac = -res(X) by Bartels-Stewart (Ac = U T U^T by dgees, then
 * dtrsyl on T^T Y + Y T = -U^T res U, E = U Y U^T).  Newton alone needs a
 * stabilizing start it cannot find; from the Schur solution it converges
 * quadratically, so one step repairs the digits an ill-conditioned U11 cost
 * (random single-input systems of order 8 gave 3e-10 before it). */
static bool newton_step(care_work *w, const double *res, double *E, double *scratch) {
    int n = w->n, sdim = 0, info = 0, isgn = 1, lwork = 8 * n + 16;
    size_t nn = (size_t)n * (size_t)n;
    double *T = scratch, *U = scratch + nn, *C = scratch + 2 * nn, *wr = scratch + 3 * nn;
    double *work = wr + 2 * (size_t)n, scale = 1;
    mat_mul(n, w->G, false, w->X, false, C);
    for (size_t k = 0; k < nn; k++)
        T[k] = w->A[k] - C[k];
    dgees_("V", "N", NULL, &n, T, &n, &sdim, wr, wr + n, U, &n, work, &lwork, NULL, &info);
    if (info != 0)
        return false;
    mat_mul(n, U, true, res, false, E);
    mat_mul(n, E, false, U, false, C);
    for (size_t k = 0; k < nn; k++)
        C[k] = -C[k];
    dtrsyl_("T", "N", &isgn, &n, &n, T, &n, T, &n, C, &n, &scale, &info);
    if (info < 0 || !(scale > 0))
        return false;
    mat_mul(n, U, false, C, false, T);
    mat_mul(n, T, false, U, true, E);
    for (size_t k = 0; k < nn; k++)
        E[k] /= scale;
    return true;
}

/* X refined by Newton steps while they shrink the residual; *rel its final
 * relative size. */
static qd_status refine(care_work *w, double *rel) {
    size_t nn = (size_t)w->n * (size_t)w->n;
    double *buf = qd__malloc(w->ctx, (6 * nn + 10 * (size_t)w->n + 16) * sizeof *buf);
    if (!buf)
        return QD_ERR_NOMEM;
    double *res = buf, *E = buf + nn, *Xn = buf + 2 * nn, *scratch = buf + 3 * nn;
    *rel = riccati_residual(w, w->X, res, scratch);
    for (int step = 0; step < 3 && *rel > 0 && newton_step(w, res, E, scratch); step++) {
        int n = w->n;
        for (int i = 0; i < n; i++)
            for (int j = 0; j < n; j++)
                Xn[i + j * n] = w->X[i + j * n] + (E[i + j * n] + E[j + i * n]) / 2;
        double next = riccati_residual(w, Xn, E, scratch);
        if (!(next < *rel / 2)) /* rounding reached: keep the better X */
            break;
        memcpy(w->X, Xn, nn * sizeof *Xn);
        memcpy(res, E, nn * sizeof *E);
        *rel = next;
    }
    qd__free(buf);
    return QD_OK;
}

static int by_re_desc(const void *pa, const void *pb) {
    const double *a = pa, *b = pb;
    if (a[0] != b[0])
        return a[0] < b[0] ? 1 : -1;
    return (a[1] < b[1]) - (a[1] > b[1]);
}

/* K = Y X (row-major out), the eigenvalues of A - B K, and the check that
 * they are all stable: what "stabilizing" promises. */
static qd_status gain(care_work *w, qd_care_result *out) {
    int n = w->n, m = w->m;
    double *cl = qd__malloc(w->ctx, (size_t)n * (size_t)n * sizeof *cl);
    double *pairs = qd__malloc(w->ctx, 2 * (size_t)n * sizeof *pairs);
    if (!cl || !pairs) {
        qd__free(cl), qd__free(pairs);
        return QD_ERR_NOMEM;
    }
    for (int i = 0; i < m; i++)
        for (int j = 0; j < n; j++) {
            double s = 0;
            for (int k = 0; k < n; k++)
                s += w->Y[i + k * m] * w->X[k + j * n];
            out->K[(size_t)i * (size_t)n + (size_t)j] = s;
        }
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            double s = w->A[i + j * n];
            for (int k = 0; k < m; k++)
                s -= w->B[i + k * n] * out->K[(size_t)k * (size_t)n + (size_t)j];
            cl[i + j * n] = s;
        }
    qd_status st = QD_OK;
    if (!gen_eigvals(w->ctx, n, cl, out->eig_re, out->eig_im)) {
        st = qd__ctx_nomem(w->ctx) ? QD_ERR_NOMEM : QD_ERR_NUMERIC;
        qd_ctx_error(w->ctx, st, "the closed-loop eigenvalues (dgeev) failed");
    } else {
        for (int k = 0; k < n; k++)
            pairs[2 * k] = out->eig_re[k], pairs[2 * k + 1] = out->eig_im[k];
        qsort(pairs, (size_t)n, 2 * sizeof *pairs, by_re_desc);
        for (int k = 0; k < n; k++)
            out->eig_re[k] = pairs[2 * k], out->eig_im[k] = pairs[2 * k + 1];
        if (out->eig_re[0] >= 0) {
            char s[64];
            mode_text(s, sizeof s, out->eig_re[0], out->eig_im[0]);
            qd_ctx_error(w->ctx, QD_ERR_NUMERIC,
                         "the solution X is not stabilizing: A - B K has the eigenvalue %s", s);
            st = fail(out, QD_CARE_NOT_STABILIZING, QD_ERR_NUMERIC);
        }
    }
    qd__free(cl);
    qd__free(pairs);
    return st;
}

void qd_care_result_free(qd_care_result *r) {
    if (!r)
        return;
    qd__free(r->X);
    qd__free(r->K);
    qd__free(r->eig_re);
    qd__free(r->eig_im);
    memset(r, 0, sizeof *r);
}

static qd_status load(care_work *w, const double *A, const double *B, const double *Q,
                      const double *R, qd_care_result *out) {
    size_t n = (size_t)w->n, m = (size_t)w->m;
    if (!all_finite(n * n, A) || !all_finite(n * m, B) || !all_finite(n * n, Q) ||
        !all_finite(m * m, R)) {
        qd_ctx_error(w->ctx, QD_ERR_ARG, "the Riccati equation needs finite A, B, Q and R");
        return QD_ERR_ARG;
    }
    w->A = col_major(w->ctx, n, n, A);
    w->B = col_major(w->ctx, n, m, B);
    w->Q = col_major(w->ctx, n, n, Q);
    if (!w->A || !w->B || !w->Q)
        return QD_ERR_NOMEM;
    w->normA = frob(n * n, w->A);
    w->normB = frob(n * m, w->B);
    w->normQ = frob(n * n, w->Q);
    qd_status st = check_r(w, R, out);
    if (st == QD_OK)
        st = check_q(w, out);
    return st;
}

/* Copy X out (row-major; it is symmetric, so the same numbers). */
static qd_status publish(care_work *w, qd_care_result *out) {
    size_t n = (size_t)w->n;
    out->n = n;
    out->m = (size_t)w->m;
    out->X = qd__malloc(w->ctx, n * n * sizeof *out->X);
    out->K = qd__malloc(w->ctx, out->m * n * sizeof *out->K);
    out->eig_re = qd__malloc(w->ctx, n * sizeof *out->eig_re);
    out->eig_im = qd__malloc(w->ctx, n * sizeof *out->eig_im);
    if (!out->X || !out->K || !out->eig_re || !out->eig_im)
        return QD_ERR_NOMEM;
    qd_status st = refine(w, &out->residual);
    if (st != QD_OK)
        return st;
    memcpy(out->X, w->X, n * n * sizeof *out->X);
    return gain(w, out);
}

qd_status qd_care_solve(qd_ctx *ctx, size_t n, size_t m, const double *A,
                        const double *B, const double *Q, const double *R,
                        qd_care_result *out) {
    QD_ARGS_CTX(ctx, ctx && A && B && Q && R && out);
    if (!out)
        return QD_ERR_ARG;
    memset(out, 0, sizeof *out);
    if (!ctx || !A || !B || !Q || !R || n == 0 || m == 0 || n > 4096 || m > 4096) {
        if (ctx)
            qd_ctx_error(ctx, QD_ERR_ARG,
                         "the Riccati equation needs n >= 1 states, m >= 1 inputs (at most 4096) "
                         "and the matrices A, B, Q, R");
        return QD_ERR_ARG;
    }
    care_work w = {.ctx = ctx, .n = (int)n, .m = (int)m};
    double *vs = NULL;
    qd_status st = load(&w, A, B, Q, R, out);
    if (st == QD_OK)
        st = weight_inputs(&w);
    if (st == QD_OK)
        st = check_modes(&w, out);
    if (st == QD_OK && !(vs = qd__malloc(ctx, 4 * n * n * sizeof *vs)))
        st = QD_ERR_NOMEM;
    if (st == QD_OK)
        st = schur_stable(&w, vs, out);
    if (st == QD_OK)
        st = solve_x(&w, vs, out);
    if (st == QD_OK)
        st = publish(&w, out);
    if (st == QD_ERR_NOMEM)
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory solving the Riccati equation");
    if (st != QD_OK) {
        qd_care_failure why = out->failure;
        double re = out->mode_re, im = out->mode_im;
        qd_care_result_free(out);
        out->failure = why, out->mode_re = re, out->mode_im = im;
    }
    qd__free(vs);
    work_free(&w);
    return st;
}
