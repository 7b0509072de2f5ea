/*
 * src/linear/constrained_at.c - the analysis on the constraint manifold at
 * one point (qd_constrained_at_solve, qdot/constrained.h): the reduction,
 * its modes and the state-space form, as `qdot modes` and `qdot linearize`
 * take them.
 */
#include "qdot/constrained.h"

#include <string.h>

#include "../base/args.h"
#include "../base/mem.h"

/* A and B of the reduction a->c with m's inputs. */
static qd_status statespace(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t nvals,
                            const qd_expr *const *syms, const double *vals,
                            qd_constrained_at *a) {
    size_t r = a->c.r, nu = a->nu = qd_model_ninputs(m);
    a->A = qd__calloc(ctx, 4 * r * r + 1, sizeof *a->A);
    a->B = qd__calloc(ctx, 2 * r * nu + 1, sizeof *a->B);
    a->u = qd__calloc(ctx, nu + 1, sizeof *a->u);
    if (!a->A || !a->B || !a->u)
        return QD_ERR_NOMEM;
    for (size_t k = 0; k < nu; k++)
        a->u[k] = qd_model_input(m, k);
    qd_status st = qd_constrained_state_matrix(ctx, &a->c, a->A);
    if (st == QD_OK)
        st = qd_constrained_input_matrix(ctx, e, &a->c, nu, a->u, nvals, syms, vals, a->B);
    return st;
}

qd_status qd_constrained_at_solve(qd_ctx *ctx, const qd_eom *e, const qd_model *m,
                                  size_t nvals, const qd_expr *const *syms, const double *vals,
                                  const size_t *indep, bool ss, qd_constrained_at *out) {
    QD_ARGS_CTX(ctx, ctx && e && m && (nvals == 0 || (syms && vals)) && out);
    memset(out, 0, sizeof *out);
    qd_status st = qd_constrained_linear_about(ctx, e, nvals, syms, vals, indep, &out->c);
    if (st != QD_OK)
        return st;
    if (ss && (st = statespace(ctx, e, m, nvals, syms, vals, out)) != QD_OK)
        return st;
    return qd_modes_solve(ctx, &out->c.lin, &out->res);
}

void qd_constrained_at_free(qd_constrained_at *a) {
    if (!a)
        return;
    qd_constrained_linear_free(&a->c);
    qd_modes_result_free(&a->res);
    qd__free(a->u);
    qd__free(a->A);
    qd__free(a->B);
    memset(a, 0, sizeof *a);
}
