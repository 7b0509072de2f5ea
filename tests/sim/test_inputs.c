/*
 * tests/sim/test_inputs.c - a model's inputs in a simulation (issue 23):
 * each source kind against a closed form of the forced oscillator
 * m x'' + k x = F, w^2 = k/m (Goldstein, Poole & Safko sec. 1.6 for the
 * oscillator; seed 002), and the errors of a missing or short source.
 *
 *   F = F0 cos(W t) from rest:  x = F0/(m (w^2 - W^2)) (cos W t - cos w t)
 *   F = -c x' (feedback on x'):  the damped oscillator, g = c/2m,
 *        x = e^(-g t) (x0 cos(wd t) + (v0 + g x0)/wd sin(wd t)), wd^2 = w^2 - g^2
 *   F = a t (a ramp, exact in a table's linear interpolation), from rest:
 *        x = a/k (t - sin(w t)/w)
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "sim_fixture.h"
#include "util/fault.h"

static const char osc[] = "coordinates x\nparameters m = 2, k = 8\ninputs F\n"
                          "T = m/2*x'^2\nV = k/2*x^2\nQ[x] = F\n";

static double cosine(void *data, double t, const double *x) {
    (void)x;
    const double *p = data; /* F0, W */
    return p[0] * cos(p[1] * t);
}

static double damper(void *data, double t, const double *x) {
    (void)t;
    return -*(const double *)data * x[1]; /* x = (q, q') */
}

static void test_callback_signal(void **state) {
    (void)state;
    sim_fix *f = sf_load(osc);
    assert_non_null(f);
    double p[2] = {3, 1.3}, w = 2, T = 10;
    assert_int_equal(qd_sim_input_callback(f->s, "F", cosine, p), QD_OK);
    assert_int_equal(sf_run(f, QD_SIM_DOP853, T, 0, 1e-13, false), QD_OK);
    double x = p[0] / (2 * (w * w - p[1] * p[1])) * (cos(p[1] * T) - cos(w * T));
    assert_true(fabs(f->last[1] - x) < 1e-9);
    sf_free(f);
}

static void test_callback_feedback(void **state) {
    (void)state;
    sim_fix *f = sf_load(osc);
    assert_non_null(f);
    double c = 0.8, m = 2, g = c / (2 * m), wd = sqrt(4 - g * g), T = 7;
    f->q0[0] = 1;
    f->qd0[0] = 0.5;
    assert_int_equal(qd_sim_input_callback(f->s, "F", damper, &c), QD_OK);
    assert_int_equal(sf_run(f, QD_SIM_DOP853, T, 0, 1e-13, false), QD_OK);
    double x = exp(-g * T) * (cos(wd * T) + (0.5 + g) / wd * sin(wd * T));
    assert_true(fabs(f->last[1] - x) < 1e-9);
    sf_free(f);
}

static void test_expression_feedback(void **state) {
    (void)state;
    sim_fix *f = sf_load(osc);
    assert_non_null(f);
    qd_diag d;
    qd_read_opts ro = {.new_symbols = false};
    const qd_expr *law = qd_read(f->ctx, "-4/5*x'", &ro, &d);
    assert_non_null(law);
    assert_int_equal(qd_sim_input_expr(f->s, "F", law), QD_OK);
    double g = 0.2, wd = sqrt(4 - g * g), T = 7;
    f->q0[0] = 1;
    f->qd0[0] = 0.5;
    assert_int_equal(sf_run(f, QD_SIM_DOP853, T, 0, 1e-13, false), QD_OK);
    double x = exp(-g * T) * (cos(wd * T) + (0.5 + g) / wd * sin(wd * T));
    assert_true(fabs(f->last[1] - x) < 1e-9);
    sf_free(f);
}

