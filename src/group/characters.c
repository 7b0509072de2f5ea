/* src/group/characters.c - the character table of a finite group.
 *
 * Cyclic and dihedral groups get their closed forms (no class matrices, so a
 * ring of 1000 masses costs O(n^2) table reads).  Any other group goes by
 * Burnside's method: the class sums multiply as C_j C_k = sum_l c_jkl C_l,
 * and for each irreducible character chi of dimension d the numbers
 * w(l) = h_l chi(l) / d (h_l the class size) satisfy
 *     w(j) w(k) = sum_l c_jkl w(l)
 * (Desloge App. 30, Theorem 23, eq. 19; seed-desloge-D.md App. 30): w is a
 * common eigenvector of the class matrices M_j[k][l] = c_jkl.  Scaled by
 * D = diag(sqrt h_l), these matrices become B_j, the multiplications by the
 * class sums in the orthonormal basis C_l / sqrt(h_l) of the centre of the
 * group algebra: they commute, B_j^T = B_j' (j' the class of the inverses)
 * and so they are normal.  One Hermitian matrix
 *     H = A + A^H,   A = sum_j (t_j + i s_j) B_j,   t, s random,
 * therefore has the common eigenvectors as its own, with distinct
 * eigenvalues almost surely, and zheev splits all the classes in one call
 * with orthonormal (well-conditioned) vectors; eigenvalues that nearly
 * coincide are split again on their subspace by another combination.  The
 * dimension follows from |u(0)|^2 = d^2 / |G| and is rounded to an integer,
 * the row from the Rayleigh quotients of the B_j (second-order accurate).
 * Groups H x C2 take H's table (product.c) before Burnside is tried.  Every
 * result is checked by both orthogonality relations and sum d^2 = |G|, or
 * refused. */
#include "group.h"
#include "../base/mem.h"

#include <complex.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

extern void zheev_(const char *jobz, const char *uplo, const int *n, double _Complex *a, const int *lda,
                   double *w, double _Complex *work, const int *lwork, double *rwork, int *info);

static const double TWO_PI = 6.28318530717958647692;

/* Above this many classes the orthogonality relations are checked on random
 * vectors (Freivalds) instead of entry by entry: O(n^2) instead of O(n^3). */
enum { EXACT_CHECK_MAX = 128, BURNSIDE_MAX_CLASSES = 1024 };

void qd__group_chartab_free(qd__chartab *t) {
    if (!t)
        return;
    qd__free(t->dim);
    qd__free(t->re);
    qd__free(t->im);
    memset(t, 0, sizeof *t);
}

/* xorshift64*: reproducible numbers without global state. */
static double rand_unit(uint64_t *s) {
    *s ^= *s >> 12;
    *s ^= *s << 25;
    *s ^= *s >> 27;
    return (double)((*s * 2685821657736338717ULL) >> 11) / 9007199254740992.0 * 2 - 1;
}

static size_t gmul(const qd__group *g, size_t a, size_t b) {
    return g->mul[a * g->order + b];
}

static size_t element_order(const qd__group *g, size_t a) {
    size_t k = 1;
    for (size_t x = a; x != g->identity; x = gmul(g, x, a))
        k++;
    return k;
}

static qd_status alloc_table(qd_ctx *ctx, size_t n, qd__chartab *t) {
    t->n = n;
    t->dim = qd__calloc(ctx, n, sizeof *t->dim);
    t->re = qd__calloc(ctx, n * n, sizeof *t->re);
    t->im = qd__calloc(ctx, n * n, sizeof *t->im);
    return t->dim && t->re && t->im ? QD_OK : QD_ERR_NOMEM;
}

/* pos[x] = k for x = r^k, SIZE_MAX off the cyclic subgroup of r. */
static void powers(const qd__group *g, size_t r, size_t *pos) {
    for (size_t x = 0; x < g->order; x++)
        pos[x] = SIZE_MAX;
    size_t k = 0;
    for (size_t x = g->identity; pos[x] == SIZE_MAX; x = gmul(g, x, r))
        pos[x] = k++;
}

