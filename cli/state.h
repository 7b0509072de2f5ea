/*
 * cli/state.h - numbers from the command line: `--set NAME=VALUE` and
 * `--at "theta1=0.3, theta2'=0.5, t=0"`.
 *
 * A value is any expression that evaluates to a finite number (2, -1e-3,
 * pi/4, sqrt(2)/2); it is read with qd_read, so it has the model language's
 * syntax.  Every function here prints its own diagnostics and returns an exit
 * status (QD_EXIT_OK to go on).
 */
#ifndef QDOT_CLI_STATE_H
#define QDOT_CLI_STATE_H

#include "qdot/model.h"

/* A point of the state space: a value for each coordinate q_j, velocity q'_j,
 * the time t and each parameter, in that order (simulate appends the
 * momenta of a model given by H). */
typedef struct cli_state {
    size_t n;
    const qd_expr **syms;
    double *vals;
} cli_state;

/* A number node as the nearest double: an exact rational p/q that fits is
 * computed as (double)p/q, correctly rounded (9.81 stays 9.81). */
double cli_state_value(const qd_expr *number);

/* Parameter i's value as a double, also when it is written as an
 * expression of constants (pi/6); NaN if it cannot be evaluated. */
double cli_param_value(const qd_model *m, size_t i);

/* x in its shortest %g form that reads back to the same double. */
void cli_state_put_double(qd_buf *b, double x);
/* A computed result for a reader (text output of equilibria, modes,
 * stability): 12 significant digits, and 0 below 1e-13, so that a root
 * found by iteration reads 0.49, not 0.48999999999999927.  JSON keeps every
 * digit (cli_state_put_double). */
void cli_state_put_result(qd_buf *b, double x);

/* Every coordinate, velocity and t at 0, every parameter at its value. */
int cli_state_init(qd_ctx *ctx, const qd_model *m, cli_state *st);
void cli_state_free(cli_state *st);
/* Apply an --at list; an unknown name is an error naming the coordinates. */
int cli_state_parse(qd_ctx *ctx, const qd_model *m, const char *text, cli_state *st);
/* The same for another option (what: "--near"), named so in the errors. */
int cli_state_parse_as(qd_ctx *ctx, const qd_model *m, const char *what, const char *text,
                      cli_state *st);

/* Read a number.  what names the value in messages ("--set m1").  *exact is
 * the expression when it is an exact or float number, else a float of *val. */
int cli_state_number(qd_ctx *ctx, const char *what, const char *text, const qd_expr **exact,
                    double *val);

/* Read one --set NAME=VALUE: name (cap bytes) and the number, for the
 * model's parse (qd_model_opts); the name is checked there. */
int cli_state_read_set(qd_ctx *ctx, const char *arg, char *name, size_t cap,
                       const qd_expr **value);

#endif
