/*
 * src/linear/modes_from.c - the modes of `qdot modes` from its options'
 * text (qdot/modes.h): the point from --about or the library's choice, and
 * the motion from --initial in the normal coordinates.  The text is read
 * against the equations' coordinates (qdot/linpoint.h).
 */
#include "qdot/linpoint.h"
#include "qdot/modes.h"

#include <string.h>

#include "../base/args.h"
#include "../base/mem.h"

qd_status qd_modes_at_choose(qd_ctx *ctx, const qd_linpoint *p, const char *about,
                             size_t at_equilibrium, qd_modes_at *out) {
    QD_ARGS_CTX(ctx, ctx && p && p->slot && out);
    memset(out, 0, sizeof *out);
    double *given = NULL;
    qd_status st = QD_OK;
    if (about && !(given = qd__calloc(ctx, p->e->n + 1, sizeof *given)))
        return QD_ERR_NOMEM;
    if (about)
        st = qd_linpoint_read_coords(ctx, p, about, given);
    if (st == QD_OK)
        st = qd_modes_at_point(ctx, p->e, p->m, p->st.n, p->st.syms, p->st.vals, given,
                               at_equilibrium, out);
    qd__free(given);
    return st;
}

qd_status qd_modes_at_initial(qd_ctx *ctx, const qd_linpoint *p, const qd_modes_at *at,
                              const char *text, double *Q, double *Qd) {
    QD_ARGS_CTX(ctx, ctx && p && at && at->q0 && text && Q && Qd);
    if (!at->res.conservative) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the motion through normal coordinates needs a "
                                      "conservative system without gyroscopic terms");
        return QD_ERR_ARG;
    }
    size_t n = p->e->n;
    double *q = qd__calloc(ctx, n + 1, sizeof *q), *qd = qd__calloc(ctx, n + 1, sizeof *qd);
    qd_status st = q && qd ? QD_OK : QD_ERR_NOMEM;
    if (st == QD_OK) {
        memcpy(q, at->q0, n * sizeof *q);
        st = qd_linpoint_read(ctx, p, text, q, qd);
    }
    if (st == QD_OK)
        st = qd_modes_normal_coords(&at->lin, &at->res, at->q0, q, qd, Q, Qd);
    qd__free(q);
    qd__free(qd);
    return st;
}
