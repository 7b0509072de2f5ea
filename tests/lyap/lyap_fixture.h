/*
 * tests/lyap/lyap_fixture.h - a model text made into a qd_lyap, and a run
 * with the options the tests vary.
 */
#ifndef QT_LYAP_FIXTURE_H
#define QT_LYAP_FIXTURE_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/lyapunov.h"

/* Hénon & Heiles, Astron. J. 69 (1964) 73: V = (x^2 + y^2)/2 + x^2 y - y^3/3. */
static const char lf_henon_heiles[] =
    "coordinates x, y\n"
    "T = (x'^2 + y'^2)/2\n"
    "V = (x^2 + y^2)/2 + x^2*y - y^3/3\n";

typedef struct lyap_fix {
    qd_ctx *ctx;
    qd_model *m;
    qd_eom *e;
    qd_lyap *l;
} lyap_fix;

static inline lyap_fix *lf_load(const char *text) {
    lyap_fix *f = calloc(1, sizeof *f);
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
    f->l = qd_lyap_new(f->ctx, f->m, f->e);
    if (!f->l)
        fprintf(stderr, "lyap: %s\n", qd_ctx_message(f->ctx));
    return f;
}

static inline void lf_free(lyap_fix *f) {
    if (!f)
        return;
    qd_lyap_free(f->l);
    if (f->e)
        qd_eom_free(f->e);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
    free(f);
}

/* dop853 at rtol 1e-11, atol 1e-13 from (q0, qd0) over [0, t_end]. */
static inline qd_sim_opts lf_opts(const double *q0, const double *qd0, double t_end) {
    return (qd_sim_opts){.method = QD_SIM_DOP853, .t0 = 0, .t_end = t_end, .rtol = 1e-11,
                         .atol = 1e-13, .q0 = q0, .qd0 = qd0};
}

/* The Hénon-Heiles initial state at energy E from (x, y, y'), x' > 0 from E. */
static inline void lf_hh_state(double E, double x, double y, double vy, double *q, double *qd) {
    double V = (x * x + y * y) / 2 + x * x * y - y * y * y / 3;
    q[0] = x;
    q[1] = y;
    qd[1] = vy;
    qd[0] = sqrt(2 * (E - V) - vy * vy);
}

#endif
