/*
 * src/linear/modes_plot_sym.c - the mode shapes drawn with a symmetry
 * (qd_symmetry_modes_plot, qdot/symmetry.h): the reduced modes in their
 * irreps' order, each panel noting its irrep (`qdot modes --plot
 * --symmetry`).
 */
#include "qdot/symmetry.h"
#include "qdot/plot.h"
#include "../base/args.h"

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

qd_status qd_symmetry_modes_plot(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t nvals,
                                 const qd_expr *const *syms, const double *vals,
                                 const qd_modes_result *res, const qd_symmetry *sym,
                                 const char *title, qd_plot **out) {
    QD_ARGS_CTX(ctx, ctx && e && m && res && out && (syms || !nvals) && (vals || !nvals));
    bool irreps = sym && sym->order > 1 && sym->omega2;
    qd_modes_result by_sym = *res;
    if (irreps) {
        by_sym.omega2 = sym->omega2;
        by_sym.shapes = sym->shapes;
    }
    qd_status st = qd_modes_plot(ctx, e, m, nvals, syms, vals, &by_sym, title, out);
    if (st == QD_OK && irreps && qd_plot_npanels(*out) == res->n)
        st = note_irreps(*out, sym);
    if (st != QD_OK) {
        qd_plot_free(*out);
        *out = NULL;
    }
    return st;
}
