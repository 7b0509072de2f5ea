/*
 * src/sym/factor.c - common factors pulled out of sums.
 *
 * For a sum sum_i c_i F_i: the numeric content g (gcd of the numerators over
 * the lcm of the denominators of the rational c_i, signed so the first term
 * keeps a positive coefficient) and, for every base present in all terms,
 * that base to its smallest exponent (x^-2 from x^-1 + x^-2: exponents may be
 * negative or fractional; a symbolic exponent must be the same in every
 * term).  2*a*x + 4*a*y = 2*a*(x + 2*y).  Applied bottom-up to every sum.
 *
 * A bare rational times a single sum is distributed again by the canonical
 * form (2*(x + 2*y) = 2*x + 4*y), so numeric content alone changes nothing.
 */
#include "node.h"
#include "../base/args.h"

#include <stdlib.h>

typedef struct common {
    const qd_expr *base, *exp; /* exp: the smallest exponent over the terms */
} common;

static const qd_expr *base_of(const qd_expr *f, const qd_expr **exp, qd_ctx *ctx) {
    if (f->kind == QD_POW) {
        *exp = f->args[1];
        return f->args[0];
    }
    *exp = ctx->sym->one;
    return f;
}

/* The factors of a term after its coefficient. */
static const qd_expr *const *factors(const qd_expr *const *slot, size_t *n) {
    const qd_expr *t = *slot;
    if (t->kind != QD_MUL) {
        *n = qd__is_num(t) ? 0 : 1;
        return slot;
    }
    size_t off = qd__is_num(t->args[0]) ? 1 : 0;
    *n = t->nargs - off;
    return t->args + off;
}

/* The exponent of base in term slot, or NULL when it is absent. */
static const qd_expr *exp_in(qd_ctx *ctx, const qd_expr *const *slot, const qd_expr *base) {
    size_t n;
    const qd_expr *const *fs = factors(slot, &n);
    for (size_t i = 0; i < n; i++) {
        const qd_expr *e, *b = base_of(fs[i], &e, ctx);
        if (b == base)
            return e;
    }
    return NULL;
}

/* The smaller of two exponents, or NULL when they cannot be compared. */
static const qd_expr *min_exp(const qd_expr *a, const qd_expr *b) {
    if (a == b)
        return a;
    if (!qd__is_rational(a) || !qd__is_rational(b))
        return NULL;
    return qd__number_cmp(a, b) <= 0 ? a : b;
}

static size_t find_common(qd_ctx *ctx, const qd_expr *s, common *out) {
    size_t n0, m = 0;
    const qd_expr *const *fs = factors(&s->args[0], &n0);
    for (size_t i = 0; i < n0; i++) {
        const qd_expr *e, *b = base_of(fs[i], &e, ctx);
        for (size_t j = 1; j < s->nargs && e; j++) {
            const qd_expr *ej = exp_in(ctx, &s->args[j], b);
            e = ej ? min_exp(e, ej) : NULL;
        }
        if (e)
            out[m++] = (common){b, e};
    }
    return m;
}

/* gcd of the rational coefficients, signed after the first term; NULL if a float. */
static const qd_expr *content(qd_ctx *ctx, const qd_expr *s) {
    mpq_t g;
    mpq_init(g);
    for (size_t i = 0; i < s->nargs; i++) {
        const qd_expr *c = qd__is_num(s->args[i]) ? s->args[i]
                                                  : qd__term_coeff(ctx, s->args[i], NULL, NULL);
        if (!qd__is_rational(c)) {
            mpq_clear(g);
            return NULL;
        }
        mpz_gcd(mpq_numref(g), mpq_numref(g), mpq_numref(c->u.q));
        mpz_lcm(mpq_denref(g), mpq_denref(g), mpq_denref(c->u.q));
    }
    mpq_canonicalize(g);
    if (qd__has_minus(s->args[0]))
        mpq_neg(g, g);
    const qd_expr *r = qd__rat_mpq(ctx, g);
    mpq_clear(g);
    return r;
}

