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
 * (qd_speeds_eval).  The derivation and the renderings are the library's
 * (qdot/render.h); the options and the state read are here.
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
    qd_eom *e;
    cli_state st;
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
    {"--set", NULL, CLI_LIST, ARG(sets), "NAME=VALUE", "a parameter's value (an expression)",
     NULL, NULL},
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

/* --solve: q'' (or u') symbolically; M and f stay when too large. */
static int solved(eom_run *r, qd_status st, const char *what) {
    if (st == QD_OK)
        return QD_EXIT_OK;
    if (st == QD_ERR_TOOBIG) {
        fprintf(stderr, "qdot: note: the solved %s exceed %d operations; "
                        "printing M and f instead (use --at for numbers)\n", what, SOLVE_MAX_OPS);
        qd_ctx_clear_error(r->c.ctx);
        return QD_EXIT_OK;
    }
    if (st == QD_ERR_NOMEM)
        return cli_diag_ctx(r->c.ctx);
    cli_diag_error("cannot solve for the %s: %s", !strcmp(what, "rates") ? "speeds' rates"
                   : what, qd_ctx_message(r->c.ctx));
    return QD_EXIT_FAIL;
}

/* The rendering on stdout, its notes on stderr; the error if it failed. */
static int emit(eom_run *r, qd_status st, qd_buf *b, qd_buf *notes) {
    const char *s = qd_buf_str(notes), *nl;
    for (; *s && (nl = strchr(s, '\n')); s = nl + 1)
        fprintf(stderr, "qdot: note: %.*s\n", (int)(nl - s), s);
    if (st == QD_OK)
        fputs(qd_buf_str(b), stdout);
    qd_buf_free(b);
    qd_buf_free(notes);
    return st == QD_OK ? QD_EXIT_OK : cli_diag_ctx(r->c.ctx);
}

static qd_render_opts render_opts(eom_run *r, const eom_args *a, qd_buf *notes) {
    return (qd_render_opts){.source = r->c.mf.path, .nstate = a->at ? r->st.n : 0,
                            .syms = r->st.syms, .vals = r->st.vals,
                            .multipliers = a->multipliers, .notes = notes};
}

/* An option of one kind of model given for the other: its name, or NULL. */
static const char *speeds_option(const eom_args *a) {
    return a->method ? "--method" : a->appell ? "--appell" : a->multipliers ? "--multipliers"
           : a->hamel_coef ? "--hamel-coefficients"
                                                                          : NULL;
}

static const char *coords_option(const eom_args *a) {
    return a->eliminate ? "--eliminate" : NULL;
}

/* Lagrange's equations in the coordinates: M q'' = f (+ A^T lambda). */
static int run_coords(eom_run *r, const eom_args *a) {
    const char *opt = speeds_option(a);
    if (opt) {
        cli_diag_error("%s is for a model with generalized speeds, and %s declares no speeds "
                       "(a `speeds` statement; without one, --solve gives the multipliers)",
                       opt, r->c.file);
        return QD_EXIT_USAGE;
    }
    qd_eom_opts opts = {.eliminate = a->eliminate};
    if (!(r->e = qd_eom_derive_opts(r->c.ctx, r->c.mf.model, &opts)))
        return cli_eom_derive_error(r->c.ctx, &r->c.mf);
    int rc = QD_EXIT_OK;
    if (a->at && (rc = cli_state_init(r->c.ctx, r->c.mf.model, &r->st)) == QD_EXIT_OK)
        rc = cli_state_parse(r->c.ctx, r->c.mf.model, a->at, &r->st);
    else if (a->solve)
        rc = solved(r, qd_eom_solve(r->c.ctx, r->e, SOLVE_MAX_OPS), "accelerations");
    if (rc != QD_EXIT_OK)
        return rc;
    qd_buf b = QD_BUF_INIT, notes = QD_BUF_INIT;
    qd_render_opts o = render_opts(r, a, &notes);
    return emit(r, qd_render_eom(r->c.ctx, r->c.mf.model, r->e, &o, a->fmt, &b), &b, &notes);
}

/* The --at state of a model with speeds: q, t, the parameters and the
 * speeds (qd_speeds_state_read; the velocities follow from the speeds). */
static int speeds_state(eom_run *r, const qd_speeds_eom *e, const char *at) {
    if (qd_speeds_state_read(r->c.ctx, r->c.mf.model, e, at, &r->st) == QD_OK)
        return QD_EXIT_OK;
    return cli_state_diag(r->c.ctx, "--at", at);
}

/* The equations in the model's speeds: q' = W u + w, M_u u' = f_u. */
static int run_speeds(eom_run *r, const eom_args *a) {
    const char *opt = coords_option(a);
    if (opt)
        return cli_usage_error("%s is not available for a model with generalized speeds (%s "
                               "declares them): qdot eom prints M u' = f in the speeds",
                               opt, r->c.file);
    if (a->at && a->fmt != QD_RENDER_TEXT && a->fmt != QD_RENDER_JSON)
        return cli_usage_error("--at with speeds prints text or json");
    qd_speeds_opts opts = {.method = a->smethod, .appell = a->appell,
                           .multipliers = a->multipliers};
    qd_speeds_eom *e = qd_speeds_derive(r->c.ctx, r->c.mf.model, &opts);
    if (!e)
        return cli_eom_derive_error(r->c.ctx, &r->c.mf);
    qd_buf b = QD_BUF_INIT, notes = QD_BUF_INIT;
    int rc = QD_EXIT_OK;
    qd_status st = QD_OK;
    if (a->hamel_coef)
        st = qd_render_hamel(r->c.ctx, e,
                             a->fmt == QD_RENDER_JSON ? QD_RENDER_JSON : QD_RENDER_TEXT, &b);
    else if (a->at)
        rc = speeds_state(r, e, a->at);
    else if (a->solve)
        rc = solved(r, qd_speeds_solve(r->c.ctx, e, SOLVE_MAX_OPS), "rates");
    qd_render_opts o = render_opts(r, a, &notes);
    if (rc == QD_EXIT_OK && !a->hamel_coef)
        st = qd_render_speeds(r->c.ctx, r->c.mf.model, e, &o, a->fmt, &b);
    if (rc == QD_EXIT_OK)
        rc = emit(r, st, &b, &notes);
    else {
        qd_buf_free(&b);
        qd_buf_free(&notes);
    }
    qd_speeds_eom_free(e);
    return rc;
}

static int run(cli_run *c) {
    eom_run *r = (eom_run *)c;
    const eom_args *a = &r->a;
    if (a->field)
        return cli_field_eom(c->ctx, &c->mf, c->file, a->sets.n, a->sets.items,
                             a->fmt == QD_RENDER_JSON);
    int rc = cli_load(c->ctx, c->file, a->sets.n, a->sets.items, "eom", &c->mf);
    if (rc == QD_EXIT_OK)
        rc = qd_model_nspeeds(c->mf.model) ? run_speeds(r, a) : run_coords(r, a);
    return rc;
}

static void run_free(cli_run *c) {
    eom_run *r = (eom_run *)c;
    cli_state_free(&r->st);
    qd_eom_free(r->e);
}

int cli_cmd_eom(int argc, char **argv) {
    static const cli_driver d = {&eom_spec, offsetof(eom_run, a), 0, check, run, run_free};
    eom_run r = {0};
    return cli_drive(&d, &r.c, argc, argv);
}
