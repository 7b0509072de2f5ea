/*
 * cli/plot_cli.h - the --plot options of simulate, poincare and modes:
 * which columns to draw, the rows kept while a run goes, and the picture
 * made with libqdot's plots (qdot/plot.h).
 */
#ifndef QDOT_CLI_PLOT_CLI_H
#define QDOT_CLI_PLOT_CLI_H

#include <stdbool.h>
#include <stddef.h>
#include "qdot/qdot.h"
#include "args.h"
#include "qdot/plot.h"

typedef struct cli_plot_args {
    const char *file;   /* --plot FILE.png|.svg|.pdf */
    const char *ycols;  /* --plot-y "NAME, NAME; NAME": columns against t (energy_error
                         * too), a panel for each group between semicolons */
    const char *phase;  /* --phase Q: Q' against Q */
    const char *title;  /* --title TEXT: else the model file's name */
    const char *xlabel; /* --xlabel TEXT: every panel's x axis */
    const char *ylabel; /* --ylabel "A; B": each panel's y axis, between semicolons */
    const char *size;   /* --size WxH in pixels, read by cli_plot_check */
    int width, height;  /* from --size, or 0: the default */
    double dpi;         /* --dpi: a PNG's resolution (0: 96) */
    double point_size;  /* poincare --point-size (0: by the dots' number) */
    size_t norbits;     /* set by the command: the orbits (qd_plot_run_opts) */
    const size_t *orbit_rows;
    const char *const *orbit_labels;
} cli_plot_args;

/* The picture's options of every command that draws (--title, --xlabel,
 * --ylabel, --size, --dpi): the fields of the cli_plot_args at MEMBER. */
extern const cli_opt cli_plot_look_opts[];
#define CLI_PLOT_LOOK_GROUP(TYPE, MEMBER) {cli_plot_look_opts, offsetof(TYPE, MEMBER)}

/* The options as the library's (qd_plot_apply); title the model file's
 * name, without its path, where --title is not given. */
qd_plot_run_opts cli_plot_opts(const cli_plot_args *a, const char *title);

/* The options together, before any work: --plot-y or --phase without
 * --plot, both at once, an unknown extension.  Exit status. */
int cli_plot_check(cli_plot_args *a, const char *cmd);

/* The rows of a run (every column), as the sink receives them. */
typedef struct cli_plot_rows {
    size_t ncols, n, cap;
    double *v;   /* n rows of ncols */
    bool failed; /* out of memory */
} cli_plot_rows;

void cli_plot_keep(cli_plot_rows *r, const double *row);
void cli_plot_rows_free(cli_plot_rows *r);

/* Which columns the plot of a run draws (x and each y), checked against
 * the run's column names (names[0] is t, the coordinates are 1..ndof):
 * exit status 2 with a message for a name that is not a column. */
typedef qd_plot_pick cli_plot_pick; /* qdot/plot.h */

/* m (may be NULL; mctx its context) gives the coordinates' units
 * (qd_model_coord_unit), so the default plot puts a unit to a panel and
 * the labels say it. */
int cli_plot_pick_columns(const cli_plot_args *a, const char *const *names, size_t ncols,
                          size_t ndof, qd_ctx *mctx, const qd_model *m, cli_plot_pick *pk);

/* The most panels --plot-y makes (one a group). */
#define CLI_PLOT_MAX_PANELS QD_PLOT_MAX_PANELS

/* Draw the rows picked into a->file; title is the model file's name.
 * range (may be NULL) gets each panel's axes' ranges drawn: x0, x1, y0,
 * y1, 4 * pk->npanels numbers.  Exit
 * status (the library's message printed on failure). */
int cli_plot_write_run(qd_ctx *ctx, const cli_plot_args *a, const cli_plot_pick *pk,
                       const char *const *names, const cli_plot_rows *r, const char *title,
                       bool points, double *range);

#endif
