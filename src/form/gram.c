/*
 * src/form/gram.c - the Gram-Schmidt orthogonalization of s vectors under a
 * symmetric matrix T (Desloge App. 21 Thms 1-2; qd_gram_schmidt, qdot/form.h).
 *
 * b(1) = a(1), b(r) = a(r) - sum_{j<r} c_rj b(j) with
 * c_rj = a(r)^T T b(j) / b(j)^T T b(j) (eq. 3b; T = 1 is Thm 1's eq. 1b):
 * b(r) is a(r) less its components along the earlier b's, so b(i)^T T b(j)
 * = 0 for i != j (eq. 4), each checked by the zero test afterwards.  Exact:
 * every entry is cancelled and simplified as it is made.
 */
#include "qdot/form.h"
#include "qdot/print.h"
#include "base/args.h"
#include "base/mem.h"

void qd_gram_free(qd_gram *g) {
    if (!g)
        return;
    qd__free(g->a);
    qd__free(g);
}

static const qd_expr *tidy(qd_ctx *ctx, const qd_expr *e) {
    return e ? qd_simplify(ctx, qd_cancel(ctx, e)) : NULL;
}

/* u^T T v (T NULL: the identity). */
static const qd_expr *dot(qd_ctx *ctx, size_t n, const qd_expr *const *T, const qd_expr *const *u,
                          const qd_expr *const *v) {
    const qd_expr *s = qd_int(ctx, 0);
    for (size_t i = 0; i < n; i++)
        for (size_t k = 0; k < n; k++) {
            if (!T && i != k)
                continue;
            const qd_expr *t = T ? T[i * n + k] : qd_int(ctx, 1);
            s = qd_add(ctx, s, qd_mul(ctx, u[i], qd_mul(ctx, t, v[k])));
        }
    return tidy(ctx, s);
}

/* Zero wherever defined: proven, or verified numerically (the zero test). */
static bool vanishes(qd_ctx *ctx, const qd_expr *e, qd_zero_result *z) {
    qd_zero_result tmp;
    z = z ? z : &tmp;
    if (qd_zero_test(ctx, e, z) != QD_OK)
        return false;
    return z->kind == QD_ZERO_PROVEN || z->kind == QD_ZERO_NUMERIC;
}

static qd_gram *gram_alloc(qd_ctx *ctx, size_t n, size_t s) {
    qd_gram *g = qd__calloc(ctx, 1, sizeof *g);
    const qd_expr **blk = g ? qd__calloc(ctx, 2 * s * n + s + s * s + 1, sizeof *blk) : NULL;
    if (!blk) {
        qd__free(g);
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory orthogonalizing vectors");
        return NULL;
    }
    *g = (qd_gram){.n = n, .s = s, .a = blk, .b = blk + s * n};
    g->norm = g->b + s * n;
    g->coef = g->norm + s;
    return g;
}

/* b(r) and its norm, App. 21 eq. 3b; false (reason in ctx) for a b(r) that
 * vanishes (a(r) dependent on the a's before it) or is a null vector of T. */
static bool next(qd_ctx *ctx, qd_gram *g, const qd_expr *const *T, size_t r) {
    size_t n = g->n, s = g->s;
    const qd_expr **b = g->b + r * n;
    for (size_t i = 0; i < n; i++)
        b[i] = g->a[r * n + i];
    for (size_t j = 0; j < r; j++) {
        const qd_expr *c = tidy(ctx, qd_div(ctx, dot(ctx, n, T, g->a + r * n, g->b + j * n),
                                            g->norm[j]));
        g->coef[r * s + j] = c;
        for (size_t i = 0; i < n; i++)
            b[i] = qd_sub(ctx, b[i], qd_mul(ctx, c, g->b[j * n + i]));
    }
    bool zero = true;
    for (size_t i = 0; i < n; i++) {
        b[i] = tidy(ctx, qd_expand(ctx, b[i]));
        if (!b[i])
            return false;
        zero = zero && vanishes(ctx, b[i], NULL);
    }
    for (size_t j = r; j < s; j++)
        g->coef[r * s + j] = qd_int(ctx, 0);
    if (zero) {
        qd_ctx_error(ctx, QD_ERR_ARG, "a%zu is a linear combination of the vectors before it: "
                     "b%zu = 0 (Gram-Schmidt needs linearly independent vectors, Desloge App. 21)",
                     r + 1, r + 1);
        return false;
    }
    g->norm[r] = dot(ctx, n, T, b, b);
    if (g->norm[r] && vanishes(ctx, g->norm[r], NULL)) {
        qd_ctx_error(ctx, QD_ERR_SINGULAR, "b%zu^T T b%zu = 0 though b%zu is not 0: T is not "
                     "definite, and the process divides by that norm (Desloge App. 21 Thm 2)",
                     r + 1, r + 1, r + 1);
        return false;
    }
    return g->norm[r] != NULL;
}

