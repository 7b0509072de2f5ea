/*
 * tests/linear/test_statespace.c - qd_linearize (issue 23) on closed forms:
 *
 *   - the simple pendulum m l^2 th'' = -m g l sin th + tau about any point
 *     (th0, w0): A = [0 1; -g/l cos th0  0], B = [0; 1/(m l^2)], and the affine
 *     term xdot0 = (w0, -g/l sin th0 + tau0/(m l^2)) (Goldstein sec. 1.6's
 *     pendulum with a torque; seed 002); exact A in the parameters;
 *   - the inverted pendulum on a cart (examples/cart_pendulum.qd, SymPy's
 *     n_link_pendulum_on_cart n = 1) upright: eigenvalues 0, 0 and
 *     +-sqrt(g (M + m)/(M l)), controllable; every allocation made to fail
 *     once (tests/util/fault.h): the answer or a clean QD_ERR_NOMEM;
 *   - refusals: a model keeping a multiplier, a point naming a parameter.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/statespace.h"
#include "util/fault.h"

#define PENDULUM                                                                               \
    "coordinates th\nparameters m = 2, l = 1.5, g = 9.81\ninputs tau\n"                        \
    "T = m*l^2*th'^2/2\nV = -m*g*l*cos(th)\nQ[th] = tau\noutputs height = -l*cos(th)\n"

#define CART                                                                                   \
    "coordinates x, th\nparameters M = 1, m = 0.1, l = 0.5, g = 9.81\ninputs F\n"              \
    "particle M at (x, 0, 0)\nparticle m at (x - l*sin(th), l*cos(th), 0)\n"                   \
    "V = m*g*l*cos(th)\nQ[x] = F\n"

static qd_status lin_text(qd_ctx *ctx, const char *text, const char *about_sym[],
                          const char *about_val[], size_t k, qd_statespace *s, qd_model **m,
                          qd_eom **e) {
    *m = qd_model_parse(ctx, text, NULL);
    *e = *m ? qd_eom_derive(ctx, *m) : NULL;
    if (!*e)
        return qd_ctx_status(ctx);
    const qd_expr *syms[8], *vals[8];
    qd_read_opts ro = {.new_symbols = false};
    for (size_t i = 0; i < k; i++) {
        syms[i] = qd_read(ctx, about_sym[i], &ro, NULL);
        vals[i] = qd_read(ctx, about_val[i], &ro, NULL);
        assert_non_null(syms[i]);
        assert_non_null(vals[i]);
    }
    return qd_linearize(ctx, *e, *m, k, syms, vals, s);
}

static void test_pendulum_any_point(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m;
    qd_eom *e;
    qd_statespace s;
    const char *names[] = {"th", "th'", "tau"}, *vals[] = {"0.7", "-1.25", "3"};
    assert_int_equal(lin_text(ctx, PENDULUM, names, vals, 3, &s, &m, &e), QD_OK);
    double g = 9.81, l = 1.5, mm = 2, th = 0.7;
    assert_int_equal(s.nx, 2);
    assert_int_equal(s.nu, 1);
    assert_true(fabs(s.A[0 * 2 + 1] - 1) == 0 && s.A[0] == 0);
    assert_true(fabs(s.A[1 * 2 + 0] + g / l * cos(th)) < 1e-13);
    assert_true(fabs(s.A[1 * 2 + 1]) < 1e-15);
    assert_true(fabs(s.B[1] - 1 / (mm * l * l)) < 1e-15);
    assert_true(fabs(s.xdot0[0] + 1.25) < 1e-15);
    assert_true(fabs(s.xdot0[1] - (-g / l * sin(th) + 3 / (mm * l * l))) < 1e-13);
    /* y = -l cos th: C = l sin th0, D = 0 */
    assert_true(fabs(s.C[0] - l * sin(th)) < 1e-14 && s.D[0] == 0);
    /* the exact entry, evaluated at the parameters' values */
    assert_non_null(s.Asym);
    const qd_expr *ps[3] = {qd_model_param(m, 0), qd_model_param(m, 1), qd_model_param(m, 2)};
    double pv[3] = {mm, l, g}, a10 = 0;
    assert_int_equal(qd_eval(ctx, s.Asym[2], 3, ps, pv, &a10), QD_OK);
    assert_true(fabs(a10 + g / l * cos(th)) < 1e-13);
    /* one input reaches the one oscillator: controllable; y = height sees it
     * (C != 0 at th0 != 0) */
    assert_true(s.controllable && s.observable);
    qd_statespace_free(&s);
    qd_eom_free(e);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

static void check_cart(const qd_statespace *s) {
    double lam = sqrt(9.81 * 1.1 / 0.5);
    assert_int_equal(s->nx, 4);
    assert_true(fabs(s->eig_re[0] - lam) < 1e-12 && fabs(s->eig_re[3] + lam) < 1e-12);
    assert_true(fabs(s->eig_re[1]) < 1e-12 && fabs(s->eig_re[2]) < 1e-12);
    assert_true(fabs(s->B[2] - 1) < 1e-15 && fabs(s->B[3] - 2) < 1e-15);
    assert_true(s->controllable && s->rank_ctrb == 4 && s->nuncontrollable == 0);
}

static qd_status cart_body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)data;
    long to_go = qt_fault_hold(f);
    qd_model *m = qd_model_parse(ctx, CART, NULL);
    assert_non_null(m);
    qd_eom *e = qd_eom_derive(ctx, m);
    assert_non_null(e);
    qt_fault_release(f, to_go);
    qd_statespace s;
    qd_status st = qd_linearize(ctx, e, m, 0, NULL, NULL, &s);
    if (st == QD_OK)
        check_cart(&s);
    qd_statespace_free(&s);
    qd_eom_free(e);
    qd_model_free(m);
    return st;
}

static void test_cart_faults(void **state) {
    (void)state;
    assert_true(qt_fault_loop("linearize cart-pendulum", cart_body, NULL, 1).allocs > 10);
}

static void test_refusals(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qd_model_parse(ctx, "coordinates x, y\nparameters m = 1\ninputs F\n"
                                      "T = m*(x'^2 + y'^2)/2\nQ[x] = F\n"
                                      "constraint c: x*y' - y*x' = 0\n", NULL);
    assert_non_null(m);
    qd_eom *e = qd_eom_derive(ctx, m);
    assert_non_null(e);
    qd_statespace s;
    assert_int_equal(qd_linearize(ctx, e, m, 0, NULL, NULL, &s), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(ctx), "linearize in independent coordinates"));
    qd_statespace_free(&s);
    qd_eom_free(e);
    qd_model_free(m);
    qd_ctx_clear_error(ctx);
    const char *names[] = {"g"}, *vals[] = {"1"};
    assert_int_equal(lin_text(ctx, PENDULUM, names, vals, 1, &s, &m, &e), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(ctx), "'g' is not a coordinate, velocity, input"));
    qd_statespace_free(&s);
    qd_eom_free(e);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pendulum_any_point),
        cmocka_unit_test(test_cart_faults),
        cmocka_unit_test(test_refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
