/*
 * tests/plot/test_plot_run.c - a run's rows drawn (qd_plot_pick_columns,
 * qd_plot_run, qd_plot_size_of): the columns --plot-y and --phase pick, the
 * panels a semicolon makes, energy_error as E - E(t0); the rows of the
 * circle x = cos t, y = sin t drawn in phase (x', x) fill [-1, 1] on both
 * axes (the axes frame the data); bad names and sizes refused naming the
 * option field.
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
#include "qdot/plot.h"

static const char *const names[] = {"t", "x", "y", "x'", "y'", "energy"};

static void test_pick(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_plot_pick pk;
    assert_int_equal(qd_plot_pick_columns(ctx, NULL, NULL, names, 6, 2, &pk), QD_OK);
    assert_true(pk.ny == 2 && pk.y[0] == 1 && pk.y[1] == 2 && pk.npanels == 1 && pk.x == 0);
    assert_int_equal(qd_plot_pick_columns(ctx, "x, y; energy_error;", NULL, names, 6, 2, &pk),
                     QD_OK);
    assert_true(pk.ny == 3 && pk.npanels == 2 && pk.panel[2] == 1 && pk.y[2] == 6);
    assert_true(pk.energy_error && pk.energy == 5);
    assert_int_equal(qd_plot_pick_columns(ctx, NULL, "x", names, 6, 2, &pk), QD_OK);
    assert_true(pk.phase && pk.x == 1 && pk.y[0] == 3);
    assert_int_equal(qd_plot_pick_columns(ctx, "z", NULL, names, 6, 2, &pk), QD_ERR_ARG);
    assert_string_equal(qd_ctx_diag(ctx)->name, "plot_y");
    qd_ctx_clear_error(ctx);
    assert_int_equal(qd_plot_pick_columns(ctx, NULL, "t", names, 6, 2, &pk), QD_ERR_ARG);
    assert_string_equal(qd_ctx_diag(ctx)->name, "phase");
    qd_ctx_clear_error(ctx);
    int w, h;
    assert_int_equal(qd_plot_size_of(ctx, "1200x800", &w, &h), QD_OK);
    assert_true(w == 1200 && h == 800);
    assert_int_equal(qd_plot_size_of(ctx, "50x50", &w, &h), QD_ERR_ARG);
    assert_string_equal(qd_ctx_diag(ctx)->name, "size");
    qd_ctx_clear_error(ctx);
    assert_int_equal(qd_plot_size_of(ctx, "1200x800x3", &w, &h), QD_ERR_ARG);
    qd_ctx_free(ctx);
}

static void test_run(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    enum { N = 2001 };
    double *rows = malloc(N * 6 * sizeof *rows);
    for (size_t k = 0; k < N; k++) {
        double t = 2 * 3.14159265358979323846 * (double)k / (N - 1);
        double r[6] = {t, cos(t), sin(t), -sin(t), cos(t), 0.5};
        memcpy(rows + 6 * k, r, sizeof r);
    }
    qd_plot_pick pk;
    assert_int_equal(qd_plot_pick_columns(ctx, NULL, "x", names, 6, 2, &pk), QD_OK);
    qd_plot_run_opts o = {.title = "circle"};
    qd_plot *p = qd_plot_run(ctx, &pk, names, rows, N, 6, &o);
    assert_non_null(p);
    assert_int_equal(qd_plot_nseries(p), 1);
    assert_int_equal(qd_plot_layout(p), QD_OK);
    double x0, x1, y0, y1;
    assert_true(qd_plot_ranges(p, 0, &x0, &x1, &y0, &y1));
    assert_true(x0 <= -1 + 1e-9 && x1 >= 1 - 1e-9 && y0 <= -1 + 1e-9 && y1 >= 1 - 1e-9);
    assert_true(x1 - x0 < 3 && y1 - y0 < 3);
    qd_plot_free(p);
    /* two panels, energy_error E - E(t0) = 0 in the second */
    assert_int_equal(qd_plot_pick_columns(ctx, "x, y; energy_error", NULL, names, 6, 2, &pk),
                     QD_OK);
    p = qd_plot_run(ctx, &pk, names, rows, N, 6, &o);
    assert_non_null(p);
    assert_int_equal(qd_plot_npanels(p), 2);
    assert_int_equal(qd_plot_nseries(p), 3);
    qd_plot_free(p);
    assert_null(qd_plot_run(ctx, &pk, names, rows, 0, 6, &o)); /* no rows */
    free(rows);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pick),
        cmocka_unit_test(test_run),
    };
    return cmocka_run_group_tests(tests, 0, NULL);
}
