/*
 * cli/eom_out.c - the five renderings of M q'' = f.
 *
 * Text is for reading (entries in the model language's syntax, numbers in
 * their shortest round-trip form); LaTeX is an align environment; JSON is for
 * programs (expressions as strings in the text syntax, numbers as numbers in
 * numeric mode); SymPy is a Python snippet that rebuilds M and f; C is one
 * qd_print_c_block so that common subexpressions are shared across M and f.
 */
#include "eom_out.h"

#include <stdlib.h>
#include <string.h>
#include "cli.h"
#include "json.h"

bool qd_eom_format_from_name(const char *name, qd_eom_format *out) {
    static const char *const names[] = {"text", "latex", "json", "sympy", "c"};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        if (!strcmp(name, names[i])) {
            *out = (qd_eom_format)i;
            return true;
        }
    return false;
}

static qd_status put(const qd_eom_view *v, qd_buf *b, const qd_expr *x, qd_format fmt) {
    if (v->numeric && fmt == QD_FMT_TEXT && qd_is_number(x)) {
        qd_state_put_double(b, qd_number_value(x));
        return QD_OK;
    }
    return qd_print(v->ctx, x, fmt, b);
}

static const char *qname(const qd_eom_view *v, size_t j) { return qd_expr_name(v->e->q[j]); }

/* The name of an output (M, f, qdd, ...) in SymPy and C: base, with
 * underscores appended while the model uses the name for a coordinate or a
 * parameter (a wedge of mass M must not be overwritten by the matrix). */
typedef struct out_name { char s[32]; } out_name;

static bool model_name(const qd_eom_view *v, const char *name) {
    const qd_model *m = v->mf->model;
    for (size_t i = 0; i < v->e->n; i++)
        if (!strcmp(qname(v, i), name))
            return true;
    for (size_t i = 0; i < qd_model_nparams(m); i++)
        if (!strcmp(qd_expr_name(qd_model_param(m, i)), name))
            return true;
    return !strcmp(name, "t");
}

static out_name pick(const qd_eom_view *v, const char *base) {
    out_name n;
    snprintf(n.s, sizeof n.s, "%s", base);
    for (size_t len = strlen(n.s); model_name(v, n.s) && len + 1 < sizeof n.s; len++)
        n.s[len] = '_', n.s[len + 1] = '\0';
    return n;
}

/* ---- text ------------------------------------------------------------------ */

static void text_header(const qd_eom_view *v, qd_buf *b) {
    const qd_model *m = v->mf->model;
    qd_buf_printf(b, "model: %s\ncoordinates:", v->mf->path);
    for (size_t j = 0; j < v->e->n; j++)
        qd_buf_printf(b, "%s %s", j ? "," : "", qname(v, j));
    qd_buf_puts(b, "\nparameters:");
    for (size_t i = 0; i < qd_model_nparams(m); i++) {
        qd_buf_printf(b, "%s %s = ", i ? "," : "", qd_expr_name(qd_model_param(m, i)));
        qd_state_put_double(b, qd_state_value(qd_model_param_value(m, i)));
    }
    if (!qd_model_nparams(m))
        qd_buf_puts(b, " none");
    qd_buf_puts(b, "\n");
    if (!v->numeric)
        return;
    qd_buf_puts(b, "at:");
    for (size_t i = 0; i < 2 * v->e->n + 1; i++) {
        qd_buf_puts(b, i ? ", " : " ");
        qd_print(v->ctx, v->st->syms[i], QD_FMT_TEXT, b);
        qd_buf_puts(b, " = ");
        qd_state_put_double(b, v->st->vals[i]);
    }
    qd_buf_puts(b, "\n");
}

