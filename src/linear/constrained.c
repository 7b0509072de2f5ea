/*
 * src/linear/constrained.c - equilibria and small oscillations on the
 * manifold of holonomic constraints kept with multipliers (see
 * qdot/constrained.h for the reduction and its formula).
 *
 * One compiled program gives, at q with q' = 0: F = f(q, 0), J = dF/dq,
 * Bv = df/dq', M, the constraint rows A, their derivatives dA_kj/dq_i and
 * phi; all exact (qd_diff on the equations' entries, small systems).  The
 * dense solves are Gaussian elimination with partial pivoting, the choice
 * of dependent coordinates a column-pivoted Gram-Schmidt QR of A.
 */
#include "linear.h"
#include "qdot/constrained.h"

#include "num/num.h"
#include "base/mem.h"
#include "../base/args.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct cw {
    qd_ctx *ctx;
    size_t n, c;
    qd_prog *prog;
    size_t nin;
    const qd_expr **inputs;
    size_t *qslot;
    double *in, *out;
} cw;

/* offsets into cw.out */
static size_t oF(const cw *w) { (void)w; return 0; }
static size_t oJ(const cw *w) { return w->n; }
static size_t oB(const cw *w) { return w->n + w->n * w->n; }
static size_t oM(const cw *w) { return w->n + 2 * w->n * w->n; }
static size_t oA(const cw *w) { return w->n + 3 * w->n * w->n; }
static size_t oH(const cw *w) { return oA(w) + w->c * w->n; }
static size_t oP(const cw *w) { return oH(w) + w->c * w->n * w->n; }
static size_t nout(const cw *w) { return oP(w) + w->c; }

static void cw_free(cw *w) {
    qd_prog_free(w->prog);
    qd__free(w->inputs);
    qd__free(w->qslot);
    qd__free(w->in);
    qd__free(w->out);
    memset(w, 0, sizeof *w);
}

static qd_status supported(qd_ctx *ctx, const qd_eom *e) {
    for (size_t k = 0; k < e->ncon; k++) {
        const qd_con *c = &e->con[k];
        if (c->kind != QD_CON_HOLONOMIC) {
            qd_ctx_error(ctx, QD_ERR_UNSUPPORTED,
                         "constraint %s constrains velocities (%s): equilibria and modes on "
                         "the manifold take holonomic constraints only (`qdot linearize` takes "
                         "it: qd_conlin_about)", c->name,
                         c->kind == QD_CON_NONHOLONOMIC ? "nonholonomic" : "Pfaffian");
            return QD_ERR_UNSUPPORTED;
        }
        if (c->a0 && !qd_is_zero(c->a0)) {
            qd_ctx_error(ctx, QD_ERR_UNSUPPORTED,
                         "constraint %s depends on t: a point at rest does not stay on it", c->name);
            return QD_ERR_UNSUPPORTED;
        }
    }
    return QD_OK;
}

static qd_status cw_build(qd_ctx *ctx, const qd_eom *e, const qd_expr **all) {
    size_t n = e->n, c = e->ncon;
    const qd_expr **zeros = qd__malloc(ctx, (n + 1) * sizeof *zeros);
    if (!zeros)
        return QD_ERR_NOMEM;
    for (size_t j = 0; j < n; j++)
        zeros[j] = qd_int(ctx, 0);
    const qd_expr *const *qd = e->qd;
    cw w = {.n = n, .c = c};
    for (size_t j = 0; j < n; j++) {
        const qd_expr *F = qd_subs(ctx, e->f[j], n, qd, zeros);
        all[oF(&w) + j] = F;
        for (size_t k = 0; k < n; k++) {
            all[oJ(&w) + j * n + k] = qd_diff(ctx, F, e->q[k]);
            all[oB(&w) + j * n + k] = qd_subs(ctx, qd_diff(ctx, e->f[j], qd[k]), n, qd, zeros);
            all[oM(&w) + j * n + k] = qd_subs(ctx, e->M[j * n + k], n, qd, zeros);
        }
    }
    for (size_t k = 0; k < c; k++) {
        all[oP(&w) + k] = e->con[k].expr;
        for (size_t j = 0; j < n; j++) {
            const qd_expr *a = qd_subs(ctx, e->con[k].a[j], n, qd, zeros);
            all[oA(&w) + k * n + j] = a;
            for (size_t i = 0; i < n; i++)
                all[oH(&w) + (k * n + j) * n + i] = qd_diff(ctx, a, e->q[i]);
        }
    }
    qd__free(zeros);
    return qd_ctx_status(ctx);
}

