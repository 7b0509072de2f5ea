/*
 * src/base/args.h - the NULL check at the top of every public function
 * (issue 30): a pointer argument a call needs and is given NULL ends the
 * call with the error value its header names, before anything is touched.
 */
#ifndef QD_BASE_ARGS_H
#define QD_BASE_ARGS_H

#include <math.h>
#include "qdot/expr.h"

/* Return ret (nothing, for a void function) unless ok. */
#define QD_ARGS(ret, ok) do { if (!(ok)) return ret; } while (0)

/* For a function returning qd_status with a context: QD_ERR_ARG, recorded
 * in ctx when ctx is given; when ctx already holds an error (the NULL is
 * the result of a call that failed), that error's status, so a chain of
 * calls reports its first failure. */
#define QD_ARGS_CTX(ctx, ok) do { if (!(ok)) return qd__args_null(ctx, __func__); } while (0)

static inline qd_status qd__args_null(qd_ctx *ctx, const char *func)
{
    if (!ctx)
        return QD_ERR_ARG;
    if (qd_ctx_status(ctx) != QD_OK)
        return qd_ctx_status(ctx);
    qd_ctx_error(ctx, QD_ERR_ARG, "%s: a required argument is NULL", func);
    return QD_ERR_ARG;
}

#endif
