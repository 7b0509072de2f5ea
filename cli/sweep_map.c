/*
 * cli/sweep_map.c - qdot sweep --map: the grid's shape read back from the
 * rows (run order is the grid's, the first axis slowest), one measure laid
 * over it and drawn by libqdot's plots.
 */
#include "sweep_map.h"

#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "model_cli.h"

int cli_sweep_map_option(int argc, char **argv, int *i, cli_sweep_map *m) {
    const char *v;
    int rc;
    if ((v = cli_value(argc, argv, i, "--map")))
        rc = cli_once("--map", &m->file, v);
    else if ((v = cli_value(argc, argv, i, "--map-measure")))
        rc = cli_once("--map-measure", &m->measure, v);
    else
        return 0;
    return rc == QD_EXIT_OK ? 1 : rc + 100;
}

static int find_measure(const cli_sweep_map *m, const qd_sweep *w, size_t *col) {
    size_t nin = qd_sweep_ninputs(w), ncols = qd_sweep_ncols(w);
    if (!m->measure) {
        *col = nin;
        return nin < ncols ? QD_EXIT_OK : QD_EXIT_USAGE;
    }
    for (*col = nin; *col < ncols; (*col)++)
        if (!strcmp(qd_sweep_col(w, *col), m->measure))
            return QD_EXIT_OK;
    cli_diag_error("--map-measure: '%s' is not a measure column of the sweep (the first is "
                   "'%s')", m->measure, nin < ncols ? qd_sweep_col(w, nin) : "");
    return QD_EXIT_USAGE;
}

int cli_sweep_map_check(const cli_sweep_map *m, const qd_sweep *w, bool grid, size_t *col) {
    if (!m->file) {
        if (m->measure)
            cli_diag_error("--map-measure says what to draw: give the file with --map FILE.png");
        return m->measure ? QD_EXIT_USAGE : QD_EXIT_OK;
    }
    qd_ctx *ctx = qd_ctx_new();
    qd_plot_format f;
    int rc = !ctx ? QD_EXIT_FAIL
             : qd_plot_format_of(ctx, m->file, &f) == QD_OK ? QD_EXIT_OK
                                                             : cli_diag_ctx(ctx);
    qd_ctx_free(ctx);
    if (rc == QD_EXIT_OK && !grid) {
        cli_diag_error("--map draws a --grid of two axes (\"A=a0:a1:N, B=b0:b1:M\"), not a "
                       "--random or --list sweep");
        rc = QD_EXIT_USAGE;
    } else if (rc == QD_EXIT_OK && qd_sweep_ninputs(w) != 2) {
        cli_diag_error("--map draws a --grid of two axes; this one has %zu",
                       qd_sweep_ninputs(w));
        rc = QD_EXIT_USAGE;
    }
    return rc == QD_EXIT_OK ? find_measure(m, w, col) : rc;
}

/* The grid's axes from its rows: run k = i * ny + j is (x[i], y[j]).
 * False when the rows are not such a product. */
static bool grid_axes(const double *rows, size_t nruns, size_t ncols, double **x, size_t *nx,
                      double **y, size_t *ny) {
    size_t n = 1;
    while (n < nruns && rows[n * ncols] == rows[0])
        n++;
    *ny = n;
    *nx = nruns / n;
    *x = malloc(*nx * sizeof **x);
    *y = malloc(*ny * sizeof **y);
    if (!*x || !*y || *nx * *ny != nruns)
        return false;
    for (size_t k = 0; k < nruns; k++) {
        size_t i = k / n, j = k % n;
        if (j == 0)
            (*x)[i] = rows[k * ncols];
        if (i == 0)
            (*y)[j] = rows[k * ncols + 1];
        if (rows[k * ncols] != (*x)[i] || rows[k * ncols + 1] != (*y)[j])
            return false;
    }
    return true;
}

static int draw(const cli_sweep_map *m, const qd_sweep *w, size_t col, const double *x,
                size_t nx, const double *y, size_t ny, const double *z, const char *title) {
    qd_ctx *ctx = qd_ctx_new();
    qd_plot *p = ctx ? qd_plot_new(ctx, 0, 0) : NULL;
    int rc = p && qd_plot_set_title(p, title) == QD_OK &&
                     qd_plot_set_xlabel(p, qd_sweep_col(w, 0)) == QD_OK &&
                     qd_plot_set_ylabel(p, qd_sweep_col(w, 1)) == QD_OK &&
                     qd_plot_add_map(p, qd_sweep_col(w, col), nx, ny, x, y, z) == QD_OK &&
                     qd_plot_write(p, m->file) == QD_OK
                 ? QD_EXIT_OK
                 : ctx ? cli_diag_ctx(ctx) : QD_EXIT_FAIL;
    qd_plot_free(p);
    qd_ctx_free(ctx);
    return rc;
}

int cli_sweep_map_write(const cli_sweep_map *m, const qd_sweep *w, const double *rows,
                        size_t col, const char *title) {
    if (!m->file)
        return QD_EXIT_OK;
    size_t nruns = qd_sweep_nruns(w), ncols = qd_sweep_ncols(w), nx = 0, ny = 0;
    double *x = NULL, *y = NULL, *z = malloc((nruns ? nruns : 1) * sizeof *z);
    int rc = QD_EXIT_OK;
    if (!z || !nruns || !grid_axes(rows, nruns, ncols, &x, &nx, &y, &ny)) {
        cli_diag_error("--map: the runs do not form a grid of two axes");
        rc = QD_EXIT_FAIL;
    }
    for (size_t k = 0; rc == QD_EXIT_OK && k < nruns; k++)
        z[(k % ny) * nx + k / ny] = rows[k * ncols + col];
    if (rc == QD_EXIT_OK)
        rc = draw(m, w, col, x, nx, y, ny, z, title);
    free(x);
    free(y);
    free(z);
    return rc;
}
