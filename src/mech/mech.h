/*
 * src/mech/mech.h - what the mechanics files share beyond mech_export.h
 * (what modules above use): the numeric cache of a qd_eom, the split of T
 * by degree, the singularity check, the constraints' set-up.
 */
#ifndef QD_MECH_MECH_H
#define QD_MECH_MECH_H

#include "qdot/eval.h"
#include "qdot/mech.h"
#include "mech_export.h"

/* A compiled qd_eom (eval.c): immutable once made.  M and f compiled
 * once, with every free symbol of M and f as an input, so a state that
 * leaves a symbol out gives it the value 0. */
struct qd_eom_prog {
    const qd_eom *e;
    qd_prog *prog; /* outputs: M (n*n, row-major), f (n), then with m
                      constraints A (m*n), b (m) and the constraints' own
                      expressions g (m): qd__out_* give the offsets */
    size_t nin, nout;
    const qd_expr **inputs;
};

/* One thread's workspace for a qd_eom_prog: one block of doubles. */
struct qd_eom_work {
    const qd_eom_prog *p;
    double *in, *out, *regs; /* nin, nout, the program's registers */
    double *K;               /* (n+m)^2 + (n+m): the solver's */
};

/* The private part of a qd_eom (its priv field): qd_eom_eval's compiled
 * program and workspace, made on first use (one thread). */
typedef struct qd__eom_num {
    qd_eom_prog *prog;
    qd_eom_work *work;
} qd__eom_num;

/* Offsets of the compiled outputs (see qd_eom_prog). */
static inline size_t qd__out_A(const qd_eom *e) { return e->n * e->n + e->n; }
static inline size_t qd__out_b(const qd_eom *e) { return qd__out_A(e) + e->ncon * e->n; }
static inline size_t qd__out_g(const qd_eom *e) { return qd__out_b(e) + e->ncon; }
static inline size_t qd__out_len(const qd_eom *e) { return qd__out_g(e) + e->ncon; }

/* Compile e's numeric program if it is not compiled yet. */
qd_status qd__mech_eom_compile(qd_ctx *ctx, const qd_eom *e);
void qd__mech_eom_num_free(qd__eom_num *num);

/* The kinetic energy grouped: T = T2 + T1 + T0 by degree in the velocities
 * (v->deg, valid when v->top <= 2).  Velocities in anything but a
 * polynomial are QD_ERR_NONLINEAR, with the reason in ctx. */
qd_status qd__mech_split_kinetic(qd_ctx *ctx, const qd_expr *T, size_t n, const qd_expr *const *qd,
                            qd__vsum *v);

/* QD_OK unless e's mass matrix is identically singular; then
 * QD_ERR_SINGULAR, with a message naming the undetermined accelerations.
 * T is the model's kinetic energy (may be NULL), used for the wording. */
qd_status qd__mech_check_singular(qd_ctx *ctx, qd_eom *e, const qd_expr *T);

/* The inputs of a random state (singular.c): each in [0.2, 1.8), draw k. */
void qd__mech_random_state(size_t nin, double *in, unsigned k);

/* Constraints whose rows are dependent at random states (redundant.c):
 * judged on the holonomic constraints' manifold.  Redundant: the one with
 * the steadiest weight is left out of e (its name appended to e->reduced,
 * e's program freed) and *dropped is true; inconsistent: QD_ERR_SINGULAR
 * with a message and the witness state; independent on the manifold:
 * QD_OK, nothing done; no verdict: QD_ERR_SINGULAR saying so. */
qd_status qd__mech_con_reduce(qd_ctx *ctx, qd_eom *e, bool *dropped);

/* The determinant of the n*n matrix A by fraction-free elimination, each
 * step cancelled; NULL on failure (reason in ctx). */
const qd_expr *qd__mech_det(qd_ctx *ctx, size_t n, const qd_expr *const *A);

struct qd_metric_singular;
/* x >= 0 wherever it is defined, read from its form (zero_set.c): positive
 * numbers, constants and symbols, even powers, products of those and sums
 * of those with one term positive; *pos: x > 0 too. */
bool qd__mech_nonneg(const qd_expr *x, bool *pos);
/* The zeros of det in the n symbols q, factor by factor (zero_set.c): a
 * factor linear in one of them solved for it (r = 0), sin and cos of one
 * (theta = 0 + k pi), any other factor = 0; factors free of q and positive
 * ones left out.  *out is allocated (qd__free), *count entries. */
qd_status qd__mech_zero_set(qd_ctx *ctx, const qd_expr *det, size_t n, const qd_expr *const *q,
                       struct qd_metric_singular **out, size_t *count);

