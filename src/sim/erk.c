/*
 * src/sim/erk.c - the engine of the explicit Runge-Kutta pairs: the step
 * size controller, the FSAL stage and the first step (Hairer, Norsett &
 * Wanner, Solving ODEs I, sec. II.4); dopri5.c and dop853.c hold their
 * error estimates and dense output, src/num their tableaux and the stage
 * loop (qd__num_rk_stages, shared with src/path's RK4).  The
 * controller is that of Hairer's dopri5.f/dop853.f: factors bounded by
 * fac1, fac2, safety 0.9, and for dopri5 the Lund stabilization (a PI
 * controller, sec. IV.2) with beta = 0.04, which keeps the step sequence
 * smooth and rejections rare.
 */
#include "simint.h"
#include "../base/mem.h"
#include "num/num.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Consecutive stage failures retried with a shorter step (10^-8 of it by
 * the last) before the failure is reported. */
#define MAX_STAGE_FAILURES 8

typedef struct erk {
    const qd__sim_erk *tab;
    double **K, **Kr;     /* stages of the last step; of a redo */
    double *ytmp, *ynew, *coef;
    double *mem;          /* everything above (K rows are swapped) */
    bool dense_ready;
    double facold;        /* error of the last accepted step (>= 1e-4) */
    bool reject;          /* the last attempt was rejected */
} erk;

double qd__sim_err_rms(const qd__sim_integ *it, const double *err, const double *ynew) {
    double sum = 0;
    for (size_t i = 0; i < it->dim; i++) {
        double sc = it->atol + it->rtol * fmax(fabs(it->y[i]), fabs(ynew[i]));
        sum += (err[i] / sc) * (err[i] / sc);
    }
    return sqrt(sum / (double)it->dim);
}

qd_status qd__sim_underflow(qd__sim_integ *it, double h) {
    qd__sim_stop(it->s, QD_STOP_STEP_UNDERFLOW, it->t, h);
    qd_ctx_error(it->s->ctx, QD_ERR_NUMERIC,
                 "step size underflow at t = %.17g (h = %.3g): the solution is not smooth "
                 "there or the tolerance is below round-off", it->t, h);
    return QD_ERR_NUMERIC;
}

static double rms(const qd__sim_integ *it, const double *v) {
    double sum = 0;
    for (size_t i = 0; i < it->dim; i++) {
        double sc = it->atol + it->rtol * fabs(it->y[i]);
        sum += (v[i] / sc) * (v[i] / sc);
    }
    return sqrt(sum / (double)it->dim);
}

/* Hairer's starting step: h0 from |y| / |f|, then from an estimate of the
 * second derivative. */
static qd_status initial_step(qd__sim_integ *it, erk *r) {
    size_t d = it->dim;
    double *f0 = r->K[0], *y1 = r->ytmp, *f1 = r->ynew;
    double d0 = rms(it, it->y), d1 = rms(it, f0);
    double h0 = d0 < 1e-5 || d1 < 1e-5 ? 1e-6 : 0.01 * d0 / d1;
    h0 = fmin(h0, fabs(it->tend - it->t));
    for (size_t i = 0; i < d; i++)
        y1[i] = it->y[i] + h0 * f0[i];
    qd_status st = qd__sim_rhs(it->s, it->form, it->t + h0, y1, f1);
    if (st != QD_OK && st != QD_ERR_NOMEM && qd__ctx_recover(it->s->ctx)) {
        /* the Euler step left the equations' domain: start with it shorter
         * and let the controller find the rest (failures there are retried) */
        it->h = h0 / 10;
        return QD_OK;
    }
    if (st != QD_OK)
        return st;
    for (size_t i = 0; i < d; i++)
        y1[i] = (f1[i] - f0[i]);
    double d2 = rms(it, y1) / h0, dm = fmax(d1, d2);
    double h1 = dm <= 1e-15 ? fmax(1e-6, h0 * 1e-3) : pow(0.01 / dm, 1.0 / (r->tab->order + 1));
    it->h = fmin(100 * h0, h1);
    return QD_OK;
}

qd_status qd__sim_erk_init(qd__sim_integ *it, const qd__sim_erk *tab) {
    size_t d = it->dim, rows = (size_t)(tab->rk->stages + 1 + tab->nextra);
    erk *r = qd__calloc(it->s->ctx, 1, sizeof *r);
    if (!r)
        return QD_ERR_NOMEM;
    it->priv = r;
    r->tab = tab;
    r->facold = 1e-4;
    r->K = qd__calloc(it->s->ctx, 2 * rows, sizeof *r->K);
    double *mem = qd__malloc(it->s->ctx, (2 * rows * d + 2 * d + (size_t)tab->ndense * d + 1) * sizeof *mem);
    if (!r->K || !mem) {
        qd__free(mem);
        return QD_ERR_NOMEM;
    }
    r->mem = mem;
    r->Kr = r->K + rows;
    for (size_t i = 0; i < 2 * rows; i++)
        r->K[i] = mem + i * d;
    r->ytmp = mem + 2 * rows * d;
    r->ynew = r->ytmp + d;
    r->coef = r->ynew + d;
    qd_status st = qd__sim_rhs(it->s, it->form, it->t, it->y, r->K[0]);
    it->y_changed = false;
    if (st == QD_OK && !it->fixed && !(it->h > 0))
        st = initial_step(it, r);
    return st;
}

