/*
 * src/path/foci.c - the kinetic foci of a motion (Desloge ch. 84): the
 * Jacobi (accessory) equation integrated along it, the zeros of det J.
 *
 * The motion and J = dq/dv0, K = J' are integrated together,
 *
 *     q' = v,  v' = a(q, v, t),  J' = K,  K' = A J + B K,
 *     J(t0) = 0, K(t0) = I,  A = da/dq, B = da/dv,
 *
 * with the Dormand-Prince 5(4) pair and Shampine's dense output (the
 * tables of src/sim/dopri5.c).  A and B are central differences of
 * qd_eom_eval's accelerations, not symbolic derivatives: e is const here
 * (qd_eom_solve would change it) and M q'' = f need not solve in closed
 * form; the step (cube root of eps, scaled) leaves them accurate to about
 * 1e-10 relative, well inside what locating a focus needs.  A focus is a
 * sign change of det J between two accepted steps, located by the Illinois
 * variant of regula falsi on the dense output to round-off in the step.  A
 * focus of even multiplicity (det touching zero, as in an isotropic
 * oscillator) does not change the sign and is not seen.
 */
#include "qdot/path.h"

#include <math.h>
#include <string.h>

#include "base/mem.h"

#define FZ_RTOL 1e-12
#define FZ_MAXSTEPS 2000000

static const double C[7] = {0, 1.0 / 5, 3.0 / 10, 4.0 / 5, 8.0 / 9, 1, 1};
static const double AT[7][6] = {
    {0, 0, 0, 0, 0, 0},
    {1.0 / 5, 0, 0, 0, 0, 0},
    {3.0 / 40, 9.0 / 40, 0, 0, 0, 0},
    {44.0 / 45, -56.0 / 15, 32.0 / 9, 0, 0, 0},
    {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729, 0, 0},
    {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656, 0},
    {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84}};
static const double E[7] = {-71.0 / 57600, 0, 71.0 / 16695, -71.0 / 1920, 17253.0 / 339200,
                            -22.0 / 525, 1.0 / 40};
static const double P[7][4] = {
    {1, -8048581381.0 / 2820520608, 8663915743.0 / 2820520608, -12715105075.0 / 11282082432},
    {0, 0, 0, 0},
    {0, 131558114200.0 / 32700410799, -68118460800.0 / 10900136933,
     87487479700.0 / 32700410799},
    {0, -1754552775.0 / 470086768, 14199869525.0 / 1410260304, -10690763975.0 / 1880347072},
    {0, 127303824393.0 / 49829197408, -318862633887.0 / 49829197408,
     701980252875.0 / 199316789632},
    {0, -282668133.0 / 205662961, 2019193451.0 / 616988883, -1453857185.0 / 822651844},
    {0, 40617522.0 / 29380423, -110615467.0 / 29380423, 69997945.0 / 29380423}};

typedef struct fz {
    qd_ctx *ctx;
    const qd_eom *e;
    size_t n, nv, dim;
    const qd_expr **syms;
    double *vals;
    double *y, *ynew, *k[7], *tmp; /* dim each */
    double *A, *B, *ap, *am, *M, *work; /* n*n, n*n, n, n, n*n, n*n */
    double *foci;
    size_t nfoci, cap;
    bool legendre;
} fz;

/* The accelerations at (t, q, v). */
static qd_status accel(fz *z, double t, const double *q, const double *v, double *a) {
    size_t n = z->n;
    memcpy(z->vals, q, n * sizeof *q);
    memcpy(z->vals + n, v, n * sizeof *v);
    z->vals[2 * n] = t;
    return qd_eom_eval(z->ctx, z->e, z->nv, z->syms, z->vals, NULL, NULL, a, NULL, NULL);
}

/* Column j of da/dx (x = q or v, which = 0 or 1) by a central difference. */
static qd_status column(fz *z, double t, double *q, double *v, size_t j, int which, double *D) {
    double *x = which ? v : q, x0 = x[j], h = 6e-6 * (1 + fabs(x0));
    size_t n = z->n;
    x[j] = x0 + h;
    qd_status st = accel(z, t, q, v, z->ap);
    x[j] = x0 - h;
    if (st == QD_OK)
        st = accel(z, t, q, v, z->am);
    x[j] = x0;
    for (size_t i = 0; i < n; i++)
        D[i * n + j] = (z->ap[i] - z->am[i]) / (2 * h);
    return st;
}

