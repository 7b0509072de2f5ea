/*
 * src/render/speeds.c - the five renderings of the equations in generalized
 * speeds: q' = W u + w (the kinematics), M_u u' = f_u, and with --appell
 * and --multipliers S and lambda (qdot/speeds.h).
 *
 * The same habits as eom_out.c: text for reading, LaTeX as one align
 * environment, JSON with expressions as strings in the model language, a
 * SymPy script that runs as it is, one C block sharing subexpressions.  The
 * speeds are functions of t like the coordinates, so u' prints as w1' (text),
 * \dot{w}_{1} (LaTeX), w1(t).diff(t) (SymPy) and w1_d (C).  With --at the
 * text and JSON carry numbers instead: q', u' and the multipliers.
 */
#include "render.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "qdot/json.h"
#include "../base/args.h"
#include "../base/mem.h"

/* What qd_render_speeds prints: at a state, qd the velocities from the
 * kinematics (n), ud the speeds' rates (m) and lambda the multipliers
 * (ncon) or NULL. */
typedef struct view {
    qd_ctx *ctx;
    const qd_model *m;
    const char *source;
    const qd_speeds_eom *e;
    bool multipliers;
    const qd_render_opts *at;
    const double *qd, *ud, *lambda;
} view;

static const char *qname(const view *v, size_t j) { return qd_expr_name(v->e->q[j]); }
static const char *uname(const view *v, size_t r) { return qd_expr_name(v->e->u[r]); }

/* The name of an output of the SymPy and C renderings, also kept clear of
 * the speeds (a speed called u must not be overwritten by the vector). */
static qd__render_name pick(const view *v, const char *base) {
    return qd__render_name_pick(v->m, base, v->e->m, v->e->u);
}

/* ---- text ------------------------------------------------------------------ */

static void text_names(qd_buf *b, const char *what, const qd_expr *const *x, size_t n) {
    qd_buf_printf(b, "%s:", what);
    for (size_t i = 0; i < n; i++)
        qd_buf_printf(b, "%s %s", i ? "," : "", qd_expr_name(x[i]));
    qd_buf_puts(b, n ? "\n" : " none\n");
}

static void text_header(const view *v, qd_buf *b) {
    qd_buf_printf(b, "model: %s\n", v->source);
    text_names(b, "coordinates", v->e->q, v->e->n);
    text_names(b, "speeds", v->e->u, v->e->m);
    qd__render_params(b, v->m);
    qd_buf_printf(b, "\nmethod: %s\n", qd_speeds_method_name(v->e->method));
}

/* "  NAME = EXPR\n" */
static qd_status text_line(const view *v, qd_buf *b, const char *name,
                           const qd_expr *x) {
    qd_buf_printf(b, "  %s = ", name);
    qd_status st = qd_print(v->ctx, x, QD_FMT_TEXT, b);
    qd_buf_puts(b, "\n");
    return st;
}

static qd_status text_kinematics(const view *v, qd_buf *b) {
    qd_status st = QD_OK;
    char lhs[160];
    qd_buf_puts(b, "\nkinematics q' = W u + w:\n");
    for (size_t j = 0; j < v->e->n && st == QD_OK; j++) {
        snprintf(lhs, sizeof lhs, "%s'", qname(v, j));
        st = text_line(v, b, lhs, v->e->kin[j]);
    }
    if (!v->e->ncon)
        return st;
    qd_buf_puts(b, "\nconstraints (the kinematics satisfy them for every u: no multiplier "
                   "enters):\n");
    for (size_t k = 0; k < v->e->ncon && st == QD_OK; k++) {
        const qd_con *c = &v->e->con[k];
        qd_buf_printf(b, "  %s (%s): ", c->name, qd_con_kind_name(c->kind));
        st = qd_print(v->ctx, c->expr, QD_FMT_TEXT, b);
        qd_buf_puts(b, " = 0\n");
    }
    return st;
}

