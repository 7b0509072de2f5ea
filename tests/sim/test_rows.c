/*
 * tests/sim/test_rows.c - what a run's rows carry, as `qdot simulate`
 * writes them (qdot/sim.h, src/sim/rows.c), on the oscillator m x'' = -k x
 * (w = sqrt(k/m) = 2; Goldstein sec.
 * 1.6), x = A sin(w t), A = 0.7, from x = 0, x' = w A:
 *   - the event column comes with an event or an impact, not without;
 *   - "columns" names t, x, x' and the energy, and "event" after them;
 *   - a run only drawn is sampled on a grid of its dense output: the rows
 *     are equally spaced, and their largest |x| is the amplitude A to the
 *     grid's (w h)^2 / 8, where the steps of a loose run miss the crests;
 *   - the picture's JSON holds the panels' ranges qd_plot_ranges gives,
 *     and the y range covers [-A, A].
 */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <setjmp.h>
#include <string.h>
#include <cmocka.h>

#include "qdot/qdot.h"
#include "qdot/plot.h"
#include "qdot/simsetup.h"
#include "util/jsonwalk.h"

static const char osc[] = "coordinates x\nparameters m = 2, k = 8\n"
                          "T = m/2*x'^2\nV = k/2*x^2\ninitial x = 0, x' = 1.4\n";
static const char wall[] = "coordinates x\nparameters m = 2, k = 8\n"
                           "T = m/2*x'^2\nV = k/2*x^2\ninitial x = 0.7\n"
                           "impact wall: x + 1 >= 0 restitution 1\n";

typedef struct kept {
    size_t n, cap, ncols;
    double *rows;
} kept;

static int keep(void *data, int event, const double *row) {
    (void)event;
    kept *k = data;
    if (k->n == k->cap) {
        k->cap = k->cap ? 2 * k->cap : 256;
        k->rows = realloc(k->rows, k->cap * k->ncols * sizeof *k->rows);
        assert_non_null(k->rows);
    }
    memcpy(k->rows + k->n++ * k->ncols, row, k->ncols * sizeof *row);
    return 0;
}

typedef struct setup {
    qd_ctx *ctx;
    qd_model *m;
    qd_sim_setup *s;
    qd_sim_opts o;
} setup;

static void open_setup(setup *u, const char *text, const char *rtol) {
    u->ctx = qd_ctx_new();
    u->m = qd_model_parse(u->ctx, text, NULL);
    assert_non_null(u->m);
    u->s = qd_sim_setup_new(u->ctx, u->m, false);
    assert_non_null(u->s);
    qd_sim_setup_opts so = {.t_end = "10", .rtol = rtol, .atol = "1e-6"};
    assert_int_equal(qd_sim_setup_options(u->s, &so, &u->o), QD_OK);
}

static void close_setup(setup *u) {
    qd_sim_setup_free(u->s);
    qd_model_free(u->m);
    qd_ctx_free(u->ctx);
}

static void test_event_column(void **state) {
    (void)state;
    setup u;
    open_setup(&u, osc, NULL);
    qd_sim *s = qd_sim_setup_sim(u.s);
    assert_false(qd_sim_event_column(s));
    qd_buf b = QD_BUF_INIT;
    qd_json j;
    qd_json_init(&j, &b);
    qd_json_begin_object(&j);
    assert_int_equal(qd_sim_columns_json(&j, s, u.o.method), QD_OK);
    qd_json_end_object(&j);
    assert_true(qt_json_valid(qd_buf_str(&b)));
    const char *cols = qt_json_get(qd_buf_str(&b), "columns");
    static const char *const want[] = {"t", "x", "x'", "energy"};
    assert_int_equal(qt_json_len(cols), 4);
    for (size_t i = 0; i < 4; i++)
        assert_true(qt_json_str_is(qt_json_at(cols, i), want[i]));
    qd_buf_free(&b);
    /* an event (x crossing 0 downwards) adds the column, last */
    assert_int_equal(qd_sim_setup_event(u.s, "x = 0, x' < 0", false), QD_OK);
    assert_true(qd_sim_event_column(s));
    b = (qd_buf)QD_BUF_INIT;
    qd_json_init(&j, &b);
    qd_json_begin_object(&j);
    assert_int_equal(qd_sim_columns_json(&j, s, u.o.method), QD_OK);
    qd_json_end_object(&j);
    cols = qt_json_get(qd_buf_str(&b), "columns");
    assert_int_equal(qt_json_len(cols), 5);
    assert_true(qt_json_str_is(qt_json_at(cols, 4), "event"));
    qd_buf_free(&b);
    close_setup(&u);
    /* so does an impact of the model, with no event given */
    open_setup(&u, wall, NULL);
    assert_true(qd_sim_event_column(qd_sim_setup_sim(u.s)));
    close_setup(&u);
}

