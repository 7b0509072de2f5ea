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
#include "equilibria.h"
#include "print.h"
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

/* "x=A:B, y=C:D" read into box: two different coordinates of e (the
 * equations of m) across and up, A and B constant expressions in m's
 * parameters (qd_model_number), A < B; nx and ny are left as they are.
 * QD_ERR_ARG with the error located in text (an unknown coordinate gets
 * "did you mean"). */
QD_API qd_status qd_zvc_box_read(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                                 const char *text, qd_zvc_box *box);

/* The zero-velocity curves W = level (qd_contour_grid on W at the grid's
 * points).  QD_ERR_ARG for a bad box (ix == iy, an index out of range, an
 * empty range, nx or ny 0). */
QD_API qd_status qd_zvc_curves(qd_ctx *ctx, const qd_eom *e, const qd_zvc *z,
                               const qd_zvc_box *box, size_t nvals,
                               const qd_expr *const *syms, const double *vals, double level,
                               qd_contour *out);


/* ---- the whole picture: curves, the equilibria in the box, written out --- */

/* What `qdot zvc` shows: the curves W = level over the box and the
 * equilibria inside it, each with W there (the level whose curve passes
 * through it: for the restricted three-body problem the Jacobi constants
 * of L1..L5, C_J = -2 W). */
typedef struct qd_zvc_picture {
    qd_zvc z;
    qd_zvc_box box;
    double level;
    qd_contour curves;
    qd_equilibria eq;   /* in the box (the other coordinates in their default
                           box); count 0 when not sought */
    double *eq_W;       /* eq.count values of W; NaN where it has none */
} qd_zvc_picture;

/* Trace the curves of z (from qd_zvc_derive for e and m) at level over box,
 * the other coordinates and the parameters from syms/vals as for
 * qd_zvc_curves, and, when equilibria is set, find the equilibria of e in
 * the box with W at each.  Errors as qd_zvc_curves and qd_equilibria_find.
 * Free with qd_zvc_picture_free (also after a failure). */
QD_API qd_status qd_zvc_picture_make(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                                     const qd_zvc *z, const qd_zvc_box *box, size_t nvals,
                                     const qd_expr *const *syms, const double *vals,
                                     double level, bool equilibria, qd_zvc_picture *out);
QD_API void qd_zvc_picture_free(qd_zvc_picture *p);

struct qd_linpoint; /* qdot/linpoint.h */

/* The level of the curves as `qdot zvc` takes it, exactly one of: level, a
 * number or a constant expression in the parameters (qd_model_number); the
 * value of W at a point at rest, through "x=..., y=..." (the unnamed
 * coordinates 0, qd_linpoint_read_coords); the value of h at a state, at
 * "x=..., x'=..." (qd_linpoint_read).  z from qd_zvc_derive on p's
 * equations.  The level into *h, the point into q (p->e->n values: the
 * other coordinates' values the curves are drawn at, 0 for a level given
 * as a number), and p's state left at q, at rest.  QD_ERR_ARG unless
 * exactly one is given; an error in the text given (the reader's, located
 * there; or QD_ERR_ARG "Jacobi's integral has no finite value there", not
 * located, its diag.name "through" or "at") with *where (may be NULL)
 * set to that text, else NULL. */
QD_API qd_status qd_zvc_level_read(qd_ctx *ctx, struct qd_linpoint *p, const qd_zvc *z,
                                   const char *level, const char *through, const char *at,
                                   double *q, double *h, const char **where);

/* The picture written for a reader, appended to out: h, W, the level, each
 * equilibrium with its kind and W, and a line per curve (closed or open,
 * its points, its extent); results with 12 significant digits. */
QD_API qd_status qd_zvc_print(qd_ctx *ctx, const qd_eom *e, const qd_zvc_picture *p,
                              qd_buf *out);
/* The curves' points as CSV: "curve,X,Y" (the box's coordinates), one row a
 * point, every digit. */
QD_API qd_status qd_zvc_csv(qd_ctx *ctx, const qd_eom *e, const qd_zvc_picture *p, qd_buf *out);
/* The picture as one JSON document and a newline: "h", "W", "level",
 * "grid" [nx, ny], "equilibria" (the coordinates, "kind", "h": W there),
 * "curves" ("closed", the two coordinates' arrays). */
QD_API qd_status qd_zvc_json(qd_ctx *ctx, const qd_eom *e, const qd_zvc_picture *p,
                             qd_buf *out);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_zvc_curves (syms, vals);
 * qd_zvc_picture_make (syms, vals). An array whose count is 0 may be NULL. */
#endif
