/*
 * tests/path/test_path.c - the stationary paths of the action between two
 * configurations (qd_path_find, qd_path_find_energy) against closed forms
 * (Desloge ch. 82-83, Hamilton's principle; ch. 84 and Byerly ch. IV for
 * Maupertuis; seed-desloge-D.md):
 *
 *   the projectile (0,0) -> (X,0) in T: one path, v0 = (X/T, gT/2),
 *     S = int (m/2 v^2 - m g y) dt = m X^2/(2T) - m g^2 T^3/24
 *     (by hand: the y part is m g^2 T^3 (1/24 - 1/4 + 1/6));
 *   the oscillator a -> b in T < pi/w: v0 = w (b - a cos wT)/sin wT,
 *     S = m w ((a^2 + b^2) cos wT - 2 a b) / (2 sin wT);
 *   the pendulum over a long time: several distinct paths, each ending at q1;
 *   the projectile at energy E through (X, Y): the high and the low lob,
 *     tan(theta) = (v^2 +- sqrt(v^4 - g (g X^2 + 2 Y v^2)))/(g X), v^2 = 2E/m;
 *   unreachable ends: off a holonomic constraint, beyond the turning point.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <string.h>

#include "qdot/path.h"
#include "sim/sim_fixture.h"

#define assert_double_equal(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

static const char *projectile = "coordinates x, y\nparameters m = 2, g = 9.81\n"
                                "particle m at (x, y)\nV = m*g*y\n";

static void test_projectile_time(void **state) {
    (void)state;
    sim_fix *f = sf_load(projectile);
    assert_non_null(f);
    double m = 2, g = 9.81, X = 10, T = 2;
    double q0[2] = {0, 0}, q1[2] = {X, 0};
    qd_path_opts o = {.t0 = 0, .t1 = T, .q0 = q0, .q1 = q1};
    qd_path_set ps;
    assert_int_equal(qd_path_find(f->ctx, f->m, f->e, &o, &ps), QD_OK);
    assert_int_equal(ps.count, 1);
    assert_double_equal(ps.paths[0].v0[0], X / T, 1e-8);
    assert_double_equal(ps.paths[0].v0[1], g * T / 2, 1e-8);
    assert_double_equal(ps.paths[0].action, m * X * X / (2 * T) - m * g * g * T * T * T / 24, 1e-7);
    /* the top of the arc at T/2: y = g T^2/8 */
    const qd_path *p = &ps.paths[0];
    assert_double_equal(p->q[(p->nsamples / 2) * 2 + 1], g * T * T / 8, 1e-8);
    /* --all finds no second path: the motion is linear in v0 */
    qd_path_set_free(&ps);
    o.all = true;
    assert_int_equal(qd_path_find(f->ctx, f->m, f->e, &o, &ps), QD_OK);
    assert_int_equal(ps.count, 1);
    qd_path_set_free(&ps);
    sf_free(f);
}

static void test_oscillator(void **state) {
    (void)state;
    sim_fix *f = sf_load("coordinates x\nparameters m = 3, k = 12\nT = m*x'^2/2\nV = k*x^2/2\n");
    assert_non_null(f);
    double m = 3, w = 2, a = 0.3, b = -0.5, T = 1.2;  /* w T = 2.4 < pi */
    qd_path_opts o = {.t0 = 0.5, .t1 = 0.5 + T, .q0 = &a, .q1 = &b, .all = true};
    qd_path_set ps;
    assert_int_equal(qd_path_find(f->ctx, f->m, f->e, &o, &ps), QD_OK);
    assert_int_equal(ps.count, 1);
    double c = cos(w * T), s = sin(w * T);
    assert_double_equal(ps.paths[0].v0[0], w * (b - a * c) / s, 1e-7);
    assert_double_equal(ps.paths[0].action, m * w * ((a * a + b * b) * c - 2 * a * b) / (2 * s), 1e-7);
    assert_double_equal(ps.paths[0].t[0], 0.5, 0);
    assert_double_equal(ps.paths[0].t[ps.paths[0].nsamples - 1], 0.5 + T, 1e-12);
    /* shorter than half a period: no focus, a true minimum (Desloge ch. 84) */
    assert_int_equal(ps.paths[0].nfoci, 0);
    assert_true(ps.paths[0].legendre && ps.paths[0].minimum);
    qd_path_set_free(&ps);
    /* longer: the focus at half a period pi/w after the start, no minimum */
    double T2 = 2.2;
    o.t1 = 0.5 + T2;
    o.all = false;
    assert_int_equal(qd_path_find(f->ctx, f->m, f->e, &o, &ps), QD_OK);
    assert_int_equal(ps.count, 1);
    assert_double_equal(ps.paths[0].v0[0], w * (b - a * cos(w * T2)) / sin(w * T2), 1e-7);
    assert_int_equal(ps.paths[0].nfoci, 1);
    assert_double_equal(ps.paths[0].foci[0], 0.5 + SF_PI / w, 1e-8);
    assert_false(ps.paths[0].minimum);
    qd_path_set_free(&ps);
    sf_free(f);
}

