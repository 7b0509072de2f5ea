/*
 * cli/modes_symmetry.h - `qdot modes --symmetry`: the symmetry group of
 * the equilibrium and the modes labelled by irreps (libqdot:
 * qdot/symmetry.h, which also prints them); rings of many identical cells
 * by the cyclic fast path.
 */
#ifndef QDOT_CLI_MODES_SYMMETRY_H
#define QDOT_CLI_MODES_SYMMETRY_H

#include "linear_cli.h"
#include "qdot/symmetry.h"

typedef struct cli_sym_run {
    qd_symmetry sym;        /* order 0 or 1: no symmetry (plain modes) */
    qd_cyclic_modes cyc;    /* the fast path when cyc.n */
    bool active;            /* the symmetry output replaces the plain modes */
} cli_sym_run;

/* The group and the labelled modes about the point in lr's state (lin its
 * linearization).  No symmetry, or a group that cannot be had (damped,
 * too large): a note on stderr, active false, QD_EXIT_OK. */
int cli_sym_compute(cli_lin_run *lr, const qd_linear *lin, cli_sym_run *s);
void cli_sym_free(cli_sym_run *s);

#endif