void qd__sim_erk_free(qd__sim_integ *it) {
    erk *r = it->priv;
    if (!r)
        return;
    qd__free(r->mem);
    qd__free(r->K);
    qd__free(r);
    it->priv = NULL;
}

/* The right-hand side as num's ODE callback, its status kept: a failing
 * stage's (and its message in the context) is the step's. */
typedef struct erk_rhs {
    qd__sim_integ *it;
    qd_status st;
} erk_rhs;

static bool rhs(void *data, double t, const double *y, double *dy) {
    erk_rhs *e = data;
    e->st = qd__sim_rhs(e->it->s, e->it->form, t, y, dy);
    return e->st == QD_OK;
}

/* The stages from (t0, y0) with K[0] = f(t0, y0) given; y1 and K[s] =
 * f(t0 + h, y1).  num's stage loop takes them (zero tableau entries
 * skipped), as it does RK4's for src/path. */
static qd_status stages(qd__sim_integ *it, const qd__sim_erk *tab, double t0, const double *y0, double h,
                        double **K, double *ytmp, double *y1) {
    erk_rhs e = {it, QD_OK};
    qd__num_rk_stages(tab->rk, rhs, &e, it->dim, t0, h, y0, y1, K, ytmp, true);
    return e.st;
}

qd_status qd__sim_erk_step(qd__sim_integ *it) {
    erk *r = it->priv;
    const qd__sim_erk *tab = r->tab;
    size_t d = it->dim;
    qd_status st = QD_OK;
    if (it->y_changed)
        st = qd__sim_rhs(it->s, it->form, it->t, it->y, r->K[0]);
    else if (it->steps) {
        /* first same as last: K[s] of the last step is K[0] of this one */
        double *k0 = r->K[0];
        r->K[0] = r->K[tab->rk->stages];
        r->K[tab->rk->stages] = k0;
    }
    it->y_changed = false;
    const double facc1 = 1 / tab->fac1, facc2 = 1 / tab->fac2;
    for (int failed = 0;;) {
        double h = it->h;
        if (st != QD_OK)
            return st;
        if (!(fabs(h) > 10 * fabs(nextafter(it->t, INFINITY) - it->t)))
            return qd__sim_underflow(it, h);
        st = stages(it, tab, it->t, it->y, h, r->K, r->ytmp, r->ynew);
        if (st != QD_OK && st != QD_ERR_NOMEM && !it->fixed && ++failed <= MAX_STAGE_FAILURES &&
            qd__ctx_recover(it->s->ctx)) {
            /* a stage's state the equations cannot take (a step too long
             * carried it out of their domain: log of a negative, a mass
             * matrix gone singular): a rejected step, ten times shorter.
             * Where the trouble is real it persists, and its message stands. */
            it->rejected++;
            r->reject = true;
            it->h = h / 10;
            st = QD_OK;
            continue;
        }
        if (st != QD_OK)
            return st;
        double err = it->fixed ? 0 : tab->err(it, (const double *const *)r->K, h, r->ynew);
        /* a NaN error, or a new state not finite, is a rejected step whatever
         * the pair's estimate makes of it (dop853's once passed NaN as 0) */
        for (size_t i = 0; !it->fixed && isfinite(err) && i < d; i++)
            if (!isfinite(r->ynew[i]))
                err = NAN;
        if (!isfinite(err))
            err = 1e10;
        double fac11 = pow(err, tab->expo);
        if (err <= 1) {
            double fac = tab->beta > 0 ? fac11 / pow(r->facold, tab->beta) : fac11;
            fac = fmax(facc2, fmin(facc1, fac / tab->safe));
            double hnew = h / fac;
            if (r->reject)
                hnew = fmin(hnew, h);
            r->facold = fmax(err, 1e-4);
            r->reject = false;
            it->told = it->t;
            memcpy(it->yold, it->y, d * sizeof *it->y);
            it->t += h;
            memcpy(it->y, r->ynew, d * sizeof *it->y);
            if (!it->fixed)
                it->h = hnew;
            r->dense_ready = false;
            return QD_OK;
        }
        it->rejected++;
        r->reject = true;
        it->h = h / fmin(facc1, fac11 / tab->safe);
    }
}

void qd__sim_erk_dense(qd__sim_integ *it, double t, double *y) {
    erk *r = it->priv;
    if (!r->dense_ready) {
        if (r->tab->dense_prep(it, r->K, r->coef) != QD_OK) {
            /* the extra stages failed (a singular state): fall back to the ends */
            memcpy(y, t - it->told < it->t - t ? it->yold : it->y, it->dim * sizeof *y);
            return;
        }
        r->dense_ready = true;
    }
    double h = it->t - it->told;
    r->tab->dense_eval(it, r->coef, h > 0 ? (t - it->told) / h : 1, y);
}

qd_status qd__sim_erk_redo(qd__sim_integ *it, double h, double *y) {
    erk *r = it->priv;
    memcpy(r->Kr[0], r->K[0], it->dim * sizeof **r->K);
    return stages(it, r->tab, it->told, it->yold, h, r->Kr, r->ytmp, y);
}
