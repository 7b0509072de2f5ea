/*
 * tests/linear/test_scan.c - an equilibrium followed along a parameter and
 * the values where its stability changes (qd_modes_scan, qdot/modes.h).
 *
 *   L4 of the restricted three-body problem, followed from the point
 *     x = 1/2 - mu, y = sqrt(3)/2 as mu goes from 0.02 to 0.05: stable
 *     until 27 mu (1 - mu) = 1, Routh's value
 *     mu = (1 - sqrt(23/27))/2 = 0.0385208965...  (Desloge ch. 62 eqs.
 *     75-77, seed-desloge-B.md C6: lambda^2 = (w^2/2)(-1 +- sqrt(1 - R^2)),
 *     R^2 = 27 mu (1 - mu));
 *   a bead on a hoop spinning at omega about its vertical diameter: the
 *     bottom theta = 0 has w^2 = g/a - omega^2 (Desloge ch. 50 example 1,
 *     eq. 39; seed 000), unstable from omega = sqrt(g/a) on;
 *   an inverted pendulum held by a horizontal spring on the bob,
 *     V = m g l cos(theta) + k/2 (l sin(theta))^2: the top has
 *     K = k l^2 - m g l, stable from k = m g/l on;
 *   steady motions (qd_stability_scan): circular orbits r = 1.3 under the
 *     force -k r^n with free angular momentum, stable iff n > -3, and on a
 *     wire driven round, stable iff n > 1 (Britannica 1911 "Dynamics"
 *     sec. 5-6, seed 004; seed-goldstein-britannica.md B08, B09, P4); the
 *     sleeping top with nu = p_psi given, stable iff nu^2 > 4 A M g h
 *     (Britannica sec. 6 (1), seed 004; B11): g = nu^2/(4 A M h);
 *   a particle in a spherical bowl turning at a rate W maintained (the
 *     driven rate follows W as it is scanned): the lowest point is stable
 *     with friction only while W^2 < g/a, always without (Britannica sec. 6
 *     eqs. (2)-(7), seed 004; seed-goldstein-britannica.md B13, P5, P6);
 *   errors: an unknown, fixed or derived parameter, an empty range, a range
 *     through 0 for a parameter assumed positive, an equilibrium that ceases
 *     to exist (V = x^3/3 + c x: x = -sqrt(-c) only while c < 0).
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
#include "qdot/modes.h"
#include "qdot/stability.h"
#include "../util/system.h"

#define THREE_BODY                                                                             \
    "coordinates x, y\nparameters mu = 0.01\n"                                                 \
    "T = 1/2*((x' - y)^2 + (y' + x)^2)\n"                                                      \
    "V = -(1 - mu)/sqrt((x + mu)^2 + y^2) - mu/sqrt((x - 1 + mu)^2 + y^2)\n"

#define HOOP                                                                                   \
    "coordinates theta\nparameters m = 0.3, a = 0.8, omega = 4, g = 9.81\n"                    \
    "r = (a*sin(theta)*cos(omega*t), a*sin(theta)*sin(omega*t), -a*cos(theta))\n"             \
    "particle m at r\nV = m*g*r.z\n"

#define INVERTED                                                                               \
    "coordinates theta\nparameters m = 1.5, l = 0.7, g = 9.81, k = 1\n"                         \
    "particle m at (l*sin(theta), l*cos(theta))\n"                                             \
    "V = m*g*l*cos(theta) + k/2*(l*sin(theta))^2\n"

#define FOLD                                                                                   \
    "coordinates x\nparameters c = -1\nT = x'^2/2\nV = x^3/3 + c*x\n"

/* n expressions read from texts in s's context. */
static void read_all(qt_system *s, size_t n, const char *const *texts, const qd_expr **out) {
    for (size_t j = 0; j < n; j++) {
        out[j] = qd_read(s->ctx, texts[j], NULL, NULL);
        assert_non_null(out[j]);
    }
}

