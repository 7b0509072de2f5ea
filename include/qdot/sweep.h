/*
 * qdot/sweep.h - many runs of one compiled system: grids, random draws and
 * lists of initial values and parameters, a few numbers ("measures") per
 * run, on a pool of threads.
 *
 * A sweep owns no equations: it reads a compiled qd_sim (shared read-only by
 * every thread, qdot/sim.h "Thread safety") and the model it came from (to
 * resolve names).  An input NAME is a coordinate (its initial value), a
 * velocity `x'` (its initial value) or a parameter (its value in the run,
 * through qd_sim_opts.par).  Each run depends only on its inputs, so the
 * rows are identical whatever the number of threads (or processes) that
 * compute them.
 *
 * Specs:
 *   grid      "NAME=A:B:N, ..."   product of the axes, the first axis
 *                                 slowest; N >= 1 points from A to B
 *                                 (N = 1 gives A alone), A <= B when N > 1
 *   random    "NAME=A:B, ..."     n runs uniform in the box; run i's draw
 *                                 depends only on (seed, i)
 *   measures  "final, energy_error, event, escape:EXPR>VAL, max:EXPR,
 *              min:EXPR, poincare-count, lyapunov, lyapunov-spectrum"
 *             (docs/cli.md, "qdot sweep", says what each gives).
 * Errors name the offending text; the call returns QD_ERR_PARSE (malformed)
 * or QD_ERR_ARG (unknown or duplicate name, N = 0, A > B) with the reason in
 * the sweep's context.
 */
#ifndef QDOT_SWEEP_H
#define QDOT_SWEEP_H

#include <stddef.h>
#include <stdint.h>
#include "lyapunov.h"
#include "model.h"
#include "plot.h"
#include "print.h"
#include "sim.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct qd_sweep qd_sweep;

/* s compiled (qd_sim_compile), shared read-only by all threads; s and m
 * must outlive the sweep.  NULL on failure, reason in ctx. */
QD_API qd_sweep *qd_sweep_new(qd_ctx *ctx, const qd_sim *s, const qd_model *m);
QD_API void qd_sweep_free(qd_sweep *w);

/* The runs: one of grid, random, list (a later call replaces the runs). */
QD_API qd_status qd_sweep_grid(qd_sweep *w, const char *spec);
QD_API qd_status qd_sweep_random(qd_sweep *w, const char *spec, size_t n, uint64_t seed);
/* nrows runs, values row-major (nrows * nnames numbers). */
QD_API qd_status qd_sweep_list(qd_sweep *w, size_t nnames, const char *const *names, size_t nrows,
                               const double *values);
/* The same from CSV text (qdot sweep --list FILE.csv): a header of names
 * separated by commas, then one row of numbers a run; blank lines are
 * skipped.  QD_ERR_PARSE located in text for an empty name, a missing or
 * extra field, a field that is not a number, or no row. */
QD_API qd_status qd_sweep_list_csv(qd_sweep *w, const char *text);

/* The measures, in the order given (a later call replaces them). */
QD_API qd_status qd_sweep_measures(qd_sweep *w, const char *spec);

/* Which events of s the measures read (indices in the order the events
 * were added to s).  `event`: the first time event k fires (default 0).
 * `poincare-count`: how many times event k fires, a Poincare section as
 * `qdot poincare --section` adds it (the condition with its guards; default:
 * none, and the measure is refused without one).  QD_ERR_ARG for an index
 * s does not have. */
QD_API qd_status qd_sweep_set_event(qd_sweep *w, size_t k);
QD_API qd_status qd_sweep_set_section(qd_sweep *w, size_t k);

/* The measures `lyapunov` (columns lyapunov, lyapunov_error: the largest
 * exponent and its error estimate) and `lyapunov-spectrum` (lyapunov_1 ..
 * lyapunov_2n, descending) integrate the variational equations of l
 * (qdot/lyapunov.h; built from the same model and equations as s) from
 * each run's initial state and parameters, with the run's t0, t_end, rtol
 * and atol, dopri5 or dop853 (another method of the run: dop853).  lo
 * gives renorm and transient (nexp is set per measure; lo NULL: the
 * defaults).  l must outlive the sweep; copied lo.  QD_ERR_ARG when l's
 * degrees of freedom are not s's.  Without l these measures are refused
 * by qd_sweep_run. */
QD_API qd_status qd_sweep_set_lyap(qd_sweep *w, const qd_lyap *l, const qd_lyap_opts *lo);

