/*
 * src/path/shoot.c - the stationary paths of the action between two
 * configurations (qd_path_find) and of given energy (qd_path_find_energy)
 * by multiple shooting (Desloge ch. 82-84; Byerly ch. IV; qdot/path.h).
 *
 * The interval is cut into N segments of equal length.  Unknowns: the
 * initial velocities v0 (and the time T at fixed energy) and the state
 * s_k = (q, q') at the start of each later segment; residuals: the jumps
 * phi_k(s_k) - s_(k+1) between segments, q(t1) - q1 at the end (and
 * h(q0, v0) - E).  Each segment is integrated by classical RK4 (src/num's
 * tableau, qd__num_rk_step) with the
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
 *
 * Isoperimetric constraints and free ends (qdot/path.h): the state becomes
 * u = (q, q', lambda) with lambda' = 0, so the multipliers' sensitivities
 * ride in Phi like any other start value, and each integrand G joins S as a
 * quadrature with its own sensitivity rows (d/dt dI/du0 = dG/du Phi).  The
 * unknowns gain the free start coordinates and the multipliers, the
 * residuals the natural conditions p_j = dL/dq'_j = 0 at the free ends and
 * integral G dx - l = 0; with neither, u = (q, q') and every number is the
 * fixed-end method's.
 */
#include "qdot/path.h"
#include "qdot/eval.h"

#include "base/mem.h"
#include "num/num.h"
#include "../base/args.h"

#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>

#define PATH_MAXSEG 64
#define PATH_MAXIT 60
#define PATH_MAXMULT 8
#define RESOLVE 6       /* halvings of the steps a converged path must settle within */

typedef struct sys {
    qd_ctx *ctx;
    const qd_model *m;
    const qd_eom *e;
    size_t n, nsym;
    const qd_expr **syms;   /* q, q', t, parameters */
    double *vals;
    qd_eom_prog *prog;
    qd_eom_work *work;
    qd_prog *aux;           /* L, Jacobi's h, the G_i, the p_j = dL/dq'_j */
    double *aux_out;
    size_t nm, ns;          /* multipliers; ns = 2n + nm, the state u */
    size_t lam_slot[PATH_MAXMULT];  /* where each lambda sits in vals */
    double lam0[PATH_MAXMULT], ell[PATH_MAXMULT];  /* start values; the l_i */
    double hmax;
    qd_status st;
} sys;

static void sys_free(sys *s) {
    qd_eom_work_free(s->work);
    qd_eom_prog_free(s->prog);
    qd_prog_free(s->aux);
    qd__free(s->aux_out);
    qd__free(s->syms);
    qd__free(s->vals);
}

static const qd_expr *jacobi_h(qd_ctx *ctx, const qd_eom *e) {
    const qd_expr *h = qd_neg(ctx, e->L);
    for (size_t j = 0; j < e->n && h; j++)
        h = qd_add(ctx, h, qd_mul(ctx, e->qd[j], qd_diff(ctx, e->L, e->qd[j])));
    return h;
}

/* Each multiplier's place among the inputs: its parameter's slot, or a
 * slot after the parameters for an undeclared lambda_NAME (0 to start). */
static qd_status sys_multipliers(sys *s) {
    const qd_model *m = s->m;
    size_t np = qd_model_nparams(m), base = 2 * s->n + 1;
    for (size_t i = 0; i < s->nm; i++) {
        const qd_expr *lam = qd_model_isoperimetric_multiplier(m, i);
        if (qd_is_number(lam)) {
            qd_ctx_error(s->ctx, QD_ERR_ARG,
                         "path: the multiplier of constraint %s is fixed to a number, but a "
                         "path solves for it (do not --set lambda_%s)",
                         qd_model_isoperimetric_name(m, i), qd_model_isoperimetric_name(m, i));
            return QD_ERR_ARG;
        }
        size_t slot = s->nsym;
        for (size_t k = 0; k < np; k++)
            if (qd_model_param(m, k) == lam)
                slot = base + k;
        if (slot == s->nsym)
            s->syms[s->nsym++] = lam;
        s->lam_slot[i] = slot;
        s->lam0[i] = s->vals[slot];
    }
    return QD_OK;
}

/* The l_i, numbers of the parameters. */
static qd_status sys_values(sys *s) {
    const qd_expr *vals[PATH_MAXMULT];
    for (size_t i = 0; i < s->nm; i++)
        vals[i] = qd_model_isoperimetric_value(s->m, i);
    if (s->nm == 0)
        return QD_OK;
    qd_prog *p = qd_prog_new(s->ctx, s->nsym, s->syms, s->nm, vals);
    if (!p)
        return qd_ctx_status(s->ctx);
    qd_prog_run(p, s->vals, s->ell);
    qd_prog_free(p);
    return QD_OK;
}

/* L, h, the integrands G_i and the momenta dL/dq'_j in one program. */
static qd_status sys_aux(sys *s) {
    qd_ctx *ctx = s->ctx;
    const qd_eom *e = s->e;
    size_t n = s->n, nout = 2 + s->nm + n;
    const qd_expr *out[2 + PATH_MAXMULT + 32];
    out[0] = e->L;
    out[1] = jacobi_h(ctx, e);
    for (size_t i = 0; i < s->nm; i++)
        out[2 + i] = qd_model_isoperimetric(s->m, i);
    for (size_t j = 0; j < n; j++)
        out[2 + s->nm + j] = qd_diff(ctx, e->L, e->qd[j]);
    for (size_t k = 0; k < nout; k++)
        if (!out[k])
            return qd_ctx_status(ctx);
    s->aux_out = qd__calloc(ctx, nout, sizeof *s->aux_out);
    s->aux = s->aux_out ? qd_prog_new(ctx, s->nsym, s->syms, nout, out) : NULL;
    return s->aux ? QD_OK : qd_ctx_status(ctx) ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
}

static qd_status sys_init(sys *s, qd_ctx *ctx, const qd_model *m, const qd_eom *e) {
    memset(s, 0, sizeof *s);
    s->ctx = ctx;
    s->m = m;
    s->e = e;
    s->n = e->n;
    s->nm = qd_model_nisoperimetric(m);
    s->ns = 2 * e->n + s->nm;
    size_t np = qd_model_nparams(m), n = e->n;
    if (s->nm > PATH_MAXMULT) {
        qd_ctx_error(ctx, QD_ERR_ARG, "path: at most %d isoperimetric constraints", PATH_MAXMULT);
        return QD_ERR_ARG;
    }
    s->nsym = 2 * n + 1 + np;
    s->syms = qd__calloc(ctx, s->nsym + s->nm, sizeof *s->syms);
    s->vals = qd__calloc(ctx, s->nsym + s->nm, sizeof *s->vals);
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
    qd_status st = sys_multipliers(s);
    if (st == QD_OK)
        st = sys_values(s);
    if (st == QD_OK)
        st = sys_aux(s);
    if (st != QD_OK)
        return st;
    s->prog = qd_eom_compile(ctx, e);
    s->work = s->prog ? qd_eom_work_new(ctx, s->prog) : NULL;
    return s->prog && s->work ? QD_OK : qd_ctx_status(ctx);
}

static void sys_load(sys *s, double t, const double *q, const double *v) {
    memcpy(s->vals, q, s->n * sizeof *q);
    memcpy(s->vals + s->n, v, s->n * sizeof *v);
    s->vals[2 * s->n] = t;
}

static void sys_lam(sys *s, const double *lam) {
    for (size_t i = 0; i < s->nm; i++)
        s->vals[s->lam_slot[i]] = lam[i];
}

