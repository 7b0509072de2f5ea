/*
 * src/linear/equilibria_print.c - an equilibrium's coordinate as text
 * (qd_equilibrium_put_value) and the sentence of an automatic choice
 * (qd_eq_chosen_name), qdot/equilibria.h: what `qdot equilibria` and
 * `qdot modes` print of a point, for any caller.
 */
#include "qdot/equilibria.h"
#include "qdot/print.h"
#include "../base/args.h"

const char *qd_eq_chosen_name(qd_eq_chosen c) {
    switch (c) {
    case QD_EQ_CHOSEN_NEAREST_MINIMUM:
        return "the minimum of the potential nearest the model's initial state";
    case QD_EQ_CHOSEN_LOWEST_MINIMUM:
        return "the minimum of the potential with the lowest V";
    case QD_EQ_CHOSEN_NEWTON_FROM_INITIAL:
        return "no minimum of the potential was found: the equilibrium reached by Newton's "
               "method from the model's initial state";
    default:
        return "no minimum of the potential was found: the first equilibrium listed";
    }
}

qd_status qd_equilibrium_put_value(qd_ctx *ctx, const qd_equilibrium *p, size_t j,
                                   qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && p && p->q && out);
    if (p->exact && p->exact[j])
        return qd_print(ctx, p->exact[j], QD_FMT_TEXT, out);
    qd_buf_put_result(out, p->q[j], 1);
    if (out->failed) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        return QD_ERR_NOMEM;
    }
    return QD_OK;
}
