/*
 * src/impulse/theorems.c - the energy theorems of impulsive motion,
 * verified on the case at hand (Byerly arts. 29-31; Desloge ch. 57; the
 * Britannica's "Dynamics" sec. 1 (30)).
 *
 * With M (q'+ - q'-) = Qhat + A^T Lambda and T = q'^T M q'/2 + p0 . q' + T0
 * at the frozen configuration:
 *
 *   Carnot: no blows, every row homogeneous (a0 = 0, E = 0) and p0 = 0:
 *     T- - T+ = (q'- - q'+)^T M (q'- - q'+)/2 + Lambda^T A q'+, and A q'+ = 0.
 *   Bertrand: the same hypotheses on the rows (blows allowed): the motion
 *     v without the sudden rows and u with them differ by M (v - u) =
 *     A^T mu, so T(v) - T(u) = (v - u)^T M (v - u)/2 + mu^T A u, and A u = 0.
 *   Thomson: the velocity change d = q'+ - q'- satisfies the KKT conditions
 *     of min d^T M d / 2 subject to the rows and to the struck points'
 *     components w_i . d (w_i the blow's generalized impulse), Qhat being
 *     sum_i w_i: the minimum is found independently and compared.
 *
 * "Holds" is verified to 1e-9 relative to the energies involved.
 */
#include "impulse_priv.h"

#include "base/mem.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define REL 1e-9

static bool close_to(double a, double b, double scale) {
    return fabs(a - b) <= REL * fmax(scale, DBL_MIN);
}

/* Every row homogeneous in the velocities, every restitution 0, and no
 * velocity-linear part in T. */
static bool homogeneous(const qd__imp *s) {
    double top = 0;
    for (size_t k = 0; k < s->nrow * s->n; k++)
        top = fmax(top, fabs(s->An[k]));
    for (size_t k = 0; k < s->nrow; k++)
        if (fabs(s->a0n[k]) > REL * fmax(top, DBL_MIN) || s->En[k] != 0)
            return false;
    double mtop = 0;
    for (size_t i = 0; i < s->n * s->n; i++)
        mtop = fmax(mtop, fabs(s->M[i]));
    for (size_t j = 0; j < s->n; j++)
        if (fabs(s->p0[j]) > REL * fmax(mtop, DBL_MIN))
            return false;
    return true;
}

static double change_energy(const qd__imp *s, const double *v1, const double *v0, double *d) {
    for (size_t j = 0; j < s->n; j++)
        d[j] = v1[j] - v0[j];
    return qd__imp_quad(s, d);
}

static void carnot(const qd__imp *s, qd_impulse *r, double *d) {
    qd_impulse_check *c = &r->carnot;
    c->applies = s->nsudden + s->npre > 0 && s->nblows == 0 && homogeneous(s);
    if (!c->applies)
        return;
    c->a = r->energy_lost;
    c->b = change_energy(s, r->qd_after, r->qd_before, d);
    c->holds = close_to(c->a, c->b, fabs(r->T_before) + fabs(r->T_after));
}

static qd_status bertrand(const qd__imp *s, qd_impulse *r, double *d) {
    qd_impulse_check *c = &r->bertrand;
    if (s->nsudden + s->npre == 0 || !homogeneous(s))
        return QD_OK;
    bool *use = qd__calloc(s->ctx, s->nrow + 1, sizeof *use);
    double *v = qd__malloc(s->ctx, (s->n + 1) * sizeof *v);
    qd_status st = use && v ? QD_OK : QD_ERR_NOMEM;
    for (size_t k = 0; k < s->nheld && st == QD_OK; k++)
        use[k] = true;
    if (st == QD_OK)
        st = qd__imp_solve(s, use, false, v, NULL, NULL);
    if (st == QD_ERR_SINGULAR) /* no motion without the sudden rows: nothing to compare */
        st = QD_OK;
    else if (st == QD_OK && (st = qd__imp_energy(s, v, &c->a)) == QD_OK) {
        c->applies = true;
        c->b = r->T_after;
        c->c = change_energy(s, v, r->qd_after, d);
        double scale = fabs(c->a) + fabs(c->b);
        c->holds = c->a >= c->b - REL * scale && close_to(c->a - c->b, c->c, scale);
    }
    qd__free(use);
    qd__free(v);
    return st;
}

/* Append row x (n) to B (m rows) unless it depends on them: Gram-Schmidt
 * against the orthonormal copies in Q.  Dependent rows say nothing new, the
 * actual change meeting them all. */
static bool append_row(size_t n, size_t *m, double *B, double *Q, const double *x) {
    double *q = Q + *m * n, norm0 = 0, norm = 0;
    memcpy(q, x, n * sizeof *q);
    for (size_t j = 0; j < n; j++)
        norm0 += x[j] * x[j];
    for (size_t i = 0; i < *m; i++) {
        double dot = 0;
        for (size_t j = 0; j < n; j++)
            dot += Q[i * n + j] * q[j];
        for (size_t j = 0; j < n; j++)
            q[j] -= dot * Q[i * n + j];
    }
    for (size_t j = 0; j < n; j++)
        norm += q[j] * q[j];
    if (!(norm > 1e-18 * norm0) || norm0 == 0)
        return false;
    for (size_t j = 0; j < n; j++)
        q[j] /= sqrt(norm);
    memcpy(B + *m * n, x, n * sizeof *B);
    ++*m;
    return true;
}

static qd_status thomson(const qd__imp *s, qd_impulse *r, double *d) {
    qd_impulse_check *c = &r->thomson;
    size_t n = s->n, rows = s->nrow + s->nblows, m = 0;
    if (s->nblows + s->npre == 0)
        return QD_OK;
    double *B = qd__malloc(s->ctx, (2 * rows * n + 2 * rows + 2 * n + 1) * sizeof *B);
    if (!B)
        return QD_ERR_NOMEM;
    double *Q = B + rows * n, *rhs = Q + rows * n, *x = rhs + rows, *zero = x + n;
    double a = change_energy(s, r->qd_after, r->qd_before, d);
    memset(zero, 0, (n + rows) * sizeof *zero);
    for (size_t k = 0; k < rows; k++) {
        const double *w = k < s->nrow ? s->An + k * n : s->W + (k - s->nrow) * n;
        double target = 0;
        for (size_t j = 0; j < n; j++)
            target += w[j] * d[j];
        if (append_row(n, &m, B, Q, w))
            rhs[m - 1] = target;
    }
    if (qd__imp_saddle(s->ctx, n, m, s->M, B, zero, rhs, x, NULL)) {
        c->applies = true;
        c->a = a;
        c->b = qd__imp_quad(s, x);
        c->holds = close_to(c->a, c->b, fabs(c->a) + fabs(c->b));
    }
    qd__free(B);
    return qd__ctx_nomem(s->ctx) ? QD_ERR_NOMEM : QD_OK;
}

qd_status qd__imp_theorems(const qd__imp *s, qd_impulse *r) {
    double *d = qd__malloc(s->ctx, (s->n + 1) * sizeof *d);
    if (!d)
        return QD_ERR_NOMEM;
    carnot(s, r, d);
    qd_status st = bertrand(s, r, d);
    if (st == QD_OK)
        st = thomson(s, r, d);
    qd__free(d);
    if (st == QD_ERR_NOMEM && !qd__ctx_nomem(s->ctx))
        qd_ctx_error(s->ctx, st, "out of memory checking the energy theorems");
    return st;
}
