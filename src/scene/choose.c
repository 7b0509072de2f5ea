/*
 * src/scene/choose.c - which points a picture draws, chosen by words
 * (qdot animate --draw), the points named by a caller (--trace, --spring),
 * their places and rotations as outputs of a run, and the frames sampled
 * from the run's rows.
 */
#include "qdot/scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/args.h"

/* The error just recorded concerns the option field name. */
static qd_status field(qd_ctx *ctx, qd_status st, const char *name) {
    if (ctx)
        qd_ctx_error_about(ctx, QD_SUBJECT_NONE, 0, name, QD_REASON_NONE, NULL);
    return st;
}

bool qd_scene_find(const qd_scene_point *pts, size_t n, const char *name, size_t len,
                   size_t *at) {
    QD_ARGS(false, (pts || n == 0) && name && at);
    if (len == 6 && !strncmp(name, "origin", 6)) {
        *at = QD_SCENE_ORIGIN;
        return true;
    }
    for (size_t i = 0; i < n; i++)
        if (qd_scene_point_is(&pts[i], name, len)) {
            *at = i;
            return true;
        }
    return false;
}

/* "no point 'NAME' (the points drawn: p1; p2; and `origin`, the fixed origin)" */
static qd_status no_point(qd_ctx *ctx, const qd_scene_point *pts, size_t n, const char *opt,
                          const char *name, size_t len) {
    char list[512] = "";
    for (size_t i = 0, at = 0; i < n && at < sizeof list; i++)
        at += (size_t)snprintf(list + at, sizeof list - at, "%s%s", i ? "; " : "", pts[i].name);
    if (ctx)
        qd_ctx_error(ctx, QD_ERR_ARG, "no point '%.*s' (the points drawn: %s; and `origin`, the "
                     "fixed origin)", (int)(len < 200 ? len : 200), name, list);
    return field(ctx, QD_ERR_ARG, opt);
}

static const char *const kinds[] = {"particles", "bodies", "positions"};

static int kind_of(const char *w) {
    for (int k = 0; k < 3; k++)
        if (!strcmp(w, kinds[k]))
            return k;
    return -1;
}

qd_status qd_scene_choose(qd_ctx *ctx, const qd_model *m, const char *const *words, size_t nwords,
                          qd_scene_point **pts, size_t *n) {
    QD_ARGS_CTX(ctx, m && (words || nwords == 0) && pts && n);
    unsigned which = 0;
    bool by_name = false;
    for (size_t i = 0; i < nwords; i++) {
        int k = words[i] ? kind_of(words[i]) : -1;
        if (!words[i])
            return QD_ERR_ARG;
        which |= k >= 0 ? 1u << k : 0;
        by_name |= k < 0;
    }
    /* a name chooses among every point, with the kinds named beside it */
    qd_status st = qd_scene_points(ctx, m, by_name ? 7 : which, pts, n);
    bool *keep = st == QD_OK && by_name ? calloc(*n + 1, sizeof *keep) : NULL;
    if (st == QD_OK && by_name && !keep)
        st = QD_ERR_NOMEM;
    for (size_t i = 0; st == QD_OK && by_name && i < nwords; i++) {
        size_t at;
        if (kind_of(words[i]) >= 0)
            continue;
        if (!qd_scene_find(*pts, *n, words[i], strlen(words[i]), &at) || at == QD_SCENE_ORIGIN)
            st = no_point(ctx, *pts, *n, "draw", words[i], strlen(words[i]));
        else
            keep[at] = true;
    }
    if (st == QD_OK && by_name) {
        size_t k = 0;
        for (size_t i = 0; i < *n; i++)
            if (keep[i] || (which & (1u << (*pts)[i].kind)))
                (*pts)[k++] = (*pts)[i];
        *n = k;
    }
    free(keep);
    if (st == QD_OK && !*n) {
        if (ctx)
            qd_ctx_error(ctx, QD_ERR_ARG, "nothing to draw: the model has no `particle`, `body` "
                         "or named position (x1 = ..., y1 = ... or a vector P1 = (x, y, z)); a "
                         "model given only by T, V or L in its coordinates has no positions");
        st = QD_ERR_ARG;
    }
    if (st != QD_OK) {
        qd_scene_points_free(*pts);
        *pts = NULL;
        *n = 0;
    }
    return st;
}

