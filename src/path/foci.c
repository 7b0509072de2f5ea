/*
 * src/path/foci.c - the kinetic foci of a motion (Desloge ch. 84): the
 * Jacobi (accessory) equation integrated along it, the times where J loses
 * rank, each with its multiplicity.
 *
 * The motion and J = dq/dv0, K = J' are integrated together,
 *
 *     q' = v,  v' = a(q, v, t),  J' = K,  K' = A J + B K,
 *     J(t0) = 0, K(t0) = Z0,  A = da/dq, B = da/dv,
 *
 * with the Dormand-Prince 5(4) pair and Shampine's dense output (the
 * tables of src/num/dopri5.c, the stages by num's loop, qd__num_rk_stages).  A and B are central differences of
 * qd_eom_eval's accelerations, not symbolic derivatives: e is const here
 * (qd_eom_solve would change it) and M q'' = f need not solve in closed
 * form; the step (cube root of eps, scaled) leaves them accurate to about
 * 1e-10 relative, well inside what locating a focus needs.
 *
 * Without constraints Z0 = I and J is n x n.  With holonomic constraints
 * (their multipliers inside a) the admissible v0 vary only in the kernel
 * of the velocity constraints, A_c(q0) dv0 = 0: Z0 is an orthonormal basis
 * of it (n x r, r = n - rank A_c), and J's columns stay tangent to the
 * constraint manifold (the linearized g'' = 0 keeps dg = dg' = 0), so J is
 * n x r and a focus is where its rank falls below r, with no basis needed
 * at q(t) (Gelfand and Fomin ch. 5 restrict the second variation to the
 * admissible variations alike).  Nonholonomic constraints are refused: the
 * path is then no stationary point of the action.
 *
 * A focus is a zero of sigma_min(J), the smallest singular value, not a
 * sign change of det J: at a focus of multiplicity k (k independent Jacobi
 * fields vanish together: k = 2 in the isotropic plane oscillator, det J =
 * (sin(w t)/w)^2) det J ~ (t - tc)^k keeps its sign for even k, while
 * sigma_min = c |t - tc| always has a minimum there.  The minima are the
 * sign changes from - to + of g = sigma_min sigma_min' = (J v).(K v) (v the
 * right singular vector), sampled NSUB times per step on the dense output
 * and located by the Illinois variant of regula falsi; one is a focus when
 * sigma_min reaches round-off there relative to |J| + (t - t0)|K|
 * (FZ_FOCUS), and its multiplicity is the number of singular values that
 * do (FZ_RANK).  A focus at t1 itself (sigma_min still falling) counts, the
 * interval being (t0, t1].  Two foci closer than h/NSUB can merge into one.
 */
#include "qdot/path.h"

#include <math.h>
#include <string.h>

#include "base/mem.h"
#include "num/num.h"
#include "../base/args.h"

#define FZ_RTOL 1e-12
#define FZ_MAXSTEPS 2000000
#define NSUB 8          /* g's samples per step */
/* sigma_min/scale at a located focus is J's error: 0 to 1e-14 with exact A
 * and B, up to 5e-11 measured with the central differences through a
 * constraint's multiplier (the pendulum on a rod, test_foci.c); a minimum
 * above FZ_FOCUS is no focus, and at a focus the singular values below
 * FZ_RANK count (foci closer than ~FZ_RANK relative merge: a multiplicity
 * then, which is what the data can tell). */
#define FZ_FOCUS 1e-7
#define FZ_RANK 1e-6
#define FZ_SWEEPS 60    /* one-sided Jacobi sweeps, far more than ever needed */

#define E qd__num_dp5_e /* the pair's tables, num's one copy */
#define P qd__num_dp5_p

