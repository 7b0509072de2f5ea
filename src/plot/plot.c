/*
 * src/plot/plot.c - a plot's series and texts, its axes' ranges and ticks,
 * and the data-to-pixel map that drawing and tests share (qdot/plot.h).
 */
#include "plot_priv.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <ctype.h>
#include <math.h>
#include <string.h>

#define DEFAULT_WIDTH 800
#define DEFAULT_HEIGHT 500

/* Tableau's ten: distinct in hue and lightness, and for the common
 * red-green colour blindness the first two (blue, orange) stay apart. */
static const unsigned palette[] = {0x1f77b4, 0xff7f0e, 0x2ca02c, 0xd62728, 0x9467bd,
                                   0x8c564b, 0xe377c2, 0x7f7f7f, 0xbcbd22, 0x17becf};
#define NPALETTE (sizeof palette / sizeof palette[0])

qd_status qd_plot_format_of(qd_ctx *ctx, const char *path, qd_plot_format *out) {
    QD_ARGS_CTX(ctx, ctx && path && out);
    static const struct { const char *ext; qd_plot_format f; } exts[] = {
        {".png", QD_PLOT_PNG}, {".svg", QD_PLOT_SVG}, {".pdf", QD_PLOT_PDF}};
    const char *dot = path ? strrchr(path, '.') : NULL;
    if (dot && !strchr(dot, '/') && strlen(dot) == 4)
        for (size_t i = 0; i < sizeof exts / sizeof exts[0]; i++) {
            size_t k = 0;
            while (k < 4 && tolower((unsigned char)dot[k]) == exts[i].ext[k])
                k++;
            if (k == 4) {
                *out = exts[i].f;
                return QD_OK;
            }
        }
    qd_ctx_error(ctx, QD_ERR_ARG, "a plot is written as .png, .svg or .pdf, not '%s'",
                 path ? path : "(none)");
    return QD_ERR_ARG;
}

qd_plot *qd_plot_new(qd_ctx *ctx, int width, int height) {
    QD_ARGS(NULL, ctx);
    if (!width && !height) {
        width = DEFAULT_WIDTH;
        height = DEFAULT_HEIGHT;
    }
    if (width < 200 || height < 200 || width > 10000 || height > 10000) {
        qd_ctx_error(ctx, QD_ERR_ARG, "a plot is 200 to 10000 pixels wide and high, not %d x %d",
                     width, height);
        return NULL;
    }
    qd_plot *p = qd__calloc(ctx, 1, sizeof *p);
    qd__plot_panel *one = p ? qd__calloc(ctx, 1, sizeof *one) : NULL;
    if (!one) {
        qd__free(p);
        return NULL;
    }
    p->ctx = ctx;
    p->width = width;
    p->height = height;
    p->panels = one;
    p->rows = p->cols = 1;
    p->dpi = 96;
    return p;
}

static void free_panels(qd_plot *p) {
    for (size_t k = 0; k < p->rows * p->cols; k++) {
        qd__free(p->panels[k].xlabel);
        qd__free(p->panels[k].ylabel);
        qd__free(p->panels[k].heading);
        qd__free(p->panels[k].note);
        qd__plot_map_free(p->panels[k].map);
    }
    qd__free(p->panels);
}

qd_status qd_plot_panels(qd_plot *p, size_t rows, size_t cols) {
    QD_ARGS(QD_ERR_ARG, p);
    bool used = p->nseries || p->nmarks || p->panels[0].map;
    if (used || rows < 1 || cols < 1 || rows > 8 || cols > 8) {
        qd_ctx_error(p->ctx, QD_ERR_ARG, used ? "a plot is divided into panels before "
                     "any series is added" : "a plot has 1 to 8 rows and columns of panels, "
                     "not %zu x %zu", rows, cols);
        return QD_ERR_ARG;
    }
    qd__plot_panel *panels = qd__calloc(p->ctx, rows * cols, sizeof *panels);
    if (!panels)
        return QD_ERR_NOMEM;
    free_panels(p);
    p->panels = panels;
    p->rows = rows;
    p->cols = cols;
    p->cur = 0;
    p->laid_out = false;
    return QD_OK;
}

qd_status qd_plot_set_equal_axes(qd_plot *p, bool equal) {
    QD_ARGS(QD_ERR_ARG, p);
    p->panels[p->cur].equal = equal;
    p->laid_out = false;
    return QD_OK;
}

size_t qd_plot_npanels(const qd_plot *p) {
    QD_ARGS(0, p);
    return p->rows * p->cols;
}

qd_status qd_plot_select(qd_plot *p, size_t panel) {
    QD_ARGS(QD_ERR_ARG, p);
    if (panel >= p->rows * p->cols) {
        qd_ctx_error(p->ctx, QD_ERR_ARG, "the plot has %zu panels; there is no panel %zu",
                     p->rows * p->cols, panel);
        return QD_ERR_ARG;
    }
    p->cur = panel;
    return QD_OK;
}

