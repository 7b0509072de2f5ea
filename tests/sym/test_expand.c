/* tests/sym/test_expand.c - qd_expand: canonical results and properties. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <gmp.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "qdot/qdot.h"
#include "util/randexpr.h"

typedef struct fix {
    qd_ctx *ctx;
    const qd_expr *x, *y, *z;
} fix;

static int setup(void **state) {
    fix *f = calloc(1, sizeof *f);
    f->ctx = qd_ctx_new();
    f->x = qd_symbol(f->ctx, "x");
    f->y = qd_symbol(f->ctx, "y");
    f->z = qd_symbol(f->ctx, "z");
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

static void test_square(void **state) {
    fix *f = *state;
    qd_ctx *c = f->ctx;
    const qd_expr *x = f->x, *y = f->y;
    const qd_expr *e = qd_expand(c, qd_powi(c, qd_add(c, x, I(1)), 2));
    assert_ptr_equal(e, ADD(qd_powi(c, x, 2), MUL(I(2), x), I(1)));
    e = qd_expand(c, qd_mul(c, qd_add(c, x, y), qd_sub(c, x, y)));
    assert_ptr_equal(e, qd_sub(c, qd_powi(c, x, 2), qd_powi(c, y, 2)));
    /* (x+y)^3 */
    e = qd_expand(c, qd_powi(c, qd_add(c, x, y), 3));
    assert_ptr_equal(e, ADD(qd_powi(c, x, 3), MUL(I(3), qd_powi(c, x, 2), y),
                            MUL(I(3), x, qd_powi(c, y, 2)), qd_powi(c, y, 3)));
    /* cancellation to zero and to a number */
    e = qd_sub(c, qd_mul(c, qd_add(c, x, y), qd_sub(c, x, y)),
               qd_sub(c, qd_powi(c, x, 2), qd_powi(c, y, 2)));
    assert_ptr_equal(qd_expand(c, e), I(0));
    e = qd_sub(c, qd_powi(c, qd_add(c, x, I(1)), 2), ADD(qd_powi(c, x, 2), MUL(I(2), x)));
    assert_ptr_equal(qd_expand(c, e), I(1));
    /* atoms and numbers are their own expansion */
    assert_ptr_equal(qd_expand(c, x), x);
    assert_ptr_equal(qd_expand(c, I(7)), I(7));
    assert_ptr_equal(qd_expand(c, qd_float(c, 2.5)), qd_float(c, 2.5));
}

static void test_rational_coeffs(void **state) {
    fix *f = *state;
    qd_ctx *c = f->ctx;
    const qd_expr *x = f->x;
    const qd_expr *e = qd_powi(c, qd_add(c, qd_mul(c, qd_rat(c, 1, 2), x), qd_rat(c, 1, 3)), 2);
    assert_ptr_equal(qd_expand(c, e), ADD(MUL(qd_rat(c, 1, 4), qd_powi(c, x, 2)),
                                          MUL(qd_rat(c, 1, 3), x), qd_rat(c, 1, 9)));
}

/* Coefficients beyond 64 bits: (2^40 x + 10^12 y)^3. */
static void test_big_coeffs(void **state) {
    fix *f = *state;
    qd_ctx *c = f->ctx;
    const qd_expr *x = f->x, *y = f->y;
    const qd_expr *a = qd_rat_str(c, "1099511627776"), *b = qd_rat_str(c, "1000000000000");
    const qd_expr *e = qd_powi(c, qd_add(c, qd_mul(c, a, x), qd_mul(c, b, y)), 3);
    const qd_expr *a2 = qd_mul(c, a, a), *b2 = qd_mul(c, b, b);
    const qd_expr *want = ADD(MUL(qd_mul(c, a2, a), qd_powi(c, x, 3)),
                              MUL(I(3), a2, b, qd_powi(c, x, 2), y),
                              MUL(I(3), a, b2, x, qd_powi(c, y, 2)),
                              MUL(qd_mul(c, b2, b), qd_powi(c, y, 3)));
    assert_ptr_equal(qd_expand(c, e), want);
    /* overflow in the sum, not the products: 2 * (2^62 x) */
    const qd_expr *h = qd_rat_str(c, "4611686018427387904");
    e = qd_add(c, qd_mul(c, qd_mul(c, h, x), qd_add(c, y, I(1))), qd_mul(c, qd_mul(c, h, x), y));
    assert_ptr_equal(qd_expand(c, e), ADD(MUL(qd_mul(c, I(2), h), x, y), MUL(h, x)));
}

