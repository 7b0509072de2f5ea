/*
 * src/linear/constrained_print.c - the small oscillations of a model on
 * its holonomic constraint manifold as text or JSON
 * (qd_constrained_modes_print, qdot/constrained.h): what `qdot modes`
 * prints for such a model, for any caller.  Its state-space form is
 * qdot/conlin.h's (one path for every constrained linearization).
 */
#include "qdot/constrained.h"
#include "qdot/json.h"
#include "qdot/print.h"
#include "../base/args.h"
#include "linear.h"

#include <math.h>
#include <stdio.h>

static const char *verdict(int s) {
    return s == 1 ? "stable" : s == 0 ? "unstable" : "borderline";
}

/* ---- what both print: the reduction ---------------------------------------- */

static void put_names(qd_buf *b, const qd_eom *e, size_t k, const size_t *ix) {
    for (size_t i = 0; i < k; i++)
        qd_buf_printf(b, "%s%s", i ? ", " : "", qd_expr_name(e->q[ix[i]]));
}

static void put_head(qd_buf *b, const qd_eom *e, const qd_constrained_linear *c) {
    qd_buf_printf(b, "on the constraint manifold (%zu coordinates, %zu constraint%s): "
                     "independent ", c->n, c->ncon, c->ncon == 1 ? "" : "s");
    put_names(b, e, c->r, c->indep);
    qd_buf_puts(b, "; dependent ");
    put_names(b, e, c->ncon, c->dep);
    qd_buf_puts(b, "\nabout ");
    for (size_t j = 0; j < c->n; j++) {
        qd_buf_printf(b, "%s%s = ", j ? ", " : "", qd_expr_name(e->q[j]));
        qd_buf_put_result(b, c->q[j], 1);
    }
    qd_buf_puts(b, "\nmultipliers ");
    for (size_t k = 0; k < c->ncon; k++) {
        qd_buf_printf(b, "%s%s = ", k ? ", " : "", qd_expr_name(e->con[k].lambda));
        qd_buf_put_result(b, c->lambda[k], 1);
    }
    qd_buf_puts(b, "\n");
}

static void json_head(qd_json *j, const qd_eom *e, const qd_constrained_linear *c) {
    qd_json_key(j, "independent");
    qd_json_begin_array(j);
    for (size_t i = 0; i < c->r; i++)
        qd_json_string(j, qd_expr_name(e->q[c->indep[i]]));
    qd_json_end_array(j);
    qd_json_key(j, "dependent");
    qd_json_begin_array(j);
    for (size_t i = 0; i < c->ncon; i++)
        qd_json_string(j, qd_expr_name(e->q[c->dep[i]]));
    qd_json_end_array(j);
    qd_json_key(j, "equilibrium");
    qd_json_begin_object(j);
    for (size_t k = 0; k < c->n; k++) {
        qd_json_key(j, qd_expr_name(e->q[k]));
        qd_json_number(j, c->q[k]);
    }
    qd_json_end_object(j);
    qd_json_key(j, "multipliers");
    qd_json_begin_object(j);
    for (size_t k = 0; k < c->ncon; k++) {
        qd_json_key(j, qd_expr_name(e->con[k].lambda));
        qd_json_number(j, c->lambda[k]);
    }
    qd_json_end_object(j);
}

static void json_eigs(qd_json *j, const qd_modes_result *res) {
    qd_json_key(j, "eigenvalues");
    qd_json_begin_array(j);
    for (size_t k = 0; k < res->neig; k++) {
        qd_json_begin_array(j);
        qd_json_number(j, qd__lin_root_shown(res, res->eig_re[k]));
        qd_json_number(j, qd__lin_root_shown(res, res->eig_im[k]));
        qd_json_end_array(j);
    }
    qd_json_end_array(j);
    qd_json_key(j, "stable");
    if (res->stable == -1)
        qd_json_null(j);
    else
        qd_json_bool(j, res->stable == 1);
    qd_json_key(j, "verdict");
    qd_json_string(j, verdict(res->stable));
}

static void text_eigs(qd_buf *b, const qd_modes_result *res) {
    qd_buf_puts(b, "eigenvalues of A:\n");
    for (size_t k = 0; k < res->neig; k++) {
        double re = qd__lin_root_shown(res, res->eig_re[k]);
        double im = qd__lin_root_shown(res, res->eig_im[k]);
        qd_buf_printf(b, "  s = %.10g %s %.10gi\n", re, im < 0 ? "-" : "+", fabs(im));
    }
}

/* ---- the modes ------------------------------------------------------------- */

