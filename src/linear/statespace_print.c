/*
 * src/linear/statespace_print.c - a linearization's state-space form as
 * text, JSON, C, SymPy or Octave (qd_statespace_render, qdot/statespace.h),
 * with its LQR design when there is one: what `qdot linearize` prints, for
 * any caller.
 */
#include "qdot/statespace.h"
#include "qdot/control.h"
#include "qdot/json.h"
#include "qdot/print.h"
#include "../base/args.h"
#include "../base/mem.h"

#include <math.h>

/* A component of an eigenvector that moves its state. */
#define MOVES 1e-6

/* ---- text ----------------------------------------------------------------------- */

static void put_names(qd_buf *b, const char *what, size_t n, const qd_expr *const *syms,
                      const char *const *names) {
    qd_buf_printf(b, "%s:", what);
    for (size_t i = 0; i < n; i++)
        qd_buf_printf(b, "%s %s", i ? "," : "", syms ? qd_expr_name(syms[i]) : names[i]);
    qd_buf_puts(b, n ? "\n" : " none\n");
}

/* Each number shortest round-trip, right-aligned to the widest. */
static void put_matrix(qd_buf *b, const char *name, size_t r, size_t c, const double *x) {
    if (r == 0 || c == 0)
        return;
    int w = 1;
    char num[QD_DOUBLE_MAX];
    for (size_t i = 0; i < r * c; i++) {
        int len = (int)qd_double_format(num, x[i] == 0 ? 0 : x[i]);
        w = len > w ? len : w;
    }
    qd_buf_printf(b, "%s =\n", name);
    for (size_t i = 0; i < r; i++) {
        qd_buf_puts(b, "  [");
        for (size_t j = 0; j < c; j++) {
            qd_double_format(num, x[i * c + j] == 0 ? 0 : x[i * c + j]);
            qd_buf_printf(b, " %*s", w, num);
        }
        qd_buf_puts(b, " ]\n");
    }
}

/* Row i is the rate of state row[i], column j the state or input col[j]. */
static void put_exact(qd_buf *b, qd_ctx *ctx, const char *name, size_t r, size_t c,
                      const qd_expr *const *x, const char *const *row, const char *const *col) {
    for (size_t i = 0; i < r; i++)
        for (size_t j = 0; j < c; j++)
            if (!qd_is_zero(x[i * c + j])) {
                qd_buf_printf(b, "  %s[%s, %s] = ", name, row[i], col[j]);
                qd_print(ctx, x[i * c + j], QD_FMT_TEXT, b);
                qd_buf_puts(b, "\n");
            }
}

static void put_eig(qd_buf *b, double re, double im) {
    char r[QD_DOUBLE_MAX], m[QD_DOUBLE_MAX];
    qd_double_format(r, re == 0 ? 0 : re);
    qd_double_format(m, fabs(im));
    if (im == 0)
        qd_buf_puts(b, r);
    else
        qd_buf_printf(b, "%s %c %si", r, im < 0 ? '-' : '+', m);
}

/* A mode named by the states its eigenvector moves. */
static void put_mode(qd_buf *b, const qd_statespace *s, size_t j) {
    qd_buf_puts(b, "s = ");
    put_eig(b, s->eig_re[j], s->eig_im[j]);
    qd_buf_puts(b, ", moving");
    size_t k = 0;
    for (size_t i = 0; i < s->nx; i++)
        if (hypot(s->vec_re[i * s->nx + j], s->vec_im[i * s->nx + j]) > MOVES)
            qd_buf_printf(b, "%s %s", k++ ? "," : "", qd_expr_name(s->states[i]));
}

static void put_rank(qd_buf *b, const char *what, bool yes, size_t rank, size_t nx) {
    qd_buf_printf(b, "%s: %s (Kalman rank %zu of %zu, singular values above %g of the largest)\n",
                  what, yes ? "yes" : "no", rank, nx, QD_SS_RANK_TOL);
}

