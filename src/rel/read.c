/*
 * src/rel/read.c - numbers, lists and particles written as text in which c
 * is the speed of light of the run (qd_rel_read_*, relativity.h): what
 * `qdot lorentz` and `qdot collide` read, so that "0.6*c" means the same
 * from the program and from any caller of the library.
 *
 * Every error is recorded about the field (subject NONE, qd_diag.name) and
 * located in the whole text given, not only in the item at fault, so the
 * caller's caret stands under the right place of the option's value.
 */
#include "base/args.h"
#include "rel.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/read.h"

#define MAX_LIST 16

/* What is read: the field, which item of a list option it is (index, 0 for
 * one), and c. */
typedef struct rd {
    qd_ctx *ctx;
    double c;
    const char *field;
    size_t index;
} rd;

/* Record the error just made in ctx about the field, at text[off, off + len). */
static qd_status about(const rd *r, const char *text, size_t off, size_t len) {
    qd_ctx *ctx = r->ctx;
    qd_ctx_error_about(ctx, QD_SUBJECT_NONE, r->index, r->field, QD_REASON_NONE, NULL);
    qd_ctx_error_at(ctx, text, off, len ? len : 1);
    return qd_ctx_status(ctx);
}

/* The item text[a, b) trimmed of blanks: *a and *b moved inwards. */
static void trim(const char *text, size_t *a, size_t *b) {
    while (*a < *b && isspace((unsigned char)text[*a]))
        (*a)++;
    while (*b > *a && isspace((unsigned char)text[*b - 1]))
        (*b)--;
}

/* The end of the item that starts at i: the next comma outside brackets. */
static size_t item_end(const char *text, size_t i, size_t end) {
    for (int depth = 0; i < end && (text[i] != ',' || depth); i++)
        depth += text[i] == '(' ? 1 : text[i] == ')' && depth ? -1 : 0;
    return i;
}

/* [*a, *b) without one bracket around the whole of it ("(a) + (b)" keeps). */
static void unwrap(const char *text, size_t *a, size_t *b) {
    if (*b - *a < 2 || text[*a] != '(' || text[*b - 1] != ')')
        return;
    int depth = 0;
    for (size_t i = *a; i < *b - 1; i++) {
        depth += (text[i] == '(') - (text[i] == ')');
        if (depth == 0)
            return;
    }
    (*a)++;
    (*b)--;
}

/* text[a, b) read and c substituted: an expression in t when t_ok, else
 * evaluated into *val. */
static qd_status read_span(const rd *r, const char *text, size_t a, size_t b,
                           const qd_expr **expr, double *val) {
    qd_ctx *ctx = r->ctx;
    char *s = malloc(b - a + 1);
    if (!s) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        return QD_ERR_NOMEM;
    }
    memcpy(s, text + a, b - a);
    s[b - a] = '\0';
    qd_diag err;
    const qd_read_opts opts = {.new_symbols = true};
    const qd_expr *e = qd_read(ctx, s, &opts, &err), *csym = NULL, *cval = NULL;
    qd_status st = QD_OK;
    if (!e) {
        qd_ctx_clear_error(ctx);
        qd_ctx_error(ctx, err.status ? err.status : QD_ERR_PARSE, "%s", err.message);
        st = about(r, text, a + (err.located ? err.offset : 0),
                   err.located ? err.length : b - a);
    } else if (!(csym = qd_symbol(ctx, "c")) || !(cval = qd_float(ctx, r->c)) ||
               !(e = qd_subs(ctx, e, 1, &csym, &cval))) {
        st = qd_ctx_status(ctx);
    } else if (expr) {
        *expr = e;
    } else if (qd_eval(ctx, e, 0, NULL, NULL, val) != QD_OK || !isfinite(*val)) {
        qd_ctx_clear_error(ctx);
        qd_ctx_error(ctx, QD_ERR_ARG,
                     "'%s' does not evaluate to a finite number (names allowed: c, pi, e)", s);
        st = about(r, text, a, b - a);
    }
    free(s);
    return st;
}

