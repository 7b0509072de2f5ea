/*
 * src/mech/legendre.c - models given by their Hamiltonian: Hamilton's
 * equations straight from H, and the inverse Legendre transform back to L
 * (Desloge ch. 71 eqs. 7b-8b, Appendix 22).
 *
 *     q'_j = dH/dp_j(q, p, t)               solved for p
 *     L(q, q', t) = sum_j p_j q'_j - H      (p substituted)
 *
 * When H is quadratic in p, dH/dp = W p + c is linear (W = d^2H/dp dp) and
 * the solve is exact elimination; H = F(p^T W p) + b.p + H0 is inverted as
 * legendre_family.c inverts L (the relativistic particle); otherwise there
 * is no closed form and the answer is QD_ERR_NONLINEAR.  A singular W (H = p_x: q' = 1 says
 * nothing about p_x) means H is not regular and has no Lagrangian at all,
 * though Hamilton's equations are still fine: qd_ham_derive keeps them and
 * only leaves L_from_H empty.
 */
#include "legendre.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const qd_expr **arr(qd_ctx *ctx, size_t n) { return qd__calloc(ctx, n ? n : 1, sizeof(const qd_expr *)); }

qd_status qd__mech_gauss_solve(qd_ctx *ctx, size_t n, const qd_expr **A, const qd_expr **x,
                          size_t *bad) {
    size_t w = n + 1;
    for (size_t k = 0; k < n; k++) {
        size_t piv = k;
        while (piv < n && qd_is_zero(A[piv * w + k] = qd_simplify(ctx, A[piv * w + k])))
            piv++;
        if (qd_ctx_status(ctx) != QD_OK)
            return qd_ctx_status(ctx);
        if (piv == n) {
            *bad = k;
            return QD_ERR_SINGULAR;
        }
        for (size_t c = 0; piv != k && c < w; c++) {
            const qd_expr *t = A[k * w + c];
            A[k * w + c] = A[piv * w + c];
            A[piv * w + c] = t;
        }
        for (size_t r = k + 1; r < n; r++) {
            const qd_expr *f = qd_div(ctx, A[r * w + k], A[k * w + k]);
            for (size_t c = k; c < w; c++)
                A[r * w + c] = qd_sub(ctx, A[r * w + c], qd_mul(ctx, f, A[k * w + c]));
        }
        if (qd_ctx_status(ctx) != QD_OK)
            return qd_ctx_status(ctx);
    }
    for (size_t k = n; k-- > 0;) {
        const qd_expr *s = A[k * w + n];
        for (size_t c = k + 1; c < n; c++)
            s = qd_sub(ctx, s, qd_mul(ctx, A[k * w + c], x[c]));
        x[k] = qd_simplify(ctx, qd_div(ctx, s, A[k * w + k]));
        if (!x[k])
            return qd_ctx_status(ctx);
    }
    return QD_OK;
}

typedef struct hsys {
    size_t n;
    const qd_expr **q, **qd, **p;
} hsys;

static qd_status hsys_init(qd_ctx *ctx, const qd_model *m, hsys *s) {
    s->n = qd_model_ncoords(m);
    s->q = arr(ctx, s->n);
    s->qd = arr(ctx, s->n);
    s->p = arr(ctx, s->n);
    if (!s->q || !s->qd || !s->p) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        return QD_ERR_NOMEM;
    }
    for (size_t j = 0; j < s->n; j++) {
        s->q[j] = qd_model_coord(m, j);
        s->qd[j] = qd_jet(ctx, s->q[j], 1);
        s->p[j] = qd_model_momentum(m, j);
        if (!s->qd[j] || !s->p[j])
            return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_ARG;
    }
    return QD_OK;
}

static void hsys_free(hsys *s) {
    qd__free(s->q);
    qd__free(s->qd);
    qd__free(s->p);
}

