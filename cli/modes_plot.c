/*
 * cli/modes_plot.c - `qdot modes --plot FILE`: the mode shapes drawn
 * (qd_modes_plot, qdot/modes.h), the picture's options applied
 * (qd_plot_apply) and written to FILE.
 */
#include "modes_plot.h"

#include "cli.h"
#include "qdot/plot.h"

/* Panel j (mode j of the symmetry's) notes its irrep, "A1", "E". */
static qd_status note_irreps(qd_plot *p, const qd_symmetry *s) {
    qd_status st = QD_OK;
    for (size_t j = 0; j < s->n && j < qd_plot_npanels(p) && st == QD_OK; j++) {
        st = qd_plot_select(p, j);
        if (st == QD_OK)
            st = qd_plot_set_note(p, s->label[s->block_irrep[s->mode_block[j]]]);
    }
    return st;
}

int cli_modes_plot(cli_lin_run *lr, const double *q0, const qd_modes_result *res,
                   const cli_plot_args *look, const char *title, const cli_sym_run *sym) {
    if (!res->conservative || !res->shapes)
        return cli_usage_error("modes --plot draws mode shapes, which a system with damping or "
                               "gyroscopic terms does not have (its modes are complex)");
    /* the symmetry's modes, ordered and paired as its irreps are (the cyclic
     * fast path's harmonics are not a point group's: plain modes there) */
    bool irreps = sym->active && sym->sym.order > 1 && sym->sym.omega2;
    qd_modes_result by_sym = *res;
    if (irreps) {
        by_sym.omega2 = sym->sym.omega2;
        by_sym.shapes = sym->sym.shapes;
    }
    qd_linpoint_set(&lr->pt, q0, NULL);
    qd_plot_run_opts o = cli_plot_opts(look, title);
    qd_plot *p = NULL;
    qd_status st = qd_modes_plot(lr->c.ctx, lr->e, lr->c.mf.model, lr->pt.st.n, lr->pt.st.syms,
                                 lr->pt.st.vals, &by_sym, o.title, &p);
    if (st == QD_OK && irreps && qd_plot_npanels(p) == res->n)
        st = note_irreps(p, &sym->sym);
    if (st == QD_OK)
        st = qd_plot_apply(p, &o);
    if (st == QD_OK)
        st = qd_plot_write(p, look->file);
    qd_plot_free(p);
    if (st == QD_OK)
        return QD_EXIT_OK;
    return qd_ctx_status(lr->c.ctx) != QD_OK ? cli_diag_ctx(lr->c.ctx) : QD_EXIT_FAIL;
}
