/*
 * tests/lyap/test_flow_columns.c - the rows of `qdot simulate --variational
 * columns` (qd_flow_run's sink every h, qd_flow_column_name) on the
 * harmonic oscillator m x'' = -k x, w = sqrt(k/m) = 2, set up as the
 * command sets it up (qdot/simsetup.h): the flow Jacobian of y = (x, x') is
 *     Phi(t) = [[cos w t, sin(w t)/w], [-w sin(w t), cos w t]]
 * (Arnold, Mathematical Methods of Classical Mechanics, sec. 25; the
 * variational equations of a linear system are the system), det Phi = 1
 * (Liouville), and the columns are named dYi/dYj0 column by column.
 */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <string.h>
#include <cmocka.h>

#include "qdot/qdot.h"
#include "qdot/lyapunov.h"
#include "qdot/simsetup.h"

static const char osc[] = "coordinates x\nparameters m = 2, k = 8\n"
                          "T = m/2*x'^2\nV = k/2*x^2\ninitial x = 1\n";

typedef struct seen {
    size_t rows;
    double worst, worst_det, worst_y, last_t;
} seen;

static int sink(void *data, double t, const double *y, const double *phi) {
    seen *s = data;
    const double w = 2, c = cos(w * t), sn = sin(w * t);
    const double want[4] = {c, sn / w, -w * sn, c}; /* phi[i * 2 + j] = dy_i/dy_j(t0) */
    for (int i = 0; i < 4; i++)
        s->worst = fmax(s->worst, fabs(phi[i] - want[i]));
    s->worst_det = fmax(s->worst_det, fabs(phi[0] * phi[3] - phi[1] * phi[2] - 1));
    s->worst_y = fmax(s->worst_y, fabs(y[0] - c) + fabs(y[1] + w * sn)); /* x = cos w t */
    s->rows++;
    s->last_t = t;
    return 0;
}

static void test_oscillator_columns(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qd_model_parse(ctx, osc, NULL);
    qd_sim_setup *set = qd_sim_setup_new(ctx, m, false);
    assert_non_null(set);
    qd_sim_setup_opts so = {.t_end = "5", .rtol = "1e-12", .atol = "1e-14"};
    qd_sim_opts o, fo_opts;
    assert_int_equal(qd_sim_setup_options(set, &so, &o), QD_OK);
    const qd_eom *e = qd_sim_setup_eom(set);
    qd_lyap *l = qd_lyap_new(ctx, m, e);
    assert_non_null(l);
    assert_int_equal(qd_flow_sim_opts(&o, &fo_opts), QD_OK);
    seen s = {0};
    qd_flow_opts fo = {.every = 0.05, .sink = sink, .data = &s};
    qd_flow f;
    assert_int_equal(qd_flow_run(ctx, l, &fo_opts, &fo, &f), QD_OK);
    assert_true(s.rows >= 100);
    assert_true(fabs(s.last_t - 5) < 1e-12);
    assert_true(s.worst < 1e-9 && s.worst_det < 1e-9 && s.worst_y < 1e-9);
    qd_flow_free(&f);
    /* the header: t, x, x', then Phi by columns */
    static const char *const names[] = {"t", "x", "x'", "dx/dx0", "dx'/dx0", "dx/dx'0",
                                        "dx'/dx'0"};
    for (size_t k = 0; k < 7; k++) {
        qd_buf b = QD_BUF_INIT;
        assert_int_equal(qd_flow_column_name(e, k, &b), QD_OK);
        assert_string_equal(qd_buf_str(&b), names[k]);
        qd_buf_free(&b);
    }
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_flow_column_name(e, 7, &b), QD_ERR_ARG);
    qd_buf_free(&b);
    qd_lyap_free(l);
    qd_sim_setup_free(set);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_oscillator_columns)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
