/*
 * src/sweep/run.c - one run of a sweep: its initial state and parameters
 * from its inputs, one qd_sim_run_with on the shared compiled system, and
 * the measures read from the rows as they come (a row at every accepted
 * step, so max, min and escape see the whole motion).
 */
#include "sweep_int.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/mem.h"
#include "../base/args.h"

/* What the sink keeps of a run. */
typedef struct sw_acc {
    const qd_sweep *w;
    size_t ncr;           /* the run's columns */
    size_t *col;          /* per measure: the run's column it reads */
    double *val;          /* per measure: max, min, escape time, crossings */
    double *prev;         /* per measure: the column's value at the last row */
    double tprev;
    bool started;
    double *evrow;        /* the row of the first `event` (ncr) */
    bool ev_found;
} sw_acc;

static double escape_time(const qd__sw_ms *x, double tprev, double vprev, double t, double v,
                          bool started) {
    double out = x->sign * (v - x->val), was = x->sign * (vprev - x->val);
    if (!(out > 0))
        return NAN;
    if (!started || !(was <= 0) || t == tprev)
        return t;
    /* crossed in (tprev, t]: linear between the rows */
    return tprev + (t - tprev) * (x->val - vprev) / (v - vprev);
}

static void measure_row(sw_acc *a, size_t k, int event, const double *row) {
    const qd__sw_ms *x = &a->w->ms[k];
    double v = a->col[k] < a->ncr ? row[a->col[k]] : NAN;
    switch (x->kind) {
    case QD__MS_MAX:
        a->val[k] = a->started ? fmax(a->val[k], v) : v;
        break;
    case QD__MS_MIN:
        a->val[k] = a->started ? fmin(a->val[k], v) : v;
        break;
    case QD__MS_ESCAPE:
        if (isnan(a->val[k]))
            a->val[k] = escape_time(x, a->tprev, a->prev[k], row[0], v, a->started);
        break;
    case QD__MS_PCOUNT:
        a->val[k] += event >= 0 && (size_t)event == a->w->section;
        break;
    default:
        break;
    }
    a->prev[k] = v;
}

static int sink(void *data, int event, const double *row) {
    sw_acc *a = data;
    if (event >= 0 && (size_t)event == a->w->event && !a->ev_found) {
        memcpy(a->evrow, row, a->ncr * sizeof *row);
        a->ev_found = true;
    }
    for (size_t k = 0; k < a->w->nms; k++)
        measure_row(a, k, event, row);
    a->tprev = row[0];
    a->started = true;
    return 0;
}

static size_t find(const char *const *names, size_t nc, const char *name) {
    for (size_t j = 0; j < nc; j++)
        if (!strcmp(names[j], name))
            return j;
    return nc;
}

/* out[0..2n): the coordinates and velocities of a run's row by name. */
static void state_of(const sw_acc *a, const char *const *names, const double *row, double *out) {
    size_t n = a->w->n;
    char buf[160];
    for (size_t i = 0; i < n; i++) {
        out[i] = row[1 + i];
        snprintf(buf, sizeof buf, "%s'", names[1 + i]);
        size_t j = find(names, a->ncr, buf);
        out[n + i] = j < a->ncr ? row[j] : NAN;
    }
}

/* The measures of a finished run into row. */
static void measures_out(const sw_acc *a, const char *const *names, const qd_sim_stats *st,
                         const double *final, double *row) {
    for (size_t k = 0; k < a->w->nms; k++) {
        const qd__sw_ms *x = &a->w->ms[k];
        double *out = row + x->first;
        switch (x->kind) {
        case QD__MS_FINAL:
            state_of(a, names, final, out);
            break;
        case QD__MS_ENERGY:
            out[0] = st->energy_error_max;
            break;
        case QD__MS_EVENT:
            if (a->ev_found) {
                out[0] = a->evrow[0];
                state_of(a, names, a->evrow, out + 1);
            }
            break;
        case QD__MS_LYAP:
        case QD__MS_LYAPSPEC:
            break;
        default:
            out[0] = a->val[k];
        }
    }
}

