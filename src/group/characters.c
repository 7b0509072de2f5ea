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
 * with orthonormal (well-conditioned) vectors.  The dimension follows from
 * |u(0)|^2 = d^2 / |G| and is rounded to an integer; the result is checked by
 * both orthogonality relations and sum d^2 = |G|, or refused. */
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

void qd__chartab_free(qd__chartab *t) {
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

static bool distinct(size_t n, const double *w) {
    double scale = fmax(fabs(w[0]), fabs(w[n - 1]));
    for (size_t i = 1; i < n; i++)
        if (w[i] - w[i - 1] < 1e-6 * scale)
            return false;
    return true;
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

/* Eigenvector u (column i of U) -> d = sqrt|G| |u_0| rounded, and
 * chi(l) = d u_l / (u_0 sqrt h_l). */
static qd_status row_from_vector(qd_ctx *ctx, const qd__group *g, const double _Complex *u, size_t i,
                                 qd__chartab *t) {
    size_t nc = g->nclass;
    double d = sqrt((double)g->order) * cabs(u[0]), dr = round(d);
    if (fabs(d - dr) > 1e-6 || dr < 1) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "character table: an irreducible dimension came out as %.9g", d);
        return QD_ERR_NUMERIC;
    }
    t->dim[i] = (size_t)dr;
    for (size_t l = 0; l < nc; l++) {
        double _Complex chi = dr * u[l] / (u[0] * sqrt((double)g->class_size[l]));
        t->re[i * nc + l] = creal(chi);
        t->im[i * nc + l] = cimag(chi);
    }
    return QD_OK;
}

static qd_status burnside_table(qd_ctx *ctx, const qd__group *g, qd__chartab *t) {
    size_t nc = g->nclass;
    if (nc > BURNSIDE_MAX_CLASSES) {
        qd_ctx_error(ctx, QD_ERR_TOOBIG, "character table: %zu classes is above the limit of %d", nc,
                     BURNSIDE_MAX_CLASSES);
        return QD_ERR_TOOBIG;
    }
    double _Complex *H = qd__malloc(ctx, 2 * nc * nc * sizeof *H), *coef = qd__malloc(ctx, nc * sizeof *coef);
    double *w = qd__malloc(ctx, nc * sizeof *w);
    qd_status st = H && coef && w ? QD_OK : QD_ERR_NOMEM;
    uint64_t seed = 0x9E3779B97F4A7C15ULL;
    bool split = false;
    for (int attempt = 0; attempt < 8 && st == QD_OK && !split; attempt++) {
        for (size_t j = 0; j < nc; j++)
            coef[j] = rand_unit(&seed) + I * rand_unit(&seed);
        burnside_matrix(g, coef, H);
        st = hermitian_eig(ctx, nc, H, w);
        split = st == QD_OK && distinct(nc, w);
    }
    if (st == QD_OK && !split) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "character table: the class matrices did not split");
        st = QD_ERR_NUMERIC;
    }
    for (size_t i = 0; i < nc && st == QD_OK; i++)
        st = row_from_vector(ctx, g, H + i * nc, i, t);
    qd__free(w);
    qd__free(coef);
    qd__free(H);
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

static void swap_rows(qd__chartab *t, size_t a, size_t b) {
    size_t n = t->n, d = t->dim[a];
    t->dim[a] = t->dim[b];
    t->dim[b] = d;
    for (size_t c = 0; c < n; c++) {
        double re = t->re[a * n + c], im = t->im[a * n + c];
        t->re[a * n + c] = t->re[b * n + c];
        t->im[a * n + c] = t->im[b * n + c];
        t->re[b * n + c] = re;
        t->im[b * n + c] = im;
    }
}

static void sort_rows(qd__chartab *t) {
    for (size_t i = 1; i < t->n; i++)
        for (size_t j = i; j > 0 && row_cmp(t, j - 1, j) > 0; j--)
            swap_rows(t, j - 1, j);
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
        st = burnside_table(ctx, g, t);
        if (st == QD_OK) {
            snap(nc * nc, t->re);
            snap(nc * nc, t->im);
            sort_rows(t);
        }
    }
    qd__free(pos);
    if (st == QD_OK) {
        snap(nc * nc, t->re);
        snap(nc * nc, t->im);
        st = verify(ctx, g, t);
    }
    if (st != QD_OK)
        qd__chartab_free(t);
    return st;
}
