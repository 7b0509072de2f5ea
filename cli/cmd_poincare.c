/*
 * cli/cmd_poincare.c - `qdot poincare FILE --section "q1 = 0, q1' > 0"
 * --crossings N`: a Poincare surface of section.  The motion is integrated
 * (qdot/sim.h, dop853 at --rtol by default) and the state at each of the
 * first N crossings of the section (qd_poincare_run), located to round-off
 * by the integrator's event machinery, is printed as CSV or as JSON of
 * simulate's shape (qd_poincare_json_begin, _end).
 */
#include "cli.h"

#include <stddef.h>

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "out.h"
#include "qdot/lyapunov.h"
#include "qdot/plot.h"
#include "progress.h"
#include "sim_cli.h"

#define DEFAULT_T_MAX "1e6"

typedef struct pc_args {
    cli_sim_args a;
    const char *section;
    size_t n;
    const char *format;
} pc_args;

static const char *const formats[] = {"csv", "json", NULL};

static const cli_opt opts[] = {
    {"--section", NULL, CLI_TEXT, offsetof(pc_args, section), "\"EXPR = EXPR[, EXPR > EXPR]\"",
     "the surface of section: a crossing and its conditions", NULL, NULL},
    {"--crossings", NULL, CLI_COUNT, offsetof(pc_args, n), "N", "the crossings to find", NULL, NULL},
    CLI_OPT_FORMATS(pc_args, format, formats),
    {NULL, NULL, CLI_FLAG, 0, NULL, NULL, NULL, NULL},
};

static const cli_group groups[] = {
    CLI_SIM_GROUP(pc_args, a),
    CLI_SIM_PLOT_GROUP(pc_args, a),
    {NULL, 0},
};

static const cli_spec spec = {
    "poincare", "FILE --section \"EXPR = EXPR[, EXPR > EXPR]\" --crossings N [options]",
    "a Poincare surface of section: the state at the first N crossings, as CSV or JSON "
    "(--t-end: 1e6 at most)",
    opts, groups, 1, 1, "FILE", false,
};

typedef struct pc_out {
    FILE *f;
    cli_plot_rows *plot; /* --plot: the crossings kept, or NULL */
    qd_json *json;       /* --format json without --out: the rows go there */
    size_t ncols;
    const char **names; /* the header, written once the run is under way */
    bool header;
    cli_progress bar;
    int werr; /* a row could not be written (its errno): the run was stopped */
} pc_out;

static void progress(void *data, double done, double t) {
    cli_progress_update(&((pc_out *)data)->bar, done, t);
}

/* Every row of the run (qd_poincare_run): the crossings written as CSV. */
static int sink(void *data, const double *row, bool crossing) {
    pc_out *o = data;
    if (o->plot && crossing)
        cli_plot_keep(o->plot, row);
    if (o->json && crossing)
        qd_json_vector(o->json, NULL, o->ncols, row);
    if (o->json) /* a failure is said at the end */
        return cli_interrupted();
    for (size_t i = 0; !o->header && i < o->ncols; i++)
        fprintf(o->f, "%s%s", i ? "," : "", o->names[i]);
    if (!o->header)
        fputc('\n', o->f);
    o->header = true;
    if (!crossing) /* samples, and the rows of the model's impacts */
        return cli_interrupted();
    char num[QD_DOUBLE_MAX];
    for (size_t i = 0; i < o->ncols; i++) {
        if (i)
            fputc(',', o->f);
        fwrite(num, 1, qd_double_format(num, row[i]), o->f);
    }
    fputc('\n', o->f);
    if (ferror(o->f)) { /* the data is lost: stop the run */
        o->werr = errno;
        return 1;
    }
    return cli_interrupted(); /* ^C: after a whole row */
}

static int pc_plot_pick(const cli_sim *c, pc_args *p, const char **names, size_t ncols,
                        cli_plot_pick *pick) {
    qd_sim_columns(c->s, c->opts.method, names, ncols);
    if (!p->a.plot.phase)
        p->a.plot.phase = qd_plot_section_phase(p->section, names, qd_sim_ndof(c->s));
    return cli_plot_pick_columns(&p->a.plot, names, ncols, qd_sim_ndof(c->s), c->ctx, c->mf.model,
                                 pick);
}

