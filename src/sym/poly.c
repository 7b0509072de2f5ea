/*
 * src/sym/poly.c - sparse Laurent polynomials (see poly.h).
 *
 * Sums and products accumulate into a hash table keyed by monomial: the
 * product of a p-term and a q-term polynomial costs p*q monomial merges and
 * table probes, whatever the number of like terms; no expression node is
 * made until the result is converted back.
 */
#include "poly.h"
#include "../base/mem.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A coefficient as a value: q points into a polynomial or a scratch mpq. */
typedef struct cval {
    uint32_t kind;
    int64_t i;
    double f;
    mpq_srcptr q;
} cval;

/* ---- memory ----------------------------------------------------------------- */

void qd__poly_free(qd__poly *p) {
    if (!p)
        return;
    for (size_t i = 0; i < p->nbig; i++) {
        mpq_clear(p->bigs[i]);
        qd__free(p->bigs[i]);
    }
    qd__free(p->bigs);
    qd__free(p->terms);
    qd__free(p->pool);
    qd__free(p);
}

qd__poly *qd__poly_zero(qd_ctx *ctx) {
    qd__poly *p = qd__calloc(ctx, 1, sizeof *p);
    if (!p)
        qd__oom(ctx);
    return p;
}

static bool grow(qd_ctx *ctx, void **v, size_t *cap, size_t need, size_t size) {
    if (need <= *cap)
        return true;
    size_t c = *cap ? *cap : 8;
    while (c < need)
        c *= 2;
    void *nv = qd__realloc(ctx, *v, c * size);
    if (!nv)
        return false;
    *v = nv;
    *cap = c;
    return true;
}

/* A new rational owned by p; its index, or -1. */
static long new_big(qd_ctx *ctx, qd__poly *p) {
    if (!grow(ctx, (void **)&p->bigs, &p->bigcap, p->nbig + 1, sizeof *p->bigs))
        return -1;
    mpq_ptr q = qd__malloc(ctx, sizeof *q);
    if (!q)
        return -1;
    mpq_init(q);
    p->bigs[p->nbig] = q;
    return (long)p->nbig++;
}

/* ---- coefficients ---------------------------------------------------------- */

static void mpz_set_i64(mpz_ptr z, int64_t v) {
    uint64_t u = v < 0 ? -(uint64_t)v : (uint64_t)v;
    mpz_import(z, 1, 1, sizeof u, 0, 0, &u);
    if (v < 0)
        mpz_neg(z, z);
}

static void mpq_set_i64(mpq_ptr q, int64_t v) {
    mpz_set_i64(mpq_numref(q), v);
    mpz_set_ui(mpq_denref(q), 1);
}

static cval cv_get(const qd__poly *p, const qd__coef *c) {
    cval v = {c->kind, 0, 0.0, NULL};
    if (c->kind == QD_COEF_INT)
        v.i = c->v.i;
    else if (c->kind == QD_COEF_FLT)
        v.f = c->v.f;
    else
        v.q = p->bigs[c->v.big];
    return v;
}

static double cv_double(cval v) {
    if (v.kind == QD_COEF_INT)
        return (double)v.i;
    return v.kind == QD_COEF_FLT ? v.f : mpq_get_d(v.q);
}

/* v as a rational in tmp (or v's own). */
static mpq_srcptr cv_mpq(cval v, mpq_ptr tmp) {
    if (v.kind == QD_COEF_BIG)
        return v.q;
    mpq_set_i64(tmp, v.i);
    return tmp;
}

/* a*b; a rational result lives in out (two scratch rationals needed). */
static cval cv_mul(cval a, cval b, mpq_ptr out, mpq_ptr tmp) {
    cval r = {QD_COEF_INT, 0, 0.0, NULL};
    if (a.kind == QD_COEF_FLT || b.kind == QD_COEF_FLT) {
        r.kind = QD_COEF_FLT;
        r.f = cv_double(a) * cv_double(b);
        return r;
    }
    if (a.kind == QD_COEF_INT && b.kind == QD_COEF_INT &&
        !__builtin_mul_overflow(a.i, b.i, &r.i))
        return r;
    mpq_srcptr qa = cv_mpq(a, out);
    mpq_srcptr qb = cv_mpq(b, tmp);
    mpq_mul(out, qa, qb);
    r.kind = QD_COEF_BIG;
    r.q = out;
    return r;
}

