/*
 * src/speeds/kane.c - Kane's equations in Lagrange's form: the residual of
 * Lagrange's equation of each coordinate, on the motion (q' and q'' in
 * speeds), projected on the partial velocities W_jr = dq'_j/du_r:
 *
 *     sum_j W_jr E_j = 0,    r = 1..m.
 *
 * The constraint forces A^T lambda are normal to every column of W (C W = 0
 * by construction), so the projection drops them: Kane's generalized
 * active plus inertia forces, F_r + F*_r = 0 (Kane and Levinson, Dynamics:
 * Theory and Applications, 1985, sec. 6.1 and 6.3, where F*_r is written
 * with T exactly so).  The default method: it shares Lagrange's machinery
 * and its simplifications (L grouped by velocity monomials).
 */
#include "spd.h"

#include "../base/mem.h"

qd_status qd__spd_kane(qd__spd *d) {
    qd_ctx *ctx = d->ctx;
    qd_speeds_eom *e = d->e;
    size_t n = d->n, m = d->m;
    const qd_expr **E = qd__calloc(ctx, n + m + 1, sizeof *E), **rows = E + n;
    if (!E)
        return QD_ERR_NOMEM;
    qd_status st = QD_OK;
    for (size_t j = 0; st == QD_OK && j < n; j++)
        if (!(E[j] = qd__spd_residual(d, j)))
            st = qd_ctx_status(ctx);
    for (size_t r = 0; st == QD_OK && r < m; r++) {
        const qd_expr *x = qd_int(ctx, 0);
        for (size_t j = 0; j < n; j++)
            if (!qd_is_zero(e->W[j * m + r]))
                x = qd_add(ctx, x, qd_mul(ctx, e->W[j * m + r], E[j]));
        if (!(rows[r] = x))
            st = qd_ctx_status(ctx);
    }
    if (st == QD_OK)
        st = qd__spd_rows(d, rows);
    qd__free(E);
    return st;
}
