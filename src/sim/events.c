/*
 * src/sim/events.c - zero crossings of event functions g(q, q', t) inside
 * a step, located to round-off.
 *
 * A sign change of g between the ends of an accepted step brackets a root;
 * the root of g along the dense output (the method's own interpolant, or a
 * cubic Hermite from the end slopes) is found by the Illinois variant of
 * regula falsi down to adjacent doubles, then refined by secant iteration
 * on the method's own step from the step's start, so that the event state is
 * the discrete solution at that time (not the interpolant's approximation).
 * The guards (theta1' > 0) are tested at the root.  A contact's gap
 * (impact.c) is an event that only closes: from above 0 to below, struck
 * when its rate is negative there.
 */
#include "simint.h"

#include <math.h>
#include <string.h>

#define MAX_ROOT_ITER 200
#define MAX_SECANT 10

/* g_k at (t, y), q' in r->qd: an expression of aux, or a friction
 * contact's switching function (friction.c). */
static qd_status g_value(qd__sim_run *r, size_t k, double t, const double *y, double *gk) {
    qd_sim *s = r->s;
    if (k >= qd__sim_fev0(s))
        return qd__sim_fric_event(r, k - qd__sim_fev0(s), t, y, gk);
    *gk = qd__sim_ev_eval(s, t, y, qd__sim_second(s, y, r->qd))[k];
    return QD_OK;
}

/* g_k at the dense state at t. */
static qd_status g_dense(qd__sim_run *r, size_t k, double t, double *gk) {
    qd_status st = qd__sim_run_dense(r, t, r->ytmp);
    if (st == QD_OK)
        st = qd__sim_run_velocity(r, t, r->ytmp);
    return st == QD_OK ? g_value(r, k, t, r->ytmp, gk) : st;
}

/* g_k after the method's own step of size tau from (told, yold); state in y. */
static qd_status g_redo(qd__sim_run *r, size_t k, double tau, double *y, double *gk) {
    qd__sim_integ *it = r->it;
    qd_status st = it->ops->redo(it, tau, y);
    if (st == QD_OK)
        st = qd__sim_run_velocity(r, it->told + tau, y);
    return st == QD_OK ? g_value(r, k, it->told + tau, y, gk) : st;
}

/* Illinois: regula falsi with the stale end's value halved. */
static qd_status root_dense(qd__sim_run *r, size_t k, double a, double ga, double b, double gb,
                            double *root, double *after) {
    int side = 0;
    for (int i = 0; i < MAX_ROOT_ITER; i++) {
        if (nextafter(a, b) == b || ga == 0 || gb == 0)
            break;
        double c = (a * gb - b * ga) / (gb - ga);
        if (!(c > fmin(a, b) && c < fmax(a, b)))
            c = 0.5 * (a + b);
        double gc;
        qd_status st = g_dense(r, k, c, &gc);
        if (st != QD_OK)
            return st;
        if ((gc > 0) == (gb > 0) && gc != 0) {
            b = c;
            gb = gc;
            if (side == -1)
                ga *= 0.5;
            side = -1;
        } else {
            a = c;
            ga = gc;
            if (side == 1)
                gb *= 0.5;
            side = 1;
        }
    }
    *root = fabs(ga) <= fabs(gb) ? a : b;
    *after = b; /* b keeps the sign g has after the crossing */
    return QD_OK;
}

/* Secant on the method's step; keeps the dense root when it does not settle. */
static qd_status polish(qd__sim_run *r, size_t k, double troot, double *y) {
    qd__sim_integ *it = r->it;
    double h = it->t - it->told, t0 = troot - it->told;
    double t1 = t0 + h * 1e-7 * (t0 < 0.5 * h ? 1 : -1), g0, g1;
    qd_status st = g_redo(r, k, t0, y, &g0);
    if (st == QD_OK)
        st = g_redo(r, k, t1, y, &g1);
    for (int i = 0; st == QD_OK && i < MAX_SECANT && g1 != g0 && g1 != 0; i++) {
        double t2 = t1 - g1 * (t1 - t0) / (g1 - g0);
        if (!(t2 > -0.01 * h && t2 < 1.01 * h))
            break;
        t0 = t1;
        g0 = g1;
        t1 = t2;
        st = g_redo(r, k, t1, y, &g1);
        if (fabs(t1 - t0) <= 2e-16 * fabs(it->told + t1))
            break;
    }
    if (st != QD_OK)
        return st;
    r->ev_t[k] = it->told + t1;
    return g_redo(r, k, t1, y, &g1);
}

