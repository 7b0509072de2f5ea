/*
 * src/sym/factor_poly.c - sums factored as polynomials (FLINT's
 * fmpz_mpoly_factor), group by group.
 *
 * The terms of a sum are grouped by their denominator: the product of their
 * factors with a negative numeric exponent (the rational coefficient's
 * denominator aside), so p^2/(2*A*s^2) - p*q*c/(A*s^2) + q^2*c^2/(2*A*s^2)
 * is one group over A*s^2 and a further q^2/(2*C) another.  A group's
 * numerator, sum c_i N_i, is a polynomial in generators: the bases of the
 * positive integer powers and every other factor (a symbol, sin(u), sqrt(..),
 * a sum, a user function) as a whole.  Its factorization over the integers,
 * times the group's denominator, replaces the group when the whole sum gets
 * shorter by qd_count_ops: (p - q*c)^2/(2*A*s^2).  A group that does not
 * factor is split into the parts that share no generator (a^2 - 2*a*b + b^2
 * + c: the square and c), and those are tried on their own.
 *
 * A factor's sign is chosen the way the printer prefers (no leading minus),
 * the sign moved to the constant when the exponent is odd, so a numerator
 * and a denominator factored apart come out with identical factors, which
 * the canonical product then cancels: (x^2 - 1)*(x + 1)^-1 -> x - 1.
 *
 * Bounded so that derivations pay little for it: a group of more than
 * MAX_TERMS terms, or with a term of total degree above MAX_DEG, is left
 * alone, as is one of total degree below 2 (nothing to factor).
 * Polynomial identities hold for every value of the generators, so the value
 * is kept wherever the input is defined.
 */
#include "factor_poly.h"
#include "../base/mem.h"

#include <flint/fmpz_mpoly.h>
#include <flint/fmpz_mpoly_factor.h>
#include <stdlib.h>

#define MAX_TERMS 60
#define MAX_DEG 12

typedef struct fterm {
    const qd_expr *coeff;         /* rational coefficient */
    const qd_expr *den;           /* product of the negative powers: the group key */
    const qd_expr *const *fs;     /* the factors after the coefficient */
    size_t nf;
    long deg;                     /* total degree of the numerator */
    bool ok;                      /* exact coefficient, degree within the bound */
} fterm;

typedef struct fsum {
    qd_ctx *ctx;
    const qd_expr **cur;          /* the sum's terms now (NULL: replaced) */
    fterm *t;
    size_t n;
    const qd_expr **extra;        /* replacements of groups */
    size_t nextra;
    size_t ops;                   /* qd_count_ops of the sum now */
    const qd_expr *sum;
} fsum;

static bool neg_power(const qd_expr *f) {
    return f->kind == QD_POW && qd__is_num(f->args[1]) && qd_number_sign(f->args[1]) < 0;
}

/* A positive factor as generator^k. */
static const qd_expr *gen_of(const qd_expr *f, long *k) {
    long den;
    if (f->kind == QD_POW && qd_rational_get(f->args[1], k, &den) && den == 1 && *k > 0)
        return f->args[0];
    *k = 1;
    return f;
}

/* The i-th factor after the coefficient of term node. */
static const qd_expr *factor_at(const qd_expr *node, const fterm *t, size_t i) {
    return node->kind == QD_MUL ? t->fs[i] : node;
}

static bool split_term(qd_ctx *ctx, const qd_expr *node, fterm *t) {
    t->ok = false;
    t->coeff = ctx->sym->one;
    t->fs = NULL;
    t->nf = 1;
    if (qd__is_num(node)) {
        t->coeff = node;
        t->nf = 0;
    } else if (node->kind == QD_MUL) {
        size_t off = qd__is_num(node->args[0]) ? 1 : 0;
        t->coeff = off ? node->args[0] : ctx->sym->one;
        t->fs = node->args + off;
        t->nf = node->nargs - off;
    }
    const qd_expr *neg[64];
    size_t nneg = 0;
    long deg = 0;
    for (size_t i = 0; i < t->nf; i++) {
        const qd_expr *f = factor_at(node, t, i);
        if (neg_power(f)) {
            if (nneg == 64)
                return true;
            neg[nneg++] = f;
        } else {
            long k;
            gen_of(f, &k);
            deg += k;
        }
    }
    /* a subset of a canonical factor list is canonical */
    t->den = nneg == 0 ? ctx->sym->one : nneg == 1 ? neg[0] : qd__mul_raw(ctx, NULL, nneg, neg);
    if (!t->den)
        return false;
    t->deg = deg;
    t->ok = qd__is_rational(t->coeff) && deg <= MAX_DEG;
    return true;
}