/* ---- what the measures ask of the run, before it is compiled ------------
 *
 * A measure that reads an expression (max:EXPR, min:EXPR, escape:EXPR>VALUE)
 * reads the run's column named by EXPR's text: unless EXPR is a column
 * already, the run needs it as an output.  escape:EXPR>VALUE also needs the
 * crossing EXPR = VALUE as an event (no guards, not stopping), so the row at
 * the crossing puts the escape time on it to round-off.  `event` needs an
 * event of the run, `poincare-count` a section, the Lyapunov measures
 * qd_sweep_set_lyap. */
typedef enum qd_sweep_need_kind {
    QD_SWEEP_NEED_OUTPUT,  /* spec[e0, e1) as an output named by that text */
    QD_SWEEP_NEED_CROSSING /* an event where spec[e0, e1) crosses spec[v0, v1) */
} qd_sweep_need_kind;

typedef struct qd_sweep_need {
    qd_sweep_need_kind kind;
    size_t e0, e1; /* EXPR: bytes [e0, e1) of the spec, trimmed */
    size_t v0, v1; /* a crossing's VALUE: bytes [v0, v1) of the spec */
} qd_sweep_need;

#define QD_SWEEP_NEEDS_EVENT 1u   /* `event`: an event (qd_sweep_set_event) */
#define QD_SWEEP_NEEDS_SECTION 2u /* `poincare-count`: a section (qd_sweep_set_section) */
#define QD_SWEEP_NEEDS_LYAP 4u    /* `lyapunov`, `lyapunov-spectrum`: qd_sweep_set_lyap */

/* The needs of the measures spec (as qd_sweep_measures reads it), in the
 * order written (an escape: its output, then its crossing): the first cap
 * into needs, the count returned; *flags gets the QD_SWEEP_NEEDS_* of the
 * measures.  An EXPR that a measure before it reads already needs no second
 * output, nor one that is a column of s (s may be NULL: every EXPR is
 * needed).  Text that is not a measure needs nothing (qd_sweep_measures
 * says why).  Reads text and s's columns only. */
QD_API size_t qd_sweep_needs(const qd_sim *s, const char *spec, qd_sweep_need *needs, size_t cap,
                             unsigned *flags);

/* An expression spec[a, b) read in the model's namespace (coordinates,
 * velocities, t, parameters, definitions...), or NULL with the reason
 * recorded in ctx, located in spec. */
typedef const qd_expr *(*qd_sweep_read_fn)(void *data, qd_ctx *ctx, const char *spec, size_t a,
                                           size_t b);

/* Add to s (not compiled yet; ctx the one s was made with) the outputs and
 * events the measures spec need (qd_sweep_needs), the events after those s
 * has, in the order of the escapes.  read: the reader of the expressions; NULL: qd_read (names as
 * symbols; a definition is not followed).  The first error is returned,
 * its reason in ctx. */
QD_API qd_status qd_sweep_prepare(qd_ctx *ctx, qd_sim *s, const char *spec, qd_sweep_read_fn read,
                                  void *data);

/* The same for a run set up by qd_sim_setup (qdot/simsetup.h), the way
 * qdot sweep takes its measures: each expression read in the model's
 * namespace as --output and --event read theirs (qd_sim_setup_output,
 * qd_sim_setup_crossing: definitions, their rates, vector components),
 * an error located in spec (the reason in ctx, the context set was made
 * with). */
struct qd_sim_setup;
QD_API qd_status qd_sweep_setup_measures(qd_ctx *ctx, struct qd_sim_setup *set,
                                         const char *spec); /* ctx: set's */

/* A whole sweep as its texts give it (qdot sweep's options). */
typedef struct qd_sweep_spec {
    const char *grid, *random, *list_csv; /* the runs: exactly one (list_csv: CSV text) */
    size_t n;                  /* random: the number of runs */
    uint64_t seed;             /* random: the seed */
    const char *measures;      /* required */
    size_t nevents;            /* the events set has before the section (`event`: the first) */
    bool section;              /* event nevents of set is poincare-count's section */
    double renorm, transient;  /* the Lyapunov measures' qd_lyap_opts (0: the defaults) */
} qd_sweep_spec;

