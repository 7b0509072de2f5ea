/*
 * src/render/eom.c - the five renderings of M q'' = f (qdot/render.h).
 *
 * Text is for reading (entries in the model language's syntax, numbers in
 * their shortest round-trip form); LaTeX is an align environment; JSON is for
 * programs (expressions as strings in the text syntax, numbers as numbers in
 * numeric mode); SymPy is a Python snippet that rebuilds M and f; C is one
 * qd_print_c_block so that common subexpressions are shared across M and f.
 */
#include "render.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "qdot/json.h"
#include "../base/args.h"
#include "../base/mem.h"


static qd_status put(const qd__eom_view *v, qd_buf *b, const qd_expr *x, qd_format fmt) {
    if (v->at && fmt == QD_FMT_TEXT && qd_is_number(x)) {
        qd__render_number(b, qd_number_value(x));
        return QD_OK;
    }
    return qd_print(v->ctx, x, fmt, b);
}

static const char *qname(const qd__eom_view *v, size_t j) { return qd_expr_name(v->e->q[j]); }

/* The name of an output (M, f, qdd, ...) in SymPy and C: one the model does
 * not use. */
typedef qd__render_name out_name;

static out_name pick(const qd__eom_view *v, const char *base) {
    return qd__render_name_pick(v->m, base, 0, NULL);
}

/* ---- text ------------------------------------------------------------------ */

/* A functional's model (`independent x`, isoperimetric constraints): the
 * variable the equations are in and what lambda_NAME stands for. */
static void text_variational(const qd__eom_view *v, qd_buf *b) {
    const qd_model *m = v->m;
    if (qd_model_independent(m))
        qd_buf_printf(b, "independent variable: %s\n", qd_model_independent(m));
    for (size_t i = 0; i < qd_model_nisoperimetric(m); i++) {
        qd_buf_printf(b, "isoperimetric %s: integral(", qd_model_isoperimetric_name(m, i));
        qd_print(v->ctx, qd_model_isoperimetric(m, i), QD_FMT_TEXT, b);
        qd_buf_puts(b, ") = ");
        qd_print(v->ctx, qd_model_isoperimetric_value(m, i), QD_FMT_TEXT, b);
        const qd_expr *lam = qd_model_isoperimetric_multiplier(m, i);
        qd_buf_printf(b, ", multiplier lambda_%s", qd_model_isoperimetric_name(m, i));
        if (qd_expr_kind(lam) == QD_SYMBOL && qd_symbol_role(lam) == QD_ROLE_PLAIN) {
            qd_buf_puts(b, " (a constant)\n");
            continue;
        }
        qd_buf_puts(b, " (the parameter: ");
        qd_print(v->ctx, lam, QD_FMT_TEXT, b);
        qd_buf_puts(b, ")\n");
    }
}

/* The state's coordinates, velocities and t, in that order. */
static const qd_expr *state_sym(const qd__eom_view *v, size_t i) {
    size_t n = v->e->n;
    return i < n ? v->e->q[i] : i < 2 * n ? v->e->qd[i - n] : qd_time(v->ctx);
}

static void text_header(const qd__eom_view *v, qd_buf *b) {
    qd_buf_printf(b, "model: %s\ncoordinates:", v->source);
    for (size_t j = 0; j < v->e->n; j++)
        qd_buf_printf(b, "%s %s", j ? "," : "", qname(v, j));
    qd_buf_puts(b, "\n");
    qd__render_params(b, v->m);
    qd_buf_puts(b, "\n");
    text_variational(v, b);
    if (!v->at)
        return;
    qd_buf_puts(b, "at:");
    for (size_t i = 0; i < 2 * v->e->n + 1; i++) {
        qd_buf_puts(b, i ? ", " : " ");
        qd_print(v->ctx, state_sym(v, i), QD_FMT_TEXT, b);
        qd_buf_puts(b, " = ");
        qd__render_number(b, qd__render_value(v->at, state_sym(v, i)));
    }
    qd_buf_puts(b, "\n");
}

