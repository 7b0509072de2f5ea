/*
 * cli/state.h - numbers from the command line: `--set NAME=VALUE` and
 * `--at "theta1=0.3, theta2'=0.5, t=0"`, read by the library's state reader
 * (qdot/state.h) and its errors shown against the option's text.
 *
 * Every function here prints its own diagnostics and returns an exit
 * status (QD_EXIT_OK to go on).
 */
#ifndef QDOT_CLI_STATE_H
#define QDOT_CLI_STATE_H

#include "qdot/model.h"
#include "qdot/state.h"

/* A point of the state space: the library's (q, q', t, the parameters,
 * then what a command appends: the momenta, the speeds). */
typedef qd_state cli_state;

/* The context's error after reading the option what's text: with a caret
 * under its place when it has one.  Returns the exit status. */
int cli_state_diag(const qd_ctx *ctx, const char *what, const char *text);

/* Every coordinate, velocity and t at 0, every parameter at its value. */
int cli_state_init(qd_ctx *ctx, const qd_model *m, cli_state *st);
void cli_state_free(cli_state *st);
/* Apply an --at list (qd_state_read); errors located in it. */
int cli_state_parse(qd_ctx *ctx, const qd_model *m, const char *text, cli_state *st);
/* The same for another option (what: "--guess"), named so in the errors. */
int cli_state_parse_as(qd_ctx *ctx, const qd_model *m, const char *what, const char *text,
                      cli_state *st);
/* The same with the reader's options (what it refuses, what it reports). */
int cli_state_read(qd_ctx *ctx, const qd_model *m, const char *what, const char *text,
                   cli_state *st, const qd_state_read_opts *opts);

/* Read a number, a constant expression (pi/4).  what names the value in
 * messages ("--t").  *exact is the expression when it is an exact or float
 * number, else a float of *val. */
int cli_state_number(qd_ctx *ctx, const char *what, const char *text, const qd_expr **exact,
                    double *val);

/* Read one --set NAME=VALUE: name (cap bytes) and the number, for the
 * model's parse (qd_model_opts); the name is checked there. */
int cli_state_read_set(qd_ctx *ctx, const char *arg, char *name, size_t cap,
                       const qd_expr **value);

#endif
