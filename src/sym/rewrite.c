/*
 * src/sym/rewrite.c - the identities qd_simplify tries on a second path
 * (issue 33), each valid wherever the input is defined (every symbol real):
 *   tan(x) = sin(x)/cos(x)             so 1 + tan^2 = 1/cos^2 and
 *                                       cos^2 (1 + tan^2) = 1 follow from
 *                                       sin^2 + cos^2 = 1;
 *   exp(a)^k = exp(k a), exp(a) exp(b) = exp(a + b);
 *   sqrt(a) sqrt(b) = sqrt(a b), and 1/(sqrt(a) sqrt(b)) = 1/sqrt(a b):
 *       where both roots are real, a, b >= 0 (a real root of a negative
 *       is undefined), the product under one root is expanded, so
 *       sqrt(2Q) sqrt(1 - K^2 q^2/(2Q)) = sqrt(2Q - K^2 q^2).  The merged
 *       root is defined on more (a, b < 0): the result equals the input
 *       on the input's domain only, so qd_zero_test checks each point in
 *       the domain of the expression as given (src/sym/certify.c).
 *       Merging only under known signs would lose the oscillator's F1,
 *       whose Q is not known positive in `canonical --generator`.
 * The rewritten expression goes through the whole pipeline beside the
 * original; the shorter result wins, so no rule makes anything longer.
 */
#include "node.h"

#include <stdlib.h>

static bool is_exp(const qd_expr *f) { return f->kind == QD_FUNC && f->tag == QD_EXP; }

/* exponent 1/2 (sign 1) or -1/2 (sign -1) */
static int half_sign(const qd_expr *f) {
    if (f->kind != QD_POW || f->args[1]->kind != QD_RATIONAL)
        return 0;
    long n, d;
    if (!qd_rational_get(f->args[1], &n, &d) || d != 2 || (n != 1 && n != -1))
        return 0;
    return (int)n;
}

/* A B^(k/2) with A = c B, c a number: c B^(k/2 + 1) (the product
 * -2 (2Q - K^2 q^2)/sqrt(2Q - K^2 q^2) is -2 sqrt(2Q - K^2 q^2)). */
static const qd_expr *absorb_root(qd_ctx *ctx, const qd_expr *e) {
    for (size_t i = 0; i < e->nargs; i++) {
        const qd_expr *r = e->args[i];
        if (r->kind != QD_POW || r->args[0]->kind != QD_ADD || r->args[1]->kind != QD_RATIONAL ||
            qd__is_num(r->args[1]) == false)
            continue;
        long n, d;
        if (!qd_rational_get(r->args[1], &n, &d) || d != 2)
            continue;
        for (size_t j = 0; j < e->nargs; j++) {
            const qd_expr *a = e->args[j];
            if (a->kind != QD_ADD || a->nargs != r->args[0]->nargs)
                continue;
            const qd_expr *c = qd_cancel(ctx, qd_div(ctx, a, r->args[0]));
            if (!c || !qd__is_num(c))
                continue;
            const qd_expr *rest = qd_mul(ctx, c, qd_pow(ctx, r->args[0], qd_rat(ctx, n + 2, 2)));
            for (size_t k = 0; k < e->nargs; k++)
                if (k != i && k != j)
                    rest = qd_mul(ctx, rest, e->args[k]);
            return rest;
        }
    }
    return e;
}

static const qd_expr *merge_mul(qd_ctx *ctx, const qd_expr *e) {
    e = absorb_root(ctx, e);
    if (!e || e->kind != QD_MUL)
        return e;
    size_t nexp = 0, nroot[2] = {0, 0};
    for (size_t i = 0; i < e->nargs; i++) {
        const qd_expr *f = e->args[i];
        nexp += is_exp(f);
        int s = half_sign(f);
        if (s)
            nroot[s > 0]++;
    }
    if (nexp < 2 && nroot[0] < 2 && nroot[1] < 2)
        return e;
    const qd_expr *sum = qd_int(ctx, 0), *under[2] = {qd_int(ctx, 1), qd_int(ctx, 1)};
    const qd_expr *rest = qd_int(ctx, 1);
    for (size_t i = 0; i < e->nargs; i++) {
        const qd_expr *f = e->args[i];
        int s = half_sign(f);
        if (nexp >= 2 && is_exp(f))
            sum = qd_add(ctx, sum, f->args[0]);
        else if (s && nroot[s > 0] >= 2)
            under[s > 0] = qd_mul(ctx, under[s > 0], f->args[0]);
        else
            rest = qd_mul(ctx, rest, f);
    }
    if (nexp >= 2)
        rest = qd_mul(ctx, rest, qd_fn(ctx, QD_EXP, sum));
    for (int k = 0; k < 2; k++)
        if (nroot[k] >= 2) {
            const qd_expr *u = qd_cancel(ctx, qd_expand(ctx, under[k]));
            rest = qd_mul(ctx, rest, qd_pow(ctx, u, qd_rat(ctx, k ? 1 : -1, 2)));
        }
    return rest;
}

static const qd_expr *post(qd_ctx *ctx, const qd_expr *e, void *data) {
    (void)data;
    if (!e)
        return NULL;
    switch ((qd_kind)e->kind) {
    case QD_FUNC:
        if (e->tag == QD_TAN)
            return qd_div(ctx, qd_fn(ctx, QD_SIN, e->args[0]), qd_fn(ctx, QD_COS, e->args[0]));
        return e;
    case QD_POW:
        if (is_exp(e->args[0]))
            return qd_fn(ctx, QD_EXP, qd_mul(ctx, e->args[1], e->args[0]->args[0]));
        return e;
    case QD_MUL: return merge_mul(ctx, e);
    default: return e;
    }
}

/* Does e use tan, exp or a square root (anything post may change)? */
static bool wants(const qd_expr *e, qd__ptrmap *seen) {
    if (!e->nargs || qd__ptrmap_has(seen, e))
        return false;
    if ((e->kind == QD_FUNC && (e->tag == QD_TAN || e->tag == QD_EXP)) || half_sign(e))
        return true;
    for (size_t i = 0; i < e->nargs; i++)
        if (wants(e->args[i], seen))
            return true;
    qd__ptrmap_put(seen, e, (void *)e);
    return false;
}

const qd_expr *qd__rewrite_identities(qd_ctx *ctx, const qd_expr *e) {
    qd__ptrmap seen = QD_PTRMAP_AL(qd__ctx_allocator(ctx));
    bool w = wants(e, &seen);
    qd__ptrmap_free(&seen);
    if (!w)
        return e;
    qd__ptrmap memo = QD_PTRMAP_AL(qd__ctx_allocator(ctx));
    const qd_expr *r = qd__map(ctx, e, &memo, post, NULL);
    qd__ptrmap_free(&memo);
    return r;
}
