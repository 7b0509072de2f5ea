/*
 * src/orbit/period.c - the quadratures of a bound (or captured) motion:
 *
 *     T_r = 2 int sqrt(M / (2 (E - V_eff))) dx,   Delta c = 2 int c'(x) sqrt(...) dx
 *
 * (for a reduced L not quadratic in x', o->general: dx/x' with h(x, x') = E
 * solved for x' at each abscissa, qd__orb_speed)
 * (an unbound orbit: Delta c from its turning point to infinity and back, by
 * exp-sinh) by tanh-sinh (num/quad.c), whose abscissas crowd double-exponentially at
 * the turning points, where the integrand has its inverse-square-root
 * singularity.  There E - V_eff(x) computed as a difference loses every
 * digit; near a turning point x_t it is formed from the distance xc = x -
 * x_t the rule supplies, by Taylor's series
 *
 *     E - V_eff(x_t + xc) = -(V1 xc + V2 xc^2/2 + V3 xc^3/6 + V4 xc^4/24)
 *
 * (E = V_eff(x_t)), used while its last term is below 1e-13 of the first,
 * |xc| <= (24e-13 |V1/V4|)^(1/3), so that what it leaves out is at round-off
 * (and within the reach that the second and third terms give a geometric
 * series: V4 may vanish at an end where V5 does not).  Beyond, the difference has lost
 * at most eps |E|/|V1 xc| of its digits.
 */
#include "orb.h"

#include <math.h>

#include "base/mem.h"
#include "num/num.h"

#define LAST 24e-13  /* 4! times the last Taylor term's bound, relative to the first */
#define RHO4 5.6e-4   /* 1e-13^(1/4): the ratio whose fourth power is LAST's 1e-13 */
#define QTOL 1e-12
#define ACCEPT 1e-8  /* not converged to QTOL but within this: a result, its error reported */

typedef struct integrand {
    qd__orb_env *env;
    double lo, hi;         /* the interval */
    bool turn_lo, turn_hi; /* which ends are turning points */
    double dlo[4], dhi[4]; /* V_eff's derivatives there */
    double nlo, nhi;       /* Taylor's series within these distances of the ends */
    int which;             /* -1: the time; i >= 0: ignored coordinate i */
} integrand;

static double taylor(const double *d, double xc) {
    return -xc * (d[0] + xc * (d[1] / 2 + xc * (d[2] / 6 + xc * d[3] / 24)));
}

static double gap(const integrand *g, double xc) {
    if (xc >= 0 && xc < g->nlo && g->turn_lo)
        return taylor(g->dlo, xc);
    if (xc <= 0 && -xc < g->nhi && g->turn_hi)
        return taylor(g->dhi, xc);
    return g->env->E - g->env->out[QD__ORB_V];
}

static double integrand_fn(void *data, double x, double xc) {
    integrand *g = data;
    const double *o = qd__orb_at(g->env, x);
    double w = gap(g, xc);
    if (!(w > 0))
        return NAN; /* at the turning point itself: the rule drops the abscissa */
    if (g->env->o->general) {
        /* dt = dx/x' with h(x, x') = E; the ignored rate is the mean of the
         * way out and back (c'(x, x') and c'(x, -x')), which also drops a
         * part linear in x' as the quadratic path's x' = 0 does */
        double xd = qd__orb_speed(g->env, x, w);
        if (!(xd > 0))
            return NAN;
        if (g->which < 0)
            return 1 / xd;
        double out = qd__orb_at2(g->env, x, xd)[QD__ORB_RATE2 + g->which];
        double back = qd__orb_at2(g->env, x, -xd)[QD__ORB_RATE2 + g->which];
        return (out + back) / (2 * xd);
    }
    double dt = sqrt(o[QD__ORB_M] / (2 * w));
    if (g->which < 0)
        return dt;
    double rate = o[QD__ORB_RATE + g->which];
    if (isnan(rate)) /* 0/0 at a removable point (no momentum, sin(theta) = 0): its limit */
        rate = qd__orb_at(g->env, x + 1e-9 * (g->hi - g->lo))[QD__ORB_RATE + g->which];
    return rate * dt;
}

/* V_eff's derivatives at x and the reach of its Taylor series there. */
static double derivatives(qd__orb_env *env, double x, double half, double *d) {
    const double *o = qd__orb_at(env, x);
    for (int k = 0; k < 4; k++)
        d[k] = o[QD__ORB_V1 + k];
    double reach = d[3] != 0 ? cbrt(LAST * fabs(d[0] / d[3])) : half;
    /* V4 may vanish where V5 does not (Kepler's V_eff at r = 5 p/4): the
     * terms of a series falling geometrically, ratio rho, give the first
     * omitted one rho^4 from the second (rho) and the third (rho^2) too */
    if (d[1] != 0)
        reach = fmin(reach, 2 * RHO4 * fabs(d[0] / d[1]));
    if (d[2] != 0)
        reach = fmin(reach, sqrt(6 * RHO4 * RHO4 * fabs(d[0] / d[2])));
    return isfinite(reach) ? fmin(reach, half) : 0;
}