static void test_table_ramp(void **state) {
    (void)state;
    sim_fix *f = sf_load(osc);
    assert_non_null(f);
    double t[] = {-1, 2.5, 6, 10.5}, v[4], a = 0.7, w = 2, T = 10;
    for (int i = 0; i < 4; i++)
        v[i] = a * t[i];
    assert_int_equal(qd_sim_input_table(f->s, "F", 4, t, v), QD_OK);
    /* the kinks of the interpolant are only round-off here: the steps
     * straddle them without trouble */
    assert_int_equal(sf_run(f, QD_SIM_DOP853, T, 0, 1e-13, false), QD_OK);
    double x = a / 8 * (T - sin(w * T) / w);
    assert_true(fabs(f->last[1] - x) < 1e-9);
    sf_free(f);
}

static void test_errors(void **state) {
    (void)state;
    sim_fix *f = sf_load(osc);
    assert_non_null(f);
    assert_int_equal(sf_run(f, QD_SIM_DOP853, 1, 0, 1e-10, false), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(f->ctx), "input F is used but not supplied"));
    /* compiled by that run: the sources are fixed from here on */
    assert_int_equal(qd_sim_input_callback(f->s, "F", damper, NULL), QD_ERR_ARG);
    sf_free(f);
    f = sf_load(osc);
    double t[] = {0, 0.5}, v[] = {1, 1};
    assert_int_equal(qd_sim_input_table(f->s, "F", 2, t, v), QD_OK);
    assert_int_equal(qd_sim_inputs_ready(f->s, 0, 1), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(f->ctx), "covers t = 0 to 0.5"));
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_sim_input_table(f->s, "G", 2, t, v), QD_ERR_ARG);
    qd_ctx_clear_error(f->ctx);
    double back[] = {1, 0};
    assert_int_equal(qd_sim_input_table(f->s, "F", 2, back, v), QD_ERR_ARG);
    qd_ctx_clear_error(f->ctx);
    qd_diag d;
    qd_read_opts ro = {.new_symbols = false};
    assert_int_equal(qd_sim_input_expr(f->s, "F", qd_read(f->ctx, "2*F", &ro, &d)),
                     QD_ERR_ARG);
    sf_free(f);
}

/* Every allocation of compiling and running with a table and an expression
 * source made to fail once: the ramp's answer or a clean QD_ERR_NOMEM. */
static qd_status faulty_body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)data;
    long to_go = qt_fault_hold(f);
    qd_model *m = qd_model_parse(ctx, "coordinates x\nparameters m = 2, k = 8\ninputs F, G\n"
                                      "T = m/2*x'^2\nV = k/2*x^2\nQ[x] = F + G\n", NULL);
    assert_non_null(m);
    qd_eom *e = qd_eom_derive(ctx, m);
    assert_non_null(e);
    qd_read_opts ro = {.new_symbols = false};
    const qd_expr *zero = qd_read(ctx, "0*x", &ro, NULL);
    qt_fault_release(f, to_go);
    double t[] = {0, 10}, v[] = {0, 7}, q0 = 0, qd0 = 0, last[8];
    qd_sim *s = qd_sim_new(ctx, m, e);
    qd_status st = s ? qd_sim_input_table(s, "F", 2, t, v) : qd_ctx_status(ctx);
    if (st == QD_OK)
        st = qd_sim_input_expr(s, "G", zero);
    qd_sim_opts o = {.method = QD_SIM_DOP853, .t_end = 10, .rtol = 1e-10, .atol = 1e-12,
                     .q0 = &q0, .qd0 = &qd0};
    if (st == QD_OK)
        st = qd_sim_run(s, &o, NULL, NULL, NULL, last);
    if (st == QD_OK)
        assert_true(fabs(last[1] - 0.7 / 8 * (10 - sin(20) / 2)) < 1e-7);
    qd_sim_free(s);
    qd_eom_free(e);
    qd_model_free(m);
    return st;
}

static void test_faults(void **state) {
    (void)state;
    assert_true(qt_fault_loop("simulate with inputs", faulty_body, NULL, 1).allocs > 10);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_callback_signal),   cmocka_unit_test(test_callback_feedback),
        cmocka_unit_test(test_expression_feedback), cmocka_unit_test(test_table_ramp),
        cmocka_unit_test(test_errors),            cmocka_unit_test(test_faults),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
