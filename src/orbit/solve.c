/*
 * src/orbit/solve.c - the motion through one state: its energy and
 * momenta, the interval it fills (turning points by scan and zeroin), its
 * kind, the quadratures, the circular motions at the same momenta and,
 * for Kepler-type reductions, the conic.
 */
#include "orb.h"

#include <math.h>
#include <string.h>

#include "base/mem.h"
#include "../base/args.h"

#define PI 3.14159265358979323846
#define CIRC_TOL 1e-8 /* circular: the other turning point within this many scales */

const char *qd_orbit_kind_name(qd_orbit_kind k) {
    static const char *const names[] = {"bound", "unbound", "circular", "capture", "asymptotic"};
    return (unsigned)k < 5 ? names[k] : "?";
}

void qd_orbit_result_free(qd_orbit_result *r) {
    if (!r)
        return;
    for (size_t i = 0; i < r->ncircle; i++)
        qd__free(r->circle[i].apsidal);
    qd__free(r->circle);
    qd__free(r->momenta);
    qd__free(r->advance);
    qd__free(r->apsidal);
    qd__free(r->precession);
    memset(r, 0, sizeof *r);
}

static double value_of(const qd_expr *s, size_t n, const qd_expr *const *syms, const double *vals,
                       bool *given) {
    for (size_t k = 0; k < n; k++)
        if (syms[k] == s) {
            if (given)
                *given = true;
            return vals[k];
        }
    if (given)
        *given = false;
    return 0;
}

/* The i-th symbol of a state: ignored coordinates and their velocities, then
 * the kept ones, then t (i = 2 n). */
static const qd_expr *state_symbol(qd_ctx *ctx, const qd_routh *h, size_t i) {
    if (i == 2 * h->n)
        return qd_time(ctx);
    if (i < 2 * h->nign)
        return i % 2 ? qd_jet(ctx, h->ign[i / 2], 1) : h->ign[i / 2];
    i -= 2 * h->nign;
    return i % 2 ? h->keepd[i / 2] : h->keep[i / 2];
}

/* The state with every coordinate, velocity and t the caller left out at 0. */
static qd_status full_state(qd_ctx *ctx, const qd_routh *h, size_t n, const qd_expr *const *syms,
                            const double *vals, const qd_expr ***fs, double **fv, size_t *fn) {
    size_t cap = n + 2 * h->n + 1, k = n;
    *fs = qd__calloc(ctx, cap, sizeof **fs);
    *fv = qd__calloc(ctx, cap, sizeof **fv);
    if (!*fs || !*fv)
        return QD_ERR_NOMEM;
    memcpy(*fs, syms, n * sizeof *syms);
    memcpy(*fv, vals, n * sizeof *vals);
    for (size_t i = 0; i <= 2 * h->n; i++) {
        const qd_expr *s = state_symbol(ctx, h, i);
        bool given;
        value_of(s, n, syms, vals, &given);
        if (!s)
            return qd_ctx_status(ctx);
        if (!given)
            (*fs)[k++] = s; /* its value stays the calloc'd 0 */
    }
    *fn = k;
    return QD_OK;
}

static qd_status momenta(qd_ctx *ctx, const qd_orbit *o, size_t n, const qd_expr *const *syms,
                         const double *vals, double *beta) {
    const qd_routh *h = o->routh;
    const qd_expr **fs = NULL;
    double *fv = NULL;
    size_t fn = 0;
    qd_status st = full_state(ctx, h, n, syms, vals, &fs, &fv, &fn);
    for (size_t i = 0; i < h->nign && st == QD_OK; i++) {
        bool given;
        beta[i] = value_of(h->beta[i], n, syms, vals, &given);
        if (!given)
            st = qd_eval(ctx, h->pdef[i], fn, fs, fv, &beta[i]);
    }
    qd__free(fs);
    qd__free(fv);
    return st;
}

static qd_status alloc_result(qd_ctx *ctx, size_t nign, qd_orbit_result *r) {
    memset(r, 0, sizeof *r);
    r->nign = nign;
    double **arrs[] = {&r->momenta, &r->advance, &r->apsidal, &r->precession};
    for (int k = 0; k < 4; k++)
        if (!(*arrs[k] = qd__calloc(ctx, nign, sizeof(double))))
            return QD_ERR_NOMEM;
    r->period = r->fall_time = r->periapsis = NAN;
    for (size_t i = 0; i < nign; i++)
        r->advance[i] = r->apsidal[i] = r->precession[i] = NAN;
    return QD_OK;
}

