/*
 * cli/cmd_hj.c - `qdot hj FILE`: the Hamilton-Jacobi equation of a model,
 * whether and how it separates, the separated equations with their
 * constants, and the complete integral W (qd_hj_derive; Desloge ch. 78-79).
 * --solve adds the motion from dW/dalpha = beta where the quadratures close.
 * A system that does not separate is an answer, not an error (exit 0).
 */
#include "cli.h"

#include <stdlib.h>
#include <string.h>
#include "qdot/json.h"
#include "eom_out.h"
#include "model_cli.h"
#include "model_file.h"

#define MAX_SETS QD_CLI_MAX_LIST

typedef enum { FMT_TEXT, FMT_JSON, FMT_LATEX, FMT_SYMPY } hj_fmt;

typedef struct hj_run {
    qd_ctx *ctx;
    cli_model_file mf;
    qd_hj *h;
    hj_fmt fmt;
    const char *file, *energy, *sets[MAX_SETS];
    size_t nsets;
    bool solve;
} hj_run;

static const char usage_text[] =
    "usage: qdot hj FILE [--format text|json|latex|sympy] [--set NAME=VALUE]... "
    "[--energy NAME] [--solve]";

static const char *const formats[] = {"text", "json", "latex", "sympy", NULL};

static int parse_option(int argc, char **argv, int *i, void *data) {
    hj_run *r = data;
    const char *v;
    int f;
    if ((v = cli_value(argc, argv, i, "--format"))) {
        int rc = cli_choice("--format", v, formats, &f);
        r->fmt = (hj_fmt)f;
        return rc;
    }
    if ((v = cli_value(argc, argv, i, "--set")))
        return cli_push("--set", r->sets, &r->nsets, MAX_SETS, v);
    if ((v = cli_value(argc, argv, i, "--energy")))
        return cli_once("--energy", &r->energy, v);
    if (!strcmp(argv[*i], "--solve")) {
        r->solve = true;
        return QD_EXIT_OK;
    }
    return cli_bad_option(argv[*i], usage_text);
}

/* ---- output ---------------------------------------------------------------- */

static qd_format expr_format(hj_fmt f) {
    return f == FMT_LATEX ? QD_FMT_LATEX : f == FMT_SYMPY ? QD_FMT_SYMPY : QD_FMT_TEXT;
}

static void put(const hj_run *r, qd_buf *b, const qd_expr *x) {
    qd_print(r->ctx, x, expr_format(r->fmt), b);
}

static const char *eol(const hj_run *r) {
    return r->fmt == FMT_LATEX ? " \\\\\n" : "\n";
}

/* "  lhs = rhs" */
static void line(const hj_run *r, qd_buf *b, const char *lhs, const qd_expr *rhs) {
    qd_buf_printf(b, "  %s = ", lhs);
    put(r, b, rhs);
    qd_buf_puts(b, eol(r));
}

/* "  lhs = rhs" with lhs an expression too (p_x^2 is p_{x}^{2} in LaTeX). */
static void line_x(const hj_run *r, qd_buf *b, const qd_expr *lhs, const qd_expr *rhs) {
    qd_buf_puts(b, "  ");
    put(r, b, lhs);
    qd_buf_puts(b, " = ");
    put(r, b, rhs);
    qd_buf_puts(b, eol(r));
}

static void write_sep(const hj_run *r, qd_buf *b, const qd_hj_sep *s, const char *cmt) {
    const char *q = qd_expr_name(s->q);
    qd_buf_printf(b, "%s%s: constant %s%s\n", cmt, q, qd_expr_name(s->constant),
                  s->cyclic ? " (cyclic: its momentum is constant)" : "");
    line_x(r, b, s->equation, qd_int(r->ctx, 0));
    if (s->pk)
        line_x(r, b, s->p, s->pk);
    else if (s->qk)
        line_x(r, b, s->q, s->qk);
    else
        line_x(r, b, qd_powi(r->ctx, s->p, 2), s->p2);
    line_x(r, b, s->constant, s->integral);
}

/* --solve: q_k(t), or the orbit q_k(q_j), where the quadrature closes. */
static void write_motion(const hj_run *r, qd_buf *b, const char *cmt) {
    const qd_hj *h = r->h;
    qd_buf_printf(b, "%smotion from dW/dalpha = beta (beta_q: the constant of integration)\n", cmt);
    for (size_t k = 0; k < h->n; k++) {
        const qd_hj_sep *s = &h->sep[k];
        if (!s->motion) {
            qd_buf_printf(b, "%s  %s: no closed form\n", cmt, qd_expr_name(s->q));
            continue;
        }
        qd_buf_puts(b, "  ");
        put(r, b, s->q);
        qd_buf_puts(b, "(");
        put(r, b, s->clock);
        qd_buf_puts(b, ") = ");
        put(r, b, s->motion);
        qd_buf_puts(b, eol(r));
    }
}

