/*
 * src/num/num.h - the numerics home: the one dense linear solver and the
 * one saddle-point assembly every module uses (mech, sim, linear), the
 * explicit Runge-Kutta tableaux and their one stage loop (sim, path), and
 * the inputs of compiled programs (the shortest round-trip printing of
 * doubles is public: qd_double_format, shortest.c).  Prefix qd__num_.
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
 * Rows and columns are first equilibrated (powers of two, exact), so the
 * test is scale-invariant: M = diag(1, r^2) at r = 6.7e6 (SI units) is
 * regular.  Singular (false, b undefined) when a row or column is zero or
 * a pivot of the equilibrated matrix is not above tol times its |.|_inf.
 * The per-evaluation solver of simulation and qd_eom_eval: hand-written
 * because reference LAPACK is 4-6x slower for the n <= 12 of mechanics
 * (docs/design.md, the numerics home). */
/* max_i sum_j |A_ij| of an n x n row-major matrix: the scale of "zero" pivots. */
double qd__num_norm_inf(size_t n, const double *A);
bool qd__num_solve(size_t n, double *A, double *b, double tol);
/* A x = b, A symmetric (its lower triangle read, overwritten by the
 * Cholesky factor), b overwritten by x: false, with A and b spoilt, when a
 * pivot is not above tol times the largest diagonal entry (A not positive
 * definite or nearly singular: then solve with qd__num_solve, whose
 * equilibrated test decides singularity).  cholesky.c. */
bool qd__num_solve_spd(size_t n, double *A, double *b, double tol);

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

/* ---- quadrature (quad.c) --------------------------------------------------
 *
 * Adaptive tanh-sinh (double-exponential) quadrature (Takahasi & Mori
 * 1974; Bailey, Jeyabalan & Li 2005): the rule of choice for the integrals
 * of orbits and scattering, whose integrands have inverse-square-root
 * singularities at the turning points.  The abscissas crowd
 * double-exponentially at the ends, so an integrable end-point singularity
 * costs nothing extra; the levels halve the step until two successive
 * estimates agree to tol.
 *
 * The integrand receives x and its signed distance from the nearer end,
 * xc = x - a (>= 0) near a or x - b (<= 0) near b, computed without the
 * cancellation of x - a at x close to a: an integrand 1/sqrt(E - V(x))
 * with E = V(a) should use xc to form E - V (a Taylor step, or the exact
 * factor (x - a)) where the difference would lose its digits; the
 * distance to the far end is (b - a) - |xc|, also without cancellation. */
typedef double (*qd__num_fn)(void *data, double x, double xc);

typedef struct qd__num_quad {
    double value;     /* the integral */
    double error;     /* the estimate: |last level - the one before| */
    size_t evals;
    bool converged;   /* error <= tol * max(1, |value|) */
} qd__num_quad;

/* The integral of f over [a, b] (a < b, both finite); tol relative (0:
 * 1e-13).  A non-finite f value at an abscissa is treated as a sign the
 * point is at the singularity and dropped when it lies within 1e-14 of an
 * end; elsewhere it is a fault of the integrand: value NaN, false.  false
 * also when the levels ran out (12, step 2^-12) without converging; r then
 * holds the last estimate. */
bool qd__num_quad_finite(qd__num_fn f, void *data, double a, double b, double tol,
                         qd__num_quad *r);

/* The integral over [a, inf) (exp-sinh), same conventions (xc = x - a). */
bool qd__num_quad_upper(qd__num_fn f, void *data, double a, double tol, qd__num_quad *r);

/* The Dormand-Prince 5(4) pair and Shampine's dense output (dopri5.c), one
 * copy for src/sim's method and src/path's Jacobi fields: nodes c, stage
 * weights a (row 6: the fifth-order result), error weights e, dense P. */
extern const double qd__num_dp5_c[7], qd__num_dp5_a[7][6], qd__num_dp5_e[7],
    qd__num_dp5_p[7][4];

/* DOP853's tables (dop853.c), src/sim's: nodes c (13-15: the dense
 * output's extra stages), stage weights a (12 x 12) and b, the dense
 * output's extra stages ax, the third-order weights bhh, the fifth-order
 * error weights e5 and the dense output's d (Hairer's dop853.f names). */
extern const double qd__num_dp8_c[16], qd__num_dp8_a[12 * 12], qd__num_dp8_b[12],
    qd__num_dp8_ax[3][16], qd__num_dp8_bhh[12], qd__num_dp8_e5[12], qd__num_dp8_d[4][16];

/* A system y' = f(t, y) of n equations: false when f is undefined there. */
typedef bool (*qd__num_ode_fn)(void *data, double t, const double *y, double *dy);

/* An explicit Runge-Kutta method (rk.c): nodes c, the strictly lower
 * stages x stages matrix a (row-major), the weights b / bden (integer
 * numerators over a common denominator keep the classical sums exact;
 * bden = 1 for tables of fractions, h / 1 being h). */
typedef struct qd__num_rk {
    int stages;
    const double *c, *a, *b;
    double bden;
} qd__num_rk;

/* The classical fourth-order method (b = (1, 2, 2, 1) / 6, rk.c); the
 * fifth-order step of the Dormand-Prince 5(4) pair (dopri5.c, 6 stages:
 * qd__num_dp5_a's rows 0-5, b its row 6); the eighth-order step of DOP853
 * (dop853.c, 12 stages).  The pairs' error estimates and dense output stay
 * with their step size control in src/sim. */
extern const qd__num_rk qd__num_rk4, qd__num_dp5, qd__num_dp8;

/* The stage loop every explicit method here runs (rk.c): for i = 0 ..
 * stages - 1, k[i] = f(t + c_i h, y0 + h sum_(j<i) a_ij k[j]) (a zero a_ij
 * or b_i is skipped, so a non-finite stage never meets a zero), then
 * y1 = y0 + h / bden sum_i b_i k[i]; y1 may be y0, which is read for the
 * last time as y1 is written.  With fsal, k[0] = f(t, y0) is given (the
 * derivative at the last step's result) and k[stages] gets f(t + h, y1),
 * the next step's k[0]: the rows are pointers so that a caller can swap
 * them instead of copying.  ytmp: n doubles.  False when f fails: y1 is then
 * as it was, unless it was fsal's last evaluation that failed. */
bool qd__num_rk_stages(const qd__num_rk *m, qd__num_ode_fn f, void *data, size_t n, double t,
                       double h, const double *y0, double *y1, double *const *k, double *ytmp,
                       bool fsal);

/* The most stages qd__num_rk_step takes: it keeps its row pointers on the
 * stack (DOP853, the largest table, has 12). */
#define QD__NUM_RK_MAX_STAGES 16

/* One step of m from (t, y) by h, y replaced by the result; w holds
 * (stages + 1) n doubles.  False when f fails at a stage (y then as it was)
 * and for a method of more than QD__NUM_RK_MAX_STAGES stages. */
bool qd__num_rk_step(const qd__num_rk *m, qd__num_ode_fn f, void *data, size_t n, double t,
                     double h, double *y, double *w);

#endif
