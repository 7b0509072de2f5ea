/*
 * cli/cmd_linearize.c - `qdot linearize FILE --about "q=..., q'=..., F=..."`:
 * the state-space form x' = A x + B u, y = C x + D u about an operating
 * point (qd_linearize), the eigenvalues of A, and controllability and
 * observability; with --lqr "Q = ..., R = ...", the LQR gain on A and B
 * (qd_care_solve, printed by cli_lqr_print).  Formats: text, json, c,
 * sympy, octave.
 */
#include "cli.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "qdot/json.h"
#include "linear_cli.h"
#include "lqr_cli.h"
#include "model_cli.h"
#include "qdot/statespace.h"

enum { F_TEXT, F_JSON, F_C, F_SYMPY, F_OCTAVE };
static const char *const formats[] = {"text", "json", "c", "sympy", "octave", NULL};

typedef struct lin_args {
    const char *file, *about, *lqr, *independent, *format_name;
    cli_list sets;
    int format;
} lin_args;

static const cli_opt opts[] = {
    {"--about", NULL, CLI_TEXT, offsetof(lin_args, about), "\"q=V, q'=V, F=V, ...\"",
     "the operating point: coordinates, velocities, inputs (others 0)", NULL, NULL},
    {"--set", NULL, CLI_LIST, offsetof(lin_args, sets), "NAME=VALUE",
     "give a parameter another value", NULL, NULL},
    {"--lqr", NULL, CLI_TEXT, offsetof(lin_args, lqr), "\"Q = ..., R = ...\"",
     "also the LQR gain for these weights", NULL, NULL},
    {"--independent", NULL, CLI_TEXT, offsetof(lin_args, independent), "\"q1, ...\"",
     "the independent coordinates on a constraint manifold", NULL, NULL},
    {"--format", NULL, CLI_CHOICE, offsetof(lin_args, format_name), "F", "output format",
     formats, NULL},
    {NULL, NULL, CLI_FLAG, 0, NULL, NULL, NULL, NULL},
};

static const cli_spec spec = {
    "linearize", "FILE [options]",
    "The state-space form x' = A x + B u, y = C x + D u about an operating point, the "
    "eigenvalues of A, controllability and observability.",
    opts, NULL, 1, 1, "FILE", false};

/* ---- --about ---------------------------------------------------------------------- */

/* The operating point given: the slots --about names (the model's state with
 * its inputs appended) and their values as read, exact (an expression in the
 * parameters); qd_linearize takes 0 for the rest. */
typedef struct lin_point {
    size_t n;
    const qd_expr **syms, **vals;
} lin_point;

static int read_about(qd_ctx *ctx, const qd_model *m, const char *text, lin_point *pt) {
    cli_state st = {0};
    int rc = cli_state_init(ctx, m, &st);
    for (size_t i = 0; rc == QD_EXIT_OK && i < qd_model_ninputs(m); i++) {
        const qd_expr *u = qd_model_input(m, i);
        if (qd_state_append(ctx, &st, 1, &u, NULL) != QD_OK)
            rc = cli_diag_ctx(ctx);
    }
    const qd_expr **exact = rc == QD_EXIT_OK ? calloc(st.n, sizeof *exact) : NULL;
    pt->syms = rc == QD_EXIT_OK ? calloc(st.n, sizeof *pt->syms) : NULL;
    pt->vals = rc == QD_EXIT_OK ? calloc(st.n, sizeof *pt->vals) : NULL;
    if (rc == QD_EXIT_OK && (!exact || !pt->syms || !pt->vals)) {
        cli_diag_error("out of memory");
        rc = QD_EXIT_FAIL;
    }
    qd_state_read_opts o = {.exact = exact};
    if (rc == QD_EXIT_OK)
        rc = cli_state_read(ctx, m, "--about", text, &st, &o);
    for (size_t k = 0; rc == QD_EXIT_OK && k < st.n; k++)
        if (exact[k]) {
            pt->syms[pt->n] = st.syms[k];
            pt->vals[pt->n++] = exact[k];
        }
    free(exact);
    cli_state_free(&st);
    return rc;
}

static void point_free(lin_point *pt) {
    free(pt->syms);
    free(pt->vals);
}

