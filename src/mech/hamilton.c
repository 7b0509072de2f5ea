/*
 * src/mech/hamilton.c - the Legendre transform: momenta, velocities in
 * terms of the momenta, H and Hamilton's equations (qdot/hamilton.h).
 *
 * p = M q' + b is read off dL/dq' with qd_linear_coeffs (a Lagrangian that
 * is not quadratic in the velocities goes to legendre_family.c), and solved
 * block by block of M, by cofactors (legendre_blocks.c); H is then
 * (p - b)^T M^-1 (p - b) / 2 - L0 in closed form.
 */
#include "qdot/hamilton.h"
#include "legendre.h"
#include "mech.h"

#include <stdio.h>
#include <stdlib.h>

#include "qdot/print.h"
#include "../base/mem.h"
#include "../base/args.h"

static const qd_expr **arr(qd_ctx *ctx, size_t n) { return qd__calloc(ctx, n ? n : 1, sizeof(const qd_expr *)); }

void qd_ham_free(qd_ham *h) {
    if (!h)
        return;
    if (h->H_given)
        qd__free(h->q);
    qd__free(h->qd);
    qd__free(h->p);
    qd__free(h->pdef);
    qd__free(h->vel);
    qd__free(h->dq);
    qd__free(h->dp);
    qd__free(h->extra);
    qd__free(h);
}

static qd_ham *ham_alloc(qd_ctx *ctx, size_t n) {
    qd_ham *h = qd__calloc(ctx, 1, sizeof *h);
    if (!h)
        return NULL;
    h->n = n;
    h->p = arr(ctx, n);
    h->pdef = arr(ctx, n);
    h->vel = arr(ctx, n);
    h->dq = arr(ctx, n);
    h->dp = arr(ctx, n);
    h->extra = arr(ctx, n);
    h->qd = arr(ctx, n);
    if (!h->qd || !h->p || !h->pdef || !h->vel || !h->dq || !h->dp || !h->extra) {
        qd_ham_free(h);
        return NULL;
    }
    return h;
}

static qd_status momenta(qd_ctx *ctx, const qd_model *m, const qd_eom *e, qd_ham *h) {
    for (size_t j = 0; j < e->n; j++) {
        char name[256];
        snprintf(name, sizeof name, "%s_%s", h->second_kind ? "s" : "p", qd_expr_name(e->q[j]));
        h->qd[j] = e->qd[j];
        h->p[j] = qd_model_momentum(m, j) && !h->second_kind ? qd_model_momentum(m, j)
                                                               : qd_symbol(ctx, name);
        h->pdef[j] = qd_simplify(ctx, qd_diff(ctx, e->L, e->qd[j]));
        if (!h->p[j] || !h->pdef[j])
            return qd_ctx_status(ctx);
    }
    return QD_OK;
}

/* Row j of [M | p - b] from p_j = dL/dq'_j. */
static qd_status row(qd_ctx *ctx, const qd_eom *e, const qd_ham *h, size_t j, const qd_expr **A) {
    const qd_expr *b = NULL;
    qd_status st = qd_linear_coeffs(ctx, h->pdef[j], e->n, e->qd, A, &b);
    if (st != QD_OK)
        return st;
    A[e->n] = qd_sub(ctx, h->p[j], b);
    return A[e->n] ? QD_OK : qd_ctx_status(ctx);
}

/* L not quadratic in q' (legendre_family.c): a singular Hessian we can
 * name, else the closed form, else q' kept implicit. */
static qd_status nonquadratic(qd_ctx *ctx, const qd_eom *e, qd_ham *h, const char *stmt) {
    if (!qd__ctx_recover(ctx))
        return QD_ERR_NOMEM;
    qd_status st = qd__mech_legendre_singular(ctx, h->pdef, e->n, e->q, e->qd, stmt);
    if (st == QD_OK)
        st = qd__mech_legendre_family(ctx, e->L, e->n, e->qd, h->p, h->vel, &h->H);
    if (st != QD_ERR_NONLINEAR)
        return st;
    h->H = NULL;
    h->implicit = true;
    for (size_t j = 0; j < e->n; j++)
        h->vel[j] = e->qd[j];
    return QD_OK;
}

