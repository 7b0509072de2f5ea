/*
 * src/path/shoot.c - the stationary paths of the action between two
 * configurations (qd_path_find) and of given energy (qd_path_find_energy)
 * by multiple shooting (Desloge ch. 82-84; Byerly ch. IV; qdot/path.h).
 *
 * The interval is cut into N segments of equal length.  Unknowns: the
 * initial velocities v0 (and the time T at fixed energy) and the state
 * s_k = (q, q') at the start of each later segment; residuals: the jumps
 * phi_k(s_k) - s_(k+1) between segments, q(t1) - q1 at the end (and
 * h(q0, v0) - E).  Each segment is integrated by classical RK4 with the
 * state, the action S (an extra state, S' = L) and the 2n x 2n sensitivity
 * Phi = d(state)/d(start) from the variational equations
 * Phi' = [0 I; dq''/dq dq''/dq'] Phi; the derivatives of q'' are central
 * differences of the numeric saddle solve (qd_eom_prog_eval), which keeps
 * constraints' multipliers in without symbolic solving.  Newton's steps are
 * Levenberg-Marquardt damped (J^T J + mu I), so that the rank-deficient
 * Jacobian of a constrained model still gives a step, with backtracking on
 * |F|.  The step size is h <= 0.04/omega (omega^2: the largest entry scale
 * of dq''/dq at the start) and at most (t1 - t0)/200; a segment spans at
 * most 3/omega, over which the sensitivities of a hyperbolic point grow by
 * at most e^3 (docs/design.md, "Variational principles").
 */
#include "qdot/path.h"
#include "qdot/eval.h"

#include "base/mem.h"
#include "num/num.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PATH_MAXSEG 64
#define PATH_MAXIT 60

typedef struct sys {
    qd_ctx *ctx;
    const qd_model *m;
    const qd_eom *e;
    size_t n, nsym;
    const qd_expr **syms;   /* q, q', t, parameters */
    double *vals;
    qd_eom_prog *prog;
    qd_eom_work *work;
    qd_prog *Lh;            /* L and Jacobi's h from the same inputs */
    double hmax;
    qd_status st;
} sys;

static void sys_free(sys *s) {
    qd_eom_work_free(s->work);
    qd_eom_prog_free(s->prog);
    qd_prog_free(s->Lh);
    qd__free(s->syms);
    qd__free(s->vals);
}

static const qd_expr *jacobi_h(qd_ctx *ctx, const qd_eom *e) {
    const qd_expr *h = qd_neg(ctx, e->L);
    for (size_t j = 0; j < e->n && h; j++)
        h = qd_add(ctx, h, qd_mul(ctx, e->qd[j], qd_diff(ctx, e->L, e->qd[j])));
    return h;
}

static qd_status sys_init(sys *s, qd_ctx *ctx, const qd_model *m, const qd_eom *e) {
    memset(s, 0, sizeof *s);
    s->ctx = ctx;
    s->m = m;
    s->e = e;
    s->n = e->n;
    size_t np = qd_model_nparams(m), n = e->n;
    s->nsym = 2 * n + 1 + np;
    s->syms = qd__calloc(ctx, s->nsym, sizeof *s->syms);
    s->vals = qd__calloc(ctx, s->nsym, sizeof *s->vals);
    if (!s->syms || !s->vals)
        return QD_ERR_NOMEM;
    for (size_t j = 0; j < n; j++) {
        s->syms[j] = e->q[j];
        s->syms[n + j] = e->qd[j];
    }
    s->syms[2 * n] = qd_time(ctx);
    for (size_t i = 0; i < np; i++) {
        s->syms[2 * n + 1 + i] = qd_model_param(m, i);
        if (qd_model_param_number(m, i, &s->vals[2 * n + 1 + i]) != QD_OK) {
            qd_ctx_error(ctx, QD_ERR_UNBOUND, "parameter %s has no numeric value",
                         qd_expr_name(qd_model_param(m, i)));
            return QD_ERR_UNBOUND;
        }
    }
    s->prog = qd_eom_compile(ctx, e);
    s->work = s->prog ? qd_eom_work_new(ctx, s->prog) : NULL;
    const qd_expr *out[2] = {e->L, jacobi_h(ctx, e)};
    s->Lh = out[1] ? qd_prog_new(ctx, s->nsym, s->syms, 2, out) : NULL;
    return s->prog && s->work && s->Lh ? QD_OK : qd_ctx_status(ctx);
}

