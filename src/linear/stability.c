/*
 * src/linear/stability.c - the stability of a steady motion: the reduced
 * equations M x'' = f linearized about it, and the verdicts.
 *
 * With x' = 0 at the steady motion, M x'' = f(x0 + dx, dx') gives
 *     M0 dx'' + B dx' + K0 dx = 0,   B = -df/dx',  K0 = -df/dx,
 * B's symmetric part is the damping C0 (from the dissipation function),
 * its skew part the gyroscopic G0 (from the Routhian's R1, or from T1 and the
 * Coriolis terms of a driven rotation).  The eigen-analysis is modes.h's.
 *
 * Secular stability is not read off these roots: by Thomson and Tait's
 * argument the energy P + V_eff decreases under any dissipation acting on
 * the kept coordinates, so the steady motion survives every such damping iff
 * V_eff has a minimum there (Britannica "Dynamics" sec. 6; with maintained
 * velocities V_eff = V - T0, ibid. and sec. 3 (21)).  Its Hessian's inertia
 * is taken from the conservative problem (M0, Hessian): w^2 > 0 for every
 * mode iff the Hessian is positive definite (M0 being so).
 */
#include "steady.h"
#include "linear.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void qd_stability_free(qd_stability *st) {
    if (!st)
        return;
    qd_linear_free(&st->lin);
    qd__free(st->hessian);
    qd__free(st->freq);
    qd_modes_result_free(&st->ordinary);
    qd_modes_result_free(&st->secular);
    qd_modes_result_free(&st->damped);
    memset(st, 0, sizeof *st);
}

/* Relative size under which a coefficient is a cancellation to rounding:
 * at n = -3 (free) or n = 1 (driven) the radial stiffness of a power-law
 * orbit is exactly zero, but its terms are not. */
#define CHOP_TOL 1e-11

/* x at the environment, and 0 when it is smaller than CHOP_TOL times the sum
 * of its expanded terms' sizes. */
static qd_status eval_chopped(qd_ctx *ctx, const qd__steady_env *env, const qd_expr *x,
                              double *out) {
    qd_status st = qd__lin_steady_eval(ctx, env, x, out);
    const qd_expr *ex = st == QD_OK && *out != 0 ? qd_expand(ctx, x) : NULL;
    if (!ex || qd_expr_kind(ex) != QD_ADD)
        return st;
    double scale = 0, t;
    for (size_t i = 0; st == QD_OK && i < qd_expr_nargs(ex); i++)
        if ((st = qd__lin_steady_eval(ctx, env, qd_expr_arg(ex, i), &t)) == QD_OK)
            scale += fabs(t);
    if (st == QD_OK && fabs(*out) <= CHOP_TOL * scale)
        *out = 0;
    return st;
}

static qd_status eval_diff(qd_ctx *ctx, const qd__steady_env *env, const qd_expr *x,
                           const qd_expr *by1, const qd_expr *by2, double *out) {
    const qd_expr *d = qd_diff(ctx, x, by1);
    if (by2)
        d = qd_diff(ctx, d, by2);
    if (!d)
        return qd_ctx_status(ctx);
    return eval_chopped(ctx, env, d, out);
}

/* M0, C0, G0, K0 and the Hessian of V_eff, as numbers. */
static qd_status linearize(qd_ctx *ctx, const qd_steady *s, const qd__steady_env *env,
                           qd_stability *out) {
    size_t n = s->nkeep;
    qd_linear *l = &out->lin;
    l->n = n;
    l->M = qd__calloc(ctx, n * n, sizeof *l->M);
    l->C = qd__calloc(ctx, n * n, sizeof *l->C);
    l->G = qd__calloc(ctx, n * n, sizeof *l->G);
    l->K = qd__calloc(ctx, n * n, sizeof *l->K);
    out->hessian = qd__calloc(ctx, n * n, sizeof *out->hessian);
    double *B = qd__calloc(ctx, n * n, sizeof *B);
    qd_status st = l->M && l->C && l->G && l->K && out->hessian && B ? QD_OK : QD_ERR_NOMEM;
    for (size_t a = 0; st == QD_OK && a < n; a++)
        for (size_t b = 0; st == QD_OK && b < n; b++) {
            size_t i = a * n + b;
            st = qd__lin_steady_eval(ctx, env, s->M[i], &l->M[i]);
            if (st == QD_OK)
                st = eval_diff(ctx, env, s->f[a], s->keep[b], NULL, &l->K[i]);
            if (st == QD_OK)
                st = eval_diff(ctx, env, s->f[a], s->keepd[b], NULL, &B[i]);
            if (st == QD_OK)
                st = eval_diff(ctx, env, s->Veff, s->keep[a], s->keep[b], &out->hessian[i]);
            l->K[i] = -l->K[i];
            B[i] = -B[i];
        }
    for (size_t a = 0; st == QD_OK && a < n; a++)
        for (size_t b = 0; b < n; b++) {
            l->C[a * n + b] = (B[a * n + b] + B[b * n + a]) / 2;
            l->G[a * n + b] = (B[a * n + b] - B[b * n + a]) / 2;
        }
    if (st == QD_OK)
        qd__lin_linear_chop(l);   /* the matrix-scale test modes and linearize use too */
    qd__free(B);
    return st;
}

