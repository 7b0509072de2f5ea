/*
 * src/plot/draw.c - a laid-out plot drawn with Cairo, written as PNG, SVG
 * or PDF through a stream this file opens, so an unwritable file is a clean
 * error naming it rather than a Cairo status.
 */
#include "plot_priv.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <cairo.h>
#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

static const double PI = 3.14159265358979323846;

static void set_rgb(cairo_t *cr, unsigned rgb) {
    cairo_set_source_rgb(cr, ((rgb >> 16) & 255) / 255.0, ((rgb >> 8) & 255) / 255.0,
                         (rgb & 255) / 255.0);
}

static void use_font(cairo_t *cr, double size, bool bold) {
    cairo_select_font_face(cr, QD__PLOT_FONT, CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
}

double qd__plot_text_width(const char *text, double size) {
    cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 1, 1);
    cairo_t *cr = cairo_create(s);
    use_font(cr, size, false);
    cairo_text_extents_t e;
    cairo_text_extents(cr, text, &e);
    cairo_destroy(cr);
    cairo_surface_destroy(s);
    return e.x_advance;
}

/* text with its anchor at (x, y): ax 0 left, 0.5 centre, 1 right of the
 * text; ay likewise from the top (0) to the bottom (1) of its ink. */
static void text_at(cairo_t *cr, const char *text, double x, double y, double ax, double ay) {
    cairo_text_extents_t e;
    cairo_text_extents(cr, text, &e);
    cairo_move_to(cr, x - e.x_bearing - ax * e.width, y - e.y_bearing - ay * e.height);
    cairo_show_text(cr, text);
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

static void draw_xticks(const qd_plot *p, size_t k, cairo_t *cr) {
    const qd__plot_panel *f = &p->panels[k];
    double step, first, px, py;
    size_t n = qd_plot_nice_ticks(f->x0, f->x1, 10, &step, &first);
    double bottom = f->top + f->height;
    for (size_t t = 0; t < n; t++) {
        double v = first + (double)t * step;
        qd_plot_to_pixel(p, k, v, f->y0, &px, &py);
        cairo_move_to(cr, px, bottom);
        cairo_line_to(cr, px, bottom + 5);
        cairo_stroke(cr);
        char buf[32];
        tick_label(buf, sizeof buf, v, step);
        text_at(cr, buf, px, bottom + 8, 0.5, 0);
    }
}

static void draw_yticks(const qd_plot *p, size_t k, cairo_t *cr) {
    const qd__plot_panel *f = &p->panels[k];
    double step, first, px, py;
    size_t n = qd_plot_nice_ticks(f->y0, f->y1, 8, &step, &first);
    for (size_t t = 0; t < n; t++) {
        double v = first + (double)t * step;
        qd_plot_to_pixel(p, k, f->x0, v, &px, &py);
        cairo_move_to(cr, f->left - 5, py);
        cairo_line_to(cr, f->left, py);
        cairo_stroke(cr);
        char buf[32];
        tick_label(buf, sizeof buf, v, step);
        text_at(cr, buf, f->left - 8, py, 1, 0.5);
    }
}

static void draw_axes(const qd_plot *p, size_t k, cairo_t *cr) {
    const qd__plot_panel *f = &p->panels[k];
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 1);
    /* on the half pixel: a 1 px line is then one crisp row of pixels */
    cairo_rectangle(cr, floor(f->left) - 0.5, floor(f->top) - 0.5, ceil(f->width) + 1,
                    ceil(f->height) + 1);
    cairo_stroke(cr);
    use_font(cr, QD__PLOT_TICK_FONT, false);
    draw_xticks(p, k, cr);
    draw_yticks(p, k, cr);
    use_font(cr, QD__PLOT_LABEL_FONT, false);
    if (f->xlabel && *f->xlabel)
        text_at(cr, f->xlabel, f->left + f->width / 2, f->top + f->height + 44, 0.5, 1);
    if (f->ylabel && *f->ylabel) {
        cairo_save(cr);
        cairo_translate(cr, f->left - 68, f->top + f->height / 2);
        cairo_rotate(cr, -PI / 2);
        text_at(cr, f->ylabel, 0, 0, 0.5, 0.5);
        cairo_restore(cr);
    }
}

