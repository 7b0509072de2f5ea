/*
 * src/mech/lu.c - a small dense solver for M q'' = f.
 *
 * Mass matrices have a few rows, so plain Gaussian elimination with partial
 * pivoting (Golub & Van Loan, Matrix Computations, alg. 3.4.1) is enough;
 * it also reports which columns have no pivot, which names the
 * accelerations a singular mass matrix leaves undetermined.
 */
#include "mech.h"

#include <math.h>

static double norm_inf(size_t n, const double *A) {
    double norm = 0;
    for (size_t i = 0; i < n; i++) {
        double s = 0;
        for (size_t j = 0; j < n; j++)
            s += fabs(A[i * n + j]);
        norm = s > norm ? s : norm;
    }
    return norm;
}

static void swap_rows(size_t n, double *A, double *b, size_t r, size_t p) {
    for (size_t j = 0; j < n; j++) {
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

/* Eliminate column c below row r. */
static void eliminate(size_t n, double *A, double *b, size_t r, size_t c) {
    for (size_t i = r + 1; i < n; i++) {
        double l = A[i * n + c] / A[r * n + c];
        A[i * n + c] = 0;
        for (size_t j = c + 1; j < n; j++)
            A[i * n + j] -= l * A[r * n + j];
        if (b)
            b[i] -= l * b[r];
    }
}

/* Back substitution over the rank rows of the echelon form; x holds the
 * right-hand side (or the fixed free variables) on entry. */
static void back_substitute(size_t n, const double *A, size_t rank, const size_t *pc, double *x) {
    for (size_t i = rank; i-- > 0;) {
        size_t c = pc[i];
        double s = x[c];
        for (size_t j = c + 1; j < n; j++)
            s -= A[i * n + j] * x[j];
        x[c] = s / A[i * n + c];
    }
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

size_t qd__gauss(size_t n, double *A, double *b, double tol, size_t *pc, bool *free_col,
                 double *null) {
    double eps = tol * norm_inf(n, A);
    size_t r = 0;
    for (size_t c = 0; c < n; c++) {
        size_t p = r;
        for (size_t i = r + 1; i < n; i++)
            if (fabs(A[i * n + c]) > fabs(A[p * n + c]))
                p = i;
        bool skip = r >= n || !(fabs(A[p * n + c]) > eps);
        if (free_col)
            free_col[c] = skip;
        if (skip)
            continue;
        swap_rows(n, A, b, r, p);
        eliminate(n, A, b, r, c);
        pc[r++] = c;
    }
    if (r == n && b)
        back_substitute(n, A, r, pc, b);
    if (r < n && null && free_col)
        null_vector(n, A, r, pc, free_col, null);
    return r;
}
