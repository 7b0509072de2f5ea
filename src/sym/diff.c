/*
 * src/sym/diff.c - derivatives: partial (with respect to a symbol) and the
 * total time derivative over the jet.
 *
 * Both are the same walk: a derivation is fixed by what it does to symbols.
 * d/dx sends x to 1 and other symbols to 0; d/dt sends t to 1, each jet
 * symbol q^(k) to q^(k+1), and constants to 0, which is exactly
 * d/dt = d/dt|explicit + sum q' d/dq + sum q'' d/dq' + ...
 * One small rule per node kind, memoized over the DAG so that a shared
 * subexpression is differentiated once.
 */
#include "node.h"
#include "../base/args.h"

#include <stdlib.h>

typedef struct deriv {
    qd_ctx *ctx;
    const qd_expr *x;  /* the symbol, or NULL for d/dt */
    qd__ptrmap memo;
} deriv;

static const qd_expr *d(deriv *dv, const qd_expr *e);

static const qd_expr *d_symbol(deriv *dv, const qd_expr *s) {
    qd_ctx *ctx = dv->ctx;
    if (dv->x)
        return s == dv->x ? ctx->sym->one : ctx->sym->zero;
    if (s->tag == QD_ROLE_TIME)
        return ctx->sym->one;
    if (s->tag == QD_ROLE_COORD)
        return qd_jet(ctx, s, s->order + 1u);
    return ctx->sym->zero;
}

static const qd_expr *d_mul(deriv *dv, const qd_expr *e) {
    qd_ctx *ctx = dv->ctx;
    size_t n = e->nargs;
    const qd_expr **terms = qd__malloc(ctx, n * sizeof *terms), **fs = qd__malloc(ctx, n * sizeof *fs);
    const qd_expr *r = NULL;
    if (!terms || !fs) {
        qd__oom(ctx);
        goto done;
    }
    size_t m = 0;
    for (size_t i = 0; i < n; i++) {
        const qd_expr *di = d(dv, e->args[i]);
        if (!di)
            goto done;
        if (qd_is_zero(di))
            continue;
        for (size_t j = 0; j < n; j++)
            fs[j] = j == i ? di : e->args[j];
        terms[m++] = qd_mul_n(ctx, n, fs);
    }
    r = qd_add_n(ctx, m, terms);
done:
    qd__free(terms);
    qd__free(fs);
    return r;
}

static const qd_expr *d_pow(deriv *dv, const qd_expr *e) {
    qd_ctx *ctx = dv->ctx;
    const qd_expr *b = e->args[0], *x = e->args[1];
    const qd_expr *db = d(dv, b), *dx = d(dv, x);
    if (!db || !dx)
        return NULL;
    if (qd_is_zero(dx)) /* (b^x)' = x b^(x-1) b' */
        return qd_mul_n(ctx, 3, (const qd_expr *[]){x, qd_pow(ctx, b, qd_sub(ctx, x, ctx->sym->one)), db});
    /* (b^x)' = b^x (x' log b + x b'/b) */
    const qd_expr *inner = qd_add(ctx, qd_mul(ctx, dx, qd_fn(ctx, QD_LOG, b)),
                                  qd_mul_n(ctx, 3, (const qd_expr *[]){x, db, qd_powi(ctx, b, -1)}));
    return qd_mul(ctx, e, inner);
}

/* d f(a)/da for the one-argument built-ins. */
static const qd_expr *outer(qd_ctx *ctx, qd_func f, const qd_expr *a, const qd_expr *fa) {
    const qd_expr *one = ctx->sym->one;
    switch (f) {
    case QD_SIN: return qd_fn(ctx, QD_COS, a);
    case QD_COS: return qd_neg(ctx, qd_fn(ctx, QD_SIN, a));
    case QD_TAN: return qd_add(ctx, one, qd_powi(ctx, fa, 2));
    case QD_ASIN: return qd_pow(ctx, qd_sub(ctx, one, qd_powi(ctx, a, 2)), qd_rat(ctx, -1, 2));
    case QD_ACOS:
        return qd_neg(ctx, qd_pow(ctx, qd_sub(ctx, one, qd_powi(ctx, a, 2)), qd_rat(ctx, -1, 2)));
    case QD_ATAN: return qd_powi(ctx, qd_add(ctx, one, qd_powi(ctx, a, 2)), -1);
    case QD_SINH: return qd_fn(ctx, QD_COSH, a);
    case QD_COSH: return qd_fn(ctx, QD_SINH, a);
    case QD_TANH: return qd_sub(ctx, one, qd_powi(ctx, fa, 2));
    case QD_EXP: return fa;
    case QD_LOG: return qd_powi(ctx, a, -1);
    case QD_ABS: return qd_fn(ctx, QD_SIGN, a);
    case QD_SIGN:
    case QD_STEP: return ctx->sym->zero; /* almost everywhere: no delta function in the kernel */
    default: return NULL;
    }
}

