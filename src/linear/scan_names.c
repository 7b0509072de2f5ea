/*
 * src/linear/scan_names.c - the words of a steady motion's scan
 * (qd_stability_scan, qdot/stability.h): the names of its unknowns
 * u = (x, w, p), the columns of the table, and what the scan follows.
 */
#include "qdot/stability.h"

#include <stdio.h>

#include "../base/args.h"

size_t qd_steady_unknown_name(const qd_steady *s, size_t k, char *out, size_t cap) {
    QD_ARGS(0, s && (out || !cap));
    size_t nk = s->nkeep, nc = s->ncyc;
    int len = 0;
    if (k < nk)
        len = snprintf(out, cap, "%s", qd_expr_name(s->keep[k]));
    else if (k < nk + nc)
        len = snprintf(out, cap, "%s'", qd_expr_name(s->cyc[k - nk]));
    else if (k < nk + 2 * nc)
        len = snprintf(out, cap, "p_%s", qd_expr_name(s->cyc[k - nk - nc]));
    else if (cap)
        out[0] = '\0';
    return len > 0 ? (size_t)len : 0;
}

qd_status qd_stability_scan_followed(const qd_steady *s, bool damped, qd_buf *out) {
    QD_ARGS(QD_ERR_ARG, s && out);
    qd_buf_printf(out, "the steady motion (%s); %s stability",
                  s->driven ? "rates maintained: V - T0" : "momenta free: Routhian",
                  damped ? "with the model's damping" : "ordinary");
    return out->failed ? QD_ERR_NOMEM : QD_OK;
}
