/* src/base/arena.c - see arena.h. */
#include "arena.h"

#include <stdlib.h>
#include <stdalign.h>
#include <stdint.h>

#define QD_ARENA_BLOCK (64u * 1024u)

struct qd__arena_block {
    qd__arena_block *next;
    size_t cap;
    alignas(max_align_t) unsigned char data[];
};

void qd__arena_init(qd__arena *a, const qd_allocator *al) {
    a->al = al;
    a->head = NULL;
    a->used = 0;
    a->total = 0;
}

void *qd__arena_alloc(qd__arena *a, size_t size) {
    const size_t align = alignof(max_align_t);
    size = (size + align - 1) & ~(align - 1);
    if (!a->head || a->head->cap - a->used < size) {
        /* Oversized requests get a block of their own size. */
        size_t cap = size > QD_ARENA_BLOCK ? size : QD_ARENA_BLOCK;
        qd__arena_block *b =
            cap > SIZE_MAX - sizeof *b ? NULL : qd__mem_malloc(a->al, sizeof *b + cap);
        if (!b)
            return NULL;
        b->cap = cap;
        b->next = a->head;
        a->head = b;
        a->used = 0;
    }
    void *p = a->head->data + a->used;
    a->used += size;
    a->total += size;
    return p;
}

void qd__arena_free(qd__arena *a) {
    qd__arena_block *b = a->head;
    while (b) {
        qd__arena_block *next = b->next;
        qd__free(b);
        b = next;
    }
    qd__arena_init(a, a->al);
}
