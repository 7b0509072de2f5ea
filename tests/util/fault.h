/*
 * tests/util/fault.h - every allocation made to fail, one at a time (SQLite's
 * test/exprfault.test, Lua's testes/memerr.lua): the failing allocator and the
 * loop that the fault tests share (tests/fault, scatter, action, hj, orbit).
 *
 * A context gets an allocator (qd_ctx_new_with) that refuses its Nth request;
 * the body runs for N = 1, 1 + stride, ... until it gets through without the
 * refusal being reached.  Each run must end with the right answer (the body
 * checks it) or a clean QD_ERR_NOMEM, recorded in the context too, and with
 * every block given back; a success must not leave QD_ERR_NOMEM recorded.
 */
#ifndef QT_FAULT_H
#define QT_FAULT_H

#include <stdbool.h>
#include "qdot/qdot.h"

typedef struct qt_faulty {
    long count;    /* requests so far (malloc and realloc) */
    long fail_at;  /* the request to refuse, 0: none */
    long live;     /* blocks outstanding */
    bool failed;   /* fail_at was reached */
} qt_faulty;

/* The allocator whose user is f: malloc, realloc and free of the C library,
 * counted, with request f->fail_at refused.  A context keeps a pointer to it,
 * so it must outlive the context. */
qd_allocator qt_faulty_allocator(qt_faulty *f);

/* Set-up a loop is not about (a parse, a derivation with a loop of its own):
 * qt_fault_hold stops the refusals and returns how many requests were still
 * to go; qt_fault_release re-arms them that many requests on. */
long qt_fault_hold(qt_faulty *f);
void qt_fault_release(qt_faulty *f, long to_go);

/* One run: QD_OK with the answer checked, or the status it failed with. */
typedef qd_status (*qt_fault_body)(qd_ctx *ctx, qt_faulty *f, void *data);

typedef struct qt_fault_stats {
    long runs, nomem; /* runs, and those that ended out of memory */
    long allocs;      /* requests of the run that succeeded */
} qt_fault_stats;

/* Runs body(ctx, f, data) failing request 1, 1 + stride, ... until one is not
 * reached, failing the test on the first run that breaks the rules above, and
 * prints a line of counts and time.  stride > 1: for bodies whose every run
 * re-derives a large model (each loop kept within ~15 s under ASan). */
qt_fault_stats qt_fault_loop(const char *what, qt_fault_body body, void *data, long stride);

#endif