static qd_status cw_init(qd_ctx *ctx, const qd_eom *e, cw *w) {
    memset(w, 0, sizeof *w);
    w->ctx = ctx;
    w->n = e->n;
    w->c = e->ncon;
    qd_status st = supported(ctx, e);
    if (st != QD_OK)
        return st;
    size_t no = nout(w);
    const qd_expr **all = qd__calloc(ctx, no + 1, sizeof *all);
    if (!all)
        return QD_ERR_NOMEM;
    st = cw_build(ctx, e, all);
    if (st == QD_OK && (w->inputs = qd__num_inputs(ctx, no, all, &w->nin)))
        w->prog = qd_prog_new(ctx, w->nin, w->inputs, no, all);
    qd__free(all);
    if (st == QD_OK && !w->prog)
        st = qd_ctx_status(ctx) ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    if (st == QD_OK) {
        w->in = qd__calloc(ctx, w->nin + 1, sizeof *w->in);
        w->out = qd__calloc(ctx, no + 1, sizeof *w->out);
        w->qslot = qd__malloc(ctx, (w->n + 1) * sizeof *w->qslot);
        if (!w->in || !w->out || !w->qslot)
            st = QD_ERR_NOMEM;
    }
    for (size_t j = 0; st == QD_OK && j < w->n; j++) {
        w->qslot[j] = SIZE_MAX;
        for (size_t i = 0; i < w->nin; i++)
            if (w->inputs[i] == e->q[j])
                w->qslot[j] = i;
    }
    if (st != QD_OK) {
        if (qd_ctx_status(ctx) == QD_OK)
            qd_ctx_error(ctx, st, "cannot differentiate the constrained equations");
        cw_free(w);
    }
    return st;
}

static void cw_bind(cw *w, size_t nvals, const qd_expr *const *syms, const double *vals) {
    for (size_t i = 0; i < w->nin; i++) {
        w->in[i] = 0;
        for (size_t k = 0; k < nvals; k++)
            if (syms[k] == w->inputs[i]) {
                w->in[i] = vals[k];
                break;
            }
    }
}

static void cw_run(cw *w, const double *q) {
    for (size_t j = 0; j < w->n; j++)
        if (w->qslot[j] != SIZE_MAX)
            w->in[w->qslot[j]] = q[j];
    qd_prog_run(w->prog, w->in, w->out);
}

/* ---- dense helpers ---------------------------------------------------------- */

static double max_abs(size_t n, const double *v) {
    double m = 0;
    for (size_t i = 0; i < n; i++)
        m = fmax(m, fabs(v[i]));
    return m;
}

/* Solve the n*n system a x = b (nrhs columns, b row-major n*nrhs) in place
 * by partial pivoting; false when a pivot is below 1e-13 of a's largest. */
static bool gauss(size_t n, double *a, double *b, size_t nrhs) {
    double big = max_abs(n * n, a);
    for (size_t k = 0; k < n; k++) {
        size_t p = k;
        for (size_t i = k + 1; i < n; i++)
            if (fabs(a[i * n + k]) > fabs(a[p * n + k]))
                p = i;
        if (!(fabs(a[p * n + k]) > 1e-13 * big))
            return false;
        for (size_t j = 0; p != k && j < n; j++) {
            double t = a[k * n + j];
            a[k * n + j] = a[p * n + j];
            a[p * n + j] = t;
        }
        for (size_t j = 0; p != k && j < nrhs; j++) {
            double t = b[k * nrhs + j];
            b[k * nrhs + j] = b[p * nrhs + j];
            b[p * nrhs + j] = t;
        }
        for (size_t i = k + 1; i < n; i++) {
            double f = a[i * n + k] / a[k * n + k];
            for (size_t j = k; j < n; j++)
                a[i * n + j] -= f * a[k * n + j];
            for (size_t j = 0; j < nrhs; j++)
                b[i * nrhs + j] -= f * b[k * nrhs + j];
        }
    }
    for (size_t k = n; k-- > 0;)
        for (size_t j = 0; j < nrhs; j++) {
            double s = b[k * nrhs + j];
            for (size_t i = k + 1; i < n; i++)
                s -= a[k * n + i] * b[i * nrhs + j];
            b[k * nrhs + j] = s / a[k * n + k];
        }
    return true;
}

/* The dependent coordinates: ncon columns of A (c*n) by column-pivoted
 * Gram-Schmidt, the largest remaining column first.  false when A has rank
 * below c (redundant constraints at q). */
static bool choose_dep(size_t c, size_t n, const double *A, bool *isdep, double *work) {
    memset(isdep, 0, n * sizeof *isdep);
    for (size_t j = 0; j < n; j++)
        for (size_t k = 0; k < c; k++)
            work[j * c + k] = A[k * n + j];
    double big = max_abs(c * n, A);
    for (size_t s = 0; s < c; s++) {
        size_t p = SIZE_MAX;
        double best = 0;
        for (size_t j = 0; j < n; j++) {
            double nn = 0;
            for (size_t k = 0; k < c; k++)
                nn += work[j * c + k] * work[j * c + k];
            if (!isdep[j] && sqrt(nn) > best * (1 + 1e-12)) {
                best = sqrt(nn);
                p = j;
            }
        }
        if (p == SIZE_MAX || !(best > 1e-10 * big))
            return false;
        isdep[p] = true;
        for (size_t k = 0; k < c; k++)
            work[p * c + k] /= best;
        for (size_t j = 0; j < n; j++) {
            if (isdep[j])
                continue;
            double d = 0;
            for (size_t k = 0; k < c; k++)
                d += work[j * c + k] * work[p * c + k];
            for (size_t k = 0; k < c; k++)
                work[j * c + k] -= d * work[p * c + k];
        }
    }
    return true;
}

