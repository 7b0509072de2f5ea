/*
 * cli/modes_plot.c - `qdot modes --plot FILE`: the mode shapes drawn
 * (qd_symmetry_modes_plot, qdot/symmetry.h), the picture's options applied
 * (qd_plot_apply) and written to FILE.
 */
#include "modes_plot.h"

#include "cli.h"
#include "qdot/plot.h"

int cli_modes_plot(cli_lin_run *lr, const double *q0, const qd_modes_result *res,
                   const cli_plot_args *look, const char *title, const cli_sym_run *sym) {
    if (!res->conservative || !res->shapes)
        return cli_usage_error("modes --plot draws mode shapes, which a system with damping or "
                               "gyroscopic terms does not have (its modes are complex)");
    qd_linpoint_set(&lr->pt, q0, NULL);
    qd_plot_run_opts o = cli_plot_opts(look, title);
    qd_plot *p = NULL; /* with --symmetry, a point group's modes with their irreps */
    qd_status st = qd_symmetry_modes_plot(lr->c.ctx, lr->e, lr->c.mf.model, lr->pt.st.n,
                                          lr->pt.st.syms, lr->pt.st.vals, res,
                                          sym->active ? &sym->sym : NULL, o.title, &p);
    if (st == QD_OK)
        st = qd_plot_apply(p, &o);
    if (st == QD_OK)
        st = qd_plot_write(p, look->file);
    qd_plot_free(p);
    if (st == QD_OK)
        return QD_EXIT_OK;
    return qd_ctx_status(lr->c.ctx) != QD_OK ? cli_diag_ctx(lr->c.ctx) : QD_EXIT_FAIL;
}
