/*
 * tests/plot/test_plot.c - plots (qdot/plot.h) looked at in their pixels:
 * known curves (a sine, a straight line, a circle of points) drawn to PNG,
 * read back with Cairo, and the series' colour found where
 * qd_plot_to_pixel puts the data, background where no curve passes; the
 * 1-2-5 ticks against their definition; SVG and PDF by their magic; the
 * errors (extension, unwritable file, empty or non-finite data).
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

#define PI 3.14159265358979323846

/* ---- ticks ---- */

static void test_ticks_known(void **state) {
    (void)state;
    double step, first;
    /* 0..10 with at most 10: step 1 gives 11, so 2: 0, 2, ..., 10 */
    assert_int_equal(qd_plot_nice_ticks(0, 10, 10, &step, &first), 6);
    assert_true(step == 2 && first == 0);
    /* 0..1 with at most 5: 0.1 gives 11, 0.2 gives 6, so 0.5 */
    assert_int_equal(qd_plot_nice_ticks(0, 1, 5, &step, &first), 3);
    assert_true(fabs(step - 0.5) < 1e-15 && first == 0);
    /* -3.7..12.2 with at most 8: step 2 from -2 to 12 */
    assert_int_equal(qd_plot_nice_ticks(-3.7, 12.2, 8, &step, &first), 8);
    assert_true(step == 2 && first == -2);
    assert_int_equal(qd_plot_nice_ticks(1, 1, 8, &step, &first), 0);
    assert_int_equal(qd_plot_nice_ticks(0, INFINITY, 8, &step, &first), 0);
}

/* The step's mantissa is 1, 2 or 5, and the next smaller such step would
 * give too many ticks: checked on ranges across many decades. */
static bool one_two_five(double step) {
    double m = step / pow(10, floor(log10(step) + 1e-12));
    return fabs(m - 1) < 1e-9 || fabs(m - 2) < 1e-9 || fabs(m - 5) < 1e-9;
}

static double smaller_step(double step) {
    double d = pow(10, floor(log10(step) + 1e-12)), m = step / d;
    return m < 1.5 ? 0.5 * d : m < 3 ? d : 2 * d;
}

static size_t count_ticks(double lo, double hi, double s) {
    return (size_t)(floor(hi / s + 1e-9) - ceil(lo / s - 1e-9) + 1);
}

static void test_ticks_definition(void **state) {
    (void)state;
    unsigned seed = 12345;
    for (int trial = 0; trial < 2000; trial++) {
        seed = seed * 1103515245u + 12345u;
        double lo = ((double)(seed >> 8) / (1 << 24) - 0.5) * pow(10, (int)(seed % 13) - 6);
        seed = seed * 1103515245u + 12345u;
        double hi = lo + (double)((seed >> 8) + 1) / (1 << 24) * pow(10, (int)(seed % 13) - 6);
        size_t max = 2 + trial % 9;
        double step, first;
        size_t n = qd_plot_nice_ticks(lo, hi, max, &step, &first);
        assert_true(n >= 1 && n <= max);
        assert_true(one_two_five(step));
        assert_true(first >= lo - 1e-9 * step && first - step < lo);
        assert_true(first + (double)(n - 1) * step <= hi + 1e-9 * step);
        assert_true(count_ticks(lo, hi, smaller_step(step)) > max);
    }
}

/* ---- pixels ---- */

typedef struct image {
    cairo_surface_t *s;
    int w, h, stride;
    const unsigned char *data;
} image;

static image load(const char *path) {
    image im = {cairo_image_surface_create_from_png(path), 0, 0, 0, NULL};
    assert_int_equal(cairo_surface_status(im.s), CAIRO_STATUS_SUCCESS);
    im.w = cairo_image_surface_get_width(im.s);
    im.h = cairo_image_surface_get_height(im.s);
    im.stride = cairo_image_surface_get_stride(im.s);
    im.data = cairo_image_surface_get_data(im.s);
    return im;
}

static unsigned pixel(const image *im, int x, int y) {
    uint32_t v;
    memcpy(&v, im->data + (size_t)y * (size_t)im->stride + 4 * (size_t)x, 4);
    return v & 0xffffff; /* Cairo's native-endian xRGB */
}

