/*
 * src/mech/integrals.c - cyclic coordinates, Jacobi's integral, the energy
 * and its balance, and the check of a proposed integral (qdot/integrals.h).
 *
 * dh/dt is formed with qd_dt (it then contains the accelerations) and
 * tested along the motion, not read off the theorem: the theorem's
 * right-hand side is computed separately and the two are compared, so a
 * wrong equation of motion would show as a remainder.
 *
 * With constraints the saddle-point accelerations hold at any state, but
 * the power of the constraint forces sum_j q'_j R_j is -sum_k lambda_k a0_k
 * only on the constraint manifold (A q' + a0 = 0).  The random states of
 * the zero test are not on it, so dh/dt is taken as
 * dh/dt - sum_k lambda_k (A_k q' + a0_k), which equals it on the manifold
 * and makes the balance with -sum_k lambda_k a0_k an identity everywhere.
 */
#include "integrals_priv.h"

#include <stdlib.h>

#include "mech.h"
#include "../base/mem.h"
#include "../base/args.h"

#define DEFAULT_MAX_OPS 4000

static const qd_expr *zero(qd_ctx *ctx) { return qd_int(ctx, 0); }

/* ---- setup ------------------------------------------------------------------ */

static qd_status sys_init(qd_ctx *ctx, const qd_model *m, qd_eom *e, const qd_integrals_opts *o,
                          qd__intsys *s) {
    *s = (qd__intsys){.m = m, .e = e, .n = e->n};
    if (e->nelim) {
        qd_ctx_error(ctx, QD_ERR_ARG, "first integrals of a model with eliminated coordinates "
                                      "are not supported: derive without elimination");
        return QD_ERR_ARG;
    }
    if (!e->L) {
        qd_ctx_error(ctx, QD_ERR_ARG, "first integrals need a Lagrangian");
        return QD_ERR_ARG;
    }
    s->L = qd_simplify(ctx, e->L);
    s->T = qd_model_lagrangian_given(m) ? NULL : qd_model_kinetic(m);
    s->V = qd_model_potential(m);
    s->U = qd_model_gen_potential(m);
    s->D = qd_model_dissipation(m);
    s->Q = qd__calloc(ctx, s->n ? s->n : 1, sizeof *s->Q);
    s->p = qd__calloc(ctx, s->n ? s->n : 1, sizeof *s->p);
    if (!s->Q || !s->p)
        return QD_ERR_NOMEM;
    for (size_t j = 0; j < s->n; j++) {
        const qd_expr *Q = qd_model_force(m, j);
        s->Q[j] = Q ? qd_simplify(ctx, Q) : zero(ctx);
        s->p[j] = qd_simplify(ctx, qd_diff(ctx, s->L, e->qd[j]));
    }
    if (qd_ctx_status(ctx) != QD_OK)
        return qd_ctx_status(ctx);
    size_t max_ops = o && o->max_ops ? o->max_ops : DEFAULT_MAX_OPS;
    if (!e->acc) {
        qd_status st = qd_eom_solve(ctx, e, max_ops);
        if (st == QD_ERR_TOOBIG)
            qd__ctx_recover(ctx);
        else if (st != QD_OK)
            return st;
    }
    s->solved = e->acc && (!e->ncon || e->mult);
    return QD_OK;
}

static void sys_free(qd__intsys *s) {
    if (!s)
        return;
    qd__free(s->Q);
    qd__free(s->p);
    qd__free(s);
}

/* ---- cyclic coordinates -------------------------------------------------- */

static bool dissipates(qd_ctx *ctx, const qd_expr *D, const qd_expr *qd) {
    if (!D)
        return false;
    const qd_expr *d = qd_simplify(ctx, qd_diff(ctx, D, qd));
    return d && !qd_is_zero(d);
}

static bool constrained(const qd_eom *e, size_t j) {
    for (size_t k = 0; k < e->ncon; k++)
        if (!qd_is_zero(e->A[k * e->n + j]))
            return true;
    return false;
}

/* L simplified; Q[j] simplified (NULL: 0); p[j] the momenta or NULL (then
 * computed). */
static void cyclic_list(qd_ctx *ctx, const qd_eom *e, const qd_expr *L, const qd_expr *const *Q,
                        const qd_expr *D, const qd_expr *const *p, qd_int_cyclic *out,
                        size_t *nc) {
    *nc = 0;
    for (size_t j = 0; j < e->n; j++) {
        if (qd_has(L, e->q[j]))
            continue;
        qd_int_cyclic *c = &out[(*nc)++];
        *c = (qd_int_cyclic){.coord = j};
        c->momentum = p ? p[j] : qd_simplify(ctx, qd_diff(ctx, L, e->qd[j]));
        if (Q[j] && !qd_is_zero(Q[j]))
            c->obstruction = "a generalized force acts on it";
        else if (dissipates(ctx, D, e->qd[j]))
            c->obstruction = "dissipation acts on it";
        else if (constrained(e, j))
            c->obstruction = "a constraint acts on it";
        c->conserved = !c->obstruction;
    }
}

