/*
 * src/scene/wall.c - the walls and floors a constrained model's points slide
 * on (qd_scene_walls): found from the sampled motion, as the rods are, not
 * guessed from the constraints' text.  A drawn point (a particle, a named
 * position, or either end of a body drawn as a rod: a body's centre is not
 * where it touches) that keeps one space coordinate while it moves is held
 * on that coordinate's plane: a ladder's foot on the floor, its top on the
 * wall.
 */
#include "qdot/scene.h"

#include <math.h>
#include <stdlib.h>

#include "base/args.h"

#define FLAT 1e-6   /* a coordinate kept (as a rod its length), relative to the size */
#define MOVES 1e-3  /* a point that moves, relative to the scene's size */

typedef struct wall_ctx {
    const qd_scene_look *looks;
    const qd_scene_frames *fr;
    size_t npts;
} wall_ctx;

/* Candidate c of point i at frame f: 0 the point itself, 1 and 2 a rod's
 * ends (false when the point has no such candidate); its centre too. */
static bool candidate(const wall_ctx *w, size_t i, size_t body, int c, size_t f, double out[3],
                      double centre[3]) {
    const double *p = w->fr->pos + 3 * (f * w->npts + i);
    const qd_scene_look *l = w->looks ? &w->looks[i] : NULL;
    bool rod = l && l->shape == QD_SHAPE_ROD;
    if (c > 0 && !rod)
        return false;
    for (int k = 0; k < 3; k++)
        out[k] = centre[k] = p[k];
    if (c == 0)
        return true;
    const double *R = w->fr->rot + 9 * (f * w->fr->nbodies + body);
    double s = (c == 1 ? -0.5 : 0.5) * l->size[0];
    for (int k = 0; k < 3; k++)
        out[k] += s * R[3 * k + l->axis];
    return true;
}

static size_t add(qd_scene_wall *out, size_t n, qd_scene_wall w, double tol) {
    for (size_t j = 0; j < n; j++)
        if (out[j].axis == w.axis && fabs(out[j].at - w.at) <= tol) {
            if (out[j].side != w.side)
                out[j].side = 0; /* points on both sides: no side is the solid one */
            return n;
        }
    out[n] = w;
    return n + 1;
}

qd_status qd_scene_walls(qd_ctx *ctx, const qd_scene_point *pts, const qd_scene_look *looks,
                         const qd_scene_frames *fr, size_t npts, const int plane[2],
                         qd_scene_wall **walls, size_t *nwalls) {
    QD_ARGS_CTX(ctx, (pts || !npts) && fr && plane && walls && nwalls &&
                         (fr->pos || !npts || !fr->nframes));
    *walls = NULL;
    *nwalls = 0;
    wall_ctx w = {looks, fr, npts};
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t f = 0; f < fr->nframes; f++)
        for (size_t i = 0; i < npts; i++)
            for (int k = 0; k < 3; k++) {
                lo[k] = fmin(lo[k], fr->pos[3 * (f * npts + i) + k]);
                hi[k] = fmax(hi[k], fr->pos[3 * (f * npts + i) + k]);
            }
    double scale = 0;
    for (int k = 0; k < 3; k++)
        scale = fmax(scale, hi[k] - lo[k]);
    qd_scene_wall *out = malloc((9 * npts + 1) * sizeof *out);
    if (!out) {
        if (ctx)
            qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory finding the scene's walls");
        return QD_ERR_NOMEM;
    }
    size_t n = 0, body = 0;
    for (size_t i = 0; i < npts && fr->nframes > 1 && scale > 0 && isfinite(scale); i++) {
        for (int c = 0; c < 3; c++) {
            double p0[3], c0[3], lo_p[3], hi_p[3], p[3], cen[3];
            if (c == 0 && pts[i].kind == QD_SCENE_BODY)
                continue; /* a body's centre is off the surface it slides on */
            if (!candidate(&w, i, body, c, 0, p0, c0))
                break;
            for (int k = 0; k < 3; k++)
                lo_p[k] = hi_p[k] = p0[k];
            for (size_t f = 1; f < fr->nframes; f++) {
                candidate(&w, i, body, c, f, p, cen);
                for (int k = 0; k < 3; k++) {
                    lo_p[k] = fmin(lo_p[k], p[k]);
                    hi_p[k] = fmax(hi_p[k], p[k]);
                }
            }
            double travel = 0;
            for (int k = 0; k < 3; k++)
                travel = fmax(travel, hi_p[k] - lo_p[k]);
            for (int k = 0; k < 3 && travel > MOVES * scale; k++) {
                bool drawing_plane = plane[0] >= 0 && k != plane[0] && k != plane[1];
                if (drawing_plane || hi_p[k] - lo_p[k] > FLAT * scale)
                    continue;
                double at = (lo_p[k] + hi_p[k]) / 2, d = c0[k] - at;
                int side = fabs(d) > FLAT * scale ? (d > 0 ? 1 : -1) : 0;
                n = add(out, n, (qd_scene_wall){.axis = k, .at = at, .side = side}, FLAT * scale);
            }
        }
        body += pts[i].kind == QD_SCENE_BODY;
    }
    *walls = out;
    *nwalls = n;
    return QD_OK;
}
