/*
 * src/action/action_out.c - the action-angle variables written out as text
 * or JSON (qd_action_print, qdot/action.h): what `qdot action` prints, for
 * any caller.
 */
#include "qdot/action.h"
#include "qdot/json.h"
#include "base/args.h"

#define PI 3.14159265358979323846

static const char *kind_name(qd_act_kind k) {
    return k == QD_ACT_ROTATION ? "rotation" : "libration";
}

/* 12 significant digits, 0 at and below 1e-12 (qd_buf_put_result). */
static void put_num(qd_buf *b, double x) { qd_buf_put_result(b, x, 1); }

/* ---- text ------------------------------------------------------------------------ */

static void put_coord_text(const qd_act_coord *c, qd_buf *b) {
    const char *q = qd_expr_name(c->q);
    bool rot = c->kind == QD_ACT_ROTATION;
    qd_buf_printf(b, "%s: %s ", q, kind_name(c->kind));
    qd_buf_puts(b, rot ? "over [" : "between ");
    put_num(b, c->lo);
    qd_buf_puts(b, rot ? ", " : " and ");
    put_num(b, c->hi);
    qd_buf_printf(b, "%s, %s = ", rot ? "]" : "", qd_expr_name(c->constant));
    put_num(b, c->value);
    qd_buf_printf(b, "\n  J_%s = ", q);
    put_num(b, c->J);
    qd_buf_printf(b, "\n  omega_%s = ", q);
    put_num(b, c->omega);
    qd_buf_puts(b, " rad/s, period ");
    put_num(b, 2 * PI / c->omega);
    qd_buf_printf(b, "\n  angle_%s = ", q);
    put_num(b, c->angle);
    qd_buf_puts(b, "\n");
}

static void put_closed_text(const qd_action *a, qd_buf *b) {
    if (a->closed == QD_ACT_H_LINEAR) {
        qd_buf_puts(b, "H(J) = ");
        for (size_t k = 0; k < a->n; k++) {
            qd_buf_puts(b, k ? " + " : "");
            put_num(b, a->c[k].omega);
            qd_buf_printf(b, "*J_%s/(2*pi)", qd_expr_name(a->c[k].q));
        }
        qd_buf_puts(b, "  (oscillators: omega J / (2 pi) each)\n");
    } else if (a->closed == QD_ACT_H_KEPLER) {
        qd_buf_puts(b, "H(J) = -");
        put_num(b, a->closed_c);
        qd_buf_puts(b, "/(");
        for (size_t k = 0; k < a->n; k++)
            qd_buf_printf(b, "%sJ_%s", k ? " + " : "", qd_expr_name(a->c[k].q));
        qd_buf_puts(b, ")^2  (Kepler: -2 pi^2 m k^2 / (sum J)^2)\n");
    }
}

static void put_text(const qd_action *a, qd_buf *b) {
    qd_buf_printf(b, "separation: %s\nenergy: ", a->form ? a->form : "");
    put_num(b, a->energy);
    qd_buf_puts(b, "\n");
    for (size_t k = 0; k < a->n; k++)
        put_coord_text(&a->c[k], b);
    for (size_t r = 0; r < a->nratio; r++) {
        const qd_act_ratio *x = &a->ratio[r];
        qd_buf_printf(b, "degenerate: omega_%s : omega_%s = %ld : %ld (commensurate: the "
                         "orbit closes)\n",
                      qd_expr_name(a->c[x->i].q), qd_expr_name(a->c[x->j].q), x->num, x->den);
    }
    put_closed_text(a, b);
}

/* ---- JSON ------------------------------------------------------------------------ */

