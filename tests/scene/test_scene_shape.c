/*
 * tests/scene/test_scene_shape.c - bodies drawn as their shapes (issue 36):
 * the scene's looks checked against the mechanics of the model, at every
 * frame of a run.
 *
 *   - A uniform rod of length 0.8 hung from a pivot at one end (a compound
 *     pendulum, Desloge ch. 50; its inertia rod(m, l) about its centre):
 *     drawn as a segment of 0.8 through its centre along its axis, R e_z, so
 *     that one end stays on the pivot at every frame, and the segment is
 *     0.8 long.  The same rod written with its inertia along body y
 *     (docs/language.md, Reactions) is read along y.
 *   - examples/double_rod_pendulum.qd (Desloge ch. 50 Problem 1): the lower
 *     end of rod 1 is the upper end of rod 2 (their hinge) at every frame.
 *   - A thin disk of radius 0.35 rolling tilted on the plane z = 0
 *     (examples/rolling_disk_tilted.qd, `rolls ... as disk(a)`, with a
 *     `shape disk as disk(a)` line): its drawn circle's lowest point,
 *     c_z - a sqrt(1 - k_z^2) with k the disk's normal R e_z, is on the
 *     plane at every frame (the rolling contact, held by the constraint).
 *   - a tumbling box drawn in 3-D, though its centre stays put;
 *   - the ladder's wall and floor found from its ends' motion;
 *   - the shape statement's refusals, located, with their hints; a size
 *     that is not positive refused when the scene is set up.
 */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <stdio.h>
#include <string.h>
#include <cmocka.h>

#include "qdot/qdot.h"
#include "qdot/scene.h"
#include "qdot/simsetup.h"

typedef struct fix {
    qd_ctx *ctx;
    qd_model *m;
    qd_sim_setup *set;
    qd_scene_setup *sc;
    const qd_scene *v;
} fix;

/* The model's scene, recorded over [0, t_end]. */
static fix record(const char *text, const char *t_end) {
    fix f = {qd_ctx_new(), NULL, NULL, NULL, NULL};
    f.m = qd_model_parse(f.ctx, text, NULL);
    assert_non_null(f.m);
    f.set = qd_sim_setup_new(f.ctx, f.m, false);
    assert_non_null(f.set);
    qd_scene_spec sp = {0};
    f.sc = qd_scene_setup_new(f.ctx, f.set, f.m, &sp);
    assert_non_null(f.sc);
    qd_sim_setup_opts so = {.t_end = t_end, .rtol = "1e-10", .atol = "1e-12"};
    qd_sim_opts o;
    assert_int_equal(qd_sim_setup_options(f.set, &so, &o), QD_OK);
    assert_int_equal(qd_scene_setup_record(f.sc, &o, NULL, NULL, NULL), QD_OK);
    f.v = qd_scene_setup_scene(f.sc);
    return f;
}

static void unload(fix *f) {
    qd_scene_setup_free(f->sc);
    qd_sim_setup_free(f->set);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
}

/* End s (-1 or +1) of body point i's rod at frame k: c + s l/2 R e_axis. */
static void rod_end(const qd_scene *v, size_t i, size_t body, size_t k, double s, double out[3]) {
    const qd_scene_look *l = &v->looks[i];
    const double *c = v->fr->pos + 3 * (k * v->npts + i);
    const double *R = v->fr->rot + 9 * (k * v->fr->nbodies + body);
    for (int r = 0; r < 3; r++)
        out[r] = c[r] + s * l->size[0] / 2 * R[3 * r + l->axis];
}

static const char rod_pendulum[] =
    "coordinates th\n"
    "parameters m = 1.5, l = 0.8, g = 9.81\n"
    "body rod mass m inertia rod(m, l) at l/2*(sin(th), -cos(th), 0) "
    "orientation rot_z(th)*rot_x(-pi/2)\n"
    "V = -m*g*l/2*cos(th)\n"
    "initial th = 1.2\n";

