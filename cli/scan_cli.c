/*
 * cli/scan_cli.c - `qdot modes FILE --scan NAME=A:B`: the equilibrium
 * followed along a parameter (qd_modes_scan) and the values where its
 * stability changes, as a table (text) or samples and `transitions`
 * (JSON).  The --about point may be written in the parameters
 * (x = 1/2 - mu): it is kept as expressions and evaluated at each value.
 */
#include "linear_cli.h"

#include <stdlib.h>
#include <string.h>
#include "qdot/state.h"
#include "model_cli.h"

/* ---- reading --------------------------------------------------------------- */

int cli_scan_range(qd_ctx *ctx, const char *text, char *name, size_t cap, double *a,
                   double *b) {
    if (qd_state_named_range(ctx, NULL, text, name, cap, a, b) != QD_OK)
        return cli_state_diag(ctx, "--scan", text);
    return QD_EXIT_OK;
}

/* ---- the command ------------------------------------------------------------------- */

int cli_scan_emit(const cli_scan_view *v, const qd_scan *sc, bool json) {
    qd_buf out = QD_BUF_INIT;
    if ((json ? qd_scan_json(v, sc, &out) : qd_scan_print(v, sc, &out)) != QD_OK) {
        cli_diag_error("cannot print the scan: %s", out.failed ? "out of memory"
                                                                : "a number JSON cannot hold");
        qd_buf_free(&out);
        return QD_EXIT_FAIL;
    }
    return cli_emit(&out, "scan");
}

int cli_scan_modes(cli_lin_run *r, const char *range, const char *about, size_t steps, bool json) {
    char name[128];
    double a, b;
    int rc = cli_scan_range(r->c.ctx, range, name, sizeof name, &a, &b);
    const qd_expr **ab = NULL;
    const char **names = calloc(r->e->n + 1, sizeof *names);
    if (!names)
        rc = QD_EXIT_FAIL;
    if (rc == QD_EXIT_OK && about) {
        ab = calloc(r->e->n + 1, sizeof *ab);
        rc = !ab ? cli_out_of_memory()
             : qd_linpoint_read_exact(r->c.ctx, &r->pt, about, ab) == QD_OK
                 ? QD_EXIT_OK
                 : cli_state_diag(r->c.ctx, "--about", about);
    }
    qd_scan_opts o = {.steps = steps, .about = ab};
    qd_scan sc = {0};
    if (rc == QD_EXIT_OK &&
        qd_modes_scan(r->c.ctx, r->e, r->c.mf.model, name, a, b, &o, &sc) != QD_OK) {
        rc = cli_exit(qd_ctx_status(r->c.ctx));
        cli_diag_error("--scan: %s", qd_ctx_message(r->c.ctx));
    } else if (rc == QD_EXIT_OK) {
        char followed[1024];
        snprintf(followed, sizeof followed, about ? "the equilibrium from %s" : "%s",
                 about ? about : "the equilibrium chosen at the start (as `qdot modes` does)");
        for (size_t j = 0; j < r->e->n; j++)
            names[j] = qd_expr_name(r->e->q[j]);
        cli_scan_view v = {name, names, followed, "equilibrium"};
        rc = cli_scan_emit(&v, &sc, json);
    }
    qd_scan_free(&sc);
    free(ab);
    free(names);
    return rc;
}
