/*
 * cli/constrained_cli.c - `qdot modes` and `qdot linearize` on a model that
 * keeps constraints with multipliers.  Both go through the state manifold
 * (qdot/conlin.h: the point, the independent states, A, B, C, D and the
 * verdict are the library's); `modes` of holonomic constraints alone keeps
 * its frequencies and shapes from the reduced M and K
 * (qd_constrained_at_solve, qd_constrained_modes_print).  This file reads
 * the options, calls and writes what the library prints.
 */
#include "linear_cli.h"
#include "plot_cli.h"

#include <stdio.h>
#include <stdlib.h>
#include "lqr_cli.h"
#include "qdot/conlin.h"
#include "qdot/constrained.h"

/* The analysis at q0, the independent coordinates named by indep (or NULL). */
static int solve(cli_lin_run *r, const double *q0, const char *indep, qd_constrained_at *at) {
    size_t *ix = NULL;
    if (indep && !(ix = calloc(r->e->n + 1, sizeof *ix)))
        return cli_out_of_memory();
    int rc = QD_EXIT_OK;
    if (indep && qd_constrained_indep_read(r->c.ctx, r->e, indep, ix) != QD_OK)
        rc = cli_state_diag(r->c.ctx, "--independent", indep);
    qd_linpoint_set(&r->pt, q0, NULL);
    const qd_state *s = &r->pt.st;
    if (rc == QD_EXIT_OK && qd_constrained_at_solve(r->c.ctx, r->e, r->c.mf.model, s->n, s->syms,
                                                    s->vals, ix, false, at) != QD_OK) {
        qd_status st = qd_ctx_status(r->c.ctx);
        cli_diag_error("%s", qd_ctx_message(r->c.ctx));
        rc = st == QD_ERR_ARG || st == QD_ERR_UNSUPPORTED ? QD_EXIT_USAGE : QD_EXIT_FAIL;
    }
    free(ix);
    return rc;
}

int cli_con_modes(cli_lin_run *r, const double *q0, const char *indep, bool json) {
    qd_constrained_at at = {0};
    qd_buf b = QD_BUF_INIT;
    int rc = solve(r, q0, indep, &at);
    if (rc == QD_EXIT_OK)
        rc = cli_emit_status(r->c.ctx, qd_constrained_modes_print(r->c.ctx, r->e, &at.c, &at.res,
                                                                  json, &b), &b, "modes");
    qd_constrained_at_free(&at);
    return rc;
}

/* The point (qd_conlin_start), a note naming the equilibrium it took. */
static int start(cli_lin_run *r, const cli_conlin_args *a, const char *opt) {
    qd_equilibrium_choice ch = {0};
    qd_ctx *ctx = r->c.ctx;
    int rc = QD_EXIT_OK;
    if (qd_conlin_start(ctx, r->e, r->c.mf.model, &r->pt, a->about, &ch) != QD_OK)
        rc = a->about && qd_ctx_diag(ctx)->located ? cli_state_diag(ctx, opt, a->about)
                                                   : cli_diag_ctx(ctx);
    qd_buf b = QD_BUF_INIT;
    if (rc == QD_EXIT_OK && ch.pt && a->fmt == QD_SS_TEXT &&
        qd_equilibrium_choice_note(r->e, &ch, &b) == QD_OK)
        fprintf(stderr, "qdot: note: about %s (choose with %s)\n", qd_buf_str(&b), opt);
    qd_buf_free(&b);
    qd_equilibrium_choice_free(&ch);
    return rc;
}

int cli_conlin(cli_lin_run *r, const cli_conlin_args *a) {
    qd_ctx *ctx = r->c.ctx;
    qd_conlin c = {0};
    qd_conlin_scan sc = {0};
    qd_care_result lqr = {0};
    qd_buf b = QD_BUF_INIT;
    char name[128];
    double lo = 0, hi = 0;
    const char *opt = a->about_opt ? a->about_opt : "--about";
    int rc = a->scan ? cli_scan_range(ctx, a->scan, name, sizeof name, &lo, &hi) : QD_EXIT_OK;
    if (rc == QD_EXIT_OK && a->scan && qd_conlin_point(ctx, r->c.mf.model, &r->pt, a->about))
        rc = cli_state_diag(ctx, opt, a->about);
    else if (rc == QD_EXIT_OK && a->scan &&
             qd_conlin_scan_run(ctx, r->e, r->c.mf.model, &r->pt, a->about, a->independent, name,
                                lo, hi, a->steps ? a->steps : 100, &sc) != QD_OK)
        rc = cli_state_diag(ctx, "--independent", a->independent);
    else if (rc == QD_EXIT_OK && a->scan)
        rc = cli_emit_status(ctx, qd_conlin_scan_print(&sc, name, a->fmt == QD_SS_JSON, &b), &b,
                             "scan");
    else if (rc == QD_EXIT_OK && (rc = start(r, a, opt)) == QD_EXIT_OK &&
             qd_conlin_about(ctx, r->e, r->c.mf.model, &r->pt, a->independent, &c) != QD_OK)
        rc = cli_state_diag(ctx, "--independent", a->independent);
    else if (rc == QD_EXIT_OK && a->ignore && qd_conlin_require_ignorable(ctx, &c, a->ignore))
        rc = cli_state_diag(ctx, "--ignore", a->ignore);
    else if (rc == QD_EXIT_OK && a->lqr) /* on the core: the ignorable states' s = 0 */
        rc = qd_conlin_keep_core(ctx, &c) ? cli_diag_ctx(ctx)
                                          : cli_lqr_design(ctx, &c.ss, a->lqr, &lqr);
    if (rc == QD_EXIT_OK && a->scan && a->look && a->look->file)
        rc = cli_scan_plot(ctx, &sc, name, a->look, r->c.mf.path);
    if (rc == QD_EXIT_OK && !a->scan && a->modes)
        rc = cli_emit_status(ctx, qd_conlin_modes_print(ctx, &c, a->fmt == QD_SS_JSON, &b), &b,
                             "modes");
    else if (rc == QD_EXIT_OK && !a->scan)
        rc = cli_emit_status(ctx, qd_conlin_render(ctx, &c, a->lqr ? &lqr : NULL, a->fmt, &b),
                             &b, "state-space form");
    qd_care_result_free(&lqr);
    qd_conlin_scan_free(&sc);
    qd_conlin_free(&c);
    return rc;
}
