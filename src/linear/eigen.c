/*
 * src/linear/eigen.c - the eigenproblems of small oscillations (LAPACK).
 *
 * Conservative, non-gyroscopic: K a = w^2 M a, symmetric-definite, by
 * dsygvd (Cholesky of M, then a symmetric divide-and-conquer eigensolve):
 * ascending w^2 and M-orthonormal shapes, also within a repeated w^2 (the
 * solver returns an M-orthonormal basis of the eigenspace).
 *
 * Otherwise M x'' + (C + G) x' + K x = 0 is written as the pencil
 *     [0 I; -K -(C + G)] z = s [I 0; 0 M] z,     z = (x, x'),
 * and solved by dggev, which needs no inverse of M.  L4 of the restricted
 * three-body problem is a maximum of the effective potential (K negative
 * definite) yet stable for 27 mu (1 - mu) < 1: only this form sees it
 * (Desloge ch. 62; seed-desloge-B.md pitfall 3).
 */
#include "linear.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* LAPACK (Fortran, column-major); the hidden lengths of the one-character
 * arguments are not passed, as is usual from C for length 1. */
extern void dsygvd_(const int *itype, const char *jobz, const char *uplo, const int *n, double *a,
                    const int *lda, double *b, const int *ldb, double *w, double *work,
                    const int *lwork, int *iwork, const int *liwork, int *info);
extern void dsyev_(const char *jobz, const char *uplo, const int *n, double *a, const int *lda,
                   double *w, double *work, const int *lwork, int *info);
extern void dggev_(const char *jobvl, const char *jobvr, const int *n, double *a, const int *lda,
                   double *b, const int *ldb, double *alphar, double *alphai, double *beta,
                   double *vl, const int *ldvl, double *vr, const int *ldvr, double *work,
                   const int *lwork, int *info);

bool qd__lin_sym_eig(qd_ctx *ctx, size_t n, const double *A, double *w, double *vecs) {
    int ni = (int)n, info = 0, lwork = -1;
    if (n == 0)
        return true;
    double *a = qd__malloc(ctx, n * n * sizeof *a), q;
    if (!a)
        return false;
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++)
            a[i + j * n] = (A[i * n + j] + A[j * n + i]) / 2;
    const char *jobz = vecs ? "V" : "N";
    dsyev_(jobz, "U", &ni, a, &ni, w, &q, &lwork, &info);
    lwork = info == 0 ? (int)q : 0;
    double *work = lwork > 0 ? qd__malloc(ctx, (size_t)lwork * sizeof *work) : NULL;
    if (work)
        dsyev_(jobz, "U", &ni, a, &ni, w, work, &lwork, &info);
    bool ok = work && info == 0;
    if (ok && vecs)
        memcpy(vecs, a, n * n * sizeof *a);
    qd__free(work);
    qd__free(a);
    return ok;
}

void qd_modes_result_free(qd_modes_result *r) {
    if (!r)
        return;
    qd__free(r->omega2);
    qd__free(r->shapes);
    qd__free(r->eig_re);
    qd__free(r->eig_im);
    memset(r, 0, sizeof *r);
}

static double max_abs(size_t n, const double *a) {
    double m = 0;
    for (size_t i = 0; i < n; i++)
        m = fmax(m, fabs(a[i]));
    return m;
}

/* Each shape's largest component positive: a deterministic sign. */
static void fix_signs(size_t n, double *shapes) {
    for (size_t j = 0; j < n; j++) {
        size_t big = 0;
        for (size_t i = 1; i < n; i++)
            if (fabs(shapes[i * n + j]) > fabs(shapes[big * n + j]) * (1 + 1e-9))
                big = i;
        if (shapes[big * n + j] < 0)
            for (size_t i = 0; i < n; i++)
                shapes[i * n + j] = -shapes[i * n + j];
    }
}

