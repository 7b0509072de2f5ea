/*
 * src/linear/ss.h - what the state-space files share: the operating point
 * as a substitution (point.c) and the analysis of A, B, C (kalman.c).
 */
#ifndef QD_LINEAR_SS_H
#define QD_LINEAR_SS_H

#include "qdot/statespace.h"

/* The point as exact values: from[i] -> to[i] for every coordinate,
 * velocity, input and t (those not given are 0). */
typedef struct qd__point {
    size_t n;
    const qd_expr **from, **to;
} qd__point;

/* QD_ERR_ARG (naming it) for a symbol that is none of those. */
qd_status qd__lin_point_make(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t npt,
                         const qd_expr *const *syms, const qd_expr *const *vals, qd__point *pt);
void qd__lin_point_free(qd__point *pt);
/* The numbers of the point's values for the k symbols which (the
 * parameters at their values in m). */
qd_status qd__lin_point_numbers(qd_ctx *ctx, const qd_model *m, const qd__point *pt, size_t k,
                            const qd_expr *const *which, double *out);

/* Eigenvalues and vectors of s->A, the Kalman ranks and the PBH modes. */
qd_status qd__lin_ss_analyse(qd_ctx *ctx, qd_statespace *s);

#endif
