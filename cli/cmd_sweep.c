/*
 * cli/cmd_sweep.c - `qdot sweep FILE --grid "NAME=A:B:N, ..." --measure
 * M[,M...]`: many runs of one compiled model (qdot/sweep.h), on threads,
 * one row per run (the inputs, the measures, the run's status) in run
 * order, as CSV or JSON.  The simulate options (--t-end, --method, --rtol,
 * --set, --initial, --native, ...) are parsed by sim_cli.c and apply to
 * every run; the sweep's inputs replace the initial values and parameters
 * they name.
 */
#define _POSIX_C_SOURCE 200809L
#include "cli.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "model_file.h"
#include "out.h"
#include "progress.h"
#include "args.h"
#include "sim_cli.h"

typedef struct sweep_args {
    cli_sim_args sim;
    const char *grid, *random, *list, *measure, *section, *format, *map, *map_measure;
    size_t n;              /* --runs: the random runs (0: not given) */
    uint64_t seed, threads; /* threads 0: one per core */
    double renorm, transient; /* the lyapunov measures */
} sweep_args;

/* ---- options ---------------------------------------------------------------- */

static const char *const formats[] = {"csv", "json", "hdf5", NULL};

#define OPT(...) CLI_OPT(sweep_args, __VA_ARGS__)
static const cli_opt opts[] = {
    OPT("--grid", CLI_TEXT, grid, "\"NAME=A:B:N, ...\"", "the runs: a grid, the first axis slowest"),
    OPT("--random", CLI_TEXT, random, "\"NAME=A:B, ...\"", "the runs: uniform in the box (--runs N)"),
    OPT("--runs", CLI_COUNT, n, "N", "the number of --random runs"),
    CLI_OPT_IN(sweep_args, "--seed", CLI_WHOLE, seed, "S", "the seed of --random (default 1)", 0,
               9007199254740992),
    OPT("--list", CLI_TEXT, list, "FILE.csv", "the runs: a header of names, a row a run"),
    OPT("--measure", CLI_TEXT, measure, "\"M, ...\"",
        "final, energy_error, event, escape:EXPR>V, max:EXPR, min:EXPR, poincare-count, ..."),
    OPT("--section", CLI_TEXT, section, "COND", "the section poincare-count counts crossing"),
    CLI_OPT_IN(sweep_args, "--threads", CLI_WHOLE, threads, "N", "threads (0, the default: one "
               "per core)", 0, QD_SWEEP_MAX_THREADS),
    OPT("--renorm", CLI_NONNEG, renorm, "DT", "the lyapunov measures' renormalization interval"),
    OPT("--transient", CLI_NONNEG, transient, "T0", "the lyapunov measures' transient"),
    {"--format", NULL, CLI_CHOICE, offsetof(sweep_args, format), "F", "the rows' format", formats,
     NULL},
    OPT("--map", CLI_TEXT, map, "FILE.png", "draw a measure of a grid of two axes (.svg, .pdf)"),
    OPT("--map-measure", CLI_TEXT, map_measure, "NAME", "the column --map draws (default: the "
        "first measure's)"),
    {NULL, NULL, 0, 0, NULL, NULL, NULL, NULL},
};

static const cli_group groups[] = {CLI_SIM_GROUP(sweep_args, sim), {NULL, 0}};

static const cli_spec spec = {
    .name = "sweep",
    .synopsis = "FILE (--grid \"NAME=A:B:N, ...\" | --random \"NAME=A:B, ...\" --runs N | --list "
                "FILE.csv) --t-end T --measure \"M, ...\" [options]",
    .summary = "Many runs of one model, a row each: the inputs, the measures and the status.\n"
               "Every option of qdot simulate that shapes a run applies too (--t-end, --method,\n"
               "--rtol, --atol, --set, --initial, --event, --stop-at, --native, ...; qdot\n"
               "simulate --help), and -o, --out FILE writes the rows.",
    .opts = opts,
    .groups = groups,
    .min_pos = 1,
    .max_pos = 1,
    .pos_name = "FILE",
};

