/*
 * cli/cmd_animate.c - `qdot animate FILE [simulate options] -o FILE.html`:
 * simulate the model (the setup of sim_cli.c), sample the positions of its
 * particles and bodies at the frames (outputs of the run: the model's own
 * position and rotation expressions, evaluated by libqdot), and write one
 * self-contained HTML page that plays the motion (animate_page.c).
 */
#include "cli.h"

#include <math.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "animate.h"
#include "progress.h"
#include "out.h"
#include "sim_cli.h"

static const char usage_text[] =
    "usage: qdot animate FILE -o FILE.html [--draw WHAT]... [--trace NAME]... "
    "[--spring A,B]... [every option of qdot simulate that shapes the motion: --t-end T, "
    "--dt H, --rtol TOL, --atol TOL, --method M, --initial \"q=VALUE, q'=VALUE\", "
    "--set NAME=VALUE, --input \"F = EXPR\" | F=FILE.csv | \"F = lqr\", --about POINT, "
    "--lqr WEIGHTS, --stop-at COND, --event COND, --max-steps N, --no-project, --no-speeds, "
    "--native, --precision P]\n"
    "What is drawn: every particle (p1, p2, ...) and body (by its name); a model with "
    "neither draws its named positions (x1 = ..., y1 = ... [, z1 = ...], named x1,y1, "
    "or a vector P1 = (x, y, z)).  --draw particles|bodies|positions takes those kinds, "
    "--draw NAME one point (p2, a body, x1,y1 or x1); repeat it.  Rods join points at a "
    "constant distance; --spring A,B draws a zigzag.";

#define FPS 60            /* frames per simulated second ... */
#define MAX_FRAMES 3600   /* ... up to a minute of them: longer runs are coarser */
#define DEFAULT_T_END "10"

typedef struct an_args {
    cli_sim_args a;
    const char *html;
    const char *traces[QD_SIM_MAX_LIST], *springs[QD_SIM_MAX_LIST], *draws[QD_SIM_MAX_LIST];
    size_t ntraces, nsprings, ndraws;
} an_args;

static int push(const char **list, size_t *n, const char *v, const char *opt) {
    if (*n == QD_SIM_MAX_LIST) {
        cli_diag_error("at most %d %s options", QD_SIM_MAX_LIST, opt);
        return QD_EXIT_USAGE;
    }
    list[(*n)++] = v;
    return QD_EXIT_OK;
}

static int parse_option(int argc, char **argv, int *i, void *data) {
    an_args *p = data;
    int rc;
    if (cli_sim_took_option(argc, argv, i, &p->a, &rc))
        return rc;
    const char *v;
    if ((v = cli_value(argc, argv, i, "--html")))
        p->html = v;
    else if ((v = cli_value(argc, argv, i, "--trace")))
        return push(p->traces, &p->ntraces, v, "--trace");
    else if ((v = cli_value(argc, argv, i, "--spring")))
        return push(p->springs, &p->nsprings, v, "--spring");
    else if ((v = cli_value(argc, argv, i, "--draw")))
        return push(p->draws, &p->ndraws, v, "--draw");
    else if (!strcmp(argv[*i], "--format") || !strcmp(argv[*i], "--variational") ||
             !strcmp(argv[*i], "--period") || !strncmp(argv[*i], "--plot", 6)) {
        /* simulate's, and they shape its rows, not the motion */
        cli_diag_error("%s is simulate's: it shapes the rows it writes; animate writes its "
                       "page with -o FILE.html", argv[*i]);
        return QD_EXIT_USAGE;
    } else {
        cli_diag_error("unknown option or missing value: '%s'\n%s", argv[*i], usage_text);
        return QD_EXIT_USAGE;
    }
    return QD_EXIT_OK;
}

/* ---- the points and their outputs ------------------------------------------ */

static int mass_of(cli_sim *c, const qd_expr *m, double *out) {
    if (!m) {
        *out = 1; /* a named position: every one drawn alike */
        return QD_EXIT_OK;
    }
    if (qd_eval(c->ctx, m, c->st.n, c->st.syms, c->st.vals, out) != QD_OK)
        return cli_diag_ctx(c->ctx);
    return QD_EXIT_OK;
}

