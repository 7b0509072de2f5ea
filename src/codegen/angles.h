/*
 * src/codegen/angles.h - the code generator's interface to the simulator:
 * the rewrite both apply before compiling, so the generated C and the
 * compiled programs compute the same formulas (cg.h is codegen's own).
 */
#ifndef QD_CODEGEN_ANGLES_H
#define QD_CODEGEN_ANGLES_H

#include <stdbool.h>
#include "qdot/expr.h"

/* Rewrite sin/cos of a difference or sum of two coordinates,
 * sin(a - b) = sin a cos b - cos a sin b, over the outputs exprs[0..n) in
 * place, when that leaves fewer sine and cosine calls in the whole set (the
 * n-link pendulum: n(n-1) calls become 2n).  *applied says whether it did. */
qd_status qd__cg_angle_sums(qd_ctx *ctx, size_t n, const qd_expr **exprs, bool *applied);

#endif