typedef struct fz {
    qd_ctx *ctx;
    const qd_eom *e;
    size_t n, r, nc, nv, dim;          /* J is n x r; nc constraint rows */
    double t0;
    const qd_expr **syms;
    double *vals;
    double *y, *ynew, *k[7], *tmp, *yd; /* dim each (tmp 2n + dim) */
    qd_status st;                       /* the last right-hand side's (stage_rhs) */
    double *A, *B, *ap, *am, *M;        /* n*n, n*n, n, n, n*n */
    double *W, *V, *sv;                 /* n*n, n*n, n: the SVD's */
    double *Ac, *Q, *Z, *Mr;            /* nc*n, n*n, n*n, n*n: the tangent space's */
    double *foci;
    size_t *mult;
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
    size_t n = z->n, r = z->r, nr = n * r;
    memcpy(z->tmp, y, 2 * n * sizeof *y); /* perturbed in place by column() */
    double *q = z->tmp, *v = z->tmp + n;
    const double *J = y + 2 * n, *K = y + 2 * n + nr;
    memcpy(dy, v, n * sizeof *v);
    qd_status st = accel(z, t, q, v, dy + n);
    for (size_t j = 0; j < n && st == QD_OK; j++) {
        st = column(z, t, q, v, j, 0, z->A);
        if (st == QD_OK)
            st = column(z, t, q, v, j, 1, z->B);
    }
    if (st != QD_OK)
        return st;
    memcpy(dy + 2 * n, K, nr * sizeof *K);
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < r; j++) {
            double s = 0;
            for (size_t l = 0; l < n; l++)
                s += z->A[i * n + l] * J[l * r + j] + z->B[i * n + l] * K[l * r + j];
            dy[2 * n + nr + i * r + j] = s;
        }
    return QD_OK;
}

/* Rotate columns p and s of the rows x cols matrix X by (cs, sn). */
static void rotate(size_t rows, size_t cols, double *X, size_t p, size_t s, double cs, double sn) {
    for (size_t i = 0; i < rows; i++) {
        double a = X[i * cols + p], b = X[i * cols + s];
        X[i * cols + p] = cs * a - sn * b;
        X[i * cols + s] = sn * a + cs * b;
    }
}

/* The singular values sv (r) of the n x r matrix W, overwritten by W V,
 * V (r x r) the right singular vectors: one-sided Jacobi (Hestenes), which
 * keeps the small singular values to full relative accuracy. */
static void svd(size_t n, size_t r, double *W, double *V, double *sv) {
    for (size_t i = 0; i < r * r; i++)
        V[i] = i % (r + 1) == 0;
    bool rotated = true;
    for (int sweep = 0; sweep < FZ_SWEEPS && rotated; sweep++) {
        rotated = false;
        for (size_t p = 0; p + 1 < r; p++)
            for (size_t s = p + 1; s < r; s++) {
                double a = 0, b = 0, c = 0;
                for (size_t i = 0; i < n; i++) {
                    a += W[i * r + p] * W[i * r + p];
                    b += W[i * r + s] * W[i * r + s];
                    c += W[i * r + p] * W[i * r + s];
                }
                if (c == 0 || fabs(c) <= 1e-15 * sqrt(a * b))
                    continue;
                rotated = true;
                double zeta = (b - a) / (2 * c);
                double tn = (zeta >= 0 ? 1 : -1) / (fabs(zeta) + sqrt(1 + zeta * zeta));
                double cs = 1 / sqrt(1 + tn * tn);
                rotate(n, r, W, p, s, cs, cs * tn);
                rotate(r, r, V, p, s, cs, cs * tn);
            }
    }
    for (size_t j = 0; j < r; j++) {
        double s = 0;
        for (size_t i = 0; i < n; i++)
            s += W[i * r + j] * W[i * r + j];
        sv[j] = sqrt(s);
    }
}

/* What the state x says of a focus at time t: returns g = sigma_min
 * sigma_min' = (J v).(K v); *rel = sigma_min/scale, scale = |J| + (t -
 * t0)|K| (J's size whatever the units), and z->sv all singular values over
 * the scale. */
