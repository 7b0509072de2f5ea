/*
 * tests/num/test_result.c - the digit rule of computed results
 * (qd_result_format, qdot/print.h): 12 significant digits, 0 at or below
 * 1e-12 of the scale, -0 as 0; and that data keep every digit
 * (qd_double_format reads back to the same double).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/print.h"

#define PI 3.14159265358979323846

static const char *fmt(double x, double scale) {
    static char s[QD_DOUBLE_MAX];
    qd_result_format(s, x, scale);
    return s;
}

static void test_digits(void **state) {
    (void)state;
    /* a root found by iteration: 0.49 to the digits that mean anything */
    assert_string_equal("0.49", fmt(0.48999999999999927, 1));
    assert_string_equal("0.333333333333", fmt(1.0 / 3, 1));
    assert_string_equal("628.318530718", fmt(200 * PI, 0));
    assert_string_equal("-1.5e+20", fmt(-1.5e20, 0));
    /* 12 digits, and no more: the 13th is rounded away */
    assert_true(fabs(strtod(fmt(PI, 1), NULL) - PI) < 5e-12);
    assert_true(strlen(fmt(PI, 1)) == strlen("3.14159265359"));
}

static void test_zero_threshold(void **state) {
    (void)state;
    /* the real part of an eigenvalue 1e-17 +- 3i is round-off against |s| = 3 */
    assert_string_equal("0", fmt(1e-17, 3));
    assert_string_equal("0", fmt(-3e-12, 3));   /* at 1e-12 * 3 */
    assert_string_equal("-3.1e-12", fmt(-3.1e-12, 3)); /* just above */
    /* relative: in small units a small number is a value */
    assert_string_equal("1e-17", fmt(1e-17, 1e-16));
    /* no scale (0, negative, NaN, infinite): against 1 */
    assert_string_equal("0", fmt(5e-13, 0));
    assert_string_equal("0", fmt(5e-13, NAN));
    assert_string_equal("0", fmt(5e-13, INFINITY));
    assert_string_equal("2e-12", fmt(2e-12, -1));
    assert_string_equal("0", fmt(-0.0, 1));
}

static void test_nonfinite(void **state) {
    (void)state;
    assert_string_equal("inf", fmt(INFINITY, 1));
    assert_string_equal("-inf", fmt(-INFINITY, 1));
    assert_non_null(strstr(fmt(NAN, 1), "nan"));
}

/* Data keep every digit: the shortest text that reads back to the double. */
static void test_data_round_trip(void **state) {
    (void)state;
    const double xs[] = {0.1 + 0.2, 9.81, 1.0 / 3, 5e-324, -2.5e-300, 0.48999999999999927};
    for (size_t i = 0; i < sizeof xs / sizeof xs[0]; i++) {
        char s[QD_DOUBLE_MAX];
        qd_double_format(s, xs[i]);
        assert_true(strtod(s, NULL) == xs[i]);
    }
    qd_buf b = QD_BUF_INIT;
    qd_buf_put_result(&b, 0.48999999999999927, 1);
    qd_buf_puts(&b, " ");
    qd_buf_put_result(&b, 1e-20, 1);
    assert_string_equal("0.49 0", qd_buf_str(&b));
    qd_buf_free(&b);
    assert_int_equal(0, qd_result_format(NULL, 1, 1));
    qd_buf_put_result(NULL, 1, 1); /* nothing, no crash */
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_digits),
        cmocka_unit_test(test_zero_threshold),
        cmocka_unit_test(test_nonfinite),
        cmocka_unit_test(test_data_round_trip),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
