/*
 * src/linear/kalman.c - the eigenvalues of A, controllability and
 * observability of (A, B, C): the ranks of Kalman's matrices
 * [B AB ... A^(nx-1) B] and [C; CA; ...] (singular values by LAPACK dgesvd)
 * and, mode by mode, the Popov-Belevitch-Hautus test: the mode of
 * eigenvalue s is unreachable when its left eigenvector w (w^H A = s w^H)
 * has w^H B = 0, unseen when its right eigenvector v has C v = 0 (dgeev
 * gives both).  For an eigenvalue repeated with a single eigenvector the
 * PBH verdict is that of the one eigenvector dgeev returns.
 */
#include "ss.h"

#include "base/mem.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

extern void dgeev_(const char *jobvl, const char *jobvr, const int *n, double *a, const int *lda,
                   double *wr, double *wi, double *vl, const int *ldvl, double *vr,
                   const int *ldvr, double *work, const int *lwork, int *info);
extern void dgesvd_(const char *jobu, const char *jobvt, const int *m, const int *n, double *a,
                    const int *lda, double *s, double *u, const int *ldu, double *vt,
                    const int *ldvt, double *work, const int *lwork, int *info);

/* The numerical rank of the r*c row-major matrix K (QD_SS_RANK_TOL). */
static qd_status rank_of(qd_ctx *ctx, size_t r, size_t c, const double *K, size_t *rank) {
    int ri = (int)r, ci = (int)c, info = 0, lwork = -1, one = 1;
    size_t k = r < c ? r : c;
    *rank = 0;
    if (k == 0)
        return QD_OK;
    double *a = qd__malloc(ctx, (r * c + k + 1) * sizeof *a), q = 0, dummy = 0;
    if (!a)
        return QD_ERR_NOMEM;
    double *sv = a + r * c;
    for (size_t i = 0; i < r; i++)
        for (size_t j = 0; j < c; j++)
            a[i + j * r] = K[i * c + j];
    dgesvd_("N", "N", &ri, &ci, a, &ri, sv, &dummy, &one, &dummy, &one, &q, &lwork, &info);
    lwork = (int)q;
    double *work = qd__malloc(ctx, ((size_t)lwork + 1) * sizeof *work);
    if (work)
        dgesvd_("N", "N", &ri, &ci, a, &ri, sv, &dummy, &one, &dummy, &one, work, &lwork, &info);
    qd_status st = !work ? QD_ERR_NOMEM : info ? QD_ERR_NUMERIC : QD_OK;
    for (size_t i = 0; st == QD_OK && i < k; i++)
        if (sv[i] > QD_SS_RANK_TOL * sv[0])
            (*rank)++;
    if (st == QD_ERR_NUMERIC)
        qd_ctx_error(ctx, st, "the singular value decomposition (dgesvd) failed: info %d", info);
    qd__free(work);
    qd__free(a);
    return st;
}

/* [B AB ... A^(nx-1) B] (nx * nx*nu) or, transposed, the observability
 * matrix [C; CA; ...] (nx*ny * nx). */
static void kalman_ctrb(const qd_statespace *s, double *K) {
    size_t nx = s->nx, nu = s->nu, w = nx * nu;
    for (size_t i = 0; i < nx; i++)
        for (size_t k = 0; k < nu; k++)
            K[i * w + k] = s->B[i * nu + k];
    for (size_t p = 1; p < nx; p++)
        for (size_t i = 0; i < nx; i++)
            for (size_t k = 0; k < nu; k++) {
                double x = 0;
                for (size_t l = 0; l < nx; l++)
                    x += s->A[i * nx + l] * K[l * w + (p - 1) * nu + k];
                K[i * w + p * nu + k] = x;
            }
}

static void kalman_obsv(const qd_statespace *s, double *K) {
    size_t nx = s->nx, ny = s->ny;
    for (size_t i = 0; i < ny; i++)
        for (size_t k = 0; k < nx; k++)
            K[i * nx + k] = s->C[i * nx + k];
    for (size_t p = 1; p < nx; p++)
        for (size_t i = 0; i < ny; i++)
            for (size_t k = 0; k < nx; k++) {
                double x = 0;
                for (size_t l = 0; l < nx; l++)
                    x += K[((p - 1) * ny + i) * nx + l] * s->A[l * nx + k];
                K[(p * ny + i) * nx + k] = x;
            }
}

