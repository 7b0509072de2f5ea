/*
 * tests/linear/test_linpoint.c - the point of a linear analysis read from
 * text (qdot/linpoint.h) and the analyses `qdot modes` and `linearize` take
 * from it (qd_modes_at_choose, qd_modes_at_initial, qd_constrained_at_solve),
 * against textbook results:
 *
 *   double pendulum, equal masses and lengths: w^2 = (g/l)(2 -+ sqrt 2),
 *     theta2/theta1 = +-sqrt 2 (Goldstein ch. 6 / seed 002; reference
 *     seed-goldstein-britannica.md, det(C - w^2 A) = 0), chosen about
 *     theta = 0 without a point; a start along the slow mode's shape excites
 *     that mode alone (its normal coordinate, the other 0);
 *   two masses tied by y = x on springs k: eliminated to one coordinate of
 *     mass 2m and stiffness 2k, w^2 = k/m; the eliminated one is refused;
 *   its equilibria from --near and --box text (qd_equilibria_find_text):
 *     sin theta1 = sin theta2 = 0, the points Newton and a box reach;
 *   the pendulum x^2 + y^2 = l^2 kept with a multiplier: on the manifold
 *     w^2 = g/l and A = [0 1; -g/l 0] (qdot/constrained.h; Desloge ch. 65).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "qdot/qdot.h"
#include "../util/system.h"

static const double PI = 3.14159265358979323846;

static const char double_pendulum[] =
    "coordinates theta1, theta2\nparameters m = 1, l = 1, g = 9.81\n"
    "x1 = l*sin(theta1)\ny1 = -l*cos(theta1)\nx2 = x1 + l*sin(theta2)\ny2 = y1 - l*cos(theta2)\n"
    "T = m/2*(x1'^2 + y1'^2) + m/2*(x2'^2 + y2'^2)\nV = m*g*y1 + m*g*y2\n";

static void test_double_pendulum(void **state) {
    qt_system *s = qt_system_derive(state, double_pendulum, true);
    const double g = 9.81, r2 = sqrt(2.0);
    qd_linpoint p;
    assert_int_equal(qd_linpoint_init(s->ctx, s->model, s->eom, &p), QD_OK);
    qd_modes_at at;
    assert_int_equal(qd_modes_at_choose(s->ctx, &p, NULL, 0, &at), QD_OK);
    assert_true(at.chosen && fabs(at.q0[0]) < 1e-12 && fabs(at.q0[1]) < 1e-12);
    qd_linpoint_set(&p, at.q0, NULL);
    assert_int_equal(qd_modes_at_solve(s->ctx, s->eom, s->model, p.st.n, p.st.syms, p.st.vals,
                                       &at), QD_OK);
    assert_true(at.res.conservative && at.res.stable == 1);
    assert_true(fabs(at.res.omega2[0] - g * (2 - r2)) < 1e-10);
    assert_true(fabs(at.res.omega2[1] - g * (2 + r2)) < 1e-10);
    /* the slow mode: theta2 = sqrt 2 theta1 */
    double Q[2], Qd[2];
    assert_int_equal(qd_modes_at_initial(s->ctx, &p, &at, "theta1 = 0.01, theta2 = 0.01*sqrt(2)",
                                         Q, Qd), QD_OK);
    assert_true(fabs(Q[0]) > 1e-3 && fabs(Q[1]) < 1e-12 && Qd[0] == 0 && Qd[1] == 0);
    /* a velocity given: Q' along the same mode */
    assert_int_equal(qd_modes_at_initial(s->ctx, &p, &at, "theta1' = 1, theta2' = -sqrt(2)", Q,
                                         Qd), QD_OK);
    assert_true(fabs(Q[0]) < 1e-15 && fabs(Q[1]) < 1e-15 && fabs(Qd[0]) < 1e-12 &&
                fabs(Qd[1]) > 0.1);
    qd_modes_at_free(&at);
    /* a point given: about the inverted position, unstable */
    assert_int_equal(qd_modes_at_choose(s->ctx, &p, "theta1 = pi, theta2 = pi", 0, &at), QD_OK);
    assert_true(!at.chosen && fabs(at.q0[0] - PI) < 1e-15 && fabs(at.q0[1] - PI) < 1e-15);
    qd_modes_at_free(&at);
    /* a misspelt name is located in the text */
    assert_int_equal(qd_modes_at_choose(s->ctx, &p, "theta1 = 0, thta2 = 1", 0, &at), QD_ERR_ARG);
    assert_true(qd_ctx_diag(s->ctx)->located && qd_ctx_diag(s->ctx)->offset == 12);
    qd_modes_at_free(&at);
    qd_linpoint_free(&p);
}

