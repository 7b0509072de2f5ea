/*
 * src/base/arena.h - a bump allocator: many small allocations, one free.
 *
 * The symbolic context puts every node here; nodes live as long as the
 * context, so there is no per-node free and no fragmentation.
 */
#ifndef QD_BASE_ARENA_H
#define QD_BASE_ARENA_H

#include <stddef.h>
#include "mem.h"

typedef struct qd__arena_block qd__arena_block;

typedef struct qd__arena {
    qd__arena_block *head;
    size_t used;       /* bytes used in head */
    size_t total;      /* bytes handed out over all blocks */
    const qd_allocator *al; /* where blocks come from (mem.h) */
} qd__arena;

void qd__arena_init(qd__arena *a, const qd_allocator *al);
/* size bytes aligned for any object; NULL when out of memory. */
void *qd__arena_alloc(qd__arena *a, size_t size);
void qd__arena_free(qd__arena *a);

#endif