static qd_status text_dynamics(const view *v, qd_buf *b) {
    size_t m = v->e->m;
    qd_status st = QD_OK;
    char lhs[300];
    qd_buf_puts(b, "\nequations M u' = f in the speeds (M is symmetric: entries with r <= s):\n");
    for (size_t r = 0; r < m; r++)
        for (size_t s = r; s < m && st == QD_OK; s++) {
            snprintf(lhs, sizeof lhs, "M[%s,%s]", uname(v, r), uname(v, s));
            st = text_line(v, b, lhs, v->e->M[r * m + s]);
        }
    for (size_t r = 0; r < m && st == QD_OK; r++) {
        snprintf(lhs, sizeof lhs, "f[%s]", uname(v, r));
        st = text_line(v, b, lhs, v->e->f[r]);
    }
    return st;
}

/* ---- numbers at a state (--at) ------------------------------------------------ */

/* The k-th symbol shown of the state (k < n + m + 1): the coordinates, the
 * speeds, then t; the parameters are in the header. */
static const qd_expr *state_sym(const view *v, size_t k) {
    size_t nq = v->e->n, m = v->e->m;
    return k < nq ? v->e->q[k] : k < nq + m ? v->e->u[k - nq] : qd_time(v->ctx);
}

static void text_state(const view *v, qd_buf *b) {
    qd_buf_puts(b, "at:");
    for (size_t k = 0; k < v->e->n + v->e->m + 1; k++) {
        qd_buf_printf(b, "%s%s = ", k ? ", " : " ", qd_expr_name(state_sym(v, k)));
        qd__render_number(b, qd__render_value(v->at, state_sym(v, k)));
    }
    qd_buf_puts(b, "\n");
}

static void text_number(qd_buf *b, const char *name, const char *suffix, double x) {
    qd_buf_printf(b, "  %s%s = ", name, suffix);
    qd__render_number(b, x);
    qd_buf_puts(b, "\n");
}

static qd_status write_text_at(const view *v, qd_buf *b) {
    text_state(v, b);
    qd_buf_puts(b, "\nvelocities q' = W u + w:\n");
    for (size_t j = 0; j < v->e->n; j++)
        text_number(b, qname(v, j), "'", v->qd[j]);
    qd_buf_puts(b, "\nthe speeds' rates, M u' = f solved:\n");
    for (size_t r = 0; r < v->e->m; r++)
        text_number(b, uname(v, r), "'", v->ud[r]);
    if (v->multipliers && !v->e->ncon)
        qd_buf_puts(b, "\nmultipliers: none (the model has no constraints)\n");
    if (v->lambda && v->e->ncon) {
        qd_buf_puts(b, "\nmultipliers:\n");
        for (size_t k = 0; k < v->e->ncon; k++)
            text_number(b, qd_expr_name(v->e->con[k].lambda), "", v->lambda[k]);
    }
    return QD_OK;
}

static qd_status write_text(const view *v, qd_buf *b) {
    text_header(v, b);
    if (v->at)
        return write_text_at(v, b);
    qd_status st = text_kinematics(v, b);
    if (st == QD_OK)
        st = text_dynamics(v, b);
    if (st == QD_OK && v->e->acc) {
        qd_buf_puts(b, "\nthe speeds' rates, u' = M^-1 f:\n");
        for (size_t r = 0; r < v->e->m && st == QD_OK; r++) {
            char lhs[160];
            snprintf(lhs, sizeof lhs, "%s'", uname(v, r));
            st = text_line(v, b, lhs, v->e->acc[r]);
        }
    }
    if (st == QD_OK && v->e->S) {
        qd_buf_puts(b, "\nGibbs-Appell function (the acceleration energy, terms free of u' "
                       "dropped):\n");
        st = text_line(v, b, "S", v->e->S);
    }
    if (st == QD_OK && v->multipliers && !v->e->ncon)
        qd_buf_puts(b, "\nmultipliers: none (the model has no constraints)\n");
    if (st == QD_OK && v->e->mult && v->e->ncon) {
        qd_buf_puts(b, "\nmultipliers (as in M q'' = f + A^T lambda, in q, u, u' and t):\n");
        for (size_t k = 0; k < v->e->ncon && st == QD_OK; k++)
            st = text_line(v, b, qd_expr_name(v->e->con[k].lambda), v->e->mult[k]);
    }
    return st;
}

/* ---- LaTeX ----------------------------------------------------------------- */

static qd_status latex_line(const view *v, qd_buf *b, bool *first, const qd_expr *lhs,
                            const qd_expr *rhs) {
    qd_buf_puts(b, *first ? "  " : " \\\\\n  ");
    *first = false;
    qd_status st = qd_print(v->ctx, lhs, QD_FMT_LATEX, b);
    qd_buf_puts(b, " &= ");
    return st == QD_OK ? qd_print(v->ctx, rhs, QD_FMT_LATEX, b) : st;
}

