/*
 * src/plot/run.c - a run's rows drawn (qdot simulate --plot, poincare
 * --plot): which columns (--plot-y, --phase, or every coordinate against
 * t), the panels, their labels, the picture's size.  Errors name the option
 * field ("plot_y", "phase", "size").
 */
#include "plot_priv.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define ENERGY_ERROR "energy_error"

/* The error just recorded concerns the option field name. */
static qd_status field(qd_ctx *ctx, const char *name) {
    qd_ctx_error_about(ctx, QD_SUBJECT_NONE, 0, name, QD_REASON_NONE, NULL);
    return QD_ERR_ARG;
}

qd_status qd_plot_size_of(qd_ctx *ctx, const char *text, int *width, int *height) {
    QD_ARGS_CTX(ctx, ctx && text && width && height);
    char *end;
    long w = strtol(text, &end, 10), h = 0;
    bool ok = end != text && (*end == 'x' || *end == 'X');
    if (ok) {
        const char *hs = end + 1;
        h = strtol(hs, &end, 10);
        ok = end != hs && !*end;
    }
    if (!ok || w < 100 || h < 100 || w > 10000 || h > 10000) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the size takes WxH in pixels (100 to 10000 each), e.g. "
                     "1200x800, not '%.80s'", text);
        return field(ctx, "size");
    }
    *width = (int)w;
    *height = (int)h;
    return QD_OK;
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

static qd_status unknown_column(qd_ctx *ctx, const char *opt, const char *name, size_t len) {
    qd_ctx_error(ctx, QD_ERR_ARG, "'%.*s' is not a column of the run (its coordinates, their "
                 "velocities NAME', energy, energy_error, the outputs: see the CSV header)",
                 (int)(len < 80 ? len : 80), name);
    return field(ctx, opt);
}

/* "a, b'; energy_error": each name a column, or energy_error; a semicolon
 * starts the next panel. */
static qd_status pick_list(qd_ctx *ctx, const char *list, const char *const *names, size_t ncols,
                           qd_plot_pick *pk) {
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
        if (pk->ny == QD_PLOT_MAX_SERIES || pk->npanels > QD_PLOT_MAX_PANELS) {
            qd_ctx_error(ctx, QD_ERR_ARG, "at most %d series in %d panels", QD_PLOT_MAX_SERIES,
                         QD_PLOT_MAX_PANELS);
            return field(ctx, "plot_y");
        }
        size_t col;
        if (len == strlen(ENERGY_ERROR) && !strncmp(w, ENERGY_ERROR, len) &&
            find_column(names, ncols, "energy", 6, &pk->energy)) {
            pk->energy_error = true;
            col = ncols;
        } else if (!find_column(names, ncols, w, len, &col)) {
            return unknown_column(ctx, "plot_y", w, len);
        }
        pk->panel[pk->ny] = pk->npanels - 1;
        pk->y[pk->ny++] = col;
    }
    if (pk->ny && pk->panel[pk->ny - 1] != pk->npanels - 1)
        pk->npanels--; /* a trailing semicolon */
    if (!pk->ny) {
        qd_ctx_error(ctx, QD_ERR_ARG, "no column named");
        return field(ctx, "plot_y");
    }
    return QD_OK;
}

qd_status qd_plot_pick_columns(qd_ctx *ctx, const char *ycols, const char *phase,
                               const char *const *names, size_t ncols, size_t ndof,
                               qd_plot_pick *pk) {
    QD_ARGS_CTX(ctx, ctx && names && pk);
    *pk = (qd_plot_pick){.npanels = 1};
    if (ycols && phase) {
        qd_ctx_error(ctx, QD_ERR_ARG, "a plot against t (plot_y) and a phase plot (q' against "
                     "q) are two kinds of plot; give one");
        return QD_ERR_ARG;
    }
    if (phase) {
        size_t len = strlen(phase);
        char vel[80];
        snprintf(vel, sizeof vel, "%s'", phase);
        pk->phase = true;
        pk->ny = 1;
        if (!find_column(names, ncols, phase, len, &pk->x) || pk->x == 0)
            return unknown_column(ctx, "phase", phase, len);
        if (!find_column(names, ncols, vel, strlen(vel), &pk->y[0]))
            return unknown_column(ctx, "phase", vel, strlen(vel));
        return QD_OK;
    }
    if (ycols)
        return pick_list(ctx, ycols, names, ncols, pk);
    for (size_t j = 0; j < ndof && j + 1 < ncols && pk->ny < QD_PLOT_MAX_SERIES; j++)
        pk->y[pk->ny++] = 1 + j; /* every coordinate against t */
    return QD_OK;
}

/* ---- drawing ------------------------------------------------------------- */

