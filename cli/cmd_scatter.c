/*
 * cli/cmd_scatter.c - `qdot scatter FILE --energy E --b B | --theta TH |
 * --lab-theta TH`: classical scattering by the central potential of a model
 * in a plane (qd_scatter_read, qd_scatter_answer_query, qd_scatter_render;
 * qdot/scatter.h, Desloge ch. 60-61).
 */
#include "cli.h"

#include "model_cli.h"
#include "model_file.h"
#include "opt_diag.h"
#include "out.h"

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
    {"--core", NULL, CLI_TEXT, T(core), "A", "a hard core of radius A (an exact wall)", NULL,
     NULL},
    {"--ignore", NULL, CLI_TEXT, offsetof(sc_args, ignore), "Q",
     "the cyclic angle, when two coordinates are cyclic", NULL, NULL},
    {"--set", NULL, CLI_LIST, offsetof(sc_args, sets), "NAME=VALUE", "a parameter's value",
     NULL, NULL},
    CLI_OPT_FORMAT(sc_args, format),
    CLI_OPT_OUT(sc_args, out),
    {0},
};
#undef T

static const cli_spec spec = {
    "scatter", "FILE --energy E (--b B | --theta TH | --lab-theta TH) [options]",
    "classical scattering by a central potential: deflection and cross sections", opts, NULL, 1,
    1, "FILE", false};

static int run(qd_ctx *ctx, const sc_args *a, const char *file, cli_model_file *mf,
               qd_eom **e, qd_scatter **s) {
    int rc = cli_load_derive(ctx, file, a->sets.n, a->sets.items, true, NULL, mf, e);
    if (rc != QD_EXIT_OK)
        return rc;
    qd_scatter_query q;
    qd_scatter_answer ans;
    qd_buf b = QD_BUF_INIT;
    qd_status st = qd_scatter_read(ctx, mf->model, &a->t, &q);
    if (st == QD_OK && !(*s = qd_scatter_from_model(ctx, mf->model, *e, a->ignore, q.core, NULL)))
        st = qd_ctx_status(ctx);
    if (st == QD_OK)
        st = qd_scatter_answer_query(ctx, *s, &q, &ans);
    if (st == QD_OK)
        st = qd_scatter_render(ctx, *s, &ans, mf->path, cli_json(a->format), &b);
    rc = st == QD_OK ? cli_out_emit(&b, a->out) : cli_diag_opts(ctx, &spec, a);
    qd_buf_free(&b);
    return rc;
}

int cli_cmd_scatter(int argc, char **argv) {
    sc_args a = {0};
    const char *file = NULL;
    int rc = cli_parse(&spec, argc, argv, &a, &file);
    qd_ctx *ctx = rc == QD_EXIT_OK ? qd_ctx_new() : NULL;
    if (rc != QD_EXIT_OK || !ctx) {
        if (rc == QD_EXIT_OK)
            cli_diag_error("out of memory");
        return rc == QD_EXIT_OK ? QD_EXIT_FAIL : rc;
    }
    cli_model_file mf = {0};
    qd_eom *e = NULL;
    qd_scatter *s = NULL;
    rc = run(ctx, &a, file, &mf, &e, &s);
    qd_scatter_free(s);
    qd_eom_free(e);
    cli_model_file_free(&mf);
    qd_ctx_free(ctx);
    return rc;
}
