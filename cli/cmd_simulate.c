/*
 * cli/cmd_simulate.c - `qdot simulate FILE --t-end T`: integrate the
 * equations of motion (qdot/sim.h) and write the trajectory as CSV (t, the
 * coordinates, velocities, momenta for the symplectic methods, the energy,
 * constraint residuals, --output columns), with a summary on stderr; with
 * --format json a JSON document on stdout (summary, final state, and the
 * rows unless --out takes them).  The model's impacts add two rows each
 * (before and after) and say on stderr how many there were, the energy
 * they took, and where a run ends in contact.  A model with `speeds` is
 * integrated in them (t, q, the speeds, q', ...; --no-speeds: the
 * multiplier form).  A model with friction contacts adds the columns
 * slip_NAME, mode_NAME and dissipated, a row at each stick/slip switch,
 * and the switches and the energy balance to the summary (JSON
 * `transitions`).
 */
#define _POSIX_C_SOURCE 200809L
#include "cli.h"

#include <stddef.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/json.h"
#include "model_cli.h"
#include "out.h"
#include "qdot/lyapunov.h"
#include "progress.h"
#include "sim_cli.h"

/* --variational (flow.c through qdot/lyapunov.h): after the run, the flow
 * Jacobian d y(t_end)/d y(t0) and what follows from it; `columns`: instead
 * of the trajectory, CSV rows of t, the state and the Jacobian's entries
 * column by column.  --period T: t_end = t0 + T, the monodromy matrix. */
typedef struct sim_cmd_args {
    cli_sim_args a;
    const char *variational_mode; /* "matrix", "columns" or NULL */
    const char *period_text, *format;
    int variational;      /* 0 none, 1 the matrix, 2 its columns */
    double period;
} sim_cmd_args;

static const char *const modes[] = {"matrix", "columns", NULL};
static const char *const formats[] = {"csv", "json", NULL};

static const cli_opt opts[] = {
    {"--format", NULL, CLI_CHOICE, offsetof(sim_cmd_args, format), "F",
     "csv rows, or one JSON document (summary, final state, rows)", formats, NULL},
    {"--variational", NULL, CLI_MAYBE, offsetof(sim_cmd_args, variational_mode), "[columns]",
     "the flow Jacobian after the run; columns: its entries as CSV rows", modes, NULL},
    {"--period", NULL, CLI_TEXT, offsetof(sim_cmd_args, period_text), "T",
     "t_end = t0 + T and the monodromy matrix (with --variational)", NULL, NULL},
    {NULL, NULL, CLI_FLAG, 0, NULL, NULL, NULL, NULL},
};

static const cli_group groups[] = {
    CLI_SIM_GROUP(sim_cmd_args, a),
    CLI_SIM_PLOT_GROUP(sim_cmd_args, a),
    {NULL, 0},
};

static const cli_spec spec = {
    "simulate", "FILE --t-end T [options]",
    "integrate the equations of motion and write the trajectory (CSV or JSON)",
    opts, groups, 1, 1, "FILE", false,
};

/* What a row does besides being written (qd_sim_writer's tap). */
typedef struct sim_out {
    double t0, t_end;
    cli_progress bar;
    cli_plot_rows *plot;  /* --plot: every row kept, or NULL */
} sim_out;

static int tap(void *data, int event, const double *row) {
    (void)event;
    sim_out *o = data;
    if (o->plot)
        cli_plot_keep(o->plot, row);
    cli_progress_update(&o->bar, (row[0] - o->t0) / (o->t_end - o->t0), row[0]);
    return cli_interrupted(); /* ^C: stop after a whole row */
}

/* After every step (qd_sim_opts.progress): the bar and ^C between rows, which
 * an output grid or a crawling step may space far apart. */
static int step_progress(void *data, double t) {
    sim_out *o = data;
    cli_progress_update(&o->bar, (t - o->t0) / (o->t_end - o->t0), t);
    return cli_interrupted();
}

/* ---- --variational ------------------------------------------------------------- */

/* A library printer's status: its text on stderr, or out of memory. */
static int put_stderr(qd_status st, qd_buf *b) {
    if (st == QD_OK)
        fputs(qd_buf_str(b), stderr);
    else
        cli_diag_error("cannot write the summary: %s", qd_status_str(st));
    qd_buf_free(b);
    return st == QD_OK ? QD_EXIT_OK : QD_EXIT_FAIL;
}

/* The flow's text on stderr (qd_flow_print). */
static int flow_print(const qd_flow *f, double period) {
    qd_buf b = QD_BUF_INIT;
    return put_stderr(qd_flow_print(f, period, "qdot: simulate: ", &b), &b);
}

