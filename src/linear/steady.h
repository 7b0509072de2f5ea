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
qd_status qd__lin_steady_env_init(qd_ctx *ctx, const qd_steady *s, size_t nvals,
                                  const qd_expr *const *syms, const double *vals,
                                  qd__steady_env *env);
void qd__lin_steady_env_free(qd__steady_env *env);
/* x at the environment; QD_ERR_SINGULAR (with a message) when not finite. */
qd_status qd__lin_steady_eval(qd_ctx *ctx, const qd__steady_env *env, const qd_expr *x,
                              double *out);

/* The size of x's terms at the environment: sums and products of the sizes
 * of their parts, sin and cos counted as 1 (their bound), so that a residual
 * like -m a (R + a cos th) sin th phi'^2 at th = pi, whose every term is
 * round-off sized, is judged against m a (R + a) phi'^2 and not against
 * itself.  Other functions count by their value; NaN when x cannot be
 * evaluated. */
double qd__lin_steady_magnitude(qd_ctx *ctx, const qd__steady_env *env, const qd_expr *x);

/* One search for a steady motion (steady.c): the unknowns (kept coordinates
 * not held, rates not given) and the equations (the kept residuals, then the
 * given momenta). */
typedef struct qd__steady_search {
    qd_ctx *ctx;
    const qd_steady *s;
    qd__steady_env env;
    size_t nu, neq;
    size_t *uslot;             /* nu: env slot of each unknown */
    const qd_expr **F;         /* neq: residual expressions (momenta minus their values) */
    double *pgiven;            /* neq: subtracted from F (0 for the kept rows) */
    const qd_expr **dF;        /* neq*nu */
} qd__steady_search;

/* S->ctx and S->s set, the rest zero: the environment, the unknowns (their
 * values from pt) and the equations. */
qd_status qd__lin_steady_search_init(qd__steady_search *S, const bool *xfix, const bool *wfix,
                                 const bool *pfix, const qd_steady_point *pt, size_t nvals,
                                 const qd_expr *const *syms, const double *vals);
void qd__lin_steady_search_free(qd__steady_search *S);
/* F (neq) and, unless NULL, J (neq*nu) at the unknowns u. */
qd_status qd__lin_steady_residual(qd__steady_search *S, const double *u, double *F, double *J);
/* Levenberg-Marquardt from u; QD_ERR_NUMERIC (with a message) when the
 * largest relative residual stays above 1e-8. */
qd_status qd__lin_steady_iterate(qd__steady_search *S, double *u, double *res);

#endif
