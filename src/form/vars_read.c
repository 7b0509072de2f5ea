/*
 * src/form/vars_read.c - the variables of a quadratic form read from text,
 * "x, y, z" (qd_qform_vars_read, qdot/form.h): what `qdot form --vars`
 * reads, errors located in the text; and names made positive symbols
 * (qd_qform_positive_read, `--positive`).
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

/* A name made a positive symbol (qd_qform_positive_read): NULL when it is
 * one of either sign already, or no name. */
static const qd_expr *positive_symbol(qd_ctx *ctx, const char *name) {
    const qd_expr *s = qd_lookup(ctx, name);
    if (s)
        return qd_expr_kind(s) == QD_SYMBOL && qd_symbol_is_positive(s) ? s : NULL;
    bool ident = (name[0] >= 'a' && name[0] <= 'z') || (name[0] >= 'A' && name[0] <= 'Z');
    for (const char *c = name; ident && *c; c++)
        ident = (*c >= 'a' && *c <= 'z') || (*c >= 'A' && *c <= 'Z') || (*c >= '0' && *c <= '9') ||
                *c == '_';
    return ident ? qd_symbol_positive(ctx, name, QD_ROLE_PLAIN) : NULL;
}

static qd_status names_read(qd_ctx *ctx, const char *text, const qd_expr **x, size_t cap,
                            size_t *n, bool positive) {
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
        const qd_expr *s = positive ? positive_symbol(ctx, name) : qd_read(ctx, name, NULL, NULL);
        bool known = positive && qd_lookup(ctx, name);
        qd__free(name);
        if (!s && qd_ctx_status(ctx) == QD_ERR_NOMEM)
            return QD_ERR_NOMEM;
        if (!s || qd_expr_kind(s) != QD_SYMBOL) {
            qd_ctx_clear_error(ctx);
            snprintf(msg, sizeof msg, known ? "'%.*s' is already a symbol of either sign: name it "
                                              "positive before it is used"
                                            : "'%.*s' is not a variable name",
                     (int)(j - i), text + i);
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

qd_status qd_qform_vars_read(qd_ctx *ctx, const char *text, const qd_expr **x, size_t cap,
                             size_t *n) {
    QD_ARGS_CTX(ctx, ctx && text && (cap == 0 || x) && n);
    return names_read(ctx, text, x, cap, n, false);
}

qd_status qd_qform_positive_read(qd_ctx *ctx, const char *text, const qd_expr **x, size_t cap,
                                 size_t *n) {
    QD_ARGS_CTX(ctx, ctx && text && (cap == 0 || x) && n);
    return names_read(ctx, text, x, cap, n, true);
}
