/*
 * src/mech/solve.c - M q'' = f solved: symbolically by fraction-free
 * elimination (numerically: eval.c).
 *
 * Fraction-free (Bareiss) elimination: after step k every entry is a
 * determinant of the original entries, so the division by the previous
 * pivot is exact as polynomials in the entries' generators (Bareiss, Math.
 * Comp. 22 (1968) 565).  Each step is expanded and cancelled, which keeps
 * the entries polynomial; only the finished accelerations are simplified.
 * The solution is x_i = N_i / det M with N_i (Cramer's numerators) found by
 * a fraction-free back substitution.  With constraints the same elimination
 * runs on the saddle-point matrix [M -A^T; A 0] (eval.c and saddle.c have
 * its numbers).
 */
#include "mech.h"

#include "base/mem.h"
#include "../base/args.h"
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

/* Intermediate entries beyond this many operations times the caller's
 * limit stop the elimination early: the result would not fit either. */
#define GROWTH 32

/* The intermediate limit for a result limit max_ops; 0 (none) when that
 * would overflow (max_ops = SIZE_MAX: no limit). */
static size_t growth_limit(size_t max_ops) {
    return max_ops && max_ops <= (SIZE_MAX - 4096) / GROWTH ? max_ops * GROWTH + 4096 : 0;
}

typedef struct elim {
    qd_ctx *ctx;
    size_t n, w;       /* rows, columns (n, or n + 1 with f) */
    const qd_expr **A; /* row-major, n*w */
    size_t limit;      /* operations per entry, 0 for none */
    int sign;          /* of the row permutation */
    bool smallest;     /* pivot on the shortest nonzero entry, not the first */
} elim;

static const qd_expr *exact_div(qd_ctx *ctx, const qd_expr *num, const qd_expr *den) {
    num = qd_expand(ctx, num);
    if (qd_is_one(den) || !num)
        return num;
    return qd_cancel(ctx, qd_div(ctx, num, den));
}

/* The row at or below k to pivot on in column k: with el->smallest the
 * one whose entry has the fewest operations (a constant first: the
 * entries then grow least), else the first nonzero; el->n when none. */
static size_t pick_row(elim *el, size_t k, qd_status *st) {
    size_t best = el->n, best_ops = 0;
    for (size_t r = k; r < el->n; r++) {
        const qd_expr *x = qd_simplify(el->ctx, el->A[r * el->w + k]);
        if (!x) { /* not a zero: the simplifier failed (out of memory) */
            *st = qd_ctx_status(el->ctx) != QD_OK ? qd_ctx_status(el->ctx) : QD_ERR_NOMEM;
            return el->n;
        }
        if (qd_is_zero(x))
            continue;
        size_t ops = qd_is_number(x) ? 0 : 1 + qd_count_ops(x);
        if (best == el->n || ops < best_ops)
            best = r, best_ops = ops;
        if (!el->smallest || !ops)
            break;
    }
    return best;
}

/* Move a row with an entry that does not simplify to 0 in column k to row
 * k; QD_ERR_SINGULAR when there is none. */
static qd_status find_pivot(elim *el, size_t k) {
    qd_status st = QD_OK;
    size_t r = pick_row(el, k, &st);
    if (st != QD_OK)
        return st;
    if (r < el->n) {
        for (size_t j = 0; r != k && j < el->w; j++) {
            const qd_expr *t = el->A[r * el->w + j];
            el->A[r * el->w + j] = el->A[k * el->w + j];
            el->A[k * el->w + j] = t;
        }
        el->sign = r != k ? -el->sign : el->sign;
        return QD_OK;
    }
    return QD_ERR_SINGULAR;
}

static qd_status step(elim *el, size_t k, const qd_expr *prev) {
    qd_ctx *ctx = el->ctx;
    const qd_expr *const *A = el->A, *pk = A[k * el->w + k];
    for (size_t i = k + 1; i < el->n; i++) {
        for (size_t j = k + 1; j < el->w; j++) {
            const qd_expr *x = qd_sub(ctx, qd_mul(ctx, pk, A[i * el->w + j]),
                                      qd_mul(ctx, A[i * el->w + k], A[k * el->w + j]));
            x = exact_div(ctx, x, prev);
            if (!x)
                return qd_ctx_status(ctx);
            if (el->limit && qd_count_ops(x) > el->limit)
                return QD_ERR_TOOBIG;
            el->A[i * el->w + j] = x;
        }
        el->A[i * el->w + k] = qd_int(ctx, 0);
    }
    return QD_OK;
}

