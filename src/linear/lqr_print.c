/*
 * src/linear/lqr_print.c - an LQR design as text, JSON or C (qd_lqr_print,
 * qdot/control.h): for `qdot lqr`, `qdot linearize --lqr` and any caller.
 */
#include "qdot/control.h"
#include "../base/args.h"
#include "../base/mem.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The names of the states and inputs: those of s, else x1..xn and u1..um
 * (room: 24 bytes each in own). */
typedef struct lqr_names {
    const char **states, **inputs;
    char (*own)[24];
} lqr_names;

static bool names_init(lqr_names *nm, const qd_statespace *s, const qd_care_result *r) {
    size_t total = r->n + r->m;
    *nm = (lqr_names){0};
    const char **all = qd__mem_malloc(NULL, (total + 1) * sizeof *all);
    if (!all)
        return false;
    nm->states = all;
    nm->inputs = all + r->n;
    if (!s) {
        nm->own = qd__mem_malloc(NULL, (total + 1) * sizeof *nm->own);
        if (!nm->own) {
            qd__free(all);
            return false;
        }
    }
    for (size_t k = 0; k < total; k++) {
        bool state = k < r->n;
        if (s) {
            all[k] = qd_expr_name(state ? s->states[k] : s->inputs[k - r->n]);
            continue;
        }
        snprintf(nm->own[k], sizeof nm->own[k], "%c%zu", state ? 'x' : 'u',
                 state ? k + 1 : k - r->n + 1);
        all[k] = nm->own[k];
    }
    return true;
}

static void names_free(lqr_names *nm) {
    qd__free(nm->states); /* inputs live in the same block */
    qd__free(nm->own);
}

/* Eigenvalues come in conjugate pairs, sorted by Re and then Im descending
 * (qd_care_result), so the +Im member is shown once as "re +- im i". */
static void text_eigenvalues(qd_buf *b, const qd_care_result *r) {
    qd_buf_puts(b, "closed-loop eigenvalues (A - B K):\n");
    for (size_t k = 0; k < r->n; k++) {
        if (r->eig_im[k] < 0)
            continue;
        if (r->eig_im[k] > 0)
            qd_buf_printf(b, "  %.10g +- %.10gi\n", r->eig_re[k], r->eig_im[k]);
        else
            qd_buf_printf(b, "  %.10g\n", r->eig_re[k]);
    }
}

/* A table with the states as column heads, each cell 10 digits, no
 * padding after the last. */
static void text_rows(qd_buf *b, size_t rows, size_t n, const double *M,
                      const char *const *row_names, const char *const *states) {
    qd_buf_printf(b, "  %-8s", "");
    for (size_t j = 0; j < n; j++)
        qd_buf_printf(b, j + 1 < n ? " %-14s" : " %s", states[j]);
    qd_buf_puts(b, "\n");
    for (size_t i = 0; i < rows; i++) {
        qd_buf_printf(b, "  %-8s", row_names[i]);
        for (size_t j = 0; j < n; j++)
            qd_buf_printf(b, j + 1 < n ? " %-14.10g" : " %.10g", M[i * n + j]);
        qd_buf_puts(b, "\n");
    }
}

static void put_text(qd_buf *b, const qd_care_result *r, const char *const *states,
                     const char *const *inputs) {
    qd_buf_puts(b, "gain K (u = -K x):\n");
    text_rows(b, r->m, r->n, r->K, inputs, states);
    qd_buf_puts(b, "Riccati solution X (A^T X + X A - X B R^-1 B^T X + Q = 0):\n");
    text_rows(b, r->n, r->n, r->X, states, states);
    text_eigenvalues(b, r);
    qd_buf_printf(b, "relative residual: %.1e\n", r->residual);
}

static void json_names(qd_json *j, const char *key, size_t n, const char *const *names) {
    qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t k = 0; k < n; k++)
        qd_json_string(j, names[k]);
    qd_json_end_array(j);
}

static void put_json_object(qd_json *j, const qd_care_result *r, const char *const *states,
                            const char *const *inputs) {
    qd_json_begin_object(j);
    json_names(j, "states", r->n, states);
    json_names(j, "inputs", r->m, inputs);
    qd_json_matrix(j, "K", r->m, r->n, r->K);
    qd_json_matrix(j, "X", r->n, r->n, r->X);
    qd_json_key(j, "closed_loop_eigenvalues");
    qd_json_begin_array(j);
    for (size_t k = 0; k < r->n; k++) {
        qd_json_begin_array(j);
        qd_json_number(j, r->eig_re[k]);
        qd_json_number(j, r->eig_im[k]);
        qd_json_end_array(j);
    }
    qd_json_end_array(j);
    qd_json_key(j, "residual");
    qd_json_number(j, r->residual);
    qd_json_key(j, "rcond");
    qd_json_number(j, r->rcond);
    qd_json_end_object(j);
}