/* lambda minimizing |F + A^T lambda|: (A A^T) lambda = -A F. */
static bool multipliers(size_t c, size_t n, const double *A, const double *F, double *lambda,
                        double *G) {
    for (size_t k = 0; k < c; k++) {
        double s = 0;
        for (size_t j = 0; j < n; j++)
            s += A[k * n + j] * F[j];
        lambda[k] = -s;
        for (size_t l = 0; l < c; l++) {
            double g = 0;
            for (size_t j = 0; j < n; j++)
                g += A[k * n + j] * A[l * n + j];
            G[k * c + l] = g;
        }
    }
    return gauss(c, G, lambda, 1);
}

static double force_res(const cw *w, const double *lambda) {
    size_t n = w->n, c = w->c;
    const double *F = w->out + oF(w), *A = w->out + oA(w);
    double r = 0;
    for (size_t j = 0; j < n; j++) {
        double s = F[j];
        for (size_t k = 0; k < c; k++)
            s += A[k * n + j] * lambda[k];
        r = fmax(r, fabs(s));
    }
    return r;
}

/* The force scale at q: |F| + |J| (1 + |q|), and phi's: |A| (1 + |q|). */
static double fscale(cw *w, const double *q) {
    double s = max_abs(w->n, w->out + oF(w)) +
               max_abs(w->n * w->n, w->out + oJ(w)) * (1 + max_abs(w->n, q));
    return isfinite(s) && s > 0 ? s : 1;
}
static double pscale(cw *w, const double *q) {
    double s = max_abs(w->c * w->n, w->out + oA(w)) * (1 + max_abs(w->n, q));
    return isfinite(s) && s > 0 ? s : 1;
}

/* ---- onto the manifold -------------------------------------------------------- */

/* Newton on phi = 0 moving only the coordinates with isdep (NULL: every
 * coordinate, minimum-norm steps).  true when |phi| <= 1e-13 of its scale. */
static bool project(cw *w, double *q, const bool *isdep, double *work) {
    size_t n = w->n, c = w->c;
    double *G = work, *d = work + c * c, *Ad = d + c;
    for (int it = 0; it < 60; it++) {
        cw_run(w, q);
        const double *A = w->out + oA(w), *P = w->out + oP(w);
        if (!isfinite(max_abs(c, P)))
            return false;
        if (max_abs(c, P) <= 1e-13 * pscale(w, q))
            return true;
        if (isdep) {
            size_t m = 0;
            for (size_t j = 0; j < n; j++)
                if (isdep[j]) {
                    for (size_t k = 0; k < c; k++)
                        Ad[k * c + m] = A[k * n + j];
                    m++;
                }
            for (size_t k = 0; k < c; k++)
                d[k] = -P[k];
            if (!gauss(c, Ad, d, 1))
                return false;
            m = 0;
            for (size_t j = 0; j < n; j++)
                if (isdep[j])
                    q[j] += d[m++];
        } else {
            for (size_t k = 0; k < c; k++) {
                d[k] = -P[k];
                for (size_t l = 0; l < c; l++) {
                    double g = 0;
                    for (size_t j = 0; j < n; j++)
                        g += A[k * n + j] * A[l * n + j];
                    G[k * c + l] = g;
                }
            }
            if (!gauss(c, G, d, 1))
                return false;
            for (size_t j = 0; j < n; j++)
                for (size_t k = 0; k < c; k++)
                    q[j] += A[k * n + j] * d[k];
        }
    }
    return false;
}

/* Damped Newton on R = (F + A^T lambda, phi) in (q, lambda).  true when
 * |F + A^T lambda| <= ftol and |phi| <= ptol. */
