/*
 * src/mech/zero_set.c - where a Jacobian determinant vanishes, factor by
 * factor (qd__mech_zero_set, mech.h): the singular points of a chart (qdot
 * metric's chart, Desloge App. 18) and the places where a change of
 * variables' Jacobian may change sign (qd_change_vars, App. 19).  Moved
 * here from metric.c so both share it.
 */
#include "mech.h"

#include <math.h>

#include "base/mem.h"
#include "qdot/metric.h"

typedef struct zs_vars {
    size_t n;
    const qd_expr *const *q;
} zs_vars;

/* The coordinate x depends on, when it is exactly one; else NULL. */
static const qd_expr *only_coord(const zs_vars *g, const qd_expr *x) {
    const qd_expr *c = NULL;
    for (size_t i = 0; i < g->n; i++)
        if (qd_has(x, g->q[i])) {
            if (c)
                return NULL;
            c = g->q[i];
        }
    return c;
}

/* a*q + b = 0 for q, when x is linear in its one coordinate q. */
static bool solve_linear(qd_ctx *ctx, const zs_vars *g, const qd_expr *x, const qd_expr **q,
                         const qd_expr **val) {
    const qd_expr *c = only_coord(g, x);
    if (!c)
        return false;
    const qd_expr *a = qd_simplify(ctx, qd_diff(ctx, x, c));
    if (!a || qd_has(a, c) || qd_is_zero(a))
        return false;
    const qd_expr *zero = qd_int(ctx, 0);
    const qd_expr *b = qd_simplify(ctx, qd_subs(ctx, x, 1, &c, &zero));
    *q = c;
    *val = b ? qd_simplify(ctx, qd_div(ctx, qd_neg(ctx, b), a)) : NULL;
    return *val != NULL;
}

/* One factor's zero set: q = value (+ k pi for sin and cos), or x = 0. */
static void factor_zero(qd_ctx *ctx, const zs_vars *g, const qd_expr *x,
                        qd_metric_singular *s) {
    const qd_expr *pi = qd_const(ctx, QD_PI);
    *s = (qd_metric_singular){.lhs = x, .rhs = qd_int(ctx, 0)};
    if (qd_expr_kind(x) == QD_FUNC &&
        (qd_expr_func(x) == QD_SIN || qd_expr_func(x) == QD_COS)) {
        const qd_expr *q, *v;
        if (solve_linear(ctx, g, qd_expr_arg(x, 0), &q, &v)) {
            /* sin(a q + b) = 0 at a q + b = k pi; cos at pi/2 + k pi */
            const qd_expr *a = qd_simplify(ctx, qd_diff(ctx, qd_expr_arg(x, 0), q));
            const qd_expr *shift = qd_expr_func(x) == QD_COS
                                       ? qd_div(ctx, qd_div(ctx, pi, qd_int(ctx, 2)), a)
                                       : qd_int(ctx, 0);
            s->lhs = q;
            s->rhs = qd_simplify(ctx, qd_add(ctx, v, shift));
            s->period = qd_simplify(ctx, qd_div(ctx, pi, a));
        }
        return;
    }
    const qd_expr *q, *v;
    if (solve_linear(ctx, g, x, &q, &v)) {
        s->lhs = q;
        s->rhs = v;
    }
}

/* x > 0 wherever it is defined, read from its form: positive numbers and
 * parameters, even powers, and products and sums of those with at least
 * one term that is positive without the coordinates (m1 + m2 sin^2(a)). */
bool qd__mech_nonneg(const qd_expr *x, bool *pos) {
    switch (qd_expr_kind(x)) {
    case QD_RATIONAL:
    case QD_FLOAT:
        *pos = qd_number_sign(x) > 0;
        return qd_number_sign(x) >= 0;
    case QD_CONSTANT:
        *pos = true;
        return true;
    case QD_SYMBOL:
        *pos = qd_symbol_is_positive(x);
        return *pos;
    case QD_POW: {
        const qd_expr *k = qd_expr_arg(x, 1);
        bool p;
        *pos = false;
        if (qd_is_integer(k) && fmod(qd_number_value(k), 2) == 0)
            return true;
        return qd__mech_nonneg(qd_expr_arg(x, 0), &p) && p && (*pos = true);
    }
    case QD_MUL: {
        bool all = true;
        *pos = true;
        for (size_t i = 0; i < qd_expr_nargs(x); i++) {
            bool p;
            all = all && qd__mech_nonneg(qd_expr_arg(x, i), &p);
            *pos = *pos && p;
        }
        return all;
    }
    case QD_ADD: {
        bool any = false;
        for (size_t i = 0; i < qd_expr_nargs(x); i++) {
            bool p;
            if (!qd__mech_nonneg(qd_expr_arg(x, i), &p))
                return *pos = false;
            any = any || p;
        }
        *pos = any;
        return true;
    }
    default:
        return *pos = false;
    }
}

/* The zeros of det, factor by factor (powers by their base; factors free
 * of the variables are not zero for the parameters' values). */
qd_status qd__mech_zero_set(qd_ctx *ctx, const qd_expr *det, size_t n, const qd_expr *const *q,
                       qd_metric_singular **out, size_t *count) {
    zs_vars vars = {n, q}, *g = &vars;
    *out = NULL;
    *count = 0;
    const qd_expr *d = qd_factor_terms(ctx, qd_trigsimp(ctx, det));
    if (!d)
        return qd_ctx_status(ctx);
    size_t nf = qd_expr_kind(d) == QD_MUL ? qd_expr_nargs(d) : 1;
    qd_metric_singular *sing = qd__calloc(ctx, nf, sizeof *sing);
    if (!sing)
        return QD_ERR_NOMEM;
    size_t ns = 0;
    for (size_t i = 0; i < nf; i++) {
        const qd_expr *f = nf > 1 || qd_expr_kind(d) == QD_MUL ? qd_expr_arg(d, i) : d;
        if (qd_expr_kind(f) == QD_POW && qd_is_number(qd_expr_arg(f, 1))) {
            if (qd_number_sign(qd_expr_arg(f, 1)) < 0)
                continue; /* 1/sin(th/2)^2 is never 0 (a pole, not a zero) */
            f = qd_expr_arg(f, 0);
        }
        bool vars_in = false;
        for (size_t j = 0; j < n; j++)
            vars_in = vars_in || qd_has(f, q[j]);
        bool pos;
        if (!vars_in || (qd__mech_nonneg(f, &pos) && pos))
            continue;
        factor_zero(ctx, g, f, &sing[ns]);
        bool seen = false;
        for (size_t k = 0; k < ns; k++)
            seen = seen || (qd_expr_cmp(sing[k].lhs, sing[ns].lhs) == 0 &&
                            qd_expr_cmp(sing[k].rhs, sing[ns].rhs) == 0);
        if (!seen)
            ns++;
    }
    *out = sing;
    *count = ns;
    return qd_ctx_status(ctx);
}