static void l4_routh_value(void **state) {
    qt_system *s = qt_system_derive(state, THREE_BODY, false);
    const char *texts[2] = {"1/2 - mu", "sqrt(3)/2"};
    const qd_expr *about[2];
    read_all(s, 2, texts, about);
    qd_scan_opts o = {.steps = 60, .about = about};
    qd_scan sc;
    assert_int_equal(qd_modes_scan(s->ctx, s->eom, s->model, "mu", 0.02, 0.05, &o, &sc), QD_OK);
    assert_int_equal(sc.count, 61);
    double routh = (1 - sqrt(23.0 / 27.0)) / 2;
    assert_int_equal(sc.ntrans, 1);
    assert_int_equal(sc.trans[0].from, 1);
    assert_int_equal(sc.trans[0].to, 0);
    assert_true(fabs(sc.trans[0].value - routh) < 1e-10);
    assert_true(sc.trans[0].hi - sc.trans[0].lo <= 1e-10);
    for (size_t k = 0; k < sc.count; k++) {
        double mu = sc.value[k];
        /* the point followed is L4 itself, and its verdict is Routh's criterion */
        assert_true(fabs(sc.q[2 * k] - (0.5 - mu)) < 1e-10);
        assert_true(fabs(sc.q[2 * k + 1] - sqrt(3) / 2) < 1e-10);
        assert_false(sc.conservative[k]);
        assert_int_equal(sc.stable[k], 27 * mu * (1 - mu) < 1 ? 1 : 0);
    }
    qd_scan_free(&sc);
    /* the model's value of mu is left as it was */
    double mu0;
    assert_int_equal(qd_eval(s->ctx, qd_model_param_value(s->model, 0), 0, NULL, NULL, &mu0),
                     QD_OK);
    assert_true(mu0 == 0.01);
}

/* Without `about`: started from a guess, the point is followed by
 * continuation alone; the steps do not move the threshold. */
static void l4_from_start(void **state) {
    qt_system *s = qt_system_derive(state, THREE_BODY, false);
    double start[2] = {0.45, 0.9};
    double routh = (1 - sqrt(23.0 / 27.0)) / 2;
    size_t steps[3] = {7, 13, 200};
    for (int i = 0; i < 3; i++) {
        qd_scan_opts o = {.steps = steps[i], .start = start};
        qd_scan sc;
        assert_int_equal(qd_modes_scan(s->ctx, s->eom, s->model, "mu", 0.001, 0.1, &o, &sc),
                         QD_OK);
        assert_int_equal(sc.ntrans, 1);
        assert_true(fabs(sc.trans[0].value - routh) < 1e-10);
        assert_true(fabs(sc.q[2 * steps[i]] - (0.5 - 0.1)) < 1e-10);
        qd_scan_free(&sc);
    }
}

static void hoop_bottom(void **state) {
    qt_system *s = qt_system_derive(state, HOOP, false);
    const char *texts[1] = {"0"};
    const qd_expr *about[1];
    read_all(s, 1, texts, about);
    qd_scan_opts o = {.steps = 25, .about = about};
    qd_scan sc;
    assert_int_equal(qd_modes_scan(s->ctx, s->eom, s->model, "omega", 1, 6, &o, &sc), QD_OK);
    assert_int_equal(sc.ntrans, 1);
    assert_int_equal(sc.trans[0].from, 1);
    assert_int_equal(sc.trans[0].to, 0);
    assert_true(fabs(sc.trans[0].value - sqrt(9.81 / 0.8)) < 1e-10);
    for (size_t k = 0; k < sc.count; k++) {
        double w = sc.value[k];
        assert_true(sc.conservative[k]);
        assert_true(fabs(sc.q[k]) < 1e-12);
        /* the margin is the w^2 of the mode: g/a - omega^2 (eq. 39) */
        assert_true(fabs(sc.margin[k] - (9.81 / 0.8 - w * w)) < 1e-9);
    }
    qd_scan_free(&sc);
}

