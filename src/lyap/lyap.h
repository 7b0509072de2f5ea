/*
 * src/lyap/lyap.h - what the Lyapunov files share: the compiled tangent
 * system (variational.c) and a run's workspace for it.  Prefix qd__lyap_.
 */
#ifndef QD_LYAP_LYAP_H
#define QD_LYAP_LYAP_H

#include "qdot/lyapunov.h"
#include "sim/simint.h"

/* The compiled system: the qd_sim of the equations (its acc program gives
 * M and f) and jac, the derivatives of the equations of motion:
 * df/dq (n*n), df/dq' (n*n), then dM/dq_k and dM/dq'_k (n*n each) for
 * every k whose derivative is not identically zero (dmq[k], dmv[k]: the
 * offset of that block in jac's outputs, or 0 when it is zero). */
struct qd_lyap {
    qd_sim *sim;
    qd_prog *jac;
    size_t n, jac_n;
    size_t *dmq, *dmv;
};

/* A run's evaluation of the tangent system: state y = (q, q') (2n), then
 * k tangent vectors of 2n numbers each (column j at y + 2n + 2n j), then
 * z, the integral of tr J.  w is the run's copy of the compiled qd_sim
 * with its own workspace (qd__sim_ws_alloc). */
typedef struct qd__lyap_ws {
    const qd_lyap *l;
    qd_sim w;
    size_t k;
    double *jout, *jwork;  /* jac's outputs and workspace */
    double *A, *B;         /* n*n: df/dq - dM/dq q'', df/dq' - dM/dq' q'' */
    double *LU, *X, *qdd;  /* M factored; the right-hand sides (n*(k+n)); q'' */
    int *ipiv;
} qd__lyap_ws;

/* The workspace for k tangent vectors, the parameters par (NULL: the
 * model's); QD_ERR_NOMEM recorded in ctx. */
qd_status qd__lyap_ws_init(qd__lyap_ws *ws, qd_ctx *ctx, const qd_lyap *l, size_t k,
                           const double *par);
void qd__lyap_ws_free(qd__lyap_ws *ws);
/* The augmented right-hand side at (t, y) (the qd_sim's ext_rhs): the
 * state's, the tangent vectors' J w_j, and tr J.  QD_ERR_SINGULAR (mass
 * matrix) or QD_ERR_NUMERIC (not finite) with the time, in the ws's ctx. */
qd_status qd__lyap_rhs(void *ws, double t, const double *y, double *dy);
/* J (2n x 2n, row-major) and F at (t, x), x the 2n state: for the tests
 * that check the symbolic Jacobian against differences of F. */
qd_status qd__lyap_jacobian(qd_ctx *ctx, const qd_lyap *l, const double *par, double t,
                            const double *x, double *F, double *J);

#endif
