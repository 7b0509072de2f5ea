/*
 * cli/cmd_field.c - `qdot eom` and `qdot modes` on a field model
 * (`field y(x, t) on x = A .. B`, qdot/field.h): the field equation of the
 * Lagrangian density, and the normal modes (closed form for constant
 * coefficients, else finite elements with the error estimate).
 */
#include "cli.h"

#include <stdio.h>
#include "model_cli.h"

/* The printer's answer: written, or why not (a non-finite number, memory). */
static int emit(qd_ctx *ctx, qd_status st, qd_buf *b, const char *what) {
    if (st != QD_OK) {
        cli_diag_error("cannot print the %s: %s", what, qd_ctx_message(ctx));
        qd_buf_free(b);
        return QD_EXIT_FAIL;
    }
    return cli_emit(b, what);
}

int cli_field_eom(qd_ctx *ctx, cli_model_file *mf, const char *file, size_t nsets,
                  const char *const *sets, bool json) {
    int rc = cli_load_field(ctx, file, nsets, sets, mf);
    const qd_expr *e = rc == QD_EXIT_OK ? qd_field_equation(ctx, mf->field) : NULL;
    if (rc == QD_EXIT_OK && !e)
        rc = cli_diag_ctx(ctx);
    if (e) {
        qd_buf b = QD_BUF_INIT;
        rc = emit(ctx, json ? qd_field_equation_json(ctx, mf->field, e, &b)
                       : qd_field_equation_print(ctx, mf->field, e, &b),
                  &b, "field equation");
    }
    return rc;
}

/* The library's reason, shown at the Ldensity statement (a bad input: 2). */
static int density_error(qd_ctx *ctx, const cli_model_file *mf) {
    if (qd_ctx_status(ctx) != QD_ERR_ARG)
        return cli_diag_ctx(ctx);
    qd_diag d;
    if (!qd_model_where(qd_field_model(mf->field), "Ldensity", &d))
        return cli_diag_ctx(ctx);
    snprintf(d.message, sizeof d.message, "%s", qd_ctx_message(ctx));
    snprintf(d.hint, sizeof d.hint, "the modes need Ldensity = rho/2*y_t^2 - tau/2*y_x^2 "
             "- kappa/2*y^2 with rho, tau, kappa functions of the space variable");
    cli_diag_show(mf->path, mf->text, &d);
    return QD_EXIT_USAGE;
}

int cli_field_modes(qd_ctx *ctx, cli_model_file *mf, const char *file, size_t nsets,
                    const char *const *sets, size_t count, double tol, bool json) {
    qd_field_modes r = {0};
    int rc = cli_load_field(ctx, file, nsets, sets, mf);
    qd_field_modes_opts o = {.count = count, .tol = tol};
    if (rc == QD_EXIT_OK && qd_field_modes_compute(ctx, mf->field, &o, &r) != QD_OK)
        rc = density_error(ctx, mf);
    if (rc == QD_EXIT_OK) {
        qd_buf b = QD_BUF_INIT;
        rc = emit(ctx, json ? qd_field_modes_json(ctx, mf->field, &r, &b)
                       : qd_field_modes_print(ctx, mf->field, &r, &b),
                  &b, "modes");
        if (rc == QD_EXIT_OK && !r.converged) {
            cli_diag_error("the modes did not converge to --tol on %zu elements: the estimates "
                           "are printed; ask for fewer modes or a larger tolerance", r.elements);
            rc = QD_EXIT_FAIL;
        }
    }
    qd_field_modes_free(&r);
    return rc;
}