/* q'' at the state u = (q, q', lambda). */
static bool accel(sys *s, double t, const double *u, double *a) {
    sys_load(s, t, u, u + s->n);
    sys_lam(s, u + 2 * s->n);
    qd_status st = qd_eom_prog_eval(s->ctx, s->prog, s->work, s->nsym, s->syms, s->vals, NULL,
                                    NULL, a, NULL, NULL);
    if (st != QD_OK && s->st == QD_OK)
        s->st = st;
    return st == QD_OK;
}

/* L, h, G_i, p_j at the state u into s->aux_out. */
static const double *aux_at(sys *s, double t, const double *u) {
    sys_load(s, t, u, u + s->n);
    sys_lam(s, u + 2 * s->n);
    qd_prog_run(s->aux, s->vals, s->aux_out);
    return s->aux_out;
}

/* L and h at (q, v) with the multipliers as they are (none at fixed energy). */
static void lagr_h(sys *s, double t, const double *q, const double *v, double out[2]) {
    sys_load(s, t, q, v);
    qd_prog_run(s->aux, s->vals, s->aux_out);
    out[0] = s->aux_out[0];
    out[1] = s->aux_out[1];
}

/* dq''/du by central differences: G is n x ns row-major. */
static bool accel_grad(sys *s, double t, const double *y, double *G, double *tmp) {
    size_t n = s->n, ns = s->ns;
    double *yp = tmp, *ap = tmp + ns, *am = tmp + ns + n;
    memcpy(yp, y, ns * sizeof *y);
    for (size_t c = 0; c < ns; c++) {
        double h = 1e-5 * (1 + fabs(y[c]));
        yp[c] = y[c] + h;
        bool ok = accel(s, t, yp, ap);
        yp[c] = y[c] - h;
        ok = ok && accel(s, t, yp, am);
        yp[c] = y[c];
        if (!ok)
            return false;
        for (size_t r = 0; r < n; r++)
            G[r * ns + c] = (ap[r] - am[r]) / (2 * h);
    }
    return true;
}

/* d(aux outputs from `first`, count of them)/du by central differences:
 * D is count x ns row-major. */
static void aux_grad(sys *s, double t, const double *y, size_t first, size_t count, double *D,
                     double *tmp) {
    size_t ns = s->ns;
    double *yp = tmp, *op = tmp + ns;
    memcpy(yp, y, ns * sizeof *y);
    for (size_t c = 0; c < ns; c++) {
        double h = 1e-5 * (1 + fabs(y[c]));
        yp[c] = y[c] + h;
        memcpy(op, aux_at(s, t, yp) + first, count * sizeof *op);
        yp[c] = y[c] - h;
        const double *om = aux_at(s, t, yp) + first;
        yp[c] = y[c];
        for (size_t r = 0; r < count; r++)
            D[r * ns + c] = (op[r] - om[r]) / (2 * h);
    }
}

/* y = (u, S, I (nm), Phi (ns + nm) x ns row-major); Phi only when sens. */
static bool rhs(sys *s, double t, const double *y, double *dy, bool sens, double *tmp) {
    size_t n = s->n, n2 = 2 * n, ns = s->ns, nm = s->nm;
    memcpy(dy, y + n, n * sizeof *y);
    if (!accel(s, t, y, dy + n))
        return false;
    for (size_t i = n2; i < ns; i++)
        dy[i] = 0;
    const double *o = aux_at(s, t, y);
    dy[ns] = o[0];
    for (size_t i = 0; i < nm; i++)
        dy[ns + 1 + i] = o[2 + i];
    if (!sens)
        return true;
    double *G = tmp, *DG = tmp + n * ns, *scratch = DG + nm * ns;
    if (!accel_grad(s, t, y, G, scratch))
        return false;
    if (nm)
        aux_grad(s, t, y, 2, nm, DG, scratch);
    const double *P = y + ns + 1 + nm;
    double *dP = dy + ns + 1 + nm;
    for (size_t c = 0; c < ns; c++) {
        for (size_t r = 0; r < n; r++)
            dP[r * ns + c] = P[(n + r) * ns + c];
        for (size_t r = 0; r < n; r++) {
            double acc = 0;
            for (size_t k = 0; k < ns; k++)
                acc += G[r * ns + k] * P[k * ns + c];
            dP[(n + r) * ns + c] = acc;
        }
        for (size_t r = n2; r < ns; r++)
            dP[r * ns + c] = 0;
        for (size_t i = 0; i < nm; i++) {
            double acc = 0;
            for (size_t k = 0; k < n2; k++)
                acc += DG[i * ns + k] * P[k * ns + c];
            dP[(ns + i) * ns + c] = acc;
        }
    }
    return true;
}

static size_t aug_size(const sys *s, bool sens) {
    return s->ns + 1 + s->nm + (sens ? (s->ns + s->nm) * s->ns : 0);
}

/* The augmented right-hand side as num's ODE callback. */
typedef struct rk_sys {
    sys *s;
    bool sens;
    double *tmp;
} rk_sys;

static bool rk_rhs(void *data, double t, const double *y, double *dy) {
    rk_sys *r = data;
    return rhs(r->s, t, y, dy, r->sens, r->tmp);
}

/* One classical RK4 step (num's tableau) of y (augmented, in place) from t
 * by h; w: the stages and the stage state (5 na), then rhs's scratch. */
static bool rk4_step(sys *s, double *y, double t, double h, bool sens, double *w) {
    size_t na = aug_size(s, sens);
    rk_sys r = {s, sens, w + 5 * na};
    return qd__num_rk_step(&qd__num_rk4, rk_rhs, &r, na, t, h, y, w);
}

/* The step grid of [ta, tb]: steps of at most hmax. */
static size_t grid_steps(const sys *s, double ta, double tb) {
    return (size_t)ceil(fabs(tb - ta) / s->hmax);
}

