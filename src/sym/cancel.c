/*
 * src/sym/cancel.c - a rational expression over one denominator, with the
 * polynomial gcd of numerator and denominator cancelled.
 *
 * Sums, products and integer powers are read as arithmetic of fractions N/D
 * of FLINT polynomials (fmpz_mpoly) in generators: every other node (symbol,
 * constant, float, function call, ...) is a generator after its own
 * arguments are cancelled; b^(p/q) is the generator b^(1/q) to the power p,
 * so x^(3/2)/x^(1/2) cancels.  Rational coefficients are cleared into
 * integers (a denominator 2 is the constant polynomial 2).  Polynomial
 * identities hold for every value of the generators, so the result equals
 * the input wherever the input is defined.
 *
 * An expression without a denominator is not expanded: only its generators
 * are cancelled inside.
 */
#include "node.h"
#include "../base/args.h"

#include <flint/fmpz_mpoly.h>
#include <stdlib.h>

#define MAX_POW 64         /* larger integer powers are generators */
#define MAX_TERMS 20000    /* give up (return the input) past this many terms */

typedef struct cc {
    qd_ctx *ctx;
    qd__ptrmap *memo;       /* node -> cancelled node, over the whole call */
    qd__ptrmap atoms;       /* node -> its generator node (or a number) */
    qd__ptrmap gidx;        /* generator node -> index + 1 */
    const qd_expr **gens;
    size_t ngens, cap;
    fmpz_mpoly_ctx_t m;
    bool failed;
} cc;

typedef struct frac {
    fmpz_mpoly_t n, d;
} frac;

static const qd_expr *cancel_expr(qd_ctx *ctx, const qd_expr *e, qd__ptrmap *memo);

/* Integer power that is read as arithmetic (not a generator). */
static bool small_int_exp(const qd_expr *e, long *k) {
    long den;
    return qd_rational_get(e, k, &den) && den == 1 && *k >= -MAX_POW && *k <= MAX_POW;
}

static bool frac_exp(const qd_expr *e, long *p, long *q) {
    return qd_rational_get(e, p, q) && *q != 1 && *p >= -MAX_POW && *p <= MAX_POW;
}

/* The generator for an atom e (power p of it in *pw), or a rational. */
static const qd_expr *atom_of(cc *c, const qd_expr *e, long *pw) {
    long p, q;
    *pw = 1;
    if (e->kind == QD_POW && frac_exp(e->args[1], &p, &q)) {
        *pw = p;
        const qd_expr *b = cancel_expr(c->ctx, e->args[0], c->memo);
        return qd_pow(c->ctx, b, qd_rat(c->ctx, 1, q));
    }
    return e->nargs ? cancel_expr(c->ctx, e, c->memo) : e;
}

static bool is_arith(const qd_expr *e, long *k) {
    return e->kind == QD_ADD || e->kind == QD_MUL ||
           (e->kind == QD_POW && small_int_exp(e->args[1], k));
}

/* Pass 1: find the generators. */
static bool collect(cc *c, const qd_expr *e) {
    long k;
    if (e->kind == QD_RATIONAL || qd__ptrmap_has(&c->atoms, e))
        return true;
    if (is_arith(e, &k)) {
        for (size_t i = 0; i < (e->kind == QD_POW ? 1u : e->nargs); i++)
            if (!collect(c, e->args[i]))
                return false;
        return true;
    }
    long pw;
    const qd_expr *g = atom_of(c, e, &pw);
    if (!g || !qd__ptrmap_put(&c->atoms, e, (void *)g))
        return false;
    if (g->kind == QD_RATIONAL || qd__ptrmap_has(&c->gidx, g))
        return true;
    if (c->ngens == c->cap) {
        size_t cap = c->cap ? 2 * c->cap : 16;
        const qd_expr **v = qd__realloc(c->ctx, c->gens, cap * sizeof *v);
        if (!v)
            return false;
        c->gens = v;
        c->cap = cap;
    }
    c->gens[c->ngens++] = g;
    return qd__ptrmap_put(&c->gidx, g, (void *)(uintptr_t)c->ngens);
}

/* Does e have a denominator that is not a number? */
static bool has_denominator(const qd_expr *e) {
    long k;
    if (e->kind == QD_POW && qd__is_num(e->args[1]) && qd_number_sign(e->args[1]) < 0)
        return true;
    if (!is_arith(e, &k))
        return false;
    for (size_t i = 0; i < e->nargs; i++)
        if (has_denominator(e->args[i]))
            return true;
    return false;
}

/* ---- fractions ------------------------------------------------------------- */

static void frac_init(cc *c, frac *f) {
    fmpz_mpoly_init(f->n, c->m);
    fmpz_mpoly_init(f->d, c->m);
    fmpz_mpoly_one(f->d, c->m);
}