static qd_status conservative(qd_ctx *ctx, const qd_linear *lin, qd_modes_result *r) {
    size_t n = lin->n;
    int ni = (int)n, itype = 1, info = 0, lwork = -1, liwork = -1, iq = 0;
    double *a = qd__malloc(ctx, n * n * sizeof *a), *b = qd__malloc(ctx, n * n * sizeof *b), q = 0;
    if (!a || !b) {
        qd__free(a);
        qd__free(b);
        return QD_ERR_NOMEM;
    }
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++) {
            a[i + j * n] = (lin->K[i * n + j] + lin->K[j * n + i]) / 2;
            b[i + j * n] = (lin->M[i * n + j] + lin->M[j * n + i]) / 2;
        }
    dsygvd_(&itype, "V", "U", &ni, a, &ni, b, &ni, r->omega2, &q, &lwork, &iq, &liwork, &info);
    lwork = (int)q;
    liwork = iq;
    double *work = qd__malloc(ctx, ((size_t)lwork + 1) * sizeof *work);
    int *iwork = qd__malloc(ctx, ((size_t)liwork + 1) * sizeof *iwork);
    if (work && iwork && info == 0)
        dsygvd_(&itype, "V", "U", &ni, a, &ni, b, &ni, r->omega2, work, &lwork, iwork, &liwork,
                &info);
    qd_status st = QD_OK;
    if (!work || !iwork) {
        st = QD_ERR_NOMEM;
    } else if (info > ni) {
        qd_ctx_error(ctx, QD_ERR_SINGULAR,
                     "the mass matrix is not positive definite at this point (leading minor %d "
                     "is not positive)", info - ni);
        st = QD_ERR_SINGULAR;
    } else if (info != 0) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "the eigen-solver (dsygvd) failed: info %d", info);
        st = QD_ERR_NUMERIC;
    }
    for (size_t i = 0; st == QD_OK && i < n; i++)
        for (size_t j = 0; j < n; j++)
            r->shapes[i * n + j] = a[i + j * n];
    qd__free(work);
    qd__free(iwork);
    qd__free(a);
    qd__free(b);
    if (st != QD_OK)
        return st;
    fix_signs(n, r->shapes);
    double tol = QD_MODES_ZERO_TOL * max_abs(n, r->omega2);
    r->stable = 1;
    for (size_t j = 0; j < n; j++) {
        double w2 = r->omega2[j];
        if (fabs(w2) <= tol)
            r->omega2[j] = w2 = 0;
        if (w2 < 0)
            r->stable = 0;
        else if (w2 == 0 && r->stable == 1)
            r->stable = -1;
        double s = sqrt(fabs(w2));
        r->eig_re[2 * j] = w2 < 0 ? s : 0;
        r->eig_im[2 * j] = w2 < 0 ? 0 : s;
        r->eig_re[2 * j + 1] = w2 < 0 ? -s : 0;
        r->eig_im[2 * j + 1] = w2 < 0 ? 0 : -s;
    }
    return QD_OK;
}

typedef struct cplx {
    double re, im;
} cplx;

static int by_re_desc(const void *pa, const void *pb) {
    const cplx *a = pa, *b = pb;
    if (a->re != b->re)
        return a->re < b->re ? 1 : -1;
    return a->im < b->im ? 1 : a->im > b->im ? -1 : 0;
}

static qd_status sort_eigs(qd_ctx *ctx, qd_modes_result *r) {
    cplx *c = qd__malloc(ctx, (r->neig + 1) * sizeof *c);
    if (!c)
        return QD_ERR_NOMEM; /* unsorted would break the documented order */
    for (size_t i = 0; i < r->neig; i++)
        c[i] = (cplx){r->eig_re[i], r->eig_im[i]};
    qsort(c, r->neig, sizeof *c, by_re_desc);
    for (size_t i = 0; i < r->neig; i++) {
        r->eig_re[i] = c[i].re;
        r->eig_im[i] = c[i].im;
    }
    qd__free(c);
    return QD_OK;
}

double qd__lin_root_shown(const qd_modes_result *r, double x) {
    double big = 0;
    for (size_t i = 0; i < r->neig; i++)
        big = fmax(big, hypot(r->eig_re[i], r->eig_im[i]));
    return fabs(x) <= QD_RESULT_ZERO * big ? 0 : x;
}

