/*
 * src/sym/read_var.c - a variable to differentiate by, read from text
 * (qd_read_variable, qdot/read.h): what `qdot diff EXPR VAR` reads, a name
 * or a rate (r, r', theta'') of an expression, its error located in text.
 */
#include <stdio.h>
#include <string.h>
#include "qdot/read.h"
#include "base/args.h"

const qd_expr *qd_read_variable(qd_ctx *ctx, const char *text, const qd_expr *within,
                                qd_read_error *err) {
    QD_ARGS(NULL, ctx && text && within);
    const qd_read_opts known = {.new_symbols = false};
    const qd_expr *v = qd_read(ctx, text, &known, NULL);
    if (v && qd_expr_kind(v) == QD_SYMBOL && qd_has(within, v))
        return v;
    qd_status st = v ? QD_OK : qd_ctx_status(ctx);
    if (st == QD_ERR_NOMEM) {
        if (err)
            *err = *qd_ctx_diag(ctx);
        return NULL;
    }
    qd_ctx_clear_error(ctx);
    size_t len = strlen(text);
    qd_ctx_error(ctx, QD_ERR_ARG, "'%s' does not occur in the expression", text);
    qd_ctx_error_about(ctx, QD_SUBJECT_TEXT, 0, NULL, QD_REASON_NONE,
                       "name one of the expression's symbols, or a rate of one (r')");
    qd_ctx_error_at(ctx, text, 0, len ? len : 1);
    if (err)
        *err = *qd_ctx_diag(ctx);
    return NULL;
}
