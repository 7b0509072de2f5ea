/*
 * qdot/constrained.h - small oscillations, equilibria and linearization of a
 * model that keeps holonomic constraints with multipliers (a pendulum written
 * as x^2 + y^2 = l^2), on the constraint manifold.
 *
 * The equations are M q'' = f + A^T lambda, phi(q) = 0 (qdot/mech.h), with
 * A = dphi/dq (ncon*n).  At rest (q' = 0) a point is an equilibrium when
 *
 *     F(q) + A(q)^T lambda = 0,   phi(q) = 0,      F(q) = f(q, 0),
 *
 * n + ncon equations in q and the multipliers lambda.  About it the motion
 * stays on the manifold: q = q0 + T y + O(y^2), T (n*r, r = n - ncon) a basis
 * of the tangent space null(A).  T is built from a choice of independent
 * coordinates q_I (the others q_D dependent): T = [I; -A_D^-1 A_I] in the
 * rows I, D, so that y are the independent coordinates' displacements.  The
 * choice is the caller's, or made by a column-pivoted QR of A (the dependent
 * columns are the best-conditioned pivots).  The reduced equations are
 *
 *     M_r y'' + (C_r + G_r) y' + K_r y = 0,
 *     M_r = T^T M T,  C_r + G_r = -T^T (df/dq') T,
 *     K_r = T^T (K - sum_k lambda_k Hess phi_k) T,   K = -dF/dq,
 *
 * the term in lambda being the second-order part of the constraint force
 * (with qdot's sign, M q'' = f + A^T lambda; written with the potential,
 * K_r = T^T (Hess V + sum_k mu_k Hess phi_k) T, grad V = -A^T mu).  Every
 * derivative is exact (symbolic differentiation of the equations' entries,
 * compiled and evaluated at the point).  Only scleronomic holonomic
 * constraints are reduced: a constraint with velocities (Pfaffian,
 * nonholonomic) or one that depends on t is QD_ERR_UNSUPPORTED.
 *
 * Equilibria (qd_equilibria_find calls qd_constrained_equilibria_find for a
 * model with constraints): a multi-start search over the box, each start
 * projected onto the manifold (minimum-norm Gauss-Newton on phi = 0), the
 * multipliers by least squares, then damped Newton on the n + ncon
 * equations; duplicates merged, each point classified by K_r.
 */
#ifndef QDOT_CONSTRAINED_H
#define QDOT_CONSTRAINED_H

#include <stdbool.h>
#include <stddef.h>
#include "equilibria.h"
#include "expr.h"
#include "mech.h"
#include "model.h"
#include "modes.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The reduction about one equilibrium on the manifold. */
typedef struct qd_constrained_linear {
    size_t n, ncon, r;     /* coordinates, constraints, r = n - ncon */
    double *q;             /* n: the point (on the manifold) */
    double *lambda;        /* ncon: the multipliers there */
    size_t *indep;         /* r indices into e->q, ascending: the independent coordinates */
    size_t *dep;           /* ncon indices into e->q, ascending */
    double *T;             /* n*r row-major: the tangent basis, T[indep[i]][i] = 1 */
    double phi_res;        /* max_k |phi_k(q)| */
    double force_res;      /* max_j |F_j + (A^T lambda)_j| */
    qd_linear lin;         /* r*r: M_r, C_r, G_r, K_r over the independent coordinates */
} qd_constrained_linear;

/* Reduce e about the point syms/vals (coordinates, t, parameters; symbols
 * not given are 0, velocities are taken as 0).  indep: r indices into e->q
 * (the caller's independent coordinates), or NULL to choose them.  The
 * point is first put on the manifold by Newton on phi = 0 moving the
 * dependent coordinates only (the independent keep their values); it must
 * then be an equilibrium: QD_ERR_ARG (message with the residual) when
 * F + A^T lambda does not vanish there (relative 1e-8 of the force scale),
 * when phi = 0 cannot be reached from it, or when the chosen dependent
 * coordinates do not determine the constraints (A_D singular there: the
 * message names a better choice).  QD_ERR_UNSUPPORTED for a model without
 * holonomic-only scleronomic constraints.  Free with
 * qd_constrained_linear_free (also after a failure). */
QD_API qd_status qd_constrained_linear_about(qd_ctx *ctx, const qd_eom *e, size_t nvals,
                                             const qd_expr *const *syms, const double *vals,
                                             const size_t *indep, qd_constrained_linear *out);
QD_API void qd_constrained_linear_free(qd_constrained_linear *c);

/* The state-space matrix of the reduced system over x = (y, y'):
 * A = [0 I; -M_r^-1 K_r  -M_r^-1 (C_r + G_r)], 2r*2r row-major into A.
 * QD_ERR_SINGULAR when M_r is singular. */
QD_API qd_status qd_constrained_state_matrix(qd_ctx *ctx, const qd_constrained_linear *c,
                                             double *A);

/* The input matrix of the reduced system for the inputs u (nu symbols, the
 * model's `inputs`): the generalized forces' rates df/du at the point c->q
 * (at rest; syms/vals as given to qd_constrained_linear_about, which also
 * fix u0) projected onto the manifold, B = [0; M_r^-1 T^T df/du], 2r*nu
 * row-major into B.  The multipliers' change with u does not enter: A^T dlambda
 * is normal to the manifold (T^T A^T = 0).  QD_ERR_SINGULAR when M_r is
 * singular. */
