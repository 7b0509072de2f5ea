/*
 * src/sym/subs.c - simultaneous substitution.
 *
 * Rebuilds the DAG bottom-up through the canonical constructors, so the
 * result is canonical again (x*y with y -> 1/x gives 1).  Memoized: a shared
 * subexpression is rebuilt once.
 */
#include "node.h"
#include "../base/args.h"

#include <stdlib.h>

const qd_expr *qd_subs(qd_ctx *ctx, const qd_expr *e, size_t n, const qd_expr *const *from,
                       const qd_expr *const *to) {
    QD_ARGS(NULL, ctx && e && (n == 0 || from) && (n == 0 || to));
    if (!e)
        return NULL;
    qd__ptrmap memo = QD_PTRMAP_AL(qd__ctx_allocator(ctx));
    const qd_expr *r = e;
    for (size_t i = 0; i < n; i++) {
        if (!from[i] || !to[i]) {
            r = NULL;
            goto done;
        }
        if (!qd__ptrmap_put(&memo, from[i], (void *)to[i])) {
            qd__oom(ctx);
            r = NULL;
            goto done;
        }
    }
    r = qd__map(ctx, e, &memo, NULL, NULL);
done:
    qd__ptrmap_free(&memo);
    return r;
}