/* Each point's position (and a body's rotation) as outputs of the run, so
 * the library evaluates them at every row. */
static int add_point_outputs(cli_sim *c, an_scene *s) {
    const qd_model *m = c->mf.model;
    char name[160];
    for (size_t i = 0, b = 0; i < s->npts; i++) {
        const qd_scene_point *sp = &s->spts[i];
        an_point *pt = &s->pts[i];
        pt->body = sp->kind == QD_SCENE_BODY;
        snprintf(pt->name, sizeof pt->name, "%s", sp->name);
        int rc = mass_of(c, sp->mass, &pt->mass);
        for (unsigned k = 0; rc == QD_EXIT_OK && k < 3; k++) {
            snprintf(name, sizeof name, "animate:%s.%c", pt->name, "xyz"[k]);
            if (qd_sim_add_output(c->s, name, sp->pos[k]) != QD_OK)
                return cli_diag_ctx(c->ctx);
        }
        for (unsigned k = 0; rc == QD_EXIT_OK && pt->body && k < 9; k++) {
            const qd_expr *r = qd_model_body_rotation(m, b, k / 3, k % 3);
            snprintf(name, sizeof name, "animate:%s.R%u%u", pt->name, k / 3, k % 3);
            if (qd_sim_add_output(c->s, name, r ? r : qd_int(c->ctx, 0)) != QD_OK)
                return cli_diag_ctx(c->ctx);
        }
        b += pt->body;
        if (rc != QD_EXIT_OK)
            return rc;
    }
    return QD_EXIT_OK;
}

/* ---- the run: rows kept, then resampled at the frames ---------------------- */

typedef struct an_rows {
    size_t first;        /* column of the first point output */
    size_t energy;       /* the energy column, or SIZE_MAX */
    size_t width;        /* numbers kept per row: t, energy, the outputs */
    size_t n, cap;
    double *v;
    double t0, t_end;
    cli_progress bar;
    bool nomem;
} an_rows;

static int keep_row(void *data, int event, const double *row) {
    an_rows *r = data;
    (void)event; /* an impact's two rows keep the jump sharp */
    if (r->n == r->cap) {
        size_t cap = r->cap ? 2 * r->cap : 1024;
        double *v = realloc(r->v, cap * r->width * sizeof *v);
        if (!v) {
            r->nomem = true;
            return 1;
        }
        r->v = v;
        r->cap = cap;
    }
    double *out = r->v + r->n++ * r->width;
    out[0] = row[0];
    out[1] = r->energy == (size_t)-1 ? NAN : row[r->energy];
    memcpy(out + 2, row + r->first, (r->width - 2) * sizeof *out);
    cli_progress_update(&r->bar, (row[0] - r->t0) / (r->t_end - r->t0), row[0]);
    return 0;
}

/* The row nearest to time t, searched forward from row *k.  Each frame is a
 * state the integrator computed, never a blend of two: a blend would cut the
 * corners of the motion (a rod would seem to shorten between steps).  On the
 * output grid of an adaptive method the rows are the frames themselves. */
static const double *nearest(const an_rows *r, size_t *k, double t) {
    while (*k + 1 < r->n && r->v[(*k + 1) * r->width] <= t)
        (*k)++;
    const double *a = r->v + *k * r->width;
    if (*k + 1 < r->n && a[r->width] - t < t - a[0])
        return a + r->width;
    return a;
}