static void sys_load(sys *s, double t, const double *q, const double *v) {
    memcpy(s->vals, q, s->n * sizeof *q);
    memcpy(s->vals + s->n, v, s->n * sizeof *v);
    s->vals[2 * s->n] = t;
}

static bool accel(sys *s, double t, const double *q, const double *v, double *a) {
    sys_load(s, t, q, v);
    qd_status st = qd_eom_prog_eval(s->ctx, s->prog, s->work, s->nsym, s->syms, s->vals, NULL,
                                    NULL, a, NULL, NULL);
    if (st != QD_OK && s->st == QD_OK)
        s->st = st;
    return st == QD_OK;
}

static void lagr_h(sys *s, double t, const double *q, const double *v, double out[2]) {
    sys_load(s, t, q, v);
    qd_prog_run(s->Lh, s->vals, out);
}

/* dq''/d(q, q') by central differences: G is n x 2n row-major. */
static bool accel_grad(sys *s, double t, const double *y, double *G, double *tmp) {
    size_t n = s->n, n2 = 2 * n;
    double *yp = tmp, *ap = tmp + n2, *am = tmp + n2 + n;
    memcpy(yp, y, n2 * sizeof *y);
    for (size_t c = 0; c < n2; c++) {
        double h = 1e-5 * (1 + fabs(y[c]));
        yp[c] = y[c] + h;
        bool ok = accel(s, t, yp, yp + n, ap);
        yp[c] = y[c] - h;
        ok = ok && accel(s, t, yp, yp + n, am);
        yp[c] = y[c];
        if (!ok)
            return false;
        for (size_t r = 0; r < n; r++)
            G[r * n2 + c] = (ap[r] - am[r]) / (2 * h);
    }
    return true;
}

/* y = (q, q', S, Phi 2n x 2n row-major); Phi only when sens. */
static bool rhs(sys *s, double t, const double *y, double *dy, bool sens, double *tmp) {
    size_t n = s->n, n2 = 2 * n;
    memcpy(dy, y + n, n * sizeof *y);
    if (!accel(s, t, y, y + n, dy + n))
        return false;
    double lh[2];
    lagr_h(s, t, y, y + n, lh);
    dy[n2] = lh[0];
    if (!sens)
        return true;
    double *G = tmp, *scratch = tmp + n * n2;
    if (!accel_grad(s, t, y, G, scratch))
        return false;
    const double *P = y + n2 + 1;
    double *dP = dy + n2 + 1;
    for (size_t c = 0; c < n2; c++) {
        for (size_t r = 0; r < n; r++)
            dP[r * n2 + c] = P[(n + r) * n2 + c];
        for (size_t r = 0; r < n; r++) {
            double acc = 0;
            for (size_t k = 0; k < n2; k++)
                acc += G[r * n2 + k] * P[k * n2 + c];
            dP[(n + r) * n2 + c] = acc;
        }
    }
    return true;
}

static size_t aug_size(size_t n, bool sens) {
    return 2 * n + 1 + (sens ? 4 * n * n : 0);
}

/* One classical RK4 step of y (augmented, in place) from t by h. */
static bool rk4_step(sys *s, double *y, double t, double h, bool sens, double *w) {
    size_t na = aug_size(s->n, sens);
    double *k1 = w, *k2 = w + na, *k3 = w + 2 * na, *k4 = w + 3 * na, *yt = w + 4 * na;
    double *tmp = w + 5 * na;
    if (!rhs(s, t, y, k1, sens, tmp))
        return false;
    for (size_t j = 0; j < na; j++)
        yt[j] = y[j] + h / 2 * k1[j];
    if (!rhs(s, t + h / 2, yt, k2, sens, tmp))
        return false;
    for (size_t j = 0; j < na; j++)
        yt[j] = y[j] + h / 2 * k2[j];
    if (!rhs(s, t + h / 2, yt, k3, sens, tmp))
        return false;
    for (size_t j = 0; j < na; j++)
        yt[j] = y[j] + h * k3[j];
    if (!rhs(s, t + h, yt, k4, sens, tmp))
        return false;
    for (size_t j = 0; j < na; j++)
        y[j] += h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
    return true;
}

