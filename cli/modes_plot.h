/*
 * cli/modes_plot.h - `qdot modes --plot FILE`: the mode shapes as a picture
 * (modes_plot.c).
 */
#ifndef QDOT_CLI_MODES_PLOT_H
#define QDOT_CLI_MODES_PLOT_H

#include "linear_cli.h"

/* The equilibrium q0 and each mode of res drawn into file; title is the
 * model file's name.  Exit status, the message printed on failure. */
int cli_modes_plot(cli_lin_run *lr, const double *q0, const qd_modes_result *res,
                   const char *file, const char *title);

#endif
