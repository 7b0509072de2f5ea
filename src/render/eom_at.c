/*
 * src/render/eom_at.c - M q'' = f at a state: every entry that qd_render_eom
 * prints, evaluated (qd_eom_eval, A and b by qd_eval, the `reaction`
 * statements by qd_eom_reaction) and kept as a number node, so that each
 * format prints the numbers the way it prints expressions.
 */
#include "render.h"

#include <stdio.h>
#include <string.h>
#include "../base/mem.h"

/* How many numbers a state gives: M, f, q'', A, b, lambda, R. */
static size_t count_numbers(const qd_eom *e) {
    size_t n = e->n, m = e->ncon;
    return n * n + 2 * n + m * n + 2 * m + n;
}

/* A and b at the state (the compiled program has them, but not as an
 * interface: qd_eval per entry is plenty for one state). */
static qd_status constraint_rows(qd__eom_view *v, const qd_render_opts *o, double *Ab) {
    const qd_eom *e = v->e;
    qd_status st = QD_OK;
    for (size_t i = 0; st == QD_OK && i < e->ncon * e->n + e->ncon; i++) {
        const qd_expr *x = i < e->ncon * e->n ? e->A[i] : e->b[i - e->ncon * e->n];
        st = qd_eval(v->ctx, x, o->nstate, o->syms, o->vals, &Ab[i]);
    }
    return st;
}

/* Is reaction i on a sudden constraint (`impact constraint`)?  qdot impulse
 * reports those. */
static bool impulsive(const qd_model *m, size_t i) {
    const char *con = qd_model_reaction_constraint(m, i);
    for (size_t k = 0; k < qd_model_nimpact_constraints(m); k++)
        if (!strcmp(con, qd_model_impact_constraint_name(m, k)))
            return true;
    return false;
}

/* One `reaction` statement at the state, appended.  A reaction that cannot
 * be had (its constraint was eliminated) is a note, not an error: the rest
 * of the output stands. */
static qd_status reaction_at(qd__eom_view *v, const qd_render_opts *o, size_t i,
                             const double *lambda) {
    const qd_model *m = v->m;
    const qd_expr *pt[3];
    double F[3], res;
    for (unsigned k = 0; k < 3; k++)
        pt[k] = qd_model_reaction_point(m, i, k);
    qd_status st = qd_eom_reaction(v->ctx, v->e, qd_model_reaction_constraint(m, i), pt,
                                   o->nstate, o->syms, o->vals, lambda, F, &res);
    if (st == QD_ERR_ARG) {
        if (o->notes)
            qd_buf_printf(o->notes, "reaction %s: %s\n", qd_model_reaction_name(m, i),
                          qd_ctx_message(v->ctx));
        qd_ctx_clear_error(v->ctx);
        return QD_OK;
    }
    size_t j = v->nreact;
    for (unsigned k = 0; st == QD_OK && k < 3; k++)
        if (!(v->react[3 * j + k] = qd_float(v->ctx, F[k])))
            st = qd_ctx_status(v->ctx);
    if (st == QD_OK) {
        v->react_name[j] = qd_model_reaction_name(m, i);
        v->react_res[j] = res;
        v->nreact++;
    }
    return st;
}

static qd_status reactions(qd__eom_view *v, const qd_render_opts *o, const double *lambda) {
    size_t nr = qd_model_nreactions(v->m);
    if (!nr)
        return QD_OK;
    v->react_name = qd__malloc(v->ctx, nr * sizeof *v->react_name);
    v->react = qd__malloc(v->ctx, 3 * nr * sizeof *v->react);
    v->react_res = qd__malloc(v->ctx, nr * sizeof *v->react_res);
    if (!v->react_name || !v->react || !v->react_res)
        return QD_ERR_NOMEM;
    qd_status st = QD_OK;
    for (size_t i = 0; i < nr && st == QD_OK; i++)
        if (!impulsive(v->m, i))
            st = reaction_at(v, o, i, lambda);
    return st;
}