/* The step grid of [ta, tb]: steps of at most hmax. */
static size_t grid_steps(const sys *s, double ta, double tb) {
    return (size_t)ceil(fabs(tb - ta) / s->hmax);
}

/* RK4 from ta to tb on its grid; y advanced in place. */
static bool advance(sys *s, double *y, double ta, double tb, bool sens, double *w) {
    size_t na = aug_size(s->n, sens), steps = grid_steps(s, ta, tb);
    if (steps == 0)
        return true;
    double h = (tb - ta) / (double)steps;
    for (size_t i = 0; i < steps; i++)
        if (!rk4_step(s, y, ta + h * (double)i, h, sens, w))
            return false;
    for (size_t j = 0; j < na; j++)
        if (!isfinite(y[j]))
            return false;
    return true;
}

static size_t work_size(size_t n) {
    return 6 * aug_size(n, true) + 2 * n * n + 6 * n + 8;
}

/* The shooting problem: layout of x = [v0 (n), T (energy only), s_1..s_(N-1) (2n each)]. */
typedef struct shoot {
    sys *s;
    size_t n, N, nx;
    double t0, t1;          /* t1 unused at fixed energy */
    const double *q0, *q1;
    bool energy;
    double E;
    double *w, *y;          /* integrator work, augmented state */
} shoot;

static double shoot_T(const shoot *p, const double *x) {
    return p->energy ? x[p->n] : p->t1 - p->t0;
}

static size_t shoot_off(const shoot *p, size_t k) {  /* where s_k starts, k >= 1 */
    return p->n + (p->energy ? 1 : 0) + 2 * p->n * (k - 1);
}

static void start_state(const shoot *p, const double *x, size_t k, double *y) {
    size_t n = p->n;
    if (k == 0) {
        memcpy(y, p->q0, n * sizeof *y);
        memcpy(y + n, x, n * sizeof *y);
    } else {
        memcpy(y, x + shoot_off(p, k), 2 * n * sizeof *y);
    }
}

/* F (nx) and, when J, the Jacobian (nx x nx row-major). */
static bool shoot_eval(shoot *p, const double *x, double *F, double *J) {
    size_t n = p->n, n2 = 2 * n, N = p->N, nx = p->nx, na = aug_size(n, J != NULL);
    double T = shoot_T(p, x), tau = T / (double)N;
    if (!(T > 0))
        return false;
    if (J)
        memset(J, 0, nx * nx * sizeof *J);
    size_t row = 0, et = p->energy ? n : 0;
    for (size_t k = 0; k < N; k++) {
        double *y = p->y;
        memset(y, 0, na * sizeof *y);
        start_state(p, x, k, y);
        for (size_t i = 0; J && i < n2; i++)
            y[n2 + 1 + i * n2 + i] = 1;
        double ta = p->t0 + tau * (double)k;
        if (!advance(p->s, y, ta, ta + tau, J != NULL, p->w))
            return false;
        bool last = k + 1 == N;
        size_t nr = last ? n : n2;
        for (size_t r = 0; r < nr; r++)
            F[row + r] = y[r] - (last ? p->q1[r] : x[shoot_off(p, k + 1) + r]);
        if (J) {
            const double *P = y + n2 + 1;
            double dy[2 * 64 + 1];
            double a[64];
            if (p->energy) {  /* autonomous: the end state moves with the duration T/N */
                accel(p->s, ta + tau, y, y + n, a);
                for (size_t r = 0; r < n; r++) {
                    dy[r] = y[n + r];
                    dy[n + r] = a[r];
                }
            }
            for (size_t r = 0; r < nr; r++) {
                double *Jr = J + (row + r) * nx;
                if (k == 0)
                    for (size_t c = 0; c < n; c++)
                        Jr[c] = P[r * n2 + n + c];
                else
                    for (size_t c = 0; c < n2; c++)
                        Jr[shoot_off(p, k) + c] = P[r * n2 + c];
                if (!last)
                    Jr[shoot_off(p, k + 1) + r] = -1;
                if (p->energy)
                    Jr[et] = dy[r] / (double)N;
            }
        }
        row += nr;
    }
    if (p->energy) {
        double lh[2], hv = 1e-6;
        lagr_h(p->s, p->t0, p->q0, x, lh);
        F[row] = lh[1] - p->E;
        for (size_t c = 0; J && c < n; c++) {
            double v[64], hp[2], hm[2];
            memcpy(v, x, n * sizeof *v);
            double d = hv * (1 + fabs(x[c]));
            v[c] = x[c] + d;
            lagr_h(p->s, p->t0, p->q0, v, hp);
            v[c] = x[c] - d;
            lagr_h(p->s, p->t0, p->q0, v, hm);
            J[row * nx + c] = (hp[1] - hm[1]) / (2 * d);
        }
    }
    return true;
}

