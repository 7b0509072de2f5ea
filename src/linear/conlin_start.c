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

/* One name of list at *i (commas and spaces between), its length in *len. */
static size_t next_name(const char *list, size_t *i, size_t *len) {
    while (list[*i] == ',' || list[*i] == ' ' || list[*i] == '\t')
        (*i)++;
    size_t s = *i;
    while (list[*i] && list[*i] != ',' && list[*i] != ' ' && list[*i] != '\t')
        (*i)++;
    *len = *i - s;
    return s;
}

qd_status qd_conlin_require_ignorable(qd_ctx *ctx, const qd_conlin *c, const char *names) {
    QD_ARGS_CTX(ctx, ctx && c && names && (c->zsym || !c->n));
    size_t i = 0, len = 0, count = 0;
    for (size_t s = next_name(names, &i, &len); len; s = next_name(names, &i, &len), count++) {
        size_t k = 0, j = c->nx;
        while (k < c->n && (strlen(qd_expr_name(c->zsym[k])) != len ||
                            strncmp(qd_expr_name(c->zsym[k]), names + s, len)))
            k++;
        for (size_t x = 0; k < c->n && x < c->nx; x++)
            if (c->indep[x] == k)
                j = x;
        if (k < c->n && j < c->nx && c->ignorable[j])
            continue;
        if (k == c->n)
            qd_ctx_error(ctx, QD_ERR_ARG, "'%.*s' is no coordinate of the equations", (int)len,
                         names + s);
        else if (j == c->nx)
            qd_ctx_error(ctx, QD_ERR_ARG, "'%.*s' is dependent on the constraint manifold, "
                         "not a cyclic coordinate", (int)len, names + s);
        else
            qd_ctx_error(ctx, QD_ERR_ARG, "'%.*s' is not cyclic at this steady motion: the "
                         "rates of other states depend on it (the ignorable states are those "
                         "no other rate depends on)", (int)len, names + s);
        qd_ctx_error_at(ctx, names, s, len);
        return QD_ERR_ARG;
    }
    if (!count) {
        qd_ctx_error(ctx, QD_ERR_ARG, "no coordinate named");
        qd_ctx_error_at(ctx, names, 0, strlen(names));
        return QD_ERR_ARG;
    }
    return QD_OK;
}
