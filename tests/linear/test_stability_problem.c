/*
 * tests/linear/test_stability_problem.c - a steady-motion problem stated by
 * name, solved and scanned (qd_stability_problem, qdot/stability.h), as
 * `qdot stability` states it, against the textbooks' closed forms:
 *
 *   conical pendulum, momentum free, held at theta0 = pi/3:
 *     phi'^2 = g/(l cos theta0) and the oscillation about it
 *     w^2 = (g/(l cos theta0)) (1 + 3 cos^2 theta0), stable (Britannica 1911
 *     "Dynamics" sec. 5, seed 004; Byerly Art. 9a, seed-byerly.md);
 *   the same pendulum driven at phi' = W (a bead on a turning hoop): the
 *     tilted motion at cos theta0 = g/(l W^2) with w^2 = W^2 sin^2 theta0
 *     ((V - T0)''/(m l^2) = g cos theta0/l - W^2 cos 2 theta0; reference
 *     seed-goldstein-britannica.md, pitfall P4);
 *   a particle in a spherical bowl turned at W with friction: the lowest
 *     point loses its stability at W^2 = g/a (Britannica sec. 6 eqs. (2)-(7);
 *     reference B13), found by the scan with the driven rate following W.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "qdot/stability.h"
#include "util/system.h"

#define QT_PI 3.14159265358979323846

static const char conical[] =
    "coordinates theta, phi\n"
    "parameters m = 2, l = 0.7, g = 9.81, W = 5\n"
    "particle m at l*(sin(theta)*cos(phi), sin(theta)*sin(phi), -cos(theta))\n"
    "V = m*g*l*(-cos(theta))\n";

static void test_conical_free(void **state) {
    qt_system *s = qt_system_derive(state, conical, false);
    const double g = 9.81, l = 0.7, c = cos(QT_PI / 3);
    qd_stability_spec spec = {.ignore = "phi", .at = "theta = pi/3"};
    qd_stability_problem p;
    assert_int_equal(qd_stability_problem_read(s->ctx, s->model, s->eom, &spec, &p), QD_OK);
    assert_int_equal(qd_stability_problem_solve(s->ctx, &p), QD_OK);
    assert_true(p.set.count >= 1);
    const qd_steady_point *pt = &p.set.pts[0];
    assert_true(fabs(pt->x[0] - QT_PI / 3) < 1e-15);
    assert_true(fabs(pt->w[0] * pt->w[0] - g / (l * c)) < 1e-10 * g / (l * c));
    assert_int_equal(p.an[0].nfreq, 1);
    double w2 = g / (l * c) * (1 + 3 * c * c);
    assert_true(fabs(p.an[0].freq[0] * p.an[0].freq[0] - w2) < 1e-9 * w2);
    assert_int_equal(p.an[0].ordinary_stable, 1);
    assert_int_equal(p.an[0].secular_stable, 1);
    qd_stability_problem_free(&p);
}

static void test_conical_driven(void **state) {
    qt_system *s = qt_system_derive(state, conical, false);
    const double g = 9.81, l = 0.7, W = 5, c = g / (l * W * W);
    const char *driven[] = {"phi' = W"};
    qd_stability_spec spec = {.driven = driven, .ndriven = 1, .guess = "theta = 1"};
    qd_stability_problem p;
    assert_int_equal(qd_stability_problem_read(s->ctx, s->model, s->eom, &spec, &p), QD_OK);
    assert_string_equal(p.driven, "phi' = W");
    assert_int_equal(qd_stability_problem_solve(s->ctx, &p), QD_OK);
    size_t tilted = p.set.count;
    for (size_t k = 0; k < p.set.count; k++)
        if (fabs(cos(p.set.pts[k].x[0]) - c) < 1e-10)
            tilted = k;
    assert_true(tilted < p.set.count);
    assert_true(p.set.pts[tilted].w[0] == W);
    double w2 = W * W * (1 - c * c);
    assert_true(fabs(p.an[tilted].freq[0] * p.an[tilted].freq[0] - w2) < 1e-9 * w2);
    assert_int_equal(p.an[tilted].ordinary_stable, 1);
    qd_stability_problem_free(&p);
}

#define BOWL                                                                                   \
    "coordinates x, y, phi\nparameters m = 1, I = 1, a = 0.8, g = 1.3, k = 0.1, W = 0.5\n"     \
    "z = a - sqrt(a^2 - x^2 - y^2)\nparticle m at rot_z(phi)*(x, y, z)\nT = I/2*phi'^2\n"      \
    "V = m*g*z\ndissipation = k*m/2*(x'^2 + y'^2 + z'^2)\n"

static void test_bowl_scan(void **state) {
    qt_system *s = qt_system_derive(state, BOWL, false);
    const char *driven[] = {"phi' = W"};
    qd_stability_spec spec = {.driven = driven, .ndriven = 1};
    qd_stability_problem p;
    assert_int_equal(qd_stability_problem_read(s->ctx, s->model, s->eom, &spec, &p), QD_OK);
    qd_scan sc;
    assert_int_equal(qd_stability_problem_scan(s->ctx, &p, s->model, "W", 0.2, 2.5, 13, &sc),
                     QD_OK);
    assert_true(sc.damped);
    assert_int_equal(sc.ntrans, 1);
    assert_true(sc.trans[0].from == 1 && sc.trans[0].to == 0);
    assert_true(fabs(sc.trans[0].value - sqrt(1.3 / 0.8)) < 1e-10);
    for (size_t k = 0; k < sc.count; k++)
        assert_true(sc.q[4 * k + 2] == sc.value[k]); /* the rate followed W */
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_stability_scan_write(s->ctx, &p, "W", &sc, true, &b), QD_OK);
    assert_true(!b.failed && qd_buf_str(&b)[0] == '{');
    qd_buf_free(&b);
    qd_scan_free(&sc);
    qd_stability_problem_free(&p);
}

static void test_errors(void **state) {
    qt_system *s = qt_system_derive(state, conical, false);
    const char *driven[] = {"phi' = W"};
    qd_stability_problem p;
    qd_stability_spec both = {.ignore = "phi", .driven = driven, .ndriven = 1};
    assert_int_equal(qd_stability_problem_read(s->ctx, s->model, s->eom, &both, &p), QD_ERR_ARG);
    qd_stability_problem_free(&p);
    qd_ctx_clear_error(s->ctx);
    qd_stability_spec at = {.ignore = "phi", .at = "thta = 1"};
    assert_int_equal(qd_stability_problem_read(s->ctx, s->model, s->eom, &at, &p), QD_ERR_ARG);
    const qd_diag *d = qd_ctx_diag(s->ctx);
    assert_true(d->located && d->offset == 0 && !strcmp(d->name, "at"));
    qd_stability_problem_free(&p);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(test_conical_free, qt_system_teardown),
        cmocka_unit_test_teardown(test_conical_driven, qt_system_teardown),
        cmocka_unit_test_teardown(test_bowl_scan, qt_system_teardown),
        cmocka_unit_test_teardown(test_errors, qt_system_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
