/*
 * src/sym/expand.c - expansion through sparse polynomials.
 *
 * Each node of the DAG is turned once into a polynomial over generators
 * (poly.h): sums add, products multiply, integer powers of sums multiply
 * out, and everything else becomes a generator after its own arguments
 * have been expanded (sin(x*(y+1)) is the generator sin(x*y + x)).  The
 * result is converted back with one qd_add_n over all terms.
 *
 * A rational power b^(p/q) is the generator b^(1/q) to the power p, so
 * sqrt(x+1)^3 * sqrt(x+1) meets as one generator to the 4th; when a
 * generator's power folds into something that is not a clean factor
 * ((x+1)^2 here), the term is rebuilt by the constructors and expanded
 * again.
 *
 * A power of a sum whose expansion would exceed QD_EXPAND_MAX_BYTES (poly.h)
 * stays a power, a generator of its own; a product that large is refused
 * (QD_ERR_TOOBIG), so GMP and FLINT are never asked for more.
 */
#include "poly.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <stdlib.h>
#include <string.h>

/* Integer exponents beyond this stay symbolic (the expansion could not be
 * stored anyway). */
#define MAX_EXPAND_EXP (1L << 24)

typedef struct qd__powslot {
    uint64_t key;
    const qd_expr *node;
} qd__powslot;

void qd__xs_init(qd__xsess *s, qd_ctx *ctx) {
    memset(s, 0, sizeof *s);
    s->ctx = ctx;
}

void qd__xs_free(qd__xsess *s) {
    for (size_t i = 0; i < s->nowned; i++)
        qd__poly_free(s->owned[i]);
    qd__free(s->owned);
    qd__free(s->gens);
    qd__free(s->pows);
    qd__ptrmap_free(&s->polys);
    qd__ptrmap_free(&s->exprs);
    qd__ptrmap_free(&s->genix);
}

static bool grow(qd_ctx *ctx, void **v, size_t *cap, size_t need, size_t size) {
    if (need <= *cap)
        return true;
    size_t c = *cap ? *cap * 2 : 16;
    while (c < need)
        c *= 2;
    void *nv = qd__realloc(ctx, *v, c * size);
    if (!nv)
        return false;
    *v = nv;
    *cap = c;
    return true;
}

bool qd__xs_own(qd__xsess *s, qd__poly *p) {
    if (!p)
        return false;
    if (!grow(s->ctx, (void **)&s->owned, &s->ocap, s->nowned + 1, sizeof *s->owned)) {
        qd__poly_free(p);
        qd__oom(s->ctx);
        return false;
    }
    s->owned[s->nowned++] = p;
    return true;
}

long qd__xs_gen(qd__xsess *s, const qd_expr *g) {
    void *v = qd__ptrmap_get(&s->genix, g);
    if (v)
        return (long)((uintptr_t)v - 1);
    if (!grow(s->ctx, (void **)&s->gens, &s->gcap, s->ngens + 1, sizeof *s->gens) ||
        !qd__ptrmap_put(&s->genix, g, (void *)(uintptr_t)(s->ngens + 1))) {
        qd__oom(s->ctx);
        return -1;
    }
    s->gens[s->ngens] = g;
    return (long)s->ngens++;
}

/* ---- expression -> polynomial ------------------------------------------------ */

/* Memoize p (a new polynomial, now owned) as the polynomial of e. */
static const qd__poly *own_as(qd__xsess *s, const qd_expr *e, qd__poly *p) {
    if (!qd__xs_own(s, p))
        return NULL;
    return qd__ptrmap_put(&s->polys, e, p) ? p : (qd__oom(s->ctx), NULL);
}

static const qd__poly *alias(qd__xsess *s, const qd_expr *e, const qd__poly *p) {
    if (!p)
        return NULL;
    return qd__ptrmap_put(&s->polys, e, (void *)p) ? p : (qd__oom(s->ctx), NULL);
}

static qd__poly *gen_poly(qd__xsess *s, const qd_expr *g, long k) {
    long i = qd__xs_gen(s, g);
    return i < 0 ? NULL : qd__poly_var(s->ctx, (uint32_t)i, (int32_t)k);
}

