/*
 * qdot/scene.h - what a picture of a model's motion draws (issue 36): the
 * points (particles, rigid bodies, and named positions: definitions
 * x1 = ..., y1 = ... [, z1 = ...] or a vector P1 = (x, y, z)) with the model's
 * expressions of their places, and, from their places sampled along a run,
 * the drawing plane, the bounding box and the rods (pairs whose distance
 * stays constant).  The caller evaluates the positions (qd_sim outputs) and
 * renders; `qdot animate` is one such caller.
 */
#ifndef QDOT_SCENE_H
#define QDOT_SCENE_H

#include <stdbool.h>
#include <stddef.h>
#include "expr.h"
#include "model.h"
#include "status.h"

#ifdef __cplusplus
extern "C" {
#endif

#define QD_SCENE_ORIGIN ((size_t)-1) /* a rod's end at the fixed origin (the pivot) */

typedef enum qd_scene_kind {
    QD_SCENE_PARTICLE,   /* a `particle`: named p1, p2, ... in file order */
    QD_SCENE_BODY,       /* a `body`: its own name, drawn with its rotation */
    QD_SCENE_POSITION    /* a named position: "x1,y1" (scalars) or "P1" (a vector) */
} qd_scene_kind;

typedef struct qd_scene_point {
    char name[96];
    qd_scene_kind kind;
    const qd_expr *mass;   /* NULL for a named position */
    const qd_expr *pos[3]; /* never NULL (0 for a planar model's missing z) */
    /* a named position's component names ("x1", "y1", "z1" or "P1"), for
     * choosing it by any of them; "" when none */
    char comp[3][32];
} qd_scene_point;

/* Which points to take: bit 1 particles, 2 bodies, 4 named positions. */
enum { QD_SCENE_PARTICLES = 1, QD_SCENE_BODIES = 2, QD_SCENE_POSITIONS = 4 };

/* The points of model m of the kinds in `which`, particles first, then
 * bodies, then named positions in the order of their definitions; *pts is
 * malloc'd (free() it), *n may be 0.  which == 0: the default, particles
 * and bodies, or named positions when the model has neither.
 * qd_scene_points_free(*pts) frees them (free() does too). */
QD_API qd_status qd_scene_points(qd_ctx *ctx, const qd_model *m, unsigned which,
                                 qd_scene_point **pts, size_t *n);
QD_API void qd_scene_points_free(qd_scene_point *pts);

/* True when a point's name, or one of its component names, is name[0, len). */
QD_API bool qd_scene_point_is(const qd_scene_point *p, const char *name, size_t len);

typedef struct qd_scene_rod {
    size_t a, b;           /* point indices, or QD_SCENE_ORIGIN */
    double length;
} qd_scene_rod;

typedef struct qd_scene_shape {
    int plane[2];          /* the drawing plane's axes (x 0, y 1, z 2), or -1 -1: 3-D */
    double lo[3], hi[3];   /* the bounding box of every point over the frames */
    double scale;          /* the largest extent, the tolerances' unit */
    qd_scene_rod *rods;    /* malloc'd (qd_scene_shape_free); nrods may be 0 */
    size_t nrods;
} qd_scene_shape;

/* The shape of a sampled motion: pos[(f * npts + i) * 3 + k], nframes >= 1.
 * A plane when one axis is flat for every point (z first, then y, then x);
 * a rod between two points, or a point and the origin, whose distance is
 * constant (to 1e-6 of the scale) over the frames while one of them moves;
 * pairs listed in skip[2 * k], skip[2 * k + 1] (nskip pairs, springs the
 * caller draws) are not rods.  qd_scene_shape_free frees out's rods (also
 * after a failure). */
QD_API qd_status qd_scene_analyse(qd_ctx *ctx, const double *pos, size_t nframes, size_t npts,
                                  const size_t *skip, size_t nskip, qd_scene_shape *out);
QD_API void qd_scene_shape_free(qd_scene_shape *s);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_scene_points (ctx); qd_scene_analyse
 * (ctx, skip). An array whose count is 0 may be NULL. */
#endif
