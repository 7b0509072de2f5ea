/*
 * src/plot/draw.c - a laid-out plot painted through the canvas of
 * src/plot/canvas.h (Cairo, in the module qdot_cairo.so), written as PNG,
 * SVG or PDF through a stream this file opens, so an unwritable file is a
 * clean error naming it rather than a drawing library's status.
 */
#include "plot_priv.h"
#include "../base/mem.h"
#include "../base/args.h"
#include "../base/module.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

static const double PI = 3.14159265358979323846;

const qd__canvas_ops *qd__plot_canvas(qd_ctx *ctx) {
    void *h = qd__module_open(ctx, "cairo", 0, QD__CANVAS_ABI, "Cairo", "libcairo2-dev");
    qd__canvas_ops_fn ops = NULL;
    if (!h || !qd__module_fn(ctx, h, "qdot_cairo.so", "qd_ext_cairo_ops", &ops, sizeof ops))
        return NULL;
    return ops();
}

double qd__plot_text_width(const qd_plot *p, const char *text, double size) {
    char m[QD__PLOT_TEXT_MAX];
    qd__plot_plain_math(text, m, sizeof m, NULL, NULL);
    return p->canvas->text_width(QD__PLOT_FONT, m, size);
}

static void use_font(const pen *cr, double size, bool bold) {
    cr->op->font(cr->cv, QD__PLOT_FONT, size, bold);
}

/* Every text is drawn as mathematics (qd__plot_math_at, text.c). */
static void text_at(const pen *cr, const char *text, double x, double y, double ax, double ay) {
    qd__plot_math_at(cr, text, x, y, ax, ay);
}

/* A tick value with the decimals its step needs, -0 printed as 0. */
static void tick_label(char *buf, size_t cap, double v, double step) {
    if (fabs(v) < 1e-9 * step)
        v = 0;
    double mag = fmax(fabs(v), step);
    if (mag >= 1e5 || step < 1e-4) {
        snprintf(buf, cap, "%.3g", v);
        return;
    }
    int dec = step >= 1 ? 0 : (int)ceil(-log10(step) - 1e-9);
    snprintf(buf, cap, "%.*f", dec, v);
}

static void draw_xticks(const qd_plot *p, size_t k, const pen *cr) {
    const qd__plot_panel *f = &p->panels[k];
    double step, first, px, py;
    size_t n = qd_plot_nice_ticks(f->x0, f->x1, 10, &step, &first);
    double bottom = f->top + f->height;
    for (size_t t = 0; t < n; t++) {
        double v = first + (double)t * step;
        qd_plot_to_pixel(p, k, v, f->y0, &px, &py);
        cr->op->move_to(cr->cv, px, bottom);
        cr->op->line_to(cr->cv, px, bottom + 5);
        cr->op->stroke(cr->cv);
        char buf[32];
        tick_label(buf, sizeof buf, v, step);
        text_at(cr, buf, px, bottom + 8, 0.5, 0);
    }
}

static void draw_yticks(const qd_plot *p, size_t k, const pen *cr) {
    const qd__plot_panel *f = &p->panels[k];
    double step, first, px, py;
    size_t n = qd_plot_nice_ticks(f->y0, f->y1, 8, &step, &first);
    for (size_t t = 0; t < n; t++) {
        double v = first + (double)t * step;
        qd_plot_to_pixel(p, k, f->x0, v, &px, &py);
        cr->op->move_to(cr->cv, f->left - 5, py);
        cr->op->line_to(cr->cv, f->left, py);
        cr->op->stroke(cr->cv);
        char buf[32];
        tick_label(buf, sizeof buf, v, step);
        text_at(cr, buf, f->left - 8, py, 1, 0.5);
    }
}

static void draw_axes(const qd_plot *p, size_t k, const pen *cr) {
    const qd__plot_panel *f = &p->panels[k];
    cr->op->rgb(cr->cv, 0x000000);
    cr->op->line_width(cr->cv, 1);
    /* on the half pixel: a 1 px line is then one crisp row of pixels */
    cr->op->rect(cr->cv, floor(f->left) - 0.5, floor(f->top) - 0.5, ceil(f->width) + 1,
                    ceil(f->height) + 1);
    cr->op->stroke(cr->cv);
    use_font(cr, QD__PLOT_TICK_FONT, false);
    draw_xticks(p, k, cr);
    draw_yticks(p, k, cr);
    use_font(cr, QD__PLOT_LABEL_FONT, false);
    if (f->xlabel && *f->xlabel)
        text_at(cr, f->xlabel, f->left + f->width / 2, f->top + f->height + 44, 0.5, 1);
    if (f->ylabel && *f->ylabel) {
        cr->op->save(cr->cv);
        cr->op->translate(cr->cv, f->left - 68, f->top + f->height / 2);
        cr->op->rotate(cr->cv, -PI / 2);
        text_at(cr, f->ylabel, 0, 0, 0.5, 0.5);
        cr->op->restore(cr->cv);
    }
}