int cli_cmd_poincare(int argc, char **argv) {
    pc_args p = {.n = 0};
    int rc = cli_parse(&spec, argc, argv, &p, &p.a.file);
    if (rc == QD_EXIT_OK && (!p.section || !p.n))
        rc = cli_usage_error("%s is missing (qdot poincare --help)",
                             p.section ? "--crossings" : "--section");
    if (rc == QD_EXIT_OK && p.n > 1000000000)
        rc = cli_usage_error("--crossings takes at most 1e9 crossings, not %zu", p.n);
    if (rc == QD_EXIT_OK && p.a.plot.ycols)
        rc = cli_usage_error("poincare --plot draws the crossings as q' against q: choose q with "
                             "--phase, not --plot-y");
    if (rc == QD_EXIT_OK && (p.a.events.n || p.a.stops.n || p.a.output)) {
        /* shared with simulate; a section's rows are the crossings alone */
        rc = cli_usage_error("poincare takes its crossings from --section: %s is simulate's",
                             p.a.output ? "--output" : "--event or --stop-at");
    }
    if (rc == QD_EXIT_OK)
        rc = cli_plot_check(&p.a.plot, "poincare");
    if (rc != QD_EXIT_OK)
        return rc;
    if (!p.a.t_end)
        p.a.t_end = DEFAULT_T_MAX;
    p.a.section = p.section;
    cli_sim c = {0};
    rc = cli_sim_setup(&c, &p.a);
    /* a fixed-step method given --dt: rows only at crossings, so any method works */
    size_t ncols = rc == QD_EXIT_OK ? qd_sim_columns(c.s, c.opts.method, NULL, 0) : 0;
    const char **names = rc == QD_EXIT_OK ? malloc((ncols + 1) * sizeof *names) : NULL;
    FILE *f = NULL;
    if (rc == QD_EXIT_OK && p.a.out)
        f = cli_out_open(p.a.out, &rc);
    cli_plot_rows rows = {.ncols = ncols};
    cli_plot_pick pick; /* --plot: its columns named before the run */
    if (rc == QD_EXIT_OK && names && p.a.plot.file)
        rc = pc_plot_pick(&c, &p, names, ncols, &pick);
    bool json = p.format && !strcmp(p.format, "json");
    qd_buf jb = QD_BUF_INIT;
    qd_json j;
    qd_json_init(&j, &jb);
    if (rc == QD_EXIT_OK && names) {
        qd_sim_columns(c.s, c.opts.method, names, ncols);
        pc_out o = {.f = f ? f : stdout, .ncols = ncols, .names = names,
                    .plot = p.a.plot.file ? &rows : NULL, .json = json && !f ? &j : NULL};
        if (json)
            qd_poincare_json_begin(&j, c.mf.path, ncols, names, o.json);
        qd_poincare_opts po = {.event = 0, .want = p.n, .sink = sink, .progress = progress,
                               .data = &o};
        qd_poincare_result r;
        cli_progress_start(&o.bar, "poincare");
        cli_interrupt_begin();
        qd_status s = qd_poincare_run(c.s, &c.opts, &po, &r);
        bool interrupted = cli_interrupted();
        cli_interrupt_end();
        double wall = cli_progress_end(&o.bar);
        int wrc = cli_out_close(o.f, f ? p.a.out : "standard output", o.werr);
        f = NULL; /* closed */
        if (wrc != QD_EXIT_OK) {
            rc = wrc;
        } else if (s != QD_OK) {
            rc = cli_sim_fail(&c, s);
        } else if (interrupted) {
            fprintf(stderr, "qdot: poincare: interrupted at t = %.17g after %zu crossings; the "
                            "rows written are whole\n", r.last_t, r.got);
            rc = CLI_EXIT_INTERRUPTED;
        } else {
            qd_buf tb = QD_BUF_INIT;
            qd_poincare_summary_print(&r, c.opts.method, "qdot: poincare: ", &tb);
            fputs(qd_buf_str(&tb), stderr);
            qd_buf_free(&tb);
            if (r.got < p.n)
                fprintf(stderr, "qdot: poincare: note: only %zu of %zu crossings before "
                                "t = %g (raise --t-end)\n", r.got, p.n, r.stats.t);
            if (json && qd_poincare_json_end(&j, c.s, &c.opts, &po, &r, wall, o.json) != QD_OK) {
                cli_diag_error("cannot write the JSON: %s", qd_json_why(&j));
                rc = QD_EXIT_FAIL;
            } else if (json) {
                printf("%s\n", qd_buf_str(&jb));
            }
            if (p.a.plot.file)
                rc = cli_plot_write_run(c.ctx, &p.a.plot, &pick, names, &rows, p.a.file, true,
                                        NULL);
        }
    } else if (rc == QD_EXIT_OK) {
        rc = QD_EXIT_FAIL;
    }
    cli_plot_rows_free(&rows);
    qd_buf_free(&jb);
    if (f)
        fclose(f);
    free(names);
    cli_sim_free(&c);
    return rc;
}
