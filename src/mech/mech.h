/*
 * src/mech/mech.h - what the mechanics files share: the numeric cache of a
 * qd_eom, the split of T by degree, the singularity check and a small dense
 * solver.
 */
#ifndef QD_MECH_MECH_H
#define QD_MECH_MECH_H

#include "qdot/eval.h"
#include "qdot/mech.h"

/* The private part of a qd_eom (its priv field): M and f compiled once,
 * with every free symbol of M and f as an input, so a state that leaves a
 * symbol out gives it the value 0. */
typedef struct qd__eom_num {
    qd_prog *prog; /* outputs: M (n*n, row-major), f (n), then with m
                      constraints A (m*n), b (m) and the constraints' own
                      expressions g (m): qd__out_* give the offsets */
    size_t nin, nout;
    const qd_expr **inputs;
    double *in, *out; /* nin and n*n + n doubles */
} qd__eom_num;

/* Every free symbol of exprs[0..n), each once, in a malloc'd array (NULL
 * on failure). */
const qd_expr **qd__inputs(qd_ctx *ctx, size_t n, const qd_expr *const *exprs, size_t *nin);

/* Offsets of the compiled outputs (see qd__eom_num). */
static inline size_t qd__out_A(const qd_eom *e) { return e->n * e->n + e->n; }
static inline size_t qd__out_b(const qd_eom *e) { return qd__out_A(e) + e->ncon * e->n; }
static inline size_t qd__out_g(const qd_eom *e) { return qd__out_b(e) + e->ncon; }
static inline size_t qd__out_len(const qd_eom *e) { return qd__out_g(e) + e->ncon; }

/* Compile e's numeric program if it is not compiled yet. */
qd_status qd__eom_compile(qd_ctx *ctx, const qd_eom *e);
void qd__eom_num_free(qd__eom_num *num);

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
qd_status qd__by_velocity(qd_ctx *ctx, const qd_expr *x, size_t n, const qd_expr *const *qd,
                          qd__vsum *v);

/* The kinetic energy grouped: T = T2 + T1 + T0 by degree in the velocities
 * (v->deg, valid when v->top <= 2).  Velocities in anything but a
 * polynomial are QD_ERR_NONLINEAR, with the reason in ctx. */
qd_status qd__split_kinetic(qd_ctx *ctx, const qd_expr *T, size_t n, const qd_expr *const *qd,
                            qd__vsum *v);

/* QD_OK unless e's mass matrix is identically singular; then
 * QD_ERR_SINGULAR, with a message naming the undetermined accelerations.
 * T is the model's kinetic energy (may be NULL), used for the wording. */
qd_status qd__check_singular(qd_ctx *ctx, const qd_eom *e, const qd_expr *T);

/* The determinant of the n*n matrix A by fraction-free elimination, each
 * step cancelled; NULL on failure (reason in ctx). */
const qd_expr *qd__det(qd_ctx *ctx, size_t n, const qd_expr *const *A);

/* Gaussian elimination with partial pivoting on A (n*n, row-major, in
 * place); pc is scratch for n indices.  A column whose best pivot is not
 * above tol times the matrix norm is skipped and marked in free_col (may be
 * NULL).  Returns the rank; when it is n and b is not NULL, b is overwritten
 * by the solution of A x = b.  With a deficient rank and null and free_col
 * not NULL, null receives a vector of the null space. */
size_t qd__gauss(size_t n, double *A, double *b, double tol, size_t *pc, bool *free_col,
                 double *null);

/* ---- constraints ---------------------------------------------------------- */

/* What Lagrange's equations are derived from: a model's content, or that
 * content after coordinates were eliminated (eliminate.c).  The arrays are
 * malloc'd (qd__sys_free); the expressions belong to the context. */
typedef struct qd__sys {
    size_t n;
    const qd_expr **q;                 /* n coordinates */
    const qd_expr **Q;                 /* n generalized forces */
    const qd_expr *T, *V, *U, *L, *D;  /* NULL where the model has none */
    bool L_given;
    size_t ncon;
    const char **con_name;             /* owned by the model */
    const qd_expr **con_expr;          /* = 0 along the motion */
} qd__sys;

qd_status qd__sys_from_model(qd_ctx *ctx, const qd_model *m, qd__sys *s);
void qd__sys_free(qd__sys *s);

/* --eliminate: solve the holonomic constraints of s that allow it for one
 * coordinate each and substitute (docs in qdot/mech.h, qd_eom_opts).  s
 * shrinks; *elim (malloc'd, *nelim entries) records what was eliminated. */
qd_status qd__eliminate(qd_ctx *ctx, qd__sys *s, qd_elim **elim, size_t *nelim);

/* Fill e->ncon, e->con, e->A and e->b from s (e->q, qd, qdd set): velocity
 * coefficients, multipliers and the closing rows A q'' = b. */
qd_status qd__con_setup(qd_ctx *ctx, qd_eom *e, const qd__sys *s);

/* Is A (m*n, row-major) of rank below m?  Then mu (m) receives a vector
 * with A^T mu = 0, largest entry 1 in magnitude.  tol is relative. */
bool qd__con_deficient(qd_ctx *ctx, size_t n, size_t m, const double *A, double tol, double *mu);

/* Report rank-deficient constraints: those with a weight in mu, named;
 * inconsistent when some combination mu of the constraints (g, or b at the
 * acceleration level) is not zero.  where: "" or " at this state". */
qd_status qd__con_report(qd_ctx *ctx, const qd_eom *e, const double *mu, bool inconsistent,
                         const char *where);

/* Solve [M -A^T; A 0] [x; lambda] = [f; b] from the compiled outputs out;
 * x (n) and lambda (m) may be NULL, R (n) = A^T lambda may be NULL.
 * QD_ERR_SINGULAR with a message when the matrix is singular. */
qd_status qd__saddle_solve(qd_ctx *ctx, const qd_eom *e, const double *out, double *x,
                           double *lambda, double *R);

/* Classify one Pfaffian constraint sum_j a_j q'_j + a0 = 0 from c->a[0..n)
 * and c->a0 (q the coordinates, t = qd_time): set c->kind
 * (QD_CON_INTEGRABLE or QD_CON_NONHOLONOMIC), c->integral (NULL when
 * nonholonomic or not found) and c->factor (1 when exact).  QD_ERR_ARG when
 * no a_j is nonzero (classify.c). */
qd_status qd__con_classify(qd_ctx *ctx, size_t n, const qd_expr *const *q, qd_con *c);

/* Are the m Pfaffian forms w_k = sum_j a_kj dq_j + a_k0 dt integrable as a
 * system (Frobenius: dw_k ^ w_1 ^ ... ^ w_m = 0 for every k, t one more
 * variable)?  m <= 16 (classify.c). */
qd_status qd__con_frobenius(qd_ctx *ctx, size_t n, const qd_expr *const *q, qd_con *const *cs,
                            size_t m, bool *integrable);

#endif