static void frac_clear(cc *c, frac *f) {
    fmpz_mpoly_clear(f->n, c->m);
    fmpz_mpoly_clear(f->d, c->m);
}

static bool too_big(cc *c, const frac *f) {
    if (fmpz_mpoly_length(f->n, c->m) > MAX_TERMS || fmpz_mpoly_length(f->d, c->m) > MAX_TERMS)
        c->failed = true;
    return c->failed;
}

static void set_rational(cc *c, frac *f, const qd_expr *r) {
    fmpz_t z;
    fmpz_init(z);
    fmpz_set_mpz(z, mpq_numref(r->u.q));
    fmpz_mpoly_set_fmpz(f->n, z, c->m);
    fmpz_set_mpz(z, mpq_denref(r->u.q));
    fmpz_mpoly_set_fmpz(f->d, z, c->m);
    fmpz_clear(z);
}

/* f += g over the lcm of the denominators. */
static void frac_add(cc *c, frac *f, frac *g) {
    if (fmpz_mpoly_is_one(g->d, c->m)) {
        fmpz_mpoly_mul(g->n, g->n, f->d, c->m);
        fmpz_mpoly_add(f->n, f->n, g->n, c->m);
        return;
    }
    fmpz_mpoly_t h;
    fmpz_mpoly_init(h, c->m);
    fmpz_mpoly_gcd(h, f->d, g->d, c->m);
    fmpz_mpoly_divides(g->d, g->d, h, c->m);   /* g->d / h */
    fmpz_mpoly_mul(f->n, f->n, g->d, c->m);
    fmpz_mpoly_divides(h, f->d, h, c->m);      /* f->d / h */
    fmpz_mpoly_mul(g->n, g->n, h, c->m);
    fmpz_mpoly_add(f->n, f->n, g->n, c->m);
    fmpz_mpoly_mul(f->d, f->d, g->d, c->m);
    fmpz_mpoly_clear(h, c->m);
}

static void frac_mul(cc *c, frac *f, const frac *g) {
    fmpz_mpoly_mul(f->n, f->n, g->n, c->m);
    fmpz_mpoly_mul(f->d, f->d, g->d, c->m);
}

static bool frac_pow(cc *c, frac *f, long k) {
    if (k < 0) {
        if (fmpz_mpoly_is_zero(f->n, c->m))
            return false;
        fmpz_mpoly_swap(f->n, f->d, c->m);
        k = -k;
    }
    return fmpz_mpoly_pow_ui(f->n, f->n, (ulong)k, c->m) &&
           fmpz_mpoly_pow_ui(f->d, f->d, (ulong)k, c->m);
}

/* Pass 2: e as a fraction. */
static bool to_frac(cc *c, const qd_expr *e, frac *f) {
    long k;
    if (e->kind == QD_RATIONAL) {
        set_rational(c, f, e);
        return true;
    }
    if (!is_arith(e, &k)) {
        const qd_expr *g = qd__ptrmap_get(&c->atoms, e);
        if (g->kind == QD_RATIONAL) {
            set_rational(c, f, g);
            return true;
        }
        atom_of(c, e, &k); /* the power only: the node is memoized */
        fmpz_mpoly_gen(f->n, (slong)(uintptr_t)qd__ptrmap_get(&c->gidx, g) - 1, c->m);
        return frac_pow(c, f, k);
    }
    if (e->kind == QD_POW)
        return to_frac(c, e->args[0], f) && frac_pow(c, f, k) && !too_big(c, f);
    if (e->kind == QD_ADD)
        fmpz_mpoly_zero(f->n, c->m);
    else
        fmpz_mpoly_one(f->n, c->m);
    bool ok = true;
    for (size_t i = 0; i < e->nargs && ok; i++) {
        frac g;
        frac_init(c, &g);
        ok = to_frac(c, e->args[i], &g);
        if (ok && e->kind == QD_ADD)
            frac_add(c, f, &g);
        else if (ok)
            frac_mul(c, f, &g);
        frac_clear(c, &g);
        ok = ok && !too_big(c, f);
    }
    return ok;
}

/* ---- back to expressions ------------------------------------------------------ */

static const qd_expr *from_poly(cc *c, const fmpz_mpoly_t p) {
    slong len = fmpz_mpoly_length(p, c->m);
    const qd_expr **terms = qd__malloc(c->ctx, ((size_t)len + 1) * sizeof *terms);
    const qd_expr **fs = qd__malloc(c->ctx, (c->ngens + 1) * sizeof *fs);
    slong *exps = qd__malloc(c->ctx, c->ngens * sizeof *exps);
    const qd_expr *r = NULL;
    if (!terms || !fs || !exps) {
        qd__oom(c->ctx);
        goto done;
    }
    fmpz_t z;
    mpq_t q;
    fmpz_init(z);
    mpq_init(q);
    for (slong i = 0; i < len; i++) {
        fmpz_mpoly_get_term_coeff_fmpz(z, p, i, c->m);
        fmpz_get_mpz(mpq_numref(q), z);
        mpz_set_ui(mpq_denref(q), 1);
        fmpz_mpoly_get_term_exp_si(exps, p, i, c->m);
        size_t m = 0;
        fs[m++] = qd__rat_mpq(c->ctx, q);
        for (size_t v = 0; v < c->ngens; v++)
            if (exps[v])
                fs[m++] = qd_powi(c->ctx, c->gens[v], exps[v]);
        terms[i] = qd_mul_n(c->ctx, m, fs);
    }
    fmpz_clear(z);
    mpq_clear(q);
    r = qd_add_n(c->ctx, (size_t)len, terms);
done:
    qd__free(terms);
    qd__free(fs);
    qd__free(exps);
    return r;
}