static int check_args(const sweep_args *a) {
    int how = (a->grid != NULL) + (a->random != NULL) + (a->list != NULL);
    const char *missing = how != 1               ? "one of --grid, --random, --list"
                          : !a->sim.t_end        ? "--t-end"
                          : !a->measure          ? "--measure"
                          : a->random && !a->n   ? "--runs (the number of random runs)"
                                                 : NULL;
    if (missing)
        return cli_usage_error("%s %s (qdot sweep --help)", how > 1 ? "give only" : "missing:",
                               missing);
    if (a->map_measure && !a->map)
        return cli_usage_error("--map-measure says what to draw: give the file with --map "
                               "FILE.png");
    return a->n && !a->random ? cli_usage_error("--runs is for --random") : QD_EXIT_OK;
}

static int progress(void *data, size_t done, size_t total) {
    cli_progress_update(data, (double)done / (double)total, (double)done);
    return 0;
}

/* ---- output: one writer per --format (hdf5 joins the table) ---------------- */

static const struct {
    const char *name;
    qd_status (*write)(const qd_sweep *w, const double *rows, const qd_sweep_outcome *outcome,
                       qd_buf *out);
} writers[] = {{"csv", qd_sweep_csv}, {"json", qd_sweep_json}, {"hdf5", NULL}};

/* Before the model: hdf5 is written to a file. */
static int check_output(const sweep_args *a, size_t fmt) {
    return writers[fmt].write || a->sim.out
               ? QD_EXIT_OK
               : cli_usage_error("--format hdf5 writes a file: give it with -o FILE.h5");
}

static int write_result(qd_ctx *ctx, const qd_sweep *w, const sweep_args *a, size_t fmt,
                        const qd_sweep_spec *sp, const qd_sweep_result *r) {
    if (!writers[fmt].write) /* with how the sweep was made */
        return qd_sweep_hdf5_made(ctx, w, r, sp, a->sim.file, a->list, a->sim.out) == QD_OK
                   ? QD_EXIT_OK
                   : cli_diag_ctx(ctx);
    qd_buf b = QD_BUF_INIT;
    if (writers[fmt].write(w, r->rows, r->outcome, &b) == QD_OK &&
        (fmt != 1 || qd_json_add_model(&b, a->sim.file) == QD_OK)) /* JSON: "model" first */
        return cli_out_emit(&b, a->sim.out);
    qd_buf_free(&b);
    cli_diag_error("out of memory writing the rows");
    return QD_EXIT_FAIL;
}

static void summary(const qd_sweep_result *r, double wall) {
    char where[48] = "";
    if (r->where.ranks > 1)
        snprintf(where, sizeof where, "%d MPI ranks x ", r->where.ranks);
    fprintf(stderr, "qdot: sweep: %zu run%s on %s%u thread%s, %zu failed, %.3g s\n", r->nruns,
            r->nruns == 1 ? "" : "s", where, r->threads, r->threads == 1 ? "" : "s", r->failed,
            wall);
}

static int run_all(cli_sim *c, qd_sweep *w, const sweep_args *a, size_t fmt,
                   const qd_sweep_spec *sp) {
    size_t mapcol = 0; /* --map: what it draws checked before the runs */
    if (a->map && qd_sweep_map_check(w, a->map, a->map_measure, &mapcol) != QD_OK)
        return cli_diag_ctx(c->ctx);
    /* under mpirun every rank gets here; only rank 0 (where.writer) writes */
    cli_progress bar;
    cli_progress_start(&bar, "sweep");
    bar.label = "runs";
    qd_sweep_result r;
    qd_status st = qd_sweep_result_run(c->ctx, w, &c->opts, (unsigned)a->threads, progress, &bar,
                                       &r);
    double wall = cli_progress_end(&bar);
    int rc = st == QD_OK ? QD_EXIT_OK : cli_diag_ctx(c->ctx);
    if (rc == QD_EXIT_OK && r.where.writer)
        rc = write_result(c->ctx, w, a, fmt, sp, &r);
    /* titled by the model's name, as every other plot (cli_plot_opts) */
    const char *title = cli_plot_opts(&(cli_plot_args){0}, a->sim.file).title;
    if (rc == QD_EXIT_OK && r.where.writer && a->map &&
        qd_sweep_map_file(w, r.rows, mapcol, title, a->map) != QD_OK)
        rc = cli_diag_ctx(c->ctx);
    if (rc == QD_EXIT_OK && r.where.writer)
        summary(&r, wall);
    if (rc == QD_EXIT_OK && qd_sweep_result_check(c->ctx, &r) != QD_OK)
        rc = cli_diag_ctx(c->ctx); /* every run failed: exit 1, the rows written */
    qd_sweep_result_free(&r);
    return rc;
}

