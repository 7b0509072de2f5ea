/*
 * src/hj/separate.c - the separation of H(q, p) = E, one coordinate at a
 * time (Benenti's peeling; Goldstein 10.5, Landau-Lifshitz §48, Desloge
 * ch. 78).
 *
 * Each step takes the unseparated rest F = 0 and isolates one coordinate
 * q_k: either q_k is cyclic (F has no q_k: p_k = alpha_k), or some factor f
 * (1, or a denominator of F's terms) makes
 *
 *     f F = c G_k(q_k, p_k) + R          (c and R free of q_k and p_k)
 *
 * so that G_k = alpha_k is an equation of q_k alone and F' = c alpha_k + R = 0
 * is left for the others.  The last coordinate keeps the energy E as its
 * constant.  f = 1 and c = 1 is additive separation; any other f or c is the
 * Liouville form when one such step does it all (spherical and polar
 * coordinates, parabolic and elliptic ones with f = the Liouville sum), and
 * Staeckel's when several are needed.  Every test is exact: terms are split
 * by the variables they contain, and a factor that mixes q_k with the
 * others is an obstruction.
 */
#include "hj_priv.h"

#include <stdio.h>
#include <string.h>
#include "base/mem.h"
#include "qdot/print.h"

enum { USED_CYCLIC = 1, USED_ADDITIVE = 2, USED_LIOUVILLE = 4, USED_STAECKEL = 8 };
#define MAX_CANDIDATES 12

static bool on_k(const qd__hj_sep_state *s, const qd_expr *e, size_t k) {
    return qd_has(e, s->q[k]) || qd_has(e, s->p[k]);
}

/* Does e contain a coordinate or momentum still unseparated other than k's? */
static bool on_others(const qd__hj_sep_state *s, const qd_expr *e, size_t k) {
    for (size_t j = 0; j < s->h->n; j++)
        if (j != k && s->left[j] && on_k(s, e, j))
            return true;
    return false;
}

static size_t nterms(const qd_expr *e) {
    return qd_expr_kind(e) == QD_ADD ? qd_expr_nargs(e) : 1;
}

static const qd_expr *term(const qd_expr *e, size_t i) {
    return qd_expr_kind(e) == QD_ADD ? qd_expr_arg(e, i) : e;
}

/* A term t of G on q_k split as t = c * own, c on the others only; false when
 * a factor mixes q_k with the others. */
static bool split_term(const qd__hj_sep_state *s, const qd_expr *t, size_t k,
                       const qd_expr **c, const qd_expr **own) {
    qd_ctx *ctx = s->ctx;
    *c = qd_int(ctx, 1);
    *own = qd_int(ctx, 1);
    size_t nf = qd_expr_kind(t) == QD_MUL ? qd_expr_nargs(t) : 1;
    for (size_t i = 0; i < nf; i++) {
        const qd_expr *f = nf > 1 || qd_expr_kind(t) == QD_MUL ? qd_expr_arg(t, i) : t;
        bool mine = on_k(s, f, k), theirs = on_others(s, f, k);
        if (mine && theirs)
            return false;
        if (theirs)
            *c = qd_mul(ctx, *c, f);
        else
            *own = qd_mul(ctx, *own, f);
    }
    return *c && *own;
}

/* G = c group + rest on q_k: group the terms on q_k, rest the others. */
static bool split_on(const qd__hj_sep_state *s, const qd_expr *G, size_t k,
                     const qd_expr **c, const qd_expr **group, const qd_expr **rest) {
    qd_ctx *ctx = s->ctx;
    *c = NULL;
    *group = qd_int(ctx, 0);
    *rest = qd_int(ctx, 0);
    for (size_t i = 0; i < nterms(G); i++) {
        const qd_expr *t = term(G, i), *tc, *own;
        if (!on_k(s, t, k)) {
            *rest = qd_add(ctx, *rest, t);
            continue;
        }
        if (!split_term(s, t, k, &tc, &own) || (*c && tc != *c))
            return false;
        *c = tc;
        *group = qd_add(ctx, *group, own);
    }
    if (!*c || !qd_has(*group, s->p[k]))
        return false;
    return *rest && *group;
}

/* The candidates f: 1, then each base b of a negative power b^-n in F's
 * terms that contains an unseparated variable (as b^n), then their product. */
