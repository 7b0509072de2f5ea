/*
 * tests/scene/test_scene.c - what a picture of the motion draws
 * (qdot/scene.h, issue 36): the named positions of the double pendulum
 * (Goldstein ch. 1 ex. 22) found as its two points, their expressions
 * evaluated to the pendulum's geometry; a rod where the distance is
 * constant, none on a spring, the plane of a planar motion, 3-D otherwise.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/qdot.h"

static const char pendulum[] =
    "coordinates theta1, theta2\n"
    "parameters l1 = 1, l2 = 2\n"
    "x1 = l1*sin(theta1)\n"
    "y1 = -l1*cos(theta1)\n"
    "x2 = x1 + l2*sin(theta2)\n"
    "y2 = y1 - l2*cos(theta2)\n"
    "v1 = x1'\n"                /* a velocity, not a place */
    "xc = 3\n"                  /* a constant, not a place */
    "yc = 4\n"
    "P3 = (x2, y2, theta1)\n"  /* a vector place */
    "T = (x1'^2 + y1'^2 + x2'^2 + y2'^2)/2\n"
    "V = 9.81*(y1 + y2)\n";

static void test_named_positions(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qd_model_parse(ctx, pendulum, NULL);
    assert_non_null(m);
    qd_scene_point *p = NULL;
    size_t n = 0;
    assert_int_equal(qd_scene_points(ctx, m, 0, &p, &n), QD_OK);
    assert_int_equal(n, 3);
    assert_string_equal(p[0].name, "x1,y1");
    assert_string_equal(p[1].name, "x2,y2");
    assert_string_equal(p[2].name, "P3");
    assert_true(p[0].kind == QD_SCENE_POSITION && !p[0].mass);
    assert_true(qd_scene_point_is(&p[1], "y2", 2) && qd_scene_point_is(&p[1], "x2,y2", 5));
    assert_false(qd_scene_point_is(&p[1], "x1", 2));
    /* at theta1 = 0.3, theta2 = -0.7: rC = l1 (sin, -cos)(0.3) + l2 (sin, -cos)(-0.7) */
    const qd_expr *syms[4] = {qd_model_coord(m, 0), qd_model_coord(m, 1), qd_param(ctx, "l1"),
                              qd_param(ctx, "l2")};
    double vals[4] = {0.3, -0.7, 1, 2}, x, y, z;
    assert_int_equal(qd_eval(ctx, p[1].pos[0], 4, syms, vals, &x), QD_OK);
    assert_int_equal(qd_eval(ctx, p[1].pos[1], 4, syms, vals, &y), QD_OK);
    assert_int_equal(qd_eval(ctx, p[1].pos[2], 4, syms, vals, &z), QD_OK);
    assert_true(fabs(x - (sin(0.3) + 2 * sin(-0.7))) < 1e-14);
    assert_true(fabs(y - (-cos(0.3) - 2 * cos(-0.7))) < 1e-14);
    assert_true(z == 0);
    free(p);
    /* particles only: none */
    assert_int_equal(qd_scene_points(ctx, m, QD_SCENE_PARTICLES, &p, &n), QD_OK);
    assert_int_equal(n, 0);
    free(p);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* Two points: a pendulum bob on a rod of length 1 from the origin, and a
 * second bob at a varying distance (a spring) from the first. */
static void test_rods_and_plane(void **state) {
    (void)state;
    enum { F = 50, N = 2 };
    double pos[F * N * 3];
    for (int f = 0; f < F; f++) {
        double th = 0.04 * f, r = 1 + 0.3 * sin(0.2 * f);
        double *a = pos + f * N * 3, *b = a + 3;
        a[0] = sin(th), a[1] = -cos(th), a[2] = 0;
        b[0] = a[0] + r * sin(2 * th), b[1] = a[1] - r * cos(2 * th), b[2] = 0;
    }
    qd_scene_shape sh;
    assert_int_equal(qd_scene_analyse(NULL, pos, F, N, NULL, 0, &sh), QD_OK);
    assert_true(sh.plane[0] == 0 && sh.plane[1] == 1);
    assert_int_equal(sh.nrods, 1);
    assert_true(sh.rods[0].a == QD_SCENE_ORIGIN && sh.rods[0].b == 0);
    assert_true(fabs(sh.rods[0].length - 1) < 1e-12);
    free(sh.rods);
    /* the pendulum's rod named as a spring: no rod */
    size_t skip[2] = {QD_SCENE_ORIGIN, 0};
    assert_int_equal(qd_scene_analyse(NULL, pos, F, N, skip, 1, &sh), QD_OK);
    assert_int_equal(sh.nrods, 0);
    free(sh.rods);
    /* out of the plane: 3-D */
    for (int f = 0; f < F; f++)
        pos[f * N * 3 + 5] = 0.01 * f;
    assert_int_equal(qd_scene_analyse(NULL, pos, F, N, NULL, 0, &sh), QD_OK);
    assert_true(sh.plane[0] == -1 && sh.plane[1] == -1);
    assert_true(fabs(sh.hi[2] - 0.49) < 1e-12 && sh.lo[2] == 0);
    free(sh.rods);
    pos[4] = NAN;
    assert_int_equal(qd_scene_analyse(NULL, pos, F, N, NULL, 0, &sh), QD_ERR_ARG);
    free(sh.rods);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_named_positions),
        cmocka_unit_test(test_rods_and_plane),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
