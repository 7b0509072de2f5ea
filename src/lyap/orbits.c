/*
 * src/lyap/orbits.c - several orbits through one Poincare section
 * (qd_poincare_orbits_run, qdot poincare with --initial given again): the
 * set-up restarted from each initial state in turn (qd_sim_setup_restart)
 * and qd_poincare_run on each, the rows going to one sink.  Every initial
 * state is read before the first run, so a mistake in the third is told
 * before any row is written.
 */
#include "qdot/lyapunov.h"
#include "qdot/simsetup.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>

#include "base/args.h"

typedef struct orbits_run {
    const qd_poincare_opts *o;
    size_t k, n;     /* the orbit running, of n */
    bool stopped;    /* the caller's sink said stop: no orbit after this one */
} orbits_run;

static int on_row(void *data, const double *row, bool crossing) {
    orbits_run *w = data;
    int stop = w->o->sink(w->o->data, row, crossing);
    w->stopped |= stop != 0;
    return stop;
}

/* done over all orbits: orbit k's share is the k-th n-th */
static void on_progress(void *data, double done, double t) {
    orbits_run *w = data;
    if (w->o->progress)
        w->o->progress(w->o->data, ((double)w->k + done) / (double)w->n, t);
}

qd_status qd_poincare_orbits_check(qd_ctx *ctx, qd_sim_setup *set, qd_sim_opts *opts,
                                   const qd_poincare_orbits *orbits, size_t *at) {
    if (at)
        *at = 0;
    QD_ARGS_CTX(ctx, ctx && set && opts && orbits && at && (orbits->n == 0 || orbits->initial));
    if (orbits->n < 1 || orbits->n > QD_POINCARE_MAX_ORBITS) {
        qd_ctx_error(ctx, QD_ERR_ARG, "a section takes 1 to %d orbits, not %zu",
                     QD_POINCARE_MAX_ORBITS, orbits->n);
        return QD_ERR_ARG;
    }
    qd_status st = QD_OK;
    for (size_t k = 0; k < orbits->n && st == QD_OK; k++)
        if ((st = qd_sim_setup_restart(set, orbits->initial[k], opts)) != QD_OK)
            *at = k;
    return st;
}

qd_status qd_poincare_orbits_run(qd_ctx *ctx, qd_sim_setup *set, qd_sim_opts *opts,
                                 const qd_poincare_opts *o, const qd_poincare_orbits *orbits,
                                 qd_poincare_result *r, size_t *at) {
    if (at)
        *at = 0;
    QD_ARGS_CTX(ctx, ctx && set && opts && o && o->sink && o->want > 0 && orbits && r && at);
    for (size_t k = 0; k < orbits->n && k < QD_POINCARE_MAX_ORBITS; k++)
        r[k] = (qd_poincare_result){.last_t = NAN};
    qd_status st = qd_poincare_orbits_check(ctx, set, opts, orbits, at);
    orbits_run w = {.o = o, .n = orbits->n};
    qd_poincare_opts each = {.event = o->event, .want = o->want, .sink = on_row,
                             .progress = on_progress, .data = &w};
    for (size_t k = 0; k < orbits->n && st == QD_OK; k++) {
        r[k] = (qd_poincare_result){.last_t = opts->t0};
        if (w.stopped)
            continue; /* not run: r[k] counts no crossing */
        *at = w.k = k; /* the orbit run (the one stopped in, after a stop) */
        st = qd_sim_setup_restart(set, orbits->initial[k], opts);
        if (st == QD_OK && orbits->start)
            orbits->start(o->data, k);
        if (st == QD_OK)
            st = qd_poincare_run(qd_sim_setup_sim(set), opts, &each, &r[k]);
    }
    return st;
}

qd_status qd_poincare_print(const qd_poincare_result *r, size_t norbits, qd_sim_method method,
                            size_t want, const char *prefix, const char *t_end_name,
                            qd_buf *out) {
    QD_ARGS(QD_ERR_ARG, (r || !norbits) && prefix && t_end_name && out);
    for (size_t k = 0; k < norbits; k++) {
        const qd_sim_stats *st = &r[k].stats;
        char orbit[32] = "";
        if (norbits > 1)
            snprintf(orbit, sizeof orbit, "orbit %zu: ", k + 1);
        qd_buf_printf(out, "%s%s%s, %zu crossings by t = %g: %zu steps, %zu evaluations, %zu "
                      "rejected; energy error %.3g over the steps and crossings\n", prefix, orbit,
                      qd_sim_method_name(method), r[k].got, st->t, st->steps, st->evals,
                      st->rejected, fmax(st->energy_error_max, st->energy_error_steps));
        if (r[k].got < want)
            qd_buf_printf(out, "%snote: %sonly %zu of %zu crossings before t = %g (raise %s)\n",
                          prefix, orbit, r[k].got, want, st->t, t_end_name);
    }
    return out->failed ? QD_ERR_NOMEM : QD_OK;
}

qd_status qd_poincare_csv(size_t ncols, const char *const *names, const double *row,
                          size_t norbits, size_t orbit, qd_buf *out) {
    QD_ARGS(QD_ERR_ARG, names && out);
    if (norbits > 1 && row)
        qd_buf_printf(out, "%zu,", orbit + 1);
    else if (norbits > 1)
        qd_buf_puts(out, "orbit,");
    for (size_t i = 0; i < ncols; i++) {
        qd_buf_puts(out, i ? "," : "");
        if (row)
            qd_buf_put_double(out, row[i]);
        else
            qd_buf_puts(out, names[i]);
    }
    qd_buf_puts(out, "\n");
    return out->failed ? QD_ERR_NOMEM : QD_OK;
}