/* ---- text ----------------------------------------------------------------------- */

static void put_names(qd_buf *b, const char *what, size_t n, const qd_expr *const *syms,
                      const char *const *names) {
    qd_buf_printf(b, "%s:", what);
    for (size_t i = 0; i < n; i++)
        qd_buf_printf(b, "%s %s", i ? "," : "", syms ? qd_expr_name(syms[i]) : names[i]);
    qd_buf_puts(b, n ? "\n" : " none\n");
}

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

/* A mode named by the states its eigenvector moves (|component| > 1e-6). */
static void put_mode(qd_buf *b, const qd_statespace *s, size_t j) {
    qd_buf_puts(b, "s = ");
    put_eig(b, s->eig_re[j], s->eig_im[j]);
    qd_buf_puts(b, ", moving");
    size_t k = 0;
    for (size_t i = 0; i < s->nx; i++)
        if (hypot(s->vec_re[i * s->nx + j], s->vec_im[i * s->nx + j]) > 1e-6)
            qd_buf_printf(b, "%s %s", k++ ? "," : "", qd_expr_name(s->states[i]));
}

static void put_rank(qd_buf *b, const char *what, bool yes, size_t rank, size_t nx) {
    qd_buf_printf(b, "%s: %s (Kalman rank %zu of %zu, singular values above %g of the largest)\n",
                  what, yes ? "yes" : "no", rank, nx, QD_SS_RANK_TOL);
}

static void text(qd_buf *b, qd_ctx *ctx, const qd_statespace *s) {
    const char **rows = malloc((s->nx + s->nu + 1) * sizeof *rows);
    if (!rows) {
        b->failed = true;
        return;
    }
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
    put_rank(b, "controllable", s->controllable, s->rank_ctrb, s->nx);
    for (size_t k = 0; k < s->nuncontrollable; k++) {
        qd_buf_puts(b, "  uncontrollable mode: ");
        put_mode(b, s, s->uncontrollable[k]);
        qd_buf_puts(b, "\n");
    }
    if (s->ny)
        put_rank(b, "observable", s->observable, s->rank_obsv, s->nx);
    for (size_t k = 0; s->ny && k < s->nunobservable; k++) {
        qd_buf_puts(b, "  unobservable mode: ");
        put_mode(b, s, s->unobservable[k]);
        qd_buf_puts(b, "\n");
    }
    free(rows);
}

/* ---- json ------------------------------------------------------------------------ */

static void json_matrix(qd_json *j, const char *key, size_t r, size_t c, const double *x) {
    qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t i = 0; i < r; i++) {
        qd_json_begin_array(j);
        for (size_t k = 0; k < c; k++)
            qd_json_number(j, x[i * c + k]);
        qd_json_end_array(j);
    }
    qd_json_end_array(j);
}

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

static void json_modes(qd_json *j, const qd_statespace *s, size_t count, const size_t *idx) {
    qd_json_begin_array(j);
    for (size_t k = 0; k < count; k++) {
        size_t e = idx[k];
        qd_json_begin_object(j);
        qd_json_key(j, "eigenvalue");
        qd_json_begin_array(j);
        qd_json_number(j, s->eig_re[e]);
        qd_json_number(j, s->eig_im[e]);
        qd_json_end_array(j);
        qd_json_key(j, "states");
        qd_json_begin_array(j);
        for (size_t i = 0; i < s->nx; i++)
            if (hypot(s->vec_re[i * s->nx + e], s->vec_im[i * s->nx + e]) > 1e-6)
                qd_json_string(j, qd_expr_name(s->states[i]));
        qd_json_end_array(j);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
}

static void json(qd_buf *b, qd_ctx *ctx, const qd_statespace *s, const qd_care_result *lqr) {
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    json_names(&j, "states", s->nx, s->states, NULL);
    json_names(&j, "inputs", s->nu, s->inputs, NULL);
    json_names(&j, "outputs", s->ny, NULL, s->outputs);
    json_matrix(&j, "A", s->nx, s->nx, s->A);
    json_matrix(&j, "B", s->nx, s->nu, s->B);
    json_matrix(&j, "C", s->ny, s->nx, s->C);
    json_matrix(&j, "D", s->ny, s->nu, s->D);
    json_matrix(&j, "xdot0", 1, s->nx, s->xdot0);
    json_exact(&j, ctx, "A_exact", s->nx, s->nx, s->Asym);
    json_exact(&j, ctx, "B_exact", s->nx, s->nu, s->Bsym);
    qd_json_key(&j, "eigenvalues");
    qd_json_begin_array(&j);
    for (size_t k = 0; k < s->nx; k++) {
        qd_json_begin_array(&j);
        qd_json_number(&j, s->eig_re[k]);
        qd_json_number(&j, s->eig_im[k]);
        qd_json_end_array(&j);
    }
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
        if (cli_lqr_json_design(&j, s, lqr) != QD_EXIT_OK)
            b->failed = true;
    }
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    b->failed = b->failed || !qd_json_ok(&j);
}

