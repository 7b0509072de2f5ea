/*
 * src/sym/integrate.c - a small table integrator, enough to integrate the
 * exact Pfaffian forms of mechanics (Desloge ch. 49: phi from
 * sum_j a_j dq_j + a_0 dt once it is exact).
 *
 * Not a Risch integrator: a sum is integrated term by term, a product must
 * be (factors free of x) * (one elementary factor in x), and the elementary
 * factors are x^n and (a x + b)^n (n a number; n = -1 gives log), c^(a x + b)
 * for c free of x, and sin, cos, exp, sinh, cosh, log of (a x + b).  When the
 * input as given does not fit, its expansion is tried once (x (x + 1) is
 * x^2 + x).  Anything else is QD_ERR_ARG: the caller decides what to do
 * without an antiderivative.  Logarithms are written log(u), not log|u|.
 */
#include "node.h"
#include "../base/args.h"

#include <stdlib.h>

/* u = a x + b with a free of x and nonzero: the slope a, else NULL. */
static const qd_expr *slope(qd_ctx *ctx, const qd_expr *u, const qd_expr *x) {
    const qd_expr *a = qd_diff(ctx, u, x);
    if (!a || qd_is_zero(a) || qd_has(a, x))
        return NULL;
    return a;
}

/* The antiderivative of b^n with b linear in x and n a number. */
static const qd_expr *int_pow_linear(qd_ctx *ctx, const qd_expr *b, const qd_expr *n,
                                     const qd_expr *x) {
    const qd_expr *a = slope(ctx, b, x);
    if (!a)
        return NULL;
    const qd_expr *n1 = qd_add(ctx, n, ctx->sym->one);
    if (n1 && qd_is_zero(n1))
        return qd_div(ctx, qd_fn(ctx, QD_LOG, b), a);
    return qd_div(ctx, qd_pow(ctx, b, n1), qd_mul(ctx, a, n1));
}

/* c^u with c free of x, u linear in x: c^u / (a log c). */
static const qd_expr *int_exp_base(qd_ctx *ctx, const qd_expr *e, const qd_expr *x) {
    const qd_expr *a = slope(ctx, e->args[1], x);
    if (!a)
        return NULL;
    return qd_div(ctx, e, qd_mul(ctx, a, qd_fn(ctx, QD_LOG, e->args[0])));
}

static const qd_expr *int_func(qd_ctx *ctx, const qd_expr *e, const qd_expr *x) {
    if (e->nargs != 1)
        return NULL;
    const qd_expr *u = e->args[0], *a = slope(ctx, u, x), *f;
    if (!a)
        return NULL;
    switch ((qd_func)e->tag) {
    case QD_SIN: f = qd_neg(ctx, qd_fn(ctx, QD_COS, u)); break;
    case QD_COS: f = qd_fn(ctx, QD_SIN, u); break;
    case QD_EXP: f = e; break;
    case QD_SINH: f = qd_fn(ctx, QD_COSH, u); break;
    case QD_COSH: f = qd_fn(ctx, QD_SINH, u); break;
    /* u log(u) - u: by parts, the generating functions' p log(p) (Desloge
     * ch. 84, seed C T27) */
    case QD_LOG: f = qd_sub(ctx, qd_mul(ctx, u, e), u); break;
    default: return NULL;
    }
    return qd_div(ctx, f, a);
}

/* One elementary factor f that depends on x. */
static const qd_expr *int_factor(qd_ctx *ctx, const qd_expr *f, const qd_expr *x) {
    if (f == x)
        return qd_mul(ctx, ctx->sym->half, qd_powi(ctx, x, 2));
    if (f->kind == QD_FUNC)
        return int_func(ctx, f, x);
    if (f->kind != QD_POW)
        return NULL;
    const qd_expr *b = f->args[0], *n = f->args[1];
    if (!qd_has(n, x))
        return qd__is_num(n) ? int_pow_linear(ctx, b, n, x) : NULL;
    return qd_has(b, x) ? NULL : int_exp_base(ctx, f, x);
}

/* A product: the factors free of x times one elementary factor. */
static const qd_expr *int_mul(qd_ctx *ctx, const qd_expr *e, const qd_expr *x) {
    const qd_expr *dep = NULL, *rest = ctx->sym->one;
    for (size_t i = 0; i < e->nargs; i++) {
        const qd_expr *f = e->args[i];
        if (!qd_has(f, x)) {
            rest = qd_mul(ctx, rest, f);
        } else if (dep) {
            return NULL;
        } else {
            dep = f;
        }
    }
    const qd_expr *r = int_factor(ctx, dep, x);
    return r ? qd_mul(ctx, rest, r) : NULL;
}

/* The antiderivative of e as it stands, or NULL (nothing recorded). */
static const qd_expr *int_expr(qd_ctx *ctx, const qd_expr *e, const qd_expr *x) {
    if (!qd_has(e, x))
        return qd_mul(ctx, e, x);
    if (e->kind == QD_MUL)
        return int_mul(ctx, e, x);
    if (e->kind != QD_ADD)
        return int_factor(ctx, e, x);
    size_t n = e->nargs;
    const qd_expr **parts = qd__malloc(ctx, n * sizeof *parts), *r = NULL;
    if (!parts) {
        qd__oom(ctx);
        return NULL;
    }
    size_t i = 0;
    for (; i < n; i++)
        if (!(parts[i] = int_expr(ctx, e->args[i], x)))
            break;
    if (i == n)
        r = qd_add_n(ctx, n, parts);
    qd__free(parts);
    return r;
}

const qd_expr *qd_integrate(qd_ctx *ctx, const qd_expr *e, const qd_expr *x) {
    QD_ARGS(NULL, ctx && e && x);
    if (!e || !x)
        return NULL;
    if (x->kind != QD_SYMBOL) {
        qd_ctx_error(ctx, QD_ERR_ARG, "can only integrate with respect to a symbol");
        return NULL;
    }
    const qd_expr *r = int_expr(ctx, e, x);
    if (!r && ctx->status == QD_OK) {
        const qd_expr *ex = qd_expand(ctx, e);
        if (ex && ex != e)
            r = int_expr(ctx, ex, x);
    }
    if (!r && ctx->status == QD_OK)
        qd_ctx_error(ctx, QD_ERR_ARG, "no antiderivative in closed form with respect to %s",
                     x->u.sym.name);
    return r;
}
