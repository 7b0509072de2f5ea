/*
 * src/scene/record.c - qd_scene_record: the run a picture is made of, its
 * rows kept in memory and sampled at the frames.
 */
#include "qdot/scene.h"

#include <stdlib.h>
#include <string.h>

#include "base/args.h"

/* Every row of the run, as the sink receives them. */
typedef struct rows {
    size_t width, n, cap;
    double *v;
    int (*progress)(void *data, double t);
    void *data;
    bool nomem;
} rows;

static int keep_row(void *data, int event, const double *row) {
    rows *r = data;
    (void)event; /* an impact's two rows keep the jump sharp */
    if (r->n == r->cap) {
        size_t cap = r->cap ? 2 * r->cap : 1024;
        double *v = cap <= SIZE_MAX / sizeof *v / r->width ? realloc(r->v, cap * r->width * sizeof *v)
                                                          : NULL;
        if (!v) {
            r->nomem = true;
            return 1;
        }
        r->v = v;
        r->cap = cap;
    }
    memcpy(r->v + r->n++ * r->width, row, r->width * sizeof *row);
    /* a stop asked for (^C) ends the run after a whole row, as a stop event */
    return r->progress && r->progress(r->data, row[0]) ? 1 : 0;
}

/* The column called name among the run's, or QD_SCENE_NONE. */
static size_t column(const qd_sim *s, qd_sim_method method, const char *name) {
    size_t n = qd_sim_columns(s, method, NULL, 0);
    const char **names = malloc((n + 1) * sizeof *names);
    size_t at = QD_SCENE_NONE;
    if (names) {
        qd_sim_columns(s, method, names, n);
        for (size_t i = 0; i < n && at == QD_SCENE_NONE; i++)
            if (!strcmp(names[i], name))
                at = i;
    }
    free(names);
    return at;
}

qd_status qd_scene_record(qd_ctx *ctx, qd_sim *s, const qd_sim_opts *opts,
                          const qd_scene_point *pts, size_t npts,
                          int (*progress)(void *data, double t), void *data,
                          qd_scene_frames *fr, qd_sim_stats *stats) {
    QD_ARGS_CTX(ctx, ctx && s && opts && (pts || !npts) && fr);
    *fr = (qd_scene_frames){0};
    qd_sim_opts o = *opts;
    /* an adaptive method writes its rows at the frames (dense output); its
     * dt would only be another output grid; a fixed step's rows are its
     * steps (the frames pick among them), whatever output spacing */
    o.every = 0;
    if (qd_sim_method_adaptive(o.method))
        o.dt = (o.t_end - o.t0) / (double)(qd_scene_nframes(o.t0, o.t_end) - 1);
    size_t width = qd_sim_columns(s, o.method, NULL, 0);
    rows r = {.width = width ? width : 1, .progress = progress, .data = data};
    qd_sim_stats st;
    qd_status rs = qd_sim_run(s, &o, keep_row, &r, &st, NULL);
    if (stats)
        *stats = st;
    if (r.nomem) {
        qd_ctx_clear_error(ctx); /* the sink's stop: the reason is memory */
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory keeping the run's %zu rows", r.n);
        rs = QD_ERR_NOMEM;
    } else if (rs == QD_OK && r.n == 0) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "the run gave no rows to draw");
        rs = QD_ERR_NUMERIC;
    }
    if (rs == QD_OK) {
        double t_end = r.v[(r.n - 1) * width]; /* a stop or a contact ends the run early */
        rs = qd_scene_sample(ctx, pts, npts, r.v, r.n, column(s, o.method, "energy"),
                             width - qd_scene_noutputs(pts, npts), width, o.t0, t_end, fr);
    }
    free(r.v);
    return rs;
}