static size_t candidates(const qd__hj_sep_state *s, const qd_expr **out) {
    qd_ctx *ctx = s->ctx;
    size_t n = 0;
    out[n++] = qd_int(ctx, 1);
    const qd_expr *all = qd_int(ctx, 1);
    for (size_t i = 0; i < nterms(s->F); i++) {
        const qd_expr *t = term(s->F, i);
        size_t nf = qd_expr_kind(t) == QD_MUL ? qd_expr_nargs(t) : 1;
        for (size_t j = 0; j < nf; j++) {
            const qd_expr *f = qd_expr_kind(t) == QD_MUL ? qd_expr_arg(t, j) : t;
            if (qd_expr_kind(f) != QD_POW || !qd_is_number(qd_expr_arg(f, 1)) ||
                qd_number_sign(qd_expr_arg(f, 1)) >= 0 || !on_others(s, f, s->h->n))
                continue;
            const qd_expr *c = qd_pow(ctx, qd_expr_arg(f, 0), qd_neg(ctx, qd_expr_arg(f, 1)));
            bool seen = false;
            for (size_t m = 0; m < n; m++)
                seen = seen || out[m] == c;
            if (!seen && n < MAX_CANDIDATES - 1) {
                out[n++] = c;
                all = qd_mul(ctx, all, c);
            }
        }
    }
    if (n > 2)
        out[n++] = all;
    return n;
}

/* A fresh constant for q_k: alpha_<q>, with underscores added while the name
 * is taken by something that is not a plain symbol. */
static const qd_expr *constant_symbol(qd_ctx *ctx, const char *base, const char *q) {
    char name[128];
    snprintf(name, sizeof name, "%s%s", base, q);
    for (;;) {
        const qd_expr *old = qd_lookup(ctx, name);
        if (!old || qd_symbol_role(old) == QD_ROLE_PLAIN)
            return qd_symbol(ctx, name);
        if (strlen(name) + 2 >= sizeof name)
            return NULL;
        strcat(name, "_");
    }
}

/* p_k^2 from eq = 0, eq = A p_k^2 + C with A, C free of p_k. */
static const qd_expr *solve_p2(qd_ctx *ctx, const qd_expr *eq, const qd_expr *p) {
    const qd_expr *x = qd_expand(ctx, eq);
    const qd_expr *A = qd_coeff(ctx, x, p, 2), *B = qd_coeff(ctx, x, p, 1);
    const qd_expr *C = qd_coeff(ctx, x, p, 0);
    if (!A || !B || !C || qd_is_zero(A) || !qd_is_zero(B) || qd_has(A, p) || qd_has(C, p))
        return NULL;
    const qd_expr *back = qd_expand(ctx, qd_sub(ctx, x, qd_add(ctx, qd_mul(ctx, A, qd_powi(ctx, p, 2)), C)));
    if (!back || !qd_is_zero(back))
        return NULL;
    return qd_simplify(ctx, qd_neg(ctx, qd_div(ctx, C, A)));
}

/* x from eq = B x + C = 0, B != 0 and B, C free of x; NULL otherwise. */
static const qd_expr *solve_linear1(qd_ctx *ctx, const qd_expr *eq, const qd_expr *x) {
    const qd_expr *X = qd_expand(ctx, eq);
    const qd_expr *B = X ? qd_coeff(ctx, X, x, 1) : NULL, *C = X ? qd_coeff(ctx, X, x, 0) : NULL;
    if (!B || !C || qd_is_zero(B) || qd_has(B, x) || qd_has(C, x))
        return NULL;
    const qd_expr *back = qd_expand(ctx, qd_sub(ctx, X, qd_add(ctx, qd_mul(ctx, B, x), C)));
    if (!back || !qd_is_zero(back))
        return NULL;
    return qd_simplify(ctx, qd_neg(ctx, qd_div(ctx, C, B)));
}

/* e simplified, or over one denominator where that is shorter (the group
 * with E = H put back: the Liouville denominators cancel). */
static const qd_expr *shorter(qd_ctx *ctx, const qd_expr *e) {
    const qd_expr *a = qd_simplify(ctx, e), *b = qd_simplify(ctx, qd_cancel(ctx, e));
    if (!a || !b)
        return NULL;
    return qd_count_ops(b) < qd_count_ops(a) ? b : a;
}

/* The constant's value as a function of q and p: v with every earlier
 * constant (and E) replaced by its own. */
static const qd_expr *as_integral(qd__hj_sep_state *s, const qd_expr *v) {
    qd_hj *h = s->h;
    for (size_t i = h->nconst; i-- > 0;)
        v = qd_subs(s->ctx, v, 1, &h->constants[i], &s->value[i]);
    v = qd_subs(s->ctx, v, 1, &h->energy, &h->H);
    return shorter(s->ctx, v);
}

