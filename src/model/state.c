/*
 * src/model/state.c - a model's state (qdot/state.h): the one layout of
 * symbols and values (q, q', t, parameters, then what a caller appends),
 * built and filled here so that no caller computes slot numbers.
 */
#include <stdlib.h>
#include <string.h>

#include "base/args.h"
#include "qdot/state.h"

static qd_status nomem(qd_ctx *ctx) {
    qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
    return QD_ERR_NOMEM;
}

qd_status qd_state_layout(qd_ctx *ctx, const qd_model *m, size_t n, const qd_expr *const *q,
                          const qd_expr **syms, double *vals) {
    QD_ARGS_CTX(ctx, m && syms && vals);
    if (!q)
        n = qd_model_ncoords(m);
    for (size_t j = 0; j < n; j++) {
        syms[qd_slot_coord(n, j)] = q ? q[j] : qd_model_coord(m, j);
        syms[qd_slot_velocity(n, j)] = qd_jet(ctx, syms[j], 1);
        if (!syms[qd_slot_velocity(n, j)])
            return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : nomem(ctx);
    }
    if (!(syms[qd_slot_time(n)] = qd_time(ctx)))
        return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : nomem(ctx);
    for (size_t i = 0; i < qd_model_nparams(m); i++) {
        size_t k = qd_slot_param(n, i);
        syms[k] = qd_model_param(m, i);
        qd_status st = qd_model_param_number(m, i, &vals[k]);
        if (st == QD_ERR_NOMEM)
            return st;
        if (st != QD_OK) {
            qd_ctx_error(ctx, QD_ERR_ARG, "parameter %s has no finite value",
                         qd_expr_name(qd_model_param(m, i)));
            qd_ctx_error_about(ctx, QD_SUBJECT_PARAM, i, qd_expr_name(qd_model_param(m, i)),
                               QD_REASON_NONE, NULL);
            return QD_ERR_ARG;
        }
    }
    return QD_OK;
}

qd_status qd_state_init(qd_ctx *ctx, const qd_model *m, qd_state *st) {
    QD_ARGS_CTX(ctx, m && st);
    size_t nq = qd_model_ncoords(m), n = qd_slot_count(nq, qd_model_nparams(m));
    st->n = n;
    st->syms = calloc(n, sizeof *st->syms);
    st->vals = calloc(n, sizeof *st->vals);
    if (!st->syms || !st->vals)
        return nomem(ctx);
    return qd_state_layout(ctx, m, nq, NULL, st->syms, st->vals);
}

qd_status qd_state_append(qd_ctx *ctx, qd_state *st, size_t count, const qd_expr *const *syms,
                          const double *vals) {
    QD_ARGS_CTX(ctx, st && (syms || !count));
    if (!count)
        return QD_OK;
    const qd_expr **s = realloc(st->syms, (st->n + count) * sizeof *s);
    if (!s)
        return nomem(ctx);
    st->syms = s;
    double *v = realloc(st->vals, (st->n + count) * sizeof *v);
    if (!v)
        return nomem(ctx);
    st->vals = v;
    for (size_t k = 0; k < count; k++) {
        st->syms[st->n + k] = syms[k];
        st->vals[st->n + k] = vals ? vals[k] : 0;
    }
    st->n += count;
    return QD_OK;
}

/* x (a constant expression in the parameters) evaluated at st. */
static qd_status value(qd_ctx *ctx, const qd_state *st, const qd_expr *x, double *out) {
    return qd_eval(ctx, x, st->n, st->syms, st->vals, out);
}

qd_status qd_state_initial(qd_ctx *ctx, const qd_model *m, qd_state *st) {
    QD_ARGS_CTX(ctx, m && st && st->syms && st->vals);
    size_t nq = qd_model_ncoords(m);
    qd_status s = QD_OK;
    for (size_t j = 0; j < nq && s == QD_OK; j++)
        for (unsigned order = 0; order < 2 && s == QD_OK; order++) {
            const qd_expr *x = qd_model_initial(m, j, order);
            size_t k = order ? qd_slot_velocity(nq, j) : qd_slot_coord(nq, j);
            if (x && k < st->n)
                s = value(ctx, st, x, &st->vals[k]);
        }
    for (size_t r = 0; r < qd_model_nspeeds(m) && s == QD_OK; r++) {
        const qd_expr *x = qd_model_speed_initial(m, r);
        size_t k = qd_state_find(st, qd_model_speed(m, r));
        if (x && k < st->n)
            s = value(ctx, st, x, &st->vals[k]);
    }
    return s;
}

size_t qd_state_find(const qd_state *st, const qd_expr *sym) {
    QD_ARGS(0, st && sym);
    for (size_t k = 0; k < st->n; k++)
        if (st->syms[k] == sym)
            return k;
    return st->n;
}

void qd_state_free(qd_state *st) {
    if (!st)
        return;
    free(st->syms);
    free(st->vals);
    st->syms = NULL;
    st->vals = NULL;
    st->n = 0;
}
