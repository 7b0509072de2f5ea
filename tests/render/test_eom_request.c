/*
 * tests/render/test_eom_request.c - `qdot eom` as one call
 * (qd_eom_request_render, qdot/render.h), its numbers against Newton:
 *
 *   the pendulum m l^2 theta'' = -m g l sin theta at theta = 0.3: M = m l^2,
 *     f = -m g l sin theta, theta'' = -(g/l) sin theta;
 *   the oscillator in a speed u = x': x' = u and u' = -(k/m) x;
 *   the step that failed: a misspelt name in the state (located in it), a
 *     singular mass matrix (T = (x' + y')^2/2) in the derivation.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "qdot/qdot.h"
#include "../util/jsonwalk.h"

static qd_model *parse(qd_ctx *ctx, const char *text) {
    qd_model *m = qd_model_parse(ctx, text, NULL);
    assert_non_null(m);
    return m;
}

static void test_pendulum_at(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse(ctx, "coordinates theta\nparameters m = 2, l = 0.5, g = 9.81\n"
                             "T = m*l^2*theta'^2/2\nV = -m*g*l*cos(theta)\n");
    qd_eom_request rq = {.fmt = QD_RENDER_JSON, .at = "theta = 0.3"};
    qd_buf b = QD_BUF_INIT, notes = QD_BUF_INIT;
    qd_eom_step step;
    assert_int_equal(qd_eom_request_render(ctx, m, &rq, &b, &notes, &step), QD_OK);
    assert_int_equal(step, QD_EOM_STEP_NONE);
    const char *j = qd_buf_str(&b);
    assert_true(qt_json_valid(j));
    double M = qt_json_num(qt_json_at(qt_json_at(qt_json_get(j, "mass_matrix"), 0), 0));
    double f = qt_json_num(qt_json_at(qt_json_get(j, "forcing"), 0));
    double a = qt_json_num(qt_json_at(qt_json_get(j, "accelerations"), 0));
    assert_true(fabs(M - 2 * 0.25) < 1e-15);
    assert_true(fabs(f + 2 * 9.81 * 0.5 * sin(0.3)) < 1e-14);
    assert_true(fabs(a + 9.81 / 0.5 * sin(0.3)) < 1e-13);
    qd_buf_free(&b);
    qd_buf_free(&notes);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

static void test_speeds_at(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse(ctx, "coordinates x\nparameters m = 2, k = 3\nspeeds u = x'\n"
                             "T = m/2*x'^2\nV = k/2*x^2\n");
    qd_eom_request rq = {.fmt = QD_RENDER_JSON, .at = "x = 0.5, u = 1"};
    qd_buf b = QD_BUF_INIT, notes = QD_BUF_INIT;
    assert_int_equal(qd_eom_request_render(ctx, m, &rq, &b, &notes, NULL), QD_OK);
    const char *j = qd_buf_str(&b);
    assert_true(qt_json_valid(j));
    assert_true(qt_json_num(qt_json_at(qt_json_get(j, "velocities"), 0)) == 1);
    assert_true(fabs(qt_json_num(qt_json_at(qt_json_get(j, "rates"), 0)) + 3.0 / 2 * 0.5) <
                1e-15);
    qd_buf_free(&b);
    qd_buf_free(&notes);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

static void test_steps(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse(ctx, "coordinates theta\nparameters m = 2, l = 0.5, g = 9.81\n"
                             "T = m*l^2*theta'^2/2\nV = -m*g*l*cos(theta)\n");
    qd_eom_request rq = {.fmt = QD_RENDER_TEXT, .at = "thta = 0.3"};
    qd_buf b = QD_BUF_INIT, notes = QD_BUF_INIT;
    qd_eom_step step;
    assert_int_equal(qd_eom_request_render(ctx, m, &rq, &b, &notes, &step), QD_ERR_ARG);
    assert_int_equal(step, QD_EOM_STEP_AT);
    assert_true(qd_ctx_diag(ctx)->located && qd_ctx_diag(ctx)->offset == 0);
    qd_buf_free(&b);
    qd_model_free(m);
    qd_ctx_free(ctx);
    /* T = (x' + y')^2/2: a singular mass matrix, the derivation's error */
    ctx = qd_ctx_new();
    m = parse(ctx, "coordinates x, y\nT = (x' + y')^2/2\nV = x^2\n");
    b = (qd_buf)QD_BUF_INIT;
    rq.at = NULL;
    assert_int_not_equal(qd_eom_request_render(ctx, m, &rq, &b, &notes, &step), QD_OK);
    assert_int_equal(step, QD_EOM_STEP_DERIVE);
    qd_buf_free(&b);
    qd_buf_free(&notes);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pendulum_at),
        cmocka_unit_test(test_speeds_at),
        cmocka_unit_test(test_steps),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
