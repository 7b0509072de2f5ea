/*
 * src/mech/legendre.h - what hamilton.c and legendre.c share: exact
 * Gaussian elimination of a small symbolic system, and the Hamiltonian of
 * a model given by H.
 */
#ifndef QD_MECH_LEGENDRE_H
#define QD_MECH_LEGENDRE_H

#include "qdot/hamilton.h"

/* Solve the augmented n x (n+1) system A (row-major, overwritten) for x,
 * pivots that simplify to nonzero, each x simplified.  QD_ERR_SINGULAR with
 * *bad the column with no pivot and NO message set (the caller knows what
 * the matrix means); other failures are the context's. */
qd_status qd__mech_gauss_solve(qd_ctx *ctx, size_t n, const qd_expr **A, const qd_expr **x,
                          size_t *bad);

/* What qd__mech_quad_inverse fills, n entries each (the caller's arrays):
 * x = M^-1 r simplified, and x_i = num_i / den_i unsimplified with den_i
 * the determinant of i's block (1 for a block solved by elimination). */
typedef struct qd__quad_inv {
    const qd_expr **x, **num, **den;
} qd__quad_inv;

/* x = M^-1 r and *half = r^T M^-1 r / 2 for the symmetric n x n M
 * (row-major; its entries are replaced by their simplified forms, the upper
 * triangle is read), block by block of M's pattern, the small blocks by
 * cofactors (legendre_blocks.c).  QD_ERR_SINGULAR, nothing recorded, when a
 * block's determinant or a pivot simplifies to 0. */
qd_status qd__mech_quad_inverse(qd_ctx *ctx, size_t n, const qd_expr **M, const qd_expr *const *r,
                                qd__quad_inv *out, const qd_expr **half);

/* qd_ham_derive for a model given by H: h allocated for n coordinates. */
qd_status qd__mech_ham_from_H(qd_ctx *ctx, const qd_model *m, qd_ham *h);

/* Velocities q'(q, p, t) for an L that is not quadratic in them
 * (legendre_family.c): L = F(q'^T G q') + a.q' + L0 with a closed-form
 * inverse fills vel and H = sum p q' - L; QD_ERR_NONLINEAR (no message) when
 * L is not of that form or g(s) = P has no closed form here.  Read the other
 * way (H for L, p for qd, qd for p) it is the inverse transform: p(q') and L. */
qd_status qd__mech_legendre_family(qd_ctx *ctx, const qd_expr *L, size_t n,
                                   const qd_expr *const *qd, const qd_expr *const *p,
                                   const qd_expr **vel, const qd_expr **H);

/* QD_ERR_SINGULAR, with the message naming the coordinate, when the Hessian
 * of L (stmt names its statement) in the velocities is singular for a reason
 * it can see: L linear in a velocity, or homogeneous of degree 1 beyond its
 * linear terms; QD_OK when it sees none. */
qd_status qd__mech_legendre_singular(qd_ctx *ctx, const qd_expr *const *pdef, size_t n,
                                const qd_expr *const *q, const qd_expr *const *qd,
                                const char *stmt);

#endif