/* Run i's initial state and parameters into q0, qd0 and par (or par NULL
 * when no parameter is swept). */
static void run_inputs(const qd_sweep *w, const qd_sim_opts *base, const double *x, double *q0,
                       double *qd0, double *par, double *pwork) {
    size_t n = w->n;
    for (size_t i = 0; i < n; i++) {
        q0[i] = base->q0 ? base->q0[i] : 0;
        qd0[i] = base->qd0 ? base->qd0[i] : 0;
    }
    if (par) {
        for (size_t p = 0; p < w->np; p++)
            par[w->np + p] = base->par ? base->par[p] : w->par0[p];
    }
    for (size_t k = 0; k < w->nin; k++) {
        const qd__sw_in *in = &w->in[k];
        if (in->kind == QD__SW_Q)
            q0[in->index] = x[k];
        else if (in->kind == QD__SW_QD)
            qd0[in->index] = x[k];
        else
            par[w->np + in->index] = x[k];
    }
    if (par)
        qd_prog_eval(w->parprog, pwork, par + w->np, par);
}

qd_status qd__sweep_ready(qd_ctx *ctx, const qd_sweep *w) {
    for (size_t k = 0; k < w->nms; k++) {
        if (w->ms[k].kind == QD__MS_EVENT && w->event >= qd_sim_nevents(w->s)) {
            qd_ctx_error(ctx, QD_ERR_ARG, "the measure event needs an event of the simulation");
            return QD_ERR_ARG;
        }
        if (w->ms[k].kind == QD__MS_PCOUNT && !w->has_section) {
            qd_ctx_error(ctx, QD_ERR_ARG, "poincare-count needs a section (qd_sweep_set_section)");
            return QD_ERR_ARG;
        }
        if ((w->ms[k].kind == QD__MS_LYAP || w->ms[k].kind == QD__MS_LYAPSPEC) && !w->lyap) {
            qd_ctx_error(ctx, QD_ERR_ARG, "%s needs the variational equations "
                         "(qd_sweep_set_lyap)", w->ms[k].text);
            return QD_ERR_ARG;
        }
    }
    if (w->how == QD__SW_NONE || !w->nms) {
        qd_ctx_error(ctx, QD_ERR_ARG, "a sweep needs its runs and its measures first");
        return QD_ERR_ARG;
    }
    return QD_OK;
}

/* The scratch of one run, in one block: the accumulators, the state, the
 * parameters and the run's column names. */
typedef struct sw_scratch {
    double *d;
    const char **names;
} sw_scratch;

static qd_status scratch(qd_ctx *ctx, const qd_sweep *w, size_t ncr, sw_acc *a, double **q0,
                         double **par, double **pwork, double **final, sw_scratch *sc) {
    size_t nms = w->nms, pw = w->parprog ? qd_prog_work_size(w->parprog) : 0;
    size_t nd = 2 * nms + 2 * ncr + 2 * w->n + 2 * w->np + pw + 1;
    sc->d = qd__malloc(ctx, nd * sizeof *sc->d + (nms + 1) * sizeof(size_t));
    sc->names = qd__malloc(ctx, (ncr + 1) * sizeof *sc->names);
    if (!sc->d || !sc->names)
        return QD_ERR_NOMEM;
    a->val = sc->d;
    a->prev = a->val + nms;
    a->evrow = a->prev + nms;
    *final = a->evrow + ncr;
    *q0 = *final + ncr;
    *par = *q0 + 2 * w->n;
    *pwork = *par + 2 * w->np;
    a->col = (size_t *)(void *)(sc->d + nd);
    if (w->parprog)
        qd_prog_work_init(w->parprog, *pwork);
    for (size_t k = 0; k < nms; k++)
        a->val[k] = w->ms[k].kind == QD__MS_PCOUNT ? 0 : NAN;
    return QD_OK;
}

/* Which run column each measure reads, for this method. */
static void bind_columns(sw_acc *a, const char *const *names) {
    for (size_t k = 0; k < a->w->nms; k++)
        a->col[k] = a->w->ms[k].col ? find(names, a->ncr, a->w->ms[k].col) : a->ncr;
}