static bool newton(cw *w, double *q, double *lambda, double ftol, double ptol, double *work,
                   double *res) {
    size_t n = w->n, c = w->c, N = n + c;
    double *Jm = work, *R = Jm + N * N, *q1 = R + N, *l1 = q1 + n;
    double norm = INFINITY;
    for (int it = 0; it < 100; it++) {
        cw_run(w, q);
        const double *F = w->out + oF(w), *J = w->out + oJ(w), *A = w->out + oA(w),
                     *H = w->out + oH(w), *P = w->out + oP(w);
        double fr = force_res(w, lambda), pr = max_abs(c, P);
        *res = fr;
        if (!isfinite(fr) || !isfinite(pr))
            return false;
        if (fr <= ftol && pr <= ptol)
            return true;
        norm = fr / ftol + pr / ptol;
        for (size_t j = 0; j < n; j++) {
            double s = F[j];
            for (size_t k = 0; k < c; k++)
                s += A[k * n + j] * lambda[k];
            R[j] = -s;
            for (size_t i = 0; i < n; i++) {
                double h = J[j * n + i];
                for (size_t k = 0; k < c; k++)
                    h += lambda[k] * H[(k * n + j) * n + i];
                Jm[j * N + i] = h;
            }
            for (size_t k = 0; k < c; k++)
                Jm[j * N + n + k] = A[k * n + j];
        }
        for (size_t k = 0; k < c; k++) {
            R[n + k] = -P[k];
            for (size_t i = 0; i < n; i++)
                Jm[(n + k) * N + i] = A[k * n + i];
            for (size_t l = 0; l < c; l++)
                Jm[(n + k) * N + n + l] = 0;
        }
        if (!gauss(N, Jm, R, 1))
            return false;
        /* halve the step until the scaled residual falls */
        double t = 1;
        for (int h = 0; h < 30; h++, t /= 2) {
            for (size_t j = 0; j < n; j++)
                q1[j] = q[j] + t * R[j];
            for (size_t k = 0; k < c; k++)
                l1[k] = lambda[k] + t * R[n + k];
            cw_run(w, q1);
            double nn = force_res(w, l1) / ftol + max_abs(c, w->out + oP(w)) / ptol;
            if (isfinite(nn) && nn < norm)
                break;
        }
        memcpy(q, q1, n * sizeof *q);
        memcpy(lambda, l1, c * sizeof *lambda);
    }
    cw_run(w, q);
    *res = force_res(w, lambda);
    return *res <= ftol && max_abs(c, w->out + oP(w)) <= ptol;
}

/* ---- the reduction ---------------------------------------------------------- */

/* T (n*r) from the dependent set at the current run; false when A_D is
 * singular. */
static bool tangent(cw *w, const size_t *indep, const size_t *dep, size_t r, double *T,
                    double *work) {
    size_t n = w->n, c = w->c;
    const double *A = w->out + oA(w);
    double *Ad = work, *rhs = work + c * c;
    for (size_t k = 0; k < c; k++) {
        for (size_t l = 0; l < c; l++)
            Ad[k * c + l] = A[k * n + dep[l]];
        for (size_t i = 0; i < r; i++)
            rhs[k * r + i] = -A[k * n + indep[i]];
    }
    if (c && r && !gauss(c, Ad, rhs, r))
        return false;
    memset(T, 0, n * r * sizeof *T);
    for (size_t i = 0; i < r; i++)
        T[indep[i] * r + i] = 1;
    for (size_t l = 0; l < c; l++)
        for (size_t i = 0; i < r; i++)
            T[dep[l] * r + i] = rhs[l * r + i];
    return true;
}

/* out = T^T X T for X n*n (row-major), out r*r. */
static void congruent(size_t n, size_t r, const double *T, const double *X, double *out) {
    for (size_t a = 0; a < r; a++)
        for (size_t b = 0; b < r; b++) {
            double s = 0;
            for (size_t i = 0; i < n; i++)
                for (size_t j = 0; j < n; j++)
                    s += T[i * r + a] * X[i * n + j] * T[j * r + b];
            out[a * r + b] = s;
        }
}

/* The reduced M, C, G, K at the current run, lambda given. */
static qd_status reduce(qd_ctx *ctx, cw *w, const double *lambda, const double *T, size_t r,
                        qd_linear *lin) {
    size_t n = w->n, c = w->c, rr = r * r;
    const double *J = w->out + oJ(w), *Bv = w->out + oB(w), *M = w->out + oM(w),
                 *H = w->out + oH(w);
    double *X = qd__malloc(ctx, (n * n + 1) * sizeof *X), *Y = qd__malloc(ctx, (rr + 1) * sizeof *Y);
    lin->n = r;
    lin->M = qd__malloc(ctx, (rr + 1) * sizeof *lin->M);
    lin->C = qd__malloc(ctx, (rr + 1) * sizeof *lin->C);
    lin->G = qd__malloc(ctx, (rr + 1) * sizeof *lin->G);
    lin->K = qd__malloc(ctx, (rr + 1) * sizeof *lin->K);
    if (!X || !Y || !lin->M || !lin->C || !lin->G || !lin->K) {
        qd__free(X);
        qd__free(Y);
        return QD_ERR_NOMEM;
    }
    congruent(n, r, T, M, lin->M);
    for (size_t j = 0; j < n; j++) /* K - sum lambda_k Hess phi_k = -d(F + A^T lambda)/dq */
        for (size_t i = 0; i < n; i++) {
            double h = J[j * n + i];
            for (size_t k = 0; k < c; k++)
                h += lambda[k] * H[(k * n + j) * n + i];
            X[j * n + i] = -h;
        }
    congruent(n, r, T, X, lin->K);
    for (size_t a = 0; a < r; a++) /* K_r is symmetric up to round-off for a potential */
        for (size_t b = a + 1; b < r; b++) {
            double s = lin->K[a * r + b], t = lin->K[b * r + a];
            if (fabs(s - t) <= 1e-12 * (fabs(s) + fabs(t)))
                lin->K[a * r + b] = lin->K[b * r + a] = (s + t) / 2;
        }
    congruent(n, r, T, Bv, Y);
    for (size_t a = 0; a < r; a++)
        for (size_t b = 0; b < r; b++) {
            lin->C[a * r + b] = -(Y[a * r + b] + Y[b * r + a]) / 2;
            lin->G[a * r + b] = -(Y[a * r + b] - Y[b * r + a]) / 2;
        }
    qd__free(X);
    qd__free(Y);
    for (size_t i = 0; i < rr; i++)
        if (!isfinite(lin->M[i]) || !isfinite(lin->K[i]) || !isfinite(lin->C[i]) ||
            !isfinite(lin->G[i])) {
            qd_ctx_error(ctx, QD_ERR_NUMERIC, "the reduced equations are not finite at this "
                                              "point (a singularity of the model)");
            return QD_ERR_NUMERIC;
        }
    return QD_OK;
}