/* Stable when every Re s < 0, or Re s = 0 only on simple nonzero roots. */
static int verdict(const qd_modes_result *r) {
    double big = 0;
    for (size_t i = 0; i < r->neig; i++)
        big = fmax(big, hypot(r->eig_re[i], r->eig_im[i]));
    double tol = QD_MODES_ZERO_TOL * big;
    int v = 1;
    for (size_t i = 0; i < r->neig; i++) {
        double re = r->eig_re[i], im = r->eig_im[i];
        if (re > tol)
            return 0;
        if (re < -tol)
            continue;
        if (fabs(im) <= tol) {
            v = -1;
            continue;
        }
        for (size_t k = 0; k < r->neig; k++)
            if (k != i && fabs(r->eig_re[k]) <= tol &&
                fabs(r->eig_im[k] - im) <= 1e3 * tol)
                v = -1;
    }
    return big == 0 ? -1 : v;
}

static qd_status state_space(qd_ctx *ctx, const qd_linear *lin, qd_modes_result *r) {
    size_t n = lin->n, N = 2 * n;
    int Ni = (int)N, info = 0, lwork = -1, one = 1;
    double *a = qd__calloc(ctx, N * N, sizeof *a), *b = qd__calloc(ctx, N * N, sizeof *b);
    double *ar = qd__malloc(ctx, N * sizeof *ar), *ai = qd__malloc(ctx, N * sizeof *ai);
    double *beta = qd__malloc(ctx, N * sizeof *beta), q = 0, dummy = 0;
    qd_status st = QD_OK;
    if (!a || !b || !ar || !ai || !beta) {
        st = QD_ERR_NOMEM;
        goto done;
    }
    for (size_t i = 0; i < n; i++) {
        a[i + (n + i) * N] = 1;
        b[i + i * N] = 1;
        for (size_t j = 0; j < n; j++) {
            a[(n + i) + j * N] = -lin->K[i * n + j];
            a[(n + i) + (n + j) * N] = -(lin->C[i * n + j] + lin->G[i * n + j]);
            b[(n + i) + (n + j) * N] = lin->M[i * n + j];
        }
    }
    dggev_("N", "N", &Ni, a, &Ni, b, &Ni, ar, ai, beta, &dummy, &one, &dummy, &one, &q, &lwork,
           &info);
    lwork = (int)q;
    double *work = qd__malloc(ctx, ((size_t)lwork + 1) * sizeof *work);
    if (!work) {
        st = QD_ERR_NOMEM;
        goto done;
    }
    dggev_("N", "N", &Ni, a, &Ni, b, &Ni, ar, ai, beta, &dummy, &one, &dummy, &one, work, &lwork,
           &info);
    qd__free(work);
    if (info != 0) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "the eigen-solver (dggev) failed: info %d", info);
        st = QD_ERR_NUMERIC;
        goto done;
    }
    double mscale = max_abs(n * n, lin->M);
    for (size_t i = 0; i < N; i++) {
        if (!(fabs(beta[i]) > 1e-13 * fmax(1, mscale))) {
            qd_ctx_error(ctx, QD_ERR_SINGULAR,
                         "the mass matrix is singular at this point: an infinite eigenvalue");
            st = QD_ERR_SINGULAR;
            goto done;
        }
        r->eig_re[i] = ar[i] / beta[i];
        r->eig_im[i] = ai[i] / beta[i];
    }
    if ((st = sort_eigs(ctx, r)) == QD_OK)
        r->stable = verdict(r);
done:
    qd__free(a);
    qd__free(b);
    qd__free(ar);
    qd__free(ai);
    qd__free(beta);
    if (st == QD_ERR_NOMEM)
        qd_ctx_error(ctx, st, "out of memory in the eigen-analysis");
    return st;
}

size_t qd_modes_multiplicity(const qd_modes_result *r, size_t j) {
    QD_ARGS(0, r);
    if (!r->conservative || j >= r->n)
        return 0;
    double big = 0;
    for (size_t k = 0; k < r->n; k++)
        big = fmax(big, fabs(r->omega2[k]));
    /* omega2 ascends, so a repeated eigenvalue is a run of neighbours: walk
     * out from j while each next value is within the tolerance of j's */
    size_t lo = j, hi = j;
    while (lo > 0 && fabs(r->omega2[lo - 1] - r->omega2[j]) <= QD_MODES_REPEAT_TOL * big)
        lo--;
    while (hi + 1 < r->n && fabs(r->omega2[hi + 1] - r->omega2[j]) <= QD_MODES_REPEAT_TOL * big)
        hi++;
    return hi - lo + 1;
}

