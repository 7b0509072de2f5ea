/*
 * src/render/hamiltonian.c - the Hamiltonian of a model printed
 * (qd_render_hamiltonian, qdot/render.h): the momenta, H(q, p, t), the
 * inverse Legendre transform of a model given by H, Hamilton's equations
 * and the verdicts H = T + V? and H conserved?, as text, LaTeX, JSON or a
 * SymPy script, symbolically or at a point (qd_ham_point_eval).  `qdot
 * hamiltonian` is this and its option parsing.
 */
#include "render.h"

#include <stdio.h>
#include <string.h>
#include "qdot/json.h"
#include "../base/args.h"
#include "../base/mem.h"

/* What every printer below reads: h's expressions, or at a point number
 * nodes in place of H, the equations and (implicit H) the velocities. */
typedef struct ham_view {
    qd_ctx *ctx;
    const qd_model *m;
    const qd_ham *h;
    const char *source;
    const qd_ham_point *at;
    qd_render_format fmt;
    const qd_expr *H;
    const qd_expr *const *vel, *const *dq, *const *dp;
    const qd_expr **numbers; /* at a point: 3n number nodes (vel, dq, dp) */
} ham_view;

static qd_format expr_format(qd_render_format f) {
    return f == QD_RENDER_LATEX ? QD_FMT_LATEX : f == QD_RENDER_SYMPY ? QD_FMT_SYMPY
                                                                      : QD_FMT_TEXT;
}

static void put(const ham_view *v, qd_buf *b, const qd_expr *x) {
    qd_print(v->ctx, x, expr_format(v->fmt), b);
}

static qd__render_name name(const ham_view *v, const char *base) {
    return qd__render_name_pick(v->m, base, 0, NULL);
}

/* ---- text and LaTeX ------------------------------------------------------------ */

/* "  lhs = rhs" (LaTeX rows end in \\). */
static void line(const ham_view *v, qd_buf *b, const qd_expr *lhs_x, const char *lhs,
                 const qd_expr *rhs) {
    qd_buf_puts(b, "  ");
    if (lhs_x)
        put(v, b, lhs_x);
    qd_buf_printf(b, "%s = ", lhs);
    put(v, b, rhs);
    qd_buf_puts(b, v->fmt == QD_RENDER_LATEX ? " \\\\\n" : "\n");
}

/* The second kind's (Desloge ch. 72 eqs. 5-6). */
static void verdicts2(const ham_view *v, qd_buf *b, const char *cmt) {
    const qd_ham *h = v->h;
    qd_buf_printf(b, "%sK = T: %s", cmt, h->is_energy ? "yes" : "no, K - T = ");
    if (!h->is_energy)
        qd_print(v->ctx, h->H_minus_E, QD_FMT_TEXT, b);
    qd_buf_printf(b, "\n%ss = p: %s\n%sK conserved: %s\n", cmt,
                  h->s_is_p ? "yes" : "no (U depends on the velocities)", cmt,
                  h->conserved ? "yes" : "no (explicit t or forces)");
}

static void verdicts(const ham_view *v, qd_buf *b, const char *cmt) {
    const qd_ham *h = v->h;
    if (h->second_kind) {
        verdicts2(v, b, cmt);
        return;
    }
    if (h->H_minus_E) {
        qd_buf_printf(b, "%sH = T + V: %s", cmt, h->is_energy ? "yes" : "no, H - (T + V) = ");
        if (!h->is_energy)
            qd_print(v->ctx, h->H_minus_E, QD_FMT_TEXT, b);
        qd_buf_puts(b, "\n");
    } else {
        qd_buf_printf(b, "%sH = T + V: unknown (the model gives %s, not T and V)\n", cmt,
                      h->H_given ? "H" : "L");
    }
    qd_buf_printf(b, "%sH conserved: %s\n", cmt,
                  h->conserved ? "yes" : "no (explicit t, generalized forces or dissipation)");
}

