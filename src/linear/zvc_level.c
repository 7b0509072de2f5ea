/*
 * src/linear/zvc_level.c - the level of the zero-velocity curves as `qdot
 * zvc` takes it (qd_zvc_level_read, qdot/zvc.h): --level H, or Jacobi's
 * integral at a point at rest (--through, W there) or at a state (--at, h
 * there).  The command line and Python's Model.zvc both call it.
 */
#include "qdot/zvc.h"
#include "qdot/linpoint.h"
#include "../base/args.h"
#include "../base/mem.h"

#include <math.h>
#include <string.h>

/* h (or W, at rest) at the point or state given by text. */
static qd_status level_at(qd_ctx *ctx, qd_linpoint *p, const qd_zvc *z, const char *what,
                          const char *text, bool rest, double *q, double *h) {
    size_t n = p->e->n;
    double *qd = qd__calloc(ctx, n + 1, sizeof *qd);
    if (!qd)
        return QD_ERR_NOMEM;
    qd_status st = rest ? qd_linpoint_read_coords(ctx, p, text, q)
                        : qd_linpoint_read(ctx, p, text, q, qd);
    if (st == QD_OK) {
        qd_linpoint_set(p, q, qd);
        st = qd_eval(ctx, rest ? z->W : z->h, p->st.n, p->st.syms, p->st.vals, h);
        if (st != QD_OK || !isfinite(*h)) {
            qd_ctx_clear_error(ctx);
            qd_ctx_error(ctx, QD_ERR_ARG, "Jacobi's integral has no finite value there");
            qd_ctx_error_about(ctx, QD_SUBJECT_NONE, 0, what, QD_REASON_NONE, NULL);
            st = QD_ERR_ARG;
        }
        qd_linpoint_set(p, q, NULL);
    }
    qd__free(qd);
    return st;
}

qd_status qd_zvc_level_read(qd_ctx *ctx, qd_linpoint *p, const qd_zvc *z, const char *level,
                            const char *through, const char *at, double *q, double *h,
                            const char **where) {
    QD_ARGS_CTX(ctx, ctx && p && p->e && p->m && z && q && h);
    if (where)
        *where = NULL;
    memset(q, 0, p->e->n * sizeof *q);
    if (!!level + !!through + !!at != 1) {
        qd_ctx_error(ctx, QD_ERR_ARG, "give the level once: a level, a point to pass through "
                                      "or a state");
        return QD_ERR_ARG;
    }
    const char *text = level ? level : through ? through : at;
    qd_status st = level ? qd_model_number(ctx, p->m, level, h)
                         : level_at(ctx, p, z, through ? "through" : "at", text, !at, q, h);
    if (st != QD_OK && where && (qd_ctx_diag(ctx)->located || st == QD_ERR_ARG))
        *where = text;
    return st;
}
