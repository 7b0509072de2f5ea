/*
 * tests/sym/test_tangent.c - forward-mode Jacobians (qdot/tangent.h)
 * against a Jacobian written by hand, against symbolic differentiation
 * (qd_diff, a different path) on random expressions over every built-in
 * function, and against central differences; constant inputs, and a
 * derivative that does not exist reported, not returned as NaN.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/tangent.h"
#include "util/randexpr.h"

static const qd_expr *rd(qd_ctx *ctx, const char *text) {
    const qd_expr *e = qd_read(ctx, text, NULL, NULL);
    assert_non_null(e);
    return e;
}

/* F(x, y, z) = (x^2 y, sin(x) e^z, atan2(y, x), sqrt(x^2 + y^2 + z^2), x^y),
 * its Jacobian by hand (calculus: d atan2(y, x) = (x dy - y dx)/(x^2 + y^2),
 * d x^y = y x^(y-1) dx + x^y log x dy). */
static void test_hand_jacobian(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *in[3] = {rd(ctx, "x"), rd(ctx, "y"), rd(ctx, "z")};
    const qd_expr *out[5] = {rd(ctx, "x^2*y"), rd(ctx, "sin(x)*exp(z)"), rd(ctx, "atan2(y, x)"),
                             rd(ctx, "sqrt(x^2 + y^2 + z^2)"), rd(ctx, "x^y")};
    qd_tangent *t = qd_tangent_new(ctx, 3, in, NULL, 5, out);
    assert_non_null(t);
    assert_int_equal(qd_tangent_nin(t), 3);
    assert_int_equal(qd_tangent_nvar(t), 3);
    assert_int_equal(qd_tangent_nout(t), 5);
    double x = 1.3, y = -0.7, z = 0.4, p[3] = {x, y, z}, F[5], J[15], F2[5];
    assert_int_equal(qd_tangent_jacobian(ctx, t, p, F, J), QD_OK);
    double r = sqrt(x * x + y * y + z * z), r2 = x * x + y * y;
    double want[15] = {2 * x * y, x * x, 0,
                       cos(x) * exp(z), 0, sin(x) * exp(z),
                       -y / r2, x / r2, 0,
                       x / r, y / r, z / r,
                       y * pow(x, y - 1), pow(x, y) * log(x), 0};
    for (int i = 0; i < 15; i++)
        assert_true(fabs(J[i] - want[i]) <= 1e-15 * fmax(1, fabs(want[i])));
    assert_true(fabs(F[1] - sin(x) * exp(z)) <= 1e-15);
    assert_int_equal(qd_tangent_eval(t, p, F2), QD_OK);
    for (int i = 0; i < 5; i++)
        assert_true(F2[i] == F[i]);
    qd_tangent_free(t);
    qd_ctx_free(ctx);
}

/* A constant input (a parameter) has no column; the Jacobian is over x, z. */
static void test_constant_inputs(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *in[3] = {rd(ctx, "x"), rd(ctx, "k"), rd(ctx, "z")};
    const qd_expr *out[2] = {rd(ctx, "k*x*z"), rd(ctx, "k^2")};
    bool vary[3] = {true, false, true};
    qd_tangent *t = qd_tangent_new(ctx, 3, in, vary, 2, out);
    assert_non_null(t);
    assert_int_equal(qd_tangent_nvar(t), 2);
    double p[3] = {2, 3, 5}, F[2], J[4];
    assert_int_equal(qd_tangent_jacobian(ctx, t, p, F, J), QD_OK);
    assert_true(J[0] == 15 && J[1] == 6 && J[2] == 0 && J[3] == 0);
    assert_true(F[1] == 9);
    qd_tangent_free(t);
    qd_ctx_free(ctx);
}

/* Random expressions over every function: the forward-mode column equals
 * qd_diff's derivative evaluated (1e-11 relative), and central differences
 * (h = 1e-6, truncation ~1e-12 times the third derivative) to 1e-6. */
static void test_random_against_diff(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qt_rng rng = {20261204u};
    const qd_expr *in[3] = {rd(ctx, "a"), rd(ctx, "b"), rd(ctx, "c")};
    size_t checked = 0;
    for (int round = 0; round < 200; round++) {
        const qd_expr *f = qt_random_expr(ctx, &rng, in, 3, 4, QT_ALL);
        assert_non_null(f);
        const qd_expr *d[3];
        for (int k = 0; k < 3; k++)
            assert_non_null(d[k] = qd_diff(ctx, f, in[k]));
        qd_tangent *t = qd_tangent_new(ctx, 3, in, NULL, 1, &f);
        qd_prog *pd = qd_prog_new(ctx, 3, in, 3, d);
        assert_non_null(t);
        assert_non_null(pd);
        double p[3] = {qt_uniform(&rng, 0.2, 1.5), qt_uniform(&rng, 0.2, 1.5),
                       qt_uniform(&rng, 0.2, 1.5)};
        double F, J[3], want[3];
        qd_prog_run(pd, p, want);
        qd_status st = qd_tangent_jacobian(ctx, t, p, &F, J);
        bool finite = isfinite(want[0]) && isfinite(want[1]) && isfinite(want[2]);
        if (st == QD_OK && finite && fabs(F) < 1e6) {
            for (int k = 0; k < 3; k++) {
                double s = fmax(1, fabs(want[k]));
                if (!(fabs(J[k] - want[k]) <= 1e-11 * s)) {
                    qd_buf txt = QD_BUF_INIT;
                    qd_print(ctx, f, QD_FMT_TEXT, &txt);
                    fprintf(stderr, "f = %s at (%.17g, %.17g, %.17g): d/d%d forward %.17g, "
                            "diff %.17g\n", qd_buf_str(&txt), p[0], p[1], p[2], k, J[k], want[k]);
                    qd_buf_free(&txt);
                }
                assert_true(fabs(J[k] - want[k]) <= 1e-11 * s);
                double h = 1e-6, pp[3] = {p[0], p[1], p[2]}, fp, fm;
                pp[k] = p[k] + h;
                qd_tangent_eval(t, pp, &fp);
                pp[k] = p[k] - h;
                qd_tangent_eval(t, pp, &fm);
                if (fabs(want[k]) < 1e4)
                    assert_true(fabs((fp - fm) / (2 * h) - J[k]) <= 1e-6 * s);
            }
            checked++;
        }
        qd_ctx_clear_error(ctx);
        qd_prog_free(pd);
        qd_tangent_free(t);
    }
    assert_true(checked >= 150);
    qd_ctx_free(ctx);
}

/* sqrt(x) at 0: the derivative is infinite, reported with QD_ERR_NUMERIC. */
static void test_not_finite(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *x = rd(ctx, "x"), *f = rd(ctx, "sqrt(x)");
    qd_tangent *t = qd_tangent_new(ctx, 1, &x, NULL, 1, &f);
    assert_non_null(t);
    double p = 0, F, J;
    assert_int_equal(qd_tangent_jacobian(ctx, t, &p, &F, &J), QD_ERR_NUMERIC);
    assert_non_null(strstr(qd_ctx_message(ctx), "derivative of output 0"));
    qd_tangent_free(t);
    /* an output with a symbol that is not an input */
    const qd_expr *g = rd(ctx, "x*w");
    qd_ctx_clear_error(ctx);
    assert_null(qd_tangent_new(ctx, 1, &x, NULL, 1, &g));
    assert_int_equal(qd_ctx_status(ctx), QD_ERR_UNBOUND);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_hand_jacobian),
        cmocka_unit_test(test_constant_inputs),
        cmocka_unit_test(test_random_against_diff),
        cmocka_unit_test(test_not_finite),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