static qd_status cyclic(qd_ctx *ctx, const qd__intsys *s, qd_integrals *I) {
    I->cyclic = qd__calloc(ctx, s->n ? s->n : 1, sizeof *I->cyclic);
    if (!I->cyclic)
        return QD_ERR_NOMEM;
    cyclic_list(ctx, s->e, s->L, s->Q, s->D, s->p, I->cyclic, &I->ncyclic);
    return qd_ctx_status(ctx);
}

qd_status qd_integrals_cyclic(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                              qd_int_cyclic *out, size_t *ncyclic) {
    QD_ARGS_CTX(ctx, ctx && m && e && out && ncyclic);
    if (!ctx || !m || !e || !out || !ncyclic)
        return QD_ERR_ARG;
    *ncyclic = 0;
    if (e->nelim || !e->L) {
        qd_ctx_error(ctx, QD_ERR_ARG, "cyclic coordinates need the model's own coordinates "
                                      "and a Lagrangian");
        return QD_ERR_ARG;
    }
    const qd_expr **Q = qd__calloc(ctx, e->n ? e->n : 1, sizeof *Q);
    if (!Q)
        return QD_ERR_NOMEM;
    for (size_t j = 0; j < e->n; j++) {
        const qd_expr *f = qd_model_force(m, j);
        Q[j] = f ? qd_simplify(ctx, f) : NULL;
    }
    const qd_expr *L = qd_simplify(ctx, e->L);
    if (L)
        cyclic_list(ctx, e, L, Q, qd_model_dissipation(m), NULL, out, ncyclic);
    qd__free(Q);
    return qd_ctx_status(ctx);
}

/* ---- Jacobi's integral and the energy ------------------------------------- */

/* sum_k lambda_k (A_k q' + a0_k): 0 on the constraint manifold. */
static const qd_expr *manifold_term(qd_ctx *ctx, const qd__intsys *s) {
    const qd_eom *e = s->e;
    const qd_expr *c = zero(ctx);
    for (size_t k = 0; k < e->ncon; k++) {
        const qd_expr *row = e->con[k].a0 ? e->con[k].a0 : zero(ctx);
        for (size_t j = 0; j < e->n; j++)
            row = qd_add(ctx, row, qd_mul(ctx, e->A[k * e->n + j], e->qd[j]));
        c = qd_add(ctx, c, qd_mul(ctx, e->con[k].lambda, row));
    }
    return c;
}

/* E = T + V + U0, U0 = U at zero velocities. */
static const qd_expr *energy(qd_ctx *ctx, const qd__intsys *s) {
    if (!s->T)
        return NULL;
    const qd_expr *E = qd_add(ctx, s->T, s->V ? s->V : zero(ctx));
    if (s->U) {
        const qd_expr **z = qd__malloc(ctx, (s->n ? s->n : 1) * sizeof *z);
        if (!z)
            return NULL;
        for (size_t j = 0; j < s->n; j++)
            z[j] = zero(ctx);
        E = qd_add(ctx, E, qd_subs(ctx, s->U, s->n, s->e->qd, z));
        qd__free(z);
    }
    return qd_simplify(ctx, E);
}

static bool nonzero(const qd_expr *x) { return x && !qd_is_zero(x); }

static const char *energy_reason(qd_ctx *ctx, const qd__intsys *s, bool equal) {
    const qd_eom *e = s->e;
    if (equal)
        return "T is homogeneous quadratic in the velocities and U at most linear in them, "
               "so sum_j q'_j dT/dq'_j = 2T (Euler) and h = T + V + U0";
    if (nonzero(e->T1) || nonzero(e->T0))
        return "T = T2 + T1 + T0 has parts of degree 1 and 0 in the velocities (moving "
               "coordinates): h = T2 - T0 + V + U0 while E = T2 + T1 + T0 + V + U0";
    if (s->U) {
        qd__vsum v;
        qd_status st = qd__mech_by_velocity(ctx, s->U, s->n, s->e->qd, &v);
        if (st != QD_OK || v.top > 1) {
            if (st != QD_OK)
                qd__ctx_recover(ctx);
            return "U is not at most linear in the velocities: its terms of degree k in them "
                   "enter h with the factor k - 1";
        }
    }
    return "h - (T + V + U0) does not vanish";
}

