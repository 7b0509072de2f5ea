/*
 * src/base/mem.h - the library's one allocation path (SQLite's malloc.c).
 *
 * Every block the library allocates carries, in a small header before it,
 * the allocator it came from, so it can be resized or freed by whoever holds
 * it, with or without its context at hand: qd__free needs only the pointer.
 * A NULL allocator is the C library's.  Memory from this path must be freed
 * by qd__free, never by free(), and the other way round.
 *
 * The qd_ctx forms record QD_ERR_NOMEM in the context when they fail; they
 * are what the library's modules call.  The qd__mem_ forms are for the base
 * containers (arena, ptrmap, buf), which know an allocator but no context.
 */
#ifndef QD_BASE_MEM_H
#define QD_BASE_MEM_H

#include <stdbool.h>
#include <stddef.h>
#include "qdot/expr.h"
#include "mem.h"

void *qd__mem_malloc(const qd_allocator *a, size_t size);
void *qd__mem_calloc(const qd_allocator *a, size_t n, size_t size);
/* p NULL: a fresh block from a; otherwise p's own allocator (a unused). */
void *qd__mem_realloc(const qd_allocator *a, void *p, size_t size);
void qd__free(void *p);  /* NULL is fine */

const qd_allocator *qd__ctx_allocator(const qd_ctx *ctx);
void *qd__malloc(qd_ctx *ctx, size_t size);
void *qd__calloc(qd_ctx *ctx, size_t n, size_t size);
void *qd__realloc(qd_ctx *ctx, void *p, size_t size);
char *qd__strdup(qd_ctx *ctx, const char *s);

/* Out of memory is the one error a caller must never clear on its way to a
 * fallback (a fallback taken for want of memory gives a wrong answer, not a
 * clean QD_ERR_NOMEM).  qd__ctx_recover clears any other error and returns
 * true; with QD_ERR_NOMEM recorded it leaves it and returns false. */
bool qd__ctx_nomem(const qd_ctx *ctx);
bool qd__ctx_recover(qd_ctx *ctx);
/* Report done of total steps of what to the context's progress function
 * (qd_ctx_set_progress, ctx.c); nonzero when it asks to stop (0 without one). */
int qd__ctx_progress(qd_ctx *ctx, const char *what, size_t done, size_t total);

#endif
