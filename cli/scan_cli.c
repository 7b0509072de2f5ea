/*
 * cli/scan_cli.c - `qdot modes FILE --scan NAME=A:B`: the equilibrium
 * followed along a parameter (qd_modes_scan) and the values where its
 * stability changes, as a table (text) or samples and `transitions`
 * (JSON).  The --about point may be written in the parameters
 * (x = 1/2 - mu): it is kept as expressions and evaluated at each value.
 */
#include "linear_cli.h"

#include "qdot/scanplot.h"
#include "qdot/state.h"
#include "model_cli.h"
#include "plot_cli.h"

/* ---- reading --------------------------------------------------------------- */

int cli_scan_range(qd_ctx *ctx, const char *text, char *name, size_t cap, double *a,
                   double *b) {
    if (qd_state_named_range(ctx, NULL, text, name, cap, a, b) != QD_OK)
        return cli_state_diag(ctx, "--scan", text);
    return QD_EXIT_OK;
}

/* ---- the picture ---------------------------------------------------------------- */

int cli_scan_plot(qd_ctx *ctx, const struct qd_conlin_scan *sc, const char *name,
                  const struct cli_plot_args *look, const char *model_path) {
    qd_plot_run_opts o = cli_plot_opts(look, model_path);
    qd_plot *p = NULL;
    qd_status st = qd_conlin_scan_plot(ctx, sc, name, o.title, &p);
    if (st == QD_OK)
        st = qd_plot_apply(p, &o);
    if (st == QD_OK)
        st = qd_plot_write(p, look->file);
    qd_plot_free(p);
    if (st == QD_OK)
        return QD_EXIT_OK;
    return qd_ctx_status(ctx) != QD_OK ? cli_diag_ctx(ctx) : QD_EXIT_FAIL;
}

/* ---- the command ------------------------------------------------------------------- */

/* The library's scan from the options (qd_modes_scan_text). */
int cli_scan_modes(cli_lin_run *r, const char *range, const char *about, size_t steps, bool json) {
    const char *where = NULL;
    qd_ctx *ctx = r->c.ctx;
    qd_buf out = QD_BUF_INIT;
    if (qd_modes_scan_text(ctx, &r->pt, range, about, steps, json, &out, &where) == QD_OK)
        return cli_emit(&out, "scan");
    qd_buf_free(&out);
    if (where)
        return cli_state_diag(ctx, where == range ? "--scan" : "--about", where);
    cli_diag_error("--scan: %s", qd_ctx_message(ctx));
    return cli_exit(qd_ctx_status(ctx));
}