void qd_constrained_linear_free(qd_constrained_linear *c) {
    if (!c)
        return;
    qd__free(c->q);
    qd__free(c->lambda);
    qd__free(c->indep);
    qd__free(c->dep);
    qd__free(c->T);
    qd_linear_free(&c->lin);
    memset(c, 0, sizeof *c);
}

static qd_status about_alloc(qd_ctx *ctx, size_t n, size_t c, qd_constrained_linear *out) {
    size_t r = n - c;
    *out = (qd_constrained_linear){.n = n, .ncon = c, .r = r};
    out->q = qd__calloc(ctx, n + 1, sizeof *out->q);
    out->lambda = qd__calloc(ctx, c + 1, sizeof *out->lambda);
    out->indep = qd__calloc(ctx, r + 1, sizeof *out->indep);
    out->dep = qd__calloc(ctx, c + 1, sizeof *out->dep);
    out->T = qd__calloc(ctx, n * r + 1, sizeof *out->T);
    return out->q && out->lambda && out->indep && out->dep && out->T ? QD_OK : QD_ERR_NOMEM;
}

/* The dependent set: the caller's complement, else the QR choice at q. */
static qd_status dependent_set(qd_ctx *ctx, cw *w, const qd_eom *e, const size_t *indep,
                               bool *isdep, double *work) {
    size_t n = w->n, c = w->c;
    if (indep) {
        for (size_t j = 0; j < n; j++)
            isdep[j] = true;
        for (size_t i = 0; i < n - c; i++) {
            if (indep[i] >= n || !isdep[indep[i]]) {
                qd_ctx_error(ctx, QD_ERR_ARG, "the independent coordinates must be %zu distinct "
                                              "coordinates of the model", n - c);
                return QD_ERR_ARG;
            }
            isdep[indep[i]] = false;
        }
        return QD_OK;
    }
    if (!choose_dep(c, n, w->out + oA(w), isdep, work)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the %zu constraint%s are not independent at this point "
                                      "(the constraint Jacobian has rank below %zu)", c,
                     c == 1 ? "" : "s", c);
        return QD_ERR_ARG;
    }
    (void)e;
    return QD_OK;
}

qd_status qd_constrained_linear_about(qd_ctx *ctx, const qd_eom *e, size_t nvals,
                                      const qd_expr *const *syms, const double *vals,
                                      const size_t *indep, qd_constrained_linear *out) {
    QD_ARGS_CTX(ctx, ctx && e && (nvals == 0 || syms) && (nvals == 0 || vals) && out);
    memset(out, 0, sizeof *out);
    if (e->ncon == 0 || e->ncon >= e->n) {
        qd_ctx_error(ctx, QD_ERR_ARG, e->ncon ? "the constraints leave no degree of freedom"
                                              : "the model keeps no constraints: use "
                                                "qd_linear_about");
        return QD_ERR_ARG;
    }
    size_t n = e->n, c = e->ncon, r = n - c, N = n + c;
    cw w;
    qd_status st = cw_init(ctx, e, &w);
    if (st != QD_OK)
        return st;
    bool *isdep = qd__calloc(ctx, n + 1, sizeof *isdep);
    double *work = qd__malloc(ctx, (N * N + 4 * N + n * n + 1) * sizeof *work);
    st = isdep && work ? about_alloc(ctx, n, c, out) : QD_ERR_NOMEM;
    if (st != QD_OK)
        goto done;
    cw_bind(&w, nvals, syms, vals);
    for (size_t j = 0; j < n; j++)
        out->q[j] = w.qslot[j] == SIZE_MAX ? 0 : w.in[w.qslot[j]];
    cw_run(&w, out->q);
    st = dependent_set(ctx, &w, e, indep, isdep, work);
    if (st != QD_OK)
        goto done;
    if (!project(&w, out->q, isdep, work)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "cannot put the point on the constraints by moving the "
                                      "dependent coordinates (give a point near the constraint "
                                      "manifold, or other independent coordinates)");
        st = QD_ERR_ARG;
        goto done;
    }
    cw_run(&w, out->q);
    if (!indep) /* the choice at the point itself */
        (void)choose_dep(c, n, w.out + oA(&w), isdep, work);
    for (size_t j = 0, a = 0, b = 0; j < n; j++) {
        if (isdep[j])
            out->dep[b++] = j;
        else
            out->indep[a++] = j;
    }
    if (!multipliers(c, n, w.out + oA(&w), w.out + oF(&w), out->lambda, work) ||
        !tangent(&w, out->indep, out->dep, r, out->T, work)) {
        char better[256] = "";
        if (choose_dep(c, n, w.out + oA(&w), isdep, work))
            for (size_t j = 0, used = 0; j < n && used < sizeof better; j++)
                if (!isdep[j])
                    used += (size_t)snprintf(better + used, sizeof better - used, "%s%s",
                                             used ? ", " : "", qd_expr_name(e->q[j]));
        qd_ctx_error(ctx, QD_ERR_ARG, "the dependent coordinates do not determine the "
                                      "constraints at this point (their columns of the "
                                      "constraint Jacobian are singular there): choose other "
                                      "independent coordinates%s%s", better[0] ? ", e.g. " : "",
                     better);
        st = QD_ERR_ARG;
        goto done;
    }
    out->phi_res = max_abs(c, w.out + oP(&w));
    out->force_res = force_res(&w, out->lambda);
    double scale = fscale(&w, out->q);
    if (!(out->force_res <= 1e-8 * scale)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the point is not an equilibrium on the constraints: "
                                      "|F + A^T lambda| = %.3g (force scale %.3g); linearize "
                                      "on the manifold about an equilibrium", out->force_res,
                     scale);
        st = QD_ERR_ARG;
        goto done;
    }
    st = reduce(ctx, &w, out->lambda, out->T, r, &out->lin);
