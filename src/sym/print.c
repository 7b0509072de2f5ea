/*
 * src/sym/print.c - qd_print: one entry point, one printer per format.
 */
#include "prec.h"

qd_status qd_print(qd_ctx *ctx, const qd_expr *e, qd_format fmt, qd_buf *out) {
    if (!ctx || !out)
        return QD_ERR_ARG;
    if (!e) {
        qd_ctx_error(ctx, QD_ERR_ARG, "nothing to print: the expression is NULL");
        return QD_ERR_ARG;
    }
    qd_status st;
    switch (fmt) {
    case QD_FMT_TEXT: st = qd__print_text(ctx, e, out); break;
    case QD_FMT_LATEX: st = qd__print_latex(ctx, e, out); break;
    case QD_FMT_C: st = qd__print_c(ctx, e, out); break;
    case QD_FMT_SYMPY: st = qd__print_sympy(ctx, e, out); break;
    default:
        qd_ctx_error(ctx, QD_ERR_ARG, "unknown print format %d", (int)fmt);
        return QD_ERR_ARG;
    }
    if (st == QD_ERR_NOMEM)
        qd__oom(ctx);
    return st;
}