/* A pendulum (omega = pi) from 0.1 to 0.2 rad in 5 time units: besides the
 * near-linear path, librations of larger amplitude whose period fits. */
static void test_pendulum_several(void **state) {
    (void)state;
    sim_fix *f = sf_load("coordinates th\nparameters g = 9.8696044010893586\n"
                         "T = th'^2/2\nV = -g*cos(th)\n");
    assert_non_null(f);
    double a = 0.1, b = 0.2;
    qd_path_opts o = {.t0 = 0, .t1 = 5, .q0 = &a, .q1 = &b, .all = true};
    qd_path_set ps;
    assert_int_equal(qd_path_find(f->ctx, f->m, f->e, &o, &ps), QD_OK);
    assert_true(ps.count >= 2);
    for (size_t i = 0; i < ps.count; i++) {
        const qd_path *p = &ps.paths[i];
        assert_double_equal(p->q[0], a, 0);
        assert_double_equal(p->q[p->nsamples - 1], b, 1e-8);
        if (i > 0) {
            assert_true(p->action >= ps.paths[i - 1].action);
            assert_true(fabs(p->v0[0] - ps.paths[i - 1].v0[0]) > 1e-6);
        }
        /* energy conserved along the samples (finite differences): the
         * sampled curve is a motion, not just any curve through the ends */
        double dt = p->t[1] - p->t[0];
        double v1 = (p->q[2] - p->q[0]) / (2 * dt);
        size_t k = p->nsamples - 2;
        double v2 = (p->q[k + 1] - p->q[k - 1]) / (2 * dt);
        double e1 = v1 * v1 / 2 - 9.8696044010893586 * cos(p->q[1]);
        double e2 = v2 * v2 / 2 - 9.8696044010893586 * cos(p->q[k]);
        assert_true(fabs(e1 - e2) < 1e-2 * (1 + fabs(e1)));
    }
    qd_path_set_free(&ps);
    sf_free(f);
}

static void projectile_lobs(double X, double Y, double v) {
    sim_fix *f = sf_load(projectile);
    assert_non_null(f);
    double m = 2, g = 9.81, E = m * v * v / 2;
    double q0[2] = {0, 0}, q1[2] = {X, Y};
    qd_path_opts o = {.t0 = 0, .q0 = q0, .q1 = q1, .all = true};
    qd_path_set ps;
    assert_int_equal(qd_path_find_energy(f->ctx, f->m, f->e, E, &o, &ps), QD_OK);
    assert_int_equal(ps.count, 2);
    double disc = sqrt(v * v * v * v - g * (g * X * X + 2 * Y * v * v));
    double th[2] = {atan((v * v - disc) / (g * X)), atan((v * v + disc) / (g * X))};
    bool seen[2] = {false, false};
    for (size_t i = 0; i < 2; i++) {
        const qd_path *p = &ps.paths[i];
        double ang = atan2(p->v0[1], p->v0[0]);
        assert_double_equal(hypot(p->v0[0], p->v0[1]), v, 1e-7);
        for (int k = 0; k < 2; k++)
            if (fabs(ang - th[k]) < 1e-7)
                seen[k] = true;
        /* the time of flight X / (v cos theta) */
        double Tf = p->t[p->nsamples - 1] - p->t[0];
        assert_double_equal(Tf, X / (v * cos(ang)), 1e-7);
    }
    assert_true(seen[0] && seen[1]);
    qd_path_set_free(&ps);
    sf_free(f);
}

/* The issue 33 case too: an end below the start with v^2/(g X) = 30, whose
 * high lob flies 54 times longer than the low one (the multistart's starts
 * near the chord missed it; the ballistic starts aim at it). */
static void test_projectile_energy(void **state) {
    (void)state;
    projectile_lobs(8, 2, 12);
    projectile_lobs(2, -1, sqrt(30 * 9.81 * 2));
}

