/*
 * src/mech/constraints.c - the constraint rows of M q'' = f + A^T lambda,
 * A q'' = b.
 *
 * Each constraint of the model is split into its velocity coefficients,
 * sum_j a_j q'_j + a0 (Desloge ch. 49 eq. 15, ch. 52 thm 1): for a holonomic
 * phi(q, t) they are a_j = dphi/dq_j and a0 = dphi/dt, for a Pfaffian one
 * qd_linear_coeffs reads them off.  The row closing the system is the
 * constraint differentiated until the accelerations appear, phi'' (holonomic)
 * or (sum a_j q'_j + a0)' (Pfaffian); its acceleration coefficients are a_j
 * again and b = -(the rest), i.e. b = -(sum_j a_j' q'_j + a0').  Virtual
 * displacements are at frozen time, so dphi/dt enters b only, never A
 * (Desloge, pitfall 1: a moving smooth surface).
 */
#include "mech.h"

#include "qdot/print.h"

#include <stdio.h>
#include <stdlib.h>

static bool has_any(const qd_expr *x, size_t n, const qd_expr *const *syms) {
    for (size_t i = 0; x && i < n; i++)
        if (qd_has(x, syms[i]))
            return true;
    return false;
}

/* A velocity of x that is in it other than linearly, for the message. */
static const char *nonlinear_velocity(qd_ctx *ctx, const qd_eom *e, const qd_expr *x) {
    for (size_t j = 0; j < e->n; j++) {
        const qd_expr *d = qd_diff(ctx, x, e->qd[j]);
        if (d && has_any(d, e->n, e->qd))
            return qd_expr_name(e->qd[j]);
    }
    return "a velocity";
}

/* x grouped by velocity monomials and simplified. */
static const qd_expr *tidy(qd_ctx *ctx, const qd_eom *e, const qd_expr *x) {
    qd__vsum v;
    qd_status st = qd__by_velocity(ctx, x, e->n, e->qd, &v);
    if (st != QD_OK && st != QD_ERR_NONLINEAR)
        return NULL;
    return qd_simplify(ctx, st == QD_OK ? v.all : x);
}

/* c->a, c->a0 and kind; the constraint differentiated once more than
 * needed for its velocity form goes to *closing. */
static qd_status split(qd_ctx *ctx, const qd_eom *e, qd_con *c, const qd_expr **closing) {
    size_t n = e->n;
    if (has_any(c->expr, n, e->qdd)) {
        qd_ctx_error(ctx, QD_ERR_ARG,
                     "constraint %s contains accelerations: a constraint relates coordinates, "
                     "velocities and t", c->name);
        return QD_ERR_ARG;
    }
    if (!has_any(c->expr, n, e->qd)) {
        c->kind = QD_CON_HOLONOMIC;
        for (size_t j = 0; j < n; j++)
            c->a[j] = qd_diff(ctx, c->expr, e->q[j]);
        c->a0 = qd_diff(ctx, c->expr, qd_time(ctx));
        *closing = qd_dt(ctx, qd_dt(ctx, c->expr));
        return *closing ? QD_OK : qd_ctx_status(ctx);
    }
    c->kind = QD_CON_NONHOLONOMIC;
    qd_status st = qd_linear_coeffs(ctx, c->expr, n, e->qd, c->a, &c->a0);
    if (st == QD_ERR_NONLINEAR) {
        qd_ctx_clear_error(ctx); /* the kernel's message does not name the constraint */
        qd_ctx_error(ctx, st,
                     "constraint %s is not linear in the velocities (%s enters nonlinearly): "
                     "qdot handles holonomic and Pfaffian constraints",
                     c->name, nonlinear_velocity(ctx, e, c->expr));
        return st;
    }
    *closing = st == QD_OK ? qd_dt(ctx, c->expr) : NULL;
    return *closing ? QD_OK : qd_ctx_status(ctx);
}

/* The multiplier's symbol: lambda_<name>, with '_' appended while a
 * coordinate or parameter has that name. */
static const qd_expr *multiplier(qd_ctx *ctx, const char *name) {
    char buf[160];
    int len = snprintf(buf, sizeof buf, "lambda_%s", name);
    if (len < 0 || (size_t)len >= sizeof buf - 8) {
        qd_ctx_error(ctx, QD_ERR_ARG, "constraint name '%s' is too long", name);
        return NULL;
    }
    for (const qd_expr *s; (s = qd_lookup(ctx, buf)) && qd_symbol_role(s) != QD_ROLE_PLAIN;)
        buf[len++] = '_', buf[len] = '\0';
    return qd_symbol(ctx, buf);
}

static qd_status row(qd_ctx *ctx, qd_eom *e, size_t k, const qd_expr **scratch) {
    qd_con *c = &e->con[k];
    const qd_expr *closing = NULL, *rest = NULL;
    qd_status st = split(ctx, e, c, &closing);
    if (st == QD_OK)
        st = qd_linear_coeffs(ctx, closing, e->n, e->qdd, scratch, &rest);
    if (st != QD_OK)
        return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : st;
    for (size_t j = 0; j < e->n; j++)
        if (!(c->a[j] = qd_simplify(ctx, c->a[j])))
            return qd_ctx_status(ctx);
    c->a0 = qd_simplify(ctx, c->a0);
    e->b[k] = tidy(ctx, e, qd_neg(ctx, rest));
    c->lambda = multiplier(ctx, c->name);
    return c->a0 && e->b[k] && c->lambda ? QD_OK : qd_ctx_status(ctx);
}

/* Pfaffian constraints that are integrable one by one must also be so
 * together (Frobenius: the two no-slip conditions of a rolling disk); when
 * they are not, none of them is counted as integrable. */
static qd_status classify_together(qd_ctx *ctx, qd_eom *e) {
    qd_con *cs[16];
    size_t m = 0;
    bool together = true;
    for (size_t k = 0; k < e->ncon && m < 16; k++)
        if (e->con[k].kind == QD_CON_INTEGRABLE)
            cs[m++] = &e->con[k];
    if (m < 2)
        return QD_OK;
    qd_status st = qd__con_frobenius(ctx, e->n, e->q, cs, m, &together);
    for (size_t i = 0; st == QD_OK && !together && i < m; i++) {
        cs[i]->kind = QD_CON_NONHOLONOMIC;
        cs[i]->integral = cs[i]->factor = NULL;
    }
    return st;
}

qd_status qd__con_setup(qd_ctx *ctx, qd_eom *e, const qd__sys *s) {
    size_t n = e->n, m = s->ncon;
    e->ncon = m;
    e->con = calloc(m ? m : 1, sizeof *e->con);
    e->A = calloc(m * n + 1, sizeof *e->A);
    e->b = calloc(m ? m : 1, sizeof *e->b);
    const qd_expr **scratch = calloc(n ? n : 1, sizeof *scratch);
    qd_status st = e->con && e->A && e->b && scratch ? QD_OK : QD_ERR_NOMEM;
    for (size_t k = 0; st == QD_OK && k < m; k++) {
        e->con[k] = (qd_con){.name = s->con_name[k], .expr = s->con_expr[k], .a = e->A + k * n};
        st = row(ctx, e, k, scratch);
        if (st == QD_OK && e->con[k].kind != QD_CON_HOLONOMIC)
            st = qd__con_classify(ctx, n, e->q, &e->con[k]);
    }
    if (st == QD_OK)
        st = classify_together(ctx, e);
    free(scratch);
    if (st == QD_ERR_NOMEM && qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, st, "out of memory deriving the constraints");
    return st;
}
