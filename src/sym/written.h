/*
 * src/sym/written.h - constructors for what a reader has just read (the
 * expression reader, read.c, and the model files' parser, model/expr.c):
 * stricter than the constructors the library uses inside, where an exact
 * 0^q can arise from a substitution and stays a node.
 */
#ifndef QD_SYM_WRITTEN_H
#define QD_SYM_WRITTEN_H

#include "qdot/expr.h"

/* b^e as written: an exact 0 to a power that is not a number (0^q, defined
 * only for q > 0) is refused, QD_ERR_ARG; else qd_pow. */
const qd_expr *qd__pow_written(qd_ctx *ctx, const qd_expr *b, const qd_expr *e);
/* atan2(y, x) as written: atan2(0, 0) with exact zeros, which has no value,
 * is refused (QD_ERR_DIVZERO); else qd_fn2. */
const qd_expr *qd__atan2_written(qd_ctx *ctx, const qd_expr *y, const qd_expr *x);

#endif
