/*
 * src/mech/canonical_out.c - the answers of `qdot canonical` written out
 * as text or JSON (qdot/canonical.h): a map's verdict with its witness, its
 * Lagrange brackets and new Hamiltonian (qd_canon_report_print), and the
 * map a generating function gives (qd_gen_result_print).
 */
#include <stdio.h>
#include "qdot/canonical.h"
#include "base/args.h"

/* One document being written: JSON when j, else text into b. */
typedef struct can_out {
    qd_ctx *ctx;
    const qd_phase *ph;
    qd_json *j;
    qd_buf *b;
} can_out;

/* An expression in the text format ("?" for none). */
static void put(const can_out *o, const qd_expr *x) {
    if (x)
        qd_print(o->ctx, x, QD_FMT_TEXT, o->b);
    else
        qd_buf_puts(o->b, "?");
}

/* key = x: a JSON member, or a line "  key = x" (nothing for NULL). */
static void put_expr(const can_out *o, const char *key, const qd_expr *x) {
    if (o->j) {
        qd_json_key(o->j, key);
        qd_json_expr(o->j, o->ctx, x);
    } else if (x) {
        qd_buf_printf(o->b, "  %s = ", key);
        put(o, x);
        qd_buf_puts(o->b, "\n");
    }
}

/* The variables' names: old (q..., p...) or new (Q..., P...), 2n of each. */
static const char *var_name(const qd_phase *ph, bool new_vars, size_t a) {
    const qd_expr *const *q = new_vars ? ph->Q : ph->q, *const *p = new_vars ? ph->P : ph->p;
    return qd_expr_name(a < ph->n ? q[a] : p[a - ph->n]);
}

/* A 2n x 2n matrix as rows of expressions. */
static void put_matrix(const can_out *o, const char *key, const qd_expr *const *M) {
    size_t m = 2 * o->ph->n;
    if (o->j) {
        qd_json_key(o->j, key);
        qd_json_begin_array(o->j);
    }
    for (size_t x = 0; x < m; x++) {
        if (o->j)
            qd_json_begin_array(o->j);
        else
            qd_buf_puts(o->b, "  [");
        for (size_t y = 0; y < m; y++) {
            if (o->j) {
                qd_json_expr(o->j, o->ctx, M[x * m + y]);
                continue;
            }
            qd_buf_puts(o->b, y ? ", " : "");
            qd_print(o->ctx, M[x * m + y], QD_FMT_TEXT, o->b);
        }
        if (o->j)
            qd_json_end_array(o->j);
        else
            qd_buf_puts(o->b, "]\n");
    }
    if (o->j)
        qd_json_end_array(o->j);
}

/* The brackets [u, v] of the old variables and L^T PB = I. */
static void put_lagrange(const can_out *o, const qd_lagrange_result *lb) {
    if (!o->j) {
        qd_buf_puts(o->b, "Lagrange brackets [u, v] = sum dQ/du dP/dv - dQ/dv dP/du, "
                          "rows and columns ");
        for (size_t k = 0; k < 2 * o->ph->n; k++)
            qd_buf_printf(o->b, "%s%s", k ? ", " : "", var_name(o->ph, false, k));
        qd_buf_puts(o->b, "\n");
    }
    put_matrix(o, "lagrange", lb->L);
    if (lb->PB) {
        if (!o->j)
            qd_buf_puts(o->b, "Poisson brackets of the old variables in the new ones\n");
        put_matrix(o, "poisson_old_in_new", lb->PB);
    }
    if (o->j) {
        qd_json_key(o->j, "duality");
        if (lb->singular)
            qd_json_null(o->j);
        else
            qd_json_bool(o->j, lb->dual);
    } else {
        qd_buf_printf(o->b, "%s\n",
                      lb->singular ? "duality: the Jacobian is singular (no inverse map)"
                      : lb->dual   ? "duality: [L]^T (P) = 1 holds"
                                   : "duality: [L]^T (P) = 1 FAILS");
    }
}

/* F and the new Hamiltonian, or why there is none. */
static void put_newham(const can_out *o, bool answered, const qd_newham *nh) {
    if (!answered) {
        if (o->j) {
            qd_json_key(o->j, "K");
            qd_json_null(o->j);
        } else {
            qd_buf_puts(o->b, "no new Hamiltonian: the map is neither canonical nor scaled\n");
        }
        return;
    }
    if (!o->j)
        qd_buf_puts(o->b, "new Hamiltonian K = c H + sum P dQ/dt + dF/dt, dF = c p dq - P dQ "
                          "(fixed t)\n");
    put_expr(o, o->j ? "valence" : "c", nh->valence);
    put_expr(o, "F", nh->F);
    put_expr(o, o->j ? "K_old" : "K(q, p, t)", nh->K_old);
    put_expr(o, o->j ? "K_new" : "K(Q, P, t)", nh->K_new);
    if (!o->j && !nh->F)
        qd_buf_puts(o->b, "  F: the exact form's antiderivative was not found in closed form\n");
}

