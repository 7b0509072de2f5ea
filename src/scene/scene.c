/*
 * src/scene/scene.c - the points a picture of the motion draws and the
 * shape of their sampled motion (qdot/scene.h, issue 36).
 */
#include "qdot/scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/args.h"

#define FLAT 1e-9   /* an axis no point moves along, relative to the scale */
#define RIGID 1e-6  /* a distance that stays constant, relative to the scale */

/* ---- the points ---------------------------------------------------------- */

/* A place: no velocity in it, and it moves with a coordinate or the time
 * (a definition of a velocity or a constant is not a point of the motion). */
static bool is_place(qd_ctx *ctx, const qd_expr *x) {
    const qd_expr *syms[64];
    size_t n = qd_free_symbols(ctx, x, syms, 64);
    bool moves = false;
    if (n > 64)
        return false;
    for (size_t i = 0; i < n; i++) {
        qd_role r = qd_symbol_role(syms[i]);
        if (r == QD_ROLE_COORD && qd_symbol_order(syms[i]) > 0)
            return false;
        moves |= r == QD_ROLE_COORD || r == QD_ROLE_TIME;
    }
    return moves;
}

/* The scalar definition named prefix + suffix, when a place: its value. */
static const qd_expr *scalar_place(qd_ctx *ctx, const qd_model *m, char prefix,
                                   const char *suffix) {
    char name[256]; /* longer than any name a model has */
    int len = snprintf(name, sizeof name, "%c%s", prefix, suffix);
    if (len < 0 || (size_t)len >= sizeof name)
        return NULL;
    const qd_expr *v = qd_model_definition(m, name);
    return v && is_place(ctx, v) ? v : NULL;
}

static bool vector_place(qd_ctx *ctx, const qd_model *m, size_t i) {
    if (qd_model_definition_size(m, i) != 3 || qd_model_definition_name(m, i)[0] != 'P')
        return false;
    bool any = false;
    for (size_t k = 0; k < 3; k++)
        any |= is_place(ctx, qd_model_definition_component(m, i, k));
    return any;
}

/* The named positions: a pair x<S>, y<S> (and z<S> when defined) found at
 * the x definition, or a vector P<S>. */
static size_t positions(qd_ctx *ctx, const qd_model *m, qd_scene_point *out) {
    size_t n = 0, nd = qd_model_ndefinitions(m);
    for (size_t i = 0; i < nd; i++) {
        const char *name = qd_model_definition_name(m, i);
        const qd_expr *x = qd_model_definition_component(m, i, 0);
        qd_scene_point p = {.kind = QD_SCENE_POSITION};
        if (name[0] == 'x' && qd_model_definition_size(m, i) == 1 && is_place(ctx, x)) {
            const char *suffix = name + 1;
            const qd_expr *y = scalar_place(ctx, m, 'y', suffix), *z = scalar_place(ctx, m, 'z', suffix);
            if (!y)
                continue;
            p.pos[0] = x;
            p.pos[1] = y;
            p.pos[2] = z ? z : qd_int(ctx, 0);
            if (z)
                snprintf(p.name, sizeof p.name, "%s,y%s,z%s", name, suffix, suffix);
            else
                snprintf(p.name, sizeof p.name, "%s,y%s", name, suffix);
            snprintf(p.comp[0], sizeof p.comp[0], "%s", name);
            snprintf(p.comp[1], sizeof p.comp[1], "y%s", suffix);
            if (z)
                snprintf(p.comp[2], sizeof p.comp[2], "z%s", suffix);
        } else if (vector_place(ctx, m, i)) {
            for (size_t k = 0; k < 3; k++)
                p.pos[k] = qd_model_definition_component(m, i, k);
            snprintf(p.name, sizeof p.name, "%s", name);
            snprintf(p.comp[0], sizeof p.comp[0], "%s", name);
        } else {
            continue;
        }
        if (out)
            out[n] = p;
        n++;
    }
    return n;
}

