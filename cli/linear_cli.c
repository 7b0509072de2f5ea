/*
 * cli/linear_cli.c - what `qdot equilibria` and `qdot modes` share (see
 * linear_cli.h): loading, deriving with the holonomic constraints
 * eliminated, and the options read against the equations' coordinates by
 * the library (qdot/linpoint.h), their errors shown under their text.
 */
#include "linear_cli.h"

#include "eom_out.h"
#include "model_cli.h"

int cli_lin_load_model(cli_lin_run *r, const char *file, const char *const *sets,
                       size_t nsets) {
    return cli_load(r->c.ctx, file, nsets, sets, "modes", &r->c.mf);
}

int cli_lin_load(cli_lin_run *r, const char *file, const char *const *sets, size_t nsets) {
    int rc = cli_lin_load_model(r, file, sets, nsets);
    return rc == QD_EXIT_OK ? cli_lin_derive(r) : rc;
}

int cli_lin_derive(cli_lin_run *r) {
    qd_eom_opts opts = {.eliminate = true};
    if (!(r->e = qd_eom_derive_opts(r->c.ctx, r->c.mf.model, &opts)))
        return cli_eom_derive_error(r->c.ctx, &r->c.mf);
    return cli_lin_setup(r);
}

int cli_lin_setup(cli_lin_run *r) {
    if (qd_linpoint_init(r->c.ctx, r->c.mf.model, r->e, &r->pt) != QD_OK)
        return cli_diag_ctx(r->c.ctx);
    return QD_EXIT_OK;
}

void cli_lin_free(cli_lin_run *r) {
    qd_linpoint_free(&r->pt);
    qd_eom_free(r->e);
    r->e = NULL;
    cli_model_file_free(&r->c.mf);
}

int cli_lin_point(cli_lin_run *r, const char *what, const char *text, double *q, double *qd) {
    qd_status st = qd ? qd_linpoint_read(r->c.ctx, &r->pt, text, q, qd)
                      : qd_linpoint_read_coords(r->c.ctx, &r->pt, text, q);
    return st == QD_OK ? QD_EXIT_OK : cli_state_diag(r->c.ctx, what, text);
}

/* The library's search from the options (qd_equilibria_find_text). */
int cli_lin_equilibria(cli_lin_run *r, const char *guess, const char *box, qd_equilibria *out) {
    const char *where = NULL;
    qd_ctx *ctx = r->c.ctx;
    if (qd_equilibria_find_text(ctx, &r->pt, guess, box, out, &where) == QD_OK)
        return QD_EXIT_OK;
    if (where)
        return cli_state_diag(ctx, where == guess ? "--guess" : "--box", where);
    cli_diag_error("%s", qd_ctx_message(ctx));
    /* a constraint the manifold search does not take (with t, with velocities) */
    return qd_ctx_status(ctx) == QD_ERR_UNSUPPORTED ? QD_EXIT_USAGE : QD_EXIT_FAIL;
}