/* The verdict's sentence and its zero test. */
static void put_verdict_text(const can_out *o, const qd_canon_verdict *v, const char *pair) {
    qd_buf *b = o->b;
    switch (v->kind) {
    case QD_CANON_YES:
        qd_buf_puts(b, "canonical");
        qd_zero_result_note(b, &v->check);
        break;
    case QD_CANON_SCALED:
        qd_buf_puts(b, "not canonical (a scaled canonical map, c = ");
        put(o, v->scale);
        qd_buf_puts(b, "): [Q_i, P_i] = ");
        put(o, v->scale);
        qd_zero_result_note(b, &v->check);
        break;
    case QD_CANON_UNDECIDED:
        qd_buf_printf(b, "could not decide: %s = ", pair);
        put(o, v->value);
        qd_buf_puts(b, ", neither proved nor refuted equal to ");
        put(o, v->target);
        break;
    default:
        qd_buf_printf(b, "not canonical: %s = ", pair);
        put(o, v->value);
        qd_buf_puts(b, " (should be ");
        put(o, v->target);
        qd_buf_puts(b, ")");
        break;
    }
    qd_buf_puts(b, "\n");
    qd_zero_result_print(b, &v->check);
}

static void put_verdict_json(const can_out *o, const qd_canon_verdict *v, const char *pair,
                             bool failed) {
    qd_json *j = o->j;
    qd_json_key(j, "verdict");
    qd_json_string(j, qd_canon_kind_name(v->kind));
    put_expr(o, "scale", failed ? NULL : v->scale);
    qd_json_key(j, "bracket");
    qd_json_string(j, failed ? pair : NULL);
    put_expr(o, "value", failed ? v->value : NULL);
    put_expr(o, "should_be", failed ? v->target : NULL);
    qd_zero_result_json(j, &v->check);
}

/* The document in b appended to out, or the error that kept it back. */
static qd_status finish(qd_ctx *ctx, qd_json *j, qd_buf *b, qd_buf *out) {
    if (j) {
        qd_json_end_object(j);
        qd_buf_puts(b, "\n");
    }
    return qd_json_commit(ctx, b, j, out);
}

static bool has_new_vars(qd_ctx *ctx, const qd_phase *ph, const char *func) {
    if ((ph->n && (!ph->Q || !ph->P)) || !ph->q || !ph->p) {
        qd_ctx_error(ctx, QD_ERR_ARG, "%s: the phase space has no new variables "
                     "(qd_phase_new_vars)", func);
        return false;
    }
    return true;
}

qd_status qd_canon_report_print(qd_ctx *ctx, const qd_phase *ph, const qd_canon_report *r,
                                bool json, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && ph && r && out);
    if (!has_new_vars(ctx, ph, __func__))
        return QD_ERR_ARG;
    const qd_canon_verdict *v = &r->v;
    size_t n = ph->n;
    bool failed = v->kind == QD_CANON_NO || v->kind == QD_CANON_UNDECIDED;
    if ((unsigned)v->kind > QD_CANON_UNDECIDED || (failed && (v->i >= n || v->j >= n)) ||
        (r->lagrange && !r->lb.L)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "%s: not a report of qd_canonical_examine", __func__);
        return QD_ERR_ARG;
    }
    qd_buf b = QD_BUF_WITH(out->alloc);
    qd_json j;
    can_out o = {ctx, ph, json ? &j : NULL, &b};
    char pair[160] = ""; /* "[Q1, P2]" */
    if (failed)
        snprintf(pair, sizeof pair, "[%s, %s]",
                 var_name(ph, true, v->pair == QD_PAIR_PP ? n + v->i : v->i),
                 var_name(ph, true, v->pair == QD_PAIR_QQ ? v->j : n + v->j));
    if (o.j) {
        qd_json_init(o.j, &b);
        qd_json_begin_object(o.j);
        put_verdict_json(&o, v, pair, failed);
    } else {
        put_verdict_text(&o, v, pair);
    }
    if (r->lagrange)
        put_lagrange(&o, &r->lb);
    if (r->newham)
        put_newham(&o, !failed, &r->nh);
    return finish(ctx, o.j, &b, out);
}

qd_status qd_gen_result_print(qd_ctx *ctx, const qd_phase *ph, qd_gen_type type,
                              const qd_expr *F, const qd_gen_result *g, bool json,
                              qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && ph && F && g && out);
    if (!has_new_vars(ctx, ph, __func__))
        return QD_ERR_ARG;
    if (type < QD_GEN_F1 || type > QD_GEN_F4 || (ph->n && (!g->Q || !g->P))) {
        qd_ctx_error(ctx, QD_ERR_ARG, "%s: not a map of qd_generate", __func__);
        return QD_ERR_ARG;
    }
    size_t n = ph->n;
    qd_buf b = QD_BUF_WITH(out->alloc);
    qd_json j;
    can_out o = {ctx, ph, json ? &j : NULL, &b};
    char name[3] = {'F', (char)('0' + type), 0};
    if (o.j) {
        qd_json_init(o.j, &b);
        qd_json_begin_object(o.j);
        qd_json_key(o.j, "type");
        qd_json_string(o.j, name);
    } else {
        qd_buf_printf(&b, "generating function %s\n", name);
    }
    put_expr(&o, "F", F);
    if (!o.j)
        qd_buf_puts(&b, "transformation (in q, p, t)\n");
    for (size_t k = 0; k < 2 * n; k++)
        put_expr(&o, var_name(ph, true, k), k < n ? g->Q[k] : g->P[k - n]);
    if (!o.j)
        qd_buf_puts(&b, "new Hamiltonian K = H + dF/dt\n");
    put_expr(&o, o.j ? "K_old" : "K(q, p, t)", g->K_old);
    put_expr(&o, o.j ? "K_new" : "K(Q, P, t)", g->K_new);
    return finish(ctx, o.j, &b, out);
}