/* The last of 16 samples of the step where contact i's gap is positive
 * (NAN when none is): the start of the bracket of a landing that follows
 * a rebound inside the same step. */
static qd_status positive_sample(qd__sim_run *r, size_t k, double *a, double *ga) {
    qd__sim_integ *it = r->it;
    *a = NAN;
    for (int j = 15; j >= 1; j--) {
        double t = it->told + (it->t - it->told) * j / 16, g;
        qd_status st = g_dense(r, k, t, &g);
        if (st != QD_OK)
            return st;
        if (g > 0) {
            *a = t;
            *ga = g;
            return QD_OK;
        }
    }
    return QD_OK;
}

/* Where contact i (event k) closes in the step: from above 0 to not above
 * it, or (its gap not positive at the start: just after its impact, or
 * touching at t0, or left at 0 by another contact's impact at the same
 * instant) from the last positive sample; a gap not struck at the start
 * with no positive sample closes there (*closed).  r->imp->unresolved = i
 * when the step follows its impact and no sample is positive: the rebound
 * and the landing both fell inside the step. */
static qd_status impact_bracket(qd__sim_run *r, size_t k, double *a, double *ga, bool *closed) {
    qd__sim_integ *it = r->it;
    size_t i = k - r->s->nev;
    *closed = false;
    if (*ga > 0)
        return QD_OK;
    qd_status st = positive_sample(r, k, a, ga);
    if (st != QD_OK || !isnan(*a))
        return st;
    *a = it->told;
    if (!r->imp->fresh[i]) {
        *closed = true;
        return QD_OK;
    }
    r->imp->unresolved = i;
    return QD_OK;
}

/* ---- crossings inside a step --------------------------------------------------
 *
 * A sign change between the step's ends is not enough: a step of
 * force-free flight can span both crossings of a grazing pass.  So g_k is
 * sampled on the dense output at NSAMPLE equal intervals (shared by every
 * event of the step), and each g_k is searched in time order for the first
 * interval with a sign change, or else for a dip: an interior minimum of
 * |g_k| in the samples (or a turn inside an end interval, seen by a probe
 * DELTA h from the end), where g_k is minimized (parabolic steps, golden
 * section as the safeguard) until it changes sign or the bracket is below
 * DELTA h.  This finds every crossing of the interpolant's g_k when g_k
 * turns at most once between samples and its two crossings lie more than
 * about DELTA h apart.  When some g_k turns at two consecutive samples the
 * step is sampled again twice as finely, up to NSAMPLE_MAX intervals; if it
 * still does, the step is counted as unresolved (qd_sim_stats). */
#define NSAMPLE 8
#define NSAMPLE_MAX QD__EV_SAMPLES_MAX
#define DELTA 1e-7

static double sample_t(const qd__sim_run *r, size_t j) {
    const qd__sim_integ *it = r->it;
    return j == 0 ? it->told : j == r->nsmp ? it->t
                             : it->told + (it->t - it->told) * (double)j / (double)r->nsmp;
}

/* A change of g from a to b that is more than round-off of their size. */
static int direction(double a, double b) {
    double d = b - a;
    if (!(fabs(d) > 1e-12 * fmax(fabs(a), fabs(b))))
        return 0;
    return d > 0 ? 1 : -1;
}

/* g_k turns (by more than a thousandth of its range over the step) at two
 * consecutive samples, or at more than a quarter of them: it oscillates
 * faster than the samples resolve. */
static bool turns_fast(const qd__sim_run *r, size_t k) {
    size_t ne = qd__sim_nev_all(r->s), n = r->nsmp;
    const double *v = r->smp;
    double lo = v[k], hi = v[k];
    for (size_t j = 1; j <= n; j++) {
        lo = fmin(lo, v[j * ne + k]);
        hi = fmax(hi, v[j * ne + k]);
    }
    double tiny = 1e-3 * (hi - lo);
    if (!(hi - lo > 1e-9 * fmax(fabs(lo), fabs(hi))))
        return false;
    int turn_prev = 0;
    size_t turns = 0;
    for (size_t j = 1; j < n; j++) {
        double d0 = v[j * ne + k] - v[(j - 1) * ne + k], d1 = v[(j + 1) * ne + k] - v[j * ne + k];
        int turn = fabs(d0) > tiny && fabs(d1) > tiny && (d0 > 0) != (d1 > 0);
        if (turn && turn_prev)
            return true;
        turns += (size_t)turn;
        turn_prev = turn;
    }
    return turns > n / 4;
}

