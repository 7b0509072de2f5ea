/*
 * src/impulse/exact.c - the impulse in closed form.
 *
 * The saddle-point system of state.c with the state's expressions put in
 * for q, q' and t (the parameters stay symbols) is a linear system with
 * symbolic entries; the mechanics layer's fraction-free elimination
 * (qd_eom_solve, src/mech/solve.c) solves it on a qd_eom that carries it:
 * M as the mass matrix, Qhat as f, the rows as A and the Newton right-hand
 * sides as b, so the velocity change comes back as e->acc and the
 * multipliers as e->mult.  Too big (max_ops) or singular for every value of
 * the parameters: no closed form, and no error (the numbers stand).
 */
#include "impulse_priv.h"

#include "base/mem.h"

typedef struct subst {
    size_t k;
    const qd_expr **from, **to;
} subst;

/* x with the state put in; the velocities by v (n) when not NULL. */
static const qd_expr *at_state(const qd__imp *s, const subst *sb, const qd_expr *x,
                               const qd_expr *const *v) {
    size_t n = s->n;
    for (size_t j = 0; v && j < n; j++)
        sb->to[n + j] = v[j];
    const qd_expr *y = qd_subs(s->ctx, x, sb->k, sb->from, sb->to);
    for (size_t j = 0; v && j < n; j++)
        sb->to[n + j] = s->qd0[j];
    return y;
}

/* The fake qd_eom's M, f, A and b (arrays in one block at M). */
static qd_status build_system(const qd__imp *s, const subst *sb, qd_eom *e) {
    qd_ctx *ctx = s->ctx;
    size_t n = s->n, r = s->nrow;
    const qd_expr **blk = qd__calloc(ctx, n * n + n + r * n + r + 1, sizeof *blk);
    if (!blk)
        return QD_ERR_NOMEM;
    *e = (qd_eom){.n = n, .M = blk, .f = blk + n * n, .ncon = r, .con = s->row,
                  .A = blk + n * n + n, .b = blk + n * n + n + r * n};
    bool ok = true;
    for (size_t i = 0; ok && i < n * n; i++)
        ok = (e->M[i] = qd_simplify(ctx, at_state(s, sb, s->e->M[i], NULL))) != NULL;
    for (size_t j = 0; ok && j < n; j++)
        ok = (e->f[j] = qd_simplify(ctx, at_state(s, sb, qd_model_impulse(s->m, j), NULL))) != NULL;
    for (size_t k = 0; ok && k < r; k++) {
        const qd_expr *c = s->row[k].a0;
        for (size_t j = 0; j < n; j++)
            c = qd_add(ctx, c, qd_mul(ctx, s->A[k * n + j], s->e->qd[j]));
        c = qd_mul(ctx, qd_neg(ctx, qd_add(ctx, qd_int(ctx, 1), s->E[k])), c);
        ok = (e->b[k] = qd_simplify(ctx, at_state(s, sb, c, NULL))) != NULL;
        for (size_t j = 0; ok && j < n; j++)
            ok = (e->A[k * n + j] = qd_simplify(ctx, at_state(s, sb, s->A[k * n + j], NULL))) != NULL;
    }
    return ok ? QD_OK : qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
}

static qd_status results(const qd__imp *s, const subst *sb, qd_eom *e, size_t max_ops,
                         qd_impulse *r) {
    qd_ctx *ctx = s->ctx;
    size_t n = s->n;
    const qd_expr **after = qd__calloc(ctx, n + 1, sizeof *after);
    if (!after)
        return QD_ERR_NOMEM;
    bool ok = true;
    for (size_t j = 0; ok && j < n; j++)
        ok = (after[j] = qd_simplify(ctx, qd_add(ctx, s->qd0[j], e->acc[j]))) != NULL;
    const qd_expr *lost = ok ? qd_sub(ctx, at_state(s, sb, s->T, NULL),
                                      at_state(s, sb, s->T, after))
                             : NULL;
    lost = lost ? qd_simplify(ctx, lost) : NULL;
    if (!lost) {
        qd__free(after);
        return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    }
    bool small = qd_count_ops(lost) <= max_ops;
    for (size_t j = 0; j < n; j++)
        small = small && qd_count_ops(after[j]) <= max_ops;
    if (!small) { /* past the caller's limit: the numbers stand */
        qd__free(after);
        return QD_OK;
    }
    r->qd_after_exact = after;
    r->mult_exact = e->mult;
    e->mult = NULL;
    r->energy_lost_exact = lost;
    r->exact = true;
    return QD_OK;
}

qd_status qd__imp_exact(const qd__imp *s, size_t max_ops, qd_impulse *r) {
    qd_ctx *ctx = s->ctx;
    size_t n = s->n, k = 2 * n + 1;
    const qd_expr **from = qd__calloc(ctx, 2 * k, sizeof *from);
    if (!from)
        return QD_ERR_NOMEM;
    subst sb = {k, from, from + k};
    for (size_t j = 0; j < n; j++) {
        from[j] = s->e->q[j], sb.to[j] = s->q0[j];
        from[n + j] = s->e->qd[j], sb.to[n + j] = s->qd0[j];
    }
    from[2 * n] = qd_time(ctx), sb.to[2 * n] = s->t0;
    qd_eom e = {0};
    qd_status st = build_system(s, &sb, &e);
    if (st == QD_OK) {
        st = qd_eom_solve(ctx, &e, max_ops);
        if (st == QD_OK)
            st = results(s, &sb, &e, max_ops, r);
        else /* too big or singular in symbols: the numbers stand */
            st = qd__ctx_recover(ctx) ? QD_OK : QD_ERR_NOMEM;
    }
    qd__free(e.acc);
    qd__free(e.mult);
    qd__free(e.M); /* the block of M, f, A and b */
    qd__free(from);
    if (st == QD_ERR_NOMEM && !qd__ctx_nomem(ctx))
        qd_ctx_error(ctx, st, "out of memory solving an impulse in closed form");
    return st;
}