/* sum_s M_rs u'_s. */
static const qd_expr *latex_row(const view *v, size_t r) {
    size_t m = v->e->m;
    const qd_expr *sum = qd_int(v->ctx, 0);
    for (size_t s = 0; s < m; s++)
        sum = qd_add(v->ctx, sum, qd_mul(v->ctx, v->e->M[r * m + s], v->e->ud[s]));
    return sum;
}

static qd_status write_latex(const view *v, qd_buf *b) {
    const qd_speeds_eom *e = v->e;
    bool first = true;
    qd_status st = QD_OK;
    qd_buf_puts(b, "\\begin{align}\n");
    for (size_t j = 0; j < e->n && st == QD_OK; j++)
        st = latex_line(v, b, &first, e->qd[j], e->kin[j]);
    for (size_t r = 0; r < e->m && st == QD_OK; r++) {
        const qd_expr *row = latex_row(v, r);
        st = row ? latex_line(v, b, &first, row, e->f[r]) : qd_ctx_status(v->ctx);
    }
    for (size_t r = 0; e->acc && r < e->m && st == QD_OK; r++)
        st = latex_line(v, b, &first, e->ud[r], e->acc[r]);
    if (st == QD_OK && e->S) {
        const qd_expr *S = qd_symbol(v->ctx, "S");
        st = S ? latex_line(v, b, &first, S, e->S) : qd_ctx_status(v->ctx);
    }
    for (size_t k = 0; e->mult && k < e->ncon && st == QD_OK; k++)
        st = latex_line(v, b, &first, e->con[k].lambda, e->mult[k]);
    qd_buf_puts(b, "\n\\end{align}\n");
    return st;
}

/* ---- JSON ------------------------------------------------------------------ */

static qd_status json_expr(const view *v, qd_json *j, const qd_expr *x, qd_buf *tmp) {
    return qd__render_json_expr(v->ctx, j, x, tmp);
}

static void json_header(const view *v, qd_json *j) {
    qd_json_key(j, "model");
    qd_json_string(j, v->source);
    qd__render_json_names(j, "coordinates", v->e->q, v->e->n);
    qd__render_json_names(j, "speeds", v->e->u, v->e->m);
    qd__render_json_params(j, v->m);
    qd_json_key(j, "method");
    qd_json_string(j, qd_speeds_method_name(v->e->method));
}

