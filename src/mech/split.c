/*
 * src/mech/split.c - expressions sorted by their monomials in the
 * velocities, and the kinetic energy split T = T2 + T1 + T0.
 *
 * Grouping by velocity monomial is what keeps Lagrange's equations short:
 * the expansion of x1'^2 + y1'^2 + ... of a chain of links has thousands of
 * terms, but each monomial q'_j q'_k collects a handful of them, and
 * simplifying that handful (cos q_j cos q_k + sin q_j sin q_k ->
 * cos(q_j - q_k), the masses summed) is cheap; simplifying the whole sum at
 * once is not.  For rheonomic coordinates the degrees also give T1 (linear)
 * and T0 (no velocity), e.g. for a bead on a turning wire.
 */
#include "mech.h"

#include "base/ptrmap.h"
#include "qdot/print.h"
#include "../base/mem.h"

#include <stdlib.h>

static bool is_velocity(const qd_expr *x, size_t n, const qd_expr *const *qd) {
    for (size_t i = 0; i < n; i++)
        if (x == qd[i])
            return true;
    return false;
}

/* The degree of one factor, or -1 when a velocity is in it other than as
 * a positive integer power. */
static long factor_degree(const qd_expr *f, size_t n, const qd_expr *const *qd) {
    if (is_velocity(f, n, qd))
        return 1;
    if (qd_expr_kind(f) == QD_POW && is_velocity(qd_expr_arg(f, 0), n, qd)) {
        long num, den;
        if (qd_rational_get(qd_expr_arg(f, 1), &num, &den) && den == 1 && num > 0)
            return num;
        return -1;
    }
    for (size_t i = 0; i < n; i++)
        if (qd_has(f, qd[i]))
            return -1;
    return 0;
}

/* One term of the expansion: its velocity monomial, the rest and the
 * degree. */
typedef struct vterm {
    const qd_expr *mono, *coef;
    long deg;
    size_t bucket;
} vterm;

typedef struct sorter {
    qd_ctx *ctx;
    size_t n;
    const qd_expr *const *qd;
    const qd_expr **mono, **coef; /* scratch for a term's factors */
} sorter;

/* Split term t; false (and *bad) when it is not polynomial. */
static bool split_term(sorter *s, const qd_expr *t, vterm *out, const qd_expr **bad) {
    bool mul = qd_expr_kind(t) == QD_MUL;
    size_t nf = mul ? qd_expr_nargs(t) : 1, nm = 0, nc = 0;
    out->deg = 0;
    for (size_t i = 0; i < nf; i++) {
        const qd_expr *f = mul ? qd_expr_arg(t, i) : t;
        long d = factor_degree(f, s->n, s->qd);
        if (d < 0) {
            *bad = f;
            return false;
        }
        if (d > 0)
            s->mono[nm++] = f;
        else
            s->coef[nc++] = f;
        out->deg += d;
    }
    out->mono = qd_mul_n(s->ctx, nm, s->mono);
    out->coef = qd_mul_n(s->ctx, nc, s->coef);
    return true;
}

static size_t max_factors(const qd_expr *x, size_t nt) {
    size_t m = 1;
    for (size_t i = 0; nt > 1 && i < nt; i++) {
        const qd_expr *t = qd_expr_arg(x, i);
        if (qd_expr_kind(t) == QD_MUL && qd_expr_nargs(t) > m)
            m = qd_expr_nargs(t);
    }
    if (nt == 1 && qd_expr_kind(x) == QD_MUL)
        m = qd_expr_nargs(x);
    return m;
}

/* Number the distinct monomials of terms[0..nt). */
static size_t number_buckets(qd_ctx *ctx, vterm *terms, size_t nt, bool *ok) {
    qd__ptrmap ids = QD_PTRMAP_AL(qd__ctx_allocator(ctx));
    size_t nb = 0;
    for (size_t i = 0; *ok && i < nt; i++) {
        size_t id = (size_t)(uintptr_t)qd__ptrmap_get(&ids, terms[i].mono);
        if (!id) {
            id = ++nb;
            *ok = qd__ptrmap_put(&ids, terms[i].mono, (void *)(uintptr_t)id);
        }
        terms[i].bucket = id - 1;
    }
    qd__ptrmap_free(&ids);
    if (!*ok) /* the map cannot say so itself */
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
    return nb;
}

/* The coefficient of a group is a sum of expanded terms already, so of
 * qd_simplify's pipeline only the trigonometric identities and the common
 * factors are left to try; the entries of M and f get the whole
 * simplifier later. */
static const qd_expr *simplify_expanded(qd_ctx *ctx, const qd_expr *c) {
    const qd_expr *t = qd_trigsimp(ctx, c), *f = qd_factor_terms(ctx, t);
    if (!t || !f)
        return NULL;
    size_t oc = qd_count_ops(c), ot = qd_count_ops(t), of = qd_count_ops(f);
    return of <= ot && of <= oc ? f : ot <= oc ? t : c;
}

/* terms[order[from..to)] share one monomial: their coefficients summed and
 * simplified, times the monomial. */
