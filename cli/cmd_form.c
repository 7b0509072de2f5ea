/*
 * cli/cmd_form.c - `qdot form "EXPR" --vars "x, y"`: a quadratic form's
 * matrix, Lagrange's reduction to a sum of squares and its inertia
 * (qd_qform_reduce; Desloge App. 24-27), printed by qd_render_qform; the
 * variables read by qd_qform_vars_read (qdot/form.h).  --homogeneity: any
 * function's degree of homogeneity (qd_homogeneity, App. 20); --periods:
 * shifts tested as periods, and their fundamental system (qd_periods_reduce,
 * App. 31); --gram-schmidt: vectors orthogonalized under the form's matrix
 * (qd_gram_schmidt, App. 21); --change with --new: a change of variables in
 * the integral of EXPR, its Jacobian (qd_change_vars, App. 19); --positive
 * names symbols assumed positive, made before anything else is read.
 */
#include "driver.h"
#include "state.h"

#include "qdot/form.h"
#include "qdot/render.h"

typedef struct form_args {
    cli_run c; /* the options follow */
    const char *format, *vars, *text, *periods, *gram, *change, *newv, *positive;
    bool homog, fourier;
} form_args;

static const cli_opt form_opts[] = {
    {"--vars", NULL, CLI_TEXT, offsetof(form_args, vars), "\"x, y, ...\"",
     "the variables of the form (required)", NULL, NULL},
    {"--homogeneity", NULL, CLI_FLAG, offsetof(form_args, homog), NULL,
     "the degree of homogeneity of EXPR in the variables (Euler's theorem), or a witness", NULL, NULL},
    {"--periods", NULL, CLI_TEXT, offsetof(form_args, periods), "\"W1; W2 ...\"",
     "test these shifts as periods of EXPR, and their fundamental system (App. 31)", NULL, NULL},
    {"--gram-schmidt", NULL, CLI_TEXT, offsetof(form_args, gram), "\"A1; A2 ...\"",
     "orthogonalize these vectors under the form's matrix: b(i)^T a b(j) = 0 (App. 21)", NULL,
     NULL},
    {"--fourier", NULL, CLI_FLAG, offsetof(form_args, fourier), NULL,
     "EXPR, a trigonometric polynomial in the variables, as a sum of harmonics (App. 31)", NULL,
     NULL},
    {"--change", NULL, CLI_TEXT, offsetof(form_args, change), "\"x = X(y), ...\"",
     "change the variables of the integral of EXPR: each old variable in terms of --new, its "
     "Jacobian (App. 19)", NULL, NULL},
    {"--new", NULL, CLI_TEXT, offsetof(form_args, newv), "\"r, th, ...\"",
     "the new variables of --change, as many as --vars", NULL, NULL},
    {"--positive", NULL, CLI_TEXT, offsetof(form_args, positive), "\"r, b, ...\"",
     "symbols assumed positive (abs(r) is r), for the sign of a Jacobian", NULL, NULL},
    CLI_OPT_FORMAT(form_args, format),
    {0},
};

static const cli_spec form_spec = {
    "form", "EXPR --vars \"x, y, ...\" [--homogeneity | --periods \"W; ...\" | "
    "--gram-schmidt \"A; ...\" | --fourier | --change \"x = X(y), ...\" --new \"y, ...\"] "
    "[--positive \"r, ...\"] [--format F]",
    "a quadratic form: its matrix, Lagrange's reduction to a sum of squares, its inertia; "
    "or (--homogeneity) any function's degree of homogeneity, or (--periods) its periods, "
    "or (--gram-schmidt) vectors orthogonalized under its matrix, or (--change) a change of "
    "variables in its integral",
    form_opts, NULL, 1, 1, "EXPR", true,
};

static int check(cli_run *c) {
    const form_args *a = (form_args *)c;
    if (!!a->gram + !!a->periods + a->homog + a->fourier + !!a->change > 1)
        return cli_usage_error("--homogeneity, --periods, --gram-schmidt, --fourier and --change "
                               "are questions of their own: give one");
    if (!a->change != !a->newv)
        return cli_usage_error(a->change ? "--change needs --new \"y1, y2, ...\", the new "
                                           "variables"
                                         : "--new is the new variables of --change");
    if (a->vars)
        return QD_EXIT_OK;
    return cli_usage_error("--vars is missing (usage: qdot form %s)", form_spec.synopsis);
}

/* --gram-schmidt: the s vectors a orthogonalized under the form's matrix
 * (Thm 1 when it is the identity, x^2 + y^2 + ...). */
static int gram(qd_ctx *ctx, const form_args *a, const qd_expr *phi, const qd_expr *const *x,
                size_t n, size_t s, const qd_expr *const *v) {
    qd_qform *f = qd_qform_reduce(ctx, phi, n, x);
    qd_gram *g = f ? qd_gram_schmidt(ctx, n, f->a, s, v) : NULL;
    qd_buf b = QD_BUF_INIT;
    qd_status st = g ? qd_render_gram(ctx, g, x, f->a, cli_render_format(a->format), &b)
                     : qd_ctx_status(ctx);
    qd_gram_free(g);
    qd_qform_free(f);
    return cli_emit_status(ctx, st, &b, "orthogonalization");
}

