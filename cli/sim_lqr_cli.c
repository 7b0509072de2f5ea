/*
 * cli/sim_lqr_cli.c - `qdot simulate --input "F = lqr" --about "..." --lqr
 * "Q = ..., R = ..."`: the library's LQR feedback on the run's input
 * (qd_sim_setup_lqr, qdot/simsetup.h), its errors named by the option they
 * are about, and the controller said on stderr (qd_sim_lqr_note).
 */
#include "cli.h"
#include "lqr_cli.h"
#include "sim_cli.h"

#include <stdio.h>
#include <string.h>

/* The error of qd_sim_setup_lqr, under the option it is about. */
static int lqr_error(cli_sim *c, const char *name, const qd_sim_lqr *l) {
    const char *part = l->part ? l->part : "";
    if (!strcmp(part, "about")) {
        const qd_diag *d = qd_ctx_diag(c->ctx);
        if (d->located) {
            cli_diag_show("--about", c->about, d);
            return cli_exit(qd_ctx_status(c->ctx));
        }
        cli_diag_error("--about: %s", qd_ctx_message(c->ctx));
        return cli_exit(qd_ctx_status(c->ctx));
    }
    if (!strcmp(part, "weights"))
        return cli_lqr_error(c->ctx, "--lqr", c->lqr);
    if (qd_ctx_status(c->ctx) == QD_ERR_NOMEM)
        return cli_diag_ctx(c->ctx);
    cli_diag_error("--input: %s = lqr: %s", name, qd_ctx_message(c->ctx));
    return strcmp(part, "point") || qd_ctx_status(c->ctx) == QD_ERR_ARG ? QD_EXIT_USAGE
                                                                         : QD_EXIT_FAIL;
}

int cli_sim_input_lqr(cli_sim *c, const char *name) {
    if (!c->lqr || !c->about) {
        cli_diag_error("--input \"%s = lqr\" needs %s: the weights --lqr \"Q = diag(...), "
                       "R = ...\" and the operating point --about \"q=VALUE, q'=VALUE, "
                       "%s=VALUE\"", name, !c->lqr && !c->about ? "--lqr and --about"
                                           : !c->lqr ? "--lqr" : "--about", name);
        return QD_EXIT_USAGE;
    }
    c->lqr_used = true;
    qd_sim_lqr l;
    int rc = QD_EXIT_OK;
    if (qd_sim_setup_lqr(c->set, name, c->about, c->lqr, &l) != QD_OK)
        rc = lqr_error(c, name, &l);
    qd_buf b = QD_BUF_INIT;
    if (rc == QD_EXIT_OK && qd_sim_lqr_note(&l, "qdot: simulate: ", &b) == QD_OK)
        fputs(qd_buf_str(&b), stderr);
    else if (rc == QD_EXIT_OK)
        rc = cli_diag_ctx(c->ctx);
    qd_buf_free(&b);
    qd_sim_lqr_free(&l);
    return rc;
}
