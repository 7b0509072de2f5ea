/*
 * src/linear/steady.h - what steady.c and stability.c share: one evaluation
 * environment for the reduced equations (parameters and t as given, then the
 * kept coordinates x, their velocities x', the cyclic rates c' and, for the
 * free case, the momenta p_<c>).
 */
#ifndef QD_LINEAR_STEADY_H
#define QD_LINEAR_STEADY_H

#include "qdot/stability.h"

typedef struct qd__steady_env {
    size_t n;
    const qd_expr **syms;
    double *vals;
    size_t x, xd, w, p;   /* first slot of each group */
} qd__steady_env;

/* Parameters, t and plain symbols are taken from syms/vals; every other slot
 * starts at 0. */
qd_status qd__steady_env_init(qd_ctx *ctx, const qd_steady *s, size_t nvals, const qd_expr *const *syms,
                              const double *vals, qd__steady_env *env);
void qd__steady_env_free(qd__steady_env *env);
/* x at the environment; QD_ERR_SINGULAR (with a message) when not finite. */
qd_status qd__steady_eval(qd_ctx *ctx, const qd__steady_env *env, const qd_expr *x, double *out);

#endif