static void set_root(qd__chartab *t, size_t i, size_t c, size_t dim, size_t jk, size_t n) {
    double a = TWO_PI * (double)(jk % n) / (double)n;
    t->re[i * t->n + c] = (double)dim * cos(a);
    t->im[i * t->n + c] = dim == 1 ? sin(a) : 0;
}

/* C_n: chi_j(r^k) = exp(2 pi i j k / n), rows j = 0, n/2 (n even), then the
 * complex pairs 1, n-1, 2, n-2, ... next to each other. */
static void cyclic_table(const qd__group *g, const size_t *pos, qd__chartab *t) {
    size_t n = g->order, i = 0;
    size_t *js = t->dim; /* borrowed as the list of j, then overwritten by 1s */
    js[i++] = 0;
    if (n % 2 == 0 && n > 1)
        js[i++] = n / 2;
    for (size_t j = 1; 2 * j < n; j++) {
        js[i++] = j;
        js[i++] = n - j;
    }
    for (i = 0; i < n; i++) {
        size_t j = js[i];
        for (size_t c = 0; c < n; c++)
            set_root(t, i, c, 1, j * pos[g->class_rep[c]], n);
    }
    for (i = 0; i < n; i++)
        t->dim[i] = 1;
}

/* D_m, m >= 3, from rotation r (order m) and reflection s: one-dimensional
 * rows (trivial; -1 on reflections; for even m the two with r -> -1), then
 * E_j, j = 1 .. (m-1)/2, with chi(r^k) = 2 cos(2 pi j k / m), 0 on reflections. */
static void dihedral_table(const qd__group *g, size_t s, const size_t *pos, qd__chartab *t) {
    size_t m = g->order / 2, nc = t->n, ones = m % 2 ? 2 : 4;
    for (size_t c = 0; c < nc; c++) {
        size_t x = g->class_rep[c], k = pos[x];
        bool refl = k == SIZE_MAX;
        if (refl)
            k = pos[gmul(g, s, x)];  /* x = s r^k */
        double par = k % 2 ? -1 : 1;
        double one[4] = {1, refl ? -1 : 1, par, refl ? -par : par};
        for (size_t i = 0; i < ones; i++)
            t->re[i * nc + c] = one[i];
        for (size_t i = ones; i < nc; i++)
            if (refl)
                t->re[i * nc + c] = 0;
            else
                set_root(t, i, c, 2, (i - ones + 1) * k, m);
    }
    for (size_t i = 0; i < nc; i++)
        t->dim[i] = i < ones ? 1 : 2;
}

/* r of order m = |G|/2 >= 3, every element off <r> an involution, and
 * s r s = r^-1 for one of them: the presentation of D_m. */
static bool is_dihedral(const qd__group *g, size_t *pos, size_t *r_out, size_t *s_out) {
    size_t n = g->order, m = n / 2, r = SIZE_MAX, s = SIZE_MAX;
    if (n % 2 || m < 3)
        return false;
    for (size_t a = 0; a < n && r == SIZE_MAX; a++)
        if (element_order(g, a) == m)
            r = a;
    if (r == SIZE_MAX)
        return false;
    powers(g, r, pos);
    for (size_t a = 0; a < n; a++)
        if (pos[a] == SIZE_MAX) {
            if (gmul(g, a, a) != g->identity)
                return false;
            s = s == SIZE_MAX ? a : s;
        }
    if (gmul(g, gmul(g, s, r), s) != g->inv[r])
        return false;
    *r_out = r;
    *s_out = s;
    return true;
}

static bool find_cyclic(const qd__group *g, size_t *r) {
    if (g->nclass != g->order)
        return false;
    for (size_t a = 0; a < g->order; a++)
        if (element_order(g, a) == g->order) {
            *r = a;
            return true;
        }
    return false;
}