static const qd_expr *or_zero(qd_ctx *ctx, const qd_expr *x) {
    return x ? x : qd_int(ctx, 0); /* a planar position has no z */
}

qd_status qd_scene_points(qd_ctx *ctx, const qd_model *m, unsigned which, qd_scene_point **pts,
                          size_t *n) {
    QD_ARGS_CTX(ctx, m && pts && n);
    *pts = NULL;
    *n = 0;
    qd_ctx *c = qd_model_ctx(m);
    size_t np = qd_model_nparticles(m), nb = qd_model_nbodies(m);
    if (!which)
        which = np + nb ? QD_SCENE_PARTICLES | QD_SCENE_BODIES : QD_SCENE_POSITIONS;
    np = which & QD_SCENE_PARTICLES ? np : 0;
    nb = which & QD_SCENE_BODIES ? nb : 0;
    size_t nn = which & QD_SCENE_POSITIONS ? positions(c, m, NULL) : 0;
    qd_scene_point *p = calloc(np + nb + nn + 1, sizeof *p);
    if (!p) {
        if (ctx)
            qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory listing the scene's points");
        return QD_ERR_NOMEM;
    }
    for (size_t i = 0; i < np; i++) {
        p[i].kind = QD_SCENE_PARTICLE;
        snprintf(p[i].name, sizeof p[i].name, "p%zu", i + 1);
        p[i].mass = qd_model_particle_mass(m, i);
        for (unsigned k = 0; k < 3; k++)
            p[i].pos[k] = or_zero(c, qd_model_particle_position(m, i, k));
    }
    for (size_t b = 0; b < nb; b++) {
        qd_scene_point *q = &p[np + b];
        q->kind = QD_SCENE_BODY;
        snprintf(q->name, sizeof q->name, "%s", qd_model_body_name(m, b));
        q->mass = qd_model_body_mass(m, b);
        for (unsigned k = 0; k < 3; k++)
            q->pos[k] = or_zero(c, qd_model_body_position(m, b, k));
        for (unsigned k = 0; k < 9; k++)
            q->inertia[k] = qd_model_body_inertia(m, b, k / 3, k % 3);
        q->shape = qd_model_body_shape(m, b, q->size, &q->axis);
        qd_model_body_ground(m, b, q->ground, q->ground + 3);
    }
    if (nn)
        positions(c, m, p + np + nb);
    *pts = p;
    *n = np + nb + nn;
    return QD_OK;
}

bool qd_scene_point_is(const qd_scene_point *p, const char *name, size_t len) {
    QD_ARGS(false, p && name);
    if (strlen(p->name) == len && !strncmp(p->name, name, len))
        return true;
    for (int k = 0; k < 3; k++)
        if (p->comp[k][0] && strlen(p->comp[k]) == len && !strncmp(p->comp[k], name, len))
            return true;
    return false;
}

/* ---- the shape of the motion --------------------------------------------- */

typedef struct frames {
    const double *pos;
    size_t nframes, npts;
} frames;

static const double *at(const frames *s, size_t f, size_t i) {
    static const double origin[3] = {0, 0, 0};
    return i == QD_SCENE_ORIGIN ? origin : s->pos + (f * s->npts + i) * 3;
}

static double distance(const frames *s, size_t f, size_t a, size_t b) {
    const double *p = at(s, f, a), *q = at(s, f, b);
    return hypot(hypot(p[0] - q[0], p[1] - q[1]), p[2] - q[2]);
}

static bool moves(const frames *s, size_t i, double scale) {
    for (size_t f = 1; i != QD_SCENE_ORIGIN && f < s->nframes; f++) {
        const double *p = at(s, f, i), *p0 = at(s, 0, i);
        if (fabs(p[0] - p0[0]) + fabs(p[1] - p0[1]) + fabs(p[2] - p0[2]) > RIGID * scale)
            return true;
    }
    return false;
}

