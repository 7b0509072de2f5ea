/*
 * src/scene/look.c - what a body is drawn as (qd_scene_looks): its `shape`
 * statement, else a slender rod read off its inertia, else nothing (the
 * page then draws a dot with the body's axes).
 */
#include "qdot/scene.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/args.h"

#define THIN 1e-12  /* a moment that is 0, relative to the largest */
#define EQUAL 1e-9  /* two moments that are equal, relatively */

/* A slender rod's inertia: diagonal, one moment 0, the other two equal
 * I = M l^2 / 12 (the rod(m, l) helper, or written out along any axis). */
static qd_status rod_from_inertia(qd_ctx *ctx, const qd_scene_point *p, size_t nsyms,
                                  const qd_expr *const *syms, const double *vals,
                                  qd_scene_look *out) {
    double I[9], M, big = 0;
    for (int k = 0; k < 9; k++) {
        if (!p->inertia[k])
            return QD_OK;
        qd_status st = qd_eval(ctx, p->inertia[k], nsyms, syms, vals, &I[k]);
        if (st != QD_OK)
            return st;
        big = fmax(big, fabs(I[k]));
    }
    qd_status st = qd_eval(ctx, p->mass, nsyms, syms, vals, &M);
    if (st != QD_OK)
        return st;
    if (!(big > 0) || !isfinite(big) || !(M > 0))
        return QD_OK;
    for (int k = 0; k < 9; k++)
        if (k % 4 && fabs(I[k]) > THIN * big)
            return QD_OK; /* not in principal axes: no rod along a body axis */
    for (int k = 0; k < 3; k++) {
        double a = I[4 * ((k + 1) % 3)], b = I[4 * ((k + 2) % 3)];
        if (fabs(I[4 * k]) <= THIN * big && fabs(a - b) <= EQUAL * big) {
            *out = (qd_scene_look){.shape = QD_SHAPE_ROD, .size = {sqrt(12 * a / M), 0, 0},
                                   .axis = k, .inferred = true};
            return QD_OK;
        }
    }
    return QD_OK;
}

qd_status qd_scene_looks(qd_ctx *ctx, const qd_scene_point *pts, size_t n, size_t nsyms,
                         const qd_expr *const *syms, const double *vals, qd_scene_look *out) {
    QD_ARGS_CTX(ctx, (pts || !n) && (out || !n) && ((syms && vals) || !nsyms));
    for (size_t i = 0; i < n; i++) {
        const qd_scene_point *p = &pts[i];
        double g[6] = {0};
        out[i] = (qd_scene_look){.shape = QD_SHAPE_NONE, .axis = 2};
        if (p->kind != QD_SCENE_BODY)
            continue;
        for (int k = 0; k < 6 && p->ground[0]; k++) {
            qd_status st = qd_eval(ctx, p->ground[k], nsyms, syms, vals, &g[k]);
            if (st != QD_OK)
                return st;
        }
        bool ground = p->ground[0] != NULL;
        if (p->shape == QD_SHAPE_NONE) {
            qd_status st = rod_from_inertia(ctx, p, nsyms, syms, vals, &out[i]);
            if (st != QD_OK)
                return st;
        } else {
            out[i] = (qd_scene_look){.shape = p->shape, .axis = p->axis};
        }
        out[i].has_ground = ground;
        memcpy(out[i].ground, g, sizeof g);
        for (int k = 0; k < 3 && p->shape != QD_SHAPE_NONE && p->size[k]; k++) {
            qd_status st = qd_eval(ctx, p->size[k], nsyms, syms, vals, &out[i].size[k]);
            if (st != QD_OK)
                return st;
            if (!(out[i].size[k] > 0) || !isfinite(out[i].size[k])) {
                if (ctx)
                    qd_ctx_error(ctx, QD_ERR_ARG, "body '%s': its shape's size %d is %g, not a "
                                 "positive length", p->name, k + 1, out[i].size[k]);
                return QD_ERR_ARG;
            }
        }
    }
    return QD_OK;
}
