/*
 * src/render/names.c - the names, bindings and numbers the renderers of
 * whole systems share (render.h).
 */
#include "render.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include "qdot/json.h"
#include "../base/args.h"
#include "../base/mem.h"

static double param_value(const qd_model *m, size_t i) {
    double x;
    qd_model_param_number(m, i, &x); /* NaN when it has none */
    return x;
}

static bool model_uses(const qd_model *m, const char *name, size_t n,
                       const qd_expr *const *avoid) {
    for (size_t i = 0; i < qd_model_ncoords(m); i++)
        if (!strcmp(qd_expr_name(qd_model_coord(m, i)), name))
            return true;
    for (size_t i = 0; i < qd_model_nparams(m); i++)
        if (!strcmp(qd_expr_name(qd_model_param(m, i)), name))
            return true;
    for (size_t i = 0; i < qd_model_nfunctions(m); i++)
        if (!strcmp(qd_model_function_name(m, i), name))
            return true;
    for (size_t i = 0; i < n; i++)
        if (!strcmp(qd_expr_name(avoid[i]), name))
            return true;
    return !strcmp(name, "t");
}

qd__render_name qd__render_name_pick(const qd_model *m, const char *base, size_t n,
                                     const qd_expr *const *avoid) {
    qd__render_name r;
    snprintf(r.s, sizeof r.s, "%s", base);
    for (size_t len = strlen(r.s); model_uses(m, r.s, n, avoid) && len + 1 < sizeof r.s; len++)
        r.s[len] = '_', r.s[len + 1] = '\0';
    return r;
}

void qd__render_sympy_bind(qd_ctx *ctx, qd_buf *b, const qd_expr *sym, bool fn) {
    qd_buf tmp = QD_BUF_WITH(b->alloc);
    const char *name = qd_expr_name(sym), *t = qd_print_time_name(ctx);
    qd_print(ctx, sym, QD_FMT_SYMPY, &tmp);
    size_t len = strlen(name), tlen = strlen(t);
    const char *s = qd_buf_str(&tmp);
    if (!strncmp(s, name, len) &&
        (fn ? s[len] == '(' && !strncmp(s + len + 1, t, tlen) && !strcmp(s + len + 1 + tlen, ")")
            : !s[len]))
        qd_buf_printf(b, "%s = %s('%s')\n", name, fn ? "Function" : "Symbol", name);
    qd_buf_free(&tmp);
}

qd_status qd__render_sympy_matrix(qd_ctx *ctx, qd_buf *b, const char *name,
                                  const qd_expr *const *x, size_t rows, size_t cols) {
    qd_status st = QD_OK;
    qd_buf_printf(b, "%s = Matrix([", name);
    for (size_t r = 0; r < rows && st == QD_OK; r++) {
        qd_buf_puts(b, cols > 1 ? "\n    [" : (r ? ", " : ""));
        for (size_t k = 0; k < cols && st == QD_OK; k++) {
            qd_buf_puts(b, k ? ", " : "");
            st = qd_print(ctx, x[r * cols + k], QD_FMT_SYMPY, b);
        }
        qd_buf_puts(b, cols > 1 ? "]," : "");
    }
    qd_buf_puts(b, cols > 1 ? "\n])\n" : "])\n");
    return st;
}

void qd__render_number(qd_buf *b, double x) {
    qd_buf_put_double(b, x == 0 ? 0.0 : x); /* -0 reads "0" */
}


void qd__render_params(qd_buf *b, const qd_model *m) {
    qd_buf_puts(b, "parameters:");
    for (size_t i = 0; i < qd_model_nparams(m); i++) {
        qd_buf_printf(b, "%s %s = ", i ? "," : "", qd_expr_name(qd_model_param(m, i)));
        qd__render_number(b, param_value(m, i));
    }
    if (!qd_model_nparams(m))
        qd_buf_puts(b, " none");
}

void qd__render_json_params(qd_json *j, const qd_model *m) {
    qd_json_key(j, "parameters");
    qd_json_begin_object(j);
    for (size_t i = 0; i < qd_model_nparams(m); i++) {
        qd_json_key(j, qd_expr_name(qd_model_param(m, i)));
        qd_json_number(j, param_value(m, i));
    }
    qd_json_end_object(j);
}

qd_status qd__render_state(qd_ctx *ctx, const qd_model *m, const qd_render_opts *o,
                           qd_render_opts *full) {
    *full = *o;
    full->syms = NULL;
    full->vals = NULL;
    if (!o->syms || !o->vals) {
        qd_ctx_error(ctx, QD_ERR_ARG, "a state of %zu values without its symbols or values",
                     o->nstate);
        return QD_ERR_ARG;
    }
    size_t np = qd_model_nparams(m), n = o->nstate;
    const qd_expr **syms = qd__malloc(ctx, (n + np + 1) * sizeof *syms);
    double *vals = qd__malloc(ctx, (n + np + 1) * sizeof *vals);
    if (!syms || !vals) {
        qd__free(syms);
        qd__free(vals);
        return QD_ERR_NOMEM;
    }
    memcpy(syms, o->syms, n * sizeof *syms);
    memcpy(vals, o->vals, n * sizeof *vals);
    for (size_t i = 0; i < np; i++) {
        const qd_expr *p = qd_model_param(m, i);
        if (isnan(qd__render_value(o, p))) { /* not given (or given as NaN: qd_eval says so) */
            syms[n] = p;
            vals[n++] = param_value(m, i);
        }
    }
    full->nstate = n;
    full->syms = syms;
    full->vals = vals;
    return QD_OK;
}

void qd__render_state_free(qd_render_opts *full) {
    qd__free((void *)full->syms);
    qd__free((void *)full->vals);
    full->syms = NULL;
    full->vals = NULL;
}

double qd__render_value(const qd_render_opts *o, const qd_expr *sym) {
    for (size_t i = 0; i < o->nstate; i++)
        if (o->syms[i] == sym)
            return o->vals[i];
    return NAN;
}

qd_status qd__render_json_status(const qd_json *j, const qd_buf *b, qd_status st) {
    if (st == QD_OK && !qd_json_ok(j))
        st = b->failed ? QD_ERR_NOMEM : QD_ERR_NUMERIC;
    return st;
}

static const char *const format_names[] = {"text", "latex", "json", "sympy", "c"};

const char *qd_render_format_name(qd_render_format f) {
    return (unsigned)f < sizeof format_names / sizeof format_names[0] ? format_names[f] : NULL;
}

bool qd_render_format_parse(const char *name, qd_render_format *out) {
    QD_ARGS(false, name && out);
    for (size_t i = 0; i < sizeof format_names / sizeof format_names[0]; i++)
        if (!strcmp(name, format_names[i])) {
            *out = (qd_render_format)i;
            return true;
        }
    return false;
}

const char *qd_con_kind_name(qd_con_kind k) {
    return k == QD_CON_HOLONOMIC ? "holonomic" : k == QD_CON_INTEGRABLE ? "integrable"
                                                                        : "nonholonomic";
}