static const qd_expr *group(qd_ctx *ctx, const vterm *terms, const size_t *order, size_t from,
                            size_t to, const qd_expr **scratch) {
    for (size_t i = from; i < to; i++)
        scratch[i - from] = terms[order[i]].coef;
    const qd_expr *c = simplify_expanded(ctx, qd_add_n(ctx, to - from, scratch));
    return qd_mul(ctx, c, terms[order[from]].mono);
}

/* Sort terms by bucket (counting sort), then sum each bucket. */
static qd_status gather(qd_ctx *ctx, const vterm *terms, size_t nt, size_t nb, qd__vsum *v) {
    size_t *start = qd__calloc(ctx, nb + 1, sizeof *start), *order = qd__malloc(ctx, nt * sizeof *order);
    const qd_expr **scratch = qd__malloc(ctx, nt * sizeof *scratch), **groups = qd__malloc(ctx, nb * sizeof *groups);
    const qd_expr **bydeg = qd__malloc(ctx, 3 * nb * sizeof *bydeg);
    size_t nd[3] = {0, 0, 0};
    qd_status st = start && order && scratch && groups && bydeg ? QD_OK : QD_ERR_NOMEM;
    for (size_t i = 0; st == QD_OK && i < nt; i++)
        start[terms[i].bucket + 1]++;
    for (size_t b = 0; st == QD_OK && b < nb; b++)
        start[b + 1] += start[b];
    for (size_t i = 0; st == QD_OK && i < nt; i++)
        order[start[terms[i].bucket]++] = i;
    for (size_t b = 0, from = 0; st == QD_OK && b < nb; from = start[b++]) {
        groups[b] = group(ctx, terms, order, from, start[b], scratch);
        long d = terms[order[from]].deg;
        if (d <= 2)
            bydeg[d * nb + nd[d]++] = groups[b];
    }
    if (st == QD_OK) {
        v->all = qd_add_n(ctx, nb, groups);
        for (int d = 0; d < 3; d++)
            v->deg[d] = qd_add_n(ctx, nd[d], bydeg + d * nb);
        st = v->all && v->deg[0] && v->deg[1] && v->deg[2] ? QD_OK : qd_ctx_status(ctx);
    }
    qd__free(start);
    qd__free(order);
    qd__free(scratch);
    qd__free(groups);
    qd__free(bydeg);
    return st;
}

static qd_status sort_terms(sorter *s, const qd_expr *x, size_t nt, vterm *terms, qd__vsum *v) {
    for (size_t i = 0; i < nt; i++) {
        if (!split_term(s, nt == 1 ? x : qd_expr_arg(x, i), &terms[i], &v->bad))
            return QD_ERR_NONLINEAR;
        if (!terms[i].mono || !terms[i].coef)
            return qd_ctx_status(s->ctx);
        v->top = terms[i].deg > v->top ? terms[i].deg : v->top;
    }
    return QD_OK;
}

qd_status qd__mech_by_velocity(qd_ctx *ctx, const qd_expr *x, size_t n, const qd_expr *const *qd,
                          qd__vsum *v) {
    *v = (qd__vsum){NULL, {NULL, NULL, NULL}, 0, NULL};
    x = qd_expand(ctx, x);
    if (!x)
        return qd_ctx_status(ctx);
    size_t nt = qd_expr_kind(x) == QD_ADD ? qd_expr_nargs(x) : 1, mf = max_factors(x, nt);
    vterm *terms = qd__malloc(ctx, nt * sizeof *terms);
    sorter s = {ctx, n, qd, qd__malloc(ctx, mf * sizeof *s.mono), qd__malloc(ctx, mf * sizeof *s.coef)};
    qd_status st = terms && s.mono && s.coef ? QD_OK : QD_ERR_NOMEM;
    if (st == QD_OK)
        st = sort_terms(&s, x, nt, terms, v);
    bool ok = true;
    size_t nb = st == QD_OK ? number_buckets(ctx, terms, nt, &ok) : 0;
    if (st == QD_OK)
        st = ok ? gather(ctx, terms, nt, nb, v) : QD_ERR_NOMEM;
    qd__free(terms);
    qd__free(s.mono);
    qd__free(s.coef);
    return st;
}

static void report_nonpoly(qd_ctx *ctx, const qd_expr *bad, size_t n, const qd_expr *const *qd) {
    const char *v = "a velocity";
    for (size_t i = 0; i < n; i++)
        if (qd_has(bad, qd[i]))
            v = qd_expr_name(qd[i]);
    qd_buf b = QD_BUF_WITH(qd__ctx_allocator(ctx));
    qd_print(ctx, bad, QD_FMT_TEXT, &b);
    qd_ctx_error(ctx, QD_ERR_NONLINEAR,
                 "the kinetic energy is not a polynomial in the velocities: %s appears in %s", v,
                 qd_buf_str(&b));
    qd_buf_free(&b);
}

qd_status qd__mech_split_kinetic(qd_ctx *ctx, const qd_expr *T, size_t n, const qd_expr *const *qd,
                            qd__vsum *v) {
    qd_status st = qd__mech_by_velocity(ctx, T, n, qd, v);
    if (st == QD_ERR_NONLINEAR)
        report_nonpoly(ctx, v->bad, n, qd);
    return st;
}
