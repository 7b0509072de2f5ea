/* tests/sym/test_collect.c - qd_linear_coeffs, qd_coeff, qd_collect. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/qdot.h"
#include "util/randexpr.h"

typedef struct fix {
    qd_ctx *ctx;
    const qd_expr *x, *y, *z, *a, *b, *p[3];
} fix;

static int setup(void **state) {
    fix *f = calloc(1, sizeof *f);
    qd_ctx *c = f->ctx = qd_ctx_new();
    f->x = qd_symbol(c, "x");
    f->y = qd_symbol(c, "y");
    f->z = qd_symbol(c, "z");
    f->a = f->p[0] = qd_symbol(c, "a");
    f->b = f->p[1] = qd_symbol(c, "b");
    f->p[2] = qd_symbol(c, "k");
    *state = f;
    return 0;
}

static int teardown(void **state) {
    fix *f = *state;
    qd_ctx_free(f->ctx);
    free(f);
    return 0;
}

#define I(v) qd_int(c, (v))
#define ADD(...) add_list(c, (const qd_expr *[]){__VA_ARGS__, NULL})
#define MUL(...) mul_list(c, (const qd_expr *[]){__VA_ARGS__, NULL})

static const qd_expr *add_list(qd_ctx *c, const qd_expr **xs) {
    size_t n = 0;
    while (xs[n])
        n++;
    return qd_add_n(c, n, xs);
}

static const qd_expr *mul_list(qd_ctx *c, const qd_expr **xs) {
    size_t n = 0;
    while (xs[n])
        n++;
    return qd_mul_n(c, n, xs);
}

static void test_linear_simple(void **state) {
    fix *f = *state;
    qd_ctx *c = f->ctx;
    const qd_expr *x = f->x, *y = f->y, *a = f->a, *b = f->b;
    const qd_expr *xs[2] = {x, y}, *co[2], *rest;
    /* (a+1)(x + 2y) + (x+y)^2 - x^2 - y^2 - 2xy + b sin(a) */
    const qd_expr *e = ADD(qd_mul(c, qd_add(c, a, I(1)), qd_add(c, x, MUL(I(2), y))),
                           qd_powi(c, qd_add(c, x, y), 2), qd_neg(c, qd_powi(c, x, 2)),
                           qd_neg(c, qd_powi(c, y, 2)), MUL(I(-2), x, y),
                           MUL(b, qd_fn(c, QD_SIN, a)));
    assert_int_equal(qd_linear_coeffs(c, e, 2, xs, co, &rest), QD_OK);
    assert_ptr_equal(co[0], qd_add(c, a, I(1)));
    assert_ptr_equal(co[1], ADD(MUL(I(2), a), I(2)));
    assert_ptr_equal(rest, MUL(b, qd_fn(c, QD_SIN, a)));
    /* absent symbols have coefficient 0; a pure number is all rest */
    assert_int_equal(qd_linear_coeffs(c, I(3), 2, xs, co, &rest), QD_OK);
    assert_ptr_equal(co[0], I(0));
    assert_ptr_equal(co[1], I(0));
    assert_ptr_equal(rest, I(3));
}

static void expect_nonlinear(qd_ctx *c, const qd_expr *e, size_t n, const qd_expr *const *xs,
                             const char *name) {
    const qd_expr *co[4] = {NULL}, *rest = NULL;
    qd_ctx_clear_error(c);
    assert_int_equal(qd_linear_coeffs(c, e, n, xs, co, &rest), QD_ERR_NONLINEAR);
    assert_null(rest);
    assert_null(co[0]);
    assert_int_equal(qd_ctx_status(c), QD_ERR_NONLINEAR);
    assert_non_null(strstr(qd_ctx_message(c), name));
    qd_ctx_clear_error(c);
}

