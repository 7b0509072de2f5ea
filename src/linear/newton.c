/*
 * src/linear/newton.c - F(q) = 0 by damped Newton steps.
 *
 * Levenberg-Marquardt: (J^T J + lambda diag(J^T J)) d = -J^T F, lambda
 * lowered after a step that reduces |F| and raised after one that does
 * not.  Near a regular root it is Newton's method (quadratic convergence);
 * far from one, or where J is singular (a continuum of equilibria, a
 * symmetric configuration), it still takes descent steps instead of
 * jumping across the configuration space as a bare Newton or secant step
 * does (seed-desloge-B.md pitfall 8: a secant from a naive guess jumped
 * from L1 to L2).
 */
#include "linear.h"

#include "num/num.h"
#include "base/mem.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Steps between the stall checks of qd__lin_lm_solve. */
#define STALL_STEPS 20

static double max_abs(size_t n, const double *v) {
    double m = 0;
    for (size_t i = 0; i < n; i++)
        m = fmax(m, fabs(v[i]));
    return m;
}

static double norm2sq(size_t n, const double *v) {
    double s = 0;
    for (size_t i = 0; i < n; i++)
        s += v[i] * v[i];
    return s;
}

static bool all_finite(size_t n, const double *v) {
    for (size_t i = 0; i < n; i++)
        if (!isfinite(v[i]))
            return false;
    return true;
}

double qd__lin_scale(qd__lin *L, const double *q) {
    size_t n = L->n;
    qd__lin_run(L, q);
    const double *F = qd__lin_F(L), *J = qd__lin_J(L);
    double s = max_abs(n, F) + qd__num_norm_inf(n, J) * (1 + max_abs(n, q));
    return isfinite(s) ? s : INFINITY;
}

bool qd__lin_lm_solve(qd__lin *L, double *q, double ftol, int maxit, double *res) {
    size_t n = L->n;
    double *F = qd__malloc(L->ctx, (n + 1) * sizeof *F), *J = qd__malloc(L->ctx, (n * n + 1) * sizeof *J);
    double *A = qd__malloc(L->ctx, (n * n + 1) * sizeof *A), *g = qd__malloc(L->ctx, (n + 1) * sizeof *g);
    double *t = qd__malloc(L->ctx, (n + 1) * sizeof *t);
    /* J^T J and -J^T F at q, kept while q stays (a refused step, a raised lambda) */
    double *A0 = qd__malloc(L->ctx, (n * n + 1) * sizeof *A0), *g0 = qd__malloc(L->ctx, (n + 1) * sizeof *g0);
    size_t *pc = qd__malloc(L->ctx, (n + 1) * sizeof *pc);
    bool ok = false, fresh = false;
    *res = INFINITY;
    if (!F || !J || !A || !g || !t || !A0 || !g0 || !pc)
        goto done;
    qd__lin_run(L, q);
    memcpy(F, qd__lin_F(L), n * sizeof *F);
    memcpy(J, qd__lin_J(L), n * n * sizeof *J);
    if (!all_finite(n, F) || !all_finite(n * n, J))
        goto done;
    double lambda = 1e-3, f2 = norm2sq(n, F), f2_mark = f2;
    for (int it = 0; it < maxit; it++) {
        *res = max_abs(n, F);
        if (*res <= ftol) {
            ok = true;
            break;
        }
        /* No progress at all in STALL_STEPS steps, far from a root: the run sits in
         * a local minimum of |F|^2 and would spend the rest of maxit there (on 16
         * coupled pendulums 85% of the multistart's runs did, at |F|^2 ~ 30-300,
         * 200 steps each; the runs that converge took at most 16).  A degenerate
         * root still gains a fixed factor a step, so it is not cut; ftol 0 (polish
         * to the end) is never cut (issue 34). */
        if (ftol > 0 && it > 0 && it % STALL_STEPS == 0) {
            if (*res > 1e3 * ftol && f2 > (1 - 1e-4) * f2_mark)
                break;
            f2_mark = f2;
        }
        /* g = -J^T F and A = J^T J by rows of J (each sum still in the order of k,
         * so the same numbers as column by column), the upper triangle mirrored:
         * a third of the time of the strided loops at n = 100; and once per point,
         * not again after each refused step (issue 34) */
        if (!fresh) {
            memset(g0, 0, n * sizeof *g0);
            memset(A0, 0, n * n * sizeof *A0);
            for (size_t k = 0; k < n; k++) {
                const double *row = J + k * n;
                for (size_t i = 0; i < n; i++) {
                    double jki = row[i], *Ai = A0 + i * n;
                    g0[i] -= jki * F[k];
                    for (size_t j = i; j < n; j++)
                        Ai[j] += jki * row[j];
                }
            }
            for (size_t i = 0; i < n; i++)
                for (size_t j = i + 1; j < n; j++)
                    A0[j * n + i] = A0[i * n + j];
            fresh = true;
        }
        memcpy(g, g0, n * sizeof *g);
        memcpy(A, A0, n * n * sizeof *A);
        /* the step in coordinates scaled by sqrt(diag(J^T J)) (Marquardt's scaling,
         * t holding the scales), the damping's floor 1e-12 of the scaled diagonal:
         * near a degenerate root, F ~ x^5 of (1 - cos x)^3 beside a y^2, J^T J's
         * x entry falls below any absolute floor and below the solve's relative
         * rank tolerance against the y entry, and the steps stalled on the
         * plateau |F| < ftol (issue 33) */
        for (size_t i = 0; i < n; i++)
            t[i] = A[i * n + i] > 0 && isfinite(A[i * n + i]) ? sqrt(A[i * n + i]) : 1;
        for (size_t i = 0; i < n; i++) {
            g[i] /= t[i];
            for (size_t j = 0; j < n; j++)
                A[i * n + j] /= t[i] * t[j];
        }
        for (size_t i = 0; i < n; i++)
            A[i * n + i] += lambda * (A[i * n + i] + 1e-12 * (1 + A[i * n + i]));
        if (qd__num_rank(n, A, g, 1e-15, pc, NULL, NULL) < n) {
            lambda *= 10;
            continue;
        }
        for (size_t i = 0; i < n; i++)
            g[i] /= t[i];
        for (size_t i = 0; i < n; i++)
            t[i] = q[i] + g[i];
        qd__lin_run(L, t);
        const double *Ft = qd__lin_F(L);
        double ft2 = norm2sq(n, Ft);
        if (all_finite(n, Ft) && all_finite(n * n, qd__lin_J(L)) && ft2 < f2) {
            memcpy(q, t, n * sizeof *q);
            memcpy(F, Ft, n * sizeof *F);
            memcpy(J, qd__lin_J(L), n * n * sizeof *J);
            f2 = ft2;
            fresh = false;
            lambda = fmax(lambda / 4, 1e-12);
        } else {
            lambda *= 8;
            if (lambda > 1e16)
                break;
        }
    }
    *res = max_abs(n, F);
    ok = *res <= ftol;
done:
    qd__free(F);
    qd__free(J);
    qd__free(A);
    qd__free(g);
    qd__free(t);
    qd__free(A0);
    qd__free(g0);
    qd__free(pc);
    return ok;
}