/* ---- one group as a polynomial -------------------------------------------- */

typedef struct gens {
    qd__ptrmap idx;                /* generator -> index + 1 */
    const qd_expr **v;
    size_t n, cap;
} gens;

static bool gens_add(qd_ctx *ctx, gens *g, const qd_expr *x) {
    if (qd__ptrmap_has(&g->idx, x))
        return true;
    if (g->n == g->cap) {
        size_t cap = g->cap ? 2 * g->cap : 16;
        const qd_expr **v = qd__realloc(ctx, g->v, cap * sizeof *v);
        if (!v)
            return false;
        g->v = v;
        g->cap = cap;
    }
    g->v[g->n++] = x;
    return qd__ptrmap_put(&g->idx, x, (void *)(uintptr_t)g->n);
}

static int cmp_gen(const void *a, const void *b) {
    return qd_expr_cmp(*(const qd_expr *const *)a, *(const qd_expr *const *)b);
}

static const qd_expr *from_poly(qd_ctx *ctx, const gens *g, const fmpz_mpoly_t p,
                                const fmpz_mpoly_ctx_t m) {
    slong len = fmpz_mpoly_length(p, m);
    const qd_expr **terms = qd__malloc(ctx, ((size_t)len + 1) * sizeof *terms);
    const qd_expr **fs = qd__malloc(ctx, (g->n + 1) * sizeof *fs);
    ulong *exps = qd__malloc(ctx, g->n * sizeof *exps);
    const qd_expr *r = NULL;
    if (!terms || !fs || !exps) {
        qd__oom(ctx);
        goto done;
    }
    fmpz_t z;
    mpq_t q;
    fmpz_init(z);
    mpq_init(q);
    for (slong i = 0; i < len; i++) {
        fmpz_mpoly_get_term_coeff_fmpz(z, p, i, m);
        fmpz_get_mpz(mpq_numref(q), z);
        mpz_set_ui(mpq_denref(q), 1);
        fmpz_mpoly_get_term_exp_ui(exps, p, i, m);
        size_t k = 0;
        fs[k++] = qd__rat_mpq(ctx, q);
        for (size_t v = 0; v < g->n; v++)
            if (exps[v])
                fs[k++] = qd_powi(ctx, g->v[v], (long)exps[v]);
        terms[i] = qd_mul_n(ctx, k, fs);
    }
    fmpz_clear(z);
    mpq_clear(q);
    r = qd_add_n(ctx, (size_t)len, terms);
done:
    qd__free(terms);
    qd__free(fs);
    qd__free(exps);
    return r;
}

/* The numerator of the terms sel[0..k) as a polynomial: their coefficients
 * times the lcm L of the coefficient denominators (returned in lcm). */
static bool build_poly(fsum *s, const size_t *sel, size_t k, gens *g, fmpz_mpoly_t p,
                       const fmpz_mpoly_ctx_t m, mpz_t lcm) {
    mpz_set_ui(lcm, 1);
    for (size_t i = 0; i < k; i++)
        mpz_lcm(lcm, lcm, mpq_denref(s->t[sel[i]].coeff->u.q));
    ulong *exps = qd__calloc(s->ctx, g->n ? g->n : 1, sizeof *exps);
    if (!exps)
        return false;
    fmpz_t c;
    mpz_t z;
    fmpz_init(c);
    mpz_init(z);
    for (size_t i = 0; i < k; i++) {
        const fterm *t = &s->t[sel[i]];
        const qd_expr *node = s->sum->args[sel[i]];
        for (size_t v = 0; v < g->n; v++)
            exps[v] = 0;
        for (size_t j = 0; j < t->nf; j++) {
            const qd_expr *f = factor_at(node, t, j);
            if (neg_power(f))
                continue;
            long e;
            const qd_expr *b = gen_of(f, &e);
            exps[(uintptr_t)qd__ptrmap_get(&g->idx, b) - 1] += (ulong)e;
        }
        mpz_divexact(z, lcm, mpq_denref(t->coeff->u.q));
        mpz_mul(z, z, mpq_numref(t->coeff->u.q));
        fmpz_set_mpz(c, z);
        fmpz_mpoly_push_term_fmpz_ui(p, c, exps, m);
    }
    fmpz_mpoly_sort_terms(p, m);
    fmpz_mpoly_combine_like_terms(p, m);
    fmpz_clear(c);
    mpz_clear(z);
    qd__free(exps);
    return true;
}