qd_status qd_scene_named(qd_ctx *ctx, const qd_scene_point *pts, size_t n,
                         const char *const *names, size_t nnames, size_t *at) {
    QD_ARGS_CTX(ctx, (pts || n == 0) && (names || nnames == 0) && (at || nnames == 0));
    for (size_t i = 0; i < nnames; i++) {
        if (!names[i])
            return QD_ERR_ARG;
        if (!qd_scene_find(pts, n, names[i], strlen(names[i]), &at[i]) ||
            at[i] == QD_SCENE_ORIGIN)
            return no_point(ctx, pts, n, "trace", names[i], strlen(names[i]));
    }
    return QD_OK;
}

qd_status qd_scene_pairs(qd_ctx *ctx, const qd_scene_point *pts, size_t n,
                         const char *const *pairs, size_t npairs, size_t *ends) {
    QD_ARGS_CTX(ctx, (pts || n == 0) && (pairs || npairs == 0) && (ends || npairs == 0));
    for (size_t i = 0; i < npairs; i++) {
        const char *v = pairs[i], *comma = v ? strchr(v, ',') : NULL;
        if (!v)
            return QD_ERR_ARG;
        if (!comma) {
            if (ctx)
                qd_ctx_error(ctx, QD_ERR_ARG, "a spring takes two points A,B, not '%s'", v);
            return field(ctx, QD_ERR_ARG, "spring");
        }
        size_t *a = &ends[2 * i], *b = &ends[2 * i + 1];
        if (!qd_scene_find(pts, n, v, (size_t)(comma - v), a))
            return no_point(ctx, pts, n, "spring", v, (size_t)(comma - v));
        if (!qd_scene_find(pts, n, comma + 1, strlen(comma + 1), b))
            return no_point(ctx, pts, n, "spring", comma + 1, strlen(comma + 1));
        if (*a == *b) {
            if (ctx)
                qd_ctx_error(ctx, QD_ERR_ARG, "'%s': a spring needs two different points", v);
            return field(ctx, QD_ERR_ARG, "spring");
        }
    }
    return QD_OK;
}

size_t qd_scene_noutputs(const qd_scene_point *pts, size_t n) {
    QD_ARGS(0, pts || n == 0);
    size_t k = 0;
    for (size_t i = 0; i < n; i++)
        k += pts[i].kind == QD_SCENE_BODY ? 12 : 3;
    return k;
}

/* The model's index of body point p (bodies are named uniquely). */
static size_t body_index(const qd_model *m, const qd_scene_point *p) {
    for (size_t b = 0; b < qd_model_nbodies(m); b++)
        if (!strcmp(qd_model_body_name(m, b), p->name))
            return b;
    return (size_t)-1;
}

qd_status qd_scene_add_outputs(qd_ctx *ctx, qd_sim *s, const qd_model *m,
                               const qd_scene_point *pts, size_t n) {
    QD_ARGS_CTX(ctx, ctx && s && m && (pts || n == 0));
    char name[160];
    qd_status st = QD_OK;
    for (size_t i = 0; st == QD_OK && i < n; i++) {
        for (unsigned k = 0; st == QD_OK && k < 3; k++) {
            snprintf(name, sizeof name, "scene:%s.%c", pts[i].name, "xyz"[k]);
            st = qd_sim_add_output(s, name, pts[i].pos[k]);
        }
        size_t b = pts[i].kind == QD_SCENE_BODY ? body_index(m, &pts[i]) : (size_t)-1;
        for (unsigned k = 0; st == QD_OK && b != (size_t)-1 && k < 9; k++) {
            const qd_expr *r = qd_model_body_rotation(m, b, k / 3, k % 3);
            snprintf(name, sizeof name, "scene:%s.R%u%u", pts[i].name, k / 3, k % 3);
            st = qd_sim_add_output(s, name, r ? r : qd_int(ctx, 0));
        }
        if (st == QD_OK && pts[i].kind == QD_SCENE_BODY && b == (size_t)-1) {
            qd_ctx_error(ctx, QD_ERR_ARG, "'%s' is no body of the model", pts[i].name);
            st = QD_ERR_ARG;
        }
    }
    return st;
}

