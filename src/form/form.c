/*
 * src/form/form.c - Lagrange's reduction of a quadratic form to a sum of
 * squares and its inertia (Desloge App. 27 Thms 3-4; qdot/form.h).
 *
 * The working matrix w holds the form in the current variables z, each z_j
 * a linear form lin_j in the caller's x.  A step completes the square on a
 * nonzero diagonal w_kk (y = sum_j w_kj/w_kk z_j) and subtracts it
 * (w_ij -= w_ik w_kj / w_kk), or, when every remaining diagonal element is
 * 0, substitutes z_i = u + v, z_j = u - v (S^T w S, App. 24 congruence),
 * so that u = (z_i + z_j)/2, v = (z_i - z_j)/2.
 */
#include <string.h>
#include "qdot/form.h"
#include "../base/args.h"
#include "../base/mem.h"

void qd_qform_free(qd_qform *f) {
    if (!f)
        return;
    qd__free(f->x);
    qd__free(f);
}

static qd_qform *qform_alloc(qd_ctx *ctx, size_t n) {
    qd_qform *f = qd__calloc(ctx, 1, sizeof *f);
    const qd_expr **blk = f ? qd__calloc(ctx, n + n * n + 2 * n + 1, sizeof *blk) : NULL;
    if (!blk) {
        qd__free(f);
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory reducing a quadratic form");
        return NULL;
    }
    f->n = n;
    f->x = blk;
    f->a = blk + n;
    f->coef = f->a + n * n;
    f->lin = f->coef + n;
    return f;
}

/* The sign of c where it is known for every value of its positive symbols
 * (1 or -1), else 0.  The constants pi and e are positive. */
static int known_sign(const qd_expr *c) {
    if (qd_is_number(c))
        return qd_number_sign(c);
    if (qd_expr_kind(c) == QD_CONSTANT)
        return 1;
    if (qd_expr_kind(c) == QD_SYMBOL)
        return qd_symbol_is_positive(c) ? 1 : 0;
    if (qd_expr_kind(c) == QD_POW) {
        int s = known_sign(qd_expr_arg(c, 0));
        return s > 0 ? 1 : 0;
    }
    if (qd_expr_kind(c) == QD_MUL) {
        int s = 1;
        for (size_t i = 0; i < qd_expr_nargs(c) && s; i++)
            s *= known_sign(qd_expr_arg(c, i));
        return s;
    }
    return 0;
}

static const qd_expr *tidy(qd_ctx *ctx, const qd_expr *e) {
    return qd_simplify(ctx, qd_cancel(ctx, e));
}

/* One Lagrange step on the live variables; false when w is 0 there. */
static bool step(qd_ctx *ctx, qd_qform *f, const qd_expr **w, const qd_expr **lin, bool *live) {
    size_t n = f->n, k = n;
    for (size_t i = 0; i < n && k == n; i++)
        if (live[i] && !qd_is_zero(w[i * n + i]))
            k = i;
    if (k == n) { /* every diagonal element is 0: the pair substitution */
        size_t pi = n, pj = n;
        for (size_t i = 0; i < n && pi == n; i++)
            for (size_t j = i + 1; j < n && pi == n; j++)
                if (live[i] && live[j] && !qd_is_zero(w[i * n + j]))
                    pi = i, pj = j;
        if (pi == n)
            return false;
        const qd_expr *aij = w[pi * n + pj];
        for (size_t m = 0; m < n; m++) {
            if (!live[m] || m == pi || m == pj)
                continue;
            const qd_expr *u = tidy(ctx, qd_add(ctx, w[pi * n + m], w[pj * n + m]));
            const qd_expr *v = tidy(ctx, qd_sub(ctx, w[pi * n + m], w[pj * n + m]));
            w[pi * n + m] = w[m * n + pi] = u;
            w[pj * n + m] = w[m * n + pj] = v;
        }
        w[pi * n + pi] = tidy(ctx, qd_mul(ctx, qd_int(ctx, 2), aij));
        w[pj * n + pj] = tidy(ctx, qd_mul(ctx, qd_int(ctx, -2), aij));
        w[pi * n + pj] = w[pj * n + pi] = qd_int(ctx, 0);
        const qd_expr *half = qd_rat(ctx, 1, 2), *li = lin[pi], *lj = lin[pj];
        lin[pi] = qd_expand(ctx, qd_mul(ctx, half, qd_add(ctx, li, lj)));
        lin[pj] = qd_expand(ctx, qd_mul(ctx, half, qd_sub(ctx, li, lj)));
        f->paired = true;
        k = pi;
    }
    const qd_expr *c = w[k * n + k], *y = qd_int(ctx, 0);
    for (size_t j = 0; j < n; j++)
        if (live[j] && !qd_is_zero(w[k * n + j]))
            y = qd_add(ctx, y, qd_mul(ctx, tidy(ctx, qd_div(ctx, w[k * n + j], c)), lin[j]));
    live[k] = false;
    for (size_t i = 0; i < n; i++)
        for (size_t j = i; j < n; j++)
            if (live[i] && live[j]) {
                const qd_expr *d = qd_div(ctx, qd_mul(ctx, w[i * n + k], w[k * n + j]), c);
                w[i * n + j] = w[j * n + i] = tidy(ctx, qd_sub(ctx, w[i * n + j], d));
            }
    f->coef[f->nsq] = c;
    f->lin[f->nsq++] = qd_expand(ctx, y);
    return true;
}