/* The flow run, its rows as CSV into rows when given (qd_flow_setup_run:
 * every --dt, else --step, else 100 rows); *f filled (qd_flow_free). */
static int flow_compute(cli_sim *c, qd_flow *f, qd_sim_opts *o, cli_out_file *rows) {
    qd_status st = qd_flow_setup_run(c->ctx, c->set, c->mf.model, &c->opts,
                                     rows ? cli_out_put : NULL, rows, o, f);
    if (st == QD_ERR_IO)
        return QD_EXIT_FAIL; /* a lost row: said when the file is closed */
    if (st == QD_ERR_ARG)
        return cli_diag_ctx(c->ctx);
    return st == QD_OK ? QD_EXIT_OK : cli_sim_fail(c, st);
}

/* --variational columns: CSV of t, the state and d y_i / d y_j(t0). */
static int run_columns(cli_sim *c, const cli_sim_args *a) {
    if (a->json || a->plot.file) {
        cli_diag_error("--variational columns writes CSV: not with --format json or --plot");
        return QD_EXIT_USAGE;
    }
    int rc = QD_EXIT_OK;
    cli_out_file rows = {a->out ? cli_out_open(a->out, &rc) : stdout, 0};
    if (!rows.f)
        return rc;
    qd_flow f;
    qd_sim_opts fopts;
    rc = flow_compute(c, &f, &fopts, &rows);
    if (rc == QD_EXIT_OK)
        rc = flow_print(&f, 0);
    qd_flow_free(&f);
    /* the rows' file closed and checked: lost rows fail the run */
    if (cli_out_close(rows.f, a->out ? a->out : "standard output", rows.err) != QD_EXIT_OK)
        rc = QD_EXIT_FAIL;
    return rc;
}

/* After a run that reached its end: the summary on stderr, the picture,
 * the flow, and the JSON document's rest on stdout. */
static int finish(cli_sim *c, const cli_sim_args *a, const sim_cmd_args *sa,
                  const qd_sim_report *rep, const char **names, cli_plot_pick *pick,
                  cli_plot_rows *rows, qd_json *j) {
    qd_buf tb = QD_BUF_INIT;
    int rc = put_stderr(qd_sim_summary_print(rep, "qdot: simulate: ", &tb), &tb);
    double range[4 * CLI_PLOT_MAX_PANELS];
    if (rc == QD_EXIT_OK && a->plot.file)
        rc = cli_plot_write_run(c->ctx, &a->plot, pick, names, rows, a->file, false, range);
    qd_flow f = {0};
    qd_sim_opts fopts;
    if (rc == QD_EXIT_OK && sa) {
        rc = flow_compute(c, &f, &fopts, NULL);
        if (rc == QD_EXIT_OK)
            rc = flow_print(&f, sa->period);
    }
    if (rc == QD_EXIT_OK && a->json) {
        qd_sim_summary_json(j, rep);
        if (sa)
            qd_flow_json(j, &f, c->e, fopts.method, sa->period);
        if (a->plot.file)
            qd_sim_plot_json(j, a->plot.file, pick->npanels, range);
        qd_json_end_object(j);
        qd_json_add_model(j->out, c->mf.path);
        if (qd_json_ok(j) && !j->out->failed) {
            printf("%s\n", qd_buf_str(j->out));
        } else {
            cli_diag_error("cannot write the JSON summary: %s",
                           j->out->failed ? "out of memory" : qd_json_why(j));
            rc = QD_EXIT_FAIL;
        }
    }
    qd_flow_free(&f);
    return rc;
}

/* The run's rows through the library's writer (qd_sim_writer): CSV to
 * --out or stdout, else into the JSON document, none for a picture only. */
