/*
 * src/sweep/prepare.c - a measure's needs added to the run before it is
 * compiled: each EXPR of max:EXPR, min:EXPR, escape:EXPR>VALUE that is not a
 * column yet becomes an output named by its text (the column the measure
 * reads), and each escape its crossing EXPR = VALUE as an event, so the
 * escape time is located to round-off rather than at a step.
 */
#include "sweep_int.h"

#include <string.h>

#include "base/mem.h"
#include "qdot/read.h"
#include "qdot/simsetup.h"
#include "../base/args.h"

/* The library's own reader: qd_read of spec[a, b), names as symbols (no
 * definitions followed), an error located in spec. */
static const qd_expr *plain_read(void *data, qd_ctx *ctx, const char *spec, size_t a,
                                 size_t b) {
    (void)data;
    char *text = qd__malloc(ctx, b - a + 1);
    if (!text)
        return NULL;
    memcpy(text, spec + a, b - a);
    text[b - a] = '\0';
    qd_diag d;
    const qd_read_opts opts = {.new_symbols = true};
    const qd_expr *x = qd_read(ctx, text, &opts, &d);
    qd__free(text);
    if (!x) { /* the record again, located in spec rather than in the copy */
        qd_ctx_clear_error(ctx);
        qd_ctx_error(ctx, d.status, "%s", d.message);
        qd_ctx_error_about(ctx, QD_SUBJECT_TEXT, 0, NULL, QD_REASON_NONE, NULL);
        qd_ctx_error_at(ctx, spec, a + d.offset, d.length ? d.length : 1);
    }
    return x;
}

static qd_status failed(qd_ctx *ctx) {
    qd_status st = qd_ctx_status(ctx);
    return st != QD_OK ? st : QD_ERR_PARSE;
}

/* Each need of spec's measures (qd_sweep_needs) handed to add with its
 * text spec[e0, e1) as a NUL-ended name; the first failure is returned. */
typedef qd_status (*need_fn)(void *data, const char *spec, const qd_sweep_need *x,
                             const char *name);

static qd_status each_need(qd_ctx *ctx, const qd_sim *s, const char *spec, need_fn add,
                           void *data) {
    unsigned flags;
    size_t n = qd_sweep_needs(s, spec, NULL, 0, &flags);
    qd_sweep_need *needs = qd__malloc(ctx, (n + 1) * sizeof *needs);
    if (!needs)
        return QD_ERR_NOMEM;
    qd_sweep_needs(s, spec, needs, n, &flags);
    qd_status st = QD_OK;
    for (size_t k = 0; st == QD_OK && k < n; k++) {
        const qd_sweep_need *x = &needs[k];
        char *name = qd__malloc(ctx, x->e1 - x->e0 + 1);
        if (!name) {
            st = QD_ERR_NOMEM;
            break;
        }
        memcpy(name, spec + x->e0, x->e1 - x->e0);
        name[x->e1 - x->e0] = '\0';
        st = add(data, spec, x, name);
        qd__free(name);
    }
    qd__free(needs);
    return st;
}

/* qd_sweep_prepare's: read by the caller's reader, added to the qd_sim. */
typedef struct to_sim {
    qd_ctx *ctx;
    qd_sim *s;
    qd_sweep_read_fn read;
    void *data;
} to_sim;

static qd_status add_to_sim(void *data, const char *spec, const qd_sweep_need *x,
                            const char *name) {
    to_sim *t = data;
    if (x->kind == QD_SWEEP_NEED_OUTPUT) {
        const qd_expr *e = t->read(t->data, t->ctx, spec, x->e0, x->e1);
        return e ? qd_sim_add_output(t->s, name, e) : failed(t->ctx);
    }
    const qd_expr *l = t->read(t->data, t->ctx, spec, x->e0, x->e1);
    const qd_expr *r = l ? t->read(t->data, t->ctx, spec, x->v0, x->v1) : NULL;
    return r ? qd_sim_add_event(t->s, qd_sub(t->ctx, l, r), 0, NULL, false) : failed(t->ctx);
}

qd_status qd_sweep_prepare(qd_ctx *ctx, qd_sim *s, const char *spec, qd_sweep_read_fn read,
                           void *data) {
    QD_ARGS_CTX(ctx, ctx && s && spec);
    to_sim t = {ctx, s, read ? read : plain_read, data};
    return each_need(ctx, s, spec, add_to_sim, &t);
}

/* qd_sweep_setup_measures': read in the model's namespace by the setup. */
static qd_status add_to_setup(void *data, const char *spec, const qd_sweep_need *x,
                              const char *name) {
    struct qd_sim_setup *set = data;
    if (x->kind == QD_SWEEP_NEED_OUTPUT)
        return qd_sim_setup_output(set, name, spec, x->e0, x->e1);
    return qd_sim_setup_crossing(set, spec, x->e0, x->e1, x->v0, x->v1);
}

qd_status qd_sweep_setup_measures(qd_ctx *ctx, struct qd_sim_setup *set, const char *spec) {
    QD_ARGS_CTX(ctx, ctx && set && spec);
    return each_need(ctx, qd_sim_setup_sim(set), spec, add_to_setup, set);
}
