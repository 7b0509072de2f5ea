/*
 * src/plot/map.c - colour maps (qdot/plot.h, qd_plot_add_map): a value
 * over a grid kept in its panel, the colour scale, and the cell geometry
 * that layout and drawing share.
 */
#include "plot_priv.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <math.h>
#include <string.h>

/* Viridis (van der Walt and Smith, matplotlib 2.0's default) at 0, 1/8,
 * ..., 1.  Its lightness rises monotonically, and so it does between two
 * samples mixed linearly: a map of x reads as a gradient in grey too. */
static const unsigned viridis[9] = {0x440154, 0x472c7a, 0x3b528b, 0x2c728e, 0x21918c,
                                    0x28ae80, 0x5ec962, 0xaddc30, 0xfde725};

unsigned qd_plot_map_color(double f) {
    f = isnan(f) ? 0.5 : f < 0 ? 0 : f > 1 ? 1 : f;
    double u = f * 8;
    size_t k = u >= 8 ? 7 : (size_t)u;
    double w = u - (double)k;
    unsigned out = 0;
    for (int sh = 16; sh >= 0; sh -= 8) {
        double a = (viridis[k] >> sh) & 255, b = (viridis[k + 1] >> sh) & 255;
        out |= (unsigned)lround(a + w * (b - a)) << sh;
    }
    return out;
}

void qd__plot_map_edges(size_t n, const double *v, size_t i, double *lo, double *hi) {
    if (n == 1) {
        double h = fabs(v[0]) > 0 ? 0.5 * fabs(v[0]) : 0.5; /* a lone point: some room */
        *lo = v[0] - h;
        *hi = v[0] + h;
        return;
    }
    *lo = i > 0 ? 0.5 * (v[i - 1] + v[i]) : v[0] - 0.5 * (v[1] - v[0]);
    *hi = i + 1 < n ? 0.5 * (v[i] + v[i + 1]) : v[n - 1] + 0.5 * (v[n - 1] - v[n - 2]);
}

void qd__plot_map_free(qd__plot_map *m) {
    if (!m)
        return;
    qd__free(m->label);
    qd__free(m->x);
    qd__free(m->y);
    qd__free(m->z);
    qd__free(m);
}

static bool increasing(size_t n, const double *v) {
    for (size_t i = 0; i < n; i++)
        if (!isfinite(v[i]) || (i > 0 && !(v[i] > v[i - 1])))
            return false;
    return true;
}

static qd_status check_map(qd_plot *p, size_t nx, size_t ny, const double *x, const double *y,
                           const double *z) {
    const char *why = NULL;
    if (p->panels[p->cur].map)
        why = "the panel has a colour map already";
    else if (nx == 0 || ny == 0 || !x || !y || !z)
        why = "a colour map needs at least one point along each axis";
    else if (!increasing(nx, x) || !increasing(ny, y))
        why = "a colour map's grid must be finite and strictly increasing along each axis";
    for (size_t k = 0; !why && k < nx * ny; k++)
        if (isinf(z[k]))
            why = "a colour map's values must be finite (NaN for none)";
    if (!why)
        return QD_OK;
    qd_ctx_error(p->ctx, QD_ERR_ARG, "%s", why);
    return QD_ERR_ARG;
}

static double *copy_of(qd_ctx *ctx, size_t n, const double *v) {
    double *c = qd__malloc(ctx, n * sizeof *c);
    if (c)
        memcpy(c, v, n * sizeof *c);
    return c;
}

static void find_range(qd__plot_map *m) {
    m->zmin = NAN;
    m->zmax = NAN;
    for (size_t k = 0; k < m->nx * m->ny; k++)
        if (!isnan(m->z[k])) {
            m->zmin = isnan(m->zmin) ? m->z[k] : fmin(m->zmin, m->z[k]);
            m->zmax = isnan(m->zmax) ? m->z[k] : fmax(m->zmax, m->z[k]);
        }
}

qd_status qd_plot_add_map(qd_plot *p, const char *label, size_t nx, size_t ny, const double *x,
                          const double *y, const double *z) {
    QD_ARGS(QD_ERR_ARG, p && (ny == 0 || x) && (ny == 0 || y) && (ny == 0 || z));
    qd_status st = check_map(p, nx, ny, x, y, z);
    if (st != QD_OK)
        return st;
    qd__plot_map *m = qd__calloc(p->ctx, 1, sizeof *m);
    if (!m)
        return QD_ERR_NOMEM;
    m->nx = nx;
    m->ny = ny;
    m->label = qd__strdup(p->ctx, label ? label : "");
    m->x = copy_of(p->ctx, nx, x);
    m->y = copy_of(p->ctx, ny, y);
    m->z = copy_of(p->ctx, nx * ny, z);
    if (!m->label || !m->x || !m->y || !m->z) {
        qd__plot_map_free(m);
        return QD_ERR_NOMEM;
    }
    find_range(m);
    p->panels[p->cur].map = m;
    p->laid_out = false;
    return QD_OK;
}

bool qd_plot_map_range(const qd_plot *p, size_t panel, double *zmin, double *zmax) {
    QD_ARGS(false, p && zmin && zmax);
    if (panel >= p->rows * p->cols || !p->panels[panel].map || isnan(p->panels[panel].map->zmin))
        return false;
    *zmin = p->panels[panel].map->zmin;
    *zmax = p->panels[panel].map->zmax;
    return true;
}

bool qd_plot_labels(const qd_plot *p, size_t panel, const char **xlabel, const char **ylabel,
                    const char **bar) {
    QD_ARGS(false, p && xlabel && ylabel && bar);
    if (panel >= p->rows * p->cols)
        return false;
    const qd__plot_panel *g = &p->panels[panel];
    *xlabel = g->xlabel ? g->xlabel : "";
    *ylabel = g->ylabel ? g->ylabel : "";
    *bar = g->map && g->map->label ? g->map->label : "";
    return true;
}
