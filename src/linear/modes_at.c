/*
 * src/linear/modes_at.c - the point small oscillations are taken about
 * and the modes there, as `qdot modes` and Python's Model.modes take them
 * (qdot/modes.h, qd_modes_at): a point given, equilibrium N of the list, or
 * the library's choice (qd_equilibria_choose).
 */
#include "qdot/modes.h"

#include <string.h>

#include "base/args.h"
#include "base/mem.h"

qd_status qd_modes_at_point(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t nvals,
                            const qd_expr *const *syms, const double *vals,
                            const double *given, size_t at_equilibrium, qd_modes_at *out) {
    QD_ARGS_CTX(ctx, ctx && e && m && (nvals == 0 || (syms && vals)) && out);
    memset(out, 0, sizeof *out);
    size_t n = e->n;
    if (!(out->q0 = qd__calloc(ctx, n + 1, sizeof *out->q0)))
        return QD_ERR_NOMEM;
    if (given) {
        memcpy(out->q0, given, n * sizeof *out->q0);
        return QD_OK;
    }
    qd_equilibria *found = &out->choice.found;
    qd_status st = at_equilibrium
                       ? qd_equilibria_find(ctx, e, m, nvals, syms, vals, NULL, found)
                       : qd_equilibria_choose(ctx, e, m, nvals, syms, vals, &out->choice);
    if (st != QD_OK)
        return st;
    if (at_equilibrium > found->count && found->count > 0) {
        qd_ctx_error(ctx, QD_ERR_ARG, "there %s %zu equilibri%s", found->count == 1 ? "is" : "are",
                     found->count, found->count == 1 ? "um" : "a");
        return QD_ERR_ARG;
    }
    out->pt = at_equilibrium ? (found->count ? &found->pts[at_equilibrium - 1] : NULL)
                             : out->choice.pt;
    if (!out->pt) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "no equilibrium found");
        return QD_ERR_NUMERIC;
    }
    out->chosen = !at_equilibrium;
    memcpy(out->q0, out->pt->q, n * sizeof *out->q0);
    return QD_OK;
}

qd_status qd_modes_at_solve(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t nvals,
                            const qd_expr *const *syms, const double *vals, qd_modes_at *at) {
    QD_ARGS_CTX(ctx, ctx && e && m && (nvals == 0 || (syms && vals)) && at && at->q0);
    size_t n = e->n;
    double *v = qd__malloc(ctx, (nvals + 1) * sizeof *v);
    if (!v)
        return QD_ERR_NOMEM;
    memcpy(v, vals, nvals * sizeof *v);
    /* the point's coordinates, at rest */
    for (size_t j = 0; j < n; j++) {
        const qd_expr *qd = qd_jet(ctx, e->q[j], 1);
        for (size_t i = 0; i < nvals; i++)
            if (syms[i] == e->q[j])
                v[i] = at->q0[j];
            else if (syms[i] == qd)
                v[i] = 0;
    }
    if (qd_eom_rest_residual(ctx, e, nvals, syms, v, &at->residual) != QD_OK)
        qd_ctx_clear_error(ctx); /* the residual is a note, not the answer */
    qd_status st = qd_linear_about(ctx, e, m, nvals, syms, v, &at->lin);
    if (st == QD_OK)
        st = qd_modes_solve(ctx, &at->lin, &at->res);
    if (st == QD_OK && at->pt && at->pt->exact && n <= 2 && at->res.conservative) {
        at->have_exact = qd_modes_exact_omega2(ctx, e, m, nvals, syms, v, at->pt->exact,
                                               at->w2exact, &at->exact_in_params) == QD_OK;
        qd_ctx_clear_error(ctx); /* no exact w^2: the numbers stand alone */
    }
    qd__free(v);
    return st;
}

void qd_modes_at_free(qd_modes_at *at) {
    if (!at)
        return;
    qd__free(at->q0);
    qd_linear_free(&at->lin);
    qd_modes_result_free(&at->res);
    qd_equilibrium_choice_free(&at->choice);
    memset(at, 0, sizeof *at);
}
