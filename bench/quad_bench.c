/*
 * bench/quad_bench.c - qdot's tanh-sinh quadrature (src/num/quad.c) against
 * GSL's QAGS (QUADPACK's adaptive Gauss-Kronrod 21 with epsilon-algorithm
 * extrapolation, the general-purpose choice for end-point singularities)
 * on the integrals of orbits: inverse-square-root singularities at both
 * turning points.  For each: the error reached, the integrand evaluations
 * and the time per integral, and the ratios qdot/GSL.  GSL is GPL: it is
 * linked here only, never into libqdot.
 *
 *   kepler(e)  int_r1^r2 r dr / sqrt((r - r1)(r2 - r)) = pi (r1 + r2)/2,
 *              r1 = 1 - e, r2 = 1 + e (Goldstein sec. 3.7)
 *   arcsine    int_-1^1 dx / sqrt(1 - x^2) = pi
 *   power      int_r1^r2 dr / (r^2 sqrt((r - r1)(r2 - r))) (a precessing
 *              orbit's advance integrand shape) = pi (r1 + r2)/(2 (r1 r2)^(3/2))
 */
#define _POSIX_C_SOURCE 199309L /* clock_gettime */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <math.h>
#include <stdio.h>
#include <time.h>

#include "num/num.h"

#define PI 3.14159265358979323846

typedef struct {
    double r1, r2;
    int kind; /* 0 kepler, 1 arcsine, 2 power */
    long evals;
} problem;

/* The integrand from the two end distances, both exact. */
static double value(const problem *p, double r, double da, double db) {
    double s = sqrt(da * db);
    switch (p->kind) {
    case 0: return r / s;
    case 1: return 1 / s;
    default: return 1 / (r * r * s);
    }
}

static double qd_f(void *data, double r, double xc) {
    problem *p = data;
    p->evals++;
    double w = p->r2 - p->r1;
    double da = xc >= 0 ? xc : w + xc, db = xc < 0 ? -xc : w - xc;
    return value(p, r, da, db);
}

static double gsl_f(double r, void *data) {
    problem *p = data;
    p->evals++;
    return value(p, r, r - p->r1, p->r2 - r);
}

static double now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static void run(const char *name, problem p, double exact) {
    enum { REPS = 200 };
    problem a = p, b = p;
    qd__num_quad r = {0};
    double t0 = now();
    for (int i = 0; i < REPS; i++) {
        a.evals = 0;
        qd__num_quad_finite(qd_f, &a, p.r1, p.r2, 1e-12, &r);
    }
    double tq = (now() - t0) / REPS;
    gsl_integration_workspace *w = gsl_integration_workspace_alloc(1000);
    gsl_function F = {gsl_f, &b};
    double gv = 0, ge = 0;
    int status = 0;
    t0 = now();
    for (int i = 0; i < REPS; i++) {
        b.evals = 0;
        status = gsl_integration_qags(&F, p.r1, p.r2, 0, 1e-12, 1000, w, &gv, &ge);
    }
    double tg = (now() - t0) / REPS;
    gsl_integration_workspace_free(w);
    double eq = fabs(r.value - exact) / fabs(exact), eg = fabs(gv - exact) / fabs(exact);
    printf("%-16s qdot: err %8.1e, %6ld evals, %8.2f us | GSL qags: err %8.1e, %6ld evals, "
           "%8.2f us%s | evals %5.2fx, time %5.2fx\n",
           name, eq, a.evals, 1e6 * tq, eg, b.evals, 1e6 * tg, status ? " (failed)" : "",
           (double)a.evals / (double)b.evals, tq / tg);
}

int main(void) {
    gsl_set_error_handler_off();
    printf("tol 1e-12 relative; ratios are qdot / GSL (below 1: qdot cheaper)\n");
    double es[] = {0.1, 0.9, 0.999};
    for (int i = 0; i < 3; i++) {
        char name[32];
        snprintf(name, sizeof name, "kepler e=%g", es[i]);
        problem p = {1 - es[i], 1 + es[i], 0, 0};
        run(name, p, PI * (p.r1 + p.r2) / 2);
    }
    problem arc = {-1, 1, 1, 0};
    run("arcsine", arc, PI);
    problem pw = {0.5, 3, 2, 0};
    run("power r1=.5 r2=3", pw, PI * (pw.r1 + pw.r2) / (2 * pow(pw.r1 * pw.r2, 1.5)));
    return 0;
}
