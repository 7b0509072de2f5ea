/*
 * src/impulse/state.c - the impulse in numbers: the state just before,
 * every coefficient at it, and the saddle-point solve
 *
 *     [ M  -A^T ] [ q'+ - q'- ]   [ Qhat                 ]
 *     [ A   0   ] [ Lambda    ] = [ -(1 + E_k) c_k(q'-)  ]
 *
 * (Desloge ch. 57 thm 1 eqs. 4-5 with Newton's law for each sudden row),
 * assembled and solved by the numerics home (src/num); the diagnosis of a
 * singular system is the mechanics layer's (qd__mech_con_deficient,
 * qd__mech_con_report), on a qd_eom view of the rows.
 */
#include "impulse_priv.h"

#include "base/mem.h"
#include "mech/mech_export.h"
#include "num/num.h"
#include "qdot/state.h"

#include <math.h>
#include <string.h>

#define SOLVE_TOL 1e-12

static qd_status nomem(qd_ctx *ctx) {
    qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory solving an impulse");
    return QD_ERR_NOMEM;
}

static qd_status eval(const qd__imp *s, const qd_expr *x, double *out) {
    if (!x)
        return qd_ctx_status(s->ctx) != QD_OK ? qd_ctx_status(s->ctx) : QD_ERR_NOMEM;
    return qd_eval(s->ctx, x, s->nv, s->syms, s->vals, out);
}

/* The value of the state for coordinate j (order 0) or its velocity. */
static qd_status state_value(qd__imp *s, const qd_expr *const *given, size_t j, unsigned order,
                             const qd_expr **out) {
    const qd_expr *x = given && given[j] ? given[j] : qd_model_initial_definition(s->m, j, order);
    if (!x) {
        qd_ctx_error(s->ctx, QD_ERR_ARG,
                     "no value of %s%s just before the impulse: give it in `initial` or the state",
                     qd_expr_name(s->e->q[j]), order ? "'" : "");
        return QD_ERR_ARG;
    }
    *out = x;
    return QD_OK;
}

/* The value of x in the parameters alone (syms from index 2n + 1 on). */
static qd_status param_value(const qd__imp *s, const qd_expr *x, double *out) {
    size_t off = qd_slot_param(s->n, 0);
    qd_status st = qd_eval(s->ctx, x, s->nv - off, s->syms + off, s->vals + off, out);
    if (st == QD_ERR_UNBOUND) {
        qd__ctx_recover(s->ctx);
        qd_ctx_error(s->ctx, QD_ERR_ARG,
                     "the state just before the impulse must be given in numbers and parameters");
        return QD_ERR_ARG;
    }
    return st;
}

qd_status qd__imp_state(qd__imp *s, const qd_impulse_opts *opts) {
    size_t n = s->n, np = qd_model_nparams(s->m);
    s->nv = qd_slot_count(n, np);
    s->syms = qd__calloc(s->ctx, s->nv, sizeof *s->syms);
    s->vals = qd__calloc(s->ctx, s->nv, sizeof *s->vals);
    s->q0 = qd__calloc(s->ctx, n + 1, sizeof *s->q0);
    s->qd0 = qd__calloc(s->ctx, n + 1, sizeof *s->qd0);
    if (!s->syms || !s->vals || !s->q0 || !s->qd0)
        return nomem(s->ctx);
    /* q, q', t and the parameters at their values (exact ones too: pi/6) */
    qd_status st = qd_state_layout(s->ctx, s->m, n, s->e->q, s->syms, s->vals);
    s->t0 = opts && opts->t ? opts->t : qd_int(s->ctx, 0);
    if (st == QD_OK)
        st = param_value(s, s->t0, &s->vals[qd_slot_time(n)]);
    for (size_t j = 0; j < n && st == QD_OK; j++) {
        st = state_value(s, opts ? opts->q : NULL, j, 0, &s->q0[j]);
        if (st == QD_OK)
            st = state_value(s, opts ? opts->qd : NULL, j, 1, &s->qd0[j]);
        if (st == QD_OK)
            st = param_value(s, s->q0[j], &s->vals[j]);
        if (st == QD_OK)
            st = param_value(s, s->qd0[j], &s->vals[qd_slot_velocity(n, j)]);
    }
    return st;
}

