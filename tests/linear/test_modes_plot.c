/*
 * tests/linear/test_modes_plot.c - the mode shapes drawn (qd_modes_plot,
 * qd_modes_picture_make; qdot/modes.h), checked against the textbook
 * modes:
 *
 *   two equal masses m on a line between two walls, joined by three equal
 *     springs k (Goldstein ch. 6, the coupled oscillators of sec. 6.4), the
 *     masses at rest at x = a and x = 2a: w^2 = k/m with the masses moving
 *     the same way by the same amount (in phase), 3k/m with them moving
 *     opposite ways (in opposition).  The particles lie on one line, so the
 *     picture draws the displacements along x against the places at rest;
 *     the largest displacement is a fifth of the chain's size a; the plot
 *     has a panel per mode, each with the equilibrium and the moved chain;
 *   the same chain in a frame moved to (1, 1) and turned by 30 degrees: the
 *     displacements are along the chain's line, in phase and in
 *     opposition, the same picture in the plane;
 *   the same oscillators without particles: one panel, a series per mode;
 *   a damped oscillator: no real shapes, refused.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/modes.h"
#include "qdot/plot.h"
#include "../util/system.h"

#define CHAIN                                                                                  \
    "coordinates x1, x2\nparameters m = 2, k = 5, a = 1.5\n"                                   \
    "particle m at (a + x1, 0)\nparticle m at (2*a + x2, 0)\n"                                 \
    "V = k/2*(x1^2 + (x2 - x1)^2 + x2^2)\n"

/* The chain along the direction (cos 30, sin 30) from (1, 1). */
#define TURNED                                                                                 \
    "coordinates x1, x2\nparameters m = 2, k = 5, a = 1.5, c = sqrt(3)/2, s = 1/2\n"           \
    "particle m at (1 + c*(a + x1), 1 + s*(a + x1))\n"                                         \
    "particle m at (1 + c*(2*a + x2), 1 + s*(2*a + x2))\n"                                     \
    "V = k/2*(x1^2 + (x2 - x1)^2 + x2^2)\n"

#define COUPLED                                                                                \
    "coordinates x1, x2\nparameters m = 2, k = 5\n"                                            \
    "T = m/2*(x1'^2 + x2'^2)\n"                                                                \
    "V = k/2*(x1^2 + (x2 - x1)^2 + x2^2)\n"

#define DAMPED                                                                                 \
    "coordinates x\nparameters m = 2, k = 8, c = 1\n"                                          \
    "T = m/2*x'^2\nV = k/2*x^2\ndissipation = c/2*x'^2\n"

typedef struct point {
    size_t n;
    const qd_expr *syms[64];
    double vals[64];
} point;

/* The state at the coordinates 0 (the chains' equilibrium), parameters at
 * their values. */
static void at_rest(const qt_system *s, point *p) {
    size_t nq = qd_model_ncoords(s->model), np = qd_model_nparams(s->model);
    p->n = nq + np;
    for (size_t i = 0; i < nq; i++) {
        p->syms[i] = qd_model_coord(s->model, i);
        p->vals[i] = 0;
    }
    for (size_t i = 0; i < np; i++) {
        p->syms[nq + i] = qd_model_param(s->model, i);
        assert_int_equal(qd_eval(s->ctx, qd_model_param_value(s->model, i), 0, NULL, NULL,
                                 &p->vals[nq + i]), QD_OK);
    }
}

static void modes_of(const qt_system *s, const point *p, qd_modes_result *res) {
    qd_linear lin;
    assert_int_equal(qd_linear_about(s->ctx, s->eom, s->model, p->n, p->syms, p->vals, &lin),
                     QD_OK);
    assert_int_equal(qd_modes_solve(s->ctx, &lin, res), QD_OK);
    qd_linear_free(&lin);
}

/* Particle i's displacement in mode j along the unit vector u. */
static double along(const qd_modes_picture *pic, size_t j, size_t i, const double *u) {
    const double *mv = pic->moved + (j * pic->np + i) * 3, *r = pic->rest + i * 3;
    return (mv[0] - r[0]) * u[0] + (mv[1] - r[1]) * u[1] + (mv[2] - r[2]) * u[2];
}

/* The chain's two modes along u: in phase, then in opposition, each with
 * the largest displacement a/5, and nothing across u. */
static void check_chain_modes(const qd_modes_picture *pic, const double *u, double a) {
    assert_int_equal(pic->np, 2);
    assert_int_equal(pic->nmode, 2);
    double d10 = along(pic, 0, 0, u), d11 = along(pic, 0, 1, u);
    double d20 = along(pic, 1, 0, u), d21 = along(pic, 1, 1, u);
    assert_true(fabs(d10 - d11) < 1e-6 * a);       /* the same way, as much */
    assert_true(fabs(d20 + d21) < 1e-6 * a);       /* opposite ways */
    assert_true(fabs(fabs(d10) - 0.2 * a) < 1e-6 * a);
    assert_true(fabs(fabs(d20) - 0.2 * a) < 1e-6 * a);
    for (size_t j = 0; j < 2; j++)
        for (size_t i = 0; i < 2; i++) {
            const double *mv = pic->moved + (j * 2 + i) * 3, *r = pic->rest + i * 3;
            double d = along(pic, j, i, u), e[3];
            for (int k = 0; k < 3; k++)
                e[k] = mv[k] - r[k] - d * u[k];
            assert_true(sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]) < 1e-6 * a);
        }
}

