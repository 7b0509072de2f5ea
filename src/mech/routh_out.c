/*
 * src/mech/routh_out.c - Routh's reduction written out (qdot/routh.h):
 * lines of text or LaTeX, a SymPy script, and a JSON document, the one
 * rendering the program and Python share.
 */
#include <stdlib.h>
#include "base/args.h"
#include "qdot/json.h"
#include "qdot/routh.h"

typedef struct rt_out {
    qd_ctx *ctx;
    const qd_routh *r;
    const qd_eom *e;
    const qd_model *m;
    const char *path;
    qd_format fmt;
} rt_out;

static void put(const rt_out *r, qd_buf *b, const qd_expr *x) {
    qd_print(r->ctx, x, r->fmt, b);
}

static const char *eol(const rt_out *r) { return r->fmt == QD_FMT_LATEX ? " \\\\\n" : "\n"; }

/* "  lhs = rhs" with lhs printed from a symbol (may be NULL) and a suffix. */
static void line(const rt_out *r, qd_buf *b, const qd_expr *lhs_x, const char *lhs,
                 const qd_expr *rhs) {
    qd_buf_puts(b, "  ");
    if (lhs_x)
        put(r, b, lhs_x);
    qd_buf_printf(b, "%s = ", lhs);
    put(r, b, rhs);
    qd_buf_puts(b, eol(r));
}

static void name_list(qd_buf *b, size_t n, const qd_expr *const *x) {
    for (size_t i = 0; i < n; i++)
        qd_buf_printf(b, "%s%s", i ? ", " : "", qd_expr_name(x[i]));
}

static void matrix_lines(const rt_out *r, qd_buf *b, const char *name, const qd_expr **A,
                         bool upper) {
    size_t nk = r->r->nkeep;
    for (size_t i = 0; i < nk; i++)
        for (size_t j = upper ? i : 0; j < nk; j++) {
            qd_buf_printf(b, "  %s[%s,%s] = ", name, qd_expr_name(r->r->keep[i]),
                          qd_expr_name(r->r->keep[j]));
            put(r, b, A[i * nk + j]);
            qd_buf_puts(b, eol(r));
        }
}

static void write_head(const rt_out *r, qd_buf *b, const char *c) {
    const qd_routh *h = r->r;
    qd_buf_printf(b, "%smodel: %s\n%signored: ", c, r->path, c);
    name_list(b, h->nign, h->ign);
    qd_buf_printf(b, h->forced ? " (momenta, constant unless forced: " : " (momenta, constant: ");
    name_list(b, h->nign, h->beta);
    qd_buf_printf(b, ")\n%skept: ", c);
    name_list(b, h->nkeep, h->keep);
    qd_buf_puts(b, "\n\n");
}

/* The ignored velocities: quadratures, or for an implicit R what they solve. */
static void write_momenta(const rt_out *r, qd_buf *b, const char *c) {
    const qd_routh *h = r->r;
    if (h->implicit)
        qd_buf_printf(b, "%smomenta (the ignored velocities solve p = dL/dq' here: no closed "
                         "form, so R is implicit):\n", c);
    else
        qd_buf_printf(b, "%smomenta and quadratures (the ignored velocities):\n", c);
    for (size_t i = 0; i < h->nign; i++) {
        line(r, b, h->beta[i], "", h->pdef[i]);
        if (!h->implicit)
            line(r, b, r->e->qd[h->ign_index[i]], "", h->ignvel[i]);
    }
}

static void write_routhian(const rt_out *r, qd_buf *b, const char *c) {
    const qd_routh *h = r->r;
    if (h->implicit) {
        qd_buf_printf(b, "\n%sRouthian R = sum p q' - L (Goldstein's sign), the ignored "
                         "velocities standing for their solution:\n", c);
        line(r, b, NULL, "R", h->R);
        return;
    }
    qd_buf_printf(b, "\n%sRouthian R = sum p q' - L (Goldstein's sign), by degree in the kept "
                     "velocities:\n", c);
    line(r, b, NULL, "R", h->R);
    line(r, b, NULL, "R2", h->R2);
    line(r, b, NULL, "R1", h->R1);
    line(r, b, NULL, "R0", h->R0);
    qd_buf_printf(b, "\n%seffective potential V_eff = R0:\n", c);
    line(r, b, NULL, "V_eff", h->Veff);
}