/* Row j of M q'' = f + A^T lambda, by names: the nonzero entries of M,
 * and lambda_k*(A_kj) for the nonzero A_kj. */
static qd_status text_row(const qd__eom_view *v, qd_buf *b, size_t j) {
    size_t n = v->e->n;
    bool any = false;
    qd_status st = QD_OK;
    qd_buf_printf(b, "  %s: ", qname(v, j));
    for (size_t k = 0; k < n; k++) {
        if (qd_is_zero(v->M[j * n + k]))
            continue;
        qd_buf_printf(b, "%sM[%s,%s]*%s''", any ? " + " : "", qname(v, j < k ? j : k),
                      qname(v, j < k ? k : j), qname(v, k));
        any = true;
    }
    qd_buf_printf(b, "%s = f[%s]", any ? "" : "0", qname(v, j));
    for (size_t k = 0; k < v->e->ncon && st == QD_OK; k++) {
        const qd_expr *a = v->A[k * n + j];
        if (qd_is_zero(a))
            continue;
        qd_buf_printf(b, " + %s*(", qd_expr_name(v->e->con[k].lambda));
        st = put(v, b, a, QD_FMT_TEXT);
        qd_buf_puts(b, ")");
    }
    qd_buf_puts(b, "\n");
    return st;
}

static qd_status text_constraint(const qd__eom_view *v, qd_buf *b, size_t k) {
    const qd_con *c = &v->e->con[k];
    size_t n = v->e->n;
    qd_buf_printf(b, "  %s (%s): ", c->name, qd_con_kind_name(c->kind));
    qd_status st = qd_print(v->ctx, c->expr, QD_FMT_TEXT, b);
    qd_buf_puts(b, " = 0\n");
    if (st == QD_OK && c->integral) {
        qd_buf_puts(b, "    integral: ");
        st = qd_print(v->ctx, c->integral, QD_FMT_TEXT, b);
        qd_buf_puts(b, " = const\n");
    }
    for (size_t j = 0; j < n && st == QD_OK; j++) {
        qd_buf_printf(b, "    A[%s,%s] = ", c->name, qname(v, j));
        st = put(v, b, v->A[k * n + j], QD_FMT_TEXT);
        qd_buf_puts(b, "\n");
    }
    if (st == QD_OK) {
        qd_buf_printf(b, "    b[%s] = ", c->name);
        st = put(v, b, v->b[k], QD_FMT_TEXT);
        qd_buf_puts(b, "\n");
    }
    return st;
}

static qd_status text_constraints(const qd__eom_view *v, qd_buf *b) {
    qd_status st = QD_OK;
    qd_buf_puts(b, "\nwith the constraints' multipliers, M q'' = f + A^T lambda:\n");
    for (size_t j = 0; j < v->e->n && st == QD_OK; j++)
        st = text_row(v, b, j);
    qd_buf_puts(b, "\nconstraints, closed by A q'' = b (holonomic ones differentiated twice, "
                   "Pfaffian ones once):\n");
    for (size_t k = 0; k < v->e->ncon && st == QD_OK; k++)
        st = text_constraint(v, b, k);
    return st;
}

static qd_status text_forces(const qd__eom_view *v, qd_buf *b) {
    qd_status st = QD_OK;
    qd_buf_puts(b, "\nmultipliers:\n");
    for (size_t k = 0; v->lambda && k < v->e->ncon && st == QD_OK; k++) {
        qd_buf_printf(b, "  %s = ", qd_expr_name(v->e->con[k].lambda));
        st = put(v, b, v->lambda[k], QD_FMT_TEXT);
        qd_buf_puts(b, "\n");
    }
    if (!v->R)
        return st;
    qd_buf_puts(b, "\ngeneralized constraint forces R = A^T lambda:\n");
    for (size_t j = 0; j < v->e->n && st == QD_OK; j++) {
        qd_buf_printf(b, "  R[%s] = ", qname(v, j));
        st = put(v, b, v->R[j], QD_FMT_TEXT);
        qd_buf_puts(b, "\n");
    }
    return st;
}