/* What a quadratic L leaves for H and the energy check: M (n x n, simplified)
 * and L0 = L at q' = 0, so that L = q'^T M q' / 2 + b.q' + L0 exactly. */
typedef struct quad {
    const qd_expr **M;
    const qd_expr *L0;
    const qd_expr **num, **den; /* q'_j = num_j / den_j (legendre.h, qd__quad_inv) */
} quad;

static const qd_expr *at_rest(qd_ctx *ctx, const qd_eom *e, const qd_expr *x) {
    const qd_expr **zero = arr(ctx, e->n);
    if (!zero)
        return NULL;
    for (size_t j = 0; j < e->n; j++)
        zero[j] = qd_int(ctx, 0);
    x = qd_subs(ctx, x, e->n, e->qd, zero);
    qd__free(zero);
    return x;
}

/* q' = M^-1 (p - b) block by block (legendre_blocks.c), and with it
 * H = (p - b)^T M^-1 (p - b) / 2 - L0: the Legendre transform of a quadratic
 * L in closed form (Goldstein sec. 8.1), never sum p q' - L with q'
 * substituted, whose cancellation is the expensive part. */
static qd_status velocities(qd_ctx *ctx, const qd_eom *e, qd_ham *h, const char *stmt, quad *qf) {
    size_t n = e->n;
    const qd_expr **A = arr(ctx, n * (n + 1)), **r = arr(ctx, n);
    qf->M = arr(ctx, n * n + 2 * n);
    if (qf->M) {
        qf->num = qf->M + n * n;
        qf->den = qf->num + n;
    }
    if (!A || !r || !qf->M) {
        qd__free(A);
        qd__free(r);
        return QD_ERR_NOMEM;
    }
    qd_status st = QD_OK;
    for (size_t j = 0; st == QD_OK && j < n; j++)
        st = row(ctx, e, h, j, A + j * (n + 1));
    for (size_t j = 0; st == QD_OK && j < n; j++) {
        r[j] = A[j * (n + 1) + n];
        for (size_t k = 0; k < n; k++)
            qf->M[j * n + k] = A[j * (n + 1) + k];
    }
    qd__free(A);
    const qd_expr *half = NULL;
    if (st == QD_OK)
        st = qd__mech_quad_inverse(ctx, n, qf->M, r, &(qd__quad_inv){h->vel, qf->num, qf->den},
                                   &half);
    qd__free(r);
    if (st == QD_ERR_NONLINEAR) {
        qd__free(qf->M);
        qf->M = NULL;
        return nonquadratic(ctx, e, h, stmt);
    }
    if (st == QD_ERR_SINGULAR && qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, st, "the mass matrix is singular: the momenta do not determine the "
                              "velocities");
    if (st != QD_OK)
        return st;
    qf->L0 = at_rest(ctx, e, e->L);
    h->H = qf->L0 ? qd_simplify(ctx, qd_sub(ctx, half, qf->L0)) : NULL;
    return h->H ? QD_OK : qd_ctx_status(ctx);
}

static const qd_expr *in_qp(qd_ctx *ctx, const qd_eom *e, const qd_ham *h, const qd_expr *x) {
    return qd_simplify(ctx, qd_subs(ctx, x, e->n, e->qd, h->vel));
}

static qd_status hamiltonian(qd_ctx *ctx, const qd_eom *e, qd_ham *h) {
    const qd_expr *s = qd_neg(ctx, e->L);
    for (size_t j = 0; j < e->n; j++)
        s = qd_add(ctx, s, qd_mul(ctx, h->p[j], e->qd[j]));
    h->H = in_qp(ctx, e, h, s);
    return h->H ? QD_OK : qd_ctx_status(ctx);
}

/* -dH/dq_j = dL/dq_j at q' = q'(q, p) for any Legendre transform (Goldstein
 * sec. 8.1), and for a quadratic L that is one quotient: with the blocks'
 * determinants D = prod d_k and q'_i = Y_i / D (Y_i = num_i D / d_i),
 * dL/dq_j = g2 + g1 + g0 by degree in q' gives
 * (g2(Y) + D g1(Y)) / D^2 + g0.  Its numerator is a polynomial, simplified
 * without a quotient to cancel: simplifying -dH/dq as it comes sums
 * quotients over D^2 term by term, a multivariate gcd for each (the
 * 4-link pendulum: 30 s for one equation). */
