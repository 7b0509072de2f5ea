/*
 * tests/plot/test_plot_fault.c - a two-panel plot built and written with
 * every allocation made to fail in turn (tests/util/fault.h): each run ends
 * with the picture written and right (the sine's colour where the map puts
 * it) or a clean QD_ERR_NOMEM, with every block given back.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <cairo.h>
#include <math.h>
#include <string.h>

#include "qdot/qdot.h"
#include "util/fault.h"

#define N 50

/* The pixel at (px, py) of the PNG just written, as 0xRRGGBB. */
static unsigned pixel_at(const char *path, double px, double py) {
    cairo_surface_t *s = cairo_image_surface_create_from_png(path);
    assert_int_equal(cairo_surface_status(s), CAIRO_STATUS_SUCCESS);
    uint32_t v;
    memcpy(&v, cairo_image_surface_get_data(s) +
                    (size_t)py * (size_t)cairo_image_surface_get_stride(s) + 4 * (size_t)px, 4);
    cairo_surface_destroy(s);
    return v & 0xffffff;
}

static qd_status build(qd_plot *p, const double *x, const double *y) {
    qd_status st = qd_plot_panels(p, 2, 1);
    if (st == QD_OK)
        st = qd_plot_set_title(p, "faults");
    if (st == QD_OK)
        st = qd_plot_set_xlabel(p, "t (s)");
    if (st == QD_OK)
        st = qd_plot_add(p, "sin t", QD_PLOT_LINE, N, x, y, NULL);
    if (st == QD_OK)
        st = qd_plot_select(p, 1);
    if (st == QD_OK)
        st = qd_plot_set_ylabel(p, "dots");
    if (st == QD_OK)
        st = qd_plot_add(p, "dots", QD_PLOT_POINTS, N, x, y, NULL);
    return st;
}

static qd_status plot_body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)f, (void)data;
    double x[N], y[N];
    for (int i = 0; i < N; i++) {
        x[i] = 6.0 * i / (N - 1);
        y[i] = sin(x[i]);
    }
    qd_plot *p = qd_plot_new(ctx, 0, 0);
    if (!p)
        return qd_ctx_status(ctx);
    qd_status st = build(p, x, y);
    if (st == QD_OK)
        st = qd_plot_write(p, "test_plot_fault.png");
    if (st == QD_OK) {
        double px, py;
        assert_true(qd_plot_to_pixel(p, 0, x[N / 3], y[N / 3], &px, &py));
        assert_int_equal(pixel_at("test_plot_fault.png", px, py), qd_plot_color(p, 0));
    }
    qd_plot_free(p);
    return st;
}

static void test_plot_faults(void **state) {
    (void)state;
    qt_fault_stats ls = qt_fault_loop("two-panel plot", plot_body, NULL, 1);
    assert_true(ls.runs > 8); /* every allocation of the plot refused once */
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_plot_faults),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