static const qd__poly *sum_poly(qd__xsess *s, const qd_expr *e) {
    const qd__poly **ps = qd__malloc(s->ctx, e->nargs * sizeof *ps);
    qd__poly *r = NULL;
    if (!ps) {
        qd__oom(s->ctx);
        return NULL;
    }
    size_t i = 0;
    for (; i < e->nargs && (ps[i] = qd__xs_poly(s, e->args[i])); i++)
        ;
    if (i == e->nargs)
        r = qd__poly_add_n(s->ctx, i, (const qd__poly *const *)ps);
    qd__free(ps);
    return r ? own_as(s, e, r) : NULL;
}

static const qd__poly *prod_poly(qd__xsess *s, const qd_expr *e) {
    const qd__poly *acc = qd__xs_poly(s, e->args[0]);
    qd__poly *mine = NULL; /* acc when it is ours to free */
    for (size_t i = 1; acc && i < e->nargs; i++) {
        const qd__poly *f = qd__xs_poly(s, e->args[i]);
        qd__poly *next = f ? qd__poly_mul(s->ctx, acc, f) : NULL;
        qd__poly_free(mine);
        acc = mine = next;
    }
    return mine ? own_as(s, e, mine) : alias(s, e, acc);
}

static bool small_int(const qd_expr *x, long *n) {
    long num, den;
    if (!qd_rational_get(x, &num, &den) || den != 1 || num > MAX_EXPAND_EXP ||
        num < -MAX_EXPAND_EXP)
        return false;
    *n = num;
    return true;
}

/* b^n for an integer n: multiplied out, or the inverse of a sum as a generator. */
static const qd__poly *int_pow(qd__xsess *s, const qd_expr *e, const qd_expr *b, long n) {
    const qd__poly *pb = qd__xs_poly(s, b);
    if (!pb)
        return NULL;
    if (n >= 2 || (n <= -2 && pb->n == 1)) {
        double bytes = qd__poly_pow_bytes(s->ctx, pb, n);
        if (bytes < 0)
            return NULL;
        if (bytes > QD_EXPAND_MAX_BYTES) { /* kept as it is, like an exponent beyond MAX_EXPAND_EXP */
            const qd_expr *g = qd_pow(s->ctx, qd__xs_expr(s, pb), qd_int(s->ctx, n));
            if (g && g->kind != QD_POW) /* (c x)^n = c^n x^n: each factor kept or expanded */
                return alias(s, e, qd__xs_poly(s, g));
            return g ? own_as(s, e, gen_poly(s, g, 1)) : NULL;
        }
    }
    if (n >= 0 || pb->n == 1)
        return own_as(s, e, qd__poly_pow(s->ctx, pb, n));
    if (pb->n == 0) {
        qd_ctx_error(s->ctx, QD_ERR_DIVZERO, "division by zero in expansion");
        return NULL;
    }
    const qd_expr *g = qd_pow(s->ctx, qd__xs_expr(s, pb), s->ctx->sym->minus_one);
    if (g && g->kind == QD_POW && qd_is_integer(g->args[1]))
        return own_as(s, e, gen_poly(s, g, -n));
    const qd__poly *pg = g ? qd__xs_poly(s, g) : NULL;
    return pg ? own_as(s, e, qd__poly_pow(s->ctx, pg, -n)) : NULL;
}

/* The generator of r = b^x (not folded): b^(1/q) to the power p when x = p/q. */
static qd__poly *root_gen(qd__xsess *s, const qd_expr *r) {
    long p, q;
    if (qd_rational_get(r->args[1], &p, &q) && q <= MAX_EXPAND_EXP && p <= MAX_EXPAND_EXP &&
        p >= -MAX_EXPAND_EXP) {
        const qd_expr *g = qd_pow(s->ctx, r->args[0], qd_rat(s->ctx, 1, q));
        if (!g)
            return NULL;
        if (g->kind == QD_POW && g->args[0] == r->args[0])
            return gen_poly(s, g, p);
    }
    return gen_poly(s, r, 1);
}

