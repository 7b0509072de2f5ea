/*
 * qdot/plot.h - line and scatter plots drawn with Cairo into PNG, SVG or PDF.
 *
 * A qd_plot holds series of (x, y) points (copied), a title and axis
 * labels, in one panel or a grid of panels (qd_plot_panels) that share the
 * title, each with its own axes, labels and legend.  qd_plot_write lays it out and draws it: axes framing the data,
 * ticks at 1, 2 or 5 times a power of ten (qd_plot_nice_ticks), tick
 * labels, the axis labels, a legend in a strip above the plot area (so it
 * never hides data) and the title; the format is chosen by the file's
 * extension (.png, .svg, .pdf).  Defaults: 800 x 500 (pixels for PNG,
 * points for SVG and PDF), antialiased lines 2 px wide, series coloured from
 * a fixed palette of distinct colours in the order added to their panel.
 *
 * The layout is deterministic: after qd_plot_layout (which qd_plot_write
 * calls) qd_plot_to_pixel maps data to the very pixel the series was drawn
 * through, so a caller (a test) can look for a curve where the data puts
 * it.  Failures return a status with the message in the context: an empty
 * plot or series, non-finite numbers (QD_ERR_ARG), an unknown extension
 * (QD_ERR_ARG), a file that cannot be opened (QD_ERR_ARG, naming it), a
 * write, flush or close that fails (QD_ERR_IO: "cannot write FILE: reason"),
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
    QD_PLOT_POINTS, /* dots: a Poincare section; 2.5 px up to 500 points, finer as
                     * 1/sqrt(n) for more (at least 0.8 px) */
    QD_PLOT_LINE_POINTS, /* a line with a dot at each point */
    QD_PLOT_DOTS    /* large dots, unjoined: the particles of a mode shape */
} qd_plot_style;

typedef enum qd_plot_format { QD_PLOT_PNG, QD_PLOT_SVG, QD_PLOT_PDF } qd_plot_format;

/* Labels are drawn as a textbook prints names (qd_plot_math_text): every
 * text of a plot (title, axis labels, legend, notes) goes through it. */

/* text with its names as mathematics into out (cap bytes, NUL-terminated,
 * truncated to fit at a whole UTF-8 character): a name (a word of letters
 * and digits after one letter or a Greek letter's name, "theta", "Omega";
 * no '_', not next to '.' or '/', so file names stay) becomes the letter,
 * its trailing digits subscripts, one or two primes after it a dot or two
 * over it: "theta1'" is a dotted theta with subscript 1 (U+03B8 U+0307
 * U+2081), "x2''" x with two dots and subscript 2, "E0" E with subscript 0.
 * Longer words ("gl4", "th'") and other text are copied.  Returns
 * the length the whole result needs (as snprintf); out may be NULL when cap
 * is 0. */
QD_API size_t qd_plot_math_text(const char *text, char *out, size_t cap);

/* The format named by path's extension (case-insensitive); QD_ERR_ARG with
 * a message for any other. */
QD_API qd_status qd_plot_format_of(qd_ctx *ctx, const char *path, qd_plot_format *out);

/* width, height 0 give 800 x 500; otherwise each at least 200 and at most
 * 10000.  NULL on failure, reason in ctx. */
QD_API qd_plot *qd_plot_new(qd_ctx *ctx, int width, int height);
QD_API void qd_plot_free(qd_plot *p); /* NULL is fine */

/* Divide the plot into rows x cols panels (1 to 8 each), filled row by
 * row; before any series is added.  The current panel is then 0. */
QD_API qd_status qd_plot_panels(qd_plot *p, size_t rows, size_t cols);
QD_API size_t qd_plot_npanels(const qd_plot *p);
/* The panel that axis labels and series go to from now on. */
QD_API qd_status qd_plot_select(qd_plot *p, size_t panel);

/* Texts, copied; NULL or "" for none.  The title is the plot's; the axis
 * labels the current panel's.  Put the unit in the label: "t (s)". */
QD_API qd_status qd_plot_set_title(qd_plot *p, const char *title);
QD_API qd_status qd_plot_set_xlabel(qd_plot *p, const char *label);
QD_API qd_status qd_plot_set_ylabel(qd_plot *p, const char *label);

