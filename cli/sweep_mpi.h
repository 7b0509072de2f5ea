/*
 * cli/sweep_mpi.h - qdot sweep across the ranks of an MPI job (issue 21).
 *
 * The same program runs alone or under `mpirun -np N qdot sweep ...`.  It
 * starts MPI only when a launcher started it (cli_mpi_launched), so a plain
 * run never touches MPI, and a program built without MPI (no QDOT_HAVE_MPI)
 * runs every sweep in its own process.  Rank 0 hands out chunks of run
 * indices, works on small chunks itself while there are few ranks, gathers
 * every row, and alone writes the output; each run's result depends only on
 * its inputs, so the output is byte for byte the single process's.
 */
#ifndef QDOT_CLI_SWEEP_MPI_H
#define QDOT_CLI_SWEEP_MPI_H

#include <stdbool.h>
#include <stddef.h>
#include "qdot/qdot.h"
#include "qdot/sweep.h"

/* Was this process started by mpirun, mpiexec or srun (their environment
 * variables)?  Always false without MPI support. */
bool cli_mpi_launched(void);

/* Is MPI support built in? */
bool cli_mpi_built(void);

/* Progress over all the runs of the sweep: done of total (rank 0 only). */
typedef void (*cli_mpi_progress)(void *data, size_t done, size_t total);

/* What one sweep across the ranks needs; rows and outcome hold every run
 * (nruns rows of ncols, nruns outcomes) on rank 0 and may be NULL elsewhere. */
typedef struct cli_mpi_job {
    const qd_sweep *w;
    const qd_sim_opts *base;
    unsigned nthreads;        /* threads in each rank; 0: all cores */
    double *rows;
    qd_sweep_outcome *outcome;
    cli_mpi_progress progress; /* may be NULL */
    void *data;
} cli_mpi_job;

/* How the runs went: where, and who writes. */
typedef struct cli_mpi_done {
    bool writer;      /* this process holds every row and writes the output */
    int ranks;        /* processes that ran the sweep (1 without MPI) */
    unsigned threads; /* threads in each (0: all cores) */
} cli_mpi_done;

/* Run every run of j->w.  Launched by an MPI launcher: start MPI, share
 * the runs out, finish MPI; only rank 0 is then the writer, holding every
 * row.  Otherwise the runs go to qd_sweep_run in this process, the writer.
 * A failed run is recorded in its row and outcome; the return is
 * not OK only when the sweep as a whole failed (out of memory; reason in
 * ctx).  MPI's own failures abort the job. */
qd_status cli_mpi_sweep(qd_ctx *ctx, const cli_mpi_job *j, cli_mpi_done *done);

/* The chunk rank 0 hands out when `remaining` runs are left among `ranks`
 * ranks of `threads` threads each: a quarter of an even share, so the last
 * chunks are small and ranks finish together, but never below one run per
 * thread, nor above 65536 runs (a message's counts stay small). */
size_t cli_mpi_chunk(size_t remaining, int ranks, unsigned threads);

#endif