static int color_dist(unsigned a, unsigned b) {
    int d = 0;
    for (int sh = 0; sh <= 16; sh += 8) {
        int c = (int)((a >> sh) & 255) - (int)((b >> sh) & 255);
        d = c < 0 ? (d > -c ? d : -c) : (d > c ? d : c);
    }
    return d;
}

/* The series colour within a pixel of (px, py) (the line is 2 px wide and
 * antialiased: its centre pixel may be a blend at a steep stretch). */
static bool has_color_near(const image *im, double px, double py, unsigned rgb) {
    int x0 = (int)floor(px), y0 = (int)floor(py);
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++)
            if (color_dist(pixel(im, x0 + dx, y0 + dy), rgb) <= 40)
                return true;
    return false;
}

static size_t count_non_white(const image *im) {
    size_t n = 0;
    for (int y = 0; y < im->h; y++)
        for (int x = 0; x < im->w; x++)
            n += pixel(im, x, y) != 0xffffff;
    return n;
}

#define NS 400

/* sin x on [0, 2 pi] and the line y = x/4 - 0.5: they cross near x = 0.7
 * and 3.1 (and not past x = 6), so the probes below keep clear of those. */
static qd_plot *sine_and_line(qd_ctx *c, size_t *isin, size_t *iline) {
    static double x[NS], s[NS], l[NS];
    for (int i = 0; i < NS; i++) {
        x[i] = 2 * PI * i / (NS - 1);
        s[i] = sin(x[i]);
        l[i] = x[i] / 4 - 0.5;
    }
    qd_plot *p = qd_plot_new(c, 0, 0);
    assert_non_null(p);
    assert_int_equal(qd_plot_set_title(p, "sine and line"), QD_OK);
    assert_int_equal(qd_plot_set_xlabel(p, "t (s)"), QD_OK);
    assert_int_equal(qd_plot_set_ylabel(p, "y"), QD_OK);
    assert_int_equal(qd_plot_add(p, "sin t", QD_PLOT_LINE, NS, x, s, isin), QD_OK);
    assert_int_equal(qd_plot_add(p, "t/4 - 1/2", QD_PLOT_LINE, NS, x, l, iline), QD_OK);
    return p;
}

static void test_png_curves(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    size_t is, il;
    qd_plot *p = sine_and_line(c, &is, &il);
    assert_int_equal(qd_plot_write(p, "test_plot_sine.png"), QD_OK);
    unsigned cs = qd_plot_color(p, is), cl = qd_plot_color(p, il);
    assert_true(color_dist(cs, cl) > 100);
    image im = load("test_plot_sine.png");
    assert_int_equal(im.w, 800);
    assert_int_equal(im.h, 500);
    size_t ink = count_non_white(&im);
    assert_true(ink > 2000 && ink < 800 * 500 / 4); /* drawn, mostly background */
    double x0, x1, y0, y1;
    assert_true(qd_plot_ranges(p, 0, &x0, &x1, &y0, &y1));
    assert_true(x0 <= 0 && x1 >= 2 * PI && y0 <= -1 && y1 >= 1.07);
    int probed = 0;
    for (double t = 0.2; t < 6.2; t += 0.1) {
        double px, py, qx, qy;
        assert_true(qd_plot_to_pixel(p, 0, t, sin(t), &px, &py));
        assert_true(qd_plot_to_pixel(p, 0, t, t / 4 - 0.5, &qx, &qy));
        if (fabs(py - qy) < 12)
            continue; /* near a crossing: either colour may be on top */
        assert_true(has_color_near(&im, px, py, cs));
        assert_true(has_color_near(&im, qx, qy, cl));
        /* 40 px above and below the sine: background, unless the line is there */
        for (int k = -1; k <= 1; k += 2) {
            double ry = py + 40 * k;
            double ty = ry, tx = px;
            if (fabs(ry - qy) < 12)
                continue;
            double ax, ay, bx, by; /* stay inside the plot area */
            qd_plot_to_pixel(p, 0, x1, y1, &ax, &ay);
            qd_plot_to_pixel(p, 0, x0, y0, &bx, &by);
            if (ry < ay + 3 || ry > by - 3)
                continue;
            assert_int_equal(pixel(&im, (int)tx, (int)ty), 0xffffff);
            probed++;
        }
    }
    assert_true(probed > 40);
    cairo_surface_destroy(im.s);
    qd_plot_free(p);
    qd_ctx_free(c);
}