/* How much faster g_k changes at the first sample (probe gp, DELTA h
 * after it) than its fastest change between the samples: above 100, g_k
 * varies on a scale finer than the samples (an aliased oscillation looks
 * smooth at the samples; its rate does not). */
static double rate_ratio(const qd__sim_run *r, size_t k, double gp) {
    size_t ne = qd__sim_nev_all(r->s), n = r->nsmp;
    const double *v = r->smp;
    double secant = 0, size = 0;
    for (size_t j = 0; j < n; j++) {
        secant = fmax(secant, fabs(v[(j + 1) * ne + k] - v[j * ne + k]));
        size = fmax(size, fabs(v[j * ne + k]));
    }
    double change = fabs(gp - v[ne + k]), expect = secant * DELTA * (double)n;
    if (!(change > 1e-12 * fmax(size, fabs(gp))))
        return 0;
    return expect > 0 ? change / expect : INFINITY;
}

/* The step's unresolved event k: counted, with the spacing it had. */
static void unresolved_step(qd__sim_run *r, size_t k) {
    qd__sim_integ *it = r->it;
    if (!r->fast_steps++) {
        r->fast_t = it->told;
        r->fast_event = k;
    }
    r->fast_spacing = fmax(r->fast_spacing, (it->t - it->told) / (double)r->nsmp);
}

/* Every event function at the samples of the step (r->smp, r->nsmp), and a
 * probe of their rate just after the first sample (gp). */
static qd_status sample_step(qd__sim_run *r) {
    qd__sim_integ *it = r->it;
    size_t ne = qd__sim_nev_all(r->s);
    double *gp = r->smp + (NSAMPLE_MAX + 1) * ne + ne; /* after ev_after */
    for (size_t n = NSAMPLE;; n *= 2) {
        r->nsmp = n;
        memcpy(r->smp, r->gold, ne * sizeof *r->smp);
        memcpy(r->smp + n * ne, r->gnew, ne * sizeof *r->smp);
        for (size_t j = 1; j <= n; j++) {
            double t = j < n ? sample_t(r, j) : sample_t(r, 1) + DELTA * (it->t - it->told);
            double *out = j < n ? r->smp + j * ne : gp;
            qd_status st = qd__sim_run_dense(r, t, r->ytmp);
            if (st == QD_OK)
                st = qd__sim_run_events_at(r, t, r->ytmp, out, NULL);
            if (st != QD_OK)
                return st;
        }
        size_t fast = ne, need = n;
        for (size_t k = 0; k < ne; k++) {
            double rho = rate_ratio(r, k, gp[k]);
            if (rho > 100 || turns_fast(r, k)) {
                fast = fast == ne ? k : fast;
                /* samples rho / 10 times finer would see its rate */
                need = rho > 100 ? (rho < 1e6 ? (size_t)(n * rho / 10) : (size_t)-1) : 2 * n;
            }
        }
        if (fast == ne)
            return QD_OK;
        if (n == NSAMPLE_MAX || need > NSAMPLE_MAX) {
            unresolved_step(r, fast);
            return QD_OK;
        }
        while (2 * n < need && 2 * n < NSAMPLE_MAX)
            n *= 2;
    }
}

/* A bracket [lo, hi] of a sign change of g_k. */
typedef struct bracket {
    double lo, glo, hi, ghi;
    bool found;
} bracket;

/* Minimize f = sg g_k over a < b < c (f(b) below f(a), f(c)) until f is
 * below 0 somewhere (br: from the point before to it) or c - a < tol. */