/* The sweep of sp over set's run: refused first when the measures need
 * what the run lacks (`event` an event, `poincare-count` the section, the
 * Lyapunov measures Lagrange's equations) or sp gives not exactly one kind
 * of runs; then the measures' needs added to set (qd_sweep_setup_measures),
 * its run compiled, the runs, the measures, the section and the Lyapunov
 * measures' variational equations (made from m and set's equations, owned
 * by the sweep).  set and m must outlive the sweep; ctx is set's.  NULL on
 * failure, the reason in ctx: an error in a text is located in it and
 * *where (may be NULL) names its field ("grid", "random", "list_csv",
 * "measures"), else *where is NULL and a refusal names the field it is
 * about in qd_diag.name ("grid", "event", "section", "no_speeds"). */
QD_API qd_sweep *qd_sweep_setup_new(qd_ctx *ctx, struct qd_sim_setup *set, const qd_model *m,
                                    const qd_sweep_spec *sp, const char **where);

/* ---- a grid of two axes as a colour map (qdot sweep --map) -------------- */

/* The measure column a map draws: measure NULL, the first measure column;
 * else the measure column so named.  QD_ERR_ARG, the reason in the sweep's
 * context naming the option field "map" (the runs are not a grid of two
 * axes, no measures) or "map_measure" (no such measure column). */
QD_API qd_status qd_sweep_map_column(const qd_sweep *w, const char *measure, size_t *col);

/* Add to p (its selected panel) column col of rows (the sweep's nruns x
 * ncols numbers, in run order, as qd_sweep_run fills them) as a colour map
 * over the grid's two axes (qd_plot_add_map): the first input across, the
 * second up, the axes labelled with their names and units, the colour bar
 * with the column's name and unit: an input's or a run column's unit as
 * the model says it (qd_model_column_unit: "theta (rad)", "theta'
 * (rad/s)"), a measure's of a column that of the column ("max:theta'
 * (rad/s)", "final_theta (rad)", "event_theta (rad)"), or the one the
 * measure fixes ("lyapunov (1/s)", "event_t (s)", "escape:x>1 (s)",
 * "poincare-count (crossings)"); none where the model states none (a
 * length, an energy).  Errors as qd_sweep_map_column's, or the plot's. */
QD_API qd_status qd_sweep_map(const qd_sweep *w, const double *rows, size_t col, qd_plot *p);

/* qdot sweep --map FILE: before the runs, that path's format (a known
 * ending: qd_plot_format_of) and the column (qd_sweep_map_column) into
 * *col; after them, qd_sweep_map of rows on a plot of its own titled title
 * (may be NULL) written to path.  Errors as those calls', in w's context. */
QD_API qd_status qd_sweep_map_check(const qd_sweep *w, const char *path, const char *measure,
                                    size_t *col);
QD_API qd_status qd_sweep_map_file(const qd_sweep *w, const double *rows, size_t col,
                                   const char *title, const char *path);

QD_API size_t qd_sweep_nruns(const qd_sweep *w);
QD_API size_t qd_sweep_ninputs(const qd_sweep *w);
QD_API size_t qd_sweep_ncols(const qd_sweep *w);          /* inputs then measures (numbers only) */
QD_API const char *qd_sweep_col(const qd_sweep *w, size_t j);

/* Run i (0 <= i < nruns) alone: thread-safe on a const w (ctx is the
 * caller's own).  row receives ncols numbers (NaN where a measure has no
 * value); a failed run returns its status with the reason in ctx and
 * fills the inputs part of row only (the rest NaN).  stop (may be NULL)
 * receives how the run's integration ended (qd_sim_stats.stop; code
 * QD_STOP_NONE when it was not integrated: it failed before, or its
 * measures are Lyapunov exponents only). */
QD_API qd_status qd_sweep_run_one(qd_ctx *ctx, const qd_sweep *w, const qd_sim_opts *base, size_t i,
                                  double *row, qd_sim_stop *stop);

/* How one run went, as data (issue 31): its status (QD_OK, or why it
 * failed) and how its integration ended.  A sweep's rows carry this, not
 * English: qd_sweep_outcome_str words it. */
typedef struct qd_sweep_outcome {
    qd_status status;
    qd_sim_stop stop;
} qd_sweep_outcome;

/* "ok"; or why the run failed: the stop's sentence and its time when the
 * integration failed ("singular equations at t = 0.5"), else the status's
 * (qd_status_str).  Written into out (cap bytes, truncated, NUL-ended);
 * returns out. */
#define QD_SWEEP_OUTCOME_MAX 96
QD_API const char *qd_sweep_outcome_str(const qd_sweep_outcome *o, char *out, size_t cap);

