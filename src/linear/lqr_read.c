/*
 * src/linear/lqr_read.c - the LQR weights "Q = diag(...), R = ..." and
 * matrices "[[a, b], [c, d]]" read from text (qdot/control.h), for the
 * program's --lqr, --weights, --A and --B and for any caller with text.
 *
 * One small recursive-descent reader: weights := item (',' item)*,
 * item := NAME '=' value, value := number | diag(list) | [[list], ...].
 * It stops at the first error and keeps its place, which the error record
 * carries (qd_ctx_error_at) so a caller can point at it with a caret.
 */
#include "qdot/control.h"
#include "../base/args.h"
#include "../base/mem.h"

#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct lqr_reader {
    qd_ctx *ctx; /* its allocator */
    const char *text;
    size_t pos;
    char err[200];
    bool failed;
} lqr_reader;

static bool oops(lqr_reader *r, const char *fmt, ...) {
    va_list ap;
    if (r->failed)
        return false;
    va_start(ap, fmt);
    vsnprintf(r->err, sizeof r->err, fmt, ap);
    va_end(ap);
    r->failed = true;
    return false;
}

static void skip_space(lqr_reader *r) {
    while (isspace((unsigned char)r->text[r->pos]))
        r->pos++;
}

static bool accept(lqr_reader *r, char c) {
    skip_space(r);
    if (r->text[r->pos] != c)
        return false;
    r->pos++;
    return true;
}

static bool expect(lqr_reader *r, char c, const char *where) {
    if (accept(r, c))
        return true;
    return oops(r, "'%c' expected %s", c, where);
}

static bool number(lqr_reader *r, double *out) {
    skip_space(r);
    char *end = NULL;
    const char *at = r->text + r->pos;
    /* strtod would also take "inf", "nan" and hexadecimal: weights are decimal */
    if (!(isdigit((unsigned char)*at) || *at == '-' || *at == '+' || *at == '.'))
        return oops(r, "a number expected");
    *out = strtod(at, &end);
    if (end == at || !isfinite(*out))
        return oops(r, "a finite number expected");
    r->pos += (size_t)(end - at);
    return true;
}

/* d1, ..., dk into out[0..k), at most max of them; *k the count. */
static bool list(lqr_reader *r, double *out, size_t max, size_t *k, const char *what) {
    *k = 0;
    do {
        double v;
        skip_space(r);
        size_t at = r->pos;
        if (!number(r, &v))
            return false;
        if (*k == max) {
            r->pos = at; /* point at the entry too many */
            return oops(r, "%s has more than %zu entries", what, max);
        }
        out[(*k)++] = v;
    } while (accept(r, ','));
    return true;
}

static bool diag_value(lqr_reader *r, char name, size_t n, double *M) {
    size_t k;
    if (!expect(r, '(', "after diag"))
        return false;
    double *d = qd__mem_calloc(qd__ctx_allocator(r->ctx), n, sizeof *d);
    if (!d)
        return oops(r, "out of memory");
    bool ok = list(r, d, n, &k, "the diagonal") && expect(r, ')', "to close diag(");
    if (ok && k != n)
        ok = oops(r, "diag(...) of %c has %zu entries; %c is %zu by %zu", name, k, name, n, n);
    for (size_t i = 0; ok && i < n; i++)
        M[i * n + i] = d[i];
    qd__free(d);
    return ok;
}

static bool matrix_value(lqr_reader *r, char name, size_t n, double *M) {
    size_t row = 0, k;
    do {
        if (row == n)
            return oops(r, "%c has more than %zu rows", name, n);
        if (!expect(r, '[', "to open a row") || !list(r, M + row * n, n, &k, "a row") ||
            !expect(r, ']', "to close a row"))
            return false;
        if (k != n)
            return oops(r, "row %zu of %c has %zu entries; %c is %zu by %zu", row + 1, name, k,
                        name, n, n);
        row++;
    } while (accept(r, ','));
    if (!expect(r, ']', "to close the matrix"))
        return false;
    if (row != n)
        return oops(r, "%c has %zu rows; it is %zu by %zu", name, row, n, n);
    return true;
}

static bool value(lqr_reader *r, char name, size_t n, double *M) {
    memset(M, 0, n * n * sizeof *M);
    skip_space(r);
    if (!strncmp(r->text + r->pos, "diag", 4)) {
        r->pos += 4;
        return diag_value(r, name, n, M);
    }
    if (accept(r, '[')) /* the row's own '[' is next */
        return matrix_value(r, name, n, M);
    char c0 = r->text[r->pos];
    if (!(isdigit((unsigned char)c0) || c0 == '-' || c0 == '+' || c0 == '.'))
        return oops(r, "a number, diag(...) or [[...], ...] expected for %c", name);
    double c;
    if (!number(r, &c))
        return false;
    for (size_t i = 0; i < n; i++)
        M[i * n + i] = c;
    return true;
}

