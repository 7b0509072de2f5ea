/* src/base/buf.c - the growable string of qdot/print.h. */
#include "qdot/print.h"
#include "mem.h"
#include "args.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void qd_buf_free(qd_buf *b) {
    QD_ARGS(, b);
    qd__free(b->s);
    b->s = NULL;
    b->len = b->cap = 0;
    b->failed = false;
}

void qd_buf_clear(qd_buf *b) {
    QD_ARGS(, b);
    b->len = 0;
    if (b->s)
        b->s[0] = '\0';
    b->failed = false;
}

static bool reserve(qd_buf *b, size_t extra) {
    if (b->failed)
        return false;
    if (b->len + extra + 1 <= b->cap)
        return true;
    size_t cap = b->cap ? b->cap : 64;
    while (cap < b->len + extra + 1)
        cap *= 2;
    char *s = qd__mem_realloc(b->alloc, b->s, cap);
    if (!s) {
        b->failed = true;
        return false;
    }
    b->s = s;
    b->cap = cap;
    return true;
}

void qd_buf_putn(qd_buf *b, const char *s, size_t n) {
    QD_ARGS(, b && s);
    if (!reserve(b, n))
        return;
    memcpy(b->s + b->len, s, n);
    b->len += n;
    b->s[b->len] = '\0';
}

void qd_buf_puts(qd_buf *b, const char *s) { QD_ARGS(, b && s); qd_buf_putn(b, s, strlen(s)); }

void qd_buf_printf(qd_buf *b, const char *fmt, ...) {
    QD_ARGS(, b && fmt);
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (n < 0 || !reserve(b, (size_t)n))
        return;
    va_start(ap, fmt);
    vsnprintf(b->s + b->len, (size_t)n + 1, fmt, ap);
    va_end(ap);
    b->len += (size_t)n;
}

const char *qd_buf_str(const qd_buf *b) { QD_ARGS("", b); return b->s ? b->s : ""; }