static const qd_expr *dp_quadratic(qd_ctx *ctx, const qd_eom *e, const quad *qf, size_t j,
                                   const qd_expr *extra) {
    size_t n = e->n;
    const qd_expr *D = qd_int(ctx, 1), **Y = arr(ctx, n);
    if (!Y)
        return NULL;
    for (size_t i = 0; i < n; i++) {
        size_t k = 0;
        while (k < i && qf->den[k] != qf->den[i])
            k++;
        if (k == i) /* a block's determinant, counted once */
            D = qd_mul(ctx, D, qf->den[i]);
    }
    for (size_t i = 0; i < n; i++)
        Y[i] = qd_mul(ctx, qf->num[i], qd_div(ctx, D, qf->den[i]));
    qd__vsum v;
    const qd_expr *g = qd_diff(ctx, e->L, e->q[j]), *r = NULL;
    if (g && qd__mech_by_velocity(ctx, g, n, e->qd, &v) == QD_OK && v.top <= 2) {
        const qd_expr *N = qd_add(ctx, qd_subs(ctx, v.deg[2], n, e->qd, Y),
                                  qd_mul(ctx, D, qd_subs(ctx, v.deg[1], n, e->qd, Y)));
        r = qd_add(ctx, qd_div(ctx, qd_simplify(ctx, N), qd_powi(ctx, D, 2)),
                   qd_simplify(ctx, qd_add(ctx, v.deg[0], extra)));
    }
    qd__free(Y);
    return r;
}

/* The force on q_j that L does not hold: Q_j - dD/dq'_j. */
static const qd_expr *force1(qd_ctx *ctx, const qd_model *m, const qd_eom *e, size_t j) {
    const qd_expr *D = qd_model_dissipation(m), *Q = qd_model_force(m, j);
    const qd_expr *x = Q ? Q : qd_int(ctx, 0);
    return D ? qd_sub(ctx, x, qd_diff(ctx, D, e->qd[j])) : x;
}

/* The force on q_j that T does not hold (Desloge ch. 72 eq. 1):
 * Q_j - dD/dq'_j - dV/dq_j + d/dt(dU/dq'_j) - dU/dq_j.  U's term may not
 * hold accelerations: U at most linear in the velocities. */
static const qd_expr *force2(qd_ctx *ctx, const qd_model *m, const qd_eom *e, size_t j) {
    const qd_expr *V = qd_model_potential(m), *U = qd_model_gen_potential(m);
    const qd_expr *x = force1(ctx, m, e, j);
    if (V)
        x = qd_sub(ctx, x, qd_diff(ctx, V, e->q[j]));
    if (!U)
        return x;
    const qd_expr *g = qd_simplify(ctx, qd_dt(ctx, qd_diff(ctx, U, e->qd[j])));
    for (size_t k = 0; g && k < e->n; k++)
        if (qd_has(g, e->qdd[k])) {
            qd_ctx_error(ctx, QD_ERR_NONLINEAR, "U is not linear in the velocities: its force "
                         "d/dt(dU/d%s') holds accelerations, so it is no force of the second "
                         "kind", qd_expr_name(e->q[j]));
            return NULL;
        }
    return qd_sub(ctx, qd_add(ctx, x, g), qd_diff(ctx, U, e->q[j]));
}

/* For a quadratic L, dH/dp = M^-1 (p - b) is the velocity solved above
 * (M symmetric, b and L0 free of p), so dq is vel itself; dp as
 * dp_quadratic has it.  The second kind: L is T and the forces force2's. */
