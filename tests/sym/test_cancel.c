/*
 * tests/sym/test_cancel.c - common denominators and cancelled gcds.
 *
 * Known gcds by construction: (p*q)/(p*r) for random polynomials must come
 * out as N/D with N*r = D*q exactly and D dividing r (p cancelled), and keep
 * its value at random points.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "qdot/qdot.h"
#include "util/randexpr.h"

typedef struct fix {
    qd_ctx *ctx;
    const qd_expr *x, *y, *z, *a, *b, *c, *d;
} fix;

static int setup(void **state) {
    static fix f;
    f.ctx = qd_ctx_new();
    f.x = qd_symbol(f.ctx, "x");
    f.y = qd_symbol(f.ctx, "y");
    f.z = qd_symbol(f.ctx, "z");
    f.a = qd_symbol(f.ctx, "a");
    f.b = qd_symbol(f.ctx, "b");
    f.c = qd_symbol(f.ctx, "c");
    f.d = qd_symbol(f.ctx, "d");
    *state = &f;
    return f.ctx ? 0 : -1;
}

static int teardown(void **state) {
    qd_ctx_free(((fix *)*state)->ctx);
    return 0;
}

#define F ((fix *)*state)
#define C (F->ctx)
#define I(n) qd_int(C, n)

static void known_quotients(void **state) {
    const qd_expr *x = F->x, *y = F->y, *a = F->a, *b = F->b, *c = F->c, *d = F->d;
    const qd_expr *e = qd_div(C, qd_sub(C, qd_powi(C, x, 2), I(1)), qd_sub(C, x, I(1)));
    assert_ptr_equal(qd_cancel(C, e), qd_add(C, x, I(1)));
    e = qd_div(C, qd_add(C, qd_mul(C, a, b), qd_mul(C, a, c)), qd_mul(C, a, d));
    assert_ptr_equal(qd_cancel(C, e), qd_div(C, qd_add(C, b, c), d));
    e = qd_div(C, x, qd_add(C, qd_mul(C, x, y), x));
    assert_ptr_equal(qd_cancel(C, e), qd_div(C, I(1), qd_add(C, y, I(1))));
    /* rational coefficients: (x/2 + 1/2)/(x + 1) = 1/2 */
    e = qd_div(C, qd_add(C, qd_mul(C, qd_rat(C, 1, 2), x), qd_rat(C, 1, 2)), qd_add(C, x, I(1)));
    assert_ptr_equal(qd_cancel(C, e), qd_rat(C, 1, 2));
    /* a common denominator: 1/x + 1/y = (x + y)/(x*y) */
    e = qd_add(C, qd_div(C, I(1), x), qd_div(C, I(1), y));
    assert_ptr_equal(qd_cancel(C, e), qd_div(C, qd_add(C, x, y), qd_mul(C, x, y)));
    /* fractional powers: (x^(3/2) + x^(1/2))/x^(1/2) = x + 1 */
    const qd_expr *h = qd_sqrt(C, x);
    e = qd_div(C, qd_add(C, qd_powi(C, h, 3), h), h);
    assert_ptr_equal(qd_cancel(C, e), qd_add(C, x, I(1)));
    /* inside a function argument, and generators that are calls */
    e = qd_div(C, qd_sub(C, qd_powi(C, x, 2), I(1)), qd_sub(C, x, I(1)));
    assert_ptr_equal(qd_cancel(C, qd_fn(C, QD_SIN, e)), qd_fn(C, QD_SIN, qd_add(C, x, I(1))));
    const qd_expr *s = qd_fn(C, QD_SIN, y);
    e = qd_div(C, qd_sub(C, qd_powi(C, s, 2), qd_powi(C, x, 2)), qd_add(C, s, x));
    assert_ptr_equal(qd_cancel(C, e), qd_sub(C, s, x));
    /* nothing to cancel: unchanged, and a polynomial is not expanded */
    e = qd_powi(C, qd_add(C, x, y), 3);
    assert_ptr_equal(qd_cancel(C, e), e);
}