static qd_status ranks(qd_ctx *ctx, qd_statespace *s) {
    size_t nx = s->nx;
    size_t big = nx * nx * (s->nu > s->ny ? s->nu : s->ny);
    double *K = qd__calloc(ctx, big + 1, sizeof *K);
    if (!K)
        return QD_ERR_NOMEM;
    kalman_ctrb(s, K);
    qd_status st = rank_of(ctx, nx, nx * s->nu, K, &s->rank_ctrb);
    if (st == QD_OK) {
        kalman_obsv(s, K);
        st = rank_of(ctx, nx * s->ny, nx, K, &s->rank_obsv);
    }
    s->controllable = s->rank_ctrb == nx;
    s->observable = s->ny > 0 && s->rank_obsv == nx;
    qd__free(K);
    return st;
}

/* ---- modes ------------------------------------------------------------------ */

typedef struct eigwork {
    size_t nx;
    double *wr, *wi, *vl, *vr;   /* dgeev's, column-major */
    bool *reach, *seen;          /* per eigenvalue, dgeev's order */
} eigwork;

/* Eigenvector j (right: vr, left: vl) as re/im parts, from dgeev's packing. */
static void vec_of(const eigwork *w, const double *V, size_t j, double *re, double *im) {
    size_t nx = w->nx;
    bool pair = w->wi[j] != 0;
    size_t c = pair && w->wi[j] < 0 ? j - 1 : j; /* the first of the pair holds re */
    double sgn = pair && w->wi[j] < 0 ? -1 : 1;
    for (size_t i = 0; i < nx; i++) {
        re[i] = V[i + c * nx];
        im[i] = pair ? sgn * V[i + (c + 1) * nx] : 0;
    }
}

static double frob(size_t n, const double *x) {
    double s = 0;
    for (size_t i = 0; i < n; i++)
        s += x[i] * x[i];
    return sqrt(s);
}

/* PBH: w^H B and C v, each against its scale. */
static void pbh(const qd_statespace *s, eigwork *w, double *re, double *im) {
    size_t nx = s->nx;
    double nB = frob(nx * s->nu, s->B), nC = frob(s->ny * nx, s->C);
    for (size_t j = 0; j < nx; j++) {
        vec_of(w, w->vl, j, re, im);
        double nw = hypot(frob(nx, re), frob(nx, im)), acc = 0;
        for (size_t k = 0; k < s->nu; k++) {
            double xr = 0, xi = 0; /* conj(w) . B_k */
            for (size_t i = 0; i < nx; i++) {
                xr += re[i] * s->B[i * s->nu + k];
                xi -= im[i] * s->B[i * s->nu + k];
            }
            acc += xr * xr + xi * xi;
        }
        w->reach[j] = sqrt(acc) > QD_SS_RANK_TOL * nw * nB && nB > 0;
        vec_of(w, w->vr, j, re, im);
        double nv = hypot(frob(nx, re), frob(nx, im));
        acc = 0;
        for (size_t k = 0; k < s->ny; k++) {
            double xr = 0, xi = 0;
            for (size_t i = 0; i < nx; i++) {
                xr += s->C[k * nx + i] * re[i];
                xi += s->C[k * nx + i] * im[i];
            }
            acc += xr * xr + xi * xi;
        }
        w->seen[j] = sqrt(acc) > QD_SS_RANK_TOL * nv * nC && nC > 0;
    }
}

/* An eigenvalue and its place in dgeev's order, for sorting. */
typedef struct eig_at {
    double re, im;
    size_t idx;
} eig_at;

static int by_re_desc(const void *pa, const void *pb) {
    const eig_at *a = pa, *b = pb;
    if (a->re != b->re)
        return a->re > b->re ? -1 : 1;
    return a->im > b->im ? -1 : a->im < b->im;
}

/* Scale v so that its largest component is 1 (a complex division). */
static void normalise(size_t nx, double *re, double *im) {
    size_t big = 0;
    for (size_t i = 1; i < nx; i++)
        if (hypot(re[i], im[i]) > hypot(re[big], im[big]) * (1 + 1e-12))
            big = i;
    double dr = re[big], di = im[big], d2 = dr * dr + di * di;
    for (size_t i = 0; d2 > 0 && i < nx; i++) {
        double r = re[i], m = im[i];
        re[i] = (r * dr + m * di) / d2;
        im[i] = (m * dr - r * di) / d2;
    }
}