/* Is q, without monomial content, irreducible for a reason that costs no
 * factorization?  When a variable v has degree 1, q = A*v + B, and a factor
 * free of v divides both A and B; if A or B is a single term that factor is a
 * monomial, which q (no monomial content) does not have.  (Most sums in
 * derivations are of this kind, and FLINT's factorization over dozens of
 * generators is not cheap.) */
static bool plainly_irreducible(qd_ctx *ctx, const fmpz_mpoly_t q, const fmpz_mpoly_ctx_t m, size_t nvars) {
    slong len = fmpz_mpoly_length(q, m);
    bool clean = qd_ctx_status(ctx) == QD_OK;
    slong *degs = qd__malloc(ctx, nvars * sizeof *degs);
    if (!degs) {
        if (clean) /* "not plainly" is a safe answer: FLINT factors it instead */
            qd_ctx_clear_error(ctx);
        return false;
    }
    fmpz_mpoly_degrees_si(degs, q, m);
    bool yes = false;
    for (size_t v = 0; v < nvars && !yes; v++) {
        if (degs[v] != 1)
            continue;
        slong with = 0;
        for (slong i = 0; i < len; i++)
            with += fmpz_mpoly_get_term_var_exp_si(q, i, (slong)v, m) != 0;
        yes = with == 1 || with == len - 1;
    }
    qd__free(degs);
    return yes;
}

/* base^e as an expression, with the base's sign made printable (no leading
 * minus); an odd power's sign goes to *neg. */
static const qd_expr *factor_power(qd_ctx *ctx, const gens *g, const fmpz_mpoly_t b, slong e,
                                   const fmpz_mpoly_ctx_t m, bool *neg) {
    const qd_expr *x = from_poly(ctx, g, b, m);
    if (x && qd__has_minus(x)) {
        x = qd_neg(ctx, x);
        *neg ^= (e & 1) != 0;
    }
    return qd_powi(ctx, x, e);
}

/* den * p/lcm as k * c * q * den: c the term content of p (a monomial), q
 * the rest, and then q split into its irreducible factors. */
typedef struct pfact {
    const qd_expr *grouped;   /* k*c*q*den; NULL when that is just the terms again */
    const qd_expr *factored;  /* k*c*prod q_i^e_i*den; NULL when q does not split */
} pfact;

