/*
 * tests/sim/sim_fixture.h - a model text compiled for simulation, and a
 * run that keeps the last row and the event rows.
 */
#ifndef QT_SIM_FIXTURE_H
#define QT_SIM_FIXTURE_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/sim.h"

#define SF_MAXEV 4096
#define SF_PI 3.14159265358979323846

typedef struct sim_fix {
    qd_ctx *ctx;
    qd_model *m;
    qd_eom *e;
    qd_sim *s;
    double q0[16], qd0[16];
    /* filled by sf_run */
    double last[128];
    size_t nev;
    double ev_t[SF_MAXEV];
    double ev_row[8][128];
    size_t max_events; /* stop after this many events (0: never) */
    size_t ncols;      /* of the last run */
    qd_sim_stats stats;
} sim_fix;

static inline double sf_number(qd_ctx *ctx, const qd_expr *v) {
    double x = 0;
    if (v)
        qd_eval(ctx, v, 0, NULL, NULL, &x);
    return x;
}

static inline sim_fix *sf_load(const char *text) {
    sim_fix *f = calloc(1, sizeof *f);
    qd_diag d;
    f->ctx = qd_ctx_new();
    f->m = qd_model_parse(f->ctx, text, &d);
    if (!f->m) {
        fprintf(stderr, "parse: %s\n", d.message);
        return NULL;
    }
    f->e = qd_eom_derive(f->ctx, f->m);
    if (!f->e) {
        fprintf(stderr, "derive: %s\n", qd_ctx_message(f->ctx));
        return NULL;
    }
    f->s = qd_sim_new(f->ctx, f->m, f->e);
    if (!f->s) {
        fprintf(stderr, "sim: %s\n", qd_ctx_message(f->ctx));
        return NULL;
    }
    for (size_t i = 0; i < qd_model_ncoords(f->m) && i < 16; i++) {
        f->q0[i] = sf_number(f->ctx, qd_model_initial(f->m, i, 0));
        f->qd0[i] = sf_number(f->ctx, qd_model_initial(f->m, i, 1));
    }
    return f;
}

static inline void sf_free(sim_fix *f) {
    if (!f)
        return;
    qd_sim_free(f->s);
    if (f->e)
        qd_eom_free(f->e);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
    free(f);
}

static inline int sf_sink(void *data, int event, const double *row) {
    sim_fix *f = data;
    if (event >= 0) {
        if (f->nev < 8)
            memcpy(f->ev_row[f->nev], row, f->ncols * sizeof *row);
        if (f->nev < SF_MAXEV)
            f->ev_t[f->nev] = row[0];
        f->nev++;
        return f->max_events && f->nev >= f->max_events;
    }
    return 0;
}

/* Run with method from 0 to t_end: fixed step dt (or the output grid), or
 * tolerance rtol; the final row in f->last. */
static inline qd_status sf_run(sim_fix *f, qd_sim_method method, double t_end, double dt, double rtol,
                        bool fixed) {
    qd_sim_opts o = {.method = method, .t0 = 0, .t_end = t_end, .dt = dt, .fixed = fixed,
                     .rtol = rtol, .atol = rtol > 0 ? rtol * 1e-2 : 0, .q0 = f->q0,
                     .qd0 = f->qd0};
    f->nev = 0;
    f->ncols = qd_sim_columns(f->s, method, NULL, 0);
    qd_status st = qd_sim_run(f->s, &o, sf_sink, f, &f->stats, f->last);
    if (st != QD_OK)
        fprintf(stderr, "run (%s): %s\n", qd_sim_method_name(method), qd_ctx_message(f->ctx));
    return st;
}

/* The column of that name in a run with method, or -1. */
static inline int sf_col(const sim_fix *f, qd_sim_method method, const char *name) {
    const char *names[128];
    size_t k = qd_sim_columns(f->s, method, names, 128);
    for (size_t i = 0; i < k && i < 128; i++)
        if (!strcmp(names[i], name))
            return (int)i;
    return -1;
}

/* K(k) = pi / (2 AGM(1, sqrt(1 - k^2))) (Abramowitz & Stegun 17.6). */
static inline double sf_ellipk(double k) {
    double a = 1, b = sqrt(1 - k * k);
    for (int i = 0; i < 40; i++) {
        double an = 0.5 * (a + b);
        b = sqrt(a * b);
        a = an;
    }
    return SF_PI / (2 * a);
}

#endif
