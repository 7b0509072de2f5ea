/*
 * src/mech/singular.c - is the mass matrix singular for every state?
 *
 * A row of zeros is the common case (T does not depend on one velocity) and
 * is read off the symbols.  Otherwise det M is not formed symbolically (a
 * dense n = 16 determinant is out of reach): M is evaluated at a few random
 * states, and one state where it has full rank proves det M is not
 * identically 0.  Rank deficiency at every state means M is singular; the
 * null space at the last state names the accelerations left undetermined.
 * Only when M cannot be compiled (a user function in it) is det M built by
 * fraction-free elimination.  With constraints the matrix to check is
 * [M -A^T; A 0]; when it is singular at every state, rank-deficient rows A
 * name the dependent constraints: redundant ones are left out by rank and
 * inconsistent ones refused (redundant.c decides which, on the manifold).
 */
#include "mech.h"

#include "num/num.h"
#include "qdot/print.h"
#include "../base/mem.h"

#include <math.h>
#include <stdlib.h>

#define NSTATES 3
#define RANK_TOL 1e-9

static void name_list(qd_buf *b, const qd_eom *e, const bool *pick, const char *suffix) {
    bool first = true;
    for (size_t j = 0; j < e->n; j++) {
        if (!pick[j])
            continue;
        qd_buf_printf(b, "%s%s%s", first ? "" : ", ", qd_expr_name(e->q[j]), suffix);
        first = false;
    }
}

/* Rows of zeros: the Lagrangian is at most linear in those velocities. */
static bool zero_rows(qd_ctx *ctx, const qd_eom *e, const qd_expr *T, bool *pick) {
    bool any = false, absent = true;
    for (size_t j = 0; j < e->n; j++) {
        pick[j] = true;
        for (size_t k = 0; k < e->n; k++)
            pick[j] = pick[j] && qd_is_zero(e->M[j * e->n + k]);
        any = any || pick[j];
        if (pick[j])
            absent = absent && !qd_has(T ? T : e->L, e->qd[j]);
    }
    if (!any)
        return false;
    qd_buf b = QD_BUF_WITH(qd__ctx_allocator(ctx));
    name_list(&b, e, pick, "'");
    if (absent)
        qd_ctx_error(ctx, QD_ERR_SINGULAR,
                     "the mass matrix is singular: the %s does not depend on %s",
                     T ? "kinetic energy" : "Lagrangian", qd_buf_str(&b));
    else
        qd_ctx_error(ctx, QD_ERR_SINGULAR,
                     "the mass matrix is singular: the Lagrangian is at most linear in %s",
                     qd_buf_str(&b));
    qd_buf_free(&b);
    return true;
}

static void report_null(qd_ctx *ctx, const qd_eom *e, const qd_expr *T, const double *null,
                        bool *pick) {
    double top = 0;
    for (size_t j = 0; j < e->n; j++)
        top = fmax(top, fabs(null[j]));
    for (size_t j = 0; j < e->n; j++)
        pick[j] = fabs(null[j]) > 1e-6 * top;
    qd_buf b = QD_BUF_WITH(qd__ctx_allocator(ctx));
    name_list(&b, e, pick, "''");
    qd_ctx_error(ctx, QD_ERR_SINGULAR,
                 "the mass matrix is singular: the accelerations %s are not determined (the "
                 "%s depends on their velocities only through a combination)",
                 qd_buf_str(&b), T ? "kinetic energy" : "Lagrangian");
    qd_buf_free(&b);
}

void qd__mech_random_state(size_t nin, double *in, unsigned k) {
    uint64_t s = 0x9e3779b97f4a7c15u * (k + 1);
    for (size_t i = 0; i < nin; i++) {
        s = s * 6364136223846793005u + 1442695040888963407u;
        in[i] = 0.2 + 1.6 * (double)(s >> 11) / 9007199254740992.0;
    }
}

static bool all_finite(size_t n, const double *x) {
    for (size_t i = 0; i < n; i++)
        if (!isfinite(x[i]))
            return false;
    return true;
}

/* Is the matrix to solve singular at the outputs out?  [M -A^T; A 0] with
 * constraints (M alone may then be singular: a massless coordinate that a
 * constraint carries), else M; null gets M's null vector. */
static bool singular_at(const qd_eom *e, double *out, double *K, size_t *pc, bool *free_col,
                        double *null) {
    size_t n = e->n, s = n + e->ncon;
    if (!e->ncon)
        return qd__num_rank(n, out, NULL, RANK_TOL, pc, free_col, null) < n;
    qd__num_saddle(n, e->ncon, out, NULL, out + qd__out_A(e), NULL, K, NULL);
    return qd__num_rank(s, K, NULL, RANK_TOL, pc, free_col, NULL) < s;
}

/* The constraints' part of a singular saddle-point matrix, at the outputs
 * out of a state where it is singular; QD_OK when A has full rank. */
