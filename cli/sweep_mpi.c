/*
 * cli/sweep_mpi.c - qdot sweep shared out across MPI ranks: rank 0 deals
 * chunks of run indices on request and gathers the rows in run order.
 *
 * The protocol is two messages each way.  A worker sends RESULT, a header
 * {first, count} (count 0 at the start: "ready"), followed for count > 0
 * by the chunk's rows and outcomes (qd_sweep_outcome: plain data, sent as
 * bytes between ranks of one build); rank 0 answers each RESULT
 * with WORK, {first, count}, count 0 meaning "stop".  A worker keeps two
 * requests out (it says "ready" twice), so the answer to one arrives while
 * it runs the chunk the other brought: it never waits for rank 0 to finish
 * a run of its own before being served.  Replies from one rank arrive in
 * order and every one after the first "stop" is "stop" too, so a worker
 * ends after the second.  Chunks shrink as the sweep nears its end
 * (cli_mpi_chunk), so a rank that drew slow runs does not keep the others
 * waiting.  With at most SELF_MAX ranks rank 0 also works, one run
 * per thread at a time, serving requests between its runs: on a small job a
 * pure master would leave a core idle; on a larger one serving is the
 * bottleneck, and rank 0 only serves.  Inside each rank qd_sweep_run runs the
 * chunk on its threads.
 */
#define _POSIX_C_SOURCE 200809L
#include "sweep_mpi.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* At most this many runs a chunk: its messages stay far inside MPI's int
 * counts, and rank 0's buffers small. */
#define CHUNK_MAX 65536

size_t cli_mpi_chunk(size_t remaining, int ranks, unsigned threads) {
    size_t share = remaining / (4 * (size_t)(ranks > 0 ? ranks : 1));
    size_t least = threads > 0 ? threads : 1;
    size_t n = share > least ? share : least;
    n = n < CHUNK_MAX ? n : CHUNK_MAX > least ? CHUNK_MAX : least;
    return n < remaining ? n : remaining;
}

/* Every run in this process: the plain (or one-rank) sweep. */
static qd_status run_here(qd_ctx *ctx, const cli_mpi_job *j) {
    return qd_sweep_run(ctx, j->w, j->base, 0, qd_sweep_nruns(j->w), j->nthreads, j->rows,
                        j->outcome, j->progress, j->data);
}

#ifndef QDOT_HAVE_MPI

bool cli_mpi_built(void) { return false; }
bool cli_mpi_launched(void) { return false; }

qd_status cli_mpi_sweep(qd_ctx *ctx, const cli_mpi_job *j, cli_mpi_done *done) {
    *done = (cli_mpi_done){.writer = true, .ranks = 1, .threads = j->nthreads};
    return run_here(ctx, j);
}

#else

#include <mpi.h>
#include <stdio.h>

enum { TAG_RESULT = 1, TAG_ROWS, TAG_OUTCOME, TAG_WORK };
#define SELF_MAX 4 /* rank 0 works too up to this many ranks */
#define AHEAD 2    /* requests a worker keeps out */

bool cli_mpi_built(void) { return true; }

/* OpenMPI's mpirun, MPICH's hydra, PMIx and PMI-2 launchers (srun among
 * them) set these in each rank's environment; a shell never does. */
bool cli_mpi_launched(void) {
    static const char *const vars[] = {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE",
                                       "MPI_LOCALNRANKS"};
    for (size_t i = 0; i < sizeof vars / sizeof vars[0]; i++)
        if (getenv(vars[i]))
            return true;
    return false;
}

/* A failure MPI cannot report through a row: the whole job stops. */
static void die(const char *what, qd_ctx *ctx) {
    const qd_diag *d = ctx ? qd_ctx_diag(ctx) : NULL;
    fprintf(stderr, "qdot: error: sweep: %s%s%s\n", what, d ? ": " : "", d ? d->message : "");
    MPI_Abort(MPI_COMM_WORLD, 1);
}

/* One chunk's results, as a worker holds them before sending. */
typedef struct chunk_buf {
    size_t cap;
    double *rows;
    qd_sweep_outcome *outcome;
} chunk_buf;

static void chunk_buf_grow(chunk_buf *b, size_t count, size_t ncols) {
    if (count <= b->cap)
        return;
    free(b->rows);
    free(b->outcome);
    b->rows = malloc(count * ncols * sizeof *b->rows);
    b->outcome = malloc(count * sizeof *b->outcome);
    if (!b->rows || !b->outcome)
        die("out of memory", NULL);
    b->cap = count;
}

static void chunk_buf_free(chunk_buf *b) {
    free(b->rows);
    free(b->outcome);
}

