/*
 * cli/plot_cli.c - the --plot options: columns picked by name, rows kept
 * during a run, and the plot drawn by libqdot (qdot/plot.h) at its end.
 */
#include "plot_cli.h"

#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "model_cli.h"

#define LOOK(field) offsetof(cli_plot_args, field)
const cli_opt cli_plot_look_opts[] = {
    {"--title", NULL, CLI_TEXT, LOOK(title), "TEXT", "the picture's title (else the file)",
     NULL, NULL},
    {"--xlabel", NULL, CLI_TEXT, LOOK(xlabel), "TEXT", "every panel's x axis", NULL, NULL},
    {"--ylabel", NULL, CLI_TEXT, LOOK(ylabel), "\"TEXT; ...\"", "each panel's y axis", NULL,
     NULL},
    {"--size", NULL, CLI_TEXT, LOOK(size), "WxH", "the picture's size in pixels", NULL, NULL},
    {"--dpi", NULL, CLI_NONNEG, LOOK(dpi), "N", "a PNG's resolution: 192 draws it twice as "
     "large (72 to 1200; default 96)", NULL, NULL},
    {NULL, NULL, CLI_FLAG, 0, NULL, NULL, NULL, NULL},
};
#undef LOOK

qd_plot_run_opts cli_plot_opts(const cli_plot_args *a, const char *title) {
    const char *slash = title ? strrchr(title, '/') : NULL;
    return (qd_plot_run_opts){.title = a->title ? a->title : slash ? slash + 1 : title,
                              .xlabel = a->xlabel, .ylabel = a->ylabel, .width = a->width,
                              .height = a->height, .dpi = a->dpi, .point_size = a->point_size,
                              .norbits = a->norbits, .orbit_rows = a->orbit_rows,
                              .orbit_labels = a->orbit_labels};
}

int cli_plot_check(cli_plot_args *a, const char *cmd) {
    const char *shape = a->ycols ? "--plot-y" : a->phase ? "--phase" : a->title ? "--title"
                        : a->xlabel ? "--xlabel" : a->ylabel ? "--ylabel" : a->size ? "--size"
                        : a->dpi ? "--dpi" : a->point_size ? "--point-size" : NULL;
    if (!a->file && shape)
        return cli_usage_error("%s says how to plot: give the file with --plot FILE.png|.svg|.pdf",
                               shape);
    qd_ctx *ctx = qd_ctx_new();
    if (!ctx)
        return QD_EXIT_FAIL;
    if ((a->size && qd_plot_size_of(ctx, a->size, &a->width, &a->height) != QD_OK) ||
        (a->dpi && qd_plot_dpi_check(ctx, a->dpi) != QD_OK)) {
        int rc = cli_diag_ctx(ctx);
        qd_ctx_free(ctx);
        return rc;
    }
    if (a->ycols && a->phase) {
        cli_diag_error("%s: --plot-y (against t) and --phase (q' against q) are two kinds of "
                       "plot; give one", cmd);
        qd_ctx_free(ctx);
        return QD_EXIT_USAGE;
    }
    qd_plot_format f;
    int rc = !a->file || qd_plot_format_of(ctx, a->file, &f) == QD_OK ? QD_EXIT_OK
                                                                      : cli_diag_ctx(ctx);
    qd_ctx_free(ctx);
    return rc;
}

void cli_plot_keep(cli_plot_rows *r, const double *row) {
    if (r->failed)
        return;
    if (r->n == r->cap) {
        size_t cap = r->cap ? 2 * r->cap : 1024;
        double *v = realloc(r->v, cap * r->ncols * sizeof *v);
        if (!v) {
            r->failed = true;
            return;
        }
        r->v = v;
        r->cap = cap;
    }
    memcpy(r->v + r->n++ * r->ncols, row, r->ncols * sizeof *row);
}

void cli_plot_rows_free(cli_plot_rows *r) {
    free(r->v);
    r->v = NULL;
    r->n = r->cap = 0;
}

int cli_plot_pick_columns(const cli_plot_args *a, const char *const *names, size_t ncols,
                          size_t ndof, qd_ctx *mctx, const qd_model *m, cli_plot_pick *pk) {
    qd_ctx *ctx = qd_ctx_new();
    const char **units = malloc((ncols + 1) * sizeof *units);
    int rc = !ctx || !units ? QD_EXIT_FAIL
             : qd_plot_pick_columns(ctx, a->ycols, a->phase, names, ncols, ndof, pk) == QD_OK
                 ? QD_EXIT_OK
                 : cli_diag_ctx(ctx);
    if (rc == QD_EXIT_OK) {
        for (size_t k = 0; k < ncols; k++)
            units[k] = m ? qd_model_column_unit(mctx, m, names[k]) : k ? NULL : "s";
        qd_plot_pick_units(pk, units, ncols, !a->ycols && !a->phase);
    }
    free(units);
    qd_ctx_free(ctx);
    return rc;
}

int cli_plot_write_run(qd_ctx *ctx, const cli_plot_args *a, const cli_plot_pick *pk,
                       const char *const *names, const cli_plot_rows *r, const char *title,
                       bool points, double *range) {
    if (r->failed) {
        cli_diag_error("out of memory keeping the rows for --plot");
        return QD_EXIT_FAIL;
    }
    qd_plot_run_opts o = cli_plot_opts(a, title);
    o.points = points;
    qd_plot *p = qd_plot_run(ctx, pk, names, r->v, r->n, r->ncols, &o);
    qd_status st = p ? qd_plot_write(p, a->file) : QD_ERR_ARG;
    for (size_t g = 0; st == QD_OK && range && g < pk->npanels; g++)
        qd_plot_ranges(p, g, &range[4 * g], &range[4 * g + 1], &range[4 * g + 2],
                       &range[4 * g + 3]);
    qd_plot_free(p);
    return st == QD_OK ? QD_EXIT_OK : cli_diag_ctx(ctx);
}
