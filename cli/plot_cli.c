/*
 * cli/plot_cli.c - the --plot options: columns picked by name, rows kept
 * during a run, and the plot drawn by libqdot (qdot/plot.h) at its end.
 */
#include "plot_cli.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "model_cli.h"

#define ENERGY_ERROR "energy_error"

int cli_plot_option(int argc, char **argv, int *i, cli_plot_args *a) {
    const char *v;
    int rc;
    if ((v = cli_value(argc, argv, i, "--plot")))
        rc = cli_once("--plot", &a->file, v);
    else if ((v = cli_value(argc, argv, i, "--plot-y")))
        rc = cli_once("--plot-y", &a->ycols, v);
    else if ((v = cli_value(argc, argv, i, "--phase")))
        rc = cli_once("--phase", &a->phase, v);
    else if ((v = cli_value(argc, argv, i, "--title")))
        rc = cli_once("--title", &a->title, v);
    else if ((v = cli_value(argc, argv, i, "--xlabel")))
        rc = cli_once("--xlabel", &a->xlabel, v);
    else if ((v = cli_value(argc, argv, i, "--ylabel")))
        rc = cli_once("--ylabel", &a->ylabel, v);
    else if ((v = cli_value(argc, argv, i, "--size")))
        rc = cli_once("--size", &a->size, v);
    else
        return 0;
    return rc == QD_EXIT_OK ? 1 : rc + 100;
}

/* --size WxH: two whole numbers of pixels, 100 to 10000 each. */
static int read_size(cli_plot_args *a) {
    char *end;
    long w = strtol(a->size, &end, 10), h = 0;
    bool ok = end != a->size && (*end == 'x' || *end == 'X');
    if (ok) {
        const char *hs = end + 1;
        h = strtol(hs, &end, 10);
        ok = end != hs && !*end;
    }
    if (!ok || w < 100 || h < 100 || w > 10000 || h > 10000) {
        cli_diag_error("--size takes WxH in pixels (100 to 10000 each), e.g. 1200x800, not '%s'",
                       a->size);
        return QD_EXIT_USAGE;
    }
    a->width = (int)w;
    a->height = (int)h;
    return QD_EXIT_OK;
}

