/* tests/util/fault.c - see fault.h. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "fault.h"

/* ---- the failing allocator ---------------------------------------------- */

static bool refuse(qt_faulty *f) {
    if (++f->count != f->fail_at)
        return false;
    f->failed = true;
    return true;
}

static void *f_malloc(void *user, size_t size) {
    qt_faulty *f = user;
    if (refuse(f))
        return NULL;
    void *p = malloc(size);
    if (p)
        f->live++;
    return p;
}

static void *f_realloc(void *user, void *p, size_t size) {
    return refuse(user) ? NULL : realloc(p, size);
}

static void f_free(void *user, void *p) {
    qt_faulty *f = user;
    f->live--;
    free(p);
}

qd_allocator qt_faulty_allocator(qt_faulty *f) {
    qd_allocator a = {f_malloc, f_realloc, f_free, f};
    return a;
}

long qt_fault_hold(qt_faulty *f) {
    long to_go = f->fail_at > f->count ? f->fail_at - f->count : 0;
    f->fail_at = 0;
    return to_go;
}

void qt_fault_release(qt_faulty *f, long to_go) {
    f->fail_at = to_go > 0 ? f->count + to_go : 0;
}

/* ---- the loop ------------------------------------------------------------ */

/* What one run left: the status returned, and what the context recorded. */
typedef struct run_end {
    qd_status st, recorded;
    char why[256];
} run_end;

static run_end run_once(qt_faulty *f, qt_fault_body body, void *data) {
    qd_allocator a = qt_faulty_allocator(f);
    qd_ctx *ctx = qd_ctx_new_with(&a);
    run_end r = {QD_ERR_NOMEM, QD_ERR_NOMEM, ""}; /* no context: its creation ran out */
    if (ctx) {
        r.st = body(ctx, f, data);
        r.recorded = qd_ctx_status(ctx);
        snprintf(r.why, sizeof r.why, "%s", qd_ctx_message(ctx));
    }
    qd_ctx_free(ctx);
    return r;
}

/* The rules every run keeps; a run that breaks one fails the test. */
static void check_run(const char *what, long n, const qt_faulty *f, const run_end *r) {
    if (f->live != 0)
        fail_msg("%s, allocation %ld failed: %ld blocks leaked", what, n, f->live);
    /* a fallback taken for want of memory: the answer happened to pass, but an
     * error was cleared on the way (or left behind a success) */
    if (r->st == QD_OK && r->recorded == QD_ERR_NOMEM)
        fail_msg("%s, allocation %ld failed: success, but out of memory recorded", what, n);
    if (r->st == QD_OK)
        return;
    if (r->st != QD_ERR_NOMEM)
        fail_msg("%s, allocation %ld failed: status %s instead of out of memory (%s)", what, n,
                 qd_status_str(r->st), r->why);
    if (!f->failed) /* out of memory from somewhere else than the refusal */
        fail_msg("%s, allocation %ld failed: out of memory, but it was never refused (%s)", what,
                 n, r->why);
    if (r->recorded != QD_ERR_NOMEM) /* the context must say why, too */
        fail_msg("%s, allocation %ld failed: out of memory, but the context says %s", what, n,
                 qd_status_str(r->recorded));
}

qt_fault_stats qt_fault_loop(const char *what, qt_fault_body body, void *data, long stride) {
    qt_fault_stats ls = {0, 0, 0};
    clock_t t0 = clock();
    for (long n = 1;; n += stride) {
        qt_faulty f = {0, n, 0, false};
        run_end r = run_once(&f, body, data);
        ls.runs++;
        check_run(what, n, &f, &r);
        ls.nomem += r.st != QD_OK;
        if (!f.failed) {
            assert_int_equal(r.st, QD_OK);
            ls.allocs = f.count;
            break;
        }
    }
    printf("%s: %ld allocations, %ld runs (%ld out of memory), stride %ld, %.2f s\n", what,
           ls.allocs, ls.runs, ls.nomem, stride, (double)(clock() - t0) / CLOCKS_PER_SEC);
    return ls;
}