/* Forward elimination; QD_ERR_SINGULAR when a column has no pivot. */
static qd_status bareiss(elim *el) {
    const qd_expr *prev = qd_int(el->ctx, 1);
    el->sign = 1;
    for (size_t k = 0; k < el->n; k++) {
        qd_status st = find_pivot(el, k);
        if (st == QD_OK)
            st = step(el, k, prev);
        if (st != QD_OK)
            return st;
        prev = el->A[k * el->w + k];
    }
    return QD_OK;
}

const qd_expr *qd__mech_det(qd_ctx *ctx, size_t n, const qd_expr *const *M) {
    const qd_expr **A = qd__malloc(ctx, (n ? n * n : 1) * sizeof *A);
    if (!A)
        return NULL;
    for (size_t i = 0; i < n * n; i++)
        A[i] = M[i];
    elim el = {ctx, n, n, A, 0, 1, false};
    qd_status st = n ? bareiss(&el) : QD_OK;
    const qd_expr *det = st == QD_ERR_SINGULAR ? qd_int(ctx, 0)
                         : st != QD_OK         ? NULL
                         : n                   ? A[n * n - 1]
                                               : qd_int(ctx, 1);
    if (det && el.sign < 0)
        det = qd_neg(ctx, det);
    qd__free(A);
    return det;
}

/* Cramer's numerators N (det times the solution) of right-hand side col
 * (a column index >= n) from the echelon form. */
static qd_status back_substitute_col(elim *el, const qd_expr *det, size_t col, const qd_expr **N) {
    qd_ctx *ctx = el->ctx;
    size_t n = el->n, w = el->w;
    for (size_t i = n; i-- > 0;) {
        const qd_expr *x = qd_mul(ctx, det, el->A[i * w + col]);
        for (size_t j = i + 1; j < n; j++)
            x = qd_sub(ctx, x, qd_mul(ctx, el->A[i * w + j], N[j]));
        N[i] = exact_div(ctx, x, el->A[i * w + i]);
        if (!N[i])
            return qd_ctx_status(ctx);
        if (el->limit && qd_count_ops(N[i]) > el->limit)
            return QD_ERR_TOOBIG;
    }
    return QD_OK;
}

static qd_status back_substitute(elim *el, const qd_expr *det, const qd_expr **N) {
    return back_substitute_col(el, det, el->n, N);
}

/* The shorter of N/det simplified as a whole and as two parts. */
static const qd_expr *quotient(qd_ctx *ctx, const qd_expr *N, const qd_expr *det_s) {
    const qd_expr *a = qd_simplify(ctx, qd_div(ctx, N, det_s));
    const qd_expr *b = qd_div(ctx, qd_simplify(ctx, N), det_s);
    if (!a || !b)
        return NULL;
    return qd_count_ops(b) < qd_count_ops(a) ? b : a;
}

static qd_status solve_entries(elim *el, const qd_expr **acc, size_t max_ops) {
    qd_ctx *ctx = el->ctx;
    qd_status st = bareiss(el);
    const qd_expr *det = el->A[el->n * el->w - 2];
    if (st != QD_OK)
        return st;
    st = back_substitute(el, det, acc);
    const qd_expr *det_s = qd_simplify(ctx, det);
    if (st != QD_OK || !det_s)
        return st != QD_OK ? st : qd_ctx_status(ctx);
    if (qd_is_zero(det_s))
        return QD_ERR_SINGULAR;
    for (size_t i = 0; i < el->n; i++) {
        acc[i] = quotient(ctx, acc[i], det_s);
        if (!acc[i])
            return qd_ctx_status(ctx);
        if (qd_count_ops(acc[i]) > max_ops)
            return QD_ERR_TOOBIG;
    }
    return QD_OK;
}

static void solve_error(qd_ctx *ctx, qd_status st, size_t ncon, size_t max_ops) {
    if (qd_ctx_status(ctx) != QD_OK)
        return;
    if (st == QD_ERR_TOOBIG)
        qd_ctx_error(ctx, st, "the explicit accelerations exceed %zu operations; keep M q'' = f",
                     max_ops);
    else if (st == QD_ERR_SINGULAR && ncon)
        qd_ctx_error(ctx, st, "the matrix [M -A^T; A 0] of the constrained equations is "
                              "singular for every state");
    else if (st == QD_ERR_SINGULAR)
        qd_ctx_error(ctx, st, "the mass matrix is singular: det M = 0 for every state");
    else
        qd_ctx_error(ctx, st, "solving M q'' = f failed");
}

