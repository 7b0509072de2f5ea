/*
 * src/linear/symmetry_cyclic.c - the fast path for rings: a system of N
 * identical cells of c coordinates each, invariant under the shift
 * q_j -> q_{j+c mod n} (the generator of C_N), splits into the N harmonics
 * of Bloch's ansatz x_{j,a} = u_a e^{i theta_k j}, theta_k = 2 pi k/N, the
 * irreps of C_N (Desloge ch. 66: the projection on each is the discrete
 * Fourier transform over the cells).  Harmonic k is the Hermitian pencil
 * Khat_k u = w^2 Mhat_k u, Khat_k[a][b] = sum_j K0[a][j c + b] e^{i theta_k j},
 * solved as its real form [[Re, -Im], [Im, Re]] (each w^2 twice) by
 * Cholesky of Mhat and a symmetric eigensolve.  Harmonics k and N - k are
 * conjugate: one real pair, a doubly degenerate w^2.  The ring of N masses
 * (c = 1): w_k^2 = (4k/m) sin^2(pi k/N).
 */
#include "symmetry.h"
#include "linear.h"

#include "base/mem.h"
#include "../base/args.h"

#include <math.h>
#include <string.h>

static const double PI = 3.14159265358979323846;

static double max_abs(size_t len, const double *a) {
    double m = 0;
    for (size_t i = 0; i < len; i++)
        m = fmax(m, fabs(a[i]));
    return m;
}

static bool shift_invariant(size_t n, size_t c, const double *A) {
    double tol = QD_SYMMETRY_TOL * max_abs(n * n, A);
    for (size_t i = 0; i < n; i++) {
        size_t si = (i + c) % n;
        for (size_t j = 0; j < n; j++)
            if (fabs(A[si * n + (j + c) % n] - A[i * n + j]) > tol)
                return false;
    }
    return true;
}

size_t qd_cyclic_cell(const qd_linear *lin) {
    QD_ARGS(0, lin);
    if (!lin)
        return 0;
    size_t n = lin->n;
    for (size_t c = 1; 3 * c <= n; c++)
        if (n % c == 0 && shift_invariant(n, c, lin->M) && shift_invariant(n, c, lin->K))
            return c;
    return 0;
}

void qd_cyclic_modes_free(qd_cyclic_modes *c) {
    if (!c)
        return;
    qd__free(c->omega2);
    qd__free(c->harmonic);
    qd__free(c->degeneracy);
    memset(c, 0, sizeof *c);
}

/* The real form (2c x 2c) of harmonic k of A. */
static void harmonic(size_t n, size_t c, size_t k, const double *A, const double *cs,
                     const double *sn, double *H) {
    size_t N = n / c, m = 2 * c;
    for (size_t a = 0; a < c; a++)
        for (size_t b = 0; b < c; b++) {
            double re = 0, im = 0;
            for (size_t j = 0; j < N; j++) {
                double x = A[a * n + j * c + b];
                size_t t = j * k % N;
                re += x * cs[t];
                im += x * sn[t];
            }
            H[a * m + b] = H[(c + a) * m + c + b] = re;
            H[a * m + c + b] = -im;
            H[(c + a) * m + b] = im;
        }
}

/* B = L L^T in place (lower); false when not positive definite. */
static bool cholesky(size_t m, double *B) {
    for (size_t j = 0; j < m; j++) {
        double d = B[j * m + j];
        for (size_t k = 0; k < j; k++)
            d -= B[j * m + k] * B[j * m + k];
        if (!(d > 0))
            return false;
        B[j * m + j] = sqrt(d);
        for (size_t i = j + 1; i < m; i++) {
            double t = B[i * m + j];
            for (size_t k = 0; k < j; k++)
                t -= B[i * m + k] * B[j * m + k];
            B[i * m + j] = t / B[j * m + j];
        }
    }
    return true;
}

/* C = L^-1 A L^-T (forward substitution on rows, then on columns). */
static void reduce(size_t m, const double *L, const double *A, double *C) {
    memcpy(C, A, m * m * sizeof *C);
    for (size_t col = 0; col < m; col++)     /* C := L^-1 C */
        for (size_t i = 0; i < m; i++) {
            double t = C[i * m + col];
            for (size_t k = 0; k < i; k++)
                t -= L[i * m + k] * C[k * m + col];
            C[i * m + col] = t / L[i * m + i];
        }
    for (size_t row = 0; row < m; row++)     /* C := C L^-T */
        for (size_t j = 0; j < m; j++) {
            double t = C[row * m + j];
            for (size_t k = 0; k < j; k++)
                t -= C[row * m + k] * L[j * m + k];
            C[row * m + j] = t / L[j * m + j];
        }
}

typedef struct cyc_work {
    double *cs, *sn, *Kh, *Mh, *C, *w;
} cyc_work;

