/*
 * src/impulse/impulse_priv.h - what the impulse solver's files share: the
 * system of one impulse (mass matrix, constraint rows, the state) in
 * symbols and in numbers.  Prefix qd__imp_.
 *
 * The rows are kept as qd_con records (name, velocity coefficients a and
 * velocity-free part a0) so that the mechanics layer's diagnosis
 * (qd__mech_con_report) and reactions (qd_eom_reaction) can be reused on a
 * qd_eom view of them (qd__imp_view).
 */
#ifndef QD_IMPULSE_PRIV_H
#define QD_IMPULSE_PRIV_H

#include "qdot/impulse.h"
#include "qdot/mech.h"

/* Rows in the order of the multipliers: held (the model's ordinary
 * constraints), sudden (`impact constraint`), prescribed (`prescribe`). */
typedef enum qd__imp_kind { QD__IMP_HELD, QD__IMP_SUDDEN, QD__IMP_PRESCRIBED } qd__imp_kind;

typedef struct qd__imp {
    qd_ctx *ctx;
    const qd_model *m;
    qd_eom *e;                 /* M (velocity-free) and the held rows */
    size_t n;
    const qd_expr *T;          /* the energy T2 + T1 + T0; a non-quadratic L's
                                  energy function sum q' dL/dq' - L */
    /* L beyond the square in the velocities (relativistic, Desloge ch. 92):
     * the jump is of the momenta P_j = dL/dq'_j, solved by Newton (momenta.c);
     * M at the state is then d^2 L/dq' dq' there, the Jacobian of P. */
    bool nonquad;
    const qd_expr **P;         /* n, when nonquad */
    /* Rows: nheld, then nsudden, then npre of them (nrow in all). */
    size_t nrow, nheld, nsudden, npre;
    qd_con *row;               /* name, expr, a (n), a0 */
    const qd_expr **A;         /* nrow*n, row-major: the rows' a */
    const qd_expr **E;         /* nrow restitutions (0 for held and prescribed rows) */
    /* The state: the symbols q (n), q' (n), t, parameters and their values. */
    size_t nv;
    const qd_expr **syms;
    double *vals;
    const qd_expr **q0, **qd0, *t0;   /* the state as expressions */
    /* Numbers at the state, in one block at M (qd__imp_numbers). */
    double *M;                 /* n*n */
    double *Qhat;              /* n */
    double *An, *a0n, *En;     /* nrow*n, nrow, nrow */
    double *p0;                /* n: dT/dq' at q' = 0 (T1's coefficients) */
    double *W;                 /* nblows*n: each blow's generalized impulse */
    size_t nblows;
} qd__imp;

/* Build s for m (rows.c): derive M, check T, collect and split the rows.
 * On failure the reason is in ctx; qd__imp_free(s) in every case. */
qd_status qd__imp_build(qd_ctx *ctx, const qd_model *m, qd__imp *s);
void qd__imp_free(qd__imp *s);

/* The state of opts (a NULL entry: the model's initial value as written)
 * and every number of s at it (state.c).  QD_ERR_ARG for a missing
 * value or a restitution outside [0, 1]. */
qd_status qd__imp_state(qd__imp *s, const qd_impulse_opts *opts);
qd_status qd__imp_numbers(qd__imp *s);

/* The right-hand side of row k, what A_k (q'+ - q'-) must be: Newton's law
 * c(q'+) = -E c(q'-) gives -(1 + E) c(q'-). */
double qd__imp_rhs(const qd__imp *s, size_t k, const double *v0);

/* x at the state with the velocities set to v. */
qd_status qd__imp_eval(const qd__imp *s, const qd_expr *x, const double *v, double *out);

/* The energy T at the frozen configuration with velocities v; the energy
 * of a velocity change d, d^T M d / 2. */
qd_status qd__imp_energy(const qd__imp *s, const double *v, double *T);
double qd__imp_quad(const qd__imp *s, const double *d);

/* Solve [M -B^T; B 0] [x; mu] = [f; r], B m*n: false when singular.
 * mu may be NULL. */
bool qd__imp_saddle(qd_ctx *ctx, size_t n, size_t m, const double *M, const double *B,
                    const double *f, const double *r, double *x, double *mu);

/* The impulse with the rows marked in use (NULL: all): the velocities
 * after (v1) and the multipliers (lambda, nrow, 0 for rows not in use).
 * Rows dependent on the others (numeric rank, relative tolerance) are
 * left out and checked afterwards: consistent, they are flagged in
 * redundant (nrow; may be NULL) with multiplier 0; else QD_ERR_SINGULAR
 * naming the inconsistent rows; report false: no message (a check's
 * re-solve). */
qd_status qd__imp_solve(const qd__imp *s, const bool *use, bool report, double *v1,
                        double *lambda, bool *redundant);

/* A qd_eom view of s with every row as a constraint (for qd__mech_con_report
 * and qd_eom_reaction); nothing to free. */
qd_eom qd__imp_view(const qd__imp *s);

/* The impulse of a non-quadratic L through the momenta (momenta.c):
 * P(q'+) - P(q'-) = Qhat + A^T Lambda with the rows' conditions on q'+. */
qd_status qd__imp_solve_momenta(const qd__imp *s, double *v1, double *lambda);

/* The theorems of Carnot, Bertrand and Thomson on the solved impulse r
 * (theorems.c). */
qd_status qd__imp_theorems(const qd__imp *s, qd_impulse *r);

/* Two bodies meeting: fill r->col when the model has exactly two mass
 * elements and a sudden constraint (collision.c). */
qd_status qd__imp_collision(const qd__imp *s, qd_impulse *r);

/* The closed forms (exact.c): r->exact false, ctx clean, when they are too
 * big or the symbolic system is singular. */
qd_status qd__imp_exact(const qd__imp *s, size_t max_ops, qd_impulse *r);

#endif