/* A = sum_j (t_j + i s_j) B_j, B_j[l][k] = c_jkl sqrt(h_l / h_k), counted
 * from the pairs x y = z with z the representative of class l; then
 * H = A + A^H, column-major for LAPACK. */
static void burnside_matrix(const qd__group *g, const double _Complex *coef, double _Complex *H) {
    size_t nc = g->nclass, n = g->order;
    double _Complex *A = H + nc * nc;
    memset(A, 0, nc * nc * sizeof *A);
    for (size_t l = 0; l < nc; l++) {
        size_t z = g->class_rep[l];
        for (size_t x = 0; x < n; x++) {
            size_t j = g->class_of[x], k = g->class_of[gmul(g, g->inv[x], z)];
            A[l * nc + k] += coef[j] * sqrt((double)g->class_size[l] / (double)g->class_size[k]);
        }
    }
    for (size_t l = 0; l < nc; l++)
        for (size_t k = 0; k < nc; k++)
            H[l + k * nc] = A[l * nc + k] + conj(A[k * nc + l]);
}

/* Eigenvalues closer than this (relative to the largest) are taken as one
 * cluster, whose vectors are split again by another random combination:
 * an eigenvector's error is about eps |H| / gap, 1e-12 at this gap. */
static const double SPLIT_GAP = 1e-4;

static double spread(size_t n, const double *w) {
    return fmax(fabs(w[0]), fabs(w[n - 1]));
}

static size_t cluster_end(size_t n, const double *w, size_t a, double scale) {
    size_t b = a + 1;
    while (b < n && w[b] - w[b - 1] < SPLIT_GAP * scale)
        b++;
    return b;
}

static qd_status hermitian_eig(qd_ctx *ctx, size_t n, double _Complex *H, double *w) {
    int ni = (int)n, info = 0, lwork = -1;
    double _Complex q;
    double *rwork = qd__malloc(ctx, (3 * n + 1) * sizeof *rwork);
    if (!rwork)
        return QD_ERR_NOMEM;
    zheev_("V", "U", &ni, H, &ni, w, &q, &lwork, rwork, &info);
    lwork = info == 0 ? (int)creal(q) : 0;
    double _Complex *work = lwork > 0 ? qd__malloc(ctx, (size_t)lwork * sizeof *work) : NULL;
    if (work)
        zheev_("V", "U", &ni, H, &ni, w, work, &lwork, rwork, &info);
    qd_status st = !work ? QD_ERR_NOMEM : info ? QD_ERR_NUMERIC : QD_OK;
    if (st == QD_ERR_NUMERIC)
        qd_ctx_error(ctx, st, "character table: the eigensolver failed (zheev info %d)", info);
    qd__free(work);
    qd__free(rwork);
    return st;
}

/* Refinement costs n nclass^2 table reads in all; above this the rows come
 * from the vectors alone. */
static const double REFINE_MAX_WORK = 4e8;

/* omega(j) = u^H B_j^T u for every class j at once: the class matrices are
 * normal, so these Rayleigh quotients are exact to second order in the
 * error of u (1e-12 -> round-off), where u_l / u_0 is only first order. */
static void rayleigh(const qd__group *g, const double _Complex *u, const double *sq, double _Complex *omega) {
    size_t nc = g->nclass, n = g->order;
    for (size_t j = 0; j < nc; j++)
        omega[j] = 0;
    for (size_t l = 0; l < nc; l++) {
        size_t z = g->class_rep[l];
        for (size_t x = 0; x < n; x++) {
            size_t k = g->class_of[g->mul[g->inv[x] * n + z]];
            omega[g->class_of[x]] += conj(u[k]) * u[l] * sq[l] / sq[k];
        }
    }
}