/* the rod along body y: inertia (m l^2/12, 0, m l^2/12), orientation rot_z */
static const char rod_along_y[] =
    "coordinates th\n"
    "parameters m = 1.5, l = 0.8, g = 9.81\n"
    "body rod mass m inertia (m*l^2/12, 0, m*l^2/12) at l/2*(sin(th), -cos(th), 0) "
    "orientation rot_z(th)\n"
    "V = -m*g*l/2*cos(th)\n"
    "initial th = 1.2\n";

static void check_hung_rod(const char *text, int axis) {
    fix f = record(text, "2");
    const qd_scene *v = f.v;
    assert_int_equal(v->npts, 1);
    assert_non_null(v->looks);
    assert_int_equal(v->looks[0].shape, QD_SHAPE_ROD);
    assert_true(v->looks[0].inferred);
    assert_int_equal(v->looks[0].axis, axis);
    assert_true(fabs(v->looks[0].size[0] - 0.8) < 1e-12);
    for (size_t k = 0; k < v->fr->nframes; k++) {
        double a[3], b[3];
        rod_end(v, 0, 0, k, -1, a);
        rod_end(v, 0, 0, k, 1, b);
        double la = hypot(hypot(a[0], a[1]), a[2]), lb = hypot(hypot(b[0], b[1]), b[2]);
        assert_true(fmin(la, lb) < 1e-9);                           /* one end on the pivot */
        assert_true(fabs(fmax(la, lb) - 0.8) < 1e-9);               /* the other at l */
        assert_true(fabs(hypot(hypot(a[0] - b[0], a[1] - b[1]), a[2] - b[2]) - 0.8) < 1e-12);
    }
    unload(&f);
}

static void test_hung_rod(void **state) {
    (void)state;
    check_hung_rod(rod_pendulum, 2);
    check_hung_rod(rod_along_y, 1);
}

static void test_double_rod(void **state) {
    (void)state;
    static const char text[] =
        "coordinates theta1, theta2\n"
        "parameters m1 = 1.1, m2 = 0.7, l1 = 1.2, l2 = 0.9, g = 9.81\n"
        "body rod1 mass m1 inertia rod(m1, l1) at l1/2*(sin(theta1), -cos(theta1), 0) "
        "orientation rot_z(theta1)*rot_x(-pi/2)\n"
        "body rod2 mass m2 inertia rod(m2, l2) at l1*(sin(theta1), -cos(theta1), 0) + "
        "l2/2*(sin(theta2), -cos(theta2), 0) orientation rot_z(theta2)*rot_x(-pi/2)\n"
        "V = m1*g*(-l1/2*cos(theta1)) + m2*g*(-l1*cos(theta1) - l2/2*cos(theta2))\n"
        "initial theta1 = 0.5, theta2 = 0\n";
    fix f = record(text, "3");
    const qd_scene *v = f.v;
    assert_int_equal(v->npts, 2);
    assert_true(fabs(v->looks[0].size[0] - 1.2) < 1e-12);
    assert_true(fabs(v->looks[1].size[0] - 0.9) < 1e-12);
    assert_true(v->plane[0] == 0 && v->plane[1] == 1); /* the rods turn about z only */
    for (size_t k = 0; k < v->fr->nframes; k++) {
        double e1[2][3], e2[2][3], best = INFINITY;
        for (int s = 0; s < 2; s++) {
            rod_end(v, 0, 0, k, 2 * s - 1, e1[s]);
            rod_end(v, 1, 1, k, 2 * s - 1, e2[s]);
        }
        /* rod 1's end away from the pivot meets one of rod 2's ends */
        int lower = hypot(e1[0][0], e1[0][1]) < hypot(e1[1][0], e1[1][1]) ? 1 : 0;
        for (int s = 0; s < 2; s++)
            best = fmin(best, hypot(hypot(e1[lower][0] - e2[s][0], e1[lower][1] - e2[s][1]),
                                    e1[lower][2] - e2[s][2]));
        assert_true(best < 1e-9);
    }
    unload(&f);
}

