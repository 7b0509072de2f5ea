/*
 * src/speeds/spd.h - what the files of the equations in speeds share: the
 * derivation's state (the velocity map P, its inverse, the kinematics and
 * the accelerations in speeds) and one entry per method.  Prefix qd__spd_.
 */
#ifndef QD_SPEEDS_SPD_H
#define QD_SPEEDS_SPD_H

#include "qdot/eval.h"
#include "qdot/speeds.h"
#include "../mech/mech_export.h"

/* The private part of a qd_speeds_eom (its priv field). */
typedef struct qd__spd_priv {
    qd_eom *shell;         /* coordinates and constraints (owns con and their rows) */
    qd_prog *prog;         /* qd_speeds_eval's: kin, M, f, mult, def */
    const qd_expr **in;    /* its inputs */
    size_t nin, nout;
    double *work;          /* inputs, outputs, registers, solver scratch */
} qd__spd_priv;

/* A derivation in progress. */
typedef struct qd__spd {
    qd_ctx *ctx;
    const qd_model *model;
    qd_speeds_eom *e;
    qd__sys sys;
    qd_eom *shell;
    const qd_expr *L;      /* grouped by velocity monomials */
    size_t n, m, nc;
    const qd_expr **P;     /* n*n: the speeds' rows A, then the constraints' rows C */
    const qd_expr **p0;    /* n: b, then c0 */
    const qd_expr **Pinv;  /* n*n: [W | Wc]; the Wc columns only when need_wc */
    bool need_wc;          /* Hamel and the multipliers use the constraints' columns */
    const qd_expr **acc;   /* n: q'' in q, u, u', t */
} qd__spd;

/* x with q' replaced by the kinematics (and q'' by acc when acc is set). */
const qd_expr *qd__spd_on_motion(qd__spd *d, const qd_expr *x);
/* d/dt of x(q, u, t) along the motion: q' by the kinematics, u' kept. */
const qd_expr *qd__spd_dt(qd__spd *d, const qd_expr *x);
/* The generalized force G_j the kinetic part leaves on coordinate j:
 * Q_j - dD/dq'_j + d/dt d(V+U)/dq'_j - d(V+U)/dq_j (only Q - dD/dq' when L
 * is given), on the motion. */
const qd_expr *qd__spd_force(qd__spd *d, size_t j);
/* Lagrange's residual E_j = d/dt dL/dq'_j - dL/dq_j + dD/dq'_j - Q_j on the
 * motion (q'' = acc). */
const qd_expr *qd__spd_residual(qd__spd *d, size_t j);
/* Fill e->M (m*m) and e->f (m) from the m expressions rows_r = M_u u' - f_u
 * (linear in u'), each entry simplified. */
qd_status qd__spd_rows(qd__spd *d, const qd_expr *const *rows);
/* x expanded and grouped by monomials in the speeds, each group's
 * coefficient through the trigonometric identities and common factors
 * (qd__mech_by_velocity); the whole simplifier only where x is not polynomial
 * in the speeds. */
const qd_expr *qd__spd_tidy(qd__spd *d, const qd_expr *x);

/* P X = B (P n*n, B and X n*nc, row-major) by Gaussian elimination on the
 * DAG, nothing expanded, pivots chosen at sample states (dagsolve.c): the
 * velocity map when the exact solve swells.  X's entries are new
 * expressions of ctx.  QD_ERR_SINGULAR when a column has no pivot that is
 * nonzero at the samples, QD_ERR_NOMEM. */
qd_status qd__spd_dag_solve(qd_ctx *ctx, const qd_model *m, size_t n, const qd_expr *const *P,
                            size_t nc, const qd_expr *const *B, const qd_expr **X);
/* The velocity map (e->W, e->w, e->kin, d->Pinv) from d->P and d->p0 by
 * qd__spd_dag_solve: what velocity_map falls back to when the exact solve
 * is too large. */
qd_status qd__spd_big_map(qd__spd *d);
/* Whether x is small enough for the simplifier: at most QD__SPD_TIDY_MAX
 * distinct nodes.  Larger expressions stay as they are (a DAG the compiled
 * program evaluates), since simplifying them costs more than their size. */
#define QD__SPD_TIDY_MAX 300
/* ... and at most this many nodes as a tree: some of the simplifier's
 * passes walk trees, and a small DAG can be a large tree. */
#define QD__SPD_TIDY_MAX_TREE 3000
/* The largest entry of the velocity map (in DAG nodes) solved exactly. */
#define QD__SPD_EXACT_MAX 32
bool qd__spd_small(qd__spd *d, const qd_expr *x);
/* qd_simplify(x) when x is small and its expansion fits, else x itself
 * (the size limit's error cleared); NULL only out of memory. */
const qd_expr *qd__spd_simplify(qd__spd *d, const qd_expr *x);

/* The methods: each fills e->M and e->f. */
qd_status qd__spd_kane(qd__spd *d);
qd_status qd__spd_hamel(qd__spd *d);
/* Gibbs-Appell: also sets e->S; with fill false only S is made. */
qd_status qd__spd_appell(qd__spd *d, bool fill);
/* e->mult from Lagrange's residuals (opts.multipliers). */
qd_status qd__spd_multipliers(qd__spd *d);

#endif
