/*
 * src/linear/speeds_choose.c - the state a model in generalized speeds is
 * linearized about when the caller names none (qd_speeds_equilibria_choose,
 * qdot/equilibria.h): the first equilibrium listed, at rest.
 */
#include "qdot/equilibria.h"
#include "qdot/speeds.h"
#include "../base/args.h"

/* The slot of x in syms, or nvals. */
static size_t slot_of(size_t nvals, const qd_expr *const *syms, const qd_expr *x) {
    size_t k = 0;
    while (k < nvals && syms[k] != x)
        k++;
    return k;
}

qd_status qd_speeds_equilibria_choose(qd_ctx *ctx, const struct qd_speeds_eom *e,
                                      const qd_model *m, size_t nvals,
                                      const qd_expr *const *syms, double *vals, bool *found) {
    QD_ARGS_CTX(ctx, ctx && e && m && (nvals == 0 || syms) && (nvals == 0 || vals) && found);
    *found = false;
    qd_speeds_equilibria s;
    qd_status st = qd_speeds_equilibria_find(ctx, e, m, nvals, syms, vals, NULL, &s);
    if (st == QD_OK && s.eq.count > 0) {
        *found = true;
        for (size_t j = 0; j < s.nsolved; j++) {
            size_t k = slot_of(nvals, syms, e->q[s.solved[j]]);
            if (k < nvals)
                vals[k] = s.eq.pts[0].q[j];
        }
        for (size_t r = 0; r < e->m; r++) { /* at rest */
            size_t k = slot_of(nvals, syms, e->u[r]);
            if (k < nvals)
                vals[k] = 0;
        }
    }
    qd_speeds_equilibria_free(&s);
    return st;
}
