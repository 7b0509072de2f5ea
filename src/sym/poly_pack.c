/*
 * src/sym/poly_pack.c - the fast product of dense-ish integer polynomials.
 *
 * When both factors have int64 coefficients and few generators of bounded
 * degree, every monomial packs into one 64-bit word (a bit field per
 * generator, exponents biased to be nonnegative), the product of two
 * monomials is the sum of their words, and the accumulator is a flat table
 * of (word, coefficient).  It serves the middle sizes: large products over
 * few generators go to FLINT first (poly_flint.c), and anything else (an
 * overflow, a rational or float coefficient, many generators) goes the
 * general way in poly.c.
 */
#include "poly.h"
#include "../base/mem.h"

#include <stdlib.h>

#define MAX_PACKED_VARS 16

typedef struct plan {
    unsigned nv, bits;
    uint32_t var[MAX_PACKED_VARS];
    int64_t lo[2][MAX_PACKED_VARS]; /* smallest exponent in x, in y */
    int64_t hi[2][MAX_PACKED_VARS];
    int64_t bias[MAX_PACKED_VARS];  /* of the result's fields */
} plan;

static int slot_of(plan *pl, uint32_t var) {
    for (unsigned i = 0; i < pl->nv; i++)
        if (pl->var[i] == var)
            return (int)i;
    if (pl->nv == MAX_PACKED_VARS)
        return -1;
    pl->var[pl->nv] = var;
    pl->lo[0][pl->nv] = pl->lo[1][pl->nv] = 0; /* an absent generator has exponent 0 */
    pl->hi[0][pl->nv] = pl->hi[1][pl->nv] = 0;
    return (int)pl->nv++;
}

static bool scan(plan *pl, const qd__poly *p, int side) {
    for (size_t t = 0; t < p->n; t++) {
        const qd__pterm *pt = &p->terms[t];
        if (pt->c.kind != QD_COEF_INT)
            return false;
        for (uint32_t i = 0; i < pt->len; i++) {
            qd__pvar v = p->pool[pt->off + i];
            int k = slot_of(pl, v.var);
            if (k < 0)
                return false;
            if (v.exp < pl->lo[side][k])
                pl->lo[side][k] = v.exp;
            if (v.exp > pl->hi[side][k])
                pl->hi[side][k] = v.exp;
        }
    }
    return true;
}

/* Sort the generators (so unpacked monomials come out sorted) and check
 * that every field holds its range: the product of x and y, or x^n when y
 * is NULL. */
static bool make_plan(plan *pl, const qd__poly *x, const qd__poly *y, long n) {
    pl->nv = 0;
    if (!scan(pl, x, 0) || (y && !scan(pl, y, 1)) || pl->nv == 0)
        return false;
    for (unsigned i = 1; i < pl->nv; i++)
        for (unsigned j = i; j > 0 && pl->var[j - 1] > pl->var[j]; j--) {
            uint32_t tv = pl->var[j];
            pl->var[j] = pl->var[j - 1];
            pl->var[j - 1] = tv;
            for (int s = 0; s < 2; s++) {
                int64_t tl = pl->lo[s][j], th = pl->hi[s][j];
                pl->lo[s][j] = pl->lo[s][j - 1], pl->hi[s][j] = pl->hi[s][j - 1];
                pl->lo[s][j - 1] = tl, pl->hi[s][j - 1] = th;
            }
        }
    pl->bits = 64 / pl->nv;
    if (pl->bits > 32)
        pl->bits = 32;
    for (unsigned i = 0; i < pl->nv; i++) {
        int64_t range = y ? pl->hi[0][i] + pl->hi[1][i] - pl->lo[0][i] - pl->lo[1][i]
                          : (pl->hi[0][i] - pl->lo[0][i]) * n;
        pl->bias[i] = y ? pl->lo[0][i] + pl->lo[1][i] : pl->lo[0][i] * n;
        if (range >= ((int64_t)1 << pl->bits) - 1)
            return false; /* keeps every word below UINT64_MAX, the empty mark */
    }
    return true;
}

