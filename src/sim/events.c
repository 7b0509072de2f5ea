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
static qd_status g_value(qd__run *r, size_t k, double t, const double *y, double *gk) {
    qd_sim *s = r->s;
    if (k >= qd__fev0(s))
        return qd__fric_event(r, k - qd__fev0(s), t, y, gk);
    qd__aux_eval(s, t, y, qd__second(s, y, r->qd));
    *gk = s->aux_out[qd__aux_ev(s) + k];
    return QD_OK;
}

/* g_k at the dense state at t. */
static qd_status g_dense(qd__run *r, size_t k, double t, double *gk) {
    qd_status st = qd__run_dense(r, t, r->ytmp);
    if (st == QD_OK)
        st = qd__run_velocity(r, t, r->ytmp);
    return st == QD_OK ? g_value(r, k, t, r->ytmp, gk) : st;
}

/* g_k after the method's own step of size tau from (told, yold); state in y. */
static qd_status g_redo(qd__run *r, size_t k, double tau, double *y, double *gk) {
    qd__integ *it = r->it;
    qd_status st = it->ops->redo(it, tau, y);
    if (st == QD_OK)
        st = qd__run_velocity(r, it->told + tau, y);
    return st == QD_OK ? g_value(r, k, it->told + tau, y, gk) : st;
}

/* Illinois: regula falsi with the stale end's value halved. */
static qd_status root_dense(qd__run *r, size_t k, double a, double ga, double b, double gb,
                            double *root) {
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
    return QD_OK;
}

/* Secant on the method's step; keeps the dense root when it does not settle. */
static qd_status polish(qd__run *r, size_t k, double troot, double *y) {
    qd__integ *it = r->it;
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
static qd_status positive_sample(qd__run *r, size_t k, double *a, double *ga) {
    qd__integ *it = r->it;
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
static qd_status impact_bracket(qd__run *r, size_t k, double *a, double *ga, bool *closed) {
    qd__integ *it = r->it;
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

/* Locate event k in the step; r->ev_hit[k] when it happened. */
static qd_status locate_one(qd__run *r, size_t k) {
    qd_sim *s = r->s;
    qd__integ *it = r->it;
    bool gap = k >= s->nev && k < qd__fev0(s), at_start = false;
    double a = it->told, ga = r->gold[k], gb = r->gnew[k];
    r->ev_hit[k] = false;
    if (gap) {
        /* a contact closes (from above); it never opens as an event */
        if (!(gb < 0 || (gb == 0 && ga > 0)))
            return QD_OK;
        qd_status st = impact_bracket(r, k, &a, &ga, &at_start);
        if (st != QD_OK || (!(ga > 0) && !at_start))
            return st;
    } else if (ga == 0 || !((ga > 0) != (gb > 0) || gb == 0)) {
        return QD_OK;
    } else if (k >= qd__fev0(s) && !qd__fric_crossing(s, k - qd__fev0(s), ga)) {
        return QD_OK;
    }
    double root = at_start ? a : it->t;
    qd_status st = gb == 0 || at_start ? QD_OK : root_dense(r, k, a, ga, it->t, gb, &root);
    double *y = r->ev_y + k * it->dim;
    r->ev_t[k] = root;
    if (st == QD_OK && it->ops->redo && root > it->told && root < it->t)
        st = polish(r, k, root, y);
    else if (st == QD_OK)
        st = root == it->told ? (memcpy(y, it->yold, it->dim * sizeof *y), QD_OK)
                              : qd__run_dense(r, root, y);
    if (st == QD_OK)
        st = qd__run_events_at(r, r->ev_t[k], y, NULL, r->ev_ok);
    if (st != QD_OK)
        return st;
    /* a contact is struck only while closing: its rate below 0 */
    r->ev_hit[k] = gap ? qd__impact_rate(r, k - s->nev, r->ev_t[k], y) < 0 : r->ev_ok[k];
    return QD_OK;
}

qd_status qd__events_locate(qd__run *r) {
    if (r->imp)
        r->imp->unresolved = r->s->nimp;
    for (size_t k = 0; k < qd__nev_all(r->s); k++) {
        qd_status st = locate_one(r, k);
        if (st != QD_OK)
            return st;
    }
    return QD_OK;
}
