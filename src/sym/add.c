/*
 * src/sym/add.c - sums in canonical form.
 *
 * A term is read as (numeric coefficient, key), where the key is the list of
 * its factors without the coefficient: 3*x*y has key [x, y], x has key [x].
 * Nested sums are flattened, numbers folded into one constant, terms sorted
 * by key and terms of one key merged by adding coefficients.  Keys are lists
 * of unique nodes, so "same key" is a pointer comparison per factor.
 */
#include "node.h"
#include "../base/args.h"

#include <stdlib.h>
#include <string.h>

typedef struct term {
    const qd_expr *node;   /* the term as given */
    const qd_expr *coeff;  /* its numeric coefficient */
} term;

/* The key of a term: its factors after the coefficient. */
static const qd_expr *const *term_key(const term *t, size_t *n) {
    const qd_expr *e = t->node;
    if (e->kind == QD_MUL) {
        size_t off = qd__is_num(e->args[0]) ? 1 : 0;
        *n = e->nargs - off;
        return e->args + off;
    }
    *n = 1;
    return &t->node;
}

static int term_cmp(const void *pa, const void *pb) {
    size_t na, nb;
    const qd_expr *const *ka = term_key(pa, &na), *const *kb = term_key(pb, &nb);
    return qd__seq_cmp(ka, na, kb, nb);
}

static bool same_key(const term *a, const term *b) {
    size_t na, nb;
    const qd_expr *const *ka = term_key(a, &na), *const *kb = term_key(b, &nb);
    return na == nb && memcmp(ka, kb, na * sizeof *ka) == 0;
}

const qd_expr *qd__term_coeff(qd_ctx *ctx, const qd_expr *t, const qd_expr *const **rest,
                              size_t *nrest) {
    if (t->kind == QD_MUL && qd__is_num(t->args[0])) {
        if (rest) {
            *rest = t->args + 1;
            *nrest = t->nargs - 1;
        }
        return t->args[0];
    }
    if (rest) {
        *rest = NULL;
        *nrest = 0;
    }
    return ctx->sym->one;
}

/* Rebuild a term with a new coefficient, reusing the node when it is unchanged. */
static const qd_expr *with_coeff(qd_ctx *ctx, const term *t, const qd_expr *c) {
    if (c == t->coeff)
        return t->node;
    size_t n;
    const qd_expr *const *key = term_key(t, &n);
    if (qd_is_one(c))
        return n == 1 ? key[0] : qd__mul_raw(ctx, NULL, n, key);
    return qd__mul_raw(ctx, c, n, key);
}

static bool push(qd_ctx *ctx, term **v, size_t *n, size_t *cap, const qd_expr *node, const qd_expr *coeff) {
    if (*n == *cap) {
        size_t c = *cap ? *cap * 2 : 16;
        term *nv = qd__realloc(ctx, *v, c * sizeof *nv);
        if (!nv)
            return false;
        *v = nv;
        *cap = c;
    }
    (*v)[*n].node = node;
    (*v)[*n].coeff = coeff;
    (*n)++;
    return true;
}

/* The first i with v[i-1] > v[i], or n when v is sorted. */
static size_t sorted_prefix(const term *v, size_t n) {
    for (size_t i = 1; i < n; i++)
        if (term_cmp(&v[i - 1], &v[i]) > 0)
            return i;
    return n;
}

/* Put v in order.  Adding a term to a long sum is the common case (sums are
 * built one term at a time): that is two sorted runs, merged in linear time
 * instead of sorted again. */
static bool sort_terms(qd_ctx *ctx, term *v, size_t n) {
    size_t k = sorted_prefix(v, n);
    if (k == n)
        return true;
    if (sorted_prefix(v + k, n - k) != n - k) {
        qsort(v, n, sizeof *v, term_cmp);
        return true;
    }
    term *tmp = qd__malloc(ctx, n * sizeof *tmp);
    if (!tmp)
        return false;
    size_t i = 0, j = k, m = 0;
    while (i < k && j < n)
        tmp[m++] = term_cmp(&v[j], &v[i]) < 0 ? v[j++] : v[i++];
    while (i < k)
        tmp[m++] = v[i++];
    while (j < n)
        tmp[m++] = v[j++];
    memcpy(v, tmp, n * sizeof *v);
    qd__free(tmp);
    return true;
}

