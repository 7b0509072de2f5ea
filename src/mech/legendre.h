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
qd_status qd__gauss_solve(qd_ctx *ctx, size_t n, const qd_expr **A, const qd_expr **x,
                          size_t *bad);

/* qd_ham_derive for a model given by H: h allocated for n coordinates. */
qd_status qd__ham_from_H(qd_ctx *ctx, const qd_model *m, qd_ham *h);

#endif