/* ---- constraints ---------------------------------------------------------- */

/* --eliminate: solve the holonomic constraints of s that allow it for one
 * coordinate each and substitute (docs in qdot/mech.h, qd_eom_opts).  s
 * shrinks; *elim (malloc'd, *nelim entries) records what was eliminated. */
qd_status qd__mech_eliminate(qd_ctx *ctx, qd__sys *s, qd_elim **elim, size_t *nelim);

/* Fill e->ncon, e->con, e->A and e->b from s (e->q, qd, qdd set): velocity
 * coefficients, multipliers and the closing rows A q'' = b (with_b; else
 * every b[k] stays NULL: the closing rows cost more than the rest). */
qd_status qd__mech_con_setup(qd_ctx *ctx, qd_eom *e, const qd__sys *s, bool with_b);

/* Solve [M -A^T; A 0] [x; lambda] = [f; b] from the compiled outputs out,
 * in the scratch K ((n+m)^2 + n+m doubles); x (n) and lambda (m) may be
 * NULL, R (n) = A^T lambda may be NULL.  QD_ERR_SINGULAR with a message
 * when the matrix is singular. */
qd_status qd__mech_saddle_solve(qd_ctx *ctx, const qd_eom *e, const double *out, double *K,
                           double *x, double *lambda, double *R);

/* Classify one Pfaffian constraint sum_j a_j q'_j + a0 = 0 from c->a[0..n)
 * and c->a0 (q the coordinates, t = qd_time): set c->kind
 * (QD_CON_INTEGRABLE or QD_CON_NONHOLONOMIC), c->integral (NULL when
 * nonholonomic or not found) and c->factor (1 when exact).  QD_ERR_ARG when
 * no a_j is nonzero (classify.c). */
qd_status qd__mech_con_classify(qd_ctx *ctx, size_t n, const qd_expr *const *q, qd_con *c);

/* Are the m Pfaffian forms w_k = sum_j a_kj dq_j + a_k0 dt integrable as a
 * system (Frobenius: dw_k ^ w_1 ^ ... ^ w_m = 0 for every k, t one more
 * variable)?  m <= 16 (classify.c). */
qd_status qd__mech_con_frobenius(qd_ctx *ctx, size_t n, const qd_expr *const *q, qd_con *const *cs,
                            size_t m, bool *integrable);

/* Solve the n equations eq_i = 0 for the unknowns xs (isolate.c): each
 * unknown isolated where it occurs once or can be made to (see the head
 * comment), one equation with one unknown at a time (or, when none has one,
 * for one of its unknowns in the others), on principal branches.
 * QD_ERR_NONLINEAR, with ctx clean, when some equation could not be solved:
 * *failed is its index. */
qd_status qd__mech_isolate(qd_ctx *ctx, size_t n, const qd_expr *const *eq,
                           const qd_expr *const *xs, const qd_expr **sol, size_t *failed);

/* e with every sin, cos or tan of an asin, acos or atan written without the
 * inverse (sin(atan(u)) = u/sqrt(1 + u^2)), simplified (isolate.c). */
const qd_expr *qd__mech_untrig(qd_ctx *ctx, const qd_expr *e);

/* phi(q, t) with d phi = sum_j c->a_j dq_j + c->a0 dt, when that form is
 * exact and phi is found in closed form (checked); NULL otherwise
 * (classify.c). */
const qd_expr *qd__mech_con_integral(qd_ctx *ctx, size_t n, const qd_expr *const *q,
                               const qd_con *c);

/* The m constraints c together (closure.c): *rank, the number of independent
 * forms w_k = sum_j a_kj dq_j + a_k0 dt, and *relations, the number of
 * independent phi(q, t) = const they imply (n + 1 minus the dimension of
 * the involutive closure of their kernel, at random points). */
qd_status qd__mech_con_closure(qd_ctx *ctx, size_t n, const qd_expr *const *q, const qd_con *c,
                          size_t m, size_t *rank, size_t *relations);

/* qd__mech_con_closure, and the integrals (up to cap, *nintegrals of them) of
 * the relations that are combinations with constant coefficients of two or
 * more constraints (roll1 - roll2 on the axle), where found in closed form. */
qd_status qd__mech_con_relations(qd_ctx *ctx, size_t n, const qd_expr *const *q, const qd_con *c,
                            size_t m, size_t *rank, size_t *relations, const qd_expr **integrals,
                            size_t cap, size_t *nintegrals);

#endif
