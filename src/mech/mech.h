/*
 * src/mech/mech.h - what the mechanics files share: the numeric cache of a
 * qd_eom, the split of T by degree, the singularity check and a small dense
 * solver.
 */
#ifndef QD_MECH_MECH_H
#define QD_MECH_MECH_H

#include "qdot/eval.h"
#include "qdot/mech.h"

/* The private part of a qd_eom (its priv field): M and f compiled once,
 * with every free symbol of M and f as an input, so a state that leaves a
 * symbol out gives it the value 0. */
typedef struct qd__eom_num {
    qd_prog *prog; /* outputs: M (n*n, row-major), then f (n) */
    size_t nin;
    const qd_expr **inputs;
    double *in, *out; /* nin and n*n + n doubles */
} qd__eom_num;

/* Every free symbol of exprs[0..n), each once, in a malloc'd array (NULL
 * on failure). */
const qd_expr **qd__inputs(qd_ctx *ctx, size_t n, const qd_expr *const *exprs, size_t *nin);

/* Compile e's numeric program if it is not compiled yet. */
qd_status qd__eom_compile(qd_ctx *ctx, const qd_eom *e);
void qd__eom_num_free(qd__eom_num *num);

/* An expression grouped by its monomials in the velocities: every group's
 * coefficient simplified on its own. */
typedef struct qd__vsum {
    const qd_expr *all;    /* the sum of every group */
    const qd_expr *deg[3]; /* the groups of degree 0, 1 and 2 */
    long top;              /* the highest degree */
    const qd_expr *bad;    /* when not a polynomial: a factor that is not */
} qd__vsum;

/* Group the expansion of x by monomials in the velocities qd[0..n).
 * QD_ERR_NONLINEAR, with v->bad set and nothing recorded in ctx, when x is
 * not a polynomial in them. */
qd_status qd__by_velocity(qd_ctx *ctx, const qd_expr *x, size_t n, const qd_expr *const *qd,
                          qd__vsum *v);

/* The kinetic energy grouped: T = T2 + T1 + T0 by degree in the velocities
 * (v->deg, valid when v->top <= 2).  Velocities in anything but a
 * polynomial are QD_ERR_NONLINEAR, with the reason in ctx. */
qd_status qd__split_kinetic(qd_ctx *ctx, const qd_expr *T, size_t n, const qd_expr *const *qd,
                            qd__vsum *v);

/* QD_OK unless e's mass matrix is identically singular; then
 * QD_ERR_SINGULAR, with a message naming the undetermined accelerations.
 * T is the model's kinetic energy (may be NULL), used for the wording. */
qd_status qd__check_singular(qd_ctx *ctx, const qd_eom *e, const qd_expr *T);

/* The determinant of the n*n matrix A by fraction-free elimination, each
 * step cancelled; NULL on failure (reason in ctx). */
const qd_expr *qd__det(qd_ctx *ctx, size_t n, const qd_expr *const *A);

/* Gaussian elimination with partial pivoting on A (n*n, row-major, in
 * place); pc is scratch for n indices.  A column whose best pivot is not
 * above tol times the matrix norm is skipped and marked in free_col (may be
 * NULL).  Returns the rank; when it is n and b is not NULL, b is overwritten
 * by the solution of A x = b.  With a deficient rank and null and free_col
 * not NULL, null receives a vector of the null space. */
size_t qd__gauss(size_t n, double *A, double *b, double tol, size_t *pc, bool *free_col,
                 double *null);

#endif