/* Eigenvector u (column i of U) -> the row: d = sqrt|G| |u_0| rounded (the
 * u_l are omega(l) / sqrt(h_l) up to a common factor), and
 * chi(l) = d omega(l) / h_l, omega refined by rayleigh() when affordable. */
static qd_status row_from_vector(qd_ctx *ctx, const qd__group *g, const double _Complex *u, size_t i,
                                 double _Complex *omega, const double *sq, qd__chartab *t) {
    size_t nc = g->nclass;
    double d = sqrt((double)g->order) * cabs(u[0]), dr = round(d);
    if (fabs(d - dr) > 1e-6 || dr < 1) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "character table: an irreducible dimension came out as %.9g", d);
        return QD_ERR_NUMERIC;
    }
    t->dim[i] = (size_t)dr;
    if ((double)g->order * (double)nc * (double)nc <= REFINE_MAX_WORK)
        rayleigh(g, u, sq, omega);
    else
        for (size_t l = 0; l < nc; l++)
            omega[l] = u[l] * sq[l] / u[0];
    for (size_t l = 0; l < nc; l++) {
        double _Complex chi = dr * omega[l] / (sq[l] * sq[l]);
        t->re[i * nc + l] = creal(chi);
        t->im[i * nc + l] = cimag(chi);
    }
    return QD_OK;
}

typedef struct burnside {
    const qd__group *g;
    size_t nc;
    double _Complex *U;     /* nc x nc: the eigenvectors, column-major */
    double _Complex *H2;    /* 2 nc x nc: another combination and its scratch */
    double _Complex *T, *C; /* nc x nc each: H2 U_c, then U_c^H H2 U_c */
    double _Complex *coef;  /* nc */
    uint64_t seed;
} burnside;

static void draw(burnside *b) {
    for (size_t j = 0; j < b->nc; j++)
        b->coef[j] = rand_unit(&b->seed) + I * rand_unit(&b->seed);
}

/* C = U_c^H H2 U_c for the k columns U_c, through T = H2 U_c. */
static void restrict_to(burnside *b, const double _Complex *Uc, size_t k) {
    size_t nc = b->nc;
    for (size_t c = 0; c < k; c++)
        for (size_t r = 0; r < nc; r++) {
            double _Complex sum = 0;
            for (size_t q = 0; q < nc; q++)
                sum += b->H2[r + q * nc] * Uc[q + c * nc];
            b->T[r + c * nc] = sum;
        }
    for (size_t c = 0; c < k; c++)
        for (size_t r = 0; r < k; r++) {
            double _Complex sum = 0;
            for (size_t q = 0; q < nc; q++)
                sum += conj(Uc[q + r * nc]) * b->T[q + c * nc];
            b->C[r + c * k] = sum;
        }
}

/* U_c <- U_c V, V the k x k eigenvectors left in C. */
static void rotate(burnside *b, double _Complex *Uc, size_t k) {
    size_t nc = b->nc;
    for (size_t c = 0; c < k; c++)
        for (size_t r = 0; r < nc; r++) {
            double _Complex sum = 0;
            for (size_t q = 0; q < k; q++)
                sum += Uc[r + q * nc] * b->C[q + c * k];
            b->T[r + c * nc] = sum;
        }
    memcpy(Uc, b->T, k * nc * sizeof *Uc);
}

/* The k columns U_c = U[:, a .. a+k) span an invariant subspace of every
 * class matrix (their eigenvalues of H nearly coincide, but are far from the
 * rest): diagonalize another random combination on it, C = U_c^H H2 U_c,
 * rotate U_c by C's eigenvectors, and split what still clusters again. */