/* A reaction whose equations J^T F = R are not consistent: the constraint
 * acts elsewhere too (include/qdot/mech.h, qd_eom_reaction). */
#define REACTION_EXACT 1e-9

static qd_status text_reactions(const qd__eom_view *v, qd_buf *b) {
    qd_status st = QD_OK;
    qd_buf_puts(b, "\nreactions (the force a constraint exerts at a point, Cartesian):\n");
    for (size_t i = 0; i < v->nreact && st == QD_OK; i++) {
        qd_buf_printf(b, "  %s = (", v->react_name[i]);
        for (int k = 0; k < 3 && st == QD_OK; k++) {
            qd_buf_puts(b, k ? ", " : "");
            st = put(v, b, v->react[3 * i + k], QD_FMT_TEXT);
        }
        qd_buf_puts(b, ")\n");
        if (v->react_res[i] > REACTION_EXACT) {
            qd_buf_puts(b, "    (least squares: the constraint also acts elsewhere; relative "
                           "residual ");
            qd__render_number(b, v->react_res[i]);
            qd_buf_puts(b, ")\n");
        }
    }
    return st;
}

static qd_status text_eliminated(const qd__eom_view *v, qd_buf *b) {
    qd_status st = QD_OK;
    qd_buf_puts(b, "\neliminated with holonomic constraints (substituted before deriving):\n");
    for (size_t i = 0; i < v->e->nelim && st == QD_OK; i++) {
        qd_buf_printf(b, "  %s = ", qd_expr_name(v->e->elim[i].q));
        st = qd_print(v->ctx, v->e->elim[i].value, QD_FMT_TEXT, b);
        qd_buf_printf(b, " (constraint %s)\n", v->e->elim[i].con);
    }
    return st;
}

static qd_status write_text(const qd__eom_view *v, qd_buf *b) {
    size_t n = v->e->n;
    qd_status st = QD_OK;
    text_header(v, b);
    if (v->e->nelim)
        st = text_eliminated(v, b);
    for (size_t i = 0; i < v->e->nreduced; i++)
        qd_buf_printf(b, "\nnote: constraint %s is redundant (a combination of the others on the "
                         "constraint manifold): left out by rank, its multiplier is not "
                         "determined\n", v->e->reduced[i]);
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
    if (st == QD_OK && v->e->ncon)
        st = text_constraints(v, b);
    if (v->acc) {
        qd_buf_puts(b, v->e->ncon ? "\naccelerations:\n" : "\naccelerations q'' = M^-1 f:\n");
        for (size_t j = 0; j < n && st == QD_OK; j++) {
            qd_buf_printf(b, "  %s'' = ", qname(v, j));
            st = put(v, b, v->acc[j], QD_FMT_TEXT);
            qd_buf_puts(b, "\n");
        }
    }
    if (st == QD_OK && v->e->ncon && (v->lambda || v->R))
        st = text_forces(v, b);
    if (st == QD_OK && v->nreact)
        st = text_reactions(v, b);
    return st;
}

/* ---- LaTeX ----------------------------------------------------------------- */

static qd_status latex_line(const qd__eom_view *v, qd_buf *b, bool *first, const char *lhs,
                            const qd_expr *rhs) {
    qd_buf_puts(b, *first ? "  " : " \\\\\n  ");
    *first = false;
    qd_buf_printf(b, "%s &= ", lhs);
    return qd_print(v->ctx, rhs, QD_FMT_LATEX, b);
}

/* sum_k M_jk q''_k in LaTeX, into lhs. */
static qd_status latex_row(const qd__eom_view *v, size_t j, qd_buf *lhs) {
    size_t n = v->e->n;
    const qd_expr *sum = qd_int(v->ctx, 0);
    for (size_t k = 0; k < n; k++)
        sum = qd_add(v->ctx, sum, qd_mul(v->ctx, v->M[j * n + k], v->e->qdd[k]));
    if (!sum)
        return qd_ctx_status(v->ctx);
    qd_buf_clear(lhs);
    return qd_print(v->ctx, sum, QD_FMT_LATEX, lhs);
}