/* The progress of a sweep: done of total runs.  Called from the calling
 * thread only, when a run ends and at least ten times a second; nonzero
 * stops the sweep: no run starts after it, the runs under way end, and
 * the call returns QD_ERR_ARG ("stopped after DONE of TOTAL runs"), the
 * runs never started with outcome QD_ERR_ARG, stop QD_STOP_CALLBACK (a
 * progress bar, or ^C from Python).  Under an MPI launcher it is called on
 * the writer, and a stop is not heeded (the ranks run on). */
typedef int (*qd_sweep_progress)(void *data, size_t done, size_t total);

/* Runs [first, first+count) on nthreads threads (0: all cores), dynamic
 * scheduling; rows[k*ncols..] and outcome[k] for run first+k; progress
 * (may be NULL) as qd_sweep_progress says.  A failed run never stops the
 * others; the call itself fails only when it cannot start (bad range, no
 * memory, no threads) or progress stops it. */
/* nthreads above QD_SWEEP_MAX_THREADS is QD_ERR_ARG.  The pool is
 * qd_sweep_threads(nthreads, count) threads (fewer only when the system
 * refuses to start one; none started is QD_ERR_UNSUPPORTED). */
#define QD_SWEEP_MAX_THREADS 1024
QD_API unsigned qd_sweep_threads(unsigned nthreads, size_t count); /* 0: above the most */
QD_API qd_status qd_sweep_run(qd_ctx *ctx, const qd_sweep *w, const qd_sim_opts *base, size_t first,
                              size_t count, unsigned nthreads, double *rows,
                              qd_sweep_outcome *outcome,
                              qd_sweep_progress progress, void *data);

/* The rows and outcomes of runs [0, nruns) as qd_sweep_run fills them,
 * appended to out: CSV, the columns then `status` in a header, a line a
 * run, its numbers (qd_double_format: nan where none) then
 * qd_sweep_outcome_str; or JSON, {"columns": [...], "rows": [[...], ...]
 * (null where none), "status": [qd_sweep_outcome_str, ...], "stop":
 * [qd_sim_stop_json, ...]} and a newline.  QD_ERR_NOMEM when out
 * could not grow. */
QD_API qd_status qd_sweep_csv(const qd_sweep *w, const double *rows,
                              const qd_sweep_outcome *outcome, qd_buf *out);
QD_API qd_status qd_sweep_json(const qd_sweep *w, const double *rows,
                               const qd_sweep_outcome *outcome, qd_buf *out);

/* ---- Across MPI ranks, and into HDF5 (optional modules) ------------------
 * Both are libqdot's optional modules, qdot_mpi.so and qdot_hdf5.so
 * (docs/design.md, "Running sweeps on a cluster"), opened only by the call
 * that needs them: a program that never shares a sweep or writes HDF5 never
 * loads OpenMPI or HDF5.  Without the module (qdot built without MPI or
 * HDF5, or not installed) those calls fail with QD_ERR_UNSUPPORTED saying
 * so; everything else works alike. */

/* Was this process started by an MPI launcher (mpirun, mpiexec, srun)?
 * Read from the environment those launchers set; MPI is not touched. */
QD_API bool qd_sweep_mpi_launched(void);

/* The chunk rank 0 hands out when `remaining` runs are left among `ranks`
 * ranks of `threads` threads each: a quarter of an even share, so the last
 * chunks are small and ranks finish together, but never below one run per
 * thread (nor above `remaining`), nor above 65536 runs (a message's counts
 * stay small).  0 when none remain. */
QD_API size_t qd_sweep_mpi_chunk(size_t remaining, int ranks, unsigned threads);

/* Where the runs of qd_sweep_run_all went. */
typedef struct qd_sweep_where {
    bool writer;      /* this process holds every row (and should write them) */
    int ranks;        /* processes that ran the sweep (1 outside a launcher) */
    unsigned threads; /* threads in each: as asked; under a launcher 1 when 0 was asked */
} qd_sweep_where;

/* Every run of w, as qd_sweep_run(ctx, w, base, 0, nruns, nthreads, ...),
 * in this process; or, started by an MPI launcher, shared out across its
 * ranks (MPI started and finished inside this call, once per process).
 * Rank 0 then deals chunks (qd_sweep_mpi_chunk) and gathers every row and
 * outcome in run order, and it alone is the writer; rows and outcome are
 * written on the writer only.  Each run depends only on its inputs, so
 * the rows are bit for bit those of one process.  A chunk that fails as a
 * whole on some rank (no memory) is recorded as failed runs.  Under a
 * launcher without the MPI module: QD_ERR_UNSUPPORTED, nothing run (each
 * rank would otherwise run and write the whole sweep).  progress as for
 * qd_sweep_run, on the writer. */