static qd_status write_text(const qd_eom_view *v, qd_buf *b) {
    size_t n = v->e->n;
    qd_status st = QD_OK;
    text_header(v, b);
    if (v->split) {
        static const char *const parts[] = {"T2", "T1", "T0"};
        qd_buf_puts(b, "\nkinetic energy T = T2 + T1 + T0 (T2 quadratic in the velocities, "
                       "T1 linear, T0 free of them):\n");
        for (size_t i = 0; i < 3 && st == QD_OK; i++) {
            qd_buf_printf(b, "  %s = ", parts[i]);
            st = put(v, b, v->T[i], QD_FMT_TEXT);
            qd_buf_puts(b, "\n");
        }
    }
    qd_buf_puts(b, "\nequations M q'' = f (M is symmetric: entries with j <= k):\n");
    for (size_t j = 0; j < n; j++)
        for (size_t k = j; k < n && st == QD_OK; k++) {
            qd_buf_printf(b, "  M[%s,%s] = ", qname(v, j), qname(v, k));
            st = put(v, b, v->M[j * n + k], QD_FMT_TEXT);
            qd_buf_puts(b, "\n");
        }
    for (size_t j = 0; j < n && st == QD_OK; j++) {
        qd_buf_printf(b, "  f[%s] = ", qname(v, j));
        st = put(v, b, v->f[j], QD_FMT_TEXT);
        qd_buf_puts(b, "\n");
    }
    if (v->acc) {
        qd_buf_puts(b, "\naccelerations q'' = M^-1 f:\n");
        for (size_t j = 0; j < n && st == QD_OK; j++) {
            qd_buf_printf(b, "  %s'' = ", qname(v, j));
            st = put(v, b, v->acc[j], QD_FMT_TEXT);
            qd_buf_puts(b, "\n");
        }
    }
    return st;
}

/* ---- LaTeX ----------------------------------------------------------------- */

static qd_status latex_line(const qd_eom_view *v, qd_buf *b, bool *first, const char *lhs,
                            const qd_expr *rhs) {
    qd_buf_puts(b, *first ? "  " : " \\\\\n  ");
    *first = false;
    qd_buf_printf(b, "%s &= ", lhs);
    return qd_print(v->ctx, rhs, QD_FMT_LATEX, b);
}

/* sum_k M_jk q''_k in LaTeX, into lhs. */
static qd_status latex_row(const qd_eom_view *v, size_t j, qd_buf *lhs) {
    size_t n = v->e->n;
    const qd_expr *sum = qd_int(v->ctx, 0);
    for (size_t k = 0; k < n; k++)
        sum = qd_add(v->ctx, sum, qd_mul(v->ctx, v->M[j * n + k], v->e->qdd[k]));
    if (!sum)
        return qd_ctx_status(v->ctx);
    qd_buf_clear(lhs);
    return qd_print(v->ctx, sum, QD_FMT_LATEX, lhs);
}

static qd_status write_latex(const qd_eom_view *v, qd_buf *b) {
    static const char *const parts[] = {"T_2", "T_1", "T_0"};
    size_t n = v->e->n;
    bool first = true;
    qd_status st = QD_OK;
    qd_buf lhs = QD_BUF_INIT;
    qd_buf_puts(b, "\\begin{align}\n");
    for (size_t i = 0; v->split && i < 3 && st == QD_OK; i++)
        st = latex_line(v, b, &first, parts[i], v->T[i]);
    for (size_t j = 0; j < n && st == QD_OK; j++) {
        st = latex_row(v, j, &lhs);
        if (st == QD_OK)
            st = latex_line(v, b, &first, qd_buf_str(&lhs), v->f[j]);
    }
    for (size_t j = 0; v->acc && j < n && st == QD_OK; j++) {
        qd_buf_clear(&lhs);
        st = qd_print(v->ctx, v->e->qdd[j], QD_FMT_LATEX, &lhs);
        if (st == QD_OK)
            st = latex_line(v, b, &first, qd_buf_str(&lhs), v->acc[j]);
    }
    qd_buf_puts(b, "\n\\end{align}\n");
    qd_buf_free(&lhs);
    return st;
}

/* ---- JSON ------------------------------------------------------------------ */

static qd_status json_entry(const qd_eom_view *v, qd_json *j, const qd_expr *x, qd_buf *tmp) {
    if (v->numeric) {
        qd_json_number(j, qd_number_value(x));
        return QD_OK;
    }
    qd_buf_clear(tmp);
    qd_status st = qd_print(v->ctx, x, QD_FMT_TEXT, tmp);
    qd_json_string(j, qd_buf_str(tmp));
    return st;
}

static qd_status json_vector(const qd_eom_view *v, qd_json *j, const char *key,
                             const qd_expr *const *x, size_t n, qd_buf *tmp) {
    qd_status st = QD_OK;
    qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t i = 0; i < n && st == QD_OK; i++)
        st = json_entry(v, j, x[i], tmp);
    qd_json_end_array(j);
    return st;
}

