/*
 * tests/sim/test_systems.c - closed forms beyond the oscillator:
 *   - the Kepler orbit (Desloge ch. 58-59, seed 000; examples/kepler_polar.qd):
 *     after one period T = 2 pi sqrt(m a^3 / k), a = -k / (2E), the state
 *     returns, in polar coordinates (non-separable H: gl6 on (q, p)) and in
 *     Cartesian ones (separable: Yoshida 8);
 *   - a constrained pendulum in Cartesian coordinates (examples/
 *     pendulum_cartesian.qd): the rod constraint held to 1e-12 by projection,
 *     and the period equal to the angle pendulum's 4 sqrt(l/g) K(sin(theta0/2));
 *   - BDF on a stiff overdamped oscillator m x'' + c x' + k x = 0 against
 *     x = A e^(r1 t) + B e^(r2 t) (Goldstein sec. 1.5, Rayleigh dissipation).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "sim_fixture.h"

#define PI 3.14159265358979323846

static const char kepler_polar[] =
    "coordinates r, theta\nparameters m = 1.3, k = 4\n"
    "particle m at r*(cos(theta), sin(theta))\nV = -k/r\n"
    "initial r = 1, theta = 0, r' = 0, theta' = 1.5\n";
static const char kepler_xy[] =
    "coordinates x, y\nparameters m = 1.3, k = 4\n"
    "particle m at (x, y)\nV = -k/sqrt(x^2 + y^2)\n"
    "initial x = 1, y = 0, x' = 0, y' = 1.5\n";

static double kepler_period(void) {
    double E = 0.5 * 1.3 * 1.5 * 1.5 - 4, a = -4 / (2 * E);
    return 2 * PI * sqrt(1.3 * a * a * a / 4);
}

static void test_kepler(void **state) {
    (void)state;
    double T = kepler_period();
    struct {
        const char *text;
        qd_sim_method m;
        double dt, rtol, tol;
        double expect[4];
    } cases[] = {
        {kepler_polar, QD_SIM_DOP853, 0, 1e-13, 1e-9, {1, 2 * PI, 0, 1.5}},
        {kepler_polar, QD_SIM_GL6, 0, 0, 1e-8, {1, 2 * PI, 0, 1.5}},
        {kepler_xy, QD_SIM_YOSHIDA8, 0, 0, 1e-8, {1, 0, 0, 1.5}},
    };
    for (size_t i = 0; i < 3; i++) {
        sim_fix *f = sf_load(cases[i].text);
        assert_non_null(f);
        double dt = T / 4000;
        assert_int_equal(sf_run(f, cases[i].m, T, cases[i].rtol > 0 ? 0 : dt, cases[i].rtol,
                                false),
                         QD_OK);
        for (int j = 0; j < 4; j++)
            if (fabs(f->last[1 + j] - cases[i].expect[j]) > cases[i].tol)
                fail_msg("%s: component %d %.17g vs %.17g", qd_sim_method_name(cases[i].m), j,
                         f->last[1 + j], cases[i].expect[j]);
        assert_true(f->stats.energy_error_max < cases[i].tol);
        sf_free(f);
    }
    /* the separability verdicts: polar H has p_theta^2/r^2, Cartesian does not */
    sim_fix *f = sf_load(kepler_polar);
    assert_false(qd_sim_separable(f->s));
    assert_true(qd_sim_canonical(f->s));
    sf_free(f);
    f = sf_load(kepler_xy);
    assert_true(qd_sim_separable(f->s));
    sf_free(f);
}

static const char rod[] = "coordinates x, y\nparameters m = 0.6, l = 1.4, g = 9.81\n"
                          "particle m at (x, y)\nV = m*g*y\n"
                          "constraint rod: x^2 + y^2 = l^2\n"
                          "initial x = 0.67, y = -1.23, x' = 0, y' = 0\n";

static void test_constrained(void **state) {
    (void)state;
    qd_sim_method ms[] = {QD_SIM_DOP853, QD_SIM_GL4};
    for (int i = 0; i < 2; i++) {
        sim_fix *f = sf_load(rod);
        assert_non_null(f);
        assert_int_equal(qd_sim_ncon(f->s), 1);
        /* from rest: the first return of x' = 0 with x > 0 is one period */
        const qd_expr *x = qd_lookup(f->ctx, "x"), *xd = qd_jet(f->ctx, x, 1);
        assert_int_equal(qd_sim_add_event(f->s, xd, 1, &x, true), QD_OK);
        assert_int_equal(sf_run(f, ms[i], 20, ms[i] == QD_SIM_GL4 ? 0.002 : 0, 1e-12, false),
                         QD_OK);
        printf("# %s rod pendulum: constraint error %.3g, energy error %.3g\n",
               qd_sim_method_name(ms[i]), f->stats.constraint_error_max,
               f->stats.energy_error_max);
        assert_true(f->stats.constraint_error_max < 1e-12);
        /* the projected start: x0 scaled onto the circle of radius l */
        double r0 = hypot(0.67, -1.23), th0 = atan2(0.67 / r0, 1.23 / r0);
        double Tex = 4 * sqrt(1.4 / 9.81) * sf_ellipk(sin(th0 / 2));
        assert_int_equal(f->nev, 1);
        if (fabs(f->ev_t[0] - Tex) > 1e-8 * Tex)
            fail_msg("%s: period %.17g vs %.17g", qd_sim_method_name(ms[i]), f->ev_t[0], Tex);
        int cres = sf_col(f, ms[i], "res_rod");
        assert_true(cres > 0 && fabs(f->last[cres]) < 1e-12);
        sf_free(f);
    }
}

static const char stiff[] = "coordinates x\nparameters m = 1, k = 1, c = 1000\n"
                            "T = m/2*x'^2\nV = k/2*x^2\ndissipation = c/2*x'^2\n"
                            "initial x = 1, x' = 0\n";

static void test_stiff(void **state) {
    (void)state;
    double c = 1000, disc = sqrt(c * c - 4);
    double r1 = (-c + disc) / 2, r2 = (-c - disc) / 2;
    double A = r2 / (r2 - r1), B = -r1 / (r2 - r1), t = 10;
    double x = A * exp(r1 * t) + B * exp(r2 * t);
    sim_fix *f = sf_load(stiff);
    assert_non_null(f);
    assert_false(qd_sim_conservative(f->s));
    assert_int_equal(sf_run(f, QD_SIM_BDF, t, 0, 1e-9, false), QD_OK);
    size_t bdf_steps = f->stats.steps;
    printf("# bdf stiff: %zu steps, x(10) %.17g vs %.17g\n", bdf_steps, f->last[1], x);
    assert_true(fabs(f->last[1] - x) < 1e-6 * fabs(x));
    assert_int_equal(sf_run(f, QD_SIM_DOP853, t, 0, 1e-9, false), QD_OK);
    /* the explicit method is held to h < 3.3/|r2| by stability */
    assert_true(f->stats.steps > 5 * bdf_steps);
    sf_free(f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_kepler),
        cmocka_unit_test(test_constrained),
        cmocka_unit_test(test_stiff),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
