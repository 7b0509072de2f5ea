/*
 * cli/sim_cli.c - the setup `qdot simulate` and `qdot poincare` share.
 *
 * Expressions on the command line (--output, --event) are read in the model
 * language; a name the reader does not know is looked up among the model's
 * definitions (x2 = x1 + l2*sin(theta2)) and replaced by its value, and a
 * definition's name with a prime (x2') is its time derivative.  A speed's
 * name (`speeds`) stands for its definition, as in the model.
 *
 * A model with speeds is simulated in them, y = (q, u) (qd_sim_new_speeds):
 * the initial speeds are those given (`initial u = ...`, --initial "u=..."),
 * the others those of the initial velocities; --no-speeds integrates the
 * multiplier form instead.
 */
#include "sim_cli.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "eom_out.h"
#include "model_cli.h"

static const char *const methods[] = {"dopri5", "dop853", "gl2",     "gl4",      "gl6",
                                      "verlet", "yoshida4", "yoshida6", "yoshida8", "bdf",
                                      "taylor", NULL};
static const char *const precisions[] = {"64", "80", "128", NULL};

#define SIM(field) offsetof(cli_sim_args, field)
const cli_opt cli_sim_opts[] = {
    {"--t-end", NULL, CLI_TEXT, SIM(t_end), "T",
     "end time (an expression in the parameters)", NULL, NULL},
    {"--dt", NULL, CLI_TEXT, SIM(dt), "H",
     "a row every H, for every method (dense output between the steps)", NULL, NULL},
    {"--step", NULL, CLI_TEXT, SIM(step), "H",
     "the step of a fixed-step method (gl4 by default; without it: --dt)", NULL, NULL},
    {"--every", NULL, CLI_TEXT, SIM(every), "H",
     "the older name of --dt (with --dt, --dt is then the step)", NULL, NULL},
    {"--rtol", NULL, CLI_TEXT, SIM(rtol), "TOL",
     "relative tolerance (step control; 1e-10)", NULL, NULL},
    {"--atol", NULL, CLI_TEXT, SIM(atol), "TOL", "absolute tolerance (1e-12)", NULL, NULL},
    {"--max-steps", NULL, CLI_TEXT, SIM(max_steps), "N",
     "the most steps a run takes (1e8)", NULL, NULL},
    {"--method", NULL, CLI_CHOICE, SIM(method), "M",
     "the integrator (dop853; gl4 with --step when conservative)", methods, NULL},
    {"--precision", NULL, CLI_CHOICE, SIM(precision), "BITS",
     "the taylor method's arithmetic in bits", precisions, NULL},
    {"--initial", NULL, CLI_TEXT, SIM(initial), "STATE",
     "initial values \"q=VALUE, q'=VALUE, t=VALUE\" (momenta, speeds too)", NULL, NULL},
    CLI_OPT_SET(cli_sim_args, sets),
    {"--output", NULL, CLI_TEXT, SIM(output), "\"EXPR, ...\"",
     "more columns: expressions in the model's names", NULL, NULL},
    {"--out", "-o", CLI_TEXT, SIM(out), "FILE", "write the rows to FILE", NULL, NULL},
    {"--input", NULL, CLI_LIST, SIM(inputs), "\"F = EXPR\"",
     "an input's source: an expression, F=FILE.csv or \"F = lqr\" (repeatable)", NULL, NULL},
    {"--about", NULL, CLI_TEXT, SIM(about), "STATE", "the point LQR linearizes about", NULL, NULL},
    {"--lqr", NULL, CLI_TEXT, SIM(lqr), "\"Q = ..., R = ...\"", "the LQR weights", NULL, NULL},
    {"--event", NULL, CLI_LIST, SIM(events), "\"EXPR = EXPR[, EXPR > EXPR]\"",
     "rows where a crossing happens under the conditions (repeatable)", NULL, NULL},
    {"--stop-at", NULL, CLI_LIST, SIM(stops), "\"EXPR = EXPR[, ...]\"",
     "an event that ends the run (repeatable; numbered after the --event ones)", NULL, NULL},
    {"--native", NULL, CLI_FLAG, SIM(native), NULL, "compile the right-hand side to C", NULL, NULL},
    {"--jit", NULL, CLI_FLAG, SIM(jit), NULL, "machine code from the start (default: once the run is long)", NULL, NULL},
    {"--no-jit", NULL, CLI_FLAG, SIM(no_jit), NULL, "interpret the compiled programs throughout", NULL, NULL},
    {"--no-project", NULL, CLI_FLAG, SIM(no_project), NULL,
     "do not project onto the constraints after each step", NULL, NULL},
    {"--no-speeds", NULL, CLI_FLAG, SIM(no_speeds), NULL,
     "a model with speeds: integrate the multiplier form", NULL, NULL},
    {NULL, NULL, CLI_FLAG, 0, NULL, NULL, NULL, NULL},
};
#undef SIM

