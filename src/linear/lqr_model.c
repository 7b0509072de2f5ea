/*
 * src/linear/lqr_model.c - an LQR design on a model linearized at a point,
 * and its feedback as an expression (qdot/control.h): what `qdot linearize
 * --lqr` prints and `qdot simulate --input "F = lqr"` integrates.
 */
#include "qdot/control.h"
#include "../base/args.h"
#include "../base/mem.h"

#include <string.h>

qd_status qd_lqr_design(qd_ctx *ctx, const qd_statespace *s, const char *weights,
                        qd_care_result *out) {
    QD_ARGS_CTX(ctx, ctx && s && weights && out);
    memset(out, 0, sizeof *out);
    if (s->nu == 0) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the model has no inputs to feed back (declare "
                                      "`inputs F, ...`)");
        qd_ctx_error_about(ctx, QD_SUBJECT_NONE, 0, "lqr", QD_REASON_NONE, NULL);
        return QD_ERR_ARG;
    }
    double *Q = qd__malloc(ctx, s->nx * s->nx * sizeof *Q);
    double *R = qd__malloc(ctx, s->nu * s->nu * sizeof *R);
    qd_status st = Q && R ? qd_lqr_weights_read(ctx, weights, s->nx, s->nu, Q, R) : QD_ERR_NOMEM;
    if (st == QD_OK)
        st = qd_care_solve(ctx, s->nx, s->nu, s->A, s->B, Q, R, out);
    qd__free(Q);
    qd__free(R);
    return st;
}

/* The exact value the point gives sym, or 0 (qd_linearize's default). */
static const qd_expr *point_value(qd_ctx *ctx, size_t npt, const qd_expr *const *syms,
                                  const qd_expr *const *vals, const qd_expr *sym) {
    for (size_t i = 0; i < npt; i++)
        if (syms[i] == sym)
            return vals[i];
    return qd_int(ctx, 0);
}

const qd_expr *qd_lqr_feedback(qd_ctx *ctx, const qd_statespace *s, const qd_care_result *r,
                               size_t npt, const qd_expr *const *syms,
                               const qd_expr *const *vals, size_t k) {
    if (!(ctx && s && r && (npt == 0 || (syms && vals)))) {
        qd__args_null(ctx, __func__);
        return NULL;
    }
    if (k >= s->nu || r->n != s->nx || r->m != s->nu || !r->K) {
        qd_ctx_error(ctx, QD_ERR_ARG, "qd_lqr_feedback: input %zu of %zu, or a design of "
                                      "another system", k, s->nu);
        return NULL;
    }
    const qd_expr **terms = qd__malloc(ctx, (s->nx + 1) * sizeof *terms);
    if (!terms)
        return NULL;
    const qd_expr *u = NULL;
    terms[0] = point_value(ctx, npt, syms, vals, s->inputs[k]);
    bool ok = terms[0] != NULL;
    for (size_t j = 0; ok && j < s->nx; j++) {
        const qd_expr *x0 = point_value(ctx, npt, syms, vals, s->states[j]);
        const qd_expr *dx = x0 ? qd_sub(ctx, s->states[j], x0) : NULL;
        const qd_expr *g = qd_float(ctx, -r->K[k * s->nx + j]);
        terms[j + 1] = dx && g ? qd_mul(ctx, g, dx) : NULL;
        ok = terms[j + 1] != NULL;
    }
    if (ok)
        u = qd_add_n(ctx, s->nx + 1, terms);
    qd__free(terms);
    return u;
}