static int frames(const an_rows *r, an_scene *s) {
    size_t n = s->nframes, np = s->npts, nb = s->nbodies;
    s->t = malloc(n * sizeof *s->t);
    s->energy = malloc(n * sizeof *s->energy);
    s->pos = malloc(n * np * 3 * sizeof *s->pos);
    s->rot = malloc((n * nb * 9 + 1) * sizeof *s->rot);
    if (!s->t || !s->energy || !s->pos || !s->rot)
        return QD_EXIT_FAIL;
    size_t k = 0;
    for (size_t f = 0; f < n; f++) {
        const double *row = nearest(r, &k, r->t0 + (r->t_end - r->t0) * (double)f / (double)(n - 1));
        s->t[f] = row[0];
        s->energy[f] = row[1];
        /* outputs: per point x, y, z, then a body's nine rotation entries */
        const double *o = row + 2;
        for (size_t i = 0, b = 0; i < np; i++) {
            memcpy(s->pos + (f * np + i) * 3, o, 3 * sizeof *o);
            o += 3;
            if (s->pts[i].body) {
                memcpy(s->rot + (f * nb + b++) * 9, o, 9 * sizeof *o);
                o += 9;
            }
        }
    }
    if (isnan(s->energy[0])) {
        free(s->energy);
        s->energy = NULL;
    }
    /* the error itself: 7 digits of E would hide it */
    for (size_t f = n; s->energy && f-- > 0;)
        s->energy[f] -= s->energy[0];
    return QD_EXIT_OK;
}

static size_t column(const cli_sim *c, const char *name) {
    size_t n = qd_sim_columns(c->s, c->opts.method, NULL, 0);
    const char **names = malloc((n + 1) * sizeof *names);
    size_t at = (size_t)-1;
    if (names) {
        qd_sim_columns(c->s, c->opts.method, names, n);
        for (size_t i = 0; i < n && at == (size_t)-1; i++)
            if (!strcmp(names[i], name))
                at = i;
    }
    free(names);
    return at;
}

static int run(cli_sim *c, an_scene *s) {
    size_t nout = 3 * s->npts + 9 * s->nbodies;
    an_rows r = {.energy = column(c, "energy"), .width = 2 + nout, .t0 = c->opts.t0,
                 .t_end = c->opts.t_end};
    r.first = qd_sim_columns(c->s, c->opts.method, NULL, 0) - nout;
    double span = c->opts.t_end - c->opts.t0;
    double want = ceil(span * FPS);
    s->nframes = (want > MAX_FRAMES ? MAX_FRAMES : want < 2 ? 2 : (size_t)want) + 1;
    /* an adaptive method writes its rows at the frames (dense output); its
     * --dt would only be another output grid */
    if (qd_sim_method_adaptive(c->opts.method))
        c->opts.dt = span / (double)(s->nframes - 1);
    qd_sim_stats st;
    cli_progress_start(&r.bar, "animate");
    qd_status rs = qd_sim_run(c->s, &c->opts, keep_row, &r, &st, NULL);
    double wall = cli_progress_end(&r.bar);
    int rc = r.nomem ? QD_EXIT_FAIL : rs != QD_OK ? cli_sim_fail(c, rs) : QD_EXIT_OK;
    if (rc == QD_EXIT_OK && r.n == 0)
        rc = QD_EXIT_FAIL;
    if (rc == QD_EXIT_OK) {
        r.t_end = r.v[(r.n - 1) * r.width]; /* a stop or a contact ends the run early */
        rc = frames(&r, s);
        if (rc != QD_EXIT_OK)
            r.nomem = true;
        s->energy_error_max = st.energy_error_max;
        s->conservative = qd_sim_conservative(c->s);
        s->method = qd_sim_method_name(c->opts.method);
        fprintf(stderr, "qdot: animate: %s, t = %g..%g: %zu frames from %zu steps, %.3g s; "
                        "energy error %.3g\n", s->method, c->opts.t0, r.t_end, s->nframes,
                st.steps, wall, st.energy_error_max);
    }
    if (r.nomem)
        cli_diag_error("out of memory keeping the run's %zu rows", r.n);
    free(r.v);
    return rc;
}

/* ---- names on the command line ----------------------------------------------- */

/* A point by name (p1, p2, ..., a body's name, a named position or one of
 * its components: x1,y1 or x1 or y1), or "origin". */
static bool find_point(const an_scene *s, const char *name, size_t len, size_t *at) {
    if (len == 6 && !strncmp(name, "origin", 6)) {
        *at = AN_ORIGIN;
        return true;
    }
    for (size_t i = 0; i < s->npts; i++)
        if (qd_scene_point_is(&s->spts[i], name, len)) {
            *at = i;
            return true;
        }
    return false;
}

