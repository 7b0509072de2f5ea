/*
 * src/mech/mech.h - what the mechanics files share: the numeric cache of a
 * qd_eom, the split of T by degree, the singularity check and a small dense
 * solver.
 */
#ifndef QD_MECH_MECH_H
#define QD_MECH_MECH_H

#include "qdot/eval.h"
#include "qdot/mech.h"

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

/* An expression grouped by its monomials in the velocities: every group's
 * coefficient simplified on its own. */
typedef struct qd__vsum {
    const qd_expr *all;    /* the sum of every group */
    const qd_expr *deg[3]; /* the groups of degree 0, 1 and 2 */
    long top;              /* the highest degree */
    const qd_expr *bad;    /* when not a polynomial: a factor that is not */
} qd__vsum;

/* Group the expansion of x by monomials in the velocities qd[0..n).
 * QD_ERR_NONLINEAR, with v->bad set and nothing recorded in ctx, when x is
 * not a polynomial in them. */
qd_status qd__mech_by_velocity(qd_ctx *ctx, const qd_expr *x, size_t n, const qd_expr *const *qd,
                          qd__vsum *v);

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

/* Solve A X = B symbolically (A n*n, B and X n*ncols, row-major) by the
 * fraction-free elimination of qd_eom_solve, each entry simplified.
 * QD_ERR_SINGULAR, nothing recorded, when det A simplifies to 0;
 * QD_ERR_TOOBIG, nothing recorded, when an entry would exceed max_ops
 * operations (0: no limit). */
qd_status qd__mech_solve_cols(qd_ctx *ctx, size_t n, const qd_expr *const *A, size_t ncols,
                         const qd_expr *const *B, const qd_expr **X, size_t max_ops);

/* The same for sparse A (solve_sparse.c): rows and columns with a single
 * entry are solved directly, only the rest by elimination.  Each unknown
 * X_j (column c) solved by a singleton row or column is passed through tidy
 * (with arg, j and c) as soon as it is known, since the rows still to come
 * substitute it: the caller knows the shape of the solution (linear in some
 * symbols, say) and can tidy it more cheaply than qd_simplify, the default
 * (tidy NULL). */
typedef const qd_expr *(*qd__tidy_fn)(void *arg, size_t j, size_t c, const qd_expr *x);
qd_status qd__mech_solve_sparse(qd_ctx *ctx, size_t n, const qd_expr *const *A, size_t ncols,
                           const qd_expr *const *B, const qd_expr **X, size_t max_ops,
                           qd__tidy_fn tidy, void *arg);

/* ---- constraints ---------------------------------------------------------- */

/* What Lagrange's equations are derived from: a model's content, or that
 * content after coordinates were eliminated (eliminate.c).  The arrays are
 * malloc'd (qd__mech_sys_free); the expressions belong to the context. */
typedef struct qd__sys {
    size_t n;
    const qd_expr **q;                 /* n coordinates */
    const qd_expr **Q;                 /* n generalized forces */
    const qd_expr *T, *V, *U, *L, *D;  /* NULL where the model has none */
    bool L_given;
    size_t ncon;
    const char **con_name;             /* owned by the model */
    const qd_expr **con_expr;          /* = 0 along the motion */
    size_t nreduced;
    const char **reduced;              /* ncon entries: redundant ones eliminate left out */
} qd__sys;

qd_status qd__mech_sys_from_model(qd_ctx *ctx, const qd_model *m, qd__sys *s);
void qd__mech_sys_free(qd__sys *s);

/* A qd_eom with e's coordinates and constraints (qd__mech_con_setup) but no
 * Lagrange rows (M and f NULL) and no closing rows (b[k] NULL): what the
 * equations in speeds start from (they need the velocity rows only). */
qd_eom *qd__mech_eom_shell(qd_ctx *ctx, const qd__sys *s);

/* Lagrange's rows M q'' = f of a shell from s with the Lagrangian L (as
 * qd__mech_sys_lagrangian gives it): e->M, e->f, e->L; each entry simplified
 * (f grouped by velocity monomials first) unless raw, for a caller that
 * combines them and simplifies only the combinations. */
qd_status qd__mech_eom_rows(qd_ctx *ctx, qd_eom *e, const qd__sys *s, const qd_expr *L, bool raw);

/* L of s grouped by velocity monomials (as qd_eom_derive differentiates it),
 * e's coordinates set; T's split goes to e->T2, T1, T0. */
const qd_expr *qd__mech_sys_lagrangian(qd_ctx *ctx, qd_eom *e, const qd__sys *s);

/* --eliminate: solve the holonomic constraints of s that allow it for one
 * coordinate each and substitute (docs in qdot/mech.h, qd_eom_opts).  s
 * shrinks; *elim (malloc'd, *nelim entries) records what was eliminated. */
qd_status qd__mech_eliminate(qd_ctx *ctx, qd__sys *s, qd_elim **elim, size_t *nelim);

/* Fill e->ncon, e->con, e->A and e->b from s (e->q, qd, qdd set): velocity
 * coefficients, multipliers and the closing rows A q'' = b (with_b; else
 * every b[k] stays NULL: the closing rows cost more than the rest). */
qd_status qd__mech_con_setup(qd_ctx *ctx, qd_eom *e, const qd__sys *s, bool with_b);

/* Is A (m*n, row-major) of rank below m?  Then mu (m) receives a vector
 * with A^T mu = 0, largest entry 1 in magnitude.  tol is relative. */
bool qd__mech_con_deficient(qd_ctx *ctx, size_t n, size_t m, const double *A, double tol,
                            double *mu);

/* Report rank-deficient constraints: those with a weight in mu, named;
 * inconsistent when some combination mu of the constraints (g, or b at the
 * acceleration level) is not zero.  where: "" or " at this state". */
qd_status qd__mech_con_report(qd_ctx *ctx, const qd_eom *e, const double *mu, bool inconsistent,
                         const char *where);

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