#define PLOT(field) offsetof(cli_plot_args, field)
const cli_opt cli_sim_plot_opts[] = {
    {"--plot", NULL, CLI_TEXT, PLOT(file), "FILE", "draw the run: FILE.png, .svg or .pdf", NULL,
     NULL},
    {"--plot-y", NULL, CLI_TEXT, PLOT(ycols), "\"NAME, ...; ...\"",
     "columns against t, a panel for each group between semicolons", NULL, NULL},
    {"--phase", NULL, CLI_TEXT, PLOT(phase), "Q", "draw Q' against Q", NULL, NULL},
    {NULL, NULL, CLI_FLAG, 0, NULL, NULL, NULL, NULL},
};
#undef PLOT

/* ---- the set-up, in the library (qdot/simsetup.h) --------------------------- */

/* The error just recorded, about the user's option opt of text: shown in
 * the text with a caret when located there, else as "opt: message". */
int cli_sim_fail_in(cli_sim *c, const char *opt, const char *text) {
    const qd_diag *d = qd_ctx_diag(c->ctx);
    if (d->located && text) {
        cli_diag_show(opt, text, d);
        return cli_exit(qd_ctx_status(c->ctx));
    }
    qd_diag e = *d;
    int k = snprintf(e.message, sizeof e.message, "%s: ", opt);
    if (k > 0 && (size_t)k < sizeof e.message)
        snprintf(e.message + k, sizeof e.message - (size_t)k, "%.200s", d->message);
    cli_diag_show("qdot", NULL, &e);
    return cli_exit(qd_ctx_status(c->ctx));
}

/* An option refused by qd_sim_setup_options: shown in its text when the
 * error is located there, after "--opt: " when not given, else the
 * library's sentence and the option its field names (cli_diag_ctx). */
static int option_error(cli_sim *c, const cli_sim_args *a) {
    const struct { const char *field, *opt, *text; } f[] = {
        {"t_end", "--t-end", a->t_end},    {"period", "--period", a->period},
        {"dt", "--dt", a->dt},             {"every", "--every", a->every},
        {"step", "--step", a->step},       {"rtol", "--rtol", a->rtol},
        {"atol", "--atol", a->atol},       {"max_steps", "--max-steps", a->max_steps},
        {"method", "--method", a->method}, {"precision", "--precision", a->precision},
        {"inputs", "--input", NULL}, /* "--input: input F is used but not supplied" */
    };
    const qd_diag *d = qd_ctx_diag(c->ctx);
    for (size_t i = 0; i < sizeof f / sizeof f[0]; i++)
        if (!strcmp(d->name, f[i].field) && (d->located || !f[i].text))
            return cli_sim_fail_in(c, f[i].opt, f[i].text);
    return cli_diag_ctx(c->ctx);
}

/* One --input (qd_sim_setup_input_text): an expression is the library's;
 * a table's file is read here (F=FILE.csv); "F = lqr" takes --about, --lqr. */
static int input(cli_sim *c, const char *text) {
    char name[128];
    qd_sim_input_kind kind;
    size_t a, b;
    if (qd_sim_setup_input_text(c->set, text, &kind, name, sizeof name, &a, &b) != QD_OK)
        return cli_sim_fail_in(c, "--input", text);
    if (kind == QD_SIM_INPUT_TABLE)
        return cli_sim_input_csv(c, name, text + a, b - a);
    return kind == QD_SIM_INPUT_LQR ? cli_sim_input_lqr(c, name) : QD_EXIT_OK;
}

static int events(cli_sim *c, const char *opt, const cli_list *l, bool stop) {
    for (size_t i = 0; i < l->n; i++)
        if (qd_sim_setup_event(c->set, l->items[i], stop) != QD_OK)
            return cli_sim_fail_in(c, opt, l->items[i]);
    return QD_EXIT_OK;
}

