/*
 * src/render/change.c - a change of variables in an integral printed
 * (qd_render_change, qdot/render.h; Desloge App. 19), as `qdot form
 * --change` and Python's qdot.change_of_variables show it.
 */
#include "render.h"

#include "qdot/json.h"
#include "../base/args.h"

static void put(qd_ctx *ctx, qd_buf *b, const qd_expr *x) {
    qd_print(ctx, x, QD_FMT_TEXT, b);
}

static const char *sign_name(int s) {
    return s > 0 ? "nonnegative" : s < 0 ? "nonpositive" : "unknown";
}

static void zeros_text(qd_ctx *ctx, qd_buf *b, const qd_change *c) {
    qd_buf_puts(b, "J = 0 where: ");
    if (!c->nsing)
        qd_buf_puts(b, "nowhere (J has no zero in the new variables)");
    for (size_t k = 0; k < c->nsing; k++) {
        qd_buf_puts(b, k ? "; " : "");
        put(ctx, b, c->sing[k].lhs);
        qd_buf_puts(b, " = ");
        put(ctx, b, c->sing[k].rhs);
        if (c->sing[k].period) {
            qd_buf_puts(b, " + k*");
            put(ctx, b, c->sing[k].period);
        }
    }
    qd_buf_puts(b, !c->nsing  ? "\n"
                   : c->sign ? "  (J keeps its sign across them: no split is needed, and the "
                               "map may still be invertible there, App. 18)\n"
                             : "  (J may change sign there: split the region, App. 19 p. 913)\n");
}

static void change_text(qd_ctx *ctx, qd_buf *b, const qd_change *c) {
    size_t n = c->n;
    qd_buf_puts(b, "change of variables (Desloge App. 19: int f(x) dx = int f(x(y)) |J(x/y)| dy)"
                   "\n");
    for (size_t i = 0; i < n; i++) {
        qd_buf_printf(b, "  %s = ", qd_expr_name(c->x[i]));
        put(ctx, b, c->map[i]);
        qd_buf_puts(b, "\n");
    }
    qd_buf_puts(b, "Jacobian matrix d(");
    for (size_t i = 0; i < n; i++)
        qd_buf_printf(b, "%s%s", i ? ", " : "", qd_expr_name(c->x[i]));
    qd_buf_puts(b, ")/d(");
    for (size_t i = 0; i < n; i++)
        qd_buf_printf(b, "%s%s", i ? ", " : "", qd_expr_name(c->y[i]));
    qd_buf_puts(b, ")\n");
    for (size_t i = 0; i < n; i++) {
        qd_buf_puts(b, "  [");
        for (size_t j = 0; j < n; j++) {
            qd_buf_puts(b, j ? ", " : "");
            put(ctx, b, c->jac[i * n + j]);
        }
        qd_buf_puts(b, "]\n");
    }
    qd_buf_puts(b, "J(x/y) = ");
    put(ctx, b, c->det);
    qd_buf_puts(b, "\nJ(y/x) = ");
    put(ctx, b, c->inverse);
    qd_buf_puts(b, "  (App. 18)\n");
    qd_buf_puts(b, c->sign > 0   ? "sign: J >= 0 (by its form)\n"
                   : c->sign < 0 ? "sign: J <= 0 (by its form)\n"
                                 : "sign: not known from its form: J may change sign where it "
                                   "vanishes\n");
    qd_buf_puts(b, "|J| = ");
    put(ctx, b, c->absdet);
    qd_buf_puts(b, "\n");
    if (c->f) {
        qd_buf_puts(b, "  f = ");
        put(ctx, b, c->f);
        qd_buf_puts(b, "\n  f(x(y)) |J| = ");
        put(ctx, b, c->integrand);
        qd_buf_puts(b, "\n");
    }
    zeros_text(ctx, b, c);
}

static void names(qd_json *j, const char *key, const qd_expr *const *x, size_t n) {
    qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t i = 0; i < n; i++)
        qd_json_string(j, qd_expr_name(x[i]));
    qd_json_end_array(j);
}

static void change_json(qd_ctx *ctx, qd_json *j, const qd_change *c) {
    size_t n = c->n;
    qd_json_begin_object(j);
    names(j, "variables", c->x, n);
    names(j, "new_variables", c->y, n);
    qd_json_key(j, "map");
    qd_json_begin_object(j);
    for (size_t i = 0; i < n; i++) {
        qd_json_key(j, qd_expr_name(c->x[i]));
        qd_json_expr(j, ctx, c->map[i]);
    }
    qd_json_end_object(j);
    qd_json_key(j, "jacobian");
    qd_json_begin_array(j);
    for (size_t i = 0; i < n; i++) {
        qd_json_begin_array(j);
        for (size_t k = 0; k < n; k++)
            qd_json_expr(j, ctx, c->jac[i * n + k]);
        qd_json_end_array(j);
    }
    qd_json_end_array(j);
    qd_json_key(j, "jacobian_det");
    qd_json_expr(j, ctx, c->det);
    qd_json_key(j, "inverse_det");
    qd_json_expr(j, ctx, c->inverse);
    qd_json_key(j, "sign");
    qd_json_string(j, sign_name(c->sign));
    qd_json_key(j, "abs_det");
    qd_json_expr(j, ctx, c->absdet);
    qd_json_key(j, "f");
    qd_json_expr(j, ctx, c->f);
    qd_json_key(j, "integrand");
    qd_json_expr(j, ctx, c->integrand);
    qd_json_key(j, "singular");
    qd_json_begin_array(j);
    for (size_t k = 0; k < c->nsing; k++) {
        qd_json_begin_object(j);
        qd_json_key(j, "lhs");
        qd_json_expr(j, ctx, c->sing[k].lhs);
        qd_json_key(j, "rhs");
        qd_json_expr(j, ctx, c->sing[k].rhs);
        qd_json_key(j, "period");
        qd_json_expr(j, ctx, c->sing[k].period);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
    qd_json_end_object(j);
}

qd_status qd_render_change(qd_ctx *ctx, const qd_change *c, qd_render_format fmt, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && c && out);
    qd_status st = qd__render_text_or_json(ctx, fmt, "a change of variables");
    if (st != QD_OK)
        return st;
    if (fmt == QD_RENDER_JSON) {
        qd_json j;
        qd_json_init(&j, out);
        change_json(ctx, &j, c);
        qd_buf_puts(out, "\n");
        st = qd__render_json_status(&j, out, QD_OK);
    } else {
        change_text(ctx, out, c);
    }
    return qd__render_finish(ctx, out, st, "the change of variables");
}
