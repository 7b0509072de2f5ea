/*
 * tests/linear/test_constrained.c - the reduction onto the manifold of
 * holonomic constraints kept with multipliers (qdot/constrained.h).
 *
 *   the pendulum x^2 + y^2 = l^2 under V = m g y: equilibria (0, -l) a
 *     minimum and (0, l) a maximum; at the bottom lambda = -m g/(2 l)
 *     (M q'' = f + A^T lambda: 0 = -m g + lambda (-2 l)), x independent,
 *     T = (1, 0), M_r = m, K_r = -lambda Hess phi = m g/l (V is linear: the
 *     whole stiffness is the multiplier's second-order term), and
 *     A = [0 1; -g/l 0]; the same as the pendulum in its angle;
 *   y named independent at the bottom is refused (A_D = 2x = 0 there);
 *   off the vertical (x = 0.5) the point is no equilibrium: refused;
 *   the spherical pendulum on x^2 + y^2 + z^2 = l^2: K_r = (m g/l) I,
 *     M_r = m I over (x, y) at the bottom;
 *   a constraint with velocities is QD_ERR_UNSUPPORTED.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "qdot/qdot.h"
#include "qdot/constrained.h"
#include "../util/system.h"

typedef struct point {
    size_t n;
    const qd_expr *syms[40];
    double vals[40];
} point;

/* q (ncoords values), q' = 0, t = 0, parameters at their values. */
static void state_at(const qt_system *s, const double *q, point *p) {
    size_t nq = qd_model_ncoords(s->model), np = qd_model_nparams(s->model);
    assert_true(2 * nq + 1 + np <= 40);
    for (size_t i = 0; i < nq; i++) {
        p->syms[i] = qd_model_coord(s->model, i);
        p->syms[nq + i] = qd_jet(s->ctx, qd_model_coord(s->model, i), 1);
        p->vals[i] = q ? q[i] : 0;
        p->vals[nq + i] = 0;
    }
    p->syms[2 * nq] = qd_time(s->ctx);
    p->vals[2 * nq] = 0;
    for (size_t i = 0; i < np; i++) {
        p->syms[2 * nq + 1 + i] = qd_model_param(s->model, i);
        assert_int_equal(qd_eval(s->ctx, qd_model_param_value(s->model, i), 0, NULL, NULL,
                                 &p->vals[2 * nq + 1 + i]), QD_OK);
    }
    p->n = 2 * nq + 1 + np;
}

static const char pendulum[] = "parameters m = 1.5, g = 9.81, l = 2\ncoordinates x, y\n"
                               "T = m/2*(x'^2 + y'^2)\nV = m*g*y\n"
                               "constraint rod: x^2 + y^2 = l^2\n";

static void test_pendulum_equilibria(void **state) {
    qt_system *s = qt_system_derive(state, pendulum, false);
    assert_int_equal(s->eom->ncon, 1);
    point p;
    state_at(s, NULL, &p);
    qd_equilibria eq;
    assert_int_equal(qd_equilibria_find(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, NULL, &eq),
                     QD_OK);
    assert_int_equal(eq.count, 2);
    assert_true(fabs(eq.pts[0].q[0]) < 1e-12 && fabs(eq.pts[0].q[1] + 2) < 1e-12);
    assert_int_equal(eq.pts[0].kind, QD_EQ_MINIMUM);
    assert_true(fabs(eq.pts[1].q[0]) < 1e-12 && fabs(eq.pts[1].q[1] - 2) < 1e-12);
    assert_int_equal(eq.pts[1].kind, QD_EQ_MAXIMUM);
    qd_equilibria_free(&eq);
}