static void draw_series(const qd_plot *p, const pen *cr, const qd__plot_series *s, unsigned rgb) {
    size_t pan = s->panel;
    double px, py;
    cr->op->rgb(cr->cv, rgb);
    /* a section of many crossings in finer dots, so its structure shows
     * rather than a blot: 2.5 px up to 500 points, then as 1/sqrt(n) */
    double dot = p->point_size > 0 ? p->point_size
                                    : fmax(0.8, fmin(2.5, 2.5 * sqrt(500.0 / (double)s->n)));
    if (s->style == QD_PLOT_POINTS || s->style == QD_PLOT_DOTS) {
        for (size_t k = 0; k < s->n; k++) {
            qd_plot_to_pixel(p, pan, s->x[k], s->y[k], &px, &py);
            cr->op->circle(cr->cv, px, py, s->style == QD_PLOT_DOTS ? 5 : dot);
        }
        cr->op->fill(cr->cv);
        return;
    }
    if (s->style == QD_PLOT_LINE_POINTS)
        for (size_t k = 0; k < s->n; k++) {
            qd_plot_to_pixel(p, pan, s->x[k], s->y[k], &px, &py);
            cr->op->circle(cr->cv, px, py, 4);
            cr->op->fill(cr->cv);
        }
    cr->op->line_width(cr->cv, 2);
    cr->op->round_ends(cr->cv);
    for (size_t k = 0; k < s->n; k++) {
        qd_plot_to_pixel(p, pan, s->x[k], s->y[k], &px, &py);
        if (k)
            cr->op->line_to(cr->cv, px, py);
        else
            cr->op->move_to(cr->cv, px, py);
    }
    if (s->n == 1)
        cr->op->line_to(cr->cv, px, py); /* a round cap: a dot */
    cr->op->stroke(cr->cv);
}

/* The map's cells, unantialiased: neighbouring cells then meet without a
 * seam of background between them. */
static void draw_map(const qd_plot *p, size_t k, const pen *cr) {
    const qd__plot_map *m = p->panels[k].map;
    double span = m->zmax - m->zmin;
    cr->op->save(cr->cv);
    cr->op->antialias(cr->cv, false);
    for (size_t j = 0; j < m->ny; j++)
        for (size_t i = 0; i < m->nx; i++) {
            double x0, x1, y0, y1, ax, ay, bx, by, z = m->z[j * m->nx + i];
            qd__plot_map_edges(m->nx, m->x, i, &x0, &x1);
            qd__plot_map_edges(m->ny, m->y, j, &y0, &y1);
            qd_plot_to_pixel(p, k, x0, y0, &ax, &ay);
            qd_plot_to_pixel(p, k, x1, y1, &bx, &by);
            cr->op->rgb(cr->cv, isnan(z) ? 0xd9d9d9
                                 : qd_plot_map_color(span > 0 ? (z - m->zmin) / span : 0.5));
            cr->op->rect(cr->cv, round(ax), round(by), round(bx) - round(ax), round(ay) - round(by));
            cr->op->fill(cr->cv);
        }
    cr->op->restore(cr->cv);
}

/* The colour bar at the panel's right: the scale from the least value
 * (bottom) to the greatest, its ticks and the map's label beside it. */
