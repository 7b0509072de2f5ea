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
static bool has_quotient(const qd_expr *e, qd_ptrmap *seen) {
    if (!e->nargs || qd_ptrmap_has(seen, e))
        return false;
    if (e->kind == QD_POW && qd__is_num(e->args[1]) && qd_number_sign(e->args[1]) < 0)
        return true;
    for (size_t i = 0; i < e->nargs; i++)
        if (has_quotient(e->args[i], seen))
            return true;
    qd_ptrmap_put(seen, e, (void *)e);
    return false;
}

typedef struct best {
    const qd_expr *e;
    size_t ops;
    bool failed;
} best;

static void consider_if(best *b, const qd_expr *cand, bool strict) {
    if (!cand) {
        b->failed = true;
        return;
    }
    if (cand == b->e)
        return;
    size_t n = qd_count_ops(cand);
    if (n < b->ops || (!strict && n == b->ops)) {
        b->e = cand;
        b->ops = n;
    }
}

static void consider(best *b, const qd_expr *cand) {
    consider_if(b, cand, false);
}

/* Is there a sum anywhere in e?  Every stage works on sums (expand
 * distributes over them, trigsimp and factoring rewrite them, cancel needs
 * one in a numerator or denominator to find a common factor): a sum-free
 * expression is canonical already. */
static bool has_sum(const qd_expr *e, qd_ptrmap *seen) {
    if (e->kind == QD_ADD)
        return true;
    if (!e->nargs || qd_ptrmap_has(seen, e))
        return false;
    for (size_t i = 0; i < e->nargs; i++)
        if (has_sum(e->args[i], seen))
            return true;
    qd_ptrmap_put(seen, e, (void *)e);
    return false;
}

const qd_expr *qd_simplify(qd_ctx *ctx, const qd_expr *e) {
    QD_ARGS(NULL, ctx && e);
    if (!e)
        return NULL;
    qd_ptrmap seen0 = QD_PTRMAP_AL(qd__ctx_allocator(ctx));
    bool sums = has_sum(e, &seen0);
    qd_ptrmap_free(&seen0);
    if (!sums)
        return e;
    best b = {e, qd_count_ops(e), false};
    const qd_expr *t = qd_trigsimp(ctx, e);
    consider(&b, t);
    consider(&b, qd_factor_terms(ctx, t));

    const qd_expr *x = qd_expand(ctx, e);
    consider(&b, x);
    x = qd_trigsimp(ctx, x);
    consider(&b, x);
    qd_ptrmap seen = QD_PTRMAP_AL(qd__ctx_allocator(ctx));
    bool quotient = x && has_quotient(x, &seen);
    qd_ptrmap_free(&seen);
    const qd_expr *c = NULL;
    if (quotient) {
        c = qd_cancel(ctx, x);
        consider(&b, c);
        consider(&b, qd_factor_terms(ctx, qd_trigsimp(ctx, c)));
    }
    consider(&b, qd_factor_terms(ctx, x));
    if (b.failed)
        return NULL;

    qd_ptrmap memo = QD_PTRMAP_AL(qd__ctx_allocator(ctx));
    if (c) {
        consider_if(&b, qd__factor_polys(ctx, x, &memo), true);
        consider_if(&b, qd__factor_polys(ctx, c, &memo), true);
    }
    consider_if(&b, qd__factor_polys(ctx, b.e, &memo), true);
    qd_ptrmap_free(&memo);
    return b.failed ? NULL : b.e;
}