static void json_header(const qd_eom_view *v, qd_json *j, qd_buf *tmp) {
    const qd_model *m = v->mf->model;
    qd_json_key(j, "model");
    qd_json_string(j, v->mf->path);
    qd_json_key(j, "coordinates");
    qd_json_begin_array(j);
    for (size_t i = 0; i < v->e->n; i++)
        qd_json_string(j, qname(v, i));
    qd_json_end_array(j);
    qd_json_key(j, "parameters");
    qd_json_begin_object(j);
    for (size_t i = 0; i < qd_model_nparams(m); i++) {
        qd_json_key(j, qd_expr_name(qd_model_param(m, i)));
        qd_json_number(j, qd_state_value(qd_model_param_value(m, i)));
    }
    qd_json_end_object(j);
    if (!v->numeric)
        return;
    qd_json_key(j, "state");
    qd_json_begin_object(j);
    for (size_t i = 0; i < 2 * v->e->n + 1; i++) {
        qd_buf_clear(tmp);
        qd_print(v->ctx, v->st->syms[i], QD_FMT_TEXT, tmp);
        qd_json_key(j, qd_buf_str(tmp));
        qd_json_number(j, v->st->vals[i]);
    }
    qd_json_end_object(j);
}

static qd_status write_json(const qd_eom_view *v, qd_buf *b) {
    static const char *const parts[] = {"T2", "T1", "T0"};
    size_t n = v->e->n;
    qd_buf tmp = QD_BUF_INIT;
    qd_json j;
    qd_status st = QD_OK;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    json_header(v, &j, &tmp);
    for (size_t i = 0; v->T[0] && i < 3 && st == QD_OK; i++) {
        qd_json_key(&j, parts[i]);
        st = json_entry(v, &j, v->T[i], &tmp);
    }
    qd_json_key(&j, "mass_matrix");
    qd_json_begin_array(&j);
    for (size_t r = 0; r < n && st == QD_OK; r++) {
        qd_json_begin_array(&j);
        for (size_t k = 0; k < n && st == QD_OK; k++)
            st = json_entry(v, &j, v->M[r * n + k], &tmp);
        qd_json_end_array(&j);
    }
    qd_json_end_array(&j);
    if (st == QD_OK)
        st = json_vector(v, &j, "forcing", v->f, n, &tmp);
    if (st == QD_OK && v->acc)
        st = json_vector(v, &j, "accelerations", v->acc, n, &tmp);
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    qd_buf_free(&tmp);
    if (st == QD_OK && !qd_json_ok(&j))
        st = b->failed ? QD_ERR_NOMEM : QD_ERR_NUMERIC;
    return st;
}

/* ---- SymPy ----------------------------------------------------------------- */

/* Bind name to Symbol or Function when the printer prints it bare (a name
 * that would shadow Python or SymPy is printed self-contained instead). */
static void sympy_bind(const qd_eom_view *v, qd_buf *b, const qd_expr *sym, bool fn) {
    qd_buf tmp = QD_BUF_INIT;
    const char *name = qd_expr_name(sym);
    qd_print(v->ctx, sym, QD_FMT_SYMPY, &tmp);
    size_t len = strlen(name);
    const char *s = qd_buf_str(&tmp);
    if (!strncmp(s, name, len) && !strcmp(s + len, fn ? "(t)" : ""))
        qd_buf_printf(b, "%s = %s('%s')\n", name, fn ? "Function" : "Symbol", name);
    qd_buf_free(&tmp);
}

static qd_status sympy_assign(const qd_eom_view *v, qd_buf *b, const char *name,
                              const qd_expr *const *x, size_t rows, size_t cols) {
    qd_status st = QD_OK;
    qd_buf_printf(b, "%s = Matrix([", name);
    for (size_t r = 0; r < rows && st == QD_OK; r++) {
        qd_buf_puts(b, cols > 1 ? "\n    [" : (r ? ", " : ""));
        for (size_t k = 0; k < cols && st == QD_OK; k++) {
            qd_buf_puts(b, k ? ", " : "");
            st = qd_print(v->ctx, x[r * cols + k], QD_FMT_SYMPY, b);
        }
        qd_buf_puts(b, cols > 1 ? "]," : "");
    }
    qd_buf_puts(b, cols > 1 ? "\n])\n" : "])\n");
    return st;
}