static double probe(fz *z, double t, const double *x, double *rel) {
    size_t n = z->n, r = z->r, nr = n * r, jm = 0;
    const double *J = x + 2 * n, *K = x + 2 * n + nr;
    double nj = 0, nk = 0, g = 0;
    if (r == 0) { /* the constraints leave no freedom: nothing to vary */
        *rel = 1;
        return 1;
    }
    for (size_t i = 0; i < nr; i++)
        nj += J[i] * J[i], nk += K[i] * K[i];
    double scale = sqrt(nj) + (t - z->t0) * sqrt(nk);
    memcpy(z->W, J, nr * sizeof *J);
    svd(n, r, z->W, z->V, z->sv);
    for (size_t j = 1; j < r; j++)
        if (z->sv[j] < z->sv[jm])
            jm = j;
    for (size_t i = 0; i < n; i++) {
        double kv = 0;
        for (size_t l = 0; l < r; l++)
            kv += K[i * r + l] * z->V[l * r + jm];
        g += z->W[i * r + jm] * kv;
    }
    for (size_t j = 0; j < r; j++)
        z->sv[j] = scale > 0 ? z->sv[j] / scale : 1;
    *rel = z->sv[jm];
    return g;
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

/* Append u (n), orthogonalized against the rank rows of Q (Gram-Schmidt
 * twice) and normalized, as Q's next row; false when it lies in their span. */
static bool extend(size_t n, double *Q, size_t rank, const double *u) {
    double *w = Q + rank * n, n0 = 0, n1 = 0;
    memcpy(w, u, n * sizeof *u);
    for (size_t i = 0; i < n; i++)
        n0 += w[i] * w[i];
    for (int pass = 0; pass < 2; pass++)
        for (size_t b = 0; b < rank; b++) {
            double d = 0;
            for (size_t i = 0; i < n; i++)
                d += w[i] * Q[b * n + i];
            for (size_t i = 0; i < n; i++)
                w[i] -= d * Q[b * n + i];
        }
    for (size_t i = 0; i < n; i++)
        n1 += w[i] * w[i];
    if (!(n1 > 1e-20 * n0))
        return false;
    for (size_t i = 0; i < n; i++)
        w[i] /= sqrt(n1);
    return true;
}

/* z->Z (n x *r, row-major): an orthonormal basis of the kernel of the
 * constraint rows A_c at the state in z->vals (R^n without constraints):
 * the rows orthonormalized, redundant ones dropped, then completed by the
 * unit vectors that stick out of the span most. */
static qd_status tangent(fz *z, size_t *r) {
    size_t n = z->n, rank = 0, rows;
    for (size_t k = 0; k < z->nc; k++) {
        for (size_t j = 0; j < n; j++) {
            qd_status st = qd_eval(z->ctx, z->e->con[k].a[j], z->nv, z->syms, z->vals,
                                   &z->Ac[j]);
            if (st != QD_OK)
                return st;
        }
        rank += extend(n, z->Q, rank, z->Ac);
    }
    rows = rank;
    while (rank < n) {
        size_t best = 0;
        double most = -1;
        for (size_t i = 0; i < n; i++) {
            double s = 1;
            for (size_t b = 0; b < rank; b++)
                s -= z->Q[b * n + i] * z->Q[b * n + i];
            if (s > most)
                most = s, best = i;
        }
        memset(z->Ac, 0, n * sizeof *z->Ac);
        z->Ac[best] = 1;
        if (!extend(n, z->Q, rank, z->Ac))
            break; /* cannot happen: the unit vector sticking out most is not in the span */
        rank++;
    }
    *r = rank - rows;
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < *r; j++)
            z->Z[i * *r + j] = z->Q[(rows + j) * n + i];
    return QD_OK;
}

/* Z^T M Z (r x r) into z->Mr. */
static void restrict_to(fz *z, size_t r) {
    size_t n = z->n;
    for (size_t a = 0; a < r; a++)
        for (size_t b = 0; b < r; b++) {
            double s = 0;
            for (size_t i = 0; i < n; i++)
                for (size_t j = 0; j < n; j++)
                    s += z->Z[i * r + a] * z->M[i * n + j] * z->Z[j * r + b];
            z->Mr[a * r + b] = s;
        }
}

/* The Legendre condition at the state y: M = d^2L/dq'dq' positive definite
 * on the admissible velocities (the constraints' tangent space). */