done:
    if (st != QD_OK && qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, st, "out of memory reducing onto the constraints");
    qd__free(isdep);
    qd__free(work);
    cw_free(&w);
    return st;
}

qd_status qd_constrained_state_matrix(qd_ctx *ctx, const qd_constrained_linear *c, double *A) {
    QD_ARGS_CTX(ctx, ctx && c && A);
    size_t r = c->r, N = 2 * r;
    double *Mc = qd__malloc(ctx, (r * r + 1) * sizeof *Mc);
    double *rhs = qd__malloc(ctx, (r * N + 1) * sizeof *rhs);
    if (!Mc || !rhs) {
        qd__free(Mc);
        qd__free(rhs);
        return QD_ERR_NOMEM;
    }
    memcpy(Mc, c->lin.M, r * r * sizeof *Mc);
    for (size_t a = 0; a < r; a++)
        for (size_t b = 0; b < r; b++) {
            rhs[a * N + b] = -c->lin.K[a * r + b];
            rhs[a * N + r + b] = -(c->lin.C[a * r + b] + c->lin.G[a * r + b]);
        }
    bool ok = gauss(r, Mc, rhs, N);
    if (ok) {
        memset(A, 0, N * N * sizeof *A);
        for (size_t a = 0; a < r; a++) {
            A[a * N + r + a] = 1;
            memcpy(A + (r + a) * N, rhs + a * N, N * sizeof *A);
        }
    } else
        qd_ctx_error(ctx, QD_ERR_SINGULAR, "the reduced mass matrix is singular");
    qd__free(Mc);
    qd__free(rhs);
    return ok ? QD_OK : QD_ERR_SINGULAR;
}

qd_status qd_constrained_input_matrix(qd_ctx *ctx, const qd_eom *e,
                                      const qd_constrained_linear *c, size_t nu,
                                      const qd_expr *const *u, size_t nvals,
                                      const qd_expr *const *syms, const double *vals,
                                      double *B) {
    QD_ARGS_CTX(ctx, ctx && e && c && (nu == 0 || u) && (nvals == 0 || syms) &&
                         (nvals == 0 || vals) && (nu == 0 || B));
    size_t n = e->n, r = c->r, no = n * nu;
    if (nu == 0)
        return QD_OK;
    if (c->n != n) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the reduction is not of these equations");
        return QD_ERR_ARG;
    }
    const qd_expr **d = qd__calloc(ctx, no + 2 * n + 1, sizeof *d), **zeros = d + no;
    double *in = NULL, *out = qd__calloc(ctx, no + r * nu + 1, sizeof *out);
    const qd_expr **ins = NULL;
    size_t nin = 0;
    qd_prog *prog = NULL;
    qd_status st = d && out ? QD_OK : QD_ERR_NOMEM;
    for (size_t j = 0; st == QD_OK && j < n; j++)
        zeros[j] = qd_int(ctx, 0);
    for (size_t j = 0; st == QD_OK && j < n; j++)
        for (size_t k = 0; k < nu; k++)
            d[j * nu + k] = qd_subs(ctx, qd_diff(ctx, e->f[j], u[k]), n,
                                    (const qd_expr *const *)e->qd, zeros);
    if (st == QD_OK && (st = qd_ctx_status(ctx)) == QD_OK &&
        (ins = qd__num_inputs(ctx, no, d, &nin)))
        prog = qd_prog_new(ctx, nin, ins, no, d);
    if (st == QD_OK && !prog)
        st = qd_ctx_status(ctx) ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    if (st == QD_OK && !(in = qd__calloc(ctx, nin + 1, sizeof *in)))
        st = QD_ERR_NOMEM;
    for (size_t i = 0; st == QD_OK && i < nin; i++) {
        for (size_t k = 0; k < nvals; k++)
            if (syms[k] == ins[i]) {
                in[i] = vals[k];
                break;
            }
        for (size_t j = 0; j < n; j++) /* the point on the manifold */
            if (ins[i] == e->q[j])
                in[i] = c->q[j];
    }
    if (st == QD_OK) {
        qd_prog_run(prog, in, out);
        double *X = out + no, *Mc = NULL;
        for (size_t a = 0; a < r; a++) /* T^T df/du */
            for (size_t k = 0; k < nu; k++) {
                double s = 0;
                for (size_t j = 0; j < n; j++)
                    s += c->T[j * r + a] * out[j * nu + k];
                X[a * nu + k] = s;
            }
        if (!(Mc = qd__malloc(ctx, (r * r + 1) * sizeof *Mc)))
            st = QD_ERR_NOMEM;
        else {
            memcpy(Mc, c->lin.M, r * r * sizeof *Mc);
            if (!gauss(r, Mc, X, nu)) {
                qd_ctx_error(ctx, QD_ERR_SINGULAR, "the reduced mass matrix is singular");
                st = QD_ERR_SINGULAR;
            }
        }
        qd__free(Mc);
        if (st == QD_OK) {
            memset(B, 0, 2 * r * nu * sizeof *B);
            memcpy(B + r * nu, X, r * nu * sizeof *B);
            for (size_t i = 0; i < 2 * r * nu; i++)
                if (!isfinite(B[i])) {
                    qd_ctx_error(ctx, QD_ERR_NUMERIC, "the input matrix is not finite here");
                    st = QD_ERR_NUMERIC;
                    break;
                }
        }
    }
    if (st != QD_OK && qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, st, "out of memory forming the input matrix");
    qd_prog_free(prog);
    qd__free(ins);
    qd__free(in);
    qd__free(out);
    qd__free(d);
    return st;
}

