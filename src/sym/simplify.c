/*
 * src/sym/simplify.c - the simplifier the mechanics layer runs on every
 * equation entry.
 *
 * A pipeline, expand -> trigsimp -> cancel (only where there is a
 * denominator) -> factor_terms, and a shorter path that skips the expansion
 * (trigsimp -> factor_terms on the input as it is).  Every stage keeps the
 * value where the input is defined; the result is the candidate with the
 * fewest operations by qd_count_ops, the input itself among them, so the
 * simplifier never makes an expression longer.  On ties the later, more
 * processed candidate wins.
 *
 * Then polynomial factorization (factor_poly.c) of the sums in the expanded
 * form, in the cancelled quotient and in the best candidate so far: a
 * factored candidate must be strictly shorter, since factoring is not
 * "more processed" in any sense a reader prefers on a tie ((a - b)*(a + b)
 * against a^2 - b^2).
 */
#include "factor_poly.h"
#include "../base/args.h"

/* A negative numeric power anywhere: a quotient cancel may shorten. */
static bool has_quotient(const qd_expr *e, qd__ptrmap *seen) {
    if (!e->nargs || qd__ptrmap_has(seen, e))
        return false;
    if (e->kind == QD_POW && qd__is_num(e->args[1]) && qd_number_sign(e->args[1]) < 0)
        return true;
    for (size_t i = 0; i < e->nargs; i++)
        if (has_quotient(e->args[i], seen))
            return true;
    qd__ptrmap_put(seen, e, (void *)e);
    return false;
}

typedef struct best {
    const qd_expr *e;
    size_t ops;
    bool nested;
    bool failed;
} best;

/* A quotient inside a denominator, x/(y/x + 1) (issue 33): of two
 * candidates of one length, the one without (x^2/(x + y)) wins. */
static bool nested_walk(const qd_expr *e, bool below, qd__ptrmap *seen) {
    if (!e->nargs || qd__ptrmap_has(&seen[below], e))
        return false;
    bool neg = e->kind == QD_POW && qd__is_num(e->args[1]) && qd_number_sign(e->args[1]) < 0;
    if (neg && below)
        return true;
    for (size_t i = 0; i < e->nargs; i++)
        if (nested_walk(e->args[i], below || neg, seen))
            return true;
    qd__ptrmap_put(&seen[below], e, (void *)e);
    return false;
}

static bool nested_quotient(qd_ctx *ctx, const qd_expr *e) {
    qd__ptrmap seen[2] = {QD_PTRMAP_AL(qd__ctx_allocator(ctx)),
                          QD_PTRMAP_AL(qd__ctx_allocator(ctx))};
    bool r = nested_walk(e, false, seen);
    qd__ptrmap_free(&seen[0]);
    qd__ptrmap_free(&seen[1]);
    return r;
}

static void consider_if(qd_ctx *ctx, best *b, const qd_expr *cand, bool strict) {
    if (!cand) {
        b->failed = true;
        return;
    }
    if (cand == b->e)
        return;
    size_t n = qd_count_ops(cand);
    bool nested = n <= b->ops && nested_quotient(ctx, cand);
    if (n < b->ops || (!strict && n == b->ops && (!nested || b->nested))) {
        b->e = cand;
        b->ops = n;
        b->nested = nested;
    }
}

static void consider(qd_ctx *ctx, best *b, const qd_expr *cand) {
    consider_if(ctx, b, cand, false);
}

/* Is there a sum anywhere in e?  Every stage works on sums (expand
 * distributes over them, trigsimp and factoring rewrite them, cancel needs
 * one in a numerator or denominator to find a common factor): a sum-free
 * expression is canonical already. */
static bool has_sum(const qd_expr *e, qd__ptrmap *seen) {
    if (e->kind == QD_ADD)
        return true;
    if (!e->nargs || qd__ptrmap_has(seen, e))
        return false;
    for (size_t i = 0; i < e->nargs; i++)
        if (has_sum(e->args[i], seen))
            return true;
    qd__ptrmap_put(seen, e, (void *)e);
    return false;
}

/* The pipeline on e, its candidates given to b; the cancelled quotient and
 * the expanded form are returned for the factoring stage. */
static void pipeline(qd_ctx *ctx, const qd_expr *e, best *b, const qd_expr **xout,
                     const qd_expr **cout) {
    const qd_expr *t = qd_trigsimp(ctx, e);
    consider(ctx, b, t);
    consider(ctx, b, qd_factor_terms(ctx, t));

    const qd_expr *x = qd_expand(ctx, e);
    consider(ctx, b, x);
    x = qd_trigsimp(ctx, x);
    consider(ctx, b, x);
    qd__ptrmap seen = QD_PTRMAP_AL(qd__ctx_allocator(ctx));
    bool quotient = x && has_quotient(x, &seen);
    qd__ptrmap_free(&seen);
    const qd_expr *c = NULL;
    if (quotient) {
        c = qd_cancel(ctx, x);
        consider(ctx, b, c);
        consider(ctx, b, qd_factor_terms(ctx, qd_trigsimp(ctx, c)));
    }
    consider(ctx, b, qd_factor_terms(ctx, x));
    *xout = x;
    *cout = c;
}

const qd_expr *qd_simplify(qd_ctx *ctx, const qd_expr *e) {
    QD_ARGS(NULL, ctx && e);
    if (!e)
        return NULL;
    qd__ptrmap seen0 = QD_PTRMAP_AL(qd__ctx_allocator(ctx));
    bool sums = has_sum(e, &seen0);
    qd__ptrmap_free(&seen0);
    const qd_expr *r = qd__rewrite_identities(ctx, e);
    if (!r)
        return NULL;
    if (!sums && r == e)
        return e;
    best b = {e, qd_count_ops(e), nested_quotient(ctx, e), false};
    const qd_expr *x = NULL, *c = NULL, *x2 = NULL, *c2 = NULL;
    if (sums)
        pipeline(ctx, e, &b, &x, &c);
    if (r != e) { /* issue 33: the identities of rewrite.c, on a second path */
        consider(ctx, &b, r);
        pipeline(ctx, r, &b, &x2, &c2);
    }
    if (b.failed)
        return NULL;

    qd__ptrmap memo = QD_PTRMAP_AL(qd__ctx_allocator(ctx));
    if (c) {
        consider_if(ctx, &b, qd__factor_polys(ctx, x, &memo), true);
        consider_if(ctx, &b, qd__factor_polys(ctx, c, &memo), true);
    }
    if (x && r != e) /* the original's factors compete with the rewritten path */
        consider_if(ctx, &b, qd__factor_polys(ctx, x, &memo), true);
    if (c2) {
        consider_if(ctx, &b, qd__factor_polys(ctx, x2, &memo), true);
        consider_if(ctx, &b, qd__factor_polys(ctx, c2, &memo), true);
    }
    consider_if(ctx, &b, qd__factor_polys(ctx, b.e, &memo), true);
    qd__ptrmap_free(&memo);
    if (!b.failed) { /* once more on the result: a factored sum may meet its root */
        const qd_expr *r2 = qd__rewrite_identities(ctx, b.e);
        if (r2 != b.e)
            consider_if(ctx, &b, r2, true);
    }
    return b.failed ? NULL : b.e;
}