static bool coef_store(qd_ctx *ctx, qd__poly *p, qd__coef *c, cval v) {
    c->kind = v.kind;
    if (v.kind == QD_COEF_INT)
        c->v.i = v.i;
    else if (v.kind == QD_COEF_FLT)
        c->v.f = v.f;
    else {
        long k = new_big(ctx, p);
        if (k < 0)
            return false;
        mpq_set(p->bigs[k], v.q);
        c->v.big = (uint32_t)k;
    }
    return true;
}

/* c += v, c stored in p; tmp is scratch. */
static bool coef_acc(qd_ctx *ctx, qd__poly *p, qd__coef *c, cval v, mpq_ptr tmp) {
    int64_t sum;
    if (c->kind == QD_COEF_INT && v.kind == QD_COEF_INT &&
        !__builtin_add_overflow(c->v.i, v.i, &sum)) {
        c->v.i = sum;
        return true;
    }
    if (c->kind == QD_COEF_FLT || v.kind == QD_COEF_FLT) {
        double x = cv_double(cv_get(p, c)) + cv_double(v);
        c->kind = QD_COEF_FLT;
        c->v.f = x;
        return true;
    }
    if (c->kind == QD_COEF_INT) {
        long k = new_big(ctx, p);
        if (k < 0)
            return false;
        mpq_set_i64(p->bigs[k], c->v.i);
        c->kind = QD_COEF_BIG;
        c->v.big = (uint32_t)k;
    }
    mpq_ptr q = p->bigs[c->v.big];
    mpq_add(q, q, cv_mpq(v, tmp));
    return true;
}

static bool coef_zero(const qd__poly *p, const qd__coef *c) {
    if (c->kind == QD_COEF_INT)
        return c->v.i == 0;
    if (c->kind == QD_COEF_FLT)
        return c->v.f == 0.0;
    return mpq_sgn(p->bigs[c->v.big]) == 0;
}

bool qd__poly_coef_is_zero(const qd__poly *p, size_t t) { return coef_zero(p, &p->terms[t].c); }

bool qd__poly_coef_is_one(const qd__poly *p, size_t t) {
    const qd__coef *c = &p->terms[t].c;
    if (c->kind == QD_COEF_INT)
        return c->v.i == 1;
    return c->kind == QD_COEF_BIG && mpq_cmp_si(p->bigs[c->v.big], 1, 1) == 0;
}

const qd_expr *qd__poly_coef_node(qd_ctx *ctx, const qd__poly *p, size_t t) {
    cval v = cv_get(p, &p->terms[t].c);
    if (v.kind == QD_COEF_FLT)
        return qd_float(ctx, v.f);
    if (v.kind == QD_COEF_BIG)
        return qd__rat_mpq(ctx, v.q);
    if (v.i >= -1000000000 && v.i <= 1000000000)
        return qd_int(ctx, (long)v.i);
    mpq_t q;
    mpq_init(q);
    mpq_set_i64(q, v.i);
    const qd_expr *r = qd__rat_mpq(ctx, q);
    mpq_clear(q);
    return r;
}

/* ---- monomials ---------------------------------------------------------------- */

