/*
 * qdot/mech.h - equations of motion from a model.
 *
 * Lagrange's equations, for each coordinate q_j,
 *
 *     d/dt(dL/dq'_j) - dL/dq_j + dD/dq'_j = Q_j,
 *
 * are linear in the accelerations and are written M(q, q', t) q'' = f(q, q', t):
 * M_jk = d^2 L / dq'_j dq'_k (the mass matrix, symmetric), and f the rest
 * moved to the right-hand side.  Every entry is simplified.
 *
 * Constraints (`constraint NAME: ...` in the model) add Lagrange multipliers:
 *
 *     M q'' = f + A^T lambda,      A q'' = b,
 *
 * A_kj the coefficient of q'_j in constraint k (holonomic: dphi_k/dq_j),
 * lambda_k a plain symbol `lambda_<name>`, and R_j = sum_k lambda_k A_kj the
 * generalized constraint force on q_j (Desloge ch. 49 thm 1, ch. 52 thm 1).
 * The second block closes the system: each holonomic constraint
 * differentiated twice, each Pfaffian one once.
 */
#ifndef QDOT_MECH_H
#define QDOT_MECH_H

#include <stddef.h>
#include "expr.h"
#include "model.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A constraint of the model, classified.
 *
 *   holonomic       phi(q, t) = 0, no velocities.  a_j = dphi/dq_j, a0 = dphi/dt,
 *                   so that phi' = sum_j a_j q'_j + a0.
 *   Pfaffian        sum_j a_j(q, t) q'_j + a0(q, t) = 0: integrable when it is
 *                   exact after multiplying by an integrating factor (then
 *                   `integral` = const along the motion and `factor` is that
 *                   factor, 1 when exact), otherwise nonholonomic.
 *   nonlinear       velocities enter nonlinearly: not supported (an error).
 */
typedef enum qd_con_kind {
    QD_CON_HOLONOMIC,
    QD_CON_INTEGRABLE,     /* Pfaffian, integrable */
    QD_CON_NONHOLONOMIC    /* Pfaffian, not integrable */
} qd_con_kind;

typedef struct qd_con {
    const char *name;            /* the model's name for it (owned by the model) */
    qd_con_kind kind;
    const qd_expr *expr;         /* as the model gives it (= 0) */
    const qd_expr **a;           /* n coefficients of the velocities */
    const qd_expr *a0;           /* the velocity-free part */
    const qd_expr *integral;     /* QD_CON_INTEGRABLE: phi(q, t), constant along the motion;
                                    NULL when integrable but not found in closed form */
    const qd_expr *factor;       /* the integrating factor used, or NULL */
    const qd_expr *lambda;       /* the multiplier, a plain symbol lambda_<name> */
} qd_con;

/* A coordinate eliminated with a holonomic constraint (qd_eom_opts.eliminate):
 * q = value along the motion, value in the remaining coordinates and t. */
typedef struct qd_elim {
    const char *con;             /* the constraint used (owned by the model) */
    const qd_expr *q;
    const qd_expr *value;
} qd_elim;

typedef struct qd_eom {
    size_t n;                    /* degrees of freedom */
    const qd_expr **q;           /* coordinates q_j */
    const qd_expr **qd;          /* velocities q'_j */
    const qd_expr **qdd;         /* accelerations q''_j */
    const qd_expr **M;           /* n*n, row-major */
    const qd_expr **f;           /* n */
    const qd_expr *L;            /* the Lagrangian used */
    /* The kinetic energy split by degree in the velocities, T = T2 + T1 + T0
     * (T1, T0 not zero for rheonomic coordinates); NULL when L was given
     * without T. */
    const qd_expr *T2, *T1, *T0;
    const qd_expr **acc;         /* n symbolic accelerations after qd_eom_solve, else NULL */
    /* Constraints: M q'' = f + A^T lambda, closed by A q'' = b (each
     * holonomic constraint differentiated twice, each Pfaffian once).
     * A is ncon*n row-major (A_kj = con[k].a[j]); b is ncon. */
    size_t ncon;
    qd_con *con;
    const qd_expr **A, **b;
    const qd_expr **mult;        /* ncon symbolic multipliers after qd_eom_solve, else NULL */
    /* Coordinates eliminated before deriving (not among q): nelim of them. */
    size_t nelim;
    qd_elim *elim;
    /* Constraints left out by rank: redundant (their rows a combination of
     * the others' on the manifold, and consistent with them), so their
     * multipliers are not determined; names owned by the model. */
    size_t nreduced;
    const char **reduced;
    void *priv;                  /* the library's: the compiled numeric program */
} qd_eom;

