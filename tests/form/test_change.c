/*
 * tests/form/test_change.c - a change of variables in an integral
 * (qd_change_vars, qd_change_read, qdot/form.h) against Desloge vol. 2
 * App. 19 (eq. 1), App. 18 and ch. 60 eq. 6 (seed 000_46d037099a6cfcd7.txt;
 * reference seed-desloge-D.md App. 18-19, P18):
 *
 *   polar x = r cos th, y = r sin th with r positive: J(x/y) = r >= 0,
 *   J(y/x) = 1/r, and x^2 + y^2 becomes r^3 (the textbook area element
 *   r dr dth);
 *   spherical: J = r^2 sin th, of unknown sign, zero at r = 0 and th = k pi
 *   (where the region must be split), |J| = r^2 abs(sin th);
 *   ch. 60 eq. 6 with s = b cot(th/2), psi = ph (b > 0): J = -b/(2 sin^2(th/2))
 *   <= 0, and s |J| / sin th = b^2/(4 sin^4(th/2)), Rutherford's cross section;
 *   the reader: each old variable once, errors at their place.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <string.h>

#include "qdot/qdot.h"
#include "qdot/form.h"
#include "util/check.h"

static const qd_expr *expr(qd_ctx *ctx, const char *text) {
    qd_diag d;
    const qd_expr *x = qd_read(ctx, text, NULL, &d);
    if (!x)
        fail_msg("cannot read %s: %s", text, d.message);
    return x;
}

/* The change read as `qdot form --change` reads it. */
static qd_change *changed(qd_ctx *ctx, const char *f, const char *old, const char *map,
                          const char *new_vars) {
    const qd_expr *x[4], *y[4], *m[4];
    size_t n = 0, k = 0;
    assert_int_equal(qd_qform_vars_read(ctx, old, x, 4, &n), QD_OK);
    assert_int_equal(qd_qform_vars_read(ctx, new_vars, y, 4, &k), QD_OK);
    assert_int_equal(n, k);
    assert_int_equal(qd_change_read(ctx, map, n, x, m), QD_OK);
    qd_change *c = qd_change_vars(ctx, expr(ctx, f), n, x, y, m);
    assert_non_null(c);
    return c;
}

static void test_polar(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *p[1];
    size_t np = 0;
    assert_int_equal(qd_qform_positive_read(ctx, "r", p, 1, &np), QD_OK);
    qd_change *c = changed(ctx, "x^2 + y^2", "x, y", "x = r*cos(th), y = r*sin(th)", "r, th");
    qt_assert_is(ctx, c->det, "r");
    qt_assert_is(ctx, c->inverse, "1/r");
    assert_int_equal(c->sign, 1);
    qt_assert_is(ctx, c->integrand, "r^3");
    qd_change_free(c);
    qd_ctx_free(ctx);
}

static void test_spherical(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_change *c = changed(ctx, "1", "x, y, z",
                           "x = r*sin(th)*cos(ph), y = r*sin(th)*sin(ph), z = r*cos(th)",
                           "r, th, ph");
    qt_assert_is(ctx, c->det, "r^2*sin(th)");
    assert_int_equal(c->sign, 0);
    qt_assert_is(ctx, c->absdet, "r^2*abs(sin(th))");
    assert_int_equal(c->nsing, 2);
    qt_assert_is(ctx, c->sing[0].lhs, "r");
    qt_assert_is(ctx, c->sing[0].rhs, "0");
    qt_assert_is(ctx, c->sing[1].lhs, "th");
    qt_assert_is(ctx, c->sing[1].period, "pi");
    qd_change_free(c);
    qd_ctx_free(ctx);
}

static void test_rutherford(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *p[1];
    size_t np = 0;
    assert_int_equal(qd_qform_positive_read(ctx, "b", p, 1, &np), QD_OK);
    qd_change *c = changed(ctx, "s", "s, psi", "s = b*cos(th/2)/sin(th/2), psi = ph", "th, ph");
    qt_assert_is(ctx, c->det, "-b/(2*sin(th/2)^2)");
    assert_int_equal(c->sign, -1);
    assert_int_equal(c->nsing, 0); /* a pole, not a zero */
    qd_zero_result z;
    const qd_expr *sigma = qd_div(ctx, c->integrand, expr(ctx, "sin(th)"));
    assert_int_equal(qd_equal_test(ctx, sigma, expr(ctx, "b^2/(4*sin(th/2)^4)"), &z), QD_OK);
    assert_true(z.kind == QD_ZERO_PROVEN || z.kind == QD_ZERO_NUMERIC);
    qd_change_free(c);
    qd_ctx_free(ctx);
}

static void test_reader_errors(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *x[2], *m[2];
    size_t n = 0;
    assert_int_equal(qd_qform_vars_read(ctx, "x, y", x, 2, &n), QD_OK);
    assert_int_equal(qd_change_read(ctx, "x = u, x = v", n, x, m), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(ctx), "x is given twice"));
    assert_int_equal(qd_ctx_diag(ctx)->col, 8);
    qd_ctx_clear_error(ctx);
    assert_int_equal(qd_change_read(ctx, "x = u, y", n, x, m), QD_ERR_ARG);
    qd_ctx_clear_error(ctx);
    const qd_expr *p[1];
    size_t np = 0; /* x exists already, of either sign */
    assert_int_equal(qd_qform_positive_read(ctx, "x", p, 1, &np), QD_ERR_ARG);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_polar),
        cmocka_unit_test(test_spherical),
        cmocka_unit_test(test_rutherford),
        cmocka_unit_test(test_reader_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
