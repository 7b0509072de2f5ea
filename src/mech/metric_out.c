/*
 * src/mech/metric_out.c - the tensors of qdot/metric.h written out, as
 * text or JSON, with a force's components: the one rendering the program
 * and Python share.
 */
#include <stdio.h>
#include <string.h>
#include "base/args.h"
#include "base/mem.h"
#include "qdot/json.h"
#include "qdot/metric.h"

/* The force's components: the model's Q unless --force gave them. */
typedef struct mt_force {
    const qd_expr *const *G;
    const qd_expr **up, **phys, **ord;
    bool given;
} mt_force;

static const char *name(const qd_metric *g, size_t i) { return qd_expr_name(g->q[i]); }

static void put_expr(qd_ctx *ctx, qd_buf *b, const qd_expr *x) { qd_print(ctx, x, QD_FMT_TEXT, b); }

/* ---- text ---------------------------------------------------------------------- */

static void text_matrix(qd_ctx *ctx, qd_buf *b, const qd_metric *g, const char *sym,
                        const qd_expr *const *A, bool upper) {
    for (size_t i = 0; i < g->n; i++)
        for (size_t j = i; j < g->n; j++) {
            if (qd_is_zero(A[i * g->n + j]))
                continue;
            qd_buf_printf(b, "  %s%s%s %s%s = ", sym, upper ? "^" : "_", name(g, i),
                          name(g, j), "");
            put_expr(ctx, b, A[i * g->n + j]);
            qd_buf_puts(b, "\n");
        }
}

static void text_christoffel(qd_ctx *ctx, qd_buf *b, const qd_metric *g) {
    size_t n = g->n;
    qd_buf_puts(b, "Christoffel symbols of the first kind [ij,l] (nonzero, i <= j):\n");
    for (size_t l = 0; l < n; l++)
        for (size_t i = 0; i < n; i++)
            for (size_t j = i; j < n; j++)
                if (!qd_is_zero(g->first[(l * n + i) * n + j])) {
                    qd_buf_printf(b, "  [%s %s, %s] = ", name(g, i), name(g, j), name(g, l));
                    put_expr(ctx, b, g->first[(l * n + i) * n + j]);
                    qd_buf_puts(b, "\n");
                }
    qd_buf_puts(b, "Christoffel symbols of the second kind Gamma^l_ij (nonzero, i <= j):\n");
    for (size_t l = 0; l < n; l++)
        for (size_t i = 0; i < n; i++)
            for (size_t j = i; j < n; j++)
                if (!qd_is_zero(g->second[(l * n + i) * n + j])) {
                    qd_buf_printf(b, "  Gamma^%s_%s %s = ", name(g, l), name(g, i), name(g, j));
                    put_expr(ctx, b, g->second[(l * n + i) * n + j]);
                    qd_buf_puts(b, "\n");
                }
}

static void text_vector(qd_ctx *ctx, qd_buf *b, const qd_metric *g, const char *label,
                        const char *sym, const qd_expr *const *x) {
    qd_buf_printf(b, "  %s:", label);
    for (size_t i = 0; i < g->n; i++) {
        qd_buf_printf(b, "%s %s%s = ", i ? "," : "", sym, name(g, i));
        put_expr(ctx, b, x[i]);
    }
    qd_buf_puts(b, "\n");
}

static void text_chart(qd_ctx *ctx, qd_buf *b, const qd_metric *g) {
    if (!g->npos) {
        qd_buf_puts(b, "chart: the model gives no particles' positions (or has rigid bodies): "
                       "singular points from det g\n");
    } else {
        qd_buf_printf(b, "chart: %zu position components of the particles, Jacobian dx/dq "
                         "(t frozen):\n", g->npos);
        for (size_t a = 0; a < g->npos; a++) {
            qd_buf_printf(b, "  %c%zu:", "xyz"[g->pos_axis[a]], g->pos_particle[a] + 1);
            for (size_t i = 0; i < g->n; i++) {
                qd_buf_puts(b, i ? ", " : " ");
                put_expr(ctx, b, g->jac[a * g->n + i]);
            }
            qd_buf_puts(b, "\n");
        }
        if (g->jac_det) {
            qd_buf_puts(b, "  det J = ");
            put_expr(ctx, b, g->jac_det);
            qd_buf_puts(b, "\n");
        }
        qd_buf_puts(b, "  det e = ");
        put_expr(ctx, b, g->e_det);
        qd_buf_puts(b, "  (e_ij = sum dx/dq_i dx/dq_j, the metric without the masses)\n");
    }
    qd_buf_puts(b, "  singular where: ");
    if (!g->nsing)
        qd_buf_puts(b, "nowhere (the determinant has no zero in the coordinates)");
    for (size_t k = 0; k < g->nsing; k++) {
        qd_buf_puts(b, k ? "; " : "");
        put_expr(ctx, b, g->sing[k].lhs);
        qd_buf_puts(b, " = ");
        put_expr(ctx, b, g->sing[k].rhs);
        if (g->sing[k].period) {
            qd_buf_puts(b, " + k*");
            put_expr(ctx, b, g->sing[k].period);
        }
    }
    qd_buf_puts(b, "\n");
}