size_t qd_scene_nframes(double t0, double t_end) {
    double want = ceil((t_end - t0) * QD_SCENE_FPS);
    if (!(want >= 2)) /* NaN too */
        want = 2;
    return (want > QD_SCENE_MAX_FRAMES ? QD_SCENE_MAX_FRAMES : (size_t)want) + 1;
}

/* The row nearest to time t, searched forward from row *k (rows ordered
 * in time).  Each frame is a state the integrator computed, never a blend
 * of two: a blend would cut the corners of the motion (a rod would seem to
 * shorten between steps). */
static const double *nearest(const double *rows, size_t nrows, size_t width, size_t *k,
                             double t) {
    while (*k + 1 < nrows && rows[(*k + 1) * width] <= t)
        (*k)++;
    const double *a = rows + *k * width;
    if (*k + 1 < nrows && a[width] - t < t - a[0])
        return a + width;
    return a;
}

qd_status qd_scene_sample(qd_ctx *ctx, const qd_scene_point *pts, size_t npts,
                          const double *rows, size_t nrows, size_t energy, size_t first,
                          size_t width, double t0, double t_end, qd_scene_frames *out) {
    QD_ARGS_CTX(ctx, (pts || npts == 0) && rows && out);
    *out = (qd_scene_frames){0};
    size_t nout = qd_scene_noutputs(pts, npts);
    if (!nrows || first + nout > width || (energy != QD_SCENE_NONE && energy >= width) ||
        !(t_end >= t0)) {
        if (ctx)
            qd_ctx_error(ctx, QD_ERR_ARG, "no rows to sample, or columns outside the rows");
        return QD_ERR_ARG;
    }
    size_t n = qd_scene_nframes(t0, t_end), nb = (nout - 3 * npts) / 9;
    out->nframes = n;
    out->nbodies = nb;
    out->t = malloc(n * sizeof *out->t);
    out->energy = energy != QD_SCENE_NONE ? malloc(n * sizeof *out->energy) : NULL;
    out->pos = malloc((n * npts * 3 + 1) * sizeof *out->pos);
    out->rot = malloc((n * nb * 9 + 1) * sizeof *out->rot);
    if (!out->t || (energy != QD_SCENE_NONE && !out->energy) || !out->pos || !out->rot) {
        qd_scene_frames_free(out);
        if (ctx)
            qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory for %zu frames", n);
        return QD_ERR_NOMEM;
    }
    if (out->energy && isnan(rows[energy])) {
        free(out->energy);
        out->energy = NULL;
    }
    size_t k = 0;
    for (size_t f = 0; f < n; f++) {
        double t = t0 + (t_end - t0) * (double)f / (double)(n - 1);
        const double *row = nearest(rows, nrows, width, &k, t);
        out->t[f] = row[0];
        if (out->energy) /* the error itself: 7 digits of E would hide it */
            out->energy[f] = row[energy] - rows[energy];
        /* per point x, y, z, then a body's nine rotation entries */
        const double *o = row + first;
        for (size_t i = 0, b = 0; i < npts; i++) {
            memcpy(out->pos + (f * npts + i) * 3, o, 3 * sizeof *o);
            o += 3;
            if (pts[i].kind == QD_SCENE_BODY) {
                memcpy(out->rot + (f * nb + b++) * 9, o, 9 * sizeof *o);
                o += 9;
            }
        }
    }
    return QD_OK;
}

void qd_scene_frames_free(qd_scene_frames *f) {
    if (!f)
        return;
    free(f->t);
    free(f->energy);
    free(f->pos);
    free(f->rot);
    *f = (qd_scene_frames){0};
}
