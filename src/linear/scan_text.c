/*
 * src/linear/scan_text.c - `qdot modes --scan NAME=A:B [--about ...]` from
 * its options' text (qd_modes_scan_text, qdot/modes.h): the range and the
 * point read against the equations' coordinates, qd_modes_scan, and the
 * scan written as the command writes it.  The command line and Python's
 * Model.modes(scan=...) both call it.
 */
#include "qdot/modes.h"
#include "qdot/linpoint.h"
#include "qdot/state.h"
#include "../base/args.h"
#include "../base/mem.h"

#include <stdio.h>
#include <string.h>

/* The scan read and run: *where names the text an error is located in. */
static qd_status scan(qd_ctx *ctx, const qd_linpoint *p, const char *range, const char *about,
                      size_t steps, char *name, size_t cap, const qd_expr **ab, qd_scan *sc,
                      const char **where) {
    double a, b;
    qd_status st = qd_state_named_range(ctx, NULL, range, name, cap, &a, &b);
    if (st != QD_OK) {
        *where = range;
        return st;
    }
    if (about && (st = qd_linpoint_read_exact(ctx, p, about, ab)) != QD_OK) {
        *where = about;
        return st;
    }
    qd_scan_opts o = {.steps = steps, .about = about ? ab : NULL};
    return qd_modes_scan(ctx, p->e, p->m, name, a, b, &o, sc);
}

qd_status qd_modes_scan_text(qd_ctx *ctx, const qd_linpoint *p, const char *range,
                             const char *about, size_t steps, bool json, qd_buf *out,
                             const char **where) {
    QD_ARGS_CTX(ctx, ctx && p && p->e && p->m && range && out);
    const char *at = NULL;
    char name[128], followed[1024];
    size_t n = p->e->n;
    const qd_expr **ab = qd__calloc(ctx, n + 1, sizeof *ab);
    const char **names = qd__calloc(ctx, n + 1, sizeof *names);
    qd_scan sc = {0};
    qd_status st = ab && names ? scan(ctx, p, range, about, steps, name, sizeof name, ab, &sc, &at)
                               : QD_ERR_NOMEM;
    if (st == QD_OK) {
        snprintf(followed, sizeof followed, about ? "the equilibrium from %s" : "%s",
                 about ? about : "the equilibrium chosen at the start (as `qdot modes` does)");
        for (size_t j = 0; j < n; j++)
            names[j] = qd_expr_name(p->e->q[j]);
        qd_scan_view v = {name, names, followed, "equilibrium"};
        st = json ? qd_scan_json(&v, &sc, out) : qd_scan_print(&v, &sc, out);
        if (st != QD_OK)
            qd_ctx_error(ctx, st, "cannot print the scan: %s",
                         out->failed ? "out of memory" : "a number JSON cannot hold");
    }
    if (where)
        *where = at;
    qd_scan_free(&sc);
    qd__free(ab);
    qd__free(names);
    return st;
}

/* The slot of syms named name that a scan may follow: a parameter, a
 * coordinate or a speed (not t). */
static const qd_expr *scan_slot(size_t nvals, const qd_expr *const *syms, const char *name) {
    const qd_expr *what = NULL;
    for (size_t k = 0; k < nvals; k++)
        if (syms[k] && !strcmp(qd_expr_name(syms[k]), name) &&
            qd_symbol_role(syms[k]) != QD_ROLE_TIME)
            what = syms[k];
    return what;
}

qd_status qd_speeds_modes_scan_text(qd_ctx *ctx, const struct qd_speeds_eom *e, size_t nvals,
                                    const qd_expr *const *syms, const double *vals,
                                    const char *range, const char *about, size_t steps,
                                    bool json, qd_buf *out, const char **where) {
    QD_ARGS_CTX(ctx, ctx && e && nvals && syms && vals && range && out);
    if (where)
        *where = NULL;
    char name[128], followed[1024];
    double a, b;
    qd_status st = qd_state_named_range(ctx, NULL, range, name, sizeof name, &a, &b);
    const qd_expr *what = st == QD_OK ? scan_slot(nvals, syms, name) : NULL;
    if (st == QD_OK && !what) {
        qd_ctx_error(ctx, QD_ERR_ARG, "%s is not a parameter, coordinate or speed of the model",
                     name);
        st = QD_ERR_ARG;
    }
    if (st != QD_OK) {
        if (where)
            *where = range;
        return st;
    }
    qd_scan_opts o = {.steps = steps};
    qd_scan sc = {0};
    st = qd_speeds_modes_scan(ctx, e, nvals, syms, vals, what, a, b, &o, &sc);
    if (st == QD_OK) {
        snprintf(followed, sizeof followed, "the state %s",
                 about ? about : "of the first equilibrium (every speed 0)");
        qd_scan_view v = {name, NULL, followed, "state"};
        st = json ? qd_scan_json(&v, &sc, out) : qd_scan_print(&v, &sc, out);
        if (st != QD_OK)
            qd_ctx_error(ctx, st, "cannot print the scan: %s",
                         out->failed ? "out of memory" : "a number JSON cannot hold");
    }
    qd_scan_free(&sc);
    return st;
}