/* f_j + sum_k lambda_k A_kj. */
static const qd_expr *with_multipliers(const qd__eom_view *v, size_t j) {
    const qd_expr *x = v->f[j];
    for (size_t k = 0; k < v->e->ncon; k++)
        x = qd_add(v->ctx, x, qd_mul(v->ctx, v->e->con[k].lambda, v->A[k * v->e->n + j]));
    return x;
}

/* sum_j A_kj q''_j in LaTeX, into lhs. */
static qd_status latex_constraint_row(const qd__eom_view *v, size_t k, qd_buf *lhs) {
    size_t n = v->e->n;
    const qd_expr *sum = qd_int(v->ctx, 0);
    for (size_t j = 0; j < n; j++)
        sum = qd_add(v->ctx, sum, qd_mul(v->ctx, v->A[k * n + j], v->e->qdd[j]));
    if (!sum)
        return qd_ctx_status(v->ctx);
    qd_buf_clear(lhs);
    return qd_print(v->ctx, sum, QD_FMT_LATEX, lhs);
}

static qd_status write_latex(const qd__eom_view *v, qd_buf *b) {
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
            st = latex_line(v, b, &first, qd_buf_str(&lhs), with_multipliers(v, j));
    }
    for (size_t k = 0; k < v->e->ncon && st == QD_OK; k++) {
        st = latex_constraint_row(v, k, &lhs);
        if (st == QD_OK)
            st = latex_line(v, b, &first, qd_buf_str(&lhs), v->b[k]);
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

static qd_status json_entry(const qd__eom_view *v, qd_json *j, const qd_expr *x, qd_buf *tmp) {
    if (v->at) {
        qd_json_number(j, qd_number_value(x));
        return QD_OK;
    }
    return qd__render_json_expr(v->ctx, j, x, tmp);
}

static qd_status json_vector(const qd__eom_view *v, qd_json *j, const char *key,
                             const qd_expr *const *x, size_t n, qd_buf *tmp) {
    qd_status st = QD_OK;
    if (key)
        qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t i = 0; i < n && st == QD_OK; i++)
        st = json_entry(v, j, x[i], tmp);
    qd_json_end_array(j);
    return st;
}

static void json_header(const qd__eom_view *v, qd_json *j, qd_buf *tmp) {
    qd_json_key(j, "model");
    qd_json_string(j, v->source);
    qd__render_json_names(j, "coordinates", v->e->q, v->e->n);
    qd__render_json_params(j, v->m);
    if (!v->at)
        return;
    qd_json_key(j, "state");
    qd_json_begin_object(j);
    for (size_t i = 0; i < 2 * v->e->n + 1; i++) {
        qd_buf_clear(tmp);
        qd_print(v->ctx, state_sym(v, i), QD_FMT_TEXT, tmp);
        qd_json_key(j, qd_buf_str(tmp));
        qd_json_number(j, qd__render_value(v->at, state_sym(v, i)));
    }
    qd_json_end_object(j);
}

static qd_status json_constraint(const qd__eom_view *v, qd_json *j, size_t k, qd_buf *tmp) {
    const qd_con *c = &v->e->con[k];
    qd_json_begin_object(j);
    qd_json_key(j, "name");
    qd_json_string(j, c->name);
    qd_json_key(j, "kind");
    qd_json_string(j, qd_con_kind_name(c->kind));
    qd_json_key(j, "expression");
    qd_status st = qd__render_json_expr(v->ctx, j, c->expr, tmp);
    if (st == QD_OK && c->integral) {
        qd_json_key(j, "integral");
        st = qd__render_json_expr(v->ctx, j, c->integral, tmp);
    }
    qd_json_key(j, "multiplier");
    qd_json_string(j, qd_expr_name(c->lambda));
    if (st == QD_OK)
        st = json_vector(v, j, "A", v->A + k * v->e->n, v->e->n, tmp);
    if (st == QD_OK) {
        qd_json_key(j, "b");
        st = json_entry(v, j, v->b[k], tmp);
    }
    qd_json_end_object(j);
    return st;
}

