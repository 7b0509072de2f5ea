/*
 * src/num/quad.c - double-exponential quadrature: tanh-sinh on [a, b] and
 * exp-sinh on [a, inf) (Takahasi & Mori 1974; Bailey, Jeyabalan & Li,
 * "A comparison of three high-precision quadrature schemes", 2005).
 *
 * Why this rule: the integrals of orbits and scattering (a radial period,
 * an apsidal angle, a deflection) have 1/sqrt singularities at the
 * turning points.  Gauss-Kronrod (QUADPACK's QAGS) reaches them by
 * bisecting towards the end and extrapolating; the double-exponential map
 * makes the transformed integrand decay like exp(-c exp|t|) whatever the
 * algebraic end-point behaviour, so the trapezoidal rule in t converges
 * geometrically with no special treatment.  bench/quad_bench.c measures it
 * against GSL's QAGS (GSL is GPL: compared, never linked into libqdot).
 *
 * Each level halves the step h and adds only the new (odd) abscissas, so
 * a level costs as much as all the levels before it.  The weights and
 * abscissas are computed on the fly (exp and a division per point): the
 * integrands here cost far more than that.
 */
#include "num.h"

#include <float.h>
#include <math.h>

#define HALF_PI 1.57079632679489661923 /* M_PI is not C11 */
#define MAX_LEVEL 12     /* h = 2^-12: at most about 2 * 6.1 * 4096 points */
#define DEFAULT_TOL 1e-13

/* The half-width of the t range: beyond it the distance of the abscissa
 * from the end, hw exp(-u)/cosh(u) with u = pi/2 sinh t, underflows. */
static double t_max_finite(void) { return asinh(1.0 / HALF_PI * 0.5 * log(1.0 / DBL_MIN)); }

/* The two abscissas +-t of tanh-sinh on [a, b] with their weight: the
 * terms w (f(x-) + f(x+)); *bad when f is not finite at a point away from
 * the ends (a fault of the integrand, not of the end point). */
static double ts_pair(qd__num_fn f, void *data, double a, double b, double t, size_t *evals,
                      bool *bad) {
    double c = 0.5 * (a + b), hw = 0.5 * (b - a);
    double u = HALF_PI * sinh(t), ch = cosh(u);
    double w = hw * HALF_PI * cosh(t) / (ch * ch);
    double d = hw * exp(-u) / ch; /* hw (1 - tanh u): the distance from the end */
    if (t == 0) {
        (*evals)++;
        double y = f(data, c, c - a); /* the midpoint: measured from a, by convention */
        if (!isfinite(y))
            *bad = true;
        return w * y;
    }
    double sum = 0;
    double pts[2] = {b - d, a + d}, xcs[2] = {-d, d};
    for (int k = 0; k < 2; k++) {
        if (d <= 0)
            continue; /* both ends reached: nothing left to add */
        (*evals)++;
        double y = f(data, pts[k], xcs[k]);
        if (!isfinite(y)) {
            if (d > 1e-14 * (fabs(a) + fabs(b) + hw))
                *bad = true;
            continue; /* at the singularity itself: the point carries no weight */
        }
        sum += w * y;
    }
    return sum;
}

bool qd__num_quad_finite(qd__num_fn f, void *data, double a, double b, double tol,
                         qd__num_quad *r) {
    *r = (qd__num_quad){0};
    if (!(a < b) || !isfinite(a) || !isfinite(b)) {
        r->value = NAN;
        return false;
    }
    if (tol <= 0)
        tol = DEFAULT_TOL;
    double tmax = t_max_finite(), h = 1.0, prev = NAN;
    bool bad = false;
    /* level 0: every integer t */
    double sum = ts_pair(f, data, a, b, 0, &r->evals, &bad);
    for (double t = 1; t <= tmax; t += 1)
        sum += ts_pair(f, data, a, b, t, &r->evals, &bad);
    r->value = h * sum;
    for (int level = 1; level <= MAX_LEVEL && !bad; level++) {
        h *= 0.5;
        for (double t = h; t <= tmax; t += 2 * h)
            sum += ts_pair(f, data, a, b, t, &r->evals, &bad);
        prev = r->value;
        r->value = h * sum;
        r->error = fabs(r->value - prev);
        /* the error squares from level to level: stop once two agree */
        if (level >= 3 && r->error <= tol * fmax(1.0, fabs(r->value))) {
            r->converged = true;
            break;
        }
    }
    if (bad) {
        r->value = NAN;
        r->converged = false;
    }
    return r->converged;
}

/* exp-sinh on [a, inf): x = a + exp(u), u = pi/2 sinh t, dx = x_c pi/2 cosh t dt. */
static double es_point(qd__num_fn f, void *data, double a, double t, size_t *evals, bool *bad) {
    double u = HALF_PI * sinh(t);
    double xc = exp(u);
    if (xc <= 0 || !isfinite(xc))
        return 0;
    (*evals)++;
    double y = f(data, a + xc, xc);
    if (!isfinite(y)) {
        if (xc > 1e-14 * fmax(1.0, fabs(a)) && xc < 1e300)
            *bad = true;
        return 0;
    }
    /* far out the weight overflows while the integrand has decayed to 0:
     * the term is 0, not inf * 0 */
    double w = xc * HALF_PI * cosh(t);
    return y == 0 || !isfinite(w) ? 0 : w * y;
}

bool qd__num_quad_upper(qd__num_fn f, void *data, double a, double tol, qd__num_quad *r) {
    *r = (qd__num_quad){0};
    if (!isfinite(a)) {
        r->value = NAN;
        return false;
    }
    if (tol <= 0)
        tol = DEFAULT_TOL;
    /* t where exp(u) reaches DBL_MIN below and the largest double above */
    double tlo = -asinh(1.0 / HALF_PI * log(1.0 / DBL_MIN)), thi = asinh(1.0 / HALF_PI * log(DBL_MAX));
    double h = 1.0, prev;
    bool bad = false;
    double sum = 0;
    for (double t = ceil(tlo); t <= thi; t += 1)
        sum += es_point(f, data, a, t, &r->evals, &bad);
    r->value = h * sum;
    for (int level = 1; level <= MAX_LEVEL && !bad; level++) {
        h *= 0.5;
        for (double t = ceil(tlo) + h; t <= thi; t += 2 * h)
            sum += es_point(f, data, a, t, &r->evals, &bad);
        prev = r->value;
        r->value = h * sum;
        r->error = fabs(r->value - prev);
        if (level >= 3 && r->error <= tol * fmax(1.0, fabs(r->value))) {
            r->converged = true;
            break;
        }
    }
    if (bad) {
        r->value = NAN;
        r->converged = false;
    }
    return r->converged;
}