/* The second kind's forces Q_j, printed as Q_<q> = ... */
static void forces(const ham_view *v, qd_buf *b, const char *cmt) {
    const qd_ham *h = v->h;
    qd_buf_printf(b, "%sgeneralized forces (all but T's: given, -dV/dq, U's, -dD/dq')\n", cmt);
    for (size_t j = 0; j < h->n; j++) {
        char lhs[272];
        snprintf(lhs, sizeof lhs, "Q_%s", qd_expr_name(h->q[j]));
        line(v, b, NULL, lhs, h->extra[j]);
    }
}

static void write_lines(const ham_view *v, qd_buf *b) {
    const qd_ham *h = v->h;
    const bool latex = v->fmt == QD_RENDER_LATEX, at = v->at != NULL, k2 = h->second_kind;
    const char *cmt = latex ? "% " : "";
    qd_buf_printf(b, "%sqdot hamiltonian %s%s\n%smomenta%s%s\n", cmt,
                  k2 ? "--second-kind " : "", v->source, cmt, k2 ? " of T" : "",
                  h->implicit ? " (no closed form for the velocities: they solve these)"
                  : at        ? ""
                              : " and velocities");
    for (size_t j = 0; j < h->n; j++) {
        if (h->pdef[j])
            line(v, b, h->p[j], "", h->pdef[j]);
        if (!at && !h->implicit)
            line(v, b, h->qd[j], "", v->vel[j]);
    }
    if (h->implicit && at) {
        qd_buf_printf(b, "%svelocities at the point (Newton's method on the momenta)\n", cmt);
        for (size_t j = 0; j < h->n; j++)
            line(v, b, h->qd[j], "", v->vel[j]);
    }
    if (h->implicit && !at)
        qd_buf_printf(b, "%s%s (defined implicitly: sum %s q' - %s at those velocities)\n", cmt,
                      k2 ? "K" : "Hamiltonian", k2 ? "s" : "p", k2 ? "T" : "L");
    else
        qd_buf_printf(b, "%s%s%s\n", cmt, k2 ? "K = sum s q' - T" : "Hamiltonian",
                      at ? " at the point" : "");
    line(v, b, NULL, k2 ? "K" : "H", v->H);
    if (k2 && !at)
        forces(v, b, cmt);
    if (h->H_given && !at) {
        qd_buf_printf(b, "%sLagrangian (inverse Legendre transform)\n", cmt);
        if (h->L_from_H)
            line(v, b, NULL, "L", h->L_from_H);
        else
            qd_buf_printf(b, "%s  none: %s\n", cmt, h->L_why);
    }
    qd_buf_printf(b, "%sHamilton's equations%s\n", cmt, k2 ? " of the second kind" : "");
    for (size_t j = 0; j < h->n; j++) {
        qd_buf_printf(b, "  d%s/dt = ", qd_expr_name(h->q[j]));
        put(v, b, v->dq[j]);
        qd_buf_printf(b, "%s  d%s/dt = ", latex ? " \\\\\n" : "\n", qd_expr_name(h->p[j]));
        put(v, b, v->dp[j]);
        qd_buf_puts(b, latex ? " \\\\\n" : "\n");
    }
    verdicts(v, b, cmt);
}

/* ---- SymPy --------------------------------------------------------------------- */

static void sympy_list(const ham_view *v, qd_buf *b, const char *base,
                       const qd_expr *const *x) {
    qd_buf_printf(b, "%s = [", name(v, base).s);
    for (size_t j = 0; j < v->h->n; j++) {
        qd_buf_puts(b, j ? ", " : "");
        put(v, b, x[j]);
    }
    qd_buf_puts(b, "]\n");
}