/* --near and --box of `qdot equilibria` (qd_equilibria_find_text): V =
 * -m g l (2 cos theta1 + cos theta2), so sin theta1 = sin theta2 = 0, the
 * four points (0 or pi, 0 or pi); Newton from near (3, 0.2) reaches (pi, 0);
 * the box theta1 in [-1, 1], theta2 in [2, 4] holds (0, pi) alone. */
static void test_equilibria_text(void **state) {
    qt_system *s = qt_system_derive(state, double_pendulum, true);
    qd_linpoint p;
    assert_int_equal(qd_linpoint_init(s->ctx, s->model, s->eom, &p), QD_OK);
    qd_equilibria eq;
    const char *bad = "unset";
    assert_int_equal(qd_equilibria_find_text(s->ctx, &p, NULL, NULL, &eq, &bad), QD_OK);
    assert_true(bad == NULL && eq.count == 4 && eq.exact);
    qd_equilibria_free(&eq);
    assert_int_equal(qd_equilibria_find_text(s->ctx, &p, "theta1 = 3, theta2 = 0.2", NULL, &eq,
                                             &bad), QD_OK);
    assert_string_equal(eq.method, "newton");
    assert_true(eq.count == 1 && fabs(eq.pts[0].q[0] - PI) < 1e-12 &&
                fabs(eq.pts[0].q[1]) < 1e-12);
    qd_equilibria_free(&eq);
    const char *box = "theta1 = -1:1, theta2 = 2:4";
    assert_int_equal(qd_equilibria_find_text(s->ctx, &p, NULL, box, &eq, &bad), QD_OK);
    assert_string_equal(eq.method, "multistart");
    assert_true(eq.count == 1 && fabs(eq.pts[0].q[0]) < 1e-12 &&
                fabs(eq.pts[0].q[1] - PI) < 1e-12);
    qd_equilibria_free(&eq);
    /* mistakes are the readers', located in their own text */
    const char *near = "thta1 = 1";
    assert_int_equal(qd_equilibria_find_text(s->ctx, &p, near, NULL, &eq, &bad), QD_ERR_ARG);
    assert_true(bad == near && qd_ctx_diag(s->ctx)->located && qd_ctx_diag(s->ctx)->offset == 0);
    qd_ctx_clear_error(s->ctx);
    box = "theta1 = 1:0";
    assert_int_equal(qd_equilibria_find_text(s->ctx, &p, NULL, box, &eq, &bad), QD_ERR_ARG);
    assert_true(bad == box && eq.count == 0);
    qd_ctx_clear_error(s->ctx);
    qd_linpoint_free(&p);
}

static void test_readers(void **state) {
    qt_system *s = qt_system_derive(state, double_pendulum, true);
    qd_linpoint p;
    assert_int_equal(qd_linpoint_init(s->ctx, s->model, s->eom, &p), QD_OK);
    double lo[2] = {-5, -5}, hi[2] = {5, 5};
    assert_int_equal(qd_linpoint_read_box(s->ctx, &p, "theta2 = -pi/2:pi", lo, hi), QD_OK);
    assert_true(lo[0] == -5 && hi[0] == 5 && fabs(lo[1] + PI / 2) < 1e-15 &&
                fabs(hi[1] - PI) < 1e-15);
    const qd_expr *about[2];
    assert_int_equal(qd_linpoint_read_exact(s->ctx, &p, "theta1 = pi/6", about), QD_OK);
    double v;
    assert_int_equal(qd_eval(s->ctx, about[0], 0, NULL, NULL, &v), QD_OK);
    assert_true(fabs(v - PI / 6) < 1e-15);
    assert_int_equal(qd_eval(s->ctx, about[1], 0, NULL, NULL, &v), QD_OK);
    assert_true(v == 0);
    /* a point at rest takes no velocity, and no parameter */
    double q[2];
    assert_int_equal(qd_linpoint_read_coords(s->ctx, &p, "theta1' = 1", q), QD_ERR_ARG);
    assert_int_equal(qd_linpoint_read_coords(s->ctx, &p, "g = 1", q), QD_ERR_ARG);
    qd_linpoint_free(&p);
}

