/*
 * tests/sim/test_nonfinite.c - no run ends well with non-finite data
 * (issue 30).  Every row a run hands to its sink is finite, and a run that
 * cannot go on fails with a status and names t:
 *
 *   - the finite-time blow-up x'' = 4 x^3 from x = 1, x' = 1 (energy
 *     1/2 - 1 = -1/2, so x' = sqrt(2 x^4 - 1) and the blow-up time is
 *     integral_1^inf dx / sqrt(2 x^4 - 1) = 0.7531): bdf stops with step
 *     size underflow there as the explicit pairs do, instead of streaming
 *     the same row; the fixed-step methods (verlet, yoshida*, gl*, taylor
 *     with a step, the pairs with a constant step, the projection path of
 *     a constrained system, the form given by H) stop at the first
 *     non-finite state;
 *   - x'' = 1/(2 sqrt(x)) from x = 1, x' = -5 reaches x = 0 at t = 0.2028
 *     and would go on into sqrt of a negative number: dop853's error
 *     estimate is NaN there, a rejected step, not error 0;
 *   - times that are not finite are refused before the run;
 *   - a sink that returns a negative value, and an input callback that
 *     returns NaN, end the run with a status;
 *   - the cause of a non-finite mass matrix or energy is named from the
 *     numbers: an overflow, a division by zero, or NaN (the domain), not
 *     always "a speed at or above c".
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "sim_fixture.h"

static const char blowup[] = "coordinates x\nparameters m = 1\nT = m/2*x'^2\nV = -x^4\n"
                             "initial x = 1, x' = 1\n";
static const char root[] = "coordinates x\nT = x'^2/2\nV = -sqrt(x)\ninitial x = 1, x' = -5\n";

typedef struct rows {
    size_t n, ncols, bad; /* rows, columns, rows with a non-finite number */
    size_t fail_at;       /* return -1 at this row (0: never) */
} rows;

static int count_rows(void *data, int event, const double *row) {
    rows *r = data;
    (void)event;
    r->n++;
    for (size_t j = 0; j < r->ncols; j++)
        if (!isfinite(row[j])) {
            r->bad++;
            break;
        }
    return r->fail_at && r->n >= r->fail_at ? -1 : 0;
}

/* Run text with o's method, t_end, dt, rtol, fixed; the status, the rows
 * counted; the message must contain words. */
static qd_status run_text(const char *text, qd_sim_opts o, rows *r, const char *words) {
    sim_fix *f = sf_load(text);
    assert_non_null(f);
    o.q0 = f->q0;
    o.qd0 = f->qd0;
    r->ncols = qd_sim_columns(f->s, o.method, NULL, 0);
    qd_status st = qd_sim_run(f->s, &o, count_rows, r, NULL, NULL);
    if (words && !strstr(qd_ctx_message(f->ctx), words))
        fail_msg("%s: status %d, message '%s', not '%s'", qd_sim_method_name(o.method), (int)st,
                 qd_ctx_message(f->ctx), words);
    sf_free(f);
    return st;
}

static void test_bdf_blowup(void **state) {
    (void)state;
    rows r = {0};
    /* without the check the steps shrink below round-off and the run meets
     * max_steps (1e8 by default) with the same row again and again */
    qd_sim_opts o = {.method = QD_SIM_BDF, .t_end = 2, .max_steps = 1000000};
    assert_int_equal(run_text(blowup, o, &r, "step size underflow at t = 0.753"), QD_ERR_NUMERIC);
    assert_int_equal(r.bad, 0);
    assert_true(r.n < 100000);
}

static void test_dop853_nan_estimate(void **state) {
    (void)state;
    qd_sim_method m[] = {QD_SIM_DOP853, QD_SIM_DOPRI5};
    for (size_t k = 0; k < 2; k++) {
        rows r = {0};
        qd_sim_opts o = {.method = m[k], .t_end = 2};
        assert_int_equal(run_text(root, o, &r, "step size underflow at t = 0.2027"),
                         QD_ERR_NUMERIC);
        assert_int_equal(r.bad, 0);
    }
}

/* The fixed-step methods on the blow-up: a failure before t = 0.8, no
 * non-finite row; the splitting ones say "non-finite state at t = ". */
