/*
 * src/render/hamel.c - Hamel's coefficients of a model's speeds printed
 * (qd_render_hamel, qdot/render.h): the nonzero gamma_ikm by index names in
 * text, every one as [i][k][m] in JSON.
 */
#include "render.h"

#include "qdot/json.h"
#include "../base/args.h"
#include "../base/mem.h"

/* The name of Hamel index i: a speed, then a constraint. */
static const char *index_name(const qd_speeds_eom *e, size_t i) {
    return i < e->m ? qd_expr_name(e->u[i]) : e->con[i - e->m].name ? e->con[i - e->m].name : "?";
}

static void write_json(qd_ctx *ctx, const qd_speeds_eom *e, const qd_expr *const *g, qd_json *j) {
    size_t n = e->n;
    qd_json_begin_object(j);
    qd_json_key(j, "indices");
    qd_json_begin_array(j);
    for (size_t i = 0; i < n; i++)
        qd_json_string(j, index_name(e, i));
    qd_json_end_array(j);
    qd_json_key(j, "gamma");
    qd_json_begin_array(j);
    for (size_t i = 0; i < n; i++) {
        qd_json_begin_array(j);
        for (size_t k = 0; k < n; k++) {
            qd_json_begin_array(j);
            for (size_t m = 0; m < n; m++)
                qd_json_expr(j, ctx, g[(i * n + k) * n + m]);
            qd_json_end_array(j);
        }
        qd_json_end_array(j);
    }
    qd_json_end_array(j);
    qd_json_end_object(j);
}

static qd_status write_text(qd_ctx *ctx, const qd_speeds_eom *e, const qd_expr *const *g,
                            qd_buf *b) {
    size_t n = e->n, nz = 0;
    qd_status st = QD_OK;
    qd_buf_puts(b, "Hamel coefficients gamma[i,k,m] = sum_jl (da_kj/dq_l - da_kl/dq_j) "
                   "b_ji b_lm (Desloge ch. 68), indices ");
    for (size_t i = 0; i < n; i++)
        qd_buf_printf(b, "%s%s", i ? ", " : "", index_name(e, i));
    qd_buf_puts(b, "\n");
    for (size_t i = 0; i < n * n * n && st == QD_OK; i++) {
        if (qd_is_zero(g[i]))
            continue;
        nz++;
        qd_buf_printf(b, "  gamma[%s,%s,%s] = ", index_name(e, i / (n * n)),
                      index_name(e, i / n % n), index_name(e, i % n));
        st = qd_print(ctx, g[i], QD_FMT_TEXT, b);
        qd_buf_puts(b, "\n");
    }
    qd_buf_puts(b, nz ? "  (the others are 0)\n"
                      : "  all 0 (the quasi-velocities are exact differentials)\n");
    return st;
}

qd_status qd_render_hamel(qd_ctx *ctx, const qd_speeds_eom *e, qd_render_format fmt,
                          qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && e && out);
    if (fmt != QD_RENDER_TEXT && fmt != QD_RENDER_JSON) {
        qd_ctx_error(ctx, QD_ERR_ARG, "Hamel's coefficients print as text or json");
        return QD_ERR_ARG;
    }
    size_t n = e->n;
    const qd_expr **g = qd__calloc(ctx, n * n * n + 1, sizeof *g);
    if (!g)
        return QD_ERR_NOMEM;
    qd_status st = qd_speeds_hamel_coefficients(ctx, e, g);
    if (st == QD_OK && fmt == QD_RENDER_JSON) {
        qd_json j;
        qd_json_init(&j, out);
        write_json(ctx, e, g, &j);
        qd_buf_puts(out, "\n");
        st = qd__render_json_status(&j, out, st);
    } else if (st == QD_OK) {
        st = write_text(ctx, e, g, out);
    }
    qd__free(g);
    if (st == QD_OK && out->failed) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory printing the coefficients");
        st = QD_ERR_NOMEM;
    }
    return st;
}