static qd_status dip(qd__sim_run *r, size_t k, double sg, double a, double fa, double b,
                     double fb, double c, double fc, bracket *br) {
    double tol = DELTA * (r->it->t - r->it->told), w1 = c - a, w2 = c - a;
    for (int i = 0; i < MAX_ROOT_ITER && c - a > tol; i++) {
        double p = (b - a) * (fb - fc), q = (b - c) * (fb - fa);
        double u = q != p ? b - 0.5 * ((b - a) * p - (b - c) * q) / (p - q) : NAN;
        bool golden = !(u > a + 0.5 * tol && u < c - 0.5 * tol) || fabs(u - b) < 0.5 * tol ||
                      c - a > 0.5 * w2;
        if (golden)
            u = b - a > c - b ? b - 0.381966 * (b - a) : b + 0.381966 * (c - b);
        w2 = w1;
        w1 = c - a;
        double fu;
        qd_status st = g_dense(r, k, u, &fu);
        if (st != QD_OK)
            return st;
        fu *= sg;
        if (fu <= 0) {
            double lo = u < b ? a : b, flo = u < b ? fa : fb;
            *br = (bracket){lo, sg * flo, u, sg * fu, true};
            return QD_OK;
        }
        if (fu < fb) {
            if (u < b) {
                c = b;
                fc = fb;
            } else {
                a = b;
                fa = fb;
            }
            b = u;
            fb = fu;
        } else if (u < b) {
            a = u;
            fa = fu;
        } else {
            c = u;
            fc = fu;
        }
    }
    return QD_OK;
}

/* The first sign change of g_k after (a, ga), ga != 0, over the samples j0
 * .. nsmp of the step (all after a). */
static qd_status search(qd__sim_run *r, size_t k, double a, double ga, size_t j0, bracket *br) {
    size_t ne = qd__sim_nev_all(r->s), m = r->nsmp - j0 + 1;
    double sg = ga > 0 ? 1 : -1, h = r->it->t - r->it->told;
    double tl = a, vl = ga, tlow = a, vlow = ga;
    int prev = 0;
    br->found = false;
    for (size_t i = 0; i < m; i++) {
        double ti = i ? sample_t(r, j0 + i - 1) : a, vi = i ? r->smp[(j0 + i - 1) * ne + k] : ga;
        double tn = sample_t(r, j0 + i), vn = r->smp[(j0 + i) * ne + k];
        if ((vi > 0) != (vn > 0) || vn == 0) {
            *br = (bracket){ti, vi, tn, vn, true};
            return QD_OK;
        }
        int dir = direction(sg * vi, sg * vn);
        qd_status st = QD_OK;
        if (i == 0 && dir > 0) {
            /* rising from the start: a turn inside the first interval? */
            double tp = ti + DELTA * h, gp;
            if ((st = g_dense(r, k, tp, &gp)) == QD_OK && direction(sg * vi, sg * gp) < 0)
                st = dip(r, k, sg, ti, sg * vi, tp, sg * gp, tn, sg * vn, br);
        } else if (dir > 0 && prev < 0) {
            st = dip(r, k, sg, tl, sg * vl, tlow, sg * vlow, tn, sg * vn, br);
        } else if (i == m - 1 && dir < 0) {
            /* falling into the end: a turn inside the last interval? */
            double tp = tn - DELTA * h, gp;
            if ((st = g_dense(r, k, tp, &gp)) == QD_OK && direction(sg * vn, sg * gp) < 0)
                st = dip(r, k, sg, ti, sg * vi, tp, sg * gp, tn, sg * vn, br);
        }
        if (st != QD_OK || br->found)
            return st;
        if (dir < 0) {
            tl = ti;
            vl = vi;
            tlow = tn;
            vlow = vn;
        }
        if (dir)
            prev = dir;
    }
    return QD_OK;
}

/* The crossing of event k in br located: the root on the dense output,
 * polished on the method's own step; the state at it in ev_y, its time in
 * ev_t, the far side of the dense bracket in ev_after. */
static qd_status locate_root(qd__sim_run *r, size_t k, const bracket *br, bool at_start) {
    qd__sim_integ *it = r->it;
    double root = at_start ? br->lo : br->hi, after = root;
    qd_status st = br->ghi == 0 || at_start
                       ? QD_OK : root_dense(r, k, br->lo, br->glo, br->hi, br->ghi, &root, &after);
    double *y = r->ev_y + k * it->dim;
    r->ev_t[k] = root;
    r->ev_after[k] = after;
    if (st == QD_OK && it->ops->redo && root > it->told && root < it->t)
        st = polish(r, k, root, y);
    else if (st == QD_OK)
        st = root == it->told ? (memcpy(y, it->yold, it->dim * sizeof *y), QD_OK)
                              : qd__sim_run_dense(r, root, y);
    if (st == QD_OK)
        st = qd__sim_run_events_at(r, r->ev_t[k], y, NULL, r->ev_ok);
    return st;
}