static void write_equations(const rt_out *r, qd_buf *b, const char *c) {
    const qd_routh *h = r->r;
    qd_buf_printf(b, "\n%sreduced equations M q'' = f (Lagrange's equations of -R%s; M is "
                     "symmetric: entries with j <= k):\n",
                  c, h->implicit ? " at fixed p, the ignored accelerations from dp/dt = 0" : "");
    matrix_lines(r, b, "M", h->M, true);
    for (size_t k = 0; k < h->nkeep; k++) {
        qd_buf_printf(b, "  f[%s] = ", qd_expr_name(h->keep[k]));
        put(r, b, h->f[k]);
        qd_buf_puts(b, eol(r));
    }
    if (h->forced) {
        qd_buf_printf(b, "\n%sforced ignored coordinates (Byerly Art. 20a): p' = Q, not constant; "
                         "with the p' kept, M q'' = f':\n", c);
        line(r, b, NULL, "Byerly's modified function M = -R",
             qd_simplify(r->ctx, qd_neg(r->ctx, h->R)));
        for (size_t i = 0; i < h->nign; i++)
            line(r, b, h->betad[i], "", h->pdot[i]);
        for (size_t k = 0; k < h->nkeep; k++) {
            qd_buf_printf(b, "  f'[%s] = ", qd_expr_name(h->keep[k]));
            put(r, b, h->f_betad[k]);
            qd_buf_puts(b, eol(r));
        }
    }
    if (h->nkeep > 1 && !h->implicit) {
        qd_buf_printf(b, "\n%sgyroscopic matrix G (skew; f contains G q'):\n", c);
        matrix_lines(r, b, "G", h->G, false);
    }
}

static void write_lines(const rt_out *r, qd_buf *b) {
    const qd_routh *h = r->r;
    const char *c = r->fmt == QD_FMT_LATEX ? "% " : "";
    write_head(r, b, c);
    write_momenta(r, b, c);
    write_routhian(r, b, c);
    write_equations(r, b, c);
    qd_buf_printf(b, "\n%sJacobi integral of -R:\n", c);
    line(r, b, NULL, h->implicit ? "R - sum q' dR/dq'" : "R0 - R2", h->h);
    qd_buf_printf(b, "%sconserved: %s\n", c,
                  h->conserved ? "yes" : "no (explicit t, generalized forces or dissipation)");
}

static void sympy_list(const rt_out *r, qd_buf *b, const char *name, size_t n,
                       const qd_expr *const *x) {
    qd_buf_printf(b, "%s = [", name);
    for (size_t j = 0; j < n; j++) {
        qd_buf_puts(b, j ? ", " : "");
        put(r, b, x[j]);
    }
    qd_buf_puts(b, "]\n");
}

static void sympy_matrix(const rt_out *r, qd_buf *b, const char *name, const qd_expr **A) {
    size_t nk = r->r->nkeep;
    qd_buf_printf(b, "%s = Matrix([\n", name);
    for (size_t i = 0; i < nk; i++) {
        qd_buf_puts(b, "    [");
        for (size_t j = 0; j < nk; j++) {
            qd_buf_puts(b, j ? ", " : "");
            put(r, b, A[i * nk + j]);
        }
        qd_buf_puts(b, "],\n");
    }
    qd_buf_puts(b, "])\n");
}

/* W = Function('W') for the user functions in R, h and the lists. */
static void sympy_functions(const rt_out *r, qd_buf *b) {
    const qd_routh *h = r->r;
    size_t nk = h->nkeep, k = 0;
    const qd_expr **all = malloc((2 + 2 * h->nign + 2 * nk * nk + nk) * sizeof *all);
    if (!all) {
        b->failed = true;
        return;
    }
    all[k++] = h->R;
    all[k++] = h->h;
    for (size_t i = 0; i < h->nign; i++) {
        all[k++] = h->pdef[i];
        all[k++] = h->ignvel[i];
    }
    for (size_t i = 0; i < nk * nk; i++) {
        all[k++] = h->M[i];
        all[k++] = h->G[i];
    }
    for (size_t i = 0; i < nk; i++)
        all[k++] = h->f[i];
    qd_print_sympy_functions(r->ctx, k, all, b);
    free(all);
}

