/*
 * tests/linear/test_modes_figure.c - what joins the particles in the mode
 * shapes' picture (qd_modes_picture's links, qd_modes_plot; qdot/modes.h),
 * against the models' own statements, and read back in the pixels:
 *
 *   three equal masses joined in a ring by three springs (Desloge ch. 66,
 *     the C3v example; examples/ring_three_masses.qd) about the equilateral
 *     triangle: three springs, one on each side, no rod, no pivot; in the
 *     PNG each mode's panel has spring-grey ink along the middle of each
 *     side between the moved masses, and none at the triangle's centre;
 *   the square of examples/symmetric_square.qd: four sides and the two
 *     diagonals, the six distance terms of its V;
 *   the linear triatomic molecule (Desloge ch. 66; symmetric_triatomic.qd):
 *     two bonds, 1-2 and 2-3, and none between the end masses;
 *   three equal masses between two walls, four springs (Goldstein ch. 6,
 *     the chain held at its ends: V = k/2 (x1^2 + (x2 - x1)^2 + (x3 - x2)^2
 *     + x3^2)): the two springs between neighbours, and a spring from each
 *     end mass to a wall beyond it, across x, one spacing out (x = 0 and
 *     4); none from the middle mass; the free triatomic has no wall; in
 *     the PNG the springs' ink between each end mass and its wall, and
 *     the wall's dark line there;
 *   a double pendulum of point masses hung from the origin: two rods (the
 *     origin to bob 1, bob 1 to bob 2) and the pivot; no rod from the
 *     origin to bob 2, whose distance changes at second order only about
 *     the hanging equilibrium;
 *   two pendulums hung from (0, 0) and (d, 0) with a spring between the
 *     bobs (Goldstein ch. 6, the coupled pendulums; Desloge ch. 66): the
 *     spring, a rod from each pivot (the second at (d, 0)) and no spring
 *     to a wall (gravity, m g y in V, holds the bobs as a wall's spring
 *     would in K0, but is linear in the positions); in the PNG the spring's
 *     ink along the middle of the bobs' segment in each mode;
 *   a bob tied by a horizontal spring to a wall point: the spring to a
 *     wall across x, and the rod from the pivot;
 *   the spring pendulum (examples/spring_pendulum.qd, Goldstein ch. 1
 *     Ex. 24: V = m g y + k/2 (r - l0)^2): the spring from the pivot at the
 *     origin to the bob, no rod, no wall.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <cairo.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/modes.h"
#include "qdot/plot.h"
#include "../util/system.h"

#define RING                                                                                   \
    "coordinates x1, y1, x2, y2, x3, y3\nparameters m = 1, k = 1, a = 1\n"                     \
    "d12 = sqrt((x1 - x2)^2 + (y1 - y2)^2)\nd23 = sqrt((x2 - x3)^2 + (y2 - y3)^2)\n"           \
    "d31 = sqrt((x3 - x1)^2 + (y3 - y1)^2)\n"                                                  \
    "particle m at (x1, y1)\nparticle m at (x2, y2)\nparticle m at (x3, y3)\n"                 \
    "V = k/2*((d12 - a)^2 + (d23 - a)^2 + (d31 - a)^2)\n"

#define SQUARE                                                                                 \
    "coordinates x1, y1, x2, y2, x3, y3, x4, y4\nparameters m = 1.5, k = 1, kd = 1.5, a = 2\n" \
    "r1 = (x1, y1)\nr2 = (x2, y2)\nr3 = (x3, y3)\nr4 = (x4, y4)\n"                             \
    "particle m at r1\nparticle m at r2\nparticle m at r3\nparticle m at r4\n"                 \
    "V = k/2*((norm(r1 - r2) - a)^2 + (norm(r2 - r3) - a)^2 + (norm(r3 - r4) - a)^2 + "        \
    "(norm(r4 - r1) - a)^2) + kd/2*((norm(r1 - r3) - a*sqrt(2))^2 + "                          \
    "(norm(r2 - r4) - a*sqrt(2))^2)\n"

#define TRIATOMIC                                                                              \
    "coordinates x1, x2, x3\nparameters m = 1, M = 3, k = 2, a = 1\n"                          \
    "particle m at (x1, 0)\nparticle M at (x2, 0)\nparticle m at (x3, 0)\n"                    \
    "V = k/2*((x2 - x1 - a)^2 + (x3 - x2 - a)^2)\n"

#define WALLED                                                                                 \
    "coordinates x1, x2, x3\nparameters m = 1, k = 1, a = 1\n"                                  \
    "particle m at (a + x1, 0)\nparticle m at (2*a + x2, 0)\nparticle m at (3*a + x3, 0)\n"    \
    "V = k/2*(x1^2 + (x2 - x1)^2 + (x3 - x2)^2 + x3^2)\n"

#define PENDULUM                                                                               \
    "coordinates th1, th2\nparameters m1 = 1.2, m2 = 0.7, l1 = 1.1, l2 = 0.8, g = 9.81\n"      \
    "rB = l1*(sin(th1), -cos(th1))\nrC = rB + l2*(sin(th2), -cos(th2))\n"                      \
    "particle m1 at rB\nparticle m2 at rC\nV = m1*g*rB.y + m2*g*rC.y\n"

#define COUPLED                                                                                \
    "coordinates th1, th2\nparameters m = 1, g = 9.81, l = 1, k = 2, d = 1.5\n"                 \
    "P1 = (l*sin(th1), -l*cos(th1))\nP2 = (d + l*sin(th2), -l*cos(th2))\n"                      \
    "particle m at P1\nparticle m at P2\n"                                                      \
    "V = m*g*(P1.y + P2.y) + k/2*(norm(P2 - P1) - d)^2\n"

#define BOB_WALL                                                                               \
    "coordinates th\nparameters m = 1, g = 9.81, l = 1, k = 5, L = 1.5\n"                       \
    "P = (l*sin(th), -l*cos(th))\nparticle m at P\n"                                           \
    "V = m*g*P.y + k/2*(sqrt((P.x + L)^2 + (P.y + l)^2) - L)^2\n"

#define SPRING_PENDULUM                                                                        \
    "coordinates r, theta\nparameters m = 0.4, k = 12, l0 = 1, g = 9.81\n"                     \
    "rb = r*(sin(theta), -cos(theta))\nparticle m at rb\nV = m*g*rb.y + k/2*(r - l0)^2\n"

typedef struct point {
    size_t n;
    const qd_expr *syms[64];
    double vals[64];
} point;

/* Coordinates at q (as many as the model has), parameters at their values. */
static void at(const qt_system *s, const double *q, point *p) {
    size_t nq = qd_model_ncoords(s->model), np = qd_model_nparams(s->model);
    p->n = nq + np;
    for (size_t i = 0; i < nq; i++) {
        p->syms[i] = qd_model_coord(s->model, i);
        p->vals[i] = q[i];
    }
    for (size_t i = 0; i < np; i++) {
        p->syms[nq + i] = qd_model_param(s->model, i);
        assert_int_equal(qd_eval(s->ctx, qd_model_param_value(s->model, i), 0, NULL, NULL,
                                 &p->vals[nq + i]), QD_OK);
    }
}