static void not_quadratic(qd_ctx *ctx, const hsys *s, size_t j) {
    qd_ctx_error(ctx, QD_ERR_NONLINEAR, "H is not quadratic in the momenta: dH/d%s is not linear "
                 "in them, and H is not F(p^T W p) + b.p + H0 with q' = dH/dp solvable in closed "
                 "form, so there is no closed-form Lagrangian", qd_expr_name(s->p[j]));
    qd_ctx_error_about(ctx, QD_SUBJECT_STATEMENT, j, "H", QD_REASON_NOT_QUADRATIC,
                       "the equations of motion need the Lagrangian, which needs q' = dH/dp "
                       "solved for p; Hamilton's equations are still given by "
                       "`qdot hamiltonian`");
}

/* Row j of [W | q'_j - c_j] from q'_j = dH/dp_j = sum_k W_jk p_k + c_j;
 * QD_ERR_NONLINEAR with no message when dH/dp_j is not linear. */
static qd_status row(qd_ctx *ctx, const hsys *s, const qd_expr *H, size_t j, const qd_expr **A) {
    const qd_expr *c = NULL, *v = qd_simplify(ctx, qd_diff(ctx, H, s->p[j]));
    if (!v)
        return qd_ctx_status(ctx);
    qd_status st = qd_linear_coeffs(ctx, v, s->n, s->p, A, &c);
    if (st == QD_ERR_NONLINEAR)
        return qd__ctx_recover(ctx) ? st : QD_ERR_NOMEM;
    if (st != QD_OK)
        return st;
    A[s->n] = qd_sub(ctx, s->qd[j], c);
    return A[s->n] ? QD_OK : qd_ctx_status(ctx);
}

/* H not quadratic in p: the same family as for L, read the other way
 * (legendre_family.c with the roles of q' and p exchanged: H =
 * sqrt(m^2 c^4 + c^2 p^2) + V gives L = -m c^2 sqrt(1 - q'^2/c^2) - V). */
static qd_status inverse_family(qd_ctx *ctx, const hsys *s, const qd_expr *H, size_t j,
                                const qd_expr **pdef, const qd_expr **L) {
    qd_status st = qd__mech_legendre_family(ctx, H, s->n, s->p, s->qd, pdef, L);
    if (st == QD_ERR_NONLINEAR)
        not_quadratic(ctx, s, j);
    return st;
}

static qd_status inverse(qd_ctx *ctx, const qd_model *m, const hsys *s, const qd_expr **pdef,
                         const qd_expr **L) {
    const qd_expr *H = qd_model_hamiltonian(m);
    size_t n = s->n, bad = 0;
    const qd_expr **A = arr(ctx, n * (n + 1));
    if (!A) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        return QD_ERR_NOMEM;
    }
    qd_status st = QD_OK;
    size_t j = 0;
    for (; st == QD_OK && j < n; j++)
        st = row(ctx, s, H, j, A + j * (n + 1));
    if (st == QD_OK)
        st = qd__mech_gauss_solve(ctx, n, A, pdef, &bad);
    else if (st == QD_ERR_NONLINEAR) {
        qd__free(A);
        return inverse_family(ctx, s, H, j - 1, pdef, L);
    }
    qd__free(A);
    if (st == QD_ERR_SINGULAR && qd_ctx_status(ctx) == QD_OK) {
        qd_ctx_error(ctx, st, "d^2H/dp^2 is singular (H is not regular): q' = dH/dp does not "
                              "determine %s, so H has no Lagrangian", qd_expr_name(s->p[bad]));
        qd_ctx_error_about(ctx, QD_SUBJECT_STATEMENT, bad, "H", QD_REASON_SINGULAR_MASS,
                           "a Lagrangian needs H quadratic in the momenta with d^2H/dp^2 "
                           "invertible; Hamilton's equations are still given by "
                           "`qdot hamiltonian`");
    }
    if (st != QD_OK)
        return st;
    const qd_expr *sum = qd_neg(ctx, H);
    for (size_t i = 0; i < n; i++)
        sum = qd_add(ctx, sum, qd_mul(ctx, s->p[i], s->qd[i]));
    *L = qd_simplify(ctx, qd_subs(ctx, sum, n, s->p, pdef));
    return *L ? QD_OK : qd_ctx_status(ctx);
}

