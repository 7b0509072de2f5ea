/*
 * src/speeds/dagsolve.c - the velocity map solved on the expression DAG,
 * for maps whose symbolic solve swells (issue 37).
 *
 * The exact solve (qd__mech_solve_sparse: fraction-free elimination,
 * every step expanded and cancelled) is what gives small systems their
 * textbook kinematics, but on the Whipple bicycle the front contact's 2x2
 * core expands past the expansion limit (and before that limit spent
 * minutes in FLINT's multivariate GCD).  Here the same system is solved by
 * plain Gaussian elimination whose entries are never expanded: each step
 * adds a few nodes to the shared DAG, the compiled program evaluates every
 * node once, so the solve happens numerically at run time.  Pivots are
 * chosen by the reduced entries' values at sample states, the parameters
 * at their values (the same elimination run in doubles alongside): the
 * entry whose smallest |value| over the samples is largest, so that a pivot
 * that is identically zero (a sum that would cancel) is never taken.  One
 * sample is the reference state q = 0 (a vehicle upright): a pivot that
 * vanishes there (the bicycle's lean enters as sin(q2)) divides 0 by 0 near
 * it, so it is avoided whenever another candidate is nonzero there.  A pivot
 * that vanishes elsewhere could still be taken, which the numeric check of
 * the mass matrix and the tests at random states guard against.
 */
#include "spd.h"

#include "../base/mem.h"

#include <math.h>

#define SAMPLES 4
#define MAXSYMS 96

/* The free symbols of the n*n entries, at most MAXSYMS (more: no numeric
 * pivoting, the first nonzero entry is taken). */
static size_t gather(qd_ctx *ctx, size_t n, const qd_expr *const *P, const qd_expr **syms) {
    size_t ns = 0;
    for (size_t i = 0; i < n * n; i++) {
        const qd_expr *buf[MAXSYMS];
        size_t k = qd_free_symbols(ctx, P[i], buf, MAXSYMS);
        if (k > MAXSYMS)
            return MAXSYMS + 1;
        for (size_t a = 0; a < k; a++) {
            bool have = false;
            for (size_t b = 0; b < ns && !have; b++)
                have = syms[b] == buf[a];
            if (!have) {
                if (ns == MAXSYMS)
                    return MAXSYMS + 1;
                syms[ns++] = buf[a];
            }
        }
    }
    return ns;
}

