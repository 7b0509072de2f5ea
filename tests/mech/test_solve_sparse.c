/*
 * tests/mech/test_solve_sparse.c - A X = B by peeling singleton rows and
 * columns before elimination (src/mech/solve_sparse.c), as the velocity map
 * of generalized speeds uses it.
 *
 * The property: for random sparse A (random expressions where a random
 * pattern allows, a nonzero diagonal so that A is regular) and random B, the
 * solution satisfies A X = B at random points; patterns range from diagonal
 * and triangular (no elimination at all) through a dense core.  Singular
 * systems (an empty row, an empty column, a singular core) are reported as
 * QD_ERR_SINGULAR, never solved.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>

#include "qdot/qdot.h"
#include "mech/mech.h"
#include "util/randexpr.h"

#define SEED 4409u
#define CASES 120
#define NMAX 6

/* The residual of row i, column c of A X - B at vals. */
static double residual(qd_ctx *ctx, size_t n, size_t nc, const qd_expr *const *A,
                       const qd_expr *const *B, const qd_expr *const *X, size_t i, size_t c,
                       const qd_expr *const *syms, const double *vals, double *scale) {
    const qd_expr *s = qd_neg(ctx, B[i * nc + c]);
    for (size_t j = 0; j < n; j++)
        s = qd_add(ctx, s, qd_mul(ctx, A[i * n + j], X[j * nc + c]));
    double r = NAN, b = 0;
    assert_int_equal(qd_eval(ctx, s, 3, syms, vals, &r), QD_OK);
    assert_int_equal(qd_eval(ctx, B[i * nc + c], 3, syms, vals, &b), QD_OK);
    *scale = 1 + fabs(b);
    return r;
}

/* pattern 0: diagonal, 1: lower triangular, 2: upper, 3: dense, 4: random,
 * 5: no row singleton but column 0 in row 0 only (solved backward, after
 * the dense rest) */
static bool entry_on(qt_rng *rng, unsigned pattern, size_t i, size_t j) {
    if (i == j)
        return true;
    switch (pattern) {
    case 0: return false;
    case 1: return j < i && qt_below(rng, 2);
    case 2: return j > i && qt_below(rng, 2);
    case 3: return true;
    case 5: return i == 0 ? j == 1 : j >= 1;
    default: return qt_below(rng, 3) == 0;
    }
}

static void test_random_systems(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *syms[3] = {qd_symbol(ctx, "x"), qd_symbol(ctx, "y"), qd_symbol(ctx, "z")};
    qt_rng rng = {SEED};
    for (int k = 0; k < CASES; k++) {
        unsigned pattern = qt_below(&rng, 6);
        /* a dense core of random trig entries grows fast under elimination */
        size_t n = 1 + qt_below(&rng, pattern >= 3 ? 3 : NMAX), nc = 1 + qt_below(&rng, 2);
        if (pattern == 5 && n < 3)
            n = 3;
        const qd_expr *A[NMAX * NMAX], *B[NMAX * 2], *X[NMAX * 2];
        for (size_t i = 0; i < n; i++)
            for (size_t j = 0; j < n; j++) {
                /* the diagonal dominates at every point in [-1, 1]: A regular */
                const qd_expr *a = entry_on(&rng, pattern, i, j)
                                       ? qt_random_expr(ctx, &rng, syms, 3, 1, QT_POLY | QT_TRIG)
                                       : qd_int(ctx, 0);
                if (i == j)
                    a = qd_add(ctx, qd_int(ctx, 40), qd_mul(ctx, qd_rat(ctx, 1, 8), a));
                else if (!qd_is_zero(a))
                    a = qd_mul(ctx, qd_rat(ctx, 1, 8), qd_fn(ctx, QD_SIN, a));
                A[i * n + j] = qd_simplify(ctx, a);
            }
        for (size_t i = 0; i < n * nc; i++)
            B[i] = qt_random_expr(ctx, &rng, syms, 3, 2, QT_POLY | QT_TRIG);
        qd_status st = qd__mech_solve_sparse(ctx, n, A, nc, B, X, 0, NULL, NULL);
        if (st != QD_OK)
            fail_msg("case %d (seed %u, n %zu, pattern %u): %s", k, SEED, n, pattern,
                     qd_ctx_message(ctx));
        for (int p = 0; p < 3; p++) {
            double vals[3];
            for (int v = 0; v < 3; v++)
                vals[v] = qt_uniform(&rng, -1, 1);
            for (size_t i = 0; i < n; i++)
                for (size_t c = 0; c < nc; c++) {
                    double scale, r = residual(ctx, n, nc, A, B, X, i, c, syms, vals, &scale);
                    if (!(fabs(r) <= 1e-11 * scale))
                        fail_msg("case %d (seed %u, n %zu, pattern %u): row %zu residual %g", k,
                                 SEED, n, pattern, i, r);
                }
        }
    }
    qd_ctx_free(ctx);
}