static void inverted_spring(void **state) {
    qt_system *s = qt_system_derive(state, INVERTED, false);
    double start[1] = {0.01};
    qd_scan_opts o = {.steps = 40, .start = start};
    qd_scan sc;
    assert_int_equal(qd_modes_scan(s->ctx, s->eom, s->model, "k", 1, 50, &o, &sc), QD_OK);
    assert_int_equal(sc.ntrans, 1);
    assert_int_equal(sc.trans[0].from, 0);
    assert_int_equal(sc.trans[0].to, 1);
    double kc = 1.5 * 9.81 / 0.7;
    assert_true(fabs(sc.trans[0].value - kc) < 1e-10 * kc);
    qd_scan_free(&sc);
}

static void expect_error(qt_system *s, const char *param, double a, double b,
                         const qd_scan_opts *o, qd_status want, const char *words) {
    qd_scan sc;
    qd_ctx_clear_error(s->ctx);
    assert_int_equal(qd_modes_scan(s->ctx, s->eom, s->model, param, a, b, o, &sc), want);
    if (!strstr(qd_ctx_message(s->ctx), words))
        fail_msg("message '%s' lacks '%s'", qd_ctx_message(s->ctx), words);
    qd_scan_free(&sc);
}

/* The message of the last expect_error, then a clean context. */
static double value_after(qt_system *s, const char *prefix) {
    const char *msg = strstr(qd_ctx_message(s->ctx), prefix);
    assert_non_null(msg);
    double v = strtod(msg + strlen(prefix), NULL);
    qd_ctx_clear_error(s->ctx);
    return v;
}

static void errors(void **state) {
    qt_system *s = qt_system_derive(state, HOOP, false);
    double start[1] = {0};
    qd_scan_opts o = {.steps = 10, .start = start};
    expect_error(s, "omaga", 1, 2, &o, QD_ERR_ARG, "'omaga' is not a parameter");
    expect_error(s, "omega", 2, 2, &o, QD_ERR_ARG, "give A < B");
    expect_error(s, "omega", 3, 1, &o, QD_ERR_ARG, "give A < B");
    expect_error(s, "omega", -1, 1, &o, QD_ERR_ARG, "assumed positive");
}

static void derived_and_fixed(void **state) {
    qt_system *s = qt_system_derive(state, "coordinates x\nparameters k = 2, m = 2*k\n"
                                           "T = m/2*x'^2\nV = k/2*x^2\n", false);
    double start[1] = {0.1};
    qd_scan_opts o = {.steps = 4, .start = start};
    expect_error(s, "m", 1, 2, &o, QD_ERR_ARG, "defined from other parameters");
    qd_ctx_clear_error(s->ctx);
    /* m follows k: w^2 = k/m = 1/2 whatever k */
    qd_scan sc;
    assert_int_equal(qd_modes_scan(s->ctx, s->eom, s->model, "k", 1, 3, &o, &sc), QD_OK);
    for (size_t i = 0; i < sc.count; i++)
        assert_true(fabs(sc.margin[i] - 0.5) < 1e-12);
    qd_scan_free(&sc);

    qd_ctx *ctx = qd_ctx_new();
    qd_param_value pv = {"k", qd_int(ctx, 3)};
    qd_model_opts mo = {.params = &pv, .nparams = 1, .fix_params = true};
    qd_model *m = qd_model_parse_opts(ctx, "coordinates x\nparameters k = 2\nT = x'^2/2\n"
                                           "V = k/2*x^2\n", &mo, NULL);
    assert_non_null(m);
    qd_eom *e = qd_eom_derive(ctx, m);
    assert_non_null(e);
    assert_int_equal(qd_modes_scan(ctx, e, m, "k", 1, 2, &o, &sc), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(ctx), "is fixed"));
    qd_scan_free(&sc);
    qd_eom_free(e);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* x = -sqrt(-c) is a maximum of V for c < 0 and meets the minimum at c = 0,
 * a fold: past it there is no equilibrium to follow. */