/* Divide out the gcd; the denominator's leading coefficient made positive. */
static const qd_expr *reduce(cc *c, frac *f) {
    fmpz_mpoly_t g;
    fmpz_mpoly_init(g, c->m);
    if (fmpz_mpoly_gcd(g, f->n, f->d, c->m) && !fmpz_mpoly_is_zero(g, c->m)) {
        fmpz_mpoly_divides(f->n, f->n, g, c->m);
        fmpz_mpoly_divides(f->d, f->d, g, c->m);
    }
    fmpz_mpoly_clear(g, c->m);
    fmpz_t z;
    fmpz_init(z);
    fmpz_mpoly_get_term_coeff_fmpz(z, f->d, 0, c->m);
    if (fmpz_sgn(z) < 0) {
        fmpz_mpoly_neg(f->n, f->n, c->m);
        fmpz_mpoly_neg(f->d, f->d, c->m);
    }
    fmpz_clear(z);
    return qd_mul(c->ctx, from_poly(c, f->n), qd_pow(c->ctx, from_poly(c, f->d), c->ctx->sym->minus_one));
}

/* e over one denominator, or NULL with c->failed when it grew too big. */
static const qd_expr *cancel_frac(cc *c, const qd_expr *e) {
    if (!collect(c, e)) {
        if (c->ctx->status == QD_OK)
            qd__oom(c->ctx);
        return NULL;
    }
    if (c->ngens == 0) {
        c->failed = true;
        return NULL;
    }
    fmpz_mpoly_ctx_init(c->m, (slong)c->ngens, ORD_LEX);
    frac f;
    frac_init(c, &f);
    const qd_expr *r = NULL;
    if (to_frac(c, e, &f))
        r = reduce(c, &f);
    else
        c->failed = true;
    frac_clear(c, &f);
    fmpz_mpoly_ctx_clear(c->m);
    return r;
}

static const qd_expr *rebuild_args(qd_ctx *ctx, const qd_expr *e, qd__ptrmap *memo) {
    const qd_expr *stack[8];
    const qd_expr **args = e->nargs <= 8 ? stack : qd__malloc(ctx, e->nargs * sizeof *args);
    if (!args) {
        qd__oom(ctx);
        return NULL;
    }
    const qd_expr *r = e;
    bool changed = false;
    for (size_t i = 0; i < e->nargs && r; i++) {
        args[i] = cancel_expr(ctx, e->args[i], memo);
        if (!args[i])
            r = NULL;
        else
            changed |= args[i] != e->args[i];
    }
    if (r && changed)
        r = qd__rebuild(ctx, e, args);
    if (args != stack)
        qd__free(args);
    return r;
}

static const qd_expr *cancel_expr(qd_ctx *ctx, const qd_expr *e, qd__ptrmap *memo) {
    if (!e->nargs)
        return e;
    const qd_expr *r = qd__ptrmap_get(memo, e);
    if (r)
        return r;
    long k;
    if (is_arith(e, &k) && has_denominator(e)) {
        cc c = {.ctx = ctx, .memo = memo}; /* the rest zero: empty maps, no generators */
        r = cancel_frac(&c, e);
        qd__ptrmap_free(&c.atoms);
        qd__ptrmap_free(&c.gidx);
        qd__free(c.gens);
        if (c.failed && !r)
            r = rebuild_args(ctx, e, memo);
    } else {
        r = rebuild_args(ctx, e, memo);
    }
    if (r && !qd__ptrmap_put(memo, e, (void *)r)) {
        qd__oom(ctx);
        r = NULL;
    }
    return r;
}

const qd_expr *qd_cancel(qd_ctx *ctx, const qd_expr *e) {
    QD_ARGS(NULL, ctx && e);
    if (!e)
        return NULL;
    qd__ptrmap memo = QD_PTRMAP_AL(qd__ctx_allocator(ctx));
    qd__gmp_section outer = qd__gmp_enter(ctx);
    const qd_expr *r = cancel_expr(ctx, e, &memo);
    qd__ptrmap_free(&memo);
    return qd__gmp_leave(ctx, outer) ? r : NULL;
}
