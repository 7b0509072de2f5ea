/*
 * src/sweep/mpi.c - qd_sweep_run_all (and qd_sweep_result_run, the same
 * into arrays of its own): a sweep in this process, or shared
 * across the ranks of an MPI job by the optional module qdot_mpi.so
 * (modules/mpi.c, which holds the protocol; src/sweep/ext.h), opened only
 * under a launcher.
 */
#include <dlfcn.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>

#include "base/args.h"
#include "base/module.h"
#include "ext.h"
#include "sweep_int.h"

/* At most this many runs a chunk: its messages stay far inside MPI's int
 * counts, and rank 0's buffers small. */
#define CHUNK_MAX 65536

size_t qd_sweep_mpi_chunk(size_t remaining, int ranks, unsigned threads) {
    size_t share = remaining / (4 * (size_t)(ranks > 0 ? ranks : 1));
    size_t least = threads > 0 ? threads : 1;
    size_t n = share > least ? share : least;
    n = n < CHUNK_MAX ? n : CHUNK_MAX > least ? CHUNK_MAX : least;
    return n < remaining ? n : remaining;
}

/* OpenMPI's mpirun, MPICH's hydra, PMIx and PMI-2 launchers (srun among
 * them) set these in each rank's environment; a shell never does. */
bool qd_sweep_mpi_launched(void) {
    static const char *const vars[] = {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE",
                                       "MPI_LOCALNRANKS"};
    for (size_t i = 0; i < sizeof vars / sizeof vars[0]; i++)
        if (getenv(vars[i]))
            return true;
    return false;
}

/* What a rank's chunks run with: the module calls back into run_chunk. */
typedef struct mpi_ctx {
    qd_ctx *ctx;
    const qd_sweep *w;
    const qd_sim_opts *base;
    unsigned nthreads;
    qd_sweep_progress progress;
    void *data;
} mpi_ctx;

static qd_status run_chunk(void *data, size_t first, size_t count, double *rows,
                           qd_sweep_outcome *outcome) {
    mpi_ctx *c = data;
    return qd_sweep_run(c->ctx, c->w, c->base, first, count, c->nthreads, rows, outcome, NULL,
                        NULL);
}

/* The writer's progress under a launcher: a stop is not heeded (the
 * ranks share the runs; qd_sweep_progress). */
static void progress(void *data, size_t done, size_t total) {
    mpi_ctx *c = data;
    if (c->progress)
        (void)c->progress(c->data, done, total);
}

qd_status qd_sweep_run_all(qd_ctx *ctx, const qd_sweep *w, const qd_sim_opts *base,
                           unsigned nthreads, double *rows, qd_sweep_outcome *outcome,
                           qd_sweep_progress prog, void *data,
                           qd_sweep_where *where) {
    QD_ARGS_CTX(ctx, ctx && w && base && rows && outcome && where);
    *where = (qd_sweep_where){.writer = true, .ranks = 1, .threads = nthreads};
    if (qd_sweep_mpi_launched()) {
        /* RTLD_GLOBAL: OpenMPI opens plug-ins of its own that need libmpi's
         * symbols in the global scope */
        void *h = qd__module_open(ctx, "mpi", RTLD_GLOBAL, QD__EXT_ABI, "MPI",
                                  "libopenmpi-dev");
        qd__mpi_sweep_fn sweep = NULL;
        if (!h || !qd__module_fn(ctx, h, "qdot_mpi.so", "qd_ext_mpi_sweep", &sweep, sizeof sweep)) {
            char why[512];
            snprintf(why, sizeof why, "%s", qd_ctx_diag(ctx)->message);
            qd_ctx_clear_error(ctx); /* the first error wins: this one says more */
            qd_ctx_error(ctx, QD_ERR_UNSUPPORTED,
                         "started by an MPI launcher, but %s; run it without mpirun", why);
            return QD_ERR_UNSUPPORTED;
        }
        /* a launcher starts a rank per core: all cores in every rank
         * would oversubscribe the node, so one thread unless asked */
        mpi_ctx c = {.ctx = ctx, .w = w, .base = base, .nthreads = nthreads > 0 ? nthreads : 1,
                     .progress = prog, .data = data};
        qd__mpi_job job = {.nruns = w->nruns, .ncols = w->ncols, .nthreads = c.nthreads,
                           .rows = rows, .outcome = outcome, .run = run_chunk,
                           .progress = progress, .chunk = qd_sweep_mpi_chunk, .data = &c};
        qd__mpi_where got = {.writer = 1, .ranks = 1};
        sweep(&job, &got);
        *where = (qd_sweep_where){.writer = got.writer, .ranks = got.ranks,
                                  .threads = c.nthreads};
        if (got.ranks > 1)
            return QD_OK;
        nthreads = c.nthreads; /* one rank: the sweep runs here, as below */
    }
    return qd_sweep_run(ctx, w, base, 0, w->nruns, nthreads, rows, outcome, prog, data);
}

qd_status qd_sweep_result_run(qd_ctx *ctx, const qd_sweep *w, const qd_sim_opts *base,
                              unsigned nthreads,
                              qd_sweep_progress prog, void *data,
                              qd_sweep_result *r) {
    QD_ARGS_CTX(ctx, ctx && w && base && r);
    *r = (qd_sweep_result){.nruns = w->nruns, .ncols = w->ncols};
    if (r->nruns > SIZE_MAX / (sizeof(double) * (r->ncols + 1) + sizeof *r->outcome)) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "%zu runs do not fit in memory", r->nruns);
        return QD_ERR_NOMEM;
    }
    r->rows = malloc((r->nruns * r->ncols + 1) * sizeof *r->rows);
    r->outcome = malloc((r->nruns + 1) * sizeof *r->outcome);
    if (!r->rows || !r->outcome) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory for %zu runs", r->nruns);
        return QD_ERR_NOMEM;
    }
    qd_status st = qd_sweep_run_all(ctx, w, base, nthreads, r->rows, r->outcome, prog, data,
                                    &r->where);
    for (size_t k = 0; st == QD_OK && r->where.writer && k < r->nruns; k++)
        r->failed += r->outcome[k].status != QD_OK;
    /* the threads the pool started: asked for (0: the cores), at most the runs */
    r->threads = r->where.ranks > 1 ? r->where.threads
                                    : qd_sweep_threads(r->where.threads, r->nruns);
    return st;
}

qd_status qd_sweep_result_check(qd_ctx *ctx, const qd_sweep_result *r) {
    QD_ARGS_CTX(ctx, ctx && r);
    if (!r->where.writer || !r->nruns || r->failed < r->nruns)
        return QD_OK;
    char why[QD_SWEEP_OUTCOME_MAX];
    qd_ctx_error(ctx, QD_ERR_NUMERIC, "every run failed (the first: %s)",
                 qd_sweep_outcome_str(&r->outcome[0], why, sizeof why));
    return QD_ERR_NUMERIC;
}

void qd_sweep_result_free(qd_sweep_result *r) {
    if (!r)
        return;
    free(r->rows);
    free(r->outcome);
    r->rows = NULL;
    r->outcome = NULL;
}
