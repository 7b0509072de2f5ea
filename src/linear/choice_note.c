/*
 * src/linear/choice_note.c - the automatic choice of an equilibrium said in
 * one line (qd_equilibrium_choice_note, qdot/equilibria.h): which point,
 * why, and how many others were found; `qdot modes` writes it as a note.
 */
#include "qdot/equilibria.h"
#include "qdot/print.h"
#include "../base/args.h"

qd_status qd_equilibrium_choice_note(const qd_eom *e, const qd_equilibrium_choice *c,
                                     qd_buf *out) {
    QD_ARGS(QD_ERR_ARG, e && c && out);
    if (!c->pt || (c->found.count && c->found.n != e->n))
        return QD_ERR_ARG;
    for (size_t j = 0; j < e->n; j++) {
        qd_buf_printf(out, "%s%s = ", j ? ", " : "", qd_expr_name(e->q[j]));
        qd_buf_put_result(out, c->pt->q[j], 1);
    }
    qd_buf_printf(out, ", %s", qd_eq_chosen_name(c->reason));
    if (c->others)
        qd_buf_printf(out, "; %zu other equilibri%s found%s", c->others,
                      c->others == 1 ? "um" : "a", c->found.continuum ? ", not isolated" : "");
    return out->failed ? QD_ERR_NOMEM : QD_OK;
}
