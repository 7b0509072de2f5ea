/*
 * src/linear/symmetry.h - what the symmetry files share: the collection of
 * operations found, and small dense helpers (internal).
 */
#ifndef QD_LINEAR_SYMMETRY_H
#define QD_LINEAR_SYMMETRY_H

#include "qdot/symmetry.h"

/* Operations S (n*n) with optional R (3x3), distinct S only. */
typedef struct qd__symm_ops {
    size_t n, count, cap;
    double *S;      /* cap * n*n */
    double *R;      /* cap * 9 */
    bool overflow;  /* more than QD_SYMMETRY_MAX_ORDER were offered */
} qd__symm_ops;

/* Add S (and R, may be NULL) unless an equal S is there; of two R giving
 * one S the one of larger trace is kept (in-plane motion: sigma_v over
 * C2', C3 over S3, E over sigma_h, so a planar figure is named as C3v).
 * false when out of memory. */
bool qd__lin_symm_ops_add(qd_ctx *ctx, qd__symm_ops *o, const double *S, const double *R);
void qd__lin_symm_ops_free(qd__symm_ops *o);

/* S^T A S == A to QD_SYMMETRY_TOL relative to max |A|. */
bool qd__lin_symm_invariant(size_t n, const double *S, const double *A);

/* The operations from the particles' geometry: *found false (no error)
 * when the model has no usable geometry (no particles, rigid bodies, a
 * coordinate that moves no particle). */
qd_status qd__lin_symm_geometric(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t nvals,
                             const qd_expr *const *syms, const double *vals,
                             const qd_linear *lin, qd__symm_ops *ops, double **rigid,
                             size_t *nrigid, qd_mode_kind **rigid_kind, bool *found);

/* The signed permutations of the coordinates leaving M0 and K0 invariant. */
qd_status qd__lin_symm_permutations(qd_ctx *ctx, const qd_linear *lin, qd__symm_ops *ops);

/* C = A B, all n*n row-major (C distinct from A and B). */
void qd__lin_symm_matmul(size_t n, const double *A, const double *B, double *C);

#endif