static void picture(const qt_system *s, const point *p, qd_modes_result *res,
                    qd_modes_picture *pic) {
    qd_linear lin;
    assert_int_equal(qd_linear_about(s->ctx, s->eom, s->model, p->n, p->syms, p->vals, &lin),
                     QD_OK);
    assert_int_equal(qd_modes_solve(s->ctx, &lin, res), QD_OK);
    qd_linear_free(&lin);
    assert_int_equal(qd_modes_picture_make(s->ctx, s->eom, s->model, p->n, p->syms, p->vals, res,
                                           pic), QD_OK);
}

/* The picture joins a and b (either order) by a link of kind. */
static bool joined(const qd_modes_picture *pic, size_t a, size_t b, qd_modes_link kind) {
    for (size_t l = 0; l < pic->nlinks; l++) {
        const qd_modes_link_of *k = &pic->links[l];
        if (k->kind == kind && ((k->a == a && k->b == b) || (k->a == b && k->b == a)))
            return true;
    }
    return false;
}

static const double TRIANGLE[6] = {0, 0, 1, 0, 0.5, 0.8660254037844386};

static void test_ring_links(void **state) {
    qt_system *s = qt_system_derive(state, RING, false);
    point p;
    at(s, TRIANGLE, &p);
    qd_modes_result res;
    qd_modes_picture pic;
    picture(s, &p, &res, &pic);
    assert_int_equal(pic.nlinks, 3);
    assert_true(joined(&pic, 0, 1, QD_MODES_SPRING) && joined(&pic, 1, 2, QD_MODES_SPRING) &&
                joined(&pic, 0, 2, QD_MODES_SPRING));
    assert_false(pic.pivot);
    qd_modes_picture_free(&pic);
    qd_modes_result_free(&res);
}

/* ---- pixels ---- */

typedef struct image {
    cairo_surface_t *s;
    int w, h, stride;
    const unsigned char *data;
} image;

