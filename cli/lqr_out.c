/*
 * cli/lqr_out.c - an LQR design as text, JSON or C (cli_lqr_print in
 * lqr_cli.h): for `qdot lqr` and for `qdot linearize --lqr`.
 */
#include "lqr_cli.h"
#include "qdot/json.h"

#include <math.h>
#include <string.h>

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

static void json_matrix(qd_json *j, const char *key, size_t rows, size_t cols,
                        const double *M) {
    qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t i = 0; i < rows; i++) {
        qd_json_begin_array(j);
        for (size_t k = 0; k < cols; k++)
            qd_json_number(j, M[i * cols + k]);
        qd_json_end_array(j);
    }
    qd_json_end_array(j);
}

void cli_lqr_json(qd_json *j, const qd_care_result *r, const char *const *states,
                  const char *const *inputs) {
    qd_json_begin_object(j);
    json_names(j, "states", r->n, states);
    json_names(j, "inputs", r->m, inputs);
    json_matrix(j, "K", r->m, r->n, r->K);
    json_matrix(j, "X", r->n, r->n, r->X);
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
    cli_lqr_json(&j, r, states, inputs);
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

bool cli_lqr_print(FILE *out, const qd_care_result *r, const char *const *states,
                   const char *const *inputs, cli_lqr_format fmt) {
    qd_buf b = QD_BUF_INIT;
    bool ok = true;
    if (fmt == CLI_LQR_JSON)
        ok = put_json(&b, r, states, inputs);
    else if (fmt == CLI_LQR_C)
        put_c(&b, r, states, inputs);
    else
        put_text(&b, r, states, inputs);
    ok = ok && !b.failed;
    if (ok)
        fputs(qd_buf_str(&b), out);
    qd_buf_free(&b);
    return ok;
}
