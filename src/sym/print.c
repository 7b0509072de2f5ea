/*
 * src/sym/print.c - qd_print: one entry point, one printer per format;
 * the time symbol's printed name, which the printers share.
 */
#include "prec.h"
#include "../base/args.h"

#include <ctype.h>
#include <string.h>

qd_status qd_print_set_time_name(qd_ctx *ctx, const char *name) {
    QD_ARGS_CTX(ctx, ctx && name);
    if (!ctx)
        return QD_ERR_ARG;
    bool ident = name && (isalpha((unsigned char)name[0]) || name[0] == '_');
    for (const char *c = name; ident && *c; c++)
        ident = isalnum((unsigned char)*c) || *c == '_';
    if (name && !ident) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the time symbol cannot print as '%s': not a name", name);
        return QD_ERR_ARG;
    }
    if (!name || !strcmp(name, "t")) {
        ctx->sym->tname = NULL;
        return QD_OK;
    }
    const char *in = qd__intern_name(ctx, name); /* lives as long as ctx */
    if (!in)
        return QD_ERR_NOMEM;
    ctx->sym->tname = in;
    return QD_OK;
}

const char *qd_print_time_name(const qd_ctx *ctx) {
    QD_ARGS(NULL, ctx);
    return ctx && ctx->sym->tname ? ctx->sym->tname : "t";
}

qd_status qd_print(qd_ctx *ctx, const qd_expr *e, qd_format fmt, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && out);
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
