/*
 * src/linear/linearize.c - Lagrange's equations linearized about a point
 * at rest.
 *
 * From M(q, q') q'' = f(q, q', t) with x = q - q0 small and q' = x' small,
 *     M(q0) x'' = f(q0, 0) + df/dq x + df/dq' x' + O(2),
 * every derivative taken exactly on the symbolic f and evaluated at q' = 0.
 * So K = -df/dq, and -df/dq' splits into its symmetric part C (Rayleigh's
 * D: d^2D/dq'dq') and its skew part G (T1 and the velocity-linear part of
 * U give exactly the skew (d a_j/dq_k - d a_k/dq_j) of their coefficients).
 * Terms quadratic in q' (the centrifugal and Coriolis parts of f from T2)
 * have zero first derivative at q' = 0, so they drop out as they must.
 */
#include "linear.h"

#include "num/num.h"
#include "base/mem.h"
#include "../base/args.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

void qd__lin_free(qd__lin *L) {
    if (!L)
        return;
    qd__free(L->F);
    qd__free(L->J);
    qd__free(L->B);
    qd__free(L->M);
    qd_prog_free(L->prog);
    qd__free(L->inputs);
    qd__free(L->qslot);
    qd__free(L->in);
    qd__free(L->out);
    memset(L, 0, sizeof *L);
}

static qd_status build(qd_ctx *ctx, const qd_eom *e, qd__lin *L) {
    size_t n = e->n, nn = n * n;
    const qd_expr **zeros = qd__malloc(ctx, (n + 1) * sizeof *zeros);
    if (!zeros)
        return QD_ERR_NOMEM;
    for (size_t j = 0; j < n; j++)
        zeros[j] = qd_int(ctx, 0);
    const qd_expr *const *qd = e->qd;
    for (size_t j = 0; j < n; j++)
        L->F[j] = qd_subs(ctx, e->f[j], n, qd, zeros);
    for (size_t j = 0; j < n; j++)
        for (size_t k = 0; k < n; k++) {
            L->J[j * n + k] = qd_diff(ctx, L->F[j], e->q[k]);
            L->B[j * n + k] = qd_subs(ctx, qd_diff(ctx, e->f[j], qd[k]), n, qd, zeros);
        }
    for (size_t i = 0; i < nn; i++)
        L->M[i] = qd_subs(ctx, e->M[i], n, qd, zeros);
    qd__free(zeros);
    return qd_ctx_status(ctx) == QD_OK ? QD_OK : qd_ctx_status(ctx);
}

static qd_status compile(qd_ctx *ctx, qd__lin *L) {
    size_t n = L->n, nout = n + 3 * n * n;
    const qd_expr **all = qd__malloc(ctx, (nout + 1) * sizeof *all);
    if (!all)
        return QD_ERR_NOMEM;
    memcpy(all, L->F, n * sizeof *all);
    memcpy(all + n, L->J, n * n * sizeof *all);
    memcpy(all + n + n * n, L->B, n * n * sizeof *all);
    memcpy(all + n + 2 * n * n, L->M, n * n * sizeof *all);
    L->inputs = qd__num_inputs(ctx, nout, all, &L->nin);
    if (L->inputs)
        L->prog = qd_prog_new(ctx, L->nin, L->inputs, nout, all);
    qd__free(all);
    if (!L->prog)
        return qd_ctx_status(ctx) ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    L->in = qd__calloc(ctx, L->nin + 1, sizeof *L->in);
    L->out = qd__calloc(ctx, nout + 1, sizeof *L->out);
    L->qslot = qd__malloc(ctx, (n + 1) * sizeof *L->qslot);
    if (!L->in || !L->out || !L->qslot)
        return QD_ERR_NOMEM;
    for (size_t j = 0; j < n; j++) {
        L->qslot[j] = SIZE_MAX;
        for (size_t i = 0; i < L->nin; i++)
            if (L->inputs[i] == L->q[j])
                L->qslot[j] = i;
    }
    return QD_OK;
}