/* dy = the right-hand side of the motion with its Jacobi equation. */
static qd_status rhs(fz *z, double t, const double *y, double *dy) {
    size_t n = z->n, nn = n * n;
    memcpy(z->tmp, y, 2 * n * sizeof *y); /* perturbed in place by column() */
    double *q = z->tmp, *v = z->tmp + n;
    const double *J = y + 2 * n, *K = y + 2 * n + nn;
    memcpy(dy, v, n * sizeof *v);
    qd_status st = accel(z, t, q, v, dy + n);
    for (size_t j = 0; j < n && st == QD_OK; j++) {
        st = column(z, t, q, v, j, 0, z->A);
        if (st == QD_OK)
            st = column(z, t, q, v, j, 1, z->B);
    }
    if (st != QD_OK)
        return st;
    memcpy(dy + 2 * n, K, nn * sizeof *K);
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++) {
            double s = 0;
            for (size_t l = 0; l < n; l++)
                s += z->A[i * n + l] * J[l * n + j] + z->B[i * n + l] * K[l * n + j];
            dy[2 * n + nn + i * n + j] = s;
        }
    return QD_OK;
}

/* The determinant of the n x n matrix a (destroyed), partial pivoting. */
static double det(size_t n, double *a) {
    double d = 1;
    for (size_t c = 0; c < n; c++) {
        size_t p = c;
        for (size_t r = c + 1; r < n; r++)
            if (fabs(a[r * n + c]) > fabs(a[p * n + c]))
                p = r;
        if (a[p * n + c] == 0)
            return 0;
        if (p != c) {
            for (size_t k = 0; k < n; k++) {
                double s = a[c * n + k];
                a[c * n + k] = a[p * n + k];
                a[p * n + k] = s;
            }
            d = -d;
        }
        d *= a[c * n + c];
        for (size_t r = c + 1; r < n; r++) {
            double f = a[r * n + c] / a[c * n + c];
            for (size_t k = c; k < n; k++)
                a[r * n + k] -= f * a[c * n + k];
        }
    }
    return d;
}

/* Is the symmetric a (destroyed) positive definite?  Cholesky. */
static bool posdef(size_t n, double *a) {
    for (size_t j = 0; j < n; j++) {
        double s = a[j * n + j];
        for (size_t k = 0; k < j; k++)
            s -= a[j * n + k] * a[j * n + k];
        if (!(s > 0))
            return false;
        a[j * n + j] = sqrt(s);
        for (size_t i = j + 1; i < n; i++) {
            double r = a[i * n + j];
            for (size_t k = 0; k < j; k++)
                r -= a[i * n + k] * a[j * n + k];
            a[i * n + j] = r / a[j * n + j];
        }
    }
    return true;
}

/* The Legendre condition at the state y: M = d^2L/dq'dq' positive definite. */
static qd_status legendre_at(fz *z, double t, const double *y) {
    size_t n = z->n;
    memcpy(z->vals, y, 2 * n * sizeof *y);
    z->vals[2 * n] = t;
    qd_status st = qd_eom_eval(z->ctx, z->e, z->nv, z->syms, z->vals, z->M, NULL, NULL, NULL,
                               NULL);
    if (st == QD_ERR_SINGULAR && qd__ctx_recover(z->ctx)) { /* singular M: not definite */
        z->legendre = false;
        return QD_OK;
    }
    if (st == QD_OK && !posdef(n, z->M))
        z->legendre = false;
    return st;
}

/* det J at told + x h from the dense output of the last step. */
static double det_dense(fz *z, double h, double x) {
    size_t n = z->n, nn = n * n, off = 2 * n;
    for (size_t i = 0; i < nn; i++) {
        double s = 0;
        for (int c = 3; c >= 0; c--) {
            double b = 0;
            for (int j = 0; j < 7; j++)
                b += z->k[j][off + i] * P[j][c];
            s = (s + b) * x;
        }
        z->work[i] = z->y[off + i] + h * s;
    }
    return det(n, z->work);
}

