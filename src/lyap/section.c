/*
 * src/lyap/section.c - a Poincare surface of section (qd_poincare_run):
 * the run's rows at the crossings of one event, located to round-off by
 * the integrator's event machinery, counted until enough are found.  The
 * section is an event of the run like any other; what this file decides is
 * which rows are crossings, when the run has found enough, and how far
 * along it is.
 */
#include "qdot/lyapunov.h"

#include <math.h>

#include "base/args.h"

typedef struct pc_run {
    const qd_poincare_opts *o;
    qd_poincare_result *r;
    double t0, t_end;
} pc_run;

static int on_row(void *data, int event, const double *row) {
    pc_run *p = data;
    bool crossing = event == p->o->event;
    int stop = p->o->sink(p->o->data, row, crossing);
    if (crossing) {
        p->r->got++;
        p->r->last_t = row[0];
    }
    if (p->o->progress) { /* done: the larger of the crossings found and the time used */
        double by_n = (double)p->r->got / (double)p->o->want;
        double by_t = (row[0] - p->t0) / (p->t_end - p->t0);
        p->o->progress(p->o->data, by_n > by_t ? by_n : by_t, row[0]);
    }
    return stop || p->r->got >= p->o->want;
}

qd_status qd_poincare_run(qd_sim *s, const qd_sim_opts *opts, const qd_poincare_opts *o,
                          qd_poincare_result *r) {
    if (r)
        *r = (qd_poincare_result){.last_t = opts ? opts->t0 : NAN};
    QD_ARGS(QD_ERR_ARG, s && opts && o && o->sink && r && o->want > 0);
    pc_run p = {o, r, opts->t0, opts->t_end};
    return qd_sim_run(s, opts, on_row, &p, &r->stats, NULL);
}
