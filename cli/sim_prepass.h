/*
 * cli/sim_prepass.h - interim, until the simulation options are a shared
 * option group on main (cli_sim_opts, T2 of issue 31): sweep and animate
 * declare their own options in a table (cli_parse) and take the simulation
 * options out of argv first, with cli_sim_took_option.
 */
#ifndef QDOT_CLI_SIM_PREPASS_H
#define QDOT_CLI_SIM_PREPASS_H

#include "sim_cli.h"

/* The simulation options of argv[0, argc) read into *a (-o is --out, an
 * option other than --set, --input, --event, --stop-at given twice is
 * refused), every other argument kept in order in rest[0, *nrest) (room for
 * argc), --help among them.  An exit status, the message printed. */
int cli_sim_prepass(int argc, char **argv, cli_sim_args *a, char **rest, int *nrest);

#endif