/* A refused set-up: shown in the text it is located in, or with its option. */
static int setup_error(cli_sim *c, const sweep_args *a, const char *where, const char *csv) {
    const struct { const char *field, *opt, *text; } f[] = {
        {"grid", "--grid", a->grid}, {"random", "--random", a->random},
        {"list_csv", a->list, csv}, {"measures", "--measure", a->measure}};
    for (size_t i = 0; where && i < sizeof f / sizeof f[0]; i++)
        if (!strcmp(where, f[i].field))
            return cli_sim_fail_in(c, f[i].opt, f[i].text);
    return cli_diag_ctx(c->ctx);
}

/* The sweep set up by the library (qd_sweep_setup_new), then run. */
static int sweep(cli_sim *c, const sweep_args *a, size_t fmt) {
    qd_sweep_spec sp = {.grid = a->grid, .random = a->random, .n = a->n,
                        .seed = a->seed, .measures = a->measure,
                        .nevents = a->sim.events.n + a->sim.stops.n, .section = a->section != NULL,
                        .renorm = a->renorm, .transient = a->transient};
    char *csv = NULL;
    size_t len;
    int rc = a->list ? cli_read_text(a->list, "a list of runs", &csv, &len) : QD_EXIT_OK;
    if (rc == QD_EXIT_OK && !writers[fmt].write && qd_sweep_hdf5_ready(c->ctx) != QD_OK)
        rc = cli_diag_ctx(c->ctx); /* before the runs: a qdot without the module */
    sp.list_csv = csv;
    const char *where = NULL;
    qd_sweep *w = rc == QD_EXIT_OK ? qd_sweep_setup_new(c->ctx, c->set, c->mf.model, &sp, &where)
                                   : NULL;
    if (rc == QD_EXIT_OK)
        rc = w ? run_all(c, w, a, fmt, &sp) : setup_error(c, a, where, csv);
    qd_sweep_free(w);
    free(csv);
    return rc;
}

int cli_cmd_sweep(int argc, char **argv) {
    sweep_args a = {.seed = 1};
    const char *pos[1];
    int rc = cli_parse(&spec, argc, argv, &a, pos);
    a.sim.file = pos[0];
    size_t fmt = 0;
    while (rc == QD_EXIT_OK && a.format && strcmp(writers[fmt].name, a.format))
        fmt++;
    if (rc == QD_EXIT_OK)
        rc = check_args(&a);
    if (rc == QD_EXIT_OK)
        rc = check_output(&a, fmt);
    if (rc != QD_EXIT_OK)
        return rc;
    if (a.section && a.sim.events.n + a.sim.stops.n == QD_SIM_MAX_LIST)
        return cli_usage_error("at most %d events with the --section", QD_SIM_MAX_LIST - 1);
    a.sim.section = a.section; /* the event after the user's (cli_sim_setup) */
    cli_sim c = {0};
    rc = cli_sim_setup(&c, &a.sim);
    if (rc == QD_EXIT_OK)
        rc = sweep(&c, &a, fmt);
    cli_sim_free(&c);
    return rc;
}
