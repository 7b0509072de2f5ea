/*
 * src/mech/condensed.c - Desloge's condensed notation (ch. 75; qdot/canonical.h):
 * r = (q_1..q_f, p_1..p_f) (eq. 1), lambda_ij = 1 for j = i + f and mu =
 * lambda - lambda^T (eqs. 2-3), Hamilton's equations r'_i = mu_ij dH/dr_j
 * (eq. 14), and for a map R = R(r) its Jacobian M = dR/dr, the Lagrange
 * brackets [r_k, r_l] = mu_ij dR_i/dr_k dR_j/dr_l = (M^T mu M)_kl (eq. 16),
 * Theorem 1 (canonical iff [r_k, r_l] = mu_kl, eq. 17; valence c when they
 * are c mu_kl, ch. 84 Thm 3) and |dR/dr| (+-1 for a canonical map, Ex. 2,
 * eq. 28).  Every entry of eq. 17 is decided by the zero test.
 */
#include "qdot/canonical.h"
#include "mech.h"
#include "../base/args.h"
#include "../base/mem.h"

void qd_condensed_free(qd_condensed *c) {
    if (!c)
        return;
    qd__free(c->r);
    *c = (qd_condensed){0};
}

static const qd_expr *tidy(qd_ctx *ctx, const qd_expr *e) {
    return e ? qd_simplify(ctx, qd_cancel(ctx, e)) : NULL;
}

static qd_status cd_alloc(qd_ctx *ctx, qd_condensed *c, size_t n) {
    size_t m = 2 * n;
    const qd_expr **blk = qd__calloc(ctx, 4 * m + 4 * m * m + 1, sizeof *blk);
    if (!blk)
        return QD_ERR_NOMEM;
    c->n = n;
    c->r = blk;
    c->R = c->r + m;
    c->grad = c->R + m;
    c->rdot = c->grad + m;
    c->lambda = c->rdot + m;
    c->mu = c->lambda + m * m;
    c->M = c->mu + m * m;
    c->bracket = c->M + m * m;
    return QD_OK;
}

/* eq. 14: r'_i = mu_ij dH/dr_j. */
static void hamilton(qd_ctx *ctx, qd_condensed *c, const qd_expr *H) {
    size_t m = 2 * c->n;
    for (size_t j = 0; j < m; j++)
        c->grad[j] = tidy(ctx, qd_diff(ctx, H, c->r[j]));
    for (size_t i = 0; i < m; i++) {
        const qd_expr *s = qd_int(ctx, 0);
        for (size_t j = 0; j < m; j++)
            if (!qd_is_zero(c->mu[i * m + j]))
                s = qd_add(ctx, s, qd_mul(ctx, c->mu[i * m + j], c->grad[j]));
        c->rdot[i] = tidy(ctx, s);
    }
    c->has_H = true;
}

/* eq. 16 and |dR/dr|. */
static void brackets(qd_ctx *ctx, qd_condensed *c) {
    size_t m = 2 * c->n;
    for (size_t i = 0; i < m; i++)
        for (size_t j = 0; j < m; j++)
            c->M[i * m + j] = tidy(ctx, qd_diff(ctx, c->R[i], c->r[j]));
    for (size_t k = 0; k < m; k++)
        for (size_t l = 0; l < m; l++) {
            const qd_expr *s = qd_int(ctx, 0);
            for (size_t i = 0; i < m; i++)
                for (size_t j = 0; j < m; j++)
                    if (!qd_is_zero(c->mu[i * m + j]))
                        s = qd_add(ctx, s, qd_mul(ctx, c->mu[i * m + j],
                                                  qd_mul(ctx, c->M[i * m + k], c->M[j * m + l])));
            c->bracket[k * m + l] = tidy(ctx, qd_expand(ctx, s));
        }
    const qd_expr *d = qd__mech_det(ctx, m, c->M);
    c->det = d ? qd_simplify(ctx, qd_trigsimp(ctx, tidy(ctx, d))) : NULL;
}