qd_status qd__lin_init(qd_ctx *ctx, const qd_eom *e, qd__lin *L) {
    memset(L, 0, sizeof *L);
    L->ctx = ctx;
    if (e->ncon) {
        qd_ctx_error(ctx, QD_ERR_ARG,
                     "the model keeps %zu constraint%s with multipliers: small oscillations need "
                     "independent coordinates (qd_constrained_linear_about reduces onto the "
                     "constraints)", e->ncon, e->ncon == 1 ? "" : "s");
        return QD_ERR_ARG;
    }
    size_t n = e->n, nn = n * n;
    L->n = n;
    L->q = e->q;
    L->F = qd__calloc(ctx, n + 1, sizeof *L->F);
    L->J = qd__calloc(ctx, nn + 1, sizeof *L->J);
    L->B = qd__calloc(ctx, nn + 1, sizeof *L->B);
    L->M = qd__calloc(ctx, nn + 1, sizeof *L->M);
    qd_status st = L->F && L->J && L->B && L->M ? build(ctx, e, L) : QD_ERR_NOMEM;
    if (st == QD_OK)
        st = compile(ctx, L);
    if (st != QD_OK) {
        if (qd_ctx_status(ctx) == QD_OK)
            qd_ctx_error(ctx, st, "cannot linearize the equations of motion");
        qd__lin_free(L);
    }
    return st;
}

void qd__lin_bind(qd__lin *L, size_t nvals, const qd_expr *const *syms, const double *vals) {
    for (size_t i = 0; i < L->nin; i++) {
        L->in[i] = 0;
        for (size_t k = 0; k < nvals; k++)
            if (syms[k] == L->inputs[i]) {
                L->in[i] = vals[k];
                break;
            }
    }
}

void qd__lin_run(qd__lin *L, const double *q) {
    for (size_t j = 0; q && j < L->n; j++)
        if (L->qslot[j] != SIZE_MAX)
            L->in[L->qslot[j]] = q[j];
    qd_prog_run(L->prog, L->in, L->out);
}

void qd_linear_free(qd_linear *l) {
    if (!l)
        return;
    qd__free(l->M);
    qd__free(l->C);
    qd__free(l->G);
    qd__free(l->K);
    memset(l, 0, sizeof *l);
}

bool qd__lin_negligible(double x, double scale) {
    return fabs(x) <= QD_LINEAR_ZERO_TOL * scale;
}

/* Round-off zeros of M0 s^2 + (C0 + G0) s + K0 set to 0, judged in the
 * coordinates that make M0's diagonal 1 (x_i sqrt(M_ii): metres and radians
 * alike) against the problem's own rate W = max(sqrt|K'|, |C'|, |G'|): a
 * stiffness against W^2, a damping or gyroscopic term against W, an
 * inertia against 1.  The ring of a rotating bowl has K0[y,y] = -1.5e-13
 * beside K0[x,x] = 952 and G0 = 10: a cancellation, which left as it is
 * gives real roots +-3.7e-7 and "unstable". */
void qd__lin_linear_chop(qd_linear *l) {
    size_t n = l->n;
    double kmax = 0, gmax = 0, mmax = 0;
#define D(i) (l->M[(i) * n + (i)] > 0 && isfinite(l->M[(i) * n + (i)]) ? 1 / sqrt(l->M[(i) * n + (i)]) : 1)
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++) {
            double d = D(i) * D(j);
            kmax = fmax(kmax, fabs(l->K[i * n + j]) * d);
            gmax = fmax(gmax, fmax(fabs(l->G[i * n + j]), fabs(l->C[i * n + j])) * d);
            mmax = fmax(mmax, fabs(l->M[i * n + j]) * d);
        }
    double w = fmax(sqrt(kmax), gmax);
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++) {
            size_t k = i * n + j;
            double d = D(i) * D(j);
            if (qd__lin_negligible(l->K[k] * d, w * w))
                l->K[k] = 0;
            if (qd__lin_negligible(l->G[k] * d, w))
                l->G[k] = 0;
            if (qd__lin_negligible(l->C[k] * d, w))
                l->C[k] = 0;
            if (i != j && qd__lin_negligible(l->M[k] * d, mmax))
                l->M[k] = 0;
        }