static qd_status add_focus(fz *z, double t) {
    if (z->nfoci == z->cap) {
        size_t cap = z->cap ? 2 * z->cap : 4;
        double *f = qd__realloc(z->ctx, z->foci, cap * sizeof *f);
        if (!f)
            return QD_ERR_NOMEM;
        z->foci = f;
        z->cap = cap;
    }
    z->foci[z->nfoci++] = t;
    return QD_OK;
}

/* The zero of det J in the step (told, told + h], d0 and d1 its values at
 * the ends of opposite signs: Illinois regula falsi in x = (t - told)/h. */
static qd_status locate(fz *z, double told, double h, double d0, double d1) {
    double a = 0, b = 1, fa = d0, fb = d1;
    int side = 0;
    for (int it = 0; it < 200 && b - a > 4 * 0x1p-52; it++) {
        double x = (a * fb - b * fa) / (fb - fa);
        if (!(x > a && x < b))
            x = 0.5 * (a + b);
        double fx = det_dense(z, h, x);
        if (fx == 0) {
            a = b = x;
            break;
        }
        if ((fx > 0) == (fb > 0)) {
            b = x, fb = fx;
            if (side == -1)
                fa *= 0.5;
            side = -1;
        } else {
            a = x, fa = fx;
            if (side == 1)
                fb *= 0.5;
            side = 1;
        }
    }
    return add_focus(z, told + h * 0.5 * (a + b));
}

/* One Dormand-Prince attempt of size h from (t, z->y): z->ynew and the
 * scaled error norm. */
static qd_status attempt(fz *z, double t, double h, double *errn) {
    size_t dim = z->dim;
    qd_status st = QD_OK;
    for (int s = 0; s < 7 && st == QD_OK; s++) {
        double *ys = s == 6 ? z->ynew : z->tmp + 2 * z->n; /* tmp's tail: stage state */
        for (size_t i = 0; i < dim; i++) {
            double acc = 0;
            for (int j = 0; j < s; j++)
                acc += AT[s][j] * z->k[j][i];
            ys[i] = z->y[i] + h * acc;
        }
        st = rhs(z, t + C[s] * h, ys, z->k[s]);
    }
    double sum = 0;
    for (size_t i = 0; i < dim && st == QD_OK; i++) {
        double err = 0;
        for (int j = 0; j < 7; j++)
            err += E[j] * z->k[j][i];
        double sc = FZ_RTOL * (1 + fmax(fabs(z->y[i]), fabs(z->ynew[i])));
        sum += (h * err / sc) * (h * err / sc);
    }
    *errn = sqrt(sum / (double)dim);
    return st;
}

/* The integration from t0 to t1, foci recorded as det J changes sign. */
static qd_status run(fz *z, double t0, double t1) {
    size_t n = z->n, nn = n * n;
    double t = t0, h = (t1 - t0) * 1e-4, dprev = 0;
    qd_status st = legendre_at(z, t, z->y);
    for (size_t steps = 0; st == QD_OK && t < t1; steps++) {
        if (steps == FZ_MAXSTEPS) {
            qd_ctx_error(z->ctx, QD_ERR_NUMERIC, "the Jacobi equation needs more than %d steps "
                         "up to t = %g (reached t = %g)", FZ_MAXSTEPS, t1, t);
            return QD_ERR_NUMERIC;
        }
        if (t + h > t1)
            h = t1 - t;
        double errn;
        st = attempt(z, t, h, &errn);
        if (st != QD_OK)
            break;
        if (!isfinite(errn) || errn > 1) {
            h *= isfinite(errn) ? fmax(0.2, 0.9 * pow(errn, -0.2)) : 0.2;
            if (h <= 1e-14 * (1 + fabs(t))) {
                qd_ctx_error(z->ctx, QD_ERR_NUMERIC, "the Jacobi equation's step fell to "
                             "round-off at t = %g", t);
                return QD_ERR_NUMERIC;
            }
            continue;
        }
        memcpy(z->work, z->ynew + 2 * n, nn * sizeof *z->work);
        double d = det(n, z->work);
        if (dprev != 0 && d != 0 && (d > 0) != (dprev > 0))
            st = locate(z, t, h, dprev, d);
        else if (d == 0 && t + h > t0)
            st = add_focus(z, t + h);
        dprev = d; /* 0 after an exact zero: the next sign starts afresh */
        t = (t + h >= t1) ? t1 : t + h;
        memcpy(z->y, z->ynew, z->dim * sizeof *z->y);
        if (st == QD_OK)
            st = legendre_at(z, t, z->y);
        h *= fmin(5.0, 0.9 * pow(fmax(errn, 1e-10), -0.2));
    }
    return st;
}

