/*
 * src/mech/legendre_blocks.c - q' = M^-1 r and r^T M^-1 r / 2 for a small
 * symbolic mass matrix, by its blocks.
 *
 * A mass matrix is block-diagonal more often than not (a free particle, a
 * pendulum on a cart, a body whose translation and rotation decouple), and
 * its blocks are small.  Gaussian elimination on the whole matrix nests
 * quotients of quotients that only a large cancellation undoes (the hoop of
 * examples/hoop_struck.qd: 7.8 s and 234 KB before); the adjugate of each
 * block, by cofactors, gives M^-1 = adj M / det M (Cramer's rule) in a form
 * that one simplification of each entry and of each block's quadratic form
 * keeps textbook-sized: the free body in Euler angles gets det M = A B C
 * sin(theta)^2 straight away, and a dense 5 x 5 block of masses that
 * elimination took past the expansion limit stays small.  Blocks larger
 * than COFACTOR_MAX (k^2 minors of order k - 1) are solved by elimination.
 */
#include "legendre.h"
#include "mech.h"
#include "../base/mem.h"

#include <stdlib.h>

enum { COFACTOR_MAX = 8 };

/* Union-find root of i (the blocks are the components of M's nonzero
 * off-diagonal pattern). */
static size_t root(size_t *up, size_t i) {
    while (up[i] != i)
        i = up[i] = up[up[i]];
    return i;
}

/* The (k-1) x (k-1) minor of the k x k matrix B without row i and column j. */
static void minor_of(size_t k, const qd_expr *const *B, size_t i, size_t j, const qd_expr **out) {
    size_t o = 0;
    for (size_t r = 0; r < k; r++)
        for (size_t c = 0; r != i && c < k; c++)
            if (c != j)
                out[o++] = B[r * k + c];
}

/* adj(B) by cofactors, each simplified, and det B simplified; QD_ERR_SINGULAR
 * (nothing recorded) when det B simplifies to 0. */
static qd_status adjugate(qd_ctx *ctx, size_t k, const qd_expr *const *B, const qd_expr **adj,
                          const qd_expr **det, const qd_expr **work) {
    *det = qd_simplify(ctx, qd__mech_det(ctx, k, B));
    if (!*det)
        return qd_ctx_status(ctx);
    if (qd_is_zero(*det))
        return QD_ERR_SINGULAR;
    for (size_t i = 0; i < k; i++)
        for (size_t j = 0; j < k; j++) {
            if (k == 1) {
                adj[0] = qd_int(ctx, 1);
                break;
            }
            if (j < i) { /* B is symmetric, so is adj B */
                adj[i * k + j] = adj[j * k + i];
                continue;
            }
            minor_of(k, B, j, i, work);
            const qd_expr *c = qd_simplify(ctx, qd__mech_det(ctx, k - 1, work));
            adj[i * k + j] = (i + j) % 2 ? qd_neg(ctx, c) : c;
            if (!adj[i * k + j])
                return qd_ctx_status(ctx);
        }
    return QD_OK;
}

/* One block by cofactors: x_i = sum_j adj_ij r_j / det, and
 * r^T adj r / (2 det), each simplified once. */
static qd_status block_cofactors(qd_ctx *ctx, size_t k, const qd_expr *const *B,
                                 const qd_expr *const *r, const qd_expr **x, const qd_expr **half,
                                 const qd_expr **num, const qd_expr **den,
                                 const qd_expr **scratch) {
    const qd_expr **adj = scratch, **work = scratch + k * k, *det = NULL;
    qd_status st = adjugate(ctx, k, B, adj, &det, work);
    if (st != QD_OK)
        return st;
    const qd_expr *form = qd_int(ctx, 0);
    for (size_t i = 0; i < k; i++) {
        const qd_expr *s = qd_int(ctx, 0);
        for (size_t j = 0; j < k; j++)
            s = qd_add(ctx, s, qd_mul(ctx, adj[i * k + j], r[j]));
        num[i] = s;
        den[i] = det;
        x[i] = qd_simplify(ctx, qd_div(ctx, s, det));
        form = qd_add(ctx, form, qd_mul(ctx, r[i], s));
        if (!x[i])
            return qd_ctx_status(ctx);
    }
    *half = qd_simplify(ctx, qd_div(ctx, form, qd_mul(ctx, qd_int(ctx, 2), det)));
    return *half ? QD_OK : qd_ctx_status(ctx);
}