void qd_plot_free(qd_plot *p) {
    if (!p)
        return;
    for (size_t i = 0; i < p->nseries; i++) {
        qd__free(p->series[i].label);
        qd__free(p->series[i].x);
        qd__free(p->series[i].y);
    }
    qd__free(p->series);
    qd__free(p->title);
    qd__plot_marks_free(p);
    free_panels(p);
    qd__free(p);
}

static qd_status set_text(qd_plot *p, char **slot, const char *text) {
    char *copy = qd__strdup(p->ctx, text ? text : "");
    if (!copy)
        return QD_ERR_NOMEM;
    qd__free(*slot);
    *slot = copy;
    p->laid_out = false;
    return QD_OK;
}

qd_status qd_plot_set_title(qd_plot *p, const char *title) {
    QD_ARGS(QD_ERR_ARG, p && title);
    return set_text(p, &p->title, title);
}

qd_status qd_plot_set_xlabel(qd_plot *p, const char *label) {
    QD_ARGS(QD_ERR_ARG, p && label);
    return set_text(p, &p->panels[p->cur].xlabel, label);
}

qd_status qd_plot_set_ylabel(qd_plot *p, const char *label) {
    QD_ARGS(QD_ERR_ARG, p && label);
    return set_text(p, &p->panels[p->cur].ylabel, label);
}

static qd_status check_points(qd_plot *p, const char *label, size_t n, const double *x,
                              const double *y) {
    if (n == 0 || !x || !y) {
        qd_ctx_error(p->ctx, QD_ERR_ARG, "plot series '%s' has no points", label ? label : "");
        return QD_ERR_ARG;
    }
    for (size_t i = 0; i < n; i++)
        if (!isfinite(x[i]) || !isfinite(y[i])) {
            qd_ctx_error(p->ctx, QD_ERR_ARG, "plot series '%s': point %zu is not finite (%g, %g)",
                         label ? label : "", i + 1, x[i], y[i]);
            return QD_ERR_ARG;
        }
    return QD_OK;
}

static double *copy_doubles(qd_ctx *ctx, size_t n, const double *v) {
    double *c = qd__malloc(ctx, n * sizeof *c);
    if (c)
        memcpy(c, v, n * sizeof *c);
    return c;
}

qd_status qd_plot_add(qd_plot *p, const char *label, qd_plot_style style, size_t n,
                      const double *x, const double *y, size_t *index) {
    QD_ARGS(QD_ERR_ARG, p && (n == 0 || x) && (n == 0 || y));
    qd_status st = check_points(p, label, n, x, y);
    if (st != QD_OK)
        return st;
    if (p->nseries == p->cap) {
        size_t cap = p->cap ? 2 * p->cap : 4;
        qd__plot_series *s = qd__realloc(p->ctx, p->series, cap * sizeof *s);
        if (!s)
            return QD_ERR_NOMEM;
        p->series = s;
        p->cap = cap;
    }
    qd__plot_panel *pan = &p->panels[p->cur];
    qd__plot_series s = {.label = qd__strdup(p->ctx, label ? label : ""), .style = style, .n = n,
                         .panel = p->cur, .nth = pan->nseries,
                         .x = copy_doubles(p->ctx, n, x), .y = copy_doubles(p->ctx, n, y)};
    if (!s.label || !s.x || !s.y) {
        qd__free(s.label);
        qd__free(s.x);
        qd__free(s.y);
        return QD_ERR_NOMEM;
    }
    p->series[p->nseries] = s;
    if (index)
        *index = p->nseries;
    p->nseries++;
    pan->nseries++;
    p->laid_out = false;
    return QD_OK;
}

size_t qd_plot_nseries(const qd_plot *p) {
    QD_ARGS(0, p);
    return p->nseries;
}

unsigned qd_plot_color(const qd_plot *p, size_t i) {
    QD_ARGS(0, p);
    return palette[(i < p->nseries ? p->series[i].nth : i) % NPALETTE];
}

size_t qd_plot_nice_ticks(double lo, double hi, size_t max_ticks, double *step, double *first) {
    QD_ARGS(0, step && first);
    if (!isfinite(lo) || !isfinite(hi) || !(lo < hi) || max_ticks < 2)
        return 0;
    double span = hi - lo;
    /* start a decade below the span's own scale and take the first
     * 1-2-5 step that fits: the most ticks allowed */
    double decade = pow(10, floor(log10(span / (double)max_ticks)));
    static const double mult[] = {1, 2, 5, 10, 20, 50};
    for (size_t k = 0; k < sizeof mult / sizeof mult[0]; k++) {
        double s = mult[k] * decade;
        double a = ceil(lo / s - 1e-9) * s;
        /* a < lo + s, so the count is never negative */
        size_t count = (size_t)(floor((hi - a) / s + 1e-9) + 1);
        if (count <= max_ticks) {
            *step = s;
            *first = a;
            return count;
        }
    }
    return 0; /* unreachable: 50 decades span the range in at most 2 */
}