static void test_nonlinear(void **state) {
    fix *f = *state;
    qd_ctx *c = f->ctx;
    const qd_expr *x = f->x, *y = f->y, *a = f->a;
    const qd_expr *xs[2] = {x, y};
    expect_nonlinear(c, qd_add(c, qd_mul(c, x, y), a), 2, xs, "not linear in");
    expect_nonlinear(c, qd_add(c, x, qd_powi(c, y, 2)), 2, xs, "y");
    expect_nonlinear(c, qd_add(c, x, qd_fn(c, QD_SIN, y)), 2, xs, "y");
    expect_nonlinear(c, qd_add(c, x, qd_sqrt(c, y)), 2, xs, "y");
    expect_nonlinear(c, qd_add(c, x, qd_div(c, a, y)), 2, xs, "y");
    expect_nonlinear(c, qd_powi(c, qd_add(c, x, a), -1), 2, xs, "x");
    expect_nonlinear(c, qd_mul(c, qd_add(c, x, a), qd_add(c, x, I(1))), 2, xs, "x");
    expect_nonlinear(c, qd_pow(c, a, x), 2, xs, "x");
    /* x^2 - x^2 is linear after all */
    const qd_expr *co[2], *rest;
    const qd_expr *e = qd_sub(c, qd_powi(c, qd_add(c, x, a), 2), qd_powi(c, x, 2));
    assert_int_equal(qd_linear_coeffs(c, e, 2, xs, co, &rest), QD_OK);
    assert_ptr_equal(co[0], MUL(I(2), a));
    assert_ptr_equal(co[1], I(0));
    assert_ptr_equal(rest, qd_powi(c, a, 2));
}

static double value_at(qd_ctx *c, const qd_expr *e, const qd_expr *const *syms, const double *v) {
    double r = NAN;
    assert_int_equal(qd_eval(c, e, 3, syms, v, &r), QD_OK);
    return r;
}

/* Random coefficient expressions (free of the xs) are recovered: exactly
 * without floats; with floats (summed in another order) to rounding. */
static void linear_random(fix *f, unsigned flags, uint64_t seed0, int cases) {
    qd_ctx *c = f->ctx;
    const qd_expr *xs[3] = {f->x, f->y, f->z};
    qt_rng rng = {seed0};
    for (int k = 0; k < cases; k++) {
        uint64_t seed = rng.s;
        const qd_expr *cs[3], *terms[4], *co[3], *rest, *want[4];
        for (int i = 0; i < 3; i++) {
            cs[i] = qt_random_expr(c, &rng, f->p, 3, 3, flags);
            terms[i] = qd_mul(c, cs[i], xs[i]);
        }
        terms[3] = qt_random_expr(c, &rng, f->p, 3, 3, flags);
        /* sometimes scaled by a factor free of the xs, which expand distributes */
        const qd_expr *scale =
            qt_below(&rng, 2) ? I(1) : qd_add(c, qd_rat(c, 1, 3), f->p[qt_below(&rng, 3)]);
        const qd_expr *e = qd_mul(c, scale, qd_add_n(c, 4, terms));
        if (qd_linear_coeffs(c, e, 3, xs, co, &rest) != QD_OK)
            fail_msg("case %d (seed %llu): %s", k, (unsigned long long)seed, qd_ctx_message(c));
        for (int i = 0; i < 4; i++)
            want[i] = qd_expand(c, qd_mul(c, scale, i < 3 ? cs[i] : terms[3]));
        for (int i = 0; i < 4; i++) {
            const qd_expr *got = i < 3 ? co[i] : rest;
            if (qd_is_zero(want[i]) && qd_is_zero(got))
                continue; /* 0.0 * x vanished: exact 0 */
            if (!(flags & QT_FLOAT)) {
                if (got != want[i])
                    fail_msg("case %d (seed %llu): part %d differs", k,
                             (unsigned long long)seed, i);
                continue;
            }
            double v[3];
            for (int j = 0; j < 3; j++)
                v[j] = qt_uniform(&rng, -1, 1);
            double g = value_at(c, got, f->p, v), w = value_at(c, want[i], f->p, v);
            if (fabs(g - w) > 1e-9 * fmax(1.0, fabs(w)))
                fail_msg("case %d (seed %llu): part %d: %.17g != %.17g", k,
                         (unsigned long long)seed, i, g, w);
        }
    }
}

static void test_linear_random(void **state) {
    linear_random(*state, QT_ALL & ~QT_FLOAT, 777, 400);
    linear_random(*state, QT_ALL, 778, 200);
}