/* An end on the envelope of the paths of one energy (the parabola of safety,
 * y = v^2/(2g) - g x^2/(2 v^2); seed-goldstein-britannica.md B19): the high
 * and the low lob merge into one path, launched at tan(theta) = v^2/(g X).
 * Newton stops within sqrt(tol) of such a double root anywhere, and --all
 * listed the one path eight times. */
static void test_projectile_envelope(void **state) {
    (void)state;
    sim_fix *f = sf_load(projectile);
    assert_non_null(f);
    double m = 2, g = 9.81, v = 12, E = m * v * v / 2, X = 8;
    double Y = v * v / (2 * g) - g * X * X / (2 * v * v);
    double q0[2] = {0, 0}, q1[2] = {X, Y};
    qd_path_opts o = {.t0 = 0, .q0 = q0, .q1 = q1, .all = true};
    qd_path_set ps;
    assert_int_equal(qd_path_find_energy(f->ctx, f->m, f->e, E, &o, &ps), QD_OK);
    assert_int_equal(ps.count, 1);
    double ang = atan2(ps.paths[0].v0[1], ps.paths[0].v0[0]);
    assert_double_equal(ang, atan(v * v / (g * X)), 1e-4); /* a double root: sqrt(tol) */
    qd_path_set_free(&ps);
    /* 1e-6 inside the envelope the two lobs are distinct (launch angles
     * theta = atan((v^2 -+ disc)/(g X)) about 3e-4 apart) and both are kept */
    q1[1] = Y - 1e-6;
    assert_int_equal(qd_path_find_energy(f->ctx, f->m, f->e, E, &o, &ps), QD_OK);
    assert_int_equal(ps.count, 2);
    double disc = sqrt(v * v * v * v - g * (g * X * X + 2 * q1[1] * v * v));
    for (size_t i = 0; i < 2; i++) {
        double a = atan2(ps.paths[i].v0[1], ps.paths[i].v0[0]);
        double lo = atan((v * v - disc) / (g * X)), hi = atan((v * v + disc) / (g * X));
        assert_true(fabs(a - lo) < 1e-6 || fabs(a - hi) < 1e-6);
    }
    assert_true(fabs(atan2(ps.paths[0].v0[1], ps.paths[0].v0[0]) -
                     atan2(ps.paths[1].v0[1], ps.paths[1].v0[0])) > 1e-4);
    qd_path_set_free(&ps);
    sf_free(f);
}

/* The action does not depend on the coordinates: the pendulum written with
 * a rod constraint in (x, y) and with its angle give the same path, x'(0) =
 * l th'(0), and the same S (Desloge ch. 82). */
static void test_constrained_same_as_angle(void **state) {
    (void)state;
    sim_fix *fc = sf_load("coordinates x, y\nparameters m = 0.6, l = 1.4, g = 9.81\n"
                          "particle m at (x, y)\nV = m*g*y\nconstraint rod: x^2 + y^2 = l^2\n");
    sim_fix *fa = sf_load("coordinates th\nparameters m = 0.6, l = 1.4, g = 9.81\n"
                          "particle m at l*(sin(th), -cos(th))\nV = -m*g*l*cos(th)\n");
    assert_non_null(fc);
    assert_non_null(fa);
    double l = 1.4, th1 = 0.3, T = 0.5;
    double q0[2] = {0, -l}, q1[2] = {l * sin(th1), -l * cos(th1)}, a0 = 0;
    qd_path_opts oc = {.t0 = 0, .t1 = T, .q0 = q0, .q1 = q1};
    qd_path_opts oa = {.t0 = 0, .t1 = T, .q0 = &a0, .q1 = &th1};
    qd_path_set pc, pa;
    assert_int_equal(qd_path_find(fc->ctx, fc->m, fc->e, &oc, &pc), QD_OK);
    assert_int_equal(qd_path_find(fa->ctx, fa->m, fa->e, &oa, &pa), QD_OK);
    assert_double_equal(pc.paths[0].v0[0], l * pa.paths[0].v0[0], 1e-6);
    assert_double_equal(pc.paths[0].v0[1], 0, 1e-6);
    assert_double_equal(pc.paths[0].action, pa.paths[0].action, 1e-6);
    /* the angle form is unconstrained: there the foci run, none before T */
    assert_true(pa.paths[0].minimum);
    qd_path_set_free(&pc);
    qd_path_set_free(&pa);
    sf_free(fc);
    sf_free(fa);
}