/* Derive the equations of a model.  Parameters stay symbolic.  A mass matrix
 * that is singular (identically: det M simplifies to 0) is QD_ERR_SINGULAR.
 * NULL on failure, reason in the context. */
QD_API qd_eom *qd_eom_derive(qd_ctx *ctx, const qd_model *m);
QD_API void qd_eom_free(qd_eom *e);

/* Options of the derivation.  eliminate: every holonomic constraint that is
 * linear in one of its coordinates with a coefficient free of coordinates
 * and time (x1 + x2 = l, r = a) is solved for that coordinate (the last one
 * declared that qualifies), which is substituted with its velocity and
 * acceleration into T, V, U, L, D, Q (Q_i += Q_j dq_j/dq_i) and the other
 * constraints before Lagrange's equations are formed (Desloge ch. 50).
 * Pfaffian constraints are never substituted: that gives wrong equations;
 * they keep their multipliers. */
typedef struct qd_eom_opts {
    bool eliminate;
} qd_eom_opts;

/* qd_eom_derive with options (opts may be NULL: the defaults, all false). */
QD_API qd_eom *qd_eom_derive_opts(qd_ctx *ctx, const qd_model *m, const qd_eom_opts *opts);

/* Solve M q'' = f symbolically for q'' (fraction-free elimination, each entry
 * simplified); with constraints, the saddle-point system
 * [M -A^T; A 0] [q''; lambda] = [f; b], the multipliers going to e->mult.
 * QD_ERR_TOOBIG when the result would exceed max_ops operations (count_ops)
 * in some entry: the caller then keeps M and f. */
QD_API qd_status qd_eom_solve(qd_ctx *ctx, qd_eom *e, size_t max_ops);

/* Numbers: M, f and q'' at one state.  vals gives the value of each symbol in
 * syms (coordinates, velocities, t, parameters); symbols not given are 0.
 * M is n*n row-major; M, f or qdd may be NULL when not wanted.  With
 * constraints, q'' and the multipliers lambda (ncon) solve
 * [M -A^T; A 0] [q''; lambda] = [f; b], and R (n) = A^T lambda is the
 * generalized constraint force; lambda and R may be NULL (R is 0 without
 * constraints).  QD_ERR_SINGULAR when M (or the saddle-point matrix) is
 * singular at that state, with a message naming the constraints when they
 * are redundant or inconsistent there (M and f are still filled).  The
 * entries are compiled on the first call and kept in e with one workspace,
 * so qd_eom_eval is for one thread; threads use qd_eom_prog_eval. */
QD_API qd_status qd_eom_eval(qd_ctx *ctx, const qd_eom *e, size_t nvals, const qd_expr *const *syms,
                      const double *vals, double *M, double *f, double *qdd, double *lambda,
                      double *R);

/* Thread safety: compile once, evaluate anywhere.  qd_eom_compile makes an
 * immutable program (e must outlive it and not change); any number of
 * threads may then call qd_eom_prog_eval on it at once, each with its own
 * workspace (qd_eom_work_new, used by one thread at a time) and its own
 * context for messages.  qd_eom_prog_eval is qd_eom_eval's computation.
 * NULL on failure, reason in ctx (the thread's own for qd_eom_work_new). */
typedef struct qd_eom_prog qd_eom_prog;
typedef struct qd_eom_work qd_eom_work;
QD_API qd_eom_prog *qd_eom_compile(qd_ctx *ctx, const qd_eom *e);
QD_API void qd_eom_prog_free(qd_eom_prog *p);
QD_API qd_eom_work *qd_eom_work_new(qd_ctx *ctx, const qd_eom_prog *p);
QD_API void qd_eom_work_free(qd_eom_work *w);
QD_API qd_status qd_eom_prog_eval(qd_ctx *ctx, const qd_eom_prog *p, qd_eom_work *w,
                                  size_t nvals, const qd_expr *const *syms, const double *vals,
                                  double *M, double *f, double *qdd, double *lambda, double *R);

/* The Cartesian force F that constraint `con` (by name) exerts at the point
 * r (r[0..2] in the model's coordinates, parameters and t), at one state
 * (syms, vals as for qd_eom_eval) with the multipliers lambda (ncon, from
 * qd_eom_eval).  Virtual work at frozen time: the constraint's generalized
 * force R_j = lambda_k A_kj must be F . dr/dq_j for every coordinate j, n
 * equations for 3 unknowns, solved in the least-squares sense with the
 * smallest |F|.  When the constraint depends on the coordinates only through
 * r (g = G(r)) the equations are consistent and F = lambda_k grad_r G
 * exactly; *residual (may be NULL) is |J^T F - R| / |R|, 0 then, and not 0
 * when the constraint also acts elsewhere (a rope on its other mass: F is
 * then the part of R that works through r).  Only the components of F along
 * the directions r can move in (the span of dr/dq_j) are determined: when
 * those span fewer than 3 dimensions (a point kept in a plane, on a circle
 * by the choice of coordinates), the component normal to them is the force
 * of the constraints built into the coordinates and is reported as 0.
 * Eliminated coordinates (qd_eom.elim) are substituted into r; a constraint
 * used for elimination has no multiplier: QD_ERR_ARG, as for an unknown
 * name. */