static const qd__poly *pow_poly(qd__xsess *s, const qd_expr *e) {
    long n;
    if (small_int(e->args[1], &n))
        return int_pow(s, e, e->args[0], n);
    const qd_expr *bx = qd__xs_expand(s, e->args[0]), *xx = qd__xs_expand(s, e->args[1]);
    if (!bx || !xx)
        return NULL;
    if (small_int(xx, &n))
        return int_pow(s, e, bx, n);
    const qd_expr *r = qd_pow(s->ctx, bx, xx);
    if (!r)
        return NULL;
    if (r->kind != QD_POW || r->args[0] != bx || r->args[1] != xx)
        return alias(s, e, qd__xs_poly(s, r)); /* folded: r is simpler than e */
    return own_as(s, e, root_gen(s, r));
}

/* A call: a generator once its arguments are expanded. */
static const qd__poly *call_poly(qd__xsess *s, const qd_expr *e) {
    const qd_expr *stack[8];
    const qd_expr **args = e->nargs <= 8 ? stack : qd__malloc(s->ctx, e->nargs * sizeof *args);
    if (!args) {
        qd__oom(s->ctx);
        return NULL;
    }
    bool changed = false, ok = true;
    for (size_t i = 0; i < e->nargs && ok; i++) {
        ok = (args[i] = qd__xs_expand(s, e->args[i])) != NULL;
        changed |= ok && args[i] != e->args[i];
    }
    const qd_expr *r = !ok ? NULL : changed ? qd__rebuild(s->ctx, e, args) : e;
    if (args != stack)
        qd__free(args);
    if (!r)
        return NULL;
    if (r->kind == QD_FUNC || r->kind == QD_UFUNC || r->kind == QD_UDERIV)
        return own_as(s, e, gen_poly(s, r, 1));
    return alias(s, e, qd__xs_poly(s, r)); /* the call folded (sin(0), sin(-x)) */
}

const qd__poly *qd__xs_poly(qd__xsess *s, const qd_expr *e) {
    if (!e)
        return NULL;
    const qd__poly *p = qd__ptrmap_get(&s->polys, e);
    if (p)
        return p;
    switch ((qd_kind)e->kind) {
    case QD_RATIONAL:
    case QD_FLOAT: return own_as(s, e, qd__poly_number(s->ctx, e));
    case QD_SYMBOL:
    case QD_CONSTANT: return own_as(s, e, gen_poly(s, e, 1));
    case QD_ADD: return sum_poly(s, e);
    case QD_MUL: return prod_poly(s, e);
    case QD_POW: return pow_poly(s, e);
    default: return call_poly(s, e);
    }
}

/* ---- polynomial -> expression ---------------------------------------------- */

static uint64_t pow_key(uint32_t var, int32_t exp) {
    uint64_t z = ((uint64_t)var << 32 | (uint32_t)exp) * 0x9e3779b97f4a7c15ULL;
    return z ^ (z >> 29);
}

/* Generator var to the power exp, cached. */
static const qd_expr *gen_pow(qd__xsess *s, uint32_t var, int32_t exp) {
    if (exp == 1)
        return s->gens[var];
    uint64_t key = (uint64_t)var << 32 | (uint32_t)exp;
    if (2 * (s->powlen + 1) > s->powcap) {
        size_t cap = s->powcap ? 2 * s->powcap : 64;
        qd__powslot *ns = qd__calloc(s->ctx, cap, sizeof *ns);
        if (!ns) {
            qd__oom(s->ctx);
            return NULL;
        }
        for (size_t i = 0; i < s->powcap; i++) {
            if (!s->pows[i].node)
                continue;
            uint64_t k = s->pows[i].key;
            size_t j = pow_key((uint32_t)(k >> 32), (int32_t)k) & (cap - 1);
            while (ns[j].node)
                j = (j + 1) & (cap - 1);
            ns[j] = s->pows[i];
        }
        qd__free(s->pows);
        s->pows = ns;
        s->powcap = cap;
    }
    size_t i = pow_key(var, exp) & (s->powcap - 1);
    for (; s->pows[i].node; i = (i + 1) & (s->powcap - 1))
        if (s->pows[i].key == key)
            return s->pows[i].node;
    const qd_expr *r = qd_pow(s->ctx, s->gens[var], qd_int(s->ctx, exp));
    if (r) {
        s->pows[i].key = key;
        s->pows[i].node = r;
        s->powlen++;
    }
    return r;
}

static const qd_expr *base_of(const qd_expr *f) { return f->kind == QD_POW ? f->args[0] : f; }

