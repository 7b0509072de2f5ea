/*
 * src/action/state.c - the state `qdot action --at` takes the actions at
 * (qd_action_state_read, qdot/action.h), for the command line and Python's
 * Model.action alike.
 */
#include "qdot/action.h"
#include "qdot/state.h"
#include "../base/args.h"
#include "../base/mem.h"

#include <string.h>

/* The momenta at's text named, kept after slot first; the others dropped
 * (qd_action_at then takes them from the velocities). */
static void keep_given(qd_state *st, size_t first, const bool *given) {
    size_t kept = first;
    for (size_t k = first; k < st->n; k++)
        if (given && given[k]) {
            st->syms[kept] = st->syms[k];
            st->vals[kept++] = st->vals[k];
        }
    st->n = kept;
}

qd_status qd_action_state_read(qd_ctx *ctx, const qd_model *m, const char *at, qd_state *st) {
    QD_ARGS_CTX(ctx, ctx && m && st);
    memset(st, 0, sizeof *st);
    size_t nq = qd_model_ncoords(m);
    qd_status s = qd_state_init(ctx, m, st);
    if (s == QD_OK)
        s = qd_state_initial(ctx, m, st);
    size_t first = st->n;
    for (size_t j = 0; s == QD_OK && qd_model_hamiltonian_given(m) && j < nq; j++) {
        const qd_expr *p = qd_model_momentum(m, j);
        if (p)
            s = qd_state_append(ctx, st, 1, &p, NULL);
    }
    bool *given = NULL;
    if (s == QD_OK && at && !(given = qd__calloc(ctx, st->n + 1, sizeof *given)))
        s = QD_ERR_NOMEM;
    qd_state_read_opts o = {.given = given};
    if (s == QD_OK && at)
        s = qd_state_read(ctx, m, st, at, &o);
    if (s == QD_OK)
        keep_given(st, first, given);
    qd__free(given);
    return s;
}
