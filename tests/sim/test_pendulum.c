/*
 * tests/sim/test_pendulum.c - the simple pendulum (Goldstein, Poole & Safko,
 * ch. 1, seed 002; Byerly, seed 001): its period 4 sqrt(l/g) K(sin(theta0/2))
 * located by an event to 1e-12, and the measured convergence order of
 * every method against the closed-form motion
 *     sin(theta/2) = k sn(K - w t | k^2),  k = sin(theta0/2),  w = sqrt(g/l)
 * (Whittaker, Analytical Dynamics, sec. 44), fitted over halved steps.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "sim_fixture.h"

static const char pend[] = "coordinates theta\nparameters m = 1, l = 1.3, g = 9.81\n"
                           "T = m/2*l^2*theta'^2\nV = -m*g*l*cos(theta)\n"
                           "initial theta = 1, theta' = 0\n";

/* sn(u | m) by the arithmetic-geometric mean (Abramowitz & Stegun 16.4). */
static double sn(double u, double m) {
    double a[16], c[16], b = sqrt(1 - m);
    a[0] = 1;
    c[0] = sqrt(m);
    int n = 0;
    while (fabs(c[n]) > 1e-17 && n < 15) {
        a[n + 1] = 0.5 * (a[n] + b);
        c[n + 1] = 0.5 * (a[n] - b);
        b = sqrt(a[n] * b);
        n++;
    }
    double phi = ldexp(a[n] * u, n);
    for (int i = n; i > 0; i--)
        phi = 0.5 * (phi + asin(c[i] / a[i] * sin(phi)));
    return sin(phi);
}

/* The period from the first return to theta' = 0 with theta > 0. */
static void check_period(const char *text, double theta0, qd_sim_method method, double dt,
                         double rtol) {
    sim_fix *f = sf_load(text);
    assert_non_null(f);
    f->q0[0] = theta0;
    double Tex = 4 * sqrt(1.3 / 9.81) * sf_ellipk(sin(theta0 / 2));
    const qd_expr *th = qd_lookup(f->ctx, "theta"), *thd = qd_jet(f->ctx, th, 1);
    assert_int_equal(qd_sim_add_event(f->s, thd, 1, &th, true), QD_OK);
    assert_int_equal(sf_run(f, method, 1.5 * Tex, dt, rtol, false), QD_OK);
    assert_int_equal(f->nev, 1);
    double err = fabs(f->ev_t[0] - Tex) / Tex;
    if (err > 1e-12)
        fail_msg("%s: period %.17g vs %.17g (relative error %.3g)", qd_sim_method_name(method),
                 f->ev_t[0], Tex, err);
    /* the run stopped at the event, on the turning point */
    assert_true(f->last[0] == f->ev_t[0]);
    assert_true(fabs(f->last[2]) < 1e-11);
    assert_true(fabs(f->last[1] - theta0) < 1e-11);
    sf_free(f);
}

static void test_period(void **state) {
    (void)state;
    check_period(pend, 1.0, QD_SIM_DOP853, 0, 1e-14);
    check_period(pend, 2.5, QD_SIM_DOP853, 0, 1e-14);
    check_period(pend, 2.5, QD_SIM_GL6, 0.002, 0);
    check_period(pend, 1.0, QD_SIM_YOSHIDA8, 0.005, 0);
}

static double K, w, k, emax;

static int err_sink(void *data, int event, const double *row) {
    (void)data;
    (void)event;
    double ex = 2 * asin(k * sn(K - w * row[0], k * k));
    emax = fmax(emax, fabs(row[1] - ex));
    return 0;
}

/* Least-squares slope of log(max error over two periods) against log h. */
static double measured_order(qd_sim_method method, double h, int levels) {
    double lh[8], le[8];
    k = sin(0.5);
    w = sqrt(9.81 / 1.3);
    K = sf_ellipk(k);
    for (int i = 0; i < levels; i++, h /= 2) {
        sim_fix *f = sf_load(pend);
        qd_sim_opts o = {.method = method, .t_end = 8 * K / w, .dt = h, .fixed = true,
                         .q0 = f->q0, .qd0 = f->qd0};
        emax = 0;
        assert_int_equal(qd_sim_run(f->s, &o, err_sink, NULL, NULL, NULL), QD_OK);
        lh[i] = log(h);
        le[i] = log(emax);
        sf_free(f);
    }
    double mx = 0, my = 0, sxx = 0, sxy = 0;
    for (int i = 0; i < levels; i++) {
        mx += lh[i] / levels;
        my += le[i] / levels;
    }
    for (int i = 0; i < levels; i++) {
        sxx += (lh[i] - mx) * (lh[i] - mx);
        sxy += (lh[i] - mx) * (le[i] - my);
    }
    return sxy / sxx;
}

static void test_orders(void **state) {
    (void)state;
    static const struct {
        qd_sim_method m;
        double h;
        int levels;
    } cases[] = {
        {QD_SIM_DOPRI5, 0.05, 4},   {QD_SIM_DOP853, 0.2, 3},    {QD_SIM_GL2, 0.02, 3},
        {QD_SIM_GL4, 0.05, 3},      {QD_SIM_GL6, 0.1, 3},       {QD_SIM_VERLET, 0.02, 3},
        {QD_SIM_YOSHIDA4, 0.02, 3}, {QD_SIM_YOSHIDA6, 0.05, 3}, {QD_SIM_YOSHIDA8, 0.1, 3},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        double p = measured_order(cases[i].m, cases[i].h, cases[i].levels);
        int nominal = qd_sim_method_order(cases[i].m);
        printf("# %-9s measured order %.3f (nominal %d)\n", qd_sim_method_name(cases[i].m), p,
               nominal);
        if (fabs(p - nominal) > 0.3)
            fail_msg("%s: measured order %.3f, nominal %d", qd_sim_method_name(cases[i].m), p,
                     nominal);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_period),
        cmocka_unit_test(test_orders),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
