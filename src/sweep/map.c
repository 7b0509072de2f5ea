/*
 * src/sweep/map.c - one measure of a grid of two axes drawn as a colour map
 * (qd_plot_add_map): the first axis across, the second up.  The axes are the
 * grid's own points (the sweep knows them), so nothing is guessed back from
 * the rows.
 */
#include "sweep_int.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/mem.h"
#include "../base/args.h"

/* The error just recorded is about the option field name ("map"). */
static qd_status field(qd_ctx *ctx, qd_status st, const char *name) {
    qd_ctx_error_about(ctx, QD_SUBJECT_NONE, 0, name, QD_REASON_NONE, NULL);
    return st;
}

qd_status qd_sweep_map_column(const qd_sweep *w, const char *measure, size_t *col) {
    QD_ARGS(QD_ERR_ARG, w && col);
    if (w->how != QD__SW_GRID) {
        qd_ctx_error(w->ctx, QD_ERR_ARG, "a map draws a grid of two axes "
                     "(\"A=a0:a1:N, B=b0:b1:M\"), not random or listed runs");
        return field(w->ctx, QD_ERR_ARG, "map");
    }
    if (w->nin != 2) {
        qd_ctx_error(w->ctx, QD_ERR_ARG, "a map draws a grid of two axes; this one has %zu",
                     w->nin);
        return field(w->ctx, QD_ERR_ARG, "map");
    }
    if (w->ncols <= w->nin) {
        qd_ctx_error(w->ctx, QD_ERR_ARG, "a map draws a measure: the sweep has none");
        return field(w->ctx, QD_ERR_ARG, "map");
    }
    if (!measure) {
        *col = w->nin;
        return QD_OK;
    }
    for (size_t j = w->nin; j < w->ncols; j++)
        if (!strcmp(w->cols[j], measure)) {
            *col = j;
            return QD_OK;
        }
    qd_ctx_error(w->ctx, QD_ERR_ARG, "'%s' is not a measure column of the sweep (the first "
                 "is '%s')", measure, w->cols[w->nin]);
    return field(w->ctx, QD_ERR_ARG, "map_measure");
}

/* A column's unit: an input's or a run column's (qd_model_column_unit:
 * s, an angle's rad, its velocity's rad/s), that of the column a measure
 * reads (final_X, event_X, max:X, min:X), or the one the measure fixes (a
 * Lyapunov exponent is a rate, 1/s; an event's and an escape's time, s; a
 * count of crossings has none but what it counts).  A length's or an
 * energy's unit is the model's, which it does not state: NULL. */
static const char *column_unit(const qd_sweep *w, const char *name) {
    static const char *const read[] = {"final_", "event_", "max:", "min:"};
    if (!strncmp(name, "lyapunov", 8)) /* an exponent, or its error */
        return "1/s";
    if (!strcmp(name, "event_t") || !strncmp(name, "escape:", 7))
        return "s";
    if (!strcmp(name, "poincare-count"))
        return "crossings";
    for (size_t k = 0; k < sizeof read / sizeof read[0]; k++)
        if (!strncmp(name, read[k], strlen(read[k])))
            name += strlen(read[k]);
    return qd_model_column_unit(w->ctx, w->m, name); /* records nothing */
}

/* "NAME (UNIT)", or NAME where the unit is not known. */
static void with_unit(const qd_sweep *w, const char *name, char *buf, size_t cap) {
    const char *unit = column_unit(w, name);
    snprintf(buf, cap, unit ? "%s (%s)" : "%s", name, unit);
}

qd_status qd_sweep_map(const qd_sweep *w, const double *rows, size_t col, qd_plot *p) {
    QD_ARGS(QD_ERR_ARG, w && rows && p);
    size_t c = 0;
    qd_status st = qd_sweep_map_column(w, NULL, &c);
    if (st != QD_OK)
        return st;
    if (col < w->nin || col >= w->ncols) {
        qd_ctx_error(w->ctx, QD_ERR_ARG, "column %zu is not a measure column of the sweep", col);
        return QD_ERR_ARG;
    }
    size_t nx = w->in[0].npts, ny = w->in[1].npts, n = nx * ny;
    double *x = qd__malloc(w->ctx, nx * sizeof *x), *y = qd__malloc(w->ctx, ny * sizeof *y);
    double *z = qd__malloc(w->ctx, n * sizeof *z);
    st = x && y && z ? QD_OK : QD_ERR_NOMEM;
    double in[2];
    /* run k = i * ny + j is (x[i], y[j]): the first axis slowest */
    for (size_t k = 0; st == QD_OK && k < n; k++) {
        size_t i = k / ny, j = k % ny;
        qd__sweep_inputs_of(w, k, in);
        x[i] = in[0];
        y[j] = in[1];
        z[j * nx + i] = rows[k * w->ncols + col];
    }
    char label[200];
    with_unit(w, w->cols[0], label, sizeof label);
    if (st == QD_OK)
        st = qd_plot_set_xlabel(p, label);
    with_unit(w, w->cols[1], label, sizeof label);
    if (st == QD_OK)
        st = qd_plot_set_ylabel(p, label);
    with_unit(w, w->cols[col], label, sizeof label);
    if (st == QD_OK)
        st = qd_plot_add_map(p, label, nx, ny, x, y, z);
    qd__free(x);
    qd__free(y);
    qd__free(z);
    return st;
}

qd_status qd_sweep_map_check(const qd_sweep *w, const char *path, const char *measure,
                             size_t *col) {
    QD_ARGS(QD_ERR_ARG, w && path && col);
    qd_plot_format f;
    qd_status st = qd_plot_format_of(w->ctx, path, &f);
    return st == QD_OK ? qd_sweep_map_column(w, measure, col) : st;
}

qd_status qd_sweep_map_file(const qd_sweep *w, const double *rows, size_t col, const char *title,
                            const char *path) {
    QD_ARGS(QD_ERR_ARG, w && rows && path);
    qd_plot *p = qd_plot_new(w->ctx, 0, 0);
    qd_status st = p ? QD_OK : qd_ctx_status(w->ctx);
    if (st == QD_OK && title)
        st = qd_plot_set_title(p, title);
    if (st == QD_OK)
        st = qd_sweep_map(w, rows, col, p);
    if (st == QD_OK)
        st = qd_plot_write(p, path);
    qd_plot_free(p);
    return st;
}