static void test_rolling_disk(void **state) {
    (void)state;
    static const char text[] =
        "coordinates x, y, z, phi, theta, psi\n"
        "parameters m = 1.4, a = 0.35, g = 9.81\n"
        "body disk mass m inertia disk(m, a) at (x, y, z) orientation euler(phi, theta, psi)\n"
        "shape disk as disk(a)\n"
        "V = m*g*z\n"
        "rolls disk on plane((0, 0, 1), (0, 0, 0)) as disk(a)\n"
        "initial x = 0, y = 0, z = 0.3, phi = 0, theta = 1.0, psi = 0, phi' = 0.8, "
        "theta' = 0, psi' = 4\n";
    fix f = record(text, "2");
    const qd_scene *v = f.v;
    const qd_scene_look *l = &v->looks[0];
    assert_int_equal(l->shape, QD_SHAPE_DISK);
    assert_false(l->inferred);
    assert_int_equal(l->axis, 2);
    assert_true(fabs(l->size[0] - 0.35) < 1e-15);
    double lowest = 0;
    for (size_t k = 0; k < v->fr->nframes; k++) {
        const double *c = v->fr->pos + 3 * k, *R = v->fr->rot + 9 * k;
        double kz = R[8]; /* the normal's z: row 2, column 2 */
        lowest = fmax(lowest, fabs(c[2] - l->size[0] * sqrt(1 - kz * kz)));
    }
    assert_true(lowest < 1e-7);
    unload(&f);
}

/* A free box tumbling about its fixed centre (examples/euler_free_body.qd,
 * Euler's equations): its centre keeps every coordinate, but its shape
 * turns out of any plane, so the picture is 3-D. */
static void test_tumbling_box_is_3d(void **state) {
    (void)state;
    static const char text[] =
        "coordinates phi, theta, psi\n"
        "body b mass 1 inertia (1, 2, 3) at (0, 0, 0) orientation euler(phi, theta, psi)\n"
        "shape b as box(1, 0.6, 0.3)\n"
        "initial theta = 1, phi' = 0.3, theta' = 1, psi' = 0.2\n";
    fix f = record(text, "1");
    assert_true(f.v->plane[0] == -1 && f.v->plane[1] == -1);
    unload(&f);
}

/* The ladder (examples/ladder.qd; Desloge ch. 50 Problem 8): a rod of length l = 3 whose top slides
 * on the wall x = 0 and foot on the floor y = 0 (constraints in x, y,
 * theta); the page's walls are those two planes, the bodies on their
 * positive sides.  The rod pendulum, with no constraint, has none. */
static void test_walls(void **state) {
    (void)state;
    static const char text[] =
        "coordinates x, y, theta\n"
        "parameters m = 2, l = 3, g = 9.81\n"
        "body rod mass m inertia rod(m, l) at (x, y, 0) orientation rot_z(theta)*rot_x(-pi/2)\n"
        "V = m*g*y\n"
        "constraint wall: x - l/2*sin(theta) = 0\n"
        "constraint floor: y - l/2*cos(theta) = 0\n"
        "initial x = 0.75, y = 1.299038105676658, theta = pi/6\n";
    fix f = record(text, "0.8");
    const qd_scene *v = f.v;
    assert_int_equal(v->nwalls, 2);
    bool wall = false, floor = false;
    for (size_t k = 0; k < 2; k++) {
        assert_true(fabs(v->walls[k].at) < 1e-6 && v->walls[k].side == 1);
        wall |= v->walls[k].axis == 0;
        floor |= v->walls[k].axis == 1;
    }
    assert_true(wall && floor);
    unload(&f);
    f = record(rod_pendulum, "1");
    assert_int_equal(f.v->nwalls, 0);
    unload(&f);
}

/* A model whose shape lines are refused at line:col, the message and the
 * hint containing what is said. */