static void put_modes(qd_buf *b, const char *what, const qd_statespace *s, size_t count,
                      const size_t *idx) {
    for (size_t k = 0; k < count; k++) {
        qd_buf_printf(b, "  %s mode: ", what);
        put_mode(b, s, idx[k]);
        qd_buf_puts(b, "\n");
    }
}

static qd_status text(qd_ctx *ctx, const qd_statespace *s, qd_buf *b) {
    const char **rows = qd__malloc(ctx, (s->nx + s->nu + 1) * sizeof *rows);
    if (!rows)
        return QD_ERR_NOMEM;
    for (size_t i = 0; i < s->nx + s->nu; i++)
        rows[i] = qd_expr_name(i < s->nx ? s->states[i] : s->inputs[i - s->nx]);
    put_names(b, "states", s->nx, s->states, NULL);
    put_names(b, "inputs", s->nu, s->inputs, NULL);
    put_names(b, "outputs", s->ny, NULL, s->outputs);
    put_matrix(b, "A", s->nx, s->nx, s->A);
    put_matrix(b, "B", s->nx, s->nu, s->B);
    put_matrix(b, "C", s->ny, s->nx, s->C);
    put_matrix(b, "D", s->ny, s->nu, s->D);
    bool rest = true;
    for (size_t i = 0; i < s->nx; i++)
        rest = rest && s->xdot0[i] == 0;
    if (!rest)
        put_matrix(b, "x' at the point (not an equilibrium)", 1, s->nx, s->xdot0);
    if (s->Asym) {
        qd_buf_puts(b, "exact, the nonzero rows of the accelerations (A[rate, state], B[rate, input]):\n");
        put_exact(b, ctx, "A", s->nx - s->n, s->nx, s->Asym + s->n * s->nx, rows + s->n, rows);
        put_exact(b, ctx, "B", s->nx - s->n, s->nu, s->Bsym + s->n * s->nu, rows + s->n,
                  rows + s->nx);
    }
    qd_buf_puts(b, "eigenvalues of A:");
    for (size_t j = 0; j < s->nx; j++) {
        qd_buf_puts(b, j ? ", " : " ");
        put_eig(b, s->eig_re[j], s->eig_im[j]);
    }
    qd_buf_puts(b, "\n");
    if (s->nu) { /* without inputs every mode is out of reach: no list of them */
        put_rank(b, "controllable", s->controllable, s->rank_ctrb, s->nx);
        put_modes(b, "uncontrollable", s, s->nuncontrollable, s->uncontrollable);
    } else
        qd_buf_puts(b, "controllable: no inputs\n");
    if (s->ny) {
        put_rank(b, "observable", s->observable, s->rank_obsv, s->nx);
        put_modes(b, "unobservable", s, s->nunobservable, s->unobservable);
    }
    qd__free(rows);
    return QD_OK;
}

/* ---- json ------------------------------------------------------------------------ */

static void json_exact(qd_json *j, qd_ctx *ctx, const char *key, size_t r, size_t c,
                       const qd_expr *const *x) {
    qd_json_key(j, key);
    if (!x) {
        qd_json_null(j);
        return;
    }
    qd_json_begin_array(j);
    for (size_t i = 0; i < r; i++) {
        qd_json_begin_array(j);
        for (size_t k = 0; k < c; k++)
            qd_json_expr(j, ctx, x[i * c + k]);
        qd_json_end_array(j);
    }
    qd_json_end_array(j);
}

static void json_names(qd_json *j, const char *key, size_t n, const qd_expr *const *syms,
                       const char *const *names) {
    qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t i = 0; i < n; i++)
        qd_json_string(j, syms ? qd_expr_name(syms[i]) : names[i]);
    qd_json_end_array(j);
}

static void json_eig(qd_json *j, double re, double im) {
    qd_json_begin_array(j);
    qd_json_number(j, re);
    qd_json_number(j, im);
    qd_json_end_array(j);
}

