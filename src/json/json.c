/*
 * src/json/json.c - the JSON writer of qdot/json.h (RFC 8259: strings, numbers,
 * objects, arrays, true, false, null).
 */
#include "qdot/json.h"

#include "../base/args.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

void qd_json_init(qd_json *j, qd_buf *out) {
    QD_ARGS(, j && out);
    *j = (qd_json){.out = out};
}

static void indent(qd_json *j) {
    qd_buf_puts(j->out, "\n");
    for (unsigned i = 0; i < j->depth; i++)
        qd_buf_puts(j->out, "  ");
}

/* Separator before a value (or a key): a comma after an earlier item, and a
 * new line inside objects.  A value right after its key needs neither. */
static void before_item(qd_json *j) {
    if (j->after_key) {
        j->after_key = false;
        return;
    }
    if (j->depth == 0)
        return;
    uint32_t bit = 1u << (j->depth - 1);
    if (j->has_items & bit)
        qd_buf_puts(j->out, (j->is_object & bit) ? "," : ", ");
    j->has_items |= bit;
    if (j->is_object & bit)
        indent(j);
}

static void open_container(qd_json *j, const char *bracket, bool object) {
    before_item(j);
    if (j->depth >= QD_JSON_MAX_DEPTH) {
        j->failed = true;
        return;
    }
    qd_buf_puts(j->out, bracket);
    uint32_t bit = 1u << j->depth;
    j->has_items &= ~bit;
    j->is_object = object ? (j->is_object | bit) : (j->is_object & ~bit);
    j->depth++;
}

static void close_container(qd_json *j, const char *bracket) {
    if (j->depth == 0) {
        j->failed = true;
        return;
    }
    uint32_t bit = 1u << (j->depth - 1);
    bool lines = (j->is_object & bit) && (j->has_items & bit);
    j->depth--;
    if (lines)
        indent(j);
    qd_buf_puts(j->out, bracket);
}

void qd_json_begin_object(qd_json *j) {
    QD_ARGS(, j); open_container(j, "{", true); }
void qd_json_end_object(qd_json *j) {
    QD_ARGS(, j); close_container(j, "}"); }
void qd_json_begin_array(qd_json *j) {
    QD_ARGS(, j); open_container(j, "[", false); }
void qd_json_end_array(qd_json *j) {
    QD_ARGS(, j); close_container(j, "]"); }

static void put_string(qd_buf *b, const char *s) {
    qd_buf_puts(b, "\"");
    for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
        switch (*p) {
        case '"': qd_buf_puts(b, "\\\""); break;
        case '\\': qd_buf_puts(b, "\\\\"); break;
        case '\n': qd_buf_puts(b, "\\n"); break;
        case '\r': qd_buf_puts(b, "\\r"); break;
        case '\t': qd_buf_puts(b, "\\t"); break;
        case '\b': qd_buf_puts(b, "\\b"); break;
        case '\f': qd_buf_puts(b, "\\f"); break;
        default:
            if (*p < 0x20)
                qd_buf_printf(b, "\\u%04x", *p);
            else
                qd_buf_putn(b, (const char *)p, 1);
        }
    }
    qd_buf_puts(b, "\"");
}

void qd_json_key(qd_json *j, const char *key) {
    QD_ARGS(, j && key);
    before_item(j);
    put_string(j->out, key);
    qd_buf_puts(j->out, ": ");
    j->after_key = true;
}

void qd_json_string(qd_json *j, const char *s) {
    QD_ARGS(, j);
    if (!s) {
        qd_json_null(j);
        return;
    }
    before_item(j);
    put_string(j->out, s);
}

bool qd_json_number(qd_json *j, double v) {
    QD_ARGS(false, j);
    if (!isfinite(v)) {
        j->failed = j->nonfinite = true;
        return false;
    }
    before_item(j);
    /* -0 is valid JSON but surprises readers; it equals 0 anyway */
    if (v == 0)
        v = 0.0;
    /* the shortest digits that read back as the same double: 9.81, not
     * 9.8100000000000005 */
    qd_buf_put_double(j->out, v);
    return true;
}

void qd_json_bool(qd_json *j, bool v) {
    QD_ARGS(, j);
    before_item(j);
    qd_buf_puts(j->out, v ? "true" : "false");
}

void qd_json_null(qd_json *j) {
    QD_ARGS(, j);
    before_item(j);
    qd_buf_puts(j->out, "null");
}

void qd_json_expr(qd_json *j, qd_ctx *ctx, const qd_expr *x) {
    QD_ARGS(, j && ctx);
    if (!x) {
        qd_json_null(j);
        return;
    }
    qd_buf s = QD_BUF_INIT;
    qd_print(ctx, x, QD_FMT_TEXT, &s);
    if (s.failed)
        j->failed = j->nomem = true;
    qd_json_string(j, qd_buf_str(&s));
    qd_buf_free(&s);
}

bool qd_json_ok(const qd_json *j) {
    QD_ARGS(false, j);
    return !j->failed && !j->out->failed && j->depth == 0 && !j->after_key;
}

const char *qd_json_why(const qd_json *j) {
    QD_ARGS(NULL, j);
    if (j->out->failed || j->nomem)
        return "out of memory";
    if (j->nonfinite)
        return "a non-finite number (JSON cannot hold it)";
    return "an unfinished or too deeply nested document";
}

qd_status qd_json_commit(qd_ctx *ctx, qd_buf *b, const qd_json *j, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && b && out);
    bool nomem = b->failed || (j && j->nomem), bad = j && !nomem && !qd_json_ok(j);
    if (!nomem && !bad)
        qd_buf_putn(out, qd_buf_str(b), b->len);
    qd_buf_free(b);
    if (bad) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "cannot write the JSON: %s", qd_json_why(j));
        return QD_ERR_NUMERIC;
    }
    if (nomem || out->failed) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        return QD_ERR_NOMEM;
    }
    return QD_OK;
}

bool qd_json_matrix(qd_json *j, const char *key, size_t rows, size_t cols, const double *x) {
    QD_ARGS(false, j && (x || !rows || !cols));
    bool ok = true;
    if (key)
        qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t i = 0; i < rows; i++) {
        qd_json_begin_array(j);
        for (size_t k = 0; k < cols; k++)
            ok = qd_json_number(j, x[i * cols + k]) && ok;
        qd_json_end_array(j);
    }
    qd_json_end_array(j);
    return ok;
}

void qd_json_number_or_null(qd_json *j, double v) {
    QD_ARGS(, j);
    if (isfinite(v))
        qd_json_number(j, v);
    else
        qd_json_null(j);
}

bool qd_json_vector(qd_json *j, const char *key, size_t n, const double *x) {
    QD_ARGS(false, j && (x || !n));
    bool ok = true;
    if (key)
        qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t i = 0; i < n; i++)
        ok = qd_json_number(j, x[i]) && ok;
    qd_json_end_array(j);
    return ok;
}

void qd_json_frequency(qd_json *j, double w2) {
    QD_ARGS(, j);
    qd_json_key(j, "omega2");
    qd_json_number(j, w2);
    qd_json_key(j, "omega");
    if (w2 >= 0)
        qd_json_number(j, sqrt(w2));
    else
        qd_json_null(j);
    qd_json_key(j, "period");
    if (w2 > 0)
        qd_json_number(j, 2 * 3.14159265358979323846 / sqrt(w2));
    else
        qd_json_null(j);
}