static bool sum_to_pos_int(const qd_expr *f) {
    return f->kind == QD_POW && f->args[0]->kind == QD_ADD && qd_is_integer(f->args[1]) &&
           qd_number_sign(f->args[1]) > 0;
}

/* Is f = g^k a factor a canonical product can hold as it is, with the
 * generator's base?  Not when it folded to a number, a product or a sum, or
 * to a positive power of a sum, unless g is one already: a power kept
 * unexpanded on purpose (too large), whose powers are larger still and would
 * only be kept again, forever. */
static bool clean_factor(const qd_expr *g, const qd_expr *f) {
    if (qd__is_num(f) || f->kind == QD_MUL || f->kind == QD_ADD || base_of(f) != base_of(g))
        return false;
    return !sum_to_pos_int(f) || sum_to_pos_int(g);
}

static void sort_factors(const qd_expr **f, size_t n) {
    for (size_t i = 1; i < n; i++) {
        const qd_expr *x = f[i];
        size_t j = i;
        for (; j > 0 && qd_expr_cmp(f[j - 1], x) > 0; j--)
            f[j] = f[j - 1];
        f[j] = x;
    }
}

/* Term t of p as a node: the trusted constructor when the factors are
 * clean, else the constructors and another expansion. */
static const qd_expr *term_expr(qd__xsess *s, const qd__poly *p, size_t t) {
    const qd__pterm *pt = &p->terms[t];
    const qd_expr *c = qd__poly_coef_is_one(p, t) ? NULL : qd__poly_coef_node(s->ctx, p, t);
    if (pt->len == 0)
        return c ? c : s->ctx->sym->one;
    const qd_expr *stack[17], **f = pt->len < 17 ? stack : qd__malloc(s->ctx, (pt->len + 1) * sizeof *f);
    if (!f) {
        qd__oom(s->ctx);
        return NULL;
    }
    const qd_expr **fs = f + 1, *r = NULL;
    bool clean = true;
    f[0] = c;
    for (uint32_t i = 0; i < pt->len; i++) {
        qd__pvar v = p->pool[pt->off + i];
        if (!(fs[i] = gen_pow(s, v.var, v.exp)))
            goto done;
        clean = clean && clean_factor(s->gens[v.var], fs[i]);
    }
    sort_factors(fs, pt->len);
    for (uint32_t i = 1; clean && i < pt->len; i++)
        clean = base_of(fs[i]) != base_of(fs[i - 1]);
    if (clean)
        r = pt->len == 1 && !c ? fs[0] : qd__mul_raw(s->ctx, c, pt->len, fs);
    else if (c)
        r = qd__xs_expand(s, qd_mul_n(s->ctx, pt->len + 1, f));
    else
        r = qd__xs_expand(s, qd_mul_n(s->ctx, pt->len, fs));
done:
    if (f != stack)
        qd__free(f);
    return r;
}

/* A term's sort key: its (generator rank, exponent) pairs by rank. */
typedef struct tkey {
    const qd__pvar *k;
    uint32_t len, term;
} tkey;

static int tkey_cmp(const void *pa, const void *pb) {
    const tkey *a = pa, *b = pb;
    for (uint32_t i = 0; i < a->len && i < b->len; i++) {
        if (a->k[i].var != b->k[i].var)
            return a->k[i].var < b->k[i].var ? -1 : 1;
        if (a->k[i].exp != b->k[i].exp)
            return a->k[i].exp < b->k[i].exp ? -1 : 1;
    }
    return (a->len > b->len) - (a->len < b->len);
}

static int node_cmp(const void *a, const void *b) {
    return qd_expr_cmp(*(const qd_expr *const *)a, *(const qd_expr *const *)b);
}

/* The ranks of the generators, when every one in p is a symbol, a call or a
 * constant: then factors compare by generator, then numerically by
 * exponent, exactly as qd_expr_cmp orders g^k. */