static int run(cli_sim *c, const cli_sim_args *a, const sim_cmd_args *sa) {
    size_t ncols = qd_sim_columns(c->s, c->opts.method, NULL, 0);
    const char **names = malloc((ncols + 1) * sizeof *names);
    double *final = malloc((ncols + 1) * sizeof *final);
    cli_plot_pick pick; /* --plot: its columns named before the run, which may be long */
    cli_plot_rows rows = {.ncols = ncols};
    int rc = names && final ? QD_EXIT_OK : QD_EXIT_FAIL;
    if (rc == QD_EXIT_OK)
        qd_sim_columns(c->s, c->opts.method, names, ncols);
    if (rc == QD_EXIT_OK && a->plot.file &&
        cli_plot_pick_columns(&a->plot, names, ncols, qd_sim_ndof(c->s), c->ctx, c->mf.model,
                              &pick) != QD_EXIT_OK)
        rc = QD_EXIT_USAGE;
    cli_out_file out = {stdout, 0};
    if (rc == QD_EXIT_OK && a->out && !(out.f = cli_out_open(a->out, &rc)))
        rc = rc != QD_EXIT_OK ? rc : QD_EXIT_FAIL;
    if (rc != QD_EXIT_OK) {
        free(names);
        free(final);
        return rc;
    }
    /* a step can span a swing: without --dt a picture alone samples the
     * dense output; rows written (--out, --format json) are never changed
     * by --plot, which then draws those rows (issue 36) */
    if (a->plot.file && !a->out && !a->json)
        qd_sim_opts_sample(&c->opts, 1000);
    sim_out o = {.t0 = c->opts.t0, .t_end = c->opts.t_end, .plot = a->plot.file ? &rows : NULL};
    qd_sim_writer w = {.tap = tap, .tap_data = &o};
    qd_sim_writer_init(&w, c->s, c->opts.method);
    qd_buf jb = QD_BUF_INIT;
    qd_json j;
    qd_json_init(&j, &jb);
    if (a->json)
        qd_json_begin_object(&j);
    if (a->out || (!a->json && !a->plot.file)) {
        w.write = cli_out_put; /* --plot alone: the picture, not CSV on stdout */
        w.data = &out;
    } else if (a->json) {
        qd_sim_columns_json(&j, c->s, c->opts.method); /* a failure is said at the end */
        qd_json_key(&j, "rows");
        qd_json_begin_array(&j);
        w.json = &j;
    }
    cli_progress_start(&o.bar, "simulate");
    c->opts.progress = step_progress;
    c->opts.progress_data = &o;
    qd_sim_stats st;
    cli_interrupt_begin();
    qd_status s = qd_sim_run(c->s, &c->opts, qd_sim_writer_sink, &w, &st, final);
    bool interrupted = cli_interrupted();
    cli_interrupt_end();
    double wall = cli_progress_end(&o.bar);
    if (w.json)
        qd_json_end_array(&j);
    /* the rows' file closed and checked first: lost rows fail the run */
    if (w.write && cli_out_close(out.f, a->out ? a->out : "standard output", out.err))
        rc = QD_EXIT_FAIL;
    if (rc != QD_EXIT_OK) {
        if (s != QD_OK && !w.failed)
            cli_sim_fail(c, s);
    } else if (s != QD_OK && w.failed) { /* JSON rows: memory ran out */
        rc = cli_out_of_memory();
    } else if (s != QD_OK) {
        rc = cli_sim_fail(c, s);
    } else if (interrupted) {
        fprintf(stderr, "qdot: simulate: interrupted at t = %.17g; the rows written are whole, "
                        "up to that time\n", w.last_t);
        rc = CLI_EXIT_INTERRUPTED;
    } else {
        qd_sim_report rep = {.s = c->s, .opts = &c->opts, .stats = &st, .final = final,
                             .wall = wall};
        rc = finish(c, a, sa, &rep, names, &pick, &rows, &j);
    }
    qd_sim_writer_free(&w);
    cli_plot_rows_free(&rows);
    qd_buf_free(&jb);
    free(names);
    free(final);
    return rc;
}

int cli_cmd_simulate(int argc, char **argv) {
    sim_cmd_args sa = {0};
    cli_sim_args *ap = &sa.a;
#define a (*ap)
    int rc = cli_parse(&spec, argc, argv, &sa, &a.file);
    a.json = sa.format && !strcmp(sa.format, "json");
    sa.variational = !sa.variational_mode ? 0 : !strcmp(sa.variational_mode, "columns") ? 2 : 1;
    if (rc == QD_EXIT_OK && sa.period_text)
        sa.variational = sa.variational ? sa.variational : 1;
    if (rc == QD_EXIT_OK)
        rc = cli_plot_check(&a.plot, "simulate");
    if (rc == QD_EXIT_OK && sa.period_text && a.t_end) {
        cli_diag_error("give --period or --t-end, not both (--period T runs from t0 to t0 + T)");
        return QD_EXIT_USAGE;
    }
    if (rc == QD_EXIT_OK && !a.t_end && !sa.period_text) {
        cli_diag_error("--t-end is missing (qdot simulate --help)");
        rc = QD_EXIT_USAGE;
    }
    if (rc != QD_EXIT_OK)
        return rc;
    a.period = sa.period_text; /* t_end = t0 + T (qd_sim_setup_options) */
    cli_sim c = {0};
    rc = cli_sim_setup(&c, &a);
    sa.period = sa.period_text ? qd_sim_setup_period_of(c.set) : 0;
    if (rc == QD_EXIT_OK && sa.variational == 2)
        rc = run_columns(&c, &a);
    else if (rc == QD_EXIT_OK)
        rc = run(&c, &a, sa.variational ? &sa : NULL);
    cli_sim_free(&c);
    return rc;
#undef a
}
