/*
 * src/plot/plot_priv.h - what the plot's data and layout (plot.c) share
 * with its drawing (draw.c).
 */
#ifndef QD_PLOT_PRIV_H
#define QD_PLOT_PRIV_H

#include <stdbool.h>
#include "qdot/plot.h"
#include "canvas.h"

typedef struct qd__plot_series {
    char *label;       /* "" when none */
    qd_plot_style style;
    size_t panel;
    size_t nth;        /* its place in its panel: the palette's index */
    size_t n;
    double *x, *y;
} qd__plot_series;

/* A mark of a figure (qd_plot_add_mark): a spring or rod between two
 * points, an arrow from the first to the second, or a pivot at the first. */
typedef struct qd__plot_mark {
    qd_plot_mark kind;
    size_t panel;
    double x0, y0, x1, y1;
} qd__plot_mark;

/* A colour map (qd_plot_add_map): nx x ny values over a grid, and its
 * value range (zmin == zmax when constant; both NaN when every value is). */
typedef struct qd__plot_map {
    char *label;
    size_t nx, ny;
    double *x, *y, *z; /* z[j*nx + i] at (x[i], y[j]) */
    double zmin, zmax;
} qd__plot_map;

/* A panel: its labels, and (after qd_plot_layout) its plot area and what
 * maps data onto it. */
typedef struct qd__plot_panel {
    char *xlabel, *ylabel;
    char *heading;                     /* above the area (qd_plot_set_heading); NULL none */
    char *note;                        /* in its top-left corner (qd_plot_set_note) */
    size_t nseries;
    bool equal;                        /* one data unit is as long on both axes */
    double left, top, width, height;   /* the plot area, in pixels */
    double x0, x1, y0, y1;             /* the data range it shows */
    double legend_top;                 /* the legend strip's top */
    size_t legend_rows;
    qd__plot_map *map;                 /* NULL: none */
} qd__plot_panel;

struct qd_plot {
    qd_ctx *ctx;
    int width, height;
    char *title;
    qd__plot_panel *panels;
    size_t rows, cols, cur;
    qd__plot_series *series;
    size_t nseries, cap;
    qd__plot_mark *marks;
    size_t nmarks, capm;
    bool shared_legend;                /* one legend under the title (qd_plot_share_legend) */
    size_t shared_rows;                /* its rows, after the layout */
    double dpi;                        /* 96: a pixel a unit of the layout */
    double point_size;                 /* QD_PLOT_POINTS' radius; 0: by their number */
    bool laid_out;
    const qd__canvas_ops *canvas; /* the drawing module's, from the first layout */
};

/* The canvas a plot paints on: the module's primitives and its surface. */
typedef struct qd__plot_pen {
    const qd__canvas_ops *op;
    void *cv;
} pen;

/* text as mathematics (qd_plot_math_text) without its combining dots,
 * into out; with base and dots (QD__PLOT_TEXT_MAX each, may be NULL) the
 * byte where each dotted letter starts in out and its dots (1 or 2),
 * returning how many (text.c). */
size_t qd__plot_plain_math(const char *text, char *out, size_t cap, size_t *base,
                           unsigned *dots);
/* text drawn as mathematics anchored as the canvas's text op: the dots,
 * which fonts put over a short letter's height and so inside a theta,
 * painted over each dotted letter's ink. */
void qd__plot_math_at(const pen *cr, const char *text, double x, double y, double ax, double ay);

/* Panel k's marks painted (marks_draw.c), in its clip. */
void qd__plot_draw_marks(const qd_plot *p, size_t k, const pen *cr);

/* Sizes of the layout, in pixels (points for SVG and PDF). */
#define QD__PLOT_FONT "sans-serif"
#define QD__PLOT_TICK_FONT 12.0
#define QD__PLOT_LABEL_FONT 14.0
#define QD__PLOT_TITLE_FONT 16.0
#define QD__PLOT_LEGEND_ROW 20.0
#define QD__PLOT_SWATCH 24.0
#define QD__PLOT_TEXT_MAX 1024 /* a text drawn, as mathematics, in bytes */

/* The drawing module's canvas (qdot_cairo.so), NULL with
 * QD_ERR_UNSUPPORTED in ctx when it cannot be loaded (draw.c). */
const qd__canvas_ops *qd__plot_canvas(qd_ctx *ctx);
/* Width of text in the legend's font, for the layout (after p->canvas). */
double qd__plot_text_width(const qd_plot *p, const char *text, double size);

/* The legend of panel k laid left to right in rows of at most width:
 * row[i] and x offset xoff[i] of series i (either may be NULL); returns the
 * row count (0 without labels). */
size_t qd__plot_legend_rows(const qd_plot *p, size_t k, double width, size_t *row, double *xoff);
/* The shared legend's entries: series i is in it when it is the first of
 * its label (every panel's series with one label are drawn alike). */
bool qd__plot_legend_first(const qd_plot *p, size_t i);
#define QD__PLOT_ANY_PANEL ((size_t)-1) /* qd__plot_legend_rows over the whole plot */

/* The marks of panel k widen lo/hi (x, else y) to take them in. */
void qd__plot_marks_range(const qd_plot *p, size_t k, bool want_y, double *lo, double *hi);
void qd__plot_marks_free(qd_plot *p);

/* The map's cells: the edges of cell i along an axis of n points v,
 * halfway to its neighbours (the end cells as wide as the next one in). */
void qd__plot_map_edges(size_t n, const double *v, size_t i, double *lo, double *hi);
void qd__plot_map_free(qd__plot_map *m);
/* Width the colour bar takes at a panel's right, in pixels. */
#define QD__PLOT_BAR_ROOM 100.0

#endif
