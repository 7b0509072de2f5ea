/*
 * modules/cairo.c - qdot_cairo.so: the drawing primitives of
 * src/plot/canvas.h over Cairo, for PNG, SVG and PDF.  libqdot opens it
 * only when a plot is laid out or written; this file calls nothing of
 * libqdot's.
 */
#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>
#include <stdlib.h>

#include "plot/canvas.h"

unsigned qd_ext_cairo_abi(void);
const qd__canvas_ops *qd_ext_cairo_ops(void);

unsigned qd_ext_cairo_abi(void) { return QD__CANVAS_ABI; }

typedef struct canvas {
    cairo_surface_t *s;
    cairo_t *cr;
    int format;
    qd__canvas_write write;
    void *closure;
} canvas;

static cairo_status_t to_stream(void *closure, const unsigned char *data, unsigned int n) {
    canvas *c = closure;
    return c->write(c->closure, data, n) ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

static void *open_canvas(int format, int w, int h, qd__canvas_write write, void *closure) {
    canvas *c = calloc(1, sizeof *c);
    if (!c)
        return NULL;
    *c = (canvas){.format = format, .write = write, .closure = closure};
    c->s = format == QD__CANVAS_SVG   ? cairo_svg_surface_create_for_stream(to_stream, c, w, h)
           : format == QD__CANVAS_PDF ? cairo_pdf_surface_create_for_stream(to_stream, c, w, h)
                                      : cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h);
    c->cr = cairo_create(c->s);
    return c;
}

static const char *close_canvas(void *cv) {
    canvas *c = cv;
    cairo_status_t cs = cairo_status(c->cr);
    cairo_destroy(c->cr);
    if (cs == CAIRO_STATUS_SUCCESS && c->format == QD__CANVAS_PNG)
        cs = cairo_surface_write_to_png_stream(c->s, to_stream, c);
    cairo_surface_finish(c->s); /* SVG and PDF write here */
    if (cs == CAIRO_STATUS_SUCCESS)
        cs = cairo_surface_status(c->s);
    cairo_surface_destroy(c->s);
    free(c);
    return cs == CAIRO_STATUS_SUCCESS ? NULL : cairo_status_to_string(cs);
}

#define CR(cv) (((canvas *)(cv))->cr)

static void rgb(void *cv, unsigned v) {
    cairo_set_source_rgb(CR(cv), ((v >> 16) & 255) / 255.0, ((v >> 8) & 255) / 255.0,
                         (v & 255) / 255.0);
}
static void line_width(void *cv, double w) { cairo_set_line_width(CR(cv), w); }
static void round_ends(void *cv) {
    cairo_set_line_join(CR(cv), CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_cap(CR(cv), CAIRO_LINE_CAP_ROUND);
}
static void move_to(void *cv, double x, double y) { cairo_move_to(CR(cv), x, y); }
static void line_to(void *cv, double x, double y) { cairo_line_to(CR(cv), x, y); }
static void rect(void *cv, double x, double y, double w, double h) {
    cairo_rectangle(CR(cv), x, y, w, h);
}
static void circle(void *cv, double x, double y, double r) {
    cairo_new_sub_path(CR(cv));
    cairo_arc(CR(cv), x, y, r, 0, 2 * 3.14159265358979323846);
}
static void stroke(void *cv) { cairo_stroke(CR(cv)); }
static void fill(void *cv) { cairo_fill(CR(cv)); }
static void paint(void *cv) { cairo_paint(CR(cv)); }
static void save(void *cv) { cairo_save(CR(cv)); }
static void restore(void *cv) { cairo_restore(CR(cv)); }
static void translate(void *cv, double x, double y) { cairo_translate(CR(cv), x, y); }
static void rotate(void *cv, double a) { cairo_rotate(CR(cv), a); }
static void scale(void *cv, double s) { cairo_scale(CR(cv), s, s); }
static void clip(void *cv) { cairo_clip(CR(cv)); }
static void antialias(void *cv, bool on) {
    cairo_set_antialias(CR(cv), on ? CAIRO_ANTIALIAS_DEFAULT : CAIRO_ANTIALIAS_NONE);
}

static void use_font(cairo_t *cr, const char *family, double size, bool bold) {
    cairo_select_font_face(cr, family, CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
}
static void font(void *cv, const char *family, double size, bool bold) {
    use_font(CR(cv), family, size, bold);
}

static void text(void *cv, const char *s, double x, double y, double ax, double ay) {
    cairo_text_extents_t e;
    cairo_text_extents(CR(cv), s, &e);
    cairo_move_to(CR(cv), x - e.x_bearing - ax * e.width, y - e.y_bearing - ay * e.height);
    cairo_show_text(CR(cv), s);
}

static void extents(void *cv, const char *s, double *xb, double *yb, double *w, double *h,
                    double *advance) {
    cairo_text_extents_t e;
    cairo_text_extents(CR(cv), s, &e);
    *xb = e.x_bearing;
    *yb = e.y_bearing;
    *w = e.width;
    *h = e.height;
    *advance = e.x_advance;
}

static double text_width(const char *family, const char *s, double size) {
    cairo_surface_t *sf = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 1, 1);
    cairo_t *cr = cairo_create(sf);
    use_font(cr, family, size, false);
    cairo_text_extents_t e;
    cairo_text_extents(cr, s, &e);
    cairo_destroy(cr);
    cairo_surface_destroy(sf);
    return e.x_advance;
}

static const qd__canvas_ops ops = {
    open_canvas, close_canvas, rgb,       line_width, round_ends, move_to, line_to,
    rect,        circle,       stroke,    fill,       paint,      save,    restore,
    translate,   rotate,       scale,     clip,       antialias,  font,    text,
    extents,     text_width,
};

const qd__canvas_ops *qd_ext_cairo_ops(void) { return &ops; }
