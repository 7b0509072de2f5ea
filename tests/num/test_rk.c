/*
 * tests/num/test_rk.c - the explicit Runge-Kutta stage loop of
 * src/num/rk.c with num's tableaux:
 *
 *   y' = y, one RK4 step from y = 1: the Taylor polynomial of e^h to h^4,
 *     1 + h + h^2/2 + h^3/6 + h^4/24 (Hairer, Norsett & Wanner I, II.1);
 *   the harmonic oscillator x'' = -x from (1, 0) to t = 1: (cos 1, -sin 1)
 *     with an error of order h^p, halving h dividing it by about 2^p:
 *     16 for RK4, 32 for the Dormand-Prince 5(4) pair's fifth-order step
 *     (qd__num_dp5), 256 for DOP853's eighth-order one (qd__num_dp8), so
 *     each table is the method of its order (a wrong coefficient drops it);
 *   the first-same-as-last form (src/sim's pairs): k_0 given, the result
 *     that of the plain step, and the last row f(t + h, y1);
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

static double oscillator_error(const qd__num_rk *m, size_t steps) {
    double y[2] = {1, 0}, w[2 * (QD__NUM_RK_MAX_STAGES + 1)], h = 1.0 / (double)steps;
    for (size_t i = 0; i < steps; i++)
        assert_true(qd__num_rk_step(m, oscillator, NULL, 2, h * (double)i, h, y, w));
    return hypot(y[0] - cos(1.0), y[1] + sin(1.0));
}

/* The error from `steps` steps and the ratio to that from twice as many,
 * about 2^p for a method of order p while round-off (1e-16) is far below. */
static void order(const qd__num_rk *m, size_t steps, double p, double emax) {
    double e1 = oscillator_error(m, steps), e2 = oscillator_error(m, 2 * steps);
    assert_true(e1 < emax);
    assert_true(e2 > 1e-14);
    double ratio = e1 / e2, expect = pow(2, p);
    assert_true(ratio > 0.88 * expect && ratio < 1.12 * expect);
}

static void fourth_order(void **state) {
    (void)state;
    order(&qd__num_rk4, 10, 4, 1e-5);
}

static void dp5_fifth_order(void **state) {
    (void)state;
    order(&qd__num_dp5, 10, 5, 1e-8);
}

static void dp8_eighth_order(void **state) {
    (void)state;
    order(&qd__num_dp8, 2, 8, 1e-9);
}

static bool counted_oscillator(void *data, double t, const double *y, double *dy) {
    ++*(int *)data;
    return oscillator(NULL, t, y, dy);
}

static void fsal(void **state) {
    (void)state;
    const qd__num_rk *m = &qd__num_dp5;
    double y0[2] = {0.3, -0.8}, y1[2], y[2] = {0.3, -0.8}, t = 0.25, h = 0.1;
    double rows[7][2], *k[7], ytmp[2], w[14], f1[2];
    for (int i = 0; i < 7; i++)
        k[i] = rows[i];
    int calls = 0;
    oscillator(NULL, t, y0, k[0]);
    assert_true(qd__num_rk_stages(m, counted_oscillator, &calls, 2, t, h, y0, y1, k, ytmp, true));
    assert_int_equal(calls, 6); /* stages 1-5 and the last row */
    assert_true(qd__num_rk_step(m, oscillator, NULL, 2, t, h, y, w));
    assert_true(y1[0] == y[0] && y1[1] == y[1]);
    oscillator(NULL, t + h, y1, f1);
    assert_true(k[6][0] == f1[0] && k[6][1] == f1[1]);
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
        cmocka_unit_test(dp5_fifth_order),
        cmocka_unit_test(dp8_eighth_order),
        cmocka_unit_test(fsal),
        cmocka_unit_test(failure_keeps_y),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
