/*
 * src/form/periods.c - a fundamental period system (Desloge App. 31 Thm 4;
 * qd_periods_reduce, qdot/form.h) and the period test of each vector.
 *
 * The components, rational multiples q of one unit, are scaled by L, the
 * lcm of the q's denominators, into an integer matrix A (g x n).  Integer
 * row operations (a swap, a negation, row_i -= c row_j) bring A to
 * Hermite's normal form H = U A with U unimodular; the nonzero rows of H,
 * times unit / L, are the fundamental periods, and A = V H with V = U^-1
 * (kept beside: each operation's inverse applied to V's columns) gives each
 * given vector's integer coordinates, checked by multiplying back.
 */
#include "qdot/form.h"
#include "qdot/print.h"
#include "qdot/read.h"
#include "base/args.h"
#include "base/ctx.h"
#include "base/diag.h"
#include "base/mem.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void qd_periods_free(qd_periods *p) {
    if (!p)
        return;
    qd__free(p->basis);
    qd__free(p->coords);
    qd__free(p->test);
    qd__free(p);
}

/* A and V, and whether an operation overflowed a long. */
typedef struct hnf {
    size_t g, n;
    long *a; /* g * n */
    long *v; /* g * g, V = U^-1 */
    bool overflow;
    long *a0; /* A before the reduction, for the check */
} hnf;

static long mul_sub(hnf *h, long x, long c, long y) { /* x - c y */
    long p = 0, r = 0;
    if (__builtin_mul_overflow(c, y, &p) || __builtin_sub_overflow(x, p, &r))
        h->overflow = true;
    return r;
}

/* row i -= c row j in A; V's column j += c column i. */
static void sub_row(hnf *h, size_t i, size_t j, long c) {
    for (size_t k = 0; k < h->n; k++)
        h->a[i * h->n + k] = mul_sub(h, h->a[i * h->n + k], c, h->a[j * h->n + k]);
    for (size_t k = 0; k < h->g; k++)
        h->v[k * h->g + j] = mul_sub(h, h->v[k * h->g + j], -c, h->v[k * h->g + i]);
}

static void swap_rows(hnf *h, size_t i, size_t j) {
    for (size_t k = 0; k < h->n; k++) {
        long t = h->a[i * h->n + k];
        h->a[i * h->n + k] = h->a[j * h->n + k];
        h->a[j * h->n + k] = t;
    }
    for (size_t k = 0; k < h->g; k++) {
        long t = h->v[k * h->g + i];
        h->v[k * h->g + i] = h->v[k * h->g + j];
        h->v[k * h->g + j] = t;
    }
}

static void negate_row(hnf *h, size_t i) {
    for (size_t k = 0; k < h->n; k++)
        h->a[i * h->n + k] = -h->a[i * h->n + k];
    for (size_t k = 0; k < h->g; k++)
        h->v[k * h->g + i] = -h->v[k * h->g + i];
}

/* Column c below row p by Euclid's algorithm on its entries: true when a
 * pivot is left at (p, c), positive, with the entries above reduced. */
static bool pivot(hnf *h, size_t p, size_t c) {
    for (;;) {
        size_t best = h->g;
        for (size_t i = p; i < h->g; i++) {
            long x = h->a[i * h->n + c];
            if (x && (best == h->g || labs(x) < labs(h->a[best * h->n + c])))
                best = i;
        }
        if (best == h->g)
            return false;
        if (best != p)
            swap_rows(h, best, p);
        bool rest = false;
        for (size_t i = p + 1; i < h->g && !h->overflow; i++) {
            sub_row(h, i, p, h->a[i * h->n + c] / h->a[p * h->n + c]);
            rest = rest || h->a[i * h->n + c];
        }
        if (h->overflow || !rest)
            break;
    }
    if (h->a[p * h->n + c] < 0)
        negate_row(h, p);
    long d = h->a[p * h->n + c];
    for (size_t i = 0; i < p && !h->overflow; i++) { /* 0 <= entry above < d */
        long x = h->a[i * h->n + c], q = x / d - (x % d < 0);
        sub_row(h, i, p, q);
    }
    return true;
}

/* The rank: H's nonzero rows, first. */
static size_t reduce(hnf *h) {
    size_t p = 0;
    for (size_t c = 0; c < h->n && p < h->g && !h->overflow; c++)
        p += pivot(h, p, c);
    return p;
}

static long gcd(long a, long b) {
    while (b) {
        long t = a % b;
        a = b;
        b = t;
    }
    return labs(a);
}