/* Python defining routh_ignored, routh_kept, routh_momenta, routh_pdef,
 * routh_quadratures, routh_R, routh_R2, routh_R1, routh_R0, routh_V_eff,
 * routh_jacobi, routh_M, routh_f, routh_G (None for an implicit R, which
 * adds routh_implicit = True) (prefixed: a model's parameters
 * are often named M, R or h); coordinates are functions of t. */
static void write_sympy(const rt_out *r, qd_buf *b) {
    const qd_routh *h = r->r;
    const qd_model *m = r->m;
    const char *t = qd_print_time_name(r->ctx); /* x for `independent x` */
    qd_buf_printf(b, "# qdot routh %s: routh_M*q.diff(%s, 2) = routh_f for the kept coordinates q\n"
                     "from sympy import *\n\n%s = Symbol('%s')\n", r->path, t, t, t);
    for (size_t j = 0; j < r->e->n; j++)
        qd_buf_printf(b, "%s = Function('%s')\n", qd_expr_name(r->e->q[j]),
                      qd_expr_name(r->e->q[j]));
    for (size_t i = 0; i < h->nign; i++)
        qd_buf_printf(b, "%s = Symbol('%s')\n", qd_expr_name(h->beta[i]),
                      qd_expr_name(h->beta[i]));
    for (size_t i = 0; i < qd_model_nparams(m); i++)
        qd_buf_printf(b, "%s = Symbol('%s')\n", qd_expr_name(qd_model_param(m, i)),
                      qd_expr_name(qd_model_param(m, i)));
    sympy_functions(r, b);
    sympy_list(r, b, "routh_ignored", h->nign, h->ign);
    sympy_list(r, b, "routh_kept", h->nkeep, h->keep);
    sympy_list(r, b, "routh_momenta", h->nign, h->beta);
    sympy_list(r, b, "routh_pdef", h->nign, h->pdef);
    sympy_list(r, b, "routh_quadratures", h->nign, h->ignvel);
    const char *names[] = {"R", "R2", "R1", "R0", "V_eff", "jacobi"};
    const qd_expr *vals[] = {h->R, h->R2, h->R1, h->R0, h->Veff, h->h};
    for (int i = 0; i < 6; i++) {
        qd_buf_printf(b, "routh_%s = ", names[i]);
        if (vals[i])
            put(r, b, vals[i]);
        else /* an implicit R is not split by degree */
            qd_buf_puts(b, "None");
        qd_buf_puts(b, "\n");
    }
    sympy_matrix(r, b, "routh_M", h->M);
    qd_buf_puts(b, "routh_f = Matrix([");
    for (size_t k = 0; k < h->nkeep; k++) {
        qd_buf_puts(b, k ? ", " : "");
        put(r, b, h->f[k]);
    }
    qd_buf_puts(b, "])\n");
    if (h->implicit)
        qd_buf_puts(b, "routh_G = None\nrouth_implicit = True\n");
    else
        sympy_matrix(r, b, "routh_G", h->G);
    qd_buf_printf(b, "routh_conserved = %s\n", h->conserved ? "True" : "False");
}

static void json_list(const rt_out *r, qd_json *j, const char *key, size_t n,
                      const qd_expr *const *x) {
    qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t k = 0; k < n; k++)
        qd_json_expr(j, r->ctx, x[k]);
    qd_json_end_array(j);
}

static void json_names(qd_json *j, const char *key, size_t n, const qd_expr *const *x) {
    qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t k = 0; k < n; k++)
        qd_json_string(j, qd_expr_name(x[k]));
    qd_json_end_array(j);
}

static void json_matrix(const rt_out *r, qd_json *j, const char *key, const qd_expr **A) {
    size_t nk = r->r->nkeep;
    qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t i = 0; i < nk; i++) {
        qd_json_begin_array(j);
        for (size_t k = 0; k < nk; k++)
            qd_json_expr(j, r->ctx, A[i * nk + k]);
        qd_json_end_array(j);
    }
    qd_json_end_array(j);
}