static bool is_lyap(const qd__sw_ms *x) {
    return x->kind == QD__MS_LYAP || x->kind == QD__MS_LYAPSPEC;
}

/* The simulation is run unless every measure is a Lyapunov exponent,
 * which integrates its own (extended) system. */
static bool needs_sim(const qd_sweep *w) {
    for (size_t k = 0; k < w->nms; k++)
        if (!is_lyap(&w->ms[k]))
            return true;
    return false;
}

/* The Lyapunov measures of the run o: the largest exponent and its error,
 * or the whole spectrum, into row. */
static qd_status lyap_measures(qd_ctx *ctx, const qd_sweep *w, const qd_sim_opts *o, double *row) {
    qd_sim_opts lo_sim = *o;
    if (lo_sim.method != QD_SIM_DOPRI5)
        lo_sim.method = QD_SIM_DOP853;
    lo_sim.fixed = false;
    lo_sim.dt = 0;
    qd_status st = QD_OK;
    for (size_t k = 0; st == QD_OK && k < w->nms; k++) {
        const qd__sw_ms *x = &w->ms[k];
        if (!is_lyap(x))
            continue;
        qd_lyap_opts lo = w->lyap_opts;
        lo.nexp = x->kind == QD__MS_LYAP ? 1 : 2 * w->n;
        double err[1];
        if (x->kind == QD__MS_LYAP)
            st = qd_lyap_run(ctx, w->lyap, &lo_sim, &lo, row + x->first, err);
        else
            st = qd_lyap_run(ctx, w->lyap, &lo_sim, &lo, row + x->first, NULL);
        if (st == QD_OK && x->kind == QD__MS_LYAP)
            row[x->first + 1] = err[0];
    }
    return st;
}

qd_status qd_sweep_run_one(qd_ctx *ctx, const qd_sweep *w, const qd_sim_opts *base, size_t i,
                           double *row, qd_sim_stop *stop) {
    QD_ARGS_CTX(ctx, ctx && w && base && row);
    if (stop)
        *stop = (qd_sim_stop){QD_STOP_NONE, NAN, NAN};
    for (size_t j = 0; j < w->ncols; j++)
        row[j] = NAN;
    if (i >= w->nruns) {
        qd_ctx_error(ctx, QD_ERR_ARG, "run %zu of %zu", i, w->nruns);
        return QD_ERR_ARG;
    }
    qd__sweep_inputs_of(w, i, row);
    qd_status st = qd__sweep_ready(ctx, w);
    if (st != QD_OK)
        return st;
    qd_sim_opts o = *base;
    size_t ncr = qd_sim_columns(w->s, o.method, NULL, 0);
    sw_acc a = {.w = w, .ncr = ncr};
    double *q0 = NULL, *par = NULL, *pwork = NULL, *final = NULL;
    sw_scratch sc = {0};
    st = scratch(ctx, w, ncr, &a, &q0, &par, &pwork, &final, &sc);
    if (st == QD_OK) {
        qd_sim_columns(w->s, o.method, sc.names, ncr);
        bind_columns(&a, sc.names);
        run_inputs(w, base, row, q0, q0 + w->n, w->parprog ? par : NULL, pwork);
        o.q0 = q0;
        o.qd0 = q0 + w->n;
        o.par = w->parprog ? par : base->par;
        /* a row at every step for max, min, escape */
        if (qd_sim_method_adaptive(o.method) && !o.fixed)
            o.dt = 0;
        o.every = 0;
        qd_sim_stats stats = {0};
        if (needs_sim(w)) {
            st = qd_sim_run_with(ctx, w->s, &o, sink, &a, &stats, final);
            if (stop)
                *stop = stats.stop;
        }
        if (st == QD_OK && w->lyap)
            st = lyap_measures(ctx, w, &o, row);
        if (st == QD_OK)
            measures_out(&a, sc.names, &stats, final, row);
        else
            for (size_t j = w->nin; j < w->ncols; j++)
                row[j] = NAN;
    } else {
        qd_ctx_error(ctx, st, "out of memory starting run %zu", i);
    }
    qd__free(sc.d);
    qd__free(sc.names);
    return st;
}