/* The augmented saddle-point matrix [M -A^T f; A 0 b] ((n+m) rows). */
static void augmented(qd_ctx *ctx, const qd_eom *e, const qd_expr **A) {
    size_t n = e->n, m = e->ncon, N = n + m, w = N + 1;
    const qd_expr *zero = qd_int(ctx, 0);
    for (size_t i = 0; i < N * w; i++)
        A[i] = zero;
    for (size_t i = 0; i < n; i++) {
        for (size_t j = 0; j < n; j++)
            A[i * w + j] = e->M[i * n + j];
        A[i * w + N] = e->f[i];
    }
    for (size_t k = 0; k < m; k++) {
        for (size_t j = 0; j < n; j++) {
            A[j * w + n + k] = qd_neg(ctx, e->A[k * n + j]);
            A[(n + k) * w + j] = e->A[k * n + j];
        }
        A[(n + k) * w + N] = e->b[k];
    }
}

static qd_status keep(qd_ctx *ctx, qd_eom *e, const qd_expr **x) {
    const qd_expr **mult = NULL;
    if (e->ncon) {
        mult = qd__malloc(ctx, e->ncon * sizeof *mult);
        if (!mult)
            return QD_ERR_NOMEM;
        for (size_t k = 0; k < e->ncon; k++)
            mult[k] = x[e->n + k];
    }
    qd__free(e->acc);
    qd__free(e->mult);
    e->acc = x;
    e->mult = mult;
    return QD_OK;
}

qd_status qd_eom_solve(qd_ctx *ctx, qd_eom *e, size_t max_ops) {
    QD_ARGS_CTX(ctx, ctx && e);
    size_t N = e->n + e->ncon, w = N + 1;
    const qd_expr **A = qd__malloc(ctx, (N * w + 1) * sizeof *A), **acc = qd__calloc(ctx, N + 1, sizeof *acc);
    qd_status st = A && acc ? QD_OK : QD_ERR_NOMEM;
    if (st == QD_OK)
        augmented(ctx, e, A);
    elim el = {ctx, N, w, A, growth_limit(max_ops), 1, false};
    if (st == QD_OK && N)
        st = solve_entries(&el, acc, max_ops);
    qd__free(A);
    if (st == QD_OK)
        st = keep(ctx, e, acc);
    if (st != QD_OK) {
        qd__free(acc);
        solve_error(ctx, st, e->ncon, max_ops);
        return st;
    }
    return QD_OK;
}

qd_status qd__mech_solve_cols(qd_ctx *ctx, size_t n, const qd_expr *const *A, size_t ncols,
                         const qd_expr *const *B, const qd_expr **X, size_t max_ops) {
    if (!n)
        return QD_OK;
    size_t w = n + ncols;
    const qd_expr **E = qd__malloc(ctx, (n * w + 1) * sizeof *E);
    const qd_expr **N = qd__malloc(ctx, (n + 1) * sizeof *N);
    qd_status st = E && N ? QD_OK : QD_ERR_NOMEM;
    for (size_t i = 0; st == QD_OK && i < n; i++) {
        for (size_t j = 0; j < n; j++)
            E[i * w + j] = A[i * n + j];
        for (size_t c = 0; c < ncols; c++)
            E[i * w + n + c] = B[i * ncols + c];
    }
    elim el = {ctx, n, w, E, growth_limit(max_ops), 1, true};
    if (st == QD_OK)
        st = bareiss(&el);
    const qd_expr *det = st == QD_OK ? qd_simplify(ctx, E[(n - 1) * w + n - 1]) : NULL;
    if (st == QD_OK && !det)
        st = qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    if (st == QD_OK && det && qd_is_zero(det))
        st = QD_ERR_SINGULAR;
    for (size_t c = 0; st == QD_OK && c < ncols; c++) {
        st = back_substitute_col(&el, E[(n - 1) * w + n - 1], n + c, N);
        for (size_t i = 0; st == QD_OK && i < n; i++)
            if (!(X[i * ncols + c] = quotient(ctx, N[i], det)))
                st = qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
            else if (max_ops && qd_count_ops(X[i * ncols + c]) > max_ops)
                st = QD_ERR_TOOBIG;
    }
    qd__free(E);
    qd__free(N);
    if (st == QD_ERR_NOMEM && qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, st, "out of memory solving a linear system");
    return st;
}
