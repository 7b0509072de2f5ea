/*
 * src/sym/poly_flint.c - large exact products and powers by FLINT.
 *
 * fmpz_mpoly multiplies (dense arrays or Johnson's heap) and powers
 * (Monagan-Pearce) faster than our hash-table loops once there are tens of
 * thousands of term pairs over a few generators, conversion included
 * (docs/design.md, "Expansion: our engine and FLINT").  Only the generators
 * that occur get a FLINT variable, in increasing index so monomials come
 * back sorted.  Laurent monomials are shifted by the least exponent of each
 * generator (times n for a power) and shifted back; rational coefficients
 * are scaled to integers by the lcm of their denominators and divided back.
 * Float coefficients, and anything whose exponents or size could overflow
 * our limits, stay on the general path in poly.c (*done false).  FLINT
 * aborts when memory runs out, as in cancel.c, instead of reporting
 * QD_ERR_NOMEM.
 */
#include "poly.h"
#include "../base/mem.h"

#include <flint/fmpz_mpoly.h>
#include <stdlib.h>

/* Where FLINT pays, conversion included (measured, see the design note):
 * products of at least this many term pairs over at most MUL_MAX_VARS
 * generators, and powers over at most POW_MAX_VARS generators worth at
 * least POW_MIN_WORK (terms of the base times a bound on the terms of the
 * result).  Below, the hash-table loops win; with more generators FLINT's
 * dense exponent vectors cost more than our sparse monomials. */
#define MUL_MIN_PAIRS 16384
#define MUL_MAX_VARS 8
#define POW_MIN_WORK 3000
#define POW_MAX_VARS 4

typedef struct fplan {
    slong nv;
    uint32_t *var;    /* slot -> generator */
    uint32_t *slot;   /* generator -> slot + 1 (0: absent) */
    int64_t *lo, *hi; /* per slot, over both operands: [2 * slot + side] */
    mpz_t den[2];     /* lcm of the coefficient denominators */
    fmpz_mpoly_ctx_t m;
    bool has_m;
} fplan;

static uint32_t max_var(const qd__poly *p) {
    uint32_t m = 0;
    for (size_t i = 0; i < p->plen; i++)
        if (p->pool[i].var > m)
            m = p->pool[i].var;
    return m;
}

/* The lcm of the denominators into den; false for a float coefficient. */
static bool scan_coefs(const qd__poly *p, mpz_ptr den) {
    mpz_set_ui(den, 1);
    for (size_t t = 0; t < p->n; t++) {
        const qd__coef *c = &p->terms[t].c;
        if (c->kind == QD_COEF_FLT)
            return false;
        if (c->kind == QD_COEF_BIG)
            mpz_lcm(den, den, mpq_denref(p->bigs[c->v.big]));
    }
    return true;
}

static void scan_exps(fplan *pl, const qd__poly *p, int side) {
    for (size_t i = 0; i < p->plen; i++) {
        qd__pvar v = p->pool[i];
        size_t k = 2 * (pl->slot[v.var] - 1) + (size_t)side;
        if (v.exp < pl->lo[k])
            pl->lo[k] = v.exp;
        if (v.exp > pl->hi[k])
            pl->hi[k] = v.exp;
    }
}

static void plan_free(fplan *pl) {
    qd__free(pl->var);
    qd__free(pl->slot);
    qd__free(pl->lo);
    qd__free(pl->hi);
    mpz_clears(pl->den[0], pl->den[1], NULL);
    if (pl->has_m)
        fmpz_mpoly_ctx_clear(pl->m);
}

/* Slots, exponent ranges and denominators of x and y (y NULL for a power);
 * -1 out of memory, 0 not for FLINT, 1 ready. */
