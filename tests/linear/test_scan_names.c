/*
 * tests/linear/test_scan_names.c - the columns of a steady motion's scan
 * (qd_steady_unknown_name, qd_stability_scan_followed, qdot/stability.h):
 * the conical pendulum (spherical pendulum, Byerly Art. 5 Ex. 3) held at
 * theta0 = pi/3 and scanned along g.  Each column found by its name holds
 * what the name says: "theta" stays pi/3, "phi'" is the rate of the
 * conical motion, phi'^2 = g/(a cos theta0), and "p_phi" its momentum
 * m a^2 sin^2 theta0 phi'.  The sentence names the Routhian for free
 * momenta and V - T0 for a driven rate.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/stability.h"

#define QT_PI 3.14159265358979323846

#define SPHERICAL                                                                              \
    "coordinates theta, phi\nparameters m = 1.1, a = 0.9, g = 9.81, w = 4\n"                   \
    "r = a*(sin(theta)*cos(phi), sin(theta)*sin(phi), -cos(theta))\nparticle m at r\n"         \
    "V = m*g*r.z\n"

static size_t column(const qd_steady *s, size_t n, const char *name) {
    char buf[64];
    for (size_t k = 0; k < n; k++) {
        size_t len = qd_steady_unknown_name(s, k, buf, sizeof buf);
        assert_int_equal(len, strlen(buf));
        if (!strcmp(buf, name))
            return k;
    }
    fail_msg("no column %s", name);
    return 0;
}

static void conical_scan(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qd_model_parse(ctx, SPHERICAL, NULL);
    assert_non_null(m);
    qd_eom *e = qd_eom_derive(ctx, m);
    assert_non_null(e);
    qd_steady *s = qd_steady_derive_named(ctx, m, e, "ignore", "phi", false);
    assert_non_null(s);
    qd_steady_given g = {0};
    qd_steady_spec spec = {.at = "theta = pi/3"};
    assert_int_equal(qd_steady_given_read(ctx, s, m, &spec, &g), QD_OK);
    qd_scan_opts o = {.steps = 8, .about = g.held};
    qd_scan sc = {0};
    assert_int_equal(qd_stability_scan(ctx, s, m, "g", 9, 11, g.xfix, g.wfix, g.pfix, g.pguess,
                                       &g.start, &o, &sc),
                     QD_OK);
    size_t n = s->nkeep + 2 * s->ncyc;
    assert_int_equal(sc.n, n);
    assert_int_equal(n, 3);
    assert_int_equal(qd_steady_unknown_name(s, n, NULL, 0), 0); /* out of range */
    assert_int_equal(qd_steady_unknown_name(s, 2, NULL, 0), strlen("p_phi"));
    char small[3];
    assert_int_equal(qd_steady_unknown_name(s, 2, small, sizeof small), 5); /* cut, as snprintf */
    assert_string_equal(small, "p_");
    size_t th = column(s, n, "theta"), w = column(s, n, "phi'"), p = column(s, n, "p_phi");
    double mass = 1.1, a = 0.9, th0 = QT_PI / 3;
    assert_true(sc.count > 2);
    for (size_t i = 0; i < sc.count; i++) {
        const double *u = sc.q + i * sc.n;
        double gi = sc.value[i];
        assert_true(fabs(u[th] - th0) < 1e-9);
        assert_true(fabs(u[w] * u[w] - gi / (a * cos(th0))) < 1e-8 * gi);
        assert_true(fabs(u[p] - mass * a * a * sin(th0) * sin(th0) * u[w]) < 1e-8);
    }
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_stability_scan_followed(s, sc.damped, &b), QD_OK);
    assert_non_null(strstr(qd_buf_str(&b), "momenta free: Routhian"));
    assert_non_null(strstr(qd_buf_str(&b), "ordinary stability")); /* no damping in the model */
    qd_buf_free(&b);
    qd_scan_free(&sc);
    qd_steady_given_free(&g);
    qd_steady_free(s);
    /* a driven rate: V - T0 */
    s = qd_steady_derive_named(ctx, m, e, "driven", "phi' = w", true);
    assert_non_null(s);
    assert_int_equal(qd_stability_scan_followed(s, false, &b), QD_OK);
    assert_non_null(strstr(qd_buf_str(&b), "rates maintained: V - T0"));
    qd_buf_free(&b);
    qd_steady_free(s);
    qd_eom_free(e);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(conical_scan),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
