/*
 * cli/cmd_path.c - `qdot path FILE --from "q=..., t=t0" --to "q=..., t=t1"`:
 * the stationary paths of the action between two configurations
 * (qd_path_find; --energy E: Maupertuis' paths of energy E, qd_path_find_energy),
 * each with its action, initial velocities, samples, kinetic foci and
 * whether it is a minimum; the isoperimetric multipliers, and free ends
 * written `y=free`.  For an `independent x` model, x names the ends' time.
 */
#include "driver.h"

#include "qdot/path.h"
#include "opt_diag.h"

typedef struct path_args {
    const char *from, *to, *energy, *format;
    size_t segments;
    bool all;
    cli_list guess, set;
} path_args;

static const cli_opt opts[] = {
    {"--from", NULL, CLI_TEXT, offsetof(path_args, from), "\"q=VALUE|free, ..., t=T0\"",
     "the start: each coordinate's value (or free) and the time (required)", NULL, NULL},
    {"--to", NULL, CLI_TEXT, offsetof(path_args, to), "\"q=VALUE|free, ..., t=T1\"",
     "the end, likewise; its time unless --energy (required)", NULL, NULL},
    {"--all", NULL, CLI_FLAG, offsetof(path_args, all), NULL,
     "search for every distinct path, not the first found", NULL, NULL},
    {"--guess", NULL, CLI_LIST, offsetof(path_args, guess), "\"q'=VALUE, ...\"",
     "initial velocities to start the search from", NULL, NULL},
    {"--energy", NULL, CLI_TEXT, offsetof(path_args, energy), "E",
     "Maupertuis' paths of this energy, whatever their time (an expression in the parameters)",
     NULL, NULL},
    {"--segments", NULL, CLI_COUNT, offsetof(path_args, segments), "N",
     "multiple-shooting segments (default: chosen)", NULL, NULL},
    CLI_OPT_FORMAT(path_args, format),
    CLI_OPT_SET(path_args, set),
    {0},
};

static const cli_spec spec = {
    "path", "FILE --from \"q=..., t=T0\" --to \"q=..., t=T1\" [options]",
    "Stationary paths of the action between two configurations, with their foci.",
    opts, NULL, 1, 1, "FILE", false,
};

typedef struct path_run {
    cli_run c;
    path_args a;
    qd_eom *e;
    qd_path_ends ends; /* the arrays of the problem (qd_path_ends_read) */
    qd_path_set ps;
} path_run;

/* A number option, an expression in the parameters: its error shown in it. */
static int path_number(qd_ctx *ctx, const qd_model *m, const char *opt, const char *text,
                       double *out) {
    if (qd_model_number(ctx, m, text, out) == QD_OK)
        return QD_EXIT_OK;
    cli_diag_show(opt, text, qd_ctx_diag(ctx));
    return cli_exit(qd_ctx_status(ctx));
}

static int run(cli_run *c) {
    path_run *r = (path_run *)c;
    const path_args *a = &r->a;
    int rc = cli_load_derive(c->ctx, c->file, a->set.n, a->set.items, "path", NULL, &c->mf, &r->e);
    qd_path_opts o = {0};
    double E = 0;
    if (rc == QD_EXIT_OK && a->energy)
        rc = path_number(c->ctx, c->mf.model, "--energy", a->energy, &E);
    if (rc == QD_EXIT_OK && qd_path_ends_read(c->ctx, c->mf.model, r->e, a->from, a->to,
                                              a->guess.n, a->guess.items, a->energy, &r->ends,
                                              &o) != QD_OK)
        rc = cli_diag_opts(c->ctx, &spec, a);
    if (rc != QD_EXIT_OK)
        return rc;
    o.all = a->all;
    o.segments = a->segments;
    qd_status st = a->energy ? qd_path_find_energy(c->ctx, c->mf.model, r->e, E, &o, &r->ps)
                             : qd_path_find(c->ctx, c->mf.model, r->e, &o, &r->ps);
    if (st != QD_OK)
        return cli_diag_ctx(c->ctx);
    qd_buf b = QD_BUF_INIT;
    st = cli_json(a->format) ? qd_path_json(c->ctx, &r->ps, c->mf.model, r->e, &b)
                             : qd_path_print(c->ctx, &r->ps, c->mf.model, r->e, &o, &b);
    return cli_emit_status(c->ctx, st, &b, "paths");
}

static int check(cli_run *c) {
    const path_args *a = &((path_run *)c)->a;
    if (a->from && a->to)
        return QD_EXIT_OK;
    return cli_usage_error("path needs --from and --to (qdot path --help)");
}

static void run_free(cli_run *c) {
    path_run *r = (path_run *)c;
    qd_path_set_free(&r->ps);
    qd_path_ends_free(&r->ends);
    qd_eom_free(r->e);
}

CLI_COMMAND(path, path_run, &spec, offsetof(path_run, a), 0, check, run, run_free)
