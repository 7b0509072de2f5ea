/*
 * src/base/ctx.h - the context as the bottom layer knows it: where memory
 * comes from (the allocator and the arena), the first error's record, and
 * one slot for the expression kernel above it.
 *
 * The context is created in two steps so that base never calls up: the
 * kernel's constructor (qd_ctx_new_with, src/sym/intern.c) asks base for a
 * bare context (qd__ctx_create), then attaches its own state, the unique
 * table, the interned names and the constants, in ctx->sym, with the
 * function that releases it in ctx->detach.  qd_ctx_free (ctx.c) calls that
 * hook, then frees what base owns.  Base reads neither field otherwise.
 */
#ifndef QD_BASE_CTX_H
#define QD_BASE_CTX_H

#include "qdot/expr.h"
#include "arena.h"

struct qd__sym_state; /* src/sym/node.h */

struct qd_ctx {
    const qd_allocator *alloc;   /* NULL: the C library's (mem.h) */
    qd__arena arena;              /* nodes and names, freed with the context */
    qd_status status;
    qd_diag diag;                /* the first error's record; diag.status == status */
    struct qd__sym_state *sym;   /* the kernel's state, attached by src/sym */
    void (*detach)(qd_ctx *ctx); /* releases sym (qd_ctx_free); NULL: nothing attached */
    qd_progress_fn progress;     /* qd_ctx_set_progress's, NULL: none */
    void *progress_data;
};

/* A context with nothing attached (allocator a, empty arena, no error);
 * NULL when out of memory. */
qd_ctx *qd__ctx_create(const qd_allocator *a);

/* size bytes from the context's arena (freed with the context); NULL with
 * QD_ERR_NOMEM recorded when out of memory. */
void *qd__alloc(qd_ctx *ctx, size_t size);
/* The error record d put back as the context's (an alternative tried and
 * abandoned must not leave its own error). */
void qd__ctx_restore(qd_ctx *ctx, const qd_diag *d);
/* Records QD_ERR_NOMEM ("out of memory"). */
void qd__oom(qd_ctx *ctx);

#endif