/* The current panel draws a unit as long along y as along x (a
 * configuration in the plane: a circle stays round); the shorter range is
 * widened about its middle. */
QD_API qd_status qd_plot_set_equal_axes(qd_plot *p, bool equal);

/* A series of n >= 1 finite points in the current panel, copied; label
 * (may be NULL) goes in its legend.  Returns its index (counted over the
 * whole plot) through *index (may be NULL). */
QD_API qd_status qd_plot_add(qd_plot *p, const char *label, qd_plot_style style, size_t n,
                             const double *x, const double *y, size_t *index);
QD_API size_t qd_plot_nseries(const qd_plot *p);

/* Figures of a configuration (the mode shapes of qdot modes --plot), in
 * the current panel's data coordinates, drawn under its series and taken
 * into its axes' ranges. */
typedef enum qd_plot_mark {
    QD_PLOT_SPRING, /* a zigzag from (x0, y0) to (x1, y1), grey */
    QD_PLOT_ROD,    /* a straight bar from (x0, y0) to (x1, y1), dark grey */
    QD_PLOT_ARROW,  /* an arrow from (x0, y0), its head at (x1, y1), red */
    QD_PLOT_PIVOT,  /* a fixed support at (x0, y0): a hatched triangle (x1, y1 unused) */
    QD_PLOT_WALL    /* a wall through (x0, y0) facing (x1, y1) (where what it holds is): a
                     * line 26 px long across that direction, hatched on the far side */
} qd_plot_mark;

/* One mark of kind with finite coordinates; QD_ERR_ARG for others. */
QD_API qd_status qd_plot_add_mark(qd_plot *p, qd_plot_mark kind, double x0, double y0,
                                  double x1, double y1);

/* The current panel's heading (a line above its area, centred: "mode 2:
 * omega = 1.2 rad/s") and note (bold, in the area's top-left corner: an
 * irrep's name), copied; NULL or "" for none. */
QD_API qd_status qd_plot_set_heading(qd_plot *p, const char *text);
QD_API qd_status qd_plot_set_note(qd_plot *p, const char *text);

/* One legend for the whole plot, in a strip under the title, instead of
 * one over each panel: an entry for each label, drawn as its first series
 * (a grid of panels drawing the same things alike).  Before the layout. */
QD_API qd_status qd_plot_share_legend(qd_plot *p, bool shared);

/* Dots per inch of a PNG (72 to 1200; 96, the default, draws the layout's
 * pixels as they are): the picture is drawn larger by dpi/96, lines and
 * letters with it, so the image is dpi/96 times the plot's size in each
 * direction; SVG and PDF are vector drawings in points and do not change.
 * qd_plot_to_pixel stays in the layout's pixels (multiply by dpi/96). */
QD_API qd_status qd_plot_set_dpi(qd_plot *p, double dpi);
/* dpi is a resolution qd_plot_set_dpi takes; QD_ERR_ARG (field "dpi"). */
QD_API qd_status qd_plot_dpi_check(qd_ctx *ctx, double dpi);

/* The radius of QD_PLOT_POINTS' dots in the layout's pixels, 0.2 to 20
 * (0, the default: by their number, as there).  QD_ERR_ARG (field
 * "point_size") for others. */
QD_API qd_status qd_plot_set_point_size(qd_plot *p, double radius);

/* The picture's size, as qd_plot_new takes it (0, 0: the default), before
 * the layout. */
QD_API qd_status qd_plot_set_size(qd_plot *p, int width, int height);

/* Series i's colour as 0xRRGGBB: the palette's k-th (cycling) for the k-th
 * series of its panel. */
QD_API unsigned qd_plot_color(const qd_plot *p, size_t i);

/* Fix the axes' ranges and the plot area.  A range is the data's, padded
 * by 5% each side (except x when every series is a line whose x never
 * decreases: a time axis is drawn exactly), then widened to the ticks' span
 * where that is at most 10% more.  QD_ERR_ARG for a plot without series. */
QD_API qd_status qd_plot_layout(qd_plot *p);

