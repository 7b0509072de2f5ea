/*
 * src/hj/hj_priv.h - what the Hamilton-Jacobi files share: the peeling of
 * H = E into one equation per coordinate (separate.c) and the quadratures
 * that make W (quadrature.c).
 */
#ifndef QD_HJ_PRIV_H
#define QD_HJ_PRIV_H

#include "qdot/hj.h"

/* The separation in progress.  F = 0 is the part of H(q, p) - E that is not
 * separated yet; left[k] marks the coordinates still in it. */
typedef struct qd__hj_sep_state {
    qd_ctx *ctx;
    qd_hj *h;
    const qd_expr **q, **p;
    bool *left;
    size_t nleft;
    const qd_expr *F;
    const qd_expr **value;   /* per constant (in h->constants order): itself as a
                                function of q and p */
    unsigned used;           /* bits: which forms the steps used */
} qd__hj_sep_state;

/* Peel H - E one coordinate at a time; fills h->sep, h->constants,
 * h->separable, h->form and h->why.  QD_OK also when H does not separate
 * (separable false); an error status only for a failure of the kernel. */
qd_status qd__hj_separate(qd__hj_sep_state *s);

/* int sqrt(p2) dq in closed form where there is one (p2 a polynomial of
 * degree <= 2 in q, or what the kernel integrates), else the unevaluated
 * integral(sqrt(p2), q). */
const qd_expr *qd__hj_quadrature(qd_ctx *ctx, const qd_expr *p2, const qd_expr *q);

/* The unevaluated integral(f, x), a user function the printers show as such
 * (sympy: Integral). */
const qd_expr *qd__hj_integral(qd_ctx *ctx, const qd_expr *f, const qd_expr *x);

/* The sign of c where it is known for every value of its positive symbols:
 * -1, 1, or 0 when it is not known (or c is 0). */
int qd__hj_sign(const qd_expr *c);

/* An explicit t with every coordinate cyclic (time_part.c): p_k = alpha_k,
 * W = sum alpha_k q_k and h->time_part f(t) = -int_0^t H(alpha, t') dt';
 * nothing is filled when a coordinate appears in H. */
qd_status qd__hj_time_part(qd_ctx *ctx, qd_hj *h, const qd_expr *const *q,
                           const qd_expr *const *p);
/* Its motion from dS/dalpha_k = beta_k: q_k = beta_k - df/dalpha_k. */
qd_status qd__hj_time_solve(qd_ctx *ctx, qd_hj *h);

#endif
