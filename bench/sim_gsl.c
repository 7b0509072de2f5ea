/*
 * bench/sim_gsl.c - the double pendulum of examples/double_pendulum.qd
 * integrated with GSL's rk8pd (Prince-Dormand 8(7), gsl_odeiv2) for
 * bench/run_simulate.py.  GPL: built only for the benchmark, never linked
 * into libqdot.  The right-hand side is bench/rhs_hand.c's textbook one.
 *
 * Usage: sim_gsl T_END RTOL ATOL
 * Prints `steps N`, `evaluations N`, `wall_s S`, `final th1 th2 w1 w2`,
 * `energy_error E` (max |E - E0| over the steps / |E0|).
 */
#define _POSIX_C_SOURCE 199309L
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

int hand_rhs_sincos(int n, const double *y, const double *par, double *dydt);

static const double par[5] = {1, 1, 1, 1, 9.81}; /* m1 m2 l1 l2 g */
static long nevals;

static int func(double t, const double y[], double dydt[], void *data) {
    (void)t;
    (void)data;
    nevals++;
    return hand_rhs_sincos(2, y, par, dydt) ? GSL_EBADFUNC : GSL_SUCCESS;
}

static double energy(const double *y) {
    double c = cos(y[0] - y[1]);
    double T = y[2] * y[2] + 0.5 * y[3] * y[3] + y[2] * y[3] * c;
    return T - 2 * 9.81 * cos(y[0]) - 9.81 * cos(y[1]);
}

static double now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int main(int argc, char **argv) {
    if (argc != 4)
        return fprintf(stderr, "usage: sim_gsl T_END RTOL ATOL\n"), 2;
    double t_end = atof(argv[1]), rtol = atof(argv[2]), atol = atof(argv[3]);
    gsl_odeiv2_system sys = {func, NULL, 4, NULL};
    gsl_odeiv2_step *step = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, 4);
    gsl_odeiv2_control *con = gsl_odeiv2_control_standard_new(atol, rtol, 1.0, 0.0);
    gsl_odeiv2_evolve *ev = gsl_odeiv2_evolve_alloc(4);
    double y[4] = {0.5, 0, 0, 0}, t = 0, h = 1e-3, e0 = energy(y), worst = 0;
    long steps = 0;
    double t0 = now();
    while (t < t_end) {
        int st = gsl_odeiv2_evolve_apply(ev, con, step, &sys, &t, t_end, &h, y);
        if (st != GSL_SUCCESS)
            return fprintf(stderr, "sim_gsl: %s at t = %g\n", gsl_strerror(st), t), 1;
        steps++;
        worst = fmax(worst, fabs(energy(y) - e0));
    }
    double wall = now() - t0;
    printf("steps %ld\nevaluations %ld\nrejected %zu\nwall_s %.4f\nfinal %.17g %.17g %.17g %.17g\n"
           "energy_error %.3g\n",
           steps, nevals, (size_t)ev->failed_steps, wall, y[0], y[1], y[2], y[3],
           worst / fabs(e0));
    gsl_odeiv2_evolve_free(ev);
    gsl_odeiv2_control_free(con);
    gsl_odeiv2_step_free(step);
    return 0;
}
