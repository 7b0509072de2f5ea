/*
 * tests/impulse/test_impulse_before.c - the state just before an impulse
 * (qd_impulse_state_read, `qdot impulse --at`): the model's `initial` as
 * written, exact, overridden by the items given; 0 where neither says.
 *
 * Exactness is what the closed forms need: al = pi/6 kept as pi/6 makes
 * sin(al) = 1/2 exactly (the rod struck at an angle, Byerly ch. III), where
 * 0.5235987755982988 would not simplify.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/impulse.h"
#include "util/check.h"

static const char *ROD = "coordinates al, x\nparameters m = 1, l = 2\n"
                         "T = m/2*x'^2 + m*l^2/6*al'^2\ninitial al = pi/6, x' = l/2\n";

static void before(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qd_model_parse(ctx, ROD, NULL);
    assert_non_null(m);
    const qd_expr *q[2], *qd[2], *t = (const qd_expr *)1;
    assert_int_equal(qd_impulse_state_read(ctx, m, NULL, q, qd, &t), QD_OK);
    qt_assert_is(ctx, qd_fn(ctx, QD_SIN, q[0]), "1/2"); /* exact: pi/6 as written */
    assert_true(qd_is_zero(q[1]) && qd_is_zero(qd[0]));
    qt_assert_is(ctx, qd[1], "l/2");             /* an expression in the parameters */
    assert_null(t);
    assert_int_equal(qd_impulse_state_read(ctx, m, "x = 1/3, al' = 2*pi, t = 1", q, qd, &t),
                     QD_OK);
    qt_assert_is(ctx, q[1], "1/3");
    qt_assert_is(ctx, qd[0], "2*pi");
    qt_assert_is(ctx, qd[1], "l/2");             /* not named: the model's */
    qt_assert_is(ctx, t, "1");
    const char *bad[] = {"l = 3", "al = 1, y = 2"};
    for (size_t k = 0; k < 2; k++) {
        qd_ctx_clear_error(ctx);
        assert_int_not_equal(qd_impulse_state_read(ctx, m, bad[k], q, qd, &t), QD_OK);
        assert_true(qd_ctx_diag(ctx)->located);
        assert_int_equal(qd_ctx_diag(ctx)->offset, strchr(bad[k], k ? 'y' : 'l') - bad[k]);
    }
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(before)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
