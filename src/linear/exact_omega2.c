/*
 * src/linear/exact_omega2.c - w^2 as an exact expression about an exact
 * equilibrium of one or two degrees of freedom (qdot/modes.h).
 *
 * Exact in the parameters only when the equilibrium does not move with
 * their values (qd_equilibrium_exact_in_parameters); otherwise the formula
 * would mix a point computed at g = 9.81 with a symbolic g, so the
 * parameters are put in as their exact values and w^2 is an exact number.
 *
 * Allocations (for the context allocator): at_values (calloc x2), freed
 * before return.
 */
#include "qdot/equilibria.h"
#include "qdot/modes.h"
#include "base/mem.h"
#include "../base/args.h"

#include <stdlib.h>

/* w2 with every parameter at its exact value, simplified. */
static const qd_expr *at_values(qd_ctx *ctx, const qd_model *m, const qd_expr *w2) {
    size_t np = qd_model_nparams(m);
    const qd_expr **from = qd__calloc(ctx, np + 1, sizeof *from), **to = qd__calloc(ctx, np + 1, sizeof *to);
    const qd_expr *out = NULL;
    bool ok = from && to;
    for (size_t i = 0; ok && i < np; i++) {
        from[i] = qd_model_param(m, i);
        ok = (to[i] = qd_model_param_value(m, i)) != NULL;
    }
    if (ok)
        out = qd_simplify(ctx, qd_subs(ctx, w2, np, from, to));
    qd__free(from);
    qd__free(to);
    return out;
}

qd_status qd_modes_exact_omega2(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t nvals,
                                const qd_expr *const *syms, const double *vals,
                                const qd_expr *const *q0, const qd_expr **w2, bool *in_params) {
    QD_ARGS_CTX(ctx, ctx && e && m && (nvals == 0 || syms) && (nvals == 0 || vals) && q0 && w2 && in_params);
    size_t n = e->n;
    const qd_expr *K[4], *M[4];
    *in_params = false;
    if (n < 1 || n > 2 || !q0) {
        qd_ctx_error(ctx, QD_ERR_ARG, "exact w^2 needs an exact point of 1 or 2 coordinates");
        return QD_ERR_ARG;
    }
    qd_status st = qd_linear_symbolic(ctx, e, q0, K, M);
    if (st == QD_OK)
        st = qd_modes_symbolic_omega2(ctx, n, K, M, w2);
    if (st != QD_OK)
        return st;
    *in_params = qd_equilibrium_exact_in_parameters(ctx, e, m, nvals, syms, vals, q0);
    for (size_t j = 0; !*in_params && j < n; j++)
        if (!(w2[j] = at_values(ctx, m, w2[j])))
            return qd_ctx_status(ctx) ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    return QD_OK;
}
