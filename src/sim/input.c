/*
 * src/sim/input.c - the model's inputs (`inputs F, ...`) in a simulation.
 *
 * Each input has one source: an expression in t, the state and the
 * parameters (a feedback law F = -k x - c x'), a table of samples (t_i, v_i)
 * interpolated linearly, or a C callback u(t, x).  Their values sit in
 * slots of the programs' inputs after the parameters and are filled before
 * every evaluation of the compiled system, so the equations, outputs and
 * events all read the same u(t, x).  A table must cover the whole run:
 * extrapolating a sampled signal would invent it.
 */
#include "simint.h"

#include "base/mem.h"
#include "../base/args.h"

#include <math.h>
#include <string.h>

typedef enum { SRC_NONE, SRC_EXPR, SRC_TABLE, SRC_FN } src_kind;

struct qd__sim_input {
    src_kind kind;
    const qd_expr *expr;
    double *t, *v;          /* the table, t strictly increasing */
    size_t nt;
    qd_sim_input_fn fn;
    void *data;
};

qd_status qd__sim_uin_init(qd_sim *s) {
    if (s->nuin == 0)
        return QD_OK;
    if (s->se) {
        qd_ctx_error(s->ctx, QD_ERR_ARG, "a model in generalized speeds with inputs is not "
                     "simulated: inputs are simulated in the form (q, q') (--no-speeds)");
        return QD_ERR_ARG;
    }
    s->uin = qd__calloc(s->ctx, s->nuin, sizeof *s->uin);
    if (!s->uin)
        return QD_ERR_NOMEM;
    for (size_t k = 0; k < s->nuin; k++)
        s->in_syms[s->uin_off + k] = qd_model_input(s->model, k);
    return QD_OK;
}

static void clear_source(struct qd__sim_input *u) {
    qd__free(u->t);
    memset(u, 0, sizeof *u);
}

void qd__sim_uin_free(qd_sim *s) {
    for (size_t k = 0; s->uin && k < s->nuin; k++)
        clear_source(&s->uin[k]);
    qd__free(s->uin);
    qd_prog_free(s->uprog);
}

/* The input named name, or NULL with QD_ERR_ARG recorded. */
static struct qd__sim_input *find(qd_sim *s, const char *name) {
    if (s->uin_ready) {
        qd_ctx_error(s->ctx, QD_ERR_ARG, "inputs are given before the simulation is compiled");
        return NULL;
    }
    for (size_t k = 0; k < s->nuin; k++)
        if (!strcmp(qd_expr_name(s->in_syms[s->uin_off + k]), name)) {
            clear_source(&s->uin[k]);
            return &s->uin[k];
        }
    qd_ctx_error(s->ctx, QD_ERR_ARG, "'%s' is not an input of the model%s", name,
                 s->nuin ? "" : " (it declares none: inputs F, ...)");
    return NULL;
}

qd_status qd_sim_input_expr(qd_sim *s, const char *name, const qd_expr *x) {
    QD_ARGS(QD_ERR_ARG, s && name && x);
    struct qd__sim_input *u = find(s, name);
    if (!u)
        return QD_ERR_ARG;
    for (size_t k = 0; k < s->nuin; k++)
        if (qd_has(x, s->in_syms[s->uin_off + k])) {
            qd_ctx_error(s->ctx, QD_ERR_ARG, "the source of input %s uses input %s: give each "
                         "in t, the state and the parameters", name,
                         qd_expr_name(s->in_syms[s->uin_off + k]));
            return QD_ERR_ARG;
        }
    u->kind = SRC_EXPR;
    u->expr = x;
    return QD_OK;
}

qd_status qd_sim_input_table(qd_sim *s, const char *name, size_t n, const double *t,
                             const double *v) {
    QD_ARGS(QD_ERR_ARG, s && name && (n == 0 || t) && (n == 0 || v));
    struct qd__sim_input *u = find(s, name);
    if (!u)
        return QD_ERR_ARG;
    for (size_t i = 0; i < n; i++)
        if (!isfinite(t[i]) || !isfinite(v[i]) || (i && !(t[i] > t[i - 1]))) {
            qd_ctx_error(s->ctx, QD_ERR_ARG, "the table of input %s: row %zu is %s", name, i + 1,
                         isfinite(t[i]) && isfinite(v[i]) ? "not later than the one before"
                                                          : "not finite");
            return QD_ERR_ARG;
        }
    if (n < 2) {
        qd_ctx_error(s->ctx, QD_ERR_ARG, "the table of input %s needs two rows at least", name);
        return QD_ERR_ARG;
    }
    u->t = qd__malloc(s->ctx, 2 * n * sizeof *u->t);
    if (!u->t)
        return QD_ERR_NOMEM;
    u->v = u->t + n;
    memcpy(u->t, t, n * sizeof *t);
    memcpy(u->v, v, n * sizeof *v);
    u->nt = n;
    u->kind = SRC_TABLE;
    return QD_OK;
}

qd_status qd_sim_input_callback(qd_sim *s, const char *name, qd_sim_input_fn fn, void *data) {
    QD_ARGS(QD_ERR_ARG, s && name);
    struct qd__sim_input *u = find(s, name);
    if (!u)
        return QD_ERR_ARG;
    u->kind = SRC_FN;
    u->fn = fn;
    u->data = data;
    return QD_OK;
}