static double norm2(size_t n, const double *v) {
    double s = 0;
    for (size_t i = 0; i < n; i++)
        s += v[i] * v[i];
    return sqrt(s);
}

/* The end-point residual |q(t1) - q1| and the worst jump, as reported. */
static double shoot_residual(size_t nx, const double *F) {
    double r = 0;
    for (size_t i = 0; i < nx; i++)
        r = fmax(r, fabs(F[i]));
    return r;
}

/* Damped Newton (Levenberg-Marquardt with backtracking): true when the
 * residual is below tol; *res the smallest residual reached. */
static bool shoot_newton(shoot *p, double *x, double tol, double *res) {
    size_t nx = p->nx;
    qd_ctx *ctx = p->s->ctx;
    double *F = qd__malloc(ctx, nx * sizeof *F), *J = qd__malloc(ctx, nx * nx * sizeof *J);
    double *A = qd__malloc(ctx, nx * nx * sizeof *A), *d = qd__malloc(ctx, nx * sizeof *d);
    double *xt = qd__malloc(ctx, nx * sizeof *xt), *Ft = qd__malloc(ctx, nx * sizeof *Ft);
    bool ok = false;
    *res = INFINITY;
    if (!F || !J || !A || !d || !xt || !Ft || !shoot_eval(p, x, F, J))
        goto done;
    double f = norm2(nx, F), mu = 0, fref = f;
    int slow = 0;
    for (int it = 0; it < PATH_MAXIT && slow < 15; it++) {
        *res = shoot_residual(nx, F);
        if (*res <= tol) {
            ok = true;
            break;
        }
        /* (J^T J + mu I) d = -J^T F; mu grows only when plain Newton fails */
        for (size_t i = 0; i < nx; i++) {
            for (size_t j = 0; j < nx; j++) {
                double s = 0;
                for (size_t k = 0; k < nx; k++)
                    s += J[k * nx + i] * J[k * nx + j];
                A[i * nx + j] = s;
            }
            double g = 0;
            for (size_t k = 0; k < nx; k++)
                g += J[k * nx + i] * F[k];
            d[i] = -g;
        }
        double scale = qd__num_norm_inf(nx, A);
        for (size_t i = 0; i < nx; i++)
            A[i * nx + i] += mu * scale + 1e-14 * scale;
        if (!qd__num_solve(nx, A, d, 1e-300)) {
            mu = mu ? mu * 10 : 1e-8;
            continue;
        }
        double lam = 1;
        bool better = false;
        for (int b = 0; b < 12 && !better; b++, lam /= 2) {
            for (size_t i = 0; i < nx; i++)
                xt[i] = x[i] + lam * d[i];
            better = shoot_eval(p, xt, Ft, NULL) && norm2(nx, Ft) < f;
        }
        if (!better) {
            if (mu > 1e6)
                break;
            mu = mu ? mu * 10 : 1e-6;
            continue;
        }
        mu /= 10;
        memcpy(x, xt, nx * sizeof *x);
        if (!shoot_eval(p, x, F, J))
            break;
        f = norm2(nx, F);
        /* a start that stalls far from a root is given up: --all has more */
        slow = f < fref / 2 ? 0 : slow + 1;
        fref = fmin(fref, f) == f && slow == 0 ? f : fref;
    }
    if (!ok && isfinite(f))
        *res = fmin(*res, shoot_residual(nx, F));
done:
    qd__free(F);
    qd__free(J);
    qd__free(A);
    qd__free(d);
    qd__free(xt);
    qd__free(Ft);
    return ok;
}

