/*
 * src/impulse/momenta.c - the impulse of a Lagrangian that is not quadratic
 * in the velocities (relativistic, L = -m c^2 sqrt(1 - v^2/c^2) - U: Desloge
 * ch. 92 Thm 1; reference seed-desloge-D.md C5, pitfall P13).  Integrating
 * Lagrange's equations over the impulse still leaves the jump of the
 * momenta (Desloge ch. 57 thm 1 with L for T),
 *
 *     P(q'+) - P(q'-) = Qhat + A^T Lambda,   A (q'+ - q'-) = r,
 *
 * P_j = dL/dq'_j at the frozen q, now nonlinear in q'+.  Newton's method on
 * (q'+, Lambda) with the exact Jacobian [H -A^T; A 0], H = d^2 L/dq' dq'
 * (the derivation's mass matrix, evaluated at the iterate), each step a
 * saddle solve; a step that leaves the domain of P (a speed beyond c) is
 * halved until it stays inside.
 */
#include "impulse_priv.h"

#include "base/mem.h"

#include <math.h>
#include <string.h>

#define MAX_NEWTON 60
#define MAX_HALVE 60
#define NEWTON_TOL 1e-14

/* P(v) (n) and, when H is not NULL, H(v) (n*n); false when not finite. */
static bool momenta_at(const qd__imp *s, const double *v, double *P, double *H, qd_status *st) {
    size_t n = s->n;
    for (size_t j = 0; j < n && *st == QD_OK; j++)
        *st = qd__imp_eval(s, s->P[j], v, &P[j]);
    for (size_t i = 0; H && i < n * n && *st == QD_OK; i++)
        *st = qd__imp_eval(s, s->e->M[i], v, &H[i]);
    if (*st != QD_OK) {
        if (*st != QD_ERR_NOMEM && qd__ctx_recover(s->ctx))
            *st = QD_OK; /* a domain error (sqrt of a negative) is "not finite" here */
        return false;
    }
    for (size_t j = 0; j < n; j++)
        if (!isfinite(P[j]))
            return false;
    for (size_t i = 0; H && i < n * n; i++)
        if (!isfinite(H[i]))
            return false;
    return true;
}

/* The residuals at (v, lam): R (n + m) and its size. */
static double residual(const qd__imp *s, const double *v, const double *lam, const double *P,
                       const double *P0, const double *r, double *R) {
    size_t n = s->n, m = s->nrow;
    const double *v0 = s->vals + n;
    double size = 0;
    for (size_t j = 0; j < n; j++) {
        R[j] = P[j] - P0[j] - s->Qhat[j];
        for (size_t k = 0; k < m; k++)
            R[j] -= s->An[k * n + j] * lam[k];
        size = fmax(size, fabs(R[j]) / (1 + fabs(P0[j]) + fabs(s->Qhat[j])));
    }
    for (size_t k = 0; k < m; k++) {
        R[n + k] = -r[k];
        for (size_t j = 0; j < n; j++)
            R[n + k] += s->An[k * n + j] * (v[j] - v0[j]);
        size = fmax(size, fabs(R[n + k]) / (1 + fabs(r[k])));
    }
    return size;
}

static qd_status fail(const qd__imp *s, qd_status st, const char *why) {
    if (st == QD_OK || st == QD_ERR_SINGULAR || st == QD_ERR_NUMERIC)
        qd_ctx_error(s->ctx, st == QD_OK ? QD_ERR_NUMERIC : st,
                     "the impulse of a Lagrangian beyond the square in the velocities: %s", why);
    return st == QD_OK ? QD_ERR_NUMERIC : st;
}

/* One damped Newton step from (v, lam); *size the residual after it. */
static qd_status step(const qd__imp *s, double *v, double *lam, double *w, const double *P0,
                      const double *r, double *size) {
    size_t n = s->n, m = s->nrow;
    double *P = w, *H = P + n, *R = H + n * n, *neg = R + n + m, *d = neg + n + m;
    double *vt = d + n + m;
    qd_status st = QD_OK;
    if (!momenta_at(s, v, P, H, &st))
        return fail(s, st, "the momenta are not finite at the iterate");
    residual(s, v, lam, P, P0, r, R);
    for (size_t i = 0; i < n + m; i++)
        neg[i] = -R[i];
    if (!qd__imp_saddle(s->ctx, n, m, H, s->An, neg, neg + n, d, d + n))
        return fail(s, qd__ctx_nomem(s->ctx) ? QD_ERR_NOMEM : QD_ERR_SINGULAR,
                    "the Jacobian [d2L/dq'dq', -A^T; A, 0] is singular at the iterate");
    for (int h = 0; h < MAX_HALVE; h++) {
        for (size_t j = 0; j < n; j++)
            vt[j] = v[j] + d[j];
        if (momenta_at(s, vt, P, NULL, &st))
            break;
        if (st != QD_OK)
            return st;
        for (size_t i = 0; i < n + m; i++)
            d[i] /= 2;
    }
    for (size_t j = 0; j < n; j++)
        v[j] += d[j];
    for (size_t k = 0; k < m; k++)
        lam[k] += d[n + k];
    *size = momenta_at(s, v, P, NULL, &st) ? residual(s, v, lam, P, P0, r, R) : INFINITY;
    return st;
}

qd_status qd__imp_solve_momenta(const qd__imp *s, double *v1, double *lambda) {
    size_t n = s->n, m = s->nrow;
    size_t len = 2 * n + m + (n + n * n + 3 * (n + m) + n) + 1;
    double *w = qd__calloc(s->ctx, len, sizeof *w);
    if (!w)
        return QD_ERR_NOMEM;
    double *P0 = w, *r = P0 + n, *lam = r + m, *work = lam + m;
    const double *v0 = s->vals + n;
    qd_status st = QD_OK;
    if (!momenta_at(s, v0, P0, NULL, &st))
        st = fail(s, st, "the momenta are not finite just before the impulse");
    for (size_t k = 0; k < m; k++)
        r[k] = qd__imp_rhs(s, k, v0);
    memcpy(v1, v0, n * sizeof *v1);
    double size = INFINITY;
    for (int it = 0; st == QD_OK && it < MAX_NEWTON && !(size <= NEWTON_TOL); it++)
        st = step(s, v1, lam, work, P0, r, &size);
    if (st == QD_OK && !(size <= 1e3 * NEWTON_TOL))
        st = fail(s, st, "Newton's method on the momentum map did not converge");
    for (size_t k = 0; st == QD_OK && lambda && k < m; k++)
        lambda[k] = lam[k];
    qd__free(w);
    return st;
}
