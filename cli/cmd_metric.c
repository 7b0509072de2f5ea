/*
 * cli/cmd_metric.c - `qdot metric FILE [--force "G1, G2, ..."] [--set
 * NAME=VALUE]... [--format text|json]`: the kinetic metric g_ij of the
 * model's coordinates, its conjugate, the Christoffel symbols of both
 * kinds, Lagrange's equations in geodesic form, a force's components
 * (covariant, contravariant, physical, ordinary), and the chart's
 * Jacobian with its singular points (qdot/metric.h; Desloge App. 23,
 * ch. 47, ch. 55).
 */
#include "cli.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/json.h"
#include "model_cli.h"
#include "qdot/metric.h"
#include "qdot/read.h"

static const char usage_text[] =
    "usage: qdot metric FILE [--force \"G1, G2, ...\"] [--set NAME=VALUE]... "
    "[--format text|json]";

static const char *const formats[] = {"text", "json", NULL};

typedef struct mt_args {
    const char *file, *force;
    const char *sets[QD_CLI_MAX_LIST];
    size_t nsets;
    bool json;
} mt_args;

static int parse_option(int argc, char **argv, int *i, void *data) {
    mt_args *a = data;
    const char *v;
    int f;
    if ((v = cli_value(argc, argv, i, "--format"))) {
        int rc = cli_choice("--format", v, formats, &f);
        a->json = f == 1;
        return rc;
    }
    if ((v = cli_value(argc, argv, i, "--force")))
        return cli_once("--force", &a->force, v);
    if ((v = cli_value(argc, argv, i, "--set")))
        return cli_push("--set", a->sets, &a->nsets, QD_CLI_MAX_LIST, v);
    return cli_bad_option(argv[*i], usage_text);
}

/* --force: n covariant components, comma-separated expressions. */
static int read_force(qd_ctx *ctx, const char *text, size_t n, const qd_expr **G) {
    size_t k = 0;
    for (size_t a = 0; text[a]; k++) {
        size_t b = cli_item_end(text, a);
        if (k == n) {
            cli_diag_error("--force: the model has %zu coordinates; more components given", n);
            return QD_EXIT_USAGE;
        }
        char *copy = malloc(b - a + 1);
        if (!copy)
            return QD_EXIT_FAIL;
        memcpy(copy, text + a, b - a);
        copy[b - a] = '\0';
        const qd_read_opts opts = {.new_symbols = false};
        qd_diag err;
        G[k] = qd_read(ctx, copy, &opts, &err);
        free(copy);
        if (!G[k]) {
            err.offset += a;
            cli_diag_read("--force", text, &err);
            return QD_EXIT_USAGE;
        }
        a = text[b] ? b + 1 : b;
    }
    if (k != n) {
        cli_diag_error("--force: %zu component%s for %zu coordinates (give one covariant "
                       "component G_i = F . dx/dq_i for each)", k, k == 1 ? "" : "s", n);
        return QD_EXIT_USAGE;
    }
    return QD_EXIT_OK;
}

/* The force's components: the model's Q unless --force gave them. */
typedef struct mt_force {
    const qd_expr **G, **up, **phys, **ord;
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
    qd_json_key(&j, "source");
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

static int run(qd_ctx *ctx, const mt_args *a, cli_model_file *mf) {
    int rc = cli_load(ctx, a->file, a->nsets, a->sets, true, mf);
    if (rc != QD_EXIT_OK)
        return rc;
    qd_metric *g = qd_metric_new(ctx, mf->model);
    if (!g)
        return cli_diag_ctx(ctx);
    size_t n = g->n;
    mt_force f = {.G = calloc(4 * n + 1, sizeof *f.G), .given = a->force != NULL};
    if (!f.G) {
        qd_metric_free(g);
        return QD_EXIT_FAIL;
    }
    f.up = f.G + n;
    f.phys = f.up + n;
    f.ord = f.phys + n;
    if (a->force)
        rc = read_force(ctx, a->force, n, f.G);
    else
        memcpy(f.G, g->Q, n * sizeof *f.G);
    if (rc == QD_EXIT_OK && qd_metric_force(ctx, g, f.G, f.up, f.phys, f.ord) != QD_OK)
        rc = cli_diag_ctx(ctx);
    if (rc == QD_EXIT_OK) {
        qd_buf b = QD_BUF_INIT;
        if (a->json)
            put_json(ctx, &b, g, &f);
        else
            put_text(ctx, &b, g, &f);
        rc = cli_emit(&b, "metric");
    }
    free(f.G);
    qd_metric_free(g);
    return rc;
}

int cli_cmd_metric(int argc, char **argv) {
    mt_args a = {0};
    int rc = cli_file_args(argc, argv, "metric", usage_text, &a.file, parse_option, &a);
    if (rc != QD_EXIT_OK)
        return rc;
    qd_ctx *ctx = qd_ctx_new();
    if (!ctx)
        return QD_EXIT_FAIL;
    cli_model_file mf = {0};
    rc = run(ctx, &a, &mf);
    cli_model_file_free(&mf);
    qd_ctx_free(ctx);
    return rc;
}