/* The first crossing of event k (not a contact's gap) after time a in the
 * step whose guards hold; r->ev_hit[k] when there is one. */
static qd_status next_crossing(qd__sim_run *r, size_t k, double a, double ga) {
    qd__sim_integ *it = r->it;
    size_t j0 = 1;
    r->ev_hit[k] = false;
    while (a < it->t) {
        while (j0 < r->nsmp && sample_t(r, j0) <= a)
            j0++;
        if (ga == 0) {
            /* at a root already (the last one, or the step's start): a
             * little further, else from the next sample */
            double h = it->t - it->told, b = fmin(a + DELTA * h, it->t), gb;
            qd_status st = g_dense(r, k, b, &gb);
            if (st != QD_OK)
                return st;
            if (gb == 0) {
                b = sample_t(r, j0);
                gb = r->smp[j0 * qd__sim_nev_all(r->s) + k];
            }
            if (b >= it->t)
                return QD_OK;
            a = b;
            ga = gb;
            continue;
        }
        bracket br;
        qd_status st = search(r, k, a, ga, j0, &br);
        if (st != QD_OK || !br.found)
            return st;
        if (k >= qd__sim_fev0(r->s) && !qd__sim_fric_crossing(r->s, k - qd__sim_fev0(r->s), br.glo)) {
            a = br.hi;
            ga = br.ghi;
            continue;
        }
        if ((st = locate_root(r, k, &br, false)) != QD_OK)
            return st;
        if (r->ev_ok[k]) {
            r->ev_hit[k] = true;
            return QD_OK;
        }
        /* a guard fails there: on to the next crossing */
        a = r->ev_after[k];
        if ((st = g_dense(r, k, a, &ga)) != QD_OK)
            return st;
    }
    return QD_OK;
}

qd_status qd__sim_events_next(qd__sim_run *r, size_t k) {
    double a = r->ev_after[k], ga;
    if (!(a < r->it->t)) {
        r->ev_hit[k] = false;
        return QD_OK;
    }
    qd_status st = g_dense(r, k, a, &ga);
    return st == QD_OK ? next_crossing(r, k, a, ga) : st;
}

/* Locate event k in the step; r->ev_hit[k] when it happened. */
static qd_status locate_one(qd__sim_run *r, size_t k) {
    qd_sim *s = r->s;
    qd__sim_integ *it = r->it;
    bool gap = k >= s->nev && k < qd__sim_fev0(s), at_start = false;
    double a = it->told, ga = r->gold[k], gb = r->gnew[k];
    r->ev_hit[k] = false;
    if (!gap)
        return k >= qd__sim_fev0(s) && ga == 0 ? QD_OK : next_crossing(r, k, a, ga);
    bracket br = {a, ga, it->t, gb, false};
    if (ga > 0) {
        /* a contact closes (from above), perhaps and opens again in the step */
        qd_status st = search(r, k, a, ga, 1, &br);
        if (st != QD_OK || !br.found)
            return st;
    } else {
        /* just after its impact, or touching at the start */
        if (!(gb < 0 || (gb == 0 && ga > 0)))
            return QD_OK;
        qd_status st = impact_bracket(r, k, &br.lo, &br.glo, &at_start);
        if (st != QD_OK || (!(br.glo > 0) && !at_start))
            return st;
    }
    qd_status st = locate_root(r, k, &br, at_start);
    if (st != QD_OK)
        return st;
    /* a contact is struck only while closing: its rate below 0 */
    r->ev_hit[k] = qd__sim_impact_rate(r, k - s->nev, r->ev_t[k], r->ev_y + k * it->dim) < 0;
    return QD_OK;
}

qd_status qd__sim_events_locate(qd__sim_run *r) {
    if (r->imp)
        r->imp->unresolved = r->s->nimp;
    qd_status st0 = sample_step(r);
    if (st0 != QD_OK)
        return st0;
    for (size_t k = 0; k < qd__sim_nev_all(r->s); k++) {
        qd_status st = locate_one(r, k);
        if (st != QD_OK)
            return st;
    }
    return QD_OK;
}