static const char tied[] = "coordinates x, y\nparameters m = 2, k = 5\n"
                           "T = m/2*(x'^2 + y'^2)\nV = k/2*(x^2 + y^2)\nconstraint c: y = x\n";

static void test_eliminated(void **state) {
    qt_system *s = qt_system_derive(state, tied, true);
    assert_int_equal(s->eom->n, 1);
    qd_linpoint p;
    assert_int_equal(qd_linpoint_init(s->ctx, s->model, s->eom, &p), QD_OK);
    const char *kept = qd_expr_name(s->eom->q[0]);
    char text[64];
    snprintf(text, sizeof text, "%s = 0.5", strcmp(kept, "x") ? "x" : "y");
    double q[1] = {0};
    assert_int_equal(qd_linpoint_read_coords(s->ctx, &p, text, q), QD_ERR_ARG);
    assert_true(qd_ctx_diag(s->ctx)->located);
    qd_ctx_clear_error(s->ctx);
    snprintf(text, sizeof text, "%s = 0.5", kept);
    assert_int_equal(qd_linpoint_read_coords(s->ctx, &p, text, q), QD_OK);
    assert_true(q[0] == 0.5);
    qd_modes_at at;
    assert_int_equal(qd_modes_at_choose(s->ctx, &p, NULL, 0, &at), QD_OK);
    qd_linpoint_set(&p, at.q0, NULL);
    assert_int_equal(qd_modes_at_solve(s->ctx, s->eom, s->model, p.st.n, p.st.syms, p.st.vals,
                                       &at), QD_OK);
    assert_true(fabs(at.res.omega2[0] - 5.0 / 2) < 1e-12); /* 2k / 2m */
    qd_modes_at_free(&at);
    qd_linpoint_free(&p);
}

static const char pendulum[] = "parameters m = 1.5, g = 9.81, l = 2\ncoordinates x, y\n"
                               "T = m/2*(x'^2 + y'^2)\nV = m*g*y\n"
                               "constraint rod: x^2 + y^2 = l^2\n";

static void test_constrained_at(void **state) {
    qt_system *s = qt_system_derive(state, pendulum, false);
    const double g = 9.81, l = 2;
    qd_linpoint p;
    assert_int_equal(qd_linpoint_init(s->ctx, s->model, s->eom, &p), QD_OK);
    const double q0[2] = {0, -1.9}; /* put onto the circle by the reduction */
    qd_linpoint_set(&p, q0, NULL);
    qd_constrained_at at;
    assert_int_equal(qd_constrained_at_solve(s->ctx, s->eom, s->model, p.st.n, p.st.syms,
                                             p.st.vals, NULL, true, &at), QD_OK);
    assert_true(fabs(at.res.omega2[0] - g / l) < 1e-12 && at.res.stable == 1);
    assert_true(at.nu == 0 && at.A[0] == 0 && at.A[1] == 1 && fabs(at.A[2] + g / l) < 1e-12 &&
                at.A[3] == 0);
    qd_constrained_at_free(&at);
    /* a point off the equilibria is refused by the reduction */
    const double q1[2] = {1, -1.7};
    qd_linpoint_set(&p, q1, NULL);
    assert_int_equal(qd_constrained_at_solve(s->ctx, s->eom, s->model, p.st.n, p.st.syms,
                                             p.st.vals, NULL, false, &at), QD_ERR_ARG);
    qd_constrained_at_free(&at);
    qd_linpoint_free(&p);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(test_double_pendulum, qt_system_teardown),
        cmocka_unit_test_teardown(test_readers, qt_system_teardown),
        cmocka_unit_test_teardown(test_equilibria_text, qt_system_teardown),
        cmocka_unit_test_teardown(test_eliminated, qt_system_teardown),
        cmocka_unit_test_teardown(test_constrained_at, qt_system_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
