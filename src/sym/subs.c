/*
 * src/sym/subs.c - simultaneous substitution.
 *
 * Rebuilds the DAG bottom-up through the canonical constructors, so the
 * result is canonical again (x*y with y -> 1/x gives 1).  Memoized: a shared
 * subexpression is rebuilt once.
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

static const qd_expr *subs_rec(qd_ctx *ctx, const qd_expr *e, qd_ptrmap *memo) {
    const qd_expr *r = qd_ptrmap_get(memo, e);
    if (r || !e->nargs)
        return r ? r : e;
    const qd_expr *stack[8];
    const qd_expr **args = e->nargs <= 8 ? stack : malloc(e->nargs * sizeof *args);
    if (!args) {
        qd__oom(ctx);
        return NULL;
    }
    bool changed = false;
    for (size_t i = 0; i < e->nargs; i++) {
        args[i] = subs_rec(ctx, e->args[i], memo);
        if (!args[i]) {
            r = NULL;
            goto done;
        }
        changed |= args[i] != e->args[i];
    }
    r = changed ? qd__rebuild(ctx, e, args) : e;
    if (r && !qd_ptrmap_put(memo, e, (void *)r)) {
        qd__oom(ctx);
        r = NULL;
    }
done:
    if (args != stack)
        free(args);
    return r;
}

const qd_expr *qd_subs(qd_ctx *ctx, const qd_expr *e, size_t n, const qd_expr *const *from,
                       const qd_expr *const *to) {
    if (!e)
        return NULL;
    qd_ptrmap memo = QD_PTRMAP_INIT;
    const qd_expr *r = e;
    for (size_t i = 0; i < n; i++) {
        if (!from[i] || !to[i]) {
            r = NULL;
            goto done;
        }
        if (!qd_ptrmap_put(&memo, from[i], (void *)to[i])) {
            qd__oom(ctx);
            r = NULL;
            goto done;
        }
    }
    r = subs_rec(ctx, e, &memo);
done:
    qd_ptrmap_free(&memo);
    return r;
}