static qd_status integrate(qd_ctx *ctx, integrand *g, double *value, double *err) {
    qd__num_quad q;
    bool ok = isinf(g->hi) ? qd__num_quad_upper(integrand_fn, g, g->lo, QTOL, &q)
                           : qd__num_quad_finite(integrand_fn, g, g->lo, g->hi, QTOL, &q);
    if (!isfinite(q.value) || (!ok && !(q.error <= ACCEPT * fmax(1, fabs(q.value))))) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC,
                     "the quadrature between %.17g and %.17g did not converge (estimate %.17g, "
                     "error %.3g)", g->lo, g->hi, q.value, q.error);
        return QD_ERR_NUMERIC;
    }
    *value = q.value;
    *err = fmax(*err, q.error / fmax(1, fabs(q.value)));
    return QD_OK;
}

/* An unbound orbit from its turning point out to infinity and back: the
 * total turn of each ignored coordinate (exp-sinh; no time, it diverges). */
static qd_status swept(qd_ctx *ctx, qd__orb_env *env, qd_orbit_result *r) {
    integrand g = {.env = env, .lo = r->lo, .hi = INFINITY, .turn_lo = true};
    g.nlo = derivatives(env, g.lo, INFINITY, g.dlo);
    double E = env->E;
    /* An energy 0 to round-off is 0 (the parabola): else a negative one turns the orbit
     * back at k/|E| ~ 1e16 and the integrand drops to nothing there. */
    if (fabs(E) <= 1e-14 * fabs(g.dlo[0] * g.lo))
        env->E = 0;
    qd_status st = QD_OK;
    for (size_t i = 0; i < r->nign && st == QD_OK; i++) {
        double v;
        g.which = (int)i;
        st = integrate(ctx, &g, &v, &r->quad_error);
        r->advance[i] = 2 * v;
    }
    env->E = E;
    return st;
}

/* A fall into the centre whose ignored rate grows like 1/distance or
 * faster there (V_eff = 2 lam r, its 1/r^2 terms cancelled, with angular
 * momentum: theta' = p/r^2 while r' stays finite, Desloge ch. 58, seed C
 * T9) turns infinitely often on the way: the advance diverges while the
 * fall time is finite.  Told from a quadrature that failed otherwise by
 * the integrand itself: x f(x) not falling as x nears the singular end. */
static bool spirals(integrand *g) {
    double L = g->hi - g->lo, f[3];
    bool at_lo = !g->turn_lo; /* the singular end */
    for (int k = 0; k < 3; k++) {
        double d = L * pow(1e-3, k + 2); /* 1e-6, 1e-9, 1e-12 of the interval */
        f[k] = d * integrand_fn(g, at_lo ? g->lo + d : g->hi - d, at_lo ? d : -d);
        if (!isfinite(f[k]) || f[k] == 0)
            return false;
    }
    return fabs(f[2]) >= 0.5 * fabs(f[1]) && fabs(f[1]) >= 0.5 * fabs(f[0]) &&
           (f[0] > 0) == (f[2] > 0);
}

static qd_status spiral(qd_ctx *ctx, integrand *g, double *advance) {
    bool at_lo = !g->turn_lo;
    double d = (g->hi - g->lo) * 1e-9;
    double f = integrand_fn(g, at_lo ? g->lo + d : g->hi - d, at_lo ? d : -d);
    *advance = copysign(INFINITY, f);
    qd__ctx_recover(ctx); /* the failed quadrature's message: the answer is infinity */
    return QD_OK;
}

qd_status qd__orb_quadratures(qd_ctx *ctx, qd__orb_env *env, qd_orbit_result *r) {
    if (r->kind == QD_ORBIT_UNBOUND)
        return r->nturn == 1 && r->turn[0] == r->lo && isinf(r->hi) ? swept(ctx, env, r) : QD_OK;
    bool bound = r->kind == QD_ORBIT_BOUND;
    integrand g = {.env = env, .lo = r->lo, .hi = r->hi, .which = -1};
    g.turn_lo = bound || r->turn[0] == r->lo;
    g.turn_hi = bound || r->turn[0] == r->hi;
    g.nlo = derivatives(env, g.lo, (g.hi - g.lo) / 2, g.dlo);
    g.nhi = derivatives(env, g.hi, (g.hi - g.lo) / 2, g.dhi);
    double twice = bound ? 2 : 1, v;
    qd_status st = integrate(ctx, &g, &v, &r->quad_error);
    if (st != QD_OK)
        return st;
    if (bound)
        r->period = 2 * v;
    else
        r->fall_time = v;
    for (size_t i = 0; i < r->nign && st == QD_OK; i++) {
        g.which = (int)i;
        st = integrate(ctx, &g, &v, &r->quad_error);
        r->advance[i] = twice * v;
        if (st == QD_ERR_NUMERIC && !bound && spirals(&g))
            st = spiral(ctx, &g, &r->advance[i]);
    }
    return st;
}