/* Thm 1 (eq. 17), or the valence c: every [r_k, r_l] - c mu_kl zero-tested. */
static qd_status theorem1(qd_ctx *ctx, qd_condensed *c) {
    size_t m = 2 * c->n;
    const qd_expr *scale = c->bracket[0 * m + c->n]; /* [q_1, p_1] */
    bool constant = !qd_is_zero(scale);
    for (size_t j = 0; j < m; j++)
        constant = constant && !qd_has(scale, c->r[j]);
    if (!constant)
        scale = qd_int(ctx, 1);
    c->kind = QD_CANON_YES;
    c->check = (qd_zero_result){.kind = QD_ZERO_PROVEN};
    for (size_t k = 0; k < m && c->kind != QD_CANON_NO; k++)
        for (size_t l = 0; l < m; l++) {
            qd_zero_result z;
            const qd_expr *want = tidy(ctx, qd_mul(ctx, scale, c->mu[k * m + l]));
            if (qd_equal_test(ctx, c->bracket[k * m + l], want, &z) != QD_OK)
                return qd_ctx_status(ctx);
            if (z.kind == QD_ZERO_PROVEN)
                continue;
            if (z.kind == QD_ZERO_NUMERIC && c->check.kind == QD_ZERO_PROVEN) {
                c->check = z;
                continue;
            }
            if (z.kind == QD_ZERO_NUMERIC)
                continue;
            c->kind = z.kind == QD_ZERO_NONZERO ? QD_CANON_NO : QD_CANON_UNDECIDED;
            c->check = z;
            c->bad_k = k;
            c->bad_l = l;
            c->should_be = want;
            if (c->kind == QD_CANON_NO)
                break;
        }
    if (c->kind == QD_CANON_YES && !qd_is_one(scale))
        c->kind = QD_CANON_SCALED;
    c->scale = c->kind == QD_CANON_YES || c->kind == QD_CANON_SCALED ? scale : NULL;
    return QD_OK;
}

qd_status qd_condensed_new(qd_ctx *ctx, size_t n, const qd_expr *const *q,
                           const qd_expr *const *p, const qd_expr *const *Q,
                           const qd_expr *const *P, const qd_expr *H, qd_condensed *out) {
    QD_ARGS_CTX(ctx, ctx && q && p && Q && P && out);
    *out = (qd_condensed){0};
    if (n == 0) {
        qd_ctx_error(ctx, QD_ERR_ARG, "condensed notation: no degrees of freedom");
        return QD_ERR_ARG;
    }
    if (cd_alloc(ctx, out, n) != QD_OK) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory writing the condensed notation");
        return QD_ERR_NOMEM;
    }
    size_t m = 2 * n;
    for (size_t i = 0; i < n; i++) {
        out->r[i] = q[i];
        out->r[n + i] = p[i];
        out->R[i] = tidy(ctx, Q[i]);
        out->R[n + i] = tidy(ctx, P[i]);
    }
    for (size_t i = 0; i < m; i++)
        for (size_t j = 0; j < m; j++) {
            out->lambda[i * m + j] = qd_int(ctx, j == i + n);
            out->mu[i * m + j] = qd_int(ctx, (j == i + n) - (i == j + n));
        }
    if (H)
        hamilton(ctx, out, H);
    brackets(ctx, out);
    qd_status st = qd_ctx_status(ctx);
    if (st == QD_OK && !out->det)
        st = QD_ERR_NOMEM;
    if (st == QD_OK)
        st = theorem1(ctx, out);
    if (st != QD_OK) {
        if (qd_ctx_status(ctx) == QD_OK)
            qd_ctx_error(ctx, st, "condensed notation: %s", qd_status_str(st));
        qd_condensed_free(out);
    }
    return st;
}

qd_status qd_phase_condensed(qd_ctx *ctx, qd_phase *ph, const qd_expr *const *Q,
                             const qd_expr *const *P, qd_condensed *out) {
    QD_ARGS_CTX(ctx, ctx && ph && Q && P && out);
    *out = (qd_condensed){0};
    const qd_expr *H = NULL;
    if (qd_phase_ham(ctx, ph, true) == QD_OK)
        H = ph->h->H;
    else if (qd_ctx_status(ctx) == QD_ERR_NONLINEAR) /* an implicit H: no eq. 14 */
        qd_ctx_clear_error(ctx);
    else
        return qd_ctx_status(ctx);
    return qd_condensed_new(ctx, ph->n, ph->q, ph->p, Q, P, H, out);
}