/* The state's coordinates, velocities and t as NAME=VALUE for a message. */
static void state_text(const qd__eom_view *v, const qd_render_opts *o, qd_buf *b) {
    size_t n = v->e->n;
    for (size_t i = 0; i < 2 * n + 1; i++) {
        const qd_expr *s = i < n ? v->e->q[i] : i < 2 * n ? v->e->qd[i - n] : qd_time(v->ctx);
        qd_buf_puts(b, i ? ", " : "");
        qd_print(v->ctx, s, QD_FMT_TEXT, b);
        qd_buf_puts(b, "=");
        qd__render_number(b, qd__render_value(o, s));
    }
}

/* The error of a failed evaluation, said with the state. */
static qd_status failed(qd__eom_view *v, const qd_render_opts *o, qd_status st) {
    if (st == QD_ERR_NOMEM)
        return st;
    qd_buf at = QD_BUF_INIT;
    char why[512];
    snprintf(why, sizeof why, "%s", qd_ctx_message(v->ctx)[0] ? qd_ctx_message(v->ctx)
                                                               : qd_status_str(st));
    state_text(v, o, &at);
    qd_ctx_clear_error(v->ctx);
    if (st == QD_ERR_SINGULAR && v->e->ncon)
        qd_ctx_error(v->ctx, st, "at %s: %s", qd_buf_str(&at), why);
    else if (st == QD_ERR_SINGULAR)
        qd_ctx_error(v->ctx, st, "the mass matrix is singular at %s: the accelerations are not "
                     "determined there", qd_buf_str(&at));
    else
        qd_ctx_error(v->ctx, st, "cannot evaluate the equations at this state: %s", why);
    qd_buf_free(&at);
    return st;
}

/* x at the state, as a number node (T2, T1, T0). */
static const qd_expr *at_state(qd__eom_view *v, const qd_render_opts *o, const qd_expr *x) {
    double val;
    if (qd_eval(v->ctx, x, o->nstate, o->syms, o->vals, &val) != QD_OK)
        return NULL;
    return qd_float(v->ctx, val);
}

qd_status qd__render_eom_numbers(qd__eom_view *v, const qd_render_opts *o) {
    const qd_eom *e = v->e;
    size_t n = e->n, m = e->ncon, total = count_numbers(e);
    qd_status st = qd__render_state(v->ctx, v->m, o, &v->full);
    if (st != QD_OK)
        return st;
    o = &v->full;
    double *num = qd__calloc(v->ctx, total + 1, sizeof *num);
    v->numbers = qd__malloc(v->ctx, (total + 1) * sizeof *v->numbers);
    if (!num || !v->numbers) {
        qd__free(num);
        return QD_ERR_NOMEM;
    }
    double *A = num + n * n + 2 * n, *lambda = A + m * n + m;
    st = qd_eom_eval(v->ctx, e, o->nstate, o->syms, o->vals, num, num + n * n,
                               num + n * n + n, lambda, lambda + m);
    if (st == QD_OK)
        st = constraint_rows(v, o, A);
    if (st == QD_OK)
        st = reactions(v, o, lambda);
    for (size_t i = 0; st == QD_OK && i < total; i++)
        if (!(v->numbers[i] = qd_float(v->ctx, num[i])))
            st = qd_ctx_status(v->ctx);
    for (size_t i = 0; st == QD_OK && i < 3 && v->T[0]; i++)
        if (!(v->T[i] = at_state(v, o, v->T[i])))
            st = qd_ctx_status(v->ctx);
    qd__free(num);
    if (st != QD_OK)
        return failed(v, o, st);
    v->at = &v->full;
    v->M = v->numbers;
    v->f = v->numbers + n * n;
    v->acc = v->numbers + n * n + n;
    v->A = v->acc + n;
    v->b = v->A + m * n;
    v->lambda = v->b + m;
    v->R = v->lambda + m;
    return QD_OK;
}

void qd__render_eom_view_free(qd__eom_view *v) {
    qd__render_state_free(&v->full);
    qd__free(v->numbers);
    qd__free(v->react_name);
    qd__free(v->react);
    qd__free(v->react_res);
}
