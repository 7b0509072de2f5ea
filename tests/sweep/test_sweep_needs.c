/*
 * tests/sweep/test_sweep_needs.c - what a sweep's measures ask of the run
 * (qd_sweep_needs, qd_sweep_prepare) and the grid's colour map
 * (qd_sweep_map_column, qd_sweep_map):
 *
 *   - the needs of a measure list: one output per expression read (not one
 *     that a run's column or an earlier measure gives), an escape's crossing,
 *     the flags of event, poincare-count and the Lyapunov measures;
 *   - prepared, the free particle x = v t: escape:x>1 at t = 1/v exactly
 *     (the crossing is an event, located to round-off), max:x^2 = (v T)^2;
 *     an error in an expression located in the measure text;
 *   - the map of the oscillator's period 2 pi sqrt(m/k) over a grid in
 *     (k, m): its range the least and greatest period, its axes the grid's;
 *     a random sweep and an unknown measure refused, naming the option field;
 *   - the runs from CSV text (qd_sweep_list_csv): the file's order, blank
 *     lines skipped, the oscillator's final x = v sin(w T)/w with w =
 *     sqrt(k); a field that is not a number located at its line and column;
 *   - the rows written (qd_sweep_csv, qd_sweep_json): read back, the free
 *     particle's final x = v T in every row, a failed run's reason in its
 *     status, JSON's null where a measure has no value.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "qdot/plot.h"
#include "qdot/sweep.h"
#include "sim/sim_fixture.h"

static bool need_is(const char *spec, const qd_sweep_need *x, qd_sweep_need_kind kind,
                    const char *expr, const char *value) {
    return x->kind == kind && x->e1 - x->e0 == strlen(expr) &&
           !strncmp(spec + x->e0, expr, strlen(expr)) &&
           (!value || (x->v1 - x->v0 == strlen(value) && !strncmp(spec + x->v0, value, strlen(value))));
}

static void test_needs(void **state) {
    (void)state;
    const char *spec = "final, max: x^2 , min:x^2, escape: x > 0.5, event, poincare-count, "
                       "lyapunov, max:f(x, y)";
    unsigned flags = 0;
    size_t n = qd_sweep_needs(NULL, spec, NULL, 0, &flags);
    qd_sweep_need needs[8];
    assert_int_equal(qd_sweep_needs(NULL, spec, needs, 8, &flags), n);
    assert_int_equal(n, 4); /* x^2 once, x and its crossing, f(x, y) */
    assert_true(need_is(spec, &needs[0], QD_SWEEP_NEED_OUTPUT, "x^2", NULL));
    assert_true(need_is(spec, &needs[1], QD_SWEEP_NEED_OUTPUT, "x", NULL));
    assert_true(need_is(spec, &needs[2], QD_SWEEP_NEED_CROSSING, "x", "0.5"));
    assert_true(need_is(spec, &needs[3], QD_SWEEP_NEED_OUTPUT, "f(x, y)", NULL));
    assert_int_equal(flags, QD_SWEEP_NEEDS_EVENT | QD_SWEEP_NEEDS_SECTION | QD_SWEEP_NEEDS_LYAP);
    /* a run whose column x is there: no output for it, the crossing still */
    sim_fix *f = sf_load("coordinates x\nT = x'^2/2\ninitial x = 0, x' = 1\n");
    assert_int_equal(qd_sweep_needs(f->s, "escape:x>1, max:x", needs, 8, &flags), 1);
    assert_true(need_is("escape:x>1, max:x", &needs[0], QD_SWEEP_NEED_CROSSING, "x", "1"));
    assert_int_equal(flags, 0);
    /* malformed measures need nothing (qd_sweep_measures says why) */
    assert_int_equal(qd_sweep_needs(NULL, "escape:x, max:, bogus", needs, 8, &flags), 0);
    sf_free(f);
}

