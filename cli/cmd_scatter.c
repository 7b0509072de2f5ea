/*
 * cli/cmd_scatter.c - `qdot scatter`: classical scattering by the central
 * potential of a model in a plane (qd_scatter_read, qd_scatter_answer_query,
 * qd_scatter_render; qdot/scatter.h, Desloge ch. 60-61).
 */
#include "driver.h"

#include "opt_diag.h"

typedef struct sc_args {
    qd_scatter_text t;
    const char *ignore, *format, *out;
    cli_list sets;
} sc_args;

#define T(field) offsetof(sc_args, t.field)
static const cli_opt opts[] = {
    {"--energy", NULL, CLI_TEXT, T(energy), "E", "the energy at infinity, E > 0", NULL, NULL},
    {"--b", NULL, CLI_TEXT, T(b), "B", "one impact parameter: its orbit and deflection", NULL,
     NULL},
    {"--theta", NULL, CLI_TEXT, T(theta), "TH",
     "one centre-of-mass angle in (0, pi): the cross section over every branch", NULL, NULL},
    {"--lab-theta", NULL, CLI_TEXT, T(lab_theta), "TH",
     "one laboratory angle (with --masses): every CM angle that reaches it", NULL, NULL},
    {"--masses", NULL, CLI_TEXT, T(masses), "m1,m2",
     "projectile and target at rest: the laboratory frame", NULL, NULL},
    {"--core", NULL, CLI_TEXT, T(core), "A", "a hard core of radius A (a wall)", NULL, NULL},
    {"--absorbing", NULL, CLI_FLAG, T(absorbing), NULL, "the core absorbs: capture", NULL, NULL},
    {"--recoil", NULL, CLI_FLAG, T(recoil), NULL, "count the target too (identical)", NULL, NULL},
    {"--ignore", NULL, CLI_TEXT, offsetof(sc_args, ignore), "Q",
     "the cyclic angle, when two coordinates are cyclic", NULL, NULL},
    CLI_OPT_SET(sc_args, sets),
    CLI_OPT_FORMAT(sc_args, format),
    CLI_OPT_OUT(sc_args, out),
    {0},
};
#undef T

static const cli_spec spec = {
    "scatter", "FILE --energy E (--b B | --theta TH | --lab-theta TH) [options]",
    "classical scattering by a central potential: deflection and cross sections", opts, NULL, 1,
    1, "FILE", false};

typedef struct sc_run {
    cli_run c;
    sc_args a;
    qd_eom *e;
    qd_scatter *s;
} sc_run;

static int run(cli_run *c) {
    sc_run *r = (sc_run *)c;
    const sc_args *a = &r->a;
    qd_ctx *ctx = c->ctx;
    const cli_model_file *mf = &c->mf;
    int rc = cli_load_derive(ctx, c->file, a->sets.n, a->sets.items, "scatter", NULL, &c->mf, &r->e);
    if (rc != QD_EXIT_OK)
        return rc;
    qd_scatter_query q;
    qd_scatter_answer ans;
    qd_buf b = QD_BUF_INIT;
    qd_status st = qd_scatter_read(ctx, mf->model, &a->t, &q);
    if (st == QD_OK &&
        !(r->s = qd_scatter_from_model(ctx, mf->model, r->e, a->ignore, q.core, NULL)))
        st = qd_ctx_status(ctx);
    if (st == QD_OK)
        st = qd_scatter_answer_query(ctx, r->s, &q, &ans);
    if (st == QD_OK)
        st = qd_scatter_render(ctx, r->s, &ans, mf->path, cli_json(a->format), &b);
    rc = st == QD_OK ? cli_out_emit(&b, a->out) : cli_diag_opts(ctx, &spec, a);
    qd_buf_free(&b);
    return rc;
}

static void run_free(cli_run *c) {
    sc_run *r = (sc_run *)c;
    qd_scatter_free(r->s);
    qd_eom_free(r->e);
}

CLI_COMMAND(scatter, sc_run, &spec, offsetof(sc_run, a), 0, NULL, run, run_free)