/* Panel k has marks (a figure): its ranges take them in, padded. */
static bool panel_marks(const qd_plot *p, size_t k) {
    for (size_t i = 0; i < p->nmarks; i++)
        if (p->marks[i].panel == k)
            return true;
    return false;
}

/* A series whose x never decreases is a graph over x (a time axis): its x
 * range is drawn exactly.  Others (a phase loop, dots) need room. */
static bool graph(const qd__plot_series *s) {
    if (s->style != QD_PLOT_LINE)
        return false;
    for (size_t k = 1; k < s->n; k++)
        if (s->x[k] < s->x[k - 1])
            return false;
    return true;
}

/* The range of axis values of every series (x when !want_y), and whether
 * any series needs padding along x. */
static void data_range(const qd_plot *p, size_t k, bool want_y, double *lo, double *hi,
                       bool *points) {
    *lo = INFINITY;
    *hi = -INFINITY;
    *points = false;
    for (size_t i = 0; i < p->nseries; i++) {
        const qd__plot_series *s = &p->series[i];
        if (s->panel != k)
            continue;
        const double *v = want_y ? s->y : s->x;
        *points |= !graph(s);
        for (size_t k = 0; k < s->n; k++) {
            *lo = fmin(*lo, v[k]);
            *hi = fmax(*hi, v[k]);
        }
    }
    qd__plot_marks_range(p, k, want_y, lo, hi);
    *points |= panel_marks(p, k);
}

/* An axis over [lo, hi]: a constant is widened around itself; padded by
 * 5% each side when pad; then taken out to the ticks around it when that
 * costs at most 10% of the span (so the frame starts and ends on a tick). */
static void axis_range(double lo, double hi, bool pad, size_t max_ticks, double *a, double *b) {
    if (!(hi - lo > 1e-12 * fmax(fabs(lo), fabs(hi)))) {
        double w = fabs(lo) > 0 ? 0.1 * fabs(lo) : 1;
        lo -= w;
        hi += w;
    } else if (pad) {
        double w = 0.05 * (hi - lo);
        lo -= w;
        hi += w;
    }
    double step, first;
    if (qd_plot_nice_ticks(lo, hi, max_ticks, &step, &first)) {
        double l = floor(lo / step + 1e-9) * step, h = ceil(hi / step - 1e-9) * step;
        if (h - l <= 1.1 * (hi - lo)) {
            lo = l;
            hi = h;
        }
    }
    *a = lo;
    *b = hi;
}

/* One data unit per as many pixels on both axes: the range with fewer
 * pixels per unit stays, the other is widened about its middle. */
static void widen(double *a, double *b, double span) {
    double mid = 0.5 * (*a + *b);
    *a = mid - 0.5 * span;
    *b = mid + 0.5 * span;
}

static void equalize(qd__plot_panel *f) {
    double ux = (f->x1 - f->x0) / f->width, uy = (f->y1 - f->y0) / f->height;
    if (ux > uy)
        widen(&f->y0, &f->y1, ux * f->height);
    else
        widen(&f->x0, &f->x1, uy * f->width);
}

/* A map's axes span its cells exactly, series included: the cells are the
 * data, and a margin of white around them would read as missing runs. */
static void map_ranges(const qd_plot *p, size_t k, qd__plot_panel *f) {
    const qd__plot_map *m = f->map;
    double lo, hi, a, b;
    bool points;
    qd__plot_map_edges(m->nx, m->x, 0, &f->x0, &b);
    qd__plot_map_edges(m->nx, m->x, m->nx - 1, &a, &f->x1);
    qd__plot_map_edges(m->ny, m->y, 0, &f->y0, &b);
    qd__plot_map_edges(m->ny, m->y, m->ny - 1, &a, &f->y1);
    if (!f->nseries)
        return;
    data_range(p, k, false, &lo, &hi, &points);
    f->x0 = fmin(f->x0, lo);
    f->x1 = fmax(f->x1, hi);
    data_range(p, k, true, &lo, &hi, &points);
    f->y0 = fmin(f->y0, lo);
    f->y1 = fmax(f->y1, hi);
}

/* Panel k in its cell of the grid (below the title): the ranges, the
 * legend's rows and the plot area.  An empty panel shows [0, 1]. */
