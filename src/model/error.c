/*
 * src/model/error.c - located errors and suggestions.
 *
 * The parser records the first error (message, hint, byte span) and stops,
 * SQLite-style; qd_diag_format turns the span into FILE:LINE:COL, the source
 * line and a caret, for the caller to show.
 */
#include "parser.h"
#include "../base/mem.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void line_col(const char *text, size_t off, size_t *line, size_t *col) {
    *line = 1;
    size_t start = 0;
    for (size_t i = 0; i < off && text[i]; i++)
        if (text[i] == '\n') {
            (*line)++;
            start = i + 1;
        }
    *col = off - start + 1;
}

static bool vperr(parser *p, size_t off, size_t len, const char *hint, const char *fmt,
                  va_list ap) {
    if (p->failed)
        return false;
    p->failed = true;
    if (!p->diag)
        return false;
    qd_diag *d = p->diag;
    d->offset = off;
    d->length = len ? len : 1;
    line_col(p->lx.src, off, &d->line, &d->col);
    vsnprintf(d->message, sizeof d->message, fmt, ap);
    snprintf(d->hint, sizeof d->hint, "%s", hint ? hint : "");
    return false;
}

bool qd__mdl_perr(parser *p, size_t off, size_t len, const char *hint, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    vperr(p, off, len, hint, fmt, ap);
    va_end(ap);
    return false;
}

bool qd__mdl_perr_tok(parser *p, const char *hint, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    vperr(p, p->lx.tok.off, p->lx.tok.len, hint, fmt, ap);
    va_end(ap);
    return false;
}

void qd_diag_format(const qd_diag *d, const char *file, const char *text, qd_buf *out) {
    qd_buf_printf(out, "%s:%zu:%zu: error: %s\n", file, d->line, d->col, d->message);
    size_t len = strlen(text), off = d->offset <= len ? d->offset : len;
    size_t start = off;
    while (start > 0 && text[start - 1] != '\n')
        start--;
    size_t end = start + strcspn(text + start, "\n");
    qd_buf_puts(out, "  ");
    qd_buf_putn(out, text + start, end - start);
    qd_buf_puts(out, "\n  ");
    for (size_t i = start; i < off; i++)
        qd_buf_putn(out, text[i] == '\t' ? "\t" : " ", 1);
    size_t w = d->length ? d->length : 1;
    if (off + w > end && end > off)
        w = end - off; /* the caret stays on the line shown */
    qd_buf_puts(out, "^");
    for (size_t i = 1; i < w; i++)
        qd_buf_puts(out, "~");
    qd_buf_puts(out, "\n");
    if (d->hint[0])
        qd_buf_printf(out, "  hint: %s\n", d->hint);
}

/* ---- suggestions --------------------------------------------------------- */

static size_t edit_distance(const char *a, size_t na, const char *b) {
    size_t nb = strlen(b);
    if (na > 64 || nb > 64)
        return (size_t)-1;
    size_t row[65];
    for (size_t j = 0; j <= nb; j++)
        row[j] = j;
    for (size_t i = 1; i <= na; i++) {
        size_t diag = row[0];
        row[0] = i;
        for (size_t j = 1; j <= nb; j++) {
            size_t up = row[j];
            size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            size_t best = diag + cost;
            if (row[j] + 1 < best)
                best = row[j] + 1;
            if (row[j - 1] + 1 < best)
                best = row[j - 1] + 1;
            row[j] = best;
            diag = up;
        }
    }
    return row[nb];
}

const char *qd__mdl_nearest(const char *word, size_t n, const char *const *names, size_t count) {
    const char *best = NULL;
    size_t bestd = (size_t)-1;
    size_t limit = n <= 3 ? 1 : n <= 6 ? 2 : 3; /* a close name, not any name */
    if (n < 2)
        return NULL; /* every one-letter name is one edit from every other */
    for (size_t i = 0; i < count; i++) {
        if (strlen(names[i]) < 2)
            continue;
        size_t d = edit_distance(word, n, names[i]);
        if (d <= limit && d < bestd) {
            bestd = d;
            best = names[i];
        }
    }
    return best;
}

const char **qd__mdl_known_names(const parser *p, size_t *count) {
    const qd_model *m = p->m;
    static const char *const extra[] = {
        "t", "pi", "sqrt", "dot", "cross", "norm", "transpose", "rot_x", "rot_y", "rot_z",
        "euler", "euler_zyz", "tait_bryan", "rod", "ring", "disk", "sphere", "shell", "cylinder",
        "cone", "box", "omega", "omega_space", "point", "rotation", "position",
    };
    size_t nextra = sizeof extra / sizeof extra[0];
    size_t cap = 2 * m->ncoords + m->nparams + m->ndefs + m->nfuncs + QD_FUNC_COUNT + nextra + 1,
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
    for (size_t i = 0; i < m->nfuncs; i++)
        v[n++] = m->funcs[i];
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
