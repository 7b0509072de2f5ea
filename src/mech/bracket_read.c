/*
 * src/mech/bracket_read.c - a bracket's operand read from text, where the
 * name H stands for the model's Hamiltonian (audit, issue 33: `qdot bracket
 * FILE F H` said "unknown name 'H'" even in a model given by H = ...).
 */
#include <stdbool.h>
#include "qdot/canonical.h"
#include "../base/args.h"

/* Is s one of the model's own names (a coordinate, a momentum or a
 * parameter)?  Such an H keeps its meaning in the model. */
static bool br_model_name(const qd_phase *ph, const qd_expr *s) {
    for (size_t j = 0; j < ph->n; j++)
        if (ph->q[j] == s || ph->p[j] == s)
            return true;
    for (size_t i = 0; i < qd_model_nparams(ph->m); i++)
        if (qd_model_param(ph->m, i) == s)
            return true;
    return false;
}

const qd_expr *qd_phase_read_h(qd_ctx *ctx, qd_phase *ph, const char *text, qd_diag *err) {
    QD_ARGS(NULL, ctx && ph && text && err);
    const qd_expr *h = qd_lookup(ctx, "H");
    if (h && br_model_name(ph, h))
        return qd_phase_read(ctx, ph, text, err);
    /* make the name known to the reader, then put H itself in its place */
    if (!h && !(h = qd_symbol(ctx, "H"))) {
        *err = *qd_ctx_diag(ctx);
        return NULL;
    }
    const qd_expr *x = qd_phase_read(ctx, ph, text, err);
    if (!x || !qd_has(x, h))
        return x;
    if (qd_phase_ham(ctx, ph, true) != QD_OK ||
        !(x = qd_simplify(ctx, qd_subs(ctx, x, 1, &h, &ph->h->H)))) {
        *err = *qd_ctx_diag(ctx);
        return NULL;
    }
    return x;
}