static uint32_t *gen_ranks(qd__xsess *s, const qd__poly *p) {
    uint32_t *rank = qd__malloc(s->ctx, (s->ngens + 1) * sizeof *rank), nused = 0;
    const qd_expr **used = qd__malloc(s->ctx, (s->ngens + 1) * sizeof *used);
    if (!rank || !used)
        goto fail;
    for (size_t g = 0; g < s->ngens; g++)
        rank[g] = UINT32_MAX;
    for (size_t i = 0; i < p->plen; i++) {
        uint32_t g = p->pool[i].var;
        if (s->gens[g]->kind == QD_POW)
            goto fail;
        if (rank[g] == UINT32_MAX)
            used[nused++] = s->gens[g], rank[g] = 0;
    }
    qsort(used, nused, sizeof *used, node_cmp);
    for (uint32_t i = 0; i < nused; i++)
        rank[(uintptr_t)qd__ptrmap_get(&s->genix, used[i]) - 1] = i;
    qd__free(used);
    return rank;
fail:
    qd__free(rank);
    qd__free(used);
    return NULL;
}

/* The terms of p in canonical order (when it can be read off cheaply), so
 * that qd_add_n finds them sorted; else in table order. */
static uint32_t *term_order(qd__xsess *s, const qd__poly *p) {
    bool clean = qd_ctx_status(s->ctx) == QD_OK;
    uint32_t *order = qd__malloc(s->ctx, p->n * sizeof *order);
    uint32_t *rank = order ? gen_ranks(s, p) : NULL;
    tkey *keys = rank ? qd__malloc(s->ctx, p->n * sizeof *keys) : NULL;
    qd__pvar *buf = keys ? qd__malloc(s->ctx, (p->plen + 1) * sizeof *buf) : NULL;
    if (order && !buf && clean && qd__ctx_nomem(s->ctx))
        qd_ctx_clear_error(s->ctx); /* only this sort ran out: table order gives the same sum */
    for (size_t t = 0; order && t < p->n; t++)
        order[t] = (uint32_t)t;
    if (buf) {
        for (size_t t = 0; t < p->n; t++) {
            const qd__pterm *pt = &p->terms[t];
            qd__pvar *k = buf + pt->off;
            for (uint32_t i = 0; i < pt->len; i++) {
                qd__pvar v = {rank[p->pool[pt->off + i].var], p->pool[pt->off + i].exp};
                uint32_t j = i;
                for (; j > 0 && k[j - 1].var > v.var; j--)
                    k[j] = k[j - 1];
                k[j] = v;
            }
            keys[t] = (tkey){k, pt->len, (uint32_t)t};
        }
        qsort(keys, p->n, sizeof *keys, tkey_cmp);
        for (size_t t = 0; t < p->n; t++)
            order[t] = keys[t].term;
    }
    qd__free(buf);
    qd__free(keys);
    qd__free(rank);
    return order;
}

const qd_expr *qd__xs_expr(qd__xsess *s, const qd__poly *p) {
    if (!p)
        return NULL;
    if (p->n == 0)
        return s->ctx->sym->zero;
    if (p->n == 1)
        return term_expr(s, p, 0);
    const qd_expr **terms = qd__malloc(s->ctx, p->n * sizeof *terms);
    uint32_t *order = terms ? term_order(s, p) : NULL;
    const qd_expr *r = NULL;
    size_t t = 0;
    for (; order && t < p->n && (terms[t] = term_expr(s, p, order[t])); t++)
        ;
    if (!order)
        qd__oom(s->ctx);
    else if (t == p->n)
        r = qd_add_n(s->ctx, t, terms);
    qd__free(terms);
    qd__free(order);
    return r;
}

const qd_expr *qd__xs_expand(qd__xsess *s, const qd_expr *e) {
    if (!e || e->nargs == 0)
        return e;
    const qd_expr *r = qd__ptrmap_get(&s->exprs, e);
    if (r)
        return r;
    r = qd__xs_expr(s, qd__xs_poly(s, e));
    if (r && !qd__ptrmap_put(&s->exprs, e, (void *)r)) {
        qd__oom(s->ctx);
        return NULL;
    }
    return r;
}

const qd_expr *qd_expand(qd_ctx *ctx, const qd_expr *e) {
    QD_ARGS(NULL, ctx && e);
    if (!e)
        return NULL;
    qd__xsess s;
    qd__xs_init(&s, ctx);
    qd__gmp_section outer = qd__gmp_enter(ctx);
    const qd_expr *r = qd__xs_expand(&s, e);
    qd__xs_free(&s);
    return qd__gmp_leave(ctx, outer) ? r : NULL;
}
