/*
 * src/model/given_stmt.c - statements given apart from the model's text (a
 * command-line option, a Python argument) added to a parsed model as
 * `symmetry`, `integral` or `prescribe` statements (qd_model_add_given):
 * the language checks them as in a file, and an error is located in the
 * text as the user gave it, not in the statement built around it.
 */
#include "parser.h"
#include "../base/args.h"

#include <ctype.h>
#include <stdio.h>
#include <string.h>

#include "qdot/state.h"

/* A refusal of the given text itself, at text[off, off + len). */
static qd_status refuse(qd_model *m, qd_diag *diag, const char *text, size_t off, size_t len,
                        const char *message) {
    qd_ctx_error(m->ctx, QD_ERR_ARG, "%s", message);
    qd_ctx_error_at(m->ctx, text, off, len ? len : 1);
    if (diag) {
        memset(diag, 0, sizeof *diag);
        diag->status = QD_ERR_ARG;
        diag->located = true;
        diag->offset = off;
        diag->length = len ? len : 1;
        snprintf(diag->message, sizeof diag->message, "%s", message);
    }
    return QD_ERR_ARG;
}

/* text starts with a label "NAME:". */
static bool has_label(const char *s) {
    while (isspace((unsigned char)*s))
        s++;
    if (!isalpha((unsigned char)*s) && *s != '_')
        return false;
    while (isalnum((unsigned char)*s) || *s == '_')
        s++;
    while (isspace((unsigned char)*s))
        s++;
    return *s == ':';
}

/* "KEYWORD [LABEL: ]text[start, start + len)" added; a parser's error moved
 * from the statement's text to the given one (inside the item, else at its
 * start: the keyword and label are not the user's). */
static qd_status add_one(qd_model *m, const char *keyword, const char *label, const char *text,
                         size_t start, size_t len, qd_diag *diag) {
    qd_buf stmt = QD_BUF_INIT;
    qd_buf_printf(&stmt, "%s ", keyword);
    if (label && !has_label(text + start))
        qd_buf_printf(&stmt, "%s: ", label);
    size_t base = stmt.len;
    qd_buf_putn(&stmt, text + start, len);
    qd_diag d;
    memset(&d, 0, sizeof d);
    qd_status st = stmt.failed ? QD_ERR_NOMEM : qd_model_add_statement(m, qd_buf_str(&stmt), &d);
    qd_buf_free(&stmt);
    if (st == QD_ERR_NOMEM)
        qd_ctx_error(m->ctx, QD_ERR_NOMEM, "out of memory");
    if (st != QD_OK && diag) {
        bool inside = d.offset >= base && d.offset - base <= len;
        d.offset = inside ? d.offset - base + start : start;
        if (!inside || d.length == 0 || d.offset + d.length > start + len)
            d.length = 1;
        d.line = d.col = 0;
        *diag = d;
    }
    return st;
}

static bool blank(const char *s, size_t len) {
    for (size_t k = 0; k < len; k++)
        if (!isspace((unsigned char)s[k]))
            return false;
    return true;
}

qd_status qd_model_add_given(qd_model *m, const char *keyword, const char *label,
                             const char *text, qd_diag *diag) {
    QD_ARGS(QD_ERR_ARG, m && keyword && text);
    size_t bad = strcspn(text, "\n#");
    if (text[bad])
        return refuse(m, diag, text, bad, 1, label ? "one statement on one line is taken, "
                      "without comments" : "one line of items is taken, without comments");
    if (label)
        return add_one(m, keyword, label, text, 0, strlen(text), diag);
    for (size_t i = 0;;) {
        size_t end = qd_state_item_end(text, i);
        if (blank(text + i, end - i))
            return refuse(m, diag, text, i, end - i, "an empty item");
        qd_status st = add_one(m, keyword, NULL, text, i, end - i, diag);
        if (st != QD_OK || !text[end])
            return st;
        i = end + 1;
    }
}