static int unknown_point(const an_scene *s, const char *opt, const char *name, size_t len) {
    char list[512] = "";
    for (size_t i = 0, at = 0; i < s->npts && at < sizeof list; i++)
        at += (size_t)snprintf(list + at, sizeof list - at, "%s%s", i ? "; " : "", s->spts[i].name);
    cli_diag_error("%s: no point '%.*s' (the points drawn: %s; and `origin`, the fixed origin; "
                   "--draw chooses them)", opt, (int)len, name, list);
    return QD_EXIT_USAGE;
}

static int name_traces(an_scene *s, const an_args *p) {
    s->traces = malloc((p->ntraces + 1) * sizeof *s->traces);
    if (!s->traces)
        return QD_EXIT_FAIL;
    for (size_t i = 0; i < p->ntraces; i++) {
        size_t at;
        if (!find_point(s, p->traces[i], strlen(p->traces[i]), &at) || at == AN_ORIGIN)
            return unknown_point(s, "--trace", p->traces[i], strlen(p->traces[i]));
        s->traces[s->ntraces++] = at;
    }
    return QD_EXIT_OK;
}

/* --spring A,B: drawn as a zigzag.  The model language has no spring
 * statement (a spring is a term of V), so the user names its ends. */
static int name_springs(an_scene *s, const an_args *p) {
    for (size_t i = 0; i < p->nsprings; i++) {
        const char *v = p->springs[i], *comma = strchr(v, ',');
        size_t a, b;
        if (!comma) {
            cli_diag_error("--spring takes two points A,B, not '%s'", v);
            return QD_EXIT_USAGE;
        }
        if (!find_point(s, v, (size_t)(comma - v), &a))
            return unknown_point(s, "--spring", v, (size_t)(comma - v));
        if (!find_point(s, comma + 1, strlen(comma + 1), &b))
            return unknown_point(s, "--spring", comma + 1, strlen(comma + 1));
        if (a == b) {
            cli_diag_error("--spring '%s': a spring needs two different points", v);
            return QD_EXIT_USAGE;
        }
        s->links[s->nlinks++] = (an_link){.a = a, .b = b, .spring = true};
    }
    return QD_EXIT_OK;
}

static void scene_free(an_scene *s) {
    free(s->pts);
    free(s->spts);
    free(s->t);
    free(s->energy);
    free(s->pos);
    free(s->rot);
    free(s->links);
    free(s->traces);
}

/* --draw: the kinds named (particles, bodies, positions) and the points
 * named; none given, the library's default. */
static unsigned draw_kinds(const an_args *p, bool *by_name) {
    unsigned which = 0;
    *by_name = false;
    for (size_t i = 0; i < p->ndraws; i++) {
        const char *w = p->draws[i];
        if (!strcmp(w, "particles"))
            which |= QD_SCENE_PARTICLES;
        else if (!strcmp(w, "bodies"))
            which |= QD_SCENE_BODIES;
        else if (!strcmp(w, "positions"))
            which |= QD_SCENE_POSITIONS;
        else
            *by_name = true;
    }
    return *by_name ? QD_SCENE_PARTICLES | QD_SCENE_BODIES | QD_SCENE_POSITIONS : which;
}

/* Keep the points --draw names (with every kind --draw names). */
static int keep_named(an_scene *s, const an_args *p) {
    bool kind[3] = {0}, *keep = calloc(s->npts + 1, sizeof *keep);
    if (!keep)
        return QD_EXIT_FAIL;
    for (size_t i = 0; i < p->ndraws; i++) {
        const char *w = p->draws[i];
        if (!strcmp(w, "particles") || !strcmp(w, "bodies") || !strcmp(w, "positions")) {
            kind[w[0] == 'p' ? (w[1] == 'a' ? 0 : 2) : 1] = true;
            continue;
        }
        size_t at;
        if (!find_point(s, w, strlen(w), &at) || at == AN_ORIGIN) {
            free(keep);
            return unknown_point(s, "--draw", w, strlen(w));
        }
        keep[at] = true;
    }
    size_t n = 0;
    for (size_t i = 0; i < s->npts; i++)
        if (keep[i] || kind[s->spts[i].kind])
            s->spts[n++] = s->spts[i];
    s->npts = n;
    free(keep);
    return QD_EXIT_OK;
}