/* A worker: ask, run, send back (which asks again), until told to stop. */
static void worker(qd_ctx *ctx, const cli_mpi_job *j) {
    size_t ncols = qd_sweep_ncols(j->w);
    chunk_buf b = {0};
    uint64_t hdr[2] = {0, 0};
    for (int k = 0; k < AHEAD; k++)
        MPI_Send(hdr, 2, MPI_UINT64_T, 0, TAG_RESULT, MPI_COMM_WORLD);
    int out = AHEAD;
    while (out > 0) {
        MPI_Recv(hdr, 2, MPI_UINT64_T, 0, TAG_WORK, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        out--;
        size_t first = (size_t)hdr[0], count = (size_t)hdr[1];
        if (count == 0)
            continue; /* the rest of the answers are "stop" too */
        chunk_buf_grow(&b, count, ncols);
        if (qd_sweep_run(ctx, j->w, j->base, first, count, j->nthreads, b.rows, b.outcome, NULL,
                         NULL) != QD_OK)
            die("a worker rank failed", ctx);
        MPI_Send(hdr, 2, MPI_UINT64_T, 0, TAG_RESULT, MPI_COMM_WORLD);
        MPI_Send(b.rows, (int)(count * ncols), MPI_DOUBLE, 0, TAG_ROWS, MPI_COMM_WORLD);
        MPI_Send(b.outcome, (int)(count * sizeof *b.outcome), MPI_BYTE, 0, TAG_OUTCOME,
                 MPI_COMM_WORLD);
        out++;
    }
    chunk_buf_free(&b);
}

/* Rank 0's bookkeeping. */
typedef struct master {
    const cli_mpi_job *j;
    size_t nruns, ncols, next, done;
    int ranks, active;   /* requests not yet answered "stop" */
    unsigned threads;    /* per rank, for the chunk size */
} master;

/* Receive one RESULT from src and place its chunk where its runs go. */
static void master_take(master *m, int src) {
    uint64_t hdr[2];
    MPI_Recv(hdr, 2, MPI_UINT64_T, src, TAG_RESULT, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    size_t first = (size_t)hdr[0], count = (size_t)hdr[1];
    if (count == 0)
        return;
    if (first + count > m->nruns)
        die("a worker sent runs out of range", NULL);
    const cli_mpi_job *j = m->j;
    MPI_Recv(j->rows + first * m->ncols, (int)(count * m->ncols), MPI_DOUBLE, src, TAG_ROWS,
             MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    MPI_Recv(j->outcome + first, (int)(count * sizeof *j->outcome), MPI_BYTE, src, TAG_OUTCOME,
             MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    m->done += count;
    if (j->progress)
        j->progress(j->data, m->done, m->nruns);
}

/* Hand src its next chunk, or tell it to stop. */
static void master_deal(master *m, int src) {
    size_t count = cli_mpi_chunk(m->nruns - m->next, m->ranks, m->threads);
    uint64_t hdr[2] = {m->next, count};
    MPI_Send(hdr, 2, MPI_UINT64_T, src, TAG_WORK, MPI_COMM_WORLD);
    m->next += count;
    if (count == 0)
        m->active--;
}

/* Serve one request: waiting for it when wait, else only one already
 * there.  True when one was served. */
static bool master_serve(master *m, bool wait) {
    MPI_Status s;
    int flag = 1;
    if (wait)
        MPI_Probe(MPI_ANY_SOURCE, TAG_RESULT, MPI_COMM_WORLD, &s);
    else
        MPI_Iprobe(MPI_ANY_SOURCE, TAG_RESULT, MPI_COMM_WORLD, &flag, &s);
    if (!flag)
        return false;
    master_take(m, s.MPI_SOURCE);
    master_deal(m, s.MPI_SOURCE);
    return true;
}

/* Rank 0's own share: a run per thread, so requests wait at most one run. */
static void master_work(qd_ctx *ctx, master *m) {
    const cli_mpi_job *j = m->j;
    size_t count = m->threads;
    if (count > m->nruns - m->next)
        count = m->nruns - m->next;
    size_t first = m->next;
    m->next += count;
    if (qd_sweep_run(ctx, j->w, j->base, first, count, j->nthreads, j->rows + first * m->ncols,
                     j->outcome + first, NULL, NULL) != QD_OK)
        die("rank 0 failed", ctx);
    m->done += count;
    if (j->progress)
        j->progress(j->data, m->done, m->nruns);
}

static void run_master(qd_ctx *ctx, const cli_mpi_job *j, int ranks, unsigned threads) {
    master m = {.j = j, .nruns = qd_sweep_nruns(j->w), .ncols = qd_sweep_ncols(j->w),
                .ranks = ranks, .active = AHEAD * (ranks - 1), .threads = threads};
    bool self = ranks <= SELF_MAX;
    while (m.active > 0 || (self && m.next < m.nruns)) {
        if (self && m.next < m.nruns) {
            while (master_serve(&m, false))
                ;
            master_work(ctx, &m);
        } else {
            master_serve(&m, true);
        }
    }
}

/* Threads per rank: as asked, and one when not (a launcher starts a rank
 * per core, so all cores in every rank would oversubscribe the node). */
static unsigned rank_threads(unsigned asked) { return asked > 0 ? asked : 1; }

qd_status cli_mpi_sweep(qd_ctx *ctx, const cli_mpi_job *j, cli_mpi_done *done) {
    *done = (cli_mpi_done){.writer = true, .ranks = 1, .threads = j->nthreads};
    if (!cli_mpi_launched())
        return run_here(ctx, j);
    int provided, rank, ranks;
    MPI_Init_thread(NULL, NULL, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    cli_mpi_job one = *j;
    one.nthreads = rank_threads(j->nthreads);
    qd_status st = QD_OK;
    if (ranks == 1)
        st = run_here(ctx, &one);
    else if (rank == 0)
        run_master(ctx, &one, ranks, one.nthreads);
    else
        worker(ctx, &one);
    *done = (cli_mpi_done){.writer = rank == 0, .ranks = ranks, .threads = one.nthreads};
    MPI_Finalize();
    return st;
}

#endif
