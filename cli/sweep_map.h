/*
 * cli/sweep_map.h - qdot sweep --map FILE.png: one measure of a 2-D grid
 * sweep drawn as a colour map over its two axes (qd_plot_add_map), the
 * first axis across, the second up (issue 21).
 */
#ifndef QDOT_CLI_SWEEP_MAP_H
#define QDOT_CLI_SWEEP_MAP_H

#include <stdbool.h>
#include <stddef.h>
#include "qdot/qdot.h"
#include "qdot/sweep.h"

typedef struct cli_sweep_map {
    const char *file;    /* --map FILE.png|.svg|.pdf */
    const char *measure; /* --map-measure NAME: a measure column (default: the first) */
} cli_sweep_map;

/* One --map option at argv[*i]: 1 taken, 0 not one, or an exit status +
 * 100 (a repeated option). */
int cli_sweep_map_option(int argc, char **argv, int *i, cli_sweep_map *m);

/* Before the runs: --map-measure without --map, an unknown extension, a
 * sweep that is not a --grid of two axes (grid: was --grid given?), a
 * measure that is not a column.  The measure's column goes to *col.  Exit
 * status, the message printed. */
int cli_sweep_map_check(const cli_sweep_map *m, const qd_sweep *w, bool grid, size_t *col);

/* After the runs: draw column col of rows (nruns x ncols, in run order)
 * over the grid; title names the model.  Exit status. */
int cli_sweep_map_write(const cli_sweep_map *m, const qd_sweep *w, const double *rows,
                        size_t col, const char *title);

#endif
