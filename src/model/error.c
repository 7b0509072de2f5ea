/*
 * src/model/error.c - located errors and suggestions.
 *
 * The parser records the first error (message, hint, byte span) in the
 * context's error record and stops, SQLite-style; qd_diag_format (base/diag.c)
 * shows it.  qd_model_locate places a derivation's error in the model text.
 */
#include "parser.h"
#include "base/diag.h"
#include "base/mem.h"
#include "../base/args.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Record the parser's first error in the context (SQLite's way: code,
 * message and byte range, and stop) and copy it for qd_model_parse's caller.
 * An error at a byte the lexer could not read names that byte instead, in
 * plain words, whatever the statement expected there. */
static bool vperr(parser *p, qd_reason why, size_t off, size_t len, const char *hint,
                  const char *fmt, va_list ap) {
    if (p->failed)
        return false;
    p->failed = true;
    char msg[256];
    vsnprintf(msg, sizeof msg, fmt, ap);
    if (p->lx.tok.kind == TK_BAD && off == p->lx.tok.off) {
        len = qd__diag_bad_char(p->lx.src + off, msg, sizeof msg, &hint);
        why = QD_REASON_BAD_BYTE;
    } else if (p->lx.too_deep || p->nest > QD_MAX_NEST) {
        why = QD_REASON_TOO_DEEP;
    }
    qd_ctx *ctx = p->ctx;
    qd_status st = qd_ctx_status(ctx);
    /* a kernel error met while parsing is reported at the parser's spot */
    qd__ctx_recover(ctx);
    qd_ctx_error(ctx, st != QD_OK ? st : QD_ERR_PARSE, "%s", msg);
    qd_ctx_error_about(ctx, QD_SUBJECT_TEXT, 0, NULL, why, hint);
    qd_ctx_error_at(ctx, p->lx.src, off, len);
    if (p->diag)
        *p->diag = *qd_ctx_diag(ctx);
    return false;
}

bool qd__mdl_perr(parser *p, size_t off, size_t len, const char *hint, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    vperr(p, QD_REASON_NONE, off, len, hint, fmt, ap);
    va_end(ap);
    return false;
}

bool qd__mdl_perr_why(parser *p, qd_reason why, size_t off, size_t len, const char *hint,
                      const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    vperr(p, why, off, len, hint, fmt, ap);
    va_end(ap);
    return false;
}

bool qd__mdl_perr_tok(parser *p, const char *hint, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    vperr(p, QD_REASON_NONE, p->lx.tok.off, p->lx.tok.len, hint, fmt, ap);
    va_end(ap);
    return false;
}

/* "constraint:NAME", "T", a coordinate's name: the key qd_model_where
 * knows the subject's statement by. */
static bool where_key(const qd_model *m, const qd_diag *d, char *key, size_t cap) {
    const char *name = d->name[0] ? d->name : NULL;
    switch (d->subject) {
    case QD_SUBJECT_STATEMENT:
        break;
    case QD_SUBJECT_CONSTRAINT:
        if (!name && d->index < m->ncons)
            name = m->con_names[d->index];
        return name && snprintf(key, cap, "constraint:%s", name) < (int)cap;
    case QD_SUBJECT_COORD:
        if (!name && d->index < m->ncoords)
            name = qd_expr_name(m->coords[d->index]);
        break;
    case QD_SUBJECT_SPEED:
        if (!name && d->index < m->nspeeds)
            name = qd_expr_name(m->speeds[d->index].sym);
        return name && snprintf(key, cap, "speed:%s", name) < (int)cap;
    case QD_SUBJECT_PARAM:
        if (!name && d->index < m->nparams)
            name = qd_expr_name(m->params[d->index]);
        break;
    default:
        return false;
    }
    return name && snprintf(key, cap, "%s", name) < (int)cap;
}

bool qd_model_locate(const qd_model *m, qd_diag *d) {
    QD_ARGS(false, m && d);
    char key[160];
    qd_diag w;
    if (!m || !d || !where_key(m, d, key, sizeof key) || !qd_model_where(m, key, &w))
        return false;
    d->located = true;
    d->offset = w.offset;
    d->length = w.length;
    d->line = w.line;
    d->col = w.col;
    return true;
}

/* ---- suggestions --------------------------------------------------------- */

const char **qd__mdl_known_names(const parser *p, size_t *count) {
    const qd_model *m = p->m;
    static const char *const extra[] = {
        "t", "pi", "sqrt", "dot", "cross", "norm", "transpose", "rot_x", "rot_y", "rot_z",
        "euler", "euler_zyz", "tait_bryan", "rod", "ring", "disk", "sphere", "shell", "cylinder",
        "cone", "box", "omega", "omega_space", "point", "rotation", "position",
    };
    size_t nextra = sizeof extra / sizeof extra[0];
    size_t cap = 2 * m->ncoords + m->nparams + m->ndefs + m->nspeeds + m->nfuncs + m->ninputs +
                 QD_FUNC_COUNT + nextra + 2,
           n = 0;
    const char **v = qd__malloc(p->ctx, cap * sizeof *v);
    if (!v) {
        *count = 0;
        return NULL;
    }
    for (size_t i = 0; i < m->ncoords; i++)
        v[n++] = qd_expr_name(m->coords[i]);
    for (size_t i = 0; i < m->nparams; i++)
        v[n++] = qd_expr_name(m->params[i]);
    for (size_t i = 0; m->mom && i < m->ncoords; i++)
        v[n++] = qd_expr_name(m->mom[i]);
    if (p->eps_ok)
        v[n++] = "eps";
    for (size_t i = 0; i < m->ndefs; i++)
        v[n++] = m->defs[i].name;
    for (size_t i = 0; i < m->nspeeds; i++)
        v[n++] = qd_expr_name(m->speeds[i].sym);
    for (size_t i = 0; i < m->nfuncs; i++)
        v[n++] = m->funcs[i];
    for (size_t i = 0; i < m->ninputs; i++)
        v[n++] = qd_expr_name(m->inputs[i]);
    if (m->indep)
        v[n++] = m->indep;
    for (int f = 0; f < QD_FUNC_COUNT; f++)
        v[n++] = qd_func_name((qd_func)f);
    for (size_t i = 0; i < nextra; i++)
        v[n++] = extra[i];
    *count = n;
    return v;
}

bool qd__mdl_name_is(const char *src, size_t off, size_t n, const char *word) {
    return strlen(word) == n && memcmp(src + off, word, n) == 0;
}