static void test_fixed_step_nonfinite(void **state) {
    (void)state;
    qd_sim_method m[] = {QD_SIM_VERLET, QD_SIM_YOSHIDA4, QD_SIM_YOSHIDA6, QD_SIM_YOSHIDA8,
                         QD_SIM_GL2,    QD_SIM_GL4,      QD_SIM_GL6,      QD_SIM_TAYLOR,
                         QD_SIM_DOPRI5, QD_SIM_DOP853};
    for (size_t k = 0; k < sizeof m / sizeof *m; k++) {
        rows r = {0};
        bool pair = m[k] == QD_SIM_DOPRI5 || m[k] == QD_SIM_DOP853;
        qd_sim_opts o = {.method = m[k], .t_end = 2, .dt = 0.01, .fixed = pair ||
                         m[k] == QD_SIM_TAYLOR};
        const char *words = m[k] <= QD_SIM_YOSHIDA8 && m[k] >= QD_SIM_VERLET
                                ? "non-finite state at t = 0."
                                : NULL;
        qd_status st = run_text(blowup, o, &r, words);
        if (st == QD_OK || r.bad)
            fail_msg("%s: status %d, %zu non-finite rows", qd_sim_method_name(m[k]), (int)st,
                     r.bad);
    }
}

/* The projection path (a constraint, dop853 with a constant step), and a
 * model given by H with verlet: the same blow-up, the same stop. */
static void test_other_paths_nonfinite(void **state) {
    (void)state;
    static const char con[] = "coordinates x, y\nT = x'^2/2 + y'^2/2\nV = -x^4\n"
                              "constraint c: y = 0\ninitial x = 1, x' = 1\n";
    rows r = {0};
    qd_sim_opts o = {.method = QD_SIM_DOP853, .t_end = 2, .dt = 0.01, .fixed = true};
    assert_int_equal(run_text(con, o, &r, "non-finite state at t = 0."), QD_ERR_NUMERIC);
    assert_int_equal(r.bad, 0);

    static const char ham[] = "coordinates x\nmomenta p\nH = p^2/2 - x^4\n"
                              "initial x = 1, x' = 1\n";
    sim_fix *f = calloc(1, sizeof *f);
    qd_diag d;
    f->ctx = qd_ctx_new();
    f->m = qd_model_parse(f->ctx, ham, &d);
    assert_non_null(f->m);
    f->s = qd_sim_new_hamilton(f->ctx, f->m);
    assert_non_null(f->s);
    double q0 = 1, p0 = 1;
    rows h = {.ncols = qd_sim_columns(f->s, QD_SIM_VERLET, NULL, 0)};
    qd_sim_opts oh = {.method = QD_SIM_VERLET, .t_end = 2, .dt = 0.01, .q0 = &q0, .qd0 = &p0,
                      .p0 = &p0};
    assert_int_equal(qd_sim_run(f->s, &oh, count_rows, &h, NULL, NULL), QD_ERR_NUMERIC);
    assert_non_null(strstr(qd_ctx_message(f->ctx), "non-finite state at t = 0."));
    assert_int_equal(h.bad, 0);
    sf_free(f);
}

static void expect_refused(qd_sim_opts o, const char *words) {
    sim_fix *f = sf_load(blowup);
    assert_non_null(f);
    o.q0 = f->q0;
    o.qd0 = f->qd0;
    assert_int_equal(qd_sim_check_opts(f->ctx, &o), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(f->ctx), words));
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_sim_run(f->s, &o, NULL, NULL, NULL, NULL), QD_ERR_ARG);
    sf_free(f);
}

static void test_times_not_finite(void **state) {
    (void)state;
    expect_refused((qd_sim_opts){.method = QD_SIM_DOP853, .t_end = INFINITY},
                   "the end time must be a finite number, not inf");
    expect_refused((qd_sim_opts){.method = QD_SIM_DOP853, .t_end = NAN},
                   "the end time must be a finite number, not nan");
    expect_refused((qd_sim_opts){.method = QD_SIM_DOP853, .t_end = 1, .dt = INFINITY},
                   "the step dt must be a finite number, not inf");
    expect_refused((qd_sim_opts){.method = QD_SIM_DOP853, .t_end = 1, .dt = NAN},
                   "the step dt must be a finite number");
    expect_refused((qd_sim_opts){.method = QD_SIM_DOP853, .t_end = 1, .dt = -1},
                   "the step dt must be positive");
    expect_refused((qd_sim_opts){.method = QD_SIM_VERLET, .t0 = NAN, .t_end = 1, .dt = 0.1},
                   "the start time t0 must be a finite number");
}

static void test_initial_not_finite(void **state) {
    (void)state;
    sim_fix *f = sf_load(blowup);
    assert_non_null(f);
    f->qd0[0] = NAN;
    qd_sim_opts o = {.method = QD_SIM_GL4, .t_end = 1, .dt = 0.1, .q0 = f->q0, .qd0 = f->qd0};
    assert_int_equal(qd_sim_run(f->s, &o, NULL, NULL, NULL, NULL), QD_ERR_ARG);
    if (!strstr(qd_ctx_message(f->ctx), "the initial state is not finite (x' = nan)"))
        fail_msg("%s", qd_ctx_message(f->ctx));
    sf_free(f);
}

