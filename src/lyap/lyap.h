/*
 * src/lyap/lyap.h - what the Lyapunov files share: the compiled tangent
 * system (variational.c) and a run's workspace for it.  Prefix qd__lyap_.
 */
#ifndef QD_LYAP_LYAP_H
#define QD_LYAP_LYAP_H

#include "qdot/lyapunov.h"
#include "sim/sim_export.h"

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

/* ---- a run of the state and k tangent vectors (tangent.c) ---------------- */

/* The integrator over y = (q, q', the k tangent vectors, z) from
 * (q0, q'0), e_1 .. e_k and z = 0, with its workspace; extra: the doubles
 * after y and yold that the caller keeps for itself. */
typedef struct qd__lyap_tangent {
    qd__lyap_ws ws;
    qd__sim_integ it;
    const qd_sim_opts *o;
    size_t d, k;           /* d = 2n */
    double *extra;
} qd__lyap_tangent;

/* The checks both runs make of o: qd_sim_check_opts, the method (dopri5
 * or dop853: "SUBJECT integrated with dopri5 or dop853, not ..."), the
 * initial state given.  QD_ERR_ARG recorded in ctx. */
qd_status qd__lyap_check_opts(qd_ctx *ctx, const qd_sim_opts *o, const char *subject);
/* r set up and its method started ("out of memory starting WHAT"); on
 * failure too, qd__lyap_tangent_free releases it. */
qd_status qd__lyap_tangent_start(qd__lyap_tangent *r, qd_ctx *ctx, const qd_lyap *l,
                                 const qd_sim_opts *o, size_t k, size_t extra,
                                 const char *what);
/* Integrate to tb exactly (the last step shortened to land there). */
qd_status qd__lyap_tangent_advance(qd__lyap_tangent *r, double tb);
void qd__lyap_tangent_free(qd__lyap_tangent *r);

#endif