static void put_coord_json(qd_json *j, const qd_act_coord *c) {
    qd_json_begin_object(j);
    qd_json_key(j, "coordinate");
    qd_json_string(j, qd_expr_name(c->q));
    qd_json_key(j, "constant");
    qd_json_string(j, qd_expr_name(c->constant));
    qd_json_key(j, "value");
    qd_json_number(j, c->value);
    qd_json_key(j, "kind");
    qd_json_string(j, kind_name(c->kind));
    qd_json_key(j, c->kind == QD_ACT_ROTATION ? "range" : "turning_points");
    qd_json_begin_array(j);
    qd_json_number(j, c->lo);
    qd_json_number(j, c->hi);
    qd_json_end_array(j);
    qd_json_key(j, "J");
    qd_json_number(j, c->J);
    qd_json_key(j, "omega");
    qd_json_number(j, c->omega);
    qd_json_key(j, "angle");
    qd_json_number(j, c->angle);
    qd_json_end_object(j);
}

static void put_closed_json(qd_json *j, const qd_action *a) {
    qd_json_key(j, "H_of_J");
    if (a->closed == QD_ACT_H_NONE) {
        qd_json_null(j);
        return;
    }
    qd_json_begin_object(j);
    qd_json_key(j, "form");
    qd_json_string(j, a->closed == QD_ACT_H_LINEAR ? "sum omega_k J_k/(2 pi)" : "-c/(sum J_k)^2");
    if (a->closed == QD_ACT_H_KEPLER) {
        qd_json_key(j, "c");
        qd_json_number(j, a->closed_c);
    }
    qd_json_end_object(j);
}

static void put_json(const qd_action *a, qd_json *j) {
    qd_json_begin_object(j);
    qd_json_key(j, "separation");
    qd_json_string(j, a->form ? a->form : "");
    qd_json_key(j, "energy");
    qd_json_number(j, a->energy);
    qd_json_key(j, "coordinates");
    qd_json_begin_array(j);
    for (size_t k = 0; k < a->n; k++)
        put_coord_json(j, &a->c[k]);
    qd_json_end_array(j);
    static const char *const keys[] = {"actions", "frequencies", "angles"};
    for (int w = 0; w < 3; w++) {
        qd_json_key(j, keys[w]);
        qd_json_begin_object(j);
        for (size_t k = 0; k < a->n; k++) {
            const qd_act_coord *c = &a->c[k];
            qd_json_key(j, qd_expr_name(c->q));
            qd_json_number(j, w == 0 ? c->J : w == 1 ? c->omega : c->angle);
        }
        qd_json_end_object(j);
    }
    qd_json_key(j, "degeneracies");
    qd_json_begin_array(j);
    for (size_t r = 0; r < a->nratio; r++) {
        qd_json_begin_object(j);
        qd_json_key(j, "coordinates");
        qd_json_begin_array(j);
        qd_json_string(j, qd_expr_name(a->c[a->ratio[r].i].q));
        qd_json_string(j, qd_expr_name(a->c[a->ratio[r].j].q));
        qd_json_end_array(j);
        qd_json_key(j, "ratio");
        qd_json_begin_array(j);
        qd_json_number(j, (double)a->ratio[r].num);
        qd_json_number(j, (double)a->ratio[r].den);
        qd_json_end_array(j);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
    put_closed_json(j, a);
    qd_json_end_object(j);
}

/* ---- the document ------------------------------------------------------------------ */

qd_status qd_action_print(qd_ctx *ctx, const qd_action *a, bool json, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && a && out);
    if (a->n && !a->c) {
        qd_ctx_error(ctx, QD_ERR_ARG, "qd_action_print: not a result of qd_action_at");
        return QD_ERR_ARG;
    }
    for (size_t r = 0; r < a->nratio; r++)
        if (!a->ratio || a->ratio[r].i >= a->n || a->ratio[r].j >= a->n) {
            qd_ctx_error(ctx, QD_ERR_ARG, "qd_action_print: a degeneracy names no coordinate");
            return QD_ERR_ARG;
        }
    qd_buf b = QD_BUF_WITH(out->alloc);
    qd_json j;
    if (json) {
        qd_json_init(&j, &b);
        put_json(a, &j);
        qd_buf_puts(&b, "\n");
    } else {
        put_text(a, &b);
    }
    return qd_json_commit(ctx, &b, json ? &j : NULL, out);
}