static void lost(void **state) {
    qt_system *s = qt_system_derive(state, FOLD, false);
    double start[1] = {-1};
    qd_scan_opts o = {.steps = 20, .start = start};
    expect_error(s, "c", -1, 1, &o, QD_ERR_NUMERIC, "the equilibrium is lost at c = ");
    double at = value_after(s, "lost at c = ");
    assert_true(at > 0 && at <= 0.1 + 1e-12);
    /* up to the fold it is followed, unstable (w^2 = -2 sqrt(-c)) */
    qd_scan sc;
    assert_int_equal(qd_modes_scan(s->ctx, s->eom, s->model, "c", -1, -0.01, &o, &sc), QD_OK);
    for (size_t k = 0; k < sc.count; k++) {
        assert_true(fabs(sc.q[k] + sqrt(-sc.value[k])) < 1e-8);
        assert_true(fabs(sc.margin[k] + 2 * sqrt(-sc.value[k])) < 1e-7);
        assert_int_equal(sc.stable[k], 0);
    }
    qd_scan_free(&sc);
}

/* ---- steady motions ------------------------------------------------------------------ */

#define POWER_LAW                                                                              \
    "coordinates r, theta\nparameters m = 3/2, k = 2, n = -2.5\n"                              \
    "particle m at (r*cos(theta), r*sin(theta))\nV = k*r^(n + 1)/(n + 1)\n"

#define SLEEPING_TOP                                                                           \
    "coordinates a, b, psi\nparameters M = 1, h = 1/2, g = 2, A = 1, C = 1/2\n"                \
    "R = rot_x(a)*rot_y(b)*rot_z(psi)\n"                                                       \
    "body top mass M inertia (A - M*h^2, A - M*h^2, C) at R*(0, 0, h) orientation R\n"         \
    "V = M*g*position(top).z\n"

/* The scan of s along param with kept coordinate 0 held at x0 (hold) or
 * momentum 0 held at p0. */
static void steady_scan(qt_system *sys, qd_steady *s, const char *param, double a, double b,
                        bool hold_x, double x0, double p0, size_t steps, qd_scan *out) {
    double x[4] = {x0}, w[2] = {1}, p[2] = {p0};
    bool xfix[4] = {hold_x}, wfix[2] = {false}, pfix[2] = {!hold_x};
    qd_steady_point start = {x, w, p};
    qd_scan_opts o = {.steps = steps};
    qd_status st = qd_stability_scan(sys->ctx, s, sys->model, param, a, b, xfix, wfix, pfix, NULL,
                                     &start, &o, out);
    if (st != QD_OK)
        fail_msg("qd_stability_scan: %s", qd_ctx_message(sys->ctx));
}

static void orbits_free_and_driven(void **state) {
    qt_system *sys = qt_system_derive(state, POWER_LAW, false);
    const qd_expr *theta = qt_symbol(sys, "theta");
    for (int driven = 0; driven < 2; driven++) {
        qd_steady *s = qd_steady_derive(sys->ctx, sys->model, sys->eom, 1, &theta, driven);
        assert_non_null(s);
        qd_scan sc;
        double a = driven ? 0 : -4, b = driven ? 3 : -2, nc = driven ? 1 : -3;
        steady_scan(sys, s, "n", a, b, true, 1.3, 0, 30, &sc);
        assert_int_equal(sc.n, 3);
        assert_int_equal(sc.ntrans, 1);
        assert_int_equal(sc.trans[0].from, 0);
        assert_int_equal(sc.trans[0].to, 1);
        assert_true(fabs(sc.trans[0].value - nc) < 1e-10);
        for (size_t k = 0; k < sc.count; k++) {
            double n = sc.value[k], w2 = 2 * pow(1.3, n - 1) / 1.5;
            assert_true(sc.q[3 * k] == 1.3);   /* held */
            assert_true(fabs(sc.q[3 * k + 1] * sc.q[3 * k + 1] - w2) < 1e-9 * w2);
        }
        qd_scan_free(&sc);
        qd_steady_free(s);
    }
}

