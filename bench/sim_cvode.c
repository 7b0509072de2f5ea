/*
 * bench/sim_cvode.c - the double pendulum of examples/double_pendulum.qd
 * integrated with SUNDIALS CVODE for bench/run_simulate.py: the Adams
 * methods (variable order up to 12) with fixed-point iteration, CVODE's
 * choice for a non-stiff problem, at the same tolerances as the others.
 * The right-hand side is bench/rhs_hand.c's textbook one, as for GSL.
 *
 * Usage: sim_cvode T_END RTOL ATOL
 * Prints `steps N`, `evaluations N`, `rejected N` (error-test failures),
 * `wall_s S`, `final th1 th2 w1 w2`, `energy_error E` (max |E - E0| over the
 * steps / |E0|), the output sim_gsl.c gives.
 */
#define _POSIX_C_SOURCE 199309L
#include <cvode/cvode.h>
#include <math.h>
#include <nvector/nvector_serial.h>
#include <stdio.h>
#include <stdlib.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>
#include <time.h>

int hand_rhs_sincos(int n, const double *y, const double *par, double *dydt);

static const double par[5] = {1, 1, 1, 1, 9.81}; /* m1 m2 l1 l2 g */

static int func(sunrealtype t, N_Vector y, N_Vector dydt, void *data) {
    (void)t;
    (void)data;
    return hand_rhs_sincos(2, N_VGetArrayPointer(y), par, N_VGetArrayPointer(dydt)) ? -1 : 0;
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
        return fprintf(stderr, "usage: sim_cvode T_END RTOL ATOL\n"), 2;
    double t_end = atof(argv[1]), rtol = atof(argv[2]), atol = atof(argv[3]);
    SUNContext sun;
    if (SUNContext_Create(NULL, &sun))
        return fprintf(stderr, "sim_cvode: no SUNDIALS context\n"), 1;
    N_Vector y = N_VNew_Serial(4, sun);
    double *yv = N_VGetArrayPointer(y);
    yv[0] = 0.5, yv[1] = 0, yv[2] = 0, yv[3] = 0;
    double e0 = energy(yv), worst = 0, t = 0;
    void *cv = CVodeCreate(CV_ADAMS, sun);
    SUNNonlinearSolver nls = SUNNonlinSol_FixedPoint(y, 0, sun);
    int bad = CVodeInit(cv, func, 0, y) || CVodeSStolerances(cv, rtol, atol) ||
              CVodeSetNonlinearSolver(cv, nls) || CVodeSetMaxNumSteps(cv, 100000000) ||
              CVodeSetStopTime(cv, t_end);
    if (bad)
        return fprintf(stderr, "sim_cvode: setting CVODE up failed\n"), 1;
    double t0 = now();
    while (t < t_end) {
        /* one step at a time, as the others, to follow the energy */
        int st = CVode(cv, t_end, y, &t, CV_ONE_STEP);
        if (st < 0)
            return fprintf(stderr, "sim_cvode: CVODE failed (%d) at t = %g\n", st, t), 1;
        worst = fmax(worst, fabs(energy(yv) - e0));
    }
    double wall = now() - t0;
    long steps = 0, nfe = 0, netf = 0;
    CVodeGetNumSteps(cv, &steps);
    CVodeGetNumRhsEvals(cv, &nfe);
    CVodeGetNumErrTestFails(cv, &netf);
    printf("steps %ld\nevaluations %ld\nrejected %ld\nwall_s %.4f\nfinal %.17g %.17g %.17g %.17g\n"
           "energy_error %.3g\n",
           steps, nfe, netf, wall, yv[0], yv[1], yv[2], yv[3], worst / fabs(e0));
    SUNNonlinSolFree(nls);
    CVodeFree(&cv);
    N_VDestroy(y);
    SUNContext_Free(&sun);
    return 0;
}