static bool item(lqr_reader *r, size_t n, size_t m, double *Q, double *R, bool seen[2]) {
    skip_space(r);
    char name = r->text[r->pos];
    size_t start = r->pos;
    if ((name != 'Q' && name != 'R') || isalnum((unsigned char)r->text[r->pos + 1]) ||
        r->text[r->pos + 1] == '_')
        return oops(r, "Q or R expected");
    int which = name == 'R';
    if (seen[which]) {
        r->pos = start;
        return oops(r, "%c is given twice", name);
    }
    seen[which] = true;
    r->pos++;
    if (!expect(r, '=', which ? "after R" : "after Q"))
        return false;
    return which ? value(r, 'R', m, R) : value(r, 'Q', n, Q);
}

/* The reader's error into ctx, located at its place in the text. */
static qd_status failed(qd_ctx *ctx, const lqr_reader *r) {
    qd_ctx_error(ctx, QD_ERR_PARSE, "%s", r->err);
    qd_ctx_error_at(ctx, r->text, r->pos, 1);
    return QD_ERR_PARSE;
}

qd_status qd_lqr_weights_read(qd_ctx *ctx, const char *text, size_t n, size_t m, double *Q,
                              double *R) {
    QD_ARGS_CTX(ctx, ctx && text && Q && R);
    lqr_reader r = {.ctx = ctx, .text = text};
    bool seen[2] = {false, false};
    do {
        if (!item(&r, n, m, Q, R, seen))
            break;
    } while (accept(&r, ','));
    skip_space(&r);
    if (!r.failed && text[r.pos] != '\0')
        oops(&r, "',' or the end expected");
    if (!r.failed && (!seen[0] || !seen[1])) /* the cost needs both: no silent default */
        oops(&r, "%s missing (give both: \"Q = diag(...), R = ...\")", seen[0] ? "R is" : "Q is");
    return r.failed ? failed(ctx, &r) : QD_OK;
}

/* One row "[a, b, ...]" appended to *m (grown by realloc); *cols set by the
 * first row, checked against it by the others. */
static bool grow_row(lqr_reader *r, double **m, size_t rows, size_t *cols) {
    size_t cap = 16, k = 0;
    double *row = qd__mem_malloc(qd__ctx_allocator(r->ctx), cap * sizeof *row), v;
    bool ok = row && expect(r, '[', "to open a row");
    if (!row)
        oops(r, "out of memory");
    while (ok && (k == 0 || accept(r, ','))) {
        if (k == cap) {
            double *more = k < 4096 ? qd__mem_realloc(NULL, row, 2 * cap * sizeof *row)
                                    : NULL;
            if (!more)
                ok = oops(r, "a row longer than 4096 entries");
            else
                row = more, cap *= 2;
        }
        if (ok && (ok = number(r, &v)))
            row[k++] = v;
    }
    ok = ok && expect(r, ']', "to close a row");
    if (ok && rows > 0 && k != *cols)
        ok = oops(r, "row %zu has %zu entries, row 1 has %zu", rows + 1, k, *cols);
    const qd_allocator *al = qd__ctx_allocator(r->ctx);
    double *more = ok && rows < 4096 ? qd__mem_realloc(al, *m, (rows + 1) * k * sizeof **m)
                                     : NULL;
    if (ok && !more)
        ok = oops(r, "more than 4096 rows");
    if (ok) {
        *m = more;
        memcpy(*m + rows * k, row, k * sizeof *row);
        *cols = k;
    }
    qd__free(row);
    return ok;
}

qd_status qd_matrix_read(qd_ctx *ctx, const char *text, qd_matrix *out) {
    QD_ARGS_CTX(ctx, ctx && text && out);
    lqr_reader r = {.ctx = ctx, .text = text};
    double *m = NULL;
    *out = (qd_matrix){0};
    size_t rows = 0, cols = 0;
    if (expect(&r, '[', "to open the matrix, as in [[1, 0], [0, 1]]")) {
        do {
            if (!grow_row(&r, &m, rows, &cols))
                break;
            ++rows;
        } while (accept(&r, ','));
    }
    if (!r.failed)
        expect(&r, ']', "to close the matrix");
    skip_space(&r);
    if (!r.failed && text[r.pos] != '\0')
        oops(&r, "the end expected after the matrix");
    if (r.failed) {
        qd__free(m);
        return failed(ctx, &r);
    }
    *out = (qd_matrix){rows, cols, m};
    return QD_OK;
}

void qd_matrix_free(qd_matrix *m) {
    if (!m)
        return;
    qd__free(m->a);
    *m = (qd_matrix){0};
}