/* Is the damping there at all?  Relative to the other coefficients, as modes.h
 * judges "conservative". */
static bool has_damping(const qd_linear *l) {
    double big = 0, c = 0;
    for (size_t i = 0; i < l->n * l->n; i++) {
        big = fmax(big, fmax(fabs(l->M[i]), fmax(fabs(l->K[i]), fabs(l->G[i]))));
        c = fmax(c, fabs(l->C[i]));
    }
    return !qd__lin_negligible(c, big);
}

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The oscillation frequencies of the undamped problem: sqrt(w^2) for the
 * positive w^2 of a conservative one, else the positive imaginary parts of
 * the roots on the imaginary axis. */
static qd_status frequencies(qd_ctx *ctx, qd_stability *out) {
    const qd_modes_result *r = &out->ordinary;
    out->freq = qd__calloc(ctx, r->neig + r->n + 1, sizeof *out->freq);
    if (!out->freq)
        return QD_ERR_NOMEM;
    double big = 0;
    for (size_t i = 0; i < r->neig; i++)
        big = fmax(big, hypot(r->eig_re[i], r->eig_im[i]));
    size_t k = 0;
    if (r->conservative && r->omega2) {
        double w2max = 0;
        for (size_t i = 0; i < r->n; i++)
            w2max = fmax(w2max, fabs(r->omega2[i]));
        for (size_t i = 0; i < r->n; i++)
            if (r->omega2[i] > QD_MODES_ZERO_TOL * w2max)
                out->freq[k++] = sqrt(r->omega2[i]);
    } else {
        for (size_t i = 0; i < r->neig; i++)
            if (fabs(r->eig_re[i]) <= QD_MODES_ZERO_TOL * big &&
                r->eig_im[i] > QD_MODES_ZERO_TOL * big)
                out->freq[k++] = r->eig_im[i];
    }
    out->nfreq = k;
    qsort(out->freq, k, sizeof *out->freq, cmp_double);
    return QD_OK;
}

/* Does the undamped problem have a root at zero?  A double root s = 0 (the
 * drift of a free particle) may come out of the eigen-solver split into
 * +-delta with delta of order sqrt(eps): a pair that close to 0 and to each
 * other is that double root. */
static bool zero_root(const qd_modes_result *r) {
    double big = 0;
    for (size_t i = 0; i < r->neig; i++)
        big = fmax(big, hypot(r->eig_re[i], r->eig_im[i]));
    big = big > 0 ? big : 1;
    for (size_t i = 0; i < r->neig; i++) {
        double m = hypot(r->eig_re[i], r->eig_im[i]);
        if (m <= QD_MODES_ZERO_TOL * big)
            return true;
        for (size_t j = 0; j < r->neig && m <= 1e-6 * big; j++)
            if (j != i && hypot(r->eig_re[j], r->eig_im[j]) <= 1e-6 * big)
                return true;
    }
    return false;
}

/* A double root on the imaginary axis (the sleeping top at nu^2 = 4 A M g h)
 * splits under rounding into a pair with real parts of order sqrt(eps): an
 * "unstable" verdict whose every growing root has such a tiny real part and a
 * partner as close is a double root, borderline. */