static bool factor_poly(qd_ctx *ctx, const gens *g, const fmpz_mpoly_t p,
                        const fmpz_mpoly_ctx_t m, const mpz_t lcm, const qd_expr *den,
                        pfact *out) {
    fmpz_mpoly_t c, q, b;
    fmpz_mpoly_init(c, m);
    fmpz_mpoly_init(q, m);
    fmpz_mpoly_init(b, m);
    fmpz_mpoly_factor_t f;
    fmpz_mpoly_factor_init(f, m);
    const qd_expr **parts = NULL;
    bool ok = true;
    out->grouped = out->factored = NULL;
    fmpz_mpoly_term_content(c, p, m);
    fmpz_mpoly_divides(q, p, c, m);
    bool trivial = fmpz_mpoly_is_one(c, m);
    bool split = fmpz_mpoly_total_degree_si(q, m) >= 2 && fmpz_mpoly_length(q, m) >= 2 &&
                 !plainly_irreducible(ctx, q, m, g->n) && fmpz_mpoly_factor(f, q, m);
    slong len = split ? fmpz_mpoly_factor_length(f, m) : 0, mult = 0;
    for (slong i = 0; i < len; i++)
        mult += fmpz_mpoly_factor_get_exp_si(f, i, m);
    split = split && mult >= 2;
    parts = qd__malloc(ctx, ((size_t)len + 4) * sizeof *parts);
    mpq_t k;
    mpq_init(k);
    if (!parts) {
        ok = false;
        goto done;
    }
    const qd_expr *cx = from_poly(ctx, g, c, m);
    for (int pass = 0; pass < 2; pass++) {
        if (pass == 0 && den == ctx->sym->one && trivial)
            continue;
        if (pass == 1 && !split)
            break;
        size_t np = 3;
        bool neg = false;
        if (pass == 0) {
            mpz_set_ui(mpq_numref(k), 1);
            parts[np++] = factor_power(ctx, g, q, 1, m, &neg);
        } else {
            fmpz_get_mpz(mpq_numref(k), f->constant);
            for (slong i = 0; i < len; i++) {
                fmpz_mpoly_factor_get_base(b, f, i, m);
                parts[np++] = factor_power(ctx, g, b, fmpz_mpoly_factor_get_exp_si(f, i, m), m,
                                           &neg);
            }
        }
        mpz_set(mpq_denref(k), lcm);
        mpq_canonicalize(k);
        if (neg)
            mpq_neg(k, k);
        /* one product: k times a lone sum would be distributed again */
        parts[0] = qd__rat_mpq(ctx, k);
        parts[1] = cx;
        parts[2] = den;
        const qd_expr *r = qd_mul_n(ctx, np, parts);
        if (!r) {
            ok = false;
            break;
        }
        *(pass ? &out->factored : &out->grouped) = r;
    }
done:
    mpq_clear(k);
    qd__free(parts);
    fmpz_mpoly_factor_clear(f, m);
    fmpz_mpoly_clear(c, m);
    fmpz_mpoly_clear(q, m);
    fmpz_mpoly_clear(b, m);
    return ok;
}

static bool try_sel(fsum *s, size_t *sel, size_t k, const qd_expr *den, int depth);

/* qd_count_ops of the sum with the terms sel[0..k) replaced by r; SIZE_MAX
 * with r NULL; false on error. */
static bool ops_with(fsum *s, const size_t *sel, size_t k, const qd_expr *r, size_t *ops) {
    *ops = SIZE_MAX;
    if (!r)
        return true;
    size_t n = 0;
    const qd_expr **v = qd__malloc(s->ctx, (s->n + s->nextra + 1) * sizeof *v);
    if (!v)
        return false;
    for (size_t i = 0; i < s->n; i++) {
        bool in = false;
        for (size_t j = 0; j < k && !in; j++)
            in = sel[j] == i;
        if (s->cur[i] && !in)
            v[n++] = s->cur[i];
    }
    for (size_t i = 0; i < s->nextra; i++)
        v[n++] = s->extra[i];
    v[n++] = r;
    const qd_expr *x = qd_add_n(s->ctx, n, v);
    qd__free(v);
    if (!x)
        return false;
    *ops = qd_count_ops(x);
    return true;
}

/* Replace the terms sel[0..k) by the shorter of a and b (a on a tie) when
 * that shortens the sum. */
static bool accept(fsum *s, const size_t *sel, size_t k, const qd_expr *a, const qd_expr *b) {
    size_t na, nb;
    if (!ops_with(s, sel, k, a, &na) || !ops_with(s, sel, k, b, &nb))
        return false;
    const qd_expr *r = nb < na ? b : a;
    size_t ops = nb < na ? nb : na;
    if (ops < s->ops) {
        for (size_t j = 0; j < k; j++)
            s->cur[sel[j]] = NULL;
        s->extra[s->nextra++] = r;
        s->ops = ops;
    }
    return true;
}

