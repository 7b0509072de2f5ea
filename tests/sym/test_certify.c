/*
 * tests/sym/test_certify.c - qd_zero_test (qdot/certify.h, issue 33): an
 * expression the simplifier reduces to 0 is PROVEN; one that is not zero
 * gets a witness point whose ball excludes 0, and the witness is checked
 * here by evaluating the expression at it in double; one that is zero but
 * not reduced is NUMERIC; one with an undefined function is UNKNOWN; a
 * witness lies in the domain of the expression as given, not only of its
 * simplified form (sqrt(a) sqrt(b) (|a| - a) is 0 wherever it is defined,
 * a, b >= 0, but simplifies to sqrt(a b) (|a| - a), which is defined and
 * nonzero at a, b < 0: it was called nonzero with a witness there).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "qdot/qdot.h"

static qd_zero_result test(qd_ctx *ctx, const char *text) {
    const qd_expr *e = qd_read(ctx, text, NULL, NULL);
    assert_non_null(e);
    qd_zero_result z;
    assert_int_equal(QD_OK, qd_zero_test(ctx, e, &z));
    return z;
}

static void proven(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    assert_int_equal(QD_ZERO_PROVEN, test(ctx, "sin(x)^2 + cos(x)^2 - 1").kind);
    assert_int_equal(QD_ZERO_PROVEN, test(ctx, "(x + y)^2 - x^2 - 2*x*y - y^2").kind);
    qd_ctx_free(ctx);
}

/* The witness is a point where the expression's value is certainly nonzero:
 * re-evaluated in double it agrees with the ball's midpoint, and the ball's
 * radius is far below its distance from 0. */
static void witness(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const char *cases[] = {"2*q - 1", "x*y - y*x + x^3 - x", "sin(x)^2 - 1 + cos(x)",
                           "log(x^2 + 1) - x^2", "exp(x)*exp(y) - exp(x + y) + 1e-30*x"};
    for (size_t c = 0; c < sizeof cases / sizeof *cases; c++) {
        const qd_expr *e = qd_read(ctx, cases[c], NULL, NULL);
        qd_zero_result z;
        assert_int_equal(QD_OK, qd_zero_test(ctx, e, &z));
        assert_int_equal(QD_ZERO_NONZERO, z.kind);
        assert_true(z.witness.radius < fabs(z.witness.value));
        if (c + 1 < sizeof cases / sizeof *cases) { /* the last is below double's reach */
            double v = 0;
            assert_int_equal(QD_OK, qd_eval(ctx, e, z.witness.n, z.witness.sym, z.witness.at, &v));
            assert_true(fabs(v - z.witness.value) <= 1e-12 * (1 + fabs(v)));
        }
    }
    qd_ctx_free(ctx);
}

/* Zero, but not reduced by the simplifier (kept here as expressions the
 * simplifier does not reduce; if it learns them the kind is PROVEN, still
 * "zero"): acos(x) + asin(x) - pi/2 on [-1, 1]. */
static void numeric(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_zero_result z = test(ctx, "acos(x/2) + asin(x/2) - pi/2");
    assert_true(z.kind == QD_ZERO_NUMERIC || z.kind == QD_ZERO_PROVEN);
    if (z.kind == QD_ZERO_NUMERIC)
        assert_int_equal(QD_ZERO_POINTS, z.points);
    z = test(ctx, "atan(x) + atan(1/x) - pi/2*sign(x)");
    assert_true(z.kind == QD_ZERO_NUMERIC || z.kind == QD_ZERO_PROVEN);
    qd_ctx_free(ctx);
}

static void undecided(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *x = qd_symbol(ctx, "x");
    const qd_expr *f = qd_ufunc(ctx, "f", 1, &x);
    qd_zero_result z;
    assert_int_equal(QD_OK, qd_zero_test(ctx, qd_sub(ctx, f, x), &z));
    assert_int_equal(QD_ZERO_UNKNOWN, z.kind);
    /* nowhere defined: log of a negative */
    z = test(ctx, "log(-1 - x^2) - x");
    assert_int_equal(QD_ZERO_UNKNOWN, z.kind);
    qd_ctx_free(ctx);
}

static void witness_in_domain(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_zero_result z = test(ctx, "sqrt(a)*sqrt(b)*(abs(a) - a)");
    assert_int_equal(QD_ZERO_NUMERIC, z.kind);
    /* nonzero on its domain: the witness is a point of it, where the
     * expression as given has the witness's value */
    const char *cases[] = {"sqrt(a)*sqrt(b)*(abs(a) - a) + sqrt(a)", "sqrt(a)*sqrt(b) - 1"};
    for (size_t c = 0; c < 2; c++) {
        const qd_expr *e = qd_read(ctx, cases[c], NULL, NULL);
        assert_int_equal(QD_OK, qd_zero_test(ctx, e, &z));
        assert_int_equal(QD_ZERO_NONZERO, z.kind);
        for (size_t i = 0; i < z.witness.n; i++)
            assert_true(z.witness.at[i] >= 0);
        double v = 0;
        assert_int_equal(QD_OK, qd_eval(ctx, e, z.witness.n, z.witness.sym, z.witness.at, &v));
        assert_true(fabs(v - z.witness.value) <= 1e-12 * (1 + fabs(v)));
    }
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(proven),
        cmocka_unit_test(witness),
        cmocka_unit_test(numeric),
        cmocka_unit_test(undecided),
        cmocka_unit_test(witness_in_domain),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