/* "kinematics": [{"coordinate": "phi", "expression": "..."}, ...] */
static qd_status json_kinematics(const view *v, qd_json *j, qd_buf *tmp) {
    qd_status st = QD_OK;
    qd_json_key(j, "kinematics");
    qd_json_begin_array(j);
    for (size_t i = 0; i < v->e->n && st == QD_OK; i++) {
        qd_json_begin_object(j);
        qd_json_key(j, "coordinate");
        qd_json_string(j, qname(v, i));
        qd_json_key(j, "expression");
        st = json_expr(v, j, v->e->kin[i], tmp);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
    return st;
}

static qd_status json_dynamics(const view *v, qd_json *j, qd_buf *tmp) {
    size_t m = v->e->m;
    qd_status st = QD_OK;
    qd_json_key(j, "mass_matrix");
    qd_json_begin_array(j);
    for (size_t r = 0; r < m && st == QD_OK; r++) {
        qd_json_begin_array(j);
        for (size_t s = 0; s < m && st == QD_OK; s++)
            st = json_expr(v, j, v->e->M[r * m + s], tmp);
        qd_json_end_array(j);
    }
    qd_json_end_array(j);
    qd_json_key(j, "forcing");
    qd_json_begin_array(j);
    for (size_t r = 0; r < m && st == QD_OK; r++)
        st = json_expr(v, j, v->e->f[r], tmp);
    qd_json_end_array(j);
    if (v->e->acc) {
        qd_json_key(j, "rates");
        qd_json_begin_array(j);
        for (size_t r = 0; r < m && st == QD_OK; r++)
            st = json_expr(v, j, v->e->acc[r], tmp);
        qd_json_end_array(j);
    }
    return st;
}

/* "constraints" (name, kind, expression, multiplier) and, when computed,
 * "multipliers" by constraint name, as for the coordinates' output. */
static qd_status json_constraints(const view *v, qd_json *j, qd_buf *tmp) {
    qd_status st = QD_OK;
    qd_json_key(j, "constraints");
    qd_json_begin_array(j);
    for (size_t k = 0; k < v->e->ncon && st == QD_OK; k++) {
        const qd_con *c = &v->e->con[k];
        qd_json_begin_object(j);
        qd_json_key(j, "name");
        qd_json_string(j, c->name);
        qd_json_key(j, "kind");
        qd_json_string(j, qd_con_kind_name(c->kind));
        qd_json_key(j, "expression");
        st = json_expr(v, j, c->expr, tmp);
        qd_json_key(j, "multiplier");
        qd_json_string(j, qd_expr_name(c->lambda));
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
    if (!v->e->mult)
        return st;
    qd_json_key(j, "multipliers");
    qd_json_begin_object(j);
    for (size_t k = 0; k < v->e->ncon && st == QD_OK; k++) {
        qd_json_key(j, v->e->con[k].name);
        st = json_expr(v, j, v->e->mult[k], tmp);
    }
    qd_json_end_object(j);
    return st;
}

static void json_numbers(qd_json *j, const char *key, const double *x, size_t n) {
    qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t i = 0; i < n; i++)
        qd_json_number(j, x[i]);
    qd_json_end_array(j);
}

/* --at: "state" (coordinates, speeds, t by name), "velocities" (in the
 * order of "coordinates"), "rates" (of "speeds") and "multipliers". */
static void json_at(const view *v, qd_json *j) {
    qd_json_key(j, "state");
    qd_json_begin_object(j);
    for (size_t k = 0; k < v->e->n + v->e->m + 1; k++) {
        qd_json_key(j, qd_expr_name(state_sym(v, k)));
        qd_json_number(j, qd__render_value(v->at, state_sym(v, k)));
    }
    qd_json_end_object(j);
    json_numbers(j, "velocities", v->qd, v->e->n);
    json_numbers(j, "rates", v->ud, v->e->m);
    if (!v->lambda && !v->multipliers)
        return;
    qd_json_key(j, "multipliers");
    qd_json_begin_object(j);
    for (size_t k = 0; v->lambda && k < v->e->ncon; k++) {
        qd_json_key(j, v->e->con[k].name);
        qd_json_number(j, v->lambda[k]);
    }
    qd_json_end_object(j);
}

static qd_status write_json(const view *v, qd_buf *b) {
    qd_buf tmp = QD_BUF_INIT;
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    json_header(v, &j);
    if (v->at) {
        json_at(v, &j);
        qd_json_end_object(&j);
        qd_buf_puts(b, "\n");
        return qd__render_json_status(&j, b, QD_OK);
    }
    qd_status st = json_kinematics(v, &j, &tmp);
    if (st == QD_OK && v->e->T) {
        qd_json_key(&j, "T");
        st = json_expr(v, &j, v->e->T, &tmp);
    }
    if (st == QD_OK)
        st = json_dynamics(v, &j, &tmp);
    if (st == QD_OK && v->e->S) {
        qd_json_key(&j, "S");
        st = json_expr(v, &j, v->e->S, &tmp);
    }
    if (st == QD_OK && v->e->ncon)
        st = json_constraints(v, &j, &tmp);
    if (v->multipliers && !v->e->ncon) {
        qd_json_key(&j, "multipliers");
        qd_json_begin_object(&j);
        qd_json_end_object(&j);
    }
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    qd_buf_free(&tmp);
    return qd__render_json_status(&j, b, st);
}

/* ---- SymPy ----------------------------------------------------------------- */

static qd_status sympy_scalar(const view *v, qd_buf *b, const char *name,
                              const qd_expr *x) {
    qd_buf_printf(b, "%s = ", name);
    qd_status st = qd_print(v->ctx, x, QD_FMT_SYMPY, b);
    qd_buf_puts(b, "\n");
    return st;
}

/* W = Function('W') for the user functions in everything printed below. */
static qd_status sympy_functions(const view *v, qd_buf *b) {
    const qd_speeds_eom *e = v->e;
    size_t n = e->n, m = e->m;
    const qd__render_part parts[] = {
        {NULL, e->kin, n, 0, 1},          {NULL, e->M, m, m, 2},
        {NULL, e->f, m, 0, 1},            {NULL, e->T ? &e->T : NULL, 1, 0, 0},
        {NULL, e->S ? &e->S : NULL, 1, 0, 0}, {NULL, e->mult, e->ncon, 0, 1}};
    return qd__render_sympy_functions(v->ctx, b, sizeof parts / sizeof *parts, parts);
}

static qd_status sympy_multipliers(const view *v, qd_buf *b) {
    qd__render_name lam = pick(v, "lam");
    qd_buf_printf(b, "%s = Matrix([", lam.s);
    for (size_t k = 0; k < v->e->ncon; k++)
        qd_buf_printf(b, "%sSymbol('%s')", k ? ", " : "", qd_expr_name(v->e->con[k].lambda));
    qd_buf_puts(b, "])\n");
    return qd__render_sympy_matrix(v->ctx, b, pick(v, "lam_value").s, v->e->mult, v->e->ncon, 1);
}

static qd_status write_sympy(const view *v, qd_buf *b) {
    const qd_model *mdl = v->m;
    const qd_speeds_eom *e = v->e;
    qd__render_name M = pick(v, "M"), f = pick(v, "f"), q = pick(v, "q"), u = pick(v, "u");
    qd__render_name kin = pick(v, "kin");
    qd_buf_printf(b, "# qdot eom %s (speeds, %s): %s.diff(t) = %s and %s*%s.diff(t) = %s\n"
                  "from sympy import *\n\nt = Symbol('t')\n", v->source,
                  qd_speeds_method_name(e->method), q.s, kin.s, M.s, u.s, f.s);
    for (size_t j = 0; j < e->n; j++)
        qd__render_sympy_bind(v->ctx, b, e->q[j], true);
    for (size_t r = 0; r < e->m; r++)
        qd__render_sympy_bind(v->ctx, b, e->u[r], true);
    for (size_t i = 0; i < qd_model_nparams(mdl); i++)
        qd__render_sympy_bind(v->ctx, b, qd_model_param(mdl, i), false);
    qd_status st = sympy_functions(v, b);
    qd_buf_puts(b, "\n");
    if (st == QD_OK)
        st = qd__render_sympy_matrix(v->ctx, b, q.s, e->q, e->n, 1);
    if (st == QD_OK)
        st = qd__render_sympy_matrix(v->ctx, b, u.s, e->u, e->m, 1);
    if (st == QD_OK)
        st = qd__render_sympy_matrix(v->ctx, b, kin.s, e->kin, e->n, 1);
    if (st == QD_OK && e->T)
        st = sympy_scalar(v, b, pick(v, "T").s, e->T);
    if (st == QD_OK)
        st = qd__render_sympy_matrix(v->ctx, b, M.s, e->M, e->m, e->m);
    if (st == QD_OK)
        st = qd__render_sympy_matrix(v->ctx, b, f.s, e->f, e->m, 1);
    if (st == QD_OK && e->acc)
        st = qd__render_sympy_matrix(v->ctx, b, pick(v, "ud").s, e->acc, e->m, 1);
    if (st == QD_OK && e->S)
        st = sympy_scalar(v, b, pick(v, "S").s, e->S);
    if (st == QD_OK && e->mult)
        st = sympy_multipliers(v, b);
    return st;
}

/* ---- C --------------------------------------------------------------------- */

static qd_status write_c(const view *v, qd_buf *b) {
    const qd_speeds_eom *e = v->e;
    size_t n = e->n, m = e->m;
    qd__render_name qd = pick(v, "qd"), M = pick(v, "M"), f = pick(v, "f");
    qd__render_name ud = pick(v, "ud"), S = pick(v, "S"), lambda = pick(v, "lambda");
    qd_buf_printf(b, "/* qdot eom %s (speeds, %s): q' = %s, %s u' = %s", v->source,
                  qd_speeds_method_name(e->method), qd.s, M.s, f.s);
    if (e->acc)
        qd_buf_printf(b, ", the rates that solve them %s", ud.s);
    if (e->S)
        qd_buf_printf(b, ", the Gibbs-Appell function %s", S.s);
    if (e->mult)
        qd_buf_printf(b, ", the multipliers %s", lambda.s);
    qd_buf_puts(b, " */\n");
    /* the block reads u' only when S or lambda need it */
    const qd__render_part in[] = {{NULL, e->q, n, 0, 1}, {NULL, e->u, m, 0, 1},
                                  {NULL, e->S || e->mult ? e->ud : NULL, m, 0, 1}};
    qd__render_c_inputs(b, v->m, 3, in);
    const qd__render_part out[] = {{qd.s, e->kin, n, 0, 1},       {M.s, e->M, m, m, 2},
                                   {f.s, e->f, m, 0, 1},          {ud.s, e->acc, m, 0, 1},
                                   {S.s, e->S ? &e->S : NULL, 1, 0, 0},
                                   {lambda.s, e->mult, e->ncon, 0, 1}};
    return qd__render_c_block(v->ctx, b, sizeof out / sizeof *out, out);
}

/* ---- at a state ------------------------------------------------------------- */

/* Every number at the state is finite; else the error naming the first
 * that is not (1/sin(theta) at theta = 0: the speed map is singular there). */
static qd_status finite_at(qd_ctx *ctx, const qd_speeds_eom *e, const double *num) {
    size_t total = e->n + e->m + (e->mult ? e->ncon : 0);
    for (size_t i = 0; i < total; i++) {
        if (isfinite(num[i]))
            continue;
        const char *what = i < e->n ? qd_expr_name(e->q[i])
                         : i < e->n + e->m ? qd_expr_name(e->u[i - e->n])
                                           : qd_expr_name(e->con[i - e->n - e->m].lambda);
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "at this state %s%s is not a finite number (the speeds "
                     "may not determine the velocities there)", what, i < e->n + e->m ? "'" : "");
        return QD_ERR_NUMERIC;
    }
    return QD_OK;
}