/* A free particle on a sphere of radius 1 (written as a constraint) from
 * the north pole to the south pole in time pi: every great circle through
 * the poles at speed 1 is a stationary path, S = m v^2 T/2 = pi/2 (the
 * geodesics of the sphere; the antipode is conjugate to the pole, Gelfand
 * and Fomin ch. 5): found with no --guess (the chord is normal to the
 * sphere, through its centre) and reported as a 1-parameter family.  A
 * quarter circle (to (1, 0, 0) in pi/2) is isolated, S = pi/4. */
static void test_sphere_antipodes(void **state) {
    (void)state;
    sim_fix *f = sf_load("coordinates x, y, z\nparameters m = 1, R = 1\n"
                         "T = m/2*(x'^2 + y'^2 + z'^2)\n"
                         "constraint sphere: x^2 + y^2 + z^2 = R^2\n");
    assert_non_null(f);
    double q0[3] = {0, 0, 1}, q1[3] = {0, 0, -1}, pi = 3.14159265358979324;
    qd_path_opts o = {.t0 = 0, .t1 = pi, .q0 = q0, .q1 = q1};
    qd_path_set ps;
    assert_int_equal(qd_path_find(f->ctx, f->m, f->e, &o, &ps), QD_OK);
    assert_double_equal(ps.paths[0].action, pi / 2, 1e-8);
    double v = sqrt(ps.paths[0].v0[0] * ps.paths[0].v0[0] + ps.paths[0].v0[1] * ps.paths[0].v0[1]);
    assert_double_equal(v, 1, 1e-8);
    assert_double_equal(ps.paths[0].v0[2], 0, 1e-8);
    assert_int_equal(ps.paths[0].family, 1);
    qd_path_set_free(&ps);
    double q2[3] = {1, 0, 0};
    qd_path_opts oq = {.t0 = 0, .t1 = pi / 2, .q0 = q0, .q1 = q2};
    assert_int_equal(qd_path_find(f->ctx, f->m, f->e, &oq, &ps), QD_OK);
    assert_double_equal(ps.paths[0].action, pi / 4, 1e-8);
    assert_int_equal(ps.paths[0].family, 0);
    qd_path_set_free(&ps);
    sf_free(f);
}

static void test_unreachable(void **state) {
    (void)state;
    sim_fix *f = sf_load("coordinates x, y\nparameters m = 0.6, l = 1.4, g = 9.81\n"
                         "particle m at (x, y)\nV = m*g*y\nconstraint rod: x^2 + y^2 = l^2\n");
    assert_non_null(f);
    double q0[2] = {0, -1.4}, q1[2] = {2, 0};
    qd_path_opts o = {.t0 = 0, .t1 = 1, .q0 = q0, .q1 = q1};
    qd_path_set ps;
    assert_int_equal(qd_path_find(f->ctx, f->m, f->e, &o, &ps), QD_ERR_NUMERIC);
    assert_non_null(strstr(qd_ctx_message(f->ctx), "residual"));
    assert_non_null(strstr(qd_ctx_message(f->ctx), "rod"));
    sf_free(f);
    /* the oscillator at E = 1/2 turns at |x| = 1: x = 2 is out of reach */
    f = sf_load("coordinates x\nT = x'^2/2\nV = x^2/2\n");
    assert_non_null(f);
    double a = 0, b = 2;
    qd_path_opts oe = {.t0 = 0, .q0 = &a, .q1 = &b};
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_path_find_energy(f->ctx, f->m, f->e, 0.5, &oe, &ps), QD_ERR_NUMERIC);
    /* said before any search: V(2) = 2, the energy at rest there, exceeds E */
    assert_non_null(strstr(qd_ctx_message(f->ctx), "the end (x = 2) is out of reach at the energy 0.5"));
    /* bad options */
    oe.q1 = NULL;
    assert_int_equal(qd_path_find(f->ctx, f->m, f->e, &oe, &ps), QD_ERR_ARG);
    sf_free(f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_projectile_time),
        cmocka_unit_test(test_oscillator),
        cmocka_unit_test(test_pendulum_several),
        cmocka_unit_test(test_projectile_energy),
        cmocka_unit_test(test_projectile_envelope),
        cmocka_unit_test(test_constrained_same_as_angle),
        cmocka_unit_test(test_sphere_antipodes),
        cmocka_unit_test(test_unreachable),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
