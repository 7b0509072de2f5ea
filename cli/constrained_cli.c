/*
 * cli/constrained_cli.c - `qdot modes` and `qdot linearize` on a model that
 * keeps holonomic constraints with multipliers (a pendulum as
 * x^2 + y^2 = l^2): the library reduces onto the constraint manifold
 * (qd_constrained_at_solve); this file reads --independent, says which
 * point was taken and writes what the library prints
 * (qd_constrained_modes_print, qd_constrained_statespace_print).
 */
#include "linear_cli.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "qdot/constrained.h"

/* The analysis at q0, the independent coordinates named by indep (or NULL). */
static int solve(cli_lin_run *r, const double *q0, const char *indep, bool ss,
                 qd_constrained_at *at) {
    size_t *ix = NULL;
    if (indep && !(ix = calloc(r->e->n + 1, sizeof *ix)))
        return cli_out_of_memory();
    int rc = QD_EXIT_OK;
    if (indep && qd_constrained_indep_read(r->c.ctx, r->e, indep, ix) != QD_OK)
        rc = cli_state_diag(r->c.ctx, "--independent", indep);
    qd_linpoint_set(&r->pt, q0, NULL);
    const qd_state *s = &r->pt.st;
    if (rc == QD_EXIT_OK && qd_constrained_at_solve(r->c.ctx, r->e, r->c.mf.model, s->n, s->syms,
                                                    s->vals, ix, ss, at) != QD_OK) {
        qd_status st = qd_ctx_status(r->c.ctx);
        cli_diag_error("%s", qd_ctx_message(r->c.ctx));
        rc = st == QD_ERR_ARG || st == QD_ERR_UNSUPPORTED ? QD_EXIT_USAGE : QD_EXIT_FAIL;
    }
    free(ix);
    return rc;
}

int cli_con_point(cli_lin_run *r, const char *about, bool quiet, double *q0) {
    if (about)
        return cli_lin_point(r, "--about", about, q0, NULL);
    qd_equilibrium_choice ch = {0};
    const qd_state *s = &r->pt.st;
    int rc = QD_EXIT_OK;
    if (qd_equilibria_choose(r->c.ctx, r->e, r->c.mf.model, s->n, s->syms, s->vals, &ch) !=
        QD_OK) {
        cli_diag_error("%s", qd_ctx_message(r->c.ctx));
        rc = QD_EXIT_FAIL;
    } else if (!ch.pt) {
        cli_diag_error("no equilibrium found on the constraints (qdot equilibria lists none): "
                      "give a point with --about");
        rc = QD_EXIT_FAIL;
    } else {
        memcpy(q0, ch.pt->q, r->e->n * sizeof *q0);
        qd_buf b = QD_BUF_INIT; /* which point, as modes says it (qd_equilibrium_choice_note) */
        if (!quiet && qd_equilibrium_choice_note(r->e, &ch, &b) == QD_OK)
            fprintf(stderr, "qdot: note: about %s (choose with --about)\n", qd_buf_str(&b));
        qd_buf_free(&b);
    }
    qd_equilibrium_choice_free(&ch);
    return rc;
}

int cli_con_modes(cli_lin_run *r, const double *q0, const char *indep, bool json) {
    qd_constrained_at at = {0};
    qd_buf b = QD_BUF_INIT;
    int rc = solve(r, q0, indep, false, &at);
    if (rc == QD_EXIT_OK)
        rc = cli_emit_status(r->c.ctx, qd_constrained_modes_print(r->c.ctx, r->e, &at.c, &at.res,
                                                                  json, &b), &b, "modes");
    qd_constrained_at_free(&at);
    return rc;
}

int cli_con_linearize(cli_lin_run *r, const double *q0, const char *indep, bool json) {
    qd_constrained_at at = {0};
    qd_buf b = QD_BUF_INIT;
    int rc = solve(r, q0, indep, true, &at);
    const qd_constrained_statespace ss = {at.A, at.nu, at.u, at.B};
    if (rc == QD_EXIT_OK)
        rc = cli_emit_status(r->c.ctx, qd_constrained_statespace_print(r->c.ctx, r->e, &at.c, &ss,
                                                                       &at.res, json, &b),
                             &b, "state-space form");
    qd_constrained_at_free(&at);
    return rc;
}