/* RK4 from ta to tb on its grid; y advanced in place. */
static bool advance(sys *s, double *y, double ta, double tb, bool sens, double *w) {
    size_t na = aug_size(s, sens), steps = grid_steps(s, ta, tb);
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

static size_t work_size(const sys *s) {
    size_t n = s->n, ns = s->ns, nout = 2 + s->nm + n;
    return 6 * aug_size(s, true) + (n + s->nm) * ns + 2 * ns + 2 * nout + 6 * n + 8;
}

/* The shooting problem: layout of x = [v0 (n), T (energy only),
 * s_1..s_(N-1) (2n each), the free start coordinates (nf0), lambda (nm)];
 * residuals: the jumps (2n each), the last segment's end (n: q_j - q1_j, or
 * p_j for a free end), p_j at the free start coordinates, integral G - l,
 * and at fixed energy h - E. */
typedef struct shoot {
    sys *s;
    size_t n, N, nx, nm, nf0;
    size_t off_free, off_lam;  /* where the free q0 and the lambdas start in x */
    int fidx[32];              /* q0_j's place among the free ones, -1: fixed */
    double t0, t1;          /* t1 unused at fixed energy */
    const double *q0, *q1;
    const bool *free1;
    bool energy;
    double E;
    double *w, *y;          /* integrator work, augmented state */
    double iso_res[PATH_MAXMULT];  /* the last integral G - l */
} shoot;

static double shoot_T(const shoot *p, const double *x) {
    return p->energy ? x[p->n] : p->t1 - p->t0;
}

static size_t shoot_off(const shoot *p, size_t k) {  /* where s_k starts, k >= 1 */
    return p->n + (p->energy ? 1 : 0) + 2 * p->n * (k - 1);
}

static void shoot_layout(shoot *p, const bool *free0) {
    p->nf0 = 0;
    for (size_t j = 0; j < p->n; j++)
        p->fidx[j] = free0 && free0[j] ? (int)p->nf0++ : -1;
    p->off_free = shoot_off(p, p->N);
    p->off_lam = p->off_free + p->nf0;
    p->nx = p->off_lam + p->nm;
}

/* The x index that segment k's start value u_c comes from; -1: a given q0. */
static long col_of(const shoot *p, size_t k, size_t c) {
    size_t n = p->n;
    if (c >= 2 * n)
        return (long)(p->off_lam + c - 2 * n);
    if (k > 0)
        return (long)(shoot_off(p, k) + c);
    if (c >= n)
        return (long)(c - n);
    return p->fidx[c] < 0 ? -1 : (long)(p->off_free + (size_t)p->fidx[c]);
}

static void start_state(const shoot *p, const double *x, size_t k, double *y) {
    size_t n = p->n;
    for (size_t c = 0; c < 2 * n + p->nm; c++) {
        long i = col_of(p, k, c);
        y[c] = i < 0 ? p->q0[c] : x[i];
    }
}

/* Row `row` of J gets d(value)/du (a 1 x ns row D) times Phi of segment k. */
static void chain_row(const shoot *p, size_t k, const double *D, const double *P, double *Jr) {
    size_t ns = p->s->ns;
    for (size_t c = 0; c < ns; c++) {
        long i = col_of(p, k, c);
        if (i < 0)
            continue;
        double acc = 0;
        for (size_t r = 0; r < ns; r++)
            acc += D[r] * (P ? P[r * ns + c] : r == c);
        Jr[i] += acc;
    }
}

/* The last segment's end rows: q_r - q1_r, or p_r at a free end. */
static void end_rows(shoot *p, const double *y, double t, double *F, double *J, size_t row) {
    sys *s = p->s;
    size_t n = p->n, ns = s->ns, nx = p->nx;
    const double *P = y + ns + 1 + p->nm;
    double *D = p->w, *tmp = p->w + n * ns;
    if (J && p->free1)
        aux_grad(s, t, y, 2 + p->nm, n, D, tmp);
    const double *o = aux_at(s, t, y);
    for (size_t r = 0; r < n; r++) {
        bool fr = p->free1 && p->free1[r];
        F[row + r] = fr ? o[2 + p->nm + r] : y[r] - p->q1[r];
        if (!J)
            continue;
        if (fr) {
            chain_row(p, p->N - 1, D + r * ns, P, J + (row + r) * nx);
        } else {
            for (size_t c = 0; c < ns; c++) {
                long i = col_of(p, p->N - 1, c);
                if (i >= 0)
                    J[(row + r) * nx + i] += P[r * ns + c];
            }
        }
    }
}

/* p_j = 0 at the free start coordinates. */
static void start_rows(shoot *p, const double *x, double *F, double *J, size_t row) {
    sys *s = p->s;
    size_t n = p->n, ns = s->ns;
    double *u = p->y, *D = p->w, *tmp = p->w + n * ns;
    start_state(p, x, 0, u);
    if (J)
        aux_grad(s, p->t0, u, 2 + p->nm, n, D, tmp);
    const double *o = aux_at(s, p->t0, u);
    for (size_t j = 0; j < n; j++) {
        if (p->fidx[j] < 0)
            continue;
        F[row] = o[2 + p->nm + j];
        if (J)
            chain_row(p, 0, D + j * ns, NULL, J + row * p->nx);
        row++;
    }
}

/* F (nx) and, when J, the Jacobian (nx x nx row-major). */
static bool shoot_eval(shoot *p, const double *x, double *F, double *J) {
    size_t n = p->n, n2 = 2 * n, N = p->N, nx = p->nx, na = aug_size(p->s, J != NULL);
    size_t ns = p->s->ns, nm = p->nm;
    double T = shoot_T(p, x), tau = T / (double)N, Isum[PATH_MAXMULT] = {0};
    if (!(T > 0))
        return false;
    if (J)
        memset(J, 0, nx * nx * sizeof *J);
    size_t row = 0, et = p->energy ? n : 0, iso_row = n2 * (N - 1) + n + p->nf0;
    for (size_t k = 0; k < N; k++) {
        double *y = p->y;
        memset(y, 0, na * sizeof *y);
        start_state(p, x, k, y);
        for (size_t i = 0; J && i < ns; i++)
            y[ns + 1 + nm + i * ns + i] = 1;
        double ta = p->t0 + tau * (double)k;
        if (!advance(p->s, y, ta, ta + tau, J != NULL, p->w))
            return false;
        bool last = k + 1 == N;
        size_t nr = last ? n : n2;
        const double *P = y + ns + 1 + nm;
        for (size_t i = 0; i < nm; i++) {
            Isum[i] += y[ns + 1 + i];
            for (size_t c = 0; J && c < ns; c++) {
                long xi = col_of(p, k, c);
                if (xi >= 0)
                    J[(iso_row + i) * nx + xi] += P[(ns + i) * ns + c];
            }
        }
        if (last) {
            end_rows(p, y, ta + tau, F, J, row);
        } else {
            for (size_t r = 0; r < nr; r++)
                F[row + r] = y[r] - x[shoot_off(p, k + 1) + r];
        }
        if (J) {
            double dy[2 * 64 + 1];
            double a[64];
            if (p->energy) {  /* autonomous: the end state moves with the duration T/N */
                accel(p->s, ta + tau, y, a);
                for (size_t r = 0; r < n; r++) {
                    dy[r] = y[n + r];
                    dy[n + r] = a[r];
                }
            }
            for (size_t r = 0; r < nr && !last; r++) {
                double *Jr = J + (row + r) * nx;
                for (size_t c = 0; c < ns; c++) {
                    long xi = col_of(p, k, c);
                    if (xi >= 0)
                        Jr[xi] = P[r * ns + c];
                }
                Jr[shoot_off(p, k + 1) + r] = -1;
            }
            for (size_t r = 0; r < nr && p->energy; r++)
                J[(row + r) * nx + et] = dy[r] / (double)N;
        }
        row += nr;
    }
    if (p->nf0) {
        start_rows(p, x, F, J, row);
        row += p->nf0;
    }
    for (size_t i = 0; i < nm; i++) {
        F[row] = Isum[i] - p->s->ell[i];
        p->iso_res[i] = F[row];
        row++;
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
    size_t n = s->n, ns = s->ns;
    double *y = w, *G = w + ns, *tmp = G + n * ns;
    memcpy(y, q0, n * sizeof *y);
    memcpy(y + n, v0, n * sizeof *y);
    memcpy(y + 2 * n, s->lam0, s->nm * sizeof *y);
    double om = 0;
    if (accel_grad(s, t0, y, G, tmp))
        for (size_t r = 0; r < n; r++)
            for (size_t c = 0; c < n; c++)
                om = fmax(om, fmax(sqrt(fabs(G[r * ns + c])), fabs(G[r * ns + n + c])));
    return isfinite(om) ? om : 0;
}

static bool any_free(const bool *f, size_t n) {
    for (size_t j = 0; f && j < n; j++)
        if (f[j])
            return true;
    return false;
}

/* Free ends and multipliers: on the fixed-time, unconstrained problem only. */
static bool free_ok(qd_ctx *ctx, const qd_model *m, const qd_eom *e, const qd_path_opts *o,
                    bool energy) {
    bool fr = any_free(o->free0, e->n) || any_free(o->free1, e->n);
    const char *why = NULL;
    if (energy && fr)
        why = "free ends need the end times, not --energy";
    else if (energy && qd_model_nisoperimetric(m))
        why = "an isoperimetric constraint needs the end points' x, not --energy";
    else if (fr && e->ncon)
        why = "free ends on a model with constraints are not supported";
    if (why)
        qd_ctx_error(ctx, QD_ERR_ARG, "path: %s", why);
    return why == NULL;
}

static bool arg_ok(qd_ctx *ctx, const qd_model *m, const qd_eom *e, const qd_path_opts *o,
                   bool energy) {
    if (!o || !o->q0 || !o->q1 || (!energy && !(o->t1 > o->t0)) || e->n == 0 || e->n > 32 ||
        (o->nguess && !o->guess) || o->segments > PATH_MAXSEG || !(o->tol >= 0)) {
        qd_ctx_error(ctx, QD_ERR_ARG,
                     "path: needs q0, q1, t1 > t0, 1 to 32 coordinates, at most %d segments",
                     PATH_MAXSEG);
        return false;
    }
    return free_ok(ctx, m, e, o, energy);
}

/* A holonomic constraint violated at an end: no path can reach it. */
/* Is G the arc length sqrt(1 + sum q'^2) of the graph q(x)? */
static bool is_arc_length(qd_ctx *ctx, const qd_eom *e, const qd_expr *G) {
    const qd_expr *sum = qd_int(ctx, 1);
    for (size_t j = 0; j < e->n && sum; j++)
        sum = qd_add(ctx, sum, qd_pow(ctx, e->qd[j], qd_int(ctx, 2)));
    return sum && qd_sqrt(ctx, sum) == G;
}

/* A length integral sqrt(1 + y'^2) dx = l below the distance between the
 * ends (their fixed coordinates) has no curve: said before solving. */
static bool lengths_reachable(sys *s, const qd_path_opts *o) {
    const qd_eom *e = s->e;
    double d2 = (o->t1 - o->t0) * (o->t1 - o->t0);
    for (size_t j = 0; j < e->n; j++)
        if (!(o->free0 && o->free0[j]) && !(o->free1 && o->free1[j]))
            d2 += (o->q1[j] - o->q0[j]) * (o->q1[j] - o->q0[j]);
    double d = sqrt(d2);
    for (size_t i = 0; i < s->nm; i++) {
        if (!is_arc_length(s->ctx, e, qd_model_isoperimetric(s->m, i)))
            continue;
        double l = s->ell[i];
        const char *name = qd_model_isoperimetric_name(s->m, i);
        if (l < d * (1 - 1e-12)) {
            qd_ctx_error(s->ctx, QD_ERR_ARG,
                         "constraint %s: the length l = %.10g is shorter than the distance %.10g "
                         "between the end points: no curve", name, l, d);
            return false;
        }
        if (l <= d * (1 + 1e-12)) {
            qd_ctx_error(s->ctx, QD_ERR_ARG,
                         "constraint %s: the length l = %.10g equals the distance between the "
                         "end points: only the straight line, with no finite multiplier",
                         name, l);
            return false;
        }
    }
    return true;
}

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

/* "x = 0, y = 0": an end written for a message (cut to the buffer), led
 * by the independent variable of a functional (the time is left out). */
static void point_text(const sys *s, double t, const double *q, char *buf, size_t cap) {
    const char *x = qd_model_independent(s->m);
    size_t len = x ? (size_t)snprintf(buf, cap, "%s = %.6g", x, t) : 0;
    buf[len] = 0;
    for (size_t j = 0; j < s->n && len + 1 < cap; j++)
        len += (size_t)snprintf(buf + len, cap - len, "%s%s = %.6g", len ? ", " : "",
                                qd_expr_name(s->e->q[j]), q[j]);
}

/* The error, and what to do in its hint (each has 255 bytes of its own). */
static void path_error(qd_ctx *ctx, const char *hint, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
static void path_error(qd_ctx *ctx, const char *hint, const char *fmt, ...) {
    char msg[sizeof ((qd_diag *)0)->message];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    qd_ctx_error(ctx, QD_ERR_NUMERIC, "%s", msg);
    qd_ctx_error_about(ctx, QD_SUBJECT_NONE, 0, NULL, QD_REASON_NONE, hint);
}

/* Are L and q'' finite at (t, q) with the velocity v or at rest?  A
 * cusp of the problem, where the motion's speed vanishes and its slope is
 * infinite (the brachistochrone released from rest: L = sqrt((1 + y'^2)/
 * (2 g y)) at y = 0), is singular at every velocity, and no shot can start
 * or end there. */
static bool state_finite(sys *s, double t, const double *q, const double *v) {
    double u[3 * 32] = {0}, a[32], zero[32] = {0};
    for (int k = 0; k < 2; k++) {
        memcpy(u, q, s->n * sizeof *u);
        memcpy(u + s->n, k ? zero : v, s->n * sizeof *u);
        memcpy(u + 2 * s->n, s->lam0, s->nm * sizeof *u);
        bool ok = isfinite(aux_at(s, t, u)[0]) && accel(s, t, u, a);
        for (size_t j = 0; ok && j < s->n; j++)
            ok = isfinite(a[j]);
        s->st = QD_OK;
        qd_ctx_clear_error(s->ctx);
        if (ok)
            return true;
    }
    return false;
}

static bool ends_regular(sys *s, const qd_path_opts *o, double t1, bool energy, const double *v) {
    /* with isoperimetric multipliers the singular points move with them (the
     * catenary's w y = lambda): left to the search */
    for (int end = 0; end < 2 && s->nm == 0; end++) {
        const double *q = end ? o->q1 : o->q0;
        double t = end && !energy ? t1 : o->t0;
        if (state_finite(s, t, q, v))
            continue;
        char at[160];
        point_text(s, t, q, at, sizeof at);
        path_error(s->ctx, "shooting integrates from a regular state: begin the path at a point "
                           "just off the singular one",
                   "no path: the equations are singular at the %s (%s): L or the accelerations "
                   "are not finite there, at the chord's velocity or at rest (a cusp, where the "
                   "speed vanishes: the brachistochrone released from rest)",
                   end ? "end" : "start", at);
        return false;
    }
    return true;
}

/* At fixed energy: each end within the region h(q, 0) <= E (h at rest is
 * the least h at q when T2 is positive definite: h = T2 - T0 + V), and the
 * start not on its edge, where the speed vanishes: there the energy row
 * h - E = |v|^2/2 + ... fixes v only to the square root of its tolerance
 * (the fall from rest of a projectile at E = V came out with x' = 7.6e-6
 * and its time 5e-6 off), and every path of that energy leaves along the
 * motion from rest (a cusp of the Jacobi metric (E - V) M). */
static bool ends_reachable(sys *s, const qd_path_opts *o, double E) {
    double zero[32] = {0}, lh[2];
    for (int end = 0; end < 2; end++) {
        const double *q = end ? o->q1 : o->q0;
        lagr_h(s, o->t0, q, zero, lh);
        double h0 = lh[1], scale = fmax(fabs(E), fabs(h0));
        char at[160];
        point_text(s, o->t0, q, at, sizeof at);
        if (E < h0 - 1e-12 * scale) {
            path_error(s->ctx, "a motion of energy E stays where the energy at rest is at most "
                               "E: a larger --energy, or an end within reach",
                       "no path: the %s (%s) is out of reach at the energy %.10g: the energy at "
                       "rest there is %.10g", end ? "end" : "start", at, E, h0);
            return false;
        }
        if (!end && E <= h0 + 1e-9 * scale) {
            char hint[256];
            snprintf(hint, sizeof hint, "the motion from rest there is qdot simulate's; the "
                                        "paths of an energy above %.10g leave with a speed",
                     h0);
            path_error(s->ctx, hint,
                       "no path: the speed vanishes at the start (%s): the energy %.10g is the "
                       "energy at rest there, a cusp where every path of this energy leaves "
                       "along the motion from rest", at, E);
            return false;
        }
    }
    return true;
}

typedef struct found {
    size_t count, cap;
    qd_path *paths;
    double *xs; /* cap x nx: the converged unknowns of each path kept */
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
    qd__free(p->mult);
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

static bool near(double a, double b) {
    return fabs(a - b) <= 1e-6 * (1 + fabs(b));
}

/* The same start (v0, the free q0, lambda) and duration as path a. */
static bool same_path(const shoot *p, const qd_path *a, const double *x, double T, double Ta) {
    for (size_t j = 0; j < a->n; j++)
        if (!near(a->v0[j], x[j]) || (p->fidx[j] >= 0 && !near(a->q[j], x[p->off_free + (size_t)p->fidx[j]])))
            return false;
    for (size_t i = 0; i < a->nmult; i++)
        if (!near(a->mult[i], x[p->off_lam + i]))
            return false;
    return near(Ta, T);
}

/* x and xk, two converged starts near each other, one double root?  Where
 * two stationary paths merge (the end on the envelope of the paths of one
 * energy) the shooting map is singular, and Newton stops anywhere in a thin
 * curved valley about the root: two starts may differ by ~1e-5 while each
 * converged.  Their midpoint lies off the valley by its curvature, and
 * Newton brings it back to the floor by a step much shorter than their
 * distance; between two distinct roots there is no floor at the midpoint,
 * and Newton has to walk about half the distance to one of them. */
static bool same_root(shoot *p, const double *x, const double *xk, double tol) {
    size_t nx = p->nx;
    double d = 0, scale = 0;
    for (size_t i = 0; i < nx; i++) {
        d = fmax(d, fabs(x[i] - xk[i]));
        scale = fmax(scale, fabs(xk[i]));
    }
    if (!(d <= 1e-3 * (1 + scale)))
        return false;
    double *mid = qd__malloc(p->s->ctx, 2 * nx * sizeof *mid), res;
    if (!mid)
        return false;
    for (size_t i = 0; i < nx; i++)
        mid[i] = mid[nx + i] = (x[i] + xk[i]) / 2;
    bool same = shoot_newton(p, mid, tol, &res);
    for (size_t i = 0; same && i < nx; i++)
        same = fabs(mid[i] - mid[nx + i]) <= 0.1 * d;
    qd__free(mid);
    qd__ctx_recover(p->s->ctx); /* a failed polish is a "no", not an error */
    return same;
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
    out->nmult = p->nm;
    out->mult = p->nm ? qd__malloc(ctx, p->nm * sizeof *out->mult) : NULL;
    if (!out->v0 || !out->t || !out->q || (p->nm && !out->mult))
        return false;
    memcpy(out->v0, x, n * sizeof *x);
    if (p->nm)
        memcpy(out->mult, x + p->off_lam, p->nm * sizeof *x);
    /* the samples interpolate (cubic Hermite in q, q') the very steps the
     * Newton iteration took, so the last one is the end reached to tol */
    size_t i = 0;
    double S = 0, prev[2 * 32], Fl = 0;
    for (size_t k = 0; k < N; k++) {
        double *y = p->y, ta = p->t0 + tau * (double)k;
        size_t steps = grid_steps(p->s, ta, ta + tau);
        steps = steps ? steps : 1;
        double h = tau / (double)steps;
        memset(y, 0, aug_size(p->s, false) * sizeof *y);
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
        S += y[p->s->ns];
        for (size_t m = 0; m < p->nm; m++)  /* the functional F = L + lambda G */
            Fl += x[p->off_lam + m] * y[p->s->ns + 1 + m];
    }
    out->action = S + Fl;
    /* p.q' = L + h along the motion, h = E conserved: A = S + E T */
    out->abbreviated = p->energy ? out->action + p->E * T : NAN;
    /* the second variation along the path: the Jacobi equation from its
     * start (foci.c); a minimum iff no focus in (t0, t1] and Legendre's
     * condition (Desloge ch. 84) */
    /* the fixed-end Jacobi equation does not decide with isoperimetric
     * multipliers or free ends; a nonholonomic model's motions do not make
     * the action stationary at all */
    if (nonholonomic(p->s->e) || p->nm || p->nf0 || p->free1)
        return true;
    out->examined = true;
    if (qd_path_foci_mult(ctx, p->s->m, p->s->e, p->t0, p->q0, x, p->t0 + T, &out->foci,
                          &out->foci_mult, &out->nfoci, &out->legendre) != QD_OK)
        return false;
    out->minimum = out->legendre && out->nfoci == 0;
    /* the end a focus of the start: a Jacobi field vanishes at both ends,
     * so the path is not isolated to first order (the great circles
     * between antipodes); its multiplicity is the family's dimension */
    size_t last = out->nfoci - 1;
    if (out->nfoci && !p->energy && fabs(out->foci[last] - (p->t0 + T)) <= 1e-6 * T)
        out->family = out->foci_mult ? out->foci_mult[last] : 1;
    return true;
}

/* Is the converged x another member of a's family (the same action, the
 * end a focus again)?  Then --all reports the family once. */
static bool family_member(shoot *p, const qd_path *a, const double *x, size_t ns) {
    if (!a->family)
        return false;
    qd_path b;
    bool same = path_fill(p, x, ns, 0, &b) && b.family == a->family &&
                fabs(b.action - a->action) <= 1e-8 * (1 + fabs(a->action));
    path_clear(&b);
    return same;
}

#define ALL_SEGMENTS 8  /* multiple shooting of the --all search at fixed energy */

static int by_action(const void *a, const void *b) {
    const qd_path *pa = a, *pb = b;
    bool fixed_e = !isnan(pa->abbreviated);  /* Maupertuis: by A, the action he varies */
    double x = fixed_e ? pa->abbreviated : pa->action, y = fixed_e ? pb->abbreviated : pb->action;
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

#define PATH_MAXCON 16  /* constraints the start velocities are projected onto */

typedef struct search {
    shoot sh;
    const qd_path_opts *o;
    size_t nstart;
    double omega, span, vscale, lscale;
    double *x, *F;
    /* the velocity constraints at the start, A v + c = 0 (m rows of n):
     * every start velocity is projected onto them, so that a constrained
     * path (a sphere written as a constraint) needs no --guess */
    size_t ncon;
    double A[PATH_MAXCON * 32], c[PATH_MAXCON];
} search;

/* A and c of every constraint at (t0, q0); false when out of memory. */
static bool start_constraints(sys *s, const qd_path_opts *o, search *sr) {
    const qd_eom *e = s->e;
    size_t n = e->n;
    sr->ncon = 0;
    if (e->ncon == 0 || e->ncon > PATH_MAXCON)
        return true;
    for (size_t k = 0; k < e->ncon; k++) {
        const qd_expr *outs[33];
        for (size_t j = 0; j < n; j++)
            outs[j] = e->con[k].a[j];
        outs[n] = e->con[k].a0;
        qd_prog *p = qd_prog_new(s->ctx, s->nsym, s->syms, n + 1, outs);
        if (!p)
            return false;
        double out[33], zero[32] = {0};
        sys_load(s, o->t0, o->q0, zero);
        qd_prog_run(p, s->vals, out);
        qd_prog_free(p);
        memcpy(sr->A + k * n, out, n * sizeof *out);
        sr->c[k] = out[n];
    }
    sr->ncon = e->ncon;
    return true;
}

/* v - A^T y with (A A^T) y = A v + c: the nearest velocity the constraints
 * admit (least squares; a dependent row is skipped). */
static void project_start(const search *sr, size_t n, double *v) {
    size_t m = sr->ncon;
    if (!m)
        return;
    double G[PATH_MAXCON * PATH_MAXCON], r[PATH_MAXCON], y[PATH_MAXCON] = {0};
    for (size_t a = 0; a < m; a++) {
        r[a] = sr->c[a];
        for (size_t j = 0; j < n; j++)
            r[a] += sr->A[a * n + j] * v[j];
        for (size_t b = 0; b < m; b++) {
            G[a * m + b] = 0;
            for (size_t j = 0; j < n; j++)
                G[a * m + b] += sr->A[a * n + j] * sr->A[b * n + j];
        }
    }
    /* Gaussian elimination with partial pivoting; a pivot below 1e-12 of
     * the diagonal's largest is a redundant row, its y left 0 */
    double top = 0;
    for (size_t a = 0; a < m; a++)
        top = fmax(top, fabs(G[a * m + a]));
    bool used[PATH_MAXCON] = {false};
    size_t piv[PATH_MAXCON];
    for (size_t col = 0; col < m; col++) {
        size_t best = m;
        for (size_t a = 0; a < m; a++)
            if (!used[a] && (best == m || fabs(G[a * m + col]) > fabs(G[best * m + col])))
                best = a;
        piv[col] = m;
        if (best == m || !(fabs(G[best * m + col]) > 1e-12 * top))
            continue;
        used[best] = true;
        piv[col] = best;
        for (size_t a = 0; a < m; a++) {
            if (a == best)
                continue;
            double f = G[a * m + col] / G[best * m + col];
            for (size_t b = 0; b < m; b++)
                G[a * m + b] -= f * G[best * m + b];
            r[a] -= f * r[best];
        }
    }
    for (size_t col = 0; col < m; col++)
        if (piv[col] < m)
            y[col] = r[piv[col]] / G[piv[col] * m + col];
    for (size_t j = 0; j < n; j++)
        for (size_t a = 0; a < m; a++)
            v[j] -= sr->A[a * n + j] * y[a];
}

/* A chord normal to the constraint surface (antipodal points on a sphere)
 * projects to no velocity at all, a start that stays put: then the
 * coordinate direction that the constraints admit best, at the chord's
 * speed, so that a constrained path needs no --guess. */
static void tangent_start(const search *sr, size_t n, double *v) {
    double chord = 0, speed = norm2(n, v), best = 0, u[32], w[32];
    const shoot *p = &sr->sh;
    for (size_t j = 0; j < n; j++)
        chord += (p->q1[j] - p->q0[j]) * (p->q1[j] - p->q0[j]);
    chord = sqrt(chord) / (p->t1 - p->t0);
    if (!sr->ncon || p->energy || !(speed < 1e-6 * chord))
        return;
    for (size_t i = 0; i < n; i++) {
        for (size_t j = 0; j < n; j++)
            w[j] = i == j;
        project_start(sr, n, w);
        double a = norm2(n, w);
        if (a > best * (1 + 1e-9)) {
            best = a;
            memcpy(u, w, n * sizeof *u);
        }
    }
    for (size_t j = 0; best > 0 && j < n; j++)
        v[j] += chord * u[j] / best;
}

/* The multipliers' starts: lambda0 + lscale times these, cycled fastest
 * (a multiplier's scale is the problem's, and a wrong sign can make the
 * equations singular at the start: the catenary's w y - lambda = 0). */
static const double lam_steps[] = {0, -1, 1, -2, 2, -4, 4, -8, 8, -0.5, 0.5, -16, 16};
#define NLAM (sizeof lam_steps / sizeof lam_steps[0])

/* The ballistic aim of make_start (lob 1 the low flight, 2 the high):
 * v and *T replaced, a the acceleration; false when the parabola cannot
 * reach q1 at this speed or the acceleration is 0 (a straight line). */
static bool ballistic_aim(shoot *p, double *v, double *T, double *a, int lob) {
    size_t n = p->n;
    double u[3 * 32] = {0}, d[32], s2 = 0, da = 0, aa = 0, dd = 0;
    memcpy(u, p->q0, n * sizeof *u);
    memcpy(u + n, v, n * sizeof *u);
    if (!accel(p->s, p->t0, u, a))
        return false;
    for (size_t j = 0; j < n; j++) {
        d[j] = p->q1[j] - p->q0[j];
        s2 += v[j] * v[j], da += d[j] * a[j], aa += a[j] * a[j], dd += d[j] * d[j];
    }
    double disc = (da + s2) * (da + s2) - aa * dd;
    if (!(aa > 0) || !isfinite(aa) || !(disc >= 0))
        return false;
    double T2 = (da + s2 + (lob == 2 ? 1 : -1) * sqrt(disc)) / (aa / 2);
    if (!(T2 > 0))
        return false;
    *T = sqrt(T2);
    for (size_t j = 0; j < n; j++)
        v[j] = d[j] / *T - a[j] * *T / 2;
    return true;
}

/* At fixed energy, the times at which the motion from (q0, v) comes
 * nearest q1: the local minima of |q(t) - q1| over 12 chord times, sampled
 * 600 times, into tmin (at most cap, ascending); their count.  The k-th of
 * them is start k's duration, so that the search aims at the first pass,
 * the way round and the next turn alike (issue 33: on a sphere the way
 * round, 3 pi/2 long, was never started near, even from --guess). */
static size_t near_passes(shoot *p, const double *v, double Tc, double *tmin, size_t cap) {
    sys *s = p->s;
    size_t n = p->n, na = aug_size(s, false), count = 0, steps = 600;
    double *y = p->y, h = 12 * Tc / (double)steps, dprev = INFINITY, dprev2 = INFINITY;
    memset(y, 0, na * sizeof *y);
    memcpy(y, p->q0, n * sizeof *y);
    memcpy(y + n, v, n * sizeof *y);
    for (size_t k = 0; k <= steps && count < cap; k++) {
        double d = 0;
        for (size_t j = 0; j < n; j++)
            d += (y[j] - p->q1[j]) * (y[j] - p->q1[j]);
        if (k >= 2 && dprev < dprev2 && dprev <= d)
            tmin[count++] = h * (double)(k - 1);
        dprev2 = dprev;
        dprev = d;
        if (k < steps && !rk4_step(s, y, p->t0 + h * (double)k, h, false, p->w))
            break;
    }
    s->st = QD_OK;
    qd_ctx_clear_error(s->ctx);
    return count;
}

/* The start vector number i: v0 (and T) then every later segment's state
 * from a straight-line interpolation at the velocity v0.  A ballistic start
 * (lob 1 or 2, at fixed energy with --all) aims instead as a projectile
 * would under the start's own acceleration a held constant: at the speed s
 * of the chord's start, q1 - q0 = d = v T + a T^2/2 with |v| = s gives
 * (a.a/4) T^4 - (d.a + s^2) T^2 + d.d = 0, the low and the high flight,
 * v = d/T - a T/2, and the segments' states on that parabola (issue 33: the
 * projectile's high lob, 54 chord times long, was missed). */
static void make_start(search *sr, size_t i, double *x, int lob) {
    shoot *p = &sr->sh;
    size_t n = p->n;
    const qd_path_opts *o = sr->o;
    double T = p->t1 - p->t0, v[32], u[32];
    size_t kl = 0;
    if (i < o->nguess) {
        memcpy(v, o->guess + i * n, n * sizeof *v);
    } else {
        size_t k = i - o->nguess;
        if (p->nm) {  /* every multiplier start at each velocity */
            kl = k % NLAM;
            k /= NLAM;
        }
        /* at fixed energy only the direction matters: the chord's unit vector */
        double d = p->energy && sr->span > 0 ? sr->span : T;
        for (size_t j = 0; j < n; j++)
            v[j] = (p->q1[j] - p->q0[j]) / d;
        if (k > 0) {
            spread(n, k - 1, (p->nm ? (sr->nstart + NLAM - 1) / NLAM : sr->nstart) - 1, u);
            for (size_t j = 0; j < n; j++)
                v[j] += sr->vscale * u[j];
        }
    }
    project_start(sr, n, v);
    tangent_start(sr, n, v);
    if (p->energy) {  /* v scaled so that h = E, T from the chord at that speed */
        double lh0[2], lh1[2], z[32] = {0};
        lagr_h(p->s, p->t0, p->q0, z, lh0);
        lagr_h(p->s, p->t0, p->q0, v, lh1);
        double a = (lh1[1] - lh0[1]) > 0 && p->E > lh0[1] ? sqrt((p->E - lh0[1]) / (lh1[1] - lh0[1])) : 1;
        for (size_t j = 0; j < n; j++)
            v[j] *= a;
        double nv = norm2(n, v), tmin[3];
        T = nv > 0 ? sr->span / nv : 1;
        /* the k-th near pass of the motion from v (k = 0 for a guess), or
         * longer lobs of the chord's time */
        size_t k = i >= o->nguess && sr->nstart > 1 ? (i - o->nguess) % 3 : 0;
        size_t np = nv > 0 ? near_passes(p, v, T, tmin, 3) : 0;
        T = k < np ? tmin[k] : T * (1 + (double)k);
        x[n] = T;
    }
    double acc[32] = {0};
    if (lob && !ballistic_aim(p, v, &T, acc, lob))
        memset(acc, 0, sizeof acc); /* no such flight: the chord's start again */
    if (p->energy)
        x[n] = T;
    memcpy(x, v, n * sizeof *v);
    for (size_t j = 0; j < n; j++)
        if (p->fidx[j] >= 0)
            x[p->off_free + (size_t)p->fidx[j]] = p->q0[j];
    for (size_t m = 0; m < p->nm; m++)
        x[p->off_lam + m] = p->s->lam0[m] + sr->lscale * lam_steps[kl];
    for (size_t k = 1; k < p->N; k++) {
        double tk = T * (double)k / (double)p->N, *s = x + shoot_off(p, k);
        for (size_t j = 0; j < n; j++) {
            s[j] = p->q0[j] + (p->q1[j] - p->q0[j]) * tk / T;
            s[n + j] = (p->q1[j] - p->q0[j]) / T;
            if (lob) {
                s[j] = p->q0[j] + v[j] * tk + acc[j] * tk * tk / 2;
                s[n + j] = v[j] + acc[j] * tk;
            }
            if (p->free1 && p->free1[j]) {  /* no end to aim at: the line at v0 */
                s[j] = p->q0[j] + v[j] * tk;
                s[n + j] = v[j];
            }
        }
    }
}

/* On a constraint surface the chord between the ends leaves it (through
 * the sphere's centre for antipodal points, where the constraint's row
 * vanishes and no segment can start): each later segment starts instead
 * where the motion from the previous one's start arrives, so the start is
 * continuous and on the surface.  Kept as the chord from the first segment
 * that cannot be followed. */
static void follow_start(search *sr, double *x) {
    shoot *p = &sr->sh;
    size_t n = p->n, na = aug_size(p->s, false);
    double tau = shoot_T(p, x) / (double)p->N;
    for (size_t k = 1; k < p->N; k++) {
        memset(p->y, 0, na * sizeof *p->y);
        start_state(p, x, k - 1, p->y);
        double ta = p->t0 + tau * (double)(k - 1);
        if (!advance(p->s, p->y, ta, ta + tau, false, p->w))
            return;
        memcpy(x + shoot_off(p, k), p->y, 2 * n * sizeof *x);
    }
}

/* No start converged: the smallest residual, and each isoperimetric
 * condition's own at that start (the one a user can act on). */
static void no_path_error(qd_ctx *ctx, const sys *s, double best, double tol, const double *iso,
                          size_t unsettled, size_t N) {
    char more[256] = "";
    size_t len = 0;
    for (size_t i = 0; i < s->nm && len < sizeof more - 1; i++)
        len += (size_t)snprintf(more + len, sizeof more - len,
                                "%s integral of constraint %s minus its value: %.3g",
                                i ? "," : ";", qd_model_isoperimetric_name(s->m, i), iso[i]);
    if (unsettled) {  /* converged, then lost when the steps were halved (resolved) */
        char hint[256];
        snprintf(hint, sizeof hint, "more shooting segments (--segments %zu) or your own initial "
                                    "velocities (--guess)", 2 * N > PATH_MAXSEG ? PATH_MAXSEG : 2 * N);
        path_error(ctx, hint,
                   "no path found: %zu start%s converged but did not settle when the steps were halved "
                   "%d times (a path of the discretized problem, not of the motion: faster than "
                   "the steps resolve, or through a singular point)%s",
                   unsettled, unsettled == 1 ? "" : "s", RESOLVE, more);
        return;
    }
    if (!isfinite(best)) {  /* every shot met a state where q'' or L is not finite */
        path_error(ctx, "starts of your own (--guess) or more shooting segments (--segments)",
                   "no path converged to the end point: every start ran into a state where the "
                   "equations are not finite (a singular point on the way)%s", more);
        return;
    }
    qd_ctx_error(ctx, QD_ERR_NUMERIC,
                 "no path converged to the end point: smallest residual %.3g (tolerance %.3g)%s; "
                 "to ask for more: starts spread around the chord's (--all), your own initial "
                 "velocities (--guess) or more shooting segments (--segments)",
                 best, tol, more);
}

/* A converged x solves the problem discretized at steps hmax; it is a path
 * of the motion only if it stays converged when the steps are halved (issue
 * 33: on a sphere, a path at 14.5 half-turns per unit time came out as RK4's,
 * action 1037.53 for the true 1037.99, and one at 25.6 was no path at all).
 * The steps are halved, and Newton rerun from x, until the residual at half
 * the steps is within 10 tol (then Newton polishes it to tol there), at most
 * RESOLVE times; false (the path is dropped) when it does not settle.  hmax is left at the settled steps, for
 * the samples and the action; the caller restores it. */
static bool resolved(shoot *p, double *x, double *F, double tol, double *res) {
    for (int k = 0; k < RESOLVE; k++) {
        p->s->hmax /= 2;
        if (!shoot_eval(p, x, F, NULL))
            return false;
        double r = shoot_residual(p->nx, F);
        if (r <= 10 * tol) { /* settled: converged again at these steps */
            if (r > tol && !shoot_newton(p, x, tol, res))
                *res = r;
            return true;
        }
        if (!shoot_newton(p, x, tol, res))
            return false;
    }
    return false;
}

static qd_status path_search(qd_ctx *ctx, const qd_model *m, const qd_eom *e, bool energy,
                             double E, const qd_path_opts *o, qd_path_set *out) {
    memset(out, 0, sizeof *out);
    if (!arg_ok(ctx, m, e, o, energy))
        return QD_ERR_ARG;
    sys s;
    qd_status st = sys_init(&s, ctx, m, e);
    search sr;
    memset(&sr, 0, sizeof sr);
    shoot *p = &sr.sh;
    size_t n = e->n;
    found fd = {0, 0, NULL, NULL};
    double best = INFINITY, tol = o->tol > 0 ? o->tol : 1e-10, best_iso[PATH_MAXMULT] = {0};
    if (st != QD_OK)
        goto done;
    if (energy && !qd_is_zero(qd_diff(ctx, e->L, qd_time(ctx)))) {
        qd_ctx_error(ctx, QD_ERR_ARG, "a path of given energy: L depends on t, so h is not conserved");
        st = QD_ERR_ARG;
        goto done;
    }
    if (!energy && !lengths_reachable(&s, o)) {
        st = QD_ERR_ARG;
        goto done;
    }
    if (!ends_on_constraints(&s, o, o->t1, energy)) {
        st = qd_ctx_status(ctx) ? qd_ctx_status(ctx) : QD_ERR_NUMERIC;
        goto done;
    }
    double chord_v[32];
    for (size_t j = 0; j < n; j++)
        chord_v[j] = energy ? o->q1[j] - o->q0[j] : (o->q1[j] - o->q0[j]) / (o->t1 - o->t0);
    if (!ends_regular(&s, o, o->t1, energy, chord_v) || (energy && !ends_reachable(&s, o, E))) {
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
    p->nm = s.nm;
    p->free1 = any_free(o->free1, n) ? o->free1 : NULL;
    p->w = qd__malloc(ctx, work_size(&s) * sizeof *p->w);
    p->y = qd__malloc(ctx, aug_size(&s, true) * sizeof *p->y);
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
    /* at fixed energy the time is unknown and omega may be 0 (a uniform
     * field): a single shot from a far start misses the long paths (the
     * projectile's high lob), so the multistart shoots in ALL_SEGMENTS */
    if (energy && o->all && !o->segments && N < ALL_SEGMENTS)
        N = ALL_SEGMENTS;
    p->N = N < 1 ? 1 : N > PATH_MAXSEG ? PATH_MAXSEG : N;
    shoot_layout(p, o->free0);
    sr.o = o;
    sr.nstart = o->all ? (n == 1 ? 25 : 36) : 1;
    if (s.nm)  /* each multiplier start at three velocities, until one converges */
        sr.nstart = 3 * NLAM;
    sr.lscale = 1;
    for (size_t i = 0; i < s.nm; i++)
        sr.lscale = fmax(sr.lscale, fabs(s.lam0[i]));
    /* the spread of the starts: the chord's speed and the speeds of the
     * motion's own time scale (twice omega times the larger of the span and 1:
     * a pendulum's librations reach 2 omega) */
    sr.vscale = 2.5 * fmax(norm2(n, vbar), sr.omega * fmax(sr.span, 1));
    if (energy)
        sr.vscale = 1.5;
    if (!start_constraints(&s, o, &sr)) {
        st = qd_ctx_status(ctx) ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
        goto done;
    }
    sr.x = qd__malloc(ctx, p->nx * sizeof *sr.x);
    sr.F = qd__malloc(ctx, p->nx * sizeof *sr.F);
    if (!sr.x || !sr.F) {
        st = QD_ERR_NOMEM;
        goto done;
    }
    size_t plain = o->nguess + (o->all || !o->nguess ? sr.nstart : 0);
    size_t total = plain + (energy && o->all && !s.nm ? 2 : 0); /* the two lobs */
    double hmax0 = s.hmax;
    size_t unsettled = 0;
    for (size_t i = 0; i < total; i++) {
        double res;
        make_start(&sr, i < plain ? i : o->nguess, sr.x, i < plain ? 0 : (int)(i - plain) + 1);
        s.hmax = hmax0;
        if (sr.ncon && !p->free1)
            follow_start(&sr, sr.x);
        bool conv = shoot_newton(p, sr.x, tol, &res);
        bool ok = conv && resolved(p, sr.x, sr.F, tol, &res);
        unsettled += conv && !ok;
        if (qd_ctx_status(ctx) == QD_ERR_NOMEM) {
            st = QD_ERR_NOMEM;
            goto done;
        }
        qd_ctx_clear_error(ctx);
        s.st = QD_OK;
        if (!ok && res < best && s.nm && shoot_eval(p, sr.x, sr.F, NULL))
            memcpy(best_iso, p->iso_res, s.nm * sizeof *best_iso);
        best = fmin(best, res);
        if (!ok)
            continue;
        double T = shoot_T(p, sr.x);
        bool dup = false;
        for (size_t k = 0; k < fd.count && !dup; k++)
            dup = same_path(p, &fd.paths[k], sr.x, T,
                            fd.paths[k].t[fd.paths[k].nsamples - 1] - o->t0) ||
                  family_member(p, &fd.paths[k], sr.x, o->nsamples ? o->nsamples : 101) ||
                  same_root(p, sr.x, fd.xs + k * p->nx, tol);
        if (dup)
            continue;
        if (fd.count == fd.cap) {
            size_t cap = fd.cap ? 2 * fd.cap : 4;
            qd_path *np = qd__realloc(ctx, fd.paths, cap * sizeof *np);
            if (np)
                fd.paths = np;
            double *nxs = np ? qd__realloc(ctx, fd.xs, cap * p->nx * sizeof *nxs) : NULL;
            if (!nxs) {
                st = QD_ERR_NOMEM;
                goto done;
            }
            fd.xs = nxs;
            fd.cap = cap;
        }
        memcpy(fd.xs + fd.count * p->nx, sr.x, p->nx * sizeof *sr.x);
        if (!path_fill(p, sr.x, o->nsamples ? o->nsamples : 101, res, &fd.paths[fd.count])) {
            path_clear(&fd.paths[fd.count]);
            st = qd_ctx_status(ctx) ? qd_ctx_status(ctx) : QD_ERR_NUMERIC;
            if (!qd_ctx_status(ctx))
                qd_ctx_error(ctx, st, "path: the samples of a converged path failed");
            goto done;
        }
        fd.count++;
        /* with multipliers the starts reach extremals of either sign (the
         * hanging chain and the arch): all are tried, the least kept */
        if (!o->all && (s.nm == 0 || i < o->nguess))
            break;
    }
    if (fd.count == 0) {
        no_path_error(ctx, &s, best, tol, best_iso, unsettled, p->N);
        st = QD_ERR_NUMERIC;
        goto done;
    }
    qsort(fd.paths, fd.count, sizeof *fd.paths, by_action);
    while (!o->all && fd.count > 1)
        path_clear(&fd.paths[--fd.count]);
    out->count = fd.count;
    out->paths = fd.paths;
    out->searched = o->all;
    fd.paths = NULL;
    fd.count = 0;
done:
    for (size_t k = 0; k < fd.count; k++)
        path_clear(&fd.paths[k]);
    qd__free(fd.paths);
    qd__free(fd.xs);
    qd__free(sr.x);
    qd__free(sr.F);
    qd__free(p->w);
    qd__free(p->y);
    sys_free(&s);
    return st;
}

qd_status qd_path_find(qd_ctx *ctx, const qd_model *m, const qd_eom *e, const qd_path_opts *opts,
                       qd_path_set *out) {
    QD_ARGS_CTX(ctx, ctx && m && e && opts && out);
    return path_search(ctx, m, e, false, 0, opts, out);
}

qd_status qd_path_find_energy(qd_ctx *ctx, const qd_model *m, const qd_eom *e, double E,
                              const qd_path_opts *opts, qd_path_set *out) {
    QD_ARGS_CTX(ctx, ctx && m && e && opts && out);
    return path_search(ctx, m, e, true, E, opts, out);
}
