/*
 * cli/cmd_equilibria.c - `qdot equilibria FILE`: the configurations of rest
 * (libqdot's qd_equilibria_find), exact where the equations come apart one
 * unknown at a time, else by Newton from --guess or a multi-start search over
 * --box; each classified by the Hessian of the potential, and printed by
 * qd_equilibria_print (qdot/equilibria.h).  The loading code shared with
 * `qdot modes` is in linear_cli.c.
 */
#include "linear_cli.h"

#include "qdot/equilibria.h"

/* ---- the command ------------------------------------------------------------ */

typedef struct eq_args {
    const char *guess, *box, *format;
    cli_list sets;
} eq_args;

static const cli_opt opts[] = {
    {"--guess", NULL, CLI_TEXT, offsetof(eq_args, guess), "\"q1=VALUE, ...\"",
     "Newton from this starting point (only the equilibrium reached)", NULL, NULL},
    {"--box", NULL, CLI_TEXT, offsetof(eq_args, box), "\"q1=LOW:HIGH, ...\"",
     "search this box (default: [-pi, pi] for an angle, else [-10, 10])", NULL, NULL},
    CLI_OPT_SET(eq_args, sets),
    CLI_OPT_FORMAT(eq_args, format),
    {0},
};

static const cli_spec spec = {
    "equilibria", "FILE [--guess \"q1=VALUE, ...\"] [--box \"q1=LOW:HIGH, ...\"] [options]",
    "the configurations of rest and their kind (the Hessian of the potential)", opts, NULL, 1, 1,
    "FILE", false};

typedef struct eq_run {
    cli_lin_run lr; /* first: the run state starts with its cli_run */
    eq_args a;
    qd_equilibria eq;
} eq_run;

static int run(cli_run *c) {
    eq_run *r = (eq_run *)c;
    const eq_args *a = &r->a;
    bool json = cli_json(a->format);
    int rc = cli_lin_load_model(&r->lr, c->file, a->sets.items, a->sets.n);
    if (rc == QD_EXIT_OK && qd_model_nspeeds(c->mf.model) > 0)
        return cli_speeds_equilibria(c->ctx, &c->mf, json, a->guess ? "--guess"
                                                           : a->box ? "--box"
                                                                    : NULL);
    if (rc == QD_EXIT_OK)
        rc = cli_lin_derive(&r->lr);
    if (rc == QD_EXIT_OK)
        rc = cli_lin_equilibria(&r->lr, a->guess, a->box, &r->eq);
    if (rc != QD_EXIT_OK)
        return rc;
    qd_buf b = QD_BUF_INIT;
    return cli_emit_status(c->ctx, qd_equilibria_print(c->ctx, r->lr.e, &r->eq, json, &b), &b,
                           "equilibria");
}

static void run_free(cli_run *c) {
    eq_run *r = (eq_run *)c;
    qd_equilibria_free(&r->eq);
    cli_lin_free(&r->lr);
}

CLI_COMMAND(equilibria, eq_run, &spec, offsetof(eq_run, a), 0, NULL, run, run_free)
