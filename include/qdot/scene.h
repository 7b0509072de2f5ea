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
#include "print.h"
#include "sim.h"
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
    /* a body's: its inertia (row-major, body axes) and `shape` statement
     * (qd_model_body_shape); else NULL and QD_SHAPE_NONE */
    const qd_expr *inertia[9];
    qd_body_shape shape;
    const qd_expr *size[3];
    int axis;
    const qd_expr *ground[6]; /* qd_model_body_ground's n, r0, or NULL */
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

/* ---- choosing the points (qdot animate --draw, --trace, --spring) ------- */

/* The points to draw, chosen by words: "particles", "bodies" and
 * "positions" take every point of that kind, any other word the one point
 * it names (qd_scene_find); no words: qd_scene_points' default (which 0).
 * In qd_scene_points' order; *pts as qd_scene_points gives it.  QD_ERR_ARG
 * for a word that names no point (the option field "draw", the points
 * listed in the message) and for nothing to draw (the model has no point
 * of the kinds asked for). */
QD_API qd_status qd_scene_choose(qd_ctx *ctx, const qd_model *m, const char *const *words,
                                 size_t nwords, qd_scene_point **pts, size_t *n);

/* The point among pts[0, n) named name[0, len) (qd_scene_point_is), or
 * QD_SCENE_ORIGIN for "origin", into *at; false when none is. */
QD_API bool qd_scene_find(const qd_scene_point *pts, size_t n, const char *name, size_t len,
                          size_t *at);

/* Each of names (the paths to trace: not the origin) as its index in
 * pts, into at[0, nnames).  QD_ERR_ARG for a name that is no point, the
 * option field "trace". */
QD_API qd_status qd_scene_named(qd_ctx *ctx, const qd_scene_point *pts, size_t n,
                                const char *const *names, size_t nnames, size_t *at);

/* Each of pairs "A,B" (springs: two different points, the origin one of
 * them if need be) as ends[2k], ends[2k + 1].  QD_ERR_ARG for no comma, a
 * name that is no point, or one point twice, the option field "spring". */
QD_API qd_status qd_scene_pairs(qd_ctx *ctx, const qd_scene_point *pts, size_t n,
                                const char *const *pairs, size_t npairs, size_t *ends);

/* ---- the points along a run --------------------------------------------- */

/* The outputs qd_scene_add_outputs adds: per point its x, y, z, and after a
 * body's its rotation (body to space, row-major: nine numbers). */
QD_API size_t qd_scene_noutputs(const qd_scene_point *pts, size_t n);

/* Add those outputs to s (before qd_sim_compile; ctx the one s was made
 * with; m the model of s and of pts), named "scene:NAME.x", ...,
 * "scene:NAME.R00", ..., so that the run evaluates them at every row. */
QD_API qd_status qd_scene_add_outputs(qd_ctx *ctx, qd_sim *s, const qd_model *m,
                                      const qd_scene_point *pts, size_t n);

/* Frames per simulated second, and at most this many intervals: a minute
 * of frames (a longer run gets coarser ones). */
#define QD_SCENE_FPS 60
#define QD_SCENE_MAX_FRAMES 3600
#define QD_SCENE_NONE ((size_t)-1)

/* The frames of a picture of [t0, t_end]: 60 a second, at least 3, at most
 * QD_SCENE_MAX_FRAMES + 1, the ends included. */
QD_API size_t qd_scene_nframes(double t0, double t_end);

typedef struct qd_scene_frames {
    size_t nframes, nbodies;
    double *t;      /* per frame: the time of the row shown */
    double *energy; /* per frame: E - E(t0), or NULL (no energy column, or NaN) */
    double *pos;    /* [frame][point][3] */
    double *rot;    /* [frame][body][9], in the bodies' order among the points */
} qd_scene_frames;

/* The frames of a run's rows (nrows rows of width numbers, in time order,
 * row[0] the time): qd_scene_nframes(t0, t_end) frames at equal times from
 * t0 to t_end, each the row nearest to its time (a state the integrator
 * computed, never a blend of two, which would cut the corners of the
 * motion).  A row's points' outputs (qd_scene_add_outputs' order) start at
 * column first; energy is its energy column, or QD_SCENE_NONE.  *out is
 * malloc'd: qd_scene_frames_free. */
QD_API qd_status qd_scene_sample(qd_ctx *ctx, const qd_scene_point *pts, size_t npts,
                                 const double *rows, size_t nrows, size_t energy, size_t first,
                                 size_t width, double t0, double t_end, qd_scene_frames *out);
QD_API void qd_scene_frames_free(qd_scene_frames *f);

/* A run of s (compiled, with qd_scene_add_outputs of pts; ctx the one s
 * was made with) from opts, its rows kept and sampled at the frames
 * (qd_scene_sample), into *fr; stats (may be NULL) the run's.  An
 * adaptive method writes its rows at the frames' spacing (dense output:
 * opts->dt is replaced in a copy); a fixed-step method keeps its step and
 * the frames take the nearest rows.  A run that stops early (a stop event,
 * a contact) gives the frames of [t0, the last row].  progress (may be
 * NULL) is called with each row's time; a nonzero return ends the run
 * after that row, as a stop event does (a Ctrl-C: the frames of [t0, t],
 * QD_OK; the caller knows it asked).  The run's failures are qd_sim_run's
 * (reason in ctx); QD_ERR_NOMEM when the rows do not fit. */