/* "constraints" (each with its row of A and b), then the multipliers by
 * constraint name and the constraint forces by coordinate name when known. */
static qd_status json_constraints(const qd__eom_view *v, qd_json *j, qd_buf *tmp) {
    qd_status st = QD_OK;
    qd_json_key(j, "constraints");
    qd_json_begin_array(j);
    for (size_t k = 0; k < v->e->ncon && st == QD_OK; k++)
        st = json_constraint(v, j, k, tmp);
    qd_json_end_array(j);
    if (v->lambda) {
        qd_json_key(j, "multipliers");
        qd_json_begin_object(j);
        for (size_t k = 0; k < v->e->ncon && st == QD_OK; k++) {
            qd_json_key(j, v->e->con[k].name);
            st = json_entry(v, j, v->lambda[k], tmp);
        }
        qd_json_end_object(j);
    }
    if (v->R) {
        qd_json_key(j, "constraint_forces");
        qd_json_begin_object(j);
        for (size_t i = 0; i < v->e->n && st == QD_OK; i++) {
            qd_json_key(j, qname(v, i));
            st = json_entry(v, j, v->R[i], tmp);
        }
        qd_json_end_object(j);
    }
    return st;
}

/* "reactions": name -> [Fx, Fy, Fz]; "reaction_residuals": name -> residual. */
static qd_status json_reactions(const qd__eom_view *v, qd_json *j, qd_buf *tmp) {
    qd_status st = QD_OK;
    qd_json_key(j, "reactions");
    qd_json_begin_object(j);
    for (size_t i = 0; i < v->nreact && st == QD_OK; i++) {
        qd_json_key(j, v->react_name[i]);
        st = json_vector(v, j, NULL, v->react + 3 * i, 3, tmp);
    }
    qd_json_end_object(j);
    qd_json_key(j, "reaction_residuals");
    qd_json_begin_object(j);
    for (size_t i = 0; i < v->nreact; i++) {
        qd_json_key(j, v->react_name[i]);
        qd_json_number(j, v->react_res[i]);
    }
    qd_json_end_object(j);
    return st;
}

static qd_status json_eliminated(const qd__eom_view *v, qd_json *j, qd_buf *tmp) {
    qd_status st = QD_OK;
    qd_json_key(j, "eliminated");
    qd_json_begin_object(j);
    for (size_t i = 0; i < v->e->nelim && st == QD_OK; i++) {
        qd_json_key(j, qd_expr_name(v->e->elim[i].q));
        qd_json_begin_object(j);
        qd_json_key(j, "constraint");
        qd_json_string(j, v->e->elim[i].con);
        qd_json_key(j, "value");
        st = qd__render_json_expr(v->ctx, j, v->e->elim[i].value, tmp);
        qd_json_end_object(j);
    }
    qd_json_end_object(j);
    return st;
}

static qd_status write_json(const qd__eom_view *v, qd_buf *b) {
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
    if (st == QD_OK && v->e->nelim)
        st = json_eliminated(v, &j, &tmp);
    if (st == QD_OK && v->e->ncon)
        st = json_constraints(v, &j, &tmp);
    if (v->e->nreduced) { /* left out by rank (redundant) */
        qd_json_key(&j, "reduced_by_rank");
        qd_json_begin_array(&j);
        for (size_t i = 0; i < v->e->nreduced; i++)
            qd_json_string(&j, v->e->reduced[i]);
        qd_json_end_array(&j);
    }
    if (st == QD_OK && v->at && qd_model_nreactions(v->m))
        st = json_reactions(v, &j, &tmp);
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    qd_buf_free(&tmp);
    return qd__render_json_status(&j, b, st);
}