static void modes_text(qd_buf *b, const qd_eom *e, const qd_constrained_linear *c,
                       const qd_modes_result *res) {
    qd_buf_puts(b, "small oscillations ");
    put_head(b, e, c);
    if (res->conservative) {
        for (size_t k = 0; k < res->n; k++) {
            double w2 = res->omega2[k];
            qd_buf_printf(b, "mode %zu: w^2 = %.12g", k + 1, w2);
            if (w2 > 0)
                qd_buf_printf(b, ", w = %.10g rad/s, period = %.10g s", sqrt(w2),
                              2 * 3.14159265358979323846 / sqrt(w2));
            qd_buf_puts(b, "\n  shape:");
            for (size_t i = 0; i < c->r; i++)
                qd_buf_printf(b, "%s %s = %.12g", i ? "," : "", qd_expr_name(e->q[c->indep[i]]),
                              res->shapes[i * res->n + k]);
            qd_buf_puts(b, "\n");
        }
    } else
        text_eigs(b, res);
    qd_buf_printf(b, "verdict: %s\n", verdict(res->stable));
}

static void modes_json(qd_json *j, const qd_eom *e, const qd_constrained_linear *c,
                       const qd_modes_result *res) {
    qd_json_begin_object(j);
    json_head(j, e, c);
    qd_json_key(j, "conservative");
    qd_json_bool(j, res->conservative);
    const double *mats[] = {c->lin.M, c->lin.C, c->lin.G, c->lin.K};
    /* the names plain modes uses (until issue 31 "M", "C", "G", "K") */
    const char *keys[] = {"mass_matrix", "damping_matrix", "gyroscopic_matrix",
                          "stiffness_matrix"};
    for (int i = 0; i < 4; i++)
        qd_json_matrix(j, keys[i], c->r, c->r, mats[i]);
    if (res->conservative) {
        qd_json_key(j, "modes");
        qd_json_begin_array(j);
        for (size_t k = 0; k < res->n; k++) {
            qd_json_begin_object(j);
            qd_json_key(j, "omega2");
            qd_json_number(j, res->omega2[k]);
            if (res->omega2[k] >= 0) {
                qd_json_key(j, "omega");
                qd_json_number(j, sqrt(res->omega2[k]));
            }
            qd_json_key(j, "shape");
            qd_json_begin_object(j);
            for (size_t i = 0; i < c->r; i++) {
                qd_json_key(j, qd_expr_name(e->q[c->indep[i]]));
                qd_json_number(j, res->shapes[i * res->n + k]);
            }
            qd_json_end_object(j);
            qd_json_end_object(j);
        }
        qd_json_end_array(j);
    }
    json_eigs(j, res);
    qd_json_end_object(j);
}

/* ---- the entry point ----------------------------------------------------- */

typedef struct con_view {
    const qd_eom *e;
    const qd_constrained_linear *c;
    const qd_modes_result *res;
} con_view;

/* v printed into a buffer of its own, appended to out when complete. */
static qd_status print(qd_ctx *ctx, const con_view *v, bool json, const char *what,
                       qd_buf *out) {
    qd_buf b = QD_BUF_WITH(out->alloc);
    qd_status st = QD_OK;
    if (json) {
        qd_json j;
        qd_json_init(&j, &b);
        modes_json(&j, v->e, v->c, v->res);
        qd_buf_puts(&b, "\n");
        if (!b.failed && !qd_json_ok(&j)) {
            qd_ctx_error(ctx, QD_ERR_NUMERIC, "cannot print the %s: %s", what, qd_json_why(&j));
            st = QD_ERR_NUMERIC;
        }
    } else
        modes_text(&b, v->e, v->c, v->res);
    if (st == QD_OK && !b.failed)
        qd_buf_putn(out, qd_buf_str(&b), b.len);
    if (st == QD_OK && (b.failed || out->failed)) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        st = QD_ERR_NOMEM;
    }
    qd_buf_free(&b);
    return st;
}

/* The modes solved for c: as many as c's independent coordinates. */
static bool fits(qd_ctx *ctx, const qd_eom *e, const qd_constrained_linear *c,
                 const qd_modes_result *res) {
    if (c->n == e->n && c->ncon == e->ncon && c->r == c->n - c->ncon && res->n == c->r &&
        res->neig == 2 * c->r)
        return true;
    qd_ctx_error(ctx, QD_ERR_ARG, "the reduction, the equations and the modes do not belong "
                                  "together (their sizes differ)");
    return false;
}

qd_status qd_constrained_modes_print(qd_ctx *ctx, const qd_eom *e, const qd_constrained_linear *c,
                                     const qd_modes_result *res, bool json, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && e && c && res && out);
    if (!fits(ctx, e, c, res))
        return QD_ERR_ARG;
    const con_view v = {e, c, res};
    return print(ctx, &v, json, "modes", out);
}
