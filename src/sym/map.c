/*
 * src/sym/map.c - the bottom-up rewrite every DAG transformation shares.
 *
 * Substitution, trigsimp and factor_terms all rebuild an expression from its
 * leaves up: arguments first, the node again through its constructor when an
 * argument changed (so the result is canonical), then an optional rewrite of
 * the rebuilt node.  The memo maps each node to its result, so a shared
 * subexpression is done once; a caller may seed it (substitution puts its
 * from -> to pairs there).
 */
#include "node.h"

#include <stdlib.h>

/* Rebuild e with new arguments through the constructor of its kind. */
const qd_expr *qd__rebuild(qd_ctx *ctx, const qd_expr *e, const qd_expr *const *args) {
    switch ((qd_kind)e->kind) {
    case QD_ADD: return qd_add_n(ctx, e->nargs, args);
    case QD_MUL: return qd_mul_n(ctx, e->nargs, args);
    case QD_POW: return qd_pow(ctx, args[0], args[1]);
    case QD_FUNC:
        return e->tag == QD_ATAN2 ? qd_fn2(ctx, QD_ATAN2, args[0], args[1])
                                  : qd_fn(ctx, (qd_func)e->tag, args[0]);
    case QD_UFUNC: return qd_ufunc(ctx, e->u.fn.name, e->nargs, args);
    case QD_UDERIV:
        return qd_uderiv(ctx, e->u.fn.name, e->u.fn.nslots, e->u.fn.slots, e->nargs, args);
    default: return e;
    }
}

const qd_expr *qd__map(qd_ctx *ctx, const qd_expr *e, qd__ptrmap *memo, qd__post_fn post,
                       void *data) {
    const qd_expr *r = qd__ptrmap_get(memo, e);
    if (r || !e->nargs)
        return r ? r : e;
    const qd_expr *stack[8];
    const qd_expr **args = e->nargs <= 8 ? stack : qd__malloc(ctx, e->nargs * sizeof *args);
    if (!args) {
        qd__oom(ctx);
        return NULL;
    }
    bool changed = false;
    for (size_t i = 0; i < e->nargs; i++) {
        args[i] = qd__map(ctx, e->args[i], memo, post, data);
        if (!args[i])
            goto done;
        changed |= args[i] != e->args[i];
    }
    r = changed ? qd__rebuild(ctx, e, args) : e;
    if (r && post)
        r = post(ctx, r, data);
    if (r && !qd__ptrmap_put(memo, e, (void *)r)) {
        qd__oom(ctx);
        r = NULL;
    }
done:
    if (args != stack)
        qd__free(args);
    return r;
}
