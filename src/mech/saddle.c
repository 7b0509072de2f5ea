/*
 * src/mech/saddle.c - numbers for constrained equations: the saddle-point
 * system
 *
 *     [ M  -A^T ] [ q''    ]   [ f ]
 *     [ A   0   ] [ lambda ] = [ b ]
 *
 * (Desloge, seed C5), assembled and solved by the numerics home (src/num),
 * and the diagnosis
 * when it is singular.  For M positive definite on the motions A allows, the
 * matrix is singular exactly when A has a rank below its row count: some
 * combination mu of the constraint rows vanishes (A^T mu = 0), so the
 * multipliers are not unique.  If the same combination of the right-hand
 * sides (or of the constraints themselves) does not vanish, no motion meets
 * them all: they are inconsistent.
 */
#include "mech.h"

#include "num/num.h"
#include "qdot/print.h"
#include "../base/mem.h"

#include <math.h>
#include <stdlib.h>

#define SOLVE_TOL 1e-12

bool qd__mech_con_deficient(qd_ctx *ctx, size_t n, size_t m, const double *A, double tol,
                            double *mu) {
    /* A^T (n x m) padded with zeros to a square: padded columns come last,
     * so the first column without a pivot is a genuine one when any is. */
    size_t s = n > m ? n : m;
    double *S = qd__calloc(ctx, s * s + 2 * s, sizeof *S);
    size_t *pc = qd__malloc(ctx, s * sizeof *pc);
    bool *free_col = qd__malloc(ctx, s * sizeof *free_col);
    bool deficient = false;
    if (S && pc && free_col) {
        double *null = S + s * s;
        for (size_t i = 0; i < n; i++)
            for (size_t k = 0; k < m; k++)
                S[i * s + k] = A[k * n + i];
        deficient = qd__num_rank(s, S, NULL, tol, pc, free_col, null) < m;
        double top = 0;
        for (size_t k = 0; deficient && k < m; k++)
            top = fmax(top, fabs(null[k]));
        for (size_t k = 0; deficient && k < m; k++)
            mu[k] = top > 0 ? null[k] / top : 0;
    }
    qd__free(S);
    qd__free(pc);
    qd__free(free_col);
    return deficient;
}

qd_status qd__mech_con_report(qd_ctx *ctx, const qd_eom *e, const double *mu, bool inconsistent,
                         const char *where) {
    qd_buf names = QD_BUF_WITH(qd__ctx_allocator(ctx));
    size_t count = 0, last = 0;
    for (size_t k = 0; k < e->ncon; k++)
        if (fabs(mu[k]) > 1e-6)
            count++, last = k;
    for (size_t k = 0, i = 0; k < e->ncon; k++) {
        if (!(fabs(mu[k]) > 1e-6))
            continue;
        qd_buf_puts(&names, i == 0 ? "" : k == last ? " and " : ", ");
        qd_buf_puts(&names, e->con[k].name);
        i++;
    }
    if (count == 1)
        qd_ctx_error(ctx, QD_ERR_SINGULAR,
                     "constraint %s is degenerate%s: its coefficients vanish, so its multiplier "
                     "is not determined", qd_buf_str(&names), where);
    else if (inconsistent)
        qd_ctx_error(ctx, QD_ERR_SINGULAR,
                     "constraints %s are inconsistent%s: no motion satisfies them all",
                     qd_buf_str(&names), where);
    else
        qd_ctx_error(ctx, QD_ERR_SINGULAR,
                     "constraints %s are redundant%s: their multipliers are not unique",
                     qd_buf_str(&names), where);
    qd_buf_free(&names);
    size_t first = 0;
    while (first < e->ncon && !(fabs(mu[first]) > 1e-6))
        first++;
    qd_reason why = count == 1 ? QD_REASON_DEGENERATE
                    : inconsistent ? QD_REASON_INCONSISTENT : QD_REASON_REDUNDANT;
    qd_ctx_error_about(ctx, QD_SUBJECT_CONSTRAINT, first, first < e->ncon ? e->con[first].name : NULL,
                       why, why == QD_REASON_INCONSISTENT
                                ? "the constraints contradict each other: correct or remove one"
                                : "remove the constraints that repeat what the others say");
    return QD_ERR_SINGULAR;
}

/* sum_k mu_k v_k against the size of v: is the combination nonzero? */
static bool combination_nonzero(size_t m, const double *mu, const double *v) {
    double s = 0, top = 0;
    for (size_t k = 0; k < m; k++) {
        s += mu[k] * v[k];
        top = fmax(top, fabs(v[k]));
    }
    return fabs(s) > 1e-9 * (1 + top);
}

static void build(const qd_eom *e, const double *out, double *K, double *rhs) {
    qd__num_saddle(e->n, e->ncon, out, out + e->n * e->n, out + qd__out_A(e), out + qd__out_b(e),
                   K, rhs);
}

static qd_status singular(qd_ctx *ctx, const qd_eom *e, const double *out) {
    size_t m = e->ncon;
    double *mu = qd__malloc(ctx, (m + 1) * sizeof *mu);
    if (!mu)
        return QD_ERR_NOMEM;
    qd_status st = QD_ERR_SINGULAR;
    if (qd__mech_con_deficient(ctx, e->n, m, out + qd__out_A(e), SOLVE_TOL * 1e3, mu))
        qd__mech_con_report(ctx, e, mu, combination_nonzero(m, mu, out + qd__out_b(e)),
                       " at this state");
    else if (qd_ctx_status(ctx) == QD_ERR_NOMEM) /* no verdict: its scratch ran out */
        st = QD_ERR_NOMEM;
    else
        qd_ctx_error(ctx, st,
                     "the mass matrix is singular on the motions the constraints allow at this "
                     "state");
    qd__free(mu);
    return st;
}

qd_status qd__mech_saddle_solve(qd_ctx *ctx, const qd_eom *e, const double *out, double *K,
                           double *x, double *lambda, double *R) {
    size_t n = e->n, m = e->ncon, s = n + m;
    double *rhs = K + s * s;
    build(e, out, K, rhs);
    if (!qd__num_solve(s, K, rhs, SOLVE_TOL * (double)s))
        return singular(ctx, e, out);
    for (size_t i = 0; x && i < n; i++)
        x[i] = rhs[i];
    for (size_t k = 0; lambda && k < m; k++)
        lambda[k] = rhs[n + k];
    for (size_t j = 0; R && j < n; j++) {
        R[j] = 0;
        for (size_t k = 0; k < m; k++)
            R[j] += out[qd__out_A(e) + k * n + j] * rhs[n + k];
    }
    return QD_OK;
}
