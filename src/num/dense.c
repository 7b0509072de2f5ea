/*
 * src/num/dense.c - dense Gaussian elimination with partial pivoting
 * (Golub & Van Loan, Matrix Computations, alg. 3.4.1): the solver for the
 * few-row systems of mechanics (mass matrices, saddle-point systems, Newton
 * steps), and its rank-revealing form for the diagnosis of singular ones.
 *
 * Why not LAPACK: reference LAPACK 3.11's dgetrf + dgetrs costs 360 ns at
 * n = 2 and 1100 ns at n = 4 against 60 ns and 200 ns here (call overhead
 * and blocking for sizes we never see); still 1.5x slower at n = 20 and 40
 * (docs/design.md, the numerics home).  LAPACK does the eigenproblems.
 */
#include "num.h"

#include <math.h>

double qd__num_norm_inf(size_t n, const double *A) {
    double norm = 0;
    for (size_t i = 0; i < n; i++) {
        double s = 0;
        for (size_t j = 0; j < n; j++)
            s += fabs(A[i * n + j]);
        norm = fmax(norm, s);
    }
    return norm;
}

/* The row at or below r with the largest entry in column c. */
static size_t pivot_row(size_t n, const double *A, size_t r, size_t c) {
    size_t p = r;
    for (size_t i = r + 1; i < n; i++)
        if (fabs(A[i * n + c]) > fabs(A[p * n + c]))
            p = i;
    return p;
}

/* Swap rows r and p from column c on (the columns before are zero in both
 * or, for the rank-revealing form, not read again) and of b. */
static void swap_rows(size_t n, double *A, double *b, size_t r, size_t p, size_t c) {
    if (p == r)
        return;
    for (size_t j = c; j < n; j++) {
        double t = A[r * n + j];
        A[r * n + j] = A[p * n + j];
        A[p * n + j] = t;
    }
    if (b) {
        double t = b[r];
        b[r] = b[p];
        b[p] = t;
    }
}

/* Eliminate column c below row r.  The multipliers are A_ic / A_rc; the
 * solver (recip) takes one reciprocal per column instead of a division per
 * row, the rank-revealing form divides.  Both are Golub & Van Loan's
 * algorithm; the two roundings keep the results each caller had before
 * the solvers were merged (printed eigenvalue orders depend on them). */
static void eliminate(size_t n, double *A, double *b, size_t r, size_t c, bool recip) {
    double piv = A[r * n + c], inv = 1 / piv;
    for (size_t i = r + 1; i < n; i++) {
        double l = recip ? A[i * n + c] * inv : A[i * n + c] / piv;
        A[i * n + c] = 0;
        for (size_t j = c + 1; j < n; j++)
            A[i * n + j] -= l * A[r * n + j];
        if (b)
            b[i] -= l * b[r];
    }
}

/* Back substitution over the rank rows of the echelon form, pivot of row i
 * in column pc[i] (NULL: column i); x holds the right-hand side (or the
 * fixed free variables) on entry. */
static void back_substitute(size_t n, const double *A, size_t rank, const size_t *pc, double *x) {
    for (size_t i = rank; i-- > 0;) {
        size_t c = pc ? pc[i] : i;
        double s = x[c];
        for (size_t j = c + 1; j < n; j++)
            s -= A[i * n + j] * x[j];
        x[c] = s / A[i * n + c];
    }
}

/* The power of two nearest 1/m (m > 0, finite): scaling by it is exact. */
static double inv_pow2(double m) {
    int e;
    frexp(m, &e);
    return ldexp(1, -e);
}

/* Equilibrate A in place (dgeequ's scaling, in powers of two so it rounds
 * nothing): each row of A and b by the power of two nearest its largest
 * entry's reciprocal, then each column likewise, the column factors kept
 * in cs (x = cs y).  false when a row or column is all zero or not finite. */
static bool equilibrate(size_t n, double *A, double *b, double *cs) {
    for (size_t i = 0; i < n; i++) {
        double m = 0;
        for (size_t j = 0; j < n; j++)
            m = fmax(m, fabs(A[i * n + j]));
        if (!(m > 0) || !isfinite(m))
            return false;
        double r = inv_pow2(m);
        for (size_t j = 0; j < n; j++)
            A[i * n + j] *= r;
        b[i] *= r;
    }
    for (size_t j = 0; cs && j < n; j++) {
        double m = 0;
        for (size_t i = 0; i < n; i++)
            m = fmax(m, fabs(A[i * n + j]));
        if (!(m > 0))
            return false;
        cs[j] = inv_pow2(m);
        for (size_t i = 0; i < n; i++)
            A[i * n + j] *= cs[j];
    }
    return true;
}

/* Columns scaled for systems up to this size (mechanics has n <= 12; a
 * larger one is scaled by rows only): no allocation on the hot path. */
#define SOLVE_COLS 64

bool qd__num_solve(size_t n, double *A, double *b, double tol) {
    double cs[SOLVE_COLS];
    double *c = n <= SOLVE_COLS ? cs : NULL;
    if (!equilibrate(n, A, b, c))
        return false;
    double eps = tol * qd__num_norm_inf(n, A);
    for (size_t k = 0; k < n; k++) {
        size_t p = pivot_row(n, A, k, k);
        if (!(fabs(A[p * n + k]) > eps))
            return false;
        swap_rows(n, A, b, k, p, k);
        eliminate(n, A, b, k, k, true);
    }
    back_substitute(n, A, n, NULL, b);
    for (size_t j = 0; c && j < n; j++)
        b[j] *= c[j];
    return true;
}

static void null_vector(size_t n, const double *A, size_t rank, const size_t *pc,
                        const bool *is_free, double *null) {
    bool first = true;
    for (size_t j = 0; j < n; j++) {
        null[j] = is_free[j] && first ? 1 : 0;
        first = first && !is_free[j];
    }
    /* pivot rows hold no right-hand side: start them at 0 */
    back_substitute(n, A, rank, pc, null);
}

size_t qd__num_rank(size_t n, double *A, double *b, double tol, size_t *pc, bool *free_col,
                    double *null) {
    double eps = tol * qd__num_norm_inf(n, A);
    size_t r = 0;
    for (size_t c = 0; c < n; c++) {
        size_t p = r < n ? pivot_row(n, A, r, c) : r;
        bool skip = r >= n || !(fabs(A[p * n + c]) > eps);
        if (free_col)
            free_col[c] = skip;
        if (skip)
            continue;
        swap_rows(n, A, b, r, p, 0);
        eliminate(n, A, b, r, c, false);
        pc[r++] = c;
    }
    if (r == n && b)
        back_substitute(n, A, r, pc, b);
    if (r < n && null && free_col)
        null_vector(n, A, r, pc, free_col, null);
    return r;
}
