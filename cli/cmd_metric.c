/*
 * cli/cmd_metric.c - `qdot metric FILE [--force "G1, G2, ..."] [--set
 * NAME=VALUE]... [--format text|json]`: the kinetic metric g_ij of the
 * model's coordinates, its conjugate, the Christoffel symbols of both
 * kinds, Lagrange's equations in geodesic form, a force's components
 * (covariant, contravariant, physical, ordinary), and the chart's
 * Jacobian with its singular points (qdot/metric.h; Desloge App. 23,
 * ch. 47, ch. 55).
 */
#include "cli.h"

#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model_cli.h"
#include "qdot/metric.h"

typedef struct mt_args {
    const char *force, *format;
    cli_list set;
} mt_args;

static const char *const formats[] = {"text", "json", NULL};

static const cli_opt opts[] = {
    {"--force", NULL, CLI_TEXT, offsetof(mt_args, force), "\"G1, G2, ...\"",
     "a force by its covariant components G_i = F . dx/dq_i (default: the model's Q)", NULL,
     NULL},
    {"--format", NULL, CLI_CHOICE, offsetof(mt_args, format), "FORMAT", "how to write it",
     formats, NULL},
    {"--set", NULL, CLI_LIST, offsetof(mt_args, set), "NAME=VALUE",
     "read the model with this parameter value", NULL, NULL},
    {0},
};

static const cli_spec spec = {
    "metric", "FILE [options]",
    "The kinetic metric g_ij, Christoffel symbols, the geodesic form, a force's components "
    "and the chart.",
    opts, NULL, 1, 1, "FILE", false,
};

static int run(qd_ctx *ctx, const char *file, const mt_args *a, cli_model_file *mf) {
    int rc = cli_load(ctx, file, a->set.n, a->set.items, true, mf);
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
    bool json = a->format && !strcmp(a->format, "json");
    if (rc == QD_EXIT_OK && (json ? qd_metric_json(ctx, g, force, &b)
                                  : qd_metric_print(ctx, g, force, QD_FMT_TEXT, &b)) != QD_OK)
        rc = cli_diag_ctx(ctx);
    if (rc == QD_EXIT_OK)
        rc = cli_emit(&b, "metric");
    else
        qd_buf_free(&b);
    free(G);
    qd_metric_free(g);
    return rc;
}

int cli_cmd_metric(int argc, char **argv) {
    mt_args a = {0};
    const char *file;
    int rc = cli_parse(&spec, argc, argv, &a, &file);
    if (rc != QD_EXIT_OK)
        return rc;
    qd_ctx *ctx = qd_ctx_new();
    if (!ctx) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    cli_model_file mf = {0};
    rc = run(ctx, file, &a, &mf);
    cli_model_file_free(&mf);
    qd_ctx_free(ctx);
    return rc;
}
