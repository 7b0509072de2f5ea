/*
 * src/speeds/kane.c - Kane's equations in Lagrange's form: Lagrange's
 * equations M q'' = f (simplified, as qd_eom_derive makes them) on the
 * motion, projected on the partial velocities W_jr = dq'_j/du_r:
 *
 *     sum_j W_jr (M q'' - f)_j = 0,   q'' = W u' + a0,
 *     M_u = W^T M W,   f_u = W^T (f - M a0),
 *
 * a0 the accelerations at u' = 0, f and M at q' = W u + w.  The constraint
 * forces A^T lambda are normal to every column of W (C W = 0 by
 * construction), so the projection drops them: Kane's generalized active
 * plus inertia forces, F_r + F*_r = 0 (Kane and Levinson, Dynamics: Theory
 * and Applications, 1985, sec. 6.1 and 6.3, where F*_r is written with T
 * exactly so).  The default method.  Lagrange's rows are taken raw (f
 * grouped by velocity monomials, nothing simplified) and only the m
 * projections are simplified: simplifying the n rows first costs more than
 * it saves in the projections (7 to 11% of the whole derivation on the
 * rolling disk and the bicycle, by instruction counts).
 */
#include "spd.h"

#include "../base/mem.h"

/* M_u = W^T M W, entry (r, s), simplified. */
static const qd_expr *mass(qd__spd *d, const qd_expr *const *M, size_t r, size_t s) {
    qd_ctx *ctx = d->ctx;
    const qd_speeds_eom *e = d->e;
    size_t n = d->n, m = d->m;
    const qd_expr *x = qd_int(ctx, 0);
    for (size_t j = 0; j < n; j++) {
        const qd_expr *Wjr = e->W[j * m + r];
        if (qd_is_zero(Wjr))
            continue;
        for (size_t k = 0; k < n; k++)
            if (!qd_is_zero(M[j * n + k]) && !qd_is_zero(e->W[k * m + s]))
                x = qd_add(ctx, x, qd_mul(ctx, Wjr, qd_mul(ctx, M[j * n + k], e->W[k * m + s])));
    }
    return qd_simplify(ctx, x);
}

qd_status qd__spd_kane(qd__spd *d) {
    qd_ctx *ctx = d->ctx;
    qd_speeds_eom *e = d->e;
    qd_eom *sh = d->shell;
    size_t n = d->n, m = d->m;
    qd_status st = qd__eom_rows(ctx, sh, &d->sys, d->L, true);
    const qd_expr **buf = qd__calloc(ctx, n * n + 2 * n + m + 1, sizeof *buf);
    if (st != QD_OK || !buf) {
        qd__free(buf);
        return st != QD_OK ? st : QD_ERR_NOMEM;
    }
    const qd_expr **M = buf, **g = M + n * n, **a0 = g + n, **zero = a0 + n;
    for (size_t r = 0; r < m; r++)
        zero[r] = qd_int(ctx, 0);
    for (size_t j = 0; j < n; j++)
        a0[j] = qd_subs(ctx, d->acc[j], m, e->ud, zero);
    for (size_t i = 0; i < n * n; i++)
        M[i] = qd__spd_on_motion(d, sh->M[i]);
    /* g = f - M a0, what is left when every u' is 0; simplified only once
     * projected (simplifying each g_j first costs more than it saves) */
    for (size_t j = 0; j < n; j++) {
        const qd_expr *x = qd__spd_on_motion(d, sh->f[j]);
        for (size_t k = 0; k < n; k++)
            if (!qd_is_zero(M[j * n + k]) && !qd_is_zero(a0[k]))
                x = qd_sub(ctx, x, qd_mul(ctx, M[j * n + k], a0[k]));
        if (!(g[j] = x))
            st = qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    }
    /* M is symmetric unless D or Q bring accelerations: then so is W^T M W */
    bool sym = true;
    for (size_t j = 0; j < n; j++)
        for (size_t k = 0; k < j; k++)
            sym = sym && sh->M[j * n + k] == sh->M[k * n + j];
    for (size_t r = 0; st == QD_OK && r < m; r++) {
        for (size_t s = 0; s < m && st == QD_OK; s++)
            if (!(e->M[r * m + s] = sym && s < r ? e->M[s * m + r] : mass(d, M, r, s)))
                st = qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
        const qd_expr *x = qd_int(ctx, 0);
        for (size_t j = 0; j < n; j++)
            if (!qd_is_zero(e->W[j * m + r]) && !qd_is_zero(g[j]))
                x = qd_add(ctx, x, qd_mul(ctx, e->W[j * m + r], g[j]));
        if (st == QD_OK && !(e->f[r] = qd__spd_tidy(d, x)))
            st = qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    }
    qd__free(buf);
    return st;
}