/* ---- code: the exact matrices where known, else the numbers -------------------- */

static void code_entry(qd_buf *b, qd_ctx *ctx, const qd_expr *x, double v, qd_format f) {
    if (x)
        qd_print(ctx, x, f, b);
    else
        qd_buf_put_double(b, v);
}

static void code_matrix(qd_buf *b, qd_ctx *ctx, int fmt, const char *name, size_t r, size_t c,
                        const qd_expr *const *x, const double *v) {
    qd_format f = fmt == F_SYMPY ? QD_FMT_SYMPY : QD_FMT_C;
    if (fmt == F_C)
        qd_buf_printf(b, "static const double %s[%zu][%zu] = {\n", name, r ? r : 1, c ? c : 1);
    else
        qd_buf_printf(b, "%s = %s", name, fmt == F_SYMPY ? "Matrix([\n" : "[\n");
    for (size_t i = 0; i < r; i++) {
        qd_buf_puts(b, fmt == F_OCTAVE ? "  " : fmt == F_C ? "    {" : "    [");
        for (size_t k = 0; k < c; k++) {
            qd_buf_puts(b, k ? ", " : "");
            code_entry(b, ctx, x ? x[i * c + k] : NULL, v[i * c + k], f);
        }
        qd_buf_puts(b, fmt == F_OCTAVE ? ";\n" : fmt == F_C ? "},\n" : "],\n");
    }
    qd_buf_puts(b, fmt == F_C ? "};\n" : fmt == F_SYMPY ? "])\n" : "];\n");
}

static void code(qd_buf *b, qd_ctx *ctx, const qd_statespace *s, int fmt) {
    const char *c = fmt == F_SYMPY ? "#" : fmt == F_OCTAVE ? "%" : "//";
    qd_buf_printf(b, "%s x = [", c);
    for (size_t i = 0; i < s->nx; i++)
        qd_buf_printf(b, "%s%s", i ? ", " : "", qd_expr_name(s->states[i]));
    qd_buf_printf(b, "], u = [");
    for (size_t i = 0; i < s->nu; i++)
        qd_buf_printf(b, "%s%s", i ? ", " : "", qd_expr_name(s->inputs[i]));
    qd_buf_printf(b, "]%s\n", s->Asym ? "" : " (numbers: the exact form grew too large)");
    code_matrix(b, ctx, fmt, "A", s->nx, s->nx, s->Asym, s->A);
    code_matrix(b, ctx, fmt, "B", s->nx, s->nu, s->Bsym, s->B);
    if (s->ny) {
        code_matrix(b, ctx, fmt, "C", s->ny, s->nx, s->Csym, s->C);
        code_matrix(b, ctx, fmt, "D", s->ny, s->nu, s->Dsym, s->D);
    }
}

/* The state-space form, then the design when there is one: text and C
 * print it after the matrices, JSON nests it under "lqr". */
static int emit(qd_ctx *ctx, const lin_args *a, const qd_statespace *s,
                const qd_care_result *lqr) {
    qd_buf b = QD_BUF_INIT;
    if (a->format == F_TEXT)
        text(&b, ctx, s);
    else if (a->format == F_JSON)
        json(&b, ctx, s, lqr);
    else
        code(&b, ctx, s, a->format);
    int rc = cli_emit(&b, "state-space form");
    if (rc != QD_EXIT_OK || !lqr || a->format == F_JSON)
        return rc;
    /* run() refused --lqr with sympy and octave */
    return cli_lqr_print_design(stdout, s, lqr, a->format == F_TEXT ? CLI_LQR_TEXT : CLI_LQR_C);
}