QD_API qd_status qd_sweep_run_all(qd_ctx *ctx, const qd_sweep *w, const qd_sim_opts *base,
                                  unsigned nthreads, double *rows, qd_sweep_outcome *outcome,
                                  qd_sweep_progress progress,
                                  void *data, qd_sweep_where *where);

/* Every run's row and outcome, as the caller of a whole sweep holds them. */
typedef struct qd_sweep_result {
    size_t nruns, ncols;       /* qd_sweep_nruns, qd_sweep_ncols */
    double *rows;              /* nruns x ncols (qd_sweep_run's) */
    qd_sweep_outcome *outcome; /* nruns */
    size_t failed;             /* runs whose status is not QD_OK (on the writer) */
    qd_sweep_where where;
    unsigned threads;          /* each process's: where.threads across ranks, else the
                                * pool's (qd_sweep_threads of where.threads) */
} qd_sweep_result;

/* qd_sweep_run_all into arrays this call allocates (malloc'd; free with
 * qd_sweep_result_free, also after a failure).  QD_ERR_NOMEM when the
 * rows of every run do not fit in memory (they are all kept until the
 * end, in run order). */
QD_API qd_status qd_sweep_result_run(qd_ctx *ctx, const qd_sweep *w, const qd_sim_opts *base,
                                     unsigned nthreads,
                                     qd_sweep_progress progress,
                                     void *data, qd_sweep_result *r);
QD_API void qd_sweep_result_free(qd_sweep_result *r); /* NULL is fine */

/* Rows of failures only are no answer: QD_ERR_NUMERIC, "every run failed
 * (the first: REASON)" in ctx, when r (on the writer) has runs and every
 * one failed (the rows, each with its reason, are still worth writing);
 * else QD_OK. */
QD_API qd_status qd_sweep_result_check(qd_ctx *ctx, const qd_sweep_result *r);

/* Can this qdot write HDF5 (qdot_hdf5.so loads)?  QD_OK, or
 * QD_ERR_UNSUPPORTED with the reason in ctx. */
QD_API qd_status qd_sweep_hdf5_ready(qd_ctx *ctx);

/* The rows and outcomes of w's runs (as qd_sweep_run fills them) into the
 * HDF5 file path, replacing it.  The file holds
 *   /runs    nruns x ncols doubles, the CSV's rows (inputs, then measures;
 *            NaN where a measure has no value), in run order; its
 *            attribute "columns" names the columns (variable-length strings);
 *   /status  nruns ints: 0 for a run that went through, else the qd_status
 *            it failed with;
 *   /reason  nruns variable-length strings: qd_sweep_outcome_str ("" for a
 *            run that went through);
 * and string attributes on the root group: qdot_version, then the nattrs
 * pairs attr_names[k] = attr_values[k] (how the sweep was made).  A file
 * that cannot be made or written is QD_ERR_IO (a partial regular file is
 * removed); no HDF5 module, QD_ERR_UNSUPPORTED; reason in ctx. */
QD_API qd_status qd_sweep_hdf5(qd_ctx *ctx, const qd_sweep *w, const double *rows,
                               const qd_sweep_outcome *outcome, size_t nattrs,
                               const char *const *attr_names, const char *const *attr_values,
                               const char *path);

/* qd_sweep_hdf5 of r's rows with how sp made the sweep as the attributes:
 * model (the caller's name for it; NULL: ""), measures, then grid, random
 * or list (sp's text; a list's the name list, a file's, as CSV text is no
 * record; NULL: ""), and for random n and seed. */
QD_API qd_status qd_sweep_hdf5_made(qd_ctx *ctx, const qd_sweep *w, const qd_sweep_result *r,
                                    const qd_sweep_spec *sp, const char *model,
                                    const char *list, const char *path);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_sweep_set_lyap (lo); qd_sweep_run
 * (data, progress); qd_sweep_run_one (stop); qd_sweep_needs (s; needs, when
 * cap is 0); qd_sweep_prepare (read, data); qd_sweep_map_column (measure);
 * qd_sweep_setup_new (where); qd_sweep_map_check (measure); qd_sweep_map_file
 * (title); qd_sweep_hdf5_made (model, list).
 * An array whose count is 0 may be NULL.  qd_sweep_outcome_str returns
 * NULL for a NULL o or out, or cap 0. */
#endif