static qd_status restitution(qd__imp *s, size_t k) {
    qd_status st = eval(s, s->E[k], &s->En[k]);
    if (st != QD_OK || (s->En[k] >= 0 && s->En[k] <= 1))
        return st;
    qd_ctx_error(s->ctx, QD_ERR_ARG,
                 "the restitution of impact constraint %s is %g: Newton's coefficient of "
                 "restitution lies in [0, 1]", s->row[k].name, s->En[k]);
    qd_ctx_error_about(s->ctx, QD_SUBJECT_CONSTRAINT, k, s->row[k].name, QD_REASON_NONE,
                       "give a restitution between 0 (plastic) and 1 (elastic)");
    return QD_ERR_ARG;
}

qd_status qd__imp_eval(const qd__imp *s, const qd_expr *x, const double *v, double *out) {
    size_t n = s->n;
    double *vals = qd__malloc(s->ctx, (s->nv + 1) * sizeof *vals);
    if (!vals)
        return nomem(s->ctx);
    memcpy(vals, s->vals, s->nv * sizeof *vals);
    memcpy(vals + n, v, n * sizeof *vals);
    qd_status st = x ? qd_eval(s->ctx, x, s->nv, s->syms, vals, out) : qd_ctx_status(s->ctx);
    qd__free(vals);
    return x || st != QD_OK ? st : QD_ERR_NOMEM;
}

/* Each blow's generalized impulse, and T1's coefficients dT/dq' at q' = 0. */
static qd_status blows_and_p0(qd__imp *s) {
    size_t n = s->n;
    qd_status st = QD_OK;
    for (size_t i = 0; i < s->nblows && st == QD_OK; i++)
        for (size_t j = 0; j < n && st == QD_OK; j++)
            st = eval(s, qd_model_blow(s->m, i, j), &s->W[i * n + j]);
    const double *zero = s->Qhat + n;
    for (size_t j = 0; j < n && st == QD_OK; j++)
        st = qd__imp_eval(s, qd_diff(s->ctx, s->T, s->e->qd[j]), zero, &s->p0[j]);
    return st;
}

/* The numbers live in one block at s->M: M (n*n), Qhat (n), n zeros (the
 * velocities at which T1 is read), p0 (n), An (r*n), a0n (r), En (r) and
 * W (nblows*n); qd__imp_free frees the block. */
qd_status qd__imp_numbers(qd__imp *s) {
    size_t n = s->n, r = s->nrow;
    size_t len = n * n + 3 * n + r * n + 2 * r + s->nblows * n + 1;
    s->M = qd__calloc(s->ctx, len, sizeof *s->M);
    if (!s->M)
        return nomem(s->ctx);
    s->Qhat = s->M + n * n;
    s->p0 = s->Qhat + 2 * n;
    s->An = s->p0 + n;
    s->a0n = s->An + r * n;
    s->En = s->a0n + r;
    s->W = s->En + r;
    qd_status st = QD_OK;
    for (size_t i = 0; i < n * n && st == QD_OK; i++)
        st = eval(s, s->e->M[i], &s->M[i]);
    for (size_t j = 0; j < n && st == QD_OK; j++)
        st = eval(s, qd_model_impulse(s->m, j), &s->Qhat[j]);
    for (size_t k = 0; k < r && st == QD_OK; k++) {
        for (size_t j = 0; j < n && st == QD_OK; j++)
            st = eval(s, s->A[k * n + j], &s->An[k * n + j]);
        if (st == QD_OK)
            st = eval(s, s->row[k].a0, &s->a0n[k]);
        if (st == QD_OK)
            st = restitution(s, k);
    }
    if (st == QD_OK)
        st = blows_and_p0(s);
    return st;
}

double qd__imp_rhs(const qd__imp *s, size_t k, const double *v0) {
    double c = s->a0n[k];
    for (size_t j = 0; j < s->n; j++)
        c += s->An[k * s->n + j] * v0[j];
    return -(1 + s->En[k]) * c;
}

