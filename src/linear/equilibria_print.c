/*
 * src/linear/equilibria_print.c - an equilibrium's coordinate as text
 * (qd_equilibrium_put_value) and the sentence of an automatic choice
 * (qd_eq_chosen_name), and the list of equilibria as text or JSON
 * (qd_equilibria_print), qdot/equilibria.h: what `qdot equilibria` and
 * `qdot modes` print of a point, for any caller.
 */
#include "qdot/equilibria.h"
#include "qdot/json.h"
#include "qdot/print.h"
#include "../base/args.h"
#include "linear.h"

const char *qd_eq_chosen_code(qd_eq_chosen c) {
    switch (c) {
    case QD_EQ_CHOSEN_NEAREST_MINIMUM:
        return "nearest_minimum";
    case QD_EQ_CHOSEN_LOWEST_MINIMUM:
        return "lowest_minimum";
    case QD_EQ_CHOSEN_INITIAL_STATE:
        return "initial_state";
    case QD_EQ_CHOSEN_NEWTON_FROM_INITIAL:
        return "newton_from_initial";
    case QD_EQ_CHOSEN_FIRST_LISTED:
        return "first_listed";
    }
    return "unknown";
}

const char *qd_eq_chosen_name(qd_eq_chosen c) {
    switch (c) {
    case QD_EQ_CHOSEN_NEAREST_MINIMUM:
        return "the minimum of the potential nearest the model's initial state";
    case QD_EQ_CHOSEN_LOWEST_MINIMUM:
        return "the minimum of the potential with the lowest V";
    case QD_EQ_CHOSEN_INITIAL_STATE:
        return "the model's initial state is an equilibrium (a minimum of the potential; no "
               "search made)";
    case QD_EQ_CHOSEN_NEWTON_FROM_INITIAL:
        return "no minimum of the potential was found: the equilibrium reached by Newton's "
               "method from the model's initial state";
    default:
        return "no minimum of the potential was found: the first equilibrium listed";
    }
}

qd_status qd_equilibrium_put_value(qd_ctx *ctx, const qd_equilibrium *p, size_t j,
                                   qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && p && p->q && out);
    if (p->exact && p->exact[j])
        return qd_print(ctx, p->exact[j], QD_FMT_TEXT, out);
    qd_buf_put_result(out, p->q[j], 1);
    if (out->failed) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        return QD_ERR_NOMEM;
    }
    return QD_OK;
}

/* ---- the list ------------------------------------------------------------------ */

enum { MAX_FAMILY_SHOWN = 10 };

static qd_status list_text(qd_ctx *ctx, const qd_eom *e, const qd_equilibria *eq, qd_buf *b) {
    qd_status st = QD_OK;
    qd_buf_printf(b, "%zu equilibri%s (%s%s)\n", eq->count, eq->count == 1 ? "um" : "a",
                  eq->method, eq->exact ? ": the complete set, angles in (-pi, pi]" : "");
    /* a family of equilibria is sampled, not enumerated: a few samples say it */
    size_t shown = eq->continuum && eq->count > MAX_FAMILY_SHOWN ? MAX_FAMILY_SHOWN : eq->count;
    for (size_t i = 0; i < shown; i++) {
        const qd_equilibrium *p = &eq->pts[i];
        qd_buf_printf(b, "%3zu  ", i + 1);
        for (size_t j = 0; j < e->n; j++) {
            qd_buf_printf(b, "%s%s = ", j ? ", " : "", qd_expr_name(e->q[j]));
            qd_status sj = qd_equilibrium_put_value(ctx, p, j, b);
            st = st == QD_OK ? sj : st;
            if (p->exact && !qd_is_number(p->exact[j])) {
                qd_buf_puts(b, " (");
                qd_buf_put_result(b, p->q[j], 1);
                qd_buf_puts(b, ")");
            }
        }
        qd_buf_printf(b, "\n     %s of the potential (Hessian: %zu positive, %zu negative, %zu "
                         "zero)%s, residual ",
                      qd_eq_kind_name(p->kind), p->npos, p->nneg, p->nzero,
                      p->symmetric ? "" : "; the forces are not from a potential: K is not "
                                          "symmetric, its symmetric part is classified");
        /* below 1e-14 the figure is round-off, different from build to build */
        if (p->residual < 1e-14)
            qd_buf_puts(b, "< 1e-14\n");
        else
            qd_buf_printf(b, "%.3g\n", p->residual);
    }
    if (shown < eq->count)
        qd_buf_printf(b, "  ... and %zu more samples (--format json lists them all)\n",
                      eq->count - shown);
    if (eq->continuum)
        qd_buf_puts(b, "note: the equilibria are not isolated (a family: a rigid motion or a "
                       "neutral direction); the points listed are samples of it\n");
    return st == QD_ERR_NOMEM ? QD_OK : st; /* the buffer's failure is the caller's */
}

