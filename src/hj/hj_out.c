/*
 * src/hj/hj_out.c - the Hamilton-Jacobi equation and its separation written
 * out (qdot/hj.h): lines of text or LaTeX, a SymPy script and a JSON
 * document, the one rendering the program and Python share.
 */
#include <stdio.h>
#include <string.h>
#include "base/args.h"
#include "qdot/hj.h"
#include "qdot/json.h"

typedef struct hj_out {
    qd_ctx *ctx;
    const qd_hj *h;
    const qd_model *m;
    const char *path;
    qd_format fmt;
} hj_out;

/* The name of an output of the script: base, with underscores appended
 * while the model uses it for a coordinate, a parameter or a function, or
 * it is t (a parameter H must not be overwritten by the Hamiltonian). */
typedef struct hj_name { char s[32]; } hj_name;

static bool model_uses(const qd_model *m, const char *name) {
    for (size_t i = 0; i < qd_model_ncoords(m); i++)
        if (!strcmp(qd_expr_name(qd_model_coord(m, i)), name))
            return true;
    for (size_t i = 0; i < qd_model_nparams(m); i++)
        if (!strcmp(qd_expr_name(qd_model_param(m, i)), name))
            return true;
    for (size_t i = 0; i < qd_model_nfunctions(m); i++)
        if (!strcmp(qd_model_function_name(m, i), name))
            return true;
    return !strcmp(name, "t");
}

static hj_name script_name(const qd_model *m, const char *base) {
    hj_name n;
    snprintf(n.s, sizeof n.s, "%s", base);
    for (size_t len = strlen(n.s); model_uses(m, n.s) && len + 1 < sizeof n.s; len++)
        n.s[len] = '_', n.s[len + 1] = '\0';
    return n;
}

static void put(const hj_out *r, qd_buf *b, const qd_expr *x) {
    qd_print(r->ctx, x, r->fmt, b);
}

static const char *eol(const hj_out *r) {
    return r->fmt == QD_FMT_LATEX ? " \\\\\n" : "\n";
}

/* "  lhs = rhs" */
static void line(const hj_out *r, qd_buf *b, const char *lhs, const qd_expr *rhs) {
    qd_buf_printf(b, "  %s = ", lhs);
    put(r, b, rhs);
    qd_buf_puts(b, eol(r));
}

/* "  lhs = rhs" with lhs an expression too (p_x^2 is p_{x}^{2} in LaTeX). */
static void line_x(const hj_out *r, qd_buf *b, const qd_expr *lhs, const qd_expr *rhs) {
    qd_buf_puts(b, "  ");
    put(r, b, lhs);
    qd_buf_puts(b, " = ");
    put(r, b, rhs);
    qd_buf_puts(b, eol(r));
}

static void write_sep(const hj_out *r, qd_buf *b, const qd_hj_sep *s, const char *cmt) {
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
static void write_motion(const hj_out *r, qd_buf *b, const char *cmt) {
    const qd_hj *h = r->h;
    qd_buf_printf(b, "%smotion from d%s/dalpha = beta (beta_q: the constant of integration)\n", cmt,
                  h->time_part ? "S" : "W");
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

static void write_lines(const hj_out *r, qd_buf *b) {
    const qd_hj *h = r->h;
    const char *cmt = r->fmt == QD_FMT_LATEX ? "% " : "";
    qd_buf_printf(b, "%sqdot hj %s\n%sHamiltonian\n", cmt, r->path, cmt);
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
                  h->time_part ? "S = W + f(t), f' = -H(alpha, t)"
                  : h->n == 1 && h->sep[0].qk ? "momentum representation, W(p) = -int q dp"
                  : h->n == 1 && h->sep[0].pk ? "W = int p dq"
                                              : "p = +sqrt(p^2) on each branch");
    line(r, b, "W", h->W);
    if (h->time_part)
        line(r, b, "f(t)", h->time_part);
    if (r->h->solved)
        write_motion(r, b, cmt);
}

/* One separated coordinate: its equation, p^2, constant and integral. */
static void json_sep(const hj_out *r, qd_json *j, const qd_hj_sep *s) {
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
    if (r->h->solved) {
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

static void write_json(const hj_out *r, qd_buf *b) {
    const qd_hj *h = r->h;
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "model");
    qd_json_string(&j, r->path);
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
    if (h->time_part) { /* S = W + time_part (an explicit t) */
        qd_json_key(&j, "time_part");
        qd_json_expr(&j, r->ctx, h->time_part);
    }
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

static void sympy_assign(const hj_out *r, qd_buf *b, const char *name, const qd_expr *x) {
    qd_buf_printf(b, "%s = ", script_name(r->m, name).s);
    if (x)
        put(r, b, x);
    else
        qd_buf_puts(b, "None");
    qd_buf_puts(b, "\n");
}

static void sympy_list(const hj_out *r, qd_buf *b, const char *name, size_t off) {
    qd_buf_printf(b, "%s = [", script_name(r->m, name).s);
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
static void write_sympy_motion(const hj_out *r, qd_buf *b) {
    for (size_t k = 0; k < r->h->n; k++)
        if (r->h->sep[k].beta)
            qd_buf_printf(b, "%s = Symbol('%s')\n", qd_expr_name(r->h->sep[k].beta),
                          qd_expr_name(r->h->sep[k].beta));
    qd_buf_printf(b, "%s = {", script_name(r->m, "motion").s);
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
static void write_sympy(const hj_out *r, qd_buf *b) {
    const qd_hj *h = r->h;
    const qd_model *m = r->m;
    const char *t = qd_print_time_name(r->ctx); /* x for `independent x` */
    qd_buf_printf(b, "# qdot hj %s\nfrom sympy import *\n\n%s = Symbol('%s')\n"
                  "integral = Integral\nS = Function('S')\n", r->path, t, t);
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
    if (h->time_part)
        sympy_assign(r, b, "f_t", h->time_part);
    sympy_list(r, b, "p2", offsetof(qd_hj_sep, p2));
    sympy_list(r, b, "integrals", offsetof(qd_hj_sep, integral));
    if (r->h->solved)
        write_sympy_motion(r, b);
    qd_buf_printf(b, "# %s\n", h->why);
}

static qd_status hj_done(qd_ctx *ctx, const qd_buf *b) {
    if (!b->failed)
        return QD_OK;
    qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory writing the Hamilton-Jacobi equation");
    return QD_ERR_NOMEM;
}

qd_status qd_hj_print(qd_ctx *ctx, const qd_hj *h, const qd_model *m, const char *model_name,
                      qd_format fmt, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && h && m && out);
    if (fmt != QD_FMT_TEXT && fmt != QD_FMT_LATEX && fmt != QD_FMT_SYMPY) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the Hamilton-Jacobi equation is written as text, LaTeX "
                                      "or SymPy");
        return QD_ERR_ARG;
    }
    hj_out o = {ctx, h, m, model_name ? model_name : "model", fmt};
    if (fmt == QD_FMT_SYMPY)
        write_sympy(&o, out);
    else
        write_lines(&o, out);
    return hj_done(ctx, out);
}

qd_status qd_hj_json(qd_ctx *ctx, const qd_hj *h, const char *model_name, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && h && out);
    hj_out o = {ctx, h, NULL, model_name, QD_FMT_TEXT};
    write_json(&o, out);
    return hj_done(ctx, out);
}
