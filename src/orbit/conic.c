/*
 * src/orbit/conic.c - Kepler-type orbits in closed form, and the orbit
 * equation r(c) or c(r) as an expression.
 *
 * With M = m constant, c' = h/x^2 and V_eff = c0 + c1/x + c2/x^2 (Kepler,
 * c2 = m h^2/2; Desloge ch. 58 P9 adds an inverse-cube force to c2), the
 * energy in u = 1/x reads E - c0 = m h^2 u_c^2/2 + c2 u^2 + c1 u, so
 *
 *     u'' + nu^2 u = k/(m h^2),  nu^2 = 2 c2/(m h^2),  k = -c1,
 *     u = (1 + e cos(nu (c - c_peri)))/p,  p = 2 c2/k,  e^2 = 1 + 4 c2 (E - c0)/k^2
 *
 * (reference seed-desloge-B.md C3, the Kepler closed forms, nu = 1).  A
 * repulsive force (k < 0) takes C3's other form, u = (e cos(nu (c - c_peri))
 * - 1)/p with p = 2 c2/|k| > 0: written with 1 + e cos, p would come out
 * negative and c_peri would name the far branch's vertex, half a turn (pi/nu)
 * from the closest approach the particle actually makes.  At the state
 * e cos(nu D) = p/x -+ 1 (- attractive, + repulsive) and e sin(nu D) =
 * p x'/(h nu) give the periapsis, D = c - c_peri.
 */
#include "orb.h"
#include "../base/args.h"

#include <float.h>
#include <math.h>
#include <stdio.h>


#define PARABOLA 1e-12 /* |e - 1| below this: a parabola, a infinite */

void qd__orb_conic(qd__orb_env *env, double x0, double xd0, double c0, qd_orbit_result *r) {
    size_t nign = env->o->routh->nign;
    const double *o = qd__orb_at(env, x0);
    double m = o[QD__ORB_M], h = o[QD__ORB_RATE] * x0 * x0;
    const double *c = o + QD__ORB_RATE + nign;
    double k = -c[1], c2 = c[2];
    double nu2 = 2 * c2 / (m * h * h), e2 = 1 + 4 * c2 * (env->E - c[0]) / (k * k);
    if (!(c2 > 0) || !(nu2 > 0) || !isfinite(nu2) || !(fabs(k) > 0))
        return; /* no angular momentum, an inverse-cube force that wins (a spiral), or
                   no 1/r term at all (p infinite) */
    /* nu^2 is 1 with no inverse-cube term, but c2 and m h^2/2 are formed
     * apart (h from the state): a difference at round-off is none (issue 33:
     * an SI Kepler orbit printed nu = 1 and cos(1*(phi + ...))) */
    if (fabs(nu2 - 1) <= 16 * DBL_EPSILON)
        nu2 = 1;
    r->conic = true;
    r->repulsive = k < 0;
    r->nu = sqrt(nu2);
    r->p = 2 * c2 / fabs(k);
    /* e from the state's own components, e cos = p/x0 -+ 1, e sin = p x'/(h nu):
     * e^2 = 1 + 4 c2 (E - c0)/k^2 cancels to round-off near a circle, which
     * the square root lifts to 1e-8; these are 0 on an exact circle */
    double ec = r->p / x0 + (r->repulsive ? 1 : -1), es = r->p * xd0 / (h * r->nu);
    r->e = r->kind == QD_ORBIT_CIRCULAR ? 0 : hypot(ec, es);
    if (!isfinite(r->e))
        r->e = e2 > 0 ? sqrt(e2) : 0;
    r->a = fabs(r->e - 1) < PARABOLA ? INFINITY : r->p / (1 - r->e * r->e);
    r->periapsis = r->e > 1e-12 ? c0 - atan2(es, ec) / r->nu : NAN;
}

static const qd_expr *num(qd_ctx *ctx, double v) { return qd_float(ctx, v); }

static const qd_expr *conic_equation(qd_ctx *ctx, const qd_orbit_result *r, const qd_expr *c) {
    const qd_expr *peri = isfinite(r->periapsis) ? num(ctx, r->periapsis) : qd_int(ctx, 0);
    const qd_expr *arg = qd_mul(ctx, num(ctx, r->nu), qd_sub(ctx, c, peri));
    const qd_expr *ecos = qd_mul(ctx, num(ctx, r->e), qd_fn(ctx, QD_COS, arg));
    const qd_expr *den = r->repulsive ? qd_sub(ctx, ecos, qd_int(ctx, 1))
                                      : qd_add(ctx, qd_int(ctx, 1), ecos);
    return qd_div(ctx, num(ctx, r->p), den);
}

/* c'(x) sqrt(M/(2 (E - V_eff))): in x, E, the momenta and the parameters. */
static const qd_expr *integrand(qd_ctx *ctx, const qd_orbit *o) {
    const qd_expr *gap = qd_sub(ctx, qd_symbol(ctx, "E"), o->Veff);
    return qd_mul(ctx, o->rate[0],
                  qd_sqrt(ctx, qd_div(ctx, o->mass, qd_mul(ctx, qd_int(ctx, 2), gap))));
}

const qd_expr *qd_orbit_equation(qd_ctx *ctx, const qd_orbit *o, const qd_orbit_result *r,
                                 const qd_expr **lhs) {
    QD_ARGS(NULL, ctx && o && r && lhs);
    const qd_expr *c = o->routh->ign[0];
    if (r->conic) {
        *lhs = o->x;
        return conic_equation(ctx, r, c);
    }
    char name[128], lower[128];
    snprintf(name, sizeof name, "%s_1", qd_expr_name(c));
    snprintf(lower, sizeof lower, "%s_1", qd_expr_name(o->x));
    *lhs = qd_sub(ctx, c, qd_symbol(ctx, name));
    const qd_expr *args[] = {integrand(ctx, o), o->x, qd_symbol(ctx, lower), o->x};
    return args[0] ? qd_ufunc(ctx, "integral", 4, args) : NULL;
}