QD_API qd_status qd_scene_record(qd_ctx *ctx, qd_sim *s, const qd_sim_opts *opts,
                                 const qd_scene_point *pts, size_t npts,
                                 int (*progress)(void *data, double t), void *data,
                                 qd_scene_frames *fr, qd_sim_stats *stats);


/* ---- the scene of a picture: masses, links, its data as JSON ------------ */

/* Each point's mass, evaluated at the values vals of the nsyms symbols syms
 * (the model's parameters: qd_eval), into mass[0, n); a named position has
 * none and weighs 1 (every one drawn alike).  Errors: qd_eval's. */
QD_API qd_status qd_scene_masses(qd_ctx *ctx, const qd_scene_point *pts, size_t n, size_t nsyms,
                                 const qd_expr *const *syms, const double *vals, double *mass);

/* What a body is drawn as: its `shape` statement, else a slender rod when
 * its inertia is one (diagonal, one moment 0 and the other two equal I:
 * a rod of length sqrt(12 I / M) along the axis of the 0), else nothing
 * (a dot with its body axes: a disk's moments are a ring's of another
 * radius, a ball's a shell's or a cube's, so they are not guessed). */
typedef struct qd_scene_look {
    qd_body_shape shape;   /* QD_SHAPE_NONE for a particle, a position, an unknown shape */
    double size[3];        /* as qd_model_body_shape's sizes, evaluated; 0 when unused */
    int axis;              /* the rod's axis or the disk's or ring's normal (body 0, 1, 2) */
    bool inferred;         /* from the inertia, not from a shape statement */
    bool has_ground;       /* the body rolls on a fixed plane: */
    double ground[6];      /* its normal n and a point r0 */
} qd_scene_look;

/* Each point's look (above) and the ground its `rolls` names, its sizes,
 * inertia and ground evaluated at the values
 * vals of the nsyms symbols syms (the parameters), into out[0, n).
 * Errors: qd_eval's; QD_ERR_ARG for a shape's size that is not a positive
 * number (the body named in the message). */
QD_API qd_status qd_scene_looks(qd_ctx *ctx, const qd_scene_point *pts, size_t n, size_t nsyms,
                                const qd_expr *const *syms, const double *vals,
                                qd_scene_look *out);

/* A plane x_axis = at that a point of a constrained model slides on (a
 * floor, a wall): side +1 or -1 the side of x_axis the points' bodies are
 * on (the solid lies on the other), 0 when both or none. */
typedef struct qd_scene_wall {
    int axis;
    double at;
    int side;
} qd_scene_wall;

/* The walls of a sampled motion (fr: qd_scene_sample's frames of pts, npts
 * points; looks per point, or NULL): every plane x_k = c that a point keeps
 * while it moves (to 1e-6 of the scene's size, as a rod its length: the
 * frames are dense output between the projected steps; moving: 1e-3 of
 * it), the points being each particle and named position and both ends of
 * a body drawn as a rod (not a body's centre, which is off what it slides
 * on); not the drawing plane (plane as qd_scene_links gives it).
 * *walls malloc'd (free(); never NULL on success).  The caller decides
 * whether the model constrains them (qd_scene_setup: a model with a
 * constraint).  QD_ERR_NOMEM. */
QD_API qd_status qd_scene_walls(qd_ctx *ctx, const qd_scene_point *pts,
                                const qd_scene_look *looks, const qd_scene_frames *fr,
                                size_t npts, const int plane[2], qd_scene_wall **walls,
                                size_t *nwalls);

typedef struct qd_scene_link {
    size_t a, b;           /* point indices, or QD_SCENE_ORIGIN */
    bool spring;           /* a zigzag the caller asked for; else a rigid rod */
} qd_scene_link;

/* The links of a sampled motion (pos as qd_scene_analyse takes it): first
 * the nsprings springs springs[2k], springs[2k + 1] (qd_scene_pairs), then
 * the rods qd_scene_analyse finds among the other pairs; *links is
 * malloc'd (free() it; never NULL on success), *nlinks its count, and
 * plane[0], plane[1] the drawing plane's axes (-1 -1: 3-D).  Errors:
 * qd_scene_analyse's (a position not finite, no frames), QD_ERR_NOMEM. */
QD_API qd_status qd_scene_links(qd_ctx *ctx, const double *pos, size_t nframes, size_t npts,
                                const size_t *springs, size_t nsprings, qd_scene_link **links,
                                size_t *nlinks, int plane[2]);

/* A picture's data: what qd_scene_json writes.  The arrays are the
 * caller's; mass per point (qd_scene_masses), traces the points whose
 * paths are drawn (qd_scene_named). */