QD_API qd_status qd_eom_reaction(qd_ctx *ctx, const qd_eom *e, const char *con,
                          const qd_expr *const r[3], size_t nvals, const qd_expr *const *syms,
                          const double *vals, const double *lambda, double F[3],
                          double *residual);

/* The degrees of freedom of e's coordinates under its constraints taken
 * together (Desloge ch. 49).  relations: the independent relations
 * phi(q, t) = const the constraints imply, the holonomic ones and the
 * integrable combinations of Pfaffian ones, even when no single constraint
 * is integrable (two wheels on an axle: th - a (p1 - p2)/(2b)); found as
 * n + 1 minus the dimension of the smallest involutive distribution that
 * contains the constraints' kernel in (q, t) (Frobenius), at random points,
 * for generic parameter values and user functions.  configurational = n - relations,
 * motional = n - independent (the rank of the constraint rows). */
#define QD_DOF_MAXCOMB 4
typedef struct qd_dof {
    size_t coordinates;          /* e->n (eliminated ones not counted) */
    size_t independent;          /* independent constraints */
    size_t relations;            /* independent integrable combinations */
    size_t configurational;
    size_t motional;
    /* phi = const for the relations that are combinations of two or more
     * constraints with constant coefficients (th - a (p1 - p2)/(2b) on the
     * axle, up to a factor), where found in closed form: ncombined of them */
    size_t ncombined;
    const qd_expr *combined[QD_DOF_MAXCOMB];
} qd_dof;

/* Fill d for e.  QD_ERR_UNBOUND when a constraint coefficient cannot be
 * evaluated (a derivative of a user function written in it), QD_ERR_TOOBIG
 * beyond 31 coordinates and symbols; d then counts no constraint. */
QD_API qd_status qd_eom_dof(qd_ctx *ctx, const qd_eom *e, qd_dof *d);

/* ---- what `qdot check` says of a model's numbers --------------------------- */

/* The mass matrix and the holonomic constraints at the model's parameter
 * values (src/model/audit.c).  mass_ok false: M is not positive definite
 * at the initial configuration (q_j its initial value, else 0.5 + 0.1 j;
 * t = 0) nor at that point moved by 0.25 + 0.1 j in each q_j, so a zero or
 * negative mass or inertia is found and a coordinate singularity (sin(theta)
 * = 0 at the start) is not; mass_coord is then the coordinate of the first
 * pivot <= 0 (its Cholesky factor) and mass_pivot its value.  A holonomic
 * constraint phi = 0 that Gauss-Newton from the initial state (0 where
 * none is given) cannot bring below 1e-9 (|grad phi| -> 0 first: x^2 + y^2
 * = -1) is unsolvable: con_ok false, con its index, con_min the least
 * |phi| reached.  residual: the largest |phi(q0, t0)| over the holonomic
 * constraints, at constraint residual_con; what a run projects away. */
typedef struct qd_audit {
    bool mass_ok;
    size_t mass_coord;
    double mass_pivot;
    bool con_ok;
    size_t con;
    double con_min;
    double residual;
    size_t residual_con;
} qd_audit;
/* QD_ERR_UNBOUND when a parameter has no number; QD_ERR_NOMEM. */
QD_API qd_status qd_eom_audit(qd_ctx *ctx, const qd_model *m, const qd_eom *e, qd_audit *out);

/* Solve eq = 0 for y in closed form by isolating it (src/mech/isolate.c:
 * what is done to y undone, outermost first, on principal branches, so a
 * squaring's condition is the caller's to check).  The solution in *sol,
 * free of y; QD_ERR_NONLINEAR, ctx clean, when y does not isolate. */
QD_API qd_status qd_isolate(qd_ctx *ctx, const qd_expr *eq, const qd_expr *y, const qd_expr **sol);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_eom_derive_opts (opts); qd_eom_eval
 * (M, R, f, lambda, qdd); qd_eom_prog_eval (M, R, f, lambda, qdd);
 * qd_eom_reaction (residual). An array whose count is 0 may be NULL. */
#endif
