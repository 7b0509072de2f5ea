/*
 * src/mech/condensed_out.c - Desloge's condensed notation written out
 * (qd_condensed_print, qdot/canonical.h; ch. 75): what `qdot canonical
 * --condensed` prints, as text or JSON.
 */
#include "qdot/canonical.h"
#include "qdot/json.h"
#include "../base/args.h"

static void put(qd_ctx *ctx, qd_buf *b, const qd_expr *x) {
    qd_print(ctx, x, QD_FMT_TEXT, b);
}

static void vec(qd_ctx *ctx, qd_buf *b, const qd_expr *const *v, size_t m) {
    qd_buf_puts(b, "(");
    for (size_t i = 0; i < m; i++) {
        qd_buf_puts(b, i ? ", " : "");
        put(ctx, b, v[i]);
    }
    qd_buf_puts(b, ")");
}

static void mat(qd_ctx *ctx, qd_buf *b, const qd_expr *const *a, size_t m) {
    for (size_t i = 0; i < m; i++) {
        qd_buf_puts(b, "  [");
        for (size_t j = 0; j < m; j++) {
            qd_buf_puts(b, j ? ", " : "");
            put(ctx, b, a[i * m + j]);
        }
        qd_buf_puts(b, "]\n");
    }
}

static void verdict_text(qd_ctx *ctx, qd_buf *b, const qd_condensed *c) {
    size_t m = 2 * c->n;
    switch (c->kind) {
    case QD_CANON_YES:
        qd_buf_puts(b, "canonical: [r_k, r_l] = mu_kl (Thm 1, eq. 17)");
        qd_zero_result_note(b, &c->check);
        break;
    case QD_CANON_SCALED:
        qd_buf_puts(b, "not canonical: [r_k, r_l] = c mu_kl with c = ");
        put(ctx, b, c->scale);
        qd_buf_puts(b, " (a map of valence c: Hamilton's form kept with K = c H, ch. 84 Thm 3)");
        break;
    default:
        qd_buf_printf(b, "%s: [%s, %s] = ", c->kind == QD_CANON_NO ? "not canonical"
                                                                   : "could not decide",
                      qd_expr_name(c->r[c->bad_k]), qd_expr_name(c->r[c->bad_l]));
        put(ctx, b, c->bracket[c->bad_k * m + c->bad_l]);
        qd_buf_puts(b, c->kind == QD_CANON_NO ? " (should be " : " (neither proved nor refuted ");
        put(ctx, b, c->should_be);
        qd_buf_puts(b, ")");
        break;
    }
    qd_buf_puts(b, "\n");
    qd_zero_result_print(b, &c->check);
}

static void text(qd_ctx *ctx, qd_buf *b, const qd_condensed *c) {
    size_t m = 2 * c->n;
    qd_buf_puts(b, "condensed notation (Desloge ch. 75): r = ");
    vec(ctx, b, c->r, m);
    qd_buf_puts(b, "\n  R = ");
    vec(ctx, b, c->R, m);
    qd_buf_puts(b, "\nlambda (lambda_ij = 1 for j = i + f)\n");
    mat(ctx, b, c->lambda, m);
    qd_buf_puts(b, "mu = lambda - lambda^T\n");
    mat(ctx, b, c->mu, m);
    if (c->has_H) {
        qd_buf_puts(b, "Hamilton's equations r'_i = mu_ij dH/dr_j (eq. 14)\n  dH/dr = ");
        vec(ctx, b, c->grad, m);
        qd_buf_puts(b, "\n");
        for (size_t i = 0; i < m; i++) {
            qd_buf_printf(b, "  %s' = ", qd_expr_name(c->r[i]));
            put(ctx, b, c->rdot[i]);
            qd_buf_puts(b, "\n");
        }
    }
    qd_buf_puts(b, "Jacobian M = dR_i/dr_j\n");
    mat(ctx, b, c->M, m);
    qd_buf_puts(b, "Lagrange brackets [r_k, r_l] = mu_ij dR_i/dr_k dR_j/dr_l = (M^T mu M)_kl "
                   "(eq. 16)\n");
    mat(ctx, b, c->bracket, m);
    verdict_text(ctx, b, c);
    qd_buf_puts(b, "|dR/dr| = ");
    put(ctx, b, c->det);
    qd_buf_puts(b, c->kind == QD_CANON_YES ? "  (+-1 for a canonical map, Ex. 2)\n" : "\n");
}

static void jvec(qd_ctx *ctx, qd_json *j, const char *key, const qd_expr *const *v, size_t m) {
    qd_json_key(j, key);
    if (!v) {
        qd_json_null(j);
        return;
    }
    qd_json_begin_array(j);
    for (size_t i = 0; i < m; i++)
        qd_json_expr(j, ctx, v[i]);
    qd_json_end_array(j);
}

static void jmat(qd_ctx *ctx, qd_json *j, const char *key, const qd_expr *const *a, size_t m) {
    qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t i = 0; i < m; i++) {
        qd_json_begin_array(j);
        for (size_t k = 0; k < m; k++)
            qd_json_expr(j, ctx, a[i * m + k]);
        qd_json_end_array(j);
    }
    qd_json_end_array(j);
}

static void json(qd_ctx *ctx, qd_json *j, const qd_condensed *c) {
    size_t m = 2 * c->n;
    bool failed = c->kind == QD_CANON_NO || c->kind == QD_CANON_UNDECIDED;
    qd_json_begin_object(j);
    jvec(ctx, j, "r", c->r, m);
    jvec(ctx, j, "R", c->R, m);
    jmat(ctx, j, "lambda", c->lambda, m);
    jmat(ctx, j, "mu", c->mu, m);
    jvec(ctx, j, "grad_H", c->has_H ? c->grad : NULL, m);
    jvec(ctx, j, "r_dot", c->has_H ? c->rdot : NULL, m);
    jmat(ctx, j, "jacobian", c->M, m);
    jmat(ctx, j, "lagrange", c->bracket, m);
    qd_json_key(j, "jacobian_det");
    qd_json_expr(j, ctx, c->det);
    qd_json_key(j, "verdict");
    qd_json_string(j, qd_canon_kind_name(c->kind));
    qd_json_key(j, "scale");
    qd_json_expr(j, ctx, c->scale);
    qd_json_key(j, "entry");
    if (failed) {
        qd_json_begin_array(j);
        qd_json_number(j, (double)(c->bad_k + 1));
        qd_json_number(j, (double)(c->bad_l + 1));
        qd_json_end_array(j);
    } else {
        qd_json_null(j);
    }
    qd_json_key(j, "value");
    qd_json_expr(j, ctx, failed ? c->bracket[c->bad_k * m + c->bad_l] : NULL);
    qd_json_key(j, "should_be");
    qd_json_expr(j, ctx, failed ? c->should_be : NULL);
    qd_zero_result_json(j, &c->check);
    qd_json_end_object(j);
}

qd_status qd_condensed_print(qd_ctx *ctx, const qd_condensed *c, bool as_json, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && c && c->r && out);
    qd_buf b = QD_BUF_INIT;
    qd_json j;
    if (as_json) {
        qd_json_init(&j, &b);
        json(ctx, &j, c);
        qd_buf_puts(&b, "\n");
    } else {
        text(ctx, &b, c);
    }
    return qd_json_commit(ctx, &b, as_json ? &j : NULL, out);
}