static int plan_make(qd_ctx *ctx, fplan *pl, const qd__poly *x, const qd__poly *y) {
    uint32_t mv = max_var(x);
    if (y && max_var(y) > mv)
        mv = max_var(y);
    *pl = (fplan){0};
    mpz_inits(pl->den[0], pl->den[1], NULL);
    if (!scan_coefs(x, pl->den[0]) || (y && !scan_coefs(y, pl->den[1])))
        return 0;
    pl->slot = qd__calloc(ctx, (size_t)mv + 1, sizeof *pl->slot);
    pl->var = qd__malloc(ctx, ((size_t)mv + 1) * sizeof *pl->var);
    if (!pl->slot || !pl->var)
        return -1;
    for (int s = 0; s < 2; s++) {
        const qd__poly *p = s ? y : x;
        for (size_t i = 0; p && i < p->plen; i++)
            pl->slot[p->pool[i].var] = 1;
    }
    for (uint32_t v = 0; v <= mv; v++)
        if (pl->slot[v]) {
            pl->var[pl->nv] = v;
            pl->slot[v] = (uint32_t)++pl->nv;
        }
    pl->lo = qd__calloc(ctx, 2 * (size_t)pl->nv + 2, sizeof *pl->lo);
    pl->hi = qd__calloc(ctx, 2 * (size_t)pl->nv + 2, sizeof *pl->hi);
    if (!pl->lo || !pl->hi)
        return -1;
    scan_exps(pl, x, 0);
    if (y)
        scan_exps(pl, y, 1);
    if (pl->nv == 0)
        return 0;
    fmpz_mpoly_ctx_init(pl->m, pl->nv, ORD_LEX);
    pl->has_m = true;
    return 1;
}

/* p (side s of the plan) as den * p, shifted to nonnegative exponents. */
static void to_flint(fmpz_mpoly_t a, fplan *pl, const qd__poly *p, int s, ulong *e) {
    fmpz_t c;
    mpz_t z;
    fmpz_init(c);
    mpz_init(z);
    fmpz_mpoly_fit_length(a, (slong)p->n, pl->m);
    for (size_t t = 0; t < p->n; t++) {
        const qd__pterm *pt = &p->terms[t];
        for (slong k = 0; k < pl->nv; k++)
            e[k] = (ulong)-pl->lo[2 * k + s];
        for (uint32_t i = 0; i < pt->len; i++) {
            qd__pvar v = p->pool[pt->off + i];
            uint32_t k = pl->slot[v.var] - 1;
            e[k] = (ulong)(v.exp - pl->lo[2 * k + (uint32_t)s]);
        }
        if (pt->c.kind == QD_COEF_INT) {
            fmpz_set_mpz(c, pl->den[s]);
            fmpz_mul_si(c, c, (slong)pt->c.v.i);
        } else {
            mpq_srcptr q = p->bigs[pt->c.v.big];
            mpz_divexact(z, pl->den[s], mpq_denref(q));
            mpz_mul(z, z, mpq_numref(q));
            fmpz_set_mpz(c, z);
        }
        fmpz_mpoly_push_term_fmpz_ui(a, c, e, pl->m);
    }
    fmpz_mpoly_sort_terms(a, pl->m);
    fmpz_clear(c);
    mpz_clear(z);
}

/* a / den as a qd__poly, exponents shifted by shift[slot]. */
static qd__poly *from_flint(qd_ctx *ctx, const fplan *pl, const fmpz_mpoly_t a,
                           const int64_t *shift, mpz_srcptr den, ulong *e, qd__pvar *m) {
    qd__poly *r = qd__poly_zero(ctx);
    bool unit = mpz_cmp_ui(den, 1) == 0;
    mpq_t q;
    mpq_init(q);
    slong n = fmpz_mpoly_length(a, pl->m);
    for (slong t = 0; r && t < n; t++) {
        fmpz_mpoly_get_term_exp_ui(e, a, t, pl->m);
        uint32_t len = 0;
        for (slong k = 0; k < pl->nv; k++) {
            int64_t x = (int64_t)e[k] + shift[k];
            if (x != 0)
                m[len++] = (qd__pvar){pl->var[k], (int32_t)x};
        }
        const fmpz *c = a->coeffs + t;
        bool ok;
        if (unit && fmpz_fits_si(c)) {
            ok = qd__poly_push_int(ctx, r, m, len, (int64_t)fmpz_get_si(c));
        } else {
            fmpz_get_mpz(mpq_numref(q), c);
            mpz_set(mpq_denref(q), den);
            mpq_canonicalize(q);
            ok = qd__poly_push_mpq(ctx, r, m, len, q);
        }
        if (!ok) {
            qd__poly_free(r);
            r = NULL;
        }
    }
    mpq_clear(q);
    return r;
}

