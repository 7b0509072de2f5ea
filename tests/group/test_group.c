/*
 * tests/group/test_group.c - finite groups, character tables, point-group
 * names and Mulliken labels (src/group) against the standard tables.
 *
 * The standard character tables are those of F. A. Cotton, "Chemical
 * Applications of Group Theory" (3rd ed., 1990), Appendix IIA; the theorems
 * checked are Desloge App. 28 and App. 30 (seed-desloge-D.md): the number of
 * irreducible representations equals the number of classes, sum d^2 = |G|,
 * both orthogonality relations, the class multiplication relation (Theorem
 * 23, eq. 19) and the multiplicity formula (Theorem 26, eq. 22), which splits
 * the vector representation (the traces of the 3x3 matrices) into the irreps
 * that Cotton's tables list for x, y, z.
 *
 * Point groups are built inside the test from generating matrices (C3v from a
 * rotation by 120 degrees and one mirror of an equilateral triangle in the xy
 * plane, Td from the S4 and C3 that map the tetrahedron (1,1,1), (1,-1,-1),
 * (-1,1,-1), (-1,-1,1) onto itself, ...): the closure under products, then the
 * multiplication table by matching matrices.
 */
#define _POSIX_C_SOURCE 200809L  /* clock_gettime */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "qdot/qdot.h"
#include "group/group.h"
#include "util/fault.h"
#include <complex.h>  /* after qdot's headers: its macro I is a parameter name there */

static const double PI = 3.14159265358979323846;

/* The D_1000 case prints its CPU time for the record and asserts nothing
 * about it: a test must not depend on the machine's speed (issue 30); the
 * speed is bench/run_symmetry's. */

enum { MAX_OPS = 120 };

typedef struct mgroup {
    size_t n;
    double R[MAX_OPS * 9];
    size_t mul[MAX_OPS * MAX_OPS];
} mgroup;

static void matmul(const double *a, const double *b, double *c) {
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            c[3 * i + j] = a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j] + a[3 * i + 2] * b[6 + j];
}

static size_t find_matrix(const mgroup *m, const double *a) {
    for (size_t k = 0; k < m->n; k++) {
        double d = 0;
        for (int i = 0; i < 9; i++)
            d = fmax(d, fabs(m->R[9 * k + i] - a[i]));
        if (d < 1e-9)
            return k;
    }
    return SIZE_MAX;
}

/* Closure of the generators (each 9 numbers, row-major) under products,
 * identity first, then the table mul[a][b] = index of R_a R_b. */