static unsigned pixel(const image *im, int x, int y) {
    uint32_t v;
    memcpy(&v, im->data + (size_t)y * (size_t)im->stride + 4 * (size_t)x, 4);
    return v & 0xffffff; /* Cairo's native-endian xRGB */
}

/* Spring grey (0x8c8c8c, antialiased lighter): grey, darker than the
 * background; the masses are blue and orange, the arrows red. */
static bool spring_ink(unsigned v) {
    int r = (v >> 16) & 255, g = (v >> 8) & 255, b = v & 255;
    return r < 235 && abs(r - g) < 12 && abs(g - b) < 12;
}

/* Spring ink within the zigzag's half-width (7 px) of (x, y). */
static bool ink_near(const image *im, double x, double y) {
    for (int dy = -8; dy <= 8; dy++)
        for (int dx = -8; dx <= 8; dx++) {
            int px = (int)lround(x) + dx, py = (int)lround(y) + dy;
            if (px >= 0 && py >= 0 && px < im->w && py < im->h && spring_ink(pixel(im, px, py)))
                return true;
        }
    return false;
}

static void test_ring_pixels(void **state) {
    qt_system *s = qt_system_derive(state, RING, false);
    point p;
    at(s, TRIANGLE, &p);
    qd_modes_result res;
    qd_modes_picture pic;
    picture(s, &p, &res, &pic);
    qd_plot *plot = NULL;
    assert_int_equal(qd_modes_plot(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, &res, "ring",
                                   &plot), QD_OK);
    assert_int_equal(qd_plot_write(plot, "test_modes_figure_ring.png"), QD_OK);
    image im = {cairo_image_surface_create_from_png("test_modes_figure_ring.png"), 0, 0, 0, NULL};
    assert_int_equal(cairo_surface_status(im.s), CAIRO_STATUS_SUCCESS);
    im.w = cairo_image_surface_get_width(im.s);
    im.h = cairo_image_surface_get_height(im.s);
    im.stride = cairo_image_surface_get_stride(im.s);
    im.data = cairo_image_surface_get_data(im.s);
    assert_int_equal(pic.ay, 1); /* the plane of x and y */
    for (size_t j = 0; j < res.n; j++) {
        const double *mv = pic.moved + j * 9;
        double cx = 0, cy = 0, px, py;
        for (size_t a = 0; a < 3; a++) {
            size_t b = (a + 1) % 3;
            int hits = 0, samples = 0;
            /* the middle 60% of the side: away from the masses' dots */
            for (double f = 0.2; f <= 0.8 + 1e-9; f += 0.05, samples++) {
                double x = mv[3 * a] + f * (mv[3 * b] - mv[3 * a]);
                double y = mv[3 * a + 1] + f * (mv[3 * b + 1] - mv[3 * a + 1]);
                assert_true(qd_plot_to_pixel(plot, j, x, y, &px, &py));
                hits += ink_near(&im, px, py);
            }
            assert_int_equal(hits, samples); /* the spring from a to b all along */
            cx += mv[3 * a] / 3;
            cy += mv[3 * a + 1] / 3;
        }
        /* the triangle's middle is empty: no spring across it */
        assert_true(qd_plot_to_pixel(plot, j, cx, cy, &px, &py));
        assert_int_equal(pixel(&im, (int)lround(px), (int)lround(py)), 0xffffff);
    }
    cairo_surface_destroy(im.s);
    qd_plot_free(plot);
    qd_modes_picture_free(&pic);
    qd_modes_result_free(&res);
}

static void test_square_links(void **state) {
    qt_system *s = qt_system_derive(state, SQUARE, false);
    const double q[8] = {1, 1, -1, 1, -1, -1, 1, -1};
    point p;
    at(s, q, &p);
    qd_modes_result res;
    qd_modes_picture pic;
    picture(s, &p, &res, &pic);
    assert_int_equal(pic.nlinks, 6);
    for (size_t a = 0; a < 4; a++) /* the sides */
        assert_true(joined(&pic, a, (a + 1) % 4, QD_MODES_SPRING));
    assert_true(joined(&pic, 0, 2, QD_MODES_SPRING) && joined(&pic, 1, 3, QD_MODES_SPRING));
    qd_modes_picture_free(&pic);
    qd_modes_result_free(&res);
}