void qd__lin_eq_point_json(qd_ctx *ctx, qd_json *j, const qd_equilibrium *p, size_t n,
                           const qd_expr *const *q, const size_t *idx) {
    qd_json_key(j, "equilibrium");
    qd_json_begin_object(j);
    for (size_t k = 0; k < n; k++) {
        qd_json_key(j, qd_expr_name(q[idx ? idx[k] : k]));
        qd_json_number(j, p->q[k]);
    }
    qd_json_end_object(j);
    if (!p->exact)
        return;
    qd_json_key(j, "exact");
    qd_json_begin_object(j);
    for (size_t k = 0; k < n; k++) {
        qd_json_key(j, qd_expr_name(q[idx ? idx[k] : k]));
        qd_json_expr(j, ctx, p->exact[k]);
    }
    qd_json_end_object(j);
}

void qd__lin_eq_json_head(qd_json *j, const qd_equilibria *eq) {
    qd_json_key(j, "method");
    qd_json_string(j, eq->method);
    qd_json_key(j, "exact");
    qd_json_bool(j, eq->exact);
    qd_json_key(j, "continuum");
    qd_json_bool(j, eq->continuum);
}

static void point_json(qd_ctx *ctx, const qd_eom *e, const qd_equilibrium *p, qd_json *j) {
    qd_json_begin_object(j);
    qd__lin_eq_point_json(ctx, j, p, e->n, e->q, NULL);
    qd_json_key(j, "kind");
    qd_json_string(j, qd_eq_kind_name(p->kind));
    qd_json_key(j, "hessian_signs");
    qd_json_begin_array(j);
    qd_json_number(j, (double)p->npos);
    qd_json_number(j, (double)p->nneg);
    qd_json_number(j, (double)p->nzero);
    qd_json_end_array(j);
    qd_json_key(j, "symmetric");
    qd_json_bool(j, p->symmetric);
    qd_json_key(j, "residual");
    qd_json_number(j, p->residual);
    qd_json_end_object(j);
}

static bool list_json(qd_ctx *ctx, const qd_eom *e, const qd_equilibria *eq, qd_buf *b) {
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    qd__lin_eq_json_head(&j, eq);
    qd_json_key(&j, "equilibria");
    qd_json_begin_array(&j);
    for (size_t i = 0; i < eq->count; i++)
        point_json(ctx, e, &eq->pts[i], &j);
    qd_json_end_array(&j);
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    return qd_json_ok(&j);
}

qd_status qd_equilibria_print(qd_ctx *ctx, const qd_eom *e, const qd_equilibria *eq, bool json,
                              qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && e && eq && out);
    if (eq->n != e->n || (eq->count && !eq->pts) || !eq->method) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the equilibria are not over the equations' coordinates");
        return QD_ERR_ARG;
    }
    qd_buf b = QD_BUF_INIT;
    bool ok = true;
    qd_status st = QD_OK;
    if (json)
        ok = list_json(ctx, e, eq, &b);
    else
        st = list_text(ctx, e, eq, &b);
    bool nomem = b.failed;
    if (ok && !nomem && st == QD_OK)
        qd_buf_putn(out, qd_buf_str(&b), b.len);
    qd_buf_free(&b);
    if (st != QD_OK)
        return st;
    if (!ok && !nomem) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "a number of the equilibria is not finite");
        return QD_ERR_NUMERIC;
    }
    if (nomem || out->failed) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        return QD_ERR_NOMEM;
    }
    return QD_OK;
}