static mgroup *matrix_group(size_t ngen, const double *gens) {
    mgroup *m = calloc(1, sizeof *m);
    assert_non_null(m);
    static const double E[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    memcpy(m->R, E, sizeof E);
    m->n = 1;
    for (size_t k = 0; k < m->n; k++)
        for (size_t i = 0; i < ngen; i++) {
            double p[9];
            matmul(&m->R[9 * k], &gens[9 * i], p);
            if (find_matrix(m, p) == SIZE_MAX) {
                assert_true(m->n < MAX_OPS);
                memcpy(&m->R[9 * m->n++], p, sizeof p);
            }
        }
    for (size_t a = 0; a < m->n; a++)
        for (size_t b = 0; b < m->n; b++) {
            double p[9];
            matmul(&m->R[9 * a], &m->R[9 * b], p);
            m->mul[a * m->n + b] = find_matrix(m, p);
            assert_true(m->mul[a * m->n + b] != SIZE_MAX);
        }
    return m;
}

static void rot_z(double angle, double *R) {
    double c = cos(angle), s = sin(angle);
    double r[9] = {c, -s, 0, s, c, 0, 0, 0, 1};
    memcpy(R, r, sizeof r);
}

/* The generating matrices of the groups the tests use. */
#define C3Z {-0.5, -0.8660254037844386, 0, 0.8660254037844386, -0.5, 0, 0, 0, 1}
#define C4Z {0, -1, 0, 1, 0, 0, 0, 0, 1}
#define C2Z {-1, 0, 0, 0, -1, 0, 0, 0, 1}
#define C2X {1, 0, 0, 0, -1, 0, 0, 0, -1}
#define SXZ {1, 0, 0, 0, -1, 0, 0, 0, 1}   /* the mirror plane xz */
#define SXY {1, 0, 0, 0, 1, 0, 0, 0, -1}   /* sigma_h */
#define INV {-1, 0, 0, 0, -1, 0, 0, 0, -1}
#define S4Z {0, 1, 0, -1, 0, 0, 0, 0, -1}
#define C3D {0, 0, 1, 1, 0, 0, 0, 1, 0}    /* C3 about (1,1,1) */

typedef struct built {
    mgroup *m;
    qd_ctx *ctx;
    qd__group g;
    qd__chartab t;
} built;

static built build(size_t ngen, const double *gens) {
    built b = {matrix_group(ngen, gens), qd_ctx_new(), {0}, {0}};
    assert_non_null(b.ctx);
    assert_int_equal(qd__group_from_table(b.ctx, b.m->n, b.m->mul, &b.g), QD_OK);
    assert_int_equal(qd__group_characters(b.ctx, &b.g, &b.t), QD_OK);
    return b;
}

static void unbuild(built *b) {
    qd__group_chartab_free(&b->t);
    qd__group_free(&b->g);
    qd_ctx_free(b->ctx);
    free(b->m);
}

static double complex chi(const qd__chartab *t, size_t i, size_t c) {
    return t->re[i * t->n + c] + I * t->im[i * t->n + c];
}

/* Desloge App. 30: irreps = classes, sum d^2 = |G|, trivial row first and
 * dimensions non-decreasing, both orthogonality relations entry by entry. */
static void check_theorems(const qd__group *g, const qd__chartab *t) {
    size_t n = t->n, sum = 0;
    assert_int_equal(n, g->nclass);
    for (size_t i = 0; i < n; i++) {
        sum += t->dim[i] * t->dim[i];
        assert_true(g->order % t->dim[i] == 0);  /* d divides |G| */
        assert_true(i == 0 || t->dim[i] >= t->dim[i - 1]);
        assert_true(cabs(chi(t, i, 0) - (double)t->dim[i]) < 1e-12);
        assert_true(cabs(chi(t, 0, i) - 1) < 1e-12);
    }
    assert_int_equal(sum, g->order);
    for (size_t a = 0; a < n; a++)
        for (size_t b = 0; b < n; b++) {
            double complex rows = 0, cols = 0;
            for (size_t x = 0; x < n; x++) {
                rows += (double)g->class_size[x] * chi(t, a, x) * conj(chi(t, b, x));
                cols += chi(t, x, a) * conj(chi(t, x, b));
            }
            assert_true(cabs(rows - (a == b ? (double)g->order : 0)) < 1e-10 * (double)g->order);
            double want = a == b ? (double)g->order / (double)g->class_size[a] : 0;
            assert_true(cabs(cols - want) < 1e-10 * (double)g->order);
        }
}

/* Theorem 23, eq. 19: h_p chi(p) h_q chi(q) = d sum_r c_pqr h_r chi(r), with
 * c_pqr counted here from the table, independently of how the table was made. */
static void check_class_products(const qd__group *g, const qd__chartab *t, size_t p, size_t q) {
    size_t n = g->order, nc = g->nclass;
    double *c = calloc(nc, sizeof *c);
    assert_non_null(c);
    for (size_t x = 0; x < n; x++)
        for (size_t y = 0; y < n && g->class_of[x] == p; y++) {
            size_t z = g->mul[x * n + y];
            if (g->class_of[y] == q && z == g->class_rep[g->class_of[z]])
                c[g->class_of[z]] += 1;
        }
    for (size_t i = 0; i < t->n; i++) {
        double complex lhs = (double)(g->class_size[p] * g->class_size[q]) * chi(t, i, p) * chi(t, i, q);
        double complex rhs = 0;
        for (size_t r = 0; r < nc; r++)
            rhs += c[r] * (double)g->class_size[r] * chi(t, i, r);
        assert_true(cabs(lhs - (double)t->dim[i] * rhs) < 1e-9 * (1 + cabs(lhs)));
    }
    free(c);
}

static void check_all_class_products(const qd__group *g, const qd__chartab *t) {
    for (size_t p = 0; p < g->nclass; p++)
        for (size_t q = 0; q < g->nclass; q++)
            check_class_products(g, t, p, q);
}

enum { MAXC = 10 };

typedef struct std_table {
    const char *name;          /* Schoenflies */
    size_t nclass;
    double cols[MAXC][9];      /* one element of each of Cotton's classes */
    size_t sizes[MAXC];
    const char *labels[MAXC];  /* Cotton's Mulliken symbols */
    double chi[MAXC][MAXC];    /* Cotton's characters, real in these groups */
    int vector[MAXC];          /* multiplicity of each irrep in (x, y, z) */
} std_table;

/* Each of Cotton's rows matches exactly one computed row on every class;
 * found[k] is the computed row of Cotton's row k. */
static void match_standard(const built *b, const std_table *s, size_t *found) {
    size_t col[MAXC];
    assert_int_equal(b->g.nclass, s->nclass);
    for (size_t k = 0; k < s->nclass; k++) {
        size_t e = find_matrix(b->m, s->cols[k]);
        assert_true(e != SIZE_MAX);
        col[k] = b->g.class_of[e];
        assert_int_equal(b->g.class_size[col[k]], s->sizes[k]);
    }
    for (size_t k = 0; k < s->nclass; k++) {
        size_t hits = 0;
        for (size_t i = 0; i < b->t.n; i++) {
            bool same = true;
            for (size_t c = 0; c < s->nclass; c++)
                same = same && cabs(chi(&b->t, i, col[c]) - s->chi[k][c]) < 1e-12;
            if (same) {
                hits++;
                found[k] = i;
            }
        }
        if (hits != 1)
            fail_msg("%s: %zu computed rows match Cotton's", s->labels[k], hits);
    }
}

/* Theorem 26, eq. 22: m_i = (1/|G|) sum_g chi_i(g)* chi(g), chi(g) = tr R_g. */
static void check_vector_rep(const built *b, const std_table *s, const size_t *found) {
    for (size_t k = 0; k < s->nclass; k++) {
        double complex m = 0;
        for (size_t e = 0; e < b->m->n; e++) {
            const double *R = &b->m->R[9 * e];
            m += conj(chi(&b->t, found[k], b->g.class_of[e])) * (R[0] + R[4] + R[8]);
        }
        m /= (double)b->m->n;
        assert_true(cabs(m - s->vector[k]) < 1e-12);
    }
}

/* The public entry (qd_group_characters, qdot/symmetry.h) from the same
 * Cayley table: Cotton's name, his class sizes (as a multiset), sum d^2 =
 * |G| (Burnside), and each of his Mulliken symbols among the labels. */
static void check_public(const built *b, const std_table *s) {
    qd_symmetry pub;
    assert_int_equal(qd_group_characters(b->ctx, b->m->n, b->m->mul, b->m->R, &pub), QD_OK);
    assert_string_equal(pub.name, s->name);
    assert_int_equal(pub.nclass, s->nclass);
    assert_int_equal(pub.nirrep, s->nclass);
    size_t want[MAXC + 1] = {0}, got[MAXC + 1] = {0}, d2 = 0;
    for (size_t k = 0; k < s->nclass; k++) {
        want[s->sizes[k] <= MAXC ? s->sizes[k] : MAXC]++;
        got[pub.class_size[k] <= MAXC ? pub.class_size[k] : MAXC]++;
        d2 += pub.irrep_dim[k] * pub.irrep_dim[k];
    }
    assert_memory_equal(want, got, sizeof want);
    assert_int_equal(d2, b->m->n);
    for (size_t k = 0; k < s->nclass; k++) {
        bool seen = false;
        for (size_t i = 0; i < pub.nirrep; i++)
            seen |= strcmp(pub.label[i], s->labels[k]) == 0;
        assert_true(seen);
    }
    qd_symmetry_free(&pub);
    /* not a group: refused, nothing to free */
    size_t bad[4] = {0, 1, 1, 1};
    assert_int_equal(qd_group_characters(b->ctx, 2, bad, NULL, &pub), QD_ERR_ARG);
    qd_ctx_clear_error(b->ctx);
}

static void check_standard(size_t ngen, const double *gens, const std_table *s) {
    built b = build(ngen, gens);
    size_t found[MAXC];
    check_theorems(&b.g, &b.t);
    check_all_class_products(&b.g, &b.t);
    match_standard(&b, s, found);
    check_vector_rep(&b, s, found);
    char name[16], labels[MAXC][12];
    assert_int_equal(qd__group_pointgroup_name(b.ctx, &b.g, b.m->R, name), QD_OK);
    assert_string_equal(name, s->name);
    assert_int_equal(qd__group_irrep_labels(b.ctx, &b.g, b.m->R, &b.t, labels), QD_OK);
    for (size_t k = 0; k < s->nclass; k++)
        assert_string_equal(labels[found[k]], s->labels[k]);
    check_public(&b, s);
    unbuild(&b);
}

/* Cotton App. IIA.  Where a table has two classes of the same kind, the
 * tests put sigma_v in the plane xz and C2' along x, as Cotton's figures do. */
#define S_YZ {-1, 0, 0, 0, 1, 0, 0, 0, 1}
#define C3Z2 {-0.5, 0.8660254037844386, 0, -0.8660254037844386, -0.5, 0, 0, 0, 1}
#define C2XY {0, 1, 0, 1, 0, 0, 0, 0, -1}     /* C2 about x = y */
#define S_D {0, 1, 0, 1, 0, 0, 0, 0, 1}       /* mirror x <-> y */
#define S3Z {-0.5, -0.8660254037844386, 0, 0.8660254037844386, -0.5, 0, 0, 0, -1}
#define S4Z_ {0, -1, 0, 1, 0, 0, 0, 0, -1}
#define S6D {0, 0, -1, -1, 0, 0, 0, -1, 0}    /* -C3 about (1,1,1) */

static const std_table C2V = {
    "C2v", 4, {{1, 0, 0, 0, 1, 0, 0, 0, 1}, C2Z, SXZ, S_YZ}, {1, 1, 1, 1},
    {"A1", "A2", "B1", "B2"},
    {{1, 1, 1, 1}, {1, 1, -1, -1}, {1, -1, 1, -1}, {1, -1, -1, 1}},
    {1, 0, 1, 1}};

static const std_table C3V = {
    "C3v", 3, {{1, 0, 0, 0, 1, 0, 0, 0, 1}, C3Z, SXZ}, {1, 2, 3},
    {"A1", "A2", "E"},
    {{1, 1, 1}, {1, 1, -1}, {2, -1, 0}},
    {1, 0, 1}};

static const std_table C4V = {
    "C4v", 5, {{1, 0, 0, 0, 1, 0, 0, 0, 1}, C4Z, C2Z, SXZ, S_D}, {1, 2, 1, 2, 2},
    {"A1", "A2", "B1", "B2", "E"},
    {{1, 1, 1, 1, 1}, {1, 1, 1, -1, -1}, {1, -1, 1, 1, -1}, {1, -1, 1, -1, 1}, {2, 0, -2, 0, 0}},
    {1, 0, 0, 0, 1}};

static const std_table D3H = {
    "D3h", 6, {{1, 0, 0, 0, 1, 0, 0, 0, 1}, C3Z, C2X, SXY, S3Z, SXZ}, {1, 2, 3, 1, 2, 3},
    {"A1'", "A2'", "E'", "A1''", "A2''", "E''"},
    {{1, 1, 1, 1, 1, 1},
     {1, 1, -1, 1, 1, -1},
     {2, -1, 0, 2, -1, 0},
     {1, 1, 1, -1, -1, -1},
     {1, 1, -1, -1, -1, 1},
     {2, -1, 0, -2, 1, 0}},
    {0, 0, 1, 0, 1, 0}};

static const std_table D4H = {
    "D4h", 10,
    {{1, 0, 0, 0, 1, 0, 0, 0, 1}, C4Z, C2Z, C2X, C2XY, INV, S4Z_, SXY, SXZ, S_D},
    {1, 2, 1, 2, 2, 1, 2, 1, 2, 2},
    {"A1g", "A2g", "B1g", "B2g", "Eg", "A1u", "A2u", "B1u", "B2u", "Eu"},
    {{1, 1, 1, 1, 1, 1, 1, 1, 1, 1},
     {1, 1, 1, -1, -1, 1, 1, 1, -1, -1},
     {1, -1, 1, 1, -1, 1, -1, 1, 1, -1},
     {1, -1, 1, -1, 1, 1, -1, 1, -1, 1},
     {2, 0, -2, 0, 0, 2, 0, -2, 0, 0},
     {1, 1, 1, 1, 1, -1, -1, -1, -1, -1},
     {1, 1, 1, -1, -1, -1, -1, -1, 1, 1},
     {1, -1, 1, 1, -1, -1, 1, -1, -1, 1},
     {1, -1, 1, -1, 1, -1, 1, -1, 1, -1},
     {2, 0, -2, 0, 0, -2, 0, 2, 0, 0}},
    {0, 0, 0, 0, 0, 0, 1, 0, 0, 1}};

static const std_table TD = {
    "Td", 5, {{1, 0, 0, 0, 1, 0, 0, 0, 1}, C3D, C2Z, S4Z, S_D}, {1, 8, 3, 6, 6},
    {"A1", "A2", "E", "T1", "T2"},
    {{1, 1, 1, 1, 1}, {1, 1, 1, -1, -1}, {2, -1, 2, 0, 0}, {3, 0, -1, 1, -1}, {3, 0, -1, -1, 1}},
    {0, 0, 0, 0, 1}};

static const std_table OH = {
    "Oh", 10,
    {{1, 0, 0, 0, 1, 0, 0, 0, 1}, C3D, C2XY, C4Z, C2Z, INV, S4Z, S6D, SXY, S_D},
    {1, 8, 6, 6, 3, 1, 6, 8, 3, 6},
    {"A1g", "A2g", "Eg", "T1g", "T2g", "A1u", "A2u", "Eu", "T1u", "T2u"},
    {{1, 1, 1, 1, 1, 1, 1, 1, 1, 1},
     {1, 1, -1, -1, 1, 1, -1, 1, 1, -1},
     {2, -1, 0, 0, 2, 2, 0, -1, 2, 0},
     {3, 0, -1, 1, -1, 3, 1, 0, -1, -1},
     {3, 0, 1, -1, -1, 3, -1, 0, -1, 1},
     {1, 1, 1, 1, 1, -1, -1, -1, -1, -1},
     {1, 1, -1, -1, 1, -1, 1, -1, -1, 1},
     {2, -1, 0, 0, 2, -2, 0, 1, -2, 0},
     {3, 0, -1, 1, -1, -3, -1, 0, 1, 1},
     {3, 0, 1, -1, -1, -3, 1, 0, 1, -1}},
    {0, 0, 0, 0, 0, 0, 0, 0, 1, 0}};

#define STANDARD_TEST(fn, table, ...)                                                           \
    static void fn(void **state) {                                                             \
        (void)state;                                                                           \
        const double gens[][9] = {__VA_ARGS__};                                                \
        check_standard(sizeof gens / sizeof gens[0], &gens[0][0], &table);                     \
    }
STANDARD_TEST(test_c2v, C2V, C2Z, SXZ)
STANDARD_TEST(test_c3v, C3V, C3Z, SXZ)
STANDARD_TEST(test_c4v, C4V, C4Z, SXZ)
STANDARD_TEST(test_d3h, D3H, C3Z, C2X, SXY)
STANDARD_TEST(test_d4h, D4H, C4Z, C2X, INV)
STANDARD_TEST(test_td, TD, S4Z, C3D)
STANDARD_TEST(test_oh, OH, C4Z, C3D, INV)

/* The cyclic group C_n, mul[a][b] = a + b mod n, and the dihedral group D_n
 * as pairs r^k s^f numbered k + n f: (r^a s^f)(r^b s^h) = r^(a + (-1)^f b) s^(f+h). */
static size_t *cyclic_mul(size_t n) {
    size_t *m = malloc(n * n * sizeof *m);
    assert_non_null(m);
    for (size_t a = 0; a < n; a++)
        for (size_t b = 0; b < n; b++)
            m[a * n + b] = (a + b) % n;
    return m;
}

static size_t *dihedral_mul(size_t n) {
    size_t N = 2 * n, *m = malloc(N * N * sizeof *m);
    assert_non_null(m);
    for (size_t x = 0; x < N; x++)
        for (size_t y = 0; y < N; y++) {
            size_t a = x % n, f = x / n, b = y % n, h = y / n;
            size_t k = f ? (a + n - b) % n : (a + b) % n;
            m[x * N + y] = k + n * ((f + h) % 2);
        }
    return m;
}

/* C_n: n classes of one element; each row a homomorphism onto the n-th roots
 * of unity, chi(1) = exp(2 pi i j / n), the n values of j all different. */
static void check_cyclic(size_t n) {
    qd_ctx *ctx = qd_ctx_new();
    size_t *m = cyclic_mul(n);
    qd__group g;
    qd__chartab t;
    assert_int_equal(qd__group_from_table(ctx, n, m, &g), QD_OK);
    assert_int_equal(g.nclass, n);
    assert_int_equal(qd__group_characters(ctx, &g, &t), QD_OK);
    bool *seen = calloc(n, sizeof *seen);
    for (size_t i = 0; i < n; i++) {
        double complex c1 = chi(&t, i, g.class_of[n > 1]);  /* the generator 1 */
        double j = carg(c1) * (double)n / (2 * PI);
        size_t jr = (size_t)((long)lround(j) + (long)n) % n;
        assert_true(fabs(j - round(j)) < 1e-9 && !seen[jr]);
        seen[jr] = true;
        for (size_t a = 0; a < n; a += 1 + n / 50)
            for (size_t b = 0; b < n; b += 1 + n / 50)
                assert_true(cabs(chi(&t, i, g.class_of[a]) * chi(&t, i, g.class_of[b]) -
                                 chi(&t, i, g.class_of[m[a * n + b]])) < 1e-12);
    }
    if (n <= 50)
        check_theorems(&g, &t);
    free(seen);
    qd__group_chartab_free(&t);
    qd__group_free(&g);
    qd_ctx_free(ctx);
    free(m);
}

static void test_cyclic(void **state) {
    (void)state;
    check_cyclic(1);
    check_cyclic(2);
    check_cyclic(5);
    check_cyclic(6);
    check_cyclic(1000);
}

/* D_n (Desloge App. 28; the ring of n equal masses): classes {e}, the pairs
 * {r^k, r^-k}, {r^(n/2)} for even n, the reflections in one class of n (n odd)
 * or two of n/2 (n even); 2 or 4 one-dimensional irreps, the rest of dimension 2. */
static void check_dihedral(size_t n, bool timed) {
    qd_ctx *ctx = qd_ctx_new();
    size_t *m = dihedral_mul(n), even = n % 2 == 0;
    qd__group g;
    qd__chartab t;
    clock_t c0 = clock();
    assert_int_equal(qd__group_from_table(ctx, 2 * n, m, &g), QD_OK);
    assert_int_equal(qd__group_characters(ctx, &g, &t), QD_OK);
    double secs = (double)(clock() - c0) / CLOCKS_PER_SEC;
    if (timed) {  /* CPU time: wall time on a shared machine is mostly waiting */
        printf("D_%zu (order %zu): group and character table in %.3f s of CPU\n", n, 2 * n, secs);
    }
    size_t nclass = (n - 1) / 2 + 1 + (even ? 3 : 1), ones = 0;
    assert_int_equal(g.nclass, nclass);
    assert_int_equal(g.class_size[g.class_of[n]], even ? n / 2 : n);  /* s */
    assert_int_equal(g.class_size[g.class_of[1]], 2);                  /* r */
    if (even)
        assert_int_equal(g.class_size[g.class_of[n / 2]], 1);
    for (size_t i = 0; i < t.n; i++)
        ones += t.dim[i] == 1;
    assert_int_equal(ones, even ? 4 : 2);
    if (n <= 50) {
        check_theorems(&g, &t);
        check_all_class_products(&g, &t);
    } else {
        size_t ps[] = {1, 2, 7, n / 2, n, n + 1, 2 * n - 1};
        for (size_t a = 0; a < 7; a++)
            for (size_t b = 0; b < 7; b++)
                check_class_products(&g, &t, g.class_of[ps[a]], g.class_of[ps[b]]);
    }
    qd__group_chartab_free(&t);
    qd__group_free(&g);
    qd_ctx_free(ctx);
    free(m);
}

static void test_dihedral(void **state) {
    (void)state;
    check_dihedral(3, false);
    check_dihedral(5, false);
    check_dihedral(6, false);
    check_dihedral(1000, true);
}

/* D_n x C2 (D_nh for even n: the ring of masses moving in space), element
 * x + 2n e for x of dihedral_mul(n) and e in C2.  Its irreducible characters
 * are D_n's times +-1 on e (written here from the dihedral closed form, not
 * from the library): each computed row must be one of them, and each of
 * them appear. */
static size_t *dnh_mul(size_t n) {
    size_t N = 2 * n, M = 2 * N, *d = dihedral_mul(n), *m = malloc(M * M * sizeof *m);
    for (size_t x = 0; x < M; x++)
        for (size_t y = 0; y < M; y++)
            m[x * M + y] = d[(x % N) * N + y % N] + N * ((x / N + y / N) % 2);
    free(d);
    return m;
}

/* chi of D_n's irrep j (0, 1: trivial and sign of the reflections; 2, 3:
 * the two with r -> -1 for even n; then E_(j-3) or E_(j-1)) at r^k s^f. */
static double dihedral_chi(size_t n, size_t j, size_t k, size_t f) {
    size_t ones = n % 2 ? 2 : 4;
    double par = k % 2 ? -1 : 1;
    if (j < ones) {
        double v[4] = {1, f ? -1 : 1, par, f ? -par : par};
        return v[j];
    }
    return f ? 0 : 2 * cos(2 * PI * (double)((j - ones + 1) * k % n) / (double)n);
}

static void check_dnh(size_t n, bool timed) {
    size_t N = 2 * n, M = 2 * N, *m = dnh_mul(n), nd = n % 2 ? (n - 1) / 2 + 2 : n / 2 + 3;
    qd_ctx *ctx = qd_ctx_new();
    qd__group g;
    qd__chartab t;
    clock_t c0 = clock();
    assert_int_equal(qd__group_from_table(ctx, M, m, &g), QD_OK);
    assert_int_equal(qd__group_characters(ctx, &g, &t), QD_OK);
    double secs = (double)(clock() - c0) / CLOCKS_PER_SEC;
    if (timed) {
        printf("D_%zu x C2 (order %zu, %zu classes): group and character table in %.3f s of CPU\n", n, M,
               g.nclass, secs);
    }
    assert_int_equal(g.nclass, 2 * nd);
    bool *hit = calloc(2 * nd, sizeof *hit);
    for (size_t i = 0; i < t.n; i++) {
        size_t found = 0;
        for (size_t j = 0; j < nd; j++)
            for (size_t e = 0; e < 2; e++) {
                bool same = true;
                for (size_t c = 0; c < g.nclass && same; c++) {
                    size_t x = g.class_rep[c], k = x % n, f = x % N / n, odd = x / N;
                    double want = dihedral_chi(n, j, k, f) * (e && odd ? -1 : 1);
                    same = cabs(chi(&t, i, c) - want) < 1e-12;
                }
                if (same) {
                    found++;
                    assert_false(hit[2 * j + e]);
                    hit[2 * j + e] = true;
                }
            }
        assert_int_equal(found, 1);
    }
    if (n <= 50)
        check_theorems(&g, &t);
    free(hit);
    qd__group_chartab_free(&t);
    qd__group_free(&g);
    qd_ctx_free(ctx);
    free(m);
}

static void test_dnh(void **state) {
    (void)state;
    check_dnh(4, false);
    check_dnh(6, false);
    check_dnh(100, false);
    check_dnh(1000, true);
}

/* C_p x C_q with p, q odd (no involution, so neither closed form nor the
 * H x C2 split applies: Burnside's method on p q classes, complex
 * characters): every row is (a, b) -> exp(2 pi i (j a / p + l b / q)) for
 * one (j, l), each pair once, to 1e-13.  169 classes take the Freivalds
 * check, and with the fixed seed two pairs of 13 x 13's eigenvalues fall
 * closer than the split gap, so it goes through split_cluster (seen with a
 * trace when this was written). */
static void check_abelian(size_t p, size_t q) {
    size_t n = p * q, *m = malloc(n * n * sizeof *m);
    for (size_t x = 0; x < n; x++)
        for (size_t y = 0; y < n; y++)
            m[x * n + y] = (x % p + y % p) % p + p * ((x / p + y / p) % q);
    qd_ctx *ctx = qd_ctx_new();
    qd__group g;
    qd__chartab t;
    assert_int_equal(qd__group_from_table(ctx, n, m, &g), QD_OK);
    assert_int_equal(g.nclass, n);
    assert_int_equal(qd__group_characters(ctx, &g, &t), QD_OK);
    bool *hit = calloc(n, sizeof *hit);
    for (size_t i = 0; i < n; i++) {
        /* (j, l) from the generators (1, 0) and (0, 1) */
        double complex c1 = chi(&t, i, g.class_of[1]), c2 = chi(&t, i, g.class_of[p]);
        size_t j = (size_t)((lround(carg(c1) * (double)p / (2 * PI)) + (long)p) % (long)p);
        size_t l = (size_t)((lround(carg(c2) * (double)q / (2 * PI)) + (long)q) % (long)q);
        assert_false(hit[j + p * l]);
        hit[j + p * l] = true;
        for (size_t x = 0; x < n; x++) {
            double a = 2 * PI * ((double)(j * (x % p) % p) / (double)p + (double)(l * (x / p) % q) / (double)q);
            assert_true(cabs(chi(&t, i, g.class_of[x]) - cexp(I * a)) < 1e-13);
        }
    }
    if (n <= 128)
        check_theorems(&g, &t);
    free(hit);
    qd__group_chartab_free(&t);
    qd__group_free(&g);
    qd_ctx_free(ctx);
    free(m);
}

static void test_abelian(void **state) {
    (void)state;
    check_abelian(3, 3);
    check_abelian(3, 9);
    check_abelian(11, 11);
    check_abelian(13, 13);
}

/* The quaternion group: element 4 s + u is (-1)^s times the unit u of
 * 1, i, j, k.  Not dihedral (one involution), so it takes Burnside's path;
 * its table is D4's: four one-dimensional rows and a two-dimensional one
 * with chi(-1) = -2 and 0 on +-i, +-j, +-k. */
static void test_quaternion(void **state) {
    (void)state;
    static const int unit[4][4] = {{0, 1, 2, 3}, {1, -0, 3, -2}, {2, -3, -0, 1}, {3, 2, -1, -0}};
    static const int sign[4][4] = {{0, 0, 0, 0}, {0, 1, 0, 1}, {0, 1, 1, 0}, {0, 0, 1, 1}};
    size_t m[64];
    for (size_t x = 0; x < 8; x++)
        for (size_t y = 0; y < 8; y++) {
            size_t u = x % 4, v = y % 4, s = (x / 4 + y / 4 + (size_t)sign[u][v]) % 2;
            m[x * 8 + y] = 4 * s + (size_t)abs(unit[u][v]);
        }
    qd_ctx *ctx = qd_ctx_new();
    qd__group g;
    qd__chartab t;
    assert_int_equal(qd__group_from_table(ctx, 8, m, &g), QD_OK);
    assert_int_equal(g.nclass, 5);
    assert_int_equal(g.class_size[g.class_of[4]], 1);  /* -1 is central */
    assert_int_equal(qd__group_characters(ctx, &g, &t), QD_OK);
    check_theorems(&g, &t);
    check_all_class_products(&g, &t);
    assert_int_equal(t.dim[4], 2);
    assert_true(chi(&t, 4, g.class_of[4]) == -2);
    for (size_t x = 1; x < 4; x++)
        assert_true(chi(&t, 4, g.class_of[x]) == 0);
    qd__group_chartab_free(&t);
    qd__group_free(&g);
    qd_ctx_free(ctx);
}

/* S5, 120 permutations of 5 points, (a b)(x) = a(b(x)): seven classes (cycle
 * types) of sizes 1, 10, 15, 20, 20, 30, 24, irreps of dimensions 1, 1, 4, 4,
 * 5, 5, 6, and the standard representation chi(g) = fix(g) - 1 among them. */
static size_t perm_index(const int *p, const int (*all)[5], size_t n) {
    for (size_t k = 0; k < n; k++)
        if (memcmp(p, all[k], 5 * sizeof *p) == 0)
            return k;
    return SIZE_MAX;
}

static void test_s5(void **state) {
    (void)state;
    static int all[120][5];
    size_t n = 0, *m = malloc(120 * 120 * sizeof *m);
    for (int a = 0; a < 3125; a++) {
        int p[5], used = 0, ok = 1;
        for (int i = 0, v = a; i < 5; i++, v /= 5) {
            p[i] = v % 5;
            ok = ok && !(used & 1 << p[i]);
            used |= 1 << p[i];
        }
        if (ok)
            memcpy(all[n++], p, sizeof p);
    }
    assert_int_equal(n, 120);
    for (size_t a = 0; a < n; a++)
        for (size_t b = 0; b < n; b++) {
            int p[5];
            for (int x = 0; x < 5; x++)
                p[x] = all[a][all[b][x]];
            m[a * n + b] = perm_index(p, (const int(*)[5])all, n);
        }
    qd_ctx *ctx = qd_ctx_new();
    qd__group g;
    qd__chartab t;
    assert_int_equal(qd__group_from_table(ctx, n, m, &g), QD_OK);
    assert_int_equal(g.nclass, 7);
    size_t count[121] = {0};
    for (size_t c = 0; c < 7; c++)
        count[g.class_size[c]]++;
    assert_true(count[1] == 1 && count[10] == 1 && count[15] == 1 && count[20] == 2 && count[30] == 1 &&
                count[24] == 1);
    assert_int_equal(qd__group_characters(ctx, &g, &t), QD_OK);
    check_theorems(&g, &t);
    check_all_class_products(&g, &t);
    static const size_t dims[7] = {1, 1, 4, 4, 5, 5, 6};
    size_t standard = 0;
    for (size_t i = 0; i < 7; i++) {
        assert_int_equal(t.dim[i], dims[i]);
        bool same = true;
        for (size_t c = 0; c < 7; c++) {
            const int *p = all[g.class_rep[c]];
            int fix = 0;
            for (int x = 0; x < 5; x++)
                fix += p[x] == x;
            same = same && chi(&t, i, c) == fix - 1;
        }
        standard += same;
    }
    assert_int_equal(standard, 1);
    qd__group_chartab_free(&t);
    qd__group_free(&g);
    qd_ctx_free(ctx);
    free(m);
}

static void expect_refused(size_t n, const size_t *m, const char *why) {
    qd_ctx *ctx = qd_ctx_new();
    qd__group g;
    assert_int_equal(qd__group_from_table(ctx, n, m, &g), QD_ERR_ARG);
    assert_int_equal(qd_ctx_status(ctx), QD_ERR_ARG);
    if (!strstr(qd_ctx_message(ctx), why))
        fail_msg("message \"%s\" lacks \"%s\"", qd_ctx_message(ctx), why);
    assert_null(g.mul);
    qd__group_free(&g);  /* harmless after a refusal */
    qd_ctx_free(ctx);
}

/* Tables that are not groups: the loop of order 5 below has an identity
 * and inverses (every row and column a permutation) but x x = 0 for every
 * x, impossible in a group of order 5 (cyclic, so only the identity is its
 * own inverse); a - b mod 4 is a Latin square with no identity. */
static void test_not_groups(void **state) {
    (void)state;
    static const size_t loop5[25] = {0, 1, 2, 3, 4, 1, 0, 3, 4, 2, 2, 4, 0, 1, 3,
                                     3, 2, 4, 0, 1, 4, 3, 1, 2, 0};
    expect_refused(5, loop5, "not associative");
    size_t diff[16], big[4] = {0, 1, 1, 7}, twice[4] = {0, 1, 1, 1};
    for (size_t a = 0; a < 4; a++)
        for (size_t b = 0; b < 4; b++)
            diff[a * 4 + b] = (a + 4 - b) % 4;  /* a - b: a Latin square, no identity */
    expect_refused(4, diff, "identity");
    expect_refused(2, big, "outside");
    expect_refused(2, twice, "twice");
    expect_refused(0, twice, "at least one element");
}

/* Rotation by angle about the unit vector k (Rodrigues), times sign (-1:
 * the improper element -C). */
static void axis_turn(const double *k, double angle, double sign, double *R) {
    double c = cos(angle), s = sin(angle), K[9] = {0, -k[2], k[1], k[2], 0, -k[0], -k[1], k[0], 0};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            R[3 * i + j] = sign * (c * (i == j) + s * K[3 * i + j] + (1 - c) * k[i] * k[j]);
}

static int cmp_str(const void *a, const void *b) {
    return strcmp(*(const char *const *)a, *(const char *const *)b);
}

/* Space-separated, sorted: a multiset of labels as one string. */
static void join_sorted(size_t n, const char **v, char *out, size_t size) {
    qsort(v, n, sizeof *v, cmp_str);
    out[0] = '\0';
    for (size_t i = 0; i < n; i++) {
        strncat(out, v[i], size - strlen(out) - 1);
        if (i + 1 < n)
            strncat(out, " ", size - strlen(out) - 1);
    }
}

/* Td is the symmetric group of the tetrahedron's four vertices (1,1,1),
 * (1,-1,-1), (-1,1,-1), (-1,-1,1): each of the 24 matrices permutes them,
 * and no two alike.  The same group, its elements renumbered at random
 * (identity no longer first), keeps its class sizes, name and labels. */
static void test_td_vertices(void **state) {
    (void)state;
    static const double V[4][3] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    const double gens[][9] = {S4Z, C3D};
    built b = build(2, &gens[0][0]);
    assert_int_equal(b.m->n, 24);
    int seen[256] = {0};
    for (size_t e = 0; e < 24; e++) {
        int code = 0;
        for (int v = 0; v < 4; v++) {
            const double *R = &b.m->R[9 * e];
            double w[3] = {0};
            for (int i = 0; i < 3; i++)
                w[i] = R[3 * i] * V[v][0] + R[3 * i + 1] * V[v][1] + R[3 * i + 2] * V[v][2];
            int hit = -1;
            for (int u = 0; u < 4; u++)
                if (fabs(w[0] - V[u][0]) + fabs(w[1] - V[u][1]) + fabs(w[2] - V[u][2]) < 1e-12)
                    hit = u;
            assert_true(hit >= 0);
            code = 4 * code + hit;
        }
        assert_int_equal(seen[code]++, 0);
    }
    /* renumber: element e becomes p[e] */
    size_t n = 24, p[24], *mul = malloc(n * n * sizeof *mul);
    double R[24 * 9];
    for (size_t e = 0; e < n; e++)
        p[e] = (7 * e + 5) % n;
    for (size_t a = 0; a < n; a++) {
        memcpy(R + 9 * p[a], b.m->R + 9 * a, 9 * sizeof *R);
        for (size_t c = 0; c < n; c++)
            mul[p[a] * n + p[c]] = p[b.m->mul[a * n + c]];
    }
    qd__group g;
    qd__chartab t;
    char name[16], labels[5][12];
    assert_int_equal(qd__group_from_table(b.ctx, n, mul, &g), QD_OK);
    assert_int_equal(g.identity, 5);
    assert_int_equal(qd__group_characters(b.ctx, &g, &t), QD_OK);
    check_theorems(&g, &t);
    assert_int_equal(qd__group_pointgroup_name(b.ctx, &g, R, name), QD_OK);
    assert_string_equal(name, "Td");
    assert_int_equal(qd__group_irrep_labels(b.ctx, &g, R, &t, labels), QD_OK);
    const char *v[5] = {labels[0], labels[1], labels[2], labels[3], labels[4]};
    char all[64];
    join_sorted(5, v, all, sizeof all);
    assert_string_equal(all, "A1 A2 E T1 T2");
    qd__group_chartab_free(&t);
    qd__group_free(&g);
    free(mul);
    unbuild(&b);
}

typedef struct named {
    const char *name;
    const char *labels;  /* Cotton's Mulliken symbols, sorted ("a"/"b": the halves of a complex E) */
    const char *vector;  /* the irreps of x, y, z in Cotton's right-hand column, sorted */
} named;

/* The point group of the generators: its name, its labels, and the labels of
 * the irreps in the vector representation (multiplicities by eq. 22). */
static void check_named(size_t ngen, const double *gens, const named *want) {
    built b = build(ngen, gens);
    size_t n = b.t.n, nv = 0;
    char name[16], (*labels)[12] = calloc(n, sizeof *labels), all[512], vec[128];
    const char **v = calloc(n, sizeof *v), *vv[3];
    assert_int_equal(qd__group_pointgroup_name(b.ctx, &b.g, b.m->R, name), QD_OK);
    assert_string_equal(name, want->name);
    assert_int_equal(qd__group_irrep_labels(b.ctx, &b.g, b.m->R, &b.t, labels), QD_OK);
    for (size_t i = 0; i < n; i++) {
        v[i] = labels[i];
        double complex m = 0;
        for (size_t e = 0; e < b.m->n; e++) {
            const double *R = &b.m->R[9 * e];
            m += conj(chi(&b.t, i, b.g.class_of[e])) * (R[0] + R[4] + R[8]);
        }
        m /= (double)b.m->n;
        assert_true(cabs(m - round(creal(m))) < 1e-12);
        for (long k = 0; k < lround(creal(m)); k++)
            vv[nv++] = labels[i];
    }
    join_sorted(n, v, all, sizeof all);
    join_sorted(nv, vv, vec, sizeof vec);
    assert_string_equal(all, want->labels);
    assert_string_equal(vec, want->vector);
    check_theorems(&b.g, &b.t);
    free(v);
    free(labels);
    unbuild(&b);
}

/* Every Schoenflies family of the flowchart, with Cotton's labels. */
static void test_point_groups(void **state) {
    (void)state;
    double c5[9], c6[9], s8[9], s6[9], c5v[9], c3v[9];
    rot_z(2 * PI / 5, c5);
    rot_z(2 * PI / 6, c6);
    axis_turn((const double[]){0, 0, 1}, 2 * PI / 8 + PI, -1, s8);  /* sigma_h C8 = -C(pi + 2 pi/8) */
    axis_turn((const double[]){0, 0, 1}, 2 * PI / 3, -1, s6);       /* i C3 */
    double phi = (1 + sqrt(5)) / 2, len = sqrt(1 + phi * phi);
    axis_turn((const double[]){0, 1 / len, phi / len}, 2 * PI / 5, 1, c5v);  /* a vertex of the icosahedron */
    memcpy(c3v, (const double[])C3D, sizeof c3v);
    const double one[][9] = {{1, 0, 0, 0, 1, 0, 0, 0, 1}};
    check_named(1, &one[0][0], &(named){"C1", "A", "A A A"});
#define NAMED(nm, lab, vec, ...)                                                                   \
    do {                                                                                           \
        const double gens[][9] = {__VA_ARGS__};                                                    \
        check_named(sizeof gens / sizeof gens[0], &gens[0][0], &(named){nm, lab, vec});            \
    } while (0)
    NAMED("Cs", "A' A''", "A' A' A''", SXY);
    NAMED("Ci", "Ag Au", "Au Au Au", INV);
    NAMED("C2", "A B", "A B B", C2Z);
    NAMED("C3", "A Ea Eb", "A Ea Eb", C3Z);
    NAMED("C2h", "Ag Au Bg Bu", "Au Bu Bu", C2Z, SXY);
    NAMED("C3h", "A' A'' Ea' Ea'' Eb' Eb''", "A'' Ea' Eb'", C3Z, SXY);
    NAMED("C4h", "Ag Au Bg Bu Eag Eau Ebg Ebu", "Au Eau Ebu", C4Z, SXY);
    NAMED("S4", "A B Ea Eb", "B Ea Eb", S4Z);
    NAMED("D2", "A B1 B2 B3", "B1 B2 B3", C2Z, C2X);
    NAMED("D2h", "Ag Au B1g B1u B2g B2u B3g B3u", "B1u B2u B3u", C2Z, C2X, INV);
    NAMED("D2d", "A1 A2 B1 B2 E", "B2 E", S4Z, C2X);
    NAMED("D3", "A1 A2 E", "A2 E", C3Z, C2X);
    NAMED("D3d", "A1g A1u A2g A2u Eg Eu", "A2u Eu", C3Z, C2X, INV);
    NAMED("T", "A Ea Eb T", "T", C3D, C2Z);
    NAMED("Th", "Ag Au Eag Eau Ebg Ebu Tg Tu", "Tu", C3D, C2Z, INV);
    NAMED("O", "A1 A2 E T1 T2", "T1", C4Z, C3D);
#undef NAMED
    const double c5vg[][9] = {{0}, SXZ};
    double g2[2][9];
    memcpy(g2, c5vg, sizeof g2);
    memcpy(g2[0], c5, sizeof c5);
    check_named(2, &g2[0][0], &(named){"C5v", "A1 A2 E1 E2", "A1 E1"});
    const double d6h[][9] = {{0}, C2X, SXY};
    double g3[3][9];
    memcpy(g3, d6h, sizeof g3);
    memcpy(g3[0], c6, sizeof c6);
    check_named(3, &g3[0][0],
                &(named){"D6h", "A1g A1u A2g A2u B1g B1u B2g B2u E1g E1u E2g E2u", "A2u E1u"});
    check_named(1, s8, &(named){"S8", "A B E1a E1b E2a E2b E3a E3b", "B E1a E1b"});
    memcpy(g2[0], s8, sizeof s8);
    memcpy(g2[1], (const double[])C2X, sizeof s8);
    check_named(2, &g2[0][0], &(named){"D4d", "A1 A2 B1 B2 E1 E2 E3", "B2 E1"});
    check_named(1, s6, &(named){"S6", "Ag Au Eag Eau Ebg Ebu", "Au Eau Ebu"});
    memcpy(g2[0], c5v, sizeof c5v);
    memcpy(g2[1], c3v, sizeof c3v);
    check_named(2, &g2[0][0], &(named){"I", "A G H T1 T2", "T1"});
    memcpy(g3[0], c5v, sizeof c5v);
    memcpy(g3[1], c3v, sizeof c3v);
    memcpy(g3[2], (const double[])INV, sizeof c3v);
    check_named(3, &g3[0][0],
                &(named){"Ih", "Ag Au Gg Gu Hg Hu T1g T1u T2g T2u", "T1u"});
}

/* The icosahedral rotation group I: irrational characters, from Burnside's
 * method to 1e-12 against Cotton's table (E, 12 C5, 12 C5^2, 20 C3, 15 C2;
 * T1: 3, (1 + sqrt 5)/2, (1 - sqrt 5)/2, 0, -1, ...), rows found by label. */
static void test_icosahedral(void **state) {
    (void)state;
    double gens[2][9], c5sq[9], phi = (1 + sqrt(5)) / 2, len = sqrt(1 + phi * phi);
    axis_turn((const double[]){0, 1 / len, phi / len}, 2 * PI / 5, 1, gens[0]);
    memcpy(gens[1], (const double[])C3D, sizeof gens[1]);
    matmul(gens[0], gens[0], c5sq);
    built b = build(2, &gens[0][0]);
    assert_int_equal(b.m->n, 60);
    const double *cols[5] = {b.m->R, gens[0], c5sq, gens[1], (const double[])C2Z};
    static const char *names[5] = {"A", "T1", "T2", "G", "H"};
    double p = phi, q = 1 - phi;
    const double want[5][5] = {{1, 1, 1, 1, 1}, {3, p, q, 0, -1}, {3, q, p, 0, -1}, {4, -1, -1, 1, 0},
                               {5, 0, 0, -1, 1}};
    char labels[5][12];
    assert_int_equal(qd__group_irrep_labels(b.ctx, &b.g, b.m->R, &b.t, labels), QD_OK);
    for (size_t k = 0; k < 5; k++) {
        size_t i = 0;
        while (i < 5 && strcmp(labels[i], names[k]))
            i++;
        assert_true(i < 5);
        for (size_t c = 0; c < 5; c++)
            assert_true(cabs(chi(&b.t, i, b.g.class_of[find_matrix(b.m, cols[c])]) - want[k][c]) < 1e-12);
    }
    unbuild(&b);
}

/* Matrices that do not represent the table (one not orthogonal, two
 * elements given the same matrix) or no matrices: no name, labels Gamma1,
 * Gamma2, ..., and no error. */
static void test_not_point_group(void **state) {
    (void)state;
    const double gens[][9] = {C2Z, SXZ};
    built b = build(2, &gens[0][0]);
    double R[4 * 9];
    memcpy(R, b.m->R, sizeof R);
    R[9 * 1 + 0] = 2;  /* not orthogonal */
    char name[16] = "x", labels[4][12];
    assert_int_equal(qd__group_pointgroup_name(b.ctx, &b.g, R, name), QD_OK);
    assert_string_equal(name, "");
    memcpy(R, b.m->R, sizeof R);
    memcpy(R + 9, b.m->R + 18, 9 * sizeof *R);  /* two elements, one matrix */
    assert_int_equal(qd__group_pointgroup_name(b.ctx, &b.g, R, name), QD_OK);
    assert_string_equal(name, "");
    assert_int_equal(qd__group_irrep_labels(b.ctx, &b.g, R, &b.t, labels), QD_OK);
    assert_string_equal(labels[0], "Gamma1");
    assert_string_equal(labels[3], "Gamma4");
    strcpy(name, "x");  /* no matrices at all: an abstract group, not an error */
    assert_int_equal(qd__group_pointgroup_name(b.ctx, &b.g, NULL, name), QD_OK);
    assert_string_equal(name, "");
    assert_int_equal(qd__group_irrep_labels(b.ctx, &b.g, NULL, &b.t, labels), QD_OK);
    assert_string_equal(labels[1], "Gamma2");
    assert_int_equal(qd_ctx_status(b.ctx), QD_OK);
    unbuild(&b);
}

/* The ring of N equal masses in the plane (issue 19): element k + N f is
 * r^k s^f, R = C_z(2 pi k / N) times the mirror xz if f (the table of
 * dihedral_mul).  C_Nv with A1, A2, B1, B2 and E_1 .. E_(N/2 - 1), E_k the
 * row with chi(C_N) = 2 cos(2 pi k / N) (Cotton's C_nv tables). */
static void test_ring(void **state) {
    (void)state;
    enum { N = 1000 };
    size_t *m = dihedral_mul(N);
    double *R = malloc(2 * N * 9 * sizeof *R);
    char(*labels)[12] = malloc((N / 2 + 3) * sizeof *labels), name[16];
    for (size_t x = 0; x < 2 * N; x++) {
        rot_z(2 * PI * (double)(x % N) / N, R + 9 * x);
        for (int i = 0; i < 3 && x >= N; i++)
            R[9 * x + 3 * i + 1] *= -1;  /* times diag(1, -1, 1) on the right */
    }
    qd_ctx *ctx = qd_ctx_new();
    qd__group g;
    qd__chartab t;
    struct timespec t0, t1;
    assert_int_equal(qd__group_from_table(ctx, 2 * N, m, &g), QD_OK);
    assert_int_equal(qd__group_characters(ctx, &g, &t), QD_OK);
    clock_gettime(CLOCK_MONOTONIC, &t0);
    assert_int_equal(qd__group_pointgroup_name(ctx, &g, R, name), QD_OK);
    assert_int_equal(qd__group_irrep_labels(ctx, &g, R, &t, labels), QD_OK);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    printf("C%dv: name and %zu labels in %.3f s\n", N, t.n,
           (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec));
    assert_string_equal(name, "C1000v");
    size_t seen[N / 2] = {0};
    for (size_t i = 0; i < t.n; i++) {
        double c1 = chi(&t, i, g.class_of[1]), cs = chi(&t, i, g.class_of[N]);
        if (labels[i][0] == 'E') {
            int k = atoi(labels[i] + 1);
            assert_true(k >= 1 && k < N / 2 && !seen[k]++);
            assert_true(fabs(c1 - 2 * cos(2 * PI * k / N)) < 1e-12);
        } else {
            char want[4] = {c1 > 0 ? 'A' : 'B', cs > 0 ? '1' : '2', 0};
            assert_string_equal(labels[i], want);
        }
    }
    qd__group_chartab_free(&t);
    qd__group_free(&g);
    qd_ctx_free(ctx);
    free(labels);
    free(R);
    free(m);
}

/* The ring moving in space: D_N x {E, sigma_h} (dnh_mul; sigma_h multiplies
 * the C_Nv matrices of test_ring), named D1000h.  For even N it holds the
 * inversion, so every label ends in g or u: A1g .. B2u and E_k g/u for
 * k = 1 .. N/2 - 1, each once, E_k with chi(C_N) = 2 cos(2 pi k / N). */
static void test_ring_in_space(void **state) {
    (void)state;
    enum { N = 1000, M = 4 * N };
    size_t *m = dnh_mul(N), nc = 2 * (N / 2 + 3);
    double *R = malloc(M * 9 * sizeof *R);
    char(*labels)[12] = malloc(nc * sizeof *labels), name[16];
    for (size_t x = 0; x < M; x++) {
        rot_z(2 * PI * (double)(x % N) / N, R + 9 * x);
        for (int i = 0; i < 3 && x % (2 * N) >= N; i++)
            R[9 * x + 3 * i + 1] *= -1;
        for (int j = 0; j < 3 && x >= 2 * N; j++)
            R[9 * x + 6 + j] *= -1;  /* sigma_h on the left: z -> -z */
    }
    qd_ctx *ctx = qd_ctx_new();
    qd__group g;
    qd__chartab t;
    assert_int_equal(qd__group_from_table(ctx, M, m, &g), QD_OK);
    assert_int_equal(qd__group_characters(ctx, &g, &t), QD_OK);
    assert_int_equal(qd__group_pointgroup_name(ctx, &g, R, name), QD_OK);
    assert_string_equal(name, "D1000h");
    assert_int_equal(qd__group_irrep_labels(ctx, &g, R, &t, labels), QD_OK);
    size_t seen[2][N / 2] = {{0}}, ones = 0;
    for (size_t i = 0; i < t.n; i++) {
        size_t len = strlen(labels[i]);
        char par = labels[i][len - 1];
        assert_true(par == 'g' || par == 'u');
        if (labels[i][0] == 'E') {
            int k = atoi(labels[i] + 1);
            assert_true(k >= 1 && k < N / 2 && !seen[par == 'u'][k]++);
            assert_true(cabs(chi(&t, i, g.class_of[1]) - 2 * cos(2 * PI * k / N)) < 1e-12);
        } else {
            ones++;
        }
    }
    assert_int_equal(ones, 8);
    qd__group_chartab_free(&t);
    qd__group_free(&g);
    qd_ctx_free(ctx);
    free(labels);
    free(R);
    free(m);
}

/* Every allocation of the group, its table, name and labels refused in turn
 * (tests/util/fault.h): each run gives the right answer or a clean
 * QD_ERR_NOMEM with every block returned.  Td takes Burnside's path, C6v
 * (D_6) the closed form. */
typedef struct fault_case {
    const mgroup *m;
    const char *name;
    const char *labels;
} fault_case;

static qd_status fault_body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)f;
    const fault_case *c = data;
    qd__group g;
    qd__chartab t = {0};
    char name[16], labels[MAXC][12], all[128];
    const char *v[MAXC];
    qd_status st = qd__group_from_table(ctx, c->m->n, c->m->mul, &g);
    if (st == QD_OK)
        st = qd__group_characters(ctx, &g, &t);
    if (st == QD_OK)
        st = qd__group_pointgroup_name(ctx, &g, c->m->R, name);
    if (st == QD_OK)
        st = qd__group_irrep_labels(ctx, &g, c->m->R, &t, labels);
    if (st == QD_OK) {
        assert_string_equal(name, c->name);
        for (size_t i = 0; i < t.n; i++)
            v[i] = labels[i];
        join_sorted(t.n, v, all, sizeof all);
        assert_string_equal(all, c->labels);
    }
    qd__group_chartab_free(&t);
    qd__group_free(&g);
    return st;
}