static void inertia(qd_qform *f) {
    f->decided = true;
    for (size_t k = 0; k < f->nsq; k++) {
        int s = known_sign(f->coef[k]);
        f->npos += s > 0;
        f->nneg += s < 0;
        f->decided = f->decided && s != 0;
    }
    f->nzero = f->n - f->nsq;
    if (!f->decided) {
        f->npos = f->nneg = 0;
        f->kind = NULL;
        return;
    }
    f->kind = f->nsq == 0            ? "zero"
              : f->npos == f->n      ? "positive definite"
              : f->nneg == f->n      ? "negative definite"
              : f->nneg == 0         ? "positive semidefinite"
              : f->npos == 0         ? "negative semidefinite"
                                     : "indefinite";
}

/* phi - sum c_k y_k^2 must vanish. */
static bool verified(qd_ctx *ctx, const qd_qform *f) {
    const qd_expr *phi = qd_int(ctx, 0), *sum = qd_int(ctx, 0);
    size_t n = f->n;
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++)
            phi = qd_add(ctx, phi, qd_mul(ctx, f->a[i * n + j], qd_mul(ctx, f->x[i], f->x[j])));
    for (size_t k = 0; k < f->nsq; k++)
        sum = qd_add(ctx, sum, qd_mul(ctx, f->coef[k], qd_powi(ctx, f->lin[k], 2)));
    const qd_expr *d = qd_simplify(ctx, qd_cancel(ctx, qd_expand(ctx, qd_sub(ctx, phi, sum))));
    return d && qd_is_zero(d);
}

static qd_qform *reduce(qd_ctx *ctx, qd_qform *f) {
    size_t n = f->n;
    const qd_expr **w = qd__calloc(ctx, 2 * n * n + 1, sizeof *w);
    bool *live = qd__calloc(ctx, n + 1, sizeof *live);
    if (!w || !live) {
        qd__free(w);
        qd__free(live);
        qd_qform_free(f);
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory reducing a quadratic form");
        return NULL;
    }
    const qd_expr **lin = w + n * n;
    memcpy(w, f->a, n * n * sizeof *w);
    for (size_t i = 0; i < n; i++) {
        lin[i] = f->x[i];
        live[i] = true;
    }
    while (qd_ctx_status(ctx) == QD_OK && step(ctx, f, w, lin, live))
        ;
    qd__free(w);
    qd__free(live);
    if (qd_ctx_status(ctx) != QD_OK) {
        qd_qform_free(f);
        return NULL;
    }
    inertia(f);
    if (!verified(ctx, f)) {
        if (qd_ctx_status(ctx) == QD_OK)
            qd_ctx_error(ctx, QD_ERR_NUMERIC, "the sum of squares does not expand back to the "
                         "form (a bug in the reduction)");
        qd_qform_free(f);
        return NULL;
    }
    return f;
}

