/*
 * src/action/cycle.c - one separated coordinate numerically: p^2(q) as a
 * compiled program, the cycle through the state (turning points, or a
 * whole period of an angle), and the integrals J = oint sqrt(p^2) dq and
 * dJ/dalpha_j = oint (dp^2/dalpha_j) / (2 sqrt(p^2)) dq by tanh-sinh
 * (src/num/quad.c) with the turning points as the end points.
 *
 * Near a turning point a, p^2(a + xc) is formed by its Taylor polynomial
 * in xc (the quadrature's end-point distance), not by evaluating p^2 where
 * its terms cancel: the integrand 1/sqrt(p^2) of dJ/dalpha would
 * otherwise read round-off as the value (Bailey et al. 2005 on
 * end-point singularities; docs/design.md, the numerics home).
 */
#include "act.h"

#include <math.h>

#include "base/mem.h"
#include "num/num.h"

#define PI 3.14159265358979323846

enum { NDER = 4 };  /* p^2 and three derivatives in q */

/* ---- p^2 as a program -------------------------------------------------------- */

static const qd_expr *value_of(const qd_expr *s, size_t n, const qd_expr *const *syms,
                               const double *vals, double *v) {
    for (size_t i = 0; i < n; i++)
        if (syms[i] == s) {
            *v = vals[i];
            return s;
        }
    return NULL;
}

/* The outputs: p^2, its q-derivatives, its alpha-derivatives. */
static const qd_expr **outputs(qd_ctx *ctx, const qd_expr *p2, const qd_expr *q, size_t nc,
                               const qd_expr *const *constants) {
    const qd_expr **o = qd__calloc(ctx, NDER + nc, sizeof *o);
    if (!o)
        return NULL;
    o[0] = p2;
    for (size_t k = 1; k < NDER; k++)
        o[k] = qd_diff(ctx, o[k - 1], q);
    for (size_t j = 0; j < nc; j++)
        o[NDER + j] = qd_diff(ctx, p2, constants[j]);
    return o;
}

bool qd__act_fn_init(qd_ctx *ctx, qd__act_fn *f, const qd_expr *p2, const qd_expr *q, size_t nc,
                     const qd_expr *const *constants, const double *cvals, size_t nvals,
                     const qd_expr *const *syms, const double *vals) {
    *f = (qd__act_fn){.nc = nc};
    const qd_expr **o = outputs(ctx, p2, q, nc, constants);
    size_t nin = 0;
    const qd_expr **in = o ? qd__num_inputs(ctx, NDER + nc, o, &nin) : NULL;
    f->in = qd__calloc(ctx, nin + 1, sizeof *f->in);
    f->out = qd__calloc(ctx, NDER + nc, sizeof *f->out);
    bool ok = in && f->in && f->out;
    /* in[] is reordered so q comes first; the others take their values now */
    for (size_t i = 0; ok && i < nin; i++) {
        if (in[i] == q)
            continue;
        size_t j = 0;
        while (j < nc && constants[j] != in[i])
            j++;
        if (j < nc)
            f->in[i] = cvals[j];
        else if (!value_of(in[i], nvals, syms, vals, &f->in[i])) {
            qd_ctx_error(ctx, QD_ERR_UNBOUND, "p^2 of %s depends on %s, which has no value",
                         qd_expr_name(q), qd_expr_name(in[i]));
            ok = false;
        }
    }
    if (ok) {
        /* q as input 0: swap it there (it may be absent, p^2 constant) */
        size_t iq = nin;
        for (size_t i = 0; i < nin; i++)
            if (in[i] == q)
                iq = i;
        if (iq == nin) {
            /* a failed realloc leaves in allocated: keep it to free below */
            const qd_expr **grown = qd__realloc(ctx, in, (nin + 1) * sizeof *in);
            ok = grown != NULL;
            if (ok) {
                in = grown;
                in[nin++] = q;
            }
        }
        if (ok) {
            const qd_expr *t = in[0];
            in[0] = q, in[iq] = t;
            double tv = f->in[0];
            f->in[0] = 0, f->in[iq] = tv;
            f->prog = qd_prog_new(ctx, nin, in, NDER + nc, o);
            ok = f->prog != NULL;
        }
    }
    qd__free(in);
    qd__free(o);
    if (!ok)
        qd__act_fn_free(f);
    return ok;
}

void qd__act_fn_free(qd__act_fn *f) {
    qd_prog_free(f->prog);
    qd__free(f->in);
    qd__free(f->out);
    *f = (qd__act_fn){0};
}

double qd__act_p2(qd__act_fn *f, double x) {
    f->in[0] = x;
    qd_prog_run(f->prog, f->in, f->out);
    return f->out[0];
}

/* ---- the cycle ----------------------------------------------------------------- */