static void put_text(qd_ctx *ctx, qd_buf *b, const qd_metric *g, const mt_force *f) {
    qd_buf_printf(b, "metric g_ij: %s = 1/2 g_ij q'^i q'^j", g->from_L ? "L" : "T");
    if (!qd_is_zero(g->T1) || !qd_is_zero(g->T0)) {
        qd_buf_puts(b, " + T1 + T0, T1 = ");
        put_expr(ctx, b, g->T1);
        qd_buf_puts(b, ", T0 = ");
        put_expr(ctx, b, g->T0);
        qd_buf_puts(b, " (not part of the metric: they act in Q)");
    }
    qd_buf_puts(b, "\n");
    text_matrix(ctx, b, g, "g", g->g, false);
    qd_buf_puts(b, "det g = ");
    put_expr(ctx, b, g->det);
    qd_buf_puts(b, "\nconjugate g^ij (nonzero, i <= j):\n");
    text_matrix(ctx, b, g, "g", g->ginv, true);
    text_christoffel(ctx, b, g);
    qd_buf_printf(b, "geodesic form q''^l + Gamma^l_ij q'^i q'^j = g^lk Q_k (each line = 0)%s:\n",
                  g->constrained ? "; the constraints' forces are not included" : "");
    for (size_t l = 0; l < g->n; l++) {
        qd_buf_printf(b, "  %s: ", name(g, l));
        put_expr(ctx, b, g->geodesic[l]);
        qd_buf_puts(b, "\n");
    }
    qd_buf_printf(b, "force (%s):\n", f->given ? "--force, covariant components"
                                                : "the model's, Q_k = -dV/dq_k + ...");
    text_vector(ctx, b, g, "covariant", "G_", f->G);
    text_vector(ctx, b, g, "contravariant g^kl G_l", "G^", f->up);
    qd_buf_printf(b, "  scale factors h_i = sqrt(%s_ii)%s:", g->scale_geometric ? "e" : "g",
                  g->scale_geometric ? "" : " (no positions: from the kinetic metric)");
    for (size_t i = 0; i < g->n; i++) {
        qd_buf_printf(b, "%s h_%s = ", i ? "," : "", name(g, i));
        put_expr(ctx, b, g->h[i]);
    }
    qd_buf_puts(b, "\n");
    text_vector(ctx, b, g, "physical G_i/h_i", "F_", f->phys);
    text_vector(ctx, b, g, g->orthogonal ? "ordinary (= physical: orthogonal coordinates)"
                                         : "ordinary h_i e^ij G_j (not orthogonal)",
                "F_", f->ord);
    text_chart(ctx, b, g);
}

/* ---- json ---------------------------------------------------------------------- */

static void json_vector(qd_json *j, qd_ctx *ctx, const qd_metric *g, const char *key,
                        const qd_expr *const *x) {
    qd_json_key(j, key);
    qd_json_begin_object(j);
    for (size_t i = 0; i < g->n; i++) {
        qd_json_key(j, name(g, i));
        qd_json_expr(j, ctx, x[i]);
    }
    qd_json_end_object(j);
}

static void json_matrix(qd_json *j, qd_ctx *ctx, const qd_metric *g, const char *key,
                        const qd_expr *const *A) {
    qd_json_key(j, key);
    qd_json_begin_object(j);
    for (size_t i = 0; i < g->n; i++)
        json_vector(j, ctx, g, name(g, i), A + i * g->n);
    qd_json_end_object(j);
}

static void json_symbols(qd_json *j, qd_ctx *ctx, const qd_metric *g, const char *key,
                         const qd_expr *const *G) {
    qd_json_key(j, key);
    qd_json_begin_object(j);
    for (size_t l = 0; l < g->n; l++)
        json_matrix(j, ctx, g, name(g, l), G + l * g->n * g->n);
    qd_json_end_object(j);
}