static void sleeping_top(void **state) {
    qt_system *sys = qt_system_derive(state, SLEEPING_TOP, false);
    const qd_expr *psi = qt_symbol(sys, "psi");
    qd_steady *s = qd_steady_derive(sys->ctx, sys->model, sys->eom, 1, &psi, false);
    assert_non_null(s);
    /* 30 steps put a sample on the threshold (borderline there), 29 do not */
    for (size_t steps = 29; steps <= 30; steps++) {
        qd_scan sc;
        steady_scan(sys, s, "g", 1, 8, false, 0, 3, steps, &sc);
        assert_int_equal(sc.ntrans, 1);
        assert_int_equal(sc.trans[0].from, 1);
        assert_int_equal(sc.trans[0].to, 0);
        /* nu^2 = 4 A M g h: g = 9/(4 * 1 * 1 * 1/2) */
        assert_true(fabs(sc.trans[0].value - 4.5) < 1e-10);
        for (size_t k = 0; k < sc.count; k++) {
            assert_true(fabs(sc.q[4 * k]) < 1e-12 && fabs(sc.q[4 * k + 1]) < 1e-12);
            assert_true(sc.q[4 * k + 3] == 3);
        }
        qd_scan_free(&sc);
    }
    qd_steady_free(s);
}

#define BOWL                                                                                   \
    "coordinates x, y, phi\nparameters m = 1, I = 1, a = 0.8, g = 1.3, k = 0.1, W = 0.5\n"     \
    "z = a - sqrt(a^2 - x^2 - y^2)\nparticle m at rot_z(phi)*(x, y, z)\nT = I/2*phi'^2\n"      \
    "V = m*g*z\ndissipation = k*m/2*(x'^2 + y'^2 + z'^2)\n"

static void bowl_driven_at_parameter(void **state) {
    qt_system *sys = qt_system_derive(state, BOWL, false);
    const qd_expr *phi = qt_symbol(sys, "phi");
    qd_steady *s = qd_steady_derive(sys->ctx, sys->model, sys->eom, 1, &phi, true);
    assert_non_null(s);
    /* u = (x, y, phi', p_phi): phi' held at W */
    double x[2] = {0, 0}, w[1] = {0.5}, p[1] = {0};
    bool xfix[2] = {false, false}, wfix[1] = {true}, pfix[1] = {false};
    const qd_expr *given[4] = {NULL, NULL, qt_symbol(sys, "W"), NULL};
    qd_steady_point start = {x, w, p};
    qd_scan_opts o = {.steps = 13, .about = given};
    qd_scan sc;
    assert_int_equal(qd_stability_scan(sys->ctx, s, sys->model, "W", 0.2, 2.5, xfix, wfix, pfix,
                                       NULL, &start, &o, &sc), QD_OK);
    assert_true(sc.damped);
    assert_int_equal(sc.ntrans, 1);
    assert_int_equal(sc.trans[0].from, 1);
    assert_int_equal(sc.trans[0].to, 0);
    assert_true(fabs(sc.trans[0].value - sqrt(1.3 / 0.8)) < 1e-10);
    for (size_t k = 0; k < sc.count; k++)
        assert_true(sc.q[4 * k + 2] == sc.value[k]);   /* the rate followed W */
    qd_scan_free(&sc);
    qd_steady_free(s);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(l4_routh_value, qt_system_teardown),
        cmocka_unit_test_teardown(l4_from_start, qt_system_teardown),
        cmocka_unit_test_teardown(hoop_bottom, qt_system_teardown),
        cmocka_unit_test_teardown(inverted_spring, qt_system_teardown),
        cmocka_unit_test_teardown(errors, qt_system_teardown),
        cmocka_unit_test_teardown(derived_and_fixed, qt_system_teardown),
        cmocka_unit_test_teardown(lost, qt_system_teardown),
        cmocka_unit_test_teardown(orbits_free_and_driven, qt_system_teardown),
        cmocka_unit_test_teardown(sleeping_top, qt_system_teardown),
        cmocka_unit_test_teardown(bowl_driven_at_parameter, qt_system_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