/* Allowed: the motion may be at x.  NaN (outside p^2's domain) is not. */
static bool allowed(double v) { return isfinite(v) && v > 0; }

/* The boundary of the allowed region between in (allowed) and out (not),
 * by bisection to the last representable point: the root p^2 = 0 as
 * closely as the doubles tell it. */
static double boundary(qd__act_fn *f, double in, double out) {
    for (int it = 0; it < 200; it++) {
        double mid = in + (out - in) / 2;
        if (mid == in || mid == out)
            break;
        if (allowed(qd__act_p2(f, mid)))
            in = mid;
        else
            out = mid;
    }
    return in;
}

/* The bottom of a dip of p^2 in [a, b] by golden sections. */
static double dip(qd__act_fn *f, double a, double b, double *where) {
    const double g = 0.6180339887498949;
    for (int it = 0; it < 80; it++) {
        double c = b - g * (b - a), d = a + g * (b - a);
        if (qd__act_p2(f, c) < qd__act_p2(f, d))
            b = d;
        else
            a = c;
    }
    *where = (a + b) / 2;
    return qd__act_p2(f, *where);
}

/* The path from the start s one way: an angle over one turn in 512 equal
 * steps and one more (a dip at the end of the turn, which is the start's
 * other side, needs a sample beyond it to be seen); another coordinate in
 * steps growing by 2^(1/16) from 1e-6 max(|s|, 1e-3), out to 1e12 (|s| + 1). */
typedef struct path {
    double s, h0;
    int dir, n;
    bool angle;
} path;

enum { TURN_STEPS = 512, PER_DOUBLING = 16 };

static path path_make(double s, int dir, bool angle) {
    path p = {s, 2 * PI / TURN_STEPS, dir, TURN_STEPS + 1, angle};
    if (!angle) {
        p.h0 = 1e-6 * fmax(fabs(s), 1e-3);
        p.n = (int)(PER_DOUBLING * log2(1e12 * (fabs(s) + 1) / p.h0)) + 1;
    }
    return p;
}

static double path_x(const path *p, int i) {
    double d = p->angle ? p->h0 * i : p->h0 * (exp2((double)i / PER_DOUBLING) - 1);
    return p->s + p->dir * d;
}

/* The first point of the path where p^2 is not positive: at a sample, or
 * at the bottom of a dip between samples (a sample below both neighbours,
 * or the start when p^2 rises from it: the narrow forbidden gap beside a
 * state near the top of a swing is narrower than a step).  true with
 * *in (allowed) and *out (not) around it; *pmin the least p^2 met. */
static bool first_forbidden(qd__act_fn *f, const path *p, double *in, double *out,
                            double *pmin) {
    double x0 = p->s, v0 = qd__act_p2(f, x0), x1 = path_x(p, 1), v1 = qd__act_p2(f, x1);
    double xm, vm;
    *pmin = v0;
    if (!allowed(v1)) {
        *in = x0, *out = x1;
        return true;
    }
    if (v1 > v0 && !allowed(vm = dip(f, x0, x1, &xm))) {
        *in = x0, *out = xm;
        return true;
    }
    for (int i = 2; i <= p->n; i++) {
        double x2 = path_x(p, i), v2 = qd__act_p2(f, x2);
        *pmin = fmin(*pmin, v1);
        if (!allowed(v2)) {
            *in = x1, *out = x2;
            return true;
        }
        if (v1 < v0 && v1 < v2) {
            vm = dip(f, x0, x2, &xm);
            *pmin = fmin(*pmin, vm);
            if (!allowed(vm)) {
                *in = (xm < x1) == (p->dir > 0) ? x0 : x1; /* the sample before it */
                *out = xm;
                return true;
            }
        }
        x0 = x1, v0 = v1, x1 = x2, v1 = v2;
    }
    *pmin = fmin(*pmin, v1);
    return false;
}

/* The turning point met going from s in direction dir, or false. */
static bool turning_point(qd__act_fn *f, double s, int dir, bool angle, double *root,
                          double *pmin) {
    path p = path_make(s, dir, angle);
    double in, out;
    if (!first_forbidden(f, &p, &in, &out, pmin))
        return false;
    *root = boundary(f, in, out);
    return true;
}

/* A state on the boundary (at rest at a turning point, p^2 = 0 up to
 * round-off): the start moves into the allowed side. */
static bool start_point(qd__act_fn *f, double q0, double *s) {
    if (allowed(qd__act_p2(f, q0))) {
        *s = q0;
        return true;
    }
    for (double h = 1e-9 * fmax(fabs(q0), 1); h < 1e-2 * fmax(fabs(q0), 1); h *= 4)
        for (int dir = -1; dir <= 1; dir += 2)
            if (allowed(qd__act_p2(f, q0 + dir * h))) {
                *s = q0 + dir * h;
                return true;
            }
    return false;
}

