/*
 * src/impulse/rows.c - the system of an impulse in symbols: the mass
 * matrix, the energy, and the velocity forms of the rows that act through
 * the impulse.
 *
 * Integrating Lagrange's equations over the impulse (Desloge ch. 57 thm 1,
 * Byerly art. 27) leaves the jump of the momenta dT/dq', which is
 * M (q'+ - q'-) only when T is at most quadratic in the velocities
 * (T = T2 + T1 + T0 with M = d^2 T2 / dq' dq' and T1's coefficients
 * unchanged, q being frozen).  Each row is a velocity form c = a . q' + a0:
 * a holonomic phi(q, t) gives a = dphi/dq, a0 = dphi/dt (its rate), a
 * Pfaffian one its coefficients (as src/mech/constraints.c does for the
 * ordinary constraints, whose rows the derivation already has).
 */
#include "impulse_priv.h"

#include "base/mem.h"
#include "mech/mech_export.h"

#include <string.h>

void qd__imp_free(qd__imp *s) {
    qd_eom_free(s->e);
    qd__free(s->row);
    qd__free(s->A);
    qd__free(s->E);
    qd__free(s->syms);
    qd__free(s->vals);
    qd__free(s->q0);
    qd__free(s->qd0);
    qd__free(s->M);
    qd__free(s->P);
    *s = (qd__imp){0};
}

static bool has_any(const qd_expr *x, size_t n, const qd_expr *const *syms) {
    for (size_t i = 0; x && i < n; i++)
        if (qd_has(x, syms[i]))
            return true;
    return false;
}

static qd_status not_quadratic(qd_ctx *ctx, const char *what) {
    if (!qd__ctx_recover(ctx))
        return QD_ERR_NOMEM;
    qd_ctx_error(ctx, QD_ERR_NONLINEAR,
                 "%s is not quadratic in the velocities: the impulse equations "
                 "M (q'+ - q'-) = Qhat need T = T2 + T1 + T0 (Desloge ch. 57 thm 1)", what);
    qd_ctx_error_about(ctx, QD_SUBJECT_STATEMENT, 0, what[0] == 'L' ? "L" : "T",
                       QD_REASON_NOT_QUADRATIC, "write T as a quadratic form in the velocities");
    return QD_ERR_NONLINEAR;
}

/* A velocity-dependence beyond the square (a relativistic L): the momenta
 * P_j = dL/dq'_j and the energy function sum q'_j P_j - L, whose jump is
 * the energy lost (its value at rest cancels, q being frozen). */
static qd_status momenta(qd__imp *s) {
    qd_ctx *ctx = s->ctx;
    if (!qd__ctx_recover(ctx))
        return QD_ERR_NOMEM;
    s->nonquad = true;
    s->P = qd__calloc(ctx, s->n + 1, sizeof *s->P);
    if (!s->P)
        return QD_ERR_NOMEM;
    const qd_expr *h = qd_neg(ctx, s->e->L);
    for (size_t j = 0; j < s->n; j++) {
        s->P[j] = qd_diff(ctx, s->e->L, s->e->qd[j]);
        h = qd_add(ctx, h, qd_mul(ctx, s->e->qd[j], s->P[j]));
    }
    s->T = h;
    return h ? QD_OK : qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
}

/* s->T: the model's T checked quadratic, or L's velocity-dependent part
 * T2 + T1 for a model given by L (its T0 cannot be told from -V; it
 * cancels from every energy difference, q being frozen). */
static qd_status energy(qd__imp *s) {
    qd_ctx *ctx = s->ctx;
    const qd_expr *T = qd_model_kinetic(s->m);
    bool given = T != NULL;
    if (!T)
        T = s->e->L;
    if (!T) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the model gives no kinetic energy or Lagrangian");
        return QD_ERR_ARG;
    }
    qd__vsum v;
    qd_status st = qd__mech_by_velocity(ctx, T, s->n, s->e->qd, &v);
    if ((st == QD_ERR_NONLINEAR || (st == QD_OK && v.top > 2)) && s->e->L)
        return momenta(s);
    if (st == QD_ERR_NONLINEAR || (st == QD_OK && v.top > 2))
        return not_quadratic(ctx, given ? "the kinetic energy T" : "L");
    if (st != QD_OK)
        return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : st;
    s->T = given ? v.all : qd_add(ctx, v.deg[2], v.deg[1]);
    return s->T ? QD_OK : qd_ctx_status(ctx);
}