/* (1+x+y+z)^20: 1771 terms; x^5 y^5 z^5 has coefficient 20!/(5!)^4. */
static void test_multinomial(void **state) {
    fix *f = *state;
    qd_ctx *c = f->ctx;
    const qd_expr *x = f->x, *y = f->y, *z = f->z;
    const qd_expr *e = qd_expand(c, qd_powi(c, ADD(I(1), x, y, z), 20));
    assert_int_equal(qd_expr_kind(e), QD_ADD);
    assert_int_equal(qd_expr_nargs(e), 1771);
    mpz_t num, den;
    mpz_inits(num, den, NULL);
    mpz_fac_ui(num, 20);
    mpz_fac_ui(den, 5);
    mpz_pow_ui(den, den, 4);
    mpz_divexact(num, num, den);
    char *text = mpz_get_str(NULL, 10, num);
    const qd_expr *want = MUL(qd_rat_str(c, text), qd_powi(c, x, 5), qd_powi(c, y, 5),
                              qd_powi(c, z, 5));
    free(text);
    mpz_clears(num, den, NULL);
    bool found = false;
    for (size_t i = 0; i < qd_expr_nargs(e); i++)
        found |= qd_expr_arg(e, i) == want;
    assert_true(found);
    assert_ptr_equal(qd_expr_arg(e, 0), I(1));
}

static void test_laurent(void **state) {
    fix *f = *state;
    qd_ctx *c = f->ctx;
    const qd_expr *x = f->x, *y = f->y;
    const qd_expr *e = qd_powi(c, qd_add(c, x, qd_powi(c, x, -1)), 2);
    assert_ptr_equal(qd_expand(c, e), ADD(qd_powi(c, x, 2), I(2), qd_powi(c, x, -2)));
    /* (x/y + y/x)(x/y - y/x) = x^2/y^2 - y^2/x^2 */
    const qd_expr *u = qd_div(c, x, y), *v = qd_div(c, y, x);
    e = qd_expand(c, qd_mul(c, qd_add(c, u, v), qd_sub(c, u, v)));
    assert_ptr_equal(e, qd_sub(c, MUL(qd_powi(c, x, 2), qd_powi(c, y, -2)),
                               MUL(qd_powi(c, x, -2), qd_powi(c, y, 2))));
}

static void test_floats(void **state) {
    fix *f = *state;
    qd_ctx *c = f->ctx;
    const qd_expr *x = f->x, *y = f->y;
    const qd_expr *e = qd_powi(c, qd_add(c, qd_mul(c, qd_float(c, 0.5), x), I(1)), 2);
    assert_ptr_equal(qd_expand(c, e), ADD(MUL(qd_float(c, 0.25), qd_powi(c, x, 2)),
                                          MUL(qd_float(c, 1.0), x), I(1)));
    /* a float term swallows an exact one of the same monomial */
    e = qd_mul(c, qd_add(c, x, y), qd_add(c, x, qd_mul(c, qd_float(c, 2.0), y)));
    assert_ptr_equal(qd_expand(c, e),
                     ADD(qd_powi(c, x, 2), MUL(qd_float(c, 3.0), x, y),
                         MUL(qd_float(c, 2.0), qd_powi(c, y, 2))));
}

static void test_deep(void **state) {
    fix *f = *state;
    qd_ctx *c = f->ctx;
    const qd_expr *x = f->x, *y = f->y;
    const qd_expr *e = qd_fn(c, QD_SIN, qd_mul(c, x, qd_add(c, y, I(1))));
    assert_ptr_equal(qd_expand(c, e), qd_fn(c, QD_SIN, qd_add(c, qd_mul(c, x, y), x)));
    /* a call inside a power inside a product */
    const qd_expr *s = qd_fn(c, QD_COS, qd_powi(c, qd_add(c, x, y), 2));
    const qd_expr *s2 = qd_fn(c, QD_COS, ADD(qd_powi(c, x, 2), MUL(I(2), x, y), qd_powi(c, y, 2)));
    e = qd_mul(c, qd_add(c, s, I(1)), qd_add(c, x, I(1)));
    assert_ptr_equal(qd_expand(c, e), ADD(MUL(x, s2), s2, x, I(1)));
    /* the denominator of a quotient, and a root */
    e = qd_div(c, I(1), qd_add(c, qd_mul(c, x, qd_add(c, y, I(1))), I(1)));
    assert_ptr_equal(qd_expand(c, e), qd_powi(c, ADD(MUL(x, y), x, I(1)), -1));
    e = qd_sqrt(c, qd_mul(c, x, qd_add(c, y, I(1))));
    assert_ptr_equal(qd_expand(c, e), qd_sqrt(c, qd_add(c, qd_mul(c, x, y), x)));
    /* user functions */
    const qd_expr *arg = qd_powi(c, qd_add(c, x, I(1)), 2);
    const qd_expr *g = qd_ufunc(c, "g", 1, &arg);
    const qd_expr *arg2 = ADD(qd_powi(c, x, 2), MUL(I(2), x), I(1));
    assert_ptr_equal(qd_expand(c, g), qd_ufunc(c, "g", 1, &arg2));
}

