/*
 * tests/model/test_coord_unit.c - a coordinate's unit from the model's
 * geometry (qd_model_coord_unit, qdot/model.h): an angle is a coordinate
 * the particles' positions and V repeat in with period 2 pi.
 *
 *   the spring pendulum (Goldstein's elastic pendulum; examples/
 *     spring_pendulum.qd): r is a length, theta an angle;
 *   the double pendulum given by T and V alone (no particles): V's
 *     -cos theta_i make both angles;
 *   the cart-pendulum: x a length, th an angle;
 *   a coordinate out of range: NULL; a run's columns: t in s, an angle's
 *   velocity in rad/s, energy unknown.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <string.h>

#include "qdot/qdot.h"
#include "qdot/model.h"
#include "../util/system.h"

static void test_spring_pendulum(void **state) {
    qt_system *s = qt_system_parse(state, "coordinates r, theta\n"
                                          "parameters m = 0.4, k = 12, l0 = 1, g = 9.81\n"
                                          "rb = r*(sin(theta), -cos(theta))\nparticle m at rb\n"
                                          "V = m*g*rb.y + k/2*(r - l0)^2\n");
    assert_null(qd_model_coord_unit(s->ctx, s->model, 0));
    assert_string_equal(qd_model_coord_unit(s->ctx, s->model, 1), "rad");
    assert_null(qd_model_coord_unit(s->ctx, s->model, 2));
    /* a run's columns: t in s, theta in rad, its velocity in rad/s */
    assert_string_equal(qd_model_column_unit(s->ctx, s->model, "t"), "s");
    assert_string_equal(qd_model_column_unit(s->ctx, s->model, "theta"), "rad");
    assert_string_equal(qd_model_column_unit(s->ctx, s->model, "theta'"), "rad/s");
    assert_null(qd_model_column_unit(s->ctx, s->model, "r'"));
    assert_null(qd_model_column_unit(s->ctx, s->model, "energy"));
}

static void test_given_by_t_and_v(void **state) {
    qt_system *s = qt_system_parse(state, "coordinates theta1, theta2\n"
                                          "parameters m = 1, l = 1, g = 9.81\n"
                                          "T = m*l^2/2*(2*theta1'^2 + theta2'^2 + "
                                          "2*theta1'*theta2'*cos(theta1 - theta2))\n"
                                          "V = -m*g*l*(2*cos(theta1) + cos(theta2))\n");
    assert_string_equal(qd_model_coord_unit(s->ctx, s->model, 0), "rad");
    assert_string_equal(qd_model_coord_unit(s->ctx, s->model, 1), "rad");
}

static void test_cart(void **state) {
    qt_system *s = qt_system_parse(state, "coordinates x, th\nparameters M = 1, m = 0.2, "
                                          "l = 0.5, g = 9.81\nparticle M at (x, 0)\n"
                                          "particle m at (x + l*sin(th), l*cos(th))\n"
                                          "V = m*g*l*cos(th)\n");
    assert_null(qd_model_coord_unit(s->ctx, s->model, 0));
    assert_string_equal(qd_model_coord_unit(s->ctx, s->model, 1), "rad");
    assert_int_equal(qd_ctx_status(s->ctx), QD_OK);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(test_spring_pendulum, qt_system_teardown),
        cmocka_unit_test_teardown(test_given_by_t_and_v, qt_system_teardown),
        cmocka_unit_test_teardown(test_cart, qt_system_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
