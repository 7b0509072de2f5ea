/*
 * tests/plot/test_plot_orbits.c - a section of several orbits drawn
 * (qd_plot_run_opts' norbits, orbit_rows, orbit_labels; qdot poincare
 * --initial given again) and the dots' size (qd_plot_set_point_size),
 * looked at in the PNG's pixels: two orbits on the circles r = 1 and r = 2
 * (the sections of two tori of the isotropic oscillator, q'^2 + q^2 = 2E
 * with E = 1/2 and 2) are two series, each in its own colour of the
 * palette, and each orbit's dots are in its colour where qd_plot_to_pixel
 * puts them; a dot of radius 6 covers a pixel 4 px from its centre, one of
 * radius 1 does not; orbits whose rows do not sum to the rows, and a
 * radius out of range, are refused.
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
#include "qdot/plot.h"

#define PI 3.14159265358979323846
#define N1 24 /* crossings of the first orbit */
#define N2 40 /* of the second */

static const char *const names[] = {"t", "q", "q'"};

/* The pixel at (px, py) of the PNG at path, as 0xRRGGBB. */
static unsigned pixel_at(const char *path, double px, double py) {
    cairo_surface_t *s = cairo_image_surface_create_from_png(path);
    assert_int_equal(cairo_surface_status(s), CAIRO_STATUS_SUCCESS);
    uint32_t v;
    memcpy(&v, cairo_image_surface_get_data(s) +
                    (size_t)py * (size_t)cairo_image_surface_get_stride(s) + 4 * (size_t)px, 4);
    cairo_surface_destroy(s);
    return v & 0xffffff;
}

/* rows t, q, q': orbit 1 on the circle of radius 1, orbit 2 of radius 2 */
static double *circle_rows(void) {
    double *rows = malloc((N1 + N2) * 3 * sizeof *rows);
    for (size_t k = 0; k < N1 + N2; k++) {
        double r = k < N1 ? 1 : 2, a = 2 * PI * (double)(k < N1 ? k : k - N1) /
                                       (double)(k < N1 ? N1 : N2);
        rows[3 * k] = (double)k;
        rows[3 * k + 1] = r * cos(a);
        rows[3 * k + 2] = r * sin(a);
    }
    return rows;
}

static qd_plot *draw(qd_ctx *ctx, const double *rows, double radius, const char *path) {
    qd_plot_pick pk;
    assert_int_equal(qd_plot_pick_columns(ctx, NULL, "q", names, 3, 1, &pk), QD_OK);
    static const size_t counts[] = {N1, N2};
    static const char *const labels[] = {"E = 1/2", NULL};
    qd_plot_run_opts o = {.title = "two orbits", .points = true, .point_size = radius,
                          .norbits = 2, .orbit_rows = counts, .orbit_labels = labels};
    qd_plot *p = qd_plot_run(ctx, &pk, names, rows, N1 + N2, 3, &o);
    assert_non_null(p);
    assert_int_equal(qd_plot_write(p, path), QD_OK);
    return p;
}

static void test_two_colours(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    double *rows = circle_rows();
    qd_plot *p = draw(ctx, rows, 4, "test_plot_orbits.png");
    assert_int_equal(qd_plot_nseries(p), 2);
    unsigned c0 = qd_plot_color(p, 0), c1 = qd_plot_color(p, 1);
    assert_true(c0 != c1);
    for (size_t k = 0; k < N1 + N2; k++) {
        double px, py;
        assert_true(qd_plot_to_pixel(p, 0, rows[3 * k + 1], rows[3 * k + 2], &px, &py));
        assert_int_equal(pixel_at("test_plot_orbits.png", px, py), k < N1 ? c0 : c1);
    }
    /* between the circles (r = 1.5) no dot: the background */
    double px, py;
    qd_plot_to_pixel(p, 0, 1.5 * cos(0.1), 1.5 * sin(0.1), &px, &py);
    assert_int_equal(pixel_at("test_plot_orbits.png", px, py), 0xffffff);
    qd_plot_free(p);
    free(rows);
    qd_ctx_free(ctx);
}

static void test_point_size(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    double *rows = circle_rows();
    double px, py; /* 4 px right of the outer orbit's first dot, at (2, 0) */
    qd_plot *p = draw(ctx, rows, 6, "test_plot_orbits_big.png");
    qd_plot_to_pixel(p, 0, 2, 0, &px, &py);
    assert_int_equal(pixel_at("test_plot_orbits_big.png", px + 4, py), qd_plot_color(p, 1));
    qd_plot_free(p);
    p = draw(ctx, rows, 1, "test_plot_orbits_small.png");
    qd_plot_to_pixel(p, 0, 2, 0, &px, &py);
    assert_int_equal(pixel_at("test_plot_orbits_small.png", px + 4, py), 0xffffff);
    assert_int_equal(qd_plot_set_point_size(p, 25), QD_ERR_ARG);
    assert_string_equal(qd_ctx_diag(ctx)->name, "point_size");
    qd_ctx_clear_error(ctx);
    assert_int_equal(qd_plot_set_point_size(p, 0.1), QD_ERR_ARG);
    qd_ctx_clear_error(ctx);
    qd_plot_free(p);
    /* orbits whose rows are not the rows drawn */
    qd_plot_pick pk;
    assert_int_equal(qd_plot_pick_columns(ctx, NULL, "q", names, 3, 1, &pk), QD_OK);
    size_t counts[] = {N1, N2 - 1};
    qd_plot_run_opts o = {.points = true, .norbits = 2, .orbit_rows = counts};
    assert_null(qd_plot_run(ctx, &pk, names, rows, N1 + N2, 3, &o));
    assert_int_equal(qd_ctx_status(ctx), QD_ERR_ARG);
    free(rows);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_two_colours),
        cmocka_unit_test(test_point_size),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