static qd_status legendre_at(fz *z, double t, const double *y) {
    size_t n = z->n, r = n;
    memcpy(z->vals, y, 2 * n * sizeof *y);
    z->vals[2 * n] = t;
    qd_status st = qd_eom_eval(z->ctx, z->e, z->nv, z->syms, z->vals, z->M, NULL, NULL, NULL,
                               NULL);
    if (st == QD_ERR_SINGULAR && qd__ctx_recover(z->ctx)) { /* singular M: not definite */
        z->legendre = false;
        return QD_OK;
    }
    if (st == QD_OK && z->nc)
        st = tangent(z, &r);
    if (st != QD_OK)
        return st;
    if (z->nc)
        restrict_to(z, r);
    else
        memcpy(z->Mr, z->M, n * n * sizeof *z->M);
    if (!posdef(r, z->Mr))
        z->legendre = false;
    return QD_OK;
}

/* The state at told + x h from the dense output of the last step, into
 * z->yd. */
static void dense(fz *z, double h, double x) {
    for (size_t i = 0; i < z->dim; i++) {
        double s = 0;
        for (int c = 3; c >= 0; c--) {
            double b = 0;
            for (int j = 0; j < 7; j++)
                b += z->k[j][i] * P[j][c];
            s = (s + b) * x;
        }
        z->yd[i] = z->y[i] + h * s;
    }
}

static double probe_at(fz *z, double told, double h, double x, double *rel) {
    dense(z, h, x);
    return probe(z, told + x * h, z->yd, rel);
}

static qd_status add_focus(fz *z, double t, size_t mult) {
    if (z->nfoci == z->cap) {
        size_t cap = z->cap ? 2 * z->cap : 4;
        double *f = qd__realloc(z->ctx, z->foci, cap * sizeof *f);
        if (f)
            z->foci = f;
        size_t *m = f ? qd__realloc(z->ctx, z->mult, cap * sizeof *m) : NULL;
        if (!m)
            return QD_ERR_NOMEM;
        z->mult = m;
        z->cap = cap;
    }
    z->foci[z->nfoci] = t;
    z->mult[z->nfoci++] = mult;
    return QD_OK;
}

/* A focus at t if sigma_min is round-off there (z->sv from the probe at t):
 * its multiplicity is how many singular values are. */
static qd_status judge(fz *z, double t, double rel) {
    if (!(rel < FZ_FOCUS))
        return QD_OK; /* a minimum of sigma_min above zero: no focus */
    size_t mult = 0;
    for (size_t j = 0; j < z->r; j++)
        mult += z->sv[j] < FZ_RANK;
    return add_focus(z, t, mult);
}

/* The minimum of sigma_min in (told + a h, told + b h), ga < 0 <= gb the
 * values of g at the ends: Illinois regula falsi on g. */
static qd_status locate(fz *z, double told, double h, double a, double b, double ga,
                        double gb) {
    int side = 0;
    double rel;
    for (int it = 0; it < 200 && b - a > 4 * 0x1p-52 && gb != 0; it++) {
        double x = (a * gb - b * ga) / (gb - ga);
        if (!(x > a && x < b))
            x = 0.5 * (a + b);
        double gx = probe_at(z, told, h, x, &rel);
        if (gx >= 0) {
            b = x, gb = gx;
            if (side == -1)
                ga *= 0.5;
            side = -1;
        } else {
            a = x, ga = gx;
            if (side == 1)
                gb *= 0.5;
            side = 1;
        }
    }
    double x = gb == 0 ? b : 0.5 * (a + b);
    (void)probe_at(z, told, h, x, &rel);
    return judge(z, told + h * x, rel);
}

/* The minima of sigma_min in the step just taken (told, told + h]: g
 * sampled NSUB times; *gprev carries g at the step's start and leaves g
 * at its end. */
