/*
 * cli/cmd_form.c - `qdot form "EXPR" --vars "x, y"`: a quadratic form's
 * matrix, Lagrange's reduction to a sum of squares and its inertia
 * (qd_qform_reduce; Desloge App. 24-27), printed by qd_render_qform; the
 * variables read by qd_qform_vars_read (qdot/form.h).
 */
#include "driver.h"

#include "qdot/form.h"
#include "qdot/render.h"

typedef struct form_args {
    cli_run c; /* the options follow */
    const char *format, *vars, *text;
} form_args;

static const cli_opt form_opts[] = {
    {"--vars", NULL, CLI_TEXT, offsetof(form_args, vars), "\"x, y, ...\"",
     "the variables of the form (required)", NULL, NULL},
    CLI_OPT_FORMAT(form_args, format),
    {0},
};

static const cli_spec form_spec = {
    "form", "EXPR --vars \"x, y, ...\" [--format F]",
    "a quadratic form: its matrix, Lagrange's reduction to a sum of squares, its inertia",
    form_opts, NULL, 1, 1, "EXPR", true,
};

static int check(cli_run *c) {
    if (((form_args *)c)->vars)
        return QD_EXIT_OK;
    return cli_usage_error("--vars is missing (usage: qdot form %s)", form_spec.synopsis);
}

static int run(cli_run *c) {
    const form_args *a = (form_args *)c;
    qd_ctx *ctx = c->ctx;
    qd_diag err;
    const qd_expr *phi = qd_read(ctx, a->text, NULL, &err), *x[64];
    size_t n = 0;
    qd_qform *f = NULL;
    int rc = QD_EXIT_OK;
    if (!phi) {
        cli_diag_read("<form>", a->text, &err);
        rc = QD_EXIT_USAGE;
    } else if (qd_qform_vars_read(ctx, a->vars, x, 64, &n) != QD_OK) {
        cli_diag_show("--vars", a->vars, qd_ctx_diag(ctx));
        rc = cli_exit(qd_ctx_status(ctx));
    } else if (!(f = qd_qform_reduce(ctx, phi, n, x))) {
        rc = cli_diag_ctx(ctx);
    }
    if (f) {
        qd_buf b = QD_BUF_INIT;
        if (qd_render_qform(ctx, phi, f, cli_render_format(a->format), &b) == QD_OK)
            fputs(qd_buf_str(&b), stdout);
        rc = qd_ctx_status(ctx) == QD_OK ? QD_EXIT_OK : cli_diag_ctx(ctx);
        qd_buf_free(&b);
    }
    qd_qform_free(f);
    return rc;
}

CLI_COMMAND(form, form_args, &form_spec, 0, offsetof(form_args, text), check, run, NULL)