static qd_status record(qd__hj_sep_state *s, size_t k, const qd_expr *constant,
                        const qd_expr *equation, const qd_expr *value, bool cyclic) {
    qd_hj *h = s->h;
    qd_hj_sep *sp = &h->sep[k];
    sp->q = s->q[k];
    sp->p = s->p[k];
    sp->constant = constant;
    sp->equation = qd_simplify(s->ctx, equation);
    sp->p2 = cyclic && constant != h->energy ? qd_powi(s->ctx, constant, 2)
                                             : solve_p2(s->ctx, equation, s->p[k]);
    sp->cyclic = cyclic;
    sp->integral = value;
    sp->pk = sp->qk = NULL;
    if (!sp->p2 && sp->equation && (sp->pk = solve_linear1(s->ctx, equation, s->p[k])))
        sp->p2 = qd_simplify(s->ctx, qd_powi(s->ctx, sp->pk, 2));
    else if (!sp->p2 && sp->equation)
        sp->qk = solve_linear1(s->ctx, equation, s->q[k]);
    if ((!sp->p2 && !sp->qk) || !sp->equation) {
        snprintf(h->why, sizeof h->why, "the equation left for %s is not of the form "
                 "A(%s) %s^2 + C(%s) = 0 (%s enters it linearly or beyond the square: a cross "
                 "term with a cyclic momentum, or a magnetic term)", qd_expr_name(s->q[k]),
                 qd_expr_name(s->q[k]), qd_expr_name(s->p[k]), qd_expr_name(s->q[k]),
                 qd_expr_name(s->p[k]));
        return qd_ctx_status(s->ctx) != QD_OK ? qd_ctx_status(s->ctx) : QD_ERR_NONLINEAR;
    }
    s->value[h->nconst] = value;
    h->constants[h->nconst++] = constant;
    s->left[k] = false;
    s->nleft--;
    return QD_OK;
}

/* F has no q_k: p_k = alpha_k. */
static qd_status peel_cyclic(qd__hj_sep_state *s, size_t k) {
    qd_ctx *ctx = s->ctx;
    const qd_expr *a = constant_symbol(ctx, "alpha_", qd_expr_name(s->q[k]));
    if (!a)
        return QD_ERR_NOMEM;
    qd_status st = record(s, k, a, qd_sub(ctx, s->p[k], a), s->p[k], true);
    if (st == QD_OK)
        s->F = qd_expand(ctx, qd_subs(ctx, s->F, 1, &s->p[k], &a));
    s->used |= USED_CYCLIC;
    return s->F ? st : QD_ERR_NOMEM;
}

/* f F = c G_k + rest with G_k = alpha_k: the others are left with
 * c alpha_k + rest = 0 (not divided by c, which would bring c's coordinates
 * into every term: Kepler's r^2 sin(theta)^2). */
static qd_status peel_group(qd__hj_sep_state *s, size_t k, const qd_expr *c, const qd_expr *group,
                            const qd_expr *rest, bool plain) {
    qd_ctx *ctx = s->ctx;
    const qd_expr *a = constant_symbol(ctx, "alpha_", qd_expr_name(s->q[k]));
    if (!a)
        return QD_ERR_NOMEM;
    qd_status st = record(s, k, a, qd_sub(ctx, group, a), as_integral(s, group), false);
    if (st != QD_OK)
        return st;
    s->F = qd_expand(ctx, qd_add(ctx, rest, qd_mul(ctx, c, a)));
    if (plain)
        s->used |= USED_ADDITIVE;
    else
        s->used |= (s->used & (USED_LIOUVILLE | USED_STAECKEL)) ? USED_STAECKEL : USED_LIOUVILLE;
    return s->F ? QD_OK : QD_ERR_NOMEM;
}

/* The coefficients c[0..max] of P as a polynomial in x (free of x);
 * its degree, or -1 when P is not one of degree <= max. */
static int poly(qd_ctx *ctx, const qd_expr *P, const qd_expr *x, int max, const qd_expr **c) {
    const qd_expr *X = qd_expand(ctx, P), *sum = qd_int(ctx, 0);
    int deg = -1;
    for (int k = 0; X && k <= max; k++) {
        if (!(c[k] = qd_coeff(ctx, X, x, k)) || qd_has(c[k], x))
            return -1;
        if (!qd_is_zero(c[k]))
            deg = k;
        sum = qd_add(ctx, sum, qd_mul(ctx, c[k], qd_powi(ctx, x, k)));
    }
    const qd_expr *d = X ? qd_expand(ctx, qd_sub(ctx, X, sum)) : NULL;
    return d && qd_is_zero(d) ? deg : -1;
}