static void test_triatomic_links(void **state) {
    qt_system *s = qt_system_derive(state, TRIATOMIC, false);
    const double q[3] = {-1, 0, 1};
    point p;
    at(s, q, &p);
    qd_modes_result res;
    qd_modes_picture pic;
    picture(s, &p, &res, &pic);
    assert_int_equal(pic.nlinks, 2);
    assert_true(joined(&pic, 0, 1, QD_MODES_SPRING) && joined(&pic, 1, 2, QD_MODES_SPRING));
    assert_false(joined(&pic, 0, 2, QD_MODES_SPRING));
    qd_modes_picture_free(&pic);
    qd_modes_result_free(&res);
}

static void test_walled_chain(void **state) {
    qt_system *s = qt_system_derive(state, WALLED, false);
    const double q[3] = {0, 0, 0};
    point p;
    at(s, q, &p);
    qd_modes_result res;
    qd_modes_picture pic;
    picture(s, &p, &res, &pic);
    assert_int_equal(pic.nwalls, 2);
    assert_int_equal(pic.nlinks, 4);
    assert_true(joined(&pic, 0, 1, QD_MODES_SPRING) && joined(&pic, 1, 2, QD_MODES_SPRING));
    assert_true(joined(&pic, 0, 4, QD_MODES_SPRING) && joined(&pic, 2, 5, QD_MODES_SPRING));
    /* the walls across x, one spacing beyond the end masses */
    assert_true(pic.wall_axis[0] == 0 && pic.wall_axis[1] == 0);
    assert_true(fabs(pic.wall[0] - 0) < 1e-9 && fabs(pic.wall[3] - 4) < 1e-9);
    assert_true(fabs(pic.wall[1]) < 1e-12 && fabs(pic.wall[4]) < 1e-12);
    /* in the PNG: each mode's panel has the spring from the moved end masses
     * to their walls, the walls' dark lines at x = 0 and 4 (across the line,
     * at displacement 0) */
    qd_plot *plot = NULL;
    assert_int_equal(qd_modes_plot(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, &res,
                                   "walls", &plot), QD_OK);
    assert_int_equal(qd_plot_write(plot, "test_modes_figure_walls.png"), QD_OK);
    image im = {cairo_image_surface_create_from_png("test_modes_figure_walls.png"), 0, 0, 0,
                NULL};
    assert_int_equal(cairo_surface_status(im.s), CAIRO_STATUS_SUCCESS);
    im.w = cairo_image_surface_get_width(im.s);
    im.h = cairo_image_surface_get_height(im.s);
    im.stride = cairo_image_surface_get_stride(im.s);
    im.data = cairo_image_surface_get_data(im.s);
    assert_int_equal(pic.ay, 3); /* on one line: displacements across it */
    for (size_t j = 0; j < res.n; j++) {
        const double *mv = pic.moved + j * 9;
        for (size_t end = 0; end < 2; end++) {
            size_t a = end ? 2 : 0;
            double ax = pic.rest[3 * a], ay = mv[3 * a] - pic.rest[3 * a];
            double wx = pic.wall[3 * end], px, py;
            for (double f = 0.3; f <= 0.7 + 1e-9; f += 0.1) {
                assert_true(qd_plot_to_pixel(plot, j, ax + f * (wx - ax), (1 - f) * ay, &px,
                                             &py));
                assert_true(ink_near(&im, px, py));
            }
            assert_true(qd_plot_to_pixel(plot, j, wx, 0, &px, &py));
            bool dark = false;
            for (int dy = -10; dy <= 10; dy++)
                for (int dx = -3; dx <= 3; dx++) { /* every channel dark: the wall's black */
                    unsigned v = pixel(&im, (int)lround(px) + dx, (int)lround(py) + dy);
                    dark |= (v >> 16) < 0x40 && ((v >> 8) & 0xff) < 0x40 && (v & 0xff) < 0x40;
                }
            assert_true(dark);
        }
    }
    cairo_surface_destroy(im.s);
    qd_plot_free(plot);
    qd_modes_picture_free(&pic);
    qd_modes_result_free(&res);
}

static void test_pendulum_rods(void **state) {
    qt_system *s = qt_system_derive(state, PENDULUM, false);
    const double q[2] = {0, 0};
    point p;
    at(s, q, &p);
    qd_modes_result res;
    qd_modes_picture pic;
    picture(s, &p, &res, &pic);
    assert_true(pic.pivot);
    assert_int_equal(pic.nlinks, 2);
    assert_true(joined(&pic, 2, 0, QD_MODES_ROD)); /* the origin (b == np) to bob 1 */
    assert_true(joined(&pic, 0, 1, QD_MODES_ROD));
    assert_false(joined(&pic, 2, 1, QD_MODES_ROD));
    qd_modes_picture_free(&pic);
    qd_modes_result_free(&res);
}