static void test_pendulum_reduction(void **state) {
    qt_system *s = qt_system_derive(state, pendulum, false);
    const double m = 1.5, g = 9.81, l = 2, q[2] = {0, -1.9};
    point p;
    state_at(s, q, &p);
    qd_constrained_linear c;
    assert_int_equal(qd_constrained_linear_about(s->ctx, s->eom, p.n, p.syms, p.vals, NULL, &c),
                     QD_OK);
    assert_int_equal(c.r, 1);
    assert_int_equal(c.indep[0], 0);
    assert_int_equal(c.dep[0], 1);
    assert_true(fabs(c.q[1] + l) < 1e-14); /* y solved onto the circle */
    assert_true(fabs(c.lambda[0] + m * g / (2 * l)) < 1e-12);
    assert_true(fabs(c.T[0] - 1) < 1e-15 && fabs(c.T[1]) < 1e-15);
    assert_true(fabs(c.lin.M[0] - m) < 1e-12);
    assert_true(fabs(c.lin.K[0] - m * g / l) < 1e-12);
    double A[4];
    assert_int_equal(qd_constrained_state_matrix(s->ctx, &c, A), QD_OK);
    assert_true(A[0] == 0 && A[1] == 1 && fabs(A[2] + g / l) < 1e-12 && A[3] == 0);
    qd_modes_result r;
    assert_int_equal(qd_modes_solve(s->ctx, &c.lin, &r), QD_OK);
    assert_true(fabs(r.omega2[0] - g / l) < 1e-12 && r.stable == 1);
    qd_modes_result_free(&r);
    qd_constrained_linear_free(&c);
}

static void test_pendulum_refusals(void **state) {
    qt_system *s = qt_system_derive(state, pendulum, false);
    const double bottom[2] = {0, -2}, off[2] = {0.5, -1.9};
    const size_t y[1] = {1};
    point p;
    qd_constrained_linear c;
    state_at(s, bottom, &p);
    assert_int_equal(qd_constrained_linear_about(s->ctx, s->eom, p.n, p.syms, p.vals, y, &c),
                     QD_ERR_ARG);
    qd_constrained_linear_free(&c);
    qd_ctx_clear_error(s->ctx);
    state_at(s, off, &p);
    assert_int_equal(qd_constrained_linear_about(s->ctx, s->eom, p.n, p.syms, p.vals, NULL, &c),
                     QD_ERR_ARG);
    qd_constrained_linear_free(&c);
}

static void test_sphere(void **state) {
    qt_system *s = qt_system_derive(state,
                                    "parameters m = 0.8, g = 9.81, l = 2\ncoordinates x, y, z\n"
                                    "T = m/2*(x'^2 + y'^2 + z'^2)\nV = m*g*z\n"
                                    "constraint sphere: x^2 + y^2 + z^2 = l^2\n",
                                    false);
    const double q[3] = {0, 0, -2};
    point p;
    state_at(s, q, &p);
    qd_constrained_linear c;
    assert_int_equal(qd_constrained_linear_about(s->ctx, s->eom, p.n, p.syms, p.vals, NULL, &c),
                     QD_OK);
    assert_int_equal(c.r, 2);
    assert_int_equal(c.dep[0], 2);
    for (size_t a = 0; a < 2; a++)
        for (size_t b = 0; b < 2; b++) {
            assert_true(fabs(c.lin.M[a * 2 + b] - (a == b ? 0.8 : 0)) < 1e-12);
            assert_true(fabs(c.lin.K[a * 2 + b] - (a == b ? 0.8 * 9.81 / 2 : 0)) < 1e-12);
        }
    qd_constrained_linear_free(&c);
}

static void test_velocity_constraint(void **state) {
    qt_system *s = qt_system_derive(state,
                                    "coordinates x, y, th\nT = (x'^2 + y'^2 + th'^2)/2\n"
                                    "constraint blade: -sin(th)*x' + cos(th)*y' = 0\n",
                                    false);
    point p;
    state_at(s, NULL, &p);
    qd_constrained_linear c;
    assert_int_equal(qd_constrained_linear_about(s->ctx, s->eom, p.n, p.syms, p.vals, NULL, &c),
                     QD_ERR_UNSUPPORTED);
    qd_constrained_linear_free(&c);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(test_pendulum_equilibria, qt_system_teardown),
        cmocka_unit_test_teardown(test_pendulum_reduction, qt_system_teardown),
        cmocka_unit_test_teardown(test_pendulum_refusals, qt_system_teardown),
        cmocka_unit_test_teardown(test_sphere, qt_system_teardown),
        cmocka_unit_test_teardown(test_velocity_constraint, qt_system_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