const qd_expr *qd_add_n(qd_ctx *ctx, size_t n, const qd_expr *const *xs) {
    QD_ARGS(NULL, ctx && (n == 0 || xs));
    for (size_t i = 0; i < n; i++)
        if (!xs[i])
            return NULL;
    if (n == 0)
        return ctx->sym->zero;
    if (n == 1)
        return xs[0];

    const qd_expr *constant = ctx->sym->zero;
    term *v = NULL;
    size_t len = 0, cap = 0;
    bool ok = true;
    for (size_t i = 0; i < n && ok; i++) {
        const qd_expr *x = xs[i];
        if (qd__is_num(x)) {
            constant = qd__number_add(ctx, constant, x);
            ok = constant != NULL;
            continue;
        }
        size_t j0 = 0;
        if (x->kind == QD_ADD) {
            if (qd__is_num(x->args[0])) {
                constant = qd__number_add(ctx, constant, x->args[0]);
                ok = constant != NULL;
                j0 = 1;
            }
            for (size_t j = j0; j < x->nargs && ok; j++)
                ok = push(ctx, &v, &len, &cap, x->args[j], qd__term_coeff(ctx, x->args[j], NULL, NULL));
        } else {
            ok = push(ctx, &v, &len, &cap, x, qd__term_coeff(ctx, x, NULL, NULL));
        }
    }
    if (!ok) {
        qd__free(v);
        if (ctx->status == QD_OK)
            qd__oom(ctx);
        return NULL;
    }
    if (!sort_terms(ctx, v, len)) {
        qd__free(v);
        qd__oom(ctx);
        return NULL;
    }

    /* Merge runs of one key, rebuild, drop zeros; write in place. */
    const qd_expr **out = qd__malloc(ctx, (len + 1) * sizeof *out);
    if (!out) {
        qd__free(v);
        qd__oom(ctx);
        return NULL;
    }
    size_t m = 0;
    if (!qd_is_zero(constant))
        out[m++] = constant;
    for (size_t i = 0; i < len && ok;) {
        size_t j = i + 1;
        const qd_expr *c = v[i].coeff;
        for (; j < len && same_key(&v[i], &v[j]); j++)
            c = qd__number_add(ctx, c, v[j].coeff);
        if (!c)
            ok = false;
        else if (!qd_is_zero(c)) {
            out[m] = with_coeff(ctx, &v[i], c);
            ok = out[m++] != NULL;
        }
        i = j;
    }
    const qd_expr *r = NULL;
    if (ok) {
        if (m == 0)
            r = qd_is_zero(constant) ? constant : ctx->sym->zero;
        else if (m == 1)
            r = out[0];
        else {
            qd_expr proto = {0};
            proto.kind = QD_ADD;
            r = qd__intern(ctx, &proto, m, out);
        }
    }
    qd__free(out);
    qd__free(v);
    return r;
}

const qd_expr *qd_add(qd_ctx *ctx, const qd_expr *a, const qd_expr *b) {
    QD_ARGS(NULL, ctx && a && b);
    const qd_expr *xs[2] = {a, b};
    return qd_add_n(ctx, 2, xs);
}

const qd_expr *qd_neg(qd_ctx *ctx, const qd_expr *a) { QD_ARGS(NULL, ctx && a); return qd_mul(ctx, ctx->sym->minus_one, a); }

const qd_expr *qd_sub(qd_ctx *ctx, const qd_expr *a, const qd_expr *b) {
    QD_ARGS(NULL, ctx && a && b);
    return qd_add(ctx, a, qd_neg(ctx, b));
}

bool qd__has_minus(const qd_expr *e) {
    switch ((qd_kind)e->kind) {
    case QD_RATIONAL:
    case QD_FLOAT:
        return qd_number_sign(e) < 0;
    case QD_MUL:
        return qd__is_num(e->args[0]) && qd_number_sign(e->args[0]) < 0;
    case QD_ADD: {
        /* Sign of the first non-constant term: decides between a - b and b - a. */
        size_t i = qd__is_num(e->args[0]) ? 1 : 0;
        return qd__has_minus(e->args[i]);
    }
    default:
        return false;
    }
}
