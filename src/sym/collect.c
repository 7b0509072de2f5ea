/*
 * src/sym/collect.c - coefficients read off the expansion.
 *
 * All three calls expand once into a polynomial (poly.h) and sort its terms
 * by their exponents of the chosen generators; no per-term expression work
 * is done before the terms are grouped.  This is how the mass matrix is read
 * off Lagrange's equations: the coefficients of the accelerations q''.
 */
#include "poly.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <stdlib.h>

/* The generator index of x: x must expand to exactly one generator. */
static long gen_of(qd__xsess *s, const qd_expr *x, const char *what) {
    const qd__poly *p = qd__xs_poly(s, x);
    if (!p)
        return -1;
    if (p->n != 1 || p->terms[0].len != 1 || p->pool[p->terms[0].off].exp != 1 ||
        !qd__poly_coef_is_one(p, 0)) {
        qd_ctx_error(s->ctx, QD_ERR_ARG, "%s: not a symbol or other generator", what);
        return -1;
    }
    return p->pool[p->terms[0].off].var;
}

static const char *name_of(const qd_expr *x) {
    const char *n = qd_expr_name(x);
    return n ? n : "the given expression";
}

/* The first of the marked nodes found under e (memo: node -> hit, or the
 * memo itself for none). */
static const qd_expr *find_marked(const qd_expr *e, const qd__ptrmap *marked, qd__ptrmap *memo) {
    if (qd__ptrmap_has(marked, e))
        return e;
    if (!e->nargs)
        return NULL;
    void *v = qd__ptrmap_get(memo, e);
    if (v)
        return v == (void *)memo ? NULL : v;
    const qd_expr *hit = NULL;
    for (uint32_t i = 0; i < e->nargs && !hit; i++)
        hit = find_marked(e->args[i], marked, memo);
    qd__ptrmap_put(memo, e, hit ? (void *)hit : (void *)memo); /* failure: only a revisit */
    return hit;
}

typedef struct lin {
    qd__xsess s;
    size_t n;
    long *slot;           /* per generator: index in xs, -1 none, -2 not looked at */
    uint32_t *xvar;       /* the generator of each x */
    qd__ptrmap marked;     /* the xs */
    qd__ptrmap memo;
    qd__poly **parts;      /* [0] the rest, [1 + i] the coefficient of xs[i] */
} lin;

/* Which x (if any) generator var is or hides; *inside set when it hides one. */
static long classify(lin *L, uint32_t var, const qd_expr **inside) {
    *inside = NULL;
    if (L->slot[var] >= -1)
        return L->slot[var];
    const qd_expr *g = L->s.gens[var];
    long k = -1;
    for (size_t i = 0; i < L->n && k < 0; i++)
        if (L->xvar[i] == var)
            k = (long)i;
    if (k < 0)
        *inside = find_marked(g, &L->marked, &L->memo);
    if (!*inside)
        L->slot[var] = k;
    return k;
}

/* Sort term t into its part, or report the symbol that makes it nonlinear. */
static qd_status place_term(lin *L, const qd__poly *p, size_t t, const qd_expr *const *xs) {
    const qd__pterm *pt = &p->terms[t];
    long which = -1;
    for (uint32_t i = 0; i < pt->len; i++) {
        qd__pvar v = p->pool[pt->off + i];
        const qd_expr *inside;
        long k = classify(L, v.var, &inside);
        if (inside || (k >= 0 && (v.exp != 1 || which >= 0))) {
            const qd_expr *x = inside ? inside : xs[k];
            qd_ctx_error(L->s.ctx, QD_ERR_NONLINEAR, "not linear in %s", name_of(x));
            return QD_ERR_NONLINEAR;
        }
        if (k >= 0)
            which = k;
    }
    uint32_t drop = which >= 0 ? L->xvar[which] : UINT32_MAX;
    if (!qd__poly_append(L->s.ctx, L->parts[which + 1], p, t, drop))
        return QD_ERR_NOMEM;
    return QD_OK;
}