/* eq. 4: b(i)^T T b(j) = 0 for i < j; the weakest verdict in g->check. */
static bool orthogonal(qd_ctx *ctx, qd_gram *g, const qd_expr *const *T) {
    g->check = QD_ZERO_PROVEN;
    for (size_t i = 0; i < g->s; i++)
        for (size_t j = i + 1; j < g->s; j++) {
            qd_zero_result z;
            const qd_expr *d = dot(ctx, g->n, T, g->b + i * g->n, g->b + j * g->n);
            if (!d || !vanishes(ctx, d, &z)) {
                if (qd_ctx_status(ctx) == QD_OK)
                    qd_ctx_error(ctx, QD_ERR_NUMERIC, "b%zu^T T b%zu is not 0 (a bug in the "
                                 "orthogonalization)", i + 1, j + 1);
                return false;
            }
            if (z.kind == QD_ZERO_NUMERIC)
                g->check = QD_ZERO_NUMERIC;
        }
    return true;
}

static bool symmetric(qd_ctx *ctx, size_t n, const qd_expr *const *T) {
    for (size_t i = 0; T && i < n; i++)
        for (size_t j = 0; j < n; j++) {
            if (!T[i * n + j]) {
                qd_ctx_error(ctx, QD_ERR_ARG, "Gram-Schmidt: matrix entry %zu,%zu is NULL",
                             i + 1, j + 1);
                return false;
            }
            const qd_expr *d = j < i ? tidy(ctx, qd_sub(ctx, T[i * n + j], T[j * n + i]))
                                     : qd_int(ctx, 0);
            if (!d || !qd_is_zero(d)) {
                if (d)
                    qd_ctx_error(ctx, QD_ERR_ARG, "Gram-Schmidt: the matrix is not symmetric "
                                 "(entries %zu,%zu and %zu,%zu)", i + 1, j + 1, j + 1, i + 1);
                return false;
            }
        }
    return true;
}

qd_gram *qd_gram_schmidt(qd_ctx *ctx, size_t n, const qd_expr *const *T, size_t s,
                         const qd_expr *const *a) {
    QD_ARGS(NULL, ctx && a);
    if (n == 0 || s == 0 || s > n) {
        qd_ctx_error(ctx, QD_ERR_ARG, "Gram-Schmidt: %zu vectors of %zu components (give 1 to "
                     "%zu linearly independent vectors)", s, n, n);
        return NULL;
    }
    for (size_t i = 0; i < s * n; i++)
        if (!a[i]) {
            qd_ctx_error(ctx, QD_ERR_ARG, "Gram-Schmidt: vector component %zu is NULL", i + 1);
            return NULL;
        }
    if (!symmetric(ctx, n, T))
        return NULL;
    qd_gram *g = gram_alloc(ctx, n, s);
    if (!g)
        return NULL;
    bool unit = true; /* T the identity is Thm 1 */
    for (size_t i = 0; T && i < n * n; i++)
        unit = unit && (i / n == i % n ? qd_is_one(T[i]) : qd_is_zero(T[i]));
    T = unit ? NULL : T;
    g->euclidean = unit;
    for (size_t i = 0; i < s * n; i++)
        g->a[i] = tidy(ctx, a[i]);
    for (size_t r = 0; r < s; r++)
        if (!next(ctx, g, T, r)) {
            qd_gram_free(g);
            return NULL;
        }
    if (!orthogonal(ctx, g, T)) {
        qd_gram_free(g);
        return NULL;
    }
    return g;
}
