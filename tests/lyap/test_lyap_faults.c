/*
 * tests/lyap/test_lyap_faults.c - every allocation of qd_lyap_new and
 * qd_lyap_run made to fail, one at a time (tests/util/fault.h): each run
 * ends with the right answer or a clean QD_ERR_NOMEM and gives every block
 * back.  The answer: the inverted oscillator x'' = a^2 x, whose exponents
 * are +a and -a (the eigenvalues of its constant Jacobian), a = 1.5, and
 * their sum the mean trace 0.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "qdot/qdot.h"
#include "util/fault.h"

static const char inverted[] = "coordinates x\nparameters a = 1.5\nT = x'^2/2\nV = -a^2/2*x^2\n";

static qd_status lyap_run(qd_ctx *ctx, const qd_lyap *l, double *ex) {
    double q0 = 0, qd0 = 0, err[2];
    qd_sim_opts o = {.method = QD_SIM_DOP853, .t0 = 0, .t_end = 30, .rtol = 1e-11,
                     .atol = 1e-13, .q0 = &q0, .qd0 = &qd0};
    qd_lyap_opts lo = {.nexp = 2, .renorm = 1, .transient = 15};
    qd_lyap_stats st;
    qd_status s = qd_lyap_run_stats(ctx, l, &o, &lo, ex, err, &st);
    if (s == QD_OK)
        assert_true(fabs(st.trace_mean) < 1e-12);
    return s;
}

static qd_status body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)data;
    long to_go = qt_fault_hold(f); /* the derivation has loops of its own */
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, inverted, &d);
    qd_eom *e = m ? qd_eom_derive(ctx, m) : NULL;
    assert_non_null(e);
    qt_fault_release(f, to_go);
    qd_lyap *l = qd_lyap_new(ctx, m, e);
    qd_status st = l ? QD_OK : qd_ctx_status(ctx);
    double ex[2];
    if (l)
        st = lyap_run(ctx, l, ex);
    if (st == QD_OK) {
        assert_true(fabs(ex[0] - 1.5) < 1e-6);
        assert_true(fabs(ex[1] + 1.5) < 1e-6);
    }
    qd_lyap_free(l);
    qd_eom_free(e);
    qd_model_free(m);
    return st;
}

static void test_faults(void **state) {
    (void)state;
    qt_fault_stats ls = qt_fault_loop("lyapunov", body, NULL, 1);
    assert_true(ls.allocs > 10);
    assert_true(ls.nomem > 10);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_faults)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
