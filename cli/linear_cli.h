/*
 * cli/linear_cli.h - what `qdot equilibria` and `qdot modes` share: a model
 * loaded with its --set values, its equations derived (holonomic
 * constraints eliminated), the state of the parameters, and the --guess /
 * --box / --about lists read against the coordinates.
 */
#ifndef QDOT_CLI_LINEAR_CLI_H
#define QDOT_CLI_LINEAR_CLI_H

#include "driver.h"
#include "qdot/json.h"
#include "qdot/equilibria.h"
#include "qdot/linpoint.h"
#include "qdot/modes.h"
#include "state.h"

#define QD_LIN_MAX_SETS 64

typedef struct cli_lin_run {
    cli_run c;          /* first: a driven command's run state may start with this */
    qd_eom *e;
    qd_linpoint pt;     /* the model's state and the slots of e's coordinates */
} cli_lin_run;

/* Load FILE, apply the --set list, derive, fill the state. */
int cli_lin_load(cli_lin_run *r, const char *file, const char *const *sets, size_t nsets);
/* The same in two steps, for a caller that looks at the model first (FILE
 * may be standard input: read once). */
int cli_lin_load_model(cli_lin_run *r, const char *file, const char *const *sets,
                       size_t nsets);
int cli_lin_derive(cli_lin_run *r);
/* The point for equations r->e already derived (cli_lin_derive's second
 * half: qd_linpoint_init). */
int cli_lin_setup(cli_lin_run *r);
void cli_lin_free(cli_lin_run *r);
/* qd_linpoint_read (qd NULL: qd_linpoint_read_coords) of the option what's
 * text ("--initial"), its error shown under that text. */
int cli_lin_point(cli_lin_run *r, const char *what, const char *text, double *q, double *qd);
/* Equilibria with the options (guess, box may be NULL). */
int cli_lin_equilibria(cli_lin_run *r, const char *guess, const char *box, qd_equilibria *out);


/* ---- models with speeds (speeds_lin_cli.c) ---------------------------------
 * mf: a model with `speeds`, loaded (cli_lin_load_model; borrowed).  refuse:
 * an option given that such a model does not take (its name, for the
 * error), or NULL. */
int cli_speeds_equilibria(qd_ctx *ctx, cli_model_file *mf, bool json, const char *refuse);
/* about: "theta=pi/2, u3=6" (coordinates and speeds), or NULL: the first
 * equilibrium, free coordinates and speeds 0.  range: --scan NAME=A:B (a
 * parameter, speed or coordinate; steps as --steps), or NULL. */
int cli_speeds_modes(qd_ctx *ctx, cli_model_file *mf, const char *about, const char *range,
                     size_t steps, bool json, const char *refuse);

/* ---- models that keep constraints (constrained_cli.c) -----------------------
 * Modes on the constraint manifold of holonomic constraints about q0 (e->n
 * values, moved onto the constraints by the dependent coordinates), from
 * the reduced M and K.  indep: "x, ..." the independent coordinates, or
 * NULL (chosen by the library). */
int cli_con_modes(cli_lin_run *r, const double *q0, const char *indep, bool json);
/* The state manifold's path (qdot/conlin.h) for `linearize` and `modes`:
 * the options given (NULL when not), the format, --steps of --scan (0: 100)
 * and whether to print the modes (qd_conlin_modes_print) or the state-space
 * form (qd_conlin_render). */
typedef struct cli_conlin_args {
    const char *about, *independent, *scan, *lqr;
    int fmt;        /* qd_ss_format */
    size_t steps;
    bool modes;
    const char *ignore;   /* stability --ignore: these must be ignorable, or NULL */
    const char *about_opt; /* the option about came from (NULL: "--about") */
    const struct cli_plot_args *look; /* --scan --plot FILE: the eigenvalues drawn, or NULL */
} cli_conlin_args;
int cli_conlin(cli_lin_run *r, const cli_conlin_args *a);

/* ---- --scan (scan_cli.c) --------------------------------------------------- */

/* "NAME=A:B": the parameter's name (cap bytes) and the range's ends. */
/* linearize --scan --plot FILE: the scan's eigenvalues drawn (qd_conlin_scan_plot) with
 * the picture's options, the title the model file's name unless --title. */
struct qd_conlin_scan;
struct cli_plot_args;
int cli_scan_plot(qd_ctx *ctx, const struct qd_conlin_scan *sc, const char *name,
                  const struct cli_plot_args *look, const char *model_path);
int cli_scan_range(qd_ctx *ctx, const char *text, char *name, size_t cap, double *a,
                   double *b);
/* `qdot modes FILE --scan NAME=A:B [--about ...] [--steps N]`: scan, print. */
int cli_scan_modes(cli_lin_run *r, const char *range, const char *about, size_t steps, bool json);

#endif
