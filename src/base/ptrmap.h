/*
 * src/base/ptrmap.h - a hash map from pointers to pointers.
 *
 * The memo of every DAG walk (derivative, substitution, evaluation,
 * printing): each shared node is visited once because its result is found
 * here the second time.
 */
#ifndef QD_BASE_PTRMAP_H
#define QD_BASE_PTRMAP_H

#include <stddef.h>
#include <stdbool.h>
#include "mem.h"

typedef struct qd__ptrmap_slot {
    const void *key;
    void *val;
} qd__ptrmap_slot;

typedef struct qd__ptrmap {
    qd__ptrmap_slot *slots;
    size_t cap;   /* a power of two, or 0 */
    size_t len;
    const qd_allocator *al; /* where slots come from (mem.h) */
} qd__ptrmap;

#define QD_PTRMAP_INIT {NULL, 0, 0, NULL}      /* the C library's memory */
#define QD_PTRMAP_AL(a) {NULL, 0, 0, (a)}       /* a context's: qd__ctx_allocator(ctx) */

void qd__ptrmap_free(qd__ptrmap *m);
void qd__ptrmap_clear(qd__ptrmap *m);
/* The value stored for key, or NULL (keys must not be NULL). */
void *qd__ptrmap_get(const qd__ptrmap *m, const void *key);
bool qd__ptrmap_has(const qd__ptrmap *m, const void *key);
/* Insert or replace; false when out of memory. */
bool qd__ptrmap_put(qd__ptrmap *m, const void *key, void *val);

#endif
