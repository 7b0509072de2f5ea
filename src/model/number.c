/*
 * src/model/number.c - a number written as a constant expression in a
 * model's parameters (qd_model_number, model.h): what a numeric option such
 * as `--t-end "2*pi/w"` reads.
 */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/diag.h"
#include "qdot/model.h"
#include "qdot/read.h"

/* The first place name stands in text as a whole word (the reader found it
 * there), or the start of text. */
static size_t word_at(const char *text, const char *name) {
    size_t n = strlen(name);
    for (const char *p = text; n && (p = strstr(p, name)); p++) {
        bool before = p == text || !(isalnum((unsigned char)p[-1]) || p[-1] == '_');
        bool after = !(isalnum((unsigned char)p[n]) || p[n] == '_');
        if (before && after)
            return (size_t)(p - text);
    }
    return 0;
}

/* "unknown name 'x'" (or "x is a coordinate"), at x in text, with the
 * nearest of pi, e and the parameters' names as the hint. */
static qd_status refuse_name(qd_ctx *ctx, const qd_model *m, const char *text, const qd_expr *s) {
    const char *name = qd_expr_name(s);
    size_t np = qd_model_nparams(m);
    const char **names = malloc((np + 2) * sizeof *names);
    const char *near = NULL;
    if (names) {
        names[0] = "pi";
        names[1] = "e";
        for (size_t i = 0; i < np; i++)
            names[i + 2] = qd_expr_name(qd_model_param(m, i));
        near = qd__diag_nearest(name, strlen(name), names, np + 2);
    }
    qd_role role = qd_symbol_role(s);
    if (role == QD_ROLE_TIME || role == QD_ROLE_COORD)
        qd_ctx_error(ctx, QD_ERR_ARG, "'%s' is not a constant: a number here takes only pi, e "
                                      "and the model's parameters", name);
    else
        qd_ctx_error(ctx, QD_ERR_ARG, "unknown name '%s' (a number here takes pi, e and the "
                                      "model's parameters)", name);
    char hint[160];
    snprintf(hint, sizeof hint, "did you mean '%s'?", near ? near : "");
    qd_ctx_error_about(ctx, QD_SUBJECT_TEXT, 0, name, QD_REASON_NONE, near ? hint : NULL);
    qd_ctx_error_at(ctx, text, word_at(text, name), strlen(name) ? strlen(name) : 1);
    free(names);
    return QD_ERR_ARG;
}

qd_status qd_model_number(qd_ctx *ctx, const qd_model *m, const char *text, double *out) {
    if (!ctx)
        return QD_ERR_ARG;
    if (!m || !text || !out) {
        qd_ctx_error(ctx, QD_ERR_ARG, "qd_model_number: a NULL argument");
        return QD_ERR_ARG;
    }
    const qd_read_opts opts = {.new_symbols = true};
    const qd_expr *x = qd_read(ctx, text, &opts, NULL);
    if (!x)
        return qd_ctx_status(ctx); /* located in text by the reader */
    size_t k = qd_free_symbols(ctx, x, NULL, 0), np = qd_model_nparams(m);
    const qd_expr **syms = malloc((k + np + 1) * sizeof *syms);
    double *vals = malloc((np + 1) * sizeof *vals);
    qd_status st = syms && vals ? QD_OK : QD_ERR_NOMEM;
    if (st != QD_OK)
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
    if (st == QD_OK)
        qd_free_symbols(ctx, x, syms + np, k);
    for (size_t i = 0; st == QD_OK && i < k; i++) {
        size_t j = 0;
        while (j < np && qd_model_param(m, j) != syms[np + i])
            j++;
        if (j == np)
            st = refuse_name(ctx, m, text, syms[np + i]);
    }
    for (size_t j = 0; st == QD_OK && j < np; j++) {
        syms[j] = qd_model_param(m, j);
        if (qd_model_param_number(m, j, &vals[j]) != QD_OK)
            vals[j] = NAN; /* an error below only if the expression uses it */
    }
    double v = NAN;
    if (st == QD_OK && (st = qd_eval(ctx, x, np, syms, vals, &v)) != QD_OK)
        qd_ctx_error_at(ctx, text, 0, strlen(text) ? strlen(text) : 1);
    if (st == QD_OK && !isfinite(v)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "'%s' does not evaluate to a finite number (%g)", text, v);
        qd_ctx_error_at(ctx, text, 0, strlen(text) ? strlen(text) : 1);
        st = QD_ERR_ARG;
    }
    if (st == QD_OK)
        *out = v;
    free(syms);
    free(vals);
    return st;
}

qd_status qd_model_number_field(qd_ctx *ctx, const qd_model *m, const char *field,
                                const char *text, size_t start, size_t len, double *out) {
    if (!ctx)
        return QD_ERR_ARG;
    if (!m || !field || !text || !out || start + len > strlen(text)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "qd_model_number_field: a NULL argument or a bad span");
        return QD_ERR_ARG;
    }
    char *part = malloc(len + 1);
    if (!part) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        return QD_ERR_NOMEM;
    }
    memcpy(part, text + start, len);
    part[len] = '\0';
    qd_status st = qd_model_number(ctx, m, part, out);
    free(part);
    if (st == QD_OK || st == QD_ERR_NOMEM)
        return st;
    qd_diag d = *qd_ctx_diag(ctx); /* re-recorded about the field, in the whole text */
    qd_ctx_clear_error(ctx);
    qd_ctx_error(ctx, d.status, "%s", d.message);
    qd_ctx_error_about(ctx, QD_SUBJECT_NONE, 0, field, d.reason, d.hint[0] ? d.hint : NULL);
    qd_ctx_error_at(ctx, text, start + (d.located ? d.offset : 0),
                    d.located ? d.length : (len ? len : 1));
    return st;
}
