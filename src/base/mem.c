/* src/base/mem.c - see mem.h. */
#include "mem.h"

#include <stdalign.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Sized and aligned so the block after it is aligned for any object. */
typedef struct header {
    alignas(max_align_t) const qd_allocator *a;
} header;

static void *libc_malloc(void *user, size_t size) {
    (void)user;
    return malloc(size);
}

static void *libc_realloc(void *user, void *p, size_t size) {
    (void)user;
    return realloc(p, size);
}

static void libc_free(void *user, void *p) {
    (void)user;
    free(p);
}

static const qd_allocator libc_allocator = {libc_malloc, libc_realloc, libc_free, NULL};

static header *header_of(void *p) { return (header *)p - 1; }

void *qd__mem_malloc(const qd_allocator *a, size_t size) {
    if (!a)
        a = &libc_allocator;
    if (size > SIZE_MAX - sizeof(header))
        return NULL;
    header *h = a->malloc_fn(a->user, sizeof *h + size);
    if (!h)
        return NULL;
    h->a = a;
    return h + 1;
}

void *qd__mem_calloc(const qd_allocator *a, size_t n, size_t size) {
    if (size && n > SIZE_MAX / size)
        return NULL;
    void *p = qd__mem_malloc(a, n * size);
    if (p)
        memset(p, 0, n * size);
    return p;
}

void *qd__mem_realloc(const qd_allocator *a, void *p, size_t size) {
    if (!p)
        return qd__mem_malloc(a, size);
    if (size > SIZE_MAX - sizeof(header))
        return NULL;
    header *h = header_of(p);
    const qd_allocator *own = h->a;
    h = own->realloc_fn(own->user, h, sizeof *h + size);
    return h ? h + 1 : NULL; /* the header moved with the block */
}

void qd__free(void *p) {
    if (!p)
        return;
    header *h = header_of(p);
    h->a->free_fn(h->a->user, h);
}