static void write_lines(const hj_run *r, qd_buf *b) {
    const qd_hj *h = r->h;
    const char *cmt = r->fmt == FMT_LATEX ? "% " : "";
    qd_buf_printf(b, "%sqdot hj %s\n%sHamiltonian\n", cmt, r->mf.path, cmt);
    line(r, b, "H", h->H);
    qd_buf_printf(b, "%sHamilton-Jacobi equation, S(q, t)%s\n", cmt,
                  h->time_independent ? " = W(q) - E*t" : "");
    qd_buf_puts(b, "  ");
    put(r, b, h->equation);
    qd_buf_printf(b, " = 0%s", eol(r));
    qd_buf_printf(b, "%sseparable: %s (%s)\n", cmt, h->separable ? "yes" : "no", h->why);
    if (!h->separable)
        return;
    qd_buf_printf(b, "%sseparated equations\n", cmt);
    for (size_t k = 0; k < h->n; k++)
        write_sep(r, b, &h->sep[k], cmt);
    qd_buf_printf(b, "%scomplete integral (%s)\n", cmt,
                  h->n == 1 && h->sep[0].qk ? "momentum representation, W(p) = -int q dp"
                  : h->n == 1 && h->sep[0].pk ? "W = int p dq"
                                              : "p = +sqrt(p^2) on each branch");
    line(r, b, "W", h->W);
    if (r->solve)
        write_motion(r, b, cmt);
}

/* One separated coordinate: its equation, p^2, constant and integral. */
static void json_sep(const hj_run *r, qd_json *j, const qd_hj_sep *s) {
    qd_json_begin_object(j);
    qd_json_key(j, "coordinate");
    qd_json_string(j, qd_expr_name(s->q));
    qd_json_key(j, "momentum");
    qd_json_string(j, qd_expr_name(s->p));
    qd_json_key(j, "constant");
    qd_json_string(j, qd_expr_name(s->constant));
    qd_json_key(j, "equation");
    qd_json_expr(j, r->ctx, s->equation);
    qd_json_key(j, "p2");
    qd_json_expr(j, r->ctx, s->p2);
    qd_json_key(j, "p");
    qd_json_expr(j, r->ctx, s->pk);
    qd_json_key(j, "q_of_p");
    qd_json_expr(j, r->ctx, s->qk);
    qd_json_key(j, "cyclic");
    qd_json_bool(j, s->cyclic);
    qd_json_key(j, "integral");
    qd_json_expr(j, r->ctx, s->integral);
    if (r->solve) {
        qd_json_key(j, "motion");
        qd_json_expr(j, r->ctx, s->motion);
        qd_json_key(j, "clock");
        if (s->clock)
            qd_json_string(j, qd_expr_name(s->clock));
        else
            qd_json_null(j);
    }
    qd_json_end_object(j);
}

static void write_json(const hj_run *r, qd_buf *b) {
    const qd_hj *h = r->h;
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "file");
    qd_json_string(&j, r->mf.path);
    qd_json_key(&j, "H");
    qd_json_expr(&j, r->ctx, h->H);
    qd_json_key(&j, "equation");
    qd_json_expr(&j, r->ctx, h->equation);
    qd_json_key(&j, "time_independent");
    qd_json_bool(&j, h->time_independent);
    qd_json_key(&j, "separable");
    qd_json_bool(&j, h->separable);
    qd_json_key(&j, "form");
    if (h->separable)
        qd_json_string(&j, h->form);
    else
        qd_json_null(&j);
    qd_json_key(&j, "why");
    qd_json_string(&j, h->why);
    qd_json_key(&j, "separation");
    qd_json_begin_array(&j);
    for (size_t k = 0; h->separable && k < h->n; k++)
        json_sep(r, &j, &h->sep[k]);
    qd_json_end_array(&j);
    qd_json_key(&j, "W");
    qd_json_expr(&j, r->ctx, h->W);
    qd_json_key(&j, "constants");
    qd_json_begin_array(&j);
    for (size_t k = 0; k < h->nconst; k++)
        qd_json_string(&j, qd_expr_name(h->constants[k]));
    qd_json_end_array(&j);
    qd_json_key(&j, "energy_constant");
    qd_json_string(&j, qd_expr_name(h->energy));
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    b->failed = b->failed || !qd_json_ok(&j);
}

static void sympy_assign(const hj_run *r, qd_buf *b, const char *name, const qd_expr *x) {
    qd_buf_printf(b, "%s = ", cli_script_name(r->mf.model, name).s);
    if (x)
        put(r, b, x);
    else
        qd_buf_puts(b, "None");
    qd_buf_puts(b, "\n");
}

static void sympy_list(const hj_run *r, qd_buf *b, const char *name, size_t off) {
    qd_buf_printf(b, "%s = [", cli_script_name(r->mf.model, name).s);
    for (size_t k = 0; r->h->separable && k < r->h->n; k++) {
        qd_buf_puts(b, k ? ", " : "");
        const qd_expr *x = *(const qd_expr *const *)((const char *)&r->h->sep[k] + off);
        if (x)
            put(r, b, x);
        else
            qd_buf_puts(b, "None"); /* p2 of the momentum representation */
    }
    qd_buf_puts(b, "]\n");
}