/* Negative and fractional powers of sums: generators, which fold back. */
static void test_roots(void **state) {
    fix *f = *state;
    qd_ctx *c = f->ctx;
    const qd_expr *x = f->x, *y = f->y;
    const qd_expr *s = qd_sqrt(c, qd_add(c, x, I(1)));
    /* (sqrt(x+1) + 1)^2 = x + 2 + 2 sqrt(x+1) */
    const qd_expr *e = qd_powi(c, qd_add(c, s, I(1)), 2);
    assert_ptr_equal(qd_expand(c, e), ADD(x, I(2), MUL(I(2), s)));
    /* (sqrt(x+1) + y)^4 has sqrt(x+1)^4 = (x+1)^2 in it */
    e = qd_expand(c, qd_powi(c, qd_add(c, s, y), 4));
    const qd_expr *s3 = qd_pow(c, qd_add(c, x, I(1)), qd_rat(c, 3, 2));
    const qd_expr *want = ADD(qd_powi(c, x, 2), MUL(I(2), x), I(1), MUL(I(4), s3, y),
                              MUL(I(6), x, qd_powi(c, y, 2)), MUL(I(6), qd_powi(c, y, 2)),
                              MUL(I(4), s, qd_powi(c, y, 3)), qd_powi(c, y, 4));
    assert_ptr_equal(e, want);
    /* x * (x+1)^-1 stays; (x+y)^-2 stays */
    const qd_expr *inv = qd_powi(c, qd_add(c, x, I(1)), -1);
    e = qd_mul(c, qd_add(c, x, y), inv);
    assert_ptr_equal(qd_expand(c, e), qd_add(c, qd_mul(c, x, inv), qd_mul(c, y, inv)));
    e = qd_powi(c, qd_add(c, x, y), -2);
    assert_ptr_equal(qd_expand(c, e), e);
    /* (x+1)^-1 * (x+1)^(1/2) meet as (x+1)^(-1/2) */
    e = qd_mul(c, qd_add(c, inv, y), qd_add(c, s, y));
    const qd_expr *r = qd_pow(c, qd_add(c, x, I(1)), qd_rat(c, -1, 2));
    assert_ptr_equal(qd_expand(c, e),
                     ADD(r, MUL(y, inv), MUL(s, y), qd_powi(c, y, 2)));
}

/* Text of e for a failure message (leaked: the test is failing anyway). */
static const char *str(qd_ctx *c, const qd_expr *e) {
    qd_buf *b = calloc(1, sizeof *b);
    qd_print(c, e, QD_FMT_TEXT, b);
    return qd_buf_str(b);
}

static bool close_enough(double a, double b) {
    double scale = fmax(1.0, fmax(fabs(a), fabs(b)));
    return fabs(a - b) <= 1e-9 * scale;
}

/* Random expressions: expand keeps the value and is idempotent. */
static void test_random(void **state) {
    fix *f = *state;
    qd_ctx *c = f->ctx;
    const qd_expr *syms[3] = {f->x, f->y, f->z};
    qt_rng rng = {20240611};
    for (int k = 0; k < 1200; k++) {
        uint64_t seed = rng.s;
        const qd_expr *e = qt_random_expr(c, &rng, syms, 3, 4, QT_ALL);
        const qd_expr *x = qd_expand(c, e);
        if (!x)
            fail_msg("case %d (seed %llu): %s", k, (unsigned long long)seed, qd_ctx_message(c));
        const qd_expr *xx = qd_expand(c, x);
        if (xx != x) {
            fail_msg("case %d (seed %llu): not idempotent\n e = %s\n expand = %s\n again = %s", k,
                     (unsigned long long)seed, str(c, e), str(c, x), str(c, xx));
        }
        for (int p = 0; p < 3; p++) {
            double v[3], ve, vx;
            for (int i = 0; i < 3; i++)
                v[i] = qt_uniform(&rng, -1, 1);
            assert_int_equal(qd_eval(c, e, 3, syms, v, &ve), QD_OK);
            assert_int_equal(qd_eval(c, x, 3, syms, v, &vx), QD_OK);
            if (!close_enough(ve, vx)) {
                fail_msg("case %d (seed %llu): %s\n e = %.17g, expand = %.17g", k,
                         (unsigned long long)seed, str(c, e), ve, vx);
            }
        }
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_square, setup, teardown),
        cmocka_unit_test_setup_teardown(test_rational_coeffs, setup, teardown),
        cmocka_unit_test_setup_teardown(test_big_coeffs, setup, teardown),
        cmocka_unit_test_setup_teardown(test_multinomial, setup, teardown),
        cmocka_unit_test_setup_teardown(test_laurent, setup, teardown),
        cmocka_unit_test_setup_teardown(test_floats, setup, teardown),
        cmocka_unit_test_setup_teardown(test_deep, setup, teardown),
        cmocka_unit_test_setup_teardown(test_roots, setup, teardown),
        cmocka_unit_test_setup_teardown(test_random, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
