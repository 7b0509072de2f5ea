/*
 * tests/linear/test_linearize_about.c - the state-space form about a point
 * read from text (qd_linearize_about, qdot/statespace.h) and the LQR gain
 * on it, against closed forms:
 *
 *   the double integrator m x'' = F: A = [0 1; 0 0], B = [0; 1/m]; with
 *     m = 1, Q = I, R = 1 the Riccati equation A^T X + X A - X B B^T X + Q = 0
 *     solves by hand to X = [sqrt 3, 1; 1, sqrt 3], K = B^T X = [1, sqrt 3]
 *     (tests/linear/test_care.c derives it);
 *   the pendulum m l^2 th'' = -m g l sin th + tau held upright at th = pi,
 *     given exactly as "th = pi": A = [0 1; g/l 0], B = [0; 1/(m l^2)], and
 *     x'' = a x + b u with Q = diag(q1, q2), R = r gives
 *     p2 = r (a + sqrt(a^2 + b^2 q1/r)) / b^2, p3 = sqrt(r (2 p2 + q2)) / b,
 *     K = (b/r) [p2, p3];
 *   a misspelt name is located in the text; a parameter is refused.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "qdot/qdot.h"
#include "../util/system.h"

static void test_double_integrator(void **state) {
    qt_system *s = qt_system_derive(state, "coordinates x\nparameters m = 1\ninputs F\n"
                                           "T = m*x'^2/2\nQ[x] = F\n", false);
    qd_statespace ss;
    assert_int_equal(qd_linearize_about(s->ctx, s->eom, s->model, NULL, &ss), QD_OK);
    assert_true(ss.nx == 2 && ss.nu == 1);
    assert_true(ss.A[0] == 0 && ss.A[1] == 1 && ss.A[2] == 0 && ss.A[3] == 0);
    assert_true(ss.B[0] == 0 && fabs(ss.B[1] - 1) < 1e-15);
    qd_care_result r;
    assert_int_equal(qd_lqr_design(s->ctx, &ss, "Q = 1, R = 1", &r), QD_OK);
    assert_true(fabs(r.K[0] - 1) < 1e-10 && fabs(r.K[1] - sqrt(3.0)) < 1e-10);
    assert_true(fabs(r.X[0] - sqrt(3.0)) < 1e-10 && fabs(r.X[1] - 1) < 1e-10);
    qd_care_result_free(&r);
    qd_statespace_free(&ss);
}

#define PENDULUM                                                                               \
    "coordinates th\nparameters m = 2, l = 1.5, g = 9.81\ninputs tau\n"                        \
    "T = m*l^2*th'^2/2\nV = -m*g*l*cos(th)\nQ[th] = tau\n"

static void test_pendulum_upright(void **state) {
    qt_system *s = qt_system_derive(state, PENDULUM, false);
    qd_statespace ss;
    assert_int_equal(qd_linearize_about(s->ctx, s->eom, s->model, "th = pi, tau = 0", &ss),
                     QD_OK);
    double g = 9.81, l = 1.5, mm = 2, a = g / l, b = 1 / (mm * l * l), q1 = 2, q2 = 0.5, rr = 0.25;
    assert_true(ss.A[0] == 0 && ss.A[1] == 1 && fabs(ss.A[2] - a) < 1e-12 && ss.A[3] == 0);
    assert_true(ss.B[0] == 0 && fabs(ss.B[1] - b) < 1e-15);
    qd_care_result r;
    assert_int_equal(qd_lqr_design(s->ctx, &ss, "Q = diag(2, 0.5), R = 0.25", &r), QD_OK);
    double p2 = rr * (a + sqrt(a * a + b * b * q1 / rr)) / (b * b);
    double p3 = sqrt(rr * (2 * p2 + q2)) / b;
    assert_true(fabs(r.K[0] - b * p2 / rr) < 1e-10 * b * p2 / rr);
    assert_true(fabs(r.K[1] - b * p3 / rr) < 1e-10 * b * p3 / rr);
    qd_care_result_free(&r);
    qd_statespace_free(&ss);
}

static void test_errors(void **state) {
    qt_system *s = qt_system_derive(state, PENDULUM, false);
    qd_statespace ss;
    assert_int_equal(qd_linearize_about(s->ctx, s->eom, s->model, "th = pi, tua = 1", &ss),
                     QD_ERR_ARG);
    assert_true(qd_ctx_diag(s->ctx)->located && qd_ctx_diag(s->ctx)->offset == 9);
    qd_statespace_free(&ss);
    qd_ctx_clear_error(s->ctx);
    assert_int_equal(qd_linearize_about(s->ctx, s->eom, s->model, "g = 1", &ss), QD_ERR_ARG);
    qd_statespace_free(&ss);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(test_double_integrator, qt_system_teardown),
        cmocka_unit_test_teardown(test_pendulum_upright, qt_system_teardown),
        cmocka_unit_test_teardown(test_errors, qt_system_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
