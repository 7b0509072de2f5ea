/*
 * cli/sim_cli.h - what `qdot simulate` and `qdot poincare` share: their
 * common options, the model compiled for simulation (qdot/sim.h), initial
 * values, --output expressions and event conditions read against the model.
 */
#ifndef QDOT_CLI_SIM_CLI_H
#define QDOT_CLI_SIM_CLI_H

#include <stdbool.h>
#include "qdot/sim.h"
#include "qdot/simsetup.h"
#include "model_file.h"
#include "plot_cli.h"
#include "state.h"

#include "args.h"

#define QD_SIM_MAX_LIST CLI_LIST_MAX

/* The simulation options simulate, poincare, lyapunov, animate and sweep
 * share, as the option table fills them (cli_sim_group).  Numbers are kept
 * as text: each may be an expression in the model's parameters ("2*pi/w"),
 * read once the model is loaded (cli_sim_setup); NULL when not given. */
typedef struct cli_sim_args {
    const char *t_end, *dt, *step, *rtol, *atol, *every, *max_steps;
    const char *method;    /* one of the method names, or NULL: the default */
    const char *precision; /* "64", "80", "128" (taylor), or NULL */
    const char *initial;   /* --initial "q=VALUE, q'=VALUE, ..." */
    const char *output;    /* --output "EXPR, ..." (simulate's columns) */
    const char *out;       /* --out FILE, -o FILE */
    cli_list sets;         /* --set NAME=VALUE */
    cli_list inputs;       /* --input "F = EXPR", F=FILE.csv or "F = lqr" */
    cli_list events;       /* --event "EXPR = EXPR[, EXPR > EXPR]..." */
    cli_list stops;        /* --stop-at: the same, ending the run (after the events) */
    const char *about, *lqr; /* --input "F = lqr": the operating point, the weights */
    bool native, jit, no_jit, no_project, no_speeds;
    /* set by the command, not by an option of the group */
    const char *file;      /* the model file */
    const char *section;   /* an event after the others (poincare, sweep --section) */
    const char *period;    /* instead of t_end: one period (simulate --period) */
    bool json;             /* --format json */
    bool fixed;            /* dopri5/dop853 with the constant step --dt (lyapunov) */
    cli_plot_args plot;    /* --plot: parsed by the commands that draw (simulate, poincare) */
} cli_sim_args;

/* The group's options, ended by {0}: the fields of a cli_sim_args. */
extern const cli_opt cli_sim_opts[];
/* The group of a command whose argument struct TYPE holds its cli_sim_args
 * as MEMBER: `static const cli_group groups[] = {CLI_SIM_GROUP(my_args, sim),
 * {NULL, 0}};` */
#define CLI_SIM_GROUP(TYPE, MEMBER) {cli_sim_opts, offsetof(TYPE, MEMBER)}
/* The --plot options of the commands that draw a run (simulate, poincare):
 * the fields of the cli_plot_args in MEMBER (a cli_sim_args). */
extern const cli_opt cli_sim_plot_opts[];
#define CLI_SIM_PLOT_GROUP(TYPE, MEMBER)                                                       \
    {cli_sim_plot_opts, offsetof(TYPE, MEMBER.plot)}, CLI_PLOT_LOOK_GROUP(TYPE, MEMBER.plot)

typedef struct cli_sim {
    qd_ctx *ctx;
    cli_model_file mf;
    qd_sim_setup *set; /* the library's set-up: equations, state, outputs, events */
    /* borrowed from set: */
    const qd_eom *e;           /* Lagrange's form, else NULL */
    const qd_speeds_eom *se;   /* a model with speeds (unless --no-speeds), else NULL */
    qd_sim *s;
    cli_state st;              /* the initial state (a read-only view) */
    qd_sim_opts opts;
    const char *about, *lqr;   /* from cli_sim_args, for --input "F = lqr" */
    bool lqr_used;             /* some input took the LQR feedback */
} cli_sim;

/* Load, --set, derive, compile, initial values, outputs and events, the
 * method and options.  Returns an exit status; prints its diagnostics. */
int cli_sim_setup(cli_sim *c, const cli_sim_args *a);
void cli_sim_free(cli_sim *c);

/* --input NAME=FILE.csv: the file's rows "t,value" (a first line that is
 * not numbers is a header) as a table; an exit status (sim_input_cli.c). */
int cli_sim_input_csv(cli_sim *c, const char *name, const char *path, size_t len);
/* --input "NAME = lqr": the model linearized about c->about, the CARE
 * solved with the weights c->lqr, and NAME = u0 - K (x - x0) (its row of
 * K) as the input's expression; an exit status (sim_lqr_cli.c). */
int cli_sim_input_lqr(cli_sim *c, const char *name);

/* The context's error about the text of a user's option opt (--measure):
 * shown in text at its place when located, else after "opt: "; an exit
 * status. */
int cli_sim_fail_in(cli_sim *c, const char *opt, const char *text);

/* Print a failed run's message; exit status 1. */
int cli_sim_fail(cli_sim *c, qd_status st);

#endif
