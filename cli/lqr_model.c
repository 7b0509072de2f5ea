/*
 * cli/lqr_model.c - the LQR options on a model: the library's design
 * (qd_lqr_design) and printer (qd_lqr_print) with the errors shown (`qdot
 * linearize --lqr`, `qdot simulate --input "F = lqr"`, `qdot lqr`).
 */
#include "cli.h"
#include "lqr_cli.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int cli_lqr_error(const qd_ctx *ctx, const char *opt, const char *text) {
    if (qd_ctx_status(ctx) != QD_ERR_PARSE || !qd_ctx_diag(ctx)->located)
        return cli_diag_ctx(ctx);
    cli_diag_show(opt, text, qd_ctx_diag(ctx));
    return QD_EXIT_USAGE;
}

/* ---- the design ------------------------------------------------------------ */

int cli_lqr_design(qd_ctx *ctx, const qd_statespace *s, const char *weights,
                   qd_care_result *out) {
    return qd_lqr_design(ctx, s, weights, out) == QD_OK ? QD_EXIT_OK
                                                        : cli_lqr_error(ctx, "--lqr", weights);
}

int cli_lqr_print_design(FILE *out, const qd_statespace *s, const qd_care_result *r,
                         cli_lqr_format fmt) {
    qd_buf b = QD_BUF_INIT;
    qd_status st = qd_lqr_print(s, r, (qd_lqr_format)fmt, &b);
    if (st == QD_OK)
        fputs(qd_buf_str(&b), out);
    else
        cli_diag_error("%s printing the design", st == QD_ERR_NOMEM ? "out of memory"
                                                                    : "a number that is not finite");
    qd_buf_free(&b);
    return st == QD_OK ? QD_EXIT_OK : QD_EXIT_FAIL;
}
