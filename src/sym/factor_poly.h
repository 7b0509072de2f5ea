/*
 * src/sym/factor_poly.h - polynomial factorization inside sums (factor_poly.c),
 * the simplifier's internal interface to it.
 */
#ifndef QD_SYM_FACTOR_POLY_H
#define QD_SYM_FACTOR_POLY_H

#include "node.h"

/* Bottom-up over e: every sum whose terms share a denominator (a group) has
 * that group's numerator factored over the integers, with every
 * non-polynomial subexpression a generator, where that makes the sum
 * shorter by qd_count_ops; the rest of the sum is left as it is.  memo maps
 * node -> result and may be shared by calls on related expressions (the
 * result depends on the node alone).  NULL on error. */
const qd_expr *qd__factor_polys(qd_ctx *ctx, const qd_expr *e, qd__ptrmap *memo);

#endif