static void test_sink_failure(void **state) {
    (void)state;
    static const char osc[] = "coordinates x\nT = x'^2/2\nV = x^2/2\ninitial x = 1\n";
    rows r = {.fail_at = 3};
    qd_sim_opts o = {.method = QD_SIM_DOP853, .t_end = 10, .dt = 0.1};
    assert_int_equal(run_text(osc, o, &r, "the row callback reported a failure at t = 0.2"),
                     QD_ERR_ARG);
    assert_int_equal(r.n, 3);
}

static size_t calls_after_nan;

static double nan_after_half(void *data, double t, const double *x) {
    bool *failed = data;
    (void)x;
    if (*failed)
        calls_after_nan++;
    if (t > 0.5)
        *failed = true;
    return *failed ? NAN : 1.0;
}

static void test_input_callback_failure(void **state) {
    (void)state;
    static const char forced[] = "coordinates x\ninputs F\nT = x'^2/2\nV = x^2/2\nQ[x] = F\n"
                                 "initial x = 1\n";
    qd_sim_method m[] = {QD_SIM_DOP853, QD_SIM_GL4, QD_SIM_BDF};
    for (size_t k = 0; k < 3; k++) {
        sim_fix *f = sf_load(forced);
        assert_non_null(f);
        bool failed = false;
        calls_after_nan = 0;
        assert_int_equal(qd_sim_input_callback(f->s, "F", nan_after_half, &failed), QD_OK);
        rows r = {.ncols = qd_sim_columns(f->s, m[k], NULL, 0)};
        qd_sim_opts o = {.method = m[k], .t_end = 2, .dt = 0.01, .q0 = f->q0, .qd0 = f->qd0};
        qd_status st = qd_sim_run(f->s, &o, count_rows, &r, NULL, NULL);
        if (st != QD_ERR_NUMERIC || !strstr(qd_ctx_message(f->ctx), "input F is not finite at t = 0."))
            fail_msg("%s: status %d, '%s'", qd_sim_method_name(m[k]), (int)st,
                     qd_ctx_message(f->ctx));
        assert_int_equal(r.bad, 0);
        /* the callback is not called on and on after it failed */
        assert_true(calls_after_nan == 0);
        sf_free(f);
    }
}

/* The cause named from the numbers. */
static void expect_cause(const char *text, qd_sim_opts o, const char *words, const char *not) {
    sim_fix *f = sf_load(text);
    assert_non_null(f);
    o.q0 = f->q0;
    o.qd0 = f->qd0;
    assert_int_equal(qd_sim_run(f->s, &o, NULL, NULL, NULL, NULL), QD_ERR_NUMERIC);
    const char *msg = qd_ctx_message(f->ctx);
    if (!strstr(msg, words) || (not && strstr(msg, not)))
        fail_msg("'%s': want '%s'%s%s", msg, words, not ? ", not " : "", not ? not : "");
    sf_free(f);
}

static void test_cause_named(void **state) {
    (void)state;
    /* M = 1 + x^2 overflows along the blow-up (fixed steps: no rejection) */
    static const char grow[] = "coordinates x\nT = (1 + x^2)*x'^2/2\nV = -x^8\n"
                               "initial x = 1, x' = 1\n";
    qd_sim_opts fixed = {.method = QD_SIM_DOPRI5, .t_end = 2, .dt = 0.01, .fixed = true};
    expect_cause(grow, fixed, "overflow", "above c");
    /* 1/sin(x)^2 at x = 0: a division by zero where the coordinate
     * degenerates (the centrifugal term of a spherical pendulum's axis) */
    static const char axis[] = "coordinates x\nT = x'^2/2\nV = 1/(2*sin(x)^2)\n"
                               "initial x = 0, x' = 1\n";
    qd_sim_opts o = {.method = QD_SIM_DOP853, .t_end = 1};
    expect_cause(axis, o, "division by zero", "speed at or above c");
    /* the relativistic L at v = c exactly: 1/0 in M; beyond c: NaN, the domain */
    static const char light[] = "coordinates x\nL = -sqrt(1 - x'^2) + x\ninitial x' = 1\n";
    static const char fast[] = "coordinates x\nL = -sqrt(1 - x'^2) + x\ninitial x' = 3/2\n";
    expect_cause(light, o, "division by zero", NULL);
    expect_cause(fast, o, "outside the domain", "division by zero");
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bdf_blowup),
        cmocka_unit_test(test_dop853_nan_estimate),
        cmocka_unit_test(test_fixed_step_nonfinite),
        cmocka_unit_test(test_other_paths_nonfinite),
        cmocka_unit_test(test_times_not_finite),
        cmocka_unit_test(test_initial_not_finite),
        cmocka_unit_test(test_sink_failure),
        cmocka_unit_test(test_input_callback_failure),
        cmocka_unit_test(test_cause_named),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
