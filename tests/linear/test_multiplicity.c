/*
 * tests/linear/test_multiplicity.c - repeated normal-mode frequencies
 * (qd_modes_multiplicity).
 *
 *   three equal masses in a ring of three springs, free in the plane
 *     (Desloge ch. 66 example, seed-desloge-D.md T33): w^2 = 0 three times
 *     (two translations, one rotation), 3k/2m twice, 3k/m once;
 *   a particle in an isotropic 3-d well with a pendulum hung from it
 *     decoupled: w^2 = k/m three times and g/l once; the shapes of the
 *     triple are one M-orthonormal basis of R^3 (any rotation of it is as
 *     good: only the span is asserted);
 *   the double pendulum (Goldstein ch. 6): two distinct w^2, each once.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include "qdot/qdot.h"
#include "qdot/modes.h"
#include "../util/system.h"

static void modes_at(const qt_system *s, const double *q, qd_linear *lin, qd_modes_result *r) {
    size_t nq = qd_model_ncoords(s->model), np = qd_model_nparams(s->model);
    const qd_expr *syms[32];
    double vals[32];
    for (size_t i = 0; i < nq; i++) {
        syms[i] = qd_model_coord(s->model, i);
        vals[i] = q ? q[i] : 0;
    }
    for (size_t i = 0; i < np; i++) {
        syms[nq + i] = qd_model_param(s->model, i);
        assert_int_equal(qd_eval(s->ctx, qd_model_param_value(s->model, i), 0, NULL, NULL,
                                 &vals[nq + i]), QD_OK);
    }
    assert_int_equal(qd_linear_about(s->ctx, s->eom, s->model, nq + np, syms, vals, lin), QD_OK);
    assert_int_equal(qd_modes_solve(s->ctx, lin, r), QD_OK);
    assert_true(r->conservative);
}

static void test_ring(void **state) {
    qt_system *s = qt_system_derive(state,
        "coordinates x1, y1, x2, y2, x3, y3\nparameters m = 2, k = 5, a = 1\n"
        "d12 = sqrt((x1 - x2)^2 + (y1 - y2)^2)\nd23 = sqrt((x2 - x3)^2 + (y2 - y3)^2)\n"
        "d31 = sqrt((x3 - x1)^2 + (y3 - y1)^2)\n"
        "particle m at (x1, y1)\nparticle m at (x2, y2)\nparticle m at (x3, y3)\n"
        "V = k/2*((d12 - a)^2 + (d23 - a)^2 + (d31 - a)^2)\n", false);
    double q[6] = {0, 0, 1, 0, 0.5, sqrt(3) / 2};
    qd_linear lin;
    qd_modes_result r;
    modes_at(s, q, &lin, &r);
    size_t want[6] = {3, 3, 3, 2, 2, 1};
    for (size_t j = 0; j < 6; j++)
        assert_int_equal(qd_modes_multiplicity(&r, j), want[j]);
    assert_int_equal(qd_modes_multiplicity(&r, 6), 0);
    qd_linear_free(&lin);
    qd_modes_result_free(&r);
}

static void test_isotropic(void **state) {
    qt_system *s = qt_system_derive(state,
        "coordinates x, y, z, th\nparameters m = 1.5, k = 6, g = 9.81, l = 2\n"
        "particle m at (x, y, z)\nparticle 1 at l*(sin(th), -cos(th), 0)\n"
        "V = k/2*(x^2 + y^2 + z^2) - g*l*cos(th)\n", false);
    qd_linear lin;
    qd_modes_result r;
    modes_at(s, NULL, &lin, &r);
    /* k/m = 4 three times, g/l = 4.905 once */
    for (size_t j = 0; j < 3; j++) {
        assert_true(fabs(r.omega2[j] - 4) < 1e-12);
        assert_int_equal(qd_modes_multiplicity(&r, j), 3);
    }
    assert_true(fabs(r.omega2[3] - 9.81 / 2) < 1e-12);
    assert_int_equal(qd_modes_multiplicity(&r, 3), 1);
    /* the triple's shapes span (x, y, z): M-orthonormal, m a.a = 1, no th */
    for (size_t j = 0; j < 3; j++) {
        assert_true(fabs(r.shapes[3 * 4 + j]) < 1e-12);
        for (size_t k = 0; k < 3; k++) {
            double dot = 0;
            for (size_t i = 0; i < 3; i++)
                dot += 1.5 * r.shapes[i * 4 + j] * r.shapes[i * 4 + k];
            assert_true(fabs(dot - (j == k)) < 1e-12);
        }
    }
    qd_linear_free(&lin);
    qd_modes_result_free(&r);
}

static void test_distinct(void **state) {
    qt_system *s = qt_system_derive(state,
        "coordinates theta1, theta2\nparameters m = 1, l = 1, g = 9.81\n"
        "x1 = l*sin(theta1)\ny1 = -l*cos(theta1)\n"
        "x2 = x1 + l*sin(theta2)\ny2 = y1 - l*cos(theta2)\n"
        "T = m/2*(x1'^2 + y1'^2) + m/2*(x2'^2 + y2'^2)\nV = m*g*y1 + m*g*y2\n", false);
    qd_linear lin;
    qd_modes_result r;
    modes_at(s, NULL, &lin, &r);
    assert_int_equal(qd_modes_multiplicity(&r, 0), 1);
    assert_int_equal(qd_modes_multiplicity(&r, 1), 1);
    qd_linear_free(&lin);
    qd_modes_result_free(&r);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(test_ring, qt_system_teardown),
        cmocka_unit_test_teardown(test_isotropic, qt_system_teardown),
        cmocka_unit_test_teardown(test_distinct, qt_system_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