/* W = Function('W') for the user functions in H, L and the lists. */
static qd_status sympy_functions(const ham_view *v, qd_buf *b) {
    const qd_ham *h = v->h;
    const qd_expr *const *lists[5] = {h->pdef, v->vel, v->dq, v->dp, h->extra};
    const qd_expr **all = qd__malloc(v->ctx, (2 + 5 * h->n) * sizeof *all);
    if (!all)
        return QD_ERR_NOMEM;
    size_t k = 0;
    all[k++] = v->H;
    all[k++] = h->L_from_H;
    for (size_t i = 0; i < (h->second_kind ? 5u : 4u); i++)
        for (size_t j = 0; j < h->n; j++)
            all[k++] = lists[i][j];
    qd_status st = qd_print_sympy_functions(v->ctx, k, all, b);
    qd__free(all);
    return st;
}

/* Python that defines momenta, pdef (dL/dq'), H, dq_dt and dp_dt (each with
 * underscores appended when the model uses the name: a length L); the
 * coordinates are functions of t as in `eom --format sympy`. */
static qd_status write_sympy(const ham_view *v, qd_buf *b) {
    const qd_ham *h = v->h;
    const qd_model *m = v->m;
    const char *t = qd_print_time_name(v->ctx); /* x for `independent x` */
    const bool k2 = h->second_kind;
    qd_buf_printf(b, "# qdot hamiltonian %s%s\nfrom sympy import *\n\n%s = Symbol('%s')\n",
                  k2 ? "--second-kind " : "", v->source, t, t);
    for (size_t j = 0; j < h->n; j++)
        qd_buf_printf(b, "%s = Function('%s')\n%s = Symbol('%s')\n", qd_expr_name(h->q[j]),
                      qd_expr_name(h->q[j]), qd_expr_name(h->p[j]), qd_expr_name(h->p[j]));
    for (size_t i = 0; i < qd_model_nparams(m); i++)
        qd_buf_printf(b, "%s = Symbol('%s')\n", qd_expr_name(qd_model_param(m, i)),
                      qd_expr_name(qd_model_param(m, i)));
    for (size_t i = 0; i < qd_model_ninputs(m); i++) /* inputs print by name */
        qd_buf_printf(b, "%s = Symbol('%s')\n", qd_expr_name(qd_model_input(m, i)),
                      qd_expr_name(qd_model_input(m, i)));
    qd_status st = sympy_functions(v, b);
    if (st != QD_OK)
        return st;
    sympy_list(v, b, "momenta", h->p);
    if (!h->n || h->pdef[0])
        sympy_list(v, b, "pdef", h->pdef);
    else
        qd_buf_printf(b, "%s = None\n", name(v, "pdef").s);
    sympy_list(v, b, "velocities", v->vel);
    if (h->implicit) /* velocities are then the symbols q' themselves, tied to p by pdef */
        qd_buf_printf(b, "%s = True\n", name(v, "implicit").s);
    qd_buf_printf(b, "%s = ", name(v, k2 ? "K" : "H").s);
    put(v, b, v->H);
    qd_buf_puts(b, "\n");
    if (k2)
        sympy_list(v, b, "forces", h->extra);
    if (h->H_given) {
        qd_buf_printf(b, "%s = ", name(v, "L").s);
        if (h->L_from_H)
            put(v, b, h->L_from_H);
        else
            qd_buf_puts(b, "None");
        qd_buf_puts(b, "\n");
    }
    sympy_list(v, b, "dq_dt", v->dq);
    sympy_list(v, b, k2 ? "ds_dt" : "dp_dt", v->dp);
    verdicts(v, b, "# ");
    return QD_OK;
}

/* ---- JSON ---------------------------------------------------------------------- */

/* A number node as the nearest double: an exact rational p/q that fits is
 * computed as (double)p/q, correctly rounded. */
static double number_value(const qd_expr *x) {
    long p, q;
    if (qd_rational_get(x, &p, &q) && (p < 0 ? -(double)p : (double)p) <= 0x1p53 &&
        (double)q <= 0x1p53)
        return (double)p / (double)q;
    return qd_number_value(x);
}