/* Parts of sel that share no generator, each tried on its own. */
static bool try_parts(fsum *s, size_t *sel, size_t k, const qd_expr *den, gens *g, int depth) {
    size_t *root = qd__malloc(s->ctx, g->n * sizeof *root), *gen_of_term = qd__malloc(s->ctx, k * sizeof *gen_of_term);
    size_t *part = qd__malloc(s->ctx, k * sizeof *part);
    bool ok = root && gen_of_term && part;
    if (!ok)
        goto done;
    for (size_t v = 0; v < g->n; v++)
        root[v] = v;
    for (size_t i = 0; i < k; i++) {
        const fterm *t = &s->t[sel[i]];
        const qd_expr *node = s->sum->args[sel[i]];
        size_t first = SIZE_MAX;
        for (size_t j = 0; j < t->nf; j++) {
            const qd_expr *f = factor_at(node, t, j);
            if (neg_power(f))
                continue;
            long e;
            size_t v = (uintptr_t)qd__ptrmap_get(&g->idx, gen_of(f, &e)) - 1;
            while (root[v] != v)
                v = root[v];
            if (first == SIZE_MAX)
                first = v;
            else if (v != first)
                root[v] = first;
        }
        gen_of_term[i] = first;
    }
    for (size_t i = 0; i < k; i++) {
        size_t v = gen_of_term[i];
        while (v != SIZE_MAX && root[v] != v)
            v = root[v];
        gen_of_term[i] = v;
    }
    /* each part in turn: the terms with the same root (constants: none) */
    for (size_t i = 0; i < k && ok; i++) {
        size_t r = gen_of_term[i];
        if (r == SIZE_MAX)
            continue;
        size_t m = 0;
        for (size_t j = i; j < k; j++)
            if (gen_of_term[j] == r) {
                part[m++] = sel[j];
                if (j != i)
                    gen_of_term[j] = SIZE_MAX;
            }
        if (m >= 2 && m < k)
            ok = try_sel(s, part, m, den, depth + 1);
    }
done:
    qd__free(root);
    qd__free(gen_of_term);
    qd__free(part);
    return ok;
}

/* Factor the terms sel[0..k) over their shared denominator den. */
static bool try_sel(fsum *s, size_t *sel, size_t k, const qd_expr *den, int depth) {
    gens g = {QD_PTRMAP_AL(qd__ctx_allocator(s->ctx)), NULL, 0, 0};
    bool ok = true;
    for (size_t i = 0; i < k && ok; i++) {
        const fterm *t = &s->t[sel[i]];
        const qd_expr *node = s->sum->args[sel[i]];
        for (size_t j = 0; j < t->nf && ok; j++) {
            const qd_expr *f = factor_at(node, t, j);
            long e;
            if (!neg_power(f))
                ok = gens_add(s->ctx, &g, gen_of(f, &e));
        }
    }
    if (!ok || g.n == 0)
        goto out;
    qsort(g.v, g.n, sizeof *g.v, cmp_gen);
    for (size_t v = 0; v < g.n && ok; v++)
        ok = qd__ptrmap_put(&g.idx, g.v[v], (void *)(uintptr_t)(v + 1));
    if (!ok)
        goto out;
    fmpz_mpoly_ctx_t m;
    fmpz_mpoly_ctx_init(m, (slong)g.n, ORD_LEX);
    fmpz_mpoly_t p;
    fmpz_mpoly_init(p, m);
    mpz_t lcm;
    mpz_init(lcm);
    ok = build_poly(s, sel, k, &g, p, m, lcm);
    pfact pf = {NULL, NULL};
    if (ok && fmpz_mpoly_length(p, m) >= 2)
        ok = factor_poly(s->ctx, &g, p, m, lcm, den, &pf);
    if (qd__ctx_nomem(s->ctx)) /* a form not built for want of memory is no "no better form" */
        ok = false;
    fmpz_mpoly_clear(p, m);
    fmpz_mpoly_ctx_clear(m);
    mpz_clear(lcm);
    size_t before = s->ops;
    /* on a tie the grouped form, the plainer one */
    if (ok && (pf.grouped || pf.factored))
        ok = accept(s, sel, k, pf.grouped, pf.factored);
    if (ok && s->ops == before && depth == 0 && k >= 3)
        ok = try_parts(s, sel, k, den, &g, depth);
out:
    qd__ptrmap_free(&g.idx);
    qd__free(g.v);
    return ok;
}

/* ---- a sum ---------------------------------------------------------------- */