/* The unit circle as points: each drawn where the map puts it, and the
 * centre left blank. */
static void test_png_points(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    double x[36], y[36];
    for (int i = 0; i < 36; i++) {
        x[i] = cos(2 * PI * i / 36);
        y[i] = sin(2 * PI * i / 36);
    }
    qd_plot *p = qd_plot_new(c, 400, 400);
    assert_int_equal(qd_plot_add(p, "section", QD_PLOT_POINTS, 36, x, y, NULL), QD_OK);
    assert_int_equal(qd_plot_write(p, "test_plot_points.png"), QD_OK);
    image im = load("test_plot_points.png");
    assert_int_equal(im.w, 400);
    assert_int_equal(im.h, 400);
    double px, py;
    for (int i = 0; i < 36; i++) {
        qd_plot_to_pixel(p, 0, x[i], y[i], &px, &py);
        assert_true(color_dist(pixel(&im, (int)px, (int)py), qd_plot_color(p, 0)) <= 40);
    }
    qd_plot_to_pixel(p, 0, 0, 0, &px, &py);
    assert_int_equal(pixel(&im, (int)px, (int)py), 0xffffff);
    qd_plot_to_pixel(p, 0, 0.5, 0.5, &px, &py);
    assert_int_equal(pixel(&im, (int)px, (int)py), 0xffffff);
    cairo_surface_destroy(im.s);
    qd_plot_free(p);
    qd_ctx_free(c);
}

/* Two panels stacked: each series where its own panel's map puts it, and
 * the second panel's ranges its own data's. */
static void test_panels(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    double x[NS], s[NS], e[NS];
    for (int i = 0; i < NS; i++) {
        x[i] = 10.0 * i / (NS - 1);
        s[i] = sin(x[i]);
        e[i] = 1e-9 * x[i]; /* a drift, as an energy error */
    }
    qd_plot *p = qd_plot_new(c, 800, 600);
    assert_int_equal(qd_plot_panels(p, 2, 1), QD_OK);
    assert_int_equal(qd_plot_npanels(p), 2);
    assert_int_equal(qd_plot_add(p, "sin t", QD_PLOT_LINE, NS, x, s, NULL), QD_OK);
    assert_int_equal(qd_plot_select(p, 1), QD_OK);
    assert_int_equal(qd_plot_add(p, "drift", QD_PLOT_LINE, NS, x, e, NULL), QD_OK);
    assert_int_equal(qd_plot_select(p, 2), QD_ERR_ARG);
    qd_ctx_clear_error(c);
    assert_int_equal(qd_plot_panels(p, 1, 2), QD_ERR_ARG); /* after series */
    qd_ctx_clear_error(c);
    assert_int_equal(qd_plot_write(p, "test_plot_panels.png"), QD_OK);
    double x0, x1, y0, y1;
    assert_true(qd_plot_ranges(p, 1, &x0, &x1, &y0, &y1));
    assert_true(y0 <= 0 && y1 >= 1e-8 && y1 < 1.3e-8);
    image im = load("test_plot_panels.png");
    unsigned col = qd_plot_color(p, 0);
    assert_int_equal(col, qd_plot_color(p, 1)); /* each panel's first colour */
    for (int i = 10; i < NS - 10; i += 10) {
        double px, py, qx, qy;
        qd_plot_to_pixel(p, 0, x[i], s[i], &px, &py);
        qd_plot_to_pixel(p, 1, x[i], e[i], &qx, &qy);
        assert_true(has_color_near(&im, px, py, col));
        assert_true(has_color_near(&im, qx, qy, col));
        assert_true(qy > 300 && py < 300); /* second panel below the first */
    }
    cairo_surface_destroy(im.s);
    qd_plot_free(p);
    qd_ctx_free(c);
}