/* ---- the interval of the motion --------------------------------------------- */

/* With E given below V_eff(x0): the allowed point nearest x0, walking both
 * ways in turn; else the error naming E and the least V_eff met. */
static qd_status allowed_start(qd_ctx *ctx, qd__orb_env *env, double *x0) {
    double a, b, best = HUGE_VAL, at = *x0, found = NAN;
    for (int dir = 1; dir >= -1; dir -= 2)
        if (qd__orb_scan(env, qd__orb_gap, *x0, dir, &a, &b) == QD__ORB_FOUND &&
            !(fabs(b - *x0) >= fabs(found - *x0)))
            found = b;
    if (!isnan(found)) {
        *x0 = found;
        return QD_OK;
    }
    /* No motion: the least V_eff, where V_eff' changes sign nearest x0. */
    double *xs = NULL;
    size_t n = 0;
    if (!qd__orb_circles(ctx, env, *x0, &xs, &n))
        return QD_ERR_NOMEM;
    for (size_t i = 0; i < n; i++) {
        double v = qd__orb_at(env, xs[i])[QD__ORB_V];
        if (v < best)
            best = v, at = xs[i];
    }
    qd__free(xs);
    if (best == HUGE_VAL)
        best = qd__orb_at(env, at)[QD__ORB_V];
    qd_ctx_error(ctx, QD_ERR_ARG,
                 "no motion: the energy E = %.12g is below the minimum of V_eff, %.12g (at "
                 "%s = %.12g)", env->E, best, qd_expr_name(env->o->x), at);
    return QD_ERR_ARG;
}

/* A turning point found to round-off may lie a few ulps inside the
 * forbidden region (E - V_eff < 0 there): moved towards from, onto the
 * allowed side, so the quadratures start where the motion is. */
static double polish(qd__orb_env *env, double x, double from) {
    for (int k = 0; k < 64 && qd__orb_gap(env, x) < 0 && x != from; k++)
        x = nextafter(x, from);
    return x;
}

/* A turning point nearer xs than the scan's first step (1e-3 scale: a
 * near-circle started at or near an apsis, whose other apsis the first step
 * jumps over): the nearest root towards dir of Taylor's quadratic
 * E - V_eff(xs + d) ~ g0 - V1 d - V2 d^2/2, bracketed by half and twice its
 * distance and found by zeroin.  false when there is none that close. */
static bool near_turn(qd__orb_env *env, double xs, int dir, double *end) {
    const double *o = qd__orb_at(env, xs);
    double g0 = env->E - o[QD__ORB_V], v1 = dir * o[QD__ORB_V1], v2 = o[QD__ORB_V2];
    /* v2/2 s^2 + v1 s - g0 = 0, its least positive root s */
    double s = NAN;
    if (v2 != 0) {
        double disc = v1 * v1 + 2 * v2 * g0;
        if (disc >= 0) {
            double r1 = (-v1 + sqrt(disc)) / v2, r2 = (-v1 - sqrt(disc)) / v2;
            s = r1 > 0 && (r2 <= 0 || r1 < r2) ? r1 : r2 > 0 ? r2 : NAN;
        }
    } else if (v1 > 0) {
        s = g0 / v1;
    }
    if (!(s > 0) || s > 1e-3 * env->scale)
        return false;
    double a = xs + dir * s / 2, b = xs + dir * 2 * s;
    if (!(qd__orb_gap(env, a) > 0) || !(qd__orb_gap(env, b) <= 0))
        return false;
    *end = polish(env, qd__orb_brent(env, qd__orb_gap, a, b), xs);
    return true;
}

/* One side of the motion from xs: a turning point, an open end or a
 * singular point. */
static qd__orb_end side(qd__orb_env *env, double xs, int dir, double *end) {
    double a, b;
    if (near_turn(env, xs, dir, end))
        return QD__ORB_FOUND;
    qd__orb_end e = qd__orb_scan(env, qd__orb_gap, xs, dir, &a, &b);
    if (e == QD__ORB_FOUND)
        *end = polish(env, qd__orb_brent(env, qd__orb_gap, a, b), a);
    else if (e == QD__ORB_SINGULAR)
        *end = b;
    else
        *end = dir * INFINITY;
    return e;
}