/* The largest |x| of a run of the oscillator at rtol, and the rows. */
static double crest(setup *u, kept *k) {
    qd_sim *s = qd_sim_setup_sim(u->s);
    k->ncols = qd_sim_columns(s, u->o.method, NULL, 0);
    qd_sim_stats st;
    assert_int_equal(qd_sim_run(s, &u->o, keep, k, &st, NULL), QD_OK);
    double top = 0;
    for (size_t i = 0; i < k->n; i++)
        top = fmax(top, fabs(k->rows[i * k->ncols + 1]));
    return top;
}

static void test_sample_and_plot(void **state) {
    (void)state;
    const double A = 0.7, w = 2;
    setup u;
    /* loose steps: the rows are the steps, far apart, and miss the crests */
    open_setup(&u, osc, "1e-4");
    kept steps = {0};
    double top_steps = crest(&u, &steps);
    assert_true(steps.n < 200);
    free(steps.rows);
    /* sampled: 1001 rows h = 10/1000 apart, the crest to (w h)^2 / 8 */
    qd_sim_opts_sample(&u.o, 1000);
    assert_true(fabs(u.o.dt - 0.01) < 1e-15);
    kept grid = {0};
    double top = crest(&u, &grid);
    assert_int_equal(grid.n, 1001);
    for (size_t i = 1; i < grid.n; i++)
        assert_true(fabs(grid.rows[i * grid.ncols] - grid.rows[(i - 1) * grid.ncols] - 0.01) <
                    1e-12);
    double h = 0.01;
    assert_true(A - top <= A * (w * h) * (w * h) / 8 + 1e-6 && top <= A + 1e-4);
    assert_true(A - top_steps > 10 * (A - top)); /* the steps' rows missed the crest */
    /* a grid already given is kept */
    qd_sim_opts o2 = u.o;
    o2.dt = 0.5;
    qd_sim_opts_sample(&o2, 1000);
    assert_true(o2.dt == 0.5);
    /* the picture of x against t, and its JSON */
    const char *names[8];
    size_t nc = qd_sim_columns(qd_sim_setup_sim(u.s), u.o.method, names, 8);
    qd_plot_pick pk;
    assert_int_equal(qd_plot_pick_columns(u.ctx, NULL, NULL, names, nc, 1, &pk), QD_OK);
    qd_plot_run_opts po = {0};
    qd_plot *p = qd_plot_run(u.ctx, &pk, names, grid.rows, grid.n, nc, &po);
    assert_non_null(p);
    assert_int_equal(qd_plot_layout(p), QD_OK);
    double range[4];
    assert_true(qd_plot_ranges(p, 0, &range[0], &range[1], &range[2], &range[3]));
    qd_buf b = QD_BUF_INIT;
    qd_json j;
    qd_json_init(&j, &b);
    qd_json_begin_object(&j);
    assert_int_equal(qd_sim_plot_json(&j, "x.svg", pk.npanels, range), QD_OK);
    qd_json_end_object(&j);
    assert_true(qt_json_valid(qd_buf_str(&b)));
    const char *plot = qt_json_get(qd_buf_str(&b), "plot");
    assert_true(qt_json_str_is(qt_json_get(plot, "file"), "x.svg"));
    const char *panels = qt_json_get(plot, "panels");
    assert_int_equal(qt_json_len(panels), 1);
    const char *p0 = qt_json_at(panels, 0);
    assert_true(qt_json_num(qt_json_get(p0, "x0")) <= 0);
    assert_true(qt_json_num(qt_json_get(p0, "x1")) >= 10);
    assert_true(qt_json_num(qt_json_get(p0, "y0")) <= -top);
    assert_true(qt_json_num(qt_json_get(p0, "y1")) >= top);
    qd_buf_free(&b);
    qd_plot_free(p);
    free(grid.rows);
    close_setup(&u);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_event_column),
        cmocka_unit_test(test_sample_and_plot),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
