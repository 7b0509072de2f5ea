/*
 * tests/sim/test_period.c - a run over one period given as text
 * (qd_sim_setup_period, qdot/simsetup.h) on the oscillator m x'' = -k x:
 * T = 2 pi sqrt(m/k) = pi read in the parameters, the run from t0 = 0.5
 * ends at t0 + T where the state is the initial one again (Goldstein sec.
 * 1.6); a period that is not positive, or not a constant, is refused with
 * the error located in its text; the same as an option of the set-up.
 */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <string.h>
#include <cmocka.h>

#include "qdot/qdot.h"
#include "qdot/simsetup.h"

static const char osc[] = "coordinates x\nparameters m = 2, k = 8\n"
                          "T = m/2*x'^2\nV = k/2*x^2\n";

typedef struct last {
    double row[8], t_first;
    size_t n;
} last;

static int sink(void *data, int event, const double *row) {
    (void)event;
    last *l = data;
    if (!l->n++)
        l->t_first = row[0];
    memcpy(l->row, row, 4 * sizeof *row);
    return 0;
}

static void test_one_period(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qd_model_parse(ctx, osc, NULL);
    qd_sim_setup *s = qd_sim_setup_new(ctx, m, false);
    assert_non_null(s);
    assert_int_equal(qd_sim_setup_initial(s, "x = 1, x' = 0.5, t = 0.5"), QD_OK);
    qd_sim_setup_opts so = {.t_end = "100", .rtol = "1e-12", .atol = "1e-14"};
    qd_sim_opts o;
    assert_int_equal(qd_sim_setup_options(s, &so, &o), QD_OK);
    double T = 0;
    assert_int_equal(qd_sim_setup_period(s, "2*pi*sqrt(m/k)", &o, &T), QD_OK);
    assert_true(fabs(T - 3.14159265358979323846) < 1e-15);
    assert_true(o.t0 == 0.5 && fabs(o.t_end - (0.5 + T)) < 1e-15);
    last l = {0};
    qd_sim_stats st;
    assert_int_equal(qd_sim_run(qd_sim_setup_sim(s), &o, sink, &l, &st, NULL), QD_OK);
    assert_true(fabs(l.row[0] - o.t_end) < 1e-12);
    assert_true(fabs(l.row[1] - 1) < 1e-9 && fabs(l.row[2] - 0.5) < 1e-9);
    /* refused, located, and the options untouched */
    double t_end = o.t_end, T2 = 7;
    assert_int_equal(qd_sim_setup_period(s, "1 - m", &o, &T2), QD_ERR_ARG);
    assert_true(qd_ctx_diag(ctx)->located && qd_ctx_diag(ctx)->offset == 0);
    assert_true(o.t_end == t_end && T2 == 7);
    qd_ctx_clear_error(ctx);
    assert_int_not_equal(qd_sim_setup_period(s, "2*x", &o, &T2), QD_OK);
    assert_true(qd_ctx_diag(ctx)->located && qd_ctx_diag(ctx)->offset == 2);
    qd_sim_setup_free(s);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* The period as an option (qd_sim_setup_opts.period): t_end = t0 + T
 * before the options are checked, so rows every dt = T/8 and a fixed step
 * are counted over one period (not refused as too many), and the run
 * returns to its start; with t_end too it is refused, by the field. */
static void test_period_option(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qd_model_parse(ctx, osc, NULL);
    qd_sim_setup *s = qd_sim_setup_new(ctx, m, false);
    assert_non_null(s);
    assert_true(isnan(qd_sim_setup_period_of(s)));
    assert_int_equal(qd_sim_setup_initial(s, "x = 1, x' = 0.5, t = 0.5"), QD_OK);
    qd_sim_setup_opts so = {.period = "2*pi*sqrt(m/k)", .dt = "pi/8", .step = "pi/800",
                            .method = "gl6"};
    qd_sim_opts o;
    assert_int_equal(qd_sim_setup_options(s, &so, &o), QD_OK);
    double T = qd_sim_setup_period_of(s);
    assert_true(fabs(T - 3.14159265358979323846) < 1e-15 && o.t_end == 0.5 + T);
    last l = {0};
    qd_sim_stats st;
    assert_int_equal(qd_sim_run(qd_sim_setup_sim(s), &o, sink, &l, &st, NULL), QD_OK);
    assert_true(l.n == 9 || l.n == 10); /* t0 + k T/8 (and t_end, an ulp on) */
    assert_true(fabs(l.row[0] - o.t_end) < 1e-12);
    assert_true(fabs(l.row[1] - 1) < 1e-9 && fabs(l.row[2] - 0.5) < 1e-9);
    so.t_end = "1";
    assert_int_equal(qd_sim_setup_options(s, &so, &o), QD_ERR_ARG);
    assert_string_equal(qd_ctx_diag(ctx)->name, "period");
    qd_sim_setup_free(s);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_one_period),
                                       cmocka_unit_test(test_period_option)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
