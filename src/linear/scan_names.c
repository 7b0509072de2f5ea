/*
 * src/linear/scan_names.c - the words of a steady motion's scan
 * (qd_stability_scan, qdot/stability.h): the names of its unknowns
 * u = (x, w, p), the columns of the table, and what the scan follows.
 */
#include "qdot/stability.h"

#include <stdio.h>

#include "../base/args.h"
#include "../base/mem.h"

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

/* The column names into one block of text, pointed to by names. */
static char *unknown_names(qd_ctx *ctx, const qd_steady *s, size_t nu, const char **names) {
    size_t len = 0;
    for (size_t k = 0; k < nu; k++)
        len += qd_steady_unknown_name(s, k, NULL, 0) + 1;
    char *text = qd__malloc(ctx, len + 1), *at = text;
    for (size_t k = 0; text && k < nu; k++) {
        names[k] = at;
        at += qd_steady_unknown_name(s, k, at, len + 1 - (size_t)(at - text)) + 1;
    }
    return text;
}

qd_status qd_stability_scan_write(qd_ctx *ctx, const qd_stability_problem *p, const char *param,
                                  const qd_scan *sc, bool json, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && p && p->s && param && sc && out);
    const qd_steady *s = p->s;
    size_t nu = s->nkeep + 2 * s->ncyc;
    const char **names = qd__calloc(ctx, nu + 1, sizeof *names);
    char *text = names ? unknown_names(ctx, s, nu, names) : NULL;
    qd_buf followed = QD_BUF_INIT;
    qd_status st = text ? qd_stability_scan_followed(s, sc->damped, &followed) : QD_ERR_NOMEM;
    qd_scan_view v = {param, names, qd_buf_str(&followed), "steady_motion"};
    if (st == QD_OK)
        st = json ? qd_scan_json(&v, sc, out) : qd_scan_print(&v, sc, out);
    qd_buf_free(&followed);
    qd__free(names);
    qd__free(text);
    return st;
}