/* The points to draw (qd_scene_points); none is bad input. */
static int scene_points(cli_sim *c, an_scene *s, const an_args *p) {
    const qd_model *m = c->mf.model;
    bool by_name;
    unsigned which = draw_kinds(p, &by_name);
    if (qd_scene_points(c->ctx, m, which, &s->spts, &s->npts) != QD_OK)
        return cli_diag_ctx(c->ctx);
    int rc = by_name ? keep_named(s, p) : QD_EXIT_OK;
    if (rc != QD_EXIT_OK)
        return rc;
    s->nbodies = 0;
    for (size_t i = 0; i < s->npts; i++)
        s->nbodies += s->spts[i].kind == QD_SCENE_BODY;
    if (!s->npts) {
        cli_diag_error("%s: nothing to draw: the model has no `particle`, `body` or named "
                       "position (x1 = ..., y1 = ... or a vector P1 = (x, y, z)); a model given "
                       "only by T, V or L in its coordinates has no positions", p->a.file);
        return QD_EXIT_USAGE;
    }
    /* springs named plus at most a rod per pair, the origin included */
    size_t maxlinks = p->nsprings + (s->npts + 1) * s->npts / 2;
    s->pts = calloc(s->npts, sizeof *s->pts);
    s->links = malloc((maxlinks + 1) * sizeof *s->links);
    if (!s->pts || !s->links)
        return QD_EXIT_FAIL;
    rc = add_point_outputs(c, s);
    if (rc == QD_EXIT_OK)
        rc = name_traces(s, p);
    if (rc == QD_EXIT_OK)
        rc = name_springs(s, p);
    return rc;
}

static int write_page(const an_scene *s, const char *path) {
    int rc = QD_EXIT_OK;
    FILE *f = cli_out_open(path, &rc);
    if (!f)
        return rc;
    rc = cli_animate_write(f, s);
    int err = ferror(f) ? errno : 0;
    int crc = cli_out_close(f, path, err);
    return rc != QD_EXIT_OK && !err ? rc : crc;
}

int cli_cmd_animate(int argc, char **argv) {
    an_args p = {0};
    int rc = cli_file_args(argc, argv, "animate", usage_text, &p.a.file, parse_option, &p);
    if (rc == QD_EXIT_OK && p.html && p.a.out) {
        cli_diag_error("give the page once: -o FILE.html (--html is the same)");
        rc = QD_EXIT_USAGE;
    } else if (rc == QD_EXIT_OK && !p.html) {
        p.html = p.a.out; /* -o and --out: the simulation group's, here the page */
    }
    if (rc == QD_EXIT_OK && !p.html) {
        cli_diag_error("-o FILE.html is missing\n%s", usage_text);
        rc = QD_EXIT_USAGE;
    } else if (rc == QD_EXIT_OK && p.a.output) {
        cli_diag_error("--output is simulate's: it adds columns to its rows; animate writes "
                       "its page with -o FILE.html");
        rc = QD_EXIT_USAGE;
    }
    if (rc != QD_EXIT_OK)
        return rc;
    if (!p.a.t_end)
        p.a.t_end = DEFAULT_T_END;
    cli_sim c = {0};
    an_scene s = {.model = p.a.file};
    rc = cli_sim_setup(&c, &p.a);
    if (rc == QD_EXIT_OK)
        rc = scene_points(&c, &s, &p);
    if (rc == QD_EXIT_OK)
        rc = run(&c, &s);
    if (rc == QD_EXIT_OK)
        rc = cli_animate_analyse(&s);
    if (rc == QD_EXIT_OK)
        rc = write_page(&s, p.html);
    if (rc == QD_EXIT_OK)
        fprintf(stderr, "qdot: animate: wrote %s (%zu point%s, %zu link%s, %s)\n", p.html,
                s.npts, s.npts == 1 ? "" : "s", s.nlinks, s.nlinks == 1 ? "" : "s",
                s.plane[0] < 0 ? "3-D" : "in a plane");
    scene_free(&s);
    cli_sim_free(&c);
    return rc;
}
