/*
 * qdot/contour.h - the level set of gridded values as polylines (marching
 * squares), the tracer of the zero-velocity curves (qdot/zvc.h) and of any
 * other curve f(x, y) = level over a box.
 */
#ifndef QDOT_CONTOUR_H
#define QDOT_CONTOUR_H

#include <stdbool.h>
#include <stddef.h>
#include "expr.h"

#ifdef __cplusplus
extern "C" {
#endif

/* One curve of a level set: count points (x[i], y[i]); a closed curve ends
 * with its first point again. */
typedef struct qd_polyline {
    size_t count;
    double *x, *y;
    bool closed;
} qd_polyline;

typedef struct qd_contour {
    size_t count;
    qd_polyline *lines;
} qd_contour;

/* The level set f = level of the grid values f[i + j (nx + 1)] at
 * x_i = x0 + (x1 - x0) i / nx, y_j = y0 + (y1 - y0) j / ny (i <= nx,
 * j <= ny), by marching squares: each cell's crossings by linear
 * interpolation on its edges, a saddle cell decided by the mean of its
 * corners, cells with a corner that is not finite (a pole) left out; the
 * segments joined through the edges they share into polylines, closed when
 * a curve returns to its start, open where it leaves the box or meets a
 * cell left out.  Polylines come in the order of their first cell (rows
 * from y0, then x0 to x1).  nx, ny >= 1.  Free with qd_contour_free. */
QD_API qd_status qd_contour_grid(qd_ctx *ctx, size_t nx, size_t ny, const double *f, double x0,
                                 double x1, double y0, double y1, double level,
                                 qd_contour *out);
QD_API void qd_contour_free(qd_contour *c);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. An array whose count is 0 may be
 * NULL. */
#endif