static qd_status lin_setup(lin *L, qd_ctx *ctx, size_t n, const qd_expr *const *xs) {
    qd__xs_init(&L->s, ctx);
    L->n = n;
    L->marked = (qd__ptrmap)QD_PTRMAP_AL(qd__ctx_allocator(ctx));
    L->memo = (qd__ptrmap)QD_PTRMAP_AL(qd__ctx_allocator(ctx));
    L->slot = NULL;
    L->parts = qd__calloc(ctx, n + 1, sizeof *L->parts);
    L->xvar = qd__malloc(ctx, (n + 1) * sizeof *L->xvar);
    if (!L->parts || !L->xvar)
        return QD_ERR_NOMEM;
    for (size_t i = 0; i <= n; i++)
        if (!qd__xs_own(&L->s, L->parts[i] = qd__poly_zero(ctx)))
            return QD_ERR_NOMEM;
    for (size_t i = 0; i < n; i++) {
        if (!xs[i])
            return QD_ERR_ARG;
        long v = gen_of(&L->s, xs[i], "linear_coeffs");
        if (v < 0)
            return ctx->status;
        L->xvar[i] = (uint32_t)v;
        if (qd__ptrmap_has(&L->marked, xs[i])) {
            qd_ctx_error(ctx, QD_ERR_ARG, "linear_coeffs: %s given twice", name_of(xs[i]));
            return QD_ERR_ARG;
        }
        if (!qd__ptrmap_put(&L->marked, xs[i], (void *)xs[i]))
            return QD_ERR_NOMEM;
    }
    return QD_OK;
}

static qd_status lin_split(lin *L, const qd_expr *e, const qd_expr *const *xs) {
    const qd__poly *p = qd__xs_poly(&L->s, e);
    if (!p)
        return L->s.ctx->status ? L->s.ctx->status : QD_ERR_NOMEM;
    L->slot = qd__malloc(L->s.ctx, (L->s.ngens + 1) * sizeof *L->slot);
    if (!L->slot)
        return QD_ERR_NOMEM;
    for (size_t v = 0; v < L->s.ngens; v++)
        L->slot[v] = -2;
    for (size_t t = 0; t < p->n; t++) {
        qd_status st = place_term(L, p, t, xs);
        if (st != QD_OK)
            return st;
    }
    return QD_OK;
}

qd_status qd_linear_coeffs(qd_ctx *ctx, const qd_expr *e, size_t n, const qd_expr *const *xs,
                           const qd_expr **coeffs, const qd_expr **rest) {
    QD_ARGS_CTX(ctx, ctx && e && (n == 0 || xs) && coeffs && rest);
    for (size_t i = 0; i < n; i++)
        coeffs[i] = NULL;
    *rest = NULL;
    if (!e)
        return ctx->status ? ctx->status : QD_ERR_ARG;
    lin L;
    qd_status st = lin_setup(&L, ctx, n, xs);
    if (st == QD_OK)
        st = lin_split(&L, e, xs);
    for (size_t i = 0; st == QD_OK && i < n; i++)
        if (!(coeffs[i] = qd__xs_expr(&L.s, L.parts[i + 1])))
            st = QD_ERR_NOMEM;
    if (st == QD_OK && !(*rest = qd__xs_expr(&L.s, L.parts[0])))
        st = QD_ERR_NOMEM;
    if (st != QD_OK) {
        if (st == QD_ERR_NOMEM && ctx->status == QD_OK)
            qd__oom(ctx);
        st = ctx->status ? ctx->status : st;
        for (size_t i = 0; i < n; i++)
            coeffs[i] = NULL;
        *rest = NULL;
    }
    qd__free(L.slot);
    qd__free(L.parts);
    qd__free(L.xvar);
    qd__ptrmap_free(&L.marked);
    qd__ptrmap_free(&L.memo);
    qd__xs_free(&L.s);
    return st;
}