static bool circular_at(qd__orb_env *env, double x) {
    const double *o = qd__orb_at(env, x);
    double v1 = fabs(o[QD__ORB_V1]), v2 = fabs(o[QD__ORB_V2]);
    return env->E - o[QD__ORB_V] <= 0 && 2 * v1 <= CIRC_TOL * env->scale * v2;
}

static bool same_energy(double E, double v) {
    return fabs(E - v) <= 1e-12 * (fabs(E) + fabs(v)) || E == v;
}

/* A barrier the walk stepped over: its growing steps can jump a forbidden
 * gap narrower than a step (E just below the top of V_eff).  V_eff is
 * monotone between its stationary points (r->circle, ascending), so the
 * first one towards dir that stands above E, with the one before it (or the
 * state), brackets the single root the motion turns at. */
static void barrier_missed(qd__orb_env *env, double xs, int dir, const qd_orbit_result *r,
                           qd__orb_end *e, double *end) {
    double prev = xs;
    for (size_t n = 0; n < r->ncircle; n++) {
        const qd_orbit_circle *c = &r->circle[dir > 0 ? n : r->ncircle - 1 - n];
        if ((c->x - xs) * dir <= 0)
            continue;
        if ((c->x - *end) * dir >= 0)
            return; /* beyond where the walk stopped */
        if (!(env->E < c->energy) || same_energy(env->E, c->energy)) {
            prev = c->x;
            continue;
        }
        if (qd__orb_gap(env, prev) > 0) {
            *end = polish(env, qd__orb_brent(env, qd__orb_gap, prev, c->x), prev);
            *e = QD__ORB_FOUND;
        }
        return;
    }
}

static void classify(qd__orb_env *env, double xs, qd_orbit_result *r) {
    qd__orb_end e[2];
    double ends[2];
    const double *o = qd__orb_at(env, xs);
    bool at_turn = !(env->E - o[QD__ORB_V] > 0);
    int forbid = o[QD__ORB_V1] > 0 ? 1 : -1; /* the force pushes away from this side */
    for (int k = 0; k < 2; k++) {
        int dir = k ? 1 : -1;
        if (at_turn && dir == forbid) {
            e[k] = QD__ORB_FOUND;
            ends[k] = xs;
        } else {
            e[k] = side(env, xs, dir, &ends[k]);
            barrier_missed(env, xs, dir, r, &e[k], &ends[k]);
        }
    }
    r->lo = ends[0];
    r->hi = ends[1];
    r->nturn = 0;
    for (int k = 0; k < 2; k++)
        if (e[k] == QD__ORB_FOUND)
            r->turn[r->nturn++] = ends[k];
    if (r->nturn == 2)
        r->kind = QD_ORBIT_BOUND;
    else if (r->nturn == 1 && (e[0] == QD__ORB_SINGULAR || e[1] == QD__ORB_SINGULAR))
        r->kind = QD_ORBIT_CAPTURE;
    else
        r->kind = QD_ORBIT_UNBOUND;
}

/* ---- circular motions -------------------------------------------------------- */

static void circle_at(qd__orb_env *env, double x, qd_orbit_circle *c) {
    const qd_orbit *ob = env->o;
    const double *o = qd__orb_at(env, x);
    if (isnan(o[QD__ORB_V2])) /* 0/0 of a term with no momentum (theta = 0): its limit */
        o = qd__orb_at(env, x + 1e-7 * env->scale);
    double M = o[QD__ORB_M], v2 = o[QD__ORB_V2];
    c->x = x;
    c->energy = o[QD__ORB_V];
    c->curvature = v2;
    double flat = 1e-9 * (fabs(o[QD__ORB_V]) + M) / (env->scale * env->scale);
    c->stable = fabs(v2) <= flat ? -1 : v2 > 0;
    c->omega = c->stable == 1 ? sqrt(v2 / M) : NAN;
    for (size_t i = 0; i < ob->routh->nign; i++)
        c->apsidal[i] = c->stable == 1 ? PI * fabs(o[QD__ORB_RATE + i]) / c->omega : NAN;
    c->bertrand = NAN;
    if (ob->central) {
        /* f = -V', V = V_eff - M h^2/(2 x^2), h = c' x^2 (Desloge ch. 59 eq. 31) */
        double h = o[QD__ORB_RATE] * x * x, cent = M * h * h;
        double f = -(o[QD__ORB_V1] + cent / (x * x * x));
        double fp = -(v2 - 3 * cent / (x * x * x * x));
        double b2 = 3 + x * fp / f;
        c->bertrand = b2 > 0 ? PI / sqrt(b2) : NAN;
    }
}