static void json_chart(qd_json *j, qd_ctx *ctx, const qd_metric *g) {
    qd_json_key(j, "chart");
    qd_json_begin_object(j);
    qd_json_key(j, "positions");
    qd_json_begin_array(j);
    for (size_t a = 0; a < g->npos; a++) {
        char lab[32];
        snprintf(lab, sizeof lab, "%c%zu", "xyz"[g->pos_axis[a]], g->pos_particle[a] + 1);
        qd_json_begin_object(j);
        qd_json_key(j, "name");
        qd_json_string(j, lab);
        qd_json_key(j, "value");
        qd_json_expr(j, ctx, g->pos[a]);
        json_vector(j, ctx, g, "jacobian", g->jac + a * g->n);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
    qd_json_key(j, "jacobian_det");
    qd_json_expr(j, ctx, g->jac_det);
    qd_json_key(j, "positions_metric_det");
    qd_json_expr(j, ctx, g->e_det);
    qd_json_key(j, "singular_of");
    qd_json_expr(j, ctx, g->sing_of);
    qd_json_key(j, "singular");
    qd_json_begin_array(j);
    for (size_t k = 0; k < g->nsing; k++) {
        qd_json_begin_object(j);
        qd_json_key(j, "lhs");
        qd_json_expr(j, ctx, g->sing[k].lhs);
        qd_json_key(j, "rhs");
        qd_json_expr(j, ctx, g->sing[k].rhs);
        qd_json_key(j, "period");
        qd_json_expr(j, ctx, g->sing[k].period);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
    qd_json_end_object(j);
}

static void put_json(qd_ctx *ctx, qd_buf *b, const qd_metric *g, const mt_force *f) {
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "coordinates");
    qd_json_begin_array(&j);
    for (size_t i = 0; i < g->n; i++)
        qd_json_string(&j, name(g, i));
    qd_json_end_array(&j);
    qd_json_key(&j, "from"); /* until issue 31 "source" */
    qd_json_string(&j, g->from_L ? "L" : "T");
    qd_json_key(&j, "T2");
    qd_json_expr(&j, ctx, g->T2);
    qd_json_key(&j, "T1");
    qd_json_expr(&j, ctx, g->T1);
    qd_json_key(&j, "T0");
    qd_json_expr(&j, ctx, g->T0);
    json_matrix(&j, ctx, g, "metric", g->g);
    json_matrix(&j, ctx, g, "metric_inverse", g->ginv);
    qd_json_key(&j, "det");
    qd_json_expr(&j, ctx, g->det);
    json_symbols(&j, ctx, g, "christoffel_first", g->first);
    json_symbols(&j, ctx, g, "christoffel_second", g->second);
    json_vector(&j, ctx, g, "Q", g->Q);
    json_vector(&j, ctx, g, "geodesic", g->geodesic);
    qd_json_key(&j, "constrained");
    qd_json_bool(&j, g->constrained);
    qd_json_key(&j, "force");
    qd_json_begin_object(&j);
    qd_json_key(&j, "given");
    qd_json_bool(&j, f->given);
    json_vector(&j, ctx, g, "covariant", f->G);
    json_vector(&j, ctx, g, "contravariant", f->up);
    json_vector(&j, ctx, g, "physical", f->phys);
    json_vector(&j, ctx, g, "ordinary", f->ord);
    qd_json_end_object(&j);
    json_vector(&j, ctx, g, "scale_factors", g->h);
    qd_json_key(&j, "scale_from");
    qd_json_string(&j, g->scale_geometric ? "positions" : "metric");
    qd_json_key(&j, "orthogonal");
    qd_json_bool(&j, g->orthogonal);
    json_chart(&j, ctx, g);
    qd_json_end_object(&j);
    if (!qd_json_ok(&j))
        b->failed = true;
}

static qd_status mt_write(qd_ctx *ctx, const qd_metric *g, const qd_expr *const *G, bool json,
                          qd_buf *out) {
    size_t n = g->n;
    const qd_expr **buf = qd__calloc(ctx, 3 * n + 1, sizeof *buf);
    if (!buf)
        return QD_ERR_NOMEM;
    mt_force f = {.G = G ? G : g->Q, .up = buf, .phys = buf + n, .ord = buf + 2 * n,
                  .given = G != NULL};
    qd_status st = qd_metric_force(ctx, g, f.G, f.up, f.phys, f.ord);
    if (st == QD_OK) {
        if (json)
            put_json(ctx, out, g, &f);
        else
            put_text(ctx, out, g, &f);
        if (out->failed) {
            qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory writing the metric");
            st = QD_ERR_NOMEM;
        }
    }
    qd__free(buf);
    return st;
}

qd_status qd_metric_print(qd_ctx *ctx, const qd_metric *g, const qd_expr *const *G,
                          qd_format fmt, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && g && out);
    if (fmt != QD_FMT_TEXT) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the metric is written as text (or JSON)");
        return QD_ERR_ARG;
    }
    return mt_write(ctx, g, G, false, out);
}

qd_status qd_metric_json(qd_ctx *ctx, const qd_metric *g, const qd_expr *const *G,
                         qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && g && out);
    return mt_write(ctx, g, G, true, out);
}
