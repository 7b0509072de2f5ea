/*
 * src/codegen/block.c - what every generated function is made of (system.c,
 * for the equations in coordinates and in speeds alike): the symbols its
 * outputs use, each bound to a local constant read from an argument array
 * (the caller's cg_bind says where), then one qd_print_c_block assigning the
 * outputs, so that every subexpression they share is computed once.  The
 * rest of a file's frame (guards, name tables, the prefix check) is here too.
 */
#include "cg.h"
#include "base/mem.h"
#include "base/ptrmap.h"
#include "sym/node.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct walk {
    qd__ptrmap seen;
    const qd_expr **syms;
    size_t n, cap;
    const qd_expr *bad; /* a user function: it has no C definition */
    bool oom;
} walk;

static void collect(walk *w, const qd_expr *e) {
    if (w->oom || qd__ptrmap_has(&w->seen, e))
        return;
    if (!qd__ptrmap_put(&w->seen, e, (void *)e)) {
        w->oom = true;
        return;
    }
    if (e->kind == QD_UFUNC || e->kind == QD_UDERIV)
        w->bad = e;
    if (e->kind == QD_SYMBOL) {
        if (w->n == w->cap) {
            size_t cap = w->cap ? 2 * w->cap : 32;
            const qd_expr **v = qd__mem_realloc(w->seen.al, w->syms, cap * sizeof *v);
            if (!v) {
                w->oom = true;
                return;
            }
            w->syms = v;
            w->cap = cap;
        }
        w->syms[w->n++] = e;
    }
    for (size_t i = 0; i < e->nargs; i++)
        collect(w, e->args[i]);
}

typedef struct binding {
    const qd_expr *sym;
    cg_slot at;
} binding;

/* Declarations in the order of the arrays' names, then of the index: the
 * same text for the same equations, whatever order the walk met them in. */
static int binding_cmp(const void *pa, const void *pb) {
    const binding *a = pa, *b = pb;
    int c = strcmp(a->at.array, b->at.array);
    if (c)
        return c;
    return a->at.index < b->at.index ? -1 : a->at.index > b->at.index;
}

void qd__cg_indent(qd_buf *out, const char *text) {
    while (*text) {
        const char *nl = strchr(text, '\n');
        size_t len = nl ? (size_t)(nl - text) + 1 : strlen(text);
        qd_buf_puts(out, "    ");
        qd_buf_putn(out, text, len);
        text += len;
    }
}

qd_status qd__cg_block(qd_ctx *ctx, qd_buf *c, size_t nout, const qd_expr *const *out,
                       const char *const *lhs, cg_bind bind, void *data) {
    walk w = {QD_PTRMAP_AL(qd__ctx_allocator(ctx)), NULL, 0, 0, NULL, false};
    qd_buf text = QD_BUF_WITH(qd__ctx_allocator(ctx));
    for (size_t i = 0; i < nout; i++)
        collect(&w, out[i]);
    qd_status st = w.oom ? QD_ERR_NOMEM : QD_OK;
    if (st == QD_OK && w.bad) {
        qd_ctx_error(ctx, QD_ERR_ARG,
                     "cannot generate C: the user function '%s' has no definition",
                     qd_expr_name(w.bad));
        st = QD_ERR_ARG;
    }
    binding *vs = st == QD_OK ? qd__malloc(ctx, (w.n ? w.n : 1) * sizeof *vs) : NULL;
    if (st == QD_OK && !vs)
        st = QD_ERR_NOMEM;
    size_t nb = 0;
    for (size_t i = 0; i < w.n && st == QD_OK; i++) {
        cg_slot at = {NULL, 0};
        if (qd_symbol_role(w.syms[i]) == QD_ROLE_TIME)
            continue; /* t is every function's argument */
        st = bind(data, w.syms[i], &at);
        if (st == QD_OK && !at.array) {
            qd_ctx_error(ctx, QD_ERR_UNBOUND, "cannot generate C: '%s' has no value there",
                         qd_expr_name(w.syms[i]));
            st = QD_ERR_UNBOUND;
        }
        if (st == QD_OK)
            vs[nb++] = (binding){w.syms[i], at};
    }
    if (st == QD_OK) {
        qsort(vs, nb, sizeof *vs, binding_cmp);
        for (size_t i = 0; i < nb; i++) {
            qd_buf_puts(c, "    const double ");
            qd_c_name(vs[i].sym, c);
            qd_buf_printf(c, " = %s[%zu];\n", vs[i].at.array, vs[i].at.index);
        }
        st = qd_print_c_block(ctx, nout, out, lhs, &text);
        if (st == QD_OK)
            qd__cg_indent(c, qd_buf_str(&text));
    }
    qd_buf_free(&text);
    if (st == QD_ERR_NOMEM)
        qd__oom(ctx);
    qd__ptrmap_free(&w.seen);
    qd__free(w.syms);
    qd__free(vs);
    return st;
}

qd_status qd__cg_block_to(qd_ctx *ctx, qd_buf *c, size_t nout, const qd_expr *const *out,
                          const char *array, size_t offset, cg_bind bind, void *data) {
    char(*names)[48] = qd__malloc(ctx, (nout + 1) * sizeof *names);
    const char **lhs = qd__malloc(ctx, (nout + 1) * sizeof *lhs);
    qd_status st = names && lhs ? QD_OK : QD_ERR_NOMEM;
    if (st == QD_OK) {
        qd__cg_lhs_names(names, lhs, array, offset, nout);
        st = qd__cg_block(ctx, c, nout, out, lhs, bind, data);
    } else
        qd__oom(ctx);
    qd__free(names);
    qd__free(lhs);
    return st;
}

void qd__cg_lhs_names(char (*names)[48], const char **lhs, const char *array, size_t offset,
                      size_t count) {
    for (size_t i = 0; i < count; i++) {
        snprintf(names[i], sizeof names[i], "%s[%zu]", array, offset + i);
        lhs[i] = names[i];
    }
}

void qd__cg_unused(qd_buf *c, const char *names) {
    qd_buf_printf(c, "    (void)t;\n    (void)qd_par;\n%s", names);
}

void qd__cg_guard(qd_buf *h, const char *P, bool open) {
    if (!open) {
        qd_buf_puts(h, "\n#ifdef __cplusplus\n}\n#endif\n#endif\n");
        return;
    }
    for (int k = 0; k < 2; k++) {
        qd_buf_puts(h, k ? "_H\n#define " : "#ifndef ");
        for (const char *p = P; *p; p++)
            qd_buf_printf(h, "%c", toupper((unsigned char)*p));
    }
    qd_buf_puts(h, "_H\n\n#ifdef __cplusplus\nextern \"C\" {\n#endif\n\n");
}

void qd__cg_name_list(qd_buf *c, const char *P, const char *what, size_t n,
                      const qd_expr *const *syms) {
    qd_buf_printf(c, "const char *const %s_%s_names[] = {", P, what);
    for (size_t i = 0; i < n; i++)
        qd_buf_printf(c, "\"%s\", ", qd_expr_name(syms[i]));
    qd_buf_puts(c, "0};\n");
}

qd_status qd__cg_prefix(qd_ctx *ctx, const char *prefix) {
    if (prefix && qd_codegen_prefix_valid(prefix))
        return QD_OK;
    qd_ctx_error(ctx, QD_ERR_ARG, "the prefix '%s' is not a C identifier", prefix ? prefix : "");
    return QD_ERR_ARG;
}