static qd_status equations(qd_ctx *ctx, const qd_model *m, const qd_eom *e, qd_ham *h,
                           const quad *qf) {
    const qd_expr *D = qd_model_dissipation(m);
    h->conserved = !qd_has(h->H, qd_time(ctx)) && (h->second_kind || !D || qd_is_zero(D));
    for (size_t j = 0; j < e->n; j++) {
        const qd_expr *Q = qd_model_force(m, j);
        const qd_expr *x = h->second_kind ? force2(ctx, m, e, j) : force1(ctx, m, e, j);
        h->extra[j] = x ? in_qp(ctx, e, h, x) : NULL;
        h->conserved = h->conserved && (h->second_kind ? h->extra[j] && qd_is_zero(h->extra[j])
                                                       : !Q || qd_is_zero(Q));
        h->dq[j] = qf->M ? h->vel[j] : qd_simplify(ctx, qd_diff(ctx, h->H, h->p[j]));
        h->dp[j] = qf->M && h->extra[j] ? dp_quadratic(ctx, e, qf, j, h->extra[j]) : NULL;
        if (!h->dp[j] && qd_ctx_status(ctx) == QD_OK) /* not quadratic after all: as it comes */
            h->dp[j] = qd_simplify(ctx, qd_add(ctx, qd_neg(ctx, qd_diff(ctx, h->H, e->q[j])),
                                               h->extra[j]));
        if (!h->extra[j] || !h->dq[j] || !h->dp[j])
            return qd_ctx_status(ctx);
    }
    return QD_OK;
}

/* H - E in q and q' for a quadratic L: H(q, p(q, q')) = q'^T M q' / 2 - L0,
 * a polynomial in q' with no quotient to cancel. */
static const qd_expr *quad_minus(qd_ctx *ctx, const qd_eom *e, const quad *qf, const qd_expr *E) {
    size_t n = e->n;
    const qd_expr *s = qd_int(ctx, 0);
    for (size_t j = 0; j < n; j++)
        for (size_t k = 0; k < n; k++) {
            const qd_expr *c = qf->M[j < k ? j * n + k : k * n + j];
            s = qd_add(ctx, s, qd_mul_n(ctx, 3, (const qd_expr *[]){c, e->qd[j], e->qd[k]}));
        }
    s = qd_sub(ctx, qd_div(ctx, s, qd_int(ctx, 2)), qd_add(ctx, qf->L0, E));
    return qd_simplify(ctx, s);
}

/* H - (T + V + U0), U0 = U at q' = 0: for a quadratic L, found 0 in q and q'
 * before anything is substituted. */
static qd_status energy(qd_ctx *ctx, const qd_model *m, const qd_eom *e, qd_ham *h,
                        const quad *qf) {
    const qd_expr *T = qd_model_kinetic(m), *V = qd_model_potential(m), *U = qd_model_gen_potential(m);
    if (!T || qd_model_lagrangian_given(m))
        return QD_OK;
    const qd_expr *E = h->second_kind ? T : qd_add(ctx, T, V ? V : qd_int(ctx, 0));
    if (U && !h->second_kind)
        E = qd_add(ctx, E, at_rest(ctx, e, U));
    const qd_expr *d = qf->M ? quad_minus(ctx, e, qf, E) : NULL;
    if (d && qd_is_zero(d))
        h->H_minus_E = d;
    else if (d)
        h->H_minus_E = in_qp(ctx, e, h, d);
    else
        h->H_minus_E = qd_simplify(ctx, qd_sub(ctx, h->H, qd_subs(ctx, E, e->n, e->qd, h->vel)));
    if (!h->H_minus_E)
        return qd_ctx_status(ctx);
    h->is_energy = qd_is_zero(h->H_minus_E);
    return QD_OK;
}

static qd_status derive(qd_ctx *ctx, const qd_model *m, const qd_eom *e, qd_ham *h) {
    quad qf = {NULL, NULL, NULL, NULL};
    qd_status st = momenta(ctx, m, e, h);
    if (st == QD_OK)
        st = velocities(ctx, e, h, qd_model_lagrangian_given(m) ? "L" : "T", &qf);
    if (st == QD_OK && !h->H) /* the closed forms of legendre_family.c come with H */
        st = hamiltonian(ctx, e, h);
    if (st == QD_OK)
        st = equations(ctx, m, e, h, &qf);
    if (st == QD_OK)
        st = energy(ctx, m, e, h, &qf);
    qd__free(qf.M);
    return st;
}

