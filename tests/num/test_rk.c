/*
 * tests/num/test_rk.c - the fixed-step explicit Runge-Kutta step of
 * src/num/rk.c with the classical RK4 tableau:
 *
 *   y' = y, one step from y = 1: the Taylor polynomial of e^h to h^4,
 *     1 + h + h^2/2 + h^3/6 + h^4/24 (Hairer, Norsett & Wanner I, II.1);
 *   the harmonic oscillator x'' = -x from (1, 0) to t = 1: (cos 1, -sin 1)
 *     with an error of order h^4 (halving h divides it by about 16);
 *   a failing right-hand side leaves y as it was.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "num/num.h"

static bool growth(void *data, double t, const double *y, double *dy) {
    (void)data, (void)t;
    dy[0] = y[0];
    return true;
}

static bool oscillator(void *data, double t, const double *y, double *dy) {
    (void)data, (void)t;
    dy[0] = y[1];
    dy[1] = -y[0];
    return true;
}

static bool fails_late(void *data, double t, const double *y, double *dy) {
    (void)y;
    int *calls = data;
    dy[0] = 1;
    return ++*calls < 3 && t >= 0;
}

static void taylor_of_exp(void **state) {
    (void)state;
    double w[5], y = 1, h = 0.1;
    assert_true(qd__num_rk_step(&qd__num_rk4, growth, NULL, 1, 0, h, &y, w));
    assert_true(fabs(y - (1 + h + h * h / 2 + h * h * h / 6 + h * h * h * h / 24)) < 1e-15);
}

static double oscillator_error(size_t steps) {
    double y[2] = {1, 0}, w[10], h = 1.0 / (double)steps;
    for (size_t i = 0; i < steps; i++)
        assert_true(qd__num_rk_step(&qd__num_rk4, oscillator, NULL, 2, h * (double)i, h, y, w));
    return hypot(y[0] - cos(1.0), y[1] + sin(1.0));
}

static void fourth_order(void **state) {
    (void)state;
    double e1 = oscillator_error(10), e2 = oscillator_error(20);
    assert_true(e1 < 1e-5);
    double ratio = e1 / e2;
    assert_true(ratio > 14 && ratio < 18);
}

static void failure_keeps_y(void **state) {
    (void)state;
    int calls = 0;
    double y = 2, w[5];
    assert_false(qd__num_rk_step(&qd__num_rk4, fails_late, &calls, 1, 0, 0.5, &y, w));
    assert_true(y == 2);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(taylor_of_exp),
        cmocka_unit_test(fourth_order),
        cmocka_unit_test(failure_keeps_y),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