static qd_status scan(fz *z, double told, double h, double *gprev, double *relend) {
    qd_status st = QD_OK;
    double xa = 0, ga = *gprev;
    for (int s = 1; s <= NSUB && st == QD_OK; s++) {
        double xb = (double)s / NSUB, gb = probe_at(z, told, h, xb, relend);
        if (ga < 0 && gb >= 0)
            st = locate(z, told, h, xa, xb, ga, gb);
        xa = xb, ga = gb;
    }
    *gprev = ga;
    return st;
}

/* rhs as num's stage loop calls it: the status kept in z->st. */
static bool stage_rhs(void *data, double t, const double *y, double *dy) {
    fz *z = data;
    z->st = rhs(z, t, y, dy);
    return z->st == QD_OK;
}

/* One Dormand-Prince attempt of size h from (t, z->y): z->ynew, the seven
 * stages in z->k (the last at t + h, for the dense output) and the scaled
 * error norm.  The stages are num's one loop (qd__num_rk_stages on
 * qd__num_dp5, as src/sim's dopri5 steps); k[0] is evaluated here, not
 * carried over from the last step, so a rejected step costs what it did. */
static qd_status attempt(fz *z, double t, double h, double *errn) {
    size_t dim = z->dim;
    z->st = rhs(z, t, z->y, z->k[0]);
    if (z->st == QD_OK) /* tmp's tail: the stage state (rhs perturbs its head) */
        (void)qd__num_rk_stages(&qd__num_dp5, stage_rhs, z, dim, t, h, z->y, z->ynew, z->k,
                                z->tmp + 2 * z->n, true);
    qd_status st = z->st;
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

/* The integration from t0 to t1, the foci recorded as found. */
static qd_status run(fz *z, double t0, double t1) {
    double t = t0, h = (t1 - t0) * 1e-4, g = 0, rel = 1;
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
        st = scan(z, t, h, &g, &rel);
        t = (t + h >= t1) ? t1 : t + h;
        memcpy(z->y, z->ynew, z->dim * sizeof *z->y);
        if (st == QD_OK)
            st = legendre_at(z, t, z->y);
        h *= fmin(5.0, 0.9 * pow(fmax(errn, 1e-10), -0.2));
    }
    if (st == QD_OK && g < 0) /* still falling at t1 (z->sv from there): a focus at t1? */
        st = judge(z, t1, rel);
    return st;
}

static qd_status setup(fz *z, const qd_model *m, const double *q0, const double *v0) {
    size_t n = z->n, np = qd_model_nparams(m), nn = n * n;
    z->nv = 2 * n + 1 + np;
    z->syms = qd__calloc(z->ctx, z->nv, sizeof *z->syms);
    z->vals = qd__calloc(z->ctx, z->nv, sizeof *z->vals);
    z->Ac = qd__calloc(z->ctx, n, sizeof *z->Ac);
    /* the tangent space's Q, Z, Mr; M, A, B, W, V; ap, am, sv */
    double *fix = qd__calloc(z->ctx, 8 * nn + 3 * n, sizeof *fix);
    if (!z->syms || !z->vals || !z->Ac || !fix) {
        qd__free(fix);
        return QD_ERR_NOMEM;
    }
    z->Q = fix, z->Z = z->Q + nn, z->Mr = z->Z + nn, z->M = z->Mr + nn, z->A = z->M + nn;
    z->B = z->A + nn, z->W = z->B + nn, z->V = z->W + nn, z->ap = z->V + nn;
    z->am = z->ap + n, z->sv = z->am + n;
    for (size_t j = 0; j < n; j++) {
        z->syms[j] = z->e->q[j];
        z->syms[n + j] = z->e->qd[j];
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
    memcpy(z->vals, q0, n * sizeof *q0);
    memcpy(z->vals + n, v0, n * sizeof *v0);
    z->vals[2 * n] = z->t0;
    return QD_OK;
}

/* The state y = (q0, v0, J = 0, K = Z0) and its workspaces. */
static qd_status start(fz *z, const double *q0, const double *v0) {
    size_t n = z->n, r = n;
    qd_status st = z->nc ? tangent(z, &r) : QD_OK;
    if (st != QD_OK)
        return st;
    z->r = r;
    z->dim = 2 * n + 2 * n * r;
    /* y, ynew, 7 stages, yd, tmp (2n + dim) */
    double *buf = qd__calloc(z->ctx, 11 * z->dim + 2 * n, sizeof *buf);
    if (!buf)
        return QD_ERR_NOMEM;
    z->y = buf, z->ynew = buf + z->dim;
    for (int s = 0; s < 7; s++)
        z->k[s] = buf + (2 + (size_t)s) * z->dim;
    z->yd = buf + 9 * z->dim, z->tmp = buf + 10 * z->dim;
    memcpy(z->y, q0, n * sizeof *q0);
    memcpy(z->y + n, v0, n * sizeof *v0);
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < r; j++)
            z->y[2 * n + n * r + i * r + j] = z->nc ? z->Z[i * r + j] : (i == j);
    return QD_OK;
}