static qd_status split_cluster(qd_ctx *ctx, burnside *b, size_t a, size_t k, int depth) {
    if (depth > 24) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "character table: the class matrices did not split");
        return QD_ERR_NUMERIC;
    }
    double _Complex *Uc = b->U + a * b->nc;
    double *w = qd__malloc(ctx, k * sizeof *w);
    if (!w)
        return QD_ERR_NOMEM;
    draw(b);
    burnside_matrix(b->g, b->coef, b->H2);
    restrict_to(b, Uc, k);
    qd_status st = hermitian_eig(ctx, k, b->C, w);
    if (st == QD_OK)
        rotate(b, Uc, k);
    for (size_t i = 0, e; i < k && st == QD_OK; i = e) {
        e = cluster_end(k, w, i, spread(k, w));
        if (e - i > 1)
            st = split_cluster(ctx, b, a + i, e - i, depth + 1);
    }
    qd__free(w);
    return st;
}

static qd_status burnside_table(qd_ctx *ctx, const qd__group *g, qd__chartab *t) {
    size_t nc = g->nclass;
    if (nc > BURNSIDE_MAX_CLASSES) {
        qd_ctx_error(ctx, QD_ERR_TOOBIG, "character table: %zu classes is above the limit of %d", nc,
                     BURNSIDE_MAX_CLASSES);
        return QD_ERR_TOOBIG;
    }
    burnside b = {g, nc, NULL, NULL, NULL, NULL, NULL, 0x9E3779B97F4A7C15ULL};
    b.U = qd__malloc(ctx, 2 * nc * nc * sizeof *b.U);
    b.H2 = qd__malloc(ctx, 2 * nc * nc * sizeof *b.H2);
    b.T = qd__malloc(ctx, nc * nc * sizeof *b.T);
    b.C = qd__malloc(ctx, nc * nc * sizeof *b.C);
    b.coef = qd__malloc(ctx, nc * sizeof *b.coef);
    double *w = qd__malloc(ctx, nc * sizeof *w);
    qd_status st = b.U && b.H2 && b.T && b.C && b.coef && w ? QD_OK : QD_ERR_NOMEM;
    if (st == QD_OK) {
        draw(&b);
        burnside_matrix(g, b.coef, b.U);
        st = hermitian_eig(ctx, nc, b.U, w);
    }
    for (size_t a = 0, e; a < nc && st == QD_OK; a = e) {
        e = cluster_end(nc, w, a, spread(nc, w));
        if (e - a > 1)
            st = split_cluster(ctx, &b, a, e - a, 0);
    }
    double _Complex *omega = st == QD_OK ? qd__malloc(ctx, nc * sizeof *omega) : NULL;
    double *sq = st == QD_OK ? qd__malloc(ctx, nc * sizeof *sq) : NULL;
    st = st != QD_OK ? st : omega && sq ? QD_OK : QD_ERR_NOMEM;
    for (size_t l = 0; l < nc && st == QD_OK; l++)
        sq[l] = sqrt((double)g->class_size[l]);
    for (size_t i = 0; i < nc && st == QD_OK; i++)
        st = row_from_vector(ctx, g, b.U + i * nc, i, omega, sq, t);
    qd__free(sq);
    qd__free(omega);
    qd__free(w);
    qd__free(b.coef);
    qd__free(b.C);
    qd__free(b.T);
    qd__free(b.H2);
    qd__free(b.U);
    return st;
}

/* Rational character values are integers; round-off off them is noise (an
 * irrational value such as 2 cos(2 pi / 4096) stays 2e-6 away from one). */
static void snap(size_t n, double *v) {
    for (size_t i = 0; i < n; i++) {
        double r = round(v[i]);
        if (fabs(v[i] - r) < 1e-10)
            v[i] = r == 0 ? 0 : r;  /* no -0 in printed tables */
    }
}

static bool row_complex(const qd__chartab *t, size_t i) {
    for (size_t c = 0; c < t->n; c++)
        if (t->im[i * t->n + c] != 0)
            return true;
    return false;
}

static bool row_trivial(const qd__chartab *t, size_t i) {
    for (size_t c = 0; c < t->n; c++)
        if (t->re[i * t->n + c] != 1 || t->im[i * t->n + c] != 0)
            return false;
    return true;
}

