/*
 * src/num/num.h - the numerics home: the one dense linear solver and the
 * one saddle-point assembly every module uses (mech, sim, linear), and the
 * inputs of compiled programs (the shortest round-trip printing of doubles
 * is public: qd_double_format, shortest.c).  Prefix qd__num_.
 *
 * This is the module's interface to the others (docs/design.md, the
 * numerics home); the other modules' own headers (mech/mech.h,
 * sim/simint.h, ...) stay inside their module.  Matrices are row-major
 * double arrays; the solvers do not allocate, so a caller's workspace
 * makes every call thread-safe.
 */
#ifndef QD_NUM_NUM_H
#define QD_NUM_NUM_H

#include <stdbool.h>
#include <stddef.h>

#include "qdot/expr.h"

/* Every free symbol of exprs[0..n), each once, in a malloc'd array (NULL
 * on failure, recorded in ctx): the inputs of a program compiled from
 * them (inputs.c). */
const qd_expr **qd__num_inputs(qd_ctx *ctx, size_t n, const qd_expr *const *exprs, size_t *nin);

/* Solve A x = b in place (A n*n destroyed, b becomes x) by Gaussian
 * elimination with partial pivoting (Golub & Van Loan, alg. 3.4.1).
 * Singular (false, b undefined) when a pivot is not above tol |A|_inf.
 * The per-evaluation solver of simulation and qd_eom_eval: hand-written
 * because reference LAPACK is 4-6x slower for the n <= 12 of mechanics
 * (docs/design.md, the numerics home). */
/* max_i sum_j |A_ij| of an n x n row-major matrix: the scale of "zero" pivots. */
double qd__num_norm_inf(size_t n, const double *A);
bool qd__num_solve(size_t n, double *A, double *b, double tol);

/* The same elimination, rank-revealing: a column whose best pivot is not
 * above tol |A|_inf is skipped and marked in free_col (may be NULL); pc is
 * scratch for n indices.  Returns the rank; when it is n and b is not
 * NULL, b is overwritten by the solution.  With a deficient rank and null
 * and free_col not NULL, null receives a vector of the null space. */
size_t qd__num_rank(size_t n, double *A, double *b, double tol, size_t *pc, bool *free_col,
                    double *null);

/* The saddle-point system of constrained motion (Desloge, seed C5)
 *
 *     [ M  -A^T ] [ q''    ]   [ f ]
 *     [ A   0   ] [ lambda ] = [ b ]
 *
 * M n*n, A m*n, assembled into K ((n+m)^2) and r (n+m). */
void qd__num_saddle(size_t n, size_t m, const double *M, const double *f, const double *A,
                    const double *b, double *K, double *r);

#endif
