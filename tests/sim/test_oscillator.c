/*
 * tests/sim/test_oscillator.c - every method on the harmonic oscillator
 * m x'' = -k x against its closed form x = x0 cos(w t) + v0/w sin(w t),
 * w = sqrt(k/m) (Goldstein, Poole & Safko, sec. 1.6 / Desloge ch. 58 for the
 * oscillator; seed 002), and the energy error every method reports.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "sim_fixture.h"

static const char osc[] = "coordinates x\nparameters m = 2, k = 8\n"
                          "T = m/2*x'^2\nV = k/2*x^2\ninitial x = 1, x' = 0.5\n";

static void check(qd_sim_method method, double dt, double rtol, double tol) {
    sim_fix *f = sf_load(osc);
    assert_non_null(f);
    double t_end = 10, w = 2;
    assert_int_equal(sf_run(f, method, t_end, dt, rtol, false), QD_OK);
    double x = cos(w * t_end) + 0.5 / w * sin(w * t_end);
    double v = -w * sin(w * t_end) + 0.5 * cos(w * t_end);
    int cx = sf_col(f, method, "x"), cv = sf_col(f, method, "x'");
    assert_true(cx == 1 && cv == 2);
    if (fabs(f->last[cx] - x) > tol || fabs(f->last[cv] - v) > tol)
        fail_msg("%s: x %.17g vs %.17g, v %.17g vs %.17g", qd_sim_method_name(method),
                 f->last[cx], x, f->last[cv], v);
    assert_true(f->last[0] == t_end);
    assert_true(f->stats.steps > 0 && f->stats.evals >= f->stats.steps);
    assert_true(f->stats.energy_error_max < 10 * tol);
    sf_free(f);
}

static void test_explicit(void **state) {
    (void)state;
    check(QD_SIM_DOPRI5, 0, 1e-11, 1e-8);
    check(QD_SIM_DOP853, 0, 1e-13, 1e-10);
}

static void test_gauss(void **state) {
    (void)state;
    check(QD_SIM_GL2, 1e-4, 0, 1e-7);
    check(QD_SIM_GL4, 1e-2, 0, 1e-8);
    check(QD_SIM_GL6, 2e-2, 0, 1e-9);
}

static void test_splitting(void **state) {
    (void)state;
    check(QD_SIM_VERLET, 1e-4, 0, 1e-7);
    check(QD_SIM_YOSHIDA4, 1e-3, 0, 1e-8);
    check(QD_SIM_YOSHIDA6, 1e-2, 0, 1e-8);
    check(QD_SIM_YOSHIDA8, 2e-2, 0, 1e-9);
}

static void test_bdf(void **state) {
    (void)state;
    check(QD_SIM_BDF, 0, 1e-10, 1e-6);
}

/* Dense output: rows on the grid t = k dt agree with the closed form. */
static double grid_err;
static int grid_sink(void *data, int event, const double *row) {
    (void)data;
    (void)event;
    double x = cos(2 * row[0]) + 0.25 * sin(2 * row[0]);
    grid_err = fmax(grid_err, fabs(row[1] - x));
    return 0;
}

static void test_dense(void **state) {
    (void)state;
    qd_sim_method ms[] = {QD_SIM_DOPRI5, QD_SIM_DOP853};
    for (int i = 0; i < 2; i++) {
        sim_fix *f = sf_load(osc);
        qd_sim_opts o = {.method = ms[i], .t_end = 10, .dt = 0.01, .rtol = 1e-12,
                         .atol = 1e-14, .q0 = f->q0, .qd0 = f->qd0};
        grid_err = 0;
        assert_int_equal(qd_sim_run(f->s, &o, grid_sink, NULL, &f->stats, NULL), QD_OK);
        assert_true(grid_err < 1e-9);
        sf_free(f);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_explicit), cmocka_unit_test(test_gauss),
        cmocka_unit_test(test_splitting), cmocka_unit_test(test_bdf),
        cmocka_unit_test(test_dense),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
