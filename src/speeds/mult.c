/*
 * src/speeds/mult.c - the constraint forces the speeds leave out.
 *
 * Lagrange's residual on the motion, E = M q'' - f, is the generalized
 * constraint force C^T lambda (qd_eom's sign: M q'' = f + A^T lambda).
 * The constraints' columns Wc of P^-1 satisfy C Wc = I, so
 * lambda = Wc^T E exactly, with no solve: each multiplier is a sum over
 * the coordinates, in q, u, u' and t (u' from M_u u' = f_u when numbers
 * are wanted: qd_speeds_eval).
 */
#include "spd.h"

#include "../base/mem.h"

qd_status qd__spd_multipliers(qd__spd *d) {
    qd_ctx *ctx = d->ctx;
    qd_speeds_eom *e = d->e;
    size_t n = d->n, m = d->m, nc = d->nc;
    const qd_expr **E = qd__calloc(ctx, n + 1, sizeof *E);
    e->mult = qd__calloc(ctx, nc + 1, sizeof *e->mult);
    if (!E || !e->mult) {
        qd__free(E);
        return QD_ERR_NOMEM;
    }
    qd_status st = QD_OK;
    for (size_t j = 0; st == QD_OK && j < n; j++)
        if (!(E[j] = qd__spd_residual(d, j)))
            st = qd_ctx_status(ctx);
    for (size_t k = 0; st == QD_OK && k < nc; k++) {
        const qd_expr *x = qd_int(ctx, 0);
        for (size_t j = 0; j < n; j++) {
            const qd_expr *c = d->Pinv[j * n + m + k];
            if (!qd_is_zero(c))
                x = qd_add(ctx, x, qd_mul(ctx, c, E[j]));
        }
        if (!(e->mult[k] = qd__spd_tidy(d, x)))
            st = qd_ctx_status(ctx);
    }
    qd__free(E);
    return st;
}
