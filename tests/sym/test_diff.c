/*
 * tests/sym/test_diff.c - partial and total time derivatives, substitution.
 *
 * Rules are checked against the calculus they encode (pointer equality with
 * the textbook derivative), and on 1000 random expressions against central
 * finite differences with Richardson extrapolation (error O(h^4)).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>

#include "qdot/qdot.h"
#include "util/randexpr.h"

static qd_ctx *ctx;
static const qd_expr *x, *y;

static int setup(void **state) {
    (void)state;
    ctx = qd_ctx_new();
    x = qd_symbol(ctx, "x");
    y = qd_symbol(ctx, "y");
    return 0;
}

static int teardown(void **state) {
    (void)state;
    qd_ctx_free(ctx);
    return 0;
}

#define I(n) qd_int(ctx, n)
#define F1(f, a) qd_fn(ctx, f, a)

static void rules(void **state) {
    (void)state;
    assert_ptr_equal(qd_diff(ctx, qd_powi(ctx, x, 3), x), qd_mul(ctx, I(3), qd_powi(ctx, x, 2)));
    assert_ptr_equal(qd_diff(ctx, F1(QD_SIN, x), x), F1(QD_COS, x));
    assert_ptr_equal(qd_diff(ctx, F1(QD_COS, x), x), qd_neg(ctx, F1(QD_SIN, x)));
    assert_ptr_equal(qd_diff(ctx, F1(QD_EXP, x), x), F1(QD_EXP, x));
    assert_ptr_equal(qd_diff(ctx, F1(QD_LOG, x), x), qd_powi(ctx, x, -1));
    assert_ptr_equal(qd_diff(ctx, qd_sqrt(ctx, x), x),
                     qd_mul(ctx, qd_rat(ctx, 1, 2), qd_pow(ctx, x, qd_rat(ctx, -1, 2))));
    /* product rule and chain rule: d/dx x sin(x y) = sin(xy) + x y cos(xy) */
    const qd_expr *xy = qd_mul(ctx, x, y);
    assert_ptr_equal(qd_diff(ctx, qd_mul(ctx, x, F1(QD_SIN, xy)), x),
                     qd_add(ctx, F1(QD_SIN, xy), qd_mul_n(ctx, 3, (const qd_expr *[]){x, y, F1(QD_COS, xy)})));
    /* d/dx x^x = x^x (log x + 1) */
    const qd_expr *xx = qd_pow(ctx, x, x);
    assert_ptr_equal(qd_diff(ctx, xx, x), qd_mul(ctx, xx, qd_add(ctx, F1(QD_LOG, x), I(1))));
    /* atan2(y, x): d/dx = -y/(x^2+y^2) */
    const qd_expr *r2 = qd_add(ctx, qd_powi(ctx, x, 2), qd_powi(ctx, y, 2));
    assert_ptr_equal(qd_diff(ctx, qd_fn2(ctx, QD_ATAN2, y, x), x), qd_div(ctx, qd_neg(ctx, y), r2));
    /* the 4th derivative of sin is sin */
    assert_ptr_equal(qd_diff_n(ctx, F1(QD_SIN, x), x, 4), F1(QD_SIN, x));
    assert_ptr_equal(qd_diff(ctx, y, x), I(0));
    assert_null(qd_diff(ctx, x, qd_add(ctx, x, y))); /* only with respect to a symbol */
    qd_ctx_clear_error(ctx);
}

/* d/dr V(r^2) = 2 r V'(r^2); mixed partials of f(x, y) commute. */
static void user_functions(void **state) {
    (void)state;
    const qd_expr *r2 = qd_powi(ctx, x, 2);
    const qd_expr *V = qd_ufunc(ctx, "V", 1, &r2);
    unsigned s0 = 0;
    const qd_expr *V1 = qd_uderiv(ctx, "V", 1, &s0, 1, &r2);
    assert_ptr_equal(qd_diff(ctx, V, x), qd_mul_n(ctx, 3, (const qd_expr *[]){I(2), x, V1}));
    const qd_expr *args[2] = {x, y};
    const qd_expr *f = qd_ufunc(ctx, "f", 2, args);
    assert_ptr_equal(qd_diff(ctx, qd_diff(ctx, f, x), y), qd_diff(ctx, qd_diff(ctx, f, y), x));
}

/* Total time derivative over the jet: d/dt (q^2 t) = 2 q q' t + q^2, and
 * d/dt of the velocity is the acceleration. */
