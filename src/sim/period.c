/*
 * src/sim/period.c - a run over one period T given as text (qdot/simsetup.h):
 * t_end = t0 + T, what `qdot simulate --period T` (the monodromy matrix with
 * --variational) runs.
 */
#include <math.h>
#include <string.h>

#include "../base/args.h"
#include "qdot/state.h"
#include "setup.h"

qd_status qd_sim_setup_period(qd_sim_setup *s, const char *text, qd_sim_opts *out,
                              double *period) {
    QD_ARGS(QD_ERR_ARG, s);
    QD_ARGS_CTX(s->ctx, text && out && period);
    const qd_expr *exact;
    double T;
    size_t len = strlen(text);
    qd_status st = qd_state_value(s->ctx, s->m, text, 0, len, &exact, &T);
    if (st == QD_OK && !(T > 0)) {
        qd_ctx_error(s->ctx, QD_ERR_ARG, "a period is a positive time, not %.17g", T);
        qd_ctx_error_at(s->ctx, text, 0, len ? len : 1);
        st = QD_ERR_ARG;
    }
    if (st == QD_OK && !isfinite(out->t0 + T)) {
        qd_ctx_error(s->ctx, QD_ERR_ARG, "t0 + T is not a finite time");
        qd_ctx_error_at(s->ctx, text, 0, len ? len : 1);
        st = QD_ERR_ARG;
    }
    if (st != QD_OK)
        return st;
    out->t_end = out->t0 + T;
    *period = T;
    return QD_OK;
}
