/*
 * tests/linear/test_scan_print.c - a scan written by the library
 * (qd_scan_print, qd_scan_json: qdot/modes.h), checked against the physics
 * it reports: the inverted pendulum held up by a spring, V = m g l cos(theta)
 * + k l^2 theta^2 / 2 (examples/inverted_pendulum_spring.qd), is stable at
 * theta = 0 exactly when k l > m g, so the scan over k from 1 to 50 reports
 * one transition, unstable -> stable, at k = m g / l, within its bracket;
 * every sample's verdict agrees with the sign of k - m g / l.
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

static const char *model = "coordinates theta\nparameters m = 1, g = 9.81, l = 1, k = 20\n"
                           "T = m*l^2*theta'^2/2\nV = m*g*l*cos(theta) + k*l^2*theta^2/2\n";

static double number_after(const char *s, const char *key) {
    const char *p = strstr(s, key);
    assert_non_null(p);
    return strtod(p + strlen(key), NULL);
}

static void test_spring_pendulum(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qd_model_parse(ctx, model, NULL);
    assert_non_null(m);
    qd_eom *e = qd_eom_derive(ctx, m);
    assert_non_null(e);
    const qd_expr *about[1] = {qd_int(ctx, 0)};
    qd_scan_opts o = {.steps = 7, .about = about};
    qd_scan sc = {0};
    assert_int_equal(qd_modes_scan(ctx, e, m, "k", 1, 50, &o, &sc), QD_OK);
    const char *names[1] = {"theta"};
    qd_scan_view v = {"k", names, "the equilibrium from theta = 0", "equilibrium"};
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_scan_json(&v, &sc, &b), QD_OK);
    const char *s = qd_buf_str(&b);
    double kc = 9.81; /* m g / l */
    assert_non_null(strstr(s, "\"from\": \"unstable\""));
    assert_non_null(strstr(s, "\"to\": \"stable\""));
    const char *tr = strstr(s, "\"transitions\"");
    assert_non_null(tr);
    double at = number_after(tr, "\"k\": ");
    double lo = number_after(tr, "\"bracket\": [");
    assert_true(fabs(at - kc) < 1e-9 && lo <= kc + 1e-12);
    /* each sample: stable exactly where k > m g / l */
    for (size_t i = 0; i < sc.count; i++)
        assert_int_equal(sc.stable[i], sc.value[i] > kc ? 1 : 0);
    qd_buf_free(&b);
    b = (qd_buf)QD_BUF_INIT;
    assert_int_equal(qd_scan_print(&v, &sc, &b), QD_OK);
    s = qd_buf_str(&b);
    assert_non_null(strstr(s, "scan of k from 1 to 50 in 7 steps"));
    assert_non_null(strstr(s, "transition: k = 9.81, unstable -> stable"));
    qd_buf_free(&b);
    /* an empty scan is refused, not read past its end */
    qd_scan none = {0};
    b = (qd_buf)QD_BUF_INIT;
    assert_int_equal(qd_scan_print(&v, &none, &b), QD_ERR_ARG);
    qd_buf_free(&b);
    qd_scan_free(&sc);
    qd_eom_free(e);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_spring_pendulum),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
