/*
 * src/linear/ss_point.c - the operating point of qd_linearize: exact
 * values for the coordinates, velocities, inputs and t, as a substitution.
 */
#include "ss.h"

#include "base/mem.h"

#include <string.h>

void qd__lin_point_free(qd__point *pt) {
    qd__free(pt->from);
    memset(pt, 0, sizeof *pt);
}

static qd_status place(qd_ctx *ctx, qd__point *pt, const qd_expr *sym, const qd_expr *val) {
    for (size_t i = 0; i < pt->n; i++)
        if (pt->from[i] == sym) {
            pt->to[i] = val;
            return QD_OK;
        }
    qd_ctx_error(ctx, QD_ERR_ARG, "'%s' is not a coordinate, velocity, input or t of the model: "
                 "an operating point gives q=..., q'=... and the inputs",
                 qd_expr_name(sym));
    return QD_ERR_ARG;
}

qd_status qd__lin_point_make(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t npt,
                         const qd_expr *const *syms, const qd_expr *const *vals, qd__point *pt) {
    size_t n = e->n, nu = qd_model_ninputs(m);
    pt->n = 2 * n + nu + 1;
    pt->from = qd__calloc(ctx, 2 * pt->n + 1, sizeof *pt->from);
    if (!pt->from)
        return QD_ERR_NOMEM;
    pt->to = pt->from + pt->n;
    for (size_t j = 0; j < n; j++) {
        pt->from[j] = e->q[j];
        pt->from[n + j] = e->qd[j];
    }
    for (size_t k = 0; k < nu; k++)
        pt->from[2 * n + k] = qd_model_input(m, k);
    pt->from[pt->n - 1] = qd_time(ctx);
    for (size_t i = 0; i < pt->n; i++)
        pt->to[i] = qd_int(ctx, 0);
    for (size_t i = 0; i < npt; i++) {
        qd_status st = place(ctx, pt, syms[i], vals[i]);
        if (st != QD_OK)
            return st;
    }
    return qd_ctx_status(ctx);
}

qd_status qd__lin_point_numbers(qd_ctx *ctx, const qd_model *m, const qd__point *pt, size_t k,
                            const qd_expr *const *which, double *out) {
    size_t np = qd_model_nparams(m);
    const qd_expr **ps = qd__malloc(ctx, (np + 1) * sizeof *ps);
    double *pv = qd__malloc(ctx, (np + 1) * sizeof *pv);
    qd_status st = ps && pv ? QD_OK : QD_ERR_NOMEM;
    for (size_t i = 0; st == QD_OK && i < np; i++) {
        ps[i] = qd_model_param(m, i);
        st = qd_model_param_number(m, i, &pv[i]);
    }
    for (size_t j = 0; st == QD_OK && j < k; j++) {
        out[j] = 0;
        for (size_t i = 0; i < pt->n; i++)
            if (pt->from[i] == which[j])
                st = qd_eval(ctx, pt->to[i], np, ps, pv, &out[j]);
    }
    qd__free(ps);
    qd__free(pv);
    return st;
}