/* Trivial first, then by dimension, real before complex, then by the
 * characters class by class, larger first: a fixed order for a given group. */
static int row_cmp(const qd__chartab *t, size_t a, size_t b) {
    if (row_trivial(t, a) != row_trivial(t, b))
        return row_trivial(t, a) ? -1 : 1;
    if (t->dim[a] != t->dim[b])
        return t->dim[a] < t->dim[b] ? -1 : 1;
    if (row_complex(t, a) != row_complex(t, b))
        return row_complex(t, a) ? 1 : -1;
    for (size_t c = 0; c < t->n; c++) {
        double da = t->re[a * t->n + c] - t->re[b * t->n + c];
        double di = t->im[a * t->n + c] - t->im[b * t->n + c];
        if (fabs(da) > 1e-9)
            return da > 0 ? -1 : 1;
        if (fabs(di) > 1e-9)
            return di > 0 ? -1 : 1;
    }
    return 0;
}

/* Merge sort of the row indices by row_cmp (stable), then one permutation
 * of the rows: the 1006 rows of D1000h would take ~1e9 moves by insertion. */
static void merge_sort(const qd__chartab *t, size_t *v, size_t *tmp, size_t n) {
    if (n < 2)
        return;
    size_t h = n / 2, i = 0, j = h, k = 0;
    merge_sort(t, v, tmp, h);
    merge_sort(t, v + h, tmp, n - h);
    while (i < h || j < n)
        tmp[k++] = j == n || (i < h && row_cmp(t, v[i], v[j]) <= 0) ? v[i++] : v[j++];
    memcpy(v, tmp, n * sizeof *v);
}

static qd_status sort_rows(qd_ctx *ctx, qd__chartab *t) {
    size_t n = t->n, *v = qd__malloc(ctx, 2 * n * sizeof *v);
    double *re = qd__malloc(ctx, n * n * sizeof *re), *im = qd__malloc(ctx, n * n * sizeof *im);
    size_t *dim = qd__malloc(ctx, n * sizeof *dim);
    qd_status st = v && re && im && dim ? QD_OK : QD_ERR_NOMEM;
    if (st == QD_OK) {
        for (size_t i = 0; i < n; i++)
            v[i] = i;
        merge_sort(t, v, v + n, n);
        for (size_t i = 0; i < n; i++) {
            dim[i] = t->dim[v[i]];
            memcpy(re + i * n, t->re + v[i] * n, n * sizeof *re);
            memcpy(im + i * n, t->im + v[i] * n, n * sizeof *im);
        }
        memcpy(t->dim, dim, n * sizeof *dim);
        memcpy(t->re, re, n * n * sizeof *re);
        memcpy(t->im, im, n * n * sizeof *im);
    }
    qd__free(dim);
    qd__free(im);
    qd__free(re);
    qd__free(v);
    return st;
}

static double _Complex chi(const qd__chartab *t, size_t i, size_t c) {
    return t->re[i * t->n + c] + I * t->im[i * t->n + c];
}

/* Largest deviation from sum_c h_c chi_i(c) chi_k(c)* = |G| delta_ik (rows)
 * or sum_i chi_i(c) chi_i(c')* = |G|/h_c delta_cc' (columns), entry by entry. */
static double exact_orthogonality(const qd__group *g, const qd__chartab *t, bool rows) {
    size_t n = t->n;
    double worst = 0;
    for (size_t a = 0; a < n; a++)
        for (size_t b = 0; b < n; b++) {
            double _Complex s = 0;
            for (size_t x = 0; x < n; x++)
                s += rows ? (double)g->class_size[x] * chi(t, a, x) * conj(chi(t, b, x))
                          : chi(t, x, a) * conj(chi(t, x, b));
            double want = a != b ? 0 : rows ? (double)g->order : (double)g->order / (double)g->class_size[a];
            worst = fmax(worst, cabs(s - want));
        }
    return worst;
}