static qd_status constraint_check(qd_ctx *ctx, const qd_eom *e, const double *out) {
    size_t m = e->ncon;
    double *mu = qd__malloc(ctx, (m + 1) * sizeof *mu);
    if (!mu)
        return QD_ERR_NOMEM;
    qd_status st = QD_OK;
    if (qd__mech_con_deficient(ctx, e->n, m, out + qd__out_A(e), RANK_TOL, mu)) {
        /* the constraints themselves (not their derivatives) decide
         * consistency: x = 1 and x = 2 have the same rows A */
        const double *g = out + qd__out_g(e);
        double s = 0, top = 0;
        for (size_t k = 0; k < m; k++) {
            s += mu[k] * g[k];
            top = fmax(top, fabs(g[k]));
        }
        st = qd__mech_con_report(ctx, e, mu, fabs(s) > 1e-9 * (1 + top), "");
    } else if (qd_ctx_status(ctx) == QD_ERR_NOMEM) {
        st = QD_ERR_NOMEM; /* no verdict on A: its scratch ran out */
    }
    qd__free(mu);
    return st;
}

static qd_status numeric_check(qd_ctx *ctx, qd_eom *e, const qd_expr *T, qd_prog *p,
                               size_t nin, size_t nout, bool *pick, bool reducible, bool *again) {
    size_t n = e->n, s = n + e->ncon;
    double *w = qd__malloc(ctx, (nin + nout + s * s + s) * sizeof *w + s * (sizeof(size_t) + 1));
    if (!w)
        return QD_ERR_NOMEM;
    /* scratch layout: in[nin], out[nout], K[s*s], null[s], pc[s], free_col[s] */
    double *in = w, *out = w + nin, *K = out + nout, *null = K + s * s;
    size_t *pc = (size_t *)(null + s);
    bool *free_col = (bool *)(pc + s);
    int sing = 0, tried = 0;
    for (unsigned k = 0; k < NSTATES && !(tried && !sing); k++) {
        qd__mech_random_state(nin, in, k);
        qd_prog_run(p, in, out);
        if (!all_finite(nout, out))
            continue;
        tried++;
        sing = singular_at(e, out, K, pc, free_col, null);
    }
    qd_status st = tried && sing ? QD_ERR_SINGULAR : QD_OK;
    if (st != QD_OK && e->ncon && reducible) {
        /* on the manifold: redundant rows go (*again), inconsistent ones
         * are refused with their witness */
        st = qd__mech_con_reduce(ctx, e, again);
        if (st != QD_OK || *again) {
            qd__free(w);
            return st;
        }
        st = QD_ERR_SINGULAR;
    }
    if (st != QD_OK && e->ncon) {
        st = constraint_check(ctx, e, out);
        if (st == QD_OK && !zero_rows(ctx, e, T, pick)) {
            qd_prog_run(p, in, out); /* M again: singular_at overwrote it */
            if (qd__num_rank(n, out, NULL, RANK_TOL, pc, free_col, null) < n)
                report_null(ctx, e, T, null, pick);
            else
                qd_ctx_error(ctx, QD_ERR_SINGULAR,
                             "the mass matrix is singular on the motions the constraints allow");
        }
        st = QD_ERR_SINGULAR;
    } else if (st != QD_OK) {
        report_null(ctx, e, T, null, pick);
    }
    qd__free(w);
    return st;
}

/* Only for a matrix that cannot be compiled: det M by elimination, for the
 * few rows where that stays cheap. */
static qd_status symbolic_check(qd_ctx *ctx, const qd_eom *e) {
    if (e->n > 4)
        return QD_OK;
    const qd_expr *det = qd_simplify(ctx, qd__mech_det(ctx, e->n, e->M));
    if (!det)
        return qd_ctx_status(ctx);
    if (!qd_is_zero(det))
        return QD_OK;
    qd_ctx_error(ctx, QD_ERR_SINGULAR, "the mass matrix is singular: det M = 0 for every state");
    return QD_ERR_SINGULAR;
}

static qd_status check_by_value(qd_ctx *ctx, qd_eom *e, const qd_expr *T, bool *pick,
                                bool *again) {
    qd__eom_num *num = e->priv;
    if (qd__mech_eom_compile(ctx, e) == QD_OK)
        return numeric_check(ctx, e, T, num->prog->prog, num->prog->nin, num->prog->nout, pick,
                             true, again);
    if (!qd__ctx_recover(ctx)) /* out of memory is no reason to check otherwise */
        return QD_ERR_NOMEM;
    size_t nin, nn = e->n * e->n;
    const qd_expr **in = qd__num_inputs(ctx, nn, e->M, &nin);
    qd_prog *p = in ? qd_prog_new(ctx, nin, in, nn, e->M) : NULL;
    qd_status st;
    if (p) {
        st = e->ncon ? QD_OK : numeric_check(ctx, e, T, p, nin, nn, pick, false, again);
    } else if (!qd__ctx_recover(ctx)) {
        st = QD_ERR_NOMEM;
    } else {
        st = symbolic_check(ctx, e);
    }
    qd_prog_free(p);
    qd__free(in);
    return st;
}

qd_status qd__mech_check_singular(qd_ctx *ctx, qd_eom *e, const qd_expr *T) {
    bool *pick = qd__calloc(ctx, e->n ? e->n : 1, sizeof *pick);
    if (!pick)
        return QD_ERR_NOMEM;
    qd_status st = QD_ERR_SINGULAR;
    /* each pass leaves out at most one redundant constraint */
    for (bool again = true; again;) {
        again = false;
        st = e->ncon || !zero_rows(ctx, e, T, pick) ? check_by_value(ctx, e, T, pick, &again)
                                                    : QD_ERR_SINGULAR;
    }
    qd__free(pick);
    return st;
}
