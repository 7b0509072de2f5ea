/*
 * src/plot/canvas.h - the drawing primitives src/plot/draw.c paints with,
 * implemented over Cairo by the optional module qdot_cairo.so
 * (modules/cairo.c), which libqdot opens only when a plot is laid out or
 * written (qd__plot_canvas).  Cairo brings some twenty libraries (pixman,
 * fontconfig, freetype, X11 and xcb, ...) that no other command needs:
 * linked in, every start of the program paid the loader's work on them.
 *
 * As for every module (src/sweep/ext.h), the module calls nothing of
 * libqdot's; the layout, ticks, colours and text anchors are computed
 * here, the module only paints.  QD__CANVAS_ABI changes with this table.
 * Coordinates are pixels (points for SVG and PDF), y down; colours 0xRRGGBB.
 */
#ifndef QD_PLOT_CANVAS_H
#define QD_PLOT_CANVAS_H

#include <stdbool.h>
#include <stddef.h>

#define QD__CANVAS_ABI 2

enum { QD__CANVAS_PNG, QD__CANVAS_SVG, QD__CANVAS_PDF };

/* The bytes of the finished file go to write(closure, data, n), which
 * returns false when they could not be written. */
typedef bool (*qd__canvas_write)(void *closure, const unsigned char *data, size_t n);

typedef struct qd__canvas_ops {
    /* A w x h surface of the format; NULL when none can be made. */
    void *(*open)(int format, int w, int h, qd__canvas_write write, void *closure);
    /* Finish the surface, write it (PNG here; SVG and PDF as they go) and
     * free it; NULL on success, else the drawing library's reason. */
    const char *(*close)(void *cv);
    void (*rgb)(void *cv, unsigned rgb);
    void (*line_width)(void *cv, double w);
    void (*round_ends)(void *cv);                    /* round joins and caps */
    void (*move_to)(void *cv, double x, double y);
    void (*line_to)(void *cv, double x, double y);
    void (*rect)(void *cv, double x, double y, double w, double h);
    void (*circle)(void *cv, double x, double y, double r); /* a closed sub-path */
    void (*stroke)(void *cv);
    void (*fill)(void *cv);
    void (*paint)(void *cv);                         /* the whole surface */
    void (*save)(void *cv);
    void (*restore)(void *cv);
    void (*translate)(void *cv, double x, double y);
    void (*rotate)(void *cv, double radians);
    void (*scale)(void *cv, double s);               /* both axes: a PNG's --dpi */
    void (*clip)(void *cv);                          /* to the current path */
    void (*antialias)(void *cv, bool on);
    void (*font)(void *cv, const char *family, double size, bool bold);
    /* text with its anchor at (x, y): ax 0 left, 0.5 centre, 1 right of the
     * text; ay likewise from the top (0) to the bottom (1) of its ink */
    void (*text)(void *cv, const char *text, double x, double y, double ax, double ay);
    /* text's ink in the current font: x and y bearings from the origin on
     * the baseline, width and height, and the advance */
    void (*extents)(void *cv, const char *text, double *xb, double *yb, double *w, double *h,
                    double *advance);
    /* the advance of text in family at size (regular), without a surface */
    double (*text_width)(const char *family, const char *text, double size);
} qd__canvas_ops;

/* modules/cairo.c's entry points */
typedef const qd__canvas_ops *(*qd__canvas_ops_fn)(void);

#endif