static uint64_t pack(const plan *pl, const qd__poly *p, size_t t, int side) {
    const qd__pterm *pt = &p->terms[t];
    int64_t e[MAX_PACKED_VARS] = {0};
    unsigned k = 0;
    for (uint32_t i = 0; i < pt->len; i++) {
        qd__pvar v = p->pool[pt->off + i];
        while (pl->var[k] != v.var)
            k++;
        e[k] = v.exp;
    }
    uint64_t w = 0;
    for (k = 0; k < pl->nv; k++)
        w |= (uint64_t)(e[k] - pl->lo[side][k]) << (k * pl->bits);
    return w;
}

typedef struct table {
    uint64_t *key; /* UINT64_MAX: empty */
    int64_t *coef;
    size_t mask, len;
    unsigned shift;
} table;

static size_t home(const table *tb, uint64_t w) {
    return (size_t)((w * 0x9e3779b97f4a7c15ULL) >> tb->shift);
}

static bool tb_init(qd_ctx *ctx, table *tb, size_t cap) {
    tb->key = qd__malloc(ctx, cap * sizeof *tb->key);
    tb->coef = qd__malloc(ctx, cap * sizeof *tb->coef);
    tb->mask = cap - 1;
    tb->len = 0;
    tb->shift = 64;
    for (size_t c = cap; c > 1; c >>= 1)
        tb->shift--;
    if (!tb->key || !tb->coef)
        return false;
    for (size_t i = 0; i < cap; i++)
        tb->key[i] = UINT64_MAX;
    return true;
}

static void tb_free(table *tb) {
    qd__free(tb->key);
    qd__free(tb->coef);
}

static bool tb_grow(qd_ctx *ctx, table *tb) {
    table nt;
    if (!tb_init(ctx, &nt, 2 * (tb->mask + 1))) {
        tb_free(&nt);
        return false;
    }
    for (size_t i = 0; i <= tb->mask; i++) {
        if (tb->key[i] == UINT64_MAX)
            continue;
        size_t j = home(&nt, tb->key[i]);
        while (nt.key[j] != UINT64_MAX)
            j = (j + 1) & nt.mask;
        nt.key[j] = tb->key[i];
        nt.coef[j] = tb->coef[i];
    }
    nt.len = tb->len;
    tb_free(tb);
    *tb = nt;
    return true;
}

/* 1 done, 0 an int64 overflow (try the general way), -1 out of memory. */
static int accumulate(qd_ctx *ctx, table *tb, const uint64_t *wx, const int64_t *cx, size_t nx,
                      const uint64_t *wy, const int64_t *cy, size_t ny) {
    for (size_t i = 0; i < nx; i++) {
        for (size_t j = 0; j < ny; j++) {
            uint64_t w = wx[i] + wy[j];
            int64_t c;
            if (__builtin_mul_overflow(cx[i], cy[j], &c))
                return 0;
            size_t s = home(tb, w);
            while (tb->key[s] != UINT64_MAX && tb->key[s] != w)
                s = (s + 1) & tb->mask;
            if (tb->key[s] == w) {
                if (__builtin_add_overflow(tb->coef[s], c, &tb->coef[s]))
                    return 0;
                continue;
            }
            tb->key[s] = w;
            tb->coef[s] = c;
            if (2 * ++tb->len > tb->mask && !tb_grow(ctx, tb))
                return -1;
        }
    }
    return 1;
}

static qd__poly *unpack(qd_ctx *ctx, const plan *pl, const table *tb) {
    qd__poly *r = qd__poly_zero(ctx);
    uint64_t field = ((uint64_t)1 << pl->bits) - 1;
    for (size_t s = 0; r && s <= tb->mask; s++) {
        if (tb->key[s] == UINT64_MAX || tb->coef[s] == 0)
            continue;
        qd__pvar m[MAX_PACKED_VARS];
        uint32_t len = 0;
        for (unsigned k = 0; k < pl->nv; k++) {
            int64_t e = (int64_t)((tb->key[s] >> (k * pl->bits)) & field) + pl->bias[k];
            if (e != 0)
                m[len++] = (qd__pvar){pl->var[k], (int32_t)e};
        }
        if (!qd__poly_push_int(ctx, r, m, len, tb->coef[s])) {
            qd__poly_free(r);
            r = NULL;
        }
    }
    return r;
}