qd_status qd__spd_dag_solve(qd_ctx *ctx, const qd_model *m, size_t n, const qd_expr *const *P,
                            size_t nc, const qd_expr *const *B, const qd_expr **X) {
    size_t w = n + nc;
    const qd_expr **A = qd__malloc(ctx, (n * w + 1) * sizeof *A);
    const qd_expr **syms = qd__malloc(ctx, (MAXSYMS + 1) * sizeof *syms);
    double *num = qd__malloc(ctx, (SAMPLES * n * n + 1) * sizeof *num);
    if (!A || !syms || !num) {
        qd__free(A), qd__free(syms), qd__free(num);
        return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    }
    for (size_t i = 0; i < n; i++) {
        for (size_t j = 0; j < n; j++)
            A[i * w + j] = P[i * n + j];
        for (size_t c = 0; c < nc; c++)
            A[i * w + n + c] = B[i * nc + c];
    }
    qd_status st = QD_OK;
    size_t ns = gather(ctx, n, P, syms);
    bool numeric = ns <= MAXSYMS;
    for (size_t s = 0; numeric && s < SAMPLES; s++) {
        double vals[MAXSYMS + 1];
        for (size_t i = 0; i < ns; i++) { /* parameters at their values; sample 0 at q = 0 */
            vals[i] = s == 0 ? 0 : 0.2 + (double)((i * 7919 + 613 * s + 17) % 101) / 101.0;
            for (size_t k = 0; m && k < qd_model_nparams(m); k++)
                if (qd_model_param(m, k) == syms[i] && qd_model_param_number(m, k, &vals[i]) != QD_OK)
                    qd__ctx_recover(ctx);
        }
        for (size_t i = 0; numeric && i < n * n; i++)
            if (qd_eval(ctx, P[i], ns, syms, vals, &num[s * n * n + i]) != QD_OK ||
                !isfinite(num[s * n * n + i])) {
                qd__ctx_recover(ctx); /* user functions have no values: first nonzero pivot */
                numeric = false;
            }
    }
    if (qd__ctx_nomem(ctx))
        st = QD_ERR_NOMEM;
    for (size_t k = 0; st == QD_OK && k < n; k++) {
        size_t best = n;
        double best_v = 0;
        bool zero_ok = false;
        for (size_t r = k; numeric && r < n; r++)
            zero_ok = zero_ok || (!qd_is_zero(A[r * w + k]) && fabs(num[r * n + k]) > 1e-9);
        for (size_t r = k; r < n; r++) {
            if (qd_is_zero(A[r * w + k]))
                continue;
            /* the smallest |value| over the samples; the reference state q = 0
             * counts only where some candidate is nonzero there */
            double v = INFINITY;
            for (size_t s = 1; numeric && s < SAMPLES; s++)
                v = fmin(v, fabs(num[s * n * n + r * n + k]));
            if (numeric && zero_ok)
                v = fmin(v, fabs(num[r * n + k]));
            if (best == n || v > best_v)
                best = r, best_v = v;
            if (!numeric)
                break;
        }
        if (best == n || (numeric && !(best_v > 1e-9))) {
            st = QD_ERR_SINGULAR;
            break;
        }
        for (size_t j = 0; best != k && j < w; j++) {
            const qd_expr *t = A[best * w + j];
            A[best * w + j] = A[k * w + j], A[k * w + j] = t;
        }
        for (size_t s = 0; numeric && best != k && s < SAMPLES; s++)
            for (size_t j = 0; j < n; j++) {
                double t = num[s * n * n + best * n + j];
                num[s * n * n + best * n + j] = num[s * n * n + k * n + j];
                num[s * n * n + k * n + j] = t;
            }
        const qd_expr *piv = A[k * w + k];
        for (size_t i = k + 1; st == QD_OK && i < n; i++) {
            if (qd_is_zero(A[i * w + k]))
                continue;
            const qd_expr *l = qd_div(ctx, A[i * w + k], piv);
            for (size_t j = k + 1; l && j < w; j++)
                if (!qd_is_zero(A[k * w + j]))
                    A[i * w + j] = qd_sub(ctx, A[i * w + j], qd_mul(ctx, l, A[k * w + j]));
            A[i * w + k] = qd_int(ctx, 0);
            for (size_t s = 0; numeric && s < SAMPLES; s++) {
                double *R = num + s * n * n, lv = R[i * n + k] / R[k * n + k];
                for (size_t j = k; j < n; j++)
                    R[i * n + j] -= lv * R[k * n + j];
            }
            if (!l)
                st = QD_ERR_NOMEM;
        }
    }
    /* back substitution, column by column */
    for (size_t c = 0; st == QD_OK && c < nc; c++)
        for (size_t i = n; i-- > 0 && st == QD_OK;) {
            const qd_expr *s = A[i * w + n + c];
            for (size_t j = i + 1; s && j < n; j++)
                if (!qd_is_zero(A[i * w + j]) && !qd_is_zero(X[j * nc + c]))
                    s = qd_sub(ctx, s, qd_mul(ctx, A[i * w + j], X[j * nc + c]));
            if (!(X[i * nc + c] = s ? qd_div(ctx, s, A[i * w + i]) : NULL))
                st = QD_ERR_NOMEM;
        }
    qd__free(A), qd__free(syms), qd__free(num);
    if (st == QD_ERR_NOMEM && qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, st, "out of memory solving the velocity map");
    return st;
}

qd_status qd__spd_big_map(qd__spd *d) {
    qd_ctx *ctx = d->ctx;
    qd_speeds_eom *e = d->e;
    size_t n = d->n, m = d->m, nx = d->need_wc ? n : m, nc = nx + 1;
    /* columns: one unit column per unknown (u, then the constraints' s), then -p0 */
    const qd_expr **B = qd__calloc(ctx, 2 * n * nc + 1, sizeof *B);
    if (!B)
        return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    const qd_expr **X = B + n * nc;
    for (size_t i = 0; i < n; i++) {
        for (size_t c = 0; c < nx; c++)
            B[i * nc + c] = qd_int(ctx, i == c);
        B[i * nc + nx] = qd_neg(ctx, d->p0[i]);
    }
    qd_status st = qd__spd_dag_solve(ctx, d->model, n, d->P, nc, B, X);
    for (size_t j = 0; st == QD_OK && j < n; j++) {
        const qd_expr *kin = e->w[j] = X[j * nc + nx];
        for (size_t r = 0; r < nx; r++) {
            d->Pinv[j * n + r] = X[j * nc + r];
            if (r < m) {
                e->W[j * m + r] = X[j * nc + r];
                kin = qd_add(ctx, qd_mul(ctx, X[j * nc + r], e->u[r]), kin);
            }
        }
        if (!(e->kin[j] = kin))
            st = QD_ERR_NOMEM;
    }
    qd__free(B);
    return st;
}
