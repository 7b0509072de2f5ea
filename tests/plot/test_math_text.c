/*
 * tests/plot/test_math_text.c - labels as a textbook prints names
 * (qd_plot_math_text, qdot/plot.h): the Unicode of each rule, spelt out.
 *
 *   theta1'  -> theta (U+03B8), a dot above (U+0307), subscript 1 (U+2081):
 *               Newton's dot for the time derivative, the index below;
 *   x2''     -> x, two dots (U+0308), subscript 2;
 *   Omega    -> capital omega (U+03A9); "omega = 2 rad/s" keeps the rest;
 *   words longer than a letter that name no Greek letter stay (gl4, th'),
 *   and so do other words: "time since release", "t (s)",
 *   a file's name ("ring6.qd", "a/x1"), names with '_' ("energy_error"),
 *   numbers ("1e-05");
 *   the length needed is returned as snprintf does, the output truncated
 *   at a whole character (Cairo refuses broken UTF-8).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <string.h>

#include "qdot/plot.h"

static void check(const char *in, const char *want) {
    char out[128];
    size_t n = qd_plot_math_text(in, out, sizeof out);
    assert_string_equal(out, want);
    assert_int_equal(n, strlen(want));
}

static void test_rules(void **state) {
    (void)state;
    check("theta1'", "\xce\xb8\xcc\x87\xe2\x82\x81");
    check("x2''", "x\xcc\x88\xe2\x82\x82");
    check("Omega", "\xce\xa9");
    check("omega = 2 rad/s", "\xcf\x89 = 2 rad/s");
    check("phi12", "\xcf\x86\xe2\x82\x81\xe2\x82\x82");
    check("(theta, theta')", "(\xce\xb8, \xce\xb8\xcc\x87)");
    check("A1", "A\xe2\x82\x81"); /* an irrep's index */
}

static void test_left_alone(void **state) {
    (void)state;
    check("time since release", "time since release");
    check("t (s)", "t (s)");
    check("ring6.qd", "ring6.qd");
    check("a/x1", "a/x1");
    check("energy_error", "energy_error");
    check("1e-05", "1e-05");
    check("gl4 and dop853", "gl4 and dop853"); /* methods' names: words */
    check("th'", "th'");
    check("E - E0", "E - E\xe2\x82\x80");
    check("x'''", "x'''"); /* three primes: no dots for them */
}

static void test_truncated(void **state) {
    (void)state;
    char out[4];
    size_t n = qd_plot_math_text("theta1'", out, sizeof out);
    assert_int_equal(n, 7);
    assert_int_equal(strlen(out), 2); /* theta whole, not half of its dot */
    assert_int_equal(qd_plot_math_text("theta", NULL, 0), 2);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rules),
        cmocka_unit_test(test_left_alone),
        cmocka_unit_test(test_truncated),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