qd_status qd__imp_energy(const qd__imp *s, const double *v, double *T) {
    qd_status st = qd__imp_eval(s, s->T, v, T);
    double rest;
    if (st == QD_OK && s->nonquad) /* the energy function less its value at rest */
        st = qd__imp_eval(s, s->T, s->Qhat + s->n, &rest);
    if (st == QD_OK && s->nonquad)
        *T -= rest;
    return st;
}

double qd__imp_quad(const qd__imp *s, const double *d) {
    double q = 0;
    for (size_t i = 0; i < s->n; i++)
        for (size_t j = 0; j < s->n; j++)
            q += d[i] * s->M[i * s->n + j] * d[j];
    return q / 2;
}

bool qd__imp_saddle(qd_ctx *ctx, size_t n, size_t m, const double *M, const double *B,
                    const double *f, const double *r, double *x, double *mu) {
    size_t N = n + m;
    double *K = qd__malloc(ctx, (N * N + N + 1) * sizeof *K);
    if (!K)
        return false;
    double *rhs = K + N * N;
    qd__num_saddle(n, m, M, f, B, r, K, rhs);
    bool ok = qd__num_solve(N, K, rhs, SOLVE_TOL * (double)N);
    for (size_t i = 0; ok && i < n; i++)
        x[i] = rhs[i];
    for (size_t k = 0; ok && mu && k < m; k++)
        mu[k] = rhs[n + k];
    qd__free(K);
    return ok;
}

/* sum_k mu_k v_k against the size of v: is the combination nonzero? */
static bool combination_nonzero(size_t m, const double *mu, const double *v) {
    double sum = 0, top = 0;
    for (size_t k = 0; k < m; k++) {
        sum += mu[k] * v[k];
        top = fmax(top, fabs(v[k]));
    }
    return fabs(sum) > 1e-9 * (1 + top);
}

/* Why the system of the used rows (B, r: m of them, idx their numbers) is
 * singular: dependent rows named, or M singular on the motions they allow. */
static qd_status diagnose(const qd__imp *s, size_t m, const size_t *idx, const double *B,
                          const double *r) {
    qd_ctx *ctx = s->ctx;
    double *mu = qd__calloc(ctx, s->nrow + m + 1, sizeof *mu);
    if (!mu)
        return nomem(ctx);
    double *mu_used = mu + s->nrow;
    if (qd__mech_con_deficient(ctx, s->n, m, B, SOLVE_TOL * 1e3, mu_used)) {
        for (size_t k = 0; k < m; k++)
            mu[idx[k]] = mu_used[k];
        qd_eom view = qd__imp_view(s);
        qd__mech_con_report(ctx, &view, mu, combination_nonzero(m, mu_used, r), " at the impact");
    } else if (!qd__ctx_nomem(ctx)) {
        qd_ctx_error(ctx, QD_ERR_SINGULAR,
                     "the mass matrix is singular at the impact on the motions the constraints "
                     "allow: the velocities after are not determined");
    }
    qd__free(mu);
    return qd__ctx_nomem(ctx) ? QD_ERR_NOMEM : QD_ERR_SINGULAR;
}

#define DEP_TOL 1e-10  /* a row within this of the span of those before it (relative) */

/* Mark the rows of B (m x n) that lie in the span of the ones kept before
 * them (modified Gram-Schmidt on a copy, tolerance relative to the row's
 * own length); false when out of memory. */
static bool dependent_rows(qd_ctx *ctx, size_t m, size_t n, const double *B, bool *dep) {
    double *Q = qd__malloc(ctx, (m * n + 1) * sizeof *Q);
    if (!Q)
        return false;
    size_t kept = 0;
    for (size_t k = 0; k < m; k++) {
        double *q = Q + kept * n, len0 = 0, len = 0;
        memcpy(q, B + k * n, n * sizeof *q);
        for (size_t j = 0; j < n; j++)
            len0 += q[j] * q[j];
        for (size_t i = 0; i < kept; i++) {
            double d = 0;
            for (size_t j = 0; j < n; j++)
                d += Q[i * n + j] * q[j];
            for (size_t j = 0; j < n; j++)
                q[j] -= d * Q[i * n + j];
        }
        for (size_t j = 0; j < n; j++)
            len += q[j] * q[j];
        dep[k] = len0 > 0 && !(sqrt(len) > DEP_TOL * sqrt(len0));
        if (dep[k] || !(len > 0))
            continue;
        for (size_t j = 0; j < n; j++)
            q[j] /= sqrt(len);
        kept++;
    }
    qd__free(Q);
    return true;
}