static bool pack_all(qd_ctx *ctx, const plan *pl, const qd__poly *p, int side, uint64_t **w,
                     int64_t **c) {
    *w = qd__malloc(ctx, (p->n + 1) * sizeof **w);
    *c = qd__malloc(ctx, (p->n + 1) * sizeof **c);
    if (!*w || !*c)
        return false;
    for (size_t t = 0; t < p->n; t++) {
        (*w)[t] = pack(pl, p, t, side);
        (*c)[t] = p->terms[t].c.v.i;
    }
    return true;
}

qd__poly *qd__poly_mul_packed(qd_ctx *ctx, const qd__poly *x, const qd__poly *y, bool *done) {
    plan pl;
    *done = false;
    if (x->n < 2 || y->n < 2 || !make_plan(&pl, x, y, 1))
        return NULL;
    uint64_t *wx = NULL, *wy = NULL;
    int64_t *cx = NULL, *cy = NULL;
    qd__poly *r = NULL;
    table tb = {0};
    size_t cap = 64;
    while (cap < 2 * (x->n > y->n ? x->n : y->n))
        cap *= 2;
    int st = -1;
    if (pack_all(ctx, &pl, x, 0, &wx, &cx) && pack_all(ctx, &pl, y, 1, &wy, &cy) && tb_init(ctx, &tb, cap))
        st = accumulate(ctx, &tb, wx, cx, x->n, wy, cy, y->n);
    if (st > 0)
        r = unpack(ctx, &pl, &tb);
    else if (st < 0)
        qd__oom(ctx);
    *done = st != 0;
    qd__free(wx), qd__free(wy), qd__free(cx), qd__free(cy);
    tb_free(&tb);
    return r;
}

/* The nonzero entries of tb as arrays (for the next multiplication). */
static bool harvest(qd_ctx *ctx, const table *tb, uint64_t **w, int64_t **c, size_t *n) {
    qd__free(*w);
    qd__free(*c);
    *w = qd__malloc(ctx, (tb->len + 1) * sizeof **w);
    *c = qd__malloc(ctx, (tb->len + 1) * sizeof **c);
    if (!*w || !*c)
        return false;
    *n = 0;
    for (size_t s = 0; s <= tb->mask; s++) {
        if (tb->key[s] == UINT64_MAX || tb->coef[s] == 0)
            continue;
        (*w)[*n] = tb->key[s];
        (*c)[(*n)++] = tb->coef[s];
    }
    return true;
}

/* a^n by repeated packed multiplication by a: no unpacking in between. */
qd__poly *qd__poly_pow_packed(qd_ctx *ctx, const qd__poly *a, long n, bool *done) {
    plan pl;
    *done = false;
    if (a->n < 2 || n < 2 || n > 65536 || !make_plan(&pl, a, NULL, n))
        return NULL;
    uint64_t *wa = NULL, *wx = NULL;
    int64_t *ca = NULL, *cx = NULL;
    size_t nx = a->n;
    table tb = {0};
    qd__poly *r = NULL;
    int st = pack_all(ctx, &pl, a, 0, &wa, &ca) && pack_all(ctx, &pl, a, 0, &wx, &cx) ? 1 : -1;
    for (long k = 1; st > 0 && k < n; k++) {
        size_t cap = 64;
        while (cap < 2 * nx)
            cap *= 2;
        tb_free(&tb);
        st = tb_init(ctx, &tb, cap) ? accumulate(ctx, &tb, wx, cx, nx, wa, ca, a->n) : -1;
        if (st > 0 && k + 1 < n && !harvest(ctx, &tb, &wx, &cx, &nx))
            st = -1;
    }
    if (st > 0)
        r = unpack(ctx, &pl, &tb);
    else if (st < 0)
        qd__oom(ctx);
    *done = st != 0;
    qd__free(wa), qd__free(wx), qd__free(ca), qd__free(cx);
    tb_free(&tb);
    return r;
}