static qd_status write_sympy(const qd_eom_view *v, qd_buf *b) {
    static const char *const parts[] = {"T2", "T1", "T0"};
    const qd_model *m = v->mf->model;
    size_t n = v->e->n;
    qd_status st = QD_OK;
    out_name M = pick(v, "M"), f = pick(v, "f"), q = pick(v, "q"), qdd = pick(v, "qdd");
    qd_buf_printf(b, "# qdot eom %s: %s*%s.diff(t, 2) = %s\nfrom sympy import *\n\n"
                  "t = Symbol('t')\n", v->mf->path, M.s, q.s, f.s);
    for (size_t j = 0; j < n; j++)
        sympy_bind(v, b, v->e->q[j], true);
    for (size_t i = 0; i < qd_model_nparams(m); i++)
        sympy_bind(v, b, qd_model_param(m, i), false);
    qd_buf_puts(b, "\n");
    st = sympy_assign(v, b, q.s, v->e->q, n, 1);
    for (size_t i = 0; v->T[0] && i < 3 && st == QD_OK; i++) {
        qd_buf_printf(b, "%s = ", pick(v, parts[i]).s);
        st = qd_print(v->ctx, v->T[i], QD_FMT_SYMPY, b);
        qd_buf_puts(b, "\n");
    }
    if (st == QD_OK)
        st = sympy_assign(v, b, M.s, v->M, n, n);
    if (st == QD_OK)
        st = sympy_assign(v, b, f.s, v->f, n, 1);
    if (st == QD_OK && v->acc)
        st = sympy_assign(v, b, qdd.s, v->acc, n, 1);
    return st;
}

/* ---- C --------------------------------------------------------------------- */

static void c_inputs(const qd_eom_view *v, qd_buf *b) {
    const qd_model *m = v->mf->model;
    const qd_eom *e = v->e;
    qd_buf_puts(b, "/* inputs (doubles in scope):");
    for (size_t j = 0; j < 2 * e->n; j++) {
        qd_buf_puts(b, " ");
        qd_c_name(j < e->n ? e->q[j] : e->qd[j - e->n], b);
    }
    qd_buf_puts(b, " t");
    for (size_t i = 0; i < qd_model_nparams(m); i++) {
        qd_buf_puts(b, " ");
        qd_c_name(qd_model_param(m, i), b);
    }
    qd_buf_puts(b, " */\n");
}

static qd_status write_c(const qd_eom_view *v, qd_buf *b) {
    size_t n = v->e->n, nout = n * n + n + (v->acc ? n : 0);
    const qd_expr **out = malloc(nout * sizeof *out);
    char (*names)[96] = malloc(nout * sizeof *names);
    const char **lhs = malloc(nout * sizeof *lhs);
    qd_status st = QD_ERR_NOMEM;
    out_name M = pick(v, "M"), f = pick(v, "f"), qdd = pick(v, "qdd");
    if (out && names && lhs) {
        for (size_t i = 0; i < nout; i++) {
            if (i < n * n)
                snprintf(names[i], sizeof names[i], "%s[%zu][%zu]", M.s, i / n, i % n);
            else if (i < n * n + n)
                snprintf(names[i], sizeof names[i], "%s[%zu]", f.s, i - n * n);
            else
                snprintf(names[i], sizeof names[i], "%s[%zu]", qdd.s, i - n * n - n);
            out[i] = i < n * n ? v->M[i] : i < n * n + n ? v->f[i - n * n] : v->acc[i - n * n - n];
            lhs[i] = names[i];
        }
        qd_buf_printf(b, "/* qdot eom %s: %s q'' = %s", v->mf->path, M.s, f.s);
        if (v->acc)
            qd_buf_printf(b, ", and %s = %s^-1 %s", qdd.s, M.s, f.s);
        qd_buf_puts(b, " */\n");
        c_inputs(v, b);
        st = qd_print_c_block(v->ctx, nout, out, lhs, b);
    }
    free(out);
    free(names);
    free(lhs);
    return st;
}

qd_status qd_eom_write(const qd_eom_view *v, qd_eom_format fmt, qd_buf *out) {
    switch (fmt) {
    case QD_EOM_LATEX: return write_latex(v, out);
    case QD_EOM_JSON: return write_json(v, out);
    case QD_EOM_SYMPY: return write_sympy(v, out);
    case QD_EOM_C: return write_c(v, out);
    case QD_EOM_TEXT: break;
    }
    return write_text(v, out);
}
