/*
 * qdot/zvc.h - Jacobi's integral and the zero-velocity curves.
 *
 * When L does not contain t (and no force or dissipation acts), Jacobi's
 * integral
 *
 *     h = sum_j q'_j dL/dq'_j - L = T2 - T0 + V (+ U0)
 *
 * is constant (qdot/integrals.h).  T2 >= 0, so a motion with constant h
 * stays where
 *
 *     W(q) = h(q, q' = 0) = V - T0 (+ U0) <= h,
 *
 * and its boundary W(q) = h, where the velocity vanishes, is the
 * zero-velocity curve (Hill's curves of the restricted three-body problem:
 * W = -(x^2 + y^2)/2 - (1 - mu)/rho1 - mu/rho2, Desloge ch. 62; the
 * astronomers' Jacobi constant is C_J = -2 h; Desloge's U adds
 * -mu (1 - mu)/2, seed-desloge-B.md C6 and pitfall 8).  The curves through
 * the collinear points L1, L2, L3 at their own values of h pinch there:
 * the regions on either side touch at the saddle of W.
 *
 * The curves are traced by marching squares on a grid over a box of two
 * coordinates (the others held at given values) and joined into polylines.
 */
#ifndef QDOT_ZVC_H
#define QDOT_ZVC_H

#include <stdbool.h>
#include <stddef.h>
#include "expr.h"
#include "mech.h"
#include "model.h"
#include "contour.h" /* the curves are qd_contour_grid's */

#ifdef __cplusplus
extern "C" {
#endif

/* Jacobi's integral of a model and its value at rest. */
typedef struct qd_zvc {
    const qd_expr *h;   /* sum_j q'_j dL/dq'_j - L, in q, q' and the parameters */
    const qd_expr *W;   /* h at q' = 0: V - T0 (+ U0) */
} qd_zvc;

/* h and W for model m with equations e (solved here for the accelerations
 * when it was not: qd_integrals_derive).  QD_ERR_ARG when h is not
 * conserved (L contains t, a force or dissipation acts: the message says
 * which) or the model has constraints with multipliers. */
QD_API qd_status qd_zvc_derive(qd_ctx *ctx, const qd_model *m, qd_eom *e, qd_zvc *out);

/* Where to trace: coordinates ix (across) and iy (up) of e over
 * [lo[0], hi[0]] x [lo[1], hi[1]] on an nx by ny grid of cells; the other
 * coordinates and the parameters from syms/vals (as for qd_eom_eval:
 * missing ones 0). */
typedef struct qd_zvc_box {
    size_t ix, iy;
    double lo[2], hi[2];
    size_t nx, ny;
} qd_zvc_box;

/* The zero-velocity curves W = level (qd_contour_grid on W at the grid's
 * points).  QD_ERR_ARG for a bad box (ix == iy, an index out of range, an
 * empty range, nx or ny 0). */
QD_API qd_status qd_zvc_curves(qd_ctx *ctx, const qd_eom *e, const qd_zvc *z,
                               const qd_zvc_box *box, size_t nvals,
                               const qd_expr *const *syms, const double *vals, double level,
                               qd_contour *out);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_zvc_curves (syms, vals). An array
 * whose count is 0 may be NULL. */
#endif
