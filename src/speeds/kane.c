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
 * exactly so).  The default method.  Lagrange's rows are taken raw
 * (nothing simplified) and only the m projections are tidied: expanded,
 * grouped by monomials in u, each group's coefficient through the
 * trigonometric identities and common factors (qd__spd_tidy).  Neither the
 * n rows nor the finished entries get the whole simplifier: on the rolling
 * disk and the bicycle that costs more than the rest of the derivation
 * (instruction counts) and only regroups what the tidy leaves.
 */
#include "spd.h"

#include "../base/mem.h"

static qd_status failed(qd_ctx *ctx) {
    return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
}

/* sum_k x_k y_k over the pairs with neither factor 0; strides sx, sy. */
static const qd_expr *dot(qd_ctx *ctx, size_t n, const qd_expr *const *x, size_t sx,
                          const qd_expr *const *y, size_t sy) {
    const qd_expr *s = qd_int(ctx, 0);
    for (size_t k = 0; s && k < n; k++)
        if (!qd_is_zero(x[k * sx]) && !qd_is_zero(y[k * sy]))
            s = qd_add(ctx, s, qd_mul(ctx, x[k * sx], y[k * sy]));
    return s;
}

qd_status qd__spd_kane(qd__spd *d) {
    qd_ctx *ctx = d->ctx;
    qd_speeds_eom *e = d->e;
    qd_eom *sh = d->shell;
    size_t n = d->n, m = d->m;
    qd_status st = qd__mech_eom_rows(ctx, sh, &d->sys, d->L, true);
    const qd_expr **buf = qd__calloc(ctx, n * n + n * m + 2 * n + m + 1, sizeof *buf);
    if (st != QD_OK || !buf) {
        qd__free(buf);
        return st != QD_OK ? st : QD_ERR_NOMEM;
    }
    /* M and f on the motion, a0 the accelerations at u' = 0, MTW = M^T W:
     * both projections go through MTW, (W^T M W)_rs = sum_k MTW_kr W_ks and
     * (W^T M a0)_r = sum_k MTW_kr a0_k, which costs n m products per entry
     * where M a0 first would cost n^2 */
    const qd_expr **M = buf, **f = M + n * n, **a0 = f + n, **zero = a0 + n, **MTW = zero + m;
    for (size_t r = 0; r < m; r++)
        zero[r] = qd_int(ctx, 0);
    for (size_t j = 0; j < n; j++) {
        a0[j] = qd_subs(ctx, d->acc[j], m, e->ud, zero);
        f[j] = qd__spd_on_motion(d, sh->f[j]);
    }
    for (size_t i = 0; i < n * n; i++)
        M[i] = qd_is_zero(sh->M[i]) ? sh->M[i] : qd__spd_on_motion(d, sh->M[i]);
    for (size_t k = 0; st == QD_OK && k < n; k++)
        for (size_t r = 0; r < m; r++)
            if (!(MTW[k * m + r] = dot(ctx, n, M + k, n, e->W + r, m)))
                st = failed(ctx);
    /* M is symmetric unless D or Q bring accelerations: then so is W^T M W */
    bool sym = true;
    for (size_t j = 0; j < n; j++)
        for (size_t k = 0; k < j; k++)
            sym = sym && sh->M[j * n + k] == sh->M[k * n + j];
    /* each entry tidied only once assembled: tidying the n rows first costs
     * more than it saves in the projections */
    for (size_t r = 0; st == QD_OK && r < m; r++) {
        for (size_t s = 0; s < m && st == QD_OK; s++)
            if (!(e->M[r * m + s] = sym && s < r ? e->M[s * m + r]
                                                 : qd__spd_tidy(d, dot(ctx, n, MTW + r, m,
                                                                       e->W + s, m))))
                st = failed(ctx);
        const qd_expr *x = qd_sub(ctx, dot(ctx, n, e->W + r, m, f, 1),
                                  dot(ctx, n, MTW + r, m, a0, 1));
        if (st == QD_OK && !(e->f[r] = qd__spd_tidy(d, x)))
            st = failed(ctx);
    }
    qd__free(buf);
    return st;
}