/* omega: the time scale of the motion near the start (sqrt of the largest
 * entry of dq''/dq and |dq''/dq'|), for the steps and the segments. */
static double rate(sys *s, double t0, const double *q0, const double *v0, double *w) {
    size_t n = s->n, n2 = 2 * n;
    double *y = w, *G = w + n2, *tmp = G + n * n2;
    memcpy(y, q0, n * sizeof *y);
    memcpy(y + n, v0, n * sizeof *y);
    double om = 0;
    if (accel_grad(s, t0, y, G, tmp))
        for (size_t r = 0; r < n; r++)
            for (size_t c = 0; c < n; c++)
                om = fmax(om, fmax(sqrt(fabs(G[r * n2 + c])), fabs(G[r * n2 + n + c])));
    return isfinite(om) ? om : 0;
}

static bool arg_ok(qd_ctx *ctx, const qd_eom *e, const qd_path_opts *o, bool energy) {
    if (!o || !o->q0 || !o->q1 || (!energy && !(o->t1 > o->t0)) || e->n == 0 || e->n > 32 ||
        (o->nguess && !o->guess) || o->segments > PATH_MAXSEG || !(o->tol >= 0)) {
        qd_ctx_error(ctx, QD_ERR_ARG,
                     "path: needs q0, q1, t1 > t0, 1 to 32 coordinates, at most %d segments",
                     PATH_MAXSEG);
        return false;
    }
    return true;
}

/* A holonomic constraint violated at an end: no path can reach it. */
static bool ends_on_constraints(sys *s, const qd_path_opts *o, double t1, bool energy) {
    const qd_eom *e = s->e;
    for (size_t k = 0; k < e->ncon; k++) {
        if (e->con[k].kind != QD_CON_HOLONOMIC)
            continue;
        qd_prog *p = qd_prog_new(s->ctx, s->nsym, s->syms, 1, &e->con[k].expr);
        if (!p)
            return false;
        double r0, r1, zero[32] = {0};
        sys_load(s, o->t0, o->q0, zero);
        qd_prog_run(p, s->vals, &r0);
        sys_load(s, energy ? o->t0 : t1, o->q1, zero);
        qd_prog_run(p, s->vals, &r1);
        qd_prog_free(p);
        double r = fmax(fabs(r0), fabs(r1));
        if (!(r <= 1e-8)) {
            qd_ctx_error(s->ctx, QD_ERR_NUMERIC,
                         "no path: the %s end violates constraint %s (residual %.3g)",
                         fabs(r0) > 1e-8 || isnan(r0) ? "start" : "final", e->con[k].name, r);
            return false;
        }
    }
    return true;
}

typedef struct found {
    size_t count, cap;
    qd_path *paths;
} found;

/* Has e a nonholonomic constraint (foci.c refuses those)? */
static bool nonholonomic(const qd_eom *e) {
    for (size_t k = 0; k < e->ncon; k++)
        if (e->con[k].kind == QD_CON_NONHOLONOMIC)
            return true;
    return false;
}

static void path_clear(qd_path *p) {
    qd__free(p->v0);
    qd__free(p->t);
    qd__free(p->q);
    qd__free(p->foci);
    qd__free(p->foci_mult);
    memset(p, 0, sizeof *p);
}

void qd_path_set_free(qd_path_set *s) {
    if (!s)
        return;
    for (size_t i = 0; i < s->count; i++)
        path_clear(&s->paths[i]);
    qd__free(s->paths);
    s->paths = NULL;
    s->count = 0;
}

static bool same_path(const qd_path *a, const double *v0, double T, double Ta) {
    for (size_t j = 0; j < a->n; j++)
        if (fabs(a->v0[j] - v0[j]) > 1e-6 * (1 + fabs(v0[j])))
            return false;
    return fabs(T - Ta) <= 1e-6 * (1 + fabs(T));
}