#define MAX_DEG 6

/* num/B as quotient + remainder/B, num and B polynomials in x (deg num >=
 * deg B >= 1); NULL when they are not. */
static const qd_expr *divide(qd_ctx *ctx, const qd_expr *num, const qd_expr *B, const qd_expr *x) {
    const qd_expr *a[MAX_DEG + 1], *b[MAX_DEG + 1];
    int dn = poly(ctx, num, x, MAX_DEG, a), dd = poly(ctx, B, x, MAX_DEG, b);
    if (dd < 1 || dn < dd)
        return NULL;
    const qd_expr *quot = qd_int(ctx, 0), *rem = qd_int(ctx, 0);
    for (int i = dn; i >= dd; i--) {
        const qd_expr *q = qd_div(ctx, a[i], b[dd]);
        quot = qd_add(ctx, quot, qd_mul(ctx, q, qd_powi(ctx, x, i - dd)));
        for (int j = 0; j <= dd; j++)
            a[i - dd + j] = qd_sub(ctx, a[i - dd + j], qd_mul(ctx, q, b[j]));
    }
    for (int j = 0; j < dd; j++)
        rem = qd_add(ctx, rem, qd_mul(ctx, a[j], qd_powi(ctx, x, j)));
    return qd_add(ctx, quot, qd_div(ctx, rem, B));
}

/* A term t = rest * num(x) / B(x), B^-1 its one negative power on the
 * coordinate x and num its other factors on x alone, rewritten as rest *
 * (quotient + remainder/B); t itself when it is not of that shape. */
static const qd_expr *proper_term(qd__hj_sep_state *s, const qd_expr *t, size_t k) {
    qd_ctx *ctx = s->ctx;
    const qd_expr *x = s->q[k], *num = qd_int(ctx, 1), *rest = qd_int(ctx, 1), *B = NULL;
    size_t nf = qd_expr_kind(t) == QD_MUL ? qd_expr_nargs(t) : 1;
    for (size_t i = 0; i < nf; i++) {
        const qd_expr *f = qd_expr_kind(t) == QD_MUL ? qd_expr_arg(t, i) : t;
        if (!qd_has(f, x) || qd_has(f, s->p[k]) || on_others(s, f, k)) {
            rest = qd_mul(ctx, rest, f);
        } else if (qd_expr_kind(f) == QD_POW && qd_expr_arg(f, 1) == qd_int(ctx, -1) && !B) {
            B = qd_expr_arg(f, 0);
        } else {
            num = qd_mul(ctx, num, f);
        }
    }
    const qd_expr *d = B ? divide(ctx, num, B, x) : NULL;
    return d ? qd_expand(ctx, qd_mul(ctx, rest, d)) : t;
}

/* G with every term in proper fractions of each coordinate: a Liouville sum
 * over a product of one-coordinate factors, (xi^2 - eta^2)/((xi^2 - 1)(1 -
 * eta^2)), only splits as 1/(1 - eta^2) + 1/(xi^2 - 1) this way (prolate
 * spheroidal coordinates). */
static const qd_expr *proper(qd__hj_sep_state *s, const qd_expr *G) {
    qd_ctx *ctx = s->ctx;
    const qd_expr *sum = qd_int(ctx, 0);
    for (size_t i = 0; sum && i < nterms(G); i++) {
        const qd_expr *t = term(G, i);
        for (size_t k = 0; t && k < s->h->n; k++)
            if (s->left[k] && qd_has(t, s->q[k]))
                t = proper_term(s, t, k);
        sum = qd_add(ctx, sum, t);
    }
    return sum;
}

/* f F term by term, so that f cancels a denominator before expansion
 * distributes it: (xi + eta) * (...)/(xi + eta). */
static const qd_expr *times(qd_ctx *ctx, const qd_expr *f, const qd_expr *F) {
    const qd_expr *sum = qd_int(ctx, 0);
    for (size_t i = 0; sum && i < nterms(F); i++)
        sum = qd_add(ctx, sum, qd_expand(ctx, qd_mul(ctx, f, term(F, i))));
    return sum;
}

/* One coordinate isolated by some candidate factor; false when none is.
 * Groups free of E first (with_energy false), so that the energy stays in
 * the equation of the last coordinate and each constant has its own. */