static void draw_series(const qd_plot *p, cairo_t *cr, const qd__plot_series *s, unsigned rgb) {
    size_t pan = s->panel;
    double px, py;
    set_rgb(cr, rgb);
    if (s->style == QD_PLOT_POINTS) {
        for (size_t k = 0; k < s->n; k++) {
            qd_plot_to_pixel(p, pan, s->x[k], s->y[k], &px, &py);
            cairo_new_sub_path(cr);
            cairo_arc(cr, px, py, 2.5, 0, 2 * PI);
        }
        cairo_fill(cr);
        return;
    }
    if (s->style == QD_PLOT_LINE_POINTS)
        for (size_t k = 0; k < s->n; k++) {
            qd_plot_to_pixel(p, pan, s->x[k], s->y[k], &px, &py);
            cairo_new_sub_path(cr);
            cairo_arc(cr, px, py, 4, 0, 2 * PI);
            cairo_fill(cr);
        }
    cairo_set_line_width(cr, 2);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    for (size_t k = 0; k < s->n; k++) {
        qd_plot_to_pixel(p, pan, s->x[k], s->y[k], &px, &py);
        if (k)
            cairo_line_to(cr, px, py);
        else
            cairo_move_to(cr, px, py);
    }
    if (s->n == 1)
        cairo_line_to(cr, px, py); /* a round cap: a dot */
    cairo_stroke(cr);
}

/* The map's cells, unantialiased: neighbouring cells then meet without a
 * seam of background between them. */
static void draw_map(const qd_plot *p, size_t k, cairo_t *cr) {
    const qd__plot_map *m = p->panels[k].map;
    double span = m->zmax - m->zmin;
    cairo_save(cr);
    cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
    for (size_t j = 0; j < m->ny; j++)
        for (size_t i = 0; i < m->nx; i++) {
            double x0, x1, y0, y1, ax, ay, bx, by, z = m->z[j * m->nx + i];
            qd__plot_map_edges(m->nx, m->x, i, &x0, &x1);
            qd__plot_map_edges(m->ny, m->y, j, &y0, &y1);
            qd_plot_to_pixel(p, k, x0, y0, &ax, &ay);
            qd_plot_to_pixel(p, k, x1, y1, &bx, &by);
            set_rgb(cr, isnan(z) ? 0xd9d9d9
                                 : qd_plot_map_color(span > 0 ? (z - m->zmin) / span : 0.5));
            cairo_rectangle(cr, round(ax), round(by), round(bx) - round(ax), round(ay) - round(by));
            cairo_fill(cr);
        }
    cairo_restore(cr);
}

/* The colour bar at the panel's right: the scale from the least value
 * (bottom) to the greatest, its ticks and the map's label beside it. */
static void draw_bar(const qd_plot *p, size_t k, cairo_t *cr) {
    const qd__plot_panel *f = &p->panels[k];
    const qd__plot_map *m = f->map;
    double left = f->left + f->width + 16, w = 18, top = f->top, h = f->height;
    for (int r = 0; r < (int)h; r++) {
        set_rgb(cr, qd_plot_map_color(1 - (r + 0.5) / h));
        cairo_rectangle(cr, left, top + r, w, 1);
        cairo_fill(cr);
    }
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 1);
    cairo_rectangle(cr, floor(left) - 0.5, floor(top) - 0.5, w + 1, ceil(h) + 1);
    cairo_stroke(cr);
    double step, first, lo = m->zmin, hi = m->zmax;
    use_font(cr, QD__PLOT_TICK_FONT, false);
    size_t n = isnan(lo) || !(hi > lo) ? 0 : qd_plot_nice_ticks(lo, hi, 8, &step, &first);
    for (size_t t = 0; t < n; t++) {
        double v = first + (double)t * step, py = top + h - (v - lo) / (hi - lo) * h;
        cairo_move_to(cr, left + w, py);
        cairo_line_to(cr, left + w + 4, py);
        cairo_stroke(cr);
        char buf[32];
        tick_label(buf, sizeof buf, v, step);
        text_at(cr, buf, left + w + 7, py, 0, 0.5);
    }
    if (*m->label) {
        use_font(cr, QD__PLOT_LABEL_FONT, false);
        cairo_save(cr);
        cairo_translate(cr, left + w + 58, top + h / 2);
        cairo_rotate(cr, -PI / 2);
        text_at(cr, m->label, 0, 0, 0.5, 0.5);
        cairo_restore(cr);
    }
}