qd_status qd_legendre_inverse_p(qd_ctx *ctx, const qd_model *m, const qd_expr **pdef,
                                const qd_expr **L) {
    QD_ARGS_CTX(ctx, ctx && m && L);
    if (!ctx || !m || !L)
        return QD_ERR_ARG;
    *L = NULL;
    if (!qd_model_hamiltonian_given(m)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the inverse Legendre transform needs a model given by H");
        return QD_ERR_ARG;
    }
    hsys s = {0};
    qd_status st = hsys_init(ctx, m, &s);
    const qd_expr **p = pdef ? pdef : arr(ctx, s.n);
    if (st == QD_OK && !p) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        st = QD_ERR_NOMEM;
    }
    if (st == QD_OK)
        st = inverse(ctx, m, &s, p, L);
    if (p != pdef)
        qd__free(p);
    hsys_free(&s);
    return st;
}

const qd_expr *qd_legendre_inverse(qd_ctx *ctx, const qd_model *m) {
    QD_ARGS(NULL, ctx && m);
    const qd_expr *L = NULL;
    return qd_legendre_inverse_p(ctx, m, NULL, &L) == QD_OK ? L : NULL;
}

/* The velocities, forces and equations straight from H. */
static qd_status equations(qd_ctx *ctx, const qd_model *m, const hsys *s, qd_ham *h) {
    const qd_expr *D = qd_model_dissipation(m);
    h->conserved = !qd_has(h->H, qd_time(ctx)) && (!D || qd_is_zero(D));
    for (size_t j = 0; j < s->n; j++) {
        h->vel[j] = h->dq[j] = qd_simplify(ctx, qd_diff(ctx, h->H, s->p[j]));
        if (!h->vel[j])
            return qd_ctx_status(ctx);
    }
    for (size_t j = 0; j < s->n; j++) {
        const qd_expr *Q = qd_model_force(m, j), *x = Q ? Q : qd_int(ctx, 0);
        if (D)
            x = qd_sub(ctx, x, qd_diff(ctx, D, s->qd[j]));
        h->conserved = h->conserved && (!Q || qd_is_zero(Q));
        h->extra[j] = qd_simplify(ctx, qd_subs(ctx, x, s->n, s->qd, h->vel));
        h->dp[j] = qd_simplify(ctx, qd_add(ctx, qd_neg(ctx, qd_diff(ctx, h->H, s->q[j])),
                                           h->extra[j]));
        if (!h->extra[j] || !h->dp[j])
            return qd_ctx_status(ctx);
    }
    return QD_OK;
}

qd_status qd__mech_ham_from_H(qd_ctx *ctx, const qd_model *m, qd_ham *h) {
    if (qd_model_nconstraints(m)) {
        qd_ctx_error(ctx, QD_ERR_ARG,
                     "Hamilton's equations with constraints are not supported yet");
        return QD_ERR_ARG;
    }
    hsys s = {0};
    qd_status st = hsys_init(ctx, m, &s);
    h->q = s.q; /* h owns the coordinates' array (H_given) */
    if (st == QD_OK) {
        for (size_t j = 0; j < s.n; j++) {
            h->qd[j] = s.qd[j];
            h->p[j] = s.p[j];
        }
        h->H = qd_simplify(ctx, qd_model_hamiltonian(m));
        st = h->H ? equations(ctx, m, &s, h) : qd_ctx_status(ctx);
    }
    if (st == QD_OK) {
        /* Hamilton's equations stand without L: a singular or non-quadratic
         * H only leaves L_from_H empty, with the reason. */
        st = inverse(ctx, m, &s, h->pdef, &h->L_from_H);
        if (st == QD_ERR_SINGULAR || st == QD_ERR_NONLINEAR) {
            snprintf(h->L_why, sizeof h->L_why, "%s", qd_ctx_message(ctx));
            qd__ctx_recover(ctx);
            h->L_from_H = NULL;
            for (size_t j = 0; j < s.n; j++)
                h->pdef[j] = NULL;
            st = QD_OK;
        }
    }
    s.q = NULL;
    hsys_free(&s);
    if (st != QD_OK && qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, st, "forming Hamilton's equations from H failed");
    return st;
}