static qd_status circles(qd_ctx *ctx, qd__orb_env *env, double x0, qd_orbit_result *r) {
    double *xs = NULL;
    size_t n = 0;
    if (!qd__orb_circles(ctx, env, x0, &xs, &n))
        return QD_ERR_NOMEM;
    r->circle = qd__calloc(ctx, n ? n : 1, sizeof *r->circle);
    if (!r->circle) {
        qd__free(xs);
        return QD_ERR_NOMEM;
    }
    for (size_t k = 0; k < n; k++) {
        r->circle[k].apsidal = qd__calloc(ctx, r->nign ? r->nign : 1, sizeof(double));
        if (!r->circle[k].apsidal) {
            qd__free(xs);
            return QD_ERR_NOMEM;
        }
        r->ncircle = k + 1;
        circle_at(env, xs[k], &r->circle[k]);
    }
    qd__free(xs);
    return QD_OK;
}

/* ---- the whole ---------------------------------------------------------------- */

static void circular_limits(qd__orb_env *env, double x, qd_orbit_result *r) {
    const double *o = qd__orb_at(env, x);
    double v2 = o[QD__ORB_V2];
    r->kind = QD_ORBIT_CIRCULAR;
    r->nturn = 0;
    r->lo = r->hi = x;
    if (!(v2 > 0))
        return; /* an unstable circle: no small oscillation, no period */
    r->period = 2 * PI / sqrt(v2 / o[QD__ORB_M]);
    for (size_t i = 0; i < r->nign; i++)
        r->advance[i] = o[QD__ORB_RATE + i] * r->period;
}

/* The first and second derivatives at x of output k by central differences
 * at steps h and 2 h, extrapolated (Richardson): errors h^4 and eps/h^2. */
static void differences(qd__orb_env *env, int k, double x, double h, double *d1, double *d2) {
    double f0 = qd__orb_at(env, x)[k];
    double p1 = qd__orb_at(env, x + h)[k], m1 = qd__orb_at(env, x - h)[k];
    double p2 = qd__orb_at(env, x + 2 * h)[k], m2 = qd__orb_at(env, x - 2 * h)[k];
    double a1 = (p1 - m1) / (2 * h), b1 = (p2 - m2) / (4 * h);
    double a2 = (p1 - 2 * f0 + m1) / (h * h), b2 = (p2 - 2 * f0 + m2) / (4 * h * h);
    *d1 = (4 * a1 - b1) / 3;
    *d2 = (4 * a2 - b2) / 3;
}

/* The small-oscillation expansion about a stable circle x_c to second order
 * in the amplitude.  In s = integral of sqrt(M) dx from x_c (unit mass), the
 * motion is s'' = -U'(s), U = u2 s^2/2 + u3 s^3/6 + u4 s^4/24, whose
 * frequency is w0 (1 + a^2 (u4/(16 u2) - 5 u3^2/(48 u2^2))), w0^2 = u2, and
 * whose s has mean -u3 a^2/(4 u2) and mean square a^2/2 (Lindstedt), a the
 * half-width in s; each ignored coordinate advances at its mean rate times
 * the period.  The V_eff derivatives are exact; M's and the rates' are taken
 * by differences (their error, about 1e-10, is multiplied by a^2). */
