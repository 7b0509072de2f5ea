/*
 * cli/cmd_eom.c - `qdot eom FILE`: Lagrange's equations of a model,
 *
 *     d/dt(dL/dq'_j) - dL/dq_j + dD/dq'_j = Q_j,   written   M q'' = f,
 *
 * derived by libqdot (qd_eom_derive) from the model read with the --set
 * values in place of its parameters', solved for q'' with --solve, or evaluated at a state with
 * --at.  Constraints add multipliers, M q'' = f + A^T lambda with A q'' = b;
 * --eliminate substitutes the holonomic ones that can be solved for a
 * coordinate instead.  With --at, the model's `reaction` statements give
 * the Cartesian force of a constraint at a point (qd_eom_reaction).  A model
 * that declares `speeds` gets its equations in the speeds instead,
 * q' = W u + w and M_u u' = f_u (qd_speeds_derive, by --method kane, appell
 * or hamel), with --appell the Gibbs-Appell function, with --multipliers
 * the constraint forces, and with --at the numbers at a state of q, u and t
 * (qd_speeds_eval).  The derivation, the state read and the renderings are
 * the library's (qd_eom_request_render, qdot/render.h); the options are here.
 */
#include "driver.h"

#include <string.h>
#include "eom_out.h"
#include "qdot/render.h"

/* Symbolic accelerations larger than this (count_ops, per entry) are not
 * worth printing: M and f say the same in far less space. */
#define SOLVE_MAX_OPS 2000

typedef struct eom_args {
    const char *format, *method, *at;
    bool solve, eliminate;
    bool appell, multipliers, hamel_coef; /* speeds only */
    cli_list sets;
    /* from the above */
    bool field; /* FILE declares a field */
    qd_render_format fmt;
    qd_speeds_method smethod;
} eom_args;

typedef struct eom_run {
    cli_run c;
    eom_args a;
} eom_run;

static const char *const formats[] = {"text", "latex", "json", "sympy", "c", NULL};
static const char *const methods[] = {"kane", "appell", "hamel", NULL}; /* qd_speeds_method_name */

#define ARG(f) offsetof(eom_args, f)
static const cli_opt eom_opts[] = {
    {"--format", NULL, CLI_CHOICE, ARG(format), "F", "the output format", formats, NULL},
    {"--solve", NULL, CLI_FLAG, ARG(solve), NULL,
     "also the accelerations q'' = M^-1 f (or u') and the multipliers, symbolically", NULL, NULL},
    {"--eliminate", NULL, CLI_FLAG, ARG(eliminate), NULL,
     "substitute the holonomic constraints that can be solved for a coordinate", NULL, NULL},
    CLI_OPT_SET(eom_args, sets),
    {"--at", NULL, CLI_TEXT, ARG(at), "STATE",
     "the numbers at a state \"q=..., q'=..., t=...\" (with speeds: the speeds)", NULL, NULL},
    {"--method", NULL, CLI_CHOICE, ARG(method), "M",
     "speeds: the derivation, kane by default", methods, NULL},
    {"--appell", NULL, CLI_FLAG, ARG(appell), NULL, "speeds: also the Gibbs-Appell function S",
     NULL, NULL},
    {"--multipliers", NULL, CLI_FLAG, ARG(multipliers), NULL,
     "speeds: also the constraints' multipliers", NULL, NULL},
    {"--hamel-coefficients", NULL, CLI_FLAG, ARG(hamel_coef), NULL,
     "speeds: Hamel's coefficients gamma_ikm instead of the equations", NULL, NULL},
    {0},
};

static const cli_spec eom_spec = {
    "eom", "FILE [options]", "Lagrange's equations of a model, M q'' = f (or in its speeds)",
    eom_opts, NULL, 1, 1, "FILE", false,
};

/* The names into the library's enums, and the options a field model takes. */
static int check(cli_run *c) {
    eom_args *a = &((eom_run *)c)->a;
    a->fmt = QD_RENDER_TEXT;
    if (a->format && !qd_render_format_parse(a->format, &a->fmt))
        return QD_EXIT_FAIL; /* the table's choices are the library's names */
    if (a->method && !qd_speeds_method_from_name(a->method, &a->smethod))
        return QD_EXIT_FAIL;
    if ((a->field = cli_model_file_is_field(c->file)) &&
        (a->solve || a->eliminate || a->appell || a->multipliers || a->hamel_coef || a->method ||
         a->at || (a->fmt != QD_RENDER_TEXT && a->fmt != QD_RENDER_JSON)))
        return cli_usage_error("a field model takes --set and --format text|json only");
    return QD_EXIT_OK;
}

