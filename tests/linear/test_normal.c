/*
 * tests/linear/test_normal.c - what is read off a modes result
 * (qd_modes_normal_coords, qd_modes_frequencies) and the residual of a
 * point at rest (qd_eom_rest_residual).
 *
 *   the double pendulum, equal masses and lengths (Goldstein ch. 6, seed
 *     002): w^2 = (g/l)(2 -+ sqrt 2); a state built as q0 + 0.3 a_1 with
 *     velocity 0.5 a_2 must have normal coordinates Q = (0.3, 0) and
 *     Q' = (0, 0.5) (the shapes are M0-orthonormal, so a^T M0 inverts them);
 *   two uncoupled damped oscillators (Rayleigh's D, seed 002; Desloge ch. 53
 *     Theorem 2): frequencies sqrt(k/m - (b/2m)^2), ascending although the
 *     eigenvalues come sorted by real part, the faster one first;
 *   the pendulum at th = 0.3: residual m g l sin 0.3; at th = 0 none.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "qdot/qdot.h"
#include "qdot/equilibria.h"
#include "qdot/modes.h"
#include "../util/system.h"

/* syms: q, q', parameters at their values; q at qv. */
static size_t state_at(const qt_system *s, const double *qv, const qd_expr **syms,
                       double *vals) {
    size_t nq = qd_model_ncoords(s->model), np = qd_model_nparams(s->model);
    for (size_t i = 0; i < nq; i++) {
        syms[i] = qd_model_coord(s->model, i);
        vals[i] = qv[i];
        syms[nq + i] = qd_jet(s->ctx, syms[i], 1);
        vals[nq + i] = 0;
    }
    for (size_t i = 0; i < np; i++) {
        syms[2 * nq + i] = qd_model_param(s->model, i);
        assert_int_equal(qd_eval(s->ctx, qd_model_param_value(s->model, i), 0, NULL, NULL,
                                 &vals[2 * nq + i]), QD_OK);
    }
    return 2 * nq + np;
}

static void solve_at(const qt_system *s, const double *q0, qd_linear *lin, qd_modes_result *r) {
    const qd_expr *syms[16];
    double vals[16];
    size_t n = state_at(s, q0, syms, vals);
    assert_int_equal(qd_linear_about(s->ctx, s->eom, s->model, n, syms, vals, lin), QD_OK);
    assert_int_equal(qd_modes_solve(s->ctx, lin, r), QD_OK);
}

static void test_double_pendulum(void **state) {
    qt_system *s = qt_system_derive(state,
        "coordinates theta1, theta2\nparameters m = 1, l = 1, g = 9.81\n"
        "x1 = l*sin(theta1)\ny1 = -l*cos(theta1)\n"
        "x2 = x1 + l*sin(theta2)\ny2 = y1 - l*cos(theta2)\n"
        "T = m/2*(x1'^2 + y1'^2) + m/2*(x2'^2 + y2'^2)\nV = m*g*y1 + m*g*y2\n", false);
    double q0[2] = {0, 0};
    qd_linear lin;
    qd_modes_result r;
    solve_at(s, q0, &lin, &r);
    assert_true(r.conservative);

    double w[4];
    assert_int_equal(qd_modes_frequencies(&r, w), 2);
    assert_true(fabs(w[0] - sqrt(9.81 * (2 - sqrt(2)))) < 1e-9);
    assert_true(fabs(w[1] - sqrt(9.81 * (2 + sqrt(2)))) < 1e-9);

    double q[2], qd[2], Q[2], Qd[2];
    for (size_t i = 0; i < 2; i++) {
        q[i] = q0[i] + 0.3 * r.shapes[i * 2 + 0];
        qd[i] = 0.5 * r.shapes[i * 2 + 1];
    }
    assert_int_equal(qd_modes_normal_coords(&lin, &r, q0, q, qd, Q, Qd), QD_OK);
    assert_true(fabs(Q[0] - 0.3) < 1e-12 && fabs(Q[1]) < 1e-12);
    assert_true(fabs(Qd[0]) < 1e-12 && fabs(Qd[1] - 0.5) < 1e-12);
    qd_linear_free(&lin);
    qd_modes_result_free(&r);
}

static void test_damped_pair(void **state) {
    qt_system *s = qt_system_derive(state,
        "coordinates x, y\nparameters m = 1, k1 = 9, b1 = 0.2, k2 = 1, b2 = 1\n"
        "particle m at (x, y)\nV = k1/2*x^2 + k2/2*y^2\n"
        "dissipation = b1/2*x'^2 + b2/2*y'^2\n", false);
    double q0[2] = {0, 0};
    qd_linear lin;
    qd_modes_result r;
    solve_at(s, q0, &lin, &r);
    assert_false(r.conservative);
    double w[4], q[2] = {0.1, 0}, zero[2] = {0, 0}, Q[2], Qd[2];
    assert_int_equal(qd_modes_frequencies(&r, w), 2);
    assert_true(fabs(w[0] - sqrt(1 - 0.25)) < 1e-9);
    assert_true(fabs(w[1] - sqrt(9 - 0.01)) < 1e-9);
    /* normal coordinates exist only for the conservative case */
    assert_int_equal(qd_modes_normal_coords(&lin, &r, q0, q, zero, Q, Qd), QD_ERR_ARG);
    qd_linear_free(&lin);
    qd_modes_result_free(&r);
}

static void test_residual(void **state) {
    qt_system *s = qt_system_derive(state,
        "coordinates th\nparameters m = 2, l = 0.5, g = 9.81\n"
        "particle m at (l*sin(th), -l*cos(th))\nV = -m*g*l*cos(th)\n", false);
    const qd_expr *syms[8];
    double vals[8], res = -1, th = 0.3;
    size_t n = state_at(s, &th, syms, vals);
    assert_int_equal(qd_eom_rest_residual(s->ctx, s->eom, n, syms, vals, &res), QD_OK);
    assert_true(fabs(res - 2 * 9.81 * 0.5 * sin(0.3)) < 1e-12);
    th = 0;
    n = state_at(s, &th, syms, vals);
    assert_int_equal(qd_eom_rest_residual(s->ctx, s->eom, n, syms, vals, &res), QD_OK);
    assert_true(res == 0);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(test_double_pendulum, qt_system_teardown),
        cmocka_unit_test_teardown(test_damped_pair, qt_system_teardown),
        cmocka_unit_test_teardown(test_residual, qt_system_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