static void json_modes(qd_json *j, const qd_statespace *s, size_t count, const size_t *idx) {
    qd_json_begin_array(j);
    for (size_t k = 0; k < count; k++) {
        size_t e = idx[k];
        qd_json_begin_object(j);
        qd_json_key(j, "eigenvalue");
        json_eig(j, s->eig_re[e], s->eig_im[e]);
        qd_json_key(j, "states");
        qd_json_begin_array(j);
        for (size_t i = 0; i < s->nx; i++)
            if (hypot(s->vec_re[i * s->nx + e], s->vec_im[i * s->nx + e]) > MOVES)
                qd_json_string(j, qd_expr_name(s->states[i]));
        qd_json_end_array(j);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
}

static qd_status json(qd_ctx *ctx, const qd_statespace *s, const qd_care_result *lqr,
                      qd_buf *b) {
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    json_names(&j, "states", s->nx, s->states, NULL);
    json_names(&j, "inputs", s->nu, s->inputs, NULL);
    json_names(&j, "outputs", s->ny, NULL, s->outputs);
    qd_json_matrix(&j, "A", s->nx, s->nx, s->A);
    qd_json_matrix(&j, "B", s->nx, s->nu, s->B);
    qd_json_matrix(&j, "C", s->ny, s->nx, s->C);
    qd_json_matrix(&j, "D", s->ny, s->nu, s->D);
    qd_json_matrix(&j, "xdot0", 1, s->nx, s->xdot0);
    json_exact(&j, ctx, "A_exact", s->nx, s->nx, s->Asym);
    json_exact(&j, ctx, "B_exact", s->nx, s->nu, s->Bsym);
    qd_json_key(&j, "eigenvalues");
    qd_json_begin_array(&j);
    for (size_t k = 0; k < s->nx; k++)
        json_eig(&j, s->eig_re[k], s->eig_im[k]);
    qd_json_end_array(&j);
    qd_json_key(&j, "rank_tolerance");
    qd_json_number(&j, QD_SS_RANK_TOL);
    qd_json_key(&j, "controllable");
    qd_json_bool(&j, s->controllable);
    qd_json_key(&j, "controllability_rank");
    qd_json_number(&j, (double)s->rank_ctrb);
    qd_json_key(&j, "uncontrollable_modes");
    json_modes(&j, s, s->nuncontrollable, s->uncontrollable);
    qd_json_key(&j, "observable");
    qd_json_bool(&j, s->observable);
    qd_json_key(&j, "observability_rank");
    qd_json_number(&j, (double)s->rank_obsv);
    qd_json_key(&j, "unobservable_modes");
    json_modes(&j, s, s->ny ? s->nunobservable : 0, s->unobservable);
    if (lqr) {
        qd_json_key(&j, "lqr");
        qd_lqr_json(&j, s, lqr);
    }
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    if (b->failed)
        return QD_ERR_NOMEM;
    if (!qd_json_ok(&j)) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "cannot print the state-space form: %s",
                     qd_json_why(&j));
        return QD_ERR_NUMERIC;
    }
    return QD_OK;
}

/* ---- code: the exact matrices where known, else the numbers -------------------- */

static void code_entry(qd_buf *b, qd_ctx *ctx, const qd_expr *x, double v, qd_format f) {
    if (x)
        qd_print(ctx, x, f, b);
    else
        qd_buf_put_double(b, v);
}

static void code_matrix(qd_buf *b, qd_ctx *ctx, qd_ss_format fmt, const char *name, size_t r,
                        size_t c, const qd_expr *const *x, const double *v) {
    qd_format f = fmt == QD_SS_SYMPY ? QD_FMT_SYMPY : QD_FMT_C;
    if (fmt == QD_SS_C)
        qd_buf_printf(b, "static const double %s[%zu][%zu] = {\n", name, r ? r : 1, c ? c : 1);
    else
        qd_buf_printf(b, "%s = %s", name, fmt == QD_SS_SYMPY ? "Matrix([\n" : "[\n");
    for (size_t i = 0; i < r; i++) {
        qd_buf_puts(b, fmt == QD_SS_OCTAVE ? "  " : fmt == QD_SS_C ? "    {" : "    [");
        for (size_t k = 0; k < c; k++) {
            qd_buf_puts(b, k ? ", " : "");
            code_entry(b, ctx, x ? x[i * c + k] : NULL, v[i * c + k], f);
        }
        qd_buf_puts(b, fmt == QD_SS_OCTAVE ? ";\n" : fmt == QD_SS_C ? "},\n" : "],\n");
    }
    qd_buf_puts(b, fmt == QD_SS_C ? "};\n" : fmt == QD_SS_SYMPY ? "])\n" : "];\n");
}