static void test_prepare_free_particle(void **state) {
    (void)state;
    sim_fix *f = sf_load("coordinates x\nparameters m = 1\nT = m*x'^2/2\ninitial x = 0\n");
    const char *spec = "escape:x>1, max:x^2";
    assert_int_equal(qd_sweep_prepare(f->ctx, f->s, spec, NULL, NULL), QD_OK);
    assert_int_equal(qd_sim_compile(f->s), QD_OK);
    qd_sweep *w = qd_sweep_new(f->ctx, f->s, f->m);
    assert_non_null(w);
    assert_int_equal(qd_sweep_grid(w, "x' = 0.5:2:4"), QD_OK);
    assert_int_equal(qd_sweep_measures(w, spec), QD_OK);
    double T = 2.5, row[3];
    qd_sim_opts o = {.method = QD_SIM_DOP853, .t_end = T, .rtol = 1e-12, .atol = 1e-14,
                     .q0 = f->q0, .qd0 = f->qd0};
    for (size_t i = 0; i < 4; i++) {
        assert_int_equal(qd_sweep_run_one(f->ctx, w, &o, i, row, NULL), QD_OK);
        double v = row[0];
        assert_true(fabs(row[1] - 1 / v) < 1e-12);
        assert_true(fabs(row[2] - v * T * v * T) < 1e-9 * v * T * v * T);
    }
    qd_sweep_free(w);
    sf_free(f);
    /* an error in an expression: located in the measure text */
    f = sf_load("coordinates x\nT = x'^2/2\ninitial x = 0, x' = 1\n");
    const char *bad = "final, max:x+*2";
    assert_int_equal(qd_sweep_prepare(f->ctx, f->s, bad, NULL, NULL), QD_ERR_PARSE);
    const qd_diag *d = qd_ctx_diag(f->ctx);
    assert_true(d->located);
    assert_true(d->offset >= 11 && d->offset < strlen(bad));
    sf_free(f);
}

/* The oscillator x'' = -(k/m) x from x = 0, x' = 1: the first upward
 * crossing of x = 0 after the start is the period 2 pi sqrt(m/k). */
static void test_map(void **state) {
    (void)state;
    sim_fix *f = sf_load("coordinates x\nparameters k = 1, m = 1\nT = m*x'^2/2\nV = k*x^2/2\n"
                         "initial x = 0, x' = 1\n");
    const qd_expr *g = qd_model_coord(f->m, 0), *up = f->e->qd[0];
    assert_int_equal(qd_sim_add_event(f->s, g, 1, &up, false), QD_OK);
    assert_int_equal(qd_sim_compile(f->s), QD_OK);
    qd_sweep *w = qd_sweep_new(f->ctx, f->s, f->m);
    assert_int_equal(qd_sweep_grid(w, "k = 1:4:4, m = 1:2:3"), QD_OK);
    assert_int_equal(qd_sweep_measures(w, "energy_error, event"), QD_OK);
    size_t col = 0;
    assert_int_equal(qd_sweep_map_column(w, NULL, &col), QD_OK);
    assert_int_equal(col, 2);
    assert_int_equal(qd_sweep_map_column(w, "event_t", &col), QD_OK);
    assert_int_equal(col, 3);
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_sweep_map_column(w, "k", &col), QD_ERR_ARG); /* an input */
    assert_string_equal(qd_ctx_diag(f->ctx)->name, "map_measure");
    size_t nruns = qd_sweep_nruns(w), ncols = qd_sweep_ncols(w);
    double *rows = malloc(nruns * ncols * sizeof *rows);
    qd_sweep_outcome st[12];
    qd_sim_opts o = {.method = QD_SIM_DOP853, .t_end = 10, .rtol = 1e-12, .atol = 1e-14,
                     .q0 = f->q0, .qd0 = f->qd0};
    assert_int_equal(nruns, 12);
    assert_int_equal(qd_sweep_run(f->ctx, w, &o, 0, nruns, 1, rows, st, NULL, NULL), QD_OK);
    qd_plot *p = qd_plot_new(f->ctx, 0, 0);
    assert_int_equal(qd_sweep_map(w, rows, col, p), QD_OK);
    double z0, z1, x0, x1, y0, y1;
    assert_true(qd_plot_map_range(p, 0, &z0, &z1));
    assert_true(fabs(z0 - 2 * SF_PI * sqrt(1.0 / 4)) < 1e-9); /* k = 4, m = 1 */
    assert_true(fabs(z1 - 2 * SF_PI * sqrt(2.0 / 1)) < 1e-9); /* k = 1, m = 2 */
    /* the cells reach halfway to their neighbours: k from 0.5 to 4.5, m from 0.75 to 2.25 */
    assert_int_equal(qd_plot_layout(p), QD_OK);
    assert_true(qd_plot_ranges(p, 0, &x0, &x1, &y0, &y1));
    assert_true(fabs(x0 - 0.5) < 1e-12 && fabs(x1 - 4.5) < 1e-12);
    assert_true(fabs(y0 - 0.75) < 1e-12 && fabs(y1 - 2.25) < 1e-12);
    /* the labels: k and m state no unit; the period is a time */
    const char *xl, *yl, *bar;
    assert_true(qd_plot_labels(p, 0, &xl, &yl, &bar));
    assert_string_equal(xl, "k");
    assert_string_equal(yl, "m");
    assert_string_equal(bar, "event_t (s)");
    qd_plot_free(p);
    free(rows);
    /* a random draw is no grid */
    assert_int_equal(qd_sweep_random(w, "k = 1:4, m = 1:2", 4, 1), QD_OK);
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_sweep_map_column(w, NULL, &col), QD_ERR_ARG);
    assert_string_equal(qd_ctx_diag(f->ctx)->name, "map");
    /* nor a grid of one axis */
    assert_int_equal(qd_sweep_grid(w, "k = 1:4:4"), QD_OK);
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_sweep_map_column(w, NULL, &col), QD_ERR_ARG);
    qd_sweep_free(w);
    sf_free(f);
}