static const qd_expr *factor_sum(qd_ctx *ctx, const qd_expr *e) {
    size_t n = e->nargs;
    fsum s = {ctx, NULL, NULL, n, NULL, 0, 0, e};
    s.cur = qd__malloc(ctx, n * sizeof *s.cur);
    s.t = qd__malloc(ctx, n * sizeof *s.t);
    s.extra = qd__malloc(ctx, n * sizeof *s.extra);
    size_t *sel = qd__malloc(ctx, n * sizeof *sel);
    bool *done = qd__calloc(ctx, n, sizeof *done);
    size_t *next = qd__malloc(ctx, n * sizeof *next);
    const qd_expr *r = NULL;
    if (!s.cur || !s.t || !s.extra || !sel || !done || !next) {
        qd__oom(ctx);
        goto out;
    }
    for (size_t i = 0; i < n; i++) {
        s.cur[i] = e->args[i];
        if (!split_term(ctx, e->args[i], &s.t[i]))
            goto out;
    }
    s.ops = qd_count_ops(e);
    /* each group: the exact, bounded terms over one denominator, chained
     * through next[] from the group's first term */
    qd__ptrmap last = QD_PTRMAP_AL(qd__ctx_allocator(ctx)); /* den -> its latest term + 1 */
    for (size_t i = 0; i < n; i++) {
        next[i] = SIZE_MAX;
        if (!s.t[i].ok)
            continue;
        size_t prev = (uintptr_t)qd__ptrmap_get(&last, s.t[i].den);
        if (prev)
            next[prev - 1] = i;
        if (!qd__ptrmap_put(&last, s.t[i].den, (void *)(uintptr_t)(i + 1))) {
            qd__ptrmap_free(&last);
            qd__oom(ctx);
            goto out;
        }
        done[i] = prev != 0; /* done: not the first of its group */
    }
    qd__ptrmap_free(&last);
    for (size_t i = 0; i < n; i++) {
        if (done[i] || !s.t[i].ok)
            continue;
        size_t k = 0;
        long deg = 0;
        for (size_t j = i; j != SIZE_MAX && k <= MAX_TERMS; j = next[j]) {
            sel[k++] = j;
            deg = s.t[j].deg > deg ? s.t[j].deg : deg;
        }
        /* a polynomial of degree 1 has nothing to factor but content, which
         * factor_terms finds; over a denominator the terms may still group */
        bool worth = deg >= 2 || s.t[i].den != ctx->sym->one;
        if (k >= 2 && k <= MAX_TERMS && worth && !try_sel(&s, sel, k, s.t[i].den, 0)) {
            if (ctx->status == QD_OK)
                qd__oom(ctx);
            goto out;
        }
    }
    r = e;
    if (s.nextra) {
        size_t m = 0;
        for (size_t i = 0; i < n; i++)
            if (s.cur[i])
                sel[m++] = i;
        const qd_expr **v = qd__malloc(ctx, (m + s.nextra) * sizeof *v);
        if (!v) {
            qd__oom(ctx);
            r = NULL;
            goto out;
        }
        for (size_t i = 0; i < m; i++)
            v[i] = s.cur[sel[i]];
        for (size_t i = 0; i < s.nextra; i++)
            v[m + i] = s.extra[i];
        r = qd_add_n(ctx, m + s.nextra, v);
        qd__free(v);
    }
out:
    qd__free(s.cur);
    qd__free(s.t);
    qd__free(s.extra);
    qd__free(sel);
    qd__free(done);
    qd__free(next);
    return r;
}

static const qd_expr *post_factor(qd_ctx *ctx, const qd_expr *e, void *data) {
    (void)data;
    return e->kind == QD_ADD ? factor_sum(ctx, e) : e;
}

const qd_expr *qd__factor_polys(qd_ctx *ctx, const qd_expr *e, qd__ptrmap *memo) {
    if (!e)
        return NULL;
    qd__gmp_section outer = qd__gmp_enter(ctx);
    const qd_expr *r = qd__map(ctx, e, memo, post_factor, NULL);
    return qd__gmp_leave(ctx, outer) ? r : NULL; /* the values memo holds are right */
}
