/*
 * cli/cmd_form.c - `qdot form "EXPR" --vars "x, y"`: a quadratic form's
 * matrix, Lagrange's reduction to a sum of squares and its inertia
 * (qd_qform_reduce; Desloge App. 24-27), printed by qd_render_qform; the
 * variables read by qd_qform_vars_read (qdot/form.h).  --homogeneity: any
 * function's degree of homogeneity (qd_homogeneity, App. 20).
 */
#include "driver.h"

#include "qdot/form.h"
#include "qdot/render.h"

typedef struct form_args {
    cli_run c; /* the options follow */
    const char *format, *vars, *text;
    bool homog;
} form_args;

static const cli_opt form_opts[] = {
    {"--vars", NULL, CLI_TEXT, offsetof(form_args, vars), "\"x, y, ...\"",
     "the variables of the form (required)", NULL, NULL},
    {"--homogeneity", NULL, CLI_FLAG, offsetof(form_args, homog), NULL,
     "the degree of homogeneity of EXPR in the variables (Euler's theorem), or a witness", NULL, NULL},
    CLI_OPT_FORMAT(form_args, format),
    {0},
};

static const cli_spec form_spec = {
    "form", "EXPR --vars \"x, y, ...\" [--homogeneity] [--format F]",
    "a quadratic form: its matrix, Lagrange's reduction to a sum of squares, its inertia; "
    "or (--homogeneity) any function's degree of homogeneity",
    form_opts, NULL, 1, 1, "EXPR", true,
};

static int check(cli_run *c) {
    if (((form_args *)c)->vars)
        return QD_EXIT_OK;
    return cli_usage_error("--vars is missing (usage: qdot form %s)", form_spec.synopsis);
}

/* --homogeneity: a "no" exits 3, undecided 1. */
static int homogeneity(qd_ctx *ctx, const qd_expr *f, const qd_expr *const *x, size_t n,
                       const char *format) {
    qd_homog h;
    qd_buf b = QD_BUF_INIT;
    if (qd_homogeneity(ctx, f, n, x, &h) != QD_OK ||
        qd_render_homog(ctx, &h, n, x, cli_render_format(format), &b) != QD_OK) {
        qd_buf_free(&b);
        return cli_diag_ctx(ctx);
    }
    int rc = cli_emit(&b, "homogeneity");
    return rc ? rc : h.verdict == QD_HOMOG_NO ? QD_EXIT_NO : h.verdict == QD_HOMOG_YES ||
                     h.verdict == QD_HOMOG_EVERY ? QD_EXIT_OK : QD_EXIT_FAIL;
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
    } else if (a->homog) {
        return homogeneity(ctx, phi, x, n, a->format);
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