typedef struct run_rows {
    const qd_plot_pick *pk;
    const char *const *names;
    const double *v;
    size_t n, ncols;
    size_t norbits; /* 1, or the orbits the rows are in turn (o->orbit_rows) */
} run_rows;

static const char *series_name(const run_rows *r, size_t i) {
    return r->pk->y[i] == r->ncols ? ENERGY_ERROR : r->names[r->pk->y[i]];
}

static double value(const run_rows *r, size_t row, size_t col) {
    if (col == r->ncols) /* energy_error: E(t) - E(t0) */
        return r->v[row * r->ncols + r->pk->energy] - r->v[r->pk->energy];
    return r->v[row * r->ncols + col];
}

void qd_plot_pick_units(qd_plot_pick *pk, const char *const *units, size_t ncols, bool split) {
    QD_ARGS(, pk && units);
    for (size_t i = 0; i < pk->ny; i++)
        pk->unit[i] = pk->y[i] < ncols ? units[pk->y[i]] : NULL;
    pk->xunit = pk->x < ncols ? units[pk->x] : NULL;
    if (!split || pk->phase)
        return;
    /* the panel of a unit: the place its unit first comes among the series */
    const char *seen[QD_PLOT_MAX_SERIES];
    size_t nseen = 0;
    for (size_t i = 0; i < pk->ny; i++) {
        size_t g = 0;
        while (g < nseen && !(seen[g] == pk->unit[i] ||
                              (seen[g] && pk->unit[i] && !strcmp(seen[g], pk->unit[i]))))
            g++;
        if (g == nseen && nseen < QD_PLOT_MAX_PANELS)
            seen[nseen++] = pk->unit[i];
        pk->panel[i] = g < nseen ? g : nseen - 1;
    }
    pk->npanels = nseen ? nseen : 1;
}

/* Panel g's y label: its series' names, "theta1, theta2", and their unit
 * when they share one, or the g-th of the labels "A; B; C" given (the last
 * one for the panels after it). */
static void y_label(const run_rows *r, size_t g, const char *ylabel, char *buf, size_t cap) {
    if (ylabel) {
        const char *at = ylabel, *semi;
        for (size_t k = 0; k < g && (semi = strchr(at, ';')); k++)
            at = semi + 1;
        while (*at == ' ')
            at++;
        semi = strchr(at, ';');
        snprintf(buf, cap, "%.*s", (int)(semi ? (size_t)(semi - at) : strlen(at)), at);
        return;
    }
    size_t k = 0;
    const char *unit = NULL;
    bool one = true, first = true;
    buf[0] = 0;
    for (size_t i = 0; i < r->pk->ny; i++) {
        if (r->pk->panel[i] != g)
            continue;
        if (k + 1 < cap)
            k += (size_t)snprintf(buf + k, cap - k, "%s%s", k ? ", " : "", series_name(r, i));
        const char *u = r->pk->unit[i];
        one &= first || (u && unit && !strcmp(u, unit));
        unit = first ? u : unit;
        first = false;
    }
    if (one && unit && k + 1 < cap)
        snprintf(buf + k, cap - k, " (%s)", unit);
}

static qd_status fill_panel(qd_plot *p, const run_rows *r, size_t g, const qd_plot_run_opts *o,
                            double *x, double *y) {
    const qd_plot_pick *pk = r->pk;
    char xu[160]; /* a phase plot's coordinate, with its unit */
    snprintf(xu, sizeof xu, pk->xunit ? "%s (%s)" : "%s", r->names[pk->x], pk->xunit);
    const char *xl = o->xlabel ? o->xlabel : pk->x == 0 ? "t (s)" : xu;
    char yl[256];
    y_label(r, g, o->ylabel, yl, sizeof yl);
    qd_status st = qd_plot_select(p, g);
    if (st == QD_OK)
        st = qd_plot_set_xlabel(p, xl);
    if (st == QD_OK)
        st = qd_plot_set_ylabel(p, yl);
    size_t inpanel = 0;
    for (size_t i = 0; i < pk->ny; i++)
        inpanel += pk->panel[i] == g;
    for (size_t i = 0; i < pk->ny && st == QD_OK; i++) {
        if (pk->panel[i] != g)
            continue;
        char pair[160]; /* a phase curve: "(theta, theta')" */
        const char *label = series_name(r, i);
        if (pk->phase)
            snprintf(pair, sizeof pair, "(%s, %s)", r->names[pk->x], label);
        label = pk->phase ? pair : label;
        size_t from = 0;
        for (size_t orbit = 0; orbit < r->norbits && st == QD_OK; orbit++) {
            size_t n = r->norbits > 1 ? o->orbit_rows[orbit] : r->n;
            for (size_t k = 0; k < n; k++) {
                x[k] = value(r, from + k, pk->x);
                y[k] = value(r, from + k, pk->y[i]);
            }
            char on[128], named[300]; /* an orbit's series: the orbit, after the series */
            const char *ol = o->orbit_labels ? o->orbit_labels[orbit] : NULL;
            if (ol)
                snprintf(on, sizeof on, "%s", ol);
            else
                snprintf(on, sizeof on, "orbit %zu", orbit + 1);
            snprintf(named, sizeof named, inpanel > 1 ? "%s: %s" : "%.0s%s", label, on);
            if (n) /* an orbit without rows is left out */
                st = qd_plot_add(p, r->norbits > 1 ? named : label,
                                 o->points ? QD_PLOT_POINTS : QD_PLOT_LINE, n, x, y, NULL);
            from += n;
        }
    }
    return st;
}