/* A string of x, or its number at a point. */
static void json_expr(const ham_view *v, qd_json *j, const qd_expr *x) {
    if (v->at && x && qd_is_number(x))
        qd_json_number(j, number_value(x));
    else
        qd_json_expr(j, v->ctx, x);
}

static void json_list(const ham_view *v, qd_json *j, const char *key, const qd_expr *const *x) {
    qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t k = 0; k < v->h->n; k++)
        if (x[k])
            json_expr(v, j, x[k]);
        else
            qd_json_null(j);
    qd_json_end_array(j);
}

/* "at": the point's coordinates, t and momenta. */
static void json_point(const ham_view *v, qd_json *j) {
    const qd_ham *h = v->h;
    qd_json_key(j, "at");
    qd_json_begin_object(j);
    for (size_t k = 0; k < h->n; k++) {
        qd_json_key(j, qd_expr_name(h->q[k]));
        qd_json_number(j, v->at->q[k]);
    }
    qd_json_key(j, qd_expr_name(qd_time(v->ctx)));
    qd_json_number(j, v->at->t);
    for (size_t k = 0; k < h->n; k++) {
        qd_json_key(j, qd_expr_name(h->p[k]));
        qd_json_number(j, v->at->p[k]);
    }
    qd_json_end_object(j);
}

/* The second kind's verdicts (Desloge ch. 72 eqs. 5-6). */
static void json_verdicts2(const ham_view *v, qd_json *j) {
    const qd_ham *h = v->h;
    qd_json_key(j, "K_is_T");
    qd_json_bool(j, h->is_energy);
    qd_json_key(j, "K_minus_T");
    qd_json_expr(j, v->ctx, h->H_minus_E);
    qd_json_key(j, "s_is_p");
    qd_json_bool(j, h->s_is_p);
    qd_json_key(j, "conserved");
    qd_json_bool(j, h->conserved);
}

static bool write_json(const ham_view *v, qd_buf *b) {
    const qd_ham *h = v->h;
    const bool k2 = h->second_kind;
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "model");
    qd_json_string(&j, v->source);
    if (k2) {
        qd_json_key(&j, "kind");
        qd_json_string(&j, "second");
    }
    qd_json_key(&j, "coordinates");
    qd_json_begin_array(&j);
    for (size_t k = 0; k < h->n; k++)
        qd_json_string(&j, qd_expr_name(h->q[k]));
    qd_json_end_array(&j);
    qd_json_key(&j, "momenta");
    qd_json_begin_array(&j);
    for (size_t k = 0; k < h->n; k++)
        qd_json_string(&j, qd_expr_name(h->p[k]));
    qd_json_end_array(&j);
    json_list(v, &j, "definitions", h->pdef);
    json_list(v, &j, "velocities", v->vel);
    if (h->implicit) { /* only then, so the other models' output is unchanged */
        qd_json_key(&j, "implicit");
        qd_json_bool(&j, true);
    }
    if (v->at)
        json_point(v, &j);
    qd_json_key(&j, k2 ? "K" : "H");
    json_expr(v, &j, v->H);
    if (k2)
        json_list(v, &j, "forces", h->extra);
    json_list(v, &j, "dq_dt", v->dq);
    json_list(v, &j, k2 ? "ds_dt" : "dp_dt", v->dp);
    if (k2) {
        json_verdicts2(v, &j);
        qd_json_end_object(&j);
        qd_buf_puts(b, "\n");
        return qd_json_ok(&j);
    }
    qd_json_key(&j, "H_is_energy");
    if (h->H_minus_E)
        qd_json_bool(&j, h->is_energy);
    else
        qd_json_null(&j);
    qd_json_key(&j, "H_minus_energy");
    qd_json_expr(&j, v->ctx, h->H_minus_E);
    qd_json_key(&j, "conserved");
    qd_json_bool(&j, h->conserved);
    qd_json_key(&j, "H_given");
    qd_json_bool(&j, h->H_given);
    if (h->H_given && !v->at) { /* the inverse Legendre transform, or why there is none */
        qd_json_key(&j, "L");
        json_expr(v, &j, h->L_from_H);
        qd_json_key(&j, "L_error");
        if (h->L_from_H)
            qd_json_null(&j);
        else
            qd_json_string(&j, h->L_why);
    }
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    return qd_json_ok(&j);
}

