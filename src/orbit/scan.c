/*
 * src/orbit/scan.c - roots along the one remaining coordinate: a walk with
 * geometrically growing steps that stops at the first sign change (so the
 * root found is the nearest one the motion reaches, not one beyond a
 * barrier), at a singular point of V_eff or far away; then Brent's zeroin
 * to round-off.  The walk's first step is 1e-3 of the coordinate's scale,
 * fine enough not to step over a pair of close roots near the state.
 */
#include "orb.h"

#include <math.h>
#include <stdlib.h>

#include "base/mem.h"

#define STEP0 1e-3   /* the first step, in units of the scale */
#define GROW 1.05    /* each step 5% longer than the one before */
#define FAR 1e8      /* open: this many scales away */

static int sign_of(double v) { return v > 0 ? 1 : v < 0 ? -1 : 0; }

/* The walk reaches the singular point 0 from prev: halve the distance until
 * f changes sign (a barrier just before it) or nothing is left. */
static qd__orb_end approach_zero(qd__orb_env *env, qd__orb_fn f, double prev, int s0, double *a,
                                 double *b) {
    for (double x = prev / 2; x != 0 && fabs(x) > 1e-300; prev = x, x /= 2) {
        double v = f(env, x);
        *a = prev;
        *b = x;
        if (!isfinite(v) || !isfinite(env->out[QD__ORB_V]))
            return QD__ORB_SINGULAR;
        if (s0 != 0 && sign_of(v) != s0)
            return QD__ORB_FOUND;
    }
    *a = prev;
    *b = 0;
    return QD__ORB_SINGULAR;
}

qd__orb_end qd__orb_scan(qd__orb_env *env, qd__orb_fn f, double x0, int dir, double *a, double *b) {
    double h = STEP0 * env->scale, prev = x0;
    int s0 = sign_of(f(env, x0));
    for (;;) {
        double x = prev + dir * h;
        *a = prev;
        *b = x;
        if (fabs(x - x0) > FAR * env->scale)
            return QD__ORB_OPEN;
        if (env->sing0 && (prev > 0) != (x > 0) && prev != 0)
            return approach_zero(env, f, prev, s0, a, b);
        double v = f(env, x);
        if (!isfinite(v) || !isfinite(env->out[QD__ORB_V]))
            return QD__ORB_SINGULAR;
        if (s0 == 0)
            s0 = sign_of(v);
        else if (sign_of(v) != s0)
            return QD__ORB_FOUND;
        prev = x;
        h *= GROW;
    }
}

/* Brent's zeroin (R. P. Brent, Algorithms for Minimization without
 * Derivatives, 1973, ch. 4): bisection safeguarding secant and inverse
 * quadratic steps. */
double qd__orb_brent(qd__orb_env *env, qd__orb_fn f, double a, double b) {
    double fa = f(env, a), fb = f(env, b);
    if (fa == 0)
        return a;
    if (fb == 0)
        return b;
    double c = a, fc = fa, d = b - a, e = d;
    for (int it = 0; it < 200; it++) {
        if ((fb > 0) == (fc > 0)) {
            c = a, fc = fa;
            d = e = b - a;
        }
        if (fabs(fc) < fabs(fb)) {
            a = b, b = c, c = a;
            fa = fb, fb = fc, fc = fa;
        }
        double tol = 2 * 1.1102230246251565e-16 * fabs(b), m = (c - b) / 2;
        if (fabs(m) <= tol || fb == 0)
            return b;
        if (fabs(e) >= tol && fabs(fa) > fabs(fb)) {
            double s = fb / fa, p, q;
            if (a == c) {
                p = 2 * m * s;
                q = 1 - s;
            } else {
                double qq = fa / fc, r = fb / fc;
                p = s * (2 * m * qq * (qq - r) - (b - a) * (r - 1));
                q = (qq - 1) * (r - 1) * (s - 1);
            }
            if (p > 0)
                q = -q;
            else
                p = -p;
            if (2 * p < fmin(3 * m * q - fabs(tol * q), fabs(e * q))) {
                e = d;
                d = p / q;
            } else {
                d = e = m;
            }
        } else {
            d = e = m;
        }
        a = b, fa = fb;
        b += fabs(d) > tol ? d : (m > 0 ? tol : -tol);
        fb = f(env, b);
    }
    return b;
}

static bool push(qd_ctx *ctx, double **xs, size_t *n, double x) {
    double *grown = qd__realloc(ctx, *xs, (*n + 1) * sizeof **xs);
    if (!grown)
        return false;
    *xs = grown;
    grown[(*n)++] = x;
    return true;
}

/* A bracketed sign change of V_eff' is a stationary point when |V_eff'|
 * there is not above its values at the bracket's ends; a pole (the
 * centrifugal barrier crossed, sin(theta) = 0) makes it larger than both. */
static bool stationary(qd__orb_env *env, double a, double b, double *x) {
    double fa = fabs(qd__orb_slope(env, a)), fb = fabs(qd__orb_slope(env, b));
    *x = qd__orb_brent(env, qd__orb_slope, a, b);
    double fx = fabs(qd__orb_slope(env, *x));
    return isfinite(fx) && fx <= fmax(fa, fb);
}

/* At most this many circles each way: a periodic V_eff (a pendulum with no
 * angular momentum) has a row of them; the nearest are the ones that matter. */
#define MAX_CIRCLES 8

static bool walk(qd_ctx *ctx, qd__orb_env *env, double x0, int dir, double **xs, size_t *n) {
    double a, b, x;
    for (int k = 0; k < MAX_CIRCLES &&
                    qd__orb_scan(env, qd__orb_slope, x0, dir, &a, &b) == QD__ORB_FOUND; k++) {
        if (!stationary(env, a, b, &x))
            return true;
        if (!push(ctx, xs, n, x))
            return false;
        x0 = b; /* beyond the root: on its far side, so the walk goes on */
    }
    return true;
}

static int ascending(const void *pa, const void *pb) {
    double a = *(const double *)pa, b = *(const double *)pb;
    return a < b ? -1 : a > b;
}

bool qd__orb_circles(qd_ctx *ctx, qd__orb_env *env, double x0, double **xs, size_t *n) {
    *xs = NULL;
    *n = 0;
    if (qd__orb_slope(env, x0) == 0 && !push(ctx, xs, n, x0)) /* the walks start past it */
        return false;
    if (!walk(ctx, env, x0, 1, xs, n) || !walk(ctx, env, x0, -1, xs, n))
        return false;
    if (*n)
        qsort(*xs, *n, sizeof **xs, ascending);
    size_t k = 0; /* a root at x0 is found by both walks */
    for (size_t i = 0; i < *n; i++)
        if (!k || (*xs)[i] - (*xs)[k - 1] > 1e-12 * env->scale)
            (*xs)[k++] = (*xs)[i];
    *n = k;
    return true;
}
