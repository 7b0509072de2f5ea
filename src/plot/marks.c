/*
 * src/plot/marks.c - the figure of a configuration over a panel's data
 * (qd_plot_add_mark: springs, rods, arrows, pivots), the panel's heading
 * and note, the shared legend and the PNG's resolution (qdot/plot.h).
 */
#include "plot_priv.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <math.h>
#include <string.h>

qd_status qd_plot_add_mark(qd_plot *p, qd_plot_mark kind, double x0, double y0, double x1,
                           double y1) {
    QD_ARGS(QD_ERR_ARG, p);
    if (kind == QD_PLOT_PIVOT)
        x1 = x0, y1 = y0;
    if ((unsigned)kind > QD_PLOT_WALL || !isfinite(x0) || !isfinite(y0) || !isfinite(x1) ||
        !isfinite(y1)) {
        qd_ctx_error(p->ctx, QD_ERR_ARG, "a plot's mark needs a known kind and finite points");
        return QD_ERR_ARG;
    }
    if (p->nmarks == p->capm) {
        size_t cap = p->capm ? 2 * p->capm : 8;
        qd__plot_mark *m = qd__realloc(p->ctx, p->marks, cap * sizeof *m);
        if (!m)
            return QD_ERR_NOMEM;
        p->marks = m;
        p->capm = cap;
    }
    p->marks[p->nmarks++] = (qd__plot_mark){kind, p->cur, x0, y0, x1, y1};
    p->laid_out = false;
    return QD_OK;
}

static qd_status set_text(qd_plot *p, char **slot, const char *text) {
    char *copy = text && *text ? qd__strdup(p->ctx, text) : NULL;
    if (text && *text && !copy)
        return QD_ERR_NOMEM;
    qd__free(*slot);
    *slot = copy;
    p->laid_out = false;
    return QD_OK;
}

qd_status qd_plot_set_heading(qd_plot *p, const char *text) {
    QD_ARGS(QD_ERR_ARG, p);
    return set_text(p, &p->panels[p->cur].heading, text);
}

qd_status qd_plot_set_note(qd_plot *p, const char *text) {
    QD_ARGS(QD_ERR_ARG, p);
    return set_text(p, &p->panels[p->cur].note, text);
}

qd_status qd_plot_share_legend(qd_plot *p, bool shared) {
    QD_ARGS(QD_ERR_ARG, p);
    p->shared_legend = shared;
    p->laid_out = false;
    return QD_OK;
}

qd_status qd_plot_set_dpi(qd_plot *p, double dpi) {
    QD_ARGS(QD_ERR_ARG, p);
    qd_status st = qd_plot_dpi_check(p->ctx, dpi);
    if (st == QD_OK)
        p->dpi = dpi;
    return st;
}

qd_status qd_plot_set_point_size(qd_plot *p, double radius) {
    QD_ARGS(QD_ERR_ARG, p);
    if (radius == 0 || (radius >= 0.2 && radius <= 20)) {
        p->point_size = radius;
        return QD_OK;
    }
    qd_ctx_error(p->ctx, QD_ERR_ARG, "a point's radius is 0.2 to 20 pixels (0: by the points' "
                 "number), not %g", radius);
    qd_ctx_error_about(p->ctx, QD_SUBJECT_NONE, 0, "point_size", QD_REASON_NONE, NULL);
    return QD_ERR_ARG;
}

qd_status qd_plot_dpi_check(qd_ctx *ctx, double dpi) {
    QD_ARGS_CTX(ctx, ctx);
    if (dpi >= 72 && dpi <= 1200)
        return QD_OK;
    qd_ctx_error(ctx, QD_ERR_ARG, "a plot's resolution is 72 to 1200 dpi, not %g", dpi);
    qd_ctx_error_about(ctx, QD_SUBJECT_NONE, 0, "dpi", QD_REASON_NONE, NULL);
    return QD_ERR_ARG;
}

qd_status qd_plot_set_size(qd_plot *p, int width, int height) {
    QD_ARGS(QD_ERR_ARG, p);
    if (!width && !height) {
        width = 800;
        height = 500;
    }
    if (width < 200 || height < 200 || width > 10000 || height > 10000) {
        qd_ctx_error(p->ctx, QD_ERR_ARG, "a plot is 200 to 10000 pixels wide and high, not %d x %d",
                     width, height);
        return QD_ERR_ARG;
    }
    p->width = width;
    p->height = height;
    p->laid_out = false;
    return QD_OK;
}

bool qd__plot_legend_first(const qd_plot *p, size_t i) {
    for (size_t k = 0; k < i; k++)
        if (!strcmp(p->series[k].label, p->series[i].label))
            return false;
    return true;
}

void qd__plot_marks_range(const qd_plot *p, size_t k, bool want_y, double *lo, double *hi) {
    for (size_t i = 0; i < p->nmarks; i++) {
        const qd__plot_mark *m = &p->marks[i];
        if (m->panel != k)
            continue;
        double a = want_y ? m->y0 : m->x0, b = want_y ? m->y1 : m->x1;
        *lo = fmin(*lo, fmin(a, b));
        *hi = fmax(*hi, fmax(a, b));
    }
}

void qd__plot_marks_free(qd_plot *p) {
    qd__free(p->marks);
    p->marks = NULL;
    p->nmarks = p->capm = 0;
}