/* The unit (the first nonzero component) and q = w / unit as p/q pairs. */
static qd_status rationals(qd_ctx *ctx, size_t m, const qd_expr *const *w, const qd_expr **unit,
                           long *num, long *den) {
    *unit = NULL;
    for (size_t k = 0; k < m; k++) {
        const qd_expr *c = qd_simplify(ctx, w[k]);
        if (!c)
            return qd_ctx_status(ctx);
        if (!*unit && !qd_is_zero(c))
            *unit = c;
        const qd_expr *q = *unit ? qd_simplify(ctx, qd_div(ctx, c, *unit)) : qd_int(ctx, 0);
        if (!q)
            return qd_ctx_status(ctx);
        if (!qd_rational_get(q, &num[k], &den[k])) {
            qd_buf a = QD_BUF_INIT, b = QD_BUF_INIT;
            qd_print(ctx, c, QD_FMT_TEXT, &a);
            qd_print(ctx, *unit, QD_FMT_TEXT, &b);
            qd_ctx_error(ctx, QD_ERR_ARG, "%s is not a rational multiple of %s: a fundamental "
                         "period system is found for commensurable periods only (Desloge "
                         "App. 31)", a.failed ? "a component" : qd_buf_str(&a),
                         b.failed ? "the first" : qd_buf_str(&b));
            qd_buf_free(&a);
            qd_buf_free(&b);
            return QD_ERR_ARG;
        }
    }
    return QD_OK;
}

/* A = round(q L) with L the lcm of the denominators. */
static qd_status scale(qd_ctx *ctx, hnf *h, const long *num, const long *den, long *L) {
    size_t m = h->g * h->n;
    *L = 1;
    for (size_t k = 0; k < m; k++) {
        long d = den[k] / gcd(*L, den[k]);
        if (__builtin_mul_overflow(*L, d, L))
            h->overflow = true;
    }
    for (size_t k = 0; k < m && !h->overflow; k++)
        if (__builtin_mul_overflow(num[k], *L / den[k], &h->a[k]))
            h->overflow = true;
    for (size_t j = 0; j < h->g; j++)
        h->v[j * h->g + j] = 1;
    for (size_t k = 0; k < m; k++)
        h->a0[k] = h->a[k];
    (void)ctx;
    return QD_OK;
}

/* The basis rows times unit / L, and the coordinates V's first rank columns,
 * checked: A = V H. */
static qd_status results(qd_ctx *ctx, qd_periods *p, const hnf *h, long L) {
    size_t n = h->n, g = h->g, k = p->rank;
    p->basis = qd__calloc(ctx, k * n + 1, sizeof *p->basis);
    p->coords = qd__calloc(ctx, g * k + 1, sizeof *p->coords);
    if (!p->basis || !p->coords)
        return QD_ERR_NOMEM;
    for (size_t i = 0; i < k * n; i++)
        p->basis[i] = qd_simplify(ctx, qd_mul(ctx, qd_rat(ctx, h->a[i], L), p->unit));
    for (size_t j = 0; j < g; j++)
        for (size_t c = 0; c < k; c++)
            p->coords[j * k + c] = h->v[j * g + c];
    hnf chk = *h; /* A = V H: V's columns past the rank meet H's zero rows */
    for (size_t j = 0; j < g; j++)
        for (size_t i = 0; i < n; i++) {
            long s = 0;
            for (size_t c = 0; c < k; c++)
                s = mul_sub(&chk, s, -p->coords[j * k + c], h->a[c * n + i]);
            if (s != h->a0[j * n + i] || chk.overflow) {
                qd_ctx_error(ctx, QD_ERR_NUMERIC, "the periods' reduction does not multiply back "
                                                  "(a bug)");
                return QD_ERR_NUMERIC;
            }
        }
    return qd_ctx_status(ctx);
}

/* f(x + w_j) - f(x) zero-tested for each j. */
static qd_status test_periods(qd_ctx *ctx, qd_periods *p, const qd_expr *f,
                              const qd_expr *const *x, const qd_expr *const *w) {
    const qd_expr **to = qd__malloc(ctx, p->r * sizeof *to);
    p->test = qd__calloc(ctx, p->g, sizeof *p->test);
    qd_status st = to && p->test ? QD_OK : QD_ERR_NOMEM;
    for (size_t j = 0; j < p->g && st == QD_OK; j++) {
        for (size_t i = 0; i < p->r; i++)
            to[i] = qd_add(ctx, x[i], w[j * p->r + i]);
        st = qd_zero_test(ctx, qd_sub(ctx, qd_subs(ctx, f, p->r, x, to), f), &p->test[j]);
    }
    qd__free(to);
    p->tested = st == QD_OK;
    return st;
}

qd_periods *qd_periods_reduce(qd_ctx *ctx, const qd_expr *f, size_t n, const qd_expr *const *x,
                              size_t g, const qd_expr *const *w) {
    QD_ARGS(NULL, ctx && (x || !n) && (w || !g) && n && g);
    qd_periods *p = qd__calloc(ctx, 1, sizeof *p);
    long *num = qd__calloc(ctx, 2 * g * n, sizeof *num);
    hnf h = {g, n, qd__calloc(ctx, g * n, sizeof(long)), qd__calloc(ctx, g * g, sizeof(long)),
             false, qd__calloc(ctx, g * n, sizeof(long))};
    qd_status st = p && num && h.a && h.v && h.a0 ? QD_OK : QD_ERR_NOMEM;
    long L = 1;
    if (st == QD_OK) {
        p->g = g;
        p->r = n;
        st = rationals(ctx, g * n, w, &p->unit, num, num + g * n);
    }
    if (st == QD_OK && p->unit && (st = scale(ctx, &h, num, num + g * n, &L)) == QD_OK)
        p->rank = reduce(&h);
    if (st == QD_OK && h.overflow) {
        qd_ctx_error(ctx, QD_ERR_TOOBIG, "the periods' integers outgrow a long");
        st = QD_ERR_TOOBIG;
    }
    if (st == QD_OK && !p->unit)
        p->unit = qd_int(ctx, 0);
    if (st == QD_OK)
        st = results(ctx, p, &h, L);
    if (st == QD_OK && f)
        st = test_periods(ctx, p, f, x, w);
    qd__free(num);
    qd__free(h.a);
    qd__free(h.v);
    qd__free(h.a0);
    if (st != QD_OK) {
        if (qd_ctx_status(ctx) == QD_OK)
            qd_ctx_error(ctx, st, "finding the fundamental periods failed");
        qd_periods_free(p);
        return NULL;
    }
    return p;
}

