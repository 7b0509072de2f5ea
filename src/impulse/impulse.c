/*
 * src/impulse/impulse.c - qd_impulse_solve: the velocities just after an
 * impulse, the impulsive multipliers and reactions, the energies, the
 * theorems that apply and the closed forms (qdot/impulse.h).
 *
 * The steps are the files of this module: rows.c (the system in symbols),
 * state.c (in numbers, and the solve), theorems.c, collision.c, exact.c.
 * The impulsive reaction at a point is the mechanics layer's
 * qd_eom_reaction on a view of the rows: an impulse does virtual "action"
 * exactly as a force does virtual work (Byerly art. 26), so the same
 * least-squares J^T F = Lambda_k a_k gives the Cartesian impulse.
 */
#include "impulse_priv.h"

#include "base/mem.h"
#include "../base/args.h"

#include <stdio.h>
#include <string.h>

void qd_impulse_free(qd_impulse *r) {
    if (!r)
        return;
    qd__free((void *)r->q);
    qd__free(r->qd_before);
    qd__free(r->qd_after);
    qd__free(r->Qhat);
    qd__free(r->R);
    qd__free(r->mult);
    for (size_t k = 0; r->mult_name && k < r->nmult; k++)
        qd__free((void *)r->mult_name[k]);
    qd__free(r->mult_name);
    qd__free(r->redundant);
    qd__free(r->react_name);
    qd__free(r->react);
    qd__free(r->qd_after_exact);
    qd__free(r->mult_exact);
    *r = (qd_impulse){0};
}

static char *mult_name(qd_ctx *ctx, const char *con) {
    size_t len = strlen(con) + sizeof "Lambda_";
    char *s = qd__malloc(ctx, len);
    if (s)
        snprintf(s, len, "Lambda_%s", con);
    return s;
}

static qd_status alloc_result(const qd__imp *s, qd_impulse *r) {
    qd_ctx *ctx = s->ctx;
    size_t n = s->n + 1, m = s->nrow + 1, nr = qd_model_nreactions(s->m) + 1;
    const qd_expr **q = qd__calloc(ctx, n, sizeof *q);
    r->q = q;
    r->qd_before = qd__calloc(ctx, n, sizeof *r->qd_before);
    r->qd_after = qd__calloc(ctx, n, sizeof *r->qd_after);
    r->Qhat = qd__calloc(ctx, n, sizeof *r->Qhat);
    r->R = qd__calloc(ctx, n, sizeof *r->R);
    r->mult = qd__calloc(ctx, m, sizeof *r->mult);
    r->mult_name = qd__calloc(ctx, m, sizeof *r->mult_name);
    r->redundant = qd__calloc(ctx, m, sizeof *r->redundant);
    r->react_name = qd__calloc(ctx, nr, sizeof *r->react_name);
    r->react = qd__calloc(ctx, nr, sizeof *r->react);
    bool ok = q && r->qd_before && r->qd_after && r->Qhat && r->R && r->mult && r->mult_name &&
              r->redundant && r->react_name && r->react;
    r->n = s->n;
    r->nmult = ok ? s->nrow : 0;
    for (size_t k = 0; ok && k < s->nrow; k++)
        ok = (r->mult_name[k] = mult_name(ctx, s->row[k].name)) != NULL;
    for (size_t j = 0; ok && j < s->n; j++)
        q[j] = s->e->q[j];
    if (!ok)
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory solving an impulse");
    return ok ? QD_OK : QD_ERR_NOMEM;
}

/* The index of the row named con, or nrow. */
static size_t find_row(const qd__imp *s, const char *con) {
    size_t k = 0;
    while (k < s->nrow && strcmp(s->row[k].name, con))
        k++;
    return k;
}

static qd_status reactions(const qd__imp *s, qd_impulse *r) {
    qd_eom view = qd__imp_view(s);
    size_t nr = qd_model_nreactions(s->m);
    for (size_t i = 0; i < nr; i++) {
        const char *con = qd_model_reaction_constraint(s->m, i);
        const qd_expr *p[3];
        for (unsigned c = 0; c < 3; c++)
            p[c] = qd_model_reaction_point(s->m, i, c);
        if (find_row(s, con) == s->nrow) {
            qd_ctx_error(s->ctx, QD_ERR_ARG, "reaction %s: no constraint named %s",
                         qd_model_reaction_name(s->m, i), con);
            return QD_ERR_ARG;
        }
        qd_status st = qd_eom_reaction(s->ctx, &view, con, p, s->nv, s->syms, s->vals, r->mult,
                                       r->react[i], NULL);
        if (st != QD_OK)
            return st;
        r->react_name[i] = qd_model_reaction_name(s->m, i);
    }
    r->nreact = nr;
    return QD_OK;
}

static qd_status solve(const qd__imp *s, qd_impulse *r) {
    size_t n = s->n;
    qd_status st = s->nonquad ? qd__imp_solve_momenta(s, r->qd_after, r->mult)
                              : qd__imp_solve(s, NULL, true, r->qd_after, r->mult, r->redundant);
    if (st != QD_OK)
        return st;
    for (size_t k = 0; k < s->nrow; k++)
        r->nredundant += r->redundant[k];
    memcpy(r->qd_before, s->vals + n, n * sizeof *r->qd_before);
    memcpy(r->Qhat, s->Qhat, n * sizeof *r->Qhat);
    for (size_t j = 0; j < n; j++)
        for (size_t k = 0; k < s->nrow; k++)
            r->R[j] += s->An[k * n + j] * r->mult[k];
    st = qd__imp_energy(s, r->qd_before, &r->T_before);
    if (st == QD_OK)
        st = qd__imp_energy(s, r->qd_after, &r->T_after);
    r->energy_lost = r->T_before - r->T_after;
    return st == QD_OK ? reactions(s, r) : st;
}

qd_status qd_impulse_solve(qd_ctx *ctx, const qd_model *m, const qd_impulse_opts *opts,
                           qd_impulse *out) {
    QD_ARGS_CTX(ctx, ctx && m && out);
    if (out)
        *out = (qd_impulse){0};
    if (!ctx || !m || !out) {
        if (ctx)
            qd_ctx_error(ctx, QD_ERR_ARG, "qd_impulse_solve: NULL argument");
        return QD_ERR_ARG;
    }
    qd__imp s;
    qd_status st = qd__imp_build(ctx, m, &s);
    if (st == QD_OK)
        st = qd__imp_state(&s, opts);
    if (st == QD_OK)
        st = qd__imp_numbers(&s);
    if (st == QD_OK)
        st = alloc_result(&s, out);
    if (st == QD_OK)
        st = solve(&s, out);
    /* the theorems, the Newtonian collision summary and the closed forms
     * rest on M (q'+ - q'-) = ...: not for a non-quadratic L */
    if (st == QD_OK && !s.nonquad)
        st = qd__imp_theorems(&s, out);
    if (st == QD_OK && !s.nonquad)
        st = qd__imp_collision(&s, out);
    if (st == QD_OK && opts && opts->exact && !s.nonquad)
        st = qd__imp_exact(&s, opts->max_ops ? opts->max_ops : 4000, out);
    if (st == QD_OK && qd__ctx_nomem(ctx)) /* a step that ran out and carried on is no success */
        st = QD_ERR_NOMEM;
    qd__imp_free(&s);
    if (st != QD_OK)
        qd_impulse_free(out);
    return st;
}