/* The same relations on random vectors (Freivalds): X h X^* v = |G| v and
 * X^* X v = |G| h^-1 v, X[i][c] = chi_i(c); a wrong table fails almost surely. */
static double random_orthogonality(const qd__group *g, const qd__chartab *t, double _Complex *y,
                                   double *v) {
    size_t n = t->n;
    uint64_t seed = 0x2545F4914F6CDD1DULL;
    double worst = 0;
    for (int pass = 0; pass < 4; pass++) {
        bool rows = pass % 2 == 0;
        for (size_t i = 0; i < n; i++)
            v[i] = rand_unit(&seed);
        for (size_t c = 0; c < n; c++) {  /* rows: y = h X^* v; columns: y = X v */
            y[c] = 0;
            for (size_t i = 0; i < n; i++)
                y[c] += rows ? conj(chi(t, i, c)) * v[i] : chi(t, c, i) * v[i];
            y[c] *= rows ? (double)g->class_size[c] : 1;
        }
        for (size_t i = 0; i < n; i++) {
            double _Complex z = 0;
            for (size_t c = 0; c < n; c++)
                z += rows ? chi(t, i, c) * y[c] : conj(chi(t, c, i)) * y[c];
            double want = (double)g->order * v[i] / (rows ? 1 : (double)g->class_size[i]);
            worst = fmax(worst, cabs(z - want));
        }
    }
    return worst;
}

static qd_status verify(qd_ctx *ctx, const qd__group *g, const qd__chartab *t) {
    size_t n = t->n, sum = 0;
    for (size_t i = 0; i < n; i++)
        sum += t->dim[i] * t->dim[i];
    double err = 0;
    if (n <= EXACT_CHECK_MAX) {
        err = fmax(exact_orthogonality(g, t, true), exact_orthogonality(g, t, false));
    } else {
        double _Complex *y = qd__malloc(ctx, n * sizeof *y);
        double *v = qd__malloc(ctx, n * sizeof *v);
        if (y && v)
            err = random_orthogonality(g, t, y, v);
        qd__free(v);
        qd__free(y);
        if (!y || !v)
            return QD_ERR_NOMEM;
    }
    if (sum != g->order || !(err <= 1e-8 * (double)g->order)) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC,
                     "character table of a group of order %zu fails its checks: sum of d^2 = %zu, "
                     "orthogonality off by %.3g",
                     g->order, sum, err);
        return QD_ERR_NUMERIC;
    }
    return QD_OK;
}

qd_status qd__group_characters(qd_ctx *ctx, const qd__group *g, qd__chartab *t) {
    if (!g || !t || !g->mul)
        return QD_ERR_ARG;
    memset(t, 0, sizeof *t);
    size_t nc = g->nclass, r = 0, s = 0;
    size_t *pos = qd__malloc(ctx, g->order * sizeof *pos);
    qd_status st = pos ? alloc_table(ctx, nc, t) : QD_ERR_NOMEM;
    if (st == QD_OK && find_cyclic(g, &r)) {
        powers(g, r, pos);
        cyclic_table(g, pos, t);
    } else if (st == QD_OK && is_dihedral(g, pos, &r, &s)) {
        dihedral_table(g, s, pos, t);
    } else if (st == QD_OK) {
        bool product = false;
        st = qd__group_product_table(ctx, g, t, &product);
        if (st == QD_OK && !product)
            st = burnside_table(ctx, g, t);
        if (st == QD_OK) {
            snap(nc * nc, t->re);
            snap(nc * nc, t->im);
            st = sort_rows(ctx, t);
        }
    }
    qd__free(pos);
    if (st == QD_OK) {
        snap(nc * nc, t->re);
        snap(nc * nc, t->im);
        st = verify(ctx, g, t);
    }
    if (st != QD_OK)
        qd__group_chartab_free(t);
    return st;
}
