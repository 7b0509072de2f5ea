/* src/group/group.h - finite groups from their multiplication table: classes,
 * character tables, point-group names and Mulliken labels (internal API) */
#ifndef QD_GROUP_GROUP_H
#define QD_GROUP_GROUP_H
#include <stddef.h>
#include "qdot/expr.h"        /* qd_status, qd_ctx */

typedef struct qd__group {
    size_t order;
    size_t *mul;         /* order*order: mul[a*order + b] = index of a*b (a applied after b) */
    size_t identity;
    size_t *inv;         /* inv[a] */
    size_t nclass;
    size_t *class_of;    /* element -> class index; class 0 is {identity} */
    size_t *class_size;  /* nclass */
    size_t *class_rep;   /* nclass: one element of each class */
} qd__group;

/* Validates (closure, identity, inverses, associativity on the table) and
 * computes inverses and conjugacy classes. Copies mul. */
qd_status qd__group_from_table(qd_ctx *ctx, size_t order, const size_t *mul, qd__group *g);
void qd__group_free(qd__group *g);

typedef struct qd__chartab {
    size_t n;            /* irreps = classes */
    size_t *dim;         /* n */
    double *re, *im;     /* n*nclass: chi of irrep i on class c at [i*nclass + c] */
} qd__chartab;

/* Burnside/Dixon (class multiplication coefficients, simultaneous eigenvectors), or
 * the closed forms for cyclic and dihedral groups; rows ordered trivial first,
 * then by dimension; verified by both orthogonality relations (error if not). */
qd_status qd__group_characters(qd_ctx *ctx, const qd__group *g, qd__chartab *t);
void qd__group_chartab_free(qd__chartab *t);

/* When the group acts on 3-space: R[a*9 .. a*9+8] the row-major 3x3 orthogonal
 * matrix of element a. Schoenflies name ("C2v", "D3h", "Td", "Oh", "Cinfv"... up to
 * 15 chars) or "" if not a point group; Mulliken labels per irrep (A1, A2, E, T2,
 * Ag, B1u, E', A2'' ...; complex pairs of cyclic groups as E1a/E1b or "E(k)"). */
qd_status qd__group_pointgroup_name(qd_ctx *ctx, const qd__group *g, const double *R,
                                    char name[16]);
qd_status qd__group_irrep_labels(qd_ctx *ctx, const qd__group *g, const double *R,
                           const qd__chartab *t, char (*labels)[12]);

/* Additions after the contract (additive only).
 * R may be NULL (an abstract group): qd__group_pointgroup_name gives "" and
 * qd__group_irrep_labels Gamma1, Gamma2, ... in the table's row order, both QD_OK;
 * so do matrices that are not a faithful orthogonal representation. */
#define QD__GROUP_MAX_ORDER 4096   /* the table alone is order^2 indices: 128 MiB here */

/* A generating set of g, at most log2(order) elements for a group: gens must
 * hold order entries.  Returns how many, or SIZE_MAX when out of memory. */
size_t qd__group_generators(qd_ctx *ctx, const qd__group *g, size_t *gens);

/* Within src/group (product.c): t allocated for g's classes is filled,
 * unsorted, when g = H x C2 (*done true); otherwise left alone. */
qd_status qd__group_product_table(qd_ctx *ctx, const qd__group *g, qd__chartab *t, bool *done);
#endif