/* The equations by kept coordinate: {"q": name, "mass_matrix": [row], "forcing": f}
 * (until issue 31 "M" and "f"). */
static void json_equations(const rt_out *r, qd_json *j) {
    const qd_routh *h = r->r;
    qd_json_key(j, "equations");
    qd_json_begin_array(j);
    for (size_t k = 0; k < h->nkeep; k++) {
        qd_json_begin_object(j);
        qd_json_key(j, "q");
        qd_json_string(j, qd_expr_name(h->keep[k]));
        json_list(r, j, "mass_matrix", h->nkeep, h->M + k * h->nkeep);
        qd_json_key(j, "forcing");
        qd_json_expr(j, r->ctx, h->f[k]);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
}

static void json_quadratures(const rt_out *r, qd_json *j) {
    const qd_routh *h = r->r;
    qd_json_key(j, "quadratures");
    if (h->implicit) { /* no closed form: the velocities solve momentum_definitions */
        qd_json_null(j);
        return;
    }
    qd_json_begin_object(j);
    for (size_t i = 0; i < h->nign; i++) {
        qd_json_key(j, qd_expr_name(r->e->qd[h->ign_index[i]]));
        qd_json_expr(j, r->ctx, h->ignvel[i]);
    }
    qd_json_end_object(j);
}

static void write_json(const rt_out *r, qd_buf *b) {
    const qd_routh *h = r->r;
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "model");
    qd_json_string(&j, r->path);
    json_names(&j, "ignored", h->nign, h->ign);
    json_names(&j, "momenta", h->nign, h->beta);
    json_names(&j, "kept", h->nkeep, h->keep);
    json_list(r, &j, "momentum_definitions", h->nign, h->pdef);
    const char *names[] = {"R", "R2", "R1", "R0", "effective_potential", "jacobi_integral"};
    const qd_expr *vals[] = {h->R, h->R2, h->R1, h->R0, h->Veff, h->h};
    for (int i = 0; i < 6; i++) {
        qd_json_key(&j, names[i]);
        qd_json_expr(&j, r->ctx, vals[i]);
    }
    json_equations(r, &j);
    if (h->implicit) {
        qd_json_key(&j, "gyroscopic");
        qd_json_null(&j);
    } else {
        json_matrix(r, &j, "gyroscopic", h->G);
    }
    json_quadratures(r, &j);
    qd_json_key(&j, "conserved");
    qd_json_bool(&j, h->conserved);
    if (h->forced) { /* only then, so the other models' output is unchanged */
        json_names(&j, "momentum_rates", h->nign, h->betad);
        json_list(r, &j, "momentum_rate_values", h->nign, h->pdot);
        json_list(r, &j, "f_with_momentum_rates", h->nkeep, h->f_betad);
    }
    if (h->implicit) { /* only then, so the other models' output is unchanged */
        qd_json_key(&j, "implicit");
        qd_json_bool(&j, true);
    }
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    b->failed = b->failed || !qd_json_ok(&j);
}

/* The buffer's failure (memory) as the context's error. */
static qd_status rt_done(qd_ctx *ctx, const qd_buf *b) {
    if (!b->failed)
        return QD_OK;
    qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory writing the Routhian");
    return QD_ERR_NOMEM;
}

qd_status qd_routh_print(qd_ctx *ctx, const qd_routh *r, const qd_model *m, const qd_eom *e,
                         const char *model_name, qd_format fmt, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && r && m && e && out);
    if (fmt != QD_FMT_TEXT && fmt != QD_FMT_LATEX && fmt != QD_FMT_SYMPY) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the Routhian is written as text, LaTeX or SymPy");
        return QD_ERR_ARG;
    }
    rt_out o = {ctx, r, e, m, model_name ? model_name : "model", fmt};
    if (fmt == QD_FMT_SYMPY)
        write_sympy(&o, out);
    else
        write_lines(&o, out);
    return rt_done(ctx, out);
}

qd_status qd_routh_json(qd_ctx *ctx, const qd_routh *r, const qd_model *m, const qd_eom *e,
                        const char *model_name, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && r && m && e && out);
    rt_out o = {ctx, r, e, m, model_name, QD_FMT_TEXT};
    write_json(&o, out);
    return rt_done(ctx, out);
}