/* The result's exponent range per slot, [shift, top]: of x*y, or of x^n
 * when n > 0.  False when the result could hold an exponent beyond int32 or
 * more terms than we allow: then the general path reports it. */
static bool result_range(const fplan *pl, long n, double terms, int64_t *shift) {
    double box = 1;
    for (slong k = 0; k < pl->nv; k++) {
        const int64_t *lo = pl->lo + 2 * k, *hi = pl->hi + 2 * k;
        int64_t top = n ? n * hi[0] : hi[0] + hi[1];
        shift[k] = n ? n * lo[0] : lo[0] + lo[1];
        if (shift[k] < -INT32_MAX || top > INT32_MAX)
            return false;
        box *= (double)(top - shift[k] + 1);
    }
    return (terms < box ? terms : box) <= QD_POLY_MAX_TERMS;
}

/* A bound on the number of terms of a t-term polynomial to the n:
 * binomial(n + t - 1, t - 1), saturating. */
static double pow_terms(size_t t, long n) {
    double b = 1;
    for (size_t i = 1; i < t && b < 1e18; i++)
        b = b * (double)((size_t)n + i) / (double)i;
    return b;
}

/* den * (x*y) in c (or den^n * x^n when y is NULL); den becomes the
 * result's denominator. */
static void compute(fmpz_mpoly_t c, fplan *pl, const qd__poly *x, const qd__poly *y, long n,
                    ulong *e) {
    fmpz_mpoly_t a, b;
    fmpz_mpoly_init(a, pl->m);
    fmpz_mpoly_init(b, pl->m);
    to_flint(a, pl, x, 0, e);
    if (y) {
        to_flint(b, pl, y, 1, e);
        fmpz_mpoly_mul(c, a, b, pl->m);
        mpz_mul(pl->den[0], pl->den[0], pl->den[1]);
    } else {
        fmpz_mpoly_pow_ui(c, a, (ulong)n, pl->m);
        mpz_pow_ui(pl->den[0], pl->den[0], (unsigned long)n);
    }
    fmpz_mpoly_clear(a, pl->m);
    fmpz_mpoly_clear(b, pl->m);
}

/* x*y, or x^n when y is NULL, when there are at most max_vars generators. */
static qd__poly *run(qd_ctx *ctx, const qd__poly *x, const qd__poly *y, long n, slong max_vars,
                    bool *done) {
    fplan pl;
    int st = plan_make(ctx, &pl, x, y);
    if (st > 0 && pl.nv > max_vars)
        st = 0;
    int64_t *shift = st > 0 ? qd__malloc(ctx, (size_t)pl.nv * sizeof *shift) : NULL;
    ulong *e = shift ? qd__malloc(ctx, (size_t)pl.nv * sizeof *e) : NULL;
    qd__pvar *m = e ? qd__malloc(ctx, (size_t)pl.nv * sizeof *m) : NULL;
    qd__poly *r = NULL;
    if (st > 0 && !m)
        st = -1;
    double terms = y ? (double)x->n * (double)y->n : pow_terms(x->n, n);
    if (st > 0 && result_range(&pl, y ? 0 : n, terms, shift)) {
        fmpz_mpoly_t c;
        fmpz_mpoly_init(c, pl.m);
        compute(c, &pl, x, y, n, e);
        r = from_flint(ctx, &pl, c, shift, pl.den[0], e, m);
        fmpz_mpoly_clear(c, pl.m);
        *done = true;
    } else if (st < 0) {
        qd__oom(ctx);
        *done = true;
    }
    qd__free(shift), qd__free(e), qd__free(m);
    plan_free(&pl);
    return r;
}

qd__poly *qd__poly_mul_flint(qd_ctx *ctx, const qd__poly *x, const qd__poly *y, bool *done) {
    *done = false;
    if ((double)x->n * (double)y->n < MUL_MIN_PAIRS)
        return NULL;
    return run(ctx, x, y, 0, MUL_MAX_VARS, done);
}

qd__poly *qd__poly_pow_flint(qd_ctx *ctx, const qd__poly *a, long n, bool *done) {
    *done = false;
    if (a->n < 2 || n < 2 || (double)a->n * pow_terms(a->n, n) < POW_MIN_WORK)
        return NULL;
    return run(ctx, a, NULL, n, POW_MAX_VARS, done);
}
