/*
 * cli/cmd_equilibria.c - `qdot equilibria FILE`: the configurations of rest
 * (libqdot's qd_equilibria_find), exact where the equations come apart one
 * unknown at a time, else by Newton from --near or a multi-start search over
 * --box; each classified by the Hessian of the potential, and printed by
 * qd_equilibria_print (qdot/equilibria.h).  The loading code shared with
 * `qdot modes` is in linear_cli.c.
 */
#include "linear_cli.h"

#include <stddef.h>
#include <string.h>
#include "qdot/equilibria.h"
#include "model_cli.h"

/* ---- the command ------------------------------------------------------------ */

typedef struct eq_args {
    const char *near, *box, *format;
    cli_list sets;
} eq_args;

static const char *const formats[] = {"text", "json", NULL};

static const cli_opt opts[] = {
    {"--near", NULL, CLI_TEXT, offsetof(eq_args, near), "\"q1=VALUE, ...\"",
     "Newton from this point (only the equilibrium reached)", NULL, NULL},
    {"--box", NULL, CLI_TEXT, offsetof(eq_args, box), "\"q1=LOW:HIGH, ...\"",
     "search this box (default: [-pi, pi] for an angle, else [-10, 10])", NULL, NULL},
    {"--set", NULL, CLI_LIST, offsetof(eq_args, sets), "NAME=VALUE", "a parameter's value", NULL,
     NULL},
    {"--format", NULL, CLI_CHOICE, offsetof(eq_args, format), "NAME", "text or json", formats,
     NULL},
    {0},
};

static const cli_spec spec = {
    "equilibria", "FILE [--near \"q1=VALUE, ...\"] [--box \"q1=LOW:HIGH, ...\"] [options]",
    "the configurations of rest and their kind (the Hessian of the potential)", opts, NULL, 1, 1,
    "FILE", false};

int cli_cmd_equilibria(int argc, char **argv) {
    eq_args a = {0};
    const char *file = NULL;
    int rc = cli_parse(&spec, argc, argv, &a, &file);
    if (rc != QD_EXIT_OK)
        return rc;
    bool json = a.format && !strcmp(a.format, "json");
    cli_lin_run r = {.ctx = qd_ctx_new()};
    if (!r.ctx) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    qd_equilibria eq = {0};
    rc = cli_lin_load_model(&r, file, a.sets.items, a.sets.n);
    bool speeds = rc == QD_EXIT_OK && qd_model_nspeeds(r.mf.model) > 0;
    if (speeds)
        rc = cli_speeds_equilibria(r.ctx, &r.mf, json, a.near ? "--near" : a.box ? "--box"
                                                                                  : NULL);
    else if (rc == QD_EXIT_OK)
        rc = cli_lin_derive(&r);
    if (rc == QD_EXIT_OK && !speeds)
        rc = cli_lin_equilibria(&r, a.near, a.box, &eq);
    if (rc == QD_EXIT_OK && !speeds) {
        qd_buf b = QD_BUF_INIT;
        if (qd_equilibria_print(r.ctx, r.e, &eq, json, &b) == QD_OK)
            rc = cli_emit(&b, "equilibria");
        else {
            qd_buf_free(&b);
            rc = cli_diag_ctx(r.ctx);
        }
    }
    qd_equilibria_free(&eq);
    cli_lin_free(&r);
    qd_ctx_free(r.ctx);
    return rc;
}
