/*
 * src/num/inputs.c - the inputs of a compiled program: every free symbol
 * of a set of expressions, each once, in the order first met, for
 * qd_eom_compile (mech/eval.c), the singularity check (mech/singular.c)
 * and the linearization (linear/linearize.c).
 */
#include "num.h"

#include "base/ptrmap.h"
#include "qdot/expr.h"
#include "base/mem.h"

#include <stdlib.h>

static bool push_symbols(qd_ctx *ctx, const qd_expr *x, qd__ptrmap *seen, const qd_expr ***all,
                         size_t *len, size_t *cap) {
    size_t k = qd_free_symbols(ctx, x, NULL, 0);
    const qd_expr **syms = qd__malloc(ctx, (k ? k : 1) * sizeof *syms);
    if (!syms || qd_ctx_status(ctx) == QD_ERR_NOMEM) { /* 0 symbols may mean out of memory */
        qd__free(syms);
        return false;
    }
    qd_free_symbols(ctx, x, syms, k);
    if (qd__ctx_nomem(ctx)) { /* the second pass can run out too: syms unwritten */
        qd__free(syms);
        return false;
    }
    bool ok = true;
    for (size_t i = 0; ok && i < k; i++) {
        if (qd__ptrmap_has(seen, syms[i]))
            continue;
        if (*len == *cap) {
            *cap = *cap ? 2 * *cap : 16;
            const qd_expr **grown = qd__realloc(ctx, *all, *cap * sizeof *grown);
            ok = grown != NULL;
            *all = grown ? grown : *all;
        }
        ok = ok && qd__ptrmap_put(seen, syms[i], (void *)syms[i]);
        if (ok)
            (*all)[(*len)++] = syms[i];
    }
    qd__free(syms);
    return ok;
}

const qd_expr **qd__num_inputs(qd_ctx *ctx, size_t n, const qd_expr *const *exprs, size_t *nin) {
    qd__ptrmap seen = QD_PTRMAP_AL(qd__ctx_allocator(ctx));
    const qd_expr **all = NULL;
    size_t len = 0, cap = 0;
    bool ok = true;
    for (size_t i = 0; ok && i < n; i++)
        ok = push_symbols(ctx, exprs[i], &seen, &all, &len, &cap);
    qd__ptrmap_free(&seen);
    if (ok && !all)
        all = qd__malloc(ctx, sizeof *all);
    if (!ok || !all) {
        qd__free(all);
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory compiling the equations of motion");
        return NULL;
    }
    *nin = len;
    return all;
}
