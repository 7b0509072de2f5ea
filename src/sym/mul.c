/*
 * src/sym/mul.c - products in canonical form.
 *
 * A factor is read as (base, exponent): x^2 is (x, 2), sin(a) is (sin(a), 1).
 * Nested products are flattened, numbers folded into one coefficient,
 * factors sorted by base and factors of one base merged by adding
 * exponents (x * x^-1 = 1).  A rational coefficient times a single sum is
 * distributed (2*(x + y) = 2*x + 2*y), which keeps like terms findable.
 */
#include "node.h"
#include "../base/args.h"

#include <stdlib.h>

typedef struct factor {
    const qd_expr *base;
    const qd_expr *exp;  /* NULL for 1 */
    const qd_expr *node;
} factor;

static factor as_factor(const qd_expr *e) {
    factor f = {e, NULL, e};
    if (e->kind == QD_POW) {
        f.base = e->args[0];
        f.exp = e->args[1];
    }
    return f;
}

static int factor_cmp(const void *pa, const void *pb) {
    const factor *a = pa, *b = pb;
    return qd_expr_cmp(a->node, b->node); /* orders by base, then exponent */
}

const qd_expr *qd__mul_raw(qd_ctx *ctx, const qd_expr *coeff, size_t n,
                           const qd_expr *const *factors) {
    qd_expr proto = {0};
    proto.kind = QD_MUL;
    if (!coeff)
        return qd__intern(ctx, &proto, n, factors);
    const qd_expr *stack[16];
    const qd_expr **args = n + 1 <= 16 ? stack : qd__malloc(ctx, (n + 1) * sizeof *args);
    if (!args) {
        qd__oom(ctx);
        return NULL;
    }
    args[0] = coeff;
    for (size_t i = 0; i < n; i++)
        args[i + 1] = factors[i];
    const qd_expr *r = qd__intern(ctx, &proto, n + 1, args);
    if (args != stack)
        qd__free(args);
    return r;
}

static const qd_expr *distribute(qd_ctx *ctx, const qd_expr *c, const qd_expr *sum) {
    const qd_expr **terms = qd__malloc(ctx, sum->nargs * sizeof *terms);
    if (!terms) {
        qd__oom(ctx);
        return NULL;
    }
    for (size_t i = 0; i < sum->nargs; i++)
        terms[i] = qd_mul(ctx, c, sum->args[i]);
    const qd_expr *r = qd_add_n(ctx, sum->nargs, terms);
    qd__free(terms);
    return r;
}

static bool push(qd_ctx *ctx, factor **v, size_t *n, size_t *cap, const qd_expr *e) {
    if (*n == *cap) {
        size_t c = *cap ? *cap * 2 : 16;
        factor *nv = qd__realloc(ctx, *v, c * sizeof *nv);
        if (!nv)
            return false;
        *v = nv;
        *cap = c;
    }
    (*v)[(*n)++] = as_factor(e);
    return true;
}

/* Flatten xs into coefficient and factor list. */
static bool gather(qd_ctx *ctx, size_t n, const qd_expr *const *xs, const qd_expr **coeff,
                   factor **v, size_t *len, size_t *cap) {
    for (size_t i = 0; i < n; i++) {
        const qd_expr *x = xs[i];
        if (qd__is_num(x)) {
            if (!(*coeff = qd__number_mul(ctx, *coeff, x)))
                return false;
        } else if (x->kind == QD_MUL) {
            for (size_t j = 0; j < x->nargs; j++) {
                if (qd__is_num(x->args[j])) {
                    if (!(*coeff = qd__number_mul(ctx, *coeff, x->args[j])))
                        return false;
                } else if (!push(ctx, v, len, cap, x->args[j])) {
                    qd__oom(ctx);
                    return false;
                }
            }
        } else if (!push(ctx, v, len, cap, x)) {
            qd__oom(ctx);
            return false;
        }
    }
    return true;
}

const qd_expr *qd_mul_n(qd_ctx *ctx, size_t n, const qd_expr *const *xs) {
    QD_ARGS(NULL, ctx && (n == 0 || xs));
    for (size_t i = 0; i < n; i++)
        if (!xs[i])
            return NULL;
    if (n == 0)
        return ctx->sym->one;
    if (n == 1)
        return xs[0];

    const qd_expr *coeff = ctx->sym->one;
    factor *v = NULL;
    size_t len = 0, cap = 0;
    const qd_expr *r = NULL, **out = NULL;
    if (!gather(ctx, n, xs, &coeff, &v, &len, &cap))
        goto done;
    if (qd_is_zero(coeff)) {
        r = coeff;
        goto done;
    }
    if (len > 1)
        qsort(v, len, sizeof *v, factor_cmp);

    out = qd__malloc(ctx, (len + 1) * sizeof *out);
    if (!out) {
        qd__oom(ctx);
        goto done;
    }
    size_t m = 0;
    bool reflatten = false;
    for (size_t i = 0; i < len;) {
        size_t j = i + 1;
        const qd_expr *f = v[i].node;
        if (j < len && v[j].base == v[i].base) {
            const qd_expr *e = v[i].exp ? v[i].exp : ctx->sym->one;
            for (; j < len && v[j].base == v[i].base; j++)
                e = qd_add(ctx, e, v[j].exp ? v[j].exp : ctx->sym->one);
            f = qd_pow(ctx, v[i].base, e);
            if (!f)
                goto done;
            /* x^a * x^b may fold to a number or a product, or to a power of
             * another base (abs(a)*abs(a) is a^2, which must meet a^-2):
             * flatten again. */
            if (qd__is_num(f) || f->kind == QD_MUL || as_factor(f).base != v[i].base)
                reflatten = true;
        }
        out[m++] = f;
        i = j;
    }
    if (reflatten) {
        out[m++] = coeff;
        r = qd_mul_n(ctx, m, out);
        goto done;
    }
    if (m == 0)
        r = coeff;
    else if (m == 1 && qd_is_one(coeff))
        r = out[0];
    else if (m == 1 && out[0]->kind == QD_ADD)
        r = distribute(ctx, coeff, out[0]);
    else
        r = qd__mul_raw(ctx, qd_is_one(coeff) ? NULL : coeff, m, out);
done:
    qd__free(out);
    qd__free(v);
    return r;
}

const qd_expr *qd_mul(qd_ctx *ctx, const qd_expr *a, const qd_expr *b) {
    QD_ARGS(NULL, ctx && a && b);
    const qd_expr *xs[2] = {a, b};
    return qd_mul_n(ctx, 2, xs);
}

const qd_expr *qd_div(qd_ctx *ctx, const qd_expr *a, const qd_expr *b) {
    QD_ARGS(NULL, ctx && a && b);
    if (b && qd_is_zero(b) && b->kind == QD_RATIONAL) {
        qd_ctx_error(ctx, QD_ERR_DIVZERO, "division by zero");
        return NULL;
    }
    return qd_mul(ctx, a, qd_pow(ctx, b, ctx->sym->minus_one));
}