qd_ham *qd_ham_derive(qd_ctx *ctx, const qd_model *m, const qd_eom *e) {
    QD_ARGS(NULL, ctx && m);
    if (!ctx || !m || (!e && !qd_model_hamiltonian_given(m)))
        return NULL;
    if (qd_model_hamiltonian_given(m)) {
        qd_ham *h = ham_alloc(ctx, qd_model_ncoords(m));
        if (!h) {
            qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory forming the Hamiltonian");
            return NULL;
        }
        h->H_given = true;
        if (qd__mech_ham_from_H(ctx, m, h) != QD_OK) {
            qd_ham_free(h);
            return NULL;
        }
        return h;
    }
    if (e->ncon || e->nelim) {
        qd_ctx_error(ctx, QD_ERR_ARG, "Hamilton's equations with constraints are not supported yet");
        return NULL;
    }
    qd_ham *h = ham_alloc(ctx, e->n);
    if (!h) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory forming the Hamiltonian");
        return NULL;
    }
    h->q = e->q;
    qd_status st = derive(ctx, m, e, h);
    if (st != QD_OK) {
        if (qd_ctx_status(ctx) == QD_OK)
            qd_ctx_error(ctx, st, "forming the Hamiltonian failed");
        qd_ham_free(h);
        return NULL;
    }
    return h;
}

/* s = p (Desloge ch. 72 eq. 6): dT/dq'_j - dL/dq'_j simplifies to 0 for
 * every j. */
static bool s_is_p(qd_ctx *ctx, const qd_eom *e, const qd_ham *h) {
    for (size_t j = 0; j < e->n; j++) {
        const qd_expr *d = qd_simplify(ctx, qd_sub(ctx, qd_diff(ctx, e->L, e->qd[j]), h->pdef[j]));
        if (!d || !qd_is_zero(d))
            return false;
    }
    return true;
}

/* Why m has no equations of the second kind (Desloge ch. 72 Thm 1 needs T
 * and no constraints), or QD_OK. */
static qd_status second_kind_refused(qd_ctx *ctx, const qd_model *m, const qd_eom *e) {
    const char *why = NULL;
    if (qd_model_hamiltonian_given(m) || qd_model_lagrangian_given(m) || !qd_model_kinetic(m))
        why = qd_model_hamiltonian_given(m) ? "H" : "L";
    if (why) {
        qd_ctx_error(ctx, QD_ERR_ARG, "Hamilton's equations of the second kind are built from "
                     "the kinetic energy T (Desloge ch. 72), and the model gives %s: give T = ... "
                     "with V = ..., forces or dissipation", why);
        return QD_ERR_ARG;
    }
    if (!e) {
        qd_ctx_error(ctx, QD_ERR_ARG, "qd_ham2_derive: no equations of motion (e is NULL)");
        return QD_ERR_ARG;
    }
    if (e->ncon || e->nelim) {
        qd_ctx_error(ctx, QD_ERR_ARG, "Hamilton's equations of the second kind with constraints "
                                      "are not supported yet");
        return QD_ERR_ARG;
    }
    return QD_OK;
}

qd_ham *qd_ham2_derive(qd_ctx *ctx, const qd_model *m, const qd_eom *e) {
    QD_ARGS(NULL, ctx && m);
    if (second_kind_refused(ctx, m, e) != QD_OK)
        return NULL;
    qd_ham *h = ham_alloc(ctx, e->n);
    if (!h) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory forming K");
        return NULL;
    }
    qd_eom et = *e; /* the Legendre transform of T in place of L */
    et.L = qd_model_kinetic(m);
    h->q = e->q;
    h->second_kind = true;
    qd_status st = derive(ctx, m, &et, h);
    if (st == QD_OK)
        h->s_is_p = s_is_p(ctx, e, h);
    if (st != QD_OK || qd_ctx_status(ctx) != QD_OK) {
        if (qd_ctx_status(ctx) == QD_OK)
            qd_ctx_error(ctx, st, "forming K failed");
        qd_ham_free(h);
        return NULL;
    }
    return h;
}