/* ---- the vectors read from text ------------------------------------------- */

void qd_periods_vectors_free(const qd_expr **w) { qd__free(w); }

/* text[i, j) without the spaces around it and one pair of parentheses. */
static void trim(const char *text, size_t *i, size_t *j) {
    while (*i < *j && text[*i] == ' ')
        (*i)++;
    while (*j > *i && text[*j - 1] == ' ')
        (*j)--;
}

/* The end of the item at i: the first sep (or ';' for ',') at depth 0. */
static size_t item_end(const char *text, size_t i, size_t j, char sep) {
    int depth = 0;
    for (; i < j; i++) {
        char c = text[i];
        depth += (c == '(') - (c == ')');
        if (depth == 0 && (c == sep || c == ';'))
            break;
    }
    return i;
}

static qd_status fail_at(qd_ctx *ctx, const char *text, size_t off, size_t len, qd_status st,
                         const char *msg) {
    if (msg)
        qd_ctx_error(ctx, st, "%s", msg);
    qd_ctx_error_at(ctx, text, off, len ? len : 1);
    return st;
}

/* One component, text[i, j), read into *x. */
static qd_status component(qd_ctx *ctx, const char *text, size_t i, size_t j, const qd_expr **x) {
    char *s = qd__malloc(ctx, j - i + 1);
    if (!s)
        return QD_ERR_NOMEM;
    memcpy(s, text + i, j - i);
    s[j - i] = '\0';
    qd_diag d;
    *x = i < j ? qd_read(ctx, s, NULL, &d) : NULL;
    qd__free(s);
    if (*x)
        return QD_OK;
    if (i == j)
        return fail_at(ctx, text, i, 1, QD_ERR_PARSE, "a component is missing");
    if (!d.located)
        return fail_at(ctx, text, i, j - i, qd_ctx_status(ctx), NULL);
    d.offset += i; /* the record in the whole text */
    qd__diag_line_col(text, d.offset, &d.line, &d.col, NULL);
    qd__ctx_restore(ctx, &d);
    return d.status;
}

/* One vector, text[i, j), of n components into x. */
static qd_status vector(qd_ctx *ctx, const char *text, size_t i, size_t j, size_t n,
                        const qd_expr **x) {
    trim(text, &i, &j);
    if (j > i + 1 && text[i] == '(' && text[j - 1] == ')' &&
        item_end(text, i, j, ')') == j - 1) { /* (2*pi, 0) */
        i++;
        j--;
    }
    size_t k = 0, start = i;
    for (size_t e; k <= n && start <= j; start = e + 1, k++) {
        e = item_end(text, start, j, ',');
        size_t a = start, b = e;
        trim(text, &a, &b);
        qd_status st = k < n ? component(ctx, text, a, b, &x[k]) : QD_OK;
        if (st != QD_OK)
            return st;
    }
    if (k != n) {
        char msg[128];
        snprintf(msg, sizeof msg, "a period has %zu components, one for each of the %zu "
                 "variables", n, n);
        return fail_at(ctx, text, i, j - i, QD_ERR_ARG, msg);
    }
    return QD_OK;
}

qd_status qd_periods_vectors_read(qd_ctx *ctx, const char *text, size_t n, size_t *g,
                                  const qd_expr ***out) {
    QD_ARGS_CTX(ctx, ctx && text && g && out && n);
    size_t len = strlen(text), cap = 1;
    *g = 0;
    *out = NULL;
    for (size_t i = 0; i < len; i++)
        cap += text[i] == ';';
    const qd_expr **w = qd__calloc(ctx, cap * n, sizeof *w);
    if (!w)
        return QD_ERR_NOMEM;
    qd_status st = QD_OK;
    for (size_t i = 0, e; st == QD_OK && i <= len; i = e + 1) {
        e = item_end(text, i, len, ';');
        size_t a = i, b = e;
        trim(text, &a, &b);
        if (a == b && e == len && *g)
            break;
        st = vector(ctx, text, i, e, n, w + *g * n);
        *g += st == QD_OK;
    }
    if (st != QD_OK) {
        qd__free(w);
        *g = 0;
        return st;
    }
    *out = w;
    return QD_OK;
}