/* A product of two of the xs, a square or a call of one makes it nonlinear. */
static void test_nonlinear_random(void **state) {
    fix *f = *state;
    qd_ctx *c = f->ctx;
    const qd_expr *xs[3] = {f->x, f->y, f->z};
    qt_rng rng = {4242};
    for (int k = 0; k < 200; k++) {
        const qd_expr *terms[4];
        for (int i = 0; i < 3; i++)
            terms[i] = qd_mul(c, qt_random_expr(c, &rng, f->p, 3, 2, QT_POLY), xs[i]);
        const qd_expr *u = xs[qt_below(&rng, 3)], *v = xs[qt_below(&rng, 3)], *bad;
        switch (qt_below(&rng, 3)) {
        case 0: bad = qd_mul(c, u, v); break;
        case 1: bad = qd_fn(c, QD_COS, u); break;
        default: bad = qd_powi(c, qd_add(c, u, f->a), -1); break;
        }
        terms[3] = qd_mul(c, qd_add(c, f->a, I(2)), bad);
        const qd_expr *co[3], *rest;
        qd_ctx_clear_error(c);
        assert_int_equal(qd_linear_coeffs(c, qd_add_n(c, 4, terms), 3, xs, co, &rest),
                         QD_ERR_NONLINEAR);
        assert_null(rest);
    }
    qd_ctx_clear_error(c);
}

static void test_coeff(void **state) {
    fix *f = *state;
    qd_ctx *c = f->ctx;
    const qd_expr *x = f->x, *y = f->y;
    /* (1+x+y)^5: x^2 has 10 (1+y)^3 */
    const qd_expr *e = qd_powi(c, ADD(I(1), x, y), 5);
    assert_ptr_equal(qd_coeff(c, e, x, 2),
                     ADD(MUL(I(10), qd_powi(c, y, 3)), MUL(I(30), qd_powi(c, y, 2)),
                         MUL(I(30), y), I(10)));
    assert_ptr_equal(qd_coeff(c, e, x, 6), I(0));
    /* x^0 keeps what is not a power of x, sin(x) included */
    e = ADD(x, qd_fn(c, QD_SIN, x), y);
    assert_ptr_equal(qd_coeff(c, e, x, 0), qd_add(c, qd_fn(c, QD_SIN, x), y));
    /* Laurent: (x + 1/x)^3 = x^3 + 3x + 3/x + x^-3 */
    e = qd_powi(c, qd_add(c, x, qd_powi(c, x, -1)), 3);
    assert_ptr_equal(qd_coeff(c, e, x, -1), I(3));
    assert_ptr_equal(qd_coeff(c, e, x, -3), I(1));
    /* a generator other than a symbol */
    const qd_expr *s = qd_fn(c, QD_SIN, y);
    e = qd_powi(c, qd_add(c, s, x), 2);
    assert_ptr_equal(qd_coeff(c, e, s, 1), MUL(I(2), x));
}

static void test_collect(void **state) {
    fix *f = *state;
    qd_ctx *c = f->ctx;
    const qd_expr *x = f->x, *a = f->a, *b = f->b, *d = f->p[2];
    const qd_expr *x2 = qd_powi(c, x, 2);
    const qd_expr *e = ADD(MUL(a, x), MUL(b, x), MUL(x2, d), x2, I(5));
    const qd_expr *want = ADD(qd_mul(c, qd_add(c, a, b), x), qd_mul(c, qd_add(c, d, I(1)), x2),
                              I(5));
    assert_ptr_equal(qd_collect(c, e, x), want);
    /* collect keeps the value: (a x + 1)^3 at a point */
    e = qd_powi(c, qd_add(c, qd_mul(c, a, x), I(1)), 3);
    const qd_expr *col = qd_collect(c, e, x), *syms[2] = {a, x};
    double v[2] = {0.3, -0.7}, r1, r2;
    assert_int_equal(qd_eval(c, e, 2, syms, v, &r1), QD_OK);
    assert_int_equal(qd_eval(c, col, 2, syms, v, &r2), QD_OK);
    assert_true(fabs(r1 - r2) < 1e-12);
    assert_ptr_equal(qd_expand(c, col), qd_expand(c, e));
    assert_ptr_equal(qd_collect(c, I(0), x), I(0));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_linear_simple, setup, teardown),
        cmocka_unit_test_setup_teardown(test_nonlinear, setup, teardown),
        cmocka_unit_test_setup_teardown(test_linear_random, setup, teardown),
        cmocka_unit_test_setup_teardown(test_nonlinear_random, setup, teardown),
        cmocka_unit_test_setup_teardown(test_coeff, setup, teardown),
        cmocka_unit_test_setup_teardown(test_collect, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
