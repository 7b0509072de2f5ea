/*
 * src/mech/mech_export.h - mech's interface to the modules above it
 * (docs/design.md, "Architecture"): the pieces of Lagrange's derivation
 * that impulse, linear and speeds build on.  Kane's and Appell's forms
 * (speeds) start from mech's system and Lagrange rows; impulse reads the
 * velocity-form constraint rows and their rank; linear solves M x = f
 * exactly.  Internal (prefix qd__mech_), not public: these take mech's
 * half-built qd_eom and change with the derivation.
 */
#ifndef QD_MECH_MECH_EXPORT_H
#define QD_MECH_MECH_EXPORT_H

#include <stdbool.h>
#include "qdot/mech.h"

/* ---- velocity monomials ---------------------------------------------------- */

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

/* ---- exact dense and sparse solves ------------------------------------------ */

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

/* ---- the system Lagrange's equations come from ------------------------------ */

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

/* ---- the constraints' rank --------------------------------------------------- */

/* Is A (m*n, row-major) of rank below m?  Then mu (m) receives a vector
 * with A^T mu = 0, largest entry 1 in magnitude.  tol is relative. */
bool qd__mech_con_deficient(qd_ctx *ctx, size_t n, size_t m, const double *A, double tol,
                            double *mu);

/* Report rank-deficient constraints: those with a weight in mu, named;
 * inconsistent when some combination mu of the constraints (g, or b at the
 * acceleration level) is not zero.  where: "" or " at this state". */
qd_status qd__mech_con_report(qd_ctx *ctx, const qd_eom *e, const double *mu, bool inconsistent,
                         const char *where);

#endif