/* The first coordinate G isolates, peeled; false when there is none. */
static bool peel_from(qd__hj_sep_state *s, const qd_expr *G, bool with_energy, bool plain,
                      qd_status *st) {
    for (size_t k = 0; G && k < s->h->n; k++) {
        const qd_expr *c, *group, *rest;
        if (!s->left[k] || !split_on(s, G, k, &c, &group, &rest) ||
            (!with_energy && qd_has(group, s->h->energy)))
            continue;
        if (!solve_p2(s->ctx, group, s->p[k]))
            continue;
        *st = peel_group(s, k, c, group, rest, plain && qd_is_one(c));
        return true;
    }
    return false;
}

static bool try_groups(qd__hj_sep_state *s, bool with_energy, qd_status *st) {
    const qd_expr *cand[MAX_CANDIDATES];
    size_t nc = candidates(s, cand);
    for (size_t i = 0; i < nc; i++) {
        const qd_expr *G = times(s->ctx, cand[i], s->F);
        if (peel_from(s, G, with_energy, i == 0, st))
            return true;
        const qd_expr *P = G ? proper(s, G) : NULL;
        if (P && P != G && peel_from(s, P, with_energy, false, st))
            return true;
    }
    return false;
}

/* Why F does not separate: its first term on two unseparated coordinates. */
static void obstruction(qd__hj_sep_state *s) {
    qd_hj *h = s->h;
    for (size_t i = 0; i < nterms(s->F); i++) {
        const qd_expr *t = term(s->F, i);
        for (size_t k = 0; k < h->n; k++) {
            if (!s->left[k] || !on_k(s, t, k) || !on_others(s, t, k))
                continue;
            for (size_t j = k + 1; j < h->n; j++)
                if (s->left[j] && on_k(s, t, j)) {
                    qd_buf b = QD_BUF_INIT;
                    qd_print(s->ctx, t, QD_FMT_TEXT, &b);
                    snprintf(h->why, sizeof h->why,
                             "the term %.120s couples %s and %s, and no factor (1 or a "
                             "denominator of H) splits it",
                             qd_buf_str(&b), qd_expr_name(s->q[k]), qd_expr_name(s->q[j]));
                    qd_buf_free(&b);
                    return;
                }
        }
    }
    snprintf(h->why, sizeof h->why, "no coordinate can be isolated (a momentum enters "
             "linearly or the equation of a coordinate is not quadratic in its momentum)");
}

/* The forms used, by the bits USED_*: Staeckel's steps include Liouville's. */
static void name_form(qd__hj_sep_state *s) {
    static const char *const forms[16] = {
        "one coordinate", "cyclic", "additive", "cyclic + additive",
        "Liouville", "cyclic + Liouville", "additive + Liouville", "cyclic + additive + Liouville",
        "Staeckel", "cyclic + Staeckel", "additive + Staeckel", "cyclic + additive + Staeckel",
        "Staeckel", "cyclic + Staeckel", "additive + Staeckel", "cyclic + additive + Staeckel"};
    s->h->form = forms[s->used & 15u];
}

/* The last coordinate: F = 0 is its equation, with the energy. */
static qd_status last(qd__hj_sep_state *s) {
    size_t k = 0;
    while (!s->left[k])
        k++;
    bool cyclic = !qd_has(s->F, s->q[k]);
    return record(s, k, s->h->energy, s->F, s->value[s->h->n - 1], cyclic);
}

qd_status qd__hj_separate(qd__hj_sep_state *s) {
    qd_hj *h = s->h;
    qd_status st = QD_OK;
    while (st == QD_OK && s->nleft > 1) {
        size_t k = 0;
        while (k < h->n && !(s->left[k] && !qd_has(s->F, s->q[k]) && qd_has(s->F, s->p[k])))
            k++;
        if (k < h->n) {
            st = peel_cyclic(s, k);
            continue;
        }
        if (!try_groups(s, false, &st) && !try_groups(s, true, &st)) {
            obstruction(s);
            return qd__ctx_nomem(s->ctx) ? QD_ERR_NOMEM : QD_OK;
        }
    }
    if (st == QD_OK && s->nleft == 1)
        st = last(s);
    if (st != QD_OK) {
        if (qd__ctx_nomem(s->ctx))
            return QD_ERR_NOMEM;
        qd__ctx_recover(s->ctx);
        return QD_OK;
    }
    h->separable = true;
    name_form(s);
    return QD_OK;
}
