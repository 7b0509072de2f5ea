/*
 * bench/eval_ref.c - the planar n-pendulum's mass matrix and potential
 * gradient written by hand (n <= 32), the baseline bench_eval.c measures qd_prog
 * against.  Input layout as in bench_eval.c: q[n], q'[n], l[n], m[n], g.
 *
 * Bob i hangs at x_i = sum_{k<=i} l_k sin q_k, y_i = -sum_{k<=i} l_k cos q_k, so
 *   M_jk = l_j l_k cos(q_j - q_k) sum_{i >= max(j,k)} m_i,
 *   dV/dq_j = g l_j sin q_j sum_{i >= j} m_i.
 */
#include <math.h>

#define REF_NMAX 32

void ref_eval(int n, const double *in, double *out);

void ref_eval(int n, const double *in, double *out) {
    const double *q = in, *l = in + 2 * n, *m = in + 3 * n, g = in[4 * n];
    double s[REF_NMAX], c[REF_NMAX], mu[REF_NMAX + 1];
    mu[n] = 0;
    for (int i = n - 1; i >= 0; i--) {
        s[i] = sin(q[i]);
        c[i] = cos(q[i]);
        mu[i] = mu[i + 1] + m[i];
    }
    for (int j = 0; j < n; j++)
        for (int k = 0; k < n; k++)
            out[j * n + k] = mu[j > k ? j : k] * l[j] * l[k] * (c[j] * c[k] + s[j] * s[k]);
    for (int j = 0; j < n; j++)
        out[n * n + j] = g * l[j] * s[j] * mu[j];
}
