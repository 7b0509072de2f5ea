/*
 * src/linear/linpoint_eq.c - the equilibria asked for in text, --near and
 * --box of `qdot equilibria` (qd_linpoint_equilibria, qdot/linpoint.h): the
 * point and the box read against the equations' coordinates, then
 * qd_equilibria_find.
 */
#include "qdot/linpoint.h"
#include "qdot/equilibria.h"

#include <string.h>

#include "../base/args.h"
#include "../base/mem.h"

qd_status qd_linpoint_equilibria(qd_ctx *ctx, const qd_linpoint *p, const char *near,
                                 const char *box, const char **bad, qd_equilibria *out) {
    QD_ARGS_CTX(ctx, ctx && p && p->e && p->m && bad && out);
    memset(out, 0, sizeof *out);
    *bad = NULL;
    size_t n = p->e->n;
    double *q = qd__malloc(ctx, (n + 1) * sizeof *q), *lo = qd__malloc(ctx, (n + 1) * sizeof *lo);
    double *hi = qd__malloc(ctx, (n + 1) * sizeof *hi);
    bool *angle = qd__malloc(ctx, (n + 1) * sizeof *angle);
    qd_status st = q && lo && hi && angle ? QD_OK : QD_ERR_NOMEM;
    qd_equilibria_opts o = {.near = near ? q : NULL, .lo = box ? lo : NULL,
                            .hi = box ? hi : NULL, .numeric_only = box != NULL};
    if (st == QD_OK)
        st = qd_equilibria_default_box(ctx, p->e, p->m, angle, lo, hi);
    if (st == QD_OK && near && (st = qd_linpoint_read_coords(ctx, p, near, q)) != QD_OK)
        *bad = near;
    if (st == QD_OK && box && (st = qd_linpoint_read_box(ctx, p, box, lo, hi)) != QD_OK)
        *bad = box;
    if (st == QD_OK)
        st = qd_equilibria_find(ctx, p->e, p->m, p->st.n, p->st.syms, p->st.vals, &o, out);
    qd__free(q);
    qd__free(lo);
    qd__free(hi);
    qd__free(angle);
    return st;
}
