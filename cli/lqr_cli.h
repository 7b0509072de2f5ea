/*
 * cli/lqr_cli.h - the weights of an LQR design as the command line gives
 * them: --lqr "Q = diag(1, 1, 10, 1), R = 0.1".
 */
#ifndef QDOT_LQR_CLI_H
#define QDOT_LQR_CLI_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>
#include "qdot/json.h"
#include "qdot/control.h"
#include "qdot/statespace.h"

/* Read text into Q (n*n) and R (m*m), row-major arrays the caller owns.
 * text is "Q = W, R = W" in either order, each given once, where W is
 *   a number c              c times the identity,
 *   diag(d1, ..., dk)       k = the size,
 *   [[a11, a12, ...], ...]  the full matrix, row by row.
 * On an error: false, the message in err (errlen bytes) and its byte offset
 * in text at *where.  Symmetry and definiteness are left to qd_care_solve,
 * which names what is wrong with them. */
bool cli_lqr_parse(const char *text, size_t n, size_t m, double *Q, double *R, char *err,
                   size_t errlen, size_t *where);

/* A matrix "[[a11, a12, ...], [a21, ...], ...]" of any shape, its rows of
 * equal length, into *out (malloc'd, row-major, rows*cols; free() it).  On
 * an error: false, *out NULL, the message and place as above. */
bool cli_matrix_parse(const char *text, size_t *rows, size_t *cols, double **out, char *err,
                      size_t errlen, size_t *where);

/* The LQR design r (qd_care_solve) on out: K with the states and inputs
 * named, X, the closed-loop eigenvalues and the residual (lqr_out.c).
 * Text shows 10 significant digits; JSON ("states", "inputs", "K", "X",
 * "closed_loop", "residual", "rcond") and C (const arrays) every digit.
 * false when out of memory or a number is not finite (nothing printed). */
typedef enum cli_lqr_format { CLI_LQR_TEXT, CLI_LQR_JSON, CLI_LQR_C } cli_lqr_format;
bool cli_lqr_print(FILE *out, const qd_care_result *r, const char *const *states,
                   const char *const *inputs, cli_lqr_format fmt);

/* The design's JSON object into j (the keys above), for a caller that nests
 * it in its own document. */
void cli_lqr_json(qd_json *j, const qd_care_result *r, const char *const *states,
                  const char *const *inputs);

/* A reader's error under the option's text, with a caret at its place:
 * QD_EXIT_USAGE. */
int cli_lqr_read_error(const char *opt, const char *text, const char *msg, size_t where);

/* ---- a design on a model (lqr_model.c) -------------------------------------- */

/* An operating point "q=VALUE, q'=VALUE, F=VALUE, ..." (--about): exact
 * values for coordinates, velocities and inputs, read against the model in
 * ctx.  syms and vals share one block; cli_point_free releases it. */
typedef struct cli_point {
    size_t n, cap;
    const qd_expr **syms, **vals;
} cli_point;
int cli_point_read(qd_ctx *ctx, const char *text, cli_point *pt);
void cli_point_free(cli_point *pt);
/* The value pt gives sym, or 0 (what qd_linearize takes for it). */
const qd_expr *cli_point_value(qd_ctx *ctx, const cli_point *pt, const qd_expr *sym);

/* The weights text (--lqr "Q = ..., R = ...") for the linearized s, solved
 * by qd_care_solve into out: an exit status, the error printed (a weight
 * misread with a caret under it, the CARE's refusal as it words it). */
int cli_lqr_design(qd_ctx *ctx, const qd_statespace *s, const char *weights,
                   qd_care_result *out);
/* r printed with s's states and inputs as names (cli_lqr_print); JSON as
 * an object nested under the caller's key (cli_lqr_json). */
int cli_lqr_print_design(FILE *out, const qd_statespace *s, const qd_care_result *r,
                         cli_lqr_format fmt);
int cli_lqr_json_design(qd_json *j, const qd_statespace *s, const qd_care_result *r);

/* `qdot lqr` (cmd_lqr.c), declared here to leave cli.h to the other commands. */
int cli_cmd_lqr(int argc, char **argv);

#endif