/* What keeps h from being conserved (when the test says it is not). */
static const char *spoiler(qd_ctx *ctx, const qd__intsys *s, bool explicit_t) {
    bool forces = false, moving = false;
    for (size_t j = 0; j < s->n; j++)
        forces |= !qd_is_zero(s->Q[j]);
    for (size_t k = 0; k < s->e->ncon; k++)
        moving |= nonzero(s->e->con[k].a0);
    const qd_expr *D = s->D ? qd_simplify(ctx, s->D) : NULL;
    bool dissipation = nonzero(D);
    if (explicit_t)
        return "L depends on t explicitly";
    if (moving)
        return "moving constraints (a0 != 0) do work";
    if (forces && dissipation)
        return "generalized forces and dissipation do work";
    if (forces)
        return "generalized forces do work";
    if (dissipation)
        return "dissipation does work";
    return "dh/dt does not vanish along the motion";
}

static qd_status jacobi(qd_ctx *ctx, const qd__intsys *s, qd_integrals *I) {
    qd_int_jacobi *J = &I->jacobi;
    const qd_eom *e = s->e;
    const qd_expr *t = qd_time(ctx), *h = qd_neg(ctx, s->L);
    for (size_t j = 0; j < s->n; j++)
        h = qd_add(ctx, h, qd_mul(ctx, e->qd[j], s->p[j]));
    J->h = qd_simplify(ctx, h);
    if (!J->h)
        return qd_ctx_status(ctx);
    J->explicit_t = qd_has(s->L, t);
    const qd_expr *X = qd_sub(ctx, qd_dt(ctx, J->h), manifold_term(ctx, s)), *shown;
    qd_status st = qd__mech_int_zero(ctx, s, X, &shown, &J->conserved, &J->numeric, &J->cert);
    if (st != QD_OK)
        return st;
    if (!J->conserved)
        J->not_conserved = spoiler(ctx, s, J->explicit_t);
    J->energy = energy(ctx, s);
    J->equals_energy = -1;
    J->reason = "the model gives L, not T and V";
    if (!J->energy)
        return qd_ctx_status(ctx);
    J->h_minus_E = qd_simplify(ctx, qd_sub(ctx, J->h, J->energy));
    bool eq, num;
    st = qd__mech_int_identically_zero(ctx, s, J->h_minus_E, &eq, &num);
    if (st != QD_OK)
        return st;
    J->equals_energy = eq;
    J->reason = energy_reason(ctx, s, eq);
    return qd_ctx_status(ctx);
}

/* ---- the energy balance -------------------------------------------------- */

static qd_status balance(qd_ctx *ctx, const qd__intsys *s, qd_integrals *I) {
    qd_int_balance *B = &I->balance;
    const qd_eom *e = s->e;
    const qd_expr *power = zero(ctx), *rate = zero(ctx), *cpower = zero(ctx);
    for (size_t j = 0; j < s->n; j++) {
        power = qd_add(ctx, power, qd_mul(ctx, s->Q[j], e->qd[j]));
        if (s->D)
            rate = qd_add(ctx, rate, qd_mul(ctx, e->qd[j], qd_diff(ctx, s->D, e->qd[j])));
    }
    for (size_t k = 0; k < e->ncon; k++)
        if (e->con[k].a0)
            cpower = qd_sub(ctx, cpower, qd_mul(ctx, e->con[k].lambda, e->con[k].a0));
    bool num;
    qd_status st = QD_OK;
    if (s->D) {
        st = qd__mech_int_identically_zero(
            ctx, s, qd_sub(ctx, rate, qd_mul(ctx, qd_int(ctx, 2), s->D)), &B->D_quadratic, &num);
        if (B->D_quadratic)
            rate = qd_mul(ctx, qd_int(ctx, 2), s->D);
    }
    if (st != QD_OK)
        return st;
    B->formula = s->D ? (B->D_quadratic ? "sum_j Q_j q'_j - 2D"
                                         : "sum_j Q_j q'_j - sum_j q'_j dD/dq'_j")
                      : "sum_j Q_j q'_j";
    const qd_expr *expected = qd_sub(ctx, power, rate);
    if (qd_has(s->L, qd_time(ctx))) {
        expected = qd_sub(ctx, expected, qd_diff(ctx, s->L, qd_time(ctx)));
        B->formula = s->D ? (B->D_quadratic ? "sum_j Q_j q'_j - 2D - dL/dt"
                                            : "sum_j Q_j q'_j - sum_j q'_j dD/dq'_j - dL/dt")
                          : "sum_j Q_j q'_j - dL/dt";
    }
    if (e->ncon) {
        expected = qd_add(ctx, expected, cpower);
        B->formula = "sum_j Q_j q'_j - sum_j q'_j dD/dq'_j - dL/dt - sum_k lambda_k a0_k";
    }
    B->expected = qd_simplify(ctx, expected);
    if (!B->expected)
        return qd_ctx_status(ctx);
    const qd_expr *dh = qd_sub(ctx, qd_dt(ctx, I->jacobi.h), manifold_term(ctx, s));
    st = qd__mech_int_zero(ctx, s, dh, &B->dhdt, &num, &num, NULL);
    if (st == QD_OK)
        st = qd__mech_int_zero(ctx, s, qd_sub(ctx, dh, B->expected), &B->remainder, &B->verified,
                          &B->numeric, NULL);
    /* Equal along the motion: the short form is the one to show. */
    if (st == QD_OK && B->verified && B->numeric) {
        B->dhdt = B->expected;
        B->remainder = qd_int(ctx, 0);
    }
    return st;
}

