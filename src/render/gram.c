/*
 * src/render/gram.c - a Gram-Schmidt orthogonalization printed
 * (qd_render_gram, qdot/render.h; Desloge App. 21), as `qdot form
 * --gram-schmidt`, `qdot metric --gram-schmidt` and Python's
 * qdot.gram_schmidt show it.
 */
#include "render.h"

#include "qdot/json.h"
#include "../base/args.h"

static void put(qd_ctx *ctx, qd_buf *b, const qd_expr *x) {
    qd_print(ctx, x, QD_FMT_TEXT, b);
}

static void vec(qd_ctx *ctx, qd_buf *b, const qd_expr *const *v, size_t n) {
    qd_buf_puts(b, "(");
    for (size_t i = 0; i < n; i++) {
        qd_buf_puts(b, i ? ", " : "");
        put(ctx, b, v[i]);
    }
    qd_buf_puts(b, ")");
}

/* "a3 - 1/2 b1 - 1/3 b2": b(r) as eq. 3b makes it. */
static void recipe(qd_ctx *ctx, qd_buf *b, const qd_gram *g, size_t r) {
    qd_buf_printf(b, "a%zu", r + 1);
    for (size_t j = 0; j < r; j++) {
        const qd_expr *c = g->coef[r * g->s + j];
        if (qd_is_zero(c))
            continue;
        qd_buf_puts(b, " - (");
        put(ctx, b, c);
        qd_buf_printf(b, ") b%zu", j + 1);
    }
}

static void gram_text(qd_ctx *ctx, qd_buf *b, const qd_gram *g, const qd_expr *const *x,
                      const qd_expr *const *T) {
    size_t n = g->n;
    T = g->euclidean ? NULL : T;
    qd_buf_puts(b, g->euclidean ? "Gram-Schmidt orthogonalization (Desloge App. 21 Thm 1: "
                                  "b(i).b(j) = 0 for i != j)\n"
                                : "Gram-Schmidt orthogonalization under T (Desloge App. 21 Thm 2: "
                                  "b(i)^T T b(j) = 0 for i != j)\n");
    if (x) {
        qd_buf_puts(b, "  components along ");
        for (size_t i = 0; i < n; i++)
            qd_buf_printf(b, "%s%s", i ? ", " : "", qd_expr_name(x[i]));
        qd_buf_puts(b, "\n");
    }
    for (size_t i = 0; T && i < n; i++) {
        qd_buf_puts(b, i ? "      [" : "  T = [");
        for (size_t k = 0; k < n; k++) {
            qd_buf_puts(b, k ? ", " : "");
            put(ctx, b, T[i * n + k]);
        }
        qd_buf_puts(b, "]\n");
    }
    for (size_t r = 0; r < g->s; r++) {
        qd_buf_printf(b, "  a%zu = ", r + 1);
        vec(ctx, b, g->a + r * n, n);
        qd_buf_puts(b, "\n");
    }
    for (size_t r = 0; r < g->s; r++) {
        qd_buf_printf(b, "  b%zu = ", r + 1);
        recipe(ctx, b, g, r);
        qd_buf_puts(b, " = ");
        vec(ctx, b, g->b + r * n, n);
        qd_buf_printf(b, g->euclidean ? ", b%zu.b%zu = " : ", b%zu^T T b%zu = ", r + 1, r + 1);
        put(ctx, b, g->norm[r]);
        qd_buf_puts(b, "\n");
    }
    qd_buf_printf(b, "checked: %s = 0 for every i != j (eq. %s)%s\n",
                  g->euclidean ? "b(i).b(j)" : "b(i)^T T b(j)", g->euclidean ? "2" : "4",
                  g->check == QD_ZERO_NUMERIC ? ", verified numerically" : "");
}

static void json_rows(qd_ctx *ctx, qd_json *j, const char *key, const qd_expr *const *v, size_t m,
                      size_t n) {
    qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t k = 0; k < m; k++) {
        qd_json_begin_array(j);
        for (size_t i = 0; i < n; i++)
            qd_json_expr(j, ctx, v[k * n + i]);
        qd_json_end_array(j);
    }
    qd_json_end_array(j);
}

static void gram_json(qd_ctx *ctx, qd_json *j, const qd_gram *g, const qd_expr *const *x,
                      const qd_expr *const *T) {
    size_t n = g->n;
    qd_json_begin_object(j);
    qd_json_key(j, "variables");
    qd_json_begin_array(j);
    for (size_t i = 0; x && i < n; i++)
        qd_json_string(j, qd_expr_name(x[i]));
    qd_json_end_array(j);
    qd_json_key(j, "euclidean");
    qd_json_bool(j, g->euclidean);
    if (T && !g->euclidean) {
        json_rows(ctx, j, "metric", T, n, n);
    } else {
        qd_json_key(j, "metric");
        qd_json_null(j);
    }
    json_rows(ctx, j, "vectors", g->a, g->s, n);
    json_rows(ctx, j, "orthogonal", g->b, g->s, n);
    qd_json_key(j, "norms");
    qd_json_begin_array(j);
    for (size_t r = 0; r < g->s; r++)
        qd_json_expr(j, ctx, g->norm[r]);
    qd_json_end_array(j);
    json_rows(ctx, j, "coefficients", g->coef, g->s, g->s);
    qd_json_key(j, "certainty");
    qd_json_string(j, qd_zero_kind_name(g->check));
    qd_json_end_object(j);
}

qd_status qd_render_gram(qd_ctx *ctx, const qd_gram *g, const qd_expr *const *x,
                         const qd_expr *const *T, qd_render_format fmt, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && g && out);
    qd_status st = qd__render_text_or_json(ctx, fmt, "an orthogonalization");
    if (st != QD_OK)
        return st;
    if (fmt == QD_RENDER_JSON) {
        qd_json j;
        qd_json_init(&j, out);
        gram_json(ctx, &j, g, x, T);
        qd_buf_puts(out, "\n");
        st = qd__render_json_status(&j, out, QD_OK);
    } else {
        gram_text(ctx, out, g, x, T);
    }
    return qd__render_finish(ctx, out, st, "the orthogonalization");
}