static void test_faults(void **state) {
    (void)state;
    const double td[][9] = {S4Z, C3D}, c6v[][9] = {{0}, SXZ};
    double g2[2][9];
    memcpy(g2, c6v, sizeof g2);
    rot_z(2 * PI / 6, g2[0]);
    fault_case a = {matrix_group(2, &td[0][0]), "Td", "A1 A2 E T1 T2"};
    fault_case b = {matrix_group(2, &g2[0][0]), "C6v", "A1 A2 B1 B2 E1 E2"};
    qt_fault_stats sa = qt_fault_loop("Td: group, characters, name, labels", fault_body, &a, 1);
    qt_fault_stats sb = qt_fault_loop("C6v: group, characters, name, labels", fault_body, &b, 1);
    assert_true(sa.nomem > 5 && sb.nomem > 5);
    free((void *)a.m);
    free((void *)b.m);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_c2v),       cmocka_unit_test(test_c3v),      cmocka_unit_test(test_c4v),
        cmocka_unit_test(test_d3h),       cmocka_unit_test(test_d4h),      cmocka_unit_test(test_td),
        cmocka_unit_test(test_oh),        cmocka_unit_test(test_cyclic),   cmocka_unit_test(test_dihedral),
        cmocka_unit_test(test_dnh),       cmocka_unit_test(test_abelian),
        cmocka_unit_test(test_quaternion), cmocka_unit_test(test_s5),      cmocka_unit_test(test_not_groups),
        cmocka_unit_test(test_td_vertices), cmocka_unit_test(test_point_groups),
        cmocka_unit_test(test_not_point_group),
        cmocka_unit_test(test_icosahedral), cmocka_unit_test(test_ring),
        cmocka_unit_test(test_ring_in_space),      cmocka_unit_test(test_faults),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
