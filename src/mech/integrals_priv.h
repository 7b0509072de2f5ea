/*
 * src/mech/integrals_priv.h - what integrals.c, noether.c and
 * integrals_zero.c share: the model's content with the substitutions made,
 * and the zero test along the motion (qdot/integrals.h explains it).
 */
#ifndef QD_MECH_INTEGRALS_PRIV_H
#define QD_MECH_INTEGRALS_PRIV_H

#include "qdot/certify.h"
#include "qdot/integrals.h"

typedef struct qd__intsys {
    const qd_model *m;
    qd_eom *e;
    size_t n;
    const qd_expr *L, *T, *V, *U, *D; /* NULL where the model has none */
    const qd_expr **Q;                /* n, never NULL entries */
    const qd_expr **p;                /* n momenta dL/dq'_j, simplified */
    bool solved;                      /* e->acc (and e->mult) usable symbolically */
} qd__intsys;

/* Does X (in q, q', q'', t, parameters and the multipliers lambda_k)
 * vanish along the motion?  *shown receives X with the solved
 * accelerations and multipliers substituted (when the eom was solved),
 * simplified; *numeric is set when the verdict rests on random states
 * only.  cert (may be NULL) receives how it is known: PROVEN, NUMERIC,
 * NONZERO with the witness state, or UNKNOWN (undecided). */
qd_status qd__mech_int_zero(qd_ctx *ctx, const qd__intsys *s, const qd_expr *X,
                       const qd_expr **shown, bool *zero, bool *numeric, qd_zero_result *cert);

/* Does X (no accelerations) vanish identically (simplify, then random
 * points; s, for the parameters' values, may be NULL)? */
qd_status qd__mech_int_identically_zero(qd_ctx *ctx, const qd__intsys *s, const qd_expr *X,
                                   bool *zero, bool *numeric);

/* The translations and rotations by coordinate names (noether.c). */
qd_status qd__mech_int_search(qd_ctx *ctx, qd_integrals *I);

#endif
