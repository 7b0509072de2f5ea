/*
 * src/render/codegen.c - the C `qdot codegen` writes for a model
 * (qd_codegen_model_c, qdot/codegen.h): the equations in generalized speeds
 * for a model with `speeds`, else Lagrange's equations, derived here, so
 * the command line and Python make the same file from the same model.
 */
#include "qdot/codegen.h"
#include "qdot/speeds.h"
#include "../base/args.h"

/* The error a derivation that returned NULL left (out of memory when none). */
static qd_status failed(const qd_ctx *ctx) {
    qd_status st = qd_ctx_status(ctx);
    return st != QD_OK ? st : QD_ERR_NOMEM;
}

static qd_status speeds_c(qd_ctx *ctx, const qd_model *m, bool eliminate, const char *prefix,
                          qd_buf *c_text, qd_buf *h_text) {
    if (eliminate) {
        qd_ctx_error(ctx, QD_ERR_ARG, "eliminate is for models without speeds: the speeds "
                                      "already take the constraints into account");
        qd_ctx_error_about(ctx, QD_SUBJECT_NONE, 0, "eliminate", QD_REASON_NONE, NULL);
        return QD_ERR_ARG;
    }
    qd_speeds_eom *se = qd_speeds_derive(ctx, m, NULL);
    if (!se)
        return failed(ctx);
    qd_status st = qd_codegen_speeds_c(ctx, m, se, prefix, c_text, h_text);
    qd_speeds_eom_free(se);
    return st;
}

qd_status qd_codegen_model_c(qd_ctx *ctx, const qd_model *m, bool eliminate, const char *prefix,
                             qd_buf *c_text, qd_buf *h_text) {
    QD_ARGS_CTX(ctx, ctx && m && c_text);
    if (qd_model_nspeeds(m))
        return speeds_c(ctx, m, eliminate, prefix, c_text, h_text);
    qd_eom_opts opts = {.eliminate = eliminate};
    qd_eom *e = qd_eom_derive_opts(ctx, m, &opts);
    if (!e)
        return failed(ctx);
    qd_status st = qd_codegen_c(ctx, m, e, prefix, c_text, h_text);
    qd_eom_free(e);
    return st;
}