static qd_status check_args(qd_ctx *ctx, const qd_eom *e, double t0, double t1) {
    for (size_t k = 0; k < e->ncon; k++)
        if (e->con[k].kind == QD_CON_NONHOLONOMIC) {
            qd_ctx_error(ctx, QD_ERR_ARG, "kinetic foci: constraint %s is nonholonomic: its "
                         "motions are no stationary paths of the action, so they have no "
                         "kinetic foci", e->con[k].name);
            return QD_ERR_ARG;
        }
    if (!(isfinite(t0) && isfinite(t1) && t1 > t0)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "kinetic foci: t1 (%g) must be after t0 (%g)", t1, t0);
        return QD_ERR_ARG;
    }
    return QD_OK;
}

static void fz_free(fz *z) {
    qd__free(z->syms);
    qd__free(z->vals);
    qd__free(z->Ac);
    qd__free(z->Q);
    qd__free(z->y);
}

qd_status qd_path_foci_mult(qd_ctx *ctx, const qd_model *m, const qd_eom *e, double t0,
                            const double *q0, const double *v0, double t1, double **foci,
                            size_t **mult, size_t *nfoci, bool *legendre) {
    QD_ARGS_CTX(ctx, ctx && m && e && q0 && v0 && foci && nfoci);
    if (!ctx || !m || !e || !q0 || !v0 || !foci || !nfoci) {
        if (ctx)
            qd_ctx_error(ctx, QD_ERR_ARG, "qd_path_foci: a NULL argument");
        return QD_ERR_ARG;
    }
    *foci = NULL;
    if (mult)
        *mult = NULL;
    *nfoci = 0;
    qd_status st = check_args(ctx, e, t0, t1);
    if (st != QD_OK)
        return st;
    fz z = {.ctx = ctx, .e = e, .n = e->n, .nc = e->ncon, .t0 = t0, .legendre = true};
    st = setup(&z, m, q0, v0);
    if (st == QD_OK)
        st = start(&z, q0, v0);
    if (st == QD_OK)
        st = run(&z, t0, t1);
    fz_free(&z);
    if (st != QD_OK) {
        qd__free(z.foci);
        qd__free(z.mult);
        return st;
    }
    *foci = z.foci;
    *nfoci = z.nfoci;
    if (mult)
        *mult = z.mult;
    else
        qd__free(z.mult);
    if (legendre)
        *legendre = z.legendre;
    return QD_OK;
}

qd_status qd_path_foci(qd_ctx *ctx, const qd_model *m, const qd_eom *e, double t0,
                       const double *q0, const double *v0, double t1, double **foci,
                       size_t *nfoci, bool *legendre) {
    QD_ARGS_CTX(ctx, ctx && m && e && q0 && v0 && foci && nfoci);
    return qd_path_foci_mult(ctx, m, e, t0, q0, v0, t1, foci, NULL, nfoci, legendre);
}

void qd_path_foci_free(qd_ctx *ctx, double *foci) {
    (void)ctx;
    qd__free(foci);
}

void qd_path_foci_mult_free(qd_ctx *ctx, size_t *mult) {
    QD_ARGS(, mult);
    (void)ctx;
    qd__free(mult);
}