/* The kinematics of the rolling disk in generalized speeds (Desloge ch. 69;
 * examples/rolling_disk_speeds.qd): triangular once the singletons go,
 * q1' = u3/cos(q2), q3' = u2 - u3 sin(q2)/cos(q2), exactly. */
static void test_triangular_exact(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *q2 = qd_symbol(ctx, "q2"), *u[3] = {qd_symbol(ctx, "u1"),
                                                        qd_symbol(ctx, "u2"),
                                                        qd_symbol(ctx, "u3")};
    const qd_expr *z = qd_int(ctx, 0), *one = qd_int(ctx, 1);
    /* unknowns q1', q2', q3'; rows u1 = q2', u2 = q3' + sin q2 q1', u3 = cos q2 q1' */
    const qd_expr *A[9] = {z, one, z, qd_fn(ctx, QD_SIN, q2), z, one, qd_fn(ctx, QD_COS, q2), z, z};
    const qd_expr *X[3];
    assert_int_equal(qd__mech_solve_sparse(ctx, 3, A, 1, u, X, 0, NULL, NULL), QD_OK);
    const qd_expr *want[3] = {qd_div(ctx, u[2], qd_fn(ctx, QD_COS, q2)), u[0],
                              qd_sub(ctx, u[1], qd_div(ctx, qd_mul(ctx, u[2], qd_fn(ctx, QD_SIN, q2)), qd_fn(ctx, QD_COS, q2)))};
    for (int j = 0; j < 3; j++)
        assert_true(qd_is_zero(qd_simplify(ctx, qd_sub(ctx, X[j], want[j]))));
    qd_ctx_free(ctx);
}

static void assert_singular(qd_ctx *ctx, size_t n, const qd_expr *const *A) {
    const qd_expr *B[4], *X[4];
    for (size_t i = 0; i < n; i++)
        B[i] = qd_int(ctx, (long)i + 1);
    assert_int_equal(qd__mech_solve_sparse(ctx, n, A, 1, B, X, 0, NULL, NULL), QD_ERR_SINGULAR);
}

static void test_singular(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *x = qd_symbol(ctx, "x"), *z = qd_int(ctx, 0), *one = qd_int(ctx, 1);
    /* an empty row */
    const qd_expr *row[4] = {one, x, z, z};
    assert_singular(ctx, 2, row);
    /* an empty column */
    const qd_expr *col[4] = {one, z, x, z};
    assert_singular(ctx, 2, col);
    /* two singletons on one column: the second row is left empty */
    const qd_expr *twice[9] = {one, z, z, x, z, z, z, one, x};
    assert_singular(ctx, 3, twice);
    /* a core whose determinant vanishes identically:
     * [sin x, cos x; cos x, cos^2 x / sin x] */
    const qd_expr *s = qd_fn(ctx, QD_SIN, x), *c = qd_fn(ctx, QD_COS, x);
    const qd_expr *core[4] = {s, c, c, qd_div(ctx, qd_mul(ctx, c, c), s)};
    assert_singular(ctx, 2, core);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_random_systems),
        cmocka_unit_test(test_triangular_exact),
        cmocka_unit_test(test_singular),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