int cli_plot_check(cli_plot_args *a, const char *cmd) {
    const char *shape = a->ycols ? "--plot-y" : a->phase ? "--phase" : a->title ? "--title"
                        : a->xlabel ? "--xlabel" : a->ylabel ? "--ylabel" : a->size ? "--size"
                        : NULL;
    if (!a->file && shape) {
        cli_diag_error("%s says how to plot: give the file with --plot FILE.png|.svg|.pdf",
                       shape);
        return QD_EXIT_USAGE;
    }
    if (a->size && read_size(a) != QD_EXIT_OK)
        return QD_EXIT_USAGE;
    if (a->ycols && a->phase) {
        cli_diag_error("%s: --plot-y (against t) and --phase (q' against q) are two kinds of "
                       "plot; give one", cmd);
        return QD_EXIT_USAGE;
    }
    if (!a->file)
        return QD_EXIT_OK;
    qd_ctx *ctx = qd_ctx_new();
    qd_plot_format f;
    int rc = !ctx ? QD_EXIT_FAIL
             : qd_plot_format_of(ctx, a->file, &f) == QD_OK ? QD_EXIT_OK
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

static bool find_column(const char *const *names, size_t ncols, const char *name, size_t len,
                        size_t *out) {
    for (size_t k = 0; k < ncols; k++)
        if (strlen(names[k]) == len && !strncmp(names[k], name, len)) {
            *out = k;
            return true;
        }
    return false;
}

static int unknown_column(const char *opt, const char *name, size_t len) {
    cli_diag_error("%s: '%.*s' is not a column of the run (its coordinates, their velocities "
                   "NAME', energy, energy_error, the outputs: see the CSV header)",
                   opt, (int)len, name);
    return QD_EXIT_USAGE;
}

/* --plot-y "a, b'; energy_error": each name a column, or energy_error; a
 * semicolon starts the next panel. */
static int pick_list(const char *list, const char *const *names, size_t ncols,
                     cli_plot_pick *pk) {
    const char *s = list;
    pk->npanels = 1;
    while (*s) {
        while (isspace((unsigned char)*s) || *s == ',' || *s == ';') {
            if (*s++ == ';' && pk->ny && pk->panel[pk->ny - 1] == pk->npanels - 1)
                pk->npanels++;
        }
        const char *w = s;
        while (*s && *s != ',' && *s != ';')
            s++;
        size_t len = (size_t)(s - w);
        while (len && isspace((unsigned char)w[len - 1]))
            len--;
        if (!len)
            continue;
        if (pk->ny == sizeof pk->y / sizeof pk->y[0] || pk->npanels > CLI_PLOT_MAX_PANELS) {
            cli_diag_error("--plot-y: at most %zu series in %d panels",
                           sizeof pk->y / sizeof pk->y[0], CLI_PLOT_MAX_PANELS);
            return QD_EXIT_USAGE;
        }
        size_t col;
        if (len == strlen(ENERGY_ERROR) && !strncmp(w, ENERGY_ERROR, len) &&
            find_column(names, ncols, "energy", 6, &pk->energy)) {
            pk->energy_error = true;
            col = ncols;
        } else if (!find_column(names, ncols, w, len, &col)) {
            return unknown_column("--plot-y", w, len);
        }
        pk->panel[pk->ny] = pk->npanels - 1;
        pk->y[pk->ny++] = col;
    }
    if (pk->ny && pk->panel[pk->ny - 1] != pk->npanels - 1)
        pk->npanels--; /* a trailing semicolon */
    if (!pk->ny) {
        cli_diag_error("--plot-y names no column");
        return QD_EXIT_USAGE;
    }
    return QD_EXIT_OK;
}

int cli_plot_pick_columns(const cli_plot_args *a, const char *const *names, size_t ncols,
                          size_t ndof, cli_plot_pick *pk) {
    *pk = (cli_plot_pick){.npanels = 1};
    if (a->phase) {
        size_t len = strlen(a->phase);
        char vel[80];
        snprintf(vel, sizeof vel, "%s'", a->phase);
        pk->phase = true;
        pk->ny = 1;
        if (!find_column(names, ncols, a->phase, len, &pk->x) || pk->x == 0)
            return unknown_column("--phase", a->phase, len);
        if (!find_column(names, ncols, vel, strlen(vel), &pk->y[0]))
            return unknown_column("--phase", vel, strlen(vel));
        return QD_EXIT_OK;
    }
    if (a->ycols)
        return pick_list(a->ycols, names, ncols, pk);
    for (size_t j = 0; j < ndof && pk->ny < sizeof pk->y / sizeof pk->y[0]; j++)
        pk->y[pk->ny++] = 1 + j; /* every coordinate against t */
    return QD_EXIT_OK;
}

static const char *series_name(const cli_plot_pick *pk, const char *const *names, size_t ncols,
                               size_t i) {
    return pk->y[i] == ncols ? ENERGY_ERROR : names[pk->y[i]];
}

/* Panel g's y label: its series' names, "theta1, theta2". */
static void y_label(const cli_plot_pick *pk, size_t g, const char *const *names, size_t ncols,
                    char *buf, size_t cap) {
    size_t k = 0;
    buf[0] = 0;
    for (size_t i = 0; i < pk->ny && k + 1 < cap; i++)
        if (pk->panel[i] == g)
            k += (size_t)snprintf(buf + k, cap - k, "%s%s", k ? ", " : "",
                                  series_name(pk, names, ncols, i));
}

static double column(const cli_plot_pick *pk, const cli_plot_rows *r, size_t row, size_t col) {
    if (col == r->ncols) /* energy_error */
        return r->v[row * r->ncols + pk->energy] - r->v[pk->energy];
    return r->v[row * r->ncols + col];
}

static qd_status add_series(qd_plot *p, const cli_plot_pick *pk, const cli_plot_rows *r,
                            const char *label, size_t col, bool points, double *x, double *y) {
    for (size_t k = 0; k < r->n; k++) {
        x[k] = column(pk, r, k, pk->x);
        y[k] = column(pk, r, k, col);
    }
    return qd_plot_add(p, label, points ? QD_PLOT_POINTS : QD_PLOT_LINE, r->n, x, y, NULL);
}

/* Panel g's labels and series. */
static qd_status fill_panel(qd_plot *p, const cli_plot_args *a, const cli_plot_pick *pk, size_t g,
                            const char *const *names, const cli_plot_rows *r, bool points,
                            double *x, double *y) {
    const char *xl = a->xlabel ? a->xlabel : pk->x == 0 ? "t (s)" : names[pk->x];
    char yl[256];
    y_label(pk, g, names, r->ncols, yl, sizeof yl);
    if (a->ylabel) { /* the g-th of "A; B; C" (the last one for the panels after it) */
        const char *at = a->ylabel, *semi;
        for (size_t k = 0; k < g && (semi = strchr(at, ';')); k++)
            at = semi + 1;
        while (*at == ' ')
            at++;
        semi = strchr(at, ';');
        snprintf(yl, sizeof yl, "%.*s", (int)(semi ? (size_t)(semi - at) : strlen(at)), at);
    }
    qd_status st = qd_plot_select(p, g);
    if (st == QD_OK)
        st = qd_plot_set_xlabel(p, xl);
    if (st == QD_OK)
        st = qd_plot_set_ylabel(p, yl);
    for (size_t i = 0; i < pk->ny && st == QD_OK; i++) {
        if (pk->panel[i] != g)
            continue;
        char pair[160]; /* a phase curve: "(theta, theta')" */
        const char *label = series_name(pk, names, r->ncols, i);
        if (pk->phase)
            snprintf(pair, sizeof pair, "(%s, %s)", names[pk->x], label);
        st = add_series(p, pk, r, pk->phase ? pair : label, pk->y[i], points, x, y);
    }
    return st;
}

static qd_status fill(qd_plot *p, const cli_plot_args *a, const cli_plot_pick *pk, const char *const *names,
                      const cli_plot_rows *r, bool points, double *x, double *y) {
    qd_status st = pk->npanels > 1 ? qd_plot_panels(p, pk->npanels, 1) : QD_OK;
    for (size_t g = 0; g < pk->npanels && st == QD_OK; g++)
        st = fill_panel(p, a, pk, g, names, r, points, x, y);
    return st;
}

int cli_plot_write_run(qd_ctx *ctx, const cli_plot_args *a, const cli_plot_pick *pk,
                       const char *const *names, const cli_plot_rows *r, const char *title,
                       bool points, double *range) {
    if (r->failed) {
        cli_diag_error("out of memory keeping the rows for --plot");
        return QD_EXIT_FAIL;
    }
    if (!r->n) {
        cli_diag_error("--plot: the run gave no rows to plot");
        return QD_EXIT_FAIL;
    }
    double *x = malloc(r->n * sizeof *x), *y = malloc(r->n * sizeof *y);
    /* one panel: 800 x 500; stacked panels 280 high each, under the title */
    int height = pk->npanels > 1 ? 40 + 280 * (int)pk->npanels : 0;
    int width = height ? 800 : 0;
    if (a->width) {
        width = a->width;
        height = a->height;
    }
    qd_plot *p = x && y ? qd_plot_new(ctx, width, height) : NULL;
    const char *slash = strrchr(title, '/');
    if (a->title)
        title = a->title;
    else if (slash)
        title = slash + 1;
    qd_status st = p ? qd_plot_set_title(p, title) : QD_ERR_NOMEM;
    if (st == QD_OK)
        st = fill(p, a, pk, names, r, points, x, y);
    if (st == QD_OK)
        st = qd_plot_write(p, a->file);
    for (size_t g = 0; st == QD_OK && range && g < pk->npanels; g++)
        qd_plot_ranges(p, g, &range[4 * g], &range[4 * g + 1], &range[4 * g + 2],
                       &range[4 * g + 3]);
    int rc = QD_EXIT_OK;
    if (st != QD_OK)
        rc = qd_ctx_status(ctx) != QD_OK ? cli_diag_ctx(ctx) : QD_EXIT_FAIL;
    qd_plot_free(p);
    free(x);
    free(y);
    return rc;
}
