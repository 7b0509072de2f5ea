/*
 * cli/cmd_linearize.c - `qdot linearize FILE --about "q=..., q'=..., F=..."`:
 * the state-space form x' = A x + B u, y = C x + D u about an operating
 * point (qd_linearize_about), the eigenvalues of A, and controllability and
 * observability; with --lqr "Q = ..., R = ...", the LQR gain on A and B
 * (qd_lqr_design).  Printed by qd_statespace_render (qdot/statespace.h) in
 * the formats text, json, c, sympy, octave.
 */
#include "linear_cli.h"

#include <stdlib.h>
#include <string.h>
#include "lqr_cli.h"
#include "plot_cli.h"
#include "qdot/statespace.h"

enum { F_TEXT, F_JSON, F_C, F_SYMPY, F_OCTAVE };
static const char *const formats[] = {"text", "json", "c", "sympy", "octave", NULL};

typedef struct lin_args {
    const char *about, *lqr, *independent, *format_name, *scan;
    cli_list sets;
    int format;
    cli_plot_args look; /* --plot with --scan: the eigenvalues against the parameter */
} lin_args;

static const cli_opt opts[] = {
    {"--about", NULL, CLI_TEXT, offsetof(lin_args, about), "\"q=V, q'=V, F=V, ...\"",
     "the operating point: coordinates, velocities, inputs (others 0)", NULL, NULL},
    {"--set", NULL, CLI_LIST, offsetof(lin_args, sets), "NAME=VALUE",
     "give a parameter another value", NULL, NULL},
    {"--lqr", NULL, CLI_TEXT, offsetof(lin_args, lqr), "\"Q = ..., R = ...\"",
     "also the LQR gain for these weights", NULL, NULL},
    {"--independent", NULL, CLI_TEXT, offsetof(lin_args, independent), "\"q1, ...\"",
     "the independent coordinates on a constraint manifold", NULL, NULL},
    {"--scan", NULL, CLI_TEXT, offsetof(lin_args, scan), "NAME=A:B", "constraints: the "
     "eigenvalues at 101 values of a parameter, and where stability changes", NULL, NULL},
    {"--format", NULL, CLI_CHOICE, offsetof(lin_args, format_name), "F", "output format",
     formats, NULL},
    {"--plot", NULL, CLI_TEXT, offsetof(lin_args, look.file), "FILE.png|.svg|.pdf",
     "with --scan: the eigenvalues against the parameter, each change of stability marked",
     NULL, NULL},
    {NULL, NULL, CLI_FLAG, 0, NULL, NULL, NULL, NULL},
};

static const cli_group groups[] = {CLI_PLOT_LOOK_GROUP(lin_args, look), {NULL, 0}};

static const cli_spec spec = {
    "linearize", "FILE [options]",
    "The state-space form x' = A x + B u, y = C x + D u about an operating point, the "
    "eigenvalues of A, controllability and observability.",
    opts, groups, 1, 1, "FILE", false};

/* The state-space form, then the design when there is one (text and C
 * print it after the matrices, JSON nests it under "lqr"): the library's
 * printer, in the format chosen. */
static int emit(qd_ctx *ctx, const lin_args *a, const qd_statespace *s,
                const qd_care_result *lqr) {
    static const qd_ss_format fmt[] = {QD_SS_TEXT, QD_SS_JSON, QD_SS_C, QD_SS_SYMPY,
                                       QD_SS_OCTAVE};
    qd_buf b = QD_BUF_INIT;
    return cli_emit_status(ctx, qd_statespace_render(ctx, s, lqr, fmt[a->format], &b), &b,
                           "state-space form");
}

/* A model that keeps constraints: on its state manifold (cli_conlin). */
static int constrained(qd_ctx *ctx, const lin_args *a, cli_model_file *mf, qd_eom *e) {
    static const qd_ss_format fmt[] = {QD_SS_TEXT, QD_SS_JSON, QD_SS_C, QD_SS_SYMPY,
                                       QD_SS_OCTAVE};
    if (!e->ncon)
        return cli_usage_error("%s: the model keeps no constraints",
                               a->scan ? "--scan" : "--independent");
    cli_lin_run r = {.c = {.ctx = ctx, .mf = *mf}, .e = e};
    const cli_conlin_args ca = {a->about, a->independent, a->scan, a->lqr, fmt[a->format], 0,
                                false, NULL, NULL, &a->look};
    int rc = cli_lin_setup(&r);
    if (rc == QD_EXIT_OK)
        rc = cli_conlin(&r, &ca);
    qd_linpoint_free(&r.pt);
    return rc;
}

typedef struct lin_run {
    cli_run c;
    lin_args a;
    qd_eom *e;
    qd_statespace s;
    qd_care_result lqr;
} lin_run;

/* The format's index, and --lqr's formats. */
static int check(cli_run *c) {
    lin_args *a = &((lin_run *)c)->a;
    for (int k = 0; a->format_name && formats[k]; k++)
        if (!strcmp(formats[k], a->format_name))
            a->format = k;
    if (a->lqr && a->format != F_TEXT && a->format != F_JSON && a->format != F_C)
        return cli_usage_error("--lqr prints as text, json or c, not %s", formats[a->format]);
    if (a->look.file && !a->scan)
        return cli_usage_error("--plot draws the eigenvalues of --scan NAME=A:B: give --scan");
    return cli_plot_check(&a->look, "linearize");
}

static int run(cli_run *c) {
    lin_run *r = (lin_run *)c;
    const lin_args *a = &r->a;
    qd_ctx *ctx = c->ctx;
    qd_eom_opts eo = {.eliminate = true};
    int rc = cli_load_derive(ctx, c->file, a->sets.n, a->sets.items, "linearize", &eo, &c->mf, &r->e);
    if (rc == QD_EXIT_OK && (r->e->ncon || a->independent || a->scan))
        return constrained(ctx, a, &c->mf, r->e);
    if (rc == QD_EXIT_OK && qd_linearize_about(ctx, r->e, c->mf.model, a->about, &r->s) != QD_OK) {
        if (qd_ctx_diag(ctx)->located)
            return cli_state_diag(ctx, "--about", a->about);
        rc = cli_exit(qd_ctx_status(ctx));
        cli_diag_error("%s", qd_ctx_message(ctx));
    }
    if (rc == QD_EXIT_OK && a->lqr)
        rc = cli_lqr_design(ctx, &r->s, a->lqr, &r->lqr);
    if (rc == QD_EXIT_OK)
        rc = emit(ctx, a, &r->s, a->lqr ? &r->lqr : NULL);
    return rc;
}

static void run_free(cli_run *c) {
    lin_run *r = (lin_run *)c;
    qd_care_result_free(&r->lqr);
    qd_statespace_free(&r->s);
    qd_eom_free(r->e);
}

int cli_cmd_linearize(int argc, char **argv) {
    static const cli_driver d = {&spec, offsetof(lin_run, a), 0, check, run, run_free};
    lin_run r = {0};
    return cli_drive(&d, &r.c, argc, argv);
}