static void work_free(cyc_work *w) {
    qd__free(w->cs);
    qd__free(w->sn);
    qd__free(w->Kh);
    qd__free(w->Mh);
    qd__free(w->C);
    qd__free(w->w);
}

/* Harmonic k's c values of w^2 appended at *pos. */
static qd_status solve_harmonic(qd_ctx *ctx, const qd_linear *lin, size_t c, size_t k,
                                cyc_work *w, qd_cyclic_modes *out, size_t *pos) {
    size_t n = lin->n, N = n / c, m = 2 * c;
    harmonic(n, c, k, lin->K, w->cs, w->sn, w->Kh);
    harmonic(n, c, k, lin->M, w->cs, w->sn, w->Mh);
    if (!cholesky(m, w->Mh)) {
        qd_ctx_error(ctx, QD_ERR_SINGULAR, "the mass matrix of harmonic %zu is not positive "
                     "definite", k);
        return QD_ERR_SINGULAR;
    }
    reduce(m, w->Mh, w->Kh, w->C);
    if (!qd__lin_sym_eig(ctx, m, w->C, w->w, NULL)) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "the eigen-solver (dsyev) failed on harmonic %zu", k);
        return QD_ERR_NUMERIC;
    }
    bool real = k == 0 || 2 * k == N;
    for (size_t a = 0; a < c; a++)   /* the real form gives each w^2 twice */
        for (size_t copy = 0; copy < (real ? 1u : 2u); copy++) {
            out->omega2[*pos] = w->w[2 * a];
            out->harmonic[*pos] = k;
            out->degeneracy[*pos] = real ? 1 : 2;
            (*pos)++;
        }
    return QD_OK;
}

static void sort_modes(qd_cyclic_modes *o) {
    for (size_t i = 1; i < o->n; i++) {   /* insertion sort: nearly sorted by k already */
        double w = o->omega2[i];
        size_t h = o->harmonic[i], d = o->degeneracy[i], j = i;
        while (j > 0 && o->omega2[j - 1] > w) {
            o->omega2[j] = o->omega2[j - 1];
            o->harmonic[j] = o->harmonic[j - 1];
            o->degeneracy[j] = o->degeneracy[j - 1];
            j--;
        }
        o->omega2[j] = w;
        o->harmonic[j] = h;
        o->degeneracy[j] = d;
    }
    double zero = QD_MODES_ZERO_TOL * max_abs(o->n, o->omega2);
    for (size_t i = 0; i < o->n; i++)
        if (fabs(o->omega2[i]) <= zero)
            o->omega2[i] = 0;
}

qd_status qd_cyclic_solve(qd_ctx *ctx, const qd_linear *lin, size_t cell, qd_cyclic_modes *out) {
    QD_ARGS_CTX(ctx, ctx && lin && out);
    memset(out, 0, sizeof *out);
    if (!ctx || !lin || cell == 0 || lin->n % cell || !shift_invariant(lin->n, cell, lin->M) ||
        !shift_invariant(lin->n, cell, lin->K)) {
        if (ctx)
            qd_ctx_error(ctx, QD_ERR_ARG, "the system is not invariant under the shift of its "
                         "coordinates by %zu", cell);
        return QD_ERR_ARG;
    }
    size_t n = lin->n, N = n / cell, m = 2 * cell, pos = 0;
    out->n = n;
    out->cells = N;
    out->cell = cell;
    out->omega2 = qd__malloc(ctx, (n + 1) * sizeof *out->omega2);
    out->harmonic = qd__malloc(ctx, (n + 1) * sizeof *out->harmonic);
    out->degeneracy = qd__malloc(ctx, (n + 1) * sizeof *out->degeneracy);
    cyc_work w = {.cs = qd__malloc(ctx, (N + 1) * sizeof *w.cs),
                  .sn = qd__malloc(ctx, (N + 1) * sizeof *w.sn),
                  .Kh = qd__malloc(ctx, (m * m + 1) * sizeof *w.Kh),
                  .Mh = qd__malloc(ctx, (m * m + 1) * sizeof *w.Mh),
                  .C = qd__malloc(ctx, (m * m + 1) * sizeof *w.C),
                  .w = qd__malloc(ctx, (m + 1) * sizeof *w.w)};
    qd_status st = out->omega2 && out->harmonic && out->degeneracy && w.cs && w.sn && w.Kh &&
                           w.Mh && w.C && w.w ? QD_OK : QD_ERR_NOMEM;
    for (size_t t = 0; st == QD_OK && t < N; t++) {
        w.cs[t] = cos(2 * PI * (double)t / (double)N);
        w.sn[t] = sin(2 * PI * (double)t / (double)N);
    }
    for (size_t k = 0; st == QD_OK && 2 * k <= N; k++)
        st = solve_harmonic(ctx, lin, cell, k, &w, out, &pos);
    work_free(&w);
    if (st == QD_OK)
        sort_modes(out);
    else
        qd_cyclic_modes_free(out);
    return st;
}