static void refused(const char *shape_lines, int line, int col, const char *msg,
                    const char *hint) {
    char text[512];
    snprintf(text, sizeof text, "coordinates th\nbody rod mass 1 inertia rod(1, 1) at "
             "(sin(th), 0, 0) orientation rot_z(th)\n%s\n", shape_lines);
    qd_ctx *ctx = qd_ctx_new();
    assert_null(qd_model_parse(ctx, text, NULL));
    const qd_diag *d = qd_ctx_diag(ctx);
    assert_true(d->located);
    assert_int_equal(d->line, line);
    assert_int_equal(d->col, col);
    assert_non_null(strstr(d->message, msg));
    assert_non_null(strstr(d->hint, hint));
    qd_ctx_free(ctx);
}

static void test_statement_errors(void **state) {
    (void)state;
    refused("shape rod as rood(1)", 3, 14, "unknown shape 'rood'", "did you mean 'rod'?");
    refused("shape rod as rod(th)", 3, 18, "does not change with the motion", "parameters");
    refused("shape rod as box(1, 2)", 3, 14, "box takes 3 arguments", "");
    refused("shape rod as sphere(1) along x", 3, 24, "'along' is for a rod", "sphere has no axis");
    refused("shape rod as rod(1) along w", 3, 21, "expected a body axis", "along x");
    refused("shape rod rod(1)", 3, 11, "expected 'as'", "write: shape BODY as");
    refused("shape bar as rod(1)", 3, 7, "'bar' is not a body", "");
    refused("shape rod as rod(1) along z\nshape rod as disk(1)", 4, 7, "has a shape already",
            "one shape statement");
}

static void test_accessor_and_size(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qd_model_parse(ctx, "coordinates th\nparameters a = 0.2, b = -1\n"
                                 "body ring mass 1 inertia ring(1, a) at (0, 0, 0) "
                                 "orientation rot_z(th)\nshape ring as ring(2*a) along x\n"
                                 "body box mass 1 inertia box(1, 1, 2, 3) at (0, 0, th)\n"
                                 "shape box as box(1, 2, -b)\n", NULL);
    assert_non_null(m);
    const qd_expr *size[3];
    int axis;
    assert_int_equal(qd_model_body_shape(m, 0, size, &axis), QD_SHAPE_RING);
    assert_int_equal(axis, 0);
    assert_non_null(size[0]);
    assert_null(size[1]);
    assert_int_equal(qd_model_body_shape(m, 1, size, &axis), QD_SHAPE_BOX);
    assert_int_equal(qd_model_body_shape(m, 2, size, NULL), QD_SHAPE_NONE);
    assert_null(size[0]);
    qd_scene_point *pts;
    size_t n;
    assert_int_equal(qd_scene_points(ctx, m, 0, &pts, &n), QD_OK);
    qd_scene_look look[2];
    const qd_expr *syms[2] = {qd_model_param(m, 0), qd_model_param(m, 1)};
    double vals[2] = {0.2, -1};
    assert_int_equal(qd_scene_looks(ctx, pts, n, 2, syms, vals, look), QD_OK);
    assert_true(look[0].shape == QD_SHAPE_RING && fabs(look[0].size[0] - 0.4) < 1e-15);
    assert_true(look[1].size[0] == 1 && look[1].size[1] == 2 && look[1].size[2] == 1);
    vals[1] = 1; /* the box's third edge -b = -1: refused, naming the body */
    assert_int_equal(qd_scene_looks(ctx, pts, n, 2, syms, vals, look), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(ctx), "body 'box'"));
    qd_scene_points_free(pts);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_hung_rod),
        cmocka_unit_test(test_double_rod),
        cmocka_unit_test(test_rolling_disk),
        cmocka_unit_test(test_walls),
        cmocka_unit_test(test_tumbling_box_is_3d),
        cmocka_unit_test(test_statement_errors),
        cmocka_unit_test(test_accessor_and_size),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