/* Where data (x, y) of a panel lands, in pixels from the image's top-left
 * corner (after qd_plot_layout; false before, or for no such panel).  The
 * panel's axes' ranges, likewise. */
QD_API bool qd_plot_to_pixel(const qd_plot *p, size_t panel, double x, double y, double *px,
                             double *py);
QD_API bool qd_plot_ranges(const qd_plot *p, size_t panel, double *x0, double *x1, double *y0,
                           double *y1);

/* Lay out and draw into path, in the format of its extension. */
QD_API qd_status qd_plot_write(qd_plot *p, const char *path);

/* Ticks for [lo, hi]: a step of 1, 2 or 5 times a power of ten giving at
 * most max_ticks (>= 2) ticks inside the range and as many as that allows;
 * *first is the smallest multiple of the step >= lo.  Returns the count (0
 * when lo >= hi or either is not finite). */
QD_API size_t qd_plot_nice_ticks(double lo, double hi, size_t max_ticks, double *step,
                                 double *first);

/* Colour maps (qdot sweep --map): a value over a 2-D grid, each grid point
 * a cell reaching halfway to its neighbours, filled with the colour of its
 * value's place between the map's least and greatest value (viridis: dark
 * purple through teal to yellow, its lightness rising all the way, so it
 * reads the same in grey and to red-green colour-blind eyes).  A colour bar
 * at the panel's right, labelled label (may be NULL), gives the scale.  The
 * panel's axes span the cells exactly.  nx, ny >= 1 points, x and y
 * strictly increasing and finite; z[j*nx + i] is the value at (x[i], y[j]),
 * NaN for none (the cell is drawn light grey).  One map per panel, under its
 * series; copied.  QD_ERR_ARG for an empty or unordered grid, infinite
 * values, or a second map. */
QD_API qd_status qd_plot_add_map(qd_plot *p, const char *label, size_t nx, size_t ny,
                                 const double *x, const double *y, const double *z);

/* The colour of fraction f (clamped to [0, 1]) of a map's range, 0xRRGGBB:
 * viridis sampled at nine points and linearly interpolated.  A constant map
 * is drawn in the colour of 0.5. */
QD_API unsigned qd_plot_map_color(double f);

/* Panel k's axis labels and its map's colour-bar label, as given (before
 * they are drawn as mathematics), "" for none; the strings are the plot's.
 * false for no such panel. */
QD_API bool qd_plot_labels(const qd_plot *p, size_t panel, const char **xlabel,
                           const char **ylabel, const char **bar);

/* Panel k's map's range of values (false without a map, or every value NaN). */
QD_API bool qd_plot_map_range(const qd_plot *p, size_t panel, double *zmin, double *zmax);

/* ---- a run's rows drawn (qdot simulate --plot, poincare --plot) -------- */

#define QD_PLOT_MAX_SERIES 16
#define QD_PLOT_MAX_PANELS 6

/* Which columns of a run a plot draws. */
typedef struct qd_plot_pick {
    bool phase;            /* x is a coordinate, y[0] its velocity */
    size_t x;              /* column of x (0: t) */
    size_t ny;
    size_t y[QD_PLOT_MAX_SERIES];     /* columns of the y series (ncols: energy_error) */
    size_t panel[QD_PLOT_MAX_SERIES]; /* the panel of each */
    size_t npanels;
    bool energy_error;     /* a series is E(t) - E(t0) */
    size_t energy;         /* then: the energy column */
    const char *unit[QD_PLOT_MAX_SERIES]; /* each y series' unit, NULL unknown */
    const char *xunit;     /* x's (phase), NULL unknown */
} qd_plot_pick;

/* The columns of a run (names[0, ncols): t, then the ndof coordinates,
 * ...): phase Q, Q' against Q; else ycols "a, b'; energy_error", each a
 * column or energy_error (E - E(t0)) against t, a semicolon starting the
 * next panel (at most QD_PLOT_MAX_SERIES in QD_PLOT_MAX_PANELS); else (both
 * NULL) every coordinate against t.  QD_ERR_ARG for a name that is not a
 * column (the option field "plot_y" or "phase"), or both given. */
