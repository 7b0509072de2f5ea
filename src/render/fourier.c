/*
 * src/render/fourier.c - a Fourier series printed (qd_render_fourier,
 * qdot/render.h; Desloge App. 31, ch. 79), as `qdot form --fourier` and
 * Python's qdot.fourier show it.
 */
#include "render.h"

#include "qdot/json.h"
#include "../base/args.h"

static void put(qd_ctx *ctx, qd_buf *b, const qd_expr *x) {
    qd_print(ctx, x, QD_FMT_TEXT, b);
}

static void fourier_text(qd_ctx *ctx, qd_buf *b, const qd_fourier *f, const qd_expr *fx,
                         const qd_expr *const *x) {
    qd_buf_puts(b, "Fourier series in ");
    for (size_t i = 0; i < f->n; i++)
        qd_buf_printf(b, "%s%s", i ? ", " : "", qd_expr_name(x[i]));
    qd_buf_puts(b, " (Desloge App. 31: f = sum_k a_k cos(k.x) + b_k sin(k.x))\n  f = ");
    put(ctx, b, fx);
    qd_buf_printf(b, "\n%zu harmonic%s\n", f->nterms, f->nterms == 1 ? "" : "s");
    for (size_t i = 0; i < f->nterms; i++) {
        const qd_fourier_term *t = &f->terms[i];
        qd_buf_puts(b, "  k = (");
        for (size_t j = 0; j < f->n; j++) {
            qd_buf_puts(b, j ? ", " : "");
            put(ctx, b, t->k[j]);
        }
        qd_buf_puts(b, "): ");
        if (qd_is_zero(t->arg)) {
            qd_buf_puts(b, "constant ");
            put(ctx, b, t->a);
        } else {
            qd_buf_puts(b, "a = ");
            put(ctx, b, t->a);
            qd_buf_puts(b, ", b = ");
            put(ctx, b, t->b);
            qd_buf_puts(b, "  (cos, sin of ");
            put(ctx, b, t->arg);
            qd_buf_puts(b, ")");
        }
        qd_buf_puts(b, "\n");
    }
    qd_buf_printf(b, "checked: the harmonics sum to f%s\n",
                  f->check == QD_ZERO_NUMERIC ? " (verified numerically)" : "");
}

static void fourier_json(qd_ctx *ctx, qd_json *j, const qd_fourier *f, const qd_expr *fx,
                         const qd_expr *const *x) {
    qd_json_begin_object(j);
    qd_json_key(j, "variables");
    qd_json_begin_array(j);
    for (size_t i = 0; i < f->n; i++)
        qd_json_string(j, qd_expr_name(x[i]));
    qd_json_end_array(j);
    qd_json_key(j, "f");
    qd_json_expr(j, ctx, fx);
    qd_json_key(j, "harmonics");
    qd_json_begin_array(j);
    for (size_t i = 0; i < f->nterms; i++) {
        const qd_fourier_term *t = &f->terms[i];
        qd_json_begin_object(j);
        qd_json_key(j, "k");
        qd_json_begin_array(j);
        for (size_t m = 0; m < f->n; m++)
            qd_json_expr(j, ctx, t->k[m]);
        qd_json_end_array(j);
        qd_json_key(j, "argument");
        qd_json_expr(j, ctx, t->arg);
        qd_json_key(j, "cos");
        qd_json_expr(j, ctx, t->a);
        qd_json_key(j, "sin");
        qd_json_expr(j, ctx, t->b);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
    qd_json_key(j, "certainty");
    qd_json_string(j, qd_zero_kind_name(f->check));
    qd_json_end_object(j);
}

qd_status qd_render_fourier(qd_ctx *ctx, const qd_fourier *f, const qd_expr *fx,
                            const qd_expr *const *x, qd_render_format fmt, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && f && fx && x && out);
    qd_status st = qd__render_text_or_json(ctx, fmt, "a Fourier series");
    if (st != QD_OK)
        return st;
    if (fmt == QD_RENDER_JSON) {
        qd_json j;
        qd_json_init(&j, out);
        fourier_json(ctx, &j, f, fx, x);
        qd_buf_puts(out, "\n");
        st = qd__render_json_status(&j, out, QD_OK);
    } else {
        fourier_text(ctx, out, f, fx, x);
    }
    return qd__render_finish(ctx, out, st, "the Fourier series");
}