static void circle_expansion(qd__orb_env *env, double xc, double lo, double hi,
                             qd_orbit_result *r) {
    const double *o = qd__orb_at(env, xc);
    double V2 = o[QD__ORB_V2], V3 = o[QD__ORB_V3], V4 = o[QD__ORB_V4], M = o[QD__ORB_M];
    double h = 1e-3 * fmax(fabs(xc), fmax(hi - lo, 1e-300)), M1, M2;
    differences(env, QD__ORB_M, xc, h, &M1, &M2);
    /* s = b1 d + b2 d^2 + b3 d^3 (d = x - x_c), reverted: d = c1 s + c2 s^2 + c3 s^3 */
    double sq = sqrt(M), b1 = sq, b2 = M1 / (4 * sq), b3 = M2 / (12 * sq) - M1 * M1 / (24 * M * sq);
    double c1 = 1 / b1, c2 = -b2 / (b1 * b1 * b1), c3 = (2 * b2 * b2 - b1 * b3) / pow(b1, 5);
    double u2 = V2 * c1 * c1, u3 = 6 * V2 * c1 * c2 + V3 * c1 * c1 * c1;
    double u4 = 12 * V2 * (c2 * c2 + 2 * c1 * c3) + 12 * V3 * c1 * c1 * c2 + V4 * pow(c1, 4);
    double dl = lo - xc, dh = hi - xc;
    double a = (b1 * (dh - dl) + b2 * (dh * dh - dl * dl) + b3 * (dh * dh * dh - dl * dl * dl)) / 2;
    double w = sqrt(u2) * (1 + a * a * (u4 / (16 * u2) - 5 * u3 * u3 / (48 * u2 * u2)));
    r->period = 2 * PI / w;
    double mean_s = -u3 * a * a / (4 * u2), mean_s2 = a * a / 2;
    for (size_t i = 0; i < r->nign; i++) {
        double R0 = qd__orb_at(env, xc)[QD__ORB_RATE + i], R1, R2;
        differences(env, QD__ORB_RATE + (int)i, xc, h, &R1, &R2);
        double rho1 = R1 * c1, rho2 = 2 * R1 * c2 + R2 * c1 * c1;
        r->advance[i] = (R0 + rho1 * mean_s + rho2 * mean_s2 / 2) * r->period;
    }
}

/* A bound motion about a stable circle x_c: E - V_eff, of size V2 A^2/2
 * for an amplitude A, is formed from E with an absolute error eps |E|, so
 * the quadratures lose eps |E| / (E - V_eff(x_c)) of their digits; the
 * small-oscillation expansion to second order in A (circle_expansion) errs
 * by about 10 (A/x_c)^4, and by the differences' 1e-10 in its A^2 terms.  The
 * smaller of the two is the result's error; true when that is the
 * expansion, which is then filled in. */
static bool near_circle(qd__orb_env *env, qd_orbit_result *r) {
    const qd_orbit_circle *c = NULL;
    for (size_t k = 0; k < r->ncircle; k++)
        if (r->circle[k].stable == 1 && r->circle[k].x > r->lo && r->circle[k].x < r->hi)
            c = &r->circle[k];
    if (!c)
        return false;
    double A = (r->hi - r->lo) / 2, gap = env->E - c->energy;
    double rel2 = (A / fmax(fabs(c->x), A)) * (A / fmax(fabs(c->x), A));
    double expansion = 10 * rel2 * rel2 + 1e-10 * rel2;
    double cancel = 2.2e-16 * (fabs(env->E) + fabs(c->energy)) / gap;
    if (!(gap > 0) || !(expansion < cancel)) {
        if (gap > 0)
            r->quad_error = fmax(r->quad_error, cancel);
        return false;
    }
    circle_expansion(env, c->x, r->lo, r->hi, r);
    r->quad_error = expansion;
    return true;
}

/* V_eff not finite at x = 0 and not continuous through it: the centre of a
 * central force (V_eff -> +-inf), not the 0/0 of a centrifugal term with no
 * momentum (a spherical pendulum swinging through the vertical). */
static bool singular_at_zero(qd__orb_env *env) {
    if (isfinite(qd__orb_at(env, 0)[QD__ORB_V]))
        return false;
    double d = 1e-6 * env->scale, v1 = qd__orb_at(env, d)[QD__ORB_V];
    double v2 = qd__orb_at(env, 2 * d)[QD__ORB_V], vm = qd__orb_at(env, -d)[QD__ORB_V];
    double tol = 1e-6 * (1 + fabs(v1));
    return !(isfinite(v1) && isfinite(v2) && isfinite(vm) && fabs(v1 - vm) <= tol &&
             fabs(v1 - v2) <= tol);
}

/* E at the top of V_eff (an unstable circle) within the interval the walk
 * found: E - V_eff touches 0 there without changing sign, so the walk went
 * through it (or stopped at it as at a turning point).  The motion creeps
 * towards that circle for ever (Desloge ch. 58 P10 b: r = b tanh(phi/sqrt 2)
 * inside it, b coth(phi/sqrt 2) outside), winding without end. */