/* Equal axes: a unit is as many pixels along y as along x, even for data
 * far wider than high (a line of particles with a tiny sideways offset). */
static void test_equal_axes(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    double x[2] = {0, 4}, y[2] = {0, 1e-30};
    qd_plot *p = qd_plot_new(c, 0, 0);
    assert_int_equal(qd_plot_set_equal_axes(p, true), QD_OK);
    assert_int_equal(qd_plot_add(p, "rod", QD_PLOT_LINE_POINTS, 2, x, y, NULL), QD_OK);
    assert_int_equal(qd_plot_layout(p), QD_OK);
    double ax, ay, bx, by, cx, cy;
    qd_plot_to_pixel(p, 0, 0, 0, &ax, &ay);
    qd_plot_to_pixel(p, 0, 1, 0, &bx, &by);
    qd_plot_to_pixel(p, 0, 0, 1, &cx, &cy);
    assert_true(fabs((bx - ax) - (ay - cy)) < 1e-9 * (bx - ax));
    assert_true(bx - ax > 100);
    qd_plot_free(p);
    qd_ctx_free(c);
}

/* ---- SVG, PDF ---- */

static size_t read_head(const char *path, char *buf, size_t cap) {
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    size_t n = fread(buf, 1, cap - 1, f);
    fseek(f, 0, SEEK_END);
    long size = ftell(f);
    fclose(f);
    buf[n] = 0;
    return (size_t)size;
}

static void test_svg_pdf(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    size_t is, il;
    qd_plot *p = sine_and_line(c, &is, &il);
    char head[64];
    assert_int_equal(qd_plot_write(p, "test_plot_sine.svg"), QD_OK);
    assert_true(read_head("test_plot_sine.svg", head, sizeof head) > 5000);
    assert_true(strstr(head, "<?xml") == head || strstr(head, "<svg") != NULL);
    assert_int_equal(qd_plot_write(p, "test_plot_sine.PDF"), QD_OK);
    assert_true(read_head("test_plot_sine.PDF", head, sizeof head) > 2000);
    assert_memory_equal(head, "%PDF-", 5);
    qd_plot_free(p);
    qd_ctx_free(c);
}

/* ---- errors ---- */

static void test_errors(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    double x[2] = {0, 1}, y[2] = {0, NAN};
    qd_plot *p = qd_plot_new(c, 0, 0);
    assert_int_equal(qd_plot_write(p, "test_plot_empty.png"), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(c), "at least one series"));
    qd_ctx_clear_error(c);
    assert_int_equal(qd_plot_add(p, "a", QD_PLOT_LINE, 0, x, y, NULL), QD_ERR_ARG);
    qd_ctx_clear_error(c);
    assert_int_equal(qd_plot_add(p, "a", QD_PLOT_LINE, 2, x, y, NULL), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(c), "not finite"));
    qd_ctx_clear_error(c);
    assert_int_equal(qd_plot_nseries(p), 0);
    y[1] = 1;
    assert_int_equal(qd_plot_add(p, "a", QD_PLOT_LINE, 2, x, y, NULL), QD_OK);
    assert_int_equal(qd_plot_write(p, "test_plot.jpg"), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(c), ".png, .svg or .pdf"));
    qd_ctx_clear_error(c);
    assert_int_equal(qd_plot_write(p, "no-such-dir/x.png"), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(c), "cannot write no-such-dir/x.png: "));
    qd_ctx_clear_error(c);
    assert_null(qd_plot_new(c, 10, 10));
    assert_int_equal(qd_ctx_status(c), QD_ERR_ARG);
    qd_plot_free(p);
    qd_ctx_free(c);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ticks_known),  cmocka_unit_test(test_ticks_definition),
        cmocka_unit_test(test_png_curves),   cmocka_unit_test(test_png_points),
        cmocka_unit_test(test_panels),       cmocka_unit_test(test_equal_axes),
        cmocka_unit_test(test_svg_pdf),      cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