/* The n items of text[a, b) (NULL exprs: numbers into out). */
static qd_status read_list(const rd *r, const char *text, size_t a, size_t b, size_t n,
                           double *out, const qd_expr **exprs) {
    qd_ctx *ctx = r->ctx;
    size_t a0 = a, b0 = b, k = 0;
    trim(text, &a, &b);
    unwrap(text, &a, &b);
    qd_status st = QD_OK;
    for (size_t i = a; st == QD_OK; k++) {
        size_t end = item_end(text, i, b), ia = i, ib = end;
        trim(text, &ia, &ib);
        if (k < n)
            st = read_span(r, text, ia, ib, exprs ? &exprs[k] : NULL,
                           exprs ? NULL : &out[k]);
        if (end >= b) {
            k++;
            break;
        }
        i = end + 1;
    }
    if (st == QD_OK && k != n) {
        qd_ctx_error(ctx, QD_ERR_ARG, "needs %zu comma-separated values, not '%.*s'", n,
                     (int)(b0 - a0), text + a0);
        st = about(r, text, a0, b0 - a0);
    }
    return st;
}

qd_status qd_rel_read_c(qd_ctx *ctx, const char *field, const char *text, double *c) {
    QD_ARGS_CTX(ctx, ctx && field && text && c);
    const rd r = {ctx, 1, field, 0};
    qd_status st = read_span(&r, text, 0, strlen(text), NULL, c);
    if (st == QD_OK && !(*c > 0)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the speed of light must be positive, not '%s'", text);
        st = about(&r, text, 0, strlen(text));
    }
    return st;
}

qd_status qd_rel_read_number(qd_ctx *ctx, double c, const char *field, const char *text,
                             double *out) {
    QD_ARGS_CTX(ctx, ctx && field && text && out);
    const rd r = {ctx, c, field, 0};
    size_t a = 0, b = strlen(text);
    trim(text, &a, &b);
    return read_span(&r, text, a, b, NULL, out);
}

qd_status qd_rel_read_numbers(qd_ctx *ctx, double c, const char *field, const char *text,
                              size_t n, double *out) {
    QD_ARGS_CTX(ctx, ctx && field && text && (n == 0 || out));
    const rd r = {ctx, c, field, 0};
    return read_list(&r, text, 0, strlen(text), n, out, NULL);
}

qd_status qd__rel_read_exprs(qd_ctx *ctx, double c, const char *field, const char *text,
                             const qd_expr *out[3]) {
    const rd r = {ctx, c, field, 0};
    return read_list(&r, text, 0, strlen(text), 3, NULL, out);
}

size_t qd__rel_count(const char *text) {
    size_t n = 1, len = strlen(text);
    for (size_t i = item_end(text, 0, len); i < len; i = item_end(text, i + 1, len))
        n++;
    return n;
}

qd_status qd__rel_read_particle(qd_ctx *ctx, double c, const char *field, size_t index,
                                const char *text, qd_rel_particle *out) {
    const rd r = {ctx, c, field, index};
    double m = NAN, v[3] = {0, 0, 0};
    size_t len = strlen(text);
    qd_status st = QD_OK;
    for (size_t i = 0; st == QD_OK;) {
        size_t end = item_end(text, i, len), a = i, b = end;
        trim(text, &a, &b);
        const char *eq = memchr(text + a, '=', b - a);
        size_t na = a, nb = eq ? (size_t)(eq - text) : a;
        trim(text, &na, &nb);
        if (!eq || nb - na != 1 || (text[na] != 'm' && text[na] != 'v')) {
            qd_ctx_error(ctx, QD_ERR_ARG, "takes \"m=MASS, v=(VX, VY, VZ)\", not '%s'", text);
            st = about(&r, text, a, b - a);
        } else if (text[na] == 'm') {
            size_t va = (size_t)(eq - text) + 1, vb = b;
            trim(text, &va, &vb);
            st = read_span(&r, text, va, vb, NULL, &m);
        } else {
            st = read_list(&r, text, (size_t)(eq - text) + 1, b, 3, v, NULL);
        }
        if (end >= len)
            break;
        i = end + 1;
    }
    if (st == QD_OK && isnan(m)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the rest mass m=... is missing in '%s'", text);
        st = about(&r, text, 0, len);
    }
    if (st == QD_OK && qd_rel_particle_make(ctx, c, m, v, out) != QD_OK)
        st = about(&r, text, 0, len);
    return st;
}

qd_status qd_rel_read_particle(qd_ctx *ctx, double c, const char *field, const char *text,
                               qd_rel_particle *out) {
    QD_ARGS_CTX(ctx, ctx && field && text && out);
    return qd__rel_read_particle(ctx, c, field, 0, text, out);
}