static bool skipped(const size_t *skip, size_t nskip, size_t a, size_t b) {
    for (size_t k = 0; k < nskip; k++)
        if ((skip[2 * k] == a && skip[2 * k + 1] == b) || (skip[2 * k] == b && skip[2 * k + 1] == a))
            return true;
    return false;
}

/* A rod: the distance is constant while at least one end moves. */
static bool rigid(const frames *s, size_t a, size_t b, double scale, double *len) {
    if (!moves(s, a, scale) && !moves(s, b, scale))
        return false;
    double d0 = distance(s, 0, a, b);
    if (d0 <= RIGID * scale)
        return false;
    for (size_t f = 1; f < s->nframes; f++)
        if (fabs(distance(s, f, a, b) - d0) > RIGID * scale)
            return false;
    *len = d0;
    return true;
}

static void bounds(const frames *s, qd_scene_shape *out) {
    double scale = 0;
    for (int k = 0; k < 3; k++) {
        out->lo[k] = INFINITY;
        out->hi[k] = -INFINITY;
    }
    for (size_t f = 0; f < s->nframes; f++)
        for (size_t i = 0; i < s->npts; i++)
            for (int k = 0; k < 3; k++) {
                double x = at(s, f, i)[k];
                out->lo[k] = fmin(out->lo[k], x);
                out->hi[k] = fmax(out->hi[k], x);
                scale = fmax(scale, fabs(x));
            }
    for (int k = 0; k < 3; k++)
        scale = fmax(scale, out->hi[k] - out->lo[k]);
    out->scale = scale > 0 ? scale : 1;
}

/* A plane when some axis is flat for every point: z first (y up on the
 * page), then y, then x. */
static void plane(qd_scene_shape *out) {
    static const int planes[3][3] = {{2, 0, 1}, {1, 0, 2}, {0, 1, 2}}; /* flat, across, up */
    out->plane[0] = out->plane[1] = -1;
    for (int p = 0; p < 3; p++)
        if (out->hi[planes[p][0]] - out->lo[planes[p][0]] <= FLAT * out->scale) {
            out->plane[0] = planes[p][1];
            out->plane[1] = planes[p][2];
            return;
        }
}

qd_status qd_scene_analyse(qd_ctx *ctx, const double *pos, size_t nframes, size_t npts,
                           const size_t *skip, size_t nskip, qd_scene_shape *out) {
    QD_ARGS_CTX(ctx, pos && out && (skip || !nskip));
    memset(out, 0, sizeof *out);
    if (!nframes) {
        if (ctx)
            qd_ctx_error(ctx, QD_ERR_ARG, "qd_scene_analyse: no frames");
        return QD_ERR_ARG;
    }
    frames s = {pos, nframes, npts};
    for (size_t i = 0; i < nframes * npts * 3; i++)
        if (!isfinite(pos[i])) {
            if (ctx)
                qd_ctx_error(ctx, QD_ERR_ARG, "qd_scene_analyse: a position is not finite "
                             "(frame %zu)", i / (npts * 3));
            return QD_ERR_ARG;
        }
    bounds(&s, out);
    plane(out);
    out->rods = malloc(((npts + 1) * npts / 2 + 1) * sizeof *out->rods);
    if (!out->rods) {
        if (ctx)
            qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory finding the scene's rods");
        return QD_ERR_NOMEM;
    }
    for (size_t b = 0; b < npts; b++)
        for (size_t k = 0; k <= b; k++) {
            size_t a = k ? k - 1 : QD_SCENE_ORIGIN; /* the origin, then the earlier points */
            double len;
            if (!skipped(skip, nskip, a, b) && rigid(&s, a, b, out->scale, &len))
                out->rods[out->nrods++] = (qd_scene_rod){a, b, len};
        }
    return QD_OK;
}

void qd_scene_points_free(qd_scene_point *pts) {
    free(pts);
}

void qd_scene_shape_free(qd_scene_shape *s) {
    if (!s)
        return;
    free(s->rods);
    s->rods = NULL;
    s->nrods = 0;
}
