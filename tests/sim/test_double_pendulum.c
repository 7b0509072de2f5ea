/*
 * tests/sim/test_double_pendulum.c - long-time energy behaviour on the
 * double pendulum (m = l = 1, g = 9.81, from theta1 = theta2 = pi/2;
 * Goldstein, Poole & Safko ch. 1 exercise 22, seed 002; examples/
 * double_pendulum.qd), a chaotic motion for which only the conserved energy
 * can be checked: DOP853 at rtol 1e-12 keeps it to 1e-9 over 1000 s, and the
 * symplectic gl6 with h = 0.002 to 2e-11 with no drift (the error over the
 * last tenth at most 3 times that over the first; Hairer, Lubich & Wanner,
 * GNI sec. X.3: bounded energy error for symplectic methods).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "sim_fixture.h"

#define PI 3.14159265358979323846
#define T_END 1000.0

static const char dp[] =
    "coordinates theta1, theta2\nparameters m1 = 1, m2 = 1, l1 = 1, l2 = 1, g = 9.81\n"
    "x1 = l1*sin(theta1)\ny1 = -l1*cos(theta1)\nx2 = x1 + l2*sin(theta2)\n"
    "y2 = y1 - l2*cos(theta2)\nT = m1/2*(x1'^2 + y1'^2) + m2/2*(x2'^2 + y2'^2)\n"
    "V = m1*g*y1 + m2*g*y2\n";

typedef struct drift {
    double E0, first, last, Tmax;
    int col;
} drift;

static int sink(void *data, int event, const double *row) {
    drift *d = data;
    (void)event;
    double dE = fabs(row[d->col] - d->E0);
    if (row[0] <= 0.1 * T_END)
        d->first = fmax(d->first, dE);
    if (row[0] >= 0.9 * T_END)
        d->last = fmax(d->last, dE);
    return 0;
}

static void test_dop853(void **state) {
    (void)state;
    sim_fix *f = sf_load(dp);
    assert_non_null(f);
    f->q0[0] = f->q0[1] = PI / 2;
    assert_int_equal(sf_run(f, QD_SIM_DOP853, T_END, 0, 1e-12, false), QD_OK);
    printf("# dop853 rtol 1e-12, 1000 s: %zu steps, %zu evaluations, %zu rejected, energy "
           "error %.3g\n", f->stats.steps, f->stats.evals, f->stats.rejected,
           f->stats.energy_error_max);
    assert_true(f->stats.energy_error_max < 1e-9);
    /* the stabilized controller (dop853.f's, beta = 0.04) rejects about as
     * few steps as GSL's rk8pd does here (12.5%); without it, 23% */
    assert_true(f->stats.rejected < 0.15 * (double)f->stats.steps);
    sf_free(f);
}

static void test_gl6(void **state) {
    (void)state;
    sim_fix *f = sf_load(dp);
    assert_non_null(f);
    f->q0[0] = f->q0[1] = PI / 2;
    drift d = {.col = sf_col(f, QD_SIM_GL6, "energy")};
    assert_true(d.col > 0);
    /* E(0) = 0 here: V = 0 with both rods horizontal, at rest */
    qd_sim_opts o = {.method = QD_SIM_GL6, .t_end = T_END, .dt = 0.002, .q0 = f->q0,
                     .qd0 = f->qd0};
    assert_int_equal(qd_sim_run(f->s, &o, sink, &d, &f->stats, NULL), QD_OK);
    printf("# gl6 h 0.002, 1000 s: %zu evaluations, energy error %.3g (first tenth %.3g, last "
           "tenth %.3g)\n", f->stats.evals, f->stats.energy_error_max, d.first, d.last);
    assert_true(fabs(f->stats.E0) < 1e-12);
    assert_true(f->stats.energy_error_max < 2e-11);
    assert_true(d.last <= 3 * d.first);
    sf_free(f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_dop853),
        cmocka_unit_test(test_gl6),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