qd_status qd__sim_uin_compile(qd_sim *s) {
    if (s->uin_ready || s->nuin == 0)
        return QD_OK;
    const qd_expr **outs = qd__malloc(s->ctx, s->nuin * sizeof *outs);
    if (!outs)
        return QD_ERR_NOMEM;
    bool any = false;
    for (size_t k = 0; k < s->nuin; k++) {
        any = any || s->uin[k].kind == SRC_EXPR;
        outs[k] = s->uin[k].kind == SRC_EXPR ? s->uin[k].expr : qd_int(s->ctx, 0);
    }
    size_t count = 0;
    s->uprog = any ? qd__sim_prog(s, s->nuin, outs, &count) : NULL;
    qd__free(outs);
    if (any && !s->uprog)
        return qd_ctx_status(s->ctx) ? qd_ctx_status(s->ctx) : QD_ERR_NOMEM;
    s->uin_ready = true;
    return QD_OK;
}

/* Does the system read input k: the equations, or an output or event? */
static bool used(const qd_sim *s, size_t k) {
    const qd_expr *u = s->in_syms[s->uin_off + k];
    for (size_t j = 0; s->e && j < s->n; j++) {
        if (qd_has(s->e->f[j], u))
            return true;
        for (size_t l = 0; l < s->n; l++)
            if (qd_has(s->e->M[j * s->n + l], u))
                return true;
    }
    for (size_t i = 0; i < s->nout; i++)
        if (qd_has(s->out_expr[i], u))
            return true;
    return false;
}

qd_status qd__sim_uin_check(qd_sim *s, double t0, double t1) {
    double lo = fmin(t0, t1), hi = fmax(t0, t1);
    for (size_t k = 0; k < s->nuin; k++) {
        const struct qd__sim_input *u = &s->uin[k];
        const char *name = qd_expr_name(s->in_syms[s->uin_off + k]);
        if (u->kind == SRC_NONE && used(s, k)) {
            qd_ctx_error(s->ctx, QD_ERR_ARG, "input %s is used but not supplied (give it a "
                         "value: an expression, a table or a callback)", name);
            return QD_ERR_ARG;
        }
        if (u->kind == SRC_TABLE && (u->t[0] > lo || u->t[u->nt - 1] < hi)) {
            qd_ctx_error(s->ctx, QD_ERR_ARG, "the table of input %s covers t = %g to %g, not the "
                         "run's %g to %g", name, u->t[0], u->t[u->nt - 1], lo, hi);
            return QD_ERR_ARG;
        }
    }
    return QD_OK;
}

/* Linear interpolation; clamped to the ends, which the check before the run
 * keeps to round-off. */
static double interp(const struct qd__sim_input *u, double t) {
    if (t <= u->t[0])
        return u->v[0];
    if (t >= u->t[u->nt - 1])
        return u->v[u->nt - 1];
    size_t a = 0, b = u->nt - 1;
    while (b - a > 1) {
        size_t m = a + (b - a) / 2;
        if (u->t[m] <= t)
            a = m;
        else
            b = m;
    }
    double w = (t - u->t[a]) / (u->t[b] - u->t[a]);
    return u->v[a] + w * (u->v[b] - u->v[a]);
}

void qd__sim_uin_eval(qd_sim *s, double t) {
    double *slot = s->in + s->uin_off;
    if (s->uprog)
        qd_prog_eval(s->uprog, s->uprog_w, s->in, s->uprog_out);
    for (size_t k = 0; k < s->nuin; k++) {
        const struct qd__sim_input *u = &s->uin[k];
        slot[k] = u->kind == SRC_EXPR    ? s->uprog_out[k]
                  : u->kind == SRC_TABLE ? interp(u, t)
                  : u->kind == SRC_FN    ? u->fn(u->data, t, s->in)
                                         : 0;
        /* a callback's NaN (or infinity) is its failure: the first one is
         * kept and ends the run (an expression's is the state's, checked
         * with it) */
        if (u->kind == SRC_FN && !isfinite(slot[k]) && !s->uin_bad) {
            s->uin_bad = k + 1;
            s->uin_bad_t = t;
            s->uin_bad_v = slot[k];
        }
    }
}

qd_status qd__sim_uin_failed(qd_sim *s) {
    size_t k = s->uin_bad - 1;
    qd__sim_stop(s, QD_STOP_NONFINITE, s->uin_bad_t, s->uin_bad_v);
    qd_ctx_error(s->ctx, QD_ERR_NUMERIC,
                 "input %s is not finite at t = %.17g (its callback returned %g): the "
                 "callback failed there, or its signal is not defined there",
                 qd_expr_name(s->in_syms[s->uin_off + k]), s->uin_bad_t, s->uin_bad_v);
    return QD_ERR_NUMERIC;
}

qd_status qd_sim_inputs_ready(qd_sim *s, double t0, double t_end) {
    QD_ARGS(QD_ERR_ARG, s);
    return qd__sim_uin_check(s, t0, t_end);
}