static qd_status setup(fz *z, const qd_model *m, double t0, const double *q0, const double *v0) {
    size_t n = z->n, np = qd_model_nparams(m), nn = n * n;
    z->nv = 2 * n + 1 + np;
    z->dim = 2 * n + 2 * nn;
    z->syms = qd__calloc(z->ctx, z->nv, sizeof *z->syms);
    z->vals = qd__calloc(z->ctx, z->nv, sizeof *z->vals);
    /* y, ynew, 7 stages, tmp (2n + dim), A, B, M, work, ap, am */
    double *buf = qd__calloc(z->ctx, 10 * z->dim + 2 * n + 4 * nn + 2 * n, sizeof *buf);
    if (!z->syms || !z->vals || !buf)
        return QD_ERR_NOMEM;
    z->y = buf, z->ynew = buf + z->dim;
    for (int s = 0; s < 7; s++)
        z->k[s] = buf + (2 + (size_t)s) * z->dim;
    z->tmp = buf + 9 * z->dim;
    z->A = z->tmp + 2 * n + z->dim, z->B = z->A + nn, z->M = z->B + nn, z->work = z->M + nn;
    z->ap = z->work + nn, z->am = z->ap + n;
    for (size_t j = 0; j < n; j++) {
        z->syms[j] = z->e->q[j];
        z->syms[n + j] = z->e->qd[j];
        z->y[j] = q0[j];
        z->y[n + j] = v0[j];
        z->y[2 * n + nn + j * n + j] = 1; /* K(t0) = I */
    }
    z->syms[2 * n] = qd_time(z->ctx);
    for (size_t i = 0; i < np; i++) {
        z->syms[2 * n + 1 + i] = qd_model_param(m, i);
        if (qd_model_param_number(m, i, &z->vals[2 * n + 1 + i]) != QD_OK) {
            qd_ctx_error(z->ctx, QD_ERR_ARG, "parameter %s has no finite value",
                         qd_expr_name(qd_model_param(m, i)));
            return QD_ERR_ARG;
        }
    }
    (void)t0;
    return QD_OK;
}

static qd_status check_args(qd_ctx *ctx, const qd_eom *e, double t0, double t1) {
    if (e->ncon > 0) {
        qd_ctx_error(ctx, QD_ERR_ARG, "kinetic foci: not yet for constrained models (%zu "
                     "constraint%s): eliminate them into the coordinates", e->ncon,
                     e->ncon == 1 ? "" : "s");
        return QD_ERR_ARG;
    }
    if (!(isfinite(t0) && isfinite(t1) && t1 > t0)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "kinetic foci: t1 (%g) must be after t0 (%g)", t1, t0);
        return QD_ERR_ARG;
    }
    return QD_OK;
}

qd_status qd_path_foci(qd_ctx *ctx, const qd_model *m, const qd_eom *e, double t0,
                       const double *q0, const double *v0, double t1, double **foci,
                       size_t *nfoci, bool *legendre) {
    if (!ctx || !m || !e || !q0 || !v0 || !foci || !nfoci) {
        if (ctx)
            qd_ctx_error(ctx, QD_ERR_ARG, "qd_path_foci: a NULL argument");
        return QD_ERR_ARG;
    }
    *foci = NULL;
    *nfoci = 0;
    qd_status st = check_args(ctx, e, t0, t1);
    if (st != QD_OK)
        return st;
    fz z = {.ctx = ctx, .e = e, .n = e->n, .legendre = true};
    st = setup(&z, m, t0, q0, v0);
    if (st == QD_OK)
        st = run(&z, t0, t1);
    qd__free(z.syms);
    qd__free(z.vals);
    qd__free(z.y);
    if (st != QD_OK) {
        qd__free(z.foci);
        return st;
    }
    *foci = z.foci;
    *nfoci = z.nfoci;
    if (legendre)
        *legendre = z.legendre;
    return QD_OK;
}

void qd_path_foci_free(qd_ctx *ctx, double *foci) {
    (void)ctx;
    qd__free(foci);
}