static image read_png(const char *path) {
    image im = {cairo_image_surface_create_from_png(path), 0, 0, 0, NULL};
    assert_int_equal(cairo_surface_status(im.s), CAIRO_STATUS_SUCCESS);
    im.w = cairo_image_surface_get_width(im.s);
    im.h = cairo_image_surface_get_height(im.s);
    im.stride = cairo_image_surface_get_stride(im.s);
    im.data = cairo_image_surface_get_data(im.s);
    return im;
}

static void test_coupled_pendulums(void **state) {
    qt_system *s = qt_system_derive(state, COUPLED, false);
    const double q[2] = {0, 0};
    point p;
    at(s, q, &p);
    qd_modes_result res;
    qd_modes_picture pic;
    picture(s, &p, &res, &pic);
    assert_true(joined(&pic, 0, 1, QD_MODES_SPRING));
    assert_true(pic.pivot && joined(&pic, 2, 0, QD_MODES_ROD)); /* from the origin */
    assert_int_equal(pic.nwalls, 1);                             /* the pivot at (d, 0) */
    assert_int_equal(pic.wall_axis[0], 3);
    assert_true(fabs(pic.wall[0] - 1.5) < 1e-6 && fabs(pic.wall[1]) < 1e-6);
    assert_true(joined(&pic, 1, 3, QD_MODES_ROD));
    assert_int_equal(pic.nlinks, 3);
    qd_plot *plot = NULL;
    assert_int_equal(qd_modes_plot(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, &res,
                                   "coupled", &plot), QD_OK);
    assert_int_equal(qd_plot_write(plot, "test_modes_figure_coupled.png"), QD_OK);
    image im = read_png("test_modes_figure_coupled.png");
    for (size_t j = 0; j < res.n; j++) {
        const double *mv = pic.moved + j * 6;
        for (double f = 0.3; f <= 0.7 + 1e-9; f += 0.05) { /* clear of the dots */
            double px, py;
            assert_true(qd_plot_to_pixel(plot, j, mv[0] + f * (mv[3] - mv[0]),
                                         mv[1] + f * (mv[4] - mv[1]), &px, &py));
            assert_true(ink_near(&im, px, py));
        }
    }
    cairo_surface_destroy(im.s);
    qd_plot_free(plot);
    qd_modes_picture_free(&pic);
    qd_modes_result_free(&res);
}

static void test_bob_wall(void **state) {
    qt_system *s = qt_system_derive(state, BOB_WALL, false);
    const double q[1] = {0};
    point p;
    at(s, q, &p);
    qd_modes_result res;
    qd_modes_picture pic;
    picture(s, &p, &res, &pic);
    assert_true(pic.pivot && joined(&pic, 1, 0, QD_MODES_ROD));
    assert_int_equal(pic.nwalls, 1);
    assert_int_equal(pic.wall_axis[0], 0); /* across x: the spring is horizontal */
    assert_true(joined(&pic, 0, 2, QD_MODES_SPRING));
    assert_int_equal(pic.nlinks, 2);
    qd_modes_picture_free(&pic);
    qd_modes_result_free(&res);
}

static void test_spring_pendulum(void **state) {
    qt_system *s = qt_system_derive(state, SPRING_PENDULUM, false);
    const double q[2] = {1 + 0.4 * 9.81 / 12, 0}; /* r = l0 + m g / k */
    point p;
    at(s, q, &p);
    qd_modes_result res;
    qd_modes_picture pic;
    picture(s, &p, &res, &pic);
    assert_true(pic.pivot);
    assert_int_equal(pic.nlinks, 1);
    assert_true(joined(&pic, 1, 0, QD_MODES_SPRING));
    assert_int_equal(pic.nwalls, 0);
    qd_modes_picture_free(&pic);
    qd_modes_result_free(&res);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(test_ring_links, qt_system_teardown),
        cmocka_unit_test_teardown(test_ring_pixels, qt_system_teardown),
        cmocka_unit_test_teardown(test_square_links, qt_system_teardown),
        cmocka_unit_test_teardown(test_triatomic_links, qt_system_teardown),
        cmocka_unit_test_teardown(test_walled_chain, qt_system_teardown),
        cmocka_unit_test_teardown(test_pendulum_rods, qt_system_teardown),
        cmocka_unit_test_teardown(test_coupled_pendulums, qt_system_teardown),
        cmocka_unit_test_teardown(test_bob_wall, qt_system_teardown),
        cmocka_unit_test_teardown(test_spring_pendulum, qt_system_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