const qd_expr *qd_coeff(qd_ctx *ctx, const qd_expr *e, const qd_expr *x, long k) {
    QD_ARGS(NULL, ctx && e && x);
    if (!e || !x)
        return NULL;
    if (k > INT32_MAX || k < -INT32_MAX) {
        qd_ctx_error(ctx, QD_ERR_ARG, "coeff: exponent %ld out of range", k);
        return NULL;
    }
    qd__xsess s;
    qd__xs_init(&s, ctx);
    const qd_expr *r = NULL;
    long var = gen_of(&s, x, "coeff");
    const qd__poly *p = var >= 0 ? qd__xs_poly(&s, e) : NULL;
    qd__poly *slice = p ? qd__poly_slice(ctx, p, (uint32_t)var, (int32_t)k) : NULL;
    if (qd__xs_own(&s, slice))
        r = qd__xs_expr(&s, slice);
    qd__xs_free(&s);
    return r;
}

static int cmp_i32(const void *a, const void *b) {
    int32_t x = *(const int32_t *)a, y = *(const int32_t *)b;
    return (x > y) - (x < y);
}

/* The distinct exponents of var in p, sorted; their number. */
static size_t exponents(const qd__poly *p, uint32_t var, int32_t *out) {
    for (size_t t = 0; t < p->n; t++)
        out[t] = qd__poly_exp(p, t, var);
    qsort(out, p->n, sizeof *out, cmp_i32);
    size_t m = 0;
    for (size_t t = 0; t < p->n; t++)
        if (m == 0 || out[m - 1] != out[t])
            out[m++] = out[t];
    return m;
}

static size_t bucket(const int32_t *ks, size_t m, int32_t k) {
    size_t lo = 0, hi = m;
    while (hi - lo > 1) {
        size_t mid = (lo + hi) / 2;
        if (ks[mid] <= k)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

/* sum_k c_k x^k from the buckets of p by the exponent of var. */
static const qd_expr *gather(qd__xsess *s, const qd__poly *p, uint32_t var, const qd_expr *x) {
    qd_ctx *ctx = s->ctx;
    int32_t *ks = qd__malloc(ctx, (p->n + 1) * sizeof *ks);
    const qd_expr **terms = qd__malloc(ctx, (p->n + 1) * sizeof *terms);
    qd__poly **parts = qd__malloc(ctx, (p->n + 1) * sizeof *parts);
    const qd_expr *r = NULL;
    if (!ks || !terms || !parts)
        goto done;
    size_t m = exponents(p, var, ks);
    for (size_t j = 0; j < m; j++)
        if (!qd__xs_own(s, parts[j] = qd__poly_zero(ctx)))
            goto done;
    for (size_t t = 0; t < p->n; t++)
        if (!qd__poly_append(ctx, parts[bucket(ks, m, qd__poly_exp(p, t, var))], p, t, var))
            goto done;
    for (size_t j = 0; j < m; j++) {
        const qd_expr *c = qd__xs_expr(s, parts[j]);
        terms[j] = qd_mul(ctx, c, qd_powi(ctx, x, ks[j]));
    }
    r = qd_add_n(ctx, m, terms);
done:
    if ((!ks || !terms || !parts) && ctx->status == QD_OK)
        qd__oom(ctx);
    qd__free(ks);
    qd__free(terms);
    qd__free(parts);
    return r;
}

const qd_expr *qd_collect(qd_ctx *ctx, const qd_expr *e, const qd_expr *x) {
    QD_ARGS(NULL, ctx && e && x);
    if (!e || !x)
        return NULL;
    qd__xsess s;
    qd__xs_init(&s, ctx);
    const qd_expr *r = NULL;
    long var = gen_of(&s, x, "collect");
    const qd__poly *p = var >= 0 ? qd__xs_poly(&s, e) : NULL;
    if (p)
        r = p->n ? gather(&s, p, (uint32_t)var, x) : ctx->sym->zero;
    qd__xs_free(&s);
    return r;
}