/* The orbits' rows sum to the rows drawn. */
static qd_status check_orbits(qd_ctx *ctx, const qd_plot_run_opts *o, size_t nrows) {
    size_t sum = 0;
    for (size_t k = 0; o->norbits > 1 && o->orbit_rows && k < o->norbits; k++)
        sum += o->orbit_rows[k];
    if (o->norbits <= 1 || (o->orbit_rows && sum == nrows))
        return QD_OK;
    qd_ctx_error(ctx, QD_ERR_ARG, "the orbits' rows (%zu) are not the rows drawn (%zu)", sum,
                 nrows);
    return QD_ERR_ARG;
}

qd_status qd_plot_apply(qd_plot *p, const qd_plot_run_opts *o) {
    QD_ARGS(QD_ERR_ARG, p && o);
    qd_status st = o->title ? qd_plot_set_title(p, o->title) : QD_OK;
    if (st == QD_OK && o->width)
        st = qd_plot_set_size(p, o->width, o->height);
    if (st == QD_OK && o->dpi)
        st = qd_plot_set_dpi(p, o->dpi);
    if (st == QD_OK && o->point_size)
        st = qd_plot_set_point_size(p, o->point_size);
    size_t cur = p->cur;
    for (size_t g = 0; g < qd_plot_npanels(p) && st == QD_OK; g++) {
        char yl[256];
        p->cur = g;
        if (o->xlabel)
            st = qd_plot_set_xlabel(p, o->xlabel);
        if (st == QD_OK && o->ylabel) {
            y_label(NULL, g, o->ylabel, yl, sizeof yl);
            st = qd_plot_set_ylabel(p, yl);
        }
    }
    p->cur = cur;
    return st;
}

qd_plot *qd_plot_run(qd_ctx *ctx, const qd_plot_pick *pk, const char *const *names,
                     const double *rows, size_t nrows, size_t ncols, const qd_plot_run_opts *o) {
    QD_ARGS(NULL, ctx && pk && names && rows && o);
    if (!nrows) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the run gave no rows to plot");
        return NULL;
    }
    if (pk->npanels < 1 || pk->npanels > QD_PLOT_MAX_PANELS) {
        qd_ctx_error(ctx, QD_ERR_ARG, "a plot of 1 to %d panels", QD_PLOT_MAX_PANELS);
        return NULL;
    }
    /* one panel: 800 x 500; stacked panels 280 high each, under the title */
    int height = pk->npanels > 1 ? 40 + 280 * (int)pk->npanels : 0;
    int width = height ? 800 : 0;
    if (o->width) {
        width = o->width;
        height = o->height;
    }
    if (check_orbits(ctx, o, nrows) != QD_OK)
        return NULL;
    double *x = qd__malloc(ctx, nrows * sizeof *x), *y = qd__malloc(ctx, nrows * sizeof *y);
    qd_plot *p = x && y ? qd_plot_new(ctx, width, height) : NULL;
    const char *title = o->title ? o->title : "";
    qd_status st = p ? qd_plot_set_title(p, title) : QD_ERR_NOMEM;
    if (st == QD_OK && o->dpi)
        st = qd_plot_set_dpi(p, o->dpi);
    if (st == QD_OK && o->point_size)
        st = qd_plot_set_point_size(p, o->point_size);
    if (st == QD_OK && pk->npanels > 1)
        st = qd_plot_panels(p, pk->npanels, 1);
    run_rows r = {.pk = pk, .names = names, .v = rows, .n = nrows, .ncols = ncols,
                  .norbits = o->norbits > 1 ? o->norbits : 1};
    for (size_t g = 0; g < pk->npanels && st == QD_OK; g++)
        st = fill_panel(p, &r, g, o, x, y);
    qd__free(x);
    qd__free(y);
    if (st != QD_OK) {
        qd_plot_free(p);
        return NULL;
    }
    return p;
}
