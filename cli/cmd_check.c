/*
 * cli/cmd_check.c - `qdot check FILE [--format text|json]`: validate a model
 * and summarize it.
 *
 * Valid means it parses (every name known, every parameter valued, T or L
 * given), its equations can be derived (the mass matrix is not identically
 * singular), and with the parameters' values the mass matrix is positive
 * definite and each constraint has a real solution near the initial state
 * (qd_check_verdict_of).  A model that does not read or derive is bad input
 * (exit 2); one that reads but fails the numbers is a certified "no" (exit
 * 3), its witness shown at the statement to blame or in the JSON.  The
 * verdict and the summary are the library's (qdot/render.h).
 */
#include "driver.h"

#include <stdio.h>
#include "eom_out.h"
#include "qdot/render.h"

typedef struct check_args {
    cli_run c; /* the option follows */
    const char *format;
} check_args;

static const cli_opt check_opts[] = {
    {"--format", NULL, CLI_CHOICE, offsetof(check_args, format), "F",
     "the summary as text or as JSON (with \"ok\", and \"code\", \"reason\" and \"witness\" for a no)",
     cli_formats_text_json, NULL},
    {0},
};

static const cli_spec check_spec = {
    "check", "FILE [--format F]",
    "validate a model and summarize it (exit 3: it fails a check, with the witness)",
    check_opts, NULL, 1, 1, "FILE", false,
};

static int summarize(qd_ctx *ctx, const cli_model_file *mf, bool json, qd_buf *out) {
    qd_eom *e = qd_eom_derive(ctx, mf->model);
    if (!e)
        return cli_eom_derive_error(ctx, mf);
    qd_check_verdict v;
    qd_render_opts o = {.source = mf->path};
    qd_status st = qd_check_verdict_of(ctx, mf->model, e, &v);
    if (st == QD_OK)
        st = qd_render_check(ctx, mf->model, e, &o, &v, json ? QD_RENDER_JSON : QD_RENDER_TEXT,
                             out);
    qd_eom_free(e);
    if (st != QD_OK)
        return cli_diag_ctx(ctx);
    if (!v.ok && !json)
        cli_model_file_error(mf, v.statement, v.message, v.hint);
    if (v.off_constraint && !json)
        fprintf(stderr, "%s: note: the initial state is off constraint %s by %.3g; a run "
                "projects it onto the constraints first\n", mf->path, v.residual_con,
                v.residual);
    return v.ok ? QD_EXIT_OK : QD_EXIT_NO;
}

static int run(cli_run *c) {
    bool json = cli_json(((check_args *)c)->format);
    qd_buf out = QD_BUF_INIT;
    int rc = cli_model_file_load(c->ctx, c->file, &c->mf);
    if (rc == QD_EXIT_OK)
        rc = summarize(c->ctx, &c->mf, json, &out);
    if (rc == QD_EXIT_OK || (rc == QD_EXIT_NO && json))
        fputs(qd_buf_str(&out), stdout);
    qd_buf_free(&out);
    return rc;
}

CLI_COMMAND(check, check_args, &check_spec, 0, 0, NULL, run, NULL)