/* A model that keeps holonomic constraints: A over the independent states
 * on the manifold (constrained_cli.c). */
static int constrained(qd_ctx *ctx, const lin_args *a, cli_model_file *mf, qd_eom *e) {
    if (!e->ncon) {
        cli_diag_error("--independent: the model keeps no constraints");
        return QD_EXIT_USAGE;
    }
    if (a->lqr || (a->format != F_TEXT && a->format != F_JSON)) {
        cli_diag_error("on the constraint manifold linearize gives A and B (text or json); %s "
                      "is not done yet", a->lqr ? "--lqr" : formats[a->format]);
        return QD_EXIT_USAGE;
    }
    cli_lin_run r = {.ctx = ctx, .mf = *mf, .e = e};
    int rc = cli_lin_setup(&r);
    double *q0 = rc == QD_EXIT_OK ? calloc(e->n + 1, sizeof *q0) : NULL;
    if (rc == QD_EXIT_OK && !q0) {
        cli_diag_error("out of memory");
        rc = QD_EXIT_FAIL;
    }
    if (rc == QD_EXIT_OK)
        rc = cli_con_point(&r, a->about, a->format == F_JSON, q0);
    if (rc == QD_EXIT_OK)
        rc = cli_con_linearize(&r, q0, a->independent, a->format == F_JSON);
    free(q0);
    cli_state_free(&r.st);
    free(r.slot);
    return rc;
}

static int run(qd_ctx *ctx, const lin_args *a) {
    cli_model_file mf = {0};
    qd_eom *e = NULL;
    lin_point pt = {0};
    qd_statespace s = {0};
    qd_care_result lqr = {0};
    qd_eom_opts eo = {.eliminate = true};
    int rc = QD_EXIT_OK;
    if (a->lqr && a->format != F_TEXT && a->format != F_JSON && a->format != F_C) {
        cli_diag_error("--lqr prints as text, json or c, not %s", formats[a->format]);
        rc = QD_EXIT_USAGE;
    }
    if (rc == QD_EXIT_OK)
        rc = cli_load_derive(ctx, a->file, a->sets.n, a->sets.items, false, &eo, &mf, &e);
    if (rc == QD_EXIT_OK && (e->ncon || a->independent)) {
        rc = constrained(ctx, a, &mf, e);
        goto done;
    }
    if (rc == QD_EXIT_OK && a->about)
        rc = read_about(ctx, mf.model, a->about, &pt);
    if (rc == QD_EXIT_OK &&
        qd_linearize(ctx, e, mf.model, pt.n, pt.syms, pt.vals, &s) != QD_OK) {
        rc = qd_ctx_status(ctx) == QD_ERR_ARG ? QD_EXIT_USAGE : QD_EXIT_FAIL;
        cli_diag_error("%s", qd_ctx_message(ctx));
    }
    if (rc == QD_EXIT_OK && a->lqr)
        rc = cli_lqr_design(ctx, &s, a->lqr, &lqr);
    if (rc == QD_EXIT_OK)
        rc = emit(ctx, a, &s, a->lqr ? &lqr : NULL);
done:
    qd_care_result_free(&lqr);
    qd_statespace_free(&s);
    point_free(&pt);
    qd_eom_free(e);
    cli_model_file_free(&mf);
    return rc;
}

int cli_cmd_linearize(int argc, char **argv) {
    lin_args a = {0};
    const char *pos[1];
    int rc = cli_parse(&spec, argc, argv, &a, pos);
    if (rc != QD_EXIT_OK)
        return rc;
    a.file = pos[0];
    for (int k = 0; a.format_name && formats[k]; k++)
        if (!strcmp(formats[k], a.format_name))
            a.format = k;
    qd_ctx *ctx = qd_ctx_new();
    if (!ctx) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    rc = run(ctx, &a);
    qd_ctx_free(ctx);
    return rc;
}