static bool put_json(qd_buf *b, const qd_care_result *r, const char *const *states,
                     const char *const *inputs) {
    qd_json j;
    qd_json_init(&j, b);
    put_json_object(&j, r, states, inputs);
    qd_buf_puts(b, "\n");
    return qd_json_ok(&j);
}

static void c_matrix(qd_buf *b, const char *name, size_t rows, size_t cols, const double *M) {
    qd_buf_printf(b, "static const double %s[%zu][%zu] = {\n", name, rows, cols);
    for (size_t i = 0; i < rows; i++) {
        qd_buf_puts(b, "    {");
        for (size_t k = 0; k < cols; k++) {
            qd_buf_puts(b, k ? ", " : "");
            qd_buf_put_double(b, M[i * cols + k]);
        }
        qd_buf_puts(b, "},\n");
    }
    qd_buf_puts(b, "};\n");
}

/* Names go into comments only: "x'" is not a C identifier. */
static void put_c(qd_buf *b, const qd_care_result *r, const char *const *states,
                  const char *const *inputs) {
    qd_buf_puts(b, "/* LQR gain, u = -K x, with x = (");
    for (size_t k = 0; k < r->n; k++)
        qd_buf_printf(b, "%s%s", k ? ", " : "", states[k]);
    qd_buf_puts(b, ") and u = (");
    for (size_t k = 0; k < r->m; k++)
        qd_buf_printf(b, "%s%s", k ? ", " : "", inputs[k]);
    qd_buf_puts(b, ") */\n");
    c_matrix(b, "K", r->m, r->n, r->K);
}

static bool finite_design(const qd_care_result *r) {
    for (size_t k = 0; k < r->n * r->n; k++)
        if (!isfinite(r->X[k]))
            return false;
    for (size_t k = 0; k < r->m * r->n; k++)
        if (!isfinite(r->K[k]))
            return false;
    for (size_t k = 0; k < r->n; k++)
        if (!isfinite(r->eig_re[k]) || !isfinite(r->eig_im[k]))
            return false;
    return isfinite(r->residual);
}

/* A design with arrays (qd_care_solve's success) and, when s is given, its
 * sizes. */
static bool a_design(const qd_statespace *s, const qd_care_result *r) {
    return r->n && r->m && r->X && r->K && r->eig_re && r->eig_im &&
           (!s || (s->nx == r->n && s->nu == r->m));
}

void qd_lqr_json(qd_json *j, const qd_statespace *s, const qd_care_result *r) {
    QD_ARGS(, j && r);
    lqr_names nm;
    if (!a_design(s, r)) {
        qd_json_null(j); /* no design: nothing to say */
        return;
    }
    if (!names_init(&nm, s, r)) {
        qd_json_null(j);
        j->nomem = true; /* qd_json_ok says so */
        return;
    }
    put_json_object(j, r, nm.states, nm.inputs);
    names_free(&nm);
}

qd_status qd_lqr_print(const qd_statespace *s, const qd_care_result *r, qd_lqr_format fmt,
                       qd_buf *out) {
    QD_ARGS(QD_ERR_ARG, r && out);
    if (!a_design(s, r))
        return QD_ERR_ARG;
    if (!finite_design(r))
        return QD_ERR_NUMERIC;
    lqr_names nm;
    if (!names_init(&nm, s, r))
        return QD_ERR_NOMEM;
    qd_buf b = QD_BUF_WITH(out->alloc);
    bool ok = true;
    if (fmt == QD_LQR_JSON)
        ok = put_json(&b, r, nm.states, nm.inputs);
    else if (fmt == QD_LQR_C)
        put_c(&b, r, nm.states, nm.inputs);
    else
        put_text(&b, r, nm.states, nm.inputs);
    names_free(&nm);
    ok = ok && !b.failed;
    if (ok)
        qd_buf_putn(out, qd_buf_str(&b), b.len);
    qd_buf_free(&b);
    return !ok ? QD_ERR_NUMERIC : out->failed ? QD_ERR_NOMEM : QD_OK;
}