static bool distinct_symbols(qd_ctx *ctx, size_t n, const qd_expr *const *x) {
    for (size_t i = 0; i < n; i++) {
        if (!x[i] || qd_expr_kind(x[i]) != QD_SYMBOL) {
            qd_ctx_error(ctx, QD_ERR_ARG, "quadratic form: variable %zu is not a symbol", i + 1);
            return false;
        }
        for (size_t j = 0; j < i; j++)
            if (x[j] == x[i]) {
                qd_ctx_error(ctx, QD_ERR_ARG, "quadratic form: the variable %s is given twice",
                             qd_expr_name(x[i]));
                return false;
            }
    }
    return true;
}

qd_qform *qd_qform_reduce_matrix(qd_ctx *ctx, size_t n, const qd_expr *const *a,
                                 const qd_expr *const *x) {
    QD_ARGS(NULL, ctx && (n == 0 || a) && (n == 0 || x));
    if (!distinct_symbols(ctx, n, x))
        return NULL;
    for (size_t i = 0; i < n * n; i++)
        if (!a[i]) {
            qd_ctx_error(ctx, QD_ERR_ARG, "quadratic form: matrix entry %zu is NULL", i);
            return NULL;
        }
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < i; j++) {
            const qd_expr *d = qd_simplify(ctx, qd_sub(ctx, a[i * n + j], a[j * n + i]));
            if (!d || !qd_is_zero(d)) {
                if (d)
                    qd_ctx_error(ctx, QD_ERR_ARG, "quadratic form: the matrix is not "
                                 "symmetric (entries %zu,%zu and %zu,%zu)", i + 1, j + 1, j + 1, i + 1);
                return NULL;
            }
        }
    qd_qform *f = qform_alloc(ctx, n);
    if (!f)
        return NULL;
    memcpy(f->x, x, n * sizeof *x);
    for (size_t i = 0; i < n * n; i++)
        f->a[i] = qd_simplify(ctx, a[i]);
    return reduce(ctx, f);
}

qd_qform *qd_qform_reduce(qd_ctx *ctx, const qd_expr *phi, size_t n, const qd_expr *const *x) {
    QD_ARGS(NULL, ctx && phi && (n == 0 || x));
    if (!distinct_symbols(ctx, n, x))
        return NULL;
    qd_qform *f = qform_alloc(ctx, n);
    if (!f)
        return NULL;
    memcpy(f->x, x, n * sizeof *x);
    /* a_ij = 1/2 d^2 phi/dx_i dx_j, then phi - x^T a x must vanish */
    const qd_expr *back = qd_int(ctx, 0);
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++) {
            const qd_expr *aij = qd_simplify(
                ctx, qd_mul(ctx, qd_rat(ctx, 1, 2), qd_diff(ctx, qd_diff(ctx, phi, x[i]), x[j])));
            f->a[i * n + j] = aij;
            for (size_t k = 0; aij && k < n; k++)
                if (qd_has(aij, x[k])) {
                    qd_ctx_error(ctx, QD_ERR_ARG, "not a quadratic form in the variables: the "
                                 "coefficient of %s*%s depends on %s", qd_expr_name(x[i]),
                                 qd_expr_name(x[j]), qd_expr_name(x[k]));
                    qd_qform_free(f);
                    return NULL;
                }
            back = qd_add(ctx, back, qd_mul(ctx, aij, qd_mul(ctx, x[i], x[j])));
        }
    const qd_expr *rest = qd_simplify(ctx, qd_expand(ctx, qd_sub(ctx, phi, back)));
    if (!rest || !qd_is_zero(rest)) {
        if (rest)
            qd_ctx_error(ctx, QD_ERR_ARG, "not a quadratic form in the variables: a term "
                         "of degree other than 2 is left (linear, constant or of higher degree)");
        qd_qform_free(f);
        return NULL;
    }
    return reduce(ctx, f);
}