/* Samples and action of a converged x, segment by segment. */
static bool path_fill(shoot *p, const double *x, size_t ns, double res, qd_path *out) {
    size_t n = p->n, N = p->N;
    qd_ctx *ctx = p->s->ctx;
    double T = shoot_T(p, x), tau = T / (double)N;
    memset(out, 0, sizeof *out);
    out->n = n;
    out->nsamples = ns;
    out->residual = res;
    out->v0 = qd__malloc(ctx, n * sizeof *out->v0);
    out->t = qd__malloc(ctx, ns * sizeof *out->t);
    out->q = qd__malloc(ctx, ns * n * sizeof *out->q);
    if (!out->v0 || !out->t || !out->q)
        return false;
    memcpy(out->v0, x, n * sizeof *x);
    /* the samples interpolate (cubic Hermite in q, q') the very steps the
     * Newton iteration took, so the last one is the end reached to tol */
    size_t i = 0;
    double S = 0, prev[2 * 32];
    for (size_t k = 0; k < N; k++) {
        double *y = p->y, ta = p->t0 + tau * (double)k;
        size_t steps = grid_steps(p->s, ta, ta + tau);
        steps = steps ? steps : 1;
        double h = tau / (double)steps;
        memset(y, 0, aug_size(n, false) * sizeof *y);
        start_state(p, x, k, y);
        for (size_t st = 0; st < steps; st++) {
            double t = ta + h * (double)st;
            memcpy(prev, y, 2 * n * sizeof *y);
            if (!rk4_step(p->s, y, t, h, false, p->w))
                return false;
            bool last = k + 1 == N && st + 1 == steps;
            for (; i < ns; i++) {
                double ti = p->t0 + T * (double)i / (double)(ns - 1);
                double th = (ti - t) / h;
                if (th > 1 + 1e-9 && !last)
                    break;
                th = fmin(fmax(th, 0), 1);
                double h00 = (1 + 2 * th) * (1 - th) * (1 - th), h10 = th * (1 - th) * (1 - th);
                double h01 = th * th * (3 - 2 * th), h11 = th * th * (th - 1);
                out->t[i] = ti;
                for (size_t j = 0; j < n; j++)
                    out->q[i * n + j] = h00 * prev[j] + h10 * h * prev[n + j] + h01 * y[j] +
                                        h11 * h * y[n + j];
            }
        }
        S += y[2 * n];
    }
    out->action = S;
    /* the second variation along the path: the Jacobi equation from its
     * start (foci.c); a minimum iff no focus in (t0, t1] and Legendre's
     * condition (Desloge ch. 84) */
    if (nonholonomic(p->s->e))  /* its motions do not make the action stationary: no foci */
        return true;
    if (qd_path_foci_mult(ctx, p->s->m, p->s->e, p->t0, p->q0, x, p->t0 + T, &out->foci,
                          &out->foci_mult, &out->nfoci, &out->legendre) != QD_OK)
        return false;
    out->minimum = out->legendre && out->nfoci == 0;
    return true;
}

static int by_action(const void *a, const void *b) {
    double x = ((const qd_path *)a)->action, y = ((const qd_path *)b)->action;
    return (x > y) - (x < y);
}

/* The multistart directions: a Halton sequence in [-1, 1]^n (n = 1: an even
 * grid), so that the starts spread without clustering. */
static double halton(size_t i, unsigned base) {
    double f = 1, r = 0;
    for (; i; i /= base) {
        f /= base;
        r += f * (double)(i % base);
    }
    return r;
}

static void spread(size_t n, size_t i, size_t count, double *u) {
    static const unsigned primes[] = {2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53};
    for (size_t j = 0; j < n; j++)
        u[j] = n == 1 ? -1 + 2 * (double)i / (double)(count - 1)
                      : 2 * halton(i + 1, primes[j % 16]) - 1;
}

typedef struct search {
    shoot sh;
    const qd_path_opts *o;
    size_t nstart;
    double omega, span, vscale;
    double *x, *guessrow;
} search;

/* The start vector number i: v0 (and T) then every later segment's state
 * from a straight-line interpolation at the velocity v0. */