/* Sorted eigenvalues, vectors and the PBH lists into s. */
static qd_status store(qd_ctx *ctx, qd_statespace *s, eigwork *w, double *re, double *im) {
    size_t nx = s->nx;
    eig_at *ord = qd__malloc(ctx, (nx + 1) * sizeof *ord);
    s->eig_re = qd__calloc(ctx, 4 * nx + 2 * nx * nx + 1, sizeof *s->eig_re);
    s->uncontrollable = qd__calloc(ctx, 2 * nx + 1, sizeof *s->uncontrollable);
    if (!ord || !s->eig_re || !s->uncontrollable) {
        qd__free(ord);
        return QD_ERR_NOMEM;
    }
    s->eig_im = s->eig_re + nx;
    s->vec_re = s->eig_im + nx;
    s->vec_im = s->vec_re + nx * nx;
    s->unobservable = s->uncontrollable + nx;
    for (size_t j = 0; j < nx; j++)
        ord[j] = (eig_at){w->wr[j], w->wi[j], j};
    qsort(ord, nx, sizeof *ord, by_re_desc);
    for (size_t j = 0; j < nx; j++) {
        size_t o = ord[j].idx;
        s->eig_re[j] = w->wr[o];
        s->eig_im[j] = w->wi[o];
        vec_of(w, w->vr, o, re, im);
        normalise(nx, re, im);
        for (size_t i = 0; i < nx; i++) {
            s->vec_re[i * nx + j] = re[i];
            s->vec_im[i * nx + j] = im[i];
        }
        if (!w->reach[o])
            s->uncontrollable[s->nuncontrollable++] = j;
        if (!w->seen[o])
            s->unobservable[s->nunobservable++] = j;
    }
    qd__free(ord);
    return QD_OK;
}

static qd_status eigen(qd_ctx *ctx, qd_statespace *s) {
    size_t nx = s->nx;
    int ni = (int)nx, info = 0, lwork = -1;
    eigwork w = {.nx = nx};
    double *buf = qd__malloc(ctx, (4 * nx * nx + 4 * nx + 1) * sizeof *buf), q = 0;
    bool *flags = qd__malloc(ctx, 2 * nx + 1);
    qd_status st = buf && flags ? QD_OK : QD_ERR_NOMEM;
    double *a = buf, *work = NULL;
    if (st == QD_OK) {
        w.wr = a + nx * nx;
        w.wi = w.wr + nx;
        w.vl = w.wi + nx;
        w.vr = w.vl + nx * nx;
        w.reach = flags;
        w.seen = flags + nx;
        for (size_t i = 0; i < nx; i++)
            for (size_t j = 0; j < nx; j++)
                a[i + j * nx] = s->A[i * nx + j];
        dgeev_("V", "V", &ni, a, &ni, w.wr, w.wi, w.vl, &ni, w.vr, &ni, &q, &lwork, &info);
        lwork = (int)q;
        work = qd__malloc(ctx, ((size_t)lwork + 1) * sizeof *work);
        if (!work)
            st = QD_ERR_NOMEM;
    }
    if (st == QD_OK)
        dgeev_("V", "V", &ni, a, &ni, w.wr, w.wi, w.vl, &ni, w.vr, &ni, work, &lwork, &info);
    if (st == QD_OK && info != 0) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "the eigen-solver (dgeev) failed: info %d", info);
        st = QD_ERR_NUMERIC;
    }
    double *re = w.vr + nx * nx, *im = re + nx; /* two scratch vectors */
    if (st == QD_OK) {
        pbh(s, &w, re, im);
        st = store(ctx, s, &w, re, im);
    }
    qd__free(work);
    qd__free(flags);
    qd__free(buf);
    return st;
}

qd_status qd__lin_ss_analyse(qd_ctx *ctx, qd_statespace *s) {
    if (s->nx == 0)
        return QD_OK;
    qd_status st = eigen(ctx, s);
    return st == QD_OK ? ranks(ctx, s) : st;
}