/* ---- equilibria ---------------------------------------------------------------- */


/* Classify the root at q: K_r's eigenvalue signs. */
static qd_status classify(qd_ctx *ctx, cw *w, const double *q, qd_equilibrium *p, double *work) {
    size_t n = w->n, c = w->c, r = n - c;
    bool *isdep = qd__calloc(ctx, n + 1, sizeof *isdep);
    size_t *ix = qd__malloc(ctx, (n + 1) * sizeof *ix);
    double *lambda = qd__calloc(ctx, c + 1, sizeof *lambda);
    double *T = qd__calloc(ctx, n * r + 1, sizeof *T), *ev = qd__calloc(ctx, r + 1, sizeof *ev);
    qd_linear lin = {0};
    qd_status st = isdep && ix && lambda && T && ev ? QD_OK : QD_ERR_NOMEM;
    if (st == QD_OK) {
        cw_run(w, q);
        if (!choose_dep(c, n, w->out + oA(w), isdep, work) ||
            !multipliers(c, n, w->out + oA(w), w->out + oF(w), lambda, work))
            st = QD_ERR_NUMERIC;
    }
    if (st == QD_OK) {
        for (size_t j = 0, a = 0, b = r; j < n; j++)
            ix[isdep[j] ? b++ : a++] = j;
        p->residual = force_res(w, lambda);
        if (!tangent(w, ix, ix + r, r, T, work))
            st = QD_ERR_NUMERIC;
    }
    if (st == QD_OK)
        st = reduce(ctx, w, lambda, T, r, &lin);
    if (st == QD_OK) {
        p->symmetric = true;
        for (size_t a = 0; a < r; a++)
            for (size_t b = 0; b < r; b++)
                if (fabs(lin.K[a * r + b] - lin.K[b * r + a]) >
                    1e-9 * (fabs(lin.K[a * r + b]) + fabs(lin.K[b * r + a]) + 1e-300))
                    p->symmetric = false;
        /* K_r a = s M_r a: the signs of K_r relative to the mass, as the
         * unconstrained classification reads the Hessian */
        if (!qd__lin_sym_eig(ctx, r, lin.K, ev, NULL))
            st = QD_ERR_NUMERIC;
    }
    if (st == QD_OK) {
        qd__lin_eq_classify(r, ev, p);
    }
    qd_linear_free(&lin);
    qd__free(isdep);
    qd__free(ix);
    qd__free(lambda);
    qd__free(T);
    qd__free(ev);
    return st;
}

static void sort_points(size_t n, qd_equilibria *out) {
    for (size_t i = 1; i < out->count; i++) /* insertion sort, lexicographic in q */
        for (size_t k = i; k > 0; k--) {
            qd_equilibrium *x = &out->pts[k - 1], *y = &out->pts[k];
            size_t j = 0;
            while (j < n && fabs(x->q[j] - y->q[j]) <= 1e-9 * (1 + fabs(x->q[j])))
                j++;
            if (j == n || x->q[j] < y->q[j])
                break;
            qd_equilibrium t = *x;
            *x = *y;
            *y = t;
        }
}