static void make_start(search *sr, size_t i, double *x) {
    shoot *p = &sr->sh;
    size_t n = p->n;
    const qd_path_opts *o = sr->o;
    double T = p->t1 - p->t0, v[32], u[32];
    if (i < o->nguess) {
        memcpy(v, o->guess + i * n, n * sizeof *v);
    } else {
        size_t k = i - o->nguess;
        /* at fixed energy only the direction matters: the chord's unit vector */
        double d = p->energy && sr->span > 0 ? sr->span : T;
        for (size_t j = 0; j < n; j++)
            v[j] = (p->q1[j] - p->q0[j]) / d;
        if (k > 0) {
            spread(n, k - 1, sr->nstart - 1, u);
            for (size_t j = 0; j < n; j++)
                v[j] += sr->vscale * u[j];
        }
    }
    if (p->energy) {  /* v scaled so that h = E, T from the chord at that speed */
        double lh0[2], lh1[2], z[32] = {0};
        lagr_h(p->s, p->t0, p->q0, z, lh0);
        lagr_h(p->s, p->t0, p->q0, v, lh1);
        double a = (lh1[1] - lh0[1]) > 0 && p->E > lh0[1] ? sqrt((p->E - lh0[1]) / (lh1[1] - lh0[1])) : 1;
        for (size_t j = 0; j < n; j++)
            v[j] *= a;
        double nv = norm2(n, v);
        T = nv > 0 ? sr->span / nv : 1;
        if (i >= o->nguess && sr->nstart > 1)  /* longer lobs too */
            T *= 1 + (double)((i - o->nguess) % 3);
        x[n] = T;
    }
    memcpy(x, v, n * sizeof *v);
    for (size_t k = 1; k < p->N; k++) {
        double tk = T * (double)k / (double)p->N, *s = x + shoot_off(p, k);
        for (size_t j = 0; j < n; j++) {
            s[j] = p->q0[j] + (p->q1[j] - p->q0[j]) * tk / T;
            s[n + j] = (p->q1[j] - p->q0[j]) / T;
        }
    }
}