static void draw_bar(const qd_plot *p, size_t k, const pen *cr) {
    const qd__plot_panel *f = &p->panels[k];
    const qd__plot_map *m = f->map;
    double left = f->left + f->width + 16, w = 18, top = f->top, h = f->height;
    for (int r = 0; r < (int)h; r++) {
        cr->op->rgb(cr->cv, qd_plot_map_color(1 - (r + 0.5) / h));
        cr->op->rect(cr->cv, left, top + r, w, 1);
        cr->op->fill(cr->cv);
    }
    cr->op->rgb(cr->cv, 0x000000);
    cr->op->line_width(cr->cv, 1);
    cr->op->rect(cr->cv, floor(left) - 0.5, floor(top) - 0.5, w + 1, ceil(h) + 1);
    cr->op->stroke(cr->cv);
    double step, first, lo = m->zmin, hi = m->zmax;
    use_font(cr, QD__PLOT_TICK_FONT, false);
    size_t n = isnan(lo) || !(hi > lo) ? 0 : qd_plot_nice_ticks(lo, hi, 8, &step, &first);
    for (size_t t = 0; t < n; t++) {
        double v = first + (double)t * step, py = top + h - (v - lo) / (hi - lo) * h;
        cr->op->move_to(cr->cv, left + w, py);
        cr->op->line_to(cr->cv, left + w + 4, py);
        cr->op->stroke(cr->cv);
        char buf[32];
        tick_label(buf, sizeof buf, v, step);
        text_at(cr, buf, left + w + 7, py, 0, 0.5);
    }
    if (*m->label) {
        use_font(cr, QD__PLOT_LABEL_FONT, false);
        cr->op->save(cr->cv);
        cr->op->translate(cr->cv, left + w + 58, top + h / 2);
        cr->op->rotate(cr->cv, -PI / 2);
        text_at(cr, m->label, 0, 0, 0.5, 0.5);
        cr->op->restore(cr->cv);
    }
}

static void draw_data(const qd_plot *p, size_t k, const pen *cr) {
    const qd__plot_panel *f = &p->panels[k];
    cr->op->save(cr->cv);
    cr->op->rect(cr->cv, f->left, f->top, f->width, f->height);
    cr->op->clip(cr->cv);
    if (f->map)
        draw_map(p, k, cr);
    qd__plot_draw_marks(p, k, cr);
    for (size_t i = 0; i < p->nseries; i++)
        if (p->series[i].panel == k)
            draw_series(p, cr, &p->series[i], qd_plot_color(p, i));
    if (f->note) {
        cr->op->rgb(cr->cv, 0x000000);
        use_font(cr, QD__PLOT_LABEL_FONT, true);
        text_at(cr, f->note, f->left + 8, f->top + 8, 0, 0);
    }
    cr->op->restore(cr->cv);
}

/* The legend of panel k over its area, or (k QD__PLOT_ANY_PANEL) the
 * plot's shared one under the title. */
static void draw_legend(const qd_plot *p, size_t k, const pen *cr, size_t *row, double *xoff) {
    bool all = k == QD__PLOT_ANY_PANEL;
    const qd__plot_panel *f = all ? NULL : &p->panels[k];
    double left = all ? 24 : f->left, top = all ? (p->title && *p->title ? 32 : 8) : f->legend_top;
    qd__plot_legend_rows(p, k, all ? (double)p->width - 48 : f->width, row, xoff);
    use_font(cr, QD__PLOT_TICK_FONT, false);
    for (size_t i = 0; i < p->nseries; i++) {
        const qd__plot_series *s = &p->series[i];
        if (!*s->label || (all ? !qd__plot_legend_first(p, i) : s->panel != k))
            continue;
        double x = left + xoff[i], y = top + ((double)row[i] + 0.5) * QD__PLOT_LEGEND_ROW;
        cr->op->rgb(cr->cv, qd_plot_color(p, i));
        if (s->style != QD_PLOT_LINE) {
            cr->op->circle(cr->cv, x + QD__PLOT_SWATCH / 2, y, s->style == QD_PLOT_POINTS ? 3 : 4);
            cr->op->fill(cr->cv);
        }
        if (s->style == QD_PLOT_LINE || s->style == QD_PLOT_LINE_POINTS) {
            cr->op->line_width(cr->cv, 2);
            cr->op->move_to(cr->cv, x, y);
            cr->op->line_to(cr->cv, x + QD__PLOT_SWATCH, y);
            cr->op->stroke(cr->cv);
        }
        cr->op->rgb(cr->cv, 0x000000);
        text_at(cr, s->label, x + QD__PLOT_SWATCH + 6, y, 0, 0.5);
    }
}

static bool has_marks(const qd_plot *p, size_t k) {
    for (size_t i = 0; i < p->nmarks; i++)
        if (p->marks[i].panel == k)
            return true;
    return false;
}

