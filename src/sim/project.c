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
#include "../base/mem.h"

#define MAX_ITER 30

/* Rows `use` of A (m*n), without the columns kept (may be NULL):
 * (A A^T) mu = r in place of r; false when singular. */
static bool normal_solve_kept(qd_sim *s, const double *A, const bool *use, const bool *kept,
                              double *r) {
    size_t n = s->n, m = s->m;
    double *G = s->K;
    for (size_t i = 0; i < m; i++)
        for (size_t k = 0; k < m; k++) {
            double v = 0;
            for (size_t j = 0; j < n; j++)
                v += kept && kept[j] ? 0 : A[i * n + j] * A[k * n + j];
            bool on = (!use || (use[i] && use[k]));
            G[i * m + k] = on ? v : (i == k ? 1 : 0);
        }
    for (size_t i = 0; use && i < m; i++)
        if (!use[i])
            r[i] = 0;
    return qd__num_rank(m, G, r, 1e-13 * (double)m, s->pc, NULL, NULL) == m;
}

static bool normal_solve(qd_sim *s, const double *A, const bool *use, double *r) {
    return normal_solve_kept(s, A, use, NULL, r);
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

/* q onto phi(q, t) = 0 (the holonomic rows), then the constraints
 * evaluated at (q, qd). */
static qd_status project_q(qd_sim *s, double t, double *q, double *qd) {
    size_t n = s->n, m = s->m;
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
    return QD_OK;
}

qd_status qd__sim_project(qd_sim *s, double t, double *q, double *qd) {
    size_t n = s->n, m = s->m;
    if (!m)
        return QD_OK;
    qd_status st = project_q(s, t, q, qd);
    if (st != QD_OK)
        return st;
    const double *A = s->con_out, *a0 = A + m * n;
    double *mu = s->rhs;
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

/* |A_k q' + a0_k| and the size it is judged against: the terms' own. */
static double row_residual(const qd_sim *s, size_t k, const double *qd, double *size) {
    size_t n = s->n;
    const double *A = s->con_out, *a0 = A + s->m * n;
    double v = a0[k], big = fabs(a0[k]);
    for (size_t j = 0; j < n; j++) {
        v += A[k * n + j] * qd[j];
        big = fmax(big, fabs(A[k * n + j] * qd[j]));
    }
    *size = big;
    return fabs(v);
}

static qd_status given_violate(qd_sim *s, double t, size_t k, double res) {
    qd__sim_stop(s, QD_STOP_REFUSED, t, res);
    qd_ctx_error(s->ctx, QD_ERR_ARG,
                 "the initial velocities given violate constraint %s by %.3g, which the "
                 "velocities not given cannot make up: give fewer velocities (those not given "
                 "are solved from the constraints)", s->cons[k].name, res);
    qd_ctx_error_about(s->ctx, QD_SUBJECT_NONE, 0, "initial", QD_REASON_NONE, NULL);
    return QD_ERR_ARG;
}

/* A q' + a0 of row k at qd, signed. */
static double row_value(const qd_sim *s, size_t k, const double *qd) {
    size_t n = s->n;
    const double *A = s->con_out, *a0 = A + s->m * n;
    double v = a0[k];
    for (size_t j = 0; j < n; j++)
        v += A[k * n + j] * qd[j];
    return v;
}

/* The rows the free velocities can satisfy together: each row in turn,
 * kept when the free columns' normal matrix stays regular with it (a row
 * no free velocity enters, or one the others already fix, is left out and
 * must then hold by itself). */
static void free_rows(qd_sim *s, const bool *given, bool *use) {
    double *r = s->tmp;
    for (size_t k = 0; k < s->m; k++) {
        use[k] = !s->fr || s->fr->on[k]; /* a slipping contact's row does not hold */
        if (!use[k])
            continue;
        for (size_t i = 0; i < s->m; i++)
            r[i] = 0;
        use[k] = normal_solve_kept(s, s->con_out, use, given, r);
    }
}

/* The start: q onto the holonomic constraints, then the velocities not
 * given by the least change that keeps A q' + a0 = 0 with the given ones
 * fixed: dq'_F = -A_F^T (A_F A_F^T)^-1 r over the free columns F (the
 * projection restricted to them), on the rows they can satisfy; a row left
 * over must hold, else the velocities given are refused, naming it.  The
 * velocities that moved are the ones solved (s->solved). */
qd_status qd__sim_project_start(qd_sim *s, double t, double *q, double *qd, const bool *given) {
    size_t n = s->n, m = s->m;
    bool any = false;
    for (size_t j = 0; given && j < n; j++)
        any = any || given[j];
    for (size_t j = 0; j < n; j++)
        s->solved[j] = false;
    if (!any || !m)
        return qd__sim_project(s, t, q, qd);
    qd_status st = project_q(s, t, q, qd);
    if (st != QD_OK)
        return st;
    const double *A = s->con_out;
    bool *use = qd__calloc(s->ctx, m + 1, sizeof *use);
    double *old = qd__malloc(s->ctx, (n + 1) * sizeof *old), *mu = s->rhs;
    if (!use || !old) {
        qd__free(use);
        qd__free(old);
        return QD_ERR_NOMEM;
    }
    memcpy(old, qd, n * sizeof *qd);
    free_rows(s, given, use);
    for (size_t k = 0; k < m; k++)
        mu[k] = use[k] ? row_value(s, k, qd) : 0;
    if (!normal_solve_kept(s, A, use, given, mu))
        st = fail(s, t, "meets a rank-deficient constraint Jacobian", 0);
    for (size_t j = 0; st == QD_OK && j < n; j++)
        for (size_t k = 0; !given[j] && k < m; k++)
            qd[j] -= use[k] ? A[k * n + j] * mu[k] : 0;
    for (size_t k = 0; st == QD_OK && k < m; k++) {
        double size, res = row_residual(s, k, qd, &size);
        if ((!s->fr || s->fr->on[k]) && res > 1e-10 * fmax(size, 1))
            st = given_violate(s, t, k, res);
    }
    for (size_t j = 0; st == QD_OK && j < n; j++)
        s->solved[j] = !given[j] && fabs(qd[j] - old[j]) > 1e-12 * fmax(1, fabs(old[j]));
    qd__free(use);
    qd__free(old);
    return st;
}