static void derivatives_at(qd__act_fn *f, double x, double *d) {
    qd__act_p2(f, x);
    for (int k = 0; k < 3; k++)
        d[k] = f->out[1 + k];
}

/* The largest p^2 on a grid of the cycle: the scale of "zero". */
static double p2_max(qd__act_fn *f, double lo, double hi) {
    double m = 0;
    for (int i = 0; i <= 64; i++)
        m = fmax(m, qd__act_p2(f, lo + (hi - lo) * i / 64));
    return m;
}

/* A double root of p^2 at an end (a separatrix), as far as the doubles
 * tell: p^2 ~ d1 x + d2 x^2 / 2 there has its vertex within tol pmax of
 * zero, so the energy is within tol (relative to the range of p^2 over
 * the cycle) of the energy of a double root.  A simple root read in
 * floating point has d1 ~ pmax / width; a separatrix met by round-off has
 * d1 ~ sqrt(round-off). */
static const double separatrix_tol = 1e-10;
static bool double_root(const double *d, double pmax) {
    return d[0] * d[0] <= 2 * fabs(d[1]) * separatrix_tol * pmax;
}

/* An end of the allowed region where p^2 does not fall to zero is no
 * turning point: the motion reaches it with p != 0.  p^2 grows without
 * bound there (a collision: Kepler's radial orbit, alpha_theta = 0, whose
 * r reaches 0), or p^2 stops at the edge of its domain.  A root found by
 * bisection leaves p^2 ~ |p^2'| ulp(end) there, far below the interior's
 * values; a pole or an edge leaves it comparable or larger (which once
 * read as a double root: "separatrix"). */
static bool singular_end(qd__act_fn *f, double lo, double hi, double *end) {
    double m = 0;
    for (int i = 1; i < 64; i++)
        m = fmax(m, qd__act_p2(f, lo + (hi - lo) * i / 64));
    for (int side = 0; side < 2; side++) {
        *end = side ? hi : lo;
        if (!(qd__act_p2(f, *end) <= 1e-6 * m))
            return true;
    }
    return false;
}

/* An angle whose p^2 stays positive over a whole turn rotates; its least
 * p^2 within tol of zero is the separatrix. */
static qd_act_fail rotation(qd__act_fn *f, double q0, double pmin, qd__act_cycle *c) {
    *c = (qd__act_cycle){.kind = QD_ACT_ROTATION, .lo = q0 - PI, .hi = q0 + PI};
    return pmin > separatrix_tol * p2_max(f, c->lo, c->hi) ? QD_ACT_OK : QD_ACT_SEPARATRIX;
}

qd_act_fail qd__act_cycle_find(qd__act_fn *f, double q0, bool angle, qd__act_cycle *c) {
    double s, lo, hi, pmin;
    *c = (qd__act_cycle){.kind = QD_ACT_LIBRATION};
    if (!start_point(f, q0, &s))
        return QD_ACT_AT_REST;
    /* an angle librates iff p^2 vanishes within a turn of the state */
    if (!turning_point(f, s, +1, angle, &hi, &pmin))
        return angle ? rotation(f, q0, pmin, c) : QD_ACT_UNBOUNDED;
    if (!turning_point(f, s, -1, angle, &lo, &pmin))
        return QD_ACT_UNBOUNDED;
    /* a cycle as narrow as the round-off of p^2 about a minimum of the
     * potential (width ~ sqrt(eps) there) is rest, not motion */
    if (hi - lo <= 1e-7 * fmax(1, fabs(q0)))
        return QD_ACT_AT_REST;
    double end;
    if (singular_end(f, lo, hi, &end)) {
        *c = (qd__act_cycle){.kind = QD_ACT_LIBRATION, .lo = end, .hi = end};
        return QD_ACT_SINGULAR;
    }
    *c = (qd__act_cycle){.kind = QD_ACT_LIBRATION, .lo = lo, .hi = hi};
    derivatives_at(f, lo, c->dlo);
    derivatives_at(f, hi, c->dhi);
    double pmax = p2_max(f, lo, hi);
    if (double_root(c->dlo, pmax) || double_root(c->dhi, pmax))
        return QD_ACT_SEPARATRIX;
    return QD_ACT_OK;
}

/* ---- the integrals ----------------------------------------------------------- */

typedef struct integrand {
    qd__act_fn *f;
    long j;                  /* -1: sqrt(p^2); else dp^2/dalpha_j / (2 sqrt(p^2)) */
    double near_lo, near_hi; /* below these distances from the turning points, Taylor */
    const double *dlo, *dhi; /* p^2's derivatives at the ends that are turning
                                points (NULL: an end where p^2 > 0) */
} integrand;

/* p^2 at x, xc from the nearer end, without the cancellation of its terms
 * near a turning point (where p^2 = 0 exactly, not as computed). */
