/*
 * src/num/cholesky.c - M x = b for a symmetric positive definite M (the
 * mass matrix of a kinetic energy) by Cholesky, M = L L^T: half the work
 * of the equilibrated LU (dense.c) and no pivot search, which is what a
 * many-link system spends its right-hand side on.  Backward stable for
 * any SPD matrix however it is scaled, so no equilibration.  The generated
 * code (src/codegen/solvers.c) factors the same way.
 */
#include "num.h"

#include <math.h>

bool qd__num_solve_spd(size_t n, double *A, double *b, double tol) {
    double big = 0;
    for (size_t j = 0; j < n; j++)
        big = A[j * n + j] > big ? A[j * n + j] : big;
    if (!(big > 0) || !isfinite(big))
        return false;
    /* L below and on the diagonal (row-major, A[i*n + j] for j <= i) */
    for (size_t j = 0; j < n; j++) {
        double *rj = A + j * n, d = rj[j];
        for (size_t k = 0; k < j; k++)
            d -= rj[k] * rj[k];
        if (!(d > tol * big))
            return false; /* not positive definite, or nearly singular: the LU decides */
        double l = sqrt(d), inv = 1 / l;
        rj[j] = l;
        for (size_t i = j + 1; i < n; i++) {
            double *ri = A + i * n, s = ri[j];
            for (size_t k = 0; k < j; k++)
                s -= ri[k] * rj[k];
            ri[j] = s * inv;
        }
    }
    for (size_t i = 0; i < n; i++) { /* L y = b */
        const double *ri = A + i * n;
        double s = b[i];
        for (size_t k = 0; k < i; k++)
            s -= ri[k] * b[k];
        b[i] = s / ri[i];
    }
    for (size_t i = n; i-- > 0;) { /* L^T x = y */
        double s = b[i];
        for (size_t k = i + 1; k < n; k++)
            s -= A[k * n + i] * b[k];
        b[i] = s / A[i * n + i];
    }
    return true;
}