#undef D
}

qd_status qd_linear_about(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t nvals,
                          const qd_expr *const *syms, const double *vals, qd_linear *out) {
    QD_ARGS_CTX(ctx, ctx && e && m && (nvals == 0 || syms) && (nvals == 0 || vals) && out);
    (void)m;
    memset(out, 0, sizeof *out);
    if (!ctx || !e)
        return QD_ERR_ARG;
    qd__lin L;
    qd_status st = qd__lin_init(ctx, e, &L);
    if (st != QD_OK)
        return st;
    size_t n = e->n, nn = n * n;
    qd__lin_bind(&L, nvals, syms, vals);
    qd__lin_run(&L, NULL);
    out->n = n;
    out->M = qd__malloc(ctx, (nn + 1) * sizeof *out->M);
    out->C = qd__malloc(ctx, (nn + 1) * sizeof *out->C);
    out->G = qd__malloc(ctx, (nn + 1) * sizeof *out->G);
    out->K = qd__malloc(ctx, (nn + 1) * sizeof *out->K);
    if (!out->M || !out->C || !out->G || !out->K) {
        qd__lin_free(&L);
        qd_linear_free(out);
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory linearizing");
        return QD_ERR_NOMEM;
    }
    const double *J = qd__lin_J(&L), *B = qd__lin_B(&L), *M = qd__lin_M(&L);
    for (size_t j = 0; j < n; j++)
        for (size_t k = 0; k < n; k++) {
            out->M[j * n + k] = M[j * n + k];
            out->K[j * n + k] = -J[j * n + k];
            out->C[j * n + k] = -(B[j * n + k] + B[k * n + j]) / 2;
            out->G[j * n + k] = -(B[j * n + k] - B[k * n + j]) / 2;
        }
    for (size_t i = 0; i < nn; i++)
        if (!isfinite(out->M[i]) || !isfinite(out->K[i]) || !isfinite(out->C[i]) ||
            !isfinite(out->G[i])) {
            qd__lin_free(&L);
            qd_linear_free(out);
            qd_ctx_error(ctx, QD_ERR_NUMERIC,
                         "the linearized equations are not finite at this point (a singularity "
                         "of the model)");
            return QD_ERR_NUMERIC;
        }
    qd__lin_linear_chop(out);
    qd__lin_free(&L);
    return QD_OK;
}

qd_status qd_linear_symbolic(qd_ctx *ctx, const qd_eom *e, const qd_expr *const *q0,
                             const qd_expr **Kout, const qd_expr **Mout) {
    QD_ARGS_CTX(ctx, ctx && e && q0 && Kout && Mout);
    size_t n = e->n;
    const qd_expr **from = qd__malloc(ctx, (2 * n + 1) * sizeof *from);
    const qd_expr **to = qd__malloc(ctx, (2 * n + 1) * sizeof *to);
    if (!from || !to) {
        qd__free(from);
        qd__free(to);
        return QD_ERR_NOMEM;
    }
    for (size_t j = 0; j < n; j++) {
        from[j] = e->qd[j];
        to[j] = qd_int(ctx, 0);
        from[n + j] = e->q[j];
        to[n + j] = q0[j];
    }
    for (size_t j = 0; j < n; j++) {
        const qd_expr *F = qd_subs(ctx, e->f[j], n, from, to);
        for (size_t k = 0; k < n; k++) {
            const qd_expr *d = qd_diff(ctx, F, e->q[k]);
            Kout[j * n + k] = qd_simplify(ctx, qd_neg(ctx, qd_subs(ctx, d, 2 * n, from, to)));
            Mout[j * n + k] = qd_simplify(ctx, qd_subs(ctx, e->M[j * n + k], 2 * n, from, to));
        }
    }
    qd__free(from);
    qd__free(to);
    return qd_ctx_status(ctx);
}