/* --change: f = EXPR in the n old variables x, x = X(y) read from --change
 * in the new ones of --new. */
static int change(qd_ctx *ctx, const form_args *a, const qd_expr *f, const qd_expr *const *x,
                  size_t n) {
    const qd_expr *y[64], *map[64];
    size_t m = 0;
    if (qd_qform_vars_read(ctx, a->newv, y, 64, &m) != QD_OK)
        return cli_state_diag(ctx, "--new", a->newv);
    if (m != n)
        return cli_usage_error("--new names %zu variable%s for the %zu of --vars", m,
                               m == 1 ? "" : "s", n);
    if (qd_change_read(ctx, a->change, n, x, map) != QD_OK)
        return cli_state_diag(ctx, "--change", a->change);
    qd_change *c = qd_change_vars(ctx, f, n, x, y, map);
    qd_buf b = QD_BUF_INIT;
    qd_status st = c ? qd_render_change(ctx, c, cli_render_format(a->format), &b)
                     : qd_ctx_status(ctx);
    qd_change_free(c);
    return cli_emit_status(ctx, st, &b, "change of variables");
}

/* --fourier: EXPR as a sum of harmonics in the variables. */
static int fourier(qd_ctx *ctx, const form_args *a, const qd_expr *f, const qd_expr *const *x,
                   size_t n) {
    qd_fourier *s = qd_fourier_series(ctx, f, n, x);
    qd_buf b = QD_BUF_INIT;
    qd_status st = s ? qd_render_fourier(ctx, s, f, x, cli_render_format(a->format), &b)
                     : qd_ctx_status(ctx);
    qd_fourier_free(s);
    return cli_emit_status(ctx, st, &b, "Fourier series");
}

/* The reduction, or (--homogeneity) the degree: a "no" exits 3, undecided 1. */
static int answer(qd_ctx *ctx, const form_args *a, const qd_expr *phi, const qd_expr *const *x,
                  size_t n, size_t g, const qd_expr *const *w) {
    qd_buf b = QD_BUF_INIT;
    qd_homog h = {.verdict = QD_HOMOG_YES};
    qd_periods *p = w ? qd_periods_reduce(ctx, phi, n, x, g, w) : NULL;
    qd_qform *f = a->homog || w ? NULL : qd_qform_reduce(ctx, phi, n, x);
    qd_render_format fmt = cli_render_format(a->format);
    bool ok = w         ? p && qd_render_periods(ctx, phi, p, x, w, fmt, &b) == QD_OK
              : a->homog ? qd_homogeneity(ctx, phi, n, x, &h) == QD_OK &&
                               qd_render_homog(ctx, &h, n, x, fmt, &b) == QD_OK
                         : f && qd_render_qform(ctx, phi, f, fmt, &b) == QD_OK;
    for (size_t j = 0; p && j < g; j++) /* a shift that is certainly no period: a "no" */
        h.verdict = p->test[j].kind == QD_ZERO_NONZERO ? QD_HOMOG_NO : h.verdict;
    qd_qform_free(f);
    qd_periods_free(p);
    if (!ok) {
        qd_buf_free(&b);
        return cli_diag_ctx(ctx);
    }
    int rc = cli_emit(&b, a->homog ? "homogeneity" : "quadratic form");
    return rc ? rc : h.verdict == QD_HOMOG_NO ? QD_EXIT_NO
                   : h.verdict == QD_HOMOG_UNDECIDED ? QD_EXIT_FAIL : QD_EXIT_OK;
}

static int run(cli_run *c) {
    const form_args *a = (form_args *)c;
    qd_diag err;
    const qd_expr *x[64], **w = NULL;
    size_t n = 0, g = 0;
    if (a->positive && qd_qform_positive_read(c->ctx, a->positive, x, 64, &n) != QD_OK)
        return cli_state_diag(c->ctx, "--positive", a->positive);
    n = 0;
    const qd_expr *phi = qd_read(c->ctx, a->text, NULL, &err);
    if (!phi) {
        cli_diag_read("<form>", a->text, &err);
        return QD_EXIT_USAGE;
    }
    if (qd_qform_vars_read(c->ctx, a->vars, x, 64, &n) != QD_OK)
        return cli_state_diag(c->ctx, "--vars", a->vars);
    if (a->change)
        return change(c->ctx, a, phi, x, n);
    if (a->fourier)
        return fourier(c->ctx, a, phi, x, n);
    const char *vecs = a->gram ? a->gram : a->periods;
    if (vecs && qd_periods_vectors_read(c->ctx, vecs, n, &g, &w) != QD_OK)
        return cli_state_diag(c->ctx, a->gram ? "--gram-schmidt" : "--periods", vecs);
    int rc = a->gram ? gram(c->ctx, a, phi, x, n, g, w) : answer(c->ctx, a, phi, x, n, g, w);
    qd_periods_vectors_free(w);
    return rc;
}

CLI_COMMAND(form, form_args, &form_spec, 0, offsetof(form_args, text), check, run, NULL)
