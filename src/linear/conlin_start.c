/*
 * src/linear/conlin_start.c - the point a command linearizes a constrained
 * model about (qd_conlin_start, qdot/conlin.h): the model's state and
 * --about, or, for holonomic constraints alone and no --about, the
 * equilibrium on them that `qdot modes` takes, so that `linearize` and
 * `modes` of one model speak of one point.
 */
#include "qdot/conlin.h"
#include "base/args.h"

#include <string.h>

qd_status qd_conlin_start(qd_ctx *ctx, const qd_eom *e, const qd_model *m, qd_linpoint *pt,
                          const char *about, qd_equilibrium_choice *choice) {
    QD_ARGS_CTX(ctx, ctx && e && m && pt && choice);
    memset(choice, 0, sizeof *choice);
    qd_status st = qd_conlin_point(ctx, m, pt, about);
    if (st != QD_OK || about || qd_conlin_needed(e))
        return st;
    /* at rest on holonomic constraints: the state a pendulum in x, y is analysed in is an
     * equilibrium, and the model's own state (often none: all 0) seldom is one */
    const qd_state *s = &pt->st;
    st = qd_equilibria_choose(ctx, e, m, s->n, s->syms, s->vals, choice);
    if (st == QD_OK && !choice->pt) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "no equilibrium found on the constraints (qdot "
                     "equilibria lists none): give a point with --about");
        return QD_ERR_NUMERIC;
    }
    if (st == QD_OK)
        qd_linpoint_set(pt, choice->pt->q, NULL);
    return st;
}