typedef struct qd_scene {
    const char *model;            /* a title (the model's file) */
    const char *method;           /* the integrator's name (qd_sim_method_name) */
    const qd_scene_point *pts;
    size_t npts;
    const double *mass;
    const qd_scene_look *looks;   /* per point (qd_scene_looks), or NULL: none */
    const qd_scene_frames *fr;    /* the points at the frames (qd_scene_sample) */
    const qd_scene_link *links;
    size_t nlinks;
    const size_t *traces;
    size_t ntraces;
    int plane[2];                 /* qd_scene_links' plane */
    const qd_scene_wall *walls;   /* qd_scene_walls' (may be NULL with nwalls 0) */
    size_t nwalls;
    double energy_error_max;      /* the run's measure (qd_sim_stats) */
    bool conservative;            /* qd_sim_conservative */
} qd_scene;

/* The scene as one JSON object appended to out, the data of `qdot
 * animate`'s page: {"model", "method", "plane": [a, b], "conservative",
 * "energy_error_max", "points": [{"name", "body", "mass"[, "shape": "rod",
 * "disk", "ring", "sphere" or "box", "size": [3], "axis", "inferred"][,
 * "ground": [nx, ny, nz, x0, y0, z0]]}...], "links":
 * [[a, b, spring]...] (an end -1 is the origin, spring 0 or 1), "traces":
 * [i...], "walls": [[axis, at, side]...], "t": [per frame], "energy_error":
 * [per frame] (only with the frames' energy), "pos": [frame][point][x, y, z] flat, "rot":
 * [frame][body][9] flat}.  Numbers to 7 significant digits (a picture
 * needs no more), null for one not finite; strings escape '"', '\', '<'
 * and control characters as \u00XX, so that the text may sit inside an
 * HTML <script>.  QD_ERR_NOMEM when out ran out of memory; model and
 * method NULL are written as "". */
QD_API qd_status qd_scene_json(const qd_scene *s, qd_buf *out);

/* The whole self-contained HTML page that plays the scene (no network:
 * the player is inline), appended to out: the template src/scene/page.html,
 * embedded at build time, with qd_scene_json in place of its data marker.
 * docs/cli.md, "qdot animate", states the drawing rules.  QD_ERR_NOMEM
 * when out ran out of memory. */
QD_API qd_status qd_scene_html(const qd_scene *s, qd_buf *out);

/* ---- a picture set up as qdot animate takes it (src/scene/setup.c) ------ */

typedef struct qd_scene_setup qd_scene_setup;

/* What to draw, as words (qdot animate's --draw, --trace, --spring). */
typedef struct qd_scene_spec {
    const char *const *draws;   /* qd_scene_choose's words (none: its default) */
    size_t ndraws;
    const char *const *traces;  /* qd_scene_named's names */
    size_t ntraces;
    const char *const *springs; /* qd_scene_pairs' "A,B" */
    size_t nsprings;
    const char *title;          /* qd_scene.model (may be NULL) */
} qd_scene_spec;

/* The points sp chooses among the model m of set (qd_scene_choose), their
 * masses at set's initial parameter values, the traces and springs it names,
 * and the points' places added to set's run as outputs (before it compiles:
 * qd_scene_add_outputs).  set, m and sp's texts must outlive the set-up;
 * ctx is set's.  NULL on failure, the reason in ctx (the errors of the
 * calls named: a word naming no point has the option field "draw",
 * "trace" or "spring" in qd_diag.name; nothing to draw has none). */
struct qd_sim_setup;
QD_API qd_scene_setup *qd_scene_setup_new(qd_ctx *ctx, struct qd_sim_setup *set,
                                          const qd_model *m, const qd_scene_spec *sp);
/* set's run from opts sampled at the frames (qd_scene_record), then its
 * links and drawing plane (qd_scene_links; 3-D instead when a body drawn
 * as a shape turns about another axis than the plane's normal), for a
 * model with a constraint its walls (qd_scene_walls), the scene completed:
 * method, energy error, conservative.  progress as qd_scene_record's: a
 * nonzero return ends the run there and the scene is that of [t0, t].
 * stats (may be NULL) gets the run's.  Once (a second call is
 * QD_ERR_ARG); the errors of qd_scene_record, or of the links (reason in
 * ctx). */
QD_API qd_status qd_scene_setup_record(qd_scene_setup *sc, const qd_sim_opts *opts,
                                       int (*progress)(void *data, double t), void *data,
                                       qd_sim_stats *stats);
/* The scene, owned by sc (its frames, links and plane once recorded). */
QD_API const qd_scene *qd_scene_setup_scene(const qd_scene_setup *sc);
QD_API void qd_scene_setup_free(qd_scene_setup *sc);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_scene_points (ctx); qd_scene_analyse
 * (ctx, skip); qd_scene_choose, qd_scene_named, qd_scene_pairs and
 * qd_scene_sample (ctx); qd_scene_masses and qd_scene_links (ctx, and
 * syms, vals or springs with a count of 0); qd_scene_json's arrays with a
 * count of 0, its model, method, looks and walls; qd_scene_walls (ctx, looks); qd_scene_looks (ctx, and syms,
 * vals with a count of 0); qd_scene_setup_record (progress, data,
 * stats). An array whose count is 0 may be NULL. */
#endif