static const qd_expr *d_func(deriv *dv, const qd_expr *e) {
    qd_ctx *ctx = dv->ctx;
    if (e->tag == QD_ATAN2) { /* (x y' - y x') / (x^2 + y^2) */
        const qd_expr *y = e->args[0], *x = e->args[1];
        const qd_expr *num = qd_sub(ctx, qd_mul(ctx, x, d(dv, y)), qd_mul(ctx, y, d(dv, x)));
        return qd_div(ctx, num, qd_add(ctx, qd_powi(ctx, x, 2), qd_powi(ctx, y, 2)));
    }
    const qd_expr *da = d(dv, e->args[0]);
    if (!da || qd_is_zero(da))
        return da;
    return qd_mul(ctx, outer(ctx, (qd_func)e->tag, e->args[0], e), da);
}

/* Chain rule through a user function: sum_i f_{S,i}(args) * args_i'. */
static const qd_expr *d_user(deriv *dv, const qd_expr *e) {
    qd_ctx *ctx = dv->ctx;
    size_t n = e->nargs, ns = e->kind == QD_UDERIV ? e->u.fn.nslots : 0;
    if (ns >= 64) {
        qd_ctx_error(ctx, QD_ERR_TOOBIG, "derivative of %s of order above 64", e->u.fn.name);
        return NULL;
    }
    unsigned slots[64];
    for (size_t k = 0; k < ns; k++)
        slots[k] = e->u.fn.slots[k];
    const qd_expr *sum = ctx->sym->zero;
    for (size_t i = 0; i < n && sum; i++) {
        const qd_expr *da = d(dv, e->args[i]);
        if (!da)
            return NULL;
        if (qd_is_zero(da))
            continue;
        slots[ns] = (unsigned)i;
        const qd_expr *fi = qd_uderiv(ctx, e->u.fn.name, ns + 1, slots, n, e->args);
        sum = qd_add(ctx, sum, qd_mul(ctx, fi, da));
    }
    return sum;
}

static const qd_expr *d(deriv *dv, const qd_expr *e) {
    if (!e)
        return NULL;
    const qd_expr *r = qd__ptrmap_get(&dv->memo, e);
    if (r)
        return r;
    qd_ctx *ctx = dv->ctx;
    switch ((qd_kind)e->kind) {
    case QD_RATIONAL:
    case QD_FLOAT:
    case QD_CONSTANT:
        return ctx->sym->zero;
    case QD_SYMBOL:
        return d_symbol(dv, e);
    case QD_ADD: {
        const qd_expr **ts = qd__malloc(ctx, e->nargs * sizeof *ts);
        if (!ts) {
            qd__oom(ctx);
            return NULL;
        }
        for (size_t i = 0; i < e->nargs; i++)
            ts[i] = d(dv, e->args[i]);
        r = qd_add_n(ctx, e->nargs, ts);
        qd__free(ts);
        break;
    }
    case QD_MUL: r = d_mul(dv, e); break;
    case QD_POW: r = d_pow(dv, e); break;
    case QD_FUNC: r = d_func(dv, e); break;
    case QD_UFUNC:
    case QD_UDERIV: r = d_user(dv, e); break;
    }
    if (r && !qd__ptrmap_put(&dv->memo, e, (void *)r)) {
        qd__oom(ctx);
        return NULL;
    }
    return r;
}

static const qd_expr *derive(qd_ctx *ctx, const qd_expr *e, const qd_expr *x) {
    if (!e)
        return NULL;
    deriv dv = {ctx, x, QD_PTRMAP_AL(qd__ctx_allocator(ctx))};
    const qd_expr *r = d(&dv, e);
    qd__ptrmap_free(&dv.memo);
    return r;
}

const qd_expr *qd_diff(qd_ctx *ctx, const qd_expr *e, const qd_expr *x) {
    QD_ARGS(NULL, ctx && e && x);
    if (!x)
        return NULL;
    if (x->kind != QD_SYMBOL) {
        qd_ctx_error(ctx, QD_ERR_ARG, "a derivative is taken with respect to a symbol");
        return NULL;
    }
    return derive(ctx, e, x);
}

const qd_expr *qd_diff_n(qd_ctx *ctx, const qd_expr *e, const qd_expr *x, unsigned n) {
    QD_ARGS(NULL, ctx && e && x);
    for (unsigned i = 0; i < n && e; i++)
        e = qd_diff(ctx, e, x);
    return e;
}

const qd_expr *qd_dt(qd_ctx *ctx, const qd_expr *e) { QD_ARGS(NULL, ctx && e); return derive(ctx, e, NULL); }
