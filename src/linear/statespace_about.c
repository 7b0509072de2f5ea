/*
 * src/linear/statespace_about.c - the operating point of the state-space
 * form read from text (qd_linearize_about, qdot/statespace.h): the model's
 * state with its inputs appended, each value named kept as the exact
 * expression read, so that qd_linearize evaluates at pi/6, not 0.5236.
 */
#include "qdot/statespace.h"

#include <string.h>

#include "qdot/state.h"
#include "../base/args.h"
#include "../base/mem.h"

qd_status qd_linearize_about(qd_ctx *ctx, const qd_eom *e, const qd_model *m,
                             const char *about, qd_statespace *out) {
    QD_ARGS_CTX(ctx, ctx && e && m && out);
    memset(out, 0, sizeof *out); /* freeable after a reader's error */
    if (!about)
        return qd_linearize(ctx, e, m, 0, NULL, NULL, out);
    qd_state st = {0};
    qd_status rc = qd_state_init(ctx, m, &st);
    for (size_t i = 0; rc == QD_OK && i < qd_model_ninputs(m); i++) {
        const qd_expr *u = qd_model_input(m, i);
        rc = qd_state_append(ctx, &st, 1, &u, NULL);
    }
    const qd_expr **exact = rc == QD_OK ? qd__calloc(ctx, st.n + 1, sizeof *exact) : NULL;
    const qd_expr **syms = rc == QD_OK ? qd__calloc(ctx, st.n + 1, sizeof *syms) : NULL;
    const qd_expr **vals = rc == QD_OK ? qd__calloc(ctx, st.n + 1, sizeof *vals) : NULL;
    if (rc == QD_OK && (!exact || !syms || !vals))
        rc = QD_ERR_NOMEM;
    qd_state_read_opts o = {.exact = exact};
    if (rc == QD_OK)
        rc = qd_state_read(ctx, m, &st, about, &o);
    size_t n = 0;
    for (size_t k = 0; rc == QD_OK && k < st.n; k++)
        if (exact[k]) {
            syms[n] = st.syms[k];
            vals[n++] = exact[k];
        }
    if (rc == QD_OK)
        rc = qd_linearize(ctx, e, m, n, syms, vals, out);
    qd__free(exact);
    qd__free(syms);
    qd__free(vals);
    qd_state_free(&st);
    return rc;
}
