/*
 * src/scatter/deflect.c - the deflection of one orbit (Desloge ch. 60):
 * the distance of closest approach by a scan inwards from far outside,
 * then alpha = int_{r0}^inf b dr / (r^2 sqrt(g)), g = 1 - V/E - b^2/r^2,
 * by the double-exponential rules of src/num/quad.c split at every jump.
 *
 * In s = r/r0 - 1 the integral is scale-free and the distance from the
 * turning point is r0 s exactly, so g near it is formed without
 * cancellation: g(r) - g(r0) = (b/r0)^2 s (2 + s)/(1 + s)^2 - (V(r) -
 * V(r0))/E, with V(r) - V(r0) from its Taylor series where r - r0 is tiny.
 */
#include "sct.h"

#include <math.h>
#include "../num/num.h"
#include "../base/args.h"

#define PER_DECADE 150
#define DECADES_OUT 4   /* the scan starts at 1e4 scale ... */
#define DECADES_IN 9    /* ... and ends at 1e-9 scale */
#define TAYLOR_S 1e-4   /* below it, V(r) - V(r0) by three Taylor terms */
#define QUAD_TOL 1e-13
#define PI 3.14159265358979323846 /* M_PI is not C11 */

static const char *const kind_names[] = {"deflected", "reflected", "orbiting", "captured"};

const char *qd_scatter_kind_name(qd_scatter_kind k) {
    return (unsigned)k < 4 ? kind_names[k] : "?";
}

typedef struct radial {
    qd_scatter *s;
    double E, b;
    double lo, hi;   /* the segment between jumps being scanned or integrated */
} radial;

static double g_at(radial *R, double r) {
    double q = R->b / r;
    return 1 - qd__sct_V(R->s, r, R->lo, R->hi) / R->E - q * q;
}

/* ---- the turning point ---------------------------------------------------- */

/* A root of g in (r_in, r_out), g(r_out) > 0 > g(r_in): bisection to
 * adjacent doubles (the jumps are segment ends, so g is continuous here). */
static double bisect_root(radial *R, double r_in, double r_out) {
    for (int it = 0; it < 200; it++) {
        double mid = 0.5 * (r_in + r_out);
        if (mid <= r_in || mid >= r_out)
            break;
        if (g_at(R, mid) > 0)
            r_out = mid;
        else
            r_in = mid;
    }
    return r_out;
}

/* A dip of g between grid points that goes below zero unseen (an orbit
 * grazing the barrier of V_eff): golden-section search for the minimum in
 * (a, c); returns a point where g < 0, or 0 when the minimum stays positive. */
static double dip_below(radial *R, double a, double c) {
    const double k = 0.3819660112501051;
    double x1 = a + k * (c - a), x2 = c - k * (c - a), g1 = g_at(R, x1), g2 = g_at(R, x2);
    for (int it = 0; it < 100 && g1 > 0 && g2 > 0; it++) {
        if (g1 < g2)
            c = x2, x2 = x1, g2 = g1, x1 = a + k * (c - a), g1 = g_at(R, x1);
        else
            a = x1, x1 = x2, g1 = g2, x2 = c - k * (c - a), g2 = g_at(R, x2);
    }
    return g1 <= 0 ? x1 : g2 <= 0 ? x2 : 0;
}

/* Scan one segment (lo, hi) inwards from r_top.  true with *r0 when g
 * turns negative in it. */
static bool scan_segment(radial *R, double r_top, double r_stop, double *r0) {
    double step = pow(10.0, -1.0 / PER_DECADE);
    double r = r_top, g = g_at(R, r), r_prev = r, g_prev = g;
    for (;;) {
        double rn = fmax(r * step, r_stop);
        double gn = g_at(R, rn);
        if (gn <= 0) {
            *r0 = bisect_root(R, rn, r);
            return true;
        }
        /* g fell, then rose: the minimum between rn and r_prev may dip below 0 */
        if (g < g_prev && gn > g && g < 0.1) {
            double x = dip_below(R, rn, r_prev);
            if (x > 0) {
                *r0 = bisect_root(R, x, r_prev);
                return true;
            }
        }
        r_prev = r, g_prev = g;
        r = rn, g = gn;
        if (r <= r_stop)
            return false;
    }
}

/* The turning point met coming in: kind DEFLECTED with a root, REFLECTED at
 * a wall (a jump g cannot cross, or the core), CAPTURED when none. */
