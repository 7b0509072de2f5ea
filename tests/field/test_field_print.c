/*
 * tests/field/test_field_print.c - a field's equation and modes as the
 * library writes them (src/field/print.c), checked against the physics:
 *
 *   - the stretched string (Desloge ch. 83, Problem 4; examples/string.qd):
 *     rho = 0.01, tau = 100, l = 0.5 fixed at both ends; omega_n =
 *     (n pi / l) sqrt(tau/rho) = 200 pi n, shapes sin(n pi x / l), read back
 *     from the JSON and the text table;
 *   - the hanging chain (examples/hanging_chain.qd): by finite elements,
 *     omega_1 = (j_01 / 2) sqrt(g/l) (j_01 = 2.404825557695773, the first zero
 *     of Bessel's J0) within the error estimate the JSON reports, and
 *     "method": "finite elements" with the tolerance held to.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/field.h"

static const double PI = 3.14159265358979323846;

static const char *string_model =
    "parameters rho = 0.01, tau = 100, l = 0.5\n"
    "field y(x, t) on x = 0 .. l\n"
    "Ldensity = rho/2*y_t^2 - tau/2*y_x^2\n"
    "boundary y(0) = 0, y(l) = 0\n";

static const char *chain_model =
    "parameters rho = 1, g = 9.81, l = 2\n"
    "field y(x, t) on x = 0 .. l\n"
    "Ldensity = rho/2*y_t^2 - rho*g*x/2*y_x^2\n"
    "boundary y(0) free, y(l) = 0\n";

/* The number after the n-th (from 0) occurrence of "key": in s. */
static double number_after(const char *s, const char *key, int n) {
    const char *p = s;
    for (int k = 0; k <= n; k++) {
        p = strstr(p, key);
        assert_non_null(p);
        p += strlen(key);
    }
    return strtod(p, NULL);
}

static void test_string_modes(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_field *f = qd_field_parse(ctx, string_model, NULL, NULL);
    assert_non_null(f);
    qd_field_modes r = {0};
    qd_field_modes_opts o = {.count = 3};
    assert_int_equal(qd_field_modes_compute(ctx, f, &o, &r), QD_OK);
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_field_modes_json(ctx, f, &r, &b), QD_OK);
    const char *s = qd_buf_str(&b);
    assert_non_null(strstr(s, "\"method\": \"exact\""));
    for (int n = 1; n <= 3; n++) {
        double w = number_after(s, "\"omega\": ", n - 1);
        double k = number_after(s, "\"k\": ", n - 1);
        assert_true(fabs(w - 200 * PI * n) < 1e-9 * w);
        assert_true(fabs(k - 2 * PI * n) < 1e-12 * k); /* n pi / l */
    }
    assert_non_null(strstr(s, "\"shape\": \"sin(6.283185307179586*x)\""));
    qd_buf_free(&b);
    /* the text table: mode 1's omega, 12 digits (200 pi = 628.318530718) */
    b = (qd_buf)QD_BUF_INIT;
    assert_int_equal(qd_field_modes_print(ctx, f, &r, &b), QD_OK);
    assert_non_null(strstr(qd_buf_str(&b), "fixed at x = 0, fixed at x = 0.5"));
    assert_non_null(strstr(qd_buf_str(&b), "\n1  628.318530718  "));
    qd_buf_free(&b);
    /* the equation: rho y_tt - tau y_xx = 0 (no y term) */
    const qd_expr *E = qd_field_equation(ctx, f);
    assert_non_null(E);
    b = (qd_buf)QD_BUF_INIT;
    assert_int_equal(qd_field_equation_json(ctx, f, E, &b), QD_OK);
    s = qd_buf_str(&b);
    assert_non_null(strstr(s, "\"equation\""));
    assert_non_null(strstr(s, "y_tt") && strstr(s, "y_xx"));
    assert_true(number_after(s, "\"interval\": [", 0) == 0);
    qd_buf_free(&b);
    qd_field_modes_free(&r);
    qd_field_free(f);
    qd_ctx_free(ctx);
}

static void test_chain_finite_elements(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_field *f = qd_field_parse(ctx, chain_model, NULL, NULL);
    assert_non_null(f);
    qd_field_modes r = {0};
    qd_field_modes_opts o = {.count = 2, .tol = 1e-7};
    assert_int_equal(qd_field_modes_compute(ctx, f, &o, &r), QD_OK);
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_field_modes_json(ctx, f, &r, &b), QD_OK);
    const char *s = qd_buf_str(&b);
    assert_non_null(strstr(s, "\"method\": \"finite elements\""));
    assert_non_null(strstr(s, "\"converged\": true"));
    assert_true(number_after(s, "\"tolerance\": ", 0) == 1e-7);
    double w = number_after(s, "\"omega\": ", 0), err = number_after(s, "\"error\": ", 0);
    double exact = 2.404825557695773 / 2 * sqrt(9.81 / 2);
    assert_true(err > 0 && fabs(w - exact) <= err + 1e-12);
    assert_non_null(strstr(s, "\"shape\": null"));
    qd_buf_free(&b);
    qd_field_modes_free(&r);
    qd_field_free(f);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_string_modes),
        cmocka_unit_test(test_chain_finite_elements),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
