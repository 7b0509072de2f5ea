/*
 * cli/cmd_bracket.c - `qdot bracket FILE F G`: the Poisson bracket [F, G]
 * (qd_bracket) in the model's canonical variables (qd_phase); `--dt F`
 * gives dF/dt along the motion (qd_phase_dt: [F, H], the explicit t and the
 * forces' part; for an implicit H in q' too).  F and G are expressions, so
 * "-x" is one and `--` ends the options.  Written by qd_phase_bracket_print
 * (qdot/canonical.h).
 */
#include "cli.h"

#include <stddef.h>
#include <string.h>
#include "model_cli.h"
#include "model_file.h"

typedef struct br_args {
    bool dt;
    const char *format;
} br_args;

static const char *const formats[] = {"text", "json", "latex", NULL};

static const cli_opt opts[] = {
    {"--dt", NULL, CLI_FLAG, offsetof(br_args, dt), NULL,
     "dF/dt along the motion instead of [F, G] (give F only)", NULL, NULL},
    {"--format", NULL, CLI_CHOICE, offsetof(br_args, format), "FORMAT", "how to write it",
     formats, NULL},
    {0},
};

static const cli_spec spec = {
    "bracket", "FILE F G | FILE --dt F [options]",
    "The Poisson bracket [F, G] in the model's coordinates and momenta p_<q>, or dF/dt.",
    opts, NULL, 2, 3, "FILE and expressions", true,
};

/* Read what (F or G) as a function on phase space; the error shown in it. */
static int read_fn(qd_ctx *ctx, const qd_phase *ph, const char *what, const char *text,
                   const qd_expr **out) {
    qd_diag err;
    if ((*out = qd_phase_read(ctx, ph, text, &err)))
        return QD_EXIT_OK;
    cli_diag_read(what, text, &err);
    return cli_exit(err.status);
}

static int run(qd_ctx *ctx, const cli_model_file *mf, qd_phase *ph, const br_args *a,
               const char *const *pos) {
    const qd_expr *F, *G = NULL, *r;
    int rc = read_fn(ctx, ph, "F", pos[1], &F);
    if (rc == QD_EXIT_OK && !a->dt)
        rc = read_fn(ctx, ph, "G", pos[2], &G);
    if (rc != QD_EXIT_OK)
        return rc;
    r = a->dt ? qd_phase_dt(ctx, ph, F) : qd_bracket(ctx, ph->n, ph->q, ph->p, F, G);
    if (!r)
        return cli_diag_model(ctx, mf->path, mf->text, mf->model);
    qd_buf b = QD_BUF_INIT;
    bool json = a->format && !strcmp(a->format, "json");
    qd_format fmt = a->format && !strcmp(a->format, "latex") ? QD_FMT_LATEX : QD_FMT_TEXT;
    if (qd_phase_bracket_print(ctx, ph, F, G, r, fmt, json, &b) != QD_OK) {
        qd_buf_free(&b);
        return cli_diag_ctx(ctx);
    }
    return cli_emit(&b, "bracket");
}

int cli_cmd_bracket(int argc, char **argv) {
    br_args a = {0};
    const char *pos[3];
    int rc = cli_parse(&spec, argc, argv, &a, pos);
    if (rc == QD_EXIT_OK && (a.dt ? pos[2] != NULL : pos[2] == NULL)) {
        cli_diag_error(a.dt ? "bracket --dt takes one expression F" : "bracket needs F and G");
        cli_usage(&spec, stderr);
        rc = QD_EXIT_USAGE;
    }
    if (rc != QD_EXIT_OK)
        return rc;
    qd_ctx *ctx = qd_ctx_new();
    cli_model_file mf = {0};
    qd_phase ph = {0};
    if (!ctx)
        cli_diag_error("out of memory");
    rc = ctx ? cli_load(ctx, pos[0], 0, NULL, true, &mf) : QD_EXIT_FAIL;
    if (rc == QD_EXIT_OK && qd_phase_init(ctx, mf.model, &ph) != QD_OK)
        rc = cli_diag_ctx(ctx);
    if (rc == QD_EXIT_OK)
        rc = run(ctx, &mf, &ph, &a, pos);
    qd_phase_free(&ph);
    cli_model_file_free(&mf);
    qd_ctx_free(ctx);
    return rc;
}