/* ---- SymPy ----------------------------------------------------------------- */

/* A, b and the multipliers: M*q'' = f + A.T*lam and A*q'' = b. */
static qd_status sympy_constraints(const qd__eom_view *v, qd_buf *b) {
    size_t n = v->e->n, m = v->e->ncon;
    out_name A = pick(v, "A"), bb = pick(v, "b"), lam = pick(v, "lam"), M = pick(v, "M");
    out_name f = pick(v, "f"), q = pick(v, "q");
    qd_buf_printf(b, "# constraints: %s*%s.diff(t, 2) = %s + %s.T*%s and %s*%s.diff(t, 2) = %s\n",
                  M.s, q.s, f.s, A.s, lam.s, A.s, q.s, bb.s);
    qd_buf_printf(b, "%s = Matrix([", lam.s);
    for (size_t k = 0; k < m; k++)
        qd_buf_printf(b, "%sSymbol('%s')", k ? ", " : "", qd_expr_name(v->e->con[k].lambda));
    qd_buf_puts(b, "])\n");
    qd_status st = qd__render_sympy_matrix(v->ctx, b, A.s, v->A, m, n);
    if (st == QD_OK)
        st = qd__render_sympy_matrix(v->ctx, b, bb.s, v->b, m, 1);
    if (st == QD_OK && v->lambda)
        st = qd__render_sympy_matrix(v->ctx, b, pick(v, "lam_value").s, v->lambda, m, 1);
    return st;
}

/* W = Function('W') for the user functions in everything printed below. */
static qd_status sympy_functions(const qd__eom_view *v, qd_buf *b) {
    size_t n = v->e->n, m = v->e->ncon;
    const qd__render_part parts[] = {
        {NULL, v->T, 3, 0, 1},    {NULL, v->M, n, n, 2}, {NULL, v->f, n, 0, 1},
        {NULL, v->acc, n, 0, 1},  {NULL, v->A, m, n, 2}, {NULL, v->b, m, 0, 1},
        {NULL, v->lambda, m, 0, 1}};
    return qd__render_sympy_functions(v->ctx, b, sizeof parts / sizeof *parts, parts);
}

static qd_status write_sympy(const qd__eom_view *v, qd_buf *b) {
    static const char *const parts[] = {"T2", "T1", "T0"};
    const qd_model *m = v->m;
    size_t n = v->e->n;
    qd_status st = QD_OK;
    out_name M = pick(v, "M"), f = pick(v, "f"), q = pick(v, "q"), qdd = pick(v, "qdd");
    const char *t = qd_print_time_name(v->ctx); /* x for `independent x` */
    qd_buf_printf(b, "# qdot eom %s: %s*%s.diff(%s, 2) = %s\nfrom sympy import *\n\n"
                  "%s = Symbol('%s')\n", v->source, M.s, q.s, t, f.s, t, t);
    for (size_t j = 0; j < n; j++)
        qd__render_sympy_bind(v->ctx, b, v->e->q[j], true);
    for (size_t i = 0; i < qd_model_nparams(m); i++)
        qd__render_sympy_bind(v->ctx, b, qd_model_param(m, i), false);
    for (size_t i = 0; i < qd_model_ninputs(m); i++) /* inputs print by name, like parameters */
        qd__render_sympy_bind(v->ctx, b, qd_model_input(m, i), false);
    for (size_t i = 0; i < qd_model_nisoperimetric(m); i++) { /* constants like the parameters */
        const qd_expr *lam = qd_model_isoperimetric_multiplier(m, i);
        if (qd_expr_kind(lam) == QD_SYMBOL && qd_symbol_role(lam) == QD_ROLE_PLAIN)
            qd__render_sympy_bind(v->ctx, b, lam, false);
    }
    st = sympy_functions(v, b);
    qd_buf_puts(b, "\n");
    if (st == QD_OK)
        st = qd__render_sympy_matrix(v->ctx, b, q.s, v->e->q, n, 1);
    for (size_t i = 0; v->T[0] && i < 3 && st == QD_OK; i++) {
        qd_buf_printf(b, "%s = ", pick(v, parts[i]).s);
        st = qd_print(v->ctx, v->T[i], QD_FMT_SYMPY, b);
        qd_buf_puts(b, "\n");
    }
    if (st == QD_OK)
        st = qd__render_sympy_matrix(v->ctx, b, M.s, v->M, n, n);
    if (st == QD_OK)
        st = qd__render_sympy_matrix(v->ctx, b, f.s, v->f, n, 1);
    if (st == QD_OK && v->acc)
        st = qd__render_sympy_matrix(v->ctx, b, qdd.s, v->acc, n, 1);
    if (st == QD_OK && v->e->ncon)
        st = sympy_constraints(v, b);
    return st;
}

