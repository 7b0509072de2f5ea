/*
 * src/linear/rest_residual.c - how far a point at rest is from an
 * equilibrium: the largest generalized force there (qdot/equilibria.h).
 *
 * Allocations (for the context allocator): qd_eom_rest_residual (calloc x2),
 * freed before return.
 */
#include "qdot/equilibria.h"
#include "base/mem.h"
#include "../base/args.h"

#include <math.h>
#include <stdlib.h>

qd_status qd_eom_rest_residual(qd_ctx *ctx, const qd_eom *e, size_t nvals,
                               const qd_expr *const *syms, const double *vals, double *res) {
    QD_ARGS_CTX(ctx, ctx && e && (nvals == 0 || syms) && (nvals == 0 || vals) && res);
    size_t n = e->n;
    /* M is wanted too: qd_eom_eval fills f beside it */
    double *f = qd__calloc(ctx, n + 1, sizeof *f), *M = qd__calloc(ctx, n * n + 1, sizeof *M);
    qd_status st = f && M ? qd_eom_eval(ctx, e, nvals, syms, vals, M, f, NULL, NULL, NULL)
                          : QD_ERR_NOMEM;
    *res = 0;
    for (size_t j = 0; st == QD_OK && j < n; j++)
        *res = fmax(*res, fabs(f[j]));
    qd__free(f);
    qd__free(M);
    return st;
}
