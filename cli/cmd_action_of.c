/*
 * cli/cmd_action_of.c - `qdot action-of FILE --path "x = ..., y = ..."
 * --t T0:T1`: the action of a trial path given in t and the parameters, and
 * the size of its first variation (qd_path_action_of; Desloge ch. 83, the
 * trial paths of Problems 1-3 compared), to weigh trial paths against each
 * other and against the true one.
 */
#include "driver.h"

#include <stdlib.h>
#include <string.h>
#include "state.h"

typedef struct ao_run {
    cli_run c;
    qd_eom *e;
    const char *path, *times, *format;
    cli_list sets;
    const qd_expr **q;   /* the trial path of each coordinate */
    double t0, t1;
} ao_run;

static const cli_opt opts[] = {
    {"--path", NULL, CLI_TEXT, offsetof(ao_run, path), "\"q = EXPR(t), ...\"",
     "the trial path: every coordinate as an expression in t", NULL, NULL},
    {"--t", NULL, CLI_TEXT, offsetof(ao_run, times), "T0:T1",
     "the time interval (expressions in the parameters)", NULL, NULL},
    CLI_OPT_SET(ao_run, sets),
    CLI_OPT_FORMAT(ao_run, format),
    {NULL, NULL, CLI_FLAG, 0, NULL, NULL, NULL, NULL},
};

static const cli_spec spec = {
    "action-of", "FILE --path \"q = EXPR(t), ...\" --t T0:T1 [options]",
    "The action of a trial path and the size of its first variation.", opts, NULL, 1, 1,
    "FILE", false};

static int parse_path(ao_run *r) {
    size_t n = qd_model_ncoords(r->c.mf.model);
    if (!(r->q = calloc(n ? n : 1, sizeof *r->q)))
        return QD_EXIT_FAIL;
    if (qd_path_trial_read(r->c.ctx, r->c.mf.model, r->path, r->q) != QD_OK)
        return cli_state_diag(r->c.ctx, "--path", r->path);
    return QD_EXIT_OK;
}

/* --t T0:T1, each a constant expression in the parameters (pi/8, 2*pi/w). */
static int parse_times(ao_run *r) {
    const char *text = r->times;
    if (qd_state_range(r->c.ctx, r->c.mf.model, text, 0, strlen(text), &r->t0, &r->t1) != QD_OK)
        return cli_state_diag(r->c.ctx, "--t", text);
    if (!(r->t1 > r->t0))
        return cli_usage_error("--t: T1 must be after T0 (%s)", text);
    return QD_EXIT_OK;
}

static int emit(ao_run *r, double S, double dS) {
    qd_buf b = QD_BUF_INIT;
    return cli_emit_status(r->c.ctx, qd_path_action_of_print(r->c.ctx, r->c.mf.path, r->t0, r->t1,
                                                            S, dS, cli_json(r->format), &b),
                           &b, "action");
}

static int check(cli_run *c) {
    ao_run *r = (ao_run *)c;
    if (r->path && r->times)
        return QD_EXIT_OK;
    return cli_usage_error("action-of needs --path and --t (qdot action-of --help)");
}

static int run(cli_run *c) {
    ao_run *r = (ao_run *)c;
    int rc = cli_load_derive(c->ctx, c->file, r->sets.n, r->sets.items, "action_of", NULL, &c->mf,
                             &r->e);
    if (rc == QD_EXIT_OK)
        rc = parse_path(r);
    if (rc == QD_EXIT_OK)
        rc = parse_times(r);
    if (rc != QD_EXIT_OK)
        return rc;
    double S = 0, dS = 0;
    if (qd_path_action_of(c->ctx, c->mf.model, r->e, r->q, r->t0, r->t1, &S, &dS) != QD_OK)
        return cli_diag_ctx(c->ctx);
    return emit(r, S, dS);
}

static void run_free(cli_run *c) {
    ao_run *r = (ao_run *)c;
    free(r->q);
    qd_eom_free(r->e);
}

CLI_COMMAND(action_of, ao_run, &spec, 0, 0, check, run, run_free)
