/*
 * src/form/vars_read.c - the variables of a quadratic form read from text,
 * "x, y, z" (qd_qform_vars_read, qdot/form.h): what `qdot form --vars`
 * reads, errors located in the text.
 */
#include <stdio.h>
#include "qdot/form.h"
#include "qdot/read.h"
#include "base/args.h"
#include "base/diag.h"
#include "base/mem.h"

/* The error at text[off, off + len), a QD_ERR_ARG. */
static qd_status vr_fail(qd_ctx *ctx, const char *text, size_t off, size_t len, const char *msg) {
    qd_ctx_error(ctx, QD_ERR_ARG, "%s", msg);
    qd_ctx_error_about(ctx, QD_SUBJECT_TEXT, 0, NULL, QD_REASON_NONE,
                       "name the variables, separated by commas or spaces: \"x, y\"");
    qd_ctx_error_at(ctx, text, off, len ? len : 1);
    return QD_ERR_ARG;
}

static bool separator(char c) { return c == ' ' || c == ','; }

qd_status qd_qform_vars_read(qd_ctx *ctx, const char *text, const qd_expr **x, size_t cap,
                             size_t *n) {
    QD_ARGS_CTX(ctx, ctx && text && (cap == 0 || x) && n);
    *n = 0;
    size_t i = 0, len = 0;
    while (text[len])
        len++;
    while (i < len) {
        while (separator(text[i]))
            i++;
        size_t j = i;
        while (text[j] && !separator(text[j]))
            j++;
        if (j == i)
            break;
        char msg[256];
        if (*n == cap) {
            snprintf(msg, sizeof msg, "more than %zu variables", cap);
            return vr_fail(ctx, text, i, j - i, msg);
        }
        char *name = qd__malloc(ctx, j - i + 1);
        if (!name)
            return QD_ERR_NOMEM;
        for (size_t k = i; k < j; k++)
            name[k - i] = text[k];
        name[j - i] = '\0';
        /* read as an expression reads it: pi is the constant, t' is 1 */
        const qd_expr *s = qd_read(ctx, name, NULL, NULL);
        qd__free(name);
        if (!s && qd_ctx_status(ctx) == QD_ERR_NOMEM)
            return QD_ERR_NOMEM;
        if (!s || qd_expr_kind(s) != QD_SYMBOL) {
            qd_ctx_clear_error(ctx);
            snprintf(msg, sizeof msg, "'%.*s' is not a variable name", (int)(j - i), text + i);
            return vr_fail(ctx, text, i, j - i, msg);
        }
        for (size_t k = 0; k < *n; k++)
            if (x[k] == s) {
                snprintf(msg, sizeof msg, "'%.*s' is given twice", (int)(j - i), text + i);
                return vr_fail(ctx, text, i, j - i, msg);
            }
        x[(*n)++] = s;
        i = j;
    }
    if (*n == 0)
        return vr_fail(ctx, text, 0, len, "no variable is named");
    return QD_OK;
}