static qd_scatter_kind turning_point(radial *R, double *r0) {
    qd_scatter *s = R->s;
    double L = qd__sct_scale(s, R->b);
    double top = L * pow(10.0, DECADES_OUT), bottom = fmax(s->core, L * pow(10.0, -DECADES_IN));
    size_t j = s->njump;
    R->hi = INFINITY;
    R->lo = j ? s->jump[j - 1] : s->core;
    double r_top = top;
    for (;;) {
        double stop = fmax(R->lo, bottom);
        if (r_top > stop && scan_segment(R, r_top, stop, r0))
            return QD_SCATTER_DEFLECTED;
        if (R->lo <= bottom || R->lo <= s->core) {
            if (s->core > 0 && R->lo <= s->core) {
                *r0 = s->core; /* an absorbing core takes what reaches it */
                return s->absorbing ? QD_SCATTER_CAPTURED : QD_SCATTER_REFLECTED;
            }
            *r0 = 0;
            return QD_SCATTER_CAPTURED;
        }
        /* cross the jump at lo: a wall when g is negative just inside */
        double a = R->lo;
        R->hi = a;
        R->lo = --j ? s->jump[j - 1] : s->core;
        if (g_at(R, a) <= 0) {
            *r0 = a;
            R->lo = a;
            return QD_SCATTER_REFLECTED;
        }
        r_top = a;
    }
}

/* ---- the integral ------------------------------------------------------------ */

typedef struct integrand {
    radial *R;
    double r0, V0d[4]; /* V and its derivatives at r0 (its segment's side) */
    bool root;         /* g(r0) = 0: form g from the distance s */
    double s_lo, s_hi; /* the segment in s */
    double far;        /* beyond it V is dropped: below round-off, and r^12 would overflow */
} integrand;

/* b/(r0 (1 + s)^2 sqrt(g)) dr/ds-scaled: the integrand of alpha in s. */
static double alpha_fn(void *data, double s, double sc) {
    integrand *I = data;
    radial *R = I->R;
    double r = I->r0 * (1 + s), q = R->b / I->r0, g;
    if (r > I->far) {
        double x = R->b / r;
        g = 1 - x * x;
    } else if (I->root && I->s_lo == 0) {
        /* the distance from r0 as the rule hands it over, without s - 0's
         * loss near the far end of a finite segment */
        double ds = sc >= 0 ? sc : I->s_hi + sc;
        double dr = I->r0 * ds, dV;
        if (ds < TAYLOR_S)
            dV = dr * (I->V0d[1] + dr * (I->V0d[2] / 2 + dr * I->V0d[3] / 6));
        else
            dV = qd__sct_V(R->s, r, R->lo, R->hi) - I->V0d[0];
        /* 1 - (r0/r)^2, the product form only where the difference would cancel */
        double u = 1 / ((1 + ds) * (1 + ds)), w = ds < 1 ? ds * (2 + ds) * u : 1 - u;
        g = q * q * w - dV / R->E;
    } else {
        g = g_at(R, r);
    }
    return q / ((1 + s) * (1 + s) * sqrt(g));
}

/* The ends of the pieces of [r0, inf) after r0: every jump above r0 (the
 * integrand is discontinuous there) and a few soft points, 2 r0 and the
 * potential's scale, so that no single piece has to resolve both the
 * turning point and a well far from it; near r0 a few more, for the
 * near-double root of an orbit close to orbiting. */
static size_t breakpoints(const qd_scatter *s, double r0, double b, double *p) {
    double L = qd__sct_scale(s, b);
    double soft[8] = {r0 * 1.001, r0 * 1.01, r0 * 1.1, 2 * r0, L / 2, L, 2 * L, 4 * L};
    size_t n = 0;
    for (size_t i = 0; i < s->njump; i++)
        if (s->jump[i] > r0)
            p[n++] = s->jump[i];
    for (int k = 0; k < 8; k++) {
        bool seen = false;
        for (size_t i = 0; i < n; i++)
            seen |= fabs(p[i] - soft[k]) <= 1e-3 * soft[k];
        if (!seen && soft[k] > r0 * (1 + 1e-4))
            p[n++] = soft[k];
    }
    for (size_t i = 1; i < n; i++) /* insertion sort: a handful */
        for (size_t j = i; j > 0 && p[j - 1] > p[j]; j--) {
            double t = p[j];
            p[j] = p[j - 1], p[j - 1] = t;
        }
    return n;
}

static bool piece(integrand *I, double lo, double hi, qd__num_quad *q) {
    radial *R = I->R;
    double mid = hi == INFINITY ? 2 * lo + 1 : 0.5 * (lo + hi);
    qd__sct_segment(R->s, mid, +1, &R->lo, &R->hi); /* the side V is evaluated on */
    I->s_lo = lo / I->r0 - 1;
    if (lo == I->r0)
        I->s_lo = 0;
    if (hi == INFINITY) {
        I->s_hi = INFINITY;
        return qd__num_quad_upper(alpha_fn, I, I->s_lo, QUAD_TOL, q);
    }
    I->s_hi = hi / I->r0 - 1;
    return qd__num_quad_finite(alpha_fn, I, I->s_lo, I->s_hi, QUAD_TOL, q);
}