static void test_list_csv(void **state) {
    (void)state;
    sim_fix *f = sf_load("coordinates x\nparameters k = 1\nT = x'^2/2\nV = k*x^2/2\n"
                         "initial x = 0, x' = 1\n");
    assert_int_equal(qd_sim_compile(f->s), QD_OK);
    qd_sweep *w = qd_sweep_new(f->ctx, f->s, f->m);
    assert_int_equal(qd_sweep_list_csv(w, " k , x'\r\n4, 0.5\n\n  \n1,2\n9,1"), QD_OK);
    assert_int_equal(qd_sweep_nruns(w), 3);
    assert_int_equal(qd_sweep_measures(w, "final"), QD_OK);
    double row[4], want[3][2] = {{4, 0.5}, {1, 2}, {9, 1}}, T = 1.5;
    qd_sim_opts o = {.method = QD_SIM_DOP853, .t_end = T, .rtol = 1e-12, .atol = 1e-14,
                     .q0 = f->q0, .qd0 = f->qd0};
    for (size_t i = 0; i < 3; i++) {
        assert_int_equal(qd_sweep_run_one(f->ctx, w, &o, i, row, NULL), QD_OK);
        assert_true(row[0] == want[i][0] && row[1] == want[i][1]);
        double om = sqrt(row[0]);
        assert_true(fabs(row[2] - row[1] * sin(om * T) / om) < 1e-9);
    }
    const char *bad = "k,x'\n1,2\n3, y\n";
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_sweep_list_csv(w, bad), QD_ERR_PARSE);
    const qd_diag *d = qd_ctx_diag(f->ctx);
    assert_true(d->located);
    assert_int_equal(d->line, 3);
    assert_int_equal(d->col, 4); /* under the y */
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_sweep_list_csv(w, "k,x'\n1,2,3\n"), QD_ERR_PARSE);
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_sweep_list_csv(w, "k,x'\n"), QD_ERR_PARSE); /* no row */
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_sweep_list_csv(w, "k,z\n1,2\n"), QD_ERR_ARG); /* no input z */
    qd_sweep_free(w);
    sf_free(f);
}