static void draw_data(const qd_plot *p, size_t k, cairo_t *cr) {
    const qd__plot_panel *f = &p->panels[k];
    cairo_save(cr);
    cairo_rectangle(cr, f->left, f->top, f->width, f->height);
    cairo_clip(cr);
    if (f->map)
        draw_map(p, k, cr);
    for (size_t i = 0; i < p->nseries; i++)
        if (p->series[i].panel == k)
            draw_series(p, cr, &p->series[i], qd_plot_color(p, i));
    cairo_restore(cr);
}

static void draw_legend(const qd_plot *p, size_t k, cairo_t *cr, size_t *row, double *xoff) {
    const qd__plot_panel *f = &p->panels[k];
    qd__plot_legend_rows(p, k, f->width, row, xoff);
    use_font(cr, QD__PLOT_TICK_FONT, false);
    for (size_t i = 0; i < p->nseries; i++) {
        const qd__plot_series *s = &p->series[i];
        if (!*s->label || s->panel != k)
            continue;
        double x = f->left + xoff[i], y = f->legend_top + ((double)row[i] + 0.5) * QD__PLOT_LEGEND_ROW;
        set_rgb(cr, qd_plot_color(p, i));
        if (s->style == QD_PLOT_POINTS) {
            cairo_arc(cr, x + QD__PLOT_SWATCH / 2, y, 3, 0, 2 * PI);
            cairo_fill(cr);
        } else {
            cairo_set_line_width(cr, 2);
            cairo_move_to(cr, x, y);
            cairo_line_to(cr, x + QD__PLOT_SWATCH, y);
            cairo_stroke(cr);
        }
        cairo_set_source_rgb(cr, 0, 0, 0);
        text_at(cr, s->label, x + QD__PLOT_SWATCH + 6, y, 0, 0.5);
    }
}

static qd_status draw(const qd_plot *p, cairo_t *cr) {
    size_t *row = qd__calloc(p->ctx, p->nseries, sizeof *row);
    double *xoff = qd__calloc(p->ctx, p->nseries, sizeof *xoff);
    if (!row || !xoff) {
        qd__free(row);
        qd__free(xoff);
        return QD_ERR_NOMEM;
    }
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    for (size_t k = 0; k < p->rows * p->cols; k++) {
        if (!p->panels[k].nseries && !p->panels[k].map)
            continue; /* the grid's unused cells stay blank */
        draw_data(p, k, cr);
        draw_axes(p, k, cr);
        if (p->panels[k].map)
            draw_bar(p, k, cr);
        draw_legend(p, k, cr, row, xoff);
    }
    if (p->title && *p->title) {
        cairo_set_source_rgb(cr, 0, 0, 0);
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

static cairo_status_t to_file(void *closure, const unsigned char *data, unsigned int length) {
    plot_out *o = closure;
    errno = 0;
    if (fwrite(data, 1, length, o->f) == length)
        return CAIRO_STATUS_SUCCESS;
    if (!o->err)
        o->err = errno ? errno : EIO;
    return CAIRO_STATUS_WRITE_ERROR;
}

static cairo_surface_t *open_surface(const qd_plot *p, qd_plot_format fmt, plot_out *out) {
    switch (fmt) {
    case QD_PLOT_SVG:
        return cairo_svg_surface_create_for_stream(to_file, out, p->width, p->height);
    case QD_PLOT_PDF:
        return cairo_pdf_surface_create_for_stream(to_file, out, p->width, p->height);
    default:
        return cairo_image_surface_create(CAIRO_FORMAT_RGB24, p->width, p->height);
    }
}

/* Draw onto a surface of the format and finish it into out. */
static qd_status render(const qd_plot *p, qd_plot_format fmt, plot_out *out) {
    cairo_surface_t *s = open_surface(p, fmt, out);
    cairo_t *cr = cairo_create(s);
    qd_status st = draw(p, cr);
    cairo_status_t cs = cairo_status(cr);
    cairo_destroy(cr);
    if (st == QD_OK && cs == CAIRO_STATUS_SUCCESS && fmt == QD_PLOT_PNG)
        cs = cairo_surface_write_to_png_stream(s, to_file, out);
    cairo_surface_finish(s); /* SVG and PDF write here */
    if (cs == CAIRO_STATUS_SUCCESS)
        cs = cairo_surface_status(s);
    cairo_surface_destroy(s);
    if (st == QD_OK && cs != CAIRO_STATUS_SUCCESS && !out->err) {
        qd_ctx_error(p->ctx, QD_ERR_NUMERIC, "drawing the plot failed: %s",
                     cairo_status_to_string(cs));
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
