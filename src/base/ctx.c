/*
 * src/base/ctx.c - the context's bottom layer (ctx.h): creation and
 * release, the allocation path that records out of memory, the error record
 * and the status strings.  The expression kernel's part of a context (its
 * unique table) is attached by src/sym; nothing here knows it.
 */
#include "ctx.h"
#include "mem.h"
#include "args.h"
#include "diag.h" /* qd__diag_line_col */

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

qd_ctx *qd__ctx_create(const qd_allocator *a) {
    qd_ctx *ctx = qd__mem_calloc(a, 1, sizeof *ctx);
    if (!ctx)
        return NULL;
    ctx->alloc = a;
    qd__arena_init(&ctx->arena, a);
    return ctx;
}

void qd_ctx_free(qd_ctx *ctx) {
    if (!ctx)
        return;
    if (ctx->detach)
        ctx->detach(ctx);
    qd__arena_free(&ctx->arena);
    qd__free(ctx);
}

void qd_ctx_set_progress(qd_ctx *ctx, qd_progress_fn fn, void *data) {
    if (!ctx)
        return;
    ctx->progress = fn;
    ctx->progress_data = fn ? data : NULL;
}

int qd__ctx_progress(qd_ctx *ctx, const char *what, size_t done, size_t total) {
    return ctx && ctx->progress ? ctx->progress(ctx->progress_data, what, done, total) : 0;
}

/* ---- the context's allocation path (mem.h) ------------------------------ */

void qd__oom(qd_ctx *ctx) { qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory"); }

void *qd__alloc(qd_ctx *ctx, size_t size) {
    void *p = qd__arena_alloc(&ctx->arena, size);
    if (!p)
        qd__oom(ctx);
    return p;
}

const qd_allocator *qd__ctx_allocator(const qd_ctx *ctx) { return ctx->alloc; }

void *qd__malloc(qd_ctx *ctx, size_t size) {
    void *p = qd__mem_malloc(ctx->alloc, size);
    if (!p)
        qd__oom(ctx);
    return p;
}

void *qd__calloc(qd_ctx *ctx, size_t n, size_t size) {
    void *p = qd__mem_calloc(ctx->alloc, n, size);
    if (!p)
        qd__oom(ctx);
    return p;
}

void *qd__realloc(qd_ctx *ctx, void *p, size_t size) {
    void *q = qd__mem_realloc(ctx->alloc, p, size);
    if (!q)
        qd__oom(ctx);
    return q;
}

char *qd__strdup(qd_ctx *ctx, const char *s) {
    size_t n = strlen(s) + 1;
    char *d = qd__malloc(ctx, n);
    if (d)
        memcpy(d, s, n);
    return d;
}

/* ---- the error record (qdot/expr.h, qdot/status.h) ------------------------ */

qd_status qd_ctx_status(const qd_ctx *ctx) { QD_ARGS(QD_ERR_ARG, ctx); return ctx->status; }
const char *qd_ctx_message(const qd_ctx *ctx) { QD_ARGS("", ctx); return ctx->diag.message; }
const qd_diag *qd_ctx_diag(const qd_ctx *ctx) { QD_ARGS(NULL, ctx); return &ctx->diag; }

void qd_ctx_clear_error(qd_ctx *ctx) {
    QD_ARGS(, ctx);
    ctx->status = QD_OK;
    memset(&ctx->diag, 0, sizeof ctx->diag);
}

bool qd__ctx_nomem(const qd_ctx *ctx) { return ctx->status == QD_ERR_NOMEM; }

bool qd__ctx_recover(qd_ctx *ctx) {
    if (ctx->status == QD_ERR_NOMEM)
        return false;
    qd_ctx_clear_error(ctx);
    return true;
}

void qd_ctx_error(qd_ctx *ctx, qd_status st, const char *fmt, ...) {
    QD_ARGS(, ctx && fmt);
    if (ctx->status != QD_OK)
        return; /* the first error is the one that explains the rest */
    ctx->status = st;
    memset(&ctx->diag, 0, sizeof ctx->diag);
    ctx->diag.status = st;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(ctx->diag.message, sizeof ctx->diag.message, fmt, ap);
    va_end(ap);
}

void qd_ctx_error_about(qd_ctx *ctx, qd_subject subject, size_t index, const char *name,
                        qd_reason why, const char *hint) {
    QD_ARGS(, ctx);
    qd_diag *d = &ctx->diag;
    if (ctx->status == QD_OK || (d->subject != QD_SUBJECT_NONE && d->subject != QD_SUBJECT_TEXT))
        return; /* no error to qualify, or it already says what it is about */
    d->subject = subject;
    d->index = index;
    snprintf(d->name, sizeof d->name, "%s", name ? name : "");
    d->reason = why;
    if (hint)
        snprintf(d->hint, sizeof d->hint, "%s", hint);
}

void qd_ctx_error_at(qd_ctx *ctx, const char *text, size_t offset, size_t length) {
    QD_ARGS(, ctx && text);
    qd_diag *d = &ctx->diag;
    if (ctx->status == QD_OK || d->located || !text)
        return;
    size_t n = strlen(text);
    d->located = true;
    d->offset = offset < n ? offset : n;
    d->length = length ? length : 1;
    qd__diag_line_col(text, d->offset, &d->line, &d->col, NULL); /* \n, \r\n or \r */
    if (d->subject == QD_SUBJECT_NONE)
        d->subject = QD_SUBJECT_TEXT;
}

void qd__ctx_restore(qd_ctx *ctx, const qd_diag *d) {
    ctx->diag = *d;
    ctx->status = d->status;
}

const char *qd_status_str(qd_status st) {
    switch (st) {
    case QD_OK: return "ok";
    case QD_ERR_NOMEM: return "out of memory";
    case QD_ERR_DIVZERO: return "division by zero";
    case QD_ERR_ARG: return "invalid argument";
    case QD_ERR_PARSE: return "syntax error";
    case QD_ERR_NONLINEAR: return "not linear";
    case QD_ERR_UNBOUND: return "symbol without a value";
    case QD_ERR_SINGULAR: return "singular matrix";
    case QD_ERR_NUMERIC: return "numerical failure";
    case QD_ERR_TOOBIG: return "result too large";
    case QD_ERR_UNSUPPORTED: return "not supported here";
    case QD_ERR_IO: return "write error";
    }
    return "unknown status";
}