QD_API qd_status qd_constrained_input_matrix(qd_ctx *ctx, const qd_eom *e,
                                             const qd_constrained_linear *c, size_t nu,
                                             const qd_expr *const *u, size_t nvals,
                                             const qd_expr *const *syms, const double *vals,
                                             double *B);

/* ---- the analysis at a point (src/linear/constrained_at.c) ---------------
 * What `qdot modes` and `qdot linearize` compute on the manifold. */
typedef struct qd_constrained_at {
    qd_constrained_linear c;  /* the reduction (qd_constrained_linear_about) */
    qd_modes_result res;      /* qd_modes_solve(c.lin) */
    size_t nu;                /* m's inputs (with statespace) */
    const qd_expr **u;        /* nu: the inputs, or NULL */
    double *A, *B;            /* with statespace: 2r*2r and 2r*nu (the matrices above), else
                                 NULL */
} qd_constrained_at;

/* The reduction about the point syms/vals (arguments as for
 * qd_constrained_linear_about), its modes and, when statespace, the
 * state-space matrices with m's inputs.  The errors of the calls: QD_ERR_ARG
 * and QD_ERR_UNSUPPORTED come only from the reduction (a point or a model
 * it does not take).  Free with qd_constrained_at_free (also after a
 * failure). */
QD_API qd_status qd_constrained_at_solve(qd_ctx *ctx, const qd_eom *e, const qd_model *m,
                                         size_t nvals, const qd_expr *const *syms,
                                         const double *vals, const size_t *indep,
                                         bool statespace, qd_constrained_at *out);
QD_API void qd_constrained_at_free(qd_constrained_at *a);

/* ---- the independent coordinates named (src/linear/constrained_read.c) -- */

/* The independent coordinates named in text, "x, y" (names of e's
 * coordinates, separated by commas or spaces), as indices into e->q in
 * ascending order into out (room for e->n - e->ncon), ready for
 * qd_constrained_linear_about.  QD_ERR_ARG, located in text (qd_ctx_diag:
 * offset and length), for a name that is not a coordinate of e, one named
 * twice, or a count other than e->n - e->ncon (located at the name one too
 * many, else at the whole text). */
QD_API qd_status qd_constrained_indep_read(qd_ctx *ctx, const qd_eom *e, const char *text,
                                           size_t *out);

/* ---- printed (src/linear/constrained_print.c) ----------------------------- */

/* What both printers below begin with, c reduced from e.  Text: "on the
 * constraint manifold (N coordinates, K constraints): independent ...;
 * dependent ...", then "about q = ..." (the point, every coordinate) and
 * "multipliers lambda_NAME = ..." (12 digits, qd_buf_put_result with scale
 * 1).  JSON: "independent", "dependent" (names), "equilibrium" and
 * "multipliers" (objects name to number).  Both end with the eigenvalues
 * of the state-space matrix and the verdict: text "eigenvalues of A:" with
 * one "s = re +- im i" a line (10 digits) unless the modes were printed,
 * then "verdict: stable|unstable|borderline"; JSON "eigenvalues" ([re, im]
 * pairs), "stable" (true, false, or null when borderline) and "verdict".
 *
 * Each appends to out only when complete (out unchanged on failure) and
 * returns QD_ERR_ARG when c, e and res do not belong together (their
 * sizes), QD_ERR_NUMERIC for a number JSON cannot hold (not finite),
 * QD_ERR_NOMEM; each is recorded in ctx. */

/* The small oscillations about c, res = qd_modes_solve(c->lin), as text or
 * JSON (json).  Text: "small oscillations " and the head; for a
 * conservative system each mode "mode K: w^2 = ..., w = ... rad/s, period =
 * ... s" (w and the period when w^2 > 0) and its shape over the
 * independent coordinates, else the eigenvalues; the verdict.  JSON: the
 * head, "conservative", "mass_matrix", "damping_matrix", "gyroscopic_matrix",
 * "stiffness_matrix" (the reduced r*r matrices M, C, G, K), for
 * a conservative system "modes" (each {"omega2", "omega" when omega2 >= 0,
 * "shape": name to number}), the eigenvalues and the verdict. */
QD_API qd_status qd_constrained_modes_print(qd_ctx *ctx, const qd_eom *e,
                                            const qd_constrained_linear *c,
                                            const qd_modes_result *res, bool json,
                                            qd_buf *out);

/* The equilibria of a model with constraints (see the head comment); the
 * arguments as for qd_equilibria_find (opts->near: Newton from that guess
 * only).  Each point lists every coordinate of e; the kind, signs and
 * symmetry are those of K_r there (r = n - ncon numbers), exact is NULL. */
QD_API qd_status qd_constrained_equilibria_find(qd_ctx *ctx, const qd_eom *e, const qd_model *m,
                                                size_t nvals, const qd_expr *const *syms,
                                                const double *vals,
                                                const qd_equilibria_opts *opts,
                                                qd_equilibria *out);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_constrained_linear_about (indep);
 * qd_constrained_at_solve (indep);
 * qd_constrained_equilibria_find (opts). An array whose count is 0 may be
 * NULL. */
#endif
