/*
 * tests/hj/test_hj_fault.c - qd_hj_derive and qd_hj_solve with every
 * allocation made to fail, one at a time (the loop of tests/util/fault.h,
 * SQLite's test/exprfault.test).
 *
 * The model is parsed with the failures off; then the Nth allocation of the
 * derivation is refused, for N = 1, 1 + s, 1 + 2 s, ... until a run gets
 * through (s a stride: a derivation makes thousands of allocations).  Each run
 * must end with the right answer or a clean QD_ERR_NOMEM (recorded in the
 * context too), with every block given back.  The answers: Kepler in the
 * plane is "cyclic" with p_r^2 = 2m(E + k/r) - alpha_theta^2/r^2 and the
 * orbit r(theta) (Desloge ch. 78 Example 2, Goldstein 10.8); the potential of
 * Landau-Lifshitz §48 eq. 48.8 in spherical coordinates is "Staeckel".
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/qdot.h"
#include "util/fault.h"

/* The run's own check of the answer: QD_OK when right. */
typedef qd_status (*check_fn)(qd_ctx *ctx, const qd_model *m, qd_hj *h);

/* A model text and the check of its answer. */
typedef struct hj_case {
    const char *text;
    check_fn check;
} hj_case;

static qd_status run(qd_ctx *ctx, qt_faulty *f, void *data) {
    const hj_case *c = data;
    long to_go = qt_fault_hold(f); /* the parse is not what this loop fails */
    qd_model *m = qd_model_parse(ctx, c->text, NULL);
    assert_non_null(m);
    qt_fault_release(f, to_go);
    qd_hj *h = qd_hj_derive(ctx, m, NULL);
    qd_status st = h ? qd_hj_solve(ctx, h) : qd_ctx_status(ctx);
    qt_fault_hold(f); /* the check itself allocates */
    if (st == QD_OK)
        st = c->check(ctx, m, h);
    qd_hj_free(h);
    qd_model_free(m);
    return st;
}

/* stride: fail every stride-th allocation only (a derivation makes thousands
 * and each run re-derives; QD_HJ_FAULT_STRIDE=1 in the environment sweeps all). */
static void fault_loop(const char *what, const char *text, check_fn check, long stride) {
    const char *env = getenv("QD_HJ_FAULT_STRIDE");
    if (env && atol(env) > 0)
        stride = atol(env);
    hj_case c = {text, check};
    assert_true(qt_fault_loop(what, run, &c, stride).runs > 20);
}

static double value(qd_ctx *ctx, const qd_model *m, const qd_expr *e, size_t n,
                    const char *const *names, const double *vals) {
    const qd_expr *syms[16];
    double v[16], out = NAN;
    size_t k = 0;
    for (size_t i = 0; i < qd_model_nparams(m); i++, k++) {
        syms[k] = qd_model_param(m, i);
        v[k] = qd_number_value(qd_model_param_value(m, i));
    }
    for (size_t i = 0; i < n; i++, k++) {
        syms[k] = qd_lookup(ctx, names[i]);
        v[k] = vals[i];
    }
    return qd_eval(ctx, e, k, syms, v, &out) == QD_OK ? out : NAN;
}

/* p_r^2 = 2 m (E + k/r) - alpha^2/r^2 at r = 1.5, E = -0.4, alpha = 0.9;
 * the orbit closes (r(theta) found). */
static qd_status check_kepler(qd_ctx *ctx, const qd_model *m, qd_hj *h) {
    if (!h->separable || strcmp(h->form, "cyclic") || !h->sep[0].motion)
        return QD_ERR_ARG;
    const char *names[3] = {"r", "E", "alpha_theta"};
    const double vals[3] = {1.5, -0.4, 0.9};
    double got = value(ctx, m, h->sep[0].p2, 3, names, vals);
    double want = 2 * 1.3 * (-0.4 + 4 / 1.5) - 0.81 / 2.25;
    return fabs(got - want) < 1e-12 ? QD_OK : QD_ERR_ARG;
}

static qd_status check_staeckel(qd_ctx *ctx, const qd_model *m, qd_hj *h) {
    (void)ctx, (void)m;
    return h->separable && !strcmp(h->form, "Staeckel") && h->W ? QD_OK : QD_ERR_ARG;
}

static void test_kepler(void **state) {
    (void)state;
    fault_loop("kepler polar", "coordinates r, theta\nparameters m = 1.3, k = 4\n"
               "particle m at r*(cos(theta), sin(theta))\nV = -k/r\n", check_kepler, 17);
}

static void test_staeckel(void **state) {
    (void)state;
    fault_loop("staeckel", "coordinates r, theta, phi\nparameters m = 1, k = 1, b = 0.3, d = 0.2\n"
               "momenta p_r, p_theta, p_phi\n"
               "H = p_r^2/(2*m) + (p_theta^2 + p_phi^2/sin(theta)^2)/(2*m*r^2) - k/r"
               " + b*cos(theta)/r^2 + d*sin(phi)^2/(r^2*sin(theta)^2)\n", check_staeckel, 41);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_kepler),
        cmocka_unit_test(test_staeckel),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
