/*
 * cli/cmd_path.c - `qdot path FILE --from "q=..., t=t0" --to "q=..., t=t1"`:
 * the stationary paths of the action between two configurations
 * (qd_path_find; --energy E: Maupertuis' paths of energy E, qd_path_find_energy),
 * each with its action, initial velocities, samples, kinetic foci and
 * whether it is a minimum; the isoperimetric multipliers, and free ends
 * written `y=free`.  For an `independent x` model, x names the ends' time.
 */
#include "driver.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "qdot/path.h"
#include "state.h"

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
    cli_state g;
    double *q0, *q1, *guess;
    qd_path_set ps;
    bool energy, any_free;
    bool free0[32], free1[32];
} path_run;

/* A free coordinate starts from the other end's value (0 if free too). */
static void free_guesses(path_run *r) {
    size_t n = r->e->n;
    for (size_t j = 0; j < n; j++) {
        if (r->free0[j])
            r->q0[j] = r->free1[j] ? 0 : r->q1[j];
        if (r->free1[j])
            r->q1[j] = r->free0[j] ? 0 : r->q0[j];
    }
}

/* One end: its error shown in the option's text. */
static int read_end(path_run *r, const char *what, const char *text, double *q, double *t,
                    bool *fr) {
    if (qd_path_end_read(r->c.ctx, r->c.mf.model, r->e, text, q, t, fr) != QD_OK)
        return cli_state_diag(r->c.ctx, what, text);
    for (size_t j = 0; j < r->e->n; j++)
        r->any_free = r->any_free || fr[j];
    return QD_EXIT_OK;
}

static int read_ends(path_run *r, const path_args *a, qd_path_opts *o) {
    const qd_model *m = r->c.mf.model;
    size_t n = r->e->n;
    if (n > sizeof r->free0 / sizeof r->free0[0])
        return cli_usage_error("path: at most %zu coordinates",
                               sizeof r->free0 / sizeof r->free0[0]);
    r->q0 = calloc(n + 1, sizeof *r->q0);
    r->q1 = calloc(n + 1, sizeof *r->q1);
    if (!r->q0 || !r->q1)
        return cli_out_of_memory();
    double t0 = 0, t1 = NAN;
    int rc = read_end(r, "--from", a->from, r->q0, &t0, r->free0);
    if (rc == QD_EXIT_OK)
        rc = read_end(r, "--to", a->to, r->q1, &t1, r->free1);
    if (rc == QD_EXIT_OK && r->energy && r->any_free)
        rc = cli_usage_error("path: free ends need the end times, not --energy");
    if (rc == QD_EXIT_OK && !r->energy && isnan(t1)) {
        const char *x = qd_model_independent(m) ? qd_model_independent(m) : "t";
        rc = cli_usage_error("path: --to needs the end %s=T1 (or give --energy E)", x);
    }
    if (rc == QD_EXIT_OK)
        free_guesses(r);
    r->guess = calloc(a->guess.n * n + 1, sizeof *r->guess);
    if (rc == QD_EXIT_OK && !r->guess)
        return cli_out_of_memory();
    for (size_t k = 0; rc == QD_EXIT_OK && k < a->guess.n; k++) {
        cli_state_free(&r->g);
        rc = cli_state_init(r->c.ctx, m, &r->g);
        if (rc == QD_EXIT_OK)
            rc = cli_state_parse_as(r->c.ctx, m, "--guess", a->guess.items[k], &r->g);
        if (rc == QD_EXIT_OK)
            memcpy(r->guess + k * n, r->g.vals + n, n * sizeof *r->guess);
    }
    if (rc != QD_EXIT_OK)
        return rc;
    o->q0 = r->q0;
    o->q1 = r->q1;
    o->t0 = t0;
    o->t1 = t1;
    o->nguess = a->guess.n;
    o->guess = a->guess.n ? r->guess : NULL;
    o->all = a->all;
    o->free0 = r->any_free ? r->free0 : NULL;
    o->free1 = r->any_free ? r->free1 : NULL;
    if (!r->energy && !(o->t1 > o->t0))
        return cli_usage_error("path: the end time %g is not after the start time %g",
                               o->t1, o->t0);
    return QD_EXIT_OK;
}

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
    r->energy = a->energy != NULL;
    if (rc == QD_EXIT_OK && a->energy)
        rc = path_number(c->ctx, c->mf.model, "--energy", a->energy, &E);
    if (rc == QD_EXIT_OK)
        rc = read_ends(r, a, &o);
    if (rc != QD_EXIT_OK)
        return rc;
    o.segments = a->segments;
    qd_status st = r->energy ? qd_path_find_energy(c->ctx, c->mf.model, r->e, E, &o, &r->ps)
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
    cli_state_free(&r->g);
    free(r->q0);
    free(r->q1);
    free(r->guess);
    qd_eom_free(r->e);
}

int cli_cmd_path(int argc, char **argv) {
    static const cli_driver d = {&spec, offsetof(path_run, a), 0, check, run, run_free};
    path_run r = {0};
    return cli_drive(&d, &r.c, argc, argv);
}