/* a - b and a / b for numbers without the general constructors (the
 * exponents and coefficients here are nearly always small rationals, and
 * qd_sub, qd_div on them were a tenth of a derivation). */
static const qd_expr *num_op(qd_ctx *ctx, const qd_expr *a, const qd_expr *b, bool divide) {
    if (!divide && a == b)
        return ctx->sym->zero;
    if (divide && b == ctx->sym->one)
        return a;
    if (!qd__is_rational(a) || !qd__is_rational(b) || (divide && mpq_sgn(b->u.q) == 0))
        return divide ? qd_div(ctx, a, b) : qd_sub(ctx, a, b);
    mpq_t r;
    mpq_init(r);
    if (divide)
        mpq_div(r, a->u.q, b->u.q);
    else
        mpq_sub(r, a->u.q, b->u.q);
    const qd_expr *e = qd__rat_mpq(ctx, r);
    mpq_clear(r);
    return e;
}

/* term / (g * prod common): the coefficient divided, common exponents lowered. */
static const qd_expr *divide_term(qd_ctx *ctx, const qd_expr *const *slot, const qd_expr *g,
                                  const common *cm, size_t m) {
    size_t n;
    const qd_expr *c = qd__is_num(*slot) ? *slot : qd__term_coeff(ctx, *slot, NULL, NULL);
    const qd_expr *const *fs = factors(slot, &n);
    const qd_expr **out = qd__malloc(ctx, (n + 1) * sizeof *out);
    if (!out) {
        qd__oom(ctx);
        return NULL;
    }
    out[0] = num_op(ctx, c, g, true);
    for (size_t i = 0; i < n; i++) {
        const qd_expr *e, *b = base_of(fs[i], &e, ctx);
        out[i + 1] = fs[i];
        for (size_t k = 0; k < m; k++)
            if (cm[k].base == b)
                out[i + 1] = qd_pow(ctx, b, num_op(ctx, e, cm[k].exp, false));
    }
    const qd_expr *r = qd_mul_n(ctx, n + 1, out);
    qd__free(out);
    return r;
}

static const qd_expr *factor_sum(qd_ctx *ctx, const qd_expr *s) {
    size_t n0;
    factors(&s->args[0], &n0);
    const qd_expr *g = content(ctx, s);
    if (!g)
        g = ctx->sym->one;
    common *cm = qd__malloc(ctx, (n0 + 1) * sizeof *cm);
    const qd_expr **parts = qd__malloc(ctx, (s->nargs + n0 + 1) * sizeof *parts);
    const qd_expr *r = NULL;
    if (!cm || !parts) {
        qd__oom(ctx);
        goto done;
    }
    size_t m = find_common(ctx, s, cm);
    if (m == 0 && qd_is_one(g)) {
        r = s;
        goto done;
    }
    for (size_t i = 0; i < s->nargs; i++)
        parts[i] = divide_term(ctx, &s->args[i], g, cm, m);
    const qd_expr *inner = qd_add_n(ctx, s->nargs, parts);
    parts[0] = g;
    parts[1] = inner;
    for (size_t k = 0; k < m; k++)
        parts[k + 2] = qd_pow(ctx, cm[k].base, cm[k].exp);
    r = qd_mul_n(ctx, m + 2, parts);
done:
    qd__free(cm);
    qd__free(parts);
    return r;
}

static const qd_expr *post_factor(qd_ctx *ctx, const qd_expr *e, void *data) {
    (void)data;
    return e->kind == QD_ADD ? factor_sum(ctx, e) : e;
}

const qd_expr *qd_factor_terms(qd_ctx *ctx, const qd_expr *e) {
    QD_ARGS(NULL, ctx && e);
    if (!e)
        return NULL;
    qd__ptrmap memo = QD_PTRMAP_AL(qd__ctx_allocator(ctx));
    const qd_expr *r = qd__map(ctx, e, &memo, post_factor, NULL);
    qd__ptrmap_free(&memo);
    return r;
}
