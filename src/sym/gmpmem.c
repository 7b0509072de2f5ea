/*
 * src/sym/gmpmem.c - GMP's and FLINT's allocations answer to the context
 * (see node.h, qd__gmp_enter; docs/design.md, "Allocation and
 * out-of-memory").
 *
 * GMP's and FLINT's allocation functions may not return NULL, and unwinding
 * out of them with longjmp is undefined (GMP manual, "Custom Allocation"), so
 * qdot never makes them fail.  Instead:
 *
 *  - size guards refuse the operations that would ask for more than a
 *    documented bound before GMP or FLINT is called (QD_EXPAND_MAX_BYTES in
 *    poly.h, QD_MAX_FOLD_BITS in node.h);
 *  - hooks, installed once and chained to the functions they replace (so a
 *    block is always made and freed by the same functions, whoever installed
 *    them first), ask the context's own allocator for every request of at
 *    least QD_GMP_PROBE_MIN bytes made inside a section (qd__gmp_enter /
 *    qd__gmp_leave) on this thread.  When the context's allocator refuses, the
 *    request is still served (by the chained function) so that GMP and FLINT
 *    finish with consistent values, and the section's end reports
 *    QD_ERR_NOMEM: its caller discards what was computed.
 *
 * A context on the C library's allocator is not asked (GMP's request is the
 * same malloc); a request the C library itself cannot meet still ends in GMP's
 * or FLINT's abort, which the guards are there to prevent.
 */
#include "node.h"
#include "../base/mem.h"

#include <flint/flint.h>
#include <gmp.h>
#include <pthread.h>

static _Thread_local qd__gmp_section cur;

static void *(*gmp_alloc)(size_t);
static void *(*gmp_realloc)(void *, size_t, size_t);
static void (*gmp_free)(void *, size_t);
static void *(*fl_alloc)(size_t);
static void *(*fl_calloc)(size_t, size_t);
static void *(*fl_realloc)(void *, size_t);
static void (*fl_free)(void *);

/* May this thread's section have size more bytes?  Asked of its context's
 * allocator; a refusal is remembered, not returned. */
static void ask(size_t size) {
    if (!cur.ctx || cur.refused || size < QD_GMP_PROBE_MIN)
        return;
    const qd_allocator *a = qd__ctx_allocator(cur.ctx);
    if (!a)
        return;
    void *p = a->malloc_fn(a->user, size);
    if (p)
        a->free_fn(a->user, p);
    else
        cur.refused = true;
}

static void *hook_gmp_alloc(size_t n) {
    ask(n);
    return gmp_alloc(n);
}

static void *hook_gmp_realloc(void *p, size_t old, size_t n) {
    if (n > old)
        ask(n);
    return gmp_realloc(p, old, n);
}

static void *hook_fl_alloc(size_t n) {
    ask(n);
    return fl_alloc(n);
}

static void *hook_fl_calloc(size_t n, size_t size) {
    ask(size && n > SIZE_MAX / size ? SIZE_MAX : n * size);
    return fl_calloc(n, size);
}

static void *hook_fl_realloc(void *p, size_t n) {
    ask(n);
    return fl_realloc(p, n);
}

static void install(void) {
    mp_get_memory_functions(&gmp_alloc, &gmp_realloc, &gmp_free);
    mp_set_memory_functions(hook_gmp_alloc, hook_gmp_realloc, gmp_free);
    __flint_get_memory_functions(&fl_alloc, &fl_calloc, &fl_realloc, &fl_free);
    __flint_set_memory_functions(hook_fl_alloc, hook_fl_calloc, hook_fl_realloc, fl_free);
}

void qd__gmp_install(void) {
    static pthread_once_t once = PTHREAD_ONCE_INIT;
    pthread_once(&once, install);
}

qd__gmp_section qd__gmp_enter(qd_ctx *ctx) {
    qd__gmp_section outer = {cur.ctx, cur.refused};
    cur.ctx = ctx;
    cur.refused = false;
    return outer;
}

bool qd__gmp_leave(qd_ctx *ctx, qd__gmp_section outer) {
    bool refused = cur.refused;
    cur.ctx = outer.ctx;
    cur.refused = outer.refused || (refused && outer.ctx == ctx);
    if (refused && ctx)
        qd__oom(ctx);
    return !refused;
}
