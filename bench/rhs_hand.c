/*
 * bench/rhs_hand.c - the planar n-link pendulum's right-hand side written by
 * hand from the textbook formulas, independently of qdot (the baseline of
 * bench/rhs_bench.c).
 *
 * Point masses m_i at the ends of massless rods l_i, angles theta_i from
 * the downward vertical, mu_p = sum_{i >= p} m_i the mass hanging from
 * link p.  Lagrange's equations are M theta'' = f with
 *
 *     M_jk = mu_max(j,k) l_j l_k cos(theta_j - theta_k),
 *     f_j  = -sum_k mu_max(j,k) l_j l_k sin(theta_j - theta_k) theta_k'^2
 *            - mu_j g l_j sin(theta_j)
 *
 * (from T = sum_i m_i |r_i'|^2/2, V = sum_i m_i g y_i with
 * r_i = sum_{p <= i} l_p (sin theta_p, -cos theta_p); for n = 2 Goldstein
 * ch. 1 ex. 22, examples/double_pendulum.qd).  M is symmetric positive definite:
 * Cholesky.  Two versions: `textbook` calls sin and cos of each difference
 * theta_j - theta_k, as the formula reads; `sincos` takes sin and cos of
 * each angle once and forms the differences with the addition theorems, as
 * a careful hand would (and as qdot's generated code does).
 *
 * Parameters in qdot's model order: m1..mn, l1..ln, g.  y = (theta, theta').
 */
#include <math.h>

#define NMAX 64

int hand_cholesky(int n, double *M, double *x);

int hand_cholesky(int n, double *M, double *x) {
    for (int j = 0; j < n; j++) {
        double s = M[j * n + j];
        for (int k = 0; k < j; k++)
            s -= M[j * n + k] * M[j * n + k];
        if (!(s > 0))
            return 1;
        double d = sqrt(s);
        M[j * n + j] = d;
        for (int i = j + 1; i < n; i++) {
            double v = M[i * n + j];
            for (int k = 0; k < j; k++)
                v -= M[i * n + k] * M[j * n + k];
            M[i * n + j] = v / d;
        }
    }
    for (int i = 0; i < n; i++) {
        for (int k = 0; k < i; k++)
            x[i] -= M[i * n + k] * x[k];
        x[i] /= M[i * n + i];
    }
    for (int i = n - 1; i >= 0; i--) {
        for (int k = i + 1; k < n; k++)
            x[i] -= M[k * n + i] * x[k];
        x[i] /= M[i * n + i];
    }
    return 0;
}

/* M (lower triangle) and f from the differences' sines and cosines. */
static void assemble(int n, const double *y, const double *par, const double *mu,
                     const double *c, const double *s, const double *sn, double *M, double *f) {
    const double *l = par + n, g = par[2 * n];
    for (int j = 0; j < n; j++) {
        f[j] = -mu[j] * g * l[j] * sn[j];
        M[j * n + j] = mu[j] * l[j] * l[j];
    }
    for (int j = 0; j < n; j++)
        for (int k = j + 1; k < n; k++) {
            double a = mu[k] * l[j] * l[k]; /* max(j, k) = k */
            M[k * n + j] = a * c[j * n + k];
            /* sin(theta_j - theta_k) = s[j*n+k]; antisymmetric */
            f[j] -= a * s[j * n + k] * y[n + k] * y[n + k];
            f[k] += a * s[j * n + k] * y[n + j] * y[n + j];
        }
}

static void masses(int n, const double *par, double *mu) {
    double acc = 0;
    for (int i = n - 1; i >= 0; i--)
        mu[i] = acc += par[i];
}

int hand_rhs_textbook(int n, const double *y, const double *par, double *dydt) {
    double mu[NMAX], c[NMAX * NMAX], s[NMAX * NMAX], sn[NMAX], M[NMAX * NMAX];
    if (n < 1 || n > NMAX)
        return 1;
    masses(n, par, mu);
    for (int j = 0; j < n; j++) {
        sn[j] = sin(y[j]);
        for (int k = j + 1; k < n; k++) {
            c[j * n + k] = cos(y[j] - y[k]);
            s[j * n + k] = sin(y[j] - y[k]);
        }
    }
    assemble(n, y, par, mu, c, s, sn, M, dydt + n);
    for (int i = 0; i < n; i++)
        dydt[i] = y[n + i];
    return hand_cholesky(n, M, dydt + n);
}

int hand_rhs_sincos(int n, const double *y, const double *par, double *dydt) {
    double mu[NMAX], c[NMAX * NMAX], s[NMAX * NMAX], sn[NMAX], cs[NMAX], M[NMAX * NMAX];
    if (n < 1 || n > NMAX)
        return 1;
    masses(n, par, mu);
    for (int j = 0; j < n; j++) {
        sn[j] = sin(y[j]);
        cs[j] = cos(y[j]);
    }
    for (int j = 0; j < n; j++)
        for (int k = j + 1; k < n; k++) {
            c[j * n + k] = cs[j] * cs[k] + sn[j] * sn[k];
            s[j * n + k] = sn[j] * cs[k] - cs[j] * sn[k];
        }
    assemble(n, y, par, mu, c, s, sn, M, dydt + n);
    for (int i = 0; i < n; i++)
        dydt[i] = y[n + i];
    return hand_cholesky(n, M, dydt + n);
}
