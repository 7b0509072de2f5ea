/*
 * src/codegen/angles.c - sines and cosines of angle differences, expanded.
 *
 * The n-link pendulum's equations hold cos(theta_j - theta_k) and
 * sin(theta_j - theta_k) for every pair: n(n-1) calls to the maths library,
 * which dominate the evaluation (a call costs tens of multiplications).
 * With sin(a + b) = sin a cos b + cos a sin b and cos(a + b) = cos a cos b -
 * sin a sin b the same numbers need the 2n sines and cosines of the single
 * angles only.  The rewrite is applied when it lowers the count of distinct
 * calls over every output of the file, so a lone sin(theta + phi) is kept.
 * The absolute error of the expanded form is a few ulps of 1, not of the
 * (possibly small) result: fine for equations of motion, whose other terms
 * are of order one.
 */
#include "cg.h"
#include "sym/node.h"

#include <stdlib.h>

/* A term usable in the expansion: a symbol, or -1 times one; *sym gets it. */
static bool plain_term(const qd_expr *t, const qd_expr **sym) {
    if (t->kind == QD_SYMBOL) {
        *sym = t;
        return true;
    }
    long num, den;
    if (t->kind == QD_MUL && t->nargs == 2 && t->args[1]->kind == QD_SYMBOL &&
        qd_rational_get(t->args[0], &num, &den) && num == -1 && den == 1) {
        *sym = t->args[1];
        return true;
    }
    return false;
}

/* sin or cos of a two-term sum of plain terms. */
static bool expandable(const qd_expr *e) {
    const qd_expr *a = NULL, *b = NULL;
    if (e->kind != QD_FUNC || (e->tag != QD_SIN && e->tag != QD_COS))
        return false;
    const qd_expr *x = e->args[0];
    return x->kind == QD_ADD && x->nargs == 2 && plain_term(x->args[0], &a) &&
           plain_term(x->args[1], &b);
}

typedef struct census {
    qd__ptrmap seen;     /* every node visited */
    qd__ptrmap single;   /* sin/cos nodes of a bare symbol */
    qd__ptrmap angles;   /* symbols in expandable arguments */
    size_t nsingle, npair, nangles;
    bool oom;
} census;

static void visit(census *c, const qd_expr *e) {
    if (qd__ptrmap_has(&c->seen, e))
        return;
    if (!qd__ptrmap_put(&c->seen, e, (void *)e)) {
        c->oom = true;
        return;
    }
    for (size_t i = 0; i < e->nargs; i++)
        visit(c, e->args[i]);
    if (e->kind == QD_FUNC && (e->tag == QD_SIN || e->tag == QD_COS) &&
        e->args[0]->kind == QD_SYMBOL) {
        c->nsingle++;
        c->oom |= !qd__ptrmap_put(&c->single, e, (void *)e);
    } else if (expandable(e)) {
        c->npair++;
        for (size_t i = 0; i < 2; i++) {
            const qd_expr *s = NULL;
            if (!plain_term(e->args[0]->args[i], &s))
                continue;
            if (!qd__ptrmap_has(&c->angles, s)) {
                c->nangles++;
                c->oom |= !qd__ptrmap_put(&c->angles, s, (void *)s);
            }
        }
    }
}

/* Calls after the rewrite: the single-angle calls there are, plus sin and
 * cos of every angle of an expanded argument that is not among them. */
static size_t calls_after(qd_ctx *ctx, const census *c) {
    size_t extra = 0;
    for (size_t i = 0; i < c->angles.cap; i++) {
        const qd_expr *s = c->angles.slots[i].key;
        if (!s)
            continue;
        extra += !qd__ptrmap_has(&c->single, qd_fn(ctx, QD_SIN, s));
        extra += !qd__ptrmap_has(&c->single, qd_fn(ctx, QD_COS, s));
    }
    return c->nsingle + extra;
}

static const qd_expr *sc(qd_ctx *ctx, qd_func f, const qd_expr *t) {
    return qd_fn(ctx, f, t);
}

static const qd_expr *rewrite(qd_ctx *ctx, const qd_expr *e, void *data) {
    (void)data;
    if (!expandable(e))
        return e;
    const qd_expr *a = e->args[0]->args[0], *b = e->args[0]->args[1];
    const qd_expr *sa = sc(ctx, QD_SIN, a), *ca = sc(ctx, QD_COS, a);
    const qd_expr *sb = sc(ctx, QD_SIN, b), *cb = sc(ctx, QD_COS, b);
    if (e->tag == QD_SIN)
        return qd_add(ctx, qd_mul(ctx, sa, cb), qd_mul(ctx, ca, sb));
    return qd_sub(ctx, qd_mul(ctx, ca, cb), qd_mul(ctx, sa, sb));
}

qd_status qd__cg_angle_sums(qd_ctx *ctx, size_t n, const qd_expr **exprs, bool *applied) {
    census c = {QD_PTRMAP_AL(qd__ctx_allocator(ctx)), QD_PTRMAP_AL(qd__ctx_allocator(ctx)), QD_PTRMAP_AL(qd__ctx_allocator(ctx)), 0, 0, 0, false};
    *applied = false;
    for (size_t i = 0; i < n && !c.oom; i++)
        visit(&c, exprs[i]);
    qd_status st = c.oom ? QD_ERR_NOMEM : QD_OK;
    if (st == QD_OK && c.npair && calls_after(ctx, &c) < c.nsingle + c.npair) {
        qd__ptrmap memo = QD_PTRMAP_AL(qd__ctx_allocator(ctx));
        for (size_t i = 0; i < n && st == QD_OK; i++) {
            exprs[i] = qd__map(ctx, exprs[i], &memo, rewrite, NULL);
            if (!exprs[i])
                st = qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
        }
        qd__ptrmap_free(&memo);
        *applied = st == QD_OK;
    }
    if (c.oom)
        qd__oom(ctx);
    qd__ptrmap_free(&c.seen);
    qd__ptrmap_free(&c.single);
    qd__ptrmap_free(&c.angles);
    return st;
}
