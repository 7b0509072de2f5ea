/*
 * tests/plot/test_plot_map.c - colour maps (qd_plot_add_map) looked at in
 * their pixels: a map of z = x drawn to PNG and read back with Cairo has at
 * each cell's centre exactly the colour of its value's place in the range,
 * so its lightness rises along x and stays along y; a NaN cell is grey; the
 * scale's ends are viridis' and its lightness never falls; the axes span
 * the cells; the errors (unordered grid, infinite value, a second map).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <cairo.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "qdot/qdot.h"

typedef struct image {
    cairo_surface_t *s;
    int stride;
    const unsigned char *data;
} image;

static image load(const char *path) {
    image im = {cairo_image_surface_create_from_png(path), 0, NULL};
    assert_int_equal(cairo_surface_status(im.s), CAIRO_STATUS_SUCCESS);
    im.stride = cairo_image_surface_get_stride(im.s);
    im.data = cairo_image_surface_get_data(im.s);
    return im;
}

static unsigned pixel(const image *im, double x, double y) {
    uint32_t v;
    memcpy(&v, im->data + (size_t)y * (size_t)im->stride + 4 * (size_t)x, 4);
    return v & 0xffffff; /* Cairo's native-endian xRGB */
}

/* Relative luminance (Rec. 709 weights) of 0xRRGGBB, 0..255. */
static double lightness(unsigned c) {
    return 0.2126 * ((c >> 16) & 255) + 0.7152 * ((c >> 8) & 255) + 0.0722 * (c & 255);
}

/* The scale's ends are viridis' own, and its lightness never falls: the
 * property that makes a map read as a gradient in grey. */
static void test_scale(void **state) {
    (void)state;
    assert_int_equal(qd_plot_map_color(0), 0x440154);
    assert_int_equal(qd_plot_map_color(1), 0xfde725);
    assert_int_equal(qd_plot_map_color(-3), 0x440154); /* clamped */
    assert_int_equal(qd_plot_map_color(7), 0xfde725);
    double prev = -1;
    for (int k = 0; k <= 1000; k++) {
        double l = lightness(qd_plot_map_color(k / 1000.0));
        assert_true(l >= prev - 0.5); /* rounding to 8 bits may dip by under half a level */
        prev = l;
    }
    assert_true(lightness(0xfde725) - lightness(0x440154) > 150);
}

#define NX 5
#define NY 3

/* z = x on a 5 x 3 grid, the middle cell of the top row NaN. */
static qd_plot *map_of_x(qd_ctx *ctx, double *z) {
    static const double x[NX] = {0, 0.5, 1, 1.5, 2}, y[NY] = {-1, 0, 1};
    for (int j = 0; j < NY; j++)
        for (int i = 0; i < NX; i++)
            z[j * NX + i] = x[i];
    z[2 * NX + 2] = NAN;
    qd_plot *p = qd_plot_new(ctx, 0, 0);
    assert_non_null(p);
    assert_int_equal(qd_plot_set_xlabel(p, "x"), QD_OK);
    assert_int_equal(qd_plot_set_ylabel(p, "y"), QD_OK);
    assert_int_equal(qd_plot_add_map(p, "z", NX, NY, x, y, z), QD_OK);
    return p;
}

static void test_map_pixels(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    double z[NX * NY];
    qd_plot *p = map_of_x(ctx, z);
    assert_int_equal(qd_plot_write(p, "test_plot_map.png"), QD_OK);
    double x0, x1, y0, y1, zmin, zmax;
    assert_true(qd_plot_ranges(p, 0, &x0, &x1, &y0, &y1));
    /* the cells reach halfway to their neighbours, the ends as far out */
    assert_true(x0 == -0.25 && x1 == 2.25 && y0 == -1.5 && y1 == 1.5);
    assert_true(qd_plot_map_range(p, 0, &zmin, &zmax));
    assert_true(zmin == 0 && zmax == 2);
    image im = load("test_plot_map.png");
    for (int j = 0; j < NY; j++) {
        double prev = -1;
        for (int i = 0; i < NX; i++) {
            double px, py;
            assert_true(qd_plot_to_pixel(p, 0, 0.5 * i, j - 1.0, &px, &py));
            unsigned c = pixel(&im, px, py);
            if (j == 2 && i == 2) {
                assert_int_equal(c, 0xd9d9d9);
                continue;
            }
            assert_int_equal(c, qd_plot_map_color(z[j * NX + i] / 2));
            assert_true(lightness(c) > prev + 10); /* a clear step each cell along x */
            prev = lightness(c);
            if (j > 0)
                assert_int_equal(c, pixel(&im, px, py + 40)); /* the row below: same */
        }
    }
    cairo_surface_destroy(im.s);
    qd_plot_free(p);
    qd_ctx_free(ctx);
}

/* A constant map is drawn in the scale's middle colour. */
static void test_constant_map(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_plot *p = qd_plot_new(ctx, 400, 300);
    double x[2] = {0, 1}, y[2] = {0, 1}, z[4] = {3, 3, 3, 3};
    assert_int_equal(qd_plot_add_map(p, NULL, 2, 2, x, y, z), QD_OK);
    assert_int_equal(qd_plot_write(p, "test_plot_map_const.png"), QD_OK);
    double px, py;
    assert_true(qd_plot_to_pixel(p, 0, 0, 0, &px, &py));
    image im = load("test_plot_map_const.png");
    assert_int_equal(pixel(&im, px, py - 1), qd_plot_map_color(0.5));
    cairo_surface_destroy(im.s);
    qd_plot_free(p);
    qd_ctx_free(ctx);
}

static void test_map_errors(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_plot *p = qd_plot_new(ctx, 0, 0);
    double x[3] = {0, 1, 1}, y[2] = {0, 1}, z[6] = {0, 1, 2, 3, 4, 5};
    assert_int_equal(qd_plot_add_map(p, "z", 3, 2, x, y, z), QD_ERR_ARG); /* x repeats */
    assert_non_null(strstr(qd_ctx_diag(ctx)->message, "increasing"));
    x[2] = 2;
    z[4] = INFINITY;
    assert_int_equal(qd_plot_add_map(p, "z", 3, 2, x, y, z), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_diag(ctx)->message, "finite"));
    z[4] = 4;
    assert_int_equal(qd_plot_add_map(p, "z", 0, 2, x, y, z), QD_ERR_ARG);
    assert_int_equal(qd_plot_add_map(p, "z", 3, 2, x, y, z), QD_OK);
    assert_int_equal(qd_plot_add_map(p, "z", 3, 2, x, y, z), QD_ERR_ARG); /* a second */
    assert_int_equal(qd_plot_panels(p, 2, 1), QD_ERR_ARG); /* after the map */
    assert_false(qd_plot_map_range(p, 1, &z[0], &z[1]));
    qd_plot_free(p);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_scale),
        cmocka_unit_test(test_map_pixels),
        cmocka_unit_test(test_constant_map),
        cmocka_unit_test(test_map_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
