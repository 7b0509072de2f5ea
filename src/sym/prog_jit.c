/*
 * src/sym/prog_jit.c - qd_prog_jit: a program's machine code by the JIT
 * module (modules/llvm.c over LLVM's ORC, src/sym/jit.h), opened on first
 * use so that only a call that compiles loads LLVM.
 */
#define _POSIX_C_SOURCE 200809L
#include "prog_int.h"
#include "sym_export.h"
#include "base/module.h"
#include "../base/args.h"

#include <dlfcn.h>
#include <pthread.h>
#include <stdio.h>

typedef const qd__jit_ops *(*ops_fn)(void);

static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
static const qd__jit_ops *ops; /* set once, under lock */

/* The module's operations, or NULL with why in ctx. */
static const qd__jit_ops *jit_ops(qd_ctx *ctx) {
    pthread_mutex_lock(&lock);
    const qd__jit_ops *o = ops;
    if (!o) {
        void *h = qd__module_open(ctx, "llvm", 0, QD__JIT_ABI, "the JIT (LLVM)", "llvm-14-dev");
        ops_fn fn = NULL;
        if (h && qd__module_fn(ctx, h, "qdot_llvm.so", "qd_ext_llvm_ops", &fn, sizeof fn))
            o = ops = fn();
    }
    pthread_mutex_unlock(&lock);
    return o;
}

/* Under lock: one compile of a program even when two runs tier up at once. */
qd_status qd_prog_jit(qd_ctx *ctx, qd_prog *p) {
    QD_ARGS_CTX(ctx, ctx && p);
    if (atomic_load_explicit(&p->jit, memory_order_acquire))
        return QD_OK;
    const qd__jit_ops *o = jit_ops(ctx);
    if (!o)
        return QD_ERR_UNSUPPORTED;
    static const qd__jit_env env = {qd__pow_value, qd__step_value};
    char err[512] = "";
    qd_status st = QD_OK;
    pthread_mutex_lock(&lock);
    if (!atomic_load_explicit(&p->jit, memory_order_relaxed)) {
        qd__jit_fn fn = NULL;
        void *code = o->compile(p, &env, &fn, err, sizeof err);
        if (code) {
            p->jit_code = code;
            atomic_store_explicit(&p->jit, fn, memory_order_release);
        } else {
            st = QD_ERR_UNSUPPORTED;
        }
    }
    pthread_mutex_unlock(&lock);
    if (st != QD_OK)
        qd_ctx_error(ctx, st, "the JIT did not compile the program: %s", err);
    return st;
}

qd_status qd__prog_jit_spd(qd_ctx *ctx, qd_prog *p, size_t n, double tol) {
    QD_ARGS_CTX(ctx, ctx && p);
    if (atomic_load_explicit(&p->spd, memory_order_acquire))
        return QD_OK;
    const qd__jit_ops *o = jit_ops(ctx);
    if (!o)
        return QD_ERR_UNSUPPORTED;
    if (p->nout < n * n + n) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the program has %zu outputs, not an %zu-by-%zu M and f",
                     p->nout, n, n);
        return QD_ERR_ARG;
    }
    static const qd__jit_env env = {qd__pow_value, qd__step_value};
    char err[512] = "";
    qd_status st = QD_OK;
    pthread_mutex_lock(&lock);
    if (!atomic_load_explicit(&p->spd, memory_order_relaxed)) {
        qd__jit_spd_fn fn = NULL;
        void *code = o->compile_spd(p, n, tol, &env, &fn, err, sizeof err);
        if (code) {
            p->spd_code = code;
            atomic_store_explicit(&p->spd, fn, memory_order_release);
        } else {
            st = QD_ERR_UNSUPPORTED;
        }
    }
    pthread_mutex_unlock(&lock);
    if (st != QD_OK)
        qd_ctx_error(ctx, st, "the JIT did not compile the program and its solve: %s", err);
    return st;
}

qd__jit_spd_fn qd__prog_spd(const qd_prog *p) {
    return atomic_load_explicit(&p->spd, memory_order_acquire);
}

bool qd_prog_jitted(const qd_prog *p) {
    return p && atomic_load_explicit(&p->jit, memory_order_acquire) != NULL;
}

void qd__prog_jit_release(qd_prog *p) {
    if (p->jit_code && ops)
        ops->release(p->jit_code);
    p->jit_code = NULL;
    atomic_store_explicit(&p->jit, NULL, memory_order_relaxed);
    if (p->spd_code && ops)
        ops->release(p->spd_code);
    p->spd_code = NULL;
    atomic_store_explicit(&p->spd, NULL, memory_order_relaxed);
}
