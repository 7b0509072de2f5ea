/*
 * src/mech/solve_sparse.c - A X = B for the sparse systems of kinematics
 * (a speed's definition is one or two velocities, a rolling constraint
 * three), by peeling singletons off before any elimination.
 *
 * A row with one unknown left gives that unknown at once (forward); an
 * unknown left in one row only is given by that row once the others are
 * known (backward, in reverse order).  What neither reaches, the core, is
 * solved by qd__mech_solve_cols' fraction-free elimination.  Bareiss on the whole
 * system would carry every row's terms through every pivot and leave the
 * determinant in each entry to cancel at the end: on the rolling disk the
 * map is triangular and the core empty, on the bicycle the core is 3 of 6.
 */
#include "mech.h"

#include "../base/mem.h"

typedef struct peel {
    qd_ctx *ctx;
    size_t n, nc;
    const qd_expr *const *A;
    const qd_expr **R;         /* the right-hand sides, reduced as we go */
    const qd_expr **X;
    bool *row_on, *col_on;
    size_t *back_row, *back_col, nback;
    qd__tidy_fn tidy;
    void *arg;
} peel;

static const qd_expr *tidy(const peel *p, size_t j, size_t c, const qd_expr *x) {
    return p->tidy ? (x ? p->tidy(p->arg, j, c, x) : NULL) : qd_simplify(p->ctx, x);
}

static bool nz(const peel *p, size_t i, size_t j) { return !qd_is_zero(p->A[i * p->n + j]); }

/* The one active column of row i, n when none, n + 1 when several. */
static size_t only_col(const peel *p, size_t i) {
    size_t at = p->n;
    for (size_t j = 0; j < p->n; j++)
        if (p->col_on[j] && nz(p, i, j)) {
            if (at != p->n)
                return p->n + 1;
            at = j;
        }
    return at;
}

static size_t only_row(const peel *p, size_t j) {
    size_t at = p->n;
    for (size_t i = 0; i < p->n; i++)
        if (p->row_on[i] && nz(p, i, j)) {
            if (at != p->n)
                return p->n + 1;
            at = i;
        }
    return at;
}

static qd_status failed(qd_ctx *ctx) {
    return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
}

/* Row i has column j alone: X_j from it, then out of every other row. */
static qd_status forward(peel *p, size_t i, size_t j) {
    qd_ctx *ctx = p->ctx;
    size_t n = p->n, nc = p->nc;
    p->row_on[i] = p->col_on[j] = false;
    for (size_t c = 0; c < nc; c++)
        if (!(p->X[j * nc + c] = tidy(p, j, c, qd_div(ctx, p->R[i * nc + c], p->A[i * n + j]))))
            return failed(ctx);
    for (size_t r = 0; r < n; r++)
        for (size_t c = 0; p->row_on[r] && nz(p, r, j) && c < nc; c++)
            if (!(p->R[r * nc + c] = qd_sub(ctx, p->R[r * nc + c],
                                            qd_mul(ctx, p->A[r * n + j], p->X[j * nc + c]))))
                return failed(ctx);
    return QD_OK;
}

/* Peel until neither kind of singleton is left; QD_ERR_SINGULAR when a
 * row or a column runs out of entries. */
static qd_status peel_all(peel *p) {
    size_t n = p->n;
    for (bool again = true; again;) {
        again = false;
        for (size_t i = 0; i < n; i++) {
            if (!p->row_on[i])
                continue;
            size_t j = only_col(p, i);
            if (j == n)
                return QD_ERR_SINGULAR;
            if (j < n) {
                qd_status st = forward(p, i, j);
                if (st != QD_OK)
                    return st;
                again = true;
            }
        }
        for (size_t j = 0; j < n; j++) {
            if (!p->col_on[j])
                continue;
            size_t i = only_row(p, j);
            if (i == n)
                return QD_ERR_SINGULAR;
            if (i < n) {
                p->row_on[i] = p->col_on[j] = false;
                p->back_row[p->nback] = i;
                p->back_col[p->nback++] = j;
                again = true;
            }
        }
    }
    return QD_OK;
}