static qd_status layout_panel(qd_plot *p, size_t k, double cell_top, double cell_h) {
    qd__plot_panel *f = &p->panels[k];
    double lo, hi, cell_w = (double)p->width / (double)p->cols;
    bool points, any = f->nseries || panel_marks(p, k);
    if (f->map) {
        map_ranges(p, k, f);
    } else {
        data_range(p, k, false, &lo, &hi, &points);
        axis_range(any ? lo : 0, any ? hi : 1, points, 10, &f->x0, &f->x1);
        data_range(p, k, true, &lo, &hi, &points);
        axis_range(any ? lo : 0, any ? hi : 1, true, 8, &f->y0, &f->y1);
    }
    bool ylab = f->ylabel && *f->ylabel, xlab = f->xlabel && *f->xlabel;
    f->left = cell_w * (double)(k % p->cols) + (ylab ? 84 : 64);
    f->width = cell_w - (ylab ? 84 : 64) - 24 - (f->map ? QD__PLOT_BAR_ROOM : 0);
    f->legend_top = cell_top + 4;
    f->legend_rows = p->shared_legend ? 0 : qd__plot_legend_rows(p, k, f->width, NULL, NULL);
    f->top = f->legend_top + (double)(f->legend_rows + (f->heading ? 1 : 0)) *
                                 QD__PLOT_LEGEND_ROW + 8;
    f->height = cell_top + cell_h - f->top - (xlab ? 52 : 32);
    if (f->width < 50 || f->height < 50) {
        qd_ctx_error(p->ctx, QD_ERR_ARG, "no room to plot in %d x %d with %zu x %zu panels "
                     "(the legend takes %zu rows)", p->width, p->height, p->rows, p->cols,
                     f->legend_rows);
        return QD_ERR_ARG;
    }
    if (f->equal)
        equalize(f);
    return QD_OK;
}

qd_status qd_plot_layout(qd_plot *p) {
    QD_ARGS(QD_ERR_ARG, p);
    bool any_map = false;
    for (size_t k = 0; k < p->rows * p->cols; k++)
        any_map |= p->panels[k].map != NULL;
    if (p->nseries == 0 && !any_map && !p->nmarks) {
        qd_ctx_error(p->ctx, QD_ERR_ARG, "a plot needs at least one series of points");
        return QD_ERR_ARG;
    }
    /* the legend's widths are the font's: the drawing module measures them */
    if (!p->canvas && !(p->canvas = qd__plot_canvas(p->ctx)))
        return QD_ERR_UNSUPPORTED;
    double top = p->title && *p->title ? 32 : 8;
    p->shared_rows = p->shared_legend ? qd__plot_legend_rows(p, QD__PLOT_ANY_PANEL,
                                                             (double)p->width - 48, NULL, NULL)
                                      : 0;
    top += (double)p->shared_rows * QD__PLOT_LEGEND_ROW;
    double cell_h = ((double)p->height - top) / (double)p->rows;
    for (size_t k = 0; k < p->rows * p->cols; k++) {
        qd_status st = layout_panel(p, k, top + cell_h * (double)(k / p->cols), cell_h);
        if (st != QD_OK)
            return st;
    }
    p->laid_out = true;
    return QD_OK;
}

bool qd_plot_to_pixel(const qd_plot *p, size_t panel, double x, double y, double *px,
                      double *py) {
    QD_ARGS(false, p && px && py);
    if (!p->laid_out || panel >= p->rows * p->cols)
        return false;
    const qd__plot_panel *f = &p->panels[panel];
    *px = f->left + (x - f->x0) / (f->x1 - f->x0) * f->width;
    *py = f->top + f->height - (y - f->y0) / (f->y1 - f->y0) * f->height;
    return true;
}

bool qd_plot_ranges(const qd_plot *p, size_t panel, double *x0, double *x1, double *y0,
                    double *y1) {
    QD_ARGS(false, p && x0 && x1 && y0 && y1);
    if (!p->laid_out || panel >= p->rows * p->cols)
        return false;
    const qd__plot_panel *f = &p->panels[panel];
    *x0 = f->x0;
    *x1 = f->x1;
    *y0 = f->y0;
    *y1 = f->y1;
    return true;
}

size_t qd__plot_legend_rows(const qd_plot *p, size_t k, double width, size_t *row, double *xoff) {
    size_t rows = 0;
    double x = 0;
    for (size_t i = 0; i < p->nseries; i++) {
        const char *label = p->series[i].label;
        if (!*label || (k == QD__PLOT_ANY_PANEL ? !qd__plot_legend_first(p, i)
                                                : p->series[i].panel != k))
            continue;
        double w = QD__PLOT_SWATCH + 6 + qd__plot_text_width(p, label, QD__PLOT_TICK_FONT) + 18;
        if (rows == 0 || (x > 0 && x + w > width)) {
            rows++;
            x = 0;
        }
        if (row)
            row[i] = rows - 1;
        if (xoff)
            xoff[i] = x;
        x += w;
    }
    return rows;
}