static qd_status search(cw *w, const double *lo, const double *hi, const double *near,
                        size_t starts, qd__roots *roots, double *work) {
    size_t n = w->n, c = w->c, N = n + c;
    double *q = work, *lambda = q + n, *sub = lambda + c;
    for (size_t s = 0; s < (near ? 1 : starts); s++) {
        if (!near && qd__ctx_progress(w->ctx, "equilibria: multistart", s, starts)) {
            qd_ctx_error(w->ctx, QD_ERR_ARG, "the search for equilibria was stopped after %zu "
                         "of %zu starts", s, starts);
            return QD_ERR_ARG;
        }
        for (size_t j = 0; j < n; j++)
            q[j] = near ? near[j]
                        : lo[j] + (hi[j] - lo[j]) * qd__lin_halton(s + 1, qd__lin_halton_primes[j % 16]);
        if (!project(w, q, NULL, sub))
            continue;
        cw_run(w, q);
        double ftol = 1e-11 * fscale(w, q), ptol = 1e-13 * pscale(w, q), res;
        if (!multipliers(c, n, w->out + oA(w), w->out + oF(w), lambda, sub))
            continue;
        if (newton(w, q, lambda, ftol, ptol, sub, &res)) {
            for (size_t j = 0; j < n; j++)
                if (fabs(q[j]) < 1e-15 * (1 + max_abs(n, q)))
                    q[j] = 0;
            if (!qd__lin_roots_add(w->ctx, roots, q, res, NULL))
                return QD_ERR_NOMEM;
        }
    }
    (void)N;
    if (!near)
        qd__ctx_progress(w->ctx, "equilibria: multistart", starts, starts);
    return QD_OK;
}

qd_status qd_constrained_equilibria_find(qd_ctx *ctx, const qd_eom *e, const qd_model *m,
                                         size_t nvals, const qd_expr *const *syms,
                                         const double *vals, const qd_equilibria_opts *opts,
                                         qd_equilibria *out) {
    QD_ARGS_CTX(ctx, ctx && e && m && (nvals == 0 || syms) && (nvals == 0 || vals) && out);
    memset(out, 0, sizeof *out);
    qd_equilibria_opts o = opts ? *opts : (qd_equilibria_opts){0};
    size_t n = e->n, c = e->ncon, N = n + c;
    out->n = n;
    if (c == 0 || c >= n) {
        qd_ctx_error(ctx, QD_ERR_ARG, c ? "the constraints leave no degree of freedom"
                                        : "the model keeps no constraints");
        return QD_ERR_ARG;
    }
    cw w;
    qd_status st = cw_init(ctx, e, &w);
    if (st != QD_OK)
        return st;
    cw_bind(&w, nvals, syms, vals);
    bool *angle = qd__calloc(ctx, n + 1, sizeof *angle);
    double *lo = qd__malloc(ctx, (n + 1) * sizeof *lo), *hi = qd__malloc(ctx, (n + 1) * sizeof *hi);
    double *work = qd__malloc(ctx, (2 * N * N + 8 * N + n * n + 1) * sizeof *work);
    qd__roots roots = {.n = n};
    if (!angle || !lo || !hi || !work) {
        st = QD_ERR_NOMEM;
        goto done;
    }
    if ((st = qd__lin_eq_box(ctx, e, m, &o, angle, lo, hi)) != QD_OK)
        goto done;
    out->method = o.near ? "newton" : o.no_search ? "none" : "multistart";
    st = search(&w, lo, hi, o.near, o.no_search ? 0 : o.starts ? o.starts : 40 * n + 40, &roots,
                work);
    if (st == QD_OK && o.near && roots.count == 0) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "no convergence: Newton's method on the constraint "
                                          "manifold from the guess found no equilibrium");
        st = QD_ERR_NUMERIC;
    }
    if (st == QD_OK && roots.count) {
        out->pts = qd__calloc(ctx, roots.count, sizeof *out->pts);
        if (!out->pts)
            st = QD_ERR_NOMEM;
    }
    for (size_t i = 0; st == QD_OK && i < roots.count; i++) {
        qd_equilibrium *p = &out->pts[out->count];
        if (!(p->q = qd__malloc(ctx, (n + 1) * sizeof *p->q))) {
            st = QD_ERR_NOMEM;
            break;
        }
        memcpy(p->q, roots.q + i * n, n * sizeof *p->q);
        out->count++;
        st = classify(ctx, &w, p->q, p, work);
        if (st == QD_ERR_NUMERIC) /* no tangent space there: the constraints degenerate */
            st = QD_OK, p->kind = QD_EQ_DEGENERATE, p->nzero = n - c;
    }
    if (st == QD_OK)
        sort_points(n, out);
done:
    if (st != QD_OK && qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, st, st == QD_ERR_NOMEM ? "out of memory finding equilibria"
                                                 : "finding equilibria failed");
    if (st != QD_OK)
        qd_equilibria_free(out);
    qd__lin_roots_free(&roots);
    qd__free(angle);
    qd__free(lo);
    qd__free(hi);
    qd__free(work);
    cw_free(&w);
    return st;
}