static double p2_at(const integrand *g, double x, double xc) {
    const double *d = xc >= 0 ? g->dlo : g->dhi;
    if (d && fabs(xc) < (xc >= 0 ? g->near_lo : g->near_hi)) {
        qd__act_p2(g->f, x); /* for the alpha-derivatives at x */
        return xc * (d[0] + xc * (d[1] / 2 + xc * d[2] / 6));
    }
    return qd__act_p2(g->f, x);
}

static double integrand_at(void *data, double x, double xc) {
    const integrand *g = data;
    double p2 = p2_at(g, x, xc);
    if (!(p2 > 0))
        return g->j < 0 ? 0 : NAN; /* only at an end: the quadrature drops it there */
    if (g->j < 0)
        return sqrt(p2);
    return g->f->out[NDER + g->j] / (2 * sqrt(p2));
}

/* The integral over [a, b] (0 when empty). */
static bool integrate(integrand *g, double a, double b, double *out) {
    qd__num_quad r = {0};
    bool ok = !(b > a) || qd__num_quad_finite(integrand_at, g, a, b, 1e-13, &r);
    *out = r.value;
    return ok || (isfinite(r.value) && r.error <= 1e-10 * fmax(1, fabs(r.value)));
}

/* The Taylor polynomial's reach at a turning point: 1e-4 of the cycle, and
 * 1e-3 of the length on which p^2 bends there (|d1/d2|, sqrt|d1/d3|, d_k
 * the k-th derivative).  An eccentric Kepler orbit's pericentre bends on
 * the scale r_min, far below the cycle's width: the cubic at 1e-4 of the
 * width was off there and the quadrature of dJ/dalpha did not converge
 * (r' = 0.4, theta' = 0.1 in examples/kepler_polar.qd). */
static double near_of(const double *d, double width) {
    double n = 1e-4 * width;
    if (d[1] != 0)
        n = fmin(n, 1e-3 * fabs(d[0] / d[1]));
    if (d[2] != 0)
        n = fmin(n, 1e-3 * sqrt(fabs(d[0] / d[2])));
    return n;
}

static integrand integrand_of(qd__act_fn *f, const qd__act_cycle *c) {
    bool lib = c->kind == QD_ACT_LIBRATION;
    double w = c->hi - c->lo;
    return (integrand){.f = f, .j = -1, .near_lo = lib ? near_of(c->dlo, w) : 0,
                       .near_hi = lib ? near_of(c->dhi, w) : 0,
                       .dlo = lib ? c->dlo : NULL, .dhi = lib ? c->dhi : NULL};
}

bool qd__act_integrals(qd__act_fn *f, const qd__act_cycle *c, double *J, double *dJ) {
    integrand g = integrand_of(f, c);
    /* a libration's cycle runs the interval twice, out and back */
    double twice = c->kind == QD_ACT_LIBRATION ? 2 : 1;
    bool ok = integrate(&g, c->lo, c->hi, J);
    *J *= twice;
    for (size_t j = 0; j < f->nc; j++) {
        g.j = (long)j;
        ok = integrate(&g, c->lo, c->hi, &dJ[j]) && ok;
        dJ[j] *= twice;
    }
    return ok;
}

/* int_origin^x dp/dalpha_j dq along the cycle: from the lower turning
 * point out (p > 0) and back (p < 0); for a rotation from the multiple of
 * 2 pi below x, in the sense of the motion.  The half nearer a turning
 * point is integrated from it, the other as the half-cycle's dJ/2 less
 * the rest, so every turning point is an end of the quadrature. */
static bool phase_one(integrand *g, const qd__act_cycle *c, double x, int sign, double dJ,
                      double *beta) {
    double I, rest;
    bool ok;
    if (c->kind == QD_ACT_ROTATION) {
        double o = 2 * PI * floor(x / (2 * PI));
        ok = integrate(g, o, x, &I);
    } else if (x - c->lo <= c->hi - x) {
        const double *dhi = g->dhi;
        g->dhi = NULL;
        ok = integrate(g, c->lo, fmax(x, c->lo), &I);
        g->dhi = dhi;
    } else {
        const double *dlo = g->dlo;
        g->dlo = NULL;
        ok = integrate(g, fmin(x, c->hi), c->hi, &rest);
        g->dlo = dlo;
        I = dJ / 2 - rest;
    }
    *beta = sign >= 0 ? I : dJ - I;
    return ok;
}

bool qd__act_phase(qd__act_fn *f, const qd__act_cycle *c, double x, int sign, const double *dJ,
                   double *beta) {
    integrand g = integrand_of(f, c);
    bool ok = true;
    for (size_t j = 0; j < f->nc; j++) {
        g.j = (long)j;
        ok = phase_one(&g, c, x, sign, dJ[j], &beta[j]) && ok;
    }
    return ok;
}