/* ---- the entry ------------------------------------------------------------------ */

/* At a point: number nodes for H, the equations and an implicit H's
 * velocities; else h's own expressions. */
static qd_status view_values(ham_view *v) {
    const qd_ham *h = v->h;
    v->H = h->H;
    v->vel = h->vel;
    v->dq = h->dq;
    v->dp = h->dp;
    if (!v->at)
        return QD_OK;
    size_t n = h->n;
    const qd_expr **x = v->numbers = qd__calloc(v->ctx, 3 * n + 1, sizeof *x);
    if (!x)
        return QD_ERR_NOMEM;
    if (!(v->H = qd_float(v->ctx, v->at->H)))
        return qd_ctx_status(v->ctx);
    for (size_t k = 0; k < n; k++) {
        if (h->implicit && !(x[k] = qd_float(v->ctx, v->at->qd[k])))
            return qd_ctx_status(v->ctx);
        if (!(x[n + k] = qd_float(v->ctx, v->at->dq[k])) ||
            !(x[2 * n + k] = qd_float(v->ctx, v->at->dp[k])))
            return qd_ctx_status(v->ctx);
    }
    if (h->implicit)
        v->vel = x;
    v->dq = x + n;
    v->dp = x + 2 * n;
    return QD_OK;
}

qd_status qd_render_hamiltonian(qd_ctx *ctx, const qd_model *m, const qd_ham *h,
                                const char *source, const qd_ham_point *at,
                                qd_render_format fmt, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && m && h && out);
    if (fmt != QD_RENDER_TEXT && fmt != QD_RENDER_LATEX && fmt != QD_RENDER_JSON &&
        fmt != QD_RENDER_SYMPY) {
        qd_ctx_error(ctx, QD_ERR_ARG, "a Hamiltonian prints as text, latex, json or sympy");
        return QD_ERR_ARG;
    }
    if (at && (at->n != h->n || (h->n && (!at->q || !at->p || !at->qd || !at->dq || !at->dp)))) {
        qd_ctx_error(ctx, QD_ERR_ARG, "qd_render_hamiltonian: a point of %zu coordinates for "
                                      "a Hamiltonian of %zu", at->n, h->n);
        return QD_ERR_ARG;
    }
    ham_view v = {ctx, m, h, source ? source : "model", at, fmt, NULL, NULL, NULL, NULL, NULL};
    qd_buf b = QD_BUF_WITH(out->alloc);
    qd_status st = view_values(&v);
    bool json_refused = false;
    if (st == QD_OK && fmt == QD_RENDER_JSON && !write_json(&v, &b)) {
        st = b.failed ? QD_ERR_NOMEM : QD_ERR_NUMERIC;
        json_refused = true;
    } else if (st == QD_OK && fmt == QD_RENDER_SYMPY)
        st = write_sympy(&v, &b);
    else if (st == QD_OK && fmt != QD_RENDER_JSON)
        write_lines(&v, &b);
    if (st == QD_OK && (b.failed || qd_ctx_status(ctx) == QD_ERR_NOMEM))
        st = QD_ERR_NOMEM;
    if (st == QD_OK)
        qd_buf_putn(out, qd_buf_str(&b), b.len);
    if (st == QD_OK && out->failed)
        st = QD_ERR_NOMEM;
    if (st == QD_ERR_NOMEM)
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
    else if (json_refused)
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "a number of the Hamiltonian is not finite");
    qd_buf_free(&b);
    qd__free(v.numbers);
    return st;
}
