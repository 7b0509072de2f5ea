/*
 * tests/linear/test_choose.c - the equilibrium chosen when none is named
 * (qd_equilibria_choose), and exact w^2 in or at the parameters
 * (qd_equilibrium_exact_in_parameters, qd_modes_exact_omega2).
 *
 * Each model is built so that a wrong rule picks a different point:
 *   the spring triangle (three equal masses, Desloge ch. 66 example,
 *     seed-desloge-D.md T33) started nearly equilateral: the equilateral
 *     triangle (sides a; w^2 = 0 x3, 3k/2m x2, 3k/m), not the first listed,
 *     a collinear saddle; without `initial` the same by lowest V;
 *   a pendulum started near th = pi: Newton goes to the top (a maximum), the
 *     choice is the bottom th = 0; an inverted one (V = +m g l cos th)
 *     started near 0: th = pi, though 0 is listed first;
 *   a tilted double well V = (x^2 - 1)^2 - x/10: the right well has the
 *     lower V (chosen without `initial`), the left one is nearer x = -0.5;
 *   an inverted oscillator V = -k x^2/2: no minimum, Newton's point or the
 *     first listed; a constant force: no equilibrium at all;
 *   V = -k cos 2 th started at th = -3: th = pi, nearer modulo 2 pi than 0;
 *   the bead on a hoop spinning at omega (Desloge ch. 50 Ex. 1 eq. 39):
 *     th = 0 holds for every g, a, omega and w^2 = g/a - omega^2 there; the
 *     off-axis point cos th0 = g/(a omega^2) is computed at the values, so
 *     w^2 = omega^2 sin^2 th0 comes out as a number;
 *   a chain of four springs k from a wall, masses m between them and a
 *     force P pulling the last one: affine equations (method "linear": one
 *     solve, no search), the one equilibrium x_j = j P/k, and the
 *     fixed-free chain's w_j = 2 sqrt(k/m) sin((2j - 1) pi / (2 (2N + 1))).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>

#include "qdot/qdot.h"
#include "qdot/equilibria.h"
#include "qdot/modes.h"
#include "../util/system.h"

static const double PI = 3.14159265358979323846;

/* The model's state as the CLI builds it: q, q', t, parameters at their
 * values. */
typedef struct point {
    size_t n;
    const qd_expr *syms[40];
    double vals[40];
} point;

