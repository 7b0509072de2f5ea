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
 * exactly so).  The default method: projecting the already simplified M
 * and f keeps the expressions to simplify small, so it costs little more
 * than Lagrange's equations themselves.
 */
#include "spd.h"

#include "../base/mem.h"

qd_status qd__spd_kane(qd__spd *d) {
    qd_ctx *ctx = d->ctx;
    qd_speeds_eom *e = d->e;
    qd_eom *sh = d->shell;
    size_t n = d->n, m = d->m;
    qd_status st = qd__eom_rows(ctx, sh, &d->sys, d->L);
    const qd_expr **buf = qd__calloc(ctx, n * n + 2 * n + m + 1, sizeof *buf);
    if (st != QD_OK || !buf) {
        qd__free(buf);
        return st != QD_OK ? st : QD_ERR_NOMEM;
    }
    const qd_expr **M = buf, **g = M + n * n, **a0 = g + n, **rows = a0 + n;
    const qd_expr **zero = rows; /* u' = 0, borrowed before rows are made */
    for (size_t r = 0; r < m; r++)
        zero[r] = qd_int(ctx, 0);
    for (size_t j = 0; j < n; j++)
        a0[j] = qd_subs(ctx, d->acc[j], m, e->ud, zero);
    for (size_t i = 0; i < n * n; i++)
        M[i] = qd__spd_on_motion(d, sh->M[i]);
    /* g = f - M a0: what is left when every u' is 0 */
    for (size_t j = 0; j < n; j++) {
        const qd_expr *x = qd__spd_on_motion(d, sh->f[j]);
        for (size_t k = 0; k < n; k++)
            if (!qd_is_zero(M[j * n + k]) && !qd_is_zero(a0[k]))
                x = qd_sub(ctx, x, qd_mul(ctx, M[j * n + k], a0[k]));
        g[j] = x;
    }
    for (size_t r = 0; r < m; r++) {
        const qd_expr *x = qd_int(ctx, 0);
        for (size_t j = 0; j < n; j++) {
            const qd_expr *Wjr = e->W[j * m + r];
            if (qd_is_zero(Wjr))
                continue;
            /* (M W u')_j - g_j */
            const qd_expr *Mj = qd_neg(ctx, g[j]);
            for (size_t k = 0; k < n; k++)
                for (size_t s = 0; s < m; s++)
                    if (!qd_is_zero(M[j * n + k]) && !qd_is_zero(e->W[k * m + s]))
                        Mj = qd_add(ctx, Mj, qd_mul(ctx, qd_mul(ctx, M[j * n + k], e->W[k * m + s]),
                                                    e->ud[s]));
            x = qd_add(ctx, x, qd_mul(ctx, Wjr, Mj));
        }
        rows[r] = x;
    }
    for (size_t r = 0; r < m; r++)
        if (!rows[r]) {
            qd__free(buf);
            return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
        }
    st = qd__spd_rows(d, rows);
    qd__free(buf);
    return st;
}