static void code(qd_ctx *ctx, const qd_statespace *s, qd_ss_format fmt, qd_buf *b) {
    const char *c = fmt == QD_SS_SYMPY ? "#" : fmt == QD_SS_OCTAVE ? "%" : "//";
    qd_buf_printf(b, "%s x = [", c);
    for (size_t i = 0; i < s->nx; i++)
        qd_buf_printf(b, "%s%s", i ? ", " : "", qd_expr_name(s->states[i]));
    qd_buf_printf(b, "], u = [");
    for (size_t i = 0; i < s->nu; i++)
        qd_buf_printf(b, "%s%s", i ? ", " : "", qd_expr_name(s->inputs[i]));
    qd_buf_printf(b, "]%s\n", s->Asym ? "" : " (numbers: the exact form was not kept)");
    code_matrix(b, ctx, fmt, "A", s->nx, s->nx, s->Asym, s->A);
    code_matrix(b, ctx, fmt, "B", s->nx, s->nu, s->Bsym, s->B);
    if (s->ny) {
        code_matrix(b, ctx, fmt, "C", s->ny, s->nx, s->Csym, s->C);
        code_matrix(b, ctx, fmt, "D", s->ny, s->nu, s->Dsym, s->D);
    }
}

/* The design after the matrices, in text or C (JSON nests it). */
static qd_status design(qd_ctx *ctx, const qd_statespace *s, const qd_care_result *lqr,
                        qd_ss_format fmt, qd_buf *b) {
    qd_status st = qd_lqr_print(s, lqr, fmt == QD_SS_TEXT ? QD_LQR_TEXT : QD_LQR_C, b);
    if (st == QD_ERR_NUMERIC)
        qd_ctx_error(ctx, st, "cannot print the LQR design: a number that is not finite");
    return st;
}

qd_status qd_statespace_render(qd_ctx *ctx, const qd_statespace *s,
                               const struct qd_care_result *lqr, qd_ss_format fmt,
                               qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && s && out);
    if (fmt != QD_SS_TEXT && fmt != QD_SS_JSON && fmt != QD_SS_C && fmt != QD_SS_SYMPY &&
        fmt != QD_SS_OCTAVE) {
        qd_ctx_error(ctx, QD_ERR_ARG, "qd_statespace_render: not a format of qd_ss_format");
        return QD_ERR_ARG;
    }
    if (lqr && (fmt == QD_SS_SYMPY || fmt == QD_SS_OCTAVE)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "an LQR design prints as text, json or c, not %s",
                     fmt == QD_SS_SYMPY ? "sympy" : "octave");
        return QD_ERR_ARG;
    }
    qd_buf b = QD_BUF_WITH(out->alloc);
    qd_status st = QD_OK;
    if (fmt == QD_SS_JSON)
        st = json(ctx, s, lqr, &b);
    else if (fmt == QD_SS_TEXT)
        st = text(ctx, s, &b);
    else
        code(ctx, s, fmt, &b);
    if (st == QD_OK && lqr && fmt != QD_SS_JSON)
        st = design(ctx, s, lqr, fmt, &b);
    if (st == QD_OK && (b.failed || qd_ctx_status(ctx) == QD_ERR_NOMEM))
        st = QD_ERR_NOMEM;
    if (st == QD_OK)
        qd_buf_putn(out, qd_buf_str(&b), b.len);
    qd_buf_free(&b);
    if (st == QD_OK && out->failed)
        st = QD_ERR_NOMEM;
    if (st == QD_ERR_NOMEM)
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
    return st;
}