static void test_write(void **state) {
    (void)state;
    sim_fix *f = sf_load("coordinates x\nT = x'^2/2\ninitial x = 0\n");
    assert_int_equal(qd_sim_compile(f->s), QD_OK);
    qd_sweep *w = qd_sweep_new(f->ctx, f->s, f->m);
    assert_int_equal(qd_sweep_grid(w, "x' = 1:3:3"), QD_OK);
    assert_int_equal(qd_sweep_measures(w, "final, escape:x>2.5"), QD_OK);
    double rows[3 * 4], T = 2;
    qd_sweep_outcome st[3];
    qd_sim_opts o = {.method = QD_SIM_DOP853, .t_end = T, .rtol = 1e-12, .atol = 1e-14,
                     .q0 = f->q0, .qd0 = f->qd0};
    assert_int_equal(qd_sweep_run(f->ctx, w, &o, 0, 3, 1, rows, st, NULL, NULL), QD_OK);
    assert_true(st[0].stop.code == QD_STOP_END && st[0].stop.t == T);
    /* as if the last had failed: the row says so in words made from the code */
    st[2] = (qd_sweep_outcome){QD_ERR_SINGULAR, {QD_STOP_SINGULAR, 1.5, NAN}};
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_sweep_csv(w, rows, st, &b), QD_OK);
    const char *text = qd_buf_str(&b);
    assert_true(!strncmp(text, "x',final_x,final_x',escape:x>2.5,status\n", 40));
    const char *line = strchr(text, '\n') + 1;
    for (size_t k = 0; k < 3; k++) {
        char *end;
        double v = strtod(line, &end), x = strtod(end + 1, &end);
        assert_true(v == 1.0 + (double)k);
        assert_true(fabs(x - v * T) < 1e-9); /* x = v t */
        line = strchr(line, '\n') + 1;
    }
    assert_non_null(strstr(text, ",ok\n"));
    assert_non_null(strstr(text, ",singular equations at t = 1.5\n"));
    qd_buf_free(&b);
    b = (qd_buf)QD_BUF_INIT;
    assert_int_equal(qd_sweep_json(w, rows, st, &b), QD_OK);
    text = qd_buf_str(&b);
    assert_non_null(strstr(text, "\"columns\""));
    assert_non_null(strstr(text, "null")); /* v = 1 never passes 2.5 by t = 2 */
    assert_null(strstr(text, "nan"));
    /* the stop record per run, the keys of Python's Result.stop */
    assert_non_null(strstr(text, "\"reason\": \"singular equations\""));
    assert_non_null(strstr(text, "\"reason\": \"reached the end time\""));
    assert_non_null(strstr(text, "\"t\": 1.5"));
    assert_non_null(strstr(text, "\"code\": \"singular\""));
    assert_non_null(strstr(text, "\"ok\": false"));
    qd_buf_free(&b);
    qd_sweep_free(w);
    sf_free(f);
}

/* A pendulum's map over (theta, theta'): theta is an angle (the bob's
 * position and V repeat in 2 pi), so its axis says rad, its velocity's
 * rad/s, and a measure reading theta' (max:theta') has theta''s unit; a
 * Lyapunov exponent is a rate, 1/s, and so is its error. */
static void test_map_units(void **state) {
    (void)state;
    sim_fix *f = sf_load("coordinates theta\nparameters m = 1, l = 1, g = 9.81\n"
                         "bob = l*(sin(theta), -cos(theta))\nparticle m at bob\n"
                         "V = m*g*bob.y\ninitial theta = 0.1\n");
    assert_int_equal(qd_sim_compile(f->s), QD_OK);
    qd_sweep *w = qd_sweep_new(f->ctx, f->s, f->m);
    assert_int_equal(qd_sweep_grid(w, "theta = 0:1:2, theta' = 0:1:2"), QD_OK);
    assert_int_equal(qd_sweep_measures(w, "max:theta', final, lyapunov"), QD_OK);
    double rows[4 * 8] = {0};
    assert_true(qd_sweep_ncols(w) <= 8);
    static const char *const want[][2] = {{"max:theta'", "max:theta' (rad/s)"},
                                          {"final_theta", "final_theta (rad)"},
                                          {"lyapunov", "lyapunov (1/s)"},
                                          {"lyapunov_error", "lyapunov_error (1/s)"}};
    for (size_t k = 0; k < 4; k++) {
        size_t col;
        assert_int_equal(qd_sweep_map_column(w, want[k][0], &col), QD_OK);
        qd_plot *p = qd_plot_new(f->ctx, 0, 0);
        assert_int_equal(qd_sweep_map(w, rows, col, p), QD_OK);
        const char *xl, *yl, *bar;
        assert_true(qd_plot_labels(p, 0, &xl, &yl, &bar));
        assert_string_equal(xl, "theta (rad)");
        assert_string_equal(yl, "theta' (rad/s)");
        assert_string_equal(bar, want[k][1]);
        qd_plot_free(p);
    }
    qd_sweep_free(w);
    sf_free(f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_needs),
        cmocka_unit_test(test_prepare_free_particle),
        cmocka_unit_test(test_map),
        cmocka_unit_test(test_map_units),
        cmocka_unit_test(test_list_csv),
        cmocka_unit_test(test_write),
    };
    return cmocka_run_group_tests(tests, 0, NULL);
}
