/*
 * src/linear/equilibria_text.c - the search `qdot equilibria` makes from
 * its options' text (qd_equilibria_find_text, qdot/equilibria.h): --guess
 * and --box read against the equations' coordinates (qdot/linpoint.h), over
 * the default box, then qd_equilibria_find.  The command line and Python's
 * Model.equilibria both call it, so both search the same places.
 */
#include "qdot/equilibria.h"
#include "qdot/linpoint.h"
#include "../base/args.h"
#include "../base/mem.h"

#include <string.h>

typedef struct box_arrays {
    double *q, *lo, *hi;
    bool *angle;
} box_arrays;

static qd_status arrays_new(qd_ctx *ctx, size_t n, box_arrays *a) {
    a->q = qd__calloc(ctx, n + 1, sizeof *a->q);
    a->lo = qd__calloc(ctx, n + 1, sizeof *a->lo);
    a->hi = qd__calloc(ctx, n + 1, sizeof *a->hi);
    a->angle = qd__calloc(ctx, n + 1, sizeof *a->angle);
    return a->q && a->lo && a->hi && a->angle ? QD_OK : QD_ERR_NOMEM;
}

static void arrays_free(box_arrays *a) {
    qd__free(a->q);
    qd__free(a->lo);
    qd__free(a->hi);
    qd__free(a->angle);
}

qd_status qd_equilibria_find_text(qd_ctx *ctx, const qd_linpoint *p, const char *guess,
                                  const char *box, qd_equilibria *out, const char **where) {
    QD_ARGS_CTX(ctx, ctx && p && p->e && p->m && out);
    memset(out, 0, sizeof *out);
    if (where)
        *where = NULL;
    box_arrays a = {0};
    qd_status st = arrays_new(ctx, p->e->n, &a);
    qd_equilibria_opts o = {.near = guess ? a.q : NULL, .lo = box ? a.lo : NULL,
                            .hi = box ? a.hi : NULL, .numeric_only = box != NULL};
    if (st == QD_OK)
        st = qd_equilibria_default_box(ctx, p->e, p->m, a.angle, a.lo, a.hi);
    if (st == QD_OK && guess && (st = qd_linpoint_read_coords(ctx, p, guess, a.q)) != QD_OK &&
        where)
        *where = guess;
    if (st == QD_OK && box && (st = qd_linpoint_read_box(ctx, p, box, a.lo, a.hi)) != QD_OK &&
        where)
        *where = box;
    if (st == QD_OK)
        st = qd_equilibria_find(ctx, p->e, p->m, p->st.n, p->st.syms, p->st.vals, &o, out);
    arrays_free(&a);
    return st;
}