/* alpha over the pieces from r0 outwards. */
static qd_status integrate(qd_ctx *ctx, radial *R, double r0, bool root, double *alpha) {
    qd_scatter *s = R->s;
    integrand I = {.R = R, .r0 = r0, .root = root, .far = 1e12 * qd__sct_scale(s, R->b)};
    double p[QD_SCT_MAX_JUMPS + 8];
    size_t np = breakpoints(s, r0, R->b, p);
    qd__sct_segment(s, r0, +1, &R->lo, &R->hi);
    qd__sct_eval(s, r0, R->lo, R->hi, I.V0d);
    double total = 0, lo = r0;
    for (size_t i = 0; i <= np; i++) {
        qd__num_quad q;
        double hi = i < np ? p[i] : INFINITY;
        bool ok = piece(&I, lo, hi, &q);
        if (!isfinite(q.value) || (!ok && !(q.error <= 1e-9 * fmax(1, fabs(q.value))))) {
            qd_ctx_error(ctx, QD_ERR_NUMERIC, "the deflection integral did not converge "
                         "(E = %g, b = %g)", R->E, R->b);
            return QD_ERR_NUMERIC;
        }
        total += q.value;
        lo = hi;
    }
    *alpha = total;
    return QD_OK;
}

/* ---- the deflection ------------------------------------------------------------ */

static double fold(double chi) { return acos(cos(chi)); }

/* b = 0: straight in; it turns back (chi = pi), passes through a centre
 * where V is finite (chi = 0), or falls into one where V -> -inf. */
static void head_on(radial *R, qd_scatter_path *out) {
    double r0;
    qd_scatter_kind k = turning_point(R, &r0);
    out->kind = k;
    out->r0 = r0;
    if (k == QD_SCATTER_CAPTURED && !(R->s->absorbing && R->s->core > 0)) {
        double L = qd__sct_scale(R->s, 0), lo, hi;
        qd__sct_segment(R->s, L * 1e-9, +1, &lo, &hi);
        if (!(fabs(qd__sct_V(R->s, L * 1e-9, lo, hi)) < 1e12 * R->E))
            return;
        out->kind = QD_SCATTER_DEFLECTED;
    }
    if (out->kind == QD_SCATTER_CAPTURED)
        return; /* absorbed by the core */
    out->alpha = k == QD_SCATTER_CAPTURED ? PI / 2 : 0; /* through the centre, or back */
    out->chi = PI - 2 * out->alpha;
    out->theta = fold(out->chi);
}

qd_status qd_scatter_deflect(qd_ctx *ctx, qd_scatter *s, double E, double b,
                             qd_scatter_path *out) {
    QD_ARGS_CTX(ctx, ctx && s && out);
    *out = (qd_scatter_path){.E = E, .b = b, .chi = NAN, .theta = NAN, .alpha = NAN};
    if (!(E > 0) || !isfinite(E)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the energy must be positive (the particle comes in "
                     "from infinity), not %g", E);
        return QD_ERR_ARG;
    }
    if (!(b >= 0) || !isfinite(b)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the impact parameter must be >= 0, not %g", b);
        return QD_ERR_ARG;
    }
    radial R = {.s = s, .E = E, .b = b};
    if (b == 0) {
        head_on(&R, out);
        return QD_OK;
    }
    double r0;
    out->kind = turning_point(&R, &r0);
    out->r0 = r0;
    if (out->kind == QD_SCATTER_CAPTURED)
        return QD_OK;
    /* a double root: g'(r0) = 0 to round-off, the orbit circles for ever */
    double v[4];
    qd__sct_eval(s, r0, R.lo, R.hi, v);
    double gp = -v[1] / E + 2 * b * b / (r0 * r0 * r0);
    if (out->kind == QD_SCATTER_DEFLECTED && fabs(gp * r0) < 1e-12) {
        out->kind = QD_SCATTER_ORBITING;
        out->alpha = INFINITY;
        out->chi = -INFINITY;
        return QD_OK;
    }
    qd_status st = integrate(ctx, &R, r0, out->kind == QD_SCATTER_DEFLECTED, &out->alpha);
    if (st != QD_OK)
        return st;
    out->chi = PI - 2 * out->alpha;
    out->theta = fold(out->chi);
    return QD_OK;
}