static int double_root(const qd_modes_result *r) {
    if (r->stable != 0)
        return r->stable;
    double big = 0;
    for (size_t i = 0; i < r->neig; i++)
        big = fmax(big, hypot(r->eig_re[i], r->eig_im[i]));
    double tol = 1e-6 * (big > 0 ? big : 1);
    for (size_t i = 0; i < r->neig; i++) {
        if (r->eig_re[i] <= QD_MODES_ZERO_TOL * big)
            continue;
        bool twin = false;
        for (size_t j = 0; j < r->neig && !twin; j++)
            twin = j != i && hypot(r->eig_re[i] - r->eig_re[j], r->eig_im[i] - r->eig_im[j]) <= tol;
        if (r->eig_re[i] > tol || !twin)
            return 0;
    }
    return -1;
}

static const char *verdict(const qd_stability *st) {
    int o = st->ordinary_stable, s = st->secular_stable;
    if (o == 1 && s == 1)
        return "stable: V_eff is a minimum (ordinarily and secularly stable)";
    if (o == 1 && s == 0)
        return "ordinarily stable but secularly unstable: gyroscopic stabilisation of a V_eff "
               "that is not a minimum, destroyed by any dissipation (Thomson and Tait)";
    if (o == 1)
        return "ordinarily stable; secular stability undecided: the Hessian of V_eff is "
               "singular (higher-order terms decide)";
    if (o == 0)
        return "unstable: a small disturbance grows exponentially";
    if (zero_root(&st->ordinary))
        return "borderline (neutral): a zero frequency, a double root s = 0 (V_eff's Hessian "
               "is singular): a disturbance can drift, growing linearly as a free particle "
               "does, not exponentially; linear theory cannot decide, higher-order terms or a "
               "neighbouring steady motion do";
    return "borderline: a repeated frequency (double root, secular growth at linear order); "
           "linear theory cannot decide";
}

static qd_status solve_modes(qd_ctx *ctx, const qd_linear *l, const double *C, const double *K,
                             qd_modes_result *r) {
    size_t n = l->n;
    double *zero = qd__calloc(ctx, n * n + 1, sizeof *zero);
    if (!zero)
        return QD_ERR_NOMEM;
    qd_linear v = {n, l->M, C ? (double *)C : zero, K == l->K ? l->G : zero, (double *)K};
    qd_status st = qd_modes_solve(ctx, &v, r);
    qd__free(zero);
    return st;
}

qd_status qd_stability_analyze(qd_ctx *ctx, const qd_steady *s, size_t nvals,
                               const qd_expr *const *syms, const double *vals,
                               const qd_steady_point *pt, qd_stability *out) {
    QD_ARGS_CTX(ctx, ctx && s && (nvals == 0 || syms) && (nvals == 0 || vals) && pt && out);
    memset(out, 0, sizeof *out);
    out->n = s->nkeep;
    qd__steady_env env;
    qd_status st = qd__lin_steady_env_init(ctx, s, nvals, syms, vals, &env);
    if (st != QD_OK)
        return st;
    for (size_t j = 0; j < s->nkeep; j++)
        env.vals[env.x + j] = pt->x[j];
    for (size_t c = 0; c < s->ncyc; c++) {
        env.vals[env.w + c] = pt->w[c];
        if (s->beta)
            env.vals[env.p + c] = pt->p[c];
    }
    st = linearize(ctx, s, &env, out);
    qd__lin_steady_env_free(&env);
    if (st == QD_OK)
        st = solve_modes(ctx, &out->lin, NULL, out->lin.K, &out->ordinary);
    if (st == QD_OK)
        st = solve_modes(ctx, &out->lin, NULL, out->hessian, &out->secular);
    out->dissipative = st == QD_OK && has_damping(&out->lin);
    if (st == QD_OK && out->dissipative)
        st = solve_modes(ctx, &out->lin, out->lin.C, out->lin.K, &out->damped);
    if (st == QD_OK)
        st = frequencies(ctx, out);
    if (st != QD_OK) {
        qd_stability_free(out);
        return st;
    }
    out->ordinary_stable = double_root(&out->ordinary);
    out->secular_stable = out->secular.stable;
    out->damped_stable = out->dissipative ? double_root(&out->damped) : out->ordinary_stable;
    out->verdict = verdict(out);
    return QD_OK;
}
