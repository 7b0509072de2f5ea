/*
 * src/num/saddle.c - the saddle-point matrix of constrained motion, the
 * one assembly that qd_eom_eval (src/mech/saddle.c), the simulator
 * (src/sim/system.c) and the singularity check (src/mech/singular.c) use.
 */
#include "num.h"

#include <string.h>

void qd__num_saddle(size_t n, size_t m, const double *M, const double *f, const double *A,
                    const double *b, double *K, double *r) {
    size_t N = n + m;
    memset(K, 0, N * N * sizeof *K);
    for (size_t i = 0; i < n; i++) {
        for (size_t j = 0; j < n; j++)
            K[i * N + j] = M[i * n + j];
        if (r)
            r[i] = f[i];
    }
    for (size_t k = 0; k < m; k++) {
        for (size_t j = 0; j < n; j++) {
            K[j * N + n + k] = -A[k * n + j];
            K[(n + k) * N + j] = A[k * n + j];
        }
        if (r)
            r[n + k] = b[k];
    }
}
