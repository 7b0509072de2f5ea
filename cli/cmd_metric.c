/*
 * cli/cmd_metric.c - `qdot metric FILE [--force "G1, G2, ..."] [--set
 * NAME=VALUE]... [--format text|json]`: the kinetic metric g_ij of the
 * model's coordinates, its conjugate, the Christoffel symbols of both
 * kinds, Lagrange's equations in geodesic form, a force's components
 * (covariant, contravariant, physical, ordinary), and the chart's
 * Jacobian with its singular points (qdot/metric.h; Desloge App. 23,
 * ch. 47, ch. 55); --gram-schmidt: the coordinate tangents orthogonalized
 * under the metric instead (qd_gram_schmidt, App. 21 Thm 2).
 */
#include "driver.h"

#include <stdlib.h>
#include "qdot/form.h"
#include "qdot/metric.h"
#include "qdot/render.h"

typedef struct mt_args {
    const char *force, *format;
    bool gram;
    cli_list set;
} mt_args;

typedef struct mt_run {
    cli_run c;
    mt_args a;
} mt_run;

static const cli_opt opts[] = {
    {"--force", NULL, CLI_TEXT, offsetof(mt_args, force), "\"G1, G2, ...\"",
     "a force by its covariant components G_i = F . dx/dq_i (default: the model's Q)", NULL,
     NULL},
    {"--gram-schmidt", NULL, CLI_FLAG, offsetof(mt_args, gram), NULL,
     "the coordinate tangents orthogonalized under the metric: b(i)^T g b(j) = 0 (App. 21)",
     NULL, NULL},
    CLI_OPT_FORMAT(mt_args, format),
    CLI_OPT_SET(mt_args, set),
    {0},
};

static const cli_spec spec = {
    "metric", "FILE [options]",
    "The kinetic metric g_ij, Christoffel symbols, the geodesic form, a force's components "
    "and the chart.",
    opts, NULL, 1, 1, "FILE", false,
};

/* The coordinate tangents orthogonalized under g_ij (qd_metric_gram_schmidt). */
static qd_status tangents(qd_ctx *ctx, const qd_metric *g, qd_render_format fmt, qd_buf *b) {
    qd_gram *gs = qd_metric_gram_schmidt(ctx, g);
    qd_status st = gs ? qd_render_gram(ctx, gs, g->q, g->g, fmt, b) : qd_ctx_status(ctx);
    qd_gram_free(gs);
    return st;
}

static int run(cli_run *c) {
    const mt_args *a = &((mt_run *)c)->a;
    qd_ctx *ctx = c->ctx;
    cli_model_file *mf = &c->mf;
    int rc = cli_load(ctx, c->file, a->set.n, a->set.items, "metric", mf);
    if (rc != QD_EXIT_OK)
        return rc;
    qd_metric *g = qd_metric_new(ctx, mf->model);
    if (!g)
        return cli_diag_ctx(ctx);
    const qd_expr **G = calloc(g->n + 1, sizeof *G);
    if (!G) {
        qd_metric_free(g);
        return QD_EXIT_FAIL;
    }
    if (a->force && qd_metric_force_read(ctx, g, a->force, G) != QD_OK) {
        cli_diag_show("--force", a->force, qd_ctx_diag(ctx));
        rc = cli_exit(qd_ctx_status(ctx));
    }
    qd_buf b = QD_BUF_INIT;
    const qd_expr *const *force = a->force ? G : NULL;
    if (rc == QD_EXIT_OK && a->gram)
        rc = cli_emit_status(ctx, tangents(ctx, g, cli_render_format(a->format), &b), &b,
                             "orthogonalization");
    else if (rc == QD_EXIT_OK)
        rc = cli_emit_status(ctx, cli_json(a->format)
                                      ? qd_metric_json(ctx, g, force, &b)
                                      : qd_metric_print(ctx, g, force, QD_FMT_TEXT, &b),
                             &b, "metric");
    free(G);
    qd_metric_free(g);
    return rc;
}

CLI_COMMAND(metric, mt_run, &spec, offsetof(mt_run, a), 0, NULL, run, NULL)
