/*
 * tests/num/test_shortest.c - qd_double_format: the fewest significant
 * digits that read back to the same double.
 *
 * Reference: the shortest %.Ng, N = 15..17 (N = 1..17 for a subnormal),
 * whose strtod is x (C11 7.21.6.1 for %g; a double needs at most 17
 * digits, IEEE 754-2008 5.12.2), and no more significant digits than the
 * shortest %.Ng of any N.  Checked on textbook cases (0.1 + 0.2, 9.81,
 * the extremes of the fast path and beyond it, subnormals, powers of 2
 * whose lower gap is half) and on 200,000 doubles with random bits, which
 * also must read back exactly.
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

#include "qdot/print.h"

static void reference(char *out, double x) {
    for (int p = fabs(x) < 0x1p-1022 ? 1 : 15; p <= 17; p++) {
        snprintf(out, QD_DOUBLE_MAX, "%.*g", p, x);
        if (strtod(out, NULL) == x)
            return;
    }
}

static void check(double x) {
    char got[QD_DOUBLE_MAX], want[QD_DOUBLE_MAX];
    size_t n = qd_double_format(got, x);
    reference(want, x);
    if (strcmp(got, want) || n != strlen(got) || strtod(got, NULL) != x)
        fail_msg("%a: got '%s', want '%s'", x, got, want);
    /* as short as any: no more significant digits than the shortest %.Ng
     * of any N (leading and trailing zeros are not significant) */
    char any[QD_DOUBLE_MAX];
    int p = 1;
    for (; p < 17; p++) {
        snprintf(any, sizeof any, "%.*g", p, x);
        if (strtod(any, NULL) == x)
            break;
    }
    int first = -1, last = -1, k = 0;
    for (const char *c = got; *c && *c != 'e'; c++) {
        if (*c < '0' || *c > '9')
            continue;
        if (*c != '0') {
            first = first < 0 ? k : first;
            last = k;
        }
        k++;
    }
    if (first >= 0 && last - first + 1 > p)
        fail_msg("%a: '%s' has more digits than '%s'", x, got, any);
}

static void test_cases(void **state) {
    (void)state;
    char s[QD_DOUBLE_MAX];
    qd_double_format(s, 0.1 + 0.2);
    assert_string_equal(s, "0.30000000000000004");
    qd_double_format(s, 9.81);
    assert_string_equal(s, "9.81");
    qd_double_format(s, -27.02816986428911);
    assert_string_equal(s, "-27.02816986428911");
    qd_double_format(s, 1e-300);
    assert_string_equal(s, "1e-300");
    double cases[] = {1, -1, 0.5, 1.0 / 3, 2.0 / 3, 1e-12, 9.999999999999999e-13, 1e15,
                      999999999999999.9, 123456789012345.6, 5e-324, 2.2250738585072014e-308,
                      1.7976931348623157e308, 0x1p53, 0x1p-20, 4503599627370497.0, 3.14159265358979,
                      3.141592653589793, -2.718281828459045, 1e-5, 1e-4,
                      0.00012345678901234567, 100, 1e14 + 0.5};
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++)
        check(cases[i]);
    for (int e = -330; e <= 310; e++)
        check(pow(10, e));
}

static void test_random_bits(void **state) {
    (void)state;
    uint64_t r = 0x9e3779b97f4a7c15u;
    for (int i = 0; i < 200000; i++) {
        r = r * 6364136223846793005u + 1442695040888963407u;
        /* half the draws with exponents near 1, where the fast path works */
        uint64_t bits = i % 2 ? r : (r & 0x800fffffffffffffu) | ((uint64_t)(1003 + r % 80) << 52);
        double x;
        memcpy(&x, &bits, sizeof x);
        if (isfinite(x))
            check(x);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cases),
        cmocka_unit_test(test_random_bits),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
