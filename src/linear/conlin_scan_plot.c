/*
 * src/linear/conlin_scan_plot.c - a constrained scan's eigenvalues against
 * its parameter (qd_conlin_scan_plot, qdot/scanplot.h): the picture of
 * Meijaard et al. 2007, fig. 3 (the Whipple bicycle's eigenvalues against
 * the speed v, Proc. R. Soc. A 463, 1955-1982), for any model `linearize
 * --scan` takes.  Dots, not lines: which eigenvalue continues which is not
 * known at a crossing, and a line joining the wrong ones would draw a
 * branch that is not there.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "qdot/scanplot.h"
#include "../base/args.h"

/* Panel 0: (p, Re s) of every eigenvalue; panel 1: (p, Im s) with Im s >= 0
 * (a conjugate pair once).  *lo, *hi: the values' range. */
static qd_status eigen_dots(qd_plot *p, const qd_conlin_scan *s, bool imag, double *x,
                            double *y, double *lo, double *hi) {
    size_t k = 0;
    *lo = INFINITY;
    *hi = -INFINITY;
    for (size_t i = 0; i < s->nsamples; i++)
        for (size_t j = 0; j < s->nx; j++) {
            double v = imag ? s->im[i * s->nx + j] : s->re[i * s->nx + j];
            if (!isfinite(v) || !isfinite(s->p[i]) || (imag && v < 0))
                continue;
            x[k] = s->p[i];
            y[k++] = v;
            *lo = fmin(*lo, v);
            *hi = fmax(*hi, v);
        }
    if (!k)
        return QD_OK;
    return qd_plot_add(p, imag ? "Im s" : "Re s", QD_PLOT_POINTS, k, x, y, NULL);
}

/* A vertical line at each change of stability over [lo, hi]; its legend in
 * the first panel only. */
static qd_status crossings(qd_plot *p, const qd_conlin_scan *s, const char *name, bool legend,
                           double lo, double hi) {
    qd_status st = QD_OK;
    for (size_t c = 0; c < s->ncross && st == QD_OK; c++) {
        const qd_conlin_cross *k = &s->cross[c];
        char label[160];
        snprintf(label, sizeof label, "%s = %.4f: %s (%s above)", name, k->at,
                 k->omega > 0 ? "a complex pair crosses" : "a real eigenvalue crosses 0",
                 k->to_stable ? "stable" : "unstable");
        double x[2] = {k->at, k->at}, y[2] = {lo, hi};
        st = qd_plot_add(p, legend ? label : NULL, QD_PLOT_LINE, 2, x, y, NULL);
    }
    return st;
}

static qd_status draw(qd_plot *p, const qd_conlin_scan *s, const char *name, const char *title) {
    size_t n = s->nsamples * s->nx;
    double *x = malloc((n + 1) * sizeof *x), *y = malloc((n + 1) * sizeof *y);
    char xlabel[140];
    snprintf(xlabel, sizeof xlabel, "%s", name);
    qd_status st = x && y ? qd_plot_panels(p, 2, 1) : QD_ERR_NOMEM;
    for (size_t panel = 0; panel < 2 && st == QD_OK; panel++) {
        double lo, hi;
        st = qd_plot_select(p, panel);
        if (st == QD_OK && panel == 0)
            st = qd_plot_set_title(p, title ? title : "eigenvalues against the parameter");
        if (st == QD_OK)
            st = qd_plot_set_xlabel(p, xlabel);
        if (st == QD_OK)
            st = qd_plot_set_ylabel(p, panel ? "Im s (1/s)" : "Re s (1/s)");
        if (st == QD_OK)
            st = eigen_dots(p, s, panel == 1, x, y, &lo, &hi);
        if (st == QD_OK && lo <= hi)
            st = crossings(p, s, name, panel == 0, lo, hi);
        if (st == QD_OK && panel == 0 && lo <= 0 && hi >= 0) {
            double zx[2] = {s->p[0], s->p[s->nsamples - 1]}, zy[2] = {0, 0};
            st = qd_plot_add(p, NULL, QD_PLOT_LINE, 2, zx, zy, NULL); /* Re s = 0 */
        }
    }
    free(x);
    free(y);
    return st;
}

qd_status qd_conlin_scan_plot(qd_ctx *ctx, const qd_conlin_scan *s, const char *name,
                              const char *title, qd_plot **out) {
    QD_ARGS_CTX(ctx, ctx && s && name && out);
    *out = NULL;
    if (!s->nsamples || !s->nx || !s->p || !s->re || !s->im) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the scan has no eigenvalues to draw");
        return QD_ERR_ARG;
    }
    qd_plot *p = qd_plot_new(ctx, 900, 700);
    if (!p)
        return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    qd_status st = draw(p, s, name, title);
    if (st != QD_OK) {
        if (qd_ctx_status(ctx) == QD_OK)
            qd_ctx_error(ctx, st, "cannot draw the scan: %s", qd_status_str(st));
        qd_plot_free(p);
        return st;
    }
    *out = p;
    return QD_OK;
}