static qd_status path_search(qd_ctx *ctx, const qd_model *m, const qd_eom *e, bool energy,
                             double E, const qd_path_opts *o, qd_path_set *out) {
    memset(out, 0, sizeof *out);
    if (!arg_ok(ctx, e, o, energy))
        return QD_ERR_ARG;
    sys s;
    qd_status st = sys_init(&s, ctx, m, e);
    search sr;
    memset(&sr, 0, sizeof sr);
    shoot *p = &sr.sh;
    size_t n = e->n;
    found fd = {0, 0, NULL};
    double best = INFINITY, tol = o->tol > 0 ? o->tol : 1e-10;
    if (st != QD_OK)
        goto done;
    if (energy && !qd_is_zero(qd_diff(ctx, e->L, qd_time(ctx)))) {
        qd_ctx_error(ctx, QD_ERR_ARG, "path --energy: L depends on t, so h is not conserved");
        st = QD_ERR_ARG;
        goto done;
    }
    if (!ends_on_constraints(&s, o, o->t1, energy)) {
        st = qd_ctx_status(ctx) ? qd_ctx_status(ctx) : QD_ERR_NUMERIC;
        goto done;
    }
    p->s = &s;
    p->n = n;
    p->t0 = o->t0;
    p->t1 = energy ? o->t0 + 1 : o->t1;
    p->q0 = o->q0;
    p->q1 = o->q1;
    p->energy = energy;
    p->E = E;
    p->w = qd__malloc(ctx, work_size(n) * sizeof *p->w);
    p->y = qd__malloc(ctx, aug_size(n, true) * sizeof *p->y);
    if (!p->w || !p->y) {
        st = QD_ERR_NOMEM;
        goto done;
    }
    double vbar[32];
    sr.span = 0;
    for (size_t j = 0; j < n; j++) {
        sr.span += (o->q1[j] - o->q0[j]) * (o->q1[j] - o->q0[j]);
        vbar[j] = energy ? 0 : (o->q1[j] - o->q0[j]) / (o->t1 - o->t0);
    }
    sr.span = sqrt(sr.span);
    sr.omega = rate(&s, o->t0, o->q0, vbar, p->w);
    double Tg = energy ? (sr.omega > 0 ? 1 / sr.omega : 1) : o->t1 - o->t0;
    s.hmax = fmin(Tg / 200, sr.omega > 0 ? 0.04 / sr.omega : INFINITY);
    size_t N = o->segments ? o->segments : (size_t)ceil(Tg * sr.omega / 3);
    p->N = N < 1 ? 1 : N > PATH_MAXSEG ? PATH_MAXSEG : N;
    p->nx = n + (energy ? 1 : 0) + 2 * n * (p->N - 1);
    sr.o = o;
    sr.nstart = o->all ? (n == 1 ? 25 : 36) : 1;
    /* the spread of the starts: the chord's speed and the speeds of the
     * motion's own time scale (twice omega times the larger of the span and 1:
     * a pendulum's librations reach 2 omega) */
    sr.vscale = 2.5 * fmax(norm2(n, vbar), sr.omega * fmax(sr.span, 1));
    if (energy)
        sr.vscale = 1.5;
    sr.x = qd__malloc(ctx, p->nx * sizeof *sr.x);
    if (!sr.x) {
        st = QD_ERR_NOMEM;
        goto done;
    }
    size_t total = o->nguess + (o->all || !o->nguess ? sr.nstart : 0);
    for (size_t i = 0; i < total; i++) {
        double res;
        make_start(&sr, i, sr.x);
        bool ok = shoot_newton(p, sr.x, tol, &res);
        if (qd_ctx_status(ctx) == QD_ERR_NOMEM) {
            st = QD_ERR_NOMEM;
            goto done;
        }
        qd_ctx_clear_error(ctx);
        s.st = QD_OK;
        best = fmin(best, res);
        if (!ok)
            continue;
        double T = shoot_T(p, sr.x);
        bool dup = false;
        for (size_t k = 0; k < fd.count && !dup; k++)
            dup = same_path(&fd.paths[k], sr.x, T, fd.paths[k].t[fd.paths[k].nsamples - 1] - o->t0);
        if (dup)
            continue;
        if (fd.count == fd.cap) {
            size_t cap = fd.cap ? 2 * fd.cap : 4;
            qd_path *np = qd__realloc(ctx, fd.paths, cap * sizeof *np);
            if (!np) {
                st = QD_ERR_NOMEM;
                goto done;
            }
            fd.paths = np;
            fd.cap = cap;
        }
        if (!path_fill(p, sr.x, o->nsamples ? o->nsamples : 101, res, &fd.paths[fd.count])) {
            path_clear(&fd.paths[fd.count]);
            st = qd_ctx_status(ctx) ? qd_ctx_status(ctx) : QD_ERR_NUMERIC;
            if (!qd_ctx_status(ctx))
                qd_ctx_error(ctx, st, "path: the samples of a converged path failed");
            goto done;
        }
        fd.count++;
        if (!o->all)
            break;
    }
    if (fd.count == 0) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC,
                     "no path converged to the end point: smallest residual %.3g (tolerance %.3g)",
                     best, tol);
        st = QD_ERR_NUMERIC;
        goto done;
    }
    qsort(fd.paths, fd.count, sizeof *fd.paths, by_action);
    out->count = fd.count;
    out->paths = fd.paths;
    fd.paths = NULL;
    fd.count = 0;
done:
    for (size_t k = 0; k < fd.count; k++)
        path_clear(&fd.paths[k]);
    qd__free(fd.paths);
    qd__free(sr.x);
    qd__free(p->w);
    qd__free(p->y);
    sys_free(&s);
    return st;
}

qd_status qd_path_find(qd_ctx *ctx, const qd_model *m, const qd_eom *e, const qd_path_opts *opts,
                       qd_path_set *out) {
    return path_search(ctx, m, e, false, 0, opts, out);
}

qd_status qd_path_find_energy(qd_ctx *ctx, const qd_model *m, const qd_eom *e, double E,
                              const qd_path_opts *opts, qd_path_set *out) {
    return path_search(ctx, m, e, true, E, opts, out);
}
