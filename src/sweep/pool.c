/*
 * src/sweep/pool.c - runs on a pool of threads.  Dynamic scheduling: each
 * worker takes the next run index from an atomic counter, so a slow run
 * (a chaotic orbit, a run that fails late) holds up one worker, not a
 * block of runs.  Workers share only the counter and the done count; each
 * has its own context for messages, and qd_sim_run_with gives each run its
 * own workspace.  The calling thread only waits and reports progress.
 */
#define _POSIX_C_SOURCE 200809L
#include "sweep_int.h"
#include "../base/args.h"

#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

typedef struct sw_pool {
    const qd_sweep *w;
    const qd_sim_opts *base;
    size_t first, count;
    double *rows;
    qd_sweep_outcome *outcome;
    atomic_size_t next, done;
    pthread_mutex_t lock;  /* with wake: the caller sleeps between runs done */
    pthread_cond_t wake;
    atomic_uint exited;    /* workers that have returned */
    atomic_bool stop;      /* progress said stop: no run starts after it */
} sw_pool;


static void wake(sw_pool *p) {
    pthread_mutex_lock(&p->lock);
    pthread_cond_signal(&p->wake);
    pthread_mutex_unlock(&p->lock);
}

static void runs(sw_pool *p, qd_ctx *ctx) {
    size_t ncols = qd_sweep_ncols(p->w);
    while (!atomic_load(&p->stop)) {
        size_t k = atomic_fetch_add(&p->next, 1);
        if (k >= p->count)
            break;
        qd_sweep_outcome *o = &p->outcome[k];
        o->status = qd_sweep_run_one(ctx, p->w, p->base, p->first + k, p->rows + k * ncols,
                                     &o->stop);
        qd_ctx_clear_error(ctx); /* the outcome holds it; the next run starts clean */
        atomic_fetch_add(&p->done, 1);
        wake(p);
    }
}

static void *worker(void *arg) {
    sw_pool *p = arg;
    qd_ctx *ctx = qd_ctx_new();
    if (ctx)
        runs(p, ctx);
    qd_ctx_free(ctx);
    atomic_fetch_add(&p->exited, 1);
    wake(p);
    return NULL;
}

static unsigned cores(void) {
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n > 0 ? (unsigned)n : 1u;
}

/* Wait for the workers, calling progress when a run is done, at least
 * every 0.1 s (a stop is heard while long runs go on) and at the end. */
static void watch(sw_pool *p, unsigned started, qd_sweep_progress progress, void *data) {
    pthread_mutex_lock(&p->lock);
    for (;;) {
        size_t done = atomic_load(&p->done);
        if (progress) {
            pthread_mutex_unlock(&p->lock);
            if (progress(data, done, p->count) != 0)
                atomic_store(&p->stop, true);
            pthread_mutex_lock(&p->lock);
        }
        if (done >= p->count || atomic_load(&p->exited) == started)
            break;
        struct timespec until;
        clock_gettime(CLOCK_REALTIME, &until);
        until.tv_nsec += 100000000L;
        if (until.tv_nsec >= 1000000000L) {
            until.tv_sec++;
            until.tv_nsec -= 1000000000L;
        }
        if (atomic_load(&p->done) == done && atomic_load(&p->exited) < started)
            pthread_cond_timedwait(&p->wake, &p->lock, &until);
    }
    pthread_mutex_unlock(&p->lock);
}

/* The runs nobody took: stopped by progress, or (every worker could not
 * start: no memory for its context) failures. */
static void untaken(sw_pool *p) {
    bool stopped = atomic_load(&p->stop);
    qd_sweep_outcome o = stopped ? (qd_sweep_outcome){QD_ERR_ARG, {QD_STOP_CALLBACK, NAN, NAN}}
                                 : (qd_sweep_outcome){QD_ERR_NOMEM, {QD_STOP_NONE, NAN, NAN}};
    for (size_t k = atomic_load(&p->next); k < p->count; k++)
        p->outcome[k] = o;
}

static qd_status start(qd_ctx *ctx, sw_pool *p, unsigned nthreads, qd_sweep_progress progress,
                       void *data) {
    pthread_t *tid = calloc(nthreads, sizeof *tid);
    if (!tid) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory starting the sweep's threads");
        return QD_ERR_NOMEM;
    }
    unsigned started = 0;
    for (; started < nthreads; started++)
        if (pthread_create(&tid[started], NULL, worker, p) != 0)
            break;
    if (started == 0) {
        free(tid);
        qd_ctx_error(ctx, QD_ERR_UNSUPPORTED, "could not start a thread for the sweep");
        return QD_ERR_UNSUPPORTED;
    }
    watch(p, started, progress, data);
    for (unsigned k = 0; k < started; k++)
        pthread_join(tid[k], NULL);
    free(tid);
    return QD_OK;
}

unsigned qd_sweep_threads(unsigned nthreads, size_t count) {
    if (nthreads > QD_SWEEP_MAX_THREADS)
        return 0;
    nthreads = nthreads ? nthreads : cores();
    return count < nthreads ? (unsigned)count : nthreads;
}

qd_status qd_sweep_run(qd_ctx *ctx, const qd_sweep *w, const qd_sim_opts *base, size_t first,
                       size_t count, unsigned nthreads, double *rows, qd_sweep_outcome *outcome,
                       qd_sweep_progress progress, void *data) {
    QD_ARGS_CTX(ctx, ctx && w && base && rows && outcome);
    if (first > w->nruns || count > w->nruns - first) {
        qd_ctx_error(ctx, QD_ERR_ARG, "runs %zu to %zu of a sweep of %zu", first, first + count,
                     w->nruns);
        return QD_ERR_ARG;
    }
    if (nthreads > QD_SWEEP_MAX_THREADS) {
        qd_ctx_error(ctx, QD_ERR_ARG, "%u threads: a sweep runs on at most %d (0: one per "
                     "core)", nthreads, QD_SWEEP_MAX_THREADS);
        return QD_ERR_ARG;
    }
    qd_status st = qd__sweep_ready(ctx, w);
    if (st != QD_OK || count == 0)
        return st;
    nthreads = qd_sweep_threads(nthreads, count);
    sw_pool p = {.w = w, .base = base, .first = first, .count = count, .rows = rows,
                 .outcome = outcome};
    atomic_init(&p.next, 0);
    atomic_init(&p.done, 0);
    atomic_init(&p.exited, 0);
    atomic_init(&p.stop, false);
    pthread_mutex_init(&p.lock, NULL);
    pthread_cond_init(&p.wake, NULL);
    st = start(ctx, &p, nthreads, progress, data);
    pthread_cond_destroy(&p.wake);
    pthread_mutex_destroy(&p.lock);
    size_t done = atomic_load(&p.done);
    if (st == QD_OK && done < count)
        untaken(&p);
    if (st == QD_OK && atomic_load(&p.stop) && done < count) {
        qd_ctx_error(ctx, QD_ERR_ARG, "stopped after %zu of %zu runs", done, count);
        st = QD_ERR_ARG;
    }
    return st;
}