/* motion = {coordinate: (clock, q)} where --solve closed the quadrature. */
static void write_sympy_motion(const hj_run *r, qd_buf *b) {
    for (size_t k = 0; k < r->h->n; k++)
        if (r->h->sep[k].beta)
            qd_buf_printf(b, "%s = Symbol('%s')\n", qd_expr_name(r->h->sep[k].beta),
                          qd_expr_name(r->h->sep[k].beta));
    qd_buf_printf(b, "%s = {", cli_script_name(r->mf.model, "motion").s);
    const char *sep = "";
    for (size_t k = 0; k < r->h->n; k++) {
        const qd_hj_sep *s = &r->h->sep[k];
        if (!s->motion)
            continue;
        qd_buf_printf(b, "%s'%s': (", sep, qd_expr_name(s->q));
        put(r, b, s->clock);
        qd_buf_puts(b, ", ");
        put(r, b, s->motion);
        qd_buf_puts(b, ")");
        sep = ", ";
    }
    qd_buf_puts(b, "}\n");
}

/* Python defining H, HJ (the equation), W, p2 and integrals (lists in
 * coordinate order), constants; integral(f, q) is SymPy's Integral. */
static void write_sympy(const hj_run *r, qd_buf *b) {
    const qd_hj *h = r->h;
    const qd_model *m = r->mf.model;
    const char *t = qd_print_time_name(r->ctx); /* x for `independent x` */
    qd_buf_printf(b, "# qdot hj %s\nfrom sympy import *\n\n%s = Symbol('%s')\n"
                  "integral = Integral\nS = Function('S')\n", r->mf.path, t, t);
    for (size_t k = 0; k < h->n; k++)
        qd_buf_printf(b, "%s = Function('%s')\n", qd_expr_name(h->sep[k].q ? h->sep[k].q
                                                                       : qd_model_coord(m, k)),
                      qd_expr_name(qd_model_coord(m, k)));
    for (size_t i = 0; i < qd_model_nparams(m); i++)
        qd_buf_printf(b, "%s = Symbol('%s')\n", qd_expr_name(qd_model_param(m, i)),
                      qd_expr_name(qd_model_param(m, i)));
    const qd_expr *syms[64];
    size_t ns = qd_free_symbols(r->ctx, h->H, syms, 64);
    for (size_t i = 0; i < ns && i < 64; i++)
        if (qd_symbol_role(syms[i]) == QD_ROLE_PLAIN)
            qd_buf_printf(b, "%s = Symbol('%s')\n", qd_expr_name(syms[i]), qd_expr_name(syms[i]));
    for (size_t k = 0; k < h->nconst; k++) /* E stays SymPy's e: the printer writes Symbol('E') */
        if (strcmp(qd_expr_name(h->constants[k]), "E"))
            qd_buf_printf(b, "%s = Symbol('%s')\n", qd_expr_name(h->constants[k]),
                          qd_expr_name(h->constants[k]));
    sympy_assign(r, b, "H", h->H);
    sympy_assign(r, b, "HJ", h->equation);
    qd_buf_printf(b, "separable = %s\n", h->separable ? "True" : "False");
    sympy_assign(r, b, "W", h->W);
    sympy_list(r, b, "p2", offsetof(qd_hj_sep, p2));
    sympy_list(r, b, "integrals", offsetof(qd_hj_sep, integral));
    if (r->solve)
        write_sympy_motion(r, b);
    qd_buf_printf(b, "# %s\n", h->why);
}

static int emit(hj_run *r) {
    qd_buf b = QD_BUF_INIT;
    if (r->fmt == FMT_JSON)
        write_json(r, &b);
    else if (r->fmt == FMT_SYMPY)
        write_sympy(r, &b);
    else
        write_lines(r, &b);
    return cli_emit(&b, "Hamilton-Jacobi equation");
}

static int run(hj_run *r) {
    int rc = cli_load(r->ctx, r->file, r->nsets, r->sets, true, &r->mf);
    if (rc != QD_EXIT_OK)
        return rc;
    qd_hj_opts opts = {.energy_name = r->energy};
    if (!(r->h = qd_hj_derive(r->ctx, r->mf.model, &opts)))
        return cli_eom_derive_error(r->ctx, &r->mf);
    r->solve = r->solve && r->h->separable;
    if (r->solve && qd_hj_solve(r->ctx, r->h) != QD_OK)
        return cli_diag_ctx(r->ctx);
    return emit(r);
}

int cli_cmd_hj(int argc, char **argv) {
    hj_run r = {.fmt = FMT_TEXT};
    int rc = cli_file_args(argc, argv, "hj", usage_text, &r.file, parse_option, &r);
    if (rc != QD_EXIT_OK)
        return rc;
    if (!(r.ctx = qd_ctx_new())) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    rc = run(&r);
    qd_hj_free(r.h);
    cli_model_file_free(&r.mf);
    qd_ctx_free(r.ctx);
    return rc;
}
