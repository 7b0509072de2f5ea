/*
 * tests/speeds/test_speeds_fault.c - the equations in speeds with every
 * allocation made to fail, one at a time (the loop of tests/util/fault.h).
 *
 * Body: the Chaplygin sleigh as a rigid body (the blade b ahead of the
 * centre of mass; tests/speeds/test_speeds.c derives its equations
 * m v' = -m b w^2, (I + m b^2) w' = m b v w), by each method with S and the
 * multiplier, then evaluated.  Each run must end with those rates and the
 * blade's force m (v w - b w') or a clean QD_ERR_NOMEM recorded in the
 * context, with every block given back.  (A small model: each run derives
 * it again.)
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "qdot/qdot.h"
#include "util/fault.h"

static const char sleigh[] =
    "coordinates x, y, th\n"
    "parameters m = 2, I = 0.3, b = 0.4\n"
    "body s mass m inertia (I, I, I) at (x, y, 0) orientation rot_z(th)\n"
    "constraint blade: -x'*sin(th) + y'*cos(th) + b*th' = 0\n"
    "speeds v = x'*cos(th) + y'*sin(th), w = th'\n";

static qd_status body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)f;
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, sleigh, &d);
    qd_speeds_opts o = {.method = *(qd_speeds_method *)data, .appell = true, .multipliers = true};
    qd_speeds_eom *e = m ? qd_speeds_derive(ctx, m, &o) : NULL;
    qd_status st = qd_ctx_status(ctx);
    if (e) {
        const qd_expr *syms[] = {qd_model_param(m, 0), qd_model_param(m, 1), qd_model_param(m, 2),
                                 qd_lookup(ctx, "th"), e->u[0], e->u[1]};
        double mm = 2, I = 0.3, b = 0.4, v = 0.7, w = -1.3;
        double vals[] = {mm, I, b, 0.6, v, w};
        double ud[2], lam[1];
        st = qd_speeds_eval(ctx, e, 6, syms, vals, NULL, ud, lam);
        if (st == QD_OK) {
            assert_non_null(e->S);
            assert_true(fabs(ud[0] + b * w * w) < 1e-13);
            assert_true(fabs(ud[1] - mm * b * v * w / (I + mm * b * b)) < 1e-13);
            assert_true(fabs(lam[0] - mm * (v * w - b * ud[1])) < 1e-13);
        }
    }
    qd_speeds_eom_free(e);
    qd_model_free(m);
    return st;
}

static void test_speeds_fault(void **state) {
    (void)state;
    static const char *names[] = {"speeds, Kane", "speeds, Appell", "speeds, Hamel"};
    for (int k = 0; k < QD_SPEEDS_METHOD_COUNT; k++) {
        qd_speeds_method method = (qd_speeds_method)k;
        assert_true(qt_fault_loop(names[k], body, &method, 7).runs > 10);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_speeds_fault)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
