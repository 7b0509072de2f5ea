/*
 * tests/action/test_action_fault.c - qd_action_at with every allocation
 * made to fail, one at a time (the loop of tests/util/fault.h,
 * SQLite's exprfault.test): each run ends with the right answer or a clean
 * QD_ERR_NOMEM, and every block given back.
 *
 * Bodies and the answers they must give (Desloge ch. 79, seed 004;
 * Goldstein sec. 10.7-10.8, seed 002):
 *   the pendulum at theta0 = 1 from rest: J = 16 m sqrt(g l^3)
 *     [E(k) - (1 - k^2) K(k)], k = sin(1/2) (K, E by the AGM);
 *   Kepler in polar coordinates (through qd_hj_derive): J_r + J_theta =
 *     2 pi k sqrt(m / (-2 E)).
 * The model is parsed with the failures off, so the loops fail the
 * allocations of the derivation, the separation and the quadratures.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "qdot/action.h"
#include "qdot/qdot.h"
#include "util/fault.h"

#define PI 3.14159265358979323846

/* A model and the state: every parameter at its value, then the extra
 * coordinates and velocities. */
typedef struct body {
    const char *text;
    size_t nset;
    const char *names[8];
    double vals[8];
    double (*answer)(const qd_action *a);
} body;

static double pendulum_answer(const qd_action *a) {
    double k = sin(0.5), x = 1, y = sqrt(1 - k * k), c = k, s = c * c / 2, pw = 0.5;
    for (int i = 0; i < 40 && c > 1e-17; i++) {
        double xn = (x + y) / 2;
        c = (x - y) / 2;
        y = sqrt(x * y);
        x = xn;
        pw *= 2;
        s += pw * c * c;
    }
    double K = PI / (2 * x), E = K * (1 - s);
    return a->c[0].J - 16 * sqrt(9.81 * 8) * (E - (1 - k * k) * K);
}

static double kepler_answer(const qd_action *a) {
    return a->c[0].J + a->c[1].J - 2 * PI * 4 * sqrt(1.3 / (-2 * a->energy));
}

static qd_status run_body(qd_ctx *ctx, qt_faulty *f, void *data) {
    const body *b = data;
    long to_go = qt_fault_hold(f); /* the parse is not what this loop fails */
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, b->text, &d);
    if (!m)
        fail_msg("parse: %s", d.message);
    const qd_expr *syms[16];
    double vals[16];
    size_t n = 0;
    for (size_t i = 0; i < qd_model_nparams(m); i++) {
        syms[n] = qd_model_param(m, i);
        qd_eval(ctx, qd_model_param_value(m, i), 0, NULL, NULL, &vals[n++]);
    }
    for (size_t i = 0; i < b->nset; i++) {
        syms[n] = qd_read(ctx, b->names[i], NULL, NULL);
        vals[n++] = b->vals[i];
    }
    qt_fault_release(f, to_go);
    qd_action a;
    qd_status st = qd_action_at(ctx, m, n, syms, vals, NULL, &a);
    qt_fault_hold(f); /* only qd_action_at is failed */
    if (st == QD_OK && !(fabs(b->answer(&a)) < 1e-10))
        fail_msg("wrong answer after %ld allocations: off by %g", f->count, b->answer(&a));
    qd_action_free(&a);
    qd_model_free(m);
    return st;
}

static void test_pendulum_fault(void **state) {
    (void)state;
    body b = {"coordinates th\nparameters m = 1, l = 2, g = 9.81\n"
              "particle m at (l*sin(th), -l*cos(th))\nV = -m*g*l*cos(th)\n",
              2, {"th", "th'"}, {1, 0}, pendulum_answer};
    /* beyond the context's own few allocations: qd_action_at was failed */
    assert_true(qt_fault_loop("pendulum action", run_body, &b, 1).runs > 20);
}

static void test_kepler_fault(void **state) {
    (void)state;
    body b = {"coordinates r, theta\nparameters m = 1.3, k = 4\n"
              "particle m at r*(cos(theta), sin(theta))\nV = -k/r\n",
              4, {"r", "theta", "r'", "theta'"}, {1, 0.3, 0.4, 1.5}, kepler_answer};
    /* beyond the context's own few allocations: qd_action_at was failed */
    assert_true(qt_fault_loop("Kepler action", run_body, &b, 7).runs > 20);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pendulum_fault),
        cmocka_unit_test(test_kepler_fault),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
