/*
 * src/linear/symmetry_method.c - which way the symmetry of small
 * oscillations is had (qd_symmetry_fast_cell, qdot/symmetry.h): the cyclic
 * fast path for a long ring of identical cells, else the group.
 */
#include "qdot/symmetry.h"
#include "../base/args.h"

#include <string.h>

size_t qd_symmetry_fast_cell(const qd_linear *lin) {
    QD_ARGS(0, lin);
    return lin->n >= QD_SYMMETRY_FAST_N ? qd_cyclic_cell(lin) : 0;
}

/* The group about the point, reduced; no symmetry (order 1) or a group
 * that cannot be had is a note, the plain modes standing. */
static qd_status group(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t nvals,
                       const qd_expr *const *syms, const double *vals, const qd_linear *lin,
                       qd_symmetry *sym, qd_buf *note) {
    qd_status st = qd_symmetry_find(ctx, e, m, nvals, syms, vals, lin, sym);
    if (st == QD_ERR_NOMEM)
        return st;
    if (st != QD_OK) {
        qd_buf_printf(note, "%s; the plain modes follow", qd_ctx_message(ctx));
        qd_ctx_clear_error(ctx);
        qd_symmetry_free(sym);
        return QD_OK;
    }
    if (sym->order <= 1) {
        qd_buf_puts(note, "the equilibrium has no symmetry (no operation but the identity "
                          "leaves M0 and K0 invariant); the plain modes follow");
        qd_symmetry_free(sym);
        return QD_OK;
    }
    return qd_symmetry_reduce(ctx, lin, sym);
}

qd_status qd_modes_symmetry(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t nvals,
                            const qd_expr *const *syms, const double *vals,
                            const qd_linear *lin, qd_symmetry *sym, qd_cyclic_modes *cyc,
                            qd_buf *note) {
    QD_ARGS_CTX(ctx, ctx && e && m && (nvals == 0 || (syms && vals)) && lin && sym && cyc &&
                         note);
    memset(sym, 0, sizeof *sym);
    memset(cyc, 0, sizeof *cyc);
    size_t cell = qd_symmetry_fast_cell(lin);
    qd_status st = cell ? qd_cyclic_solve(ctx, lin, cell, cyc)
                        : group(ctx, e, m, nvals, syms, vals, lin, sym, note);
    if (st == QD_OK && note->failed) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory writing the symmetry's note");
        st = QD_ERR_NOMEM;
    }
    return st;
}