static qd_status draw(const qd_plot *p, const pen *cr) {
    size_t *row = qd__calloc(p->ctx, p->nseries, sizeof *row);
    double *xoff = qd__calloc(p->ctx, p->nseries, sizeof *xoff);
    if (!row || !xoff) {
        qd__free(row);
        qd__free(xoff);
        return QD_ERR_NOMEM;
    }
    cr->op->rgb(cr->cv, 0xffffff);
    cr->op->paint(cr->cv);
    for (size_t k = 0; k < p->rows * p->cols; k++) {
        const qd__plot_panel *f = &p->panels[k];
        if (!f->nseries && !f->map && !f->heading && !f->note && !has_marks(p, k))
            continue; /* the grid's unused cells stay blank */
        draw_data(p, k, cr);
        draw_axes(p, k, cr);
        if (f->map)
            draw_bar(p, k, cr);
        if (!p->shared_legend)
            draw_legend(p, k, cr, row, xoff);
        if (f->heading) {
            cr->op->rgb(cr->cv, 0x000000);
            use_font(cr, QD__PLOT_LABEL_FONT, false);
            text_at(cr, f->heading, f->left + f->width / 2,
                    f->legend_top + ((double)f->legend_rows + 0.5) * QD__PLOT_LEGEND_ROW, 0.5,
                    0.5);
        }
    }
    if (p->shared_legend)
        draw_legend(p, QD__PLOT_ANY_PANEL, cr, row, xoff);
    if (p->title && *p->title) {
        cr->op->rgb(cr->cv, 0x000000);
        use_font(cr, QD__PLOT_TITLE_FONT, true);
        text_at(cr, p->title, p->width / 2.0, 10, 0.5, 0);
    }
    qd__free(row);
    qd__free(xoff);
    return QD_OK;
}

/* The file a plot is written into, and the errno of its first failed write. */
typedef struct plot_out {
    FILE *f;
    int err;
} plot_out;

static bool to_file(void *closure, const unsigned char *data, size_t length) {
    plot_out *o = closure;
    errno = 0;
    if (fwrite(data, 1, length, o->f) == length)
        return true;
    if (!o->err)
        o->err = errno ? errno : EIO;
    return false;
}

/* Draw onto a surface of the format and finish it into out. */
static qd_status render(const qd_plot *p, qd_plot_format fmt, plot_out *out) {
    int format = fmt == QD_PLOT_SVG ? QD__CANVAS_SVG : fmt == QD_PLOT_PDF ? QD__CANVAS_PDF
                                                                          : QD__CANVAS_PNG;
    /* --dpi: a PNG drawn larger, everything with it; vector formats are in points */
    double zoom = format == QD__CANVAS_PNG ? p->dpi / 96 : 1;
    int w = (int)lround(p->width * zoom), h = (int)lround(p->height * zoom);
    pen cr = {p->canvas, p->canvas->open(format, w, h, to_file, out)};
    if (!cr.cv) {
        qd_ctx_error(p->ctx, QD_ERR_NOMEM, "out of memory for the plot's surface");
        return QD_ERR_NOMEM;
    }
    if (zoom != 1)
        cr.op->scale(cr.cv, zoom);
    qd_status st = draw(p, &cr);
    const char *why = cr.op->close(cr.cv);
    if (st == QD_OK && why && !out->err) {
        qd_ctx_error(p->ctx, QD_ERR_NUMERIC, "drawing the plot failed: %s", why);
        st = QD_ERR_NUMERIC;
    }
    return st;
}

qd_status qd_plot_write(qd_plot *p, const char *path) {
    QD_ARGS(QD_ERR_ARG, p && path);
    qd_plot_format fmt;
    qd_status st = qd_plot_format_of(p->ctx, path, &fmt);
    if (st == QD_OK)
        st = qd_plot_layout(p);
    if (st != QD_OK)
        return st;
    FILE *f = fopen(path, "wb");
    if (!f) {
        qd_ctx_error(p->ctx, QD_ERR_ARG, "cannot write %s: %s", path, strerror(errno));
        return QD_ERR_ARG;
    }
    plot_out out = {.f = f};
    st = render(p, fmt, &out);
    errno = 0;
    if (fflush(f) != 0 && !out.err)
        out.err = errno ? errno : EIO;
    errno = 0;
    if (fclose(f) != 0 && !out.err)
        out.err = errno ? errno : EIO;
    if (out.err && st == QD_OK) {
        /* the disk's failure, not the input's (exit 1 in the CLI) */
        qd_ctx_error(p->ctx, QD_ERR_IO, "cannot write %s: %s", path, strerror(out.err));
        st = QD_ERR_IO;
    }
    return st;
}
