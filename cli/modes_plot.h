/*
 * cli/modes_plot.h - `qdot modes --plot FILE`: the mode shapes as a picture
 * (modes_plot.c).
 */
#ifndef QDOT_CLI_MODES_PLOT_H
#define QDOT_CLI_MODES_PLOT_H

#include "linear_cli.h"
#include "modes_symmetry.h"
#include "plot_cli.h"

/* The equilibrium q0 and each mode of res drawn into look->file, with the
 * picture's options of look; title is the model file's name.  With sym
 * active (--symmetry, a point group), the symmetry's modes are drawn, each
 * panel noting its irrep.  Exit status, the message printed on failure. */
int cli_modes_plot(cli_lin_run *lr, const double *q0, const qd_modes_result *res,
                   const cli_plot_args *look, const char *title, const cli_sym_run *sym);

#endif
