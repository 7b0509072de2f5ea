/*
 * modules/mpi.c - qdot_mpi.so: one sweep shared out across the ranks of an
 * MPI job (`mpirun -np N qdot sweep ...`).  libqdot opens it only under a
 * launcher (qd_sweep_run_all, src/sweep/mpi.c); the interface is
 * src/sweep/ext.h, and this file calls nothing of libqdot's.
 *
 * Rank 0 deals chunks of run indices on request and gathers the rows in
 * run order.  The protocol is two messages each way.  A worker sends
 * RESULT, a header {first, count, status} (count 0 at the start:
 * "ready"), followed, for count > 0 and status 0, by the chunk's rows and
 * outcomes (plain data, sent as bytes between ranks of one build); a
 * chunk that failed as a whole (status: no memory, no threads) sends no
 * rows, and rank 0 marks its runs failed with that status.  Rank 0
 * answers each RESULT with WORK, {first, count}, count 0 meaning "stop".
 * A worker keeps two requests out (it says "ready" twice), so the answer
 * to one arrives while it runs the chunk the other brought: it never
 * waits for rank 0 to finish a run of its own before being served.
 * Replies from one rank arrive in order and every one after the first
 * "stop" is "stop" too, so a worker ends after the second.  Chunks shrink
 * as the sweep nears its end (qd_sweep_mpi_chunk), so a rank that drew
 * slow runs does not keep the others waiting.  With at most SELF_MAX
 * ranks rank 0 also works, one run per thread at a time, serving
 * requests between its runs: on a small job a pure master would leave a
 * core idle; on a larger one serving is the bottleneck, and rank 0 only
 * serves.
 */
#include <math.h>
#include <mpi.h>
#include <stdint.h>
#include <stdlib.h>

#include "sweep/ext.h"

enum { TAG_RESULT = 1, TAG_ROWS, TAG_OUTCOME, TAG_WORK };
#define SELF_MAX 4 /* rank 0 works too up to this many ranks */
#define AHEAD 2    /* requests a worker keeps out */

unsigned qd_ext_mpi_abi(void);
void qd_ext_mpi_sweep(const qd__mpi_job *job, qd__mpi_where *where);

unsigned qd_ext_mpi_abi(void) { return QD__EXT_ABI; }

/* Runs [first, first+count) failed together with st: NaN rows. */
static void mark_failed(const qd__mpi_job *j, size_t first, size_t count, qd_status st) {
    for (size_t k = first; k < first + count; k++) {
        for (size_t c = 0; c < j->ncols; c++)
            j->rows[k * j->ncols + c] = NAN;
        j->outcome[k] = (qd_sweep_outcome){.status = st, .stop = {.code = QD_STOP_NONE}};
    }
}

/* One chunk's results, as a worker holds them before sending. */
typedef struct chunk_buf {
    size_t cap;
    double *rows;
    qd_sweep_outcome *outcome;
} chunk_buf;

static bool chunk_buf_grow(chunk_buf *b, size_t count, size_t ncols) {
    if (count <= b->cap)
        return true;
    free(b->rows);
    free(b->outcome);
    b->rows = malloc(count * ncols * sizeof *b->rows);
    b->outcome = malloc(count * sizeof *b->outcome);
    b->cap = b->rows && b->outcome ? count : 0;
    return b->cap > 0;
}

