/*
 * qdot/plot.h - line and scatter plots drawn with Cairo into PNG, SVG or PDF.
 *
 * A qd_plot holds series of (x, y) points (copied), a title and axis
 * labels.  qd_plot_write lays it out and draws it: axes framing the data,
 * ticks at 1, 2 or 5 times a power of ten (qd_plot_nice_ticks), tick
 * labels, the axis labels, a legend in a strip above the plot area (so it
 * never hides data) and the title; the format is chosen by the file's
 * extension (.png, .svg, .pdf).  Defaults: 800 x 500 (pixels for PNG,
 * points for SVG and PDF), antialiased lines 2 px wide, series coloured from
 * a fixed palette of distinct colours in the order added.
 *
 * The layout is deterministic: after qd_plot_layout (which qd_plot_write
 * calls) qd_plot_to_pixel maps data to the very pixel the series was drawn
 * through, so a caller (a test) can look for a curve where the data puts
 * it.  Failures return a status with the message in the context: an empty
 * plot or series, non-finite numbers (QD_ERR_ARG), an unknown extension
 * (QD_ERR_ARG), a file that cannot be written (QD_ERR_ARG, naming it),
 * Cairo failing (QD_ERR_NUMERIC).
 */
#ifndef QDOT_PLOT_H
#define QDOT_PLOT_H

#include <stddef.h>
#include "expr.h"
#include "status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct qd_plot qd_plot;

typedef enum qd_plot_style {
    QD_PLOT_LINE,   /* points joined in order: a time series, a phase curve */
    QD_PLOT_POINTS, /* dots: a Poincare section */
    QD_PLOT_LINE_POINTS /* a line with a dot at each point: particles of a mode shape */
} qd_plot_style;

typedef enum qd_plot_format { QD_PLOT_PNG, QD_PLOT_SVG, QD_PLOT_PDF } qd_plot_format;

/* The format named by path's extension (case-insensitive); QD_ERR_ARG with
 * a message for any other. */
QD_API qd_status qd_plot_format_of(qd_ctx *ctx, const char *path, qd_plot_format *out);

/* width, height 0 give 800 x 500; otherwise each at least 200 and at most
 * 10000.  NULL on failure, reason in ctx. */
QD_API qd_plot *qd_plot_new(qd_ctx *ctx, int width, int height);
QD_API void qd_plot_free(qd_plot *p); /* NULL is fine */

/* Texts, copied; NULL or "" for none.  Put the unit in the label: "t (s)". */
QD_API qd_status qd_plot_set_title(qd_plot *p, const char *title);
QD_API qd_status qd_plot_set_xlabel(qd_plot *p, const char *label);
QD_API qd_status qd_plot_set_ylabel(qd_plot *p, const char *label);

/* A series of n >= 1 finite points, copied; label (may be NULL) goes in the
 * legend.  Returns its index through *index (may be NULL). */
QD_API qd_status qd_plot_add(qd_plot *p, const char *label, qd_plot_style style, size_t n,
                             const double *x, const double *y, size_t *index);
QD_API size_t qd_plot_nseries(const qd_plot *p);

/* Series i's colour as 0xRRGGBB (the palette's i-th, cycling). */
QD_API unsigned qd_plot_color(const qd_plot *p, size_t i);

/* Fix the axes' ranges and the plot area.  A range is the data's, padded
 * by 5% each side (except x when every series is a line whose x never
 * decreases: a time axis is drawn exactly), then widened to the ticks' span
 * where that is at most 10% more.  QD_ERR_ARG for a plot without series. */
QD_API qd_status qd_plot_layout(qd_plot *p);

/* Where data (x, y) lands, in pixels from the image's top-left corner
 * (after qd_plot_layout; false before).  The axes' ranges and the plot
 * area's corners, likewise. */
QD_API bool qd_plot_to_pixel(const qd_plot *p, double x, double y, double *px, double *py);
QD_API bool qd_plot_ranges(const qd_plot *p, double *x0, double *x1, double *y0, double *y1);

/* Lay out and draw into path, in the format of its extension. */
QD_API qd_status qd_plot_write(qd_plot *p, const char *path);

/* Ticks for [lo, hi]: a step of 1, 2 or 5 times a power of ten giving at
 * most max_ticks (>= 2) ticks inside the range and as many as that allows;
 * *first is the smallest multiple of the step >= lo.  Returns the count (0
 * when lo >= hi or either is not finite). */
QD_API size_t qd_plot_nice_ticks(double lo, double hi, size_t max_ticks, double *step,
                                 double *first);

#ifdef __cplusplus
}
#endif
#endif