/* ---- C --------------------------------------------------------------------- */

static qd_status write_c(const qd__eom_view *v, qd_buf *b) {
    const qd_model *mdl = v->m;
    size_t n = v->e->n, m = v->e->ncon;
    out_name M = pick(v, "M"), f = pick(v, "f"), qdd = pick(v, "qdd"), A = pick(v, "A");
    out_name bb = pick(v, "b");
    qd_buf_printf(b, "/* qdot eom %s: %s q'' = %s", v->source, M.s, f.s);
    if (m)
        qd_buf_printf(b, " + %s^T lambda, %s q'' = %s", A.s, A.s, bb.s);
    if (v->acc && m)
        qd_buf_printf(b, ", and %s the accelerations that solve them", qdd.s);
    else if (v->acc)
        qd_buf_printf(b, ", and %s = %s^-1 %s", qdd.s, M.s, f.s);
    qd_buf_puts(b, " */\n");
    const qd__render_part in[] = {{NULL, v->e->q, n, 0, 1}, {NULL, v->e->qd, n, 0, 1}};
    qd__render_c_inputs(b, mdl, 2, in);
    if (qd_model_independent(mdl)) /* C keeps t: one spelling for every generated program */
        qd_buf_printf(b, "/* t is the independent variable %s; the _d, _dd are d/d%s */\n",
                      qd_model_independent(mdl), qd_model_independent(mdl));
    const qd__render_part out[] = {{M.s, v->M, n, n, 2}, {f.s, v->f, n, 0, 1},
                                   {qdd.s, v->acc, n, 0, 1}, {A.s, v->A, m, n, 2},
                                   {bb.s, v->b, m, 0, 1}};
    return qd__render_c_block(v->ctx, b, sizeof out / sizeof *out, out);
}

/* The writer of each format. */
static qd_status (*const writers[])(const qd__eom_view *, qd_buf *) = {
    [QD_RENDER_TEXT] = write_text,   [QD_RENDER_LATEX] = write_latex,
    [QD_RENDER_JSON] = write_json,   [QD_RENDER_SYMPY] = write_sympy,
    [QD_RENDER_C] = write_c};

qd_status qd_render_eom(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                        const qd_render_opts *o, qd_render_format fmt, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && m && e && out);
    if ((unsigned)fmt > QD_RENDER_C) {
        qd_ctx_error(ctx, QD_ERR_ARG, "not a format of qd_render_format: %d", (int)fmt);
        return QD_ERR_ARG;
    }
    qd__eom_view v = {.ctx = ctx, .m = m, .source = o && o->source ? o->source : "model",
                      .e = e, .M = e->M, .f = e->f, .acc = e->acc, .A = e->A, .b = e->b,
                      .lambda = e->mult, .T = {e->T2, e->T1, e->T0}};
    v.split = e->T2 && e->T1 && e->T0 && (!qd_is_zero(e->T1) || !qd_is_zero(e->T0));
    qd_status st = o && o->nstate ? qd__render_eom_numbers(&v, o) : QD_OK;
    if (st == QD_OK)
        st = qd__render_done(ctx, out, writers[fmt](&v, out));
    qd__render_eom_view_free(&v);
    return st;
}