static uint64_t pair_hash(uint32_t var, int32_t exp) {
    uint64_t z = ((uint64_t)var << 32 | (uint32_t)exp) + 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

/* The product of two monomials into out; its length, or -1 on overflow. */
static long mono_mul(qd__pvar *out, const qd__pvar *a, uint32_t na, const qd__pvar *b,
                     uint32_t nb, uint64_t *hash) {
    uint32_t i = 0, j = 0;
    long n = 0;
    uint64_t h = 0;
    while (i < na || j < nb) {
        qd__pvar v;
        if (j == nb || (i < na && a[i].var < b[j].var))
            v = a[i++];
        else if (i == na || b[j].var < a[i].var)
            v = b[j++];
        else {
            v.var = a[i].var;
            if (__builtin_add_overflow(a[i].exp, b[j].exp, &v.exp))
                return -1;
            i++, j++;
            if (v.exp == 0)
                continue; /* x * x^-1 */
        }
        out[n++] = v;
        h += pair_hash(v.var, v.exp);
    }
    *hash = h;
    return n;
}

/* The monomial of term t.  A constant term's is empty, and a polynomial of
 * constants has no pool at all: NULL + 0 is undefined in C, so NULL. */
static const qd__pvar *mono_of(const qd__poly *p, const qd__pterm *t) {
    return t->len ? p->pool + t->off : NULL;
}

static bool mono_eq(const qd__pvar *a, const qd__pvar *b, uint32_t len) {
    for (uint32_t i = 0; i < len; i++)
        if (a[i].var != b[i].var || a[i].exp != b[i].exp)
            return false;
    return true;
}

/* ---- the accumulating builder ------------------------------------------------- */

typedef struct pbuild {
    qd_ctx *ctx;
    qd__poly *out;
    uint32_t *slot; /* term index + 1; 0 is empty: small, or allocated */
    size_t mask;
    uint32_t small[64]; /* most builds are a few terms: no table to allocate */
    /* Scratch rationals, initialized on the first coefficient that leaves
     * int64: most builds never need them, and three mpq_init/mpq_clear
     * pairs (six allocations) per build were an eighth of a derivation. */
    bool big;
    mpq_t tmp, prod, tmp2;
} pbuild;

static void pb_big(pbuild *b) {
    if (!b->big)
        mpq_inits(b->tmp, b->prod, b->tmp2, NULL);
    b->big = true;
}

static bool pb_init(pbuild *b, qd_ctx *ctx, size_t expect) {
    size_t cap = 16;
    while (cap < 2 * expect && cap < ((size_t)1 << 26))
        cap *= 2;
    b->ctx = ctx;
    b->out = qd__calloc(ctx, 1, sizeof *b->out);
    if (cap <= sizeof b->small / sizeof b->small[0]) {
        memset(b->small, 0, cap * sizeof b->small[0]);
        b->slot = b->small;
    } else {
        b->slot = qd__calloc(ctx, cap, sizeof *b->slot);
    }
    b->mask = cap - 1;
    b->big = false;
    if (!b->out || !b->slot) {
        qd__oom(ctx);
        return false;
    }
    return true;
}

static void pb_release(pbuild *b) {
    if (b->slot != b->small)
        qd__free(b->slot);
    b->slot = NULL;
    if (b->big)
        mpq_clears(b->tmp, b->prod, b->tmp2, NULL);
    b->big = false;
}

static void pb_fail(pbuild *b) {
    pb_release(b);
    qd__poly_free(b->out);
    b->out = NULL;
}

static bool pb_rehash(pbuild *b) {
    size_t cap = (b->mask + 1) * 2;
    uint32_t *slot = qd__calloc(b->ctx, cap, sizeof *slot); /* small is the table read */
    if (!slot)
        return false;
    for (size_t t = 0; t < b->out->n; t++) {
        size_t i = b->out->terms[t].hash & (cap - 1);
        while (slot[i])
            i = (i + 1) & (cap - 1);
        slot[i] = (uint32_t)t + 1;
    }
    if (b->slot != b->small)
        qd__free(b->slot);
    b->slot = slot;
    b->mask = cap - 1;
    return true;
}

static bool pb_new_term(pbuild *b, size_t i, const qd__pvar *m, uint32_t len, uint64_t h,
                        cval c) {
    qd__poly *p = b->out;
    if (p->n >= QD_POLY_MAX_TERMS) {
        qd_ctx_error(b->ctx, QD_ERR_TOOBIG, "expansion beyond %u terms", QD_POLY_MAX_TERMS);
        return false;
    }
    if (!grow(b->ctx, (void **)&p->terms, &p->cap, p->n + 1, sizeof *p->terms) ||
        !grow(b->ctx, (void **)&p->pool, &p->pcap, p->plen + len, sizeof *p->pool))
        goto oom;
    qd__pterm *t = &p->terms[p->n];
    t->hash = h;
    t->off = (uint32_t)p->plen;
    t->len = len;
    if (len)
        memcpy(p->pool + p->plen, m, len * sizeof *m);
    p->plen += len;
    if (!coef_store(b->ctx, p, &t->c, c))
        goto oom;
    b->slot[i] = (uint32_t)++p->n;
    if (2 * p->n > b->mask && !pb_rehash(b))
        goto oom;
    return true;
oom:
    qd__oom(b->ctx);
    return false;
}

/* Add c times the monomial m. */
static bool pb_add(pbuild *b, const qd__pvar *m, uint32_t len, uint64_t h, cval c) {
    size_t i = h & b->mask;
    for (uint32_t s; (s = b->slot[i]) != 0; i = (i + 1) & b->mask) {
        qd__pterm *t = &b->out->terms[s - 1];
        if (t->hash == h && t->len == len && mono_eq(mono_of(b->out, t), m, len)) {
            int64_t sum;
            if (t->c.kind != QD_COEF_INT || c.kind != QD_COEF_INT ||
                __builtin_add_overflow(t->c.v.i, c.i, &sum))
                pb_big(b);
            if (coef_acc(b->ctx, b->out, &t->c, c, b->tmp))
                return true;
            qd__oom(b->ctx);
            return false;
        }
    }
    return pb_new_term(b, i, m, len, h, c);
}

/* The result, without the terms that cancelled. */
static qd__poly *pb_finish(pbuild *b) {
    qd__poly *p = b->out;
    size_t m = 0;
    for (size_t t = 0; t < p->n; t++)
        if (!coef_zero(p, &p->terms[t].c))
            p->terms[m++] = p->terms[t];
    p->n = m;
    pb_release(b);
    return p;
}

/* ---- arithmetic ------------------------------------------------------------------ */

static qd__poly *single(qd_ctx *ctx, const qd__pvar *m, uint32_t len, cval c) {
    pbuild b;
    uint64_t h = 0;
    for (uint32_t i = 0; i < len; i++)
        h += pair_hash(m[i].var, m[i].exp);
    if (!pb_init(&b, ctx, 1) || !pb_add(&b, m, len, h, c)) {
        pb_fail(&b);
        return NULL;
    }
    return pb_finish(&b);
}

qd__poly *qd__poly_number(qd_ctx *ctx, const qd_expr *num) {
    cval c = {QD_COEF_FLT, 0, 0.0, NULL};
    if (num->kind == QD_FLOAT) {
        c.f = num->u.f;
    } else if (mpz_cmp_ui(mpq_denref(num->u.q), 1) == 0 &&
               mpz_sizeinbase(mpq_numref(num->u.q), 2) < 62) {
        c.kind = QD_COEF_INT;
        c.i = mpz_get_si(mpq_numref(num->u.q));
    } else {
        c.kind = QD_COEF_BIG;
        c.q = num->u.q;
    }
    return single(ctx, NULL, 0, c);
}

qd__poly *qd__poly_var(qd_ctx *ctx, uint32_t var, int32_t exp) {
    qd__pvar v = {var, exp};
    cval one = {QD_COEF_INT, 1, 0.0, NULL};
    return single(ctx, &v, exp ? 1 : 0, one);
}

qd__poly *qd__poly_add_n(qd_ctx *ctx, size_t n, const qd__poly *const *ps) {
    size_t total = 0;
    for (size_t k = 0; k < n; k++)
        total += ps[k]->n;
    pbuild b;
    if (!pb_init(&b, ctx, total))
        goto fail;
    for (size_t k = 0; k < n; k++) {
        const qd__poly *p = ps[k];
        for (size_t t = 0; t < p->n; t++) {
            const qd__pterm *pt = &p->terms[t];
            if (!pb_add(&b, mono_of(p, pt), pt->len, pt->hash, cv_get(p, &pt->c)))
                goto fail;
        }
    }
    return pb_finish(&b);
fail:
    pb_fail(&b);
    return NULL;
}

static size_t max_len(const qd__poly *p) {
    size_t m = 0;
    for (size_t t = 0; t < p->n; t++)
        if (p->terms[t].len > m)
            m = p->terms[t].len;
    return m;
}

/* ---- size bounds -------------------------------------------------------------
 * What x*y or a^n would take, bounded from above before any of it is made, so
 * that an expansion too large for memory is refused (or, in expand.c, left as
 * a power) instead of running GMP and FLINT out of memory, which abort. */

/* log2 of the sum of |numerator| over p's terms (bits of its height bound),
 * and the bits of its largest denominator; float coefficients count as 64
 * bits that do not grow. */
static void coef_bits(const qd__poly *p, double *num, double *den, bool *flt) {
    double top = 0, sum = 0;
    *den = 0;
    *flt = false;
    for (size_t t = 0; t < p->n; t++) {
        const qd__coef *c = &p->terms[t].c;
        double nb = 0, db = 0; /* log2 |numerator|, bits of the denominator */
        if (c->kind == QD_COEF_INT) {
            nb = c->v.i == 0 ? -1e300 : log2(fabs((double)c->v.i));
        } else if (c->kind == QD_COEF_BIG) {
            signed long ex;
            double m = mpz_get_d_2exp(&ex, mpq_numref(p->bigs[c->v.big]));
            nb = log2(fabs(m)) + (double)ex;
            db = (double)mpz_sizeinbase(mpq_denref(p->bigs[c->v.big]), 2);
        } else {
            *flt = true;
        }
        if (nb > top) { /* sum stays the sum of 2^(nb - top) */
            sum = sum * exp2(top - nb) + 1;
            top = nb;
        } else {
            sum += exp2(nb - top);
        }
        *den = db > *den ? db : *den;
    }
    *num = top + log2(sum > 1 ? sum : 1);
}

typedef struct vexp {
    uint32_t var, side;
    int32_t exp;
} vexp;

static int vexp_cmp(const void *pa, const void *pb) {
    const vexp *a = pa, *b = pb;
    return (a->var > b->var) - (a->var < b->var);
}

/* The number of monomials in the exponent box of x^n (y NULL) or x*y, and
 * in *nvars the number of generators; a negative number when out of memory. */
static double box_terms(qd_ctx *ctx, const qd__poly *x, const qd__poly *y, long n, double *nvars) {
    size_t len = x->plen + (y ? y->plen : 0), k = 0;
    vexp *v = qd__malloc(ctx, (len + 1) * sizeof *v);
    if (!v)
        return -1;
    for (size_t i = 0; i < x->plen; i++)
        v[k++] = (vexp){x->pool[i].var, 0, x->pool[i].exp};
    for (size_t i = 0; y && i < y->plen; i++)
        v[k++] = (vexp){y->pool[i].var, 1, y->pool[i].exp};
    qsort(v, len, sizeof *v, vexp_cmp);
    double box = 1;
    *nvars = 0;
    for (size_t i = 0; i < len && box < 1e300; ++*nvars) {
        double lo[2] = {0, 0}, hi[2] = {0, 0};
        size_t j = i;
        for (; j < len && v[j].var == v[i].var; j++) {
            lo[v[j].side] = v[j].exp < lo[v[j].side] ? v[j].exp : lo[v[j].side];
            hi[v[j].side] = v[j].exp > hi[v[j].side] ? v[j].exp : hi[v[j].side];
        }
        box *= (y ? hi[0] - lo[0] + hi[1] - lo[1] : (double)n * (hi[0] - lo[0])) + 1;
        i = j;
    }
    qd__free(v);
    return box;
}

/* binomial(n + t - 1, t - 1): the monomials of degree n in t unknowns. */
static double degree_terms(size_t t, long n) {
    double b = 1;
    for (size_t i = 1; i < t && b < 1e300; i++)
        b = b * (double)((size_t)n + i) / (double)i;
    return b;
}

static double bytes_of(double terms, double bits, double mono) {
    return terms * ((double)sizeof(qd__pterm) + mono * (double)sizeof(qd__pvar) + bits / 8);
}

bool qd__poly_fits(qd_ctx *ctx, double bytes) {
    if (bytes >= 0 && bytes <= QD_EXPAND_MAX_BYTES)
        return true;
    if (bytes >= 0)
        qd_ctx_error(ctx, QD_ERR_TOOBIG,
                     "expression too large: expanding it would take about %.2g bytes (limit %d MiB)",
                     bytes, QD_EXPAND_MAX_BYTES >> 20);
    return false;
}

double qd__poly_pow_bytes(qd_ctx *ctx, const qd__poly *a, long n) {
    if (a->n == 0 || (a->n >= 2 && n < 2))
        return 0;
    if (n < 0) /* one term: its inverse to the -n */
        n = n == LONG_MIN ? LONG_MAX : -n;
    double num, den, nvars, box = box_terms(ctx, a, NULL, n, &nvars);
    bool flt;
    if (box < 0) {
        qd__oom(ctx);
        return -1;
    }
    coef_bits(a, &num, &den, &flt);
    /* each numerator of a^n (over den^n) is at most (sum |num|)^n */
    double bits = flt ? 64 : (double)n * (num + den) + 1;
    return bytes_of(fmin(box, degree_terms(a->n, n)), bits, nvars);
}

double qd__poly_mul_bytes(qd_ctx *ctx, const qd__poly *x, const qd__poly *y) {
    double nx, dx, ny, dy, nvars;
    bool fx, fy;
    coef_bits(x, &nx, &dx, &fx);
    coef_bits(y, &ny, &dy, &fy);
    double bits = fx || fy ? 64 : nx + ny + dx + dy + 1; /* |num| <= sum|x| sum|y| */
    /* x->n * y->n terms of at most max_len(x) + max_len(y) generators bound
     * the box's count from above: when that bound fits, the sorted box (most
     * of the cost of a small product) is not needed. */
    double cheap = bytes_of((double)x->n * (double)y->n, bits, (double)(max_len(x) + max_len(y)));
    if (cheap <= QD_EXPAND_MAX_BYTES)
        return cheap;
    double box = box_terms(ctx, x, y, 0, &nvars);
    if (box < 0) {
        qd__oom(ctx);
        return -1;
    }
    return bytes_of(fmin(box, (double)x->n * (double)y->n), bits, nvars);
}

static bool mul_into(pbuild *b, const qd__poly *x, const qd__poly *y, qd__pvar *m) {
    for (size_t i = 0; i < x->n; i++) {
        const qd__pterm *s = &x->terms[i];
        cval cs = cv_get(x, &s->c);
        for (size_t j = 0; j < y->n; j++) {
            const qd__pterm *t = &y->terms[j];
            uint64_t h;
            long len = mono_mul(m, mono_of(x, s), s->len, mono_of(y, t), t->len, &h);
            if (len < 0) {
                qd_ctx_error(b->ctx, QD_ERR_TOOBIG, "exponent overflow in expansion");
                return false;
            }
            cval c = cv_get(y, &t->c);
            int64_t prod;
            if (cs.kind == QD_COEF_INT && c.kind == QD_COEF_INT &&
                !__builtin_mul_overflow(cs.i, c.i, &prod))
                c.i = prod; /* no scratch needed */
            else {
                pb_big(b);
                c = cv_mul(cs, c, b->prod, b->tmp2);
            }
            if (!pb_add(b, m, (uint32_t)len, h, c))
                return false;
        }
    }
    return true;
}

qd__poly *qd__poly_mul(qd_ctx *ctx, const qd__poly *x, const qd__poly *y) {
    bool done;
    if (!qd__poly_fits(ctx, qd__poly_mul_bytes(ctx, x, y)))
        return NULL;
    qd__poly *fast = qd__poly_mul_flint(ctx, x, y, &done);
    if (!done)
        fast = qd__poly_mul_packed(ctx, x, y, &done);
    if (done)
        return fast;
    /* Like terms usually merge, and a small table stays in cache; it grows
     * when they do not. */
    size_t expect = x->n > y->n ? x->n : y->n;
    qd__pvar stack[64];
    size_t need = max_len(x) + max_len(y);
    pbuild b;
    if (!pb_init(&b, ctx, expect)) {
        pb_fail(&b);
        return NULL;
    }
    qd__pvar *m = need <= 64 ? stack : qd__malloc(ctx, need * sizeof *m);
    if (!m)
        qd__oom(ctx);
    bool ok = m && mul_into(&b, x, y, m);
    if (m != stack)
        qd__free(m);
    if (!ok) {
        pb_fail(&b);
        return NULL;
    }
    return pb_finish(&b);
}

/* c^n for a single term, exactly (or in floating point when c is a float). */
static cval cv_pow(cval c, long n, mpq_ptr out) {
    cval r = c;
    if (c.kind == QD_COEF_FLT) {
        r.f = pow(c.f, (double)n);
        return r;
    }
    if (c.kind == QD_COEF_INT && (c.i == 1 || c.i == -1)) {
        r.i = (n % 2 == 0) ? 1 : c.i;
        return r;
    }
    unsigned long an = n < 0 ? (unsigned long)-n : (unsigned long)n;
    mpq_set(out, cv_mpq(c, out));
    mpz_pow_ui(mpq_numref(out), mpq_numref(out), an);
    mpz_pow_ui(mpq_denref(out), mpq_denref(out), an);
    if (n < 0)
        mpq_inv(out, out);
    r.kind = QD_COEF_BIG;
    r.q = out;
    return r;
}

static qd__poly *mono_pow(qd_ctx *ctx, const qd__poly *a, long n) {
    const qd__pterm *t = &a->terms[0];
    qd__pvar stack[64];
    qd__pvar *m = t->len <= 64 ? stack : qd__malloc(ctx, t->len * sizeof *m);
    if (!m) {
        qd__oom(ctx);
        return NULL;
    }
    qd__poly *r = NULL;
    bool ok = n <= INT32_MAX && n >= -INT32_MAX;
    for (uint32_t i = 0; ok && i < t->len; i++) {
        m[i] = a->pool[t->off + i];
        ok = !__builtin_mul_overflow(m[i].exp, (int32_t)n, &m[i].exp);
    }
    if (ok) {
        mpq_t q;
        mpq_init(q);
        r = single(ctx, m, t->len, cv_pow(cv_get(a, &t->c), n, q));
        mpq_clear(q);
    } else {
        qd_ctx_error(ctx, QD_ERR_TOOBIG, "exponent overflow in expansion");
    }
    if (m != stack)
        qd__free(m);
    return r;
}

qd__poly *qd__poly_pow(qd_ctx *ctx, const qd__poly *a, long n) {
    if (n == 0) {
        cval one = {QD_COEF_INT, 1, 0.0, NULL};
        return single(ctx, NULL, 0, one);
    }
    if (a->n == 0)
        return n > 0 ? qd__poly_zero(ctx) : NULL;
    if (!qd__poly_fits(ctx, qd__poly_pow_bytes(ctx, a, n)))
        return NULL;
    if (a->n == 1)
        return mono_pow(ctx, a, n);
    if (n < 0) {
        qd_ctx_error(ctx, QD_ERR_ARG, "negative power of a polynomial with %zu terms", a->n);
        return NULL;
    }
    bool done;
    qd__poly *fast = qd__poly_pow_flint(ctx, a, n, &done);
    if (!done)
        fast = qd__poly_pow_packed(ctx, a, n, &done);
    if (done)
        return fast;
    /* Repeated multiplication by the (small) base beats squaring here: the
     * last squaring alone costs |a^(n/2)|^2, more than all n steps. */
    qd__poly *acc = qd__poly_mul(ctx, a, a);
    for (long k = 2; acc && k < n; k++) {
        qd__poly *next = qd__poly_mul(ctx, acc, a);
        qd__poly_free(acc);
        acc = next;
    }
    return acc;
}

int32_t qd__poly_exp(const qd__poly *p, size_t t, uint32_t var) {
    const qd__pterm *pt = &p->terms[t];
    for (uint32_t i = 0; i < pt->len; i++)
        if (p->pool[pt->off + i].var == var)
            return p->pool[pt->off + i].exp;
    return 0;
}

bool qd__poly_append(qd_ctx *ctx, qd__poly *dst, const qd__poly *src, size_t t, uint32_t var) {
    const qd__pterm *st = &src->terms[t];
    if (!grow(ctx, (void **)&dst->terms, &dst->cap, dst->n + 1, sizeof *dst->terms) ||
        !grow(ctx, (void **)&dst->pool, &dst->pcap, dst->plen + st->len, sizeof *dst->pool))
        goto oom;
    qd__pterm *dt = &dst->terms[dst->n];
    dt->off = (uint32_t)dst->plen;
    dt->hash = 0;
    for (uint32_t i = 0; i < st->len; i++) {
        qd__pvar v = src->pool[st->off + i];
        if (v.var == var)
            continue;
        dst->pool[dst->plen++] = v;
        dt->hash += pair_hash(v.var, v.exp);
    }
    dt->len = (uint32_t)(dst->plen - dt->off);
    if (!coef_store(ctx, dst, &dt->c, cv_get(src, &st->c)))
        goto oom;
    dst->n++;
    return true;
oom:
    qd__oom(ctx);
    return false;
}

static bool push(qd_ctx *ctx, qd__poly *p, const qd__pvar *m, uint32_t len, cval c) {
    if (!grow(ctx, (void **)&p->terms, &p->cap, p->n + 1, sizeof *p->terms) ||
        !grow(ctx, (void **)&p->pool, &p->pcap, p->plen + len, sizeof *p->pool) ||
        !coef_store(ctx, p, &p->terms[p->n].c, c)) {
        qd__oom(ctx);
        return false;
    }
    qd__pterm *t = &p->terms[p->n++];
    t->off = (uint32_t)p->plen;
    t->len = len;
    t->hash = 0;
    for (uint32_t i = 0; i < len; i++) {
        p->pool[p->plen++] = m[i];
        t->hash += pair_hash(m[i].var, m[i].exp);
    }
    return true;
}

bool qd__poly_push_int(qd_ctx *ctx, qd__poly *p, const qd__pvar *m, uint32_t len, int64_t c) {
    cval v = {QD_COEF_INT, c, 0.0, NULL};
    return push(ctx, p, m, len, v);
}

bool qd__poly_push_mpq(qd_ctx *ctx, qd__poly *p, const qd__pvar *m, uint32_t len, mpq_srcptr c) {
    cval v = {QD_COEF_BIG, 0, 0.0, c};
    if (mpz_cmp_ui(mpq_denref(c), 1) == 0 && mpz_sizeinbase(mpq_numref(c), 2) < 63) {
        v.kind = QD_COEF_INT;
        v.i = mpz_get_si(mpq_numref(c));
    }
    return push(ctx, p, m, len, v);
}

qd__poly *qd__poly_slice(qd_ctx *ctx, const qd__poly *p, uint32_t var, int32_t exp) {
    qd__poly *r = qd__poly_zero(ctx);
    for (size_t t = 0; r && t < p->n; t++) {
        if (qd__poly_exp(p, t, var) == exp && !qd__poly_append(ctx, r, p, t, var)) {
            qd__poly_free(r);
            r = NULL;
        }
    }
    return r;
}
