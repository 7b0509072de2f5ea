/*
 * src/render/outputs.c - the results of the C and SymPy renderings of a
 * whole system, described as parts (render.h): the C block that assigns
 * them all, its inputs line, and the SymPy functions they use.  eom.c
 * (M q'' = f) and speeds.c (q' = W u + w, M_u u' = f_u) differ in which
 * parts they list, not in how a part is written.
 */
#include "render.h"

#include <stdio.h>
#include "qdot/json.h"
#include "../base/mem.h"

static size_t part_size(const qd__render_part *p) {
    return p->rank == 0 ? 1 : p->rank == 1 ? p->rows : p->rows * p->cols;
}

/* "name", "name[i]" or "name[i][j]" for entry k of p. */
static void part_name(const qd__render_part *p, size_t k, char *out, size_t cap) {
    if (p->rank == 2)
        snprintf(out, cap, "%s[%zu][%zu]", p->name, k / p->cols, k % p->cols);
    else if (p->rank == 1)
        snprintf(out, cap, "%s[%zu]", p->name, k);
    else
        snprintf(out, cap, "%s", p->name);
}

/* Every part's expressions in order, in one array (qd__free it); *n their
 * count.  NULL for want of memory. */
static const qd_expr **flatten(qd_ctx *ctx, size_t nparts, const qd__render_part *parts,
                               size_t *n) {
    *n = 0;
    for (size_t i = 0; i < nparts; i++)
        *n += parts[i].x ? part_size(&parts[i]) : 0;
    const qd_expr **all = qd__malloc(ctx, (*n + 1) * sizeof *all);
    size_t k = 0;
    for (size_t i = 0; all && i < nparts; i++)
        for (size_t j = 0; parts[i].x && j < part_size(&parts[i]); j++)
            all[k++] = parts[i].x[j];
    return all;
}

qd_status qd__render_c_block(qd_ctx *ctx, qd_buf *b, size_t nparts,
                             const qd__render_part *parts) {
    size_t nout, k = 0;
    const qd_expr **x = flatten(ctx, nparts, parts, &nout);
    char(*names)[96] = qd__malloc(ctx, (nout + 1) * sizeof *names);
    const char **lhs = qd__malloc(ctx, (nout + 1) * sizeof *lhs);
    qd_status st = QD_ERR_NOMEM;
    if (x && names && lhs) {
        for (size_t i = 0; i < nparts; i++)
            for (size_t j = 0; parts[i].x && j < part_size(&parts[i]); j++, k++) {
                part_name(&parts[i], j, names[k], sizeof names[k]);
                lhs[k] = names[k];
            }
        st = qd_print_c_block(ctx, nout, x, lhs, b);
    }
    qd__free(x);
    qd__free(names);
    qd__free(lhs);
    return st;
}

void qd__render_c_inputs(qd_buf *b, const qd_model *m, size_t ngroups,
                         const qd__render_part *groups) {
    qd_buf_puts(b, "/* inputs (doubles in scope):");
    for (size_t g = 0; g < ngroups; g++)
        for (size_t j = 0; groups[g].x && j < part_size(&groups[g]); j++) {
            qd_buf_puts(b, " ");
            qd_c_name(groups[g].x[j], b);
        }
    qd_buf_puts(b, " t");
    for (size_t i = 0; i < qd_model_nparams(m); i++) {
        qd_buf_puts(b, " ");
        qd_c_name(qd_model_param(m, i), b);
    }
    qd_buf_puts(b, " */\n");
}

qd_status qd__render_sympy_functions(qd_ctx *ctx, qd_buf *b, size_t nparts,
                                     const qd__render_part *parts) {
    size_t nout;
    const qd_expr **all = flatten(ctx, nparts, parts, &nout);
    if (!all)
        return QD_ERR_NOMEM;
    qd_status st = qd_print_sympy_functions(ctx, nout, all, b);
    qd__free(all);
    return st;
}

qd_status qd__render_done(qd_ctx *ctx, const qd_buf *out, qd_status st) {
    if (st == QD_OK && out->failed) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory printing the equations");
        st = QD_ERR_NOMEM;
    }
    return st;
}

qd_status qd__render_text_or_json(qd_ctx *ctx, qd_render_format fmt, const char *what) {
    if (fmt == QD_RENDER_TEXT || fmt == QD_RENDER_JSON)
        return QD_OK;
    qd_ctx_error(ctx, QD_ERR_ARG, "%s prints as text or json", what);
    return QD_ERR_ARG;
}

qd_status qd__render_finish(qd_ctx *ctx, const qd_buf *out, qd_status st, const char *name) {
    if (st == QD_OK && out->failed)
        st = QD_ERR_NOMEM;
    if (st != QD_OK)
        qd_ctx_error(ctx, st, "cannot print %s: %s", name, qd_status_str(st));
    return st;
}

qd_status qd__render_json_expr(qd_ctx *ctx, qd_json *j, const qd_expr *x, qd_buf *tmp) {
    qd_buf_clear(tmp);
    qd_status st = qd_print(ctx, x, QD_FMT_TEXT, tmp);
    qd_json_string(j, qd_buf_str(tmp));
    return st;
}

void qd__render_json_names(qd_json *j, const char *key, const qd_expr *const *x, size_t n) {
    qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t i = 0; i < n; i++)
        qd_json_string(j, qd_expr_name(x[i]));
    qd_json_end_array(j);
}