static void asymptotic(qd__orb_env *env, double xs, qd_orbit_result *r) {
    double lo = r->lo, hi = r->hi, near = 1e-6 * env->scale;
    bool found = false;
    for (size_t k = 0; k < r->ncircle; k++) {
        const qd_orbit_circle *c = &r->circle[k];
        if (c->stable == 1 || !same_energy(env->E, c->energy) || c->x == xs ||
            c->x < r->lo - near || c->x > r->hi + near)
            continue;
        found = true;
        if (c->x < xs)
            lo = fmax(lo, c->x);
        else
            hi = fmin(hi, c->x);
    }
    if (!found)
        return;
    size_t n = 0;
    for (size_t k = 0; k < r->nturn; k++)
        if (r->turn[k] > lo + near && r->turn[k] < hi - near)
            r->turn[n++] = r->turn[k];
    r->nturn = n;
    r->lo = lo;
    r->hi = hi;
    r->kind = QD_ORBIT_ASYMPTOTIC;
    double at = xs < lo + near ? lo : hi; /* the circle it creeps towards */
    const double *o = qd__orb_at(env, isfinite(at) ? at : lo);
    for (size_t i = 0; i < r->nign; i++) {
        double rate = o[QD__ORB_RATE + i];
        r->advance[i] = rate == 0 ? 0 : copysign(INFINITY, rate);
    }
}

/* da nearer x0 than dc (a tie to the earlier, so that one of -pi, pi stays). */
static bool nearer(double da, double dc, bool earlier, double scale) {
    return fabs(da - dc) <= 1e-12 * scale ? earlier : da < dc;
}

/* Revolutions about the origin per radial period, the precession's
 * reference: one either way when the ignored rate keeps its sign (Kepler's
 * ellipse), else the nearest whole number of turns, as for an orbit that
 * does not enclose the origin (a cyclotron circle off the centre: advance
 * 0, which is its own closed figure, not a precession of -2 pi; audit,
 * issue 33). */
static double revolutions(qd__orb_env *env, const qd_orbit_result *r, size_t i) {
    double adv = r->advance[i];
    if (r->kind == QD_ORBIT_BOUND && r->nturn == 2) {
        double a = qd__orb_at(env, r->turn[0])[QD__ORB_RATE + i];
        double b = qd__orb_at(env, r->turn[1])[QD__ORB_RATE + i];
        if (!(a * b > 0))
            return nearbyint(adv / (2 * PI));
    }
    return adv < 0 ? -1 : 1;
}

/* A periodic V_eff (an angle coordinate) repeats its circles every 2 pi:
 * those 2 pi k from one nearer x0, at the same energy and curvature, are the
 * same motion and are dropped. */
static void merge_periodic(qd__orb_env *env, double x0, qd_orbit_result *r) {
    size_t n = 0;
    for (size_t i = 0; i < r->ncircle; i++) {
        qd_orbit_circle *c = &r->circle[i];
        bool dup = false;
        for (size_t j = 0; j < r->ncircle && !dup; j++) {
            const qd_orbit_circle *d = &r->circle[j];
            double turns = (c->x - d->x) / (2 * PI), k = round(turns);
            dup = j != i && k != 0 && fabs(turns - k) <= 1e-9 * fmax(1, fabs(k)) &&
                  nearer(fabs(d->x - x0), fabs(c->x - x0), j < i, env->scale) &&
                  same_energy(c->energy, d->energy) &&
                  same_energy(c->curvature, d->curvature);
        }
        if (dup) {
            qd__free(c->apsidal);
            continue;
        }
        r->circle[n++] = *c;
    }
    r->ncircle = n;
}

