/*
 * cli/lqr_cli.h - the LQR options of the qdot program over the library's
 * design (qdot/control.h): --lqr "Q = ..., R = ..." on a model.
 */
#ifndef QDOT_LQR_CLI_H
#define QDOT_LQR_CLI_H

#include <stdio.h>
#include "qdot/control.h"
#include "qdot/json.h"
#include "qdot/statespace.h"

/* The context's error after reading the text of option opt: a reader's
 * (located) under the text with a caret, any other as cli_diag_ctx.  Returns
 * the exit status. */
int cli_lqr_error(const qd_ctx *ctx, const char *opt, const char *text);

/* qd_lqr_design for the weights of --lqr: an exit status, the error
 * printed (a weight misread with a caret under it). */
int cli_lqr_design(qd_ctx *ctx, const qd_statespace *s, const char *weights,
                   qd_care_result *out);
/* qd_lqr_print on out. */
typedef enum cli_lqr_format {
    CLI_LQR_TEXT = QD_LQR_TEXT, CLI_LQR_JSON = QD_LQR_JSON, CLI_LQR_C = QD_LQR_C
} cli_lqr_format;
int cli_lqr_print_design(FILE *out, const qd_statespace *s, const qd_care_result *r,
                         cli_lqr_format fmt);

/* `qdot lqr` (cmd_lqr.c), declared here to leave cli.h to the other commands. */
int cli_cmd_lqr(int argc, char **argv);

#endif