/* c->a, c->a0 of a sudden constraint or prescription c->expr. */
static qd_status velocity_form(qd__imp *s, qd_con *c, const char *what) {
    qd_ctx *ctx = s->ctx;
    const qd_eom *e = s->e;
    size_t n = s->n;
    if (has_any(c->expr, n, e->qdd)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "%s %s contains accelerations", what, c->name);
        return QD_ERR_ARG;
    }
    c->kind = has_any(c->expr, n, e->qd) ? QD_CON_NONHOLONOMIC : QD_CON_HOLONOMIC;
    if (c->kind == QD_CON_HOLONOMIC) { /* its rate */
        for (size_t j = 0; j < n; j++)
            c->a[j] = qd_diff(ctx, c->expr, e->q[j]);
        c->a0 = qd_diff(ctx, c->expr, qd_time(ctx));
    } else if (qd_linear_coeffs(ctx, c->expr, n, e->qd, c->a, &c->a0) == QD_ERR_NONLINEAR) {
        if (!qd__ctx_recover(ctx))
            return QD_ERR_NOMEM;
        qd_ctx_error(ctx, QD_ERR_ARG,
                     "%s %s is not linear in the velocities: the velocities after an impulse "
                     "obey linear conditions only", what, c->name);
        return QD_ERR_ARG;
    }
    for (size_t j = 0; j < n; j++)
        if (!c->a[j] || !(c->a[j] = qd_simplify(ctx, c->a[j])))
            return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    c->a0 = c->a0 ? qd_simplify(ctx, c->a0) : NULL;
    return c->a0 ? QD_OK : qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
}

static qd_status alloc_rows(qd__imp *s) {
    size_t r = s->nrow + 1, n = s->n ? s->n : 1;
    s->row = qd__calloc(s->ctx, r, sizeof *s->row);
    s->A = qd__calloc(s->ctx, r * n, sizeof *s->A);
    s->E = qd__calloc(s->ctx, r, sizeof *s->E);
    if (!s->row || !s->A || !s->E) {
        qd_ctx_error(s->ctx, QD_ERR_NOMEM, "out of memory setting up an impulse");
        return QD_ERR_NOMEM;
    }
    for (size_t k = 0; k < s->nrow; k++)
        s->row[k].a = s->A + k * s->n;
    return QD_OK;
}

/* Row k from the model's i-th sudden constraint or prescription. */
static qd_status model_row(qd__imp *s, size_t k, size_t i, qd__imp_kind kind) {
    qd_con *c = &s->row[k];
    const qd_model *m = s->m;
    bool sudden = kind == QD__IMP_SUDDEN;
    c->name = sudden ? qd_model_impact_constraint_name(m, i) : qd_model_prescribed_name(m, i);
    c->expr = sudden ? qd_model_impact_constraint(m, i) : qd_model_prescribed(m, i);
    const qd_expr *E = sudden ? qd_model_impact_constraint_restitution(m, i) : NULL;
    s->E[k] = E ? E : qd_int(s->ctx, 0);
    if (!sudden && !has_any(c->expr, s->n, s->e->qd)) {
        qd_ctx_error(s->ctx, QD_ERR_ARG,
                     "prescription %s has no velocity in it: Thomson's problem prescribes "
                     "velocities", c->name);
        return QD_ERR_ARG;
    }
    return velocity_form(s, c, sudden ? "impact constraint" : "prescription");
}

static qd_status rows(qd__imp *s) {
    const qd_eom *e = s->e;
    s->nheld = e->ncon;
    s->nsudden = qd_model_nimpact_constraints(s->m);
    s->npre = qd_model_nprescribed(s->m);
    s->nrow = s->nheld + s->nsudden + s->npre;
    qd_status st = alloc_rows(s);
    for (size_t k = 0; st == QD_OK && k < s->nheld; k++) {
        const qd_expr **a = s->row[k].a;
        s->row[k] = e->con[k];
        s->row[k].a = a;
        memcpy(a, e->con[k].a, s->n * sizeof *a);
        s->E[k] = qd_int(s->ctx, 0);
    }
    for (size_t i = 0; st == QD_OK && i < s->nsudden; i++)
        st = model_row(s, s->nheld + i, i, QD__IMP_SUDDEN);
    for (size_t i = 0; st == QD_OK && i < s->npre; i++)
        st = model_row(s, s->nheld + s->nsudden + i, i, QD__IMP_PRESCRIBED);
    return st;
}

qd_status qd__imp_build(qd_ctx *ctx, const qd_model *m, qd__imp *s) {
    *s = (qd__imp){.ctx = ctx, .m = m, .nblows = qd_model_nblows(m)};
    if (!s->nblows && !qd_model_nimpact_constraints(m) && !qd_model_nprescribed(m)) {
        qd_ctx_error(ctx, QD_ERR_ARG,
                     "the model has no impulse: give a blow (impulse J at r, impulse G on "
                     "BODY, Qhat[q] = X), an impact constraint or a prescription");
        return QD_ERR_ARG;
    }
    s->e = qd_eom_derive(ctx, m);
    if (!s->e)
        return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    s->n = s->e->n;
    qd_status st = energy(s);
    return st == QD_OK ? rows(s) : st;
}

qd_eom qd__imp_view(const qd__imp *s) {
    return (qd_eom){.n = s->n, .q = s->e->q, .qd = s->e->qd, .qdd = s->e->qdd, .M = s->e->M,
                    .ncon = s->nrow, .con = s->row, .A = s->A, .L = s->e->L};
}
