/*
 * cli/modes_symmetry.h - `qdot modes --symmetry`: the symmetry group of
 * the equilibrium, its character table, the decomposition of the
 * displacements, the symmetry coordinates, K0 by blocks and the modes
 * labelled by irreps (libqdot: qdot/symmetry.h); rings of many identical
 * cells by the cyclic fast path.
 */
#ifndef QDOT_CLI_MODES_SYMMETRY_H
#define QDOT_CLI_MODES_SYMMETRY_H

#include "qdot/json.h"
#include "linear_cli.h"
#include "qdot/symmetry.h"

/* From this many coordinates on, a system invariant under a shift of its
 * coordinates takes the fast path (no group table). */
#define CLI_SYM_FAST_N 48

typedef struct cli_sym_run {
    qd_symmetry sym;        /* order 0 or 1: no symmetry (plain modes) */
    qd_cyclic_modes cyc;    /* the fast path when cyc.n */
    bool active;            /* the symmetry output replaces the plain modes */
} cli_sym_run;

/* The group and the labelled modes about the point in lr's state (lin its
 * linearization).  No symmetry, or a group that cannot be had (damped,
 * too large): a note on stderr, active false, QD_EXIT_OK. */
int cli_sym_compute(cli_lin_run *lr, const qd_linear *lin, cli_sym_run *s);
/* Text: group, characters, Gamma, coordinates, blocks, modes. */
void cli_sym_put_text(const cli_sym_run *s, const qd_eom *e, qd_buf *b);
/* JSON: the "symmetry" object (key included). */
void cli_sym_put_json(const cli_sym_run *s, const qd_eom *e, qd_json *j);
/* JSON: the modes array (key included) with "irrep" on each. */
void cli_sym_json_modes(const cli_sym_run *s, const qd_eom *e, qd_json *j);
void cli_sym_free(cli_sym_run *s);

#endif