/* ---- proposed integrals ------------------------------------------------------ */

static qd_status along_motion_ok(qd_ctx *ctx, const qd__intsys *s, const char *what) {
    if (s->e->ncon) {
        qd_ctx_error(ctx, QD_ERR_ARG,
                     "%s with constraints is not supported: the test needs states on the "
                     "constraint manifold; write the model in independent coordinates", what);
        return QD_ERR_ARG;
    }
    return QD_OK;
}

static bool has_acceleration(const qd__intsys *s, const qd_expr *x) {
    for (size_t j = 0; j < s->n; j++)
        if (qd_has(x, s->e->qdd[j]))
            return true;
    return false;
}

qd_status qd_integrals_check(qd_ctx *ctx, qd_integrals *I, const char *name, const qd_expr *expr,
                             qd_int_proposed *out) {
    QD_ARGS_CTX(ctx, ctx && I && name && expr && out);
    if (!ctx || !I || !expr || !out)
        return QD_ERR_ARG;
    qd__intsys *s = I->priv;
    *out = (qd_int_proposed){.name = name};
    qd_status st = along_motion_ok(ctx, s, "checking a proposed integral");
    if (st != QD_OK)
        return st;
    out->expr = qd_simplify(ctx, expr);
    if (!out->expr)
        return qd_ctx_status(ctx);
    if (has_acceleration(s, out->expr)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "a proposed integral is a function of q, q' and t, "
                                      "without accelerations");
        return QD_ERR_ARG;
    }
    return qd__mech_int_zero(ctx, s, qd_dt(ctx, out->expr), &out->remainder, &out->conserved,
                        &out->numeric, &out->cert);
}

/* ---- derive ------------------------------------------------------------------ */

void qd_integrals_free(qd_integrals *I) {
    if (!I)
        return;
    for (size_t i = 0; i < I->nfound; i++)
        qd_noether_clear(&I->found[i]);
    qd__free(I->found);
    qd__free(I->tested);
    qd__free(I->cyclic);
    sys_free(I->priv);
    qd__free(I);
}

qd_integrals *qd_integrals_derive(qd_ctx *ctx, const qd_model *m, qd_eom *e,
                                  const qd_integrals_opts *opts) {
    QD_ARGS(NULL, ctx && m && e);
    if (!ctx || !m || !e)
        return NULL;
    qd_integrals *I = qd__calloc(ctx, 1, sizeof *I);
    qd__intsys *s = qd__calloc(ctx, 1, sizeof *s);
    if (!I || !s) {
        qd__free(I);
        qd__free(s);
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory finding first integrals");
        return NULL;
    }
    I->priv = s;
    qd_status st = sys_init(ctx, m, e, opts, s);
    if (st == QD_OK) {
        I->n = e->n;
        I->q = e->q;
        I->qd = e->qd;
        I->L = s->L;
        I->searched = opts && opts->search;
        I->constrained = e->ncon > 0;
        st = cyclic(ctx, s, I);
    }
    if (st == QD_OK)
        st = jacobi(ctx, s, I);
    if (st == QD_OK)
        st = balance(ctx, s, I);
    if (st == QD_OK && opts && opts->search && !e->ncon)
        st = qd__mech_int_search(ctx, I);
    if (st != QD_OK) {
        if (qd_ctx_status(ctx) == QD_OK)
            qd_ctx_error(ctx, st, "finding first integrals failed");
        qd_integrals_free(I);
        return NULL;
    }
    return I;
}