/* An option of one kind of model given for the other: its name, or NULL. */
static const char *speeds_option(const eom_args *a) {
    return a->method ? "--method" : a->appell ? "--appell" : a->multipliers ? "--multipliers"
           : a->hamel_coef ? "--hamel-coefficients"
                                                                          : NULL;
}

/* The options of the other kind of model refused, in the words of each. */
static int refuse(const eom_run *r, const eom_args *a, bool speeds) {
    const char *opt = speeds ? (a->eliminate ? "--eliminate" : NULL) : speeds_option(a);
    if (opt && !speeds) {
        cli_diag_error("%s is for a model with generalized speeds, and %s declares no speeds "
                       "(a `speeds` statement; without one, --solve gives the multipliers)",
                       opt, r->c.file);
        return QD_EXIT_USAGE;
    }
    if (opt)
        return cli_usage_error("%s is not available for a model with generalized speeds (%s "
                               "declares them): qdot eom prints M u' = f in the speeds",
                               opt, r->c.file);
    if (speeds && a->at && a->fmt != QD_RENDER_TEXT && a->fmt != QD_RENDER_JSON)
        return cli_usage_error("--at with speeds prints text or json");
    return QD_EXIT_OK;
}

/* The library's notes on stderr, the rendering on stdout; the error of the
 * step that failed. */
static int emit(eom_run *r, qd_status st, qd_eom_step step, qd_buf *b, qd_buf *notes) {
    const char *s = qd_buf_str(notes), *nl;
    for (; *s && (nl = strchr(s, '\n')); s = nl + 1)
        fprintf(stderr, "qdot: note: %.*s\n", (int)(nl - s), s);
    if (st == QD_OK)
        fputs(qd_buf_str(b), stdout);
    qd_buf_free(b);
    qd_buf_free(notes);
    if (st == QD_OK)
        return QD_EXIT_OK;
    if (step == QD_EOM_STEP_DERIVE)
        return cli_eom_derive_error(r->c.ctx, &r->c.mf);
    if (step == QD_EOM_STEP_AT)
        return cli_state_diag(r->c.ctx, "--at", r->a.at);
    if (step == QD_EOM_STEP_SOLVE && st != QD_ERR_NOMEM) {
        cli_diag_error("cannot solve for the %s: %s",
                       qd_model_nspeeds(r->c.mf.model) ? "speeds' rates" : "accelerations",
                       qd_ctx_message(r->c.ctx));
        return QD_EXIT_FAIL;
    }
    return cli_diag_ctx(r->c.ctx);
}

static int run(cli_run *c) {
    eom_run *r = (eom_run *)c;
    const eom_args *a = &r->a;
    if (a->field)
        return cli_field_eom(c->ctx, &c->mf, c->file, a->sets.n, a->sets.items,
                             a->fmt == QD_RENDER_JSON);
    int rc = cli_load(c->ctx, c->file, a->sets.n, a->sets.items, "eom", &c->mf);
    if (rc == QD_EXIT_OK)
        rc = refuse(r, a, qd_model_nspeeds(c->mf.model) > 0);
    if (rc != QD_EXIT_OK)
        return rc;
    qd_eom_request rq = {.fmt = a->fmt, .source = c->mf.path, .at = a->at, .solve = a->solve,
                         .max_ops = SOLVE_MAX_OPS, .eliminate = a->eliminate,
                         .speeds = {.method = a->smethod, .appell = a->appell,
                                    .multipliers = a->multipliers},
                         .hamel = a->hamel_coef};
    qd_buf b = QD_BUF_INIT, notes = QD_BUF_INIT;
    qd_eom_step step;
    qd_status st = qd_eom_request_render(c->ctx, c->mf.model, &rq, &b, &notes, &step);
    return emit(r, st, step, &b, &notes);
}

CLI_COMMAND(eom, eom_run, &eom_spec, offsetof(eom_run, a), 0, check, run, NULL)