static void time_derivative(void **state) {
    (void)state;
    const qd_expr *q = qd_coord(ctx, "q"), *qd = qd_jet(ctx, q, 1), *qdd = qd_jet(ctx, q, 2);
    const qd_expr *t = qd_time(ctx), *m = qd_param(ctx, "m");
    const qd_expr *e = qd_mul(ctx, qd_powi(ctx, q, 2), t);
    assert_ptr_equal(qd_dt(ctx, e),
                     qd_add(ctx, qd_mul_n(ctx, 4, (const qd_expr *[]){I(2), q, qd, t}), qd_powi(ctx, q, 2)));
    assert_ptr_equal(qd_dt(ctx, qd), qdd);
    assert_ptr_equal(qd_dt(ctx, m), I(0)); /* parameters are constant */
    assert_ptr_equal(qd_dt(ctx, x), I(0)); /* so are plain symbols */
    /* x1 = l sin(q): x1' = l cos(q) q' */
    const qd_expr *l = qd_param(ctx, "l");
    assert_ptr_equal(qd_dt(ctx, qd_mul(ctx, l, F1(QD_SIN, q))),
                     qd_mul_n(ctx, 3, (const qd_expr *[]){l, F1(QD_COS, q), qd}));
    /* chain identity: d/dt f = sum over jet of df/ds * s' + df/dt */
    const qd_expr *g = qd_mul_n(ctx, 3, (const qd_expr *[]){F1(QD_SIN, qd_mul(ctx, q, t)), qd, qd});
    const qd_expr *chain = qd_add_n(ctx, 3, (const qd_expr *[]){
        qd_mul(ctx, qd_diff(ctx, g, q), qd), qd_mul(ctx, qd_diff(ctx, g, qd), qdd), qd_diff(ctx, g, t)});
    /* equal as values (the product rule leaves cos(q t)(q' t + q) unexpanded) */
    const qd_expr *syms[4] = {q, qd, qdd, t};
    qt_rng r = {3};
    for (int i = 0; i < 20; i++) {
        double v[4], a, b;
        for (int k = 0; k < 4; k++)
            v[k] = qt_uniform(&r, -2, 2);
        assert_int_equal(qd_eval(ctx, qd_dt(ctx, g), 4, syms, v, &a), QD_OK);
        assert_int_equal(qd_eval(ctx, chain, 4, syms, v, &b), QD_OK);
        assert_true(fabs(a - b) <= 1e-12 * fmax(1, fabs(a)));
    }
}

static void substitution(void **state) {
    (void)state;
    const qd_expr *e = qd_add(ctx, qd_mul(ctx, x, y), F1(QD_SIN, x));
    const qd_expr *from[1] = {y}, *to[1] = {qd_powi(ctx, x, -1)};
    assert_ptr_equal(qd_subs(ctx, e, 1, from, to), qd_add(ctx, I(1), F1(QD_SIN, x)));
    /* simultaneous: x -> y, y -> x swaps */
    const qd_expr *sf[2] = {x, y}, *st[2] = {y, x};
    const qd_expr *s = qd_sub(ctx, qd_powi(ctx, x, 2), y);
    assert_ptr_equal(qd_subs(ctx, s, 2, sf, st), qd_sub(ctx, qd_powi(ctx, y, 2), x));
    /* substituting a number folds */
    const qd_expr *z[1] = {I(0)};
    assert_ptr_equal(qd_subs(ctx, F1(QD_COS, x), 1, from, z), F1(QD_COS, x));
    assert_ptr_equal(qd_subs(ctx, F1(QD_COS, x), 1, (const qd_expr *[]){x}, z), I(1));
}

static double at(const qd_expr *e, const qd_expr *const *syms, const double *v) {
    double r;
    qd_status st = qd_eval(ctx, e, 3, syms, v, &r);
    assert_int_equal(st, QD_OK);
    return r;
}

static double central(const qd_expr *e, const qd_expr *const *syms, double *v, int k, double h) {
    double x0 = v[k];
    v[k] = x0 + h;
    double fp = at(e, syms, v);
    v[k] = x0 - h;
    double fm = at(e, syms, v);
    v[k] = x0;
    return (fp - fm) / (2 * h);
}

/* 1000 random expressions: d/dx_k at a random point equals the
 * Richardson-extrapolated central difference. */
static void finite_differences(void **state) {
    (void)state;
    const qd_expr *syms[3] = {x, y, qd_symbol(ctx, "z")};
    qt_rng r = {20261121};
    int checked = 0;
    for (int i = 0; i < 1000; i++) {
        const qd_expr *e = qt_random_expr(ctx, &r, syms, 3, 5, QT_ALL);
        assert_non_null(e);
        double v[3];
        for (int k = 0; k < 3; k++)
            v[k] = qt_uniform(&r, -1, 1);
        int k = (int)qt_below(&r, 3);
        const qd_expr *de = qd_diff(ctx, e, syms[k]);
        assert_non_null(de);
        double exact = at(de, syms, v);
        /* Richardson-extrapolated central differences, error O(h^4); a
         * fast oscillation (sin(90 z^2)) needs the smaller step. */
        double scale = fmax(1.0, fmax(fabs(exact), fabs(at(e, syms, v))));
        double fd = 0;
        for (double h = 1e-3; h >= 1e-4; h /= 10) {
            double d1 = central(e, syms, v, k, h), d2 = central(e, syms, v, k, h / 2);
            fd = (4 * d2 - d1) / 3;
            if (fabs(exact - fd) <= 1e-6 * scale)
                break;
        }
        if (fabs(exact - fd) > 1e-6 * scale) {
            qd_buf b = QD_BUF_INIT;
            qd_print(ctx, e, QD_FMT_TEXT, &b);
            fail_msg("case %d: d/d%s of %s: exact %.15g, differences %.15g", i,
                     qd_expr_name(syms[k]), qd_buf_str(&b), exact, fd);
        }
        checked++;
    }
    assert_int_equal(checked, 1000);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(rules),
        cmocka_unit_test(user_functions),
        cmocka_unit_test(time_derivative),
        cmocka_unit_test(substitution),
        cmocka_unit_test(finite_differences),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
