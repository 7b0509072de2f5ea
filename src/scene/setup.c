/*
 * src/scene/setup.c - a picture set up as `qdot animate` takes it
 * (qd_scene_setup_new, qd_scene_setup_record): the points the words
 * choose, their masses and looks (shapes), the traces and springs they name, their places as
 * outputs of the run; then the run sampled at the frames, the links, the
 * drawing plane and, for a constrained model, the walls its points slide on.  The set-up owns every array its qd_scene points to.
 */
#include "qdot/scene.h"

#include <math.h>
#include <stdlib.h>

#include "base/args.h"
#include "base/mem.h"
#include "qdot/simsetup.h"

struct qd_scene_setup {
    qd_ctx *ctx;
    qd_sim_setup *set;
    qd_scene view;
    qd_scene_point *pts;
    double *mass;
    qd_scene_look *looks;
    size_t *traces, *springs, nsprings;
    qd_scene_frames fr;
    qd_scene_link *links;
    qd_scene_wall *walls;
    bool constrained; /* the model has a constraint: its points' walls are drawn */
};

void qd_scene_setup_free(qd_scene_setup *sc) {
    if (!sc)
        return;
    qd_scene_points_free(sc->pts);
    qd_scene_frames_free(&sc->fr);
    free(sc->links);
    free(sc->walls);
    qd__free(sc->mass);
    qd__free(sc->looks);
    qd__free(sc->traces);
    qd__free(sc->springs);
    qd__free(sc);
}

/* The points and what they are drawn with, their places added to the run. */
static qd_status points(qd_scene_setup *sc, const qd_model *m, const qd_scene_spec *sp) {
    size_t n = 0;
    qd_status st = qd_scene_choose(sc->ctx, m, sp->draws, sp->ndraws, &sc->pts, &n);
    if (st != QD_OK)
        return st;
    sc->mass = qd__malloc(sc->ctx, (n + 1) * sizeof *sc->mass);
    sc->looks = qd__malloc(sc->ctx, (n + 1) * sizeof *sc->looks);
    sc->traces = qd__malloc(sc->ctx, (sp->ntraces + 1) * sizeof *sc->traces);
    sc->springs = qd__malloc(sc->ctx, (2 * sp->nsprings + 1) * sizeof *sc->springs);
    if (!sc->mass || !sc->looks || !sc->traces || !sc->springs)
        return QD_ERR_NOMEM;
    const qd_expr *const *syms;
    const double *vals;
    size_t ns = qd_sim_setup_state(sc->set, &syms, &vals);
    if ((st = qd_scene_masses(sc->ctx, sc->pts, n, ns, syms, vals, sc->mass)) != QD_OK ||
        (st = qd_scene_looks(sc->ctx, sc->pts, n, ns, syms, vals, sc->looks)) != QD_OK ||
        (st = qd_scene_named(sc->ctx, sc->pts, n, sp->traces, sp->ntraces, sc->traces)) != QD_OK ||
        (st = qd_scene_pairs(sc->ctx, sc->pts, n, sp->springs, sp->nsprings, sc->springs)) !=
            QD_OK)
        return st;
    sc->nsprings = sp->nsprings;
    sc->view = (qd_scene){.model = sp->title, .pts = sc->pts, .npts = n, .mass = sc->mass,
                          .looks = sc->looks, .traces = sc->traces, .ntraces = sp->ntraces};
    return qd_scene_add_outputs(sc->ctx, qd_sim_setup_sim(sc->set), m, sc->pts, n);
}

qd_scene_setup *qd_scene_setup_new(qd_ctx *ctx, struct qd_sim_setup *set, const qd_model *m,
                                   const qd_scene_spec *sp) {
    QD_ARGS(NULL, ctx && set && m && sp);
    qd_scene_setup *sc = qd__calloc(ctx, 1, sizeof *sc);
    if (!sc)
        return NULL;
    sc->ctx = ctx;
    sc->set = set;
    sc->constrained = qd_model_nconstraints(m) > 0;
    if (points(sc, m, sp) != QD_OK) {
        qd_scene_setup_free(sc);
        return NULL;
    }
    return sc;
}

/* A drawing plane holds the bodies' shapes too: each shaped body turns
 * about the flat axis only (the flat row of its rotation is the same in
 * every frame); else the picture is 3-D (a box tumbling about its centre). */
static bool shapes_in_plane(const qd_scene_setup *sc, int flat) {
    const qd_scene_frames *fr = &sc->fr;
    for (size_t i = 0, b = 0; i < sc->view.npts; i++) {
        if (sc->pts[i].kind != QD_SCENE_BODY)
            continue;
        bool shaped = sc->looks[i].shape != QD_SHAPE_NONE;
        for (size_t f = 1; shaped && f < fr->nframes; f++)
            for (int c = 0; c < 3; c++) {
                const double *r0 = fr->rot + 9 * b, *r = fr->rot + 9 * (f * fr->nbodies + b);
                if (fabs(r[3 * flat + c] - r0[3 * flat + c]) > 1e-9)
                    return false;
            }
        b++;
    }
    return true;
}

qd_status qd_scene_setup_record(qd_scene_setup *sc, const qd_sim_opts *opts,
                                int (*progress)(void *data, double t), void *data,
                                qd_sim_stats *stats) {
    QD_ARGS(QD_ERR_ARG, sc && opts && !sc->view.fr);
    qd_sim_stats st;
    qd_sim *s = qd_sim_setup_sim(sc->set);
    qd_status rs = qd_scene_record(sc->ctx, s, opts, sc->pts, sc->view.npts, progress, data,
                                   &sc->fr, &st);
    if (stats)
        *stats = st;
    if (rs != QD_OK)
        return rs;
    rs = qd_scene_links(NULL, sc->fr.pos, sc->fr.nframes, sc->view.npts, sc->springs,
                        sc->nsprings, &sc->links, &sc->view.nlinks, sc->view.plane);
    if (rs != QD_OK) {
        qd_ctx_error(sc->ctx, rs, "the scene's positions could not be analysed (%s)",
                     qd_status_str(rs));
        return rs;
    }
    int *pl = sc->view.plane;
    if (pl[0] >= 0 && !shapes_in_plane(sc, 3 - pl[0] - pl[1]))
        pl[0] = pl[1] = -1;
    if (sc->constrained)
        rs = qd_scene_walls(sc->ctx, sc->pts, sc->looks, &sc->fr, sc->view.npts, sc->view.plane,
                            &sc->walls, &sc->view.nwalls);
    if (rs != QD_OK)
        return rs;
    sc->view.walls = sc->walls;
    sc->view.links = sc->links;
    sc->view.fr = &sc->fr;
    sc->view.energy_error_max = st.energy_error_max;
    sc->view.conservative = qd_sim_conservative(s);
    sc->view.method = qd_sim_method_name(opts->method);
    return QD_OK;
}

const qd_scene *qd_scene_setup_scene(const qd_scene_setup *sc) {
    QD_ARGS(NULL, sc);
    return &sc->view;
}