/* q', u' and the multipliers at the state (qd_speeds_eval) into num. */
static qd_status numbers(const view *v, const qd_render_opts *o, double *num) {
    const qd_speeds_eom *e = v->e;
    qd_status st = qd_speeds_eval(v->ctx, e, o->nstate, o->syms, o->vals, num, num + e->n,
                                  e->mult ? num + e->n + e->m : NULL);
    if (st == QD_OK)
        return finite_at(v->ctx, e, num);
    if (st != QD_ERR_NOMEM) {
        char why[512];
        snprintf(why, sizeof why, "%s", qd_ctx_message(v->ctx)[0] ? qd_ctx_message(v->ctx)
                                                                   : qd_status_str(st));
        qd_ctx_clear_error(v->ctx);
        qd_ctx_error(v->ctx, st, "cannot evaluate the equations at this state: %s", why);
    }
    return st;
}

/* The writer of each format. */
static qd_status (*const writers[])(const view *, qd_buf *) = {
    [QD_RENDER_TEXT] = write_text,   [QD_RENDER_LATEX] = write_latex,
    [QD_RENDER_JSON] = write_json,   [QD_RENDER_SYMPY] = write_sympy,
    [QD_RENDER_C] = write_c};

qd_status qd_render_speeds(qd_ctx *ctx, const qd_model *m, const qd_speeds_eom *e,
                           const qd_render_opts *o, qd_render_format fmt, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && m && e && out);
    bool at = o && o->nstate;
    if ((unsigned)fmt > QD_RENDER_C || (at && fmt != QD_RENDER_TEXT && fmt != QD_RENDER_JSON)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the equations in speeds at a state print as text or json");
        return QD_ERR_ARG;
    }
    view v = {.ctx = ctx, .m = m, .source = o && o->source ? o->source : "model", .e = e,
              .multipliers = o && o->multipliers};
    qd_render_opts full = {0};
    double *num = at ? qd__calloc(ctx, e->n + e->m + e->ncon + 1, sizeof *num) : NULL;
    qd_status st = at && !num ? QD_ERR_NOMEM : QD_OK;
    if (st == QD_OK && at)
        st = qd__render_state(ctx, m, o, &full);
    if (st == QD_OK && at) {
        st = numbers(&v, &full, num);
        v.at = &full;
        v.qd = num;
        v.ud = num + e->n;
        v.lambda = e->mult ? num + e->n + e->m : NULL;
    }
    if (st == QD_OK)
        st = qd__render_done(ctx, out, writers[fmt](&v, out));
    qd__free(num);
    qd__render_state_free(&full);
    return st;
}
