/*
 * cli/cmd_impulse.c - `qdot impulse FILE`: the motion just after a blow, a
 * sudden constraint or a collision (qdot/impulse.h solves M (q'+ - q'-) =
 * Qhat + A^T Lambda); here the state before is gathered, --prescribe is
 * added to the model, and the answer is printed: the velocities after
 * (with their closed forms), the impulsive multipliers and reactions, the
 * energies, the theorems of impulsive motion that apply (Carnot's,
 * Bertrand's, Thomson's) with their numbers, and a two-body collision's
 * lab/centre-of-mass description (Desloge ch. 57 and 61, Byerly ch. III).
 *
 * The state before is the model's `initial` as written, an expression in the
 * parameters (al = pi/6 stays pi/6, so sin(al) is 1/2 in the closed forms),
 * overridden by --at; a coordinate or velocity named in neither is 0.
 */
#include "driver.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "state.h"
#include "qdot/impulse.h"
#include "qdot/render.h"

typedef struct imp_args {
    const char *at, *format;
    cli_list sets, pres;
} imp_args;

typedef struct imp_run {
    cli_run c;
    imp_args a;
    size_t n;
    const qd_expr **q0, **qd0;   /* the state before, exact: n each */
    const qd_expr *t0;
    qd_impulse res;
} imp_run;

static const char *const formats[] = {"text", "json", "latex", NULL};

static const cli_opt opts[] = {
    {"--at", NULL, CLI_TEXT, offsetof(imp_args, at), "\"q=V, q'=V, t=V\"",
     "the state just before (over the model's initial; others 0)", NULL, NULL},
    CLI_OPT_SET(imp_args, sets),
    {"--prescribe", NULL, CLI_LIST, offsetof(imp_args, pres), "\"[NAME:] LHS = RHS, ...\"",
     "velocities to hold just after (Thomson's problem)", NULL, NULL},
    CLI_OPT_FORMATS(imp_args, format, formats),
    {NULL, NULL, CLI_FLAG, 0, NULL, NULL, NULL, NULL},
};

static const cli_spec spec = {
    "impulse", "FILE [options]",
    "The motion just after a blow, a sudden constraint or a collision: the velocities after, "
    "the impulsive reactions, the energies and the theorems of impulsive motion.",
    opts, NULL, 1, 1, "FILE", false};

/* ---- the state before ----------------------------------------------------------- */

/* `initial` as written, then --at, exact (qd_impulse_state_read). */
static int state_before(imp_run *r, const char *at) {
    r->q0 = calloc(r->n + 1, sizeof *r->q0);
    r->qd0 = calloc(r->n + 1, sizeof *r->qd0);
    if (!r->q0 || !r->qd0)
        return cli_out_of_memory();
    if (qd_impulse_state_read(r->c.ctx, r->c.mf.model, at, r->q0, r->qd0, &r->t0) != QD_OK)
        return cli_state_diag(r->c.ctx, "--at", at);
    return QD_EXIT_OK;
}

/* ---- solving -------------------------------------------------------------------- */

/* The solver's error, at the statement it is about when it names one. */
static int solve_failed(imp_run *r) {
    qd_diag d = *qd_ctx_diag(r->c.ctx);
    bool about = d.subject != QD_SUBJECT_NONE && d.subject != QD_SUBJECT_TEXT;
    if (about && qd_model_locate(r->c.mf.model, &d))
        cli_diag_show(r->c.mf.path, r->c.mf.text, &d);
    else
        cli_diag_show("qdot", NULL, &d);
    /* dependent or inconsistent sudden constraints are a numerical failure (exit 1) */
    return cli_exit(qd_ctx_status(r->c.ctx));
}

static int solve(imp_run *r) {
    qd_impulse_opts o = {.q = r->q0, .qd = r->qd0, .t = r->t0, .exact = true, .max_ops = 0};
    if (qd_impulse_solve(r->c.ctx, r->c.mf.model, &o, &r->res) != QD_OK)
        return solve_failed(r);
    return QD_EXIT_OK;
}

/* ---- the command ------------------------------------------------------------------ */

static int emit(imp_run *r, qd_render_format fmt) {
    qd_buf b = QD_BUF_INIT;
    if (qd_render_impulse(r->c.ctx, r->c.mf.model, &r->res, fmt, &b) == QD_ERR_NOMEM)
        b.failed = true;
    return cli_emit(&b, "result");
}

static void run_free(cli_run *c) {
    imp_run *r = (imp_run *)c;
    qd_impulse_free(&r->res);
    free(r->q0);
    free(r->qd0);
}

static int run(cli_run *c) {
    imp_run *r = (imp_run *)c;
    /* the closed forms stay in the parameters' names, as the other numeric
     * commands print them; --set gives the values */
    int rc = cli_load(c->ctx, c->file, r->a.sets.n, r->a.sets.items, "impulse", &c->mf);
    if (rc == QD_EXIT_OK) {
        r->n = qd_model_ncoords(c->mf.model);
        for (size_t k = 0; rc == QD_EXIT_OK && k < r->a.pres.n; k++) /* Thomson's problem */
            rc = cli_model_add_given(&c->mf, "--prescribe", "prescribe", NULL, r->a.pres.items[k]);
    }
    if (rc == QD_EXIT_OK)
        rc = state_before(r, r->a.at);
    if (rc == QD_EXIT_OK)
        rc = solve(r);
    if (rc == QD_EXIT_OK)
        rc = emit(r, cli_render_format(r->a.format));
    return rc;
}

CLI_COMMAND(impulse, imp_run, &spec, offsetof(imp_run, a), 0, NULL, run, run_free)