static qd_status analyse(qd_ctx *ctx, qd__orb_env *env, double x0, double xd0, double c0,
                         bool energy_given, qd_orbit_result *r) {
    qd_status st = QD_OK;
    double xs = x0;
    if (energy_given && !(qd__orb_gap(env, x0) >= 0) && (st = allowed_start(ctx, env, &xs)))
        return st;
    if ((st = circles(ctx, env, xs, r)))
        return st;
    if (circular_at(env, xs))
        circular_limits(env, xs, r);
    else
        classify(env, xs, r);
    if (r->kind != QD_ORBIT_CIRCULAR)
        asymptotic(env, xs, r);
    if (r->kind == QD_ORBIT_BOUND && !env->o->general && near_circle(env, r))
        ; /* the expansion about the circle is the more accurate */
    else if (r->kind != QD_ORBIT_CIRCULAR && r->kind != QD_ORBIT_ASYMPTOTIC)
        st = qd__orb_quadratures(ctx, env, r);
    for (size_t i = 0; i < r->nign && (r->kind == QD_ORBIT_BOUND || r->kind == QD_ORBIT_CIRCULAR);
         i++) {
        r->apsidal[i] = fabs(r->advance[i]) / 2; /* an angle between apsides, either way round */
        r->precession[i] = r->advance[i] - 2 * PI * revolutions(env, r, i);
        if (fabs(r->precession[i]) <= 8 * fmax(r->quad_error, 1e-13) * fabs(r->advance[i]))
            r->precession[i] = 0; /* closed to within the quadrature's error */
    }
    merge_periodic(env, xs, r);
    if (st == QD_OK && env->o->kepler) {
        const double *o = qd__orb_at(env, xs);
        double w = 2 * (env->E - o[QD__ORB_V]) / o[QD__ORB_M];
        double xd = (xd0 < 0 ? -1 : 1) * sqrt(w > 0 ? w : 0);
        qd__orb_conic(env, xs, xd, c0, r);
    }
    return st;
}

qd_status qd_orbit_solve(qd_ctx *ctx, const qd_orbit *o, size_t n, const qd_expr *const *syms,
                         const double *vals, const double *energy, qd_orbit_result *r) {
    QD_ARGS_CTX(ctx, ctx && o && (n == 0 || syms) && (n == 0 || vals) && r);
    qd__orb_env env = {0};
    qd_status st = alloc_result(ctx, o->routh->nign, r);
    if (st == QD_OK)
        st = momenta(ctx, o, n, syms, vals, r->momenta);
    if (st == QD_OK)
        st = qd__orb_env_init(ctx, o, n, syms, vals, r->momenta, &env);
    if (st != QD_OK) {
        qd_orbit_result_free(r);
        return st;
    }
    double x0 = value_of(o->x, n, syms, vals, NULL), xd0 = value_of(o->xd, n, syms, vals, NULL);
    double c0 = value_of(o->routh->ign[0], n, syms, vals, NULL);
    const double *out = qd__orb_at(&env, x0);
    r->x0 = x0;
    if (!isfinite(out[QD__ORB_V]) || !isfinite(out[QD__ORB_M])) {
        qd_ctx_error(ctx, QD_ERR_ARG, "V_eff is not defined at %s = %.12g: choose another state",
                     qd_expr_name(o->x), x0);
        st = QD_ERR_ARG;
    } else {
        env.E = r->energy = energy             ? *energy
                            : o->general ? qd__orb_at2(&env, x0, xd0)[QD__ORB_H]
                                         : out[QD__ORB_V] + out[QD__ORB_M] * xd0 * xd0 / 2;
        env.scale = x0 != 0 ? fabs(x0) : 1;
        env.sing0 = singular_at_zero(&env);
        st = analyse(ctx, &env, x0, xd0, c0, energy != NULL, r);
    }
    qd__orb_env_free(&env);
    if (st != QD_OK)
        qd_orbit_result_free(r);
    return st;
}

qd_status qd_orbit_period(qd_ctx *ctx, const qd_orbit *o, const qd_orbit_result *r,
                          double *period) {
    QD_ARGS_CTX(ctx, ctx && o && r && period);
    const char *x = qd_expr_name(o->x);
    if (r->kind == QD_ORBIT_UNBOUND) {
        if (r->nturn == 1)
            qd_ctx_error(ctx, QD_ERR_ARG,
                         "the orbit is unbound: one turning point, %s = %.12g; no period", x,
                         r->turn[0]);
        else
            qd_ctx_error(ctx, QD_ERR_ARG, "the orbit is unbound: no turning point; no period");
        return QD_ERR_ARG;
    }
    if (r->kind == QD_ORBIT_CAPTURE || !isfinite(r->period)) {
        qd_ctx_error(ctx, QD_ERR_ARG,
                     "the orbit has no period: it %s",
                     r->kind == QD_ORBIT_CAPTURE      ? "falls into the singular point of V_eff"
                     : r->kind == QD_ORBIT_ASYMPTOTIC ? "creeps towards an unstable circle"
                                                      : "is an unstable circle");
        return QD_ERR_ARG;
    }
    *period = r->period;
    return QD_OK;
}