/* A random polynomial in x, y, z: 2..4 monomials with small coefficients. */
static const qd_expr *rand_poly(qd_ctx *ctx, qt_rng *r, const qd_expr *const *v) {
    const qd_expr *p = qd_int(ctx, 0);
    for (unsigned n = qt_below(r, 3) + 2; n > 0; n--) {
        long k = (long)qt_below(r, 6) - 3;
        const qd_expr *t = qd_int(ctx, k >= 0 ? k + 1 : k);
        for (int i = 0; i < 3; i++)
            t = qd_mul(ctx, t, qd_powi(ctx, v[i], (long)qt_below(r, 3)));
        p = qd_add(ctx, p, t);
    }
    return p;
}

/* Split a product into numerator and denominator (negative powers). */
static void split(qd_ctx *ctx, const qd_expr *e, const qd_expr **n, const qd_expr **d) {
    bool mul = qd_expr_kind(e) == QD_MUL;
    size_t m = mul ? qd_expr_nargs(e) : 1;
    *n = qd_int(ctx, 1);
    *d = qd_int(ctx, 1);
    for (size_t i = 0; i < m; i++) {
        const qd_expr *f = mul ? qd_expr_arg(e, i) : e;
        if (qd_expr_kind(f) == QD_POW && qd_is_number(qd_expr_arg(f, 1)) &&
            qd_number_sign(qd_expr_arg(f, 1)) < 0)
            *d = qd_mul(ctx, *d, qd_pow(ctx, f, qd_int(ctx, -1)));
        else
            *n = qd_mul(ctx, *n, f);
    }
}

static bool has_negative_power(const qd_expr *e) {
    if (qd_expr_kind(e) == QD_POW && qd_is_number(qd_expr_arg(e, 1)) &&
        qd_number_sign(qd_expr_arg(e, 1)) < 0)
        return true;
    for (size_t i = 0; i < qd_expr_nargs(e); i++)
        if (has_negative_power(qd_expr_arg(e, i)))
            return true;
    return false;
}

static void random_gcds(void **state) {
    const qd_expr *v[3] = {F->x, F->y, F->z};
    qt_rng r = {77001};
    for (int n = 0; n < 200; n++) {
        const qd_expr *p = rand_poly(C, &r, v), *q = rand_poly(C, &r, v), *s = rand_poly(C, &r, v);
        if (qd_is_number(p) || qd_is_zero(q) || qd_is_zero(s))
            continue;
        const qd_expr *num = qd_expand(C, qd_mul(C, p, q)), *den = qd_expand(C, qd_mul(C, p, s));
        const qd_expr *e = qd_div(C, num, den), *got = qd_cancel(C, e), *gn, *gd;
        assert_non_null(got);
        split(C, got, &gn, &gd);
        /* N/D = q/s exactly, and D divides s: p is gone */
        const qd_expr *cross = qd_expand(C, qd_sub(C, qd_mul(C, gn, s), qd_mul(C, gd, q)));
        if (!qd_is_zero(cross) || has_negative_power(qd_cancel(C, qd_div(C, s, gd))))
            fail_msg("case %d (seed 77001): p*q/(p*s) did not cancel to q/s", n);
        double pt[3] = {qt_uniform(&r, -1, 1), qt_uniform(&r, -1, 1), qt_uniform(&r, -1, 1)};
        double ve, vg;
        if (qd_eval(C, e, 3, v, pt, &ve) != QD_OK || !isfinite(ve))
            continue;
        assert_int_equal(qd_eval(C, got, 3, v, pt, &vg), QD_OK);
        if (fabs(ve - vg) > 1e-8 * (1 + fabs(ve)))
            fail_msg("case %d (seed 77001): %g != %g", n, ve, vg);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(known_quotients, setup, teardown),
        cmocka_unit_test_setup_teardown(random_gcds, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