/* One block by elimination (too large for cofactors): x, and r . x / 2. */
static qd_status block_gauss(qd_ctx *ctx, size_t k, const qd_expr *const *B,
                             const qd_expr *const *r, const qd_expr **x, const qd_expr **half,
                             const qd_expr **num, const qd_expr **den,
                             const qd_expr **scratch) {
    const qd_expr **A = scratch;
    for (size_t i = 0; i < k; i++) {
        for (size_t j = 0; j < k; j++)
            A[i * (k + 1) + j] = B[i * k + j];
        A[i * (k + 1) + k] = r[i];
    }
    size_t bad = 0;
    qd_status st = qd__mech_gauss_solve(ctx, k, A, x, &bad);
    if (st != QD_OK)
        return st;
    const qd_expr *form = qd_int(ctx, 0);
    for (size_t i = 0; i < k; i++) {
        form = qd_add(ctx, form, qd_mul(ctx, r[i], x[i]));
        num[i] = x[i];
        den[i] = qd_int(ctx, 1);
    }
    *half = qd_simplify(ctx, qd_div(ctx, form, qd_int(ctx, 2)));
    return *half ? QD_OK : qd_ctx_status(ctx);
}

/* The block of M on the indices idx[0..k): its part of x and of the form. */
static qd_status block(qd_ctx *ctx, size_t n, const qd_expr *const *M, const qd_expr *const *r,
                       const size_t *idx, size_t k, qd__quad_inv *out, const qd_expr **half,
                       const qd_expr **buf) {
    const qd_expr **B = buf, **rb = buf + k * k, **xb = rb + k, **nb = xb + k, **db = nb + k,
                  **scratch = db + k;
    for (size_t i = 0; i < k; i++) {
        rb[i] = r[idx[i]];
        for (size_t j = 0; j < k; j++) {
            size_t a = idx[i < j ? i : j], c = idx[i < j ? j : i]; /* the upper triangle */
            B[i * k + j] = M[a * n + c];
        }
    }
    qd_status st = k <= COFACTOR_MAX ? block_cofactors(ctx, k, B, rb, xb, half, nb, db, scratch)
                                     : block_gauss(ctx, k, B, rb, xb, half, nb, db, scratch);
    for (size_t i = 0; st == QD_OK && i < k; i++) {
        out->x[idx[i]] = xb[i];
        out->num[idx[i]] = nb[i];
        out->den[idx[i]] = db[i];
    }
    return st;
}

qd_status qd__mech_quad_inverse(qd_ctx *ctx, size_t n, const qd_expr **M, const qd_expr *const *r,
                                qd__quad_inv *out, const qd_expr **half) {
    size_t *up = qd__malloc(ctx, (2 * n + 1) * sizeof *up), *idx = up ? up + n : NULL;
    /* B, r, x, num, den of a block, and the adjugate and a minor (cofactors)
     * or the augmented system (elimination): at most 3 k^2 + 5 k entries */
    const qd_expr **buf = qd__calloc(ctx, 3 * n * n + 5 * n + 1, sizeof *buf);
    qd_status st = up && buf ? QD_OK : QD_ERR_NOMEM;
    for (size_t i = 0; st == QD_OK && i < n; i++)
        up[i] = i;
    for (size_t i = 0; st == QD_OK && i < n * n; i++) {
        M[i] = qd_simplify(ctx, M[i]);
        if (!M[i])
            st = qd_ctx_status(ctx);
        else if (i / n < i % n && !qd_is_zero(M[i]))
            up[root(up, i / n)] = root(up, i % n);
    }
    *half = qd_int(ctx, 0);
    for (size_t b = 0; st == QD_OK && b < n; b++) {
        if (root(up, b) != b)
            continue;
        size_t k = 0;
        for (size_t i = 0; i < n; i++)
            if (root(up, i) == b)
                idx[k++] = i;
        const qd_expr *hb = NULL;
        st = block(ctx, n, M, r, idx, k, out, &hb, buf);
        if (st == QD_OK)
            *half = qd_add(ctx, *half, hb);
    }
    qd__free(up);
    qd__free(buf);
    if (st == QD_OK && !*half)
        st = qd_ctx_status(ctx);
    return st;
}
