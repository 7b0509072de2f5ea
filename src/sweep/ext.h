/*
 * src/sweep/ext.h - the interface between libqdot and its two optional
 * modules, modules/mpi.c and modules/hdf5.c, which libqdot opens with
 * dlopen only when a sweep asks for them (qd__module_open, src/base).
 *
 * Why modules: OpenMPI and HDF5 bring some sixty shared libraries with
 * them (curl, krb5, ldap, hwloc, ...), and a program that links them pays
 * the dynamic loader's cost on every start, `qdot --version` included.
 * Loaded on demand they cost nothing to a command that does not use them.
 *
 * A module calls nothing in libqdot: everything it needs arrives here as
 * data and callbacks.  The program may hold libqdot as an archive (the
 * qdot program) or as libqdot.so (Python), and a module that linked
 * against libqdot.so would then be a second copy of the library.  The
 * types of qdot/sweep.h are plain data shared by value; QD__EXT_ABI
 * changes whenever a struct here changes, and a module of another ABI
 * is refused.
 */
#ifndef QD_SWEEP_EXT_H
#define QD_SWEEP_EXT_H

#include <stddef.h>
#include "qdot/sweep.h"

#define QD__EXT_ABI 1

/* ---- modules/mpi.c: entry points qd_ext_mpi_abi, qd_ext_mpi_sweep ---- */

/* One sweep shared across the ranks.  run fills rows (count x ncols) and
 * outcome (count) for runs [first, first+count) on nthreads threads and
 * returns QD_OK, or the status with which the whole chunk failed (the
 * module then marks those runs failed with it).  rows and outcome hold
 * every run on rank 0 and are not touched on the others. */
typedef struct qd__mpi_job {
    size_t nruns, ncols;
    unsigned nthreads;
    double *rows;
    qd_sweep_outcome *outcome;
    qd_status (*run)(void *data, size_t first, size_t count, double *rows,
                     qd_sweep_outcome *outcome);
    void (*progress)(void *data, size_t done, size_t total); /* rank 0; may be NULL */
    size_t (*chunk)(size_t remaining, int ranks, unsigned threads); /* qd_sweep_mpi_chunk */
    void *data;
} qd__mpi_job;

typedef struct qd__mpi_where {
    int writer; /* this rank holds every row */
    int ranks;
} qd__mpi_where;

typedef unsigned (*qd__ext_abi_fn)(void);
/* MPI_Init_thread, the sweep, MPI_Finalize.  A job of one rank runs
 * nothing (where->ranks == 1): the caller runs the sweep itself, with its
 * progress.  MPI's own failures abort the job (MPI_ERRORS_ARE_FATAL: a
 * rank cannot leave the others waiting). */
typedef void (*qd__mpi_sweep_fn)(const qd__mpi_job *job, qd__mpi_where *where);

/* ---- modules/hdf5.c: entry points qd_ext_hdf5_abi, qd_ext_hdf5_image ---- */

/* The file's contents (layout: qdot/sweep.h, qd_sweep_hdf5). */
typedef struct qd__h5_table {
    size_t nruns, ncols;
    const char *const *names;   /* ncols column names */
    const double *rows;         /* nruns x ncols */
    const int *status;          /* nruns */
    const char *const *reason;  /* nruns */
    size_t nattrs;              /* root attributes: name = value */
    const char *const *attr_names;
    const char *const *attr_values;
} qd__h5_table;

/* The HDF5 file image of t, malloc'd (the caller frees it) with its size;
 * NULL when HDF5 fails. */
typedef void *(*qd__h5_image_fn)(const qd__h5_table *t, size_t *size);

#endif