/* The core: the rows and columns still on, by elimination. */
static qd_status core(peel *p, size_t max_ops) {
    qd_ctx *ctx = p->ctx;
    size_t n = p->n, nc = p->nc, k = 0, *rows = qd__malloc(ctx, 2 * (n + 1) * sizeof *rows);
    if (!rows)
        return failed(ctx);
    size_t *cols = rows + n + 1, kc = 0;
    for (size_t i = 0; i < n; i++) {
        if (p->row_on[i])
            rows[k++] = i;
        if (p->col_on[i])
            cols[kc++] = i;
    }
    const qd_expr **S = k ? qd__malloc(ctx, (k * k + 2 * k * nc) * sizeof *S) : NULL;
    qd_status st = !k ? QD_OK : S ? QD_OK : failed(ctx);
    if (st == QD_OK && k) {
        const qd_expr **SB = S + k * k, **SX = SB + k * nc;
        for (size_t a = 0; a < k; a++) {
            for (size_t b = 0; b < k; b++)
                S[a * k + b] = p->A[rows[a] * n + cols[b]];
            for (size_t c = 0; c < nc; c++)
                SB[a * nc + c] = p->R[rows[a] * nc + c];
        }
        st = qd__mech_solve_cols(ctx, k, S, nc, SB, SX, max_ops);
        for (size_t b = 0; st == QD_OK && b < k; b++)
            for (size_t c = 0; c < nc; c++)
                p->X[cols[b] * nc + c] = SX[b * nc + c];
    }
    qd__free(S);
    qd__free(rows);
    return st;
}

/* The rows peeled as a column's only entry, last first: every other
 * unknown of the row is known by then. */
static qd_status backward(peel *p, const qd_expr *const *B) {
    qd_ctx *ctx = p->ctx;
    size_t n = p->n, nc = p->nc;
    for (size_t b = p->nback; b-- > 0;) {
        size_t i = p->back_row[b], j = p->back_col[b];
        for (size_t c = 0; c < nc; c++) {
            const qd_expr *s = B[i * nc + c];
            for (size_t l = 0; l < n && s; l++)
                if (l != j && nz(p, i, l))
                    s = qd_sub(ctx, s, qd_mul(ctx, p->A[i * n + l], p->X[l * nc + c]));
            if (!(p->X[j * nc + c] = tidy(p, j, c, qd_div(ctx, s, p->A[i * n + j]))))
                return failed(ctx);
        }
    }
    return QD_OK;
}

qd_status qd__mech_solve_sparse(qd_ctx *ctx, size_t n, const qd_expr *const *A, size_t ncols,
                           const qd_expr *const *B, const qd_expr **X, size_t max_ops,
                           qd__tidy_fn tidy, void *arg) {
    if (!n)
        return QD_OK;
    peel p = {.ctx = ctx, .n = n, .nc = ncols, .A = A, .tidy = tidy, .arg = arg};
    p.R = qd__malloc(ctx, (n * ncols + 1) * sizeof *p.R);
    p.row_on = qd__malloc(ctx, 2 * n * sizeof *p.row_on);
    p.back_row = qd__malloc(ctx, 2 * n * sizeof *p.back_row);
    qd_status st = p.R && p.row_on && p.back_row ? QD_OK : failed(ctx);
    if (st == QD_OK) {
        p.X = X;
        p.col_on = p.row_on + n;
        p.back_col = p.back_row + n;
        for (size_t i = 0; i < n; i++)
            p.row_on[i] = p.col_on[i] = true;
        for (size_t i = 0; i < n * ncols; i++)
            p.R[i] = B[i];
        st = peel_all(&p);
    }
    if (st == QD_OK)
        st = core(&p, max_ops);
    if (st == QD_OK)
        st = backward(&p, B);
    for (size_t i = 0; st == QD_OK && max_ops && i < n * ncols; i++)
        if (qd_count_ops(X[i]) > max_ops)
            st = QD_ERR_TOOBIG;
    qd__free(p.R);
    qd__free(p.row_on);
    qd__free(p.back_row);
    if (st == QD_ERR_NOMEM && qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, st, "out of memory solving a linear system");
    return st;
}