qd_status qd_modes_solve(qd_ctx *ctx, const qd_linear *lin, qd_modes_result *out) {
    QD_ARGS_CTX(ctx, ctx && lin && out);
    memset(out, 0, sizeof *out);
    size_t n = lin->n, nn = n * n;
    out->n = n;
    out->neig = 2 * n;
    out->eig_re = qd__calloc(ctx, 2 * n + 1, sizeof *out->eig_re);
    out->eig_im = qd__calloc(ctx, 2 * n + 1, sizeof *out->eig_im);
    if (!out->eig_re || !out->eig_im) {
        qd_modes_result_free(out);
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory in the eigen-analysis");
        return QD_ERR_NOMEM;
    }
    double scale = sqrt(max_abs(nn, lin->K) * max_abs(nn, lin->M));
    double cg = fmax(max_abs(nn, lin->C), max_abs(nn, lin->G));
    /* Circulatory forces (Q depending on q, not from a potential) make K
     * unsymmetric: dsygvd would read only one triangle and answer wrongly,
     * so such a K goes to the state-space problem like damping does. */
    double skew = 0;
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < i; j++)
            skew = fmax(skew, fabs(lin->K[i * n + j] - lin->K[j * n + i]));
    out->conservative =
        (cg == 0 || qd__lin_negligible(cg, scale)) && qd__lin_negligible(skew, max_abs(nn, lin->K));
    qd_status st;
    if (out->conservative) {
        out->omega2 = qd__calloc(ctx, n + 1, sizeof *out->omega2);
        out->shapes = qd__calloc(ctx, nn + 1, sizeof *out->shapes);
        st = out->omega2 && out->shapes ? conservative(ctx, lin, out) : QD_ERR_NOMEM;
        if (st == QD_OK)
            st = sort_eigs(ctx, out);
    } else {
        st = state_space(ctx, lin, out);
    }
    if (st != QD_OK) {
        if (st == QD_ERR_NOMEM && qd_ctx_status(ctx) == QD_OK)
            qd_ctx_error(ctx, st, "out of memory in the eigen-analysis");
        qd_modes_result_free(out);
    }
    return st;
}

qd_status qd_modes_symbolic_omega2(qd_ctx *ctx, size_t n, const qd_expr *const *K,
                                   const qd_expr *const *M, const qd_expr **w2) {
    QD_ARGS_CTX(ctx, ctx && K && M && w2);
    if (n == 1) {
        w2[0] = qd_simplify(ctx, qd_div(ctx, K[0], M[0]));
        return w2[0] ? QD_OK : qd_ctx_status(ctx);
    }
    if (n != 2) {
        qd_ctx_error(ctx, QD_ERR_ARG, "symbolic frequencies only for 1 or 2 degrees of freedom");
        return QD_ERR_ARG;
    }
    /* det(K - x M) = a x^2 + b x + c */
    const qd_expr *a = qd_sub(ctx, qd_mul(ctx, M[0], M[3]), qd_mul(ctx, M[1], M[2]));
    const qd_expr *b = qd_neg(ctx, qd_add_n(ctx, 4, (const qd_expr *[]){
        qd_mul(ctx, K[0], M[3]), qd_mul(ctx, K[3], M[0]),
        qd_neg(ctx, qd_mul(ctx, K[1], M[2])), qd_neg(ctx, qd_mul(ctx, K[2], M[1]))}));
    const qd_expr *c = qd_sub(ctx, qd_mul(ctx, K[0], K[3]), qd_mul(ctx, K[1], K[2]));
    a = qd_simplify(ctx, a);
    b = qd_simplify(ctx, b);
    c = qd_simplify(ctx, c);
    const qd_expr *disc = qd_simplify(ctx, qd_sub(ctx, qd_mul(ctx, b, b),
                                                  qd_mul(ctx, qd_int(ctx, 4), qd_mul(ctx, a, c))));
    const qd_expr *root = qd_sqrt(ctx, disc), *den = qd_mul(ctx, qd_int(ctx, 2), a);
    w2[0] = qd_simplify(ctx, qd_div(ctx, qd_sub(ctx, qd_neg(ctx, b), root), den));
    w2[1] = qd_simplify(ctx, qd_div(ctx, qd_add(ctx, qd_neg(ctx, b), root), den));
    return w2[0] && w2[1] ? QD_OK : qd_ctx_status(ctx);
}