/* Does row k of B hold at dv, relative to the row's size times dv's?
 * Not relative to its own terms: a row that holds because dv is 0 where
 * the row is not (a rod's point prescribed to stay still along the rod)
 * has terms of rounding size only, and would look violated (issue 33). */
static bool row_holds(size_t n, const double *Bk, double rk, const double *dv) {
    double sum = 0, row = 0, top = 0;
    for (size_t j = 0; j < n; j++) {
        sum += Bk[j] * dv[j];
        row += fabs(Bk[j]);
        top = fmax(top, fabs(dv[j]));
    }
    double size = fabs(rk) + row * top;
    return fabs(sum - rk) <= 1e-9 * (size > 0 ? size : 1);
}

qd_status qd__imp_solve(const qd__imp *s, const bool *use, bool report, double *v1,
                        double *lambda, bool *redundant) {
    qd_ctx *ctx = s->ctx;
    size_t n = s->n, m = 0;
    double *B = qd__malloc(ctx, (s->nrow * (n + 3) + n + 1) * sizeof *B);
    size_t *idx = qd__malloc(ctx, (s->nrow + 1) * sizeof *idx);
    if (!B || !idx) {
        qd__free(B);
        qd__free(idx);
        return nomem(ctx);
    }
    double *r = B + s->nrow * n, *mu = r + s->nrow, *dv = mu + s->nrow;
    const double *v0 = s->vals + n;
    for (size_t k = 0; k < s->nrow; k++) {
        if (use && !use[k])
            continue;
        memcpy(B + m * n, s->An + k * n, n * sizeof *B);
        r[m] = qd__imp_rhs(s, k, v0);
        idx[m++] = k;
    }
    qd_status st = QD_OK;
    /* the independent rows first: redundant ones (dependent, consistent) are
     * reduced by rank, the saddle of the rest solved, the others checked */
    bool *dep = qd__calloc(ctx, m + 1, sizeof *dep);
    double *Bi = qd__malloc(ctx, (m * (n + 1) + 1) * sizeof *Bi);
    size_t *ii = qd__malloc(ctx, (m + 1) * sizeof *ii);
    size_t mi = 0;
    if (!dep || !Bi || !ii || !dependent_rows(ctx, m, n, B, dep)) {
        st = nomem(ctx);
    } else {
        double *ri = Bi + m * n;
        for (size_t k = 0; k < m; k++)
            if (!dep[k]) {
                memcpy(Bi + mi * n, B + k * n, n * sizeof *Bi);
                ri[mi] = r[k];
                ii[mi++] = k;
            }
        if (!qd__imp_saddle(ctx, n, mi, s->M, Bi, s->Qhat, ri, dv, mu))
            st = qd__ctx_nomem(ctx) ? QD_ERR_NOMEM
                 : report           ? diagnose(s, m, idx, B, r)
                                    : QD_ERR_SINGULAR;
        for (size_t k = 0; st == QD_OK && k < m; k++)
            if (dep[k] && !row_holds(n, B + k * n, r[k], dv))
                st = report ? diagnose(s, m, idx, B, r) : QD_ERR_SINGULAR;
    }
    for (size_t j = 0; st == QD_OK && j < n; j++)
        v1[j] = v0[j] + dv[j];
    for (size_t k = 0; st == QD_OK && lambda && k < s->nrow; k++)
        lambda[k] = 0;
    for (size_t k = 0; st == QD_OK && redundant && k < s->nrow; k++)
        redundant[k] = false;
    for (size_t k = 0; st == QD_OK && lambda && k < mi; k++)
        lambda[idx[ii[k]]] = mu[k];
    for (size_t k = 0; st == QD_OK && redundant && k < m; k++)
        redundant[idx[k]] = dep[k];
    qd__free(dep);
    qd__free(Bi);
    qd__free(ii);
    qd__free(B);
    qd__free(idx);
    return st;
}
