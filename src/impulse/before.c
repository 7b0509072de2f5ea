/*
 * src/impulse/before.c - the state just before an impulse as `qdot impulse
 * --at` and Python's Model.impulse(at=...) give it (qd_impulse_state_read):
 * the model's `initial` as written, kept exact (al = pi/6 stays pi/6, so
 * sin(al) is 1/2 in the closed forms), overridden by the items given.
 */
#include "qdot/impulse.h"

#include <stdlib.h>

#include "qdot/state.h"
#include "../base/args.h"

qd_status qd_impulse_state_read(qd_ctx *ctx, const qd_model *m, const char *at,
                                const qd_expr **q, const qd_expr **qd, const qd_expr **t) {
    QD_ARGS_CTX(ctx, ctx && m && q && qd && t);
    size_t n = qd_model_ncoords(m);
    const qd_expr *zero = qd_int(ctx, 0);
    if (!zero)
        return qd_ctx_status(ctx);
    for (size_t j = 0; j < n; j++) {
        const qd_expr *x = qd_model_initial_definition(m, j, 0);
        const qd_expr *v = qd_model_initial_definition(m, j, 1);
        q[j] = x ? x : zero;
        qd[j] = v ? v : zero;
    }
    *t = NULL;
    if (!at)
        return QD_OK;
    qd_state st = {0};
    qd_status s = qd_state_init(ctx, m, &st);
    const qd_expr **exact = s == QD_OK ? calloc(st.n, sizeof *exact) : NULL;
    if (s == QD_OK && !exact) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory reading the state before an impulse");
        s = QD_ERR_NOMEM;
    }
    qd_state_read_opts o = {.refuse = QD_STATE_PARAMS, .exact = exact};
    if (s == QD_OK)
        s = qd_state_read(ctx, m, &st, at, &o);
    for (size_t j = 0; s == QD_OK && j < n; j++) {
        if (exact[qd_slot_coord(n, j)])
            q[j] = exact[qd_slot_coord(n, j)];
        if (exact[qd_slot_velocity(n, j)])
            qd[j] = exact[qd_slot_velocity(n, j)];
    }
    if (s == QD_OK)
        *t = exact[qd_slot_time(n)];
    free(exact);
    qd_state_free(&st);
    return s;
}
