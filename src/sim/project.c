/*
 * src/sim/project.c - keeping a constrained motion on its constraints.
 *
 * The index-reduced equations (each holonomic constraint differentiated
 * twice, qdot/mech.h) keep phi'' = 0 but not phi = 0: round-off and
 * truncation drift off the constraint manifold.  After each step the
 * positions are projected back onto phi(q, t) = 0 by Gauss-Newton with the
 * constraint Jacobian A (minimum-norm correction dq = -A^T (A A^T)^-1 phi,
 * Hairer, Lubich & Wanner, GNI sec. IV.4), then the velocities onto
 * A q' + a0 = 0, which is linear: one correction is exact.
 */
#include "simint.h"

#include <math.h>
#include <string.h>

#include "num/num.h"

#define MAX_ITER 30

/* Rows `use` of A (m*n): (A A^T) mu = r in place of r; false when singular. */
static bool normal_solve(qd_sim *s, const double *A, const bool *use, double *r) {
    size_t n = s->n, m = s->m;
    double *G = s->K;
    for (size_t i = 0; i < m; i++)
        for (size_t k = 0; k < m; k++) {
            double v = 0;
            for (size_t j = 0; j < n; j++)
                v += A[i * n + j] * A[k * n + j];
            bool on = (!use || (use[i] && use[k]));
            G[i * m + k] = on ? v : (i == k ? 1 : 0);
        }
    for (size_t i = 0; use && i < m; i++)
        if (!use[i])
            r[i] = 0;
    return qd__num_rank(m, G, r, 1e-13 * (double)m, s->pc, NULL, NULL) == m;
}

static qd_status fail(qd_sim *s, double t, const char *what, double res) {
    size_t worst = 0;
    double top = -1;
    const double *g = s->con_out + s->m * s->n + s->m;
    for (size_t k = 0; k < s->m; k++)
        if (s->holonomic[k] && fabs(g[k]) > top) {
            top = fabs(g[k]);
            worst = k;
        }
    qd__sim_stop(s, QD_STOP_PROJECTION, t, res);
    qd_ctx_error(s->ctx, QD_ERR_NUMERIC,
                 "constraint %s cannot be satisfied at t = %.17g: the projection onto the "
                 "constraints %s (residual %.3g)", s->cons[worst].name, t, what, res);
    return QD_ERR_NUMERIC;
}

qd_status qd__sim_project(qd_sim *s, double t, double *q, double *qd) {
    size_t n = s->n, m = s->m;
    if (!m)
        return QD_OK;
    const double *A = s->con_out, *a0 = A + m * n, *g = a0 + m;
    double *mu = s->rhs, prev = INFINITY;
    bool any = false;
    for (size_t k = 0; k < m; k++)
        any = any || s->holonomic[k];
    for (int iter = 0; any; iter++) {
        qd__sim_con_eval(s, t, q, qd);
        double res = 0, scale = 1;
        for (size_t k = 0; k < m; k++)
            if (s->holonomic[k])
                res = fmax(res, fabs(g[k]));
        for (size_t j = 0; j < n; j++)
            scale = fmax(scale, fabs(q[j]));
        if (!isfinite(res))
            return fail(s, t, "met a non-finite residual", res);
        if (res <= 4e-16 * scale || (res >= prev && res < 1e-11))
            break;
        if (iter == MAX_ITER)
            return fail(s, t, "does not converge", res);
        prev = res;
        for (size_t k = 0; k < m; k++)
            mu[k] = g[k];
        if (!normal_solve(s, A, s->holonomic, mu))
            return fail(s, t, "meets a rank-deficient constraint Jacobian", res);
        for (size_t j = 0; j < n; j++)
            for (size_t k = 0; k < m; k++)
                if (s->holonomic[k])
                    q[j] -= A[k * n + j] * mu[k];
    }
    qd__sim_con_eval(s, t, q, qd);
    for (size_t k = 0; k < m; k++) {
        double v = a0[k];
        for (size_t j = 0; j < n; j++)
            v += A[k * n + j] * qd[j];
        mu[k] = v;
    }
    /* a slipping friction contact's rows do not hold (friction.c) */
    if (!normal_solve(s, A, s->fr ? s->fr->on : NULL, mu))
        return fail(s, t, "meets a rank-deficient constraint Jacobian", 0);
    for (size_t j = 0; j < n; j++)
        for (size_t k = 0; k < m; k++)
            qd[j] -= A[k * n + j] * mu[k];
    return QD_OK;
}