QD_API qd_status qd_plot_pick_columns(qd_ctx *ctx, const char *ycols, const char *phase,
                                      const char *const *names, size_t ncols, size_t ndof,
                                      qd_plot_pick *pk);

/* The units of pk's columns from units[0, ncols) (each a unit, "rad", or
 * NULL unknown; units[0], t's, is s); with split (the default pick, every
 * coordinate against t) the series are grouped into panels by unit in the
 * order the units first come (one unit per panel: metres and radians never
 * share an axis), at most QD_PLOT_MAX_PANELS.  qd_plot_run then ends a
 * panel's y label with its unit, "theta1, theta2 (rad)", when its series
 * share one. */
QD_API void qd_plot_pick_units(qd_plot_pick *pk, const char *const *units, size_t ncols,
                               bool split);

/* The coordinate a Poincare section's plot shows by default (its phase
 * for qd_plot_pick_columns): the section "EXPR = EXPR[, EXPR > EXPR]" fixes
 * the coordinates it names, so the first of names[1 .. ndof] (the run's
 * coordinates, names as for qd_plot_pick_columns) that is not a word of the
 * section's text (a name with no letter, digit or '_' either side: "x" is
 * named in "x' > 0" and "2*x = 1", not in "x2 = 0"); names[1] when the
 * section names them all; NULL when ndof is 0, or for a NULL section or
 * names.  The result points into names. */
QD_API const char *qd_plot_section_phase(const char *section, const char *const *names,
                                         size_t ndof);

/* The size "WxH" in pixels, 100 to 10000 each; QD_ERR_ARG (field "size"). */
QD_API qd_status qd_plot_size_of(qd_ctx *ctx, const char *text, int *width, int *height);

typedef struct qd_plot_run_opts {
    const char *title;  /* NULL: none */
    const char *xlabel; /* every panel's x axis; NULL: "t (s)", or the coordinate */
    const char *ylabel; /* "A; B": each panel's y axis (the last for the panels after); NULL:
                         * the panel's series' names */
    int width, height;  /* 0: 800 x 500, or 800 wide and 280 a panel (+ 40) when stacked */
    double dpi;         /* 0: 96 (qd_plot_set_dpi) */
    bool points;        /* dots (a Poincare section), else lines */
    double point_size;  /* the dots' radius in pixels (qd_plot_set_point_size); 0: by their
                         * number */
    /* Orbits (qdot poincare with several --initial): norbits > 1 says the
     * rows are norbits orbits one after another, orbit k's orbit_rows[k]
     * of them (summing to nrows); each series is then drawn once an
     * orbit, in the palette's k-th colour, labelled orbit_labels[k] in the
     * legend ("orbit K" where orbit_labels or its entry is NULL). */
    size_t norbits;
    const size_t *orbit_rows;
    const char *const *orbit_labels;
} qd_plot_run_opts;

/* The options of o that are given, applied to a plot made elsewhere (the
 * mode shapes, a sweep's map): title, xlabel on every panel, ylabel "A;
 * B" on each panel in turn (the last for the panels after), the size when
 * width is not 0, dpi when not 0; points is not used.  The plot's errors. */
QD_API qd_status qd_plot_apply(qd_plot *p, const qd_plot_run_opts *o);

/* A plot of the columns pk picks of rows (nrows x ncols, names as for
 * qd_plot_pick_columns), a panel per group, stacked; NULL on failure (no
 * rows, orbits whose rows do not sum to nrows, the plot's errors), the
 * reason in ctx.  Write it with
 * qd_plot_write; qd_plot_free. */
QD_API qd_plot *qd_plot_run(qd_ctx *ctx, const qd_plot_pick *pk, const char *const *names,
                            const double *rows, size_t nrows, size_t ncols,
                            const qd_plot_run_opts *o);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_plot_add (index, label);
 * qd_plot_add_map (label); qd_plot_pick_columns (ycols, phase); qd_plot_math_text (out, when
 * cap is 0); qd_plot_set_heading, qd_plot_set_note (text). An array whose count is 0 may be NULL. */
#endif