/* A worker: ask, run, send back (which asks again), until told to stop. */
static void worker(const qd__mpi_job *j) {
    chunk_buf b = {0};
    uint64_t hdr[3] = {0, 0, 0};
    for (int k = 0; k < AHEAD; k++)
        MPI_Send(hdr, 3, MPI_UINT64_T, 0, TAG_RESULT, MPI_COMM_WORLD);
    int out = AHEAD;
    while (out > 0) {
        uint64_t work[2];
        MPI_Recv(work, 2, MPI_UINT64_T, 0, TAG_WORK, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        out--;
        size_t first = (size_t)work[0], count = (size_t)work[1];
        if (count == 0)
            continue; /* the rest of the answers are "stop" too */
        qd_status st = chunk_buf_grow(&b, count, j->ncols)
                           ? j->run(j->data, first, count, b.rows, b.outcome)
                           : QD_ERR_NOMEM;
        hdr[0] = first;
        hdr[1] = count;
        hdr[2] = (uint64_t)st;
        MPI_Send(hdr, 3, MPI_UINT64_T, 0, TAG_RESULT, MPI_COMM_WORLD);
        if (st == QD_OK) {
            MPI_Send(b.rows, (int)(count * j->ncols), MPI_DOUBLE, 0, TAG_ROWS, MPI_COMM_WORLD);
            MPI_Send(b.outcome, (int)(count * sizeof *b.outcome), MPI_BYTE, 0, TAG_OUTCOME,
                     MPI_COMM_WORLD);
        }
        out++;
    }
    free(b.rows);
    free(b.outcome);
}

/* Rank 0's bookkeeping. */
typedef struct master {
    const qd__mpi_job *j;
    size_t next, done;
    int ranks, active; /* requests not yet answered "stop" */
} master;

static void count_done(master *m, size_t count) {
    m->done += count;
    if (m->j->progress)
        m->j->progress(m->j->data, m->done, m->j->nruns);
}

/* Receive one RESULT from src and place its chunk where its runs go. */
static void master_take(master *m, int src) {
    const qd__mpi_job *j = m->j;
    uint64_t hdr[3];
    MPI_Recv(hdr, 3, MPI_UINT64_T, src, TAG_RESULT, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    size_t first = (size_t)hdr[0], count = (size_t)hdr[1];
    if (count == 0)
        return;
    if (first > j->nruns || count > j->nruns - first)
        MPI_Abort(MPI_COMM_WORLD, 1); /* ranks of different builds: nothing to trust */
    if (hdr[2] != QD_OK) {
        mark_failed(j, first, count, (qd_status)hdr[2]);
    } else {
        MPI_Recv(j->rows + first * j->ncols, (int)(count * j->ncols), MPI_DOUBLE, src, TAG_ROWS,
                 MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        MPI_Recv(j->outcome + first, (int)(count * sizeof *j->outcome), MPI_BYTE, src,
                 TAG_OUTCOME, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    }
    count_done(m, count);
}

/* Hand src its next chunk, or tell it to stop. */
static void master_deal(master *m, int src) {
    size_t count = m->j->chunk(m->j->nruns - m->next, m->ranks, m->j->nthreads);
    uint64_t work[2] = {m->next, count};
    MPI_Send(work, 2, MPI_UINT64_T, src, TAG_WORK, MPI_COMM_WORLD);
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
static void master_work(master *m) {
    const qd__mpi_job *j = m->j;
    size_t count = j->nthreads;
    if (count > j->nruns - m->next)
        count = j->nruns - m->next;
    size_t first = m->next;
    m->next += count;
    qd_status st = j->run(j->data, first, count, j->rows + first * j->ncols, j->outcome + first);
    if (st != QD_OK)
        mark_failed(j, first, count, st);
    count_done(m, count);
}

static void run_master(const qd__mpi_job *j, int ranks) {
    master m = {.j = j, .ranks = ranks, .active = AHEAD * (ranks - 1)};
    bool self = ranks <= SELF_MAX;
    while (m.active > 0 || (self && m.next < j->nruns)) {
        if (self && m.next < j->nruns) {
            while (master_serve(&m, false))
                ;
            master_work(&m);
        } else {
            master_serve(&m, true);
        }
    }
}

void qd_ext_mpi_sweep(const qd__mpi_job *j, qd__mpi_where *where) {
    int provided, rank, ranks;
    MPI_Init_thread(NULL, NULL, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    if (ranks == 1) {
        /* nothing to share: the caller runs the sweep in this process */
    } else if (rank == 0) {
        run_master(j, ranks);
    } else {
        worker(j);
    }
    *where = (qd__mpi_where){.writer = rank == 0, .ranks = ranks};
    MPI_Finalize();
}