int cli_sim_setup(cli_sim *c, const cli_sim_args *a) {
    c->ctx = qd_ctx_new();
    if (!c->ctx) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    int rc = cli_load(c->ctx, a->file, a->sets.n, a->sets.items, "simulate", &c->mf);
    if (rc != QD_EXIT_OK)
        return rc;
    c->set = qd_sim_setup_new(c->ctx, c->mf.model, a->no_speeds);
    if (!c->set)
        return cli_eom_derive_error(c->ctx, &c->mf);
    c->s = qd_sim_setup_sim(c->set);
    c->e = qd_sim_setup_eom(c->set);
    c->se = qd_sim_setup_speeds_eom(c->set);
    const qd_expr *const *syms;
    const double *vals;
    c->st.n = qd_sim_setup_state(c->set, &syms, &vals);
    c->st.syms = (const qd_expr **)(void *)syms; /* a view: read only */
    c->st.vals = (double *)(void *)vals;
    if (a->initial && qd_sim_setup_initial(c->set, a->initial) != QD_OK)
        return cli_sim_fail_in(c, "--initial", a->initial);
    if (a->output && qd_sim_setup_outputs(c->set, a->output) != QD_OK)
        return cli_sim_fail_in(c, "--output", a->output);
    c->about = a->about;
    c->lqr = a->lqr;
    for (size_t i = 0; rc == QD_EXIT_OK && i < a->inputs.n; i++)
        rc = input(c, a->inputs.items[i]);
    if (rc == QD_EXIT_OK && (a->about || a->lqr) && !c->lqr_used) {
        cli_diag_error("%s is for --input \"NAME = lqr\" (the LQR feedback), which is not given",
                       a->lqr ? "--lqr" : "--about");
        rc = QD_EXIT_USAGE;
    }
    if (rc == QD_EXIT_OK)
        rc = events(c, "--event", &a->events, false);
    if (rc == QD_EXIT_OK)
        rc = events(c, "--stop-at", &a->stops, true);
    if (rc == QD_EXIT_OK && a->section && qd_sim_setup_event(c->set, a->section, false) != QD_OK)
        rc = cli_sim_fail_in(c, "--section", a->section);
    qd_sim_setup_opts so = {.t_end = a->t_end, .period = a->period, .dt = a->dt,
                            .step = a->step, .rtol = a->rtol, .atol = a->atol, .every = a->every,
                            .max_steps = a->max_steps, .method = a->method,
                            .precision = a->precision ? atoi(a->precision) : 0,
                            .no_project = a->no_project, .fixed = a->fixed};
    if (rc == QD_EXIT_OK && qd_sim_setup_options(c->set, &so, &c->opts) != QD_OK)
        rc = option_error(c, a);
    char note[400] = "";
    if (rc == QD_EXIT_OK && a->native &&
        qd_sim_setup_native(c->set, &c->opts, note, sizeof note) != QD_OK)
        rc = cli_diag_ctx(c->ctx);
    if (rc == QD_EXIT_OK && note[0])
        fprintf(stderr, "qdot: note: --%s\n", note);
    if (rc == QD_EXIT_OK && a->jit && a->no_jit) {
        cli_diag_error("--jit and --no-jit: give one");
        rc = QD_EXIT_USAGE;
    }
    c->opts.jit = a->jit ? QD_SIM_JIT_ON : a->no_jit ? QD_SIM_JIT_OFF : QD_SIM_JIT_AUTO;
    if (rc == QD_EXIT_OK && a->jit && qd_sim_setup_jit(c->set, note, sizeof note) != QD_OK)
        rc = cli_diag_ctx(c->ctx);
    if (rc == QD_EXIT_OK && a->jit && note[0])
        fprintf(stderr, "qdot: note: --%s\n", note);
    return rc;
}

void cli_sim_free(cli_sim *c) {
    qd_sim_setup_free(c->set);
    cli_model_file_free(&c->mf);
    qd_ctx_free(c->ctx);
}

int cli_sim_fail(cli_sim *c, qd_status st) {
    /* the initial velocities given violate a constraint: bad input */
    if (st == QD_ERR_ARG && !strcmp(qd_ctx_diag(c->ctx)->name, "initial"))
        return cli_sim_fail_in(c, "--initial", NULL);
    const char *msg = qd_ctx_message(c->ctx);
    cli_diag_error("%s", msg[0] ? msg : qd_status_str(st));
    /* options were checked before the run: what fails now is the system's,
     * but for an output or event the user wrote that has no value (a third
     * derivative, a name that is not an input), found when the run compiles */
    return st == QD_ERR_UNBOUND ? QD_EXIT_USAGE : QD_EXIT_FAIL;
}