static void test_chain(void **state) {
    qt_system *s = qt_system_derive(state, CHAIN, true);
    point p;
    at_rest(s, &p);
    qd_modes_result res;
    modes_of(s, &p, &res);
    assert_true(res.conservative);
    /* w^2 = k/m and 3k/m (Goldstein sec. 6.4) */
    assert_true(fabs(res.omega2[0] - 2.5) < 1e-9 && fabs(res.omega2[1] - 7.5) < 1e-9);
    qd_modes_picture pic;
    assert_int_equal(qd_modes_picture_make(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, &res,
                                           &pic), QD_OK);
    /* at rest at (a, 0, 0) and (2a, 0, 0) */
    assert_true(fabs(pic.rest[0] - 1.5) < 1e-12 && fabs(pic.rest[3] - 3) < 1e-12);
    assert_true(pic.rest[1] == 0 && pic.rest[2] == 0 && pic.rest[4] == 0 && pic.rest[5] == 0);
    const double ux[3] = {1, 0, 0};
    check_chain_modes(&pic, ux, 1.5);
    assert_int_equal(pic.ax, 0); /* on the x axis: displacements across it */
    assert_int_equal(pic.ay, 3);
    qd_modes_picture_free(&pic);

    qd_plot *plot = NULL;
    assert_int_equal(qd_modes_plot(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, &res,
                                   "chain", &plot), QD_OK);
    assert_non_null(plot);
    assert_int_equal(qd_plot_npanels(plot), 2);  /* a panel per mode */
    assert_int_equal(qd_plot_nseries(plot), 4); /* the chain at rest and moved, in each */
    assert_int_equal(qd_plot_layout(plot), QD_OK);
    /* mode 2's panel: the displacements either side of 0 by a/5 */
    double x0, x1, y0, y1;
    assert_true(qd_plot_ranges(plot, 1, &x0, &x1, &y0, &y1));
    assert_true(y0 <= -0.3 && y1 >= 0.3);
    assert_true(x0 <= 1.5 && x1 >= 3);
    /* mode 1's: both the same way, y on one side (padding aside) */
    assert_true(qd_plot_ranges(plot, 0, &x0, &x1, &y0, &y1));
    assert_true(y0 * y1 < 0 ? fmin(-y0, y1) < 0.1 * 0.3 : true);
    qd_plot_free(plot);
    qd_modes_result_free(&res);
}

static void test_turned_chain(void **state) {
    qt_system *s = qt_system_derive(state, TURNED, true);
    point p;
    at_rest(s, &p);
    qd_modes_result res;
    modes_of(s, &p, &res);
    qd_modes_picture pic;
    assert_int_equal(qd_modes_picture_make(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, &res,
                                           &pic), QD_OK);
    const double u[3] = {sqrt(3) / 2, 0.5, 0};
    /* the chain's size is its extent along x, a cos 30, and the largest
     * displacement along an axis (along x, |d| cos 30) a fifth of it: |d| =
     * a/5 again */
    check_chain_modes(&pic, u, 1.5);
    assert_int_equal(pic.ax, 0); /* drawn in the x-y plane */
    assert_int_equal(pic.ay, 1);
    qd_modes_picture_free(&pic);
    qd_modes_result_free(&res);
}

static void test_without_particles(void **state) {
    qt_system *s = qt_system_derive(state, COUPLED, true);
    point p;
    at_rest(s, &p);
    qd_modes_result res;
    modes_of(s, &p, &res);
    qd_modes_picture pic;
    assert_int_equal(qd_modes_picture_make(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, &res,
                                           &pic), QD_OK);
    assert_int_equal(pic.np, 0);
    assert_null(pic.rest);
    qd_plot *plot = NULL;
    assert_int_equal(qd_modes_plot(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, &res, "c",
                                   &plot), QD_OK);
    assert_int_equal(qd_plot_npanels(plot), 1);
    assert_int_equal(qd_plot_nseries(plot), 2); /* a_i1 and a_i2 against i */
    assert_int_equal(qd_plot_layout(plot), QD_OK);
    double x0, x1, y0, y1;
    assert_true(qd_plot_ranges(plot, 0, &x0, &x1, &y0, &y1));
    /* shapes scaled to a largest entry 1, the in-opposition one reaching -1 */
    assert_true(y1 >= 1 && y0 <= -1 && x0 <= 1 && x1 >= 2);
    qd_plot_free(plot);
    qd_modes_result_free(&res);
}

static void test_damped_refused(void **state) {
    qt_system *s = qt_system_derive(state, DAMPED, true);
    point p;
    at_rest(s, &p);
    qd_modes_result res;
    modes_of(s, &p, &res);
    assert_false(res.conservative);
    qd_plot *plot = (qd_plot *)&p; /* overwritten */
    assert_int_equal(qd_modes_plot(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, &res, "d",
                                   &plot), QD_ERR_ARG);
    assert_null(plot);
    assert_non_null(strstr(qd_ctx_message(s->ctx), "no mode shapes"));
    qd_modes_result_free(&res);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(test_chain, qt_system_teardown),
        cmocka_unit_test_teardown(test_turned_chain, qt_system_teardown),
        cmocka_unit_test_teardown(test_without_particles, qt_system_teardown),
        cmocka_unit_test_teardown(test_damped_refused, qt_system_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