static void state_of(const qt_system *s, point *p) {
    size_t nq = qd_model_ncoords(s->model), np = qd_model_nparams(s->model);
    assert_true(2 * nq + 1 + np <= 40);
    for (size_t i = 0; i < nq; i++) {
        p->syms[i] = qd_model_coord(s->model, i);
        p->syms[nq + i] = qd_jet(s->ctx, qd_model_coord(s->model, i), 1);
        p->vals[i] = p->vals[nq + i] = 0;
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

static void choose(const qt_system *s, qd_equilibrium_choice *c) {
    point p;
    state_of(s, &p);
    assert_int_equal(qd_equilibria_choose(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, c),
                     QD_OK);
}

static const char ring[] =
    "coordinates x1, y1, x2, y2, x3, y3\nparameters m = 2, k = 3, a = 1\n"
    "d12 = sqrt((x1 - x2)^2 + (y1 - y2)^2)\nd23 = sqrt((x2 - x3)^2 + (y2 - y3)^2)\n"
    "d31 = sqrt((x3 - x1)^2 + (y3 - y1)^2)\n"
    "particle m at (x1, y1)\nparticle m at (x2, y2)\nparticle m at (x3, y3)\n"
    "V = k/2*((d12 - a)^2 + (d23 - a)^2 + (d31 - a)^2)\n";

/* The chosen triangle is equilateral of side a = 1 and its modes are
 * 0 x3, 3k/2m x2, 3k/m with k = 3, m = 2. */
static void assert_equilateral(const qt_system *s, const qd_equilibrium *pt) {
    const double *q = pt->q;
    double d12 = hypot(q[0] - q[2], q[1] - q[3]), d23 = hypot(q[2] - q[4], q[3] - q[5]);
    double d31 = hypot(q[4] - q[0], q[5] - q[1]);
    assert_true(fabs(d12 - 1) < 1e-8 && fabs(d23 - 1) < 1e-8 && fabs(d31 - 1) < 1e-8);
    point p;
    state_of(s, &p);
    for (size_t j = 0; j < 6; j++)
        p.vals[j] = q[j];
    qd_linear lin;
    qd_modes_result r;
    assert_int_equal(qd_linear_about(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, &lin), QD_OK);
    assert_int_equal(qd_modes_solve(s->ctx, &lin, &r), QD_OK);
    double want[6] = {0, 0, 0, 9.0 / 4, 9.0 / 4, 9.0 / 2};
    for (size_t j = 0; j < 6; j++)
        assert_true(fabs(r.omega2[j] - want[j]) < 1e-8);
    qd_linear_free(&lin);
    qd_modes_result_free(&r);
}

static void test_ring_initial(void **state) {
    char text[1024];
    snprintf(text, sizeof text, "%sinitial x1 = 0.01, y1 = 0, x2 = 1, y2 = 0, x3 = 0.5, "
             "y3 = 0.8660254037844386\n", ring);
    qt_system *s = qt_system_derive(state, text, false);
    qd_equilibrium_choice c;
    choose(s, &c);
    assert_non_null(c.pt);
    assert_int_equal(c.reason, QD_EQ_CHOSEN_NEAREST_MINIMUM);
    assert_true(c.others > 0);
    /* the rule matters: the first listed is not the triangle */
    assert_true(c.found.count > 1 && c.pt != &c.found.pts[0]);
    assert_equilateral(s, c.pt);
    qd_equilibrium_choice_free(&c);
}

static void test_ring_lowest(void **state) {
    qt_system *s = qt_system_derive(state, ring, false);
    qd_equilibrium_choice c;
    choose(s, &c);
    assert_non_null(c.pt);
    assert_int_equal(c.reason, QD_EQ_CHOSEN_LOWEST_MINIMUM);
    assert_int_equal(c.from_initial.count, 0);
    assert_equilateral(s, c.pt);
    assert_int_equal(c.others, c.found.count - 1);
    qd_equilibrium_choice_free(&c);
}

/* One coordinate: the chosen value and the reason. */
static void one(void **state, const char *text, double want, qd_eq_chosen why) {
    qt_system *s = qt_system_derive(state, text, false);
    qd_equilibrium_choice c;
    choose(s, &c);
    assert_non_null(c.pt);
    assert_int_equal(c.reason, why);
    assert_true(fabs(c.pt->q[0] - want) < 1e-9);
    qd_equilibrium_choice_free(&c);
}

static void test_pendulum_near_top(void **state) {
    const char *t = "coordinates th\nparameters m = 1, l = 1, g = 9.81\n"
                    "particle m at (l*sin(th), -l*cos(th))\nV = -m*g*l*cos(th)\n"
                    "initial th = 3\n";
    qt_system *s = qt_system_derive(state, t, false);
    qd_equilibrium_choice c;
    choose(s, &c);
    /* Newton from 3 reaches the top; the choice is the bottom */
    assert_int_equal(c.from_initial.count, 1);
    assert_true(fabs(fabs(c.from_initial.pts[0].q[0]) - PI) < 1e-8);
    assert_non_null(c.pt);
    assert_int_equal(c.reason, QD_EQ_CHOSEN_NEAREST_MINIMUM);
    assert_true(fabs(c.pt->q[0]) < 1e-12);
    assert_int_equal(c.pt->kind, QD_EQ_MINIMUM);
    assert_int_equal(c.others, 1);
    qd_equilibrium_choice_free(&c);
}

/* Two minima, th = 0 and pi; from th = -3 the nearer is pi (0.14 away
 * modulo 2 pi, against 3 to th = 0), the listed one with its exact value.
 * Before angles were compared modulo 2 pi, th = 0 was taken. */
static void test_wrap(void **state) {
    qt_system *s = qt_system_derive(state, "coordinates th\nparameters m = 1, l = 1, k = 2\n"
                                           "particle m at (l*sin(th), -l*cos(th))\n"
                                           "V = -k*cos(2*th)\ninitial th = -3\n", false);
    qd_equilibrium_choice c;
    choose(s, &c);
    assert_non_null(c.pt);
    assert_int_equal(c.reason, QD_EQ_CHOSEN_NEAREST_MINIMUM);
    assert_true(fabs(fabs(c.pt->q[0]) - PI) < 1e-12);
    assert_true(c.pt >= c.found.pts && c.pt < c.found.pts + c.found.count);
    assert_non_null(c.pt->exact);
    assert_int_equal(c.found.count, 4);
    assert_int_equal(c.others, 3);
    qd_equilibrium_choice_free(&c);
}

static void test_inverted_near_bottom(void **state) {
    one(state, "coordinates th\nparameters m = 1, l = 1, g = 9.81\n"
               "particle m at (l*sin(th), -l*cos(th))\nV = m*g*l*cos(th)\ninitial th = 0.1\n",
        PI, QD_EQ_CHOSEN_NEAREST_MINIMUM);
}

static const char tilted[] = "coordinates x\nparticle 1 at (x, 0)\nV = (x^2 - 1)^2 - x/10\n";

static void test_tilted_lowest(void **state) {
    /* the right well: a root of 4 x^3 - 4 x - 1/10 (SymPy nroots) */
    one(state, tilted, 1.01227313103, QD_EQ_CHOSEN_LOWEST_MINIMUM);
}

static void test_tilted_nearest(void **state) {
    char text[256];
    snprintf(text, sizeof text, "%sinitial x = -0.5\n", tilted);
    one(state, text, -0.987257476662, QD_EQ_CHOSEN_NEAREST_MINIMUM);
}

static void test_no_minimum(void **state) {
    one(state, "coordinates x\nparameters k = 2\nparticle 1 at (x, 0)\nV = -k*x^2/2\n"
               "initial x = 0.3\n", 0, QD_EQ_CHOSEN_NEWTON_FROM_INITIAL);
}

static void test_no_minimum_no_initial(void **state) {
    one(state, "coordinates x\nparameters k = 2\nparticle 1 at (x, 0)\nV = -k*x^2/2\n", 0,
        QD_EQ_CHOSEN_FIRST_LISTED);
}

static void test_none(void **state) {
    qt_system *s = qt_system_derive(state, "coordinates x\nparticle 1 at (x, 0)\nV = 3*x\n"
                                           "initial x = 1\n", false);
    qd_equilibrium_choice c;
    choose(s, &c);
    assert_null(c.pt);
    assert_int_equal(c.others, 0);
    qd_equilibrium_choice_free(&c);
}

static void test_chain_linear(void **state) {
    qt_system *s = qt_system_derive(state, "coordinates x1, x2, x3, x4\n"
                                           "parameters m = 1, k = 2, P = 0.5\n"
                                           "particle m at (x1, 0)\nparticle m at (x2, 0)\n"
                                           "particle m at (x3, 0)\nparticle m at (x4, 0)\n"
                                           "V = k/2*(x1^2 + (x2 - x1)^2 + (x3 - x2)^2 + "
                                           "(x4 - x3)^2) - P*x4\n", false);
    qd_equilibrium_choice c;
    choose(s, &c);
    assert_string_equal(c.found.method, "linear");
    assert_int_equal(c.found.count, 1);
    assert_non_null(c.pt);
    for (size_t j = 0; j < 4; j++)
        assert_true(fabs(c.pt->q[j] - (double)(j + 1) * 0.5 / 2) < 1e-12);
    point p;
    state_of(s, &p);
    for (size_t j = 0; j < 4; j++)
        p.vals[j] = c.pt->q[j];
    qd_linear lin;
    qd_modes_result r;
    assert_int_equal(qd_linear_about(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, &lin), QD_OK);
    assert_int_equal(qd_modes_solve(s->ctx, &lin, &r), QD_OK);
    for (size_t j = 0; j < 4; j++) {
        double w = 2 * sqrt(2.0) * sin((2.0 * (double)j + 1) * PI / 18);
        assert_true(fabs(r.omega2[j] - w * w) < 1e-10);
    }
    qd_linear_free(&lin);
    qd_modes_result_free(&r);
    qd_equilibrium_choice_free(&c);
}

static const char hoop[] =
    "coordinates theta\nparameters m = 0.3, a = 0.8, omega = 4, g = 9.81\n"
    "r = (a*sin(theta)*cos(omega*t), a*sin(theta)*sin(omega*t), -a*cos(theta))\n"
    "particle m at r\nV = m*g*r.z\n";

static double eval_at(qd_ctx *ctx, const qd_expr *x, const point *p) {
    double v = NAN;
    assert_int_equal(qd_eval(ctx, x, p->n, p->syms, p->vals, &v), QD_OK);
    return v;
}

static void test_hoop_exact(void **state) {
    qt_system *s = qt_system_derive(state, hoop, false);
    point p;
    state_of(s, &p);
    qd_equilibria eq;
    assert_int_equal(qd_equilibria_find(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, NULL, &eq),
                     QD_OK);
    const qd_equilibrium *axis = NULL, *off = NULL;
    for (size_t k = 0; k < eq.count; k++) {
        assert_non_null(eq.pts[k].exact);
        if (fabs(eq.pts[k].q[0]) < 1e-12)
            axis = &eq.pts[k];
        else if (eq.pts[k].q[0] > 0 && eq.pts[k].q[0] < PI / 2)
            off = &eq.pts[k];
    }
    assert_non_null(axis);
    assert_non_null(off);
    double g = 9.81, a = 0.8, om = 4, c0 = g / (a * om * om);
    assert_true(fabs(cos(off->q[0]) - c0) < 1e-12);
    assert_true(qd_equilibrium_exact_in_parameters(s->ctx, s->eom, s->model, p.n, p.syms, p.vals,
                                                   axis->exact));
    assert_false(qd_equilibrium_exact_in_parameters(s->ctx, s->eom, s->model, p.n, p.syms,
                                                    p.vals, off->exact));

    const qd_expr *w2[2];
    bool in_params = false;
    assert_int_equal(qd_modes_exact_omega2(s->ctx, s->eom, s->model, p.n, p.syms, p.vals,
                                           axis->exact, w2, &in_params), QD_OK);
    assert_true(in_params);
    /* a formula: g/a - omega^2 at other values too */
    point q = p;
    q.vals[4] = 1.5, q.vals[5] = 2, q.vals[6] = 7; /* a, omega, g (after m at 3) */
    assert_true(fabs(eval_at(s->ctx, w2[0], &q) - (7 / 1.5 - 4)) < 1e-12);

    assert_int_equal(qd_modes_exact_omega2(s->ctx, s->eom, s->model, p.n, p.syms, p.vals,
                                           off->exact, w2, &in_params), QD_OK);
    assert_false(in_params);
    double v = NAN;
    assert_int_equal(qd_eval(s->ctx, w2[0], 0, NULL, NULL, &v), QD_OK); /* no symbol left */
    assert_true(fabs(v - om * om * (1 - c0 * c0)) < 1e-12);
    qd_equilibria_free(&eq);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(test_ring_initial, qt_system_teardown),
        cmocka_unit_test_teardown(test_ring_lowest, qt_system_teardown),
        cmocka_unit_test_teardown(test_pendulum_near_top, qt_system_teardown),
        cmocka_unit_test_teardown(test_inverted_near_bottom, qt_system_teardown),
        cmocka_unit_test_teardown(test_wrap, qt_system_teardown),
        cmocka_unit_test_teardown(test_tilted_lowest, qt_system_teardown),
        cmocka_unit_test_teardown(test_tilted_nearest, qt_system_teardown),
        cmocka_unit_test_teardown(test_no_minimum, qt_system_teardown),
        cmocka_unit_test_teardown(test_no_minimum_no_initial, qt_system_teardown),
        cmocka_unit_test_teardown(test_none, qt_system_teardown),
        cmocka_unit_test_teardown(test_hoop_exact, qt_system_teardown),
        cmocka_unit_test_teardown(test_chain_linear, qt_system_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
