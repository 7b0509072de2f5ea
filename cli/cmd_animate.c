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
#include "args.h"
#include "sim_cli.h"

#define DEFAULT_T_END "10"

typedef struct an_args {
    cli_sim_args a;     /* -o, --out: the page */
    cli_list traces, springs, draws;
} an_args;

static const cli_opt opts[] = {
    {"--draw", NULL, CLI_LIST, offsetof(an_args, draws), "WHAT",
     "particles, bodies, positions, or one point by name (p2, a body, x1,y1 or x1)", NULL, NULL},
    {"--trace", NULL, CLI_LIST, offsetof(an_args, traces), "NAME", "draw the path of that point",
     NULL, NULL},
    {"--spring", NULL, CLI_LIST, offsetof(an_args, springs), "A,B",
     "a zigzag between two points (origin, p1, a body's name)", NULL, NULL},
    {NULL, NULL, 0, 0, NULL, NULL, NULL, NULL},
};

static const cli_group groups[] = {CLI_SIM_GROUP(an_args, a), {NULL, 0}};

static const cli_spec spec = {
    .name = "animate",
    .synopsis = "FILE -o FILE.html [--draw WHAT]... [--trace NAME]... [--spring A,B]... "
                "[simulate options]",
    .summary = "Simulate the model and write one self-contained HTML page that plays its\n"
               "motion: every particle and body, or the named positions of a model with\n"
               "neither; rods where two points keep their distance.  -o, --out FILE.html is\n"
               "the page.  Every option of qdot simulate that shapes the motion applies too\n"
               "(--t-end, default 10, --dt, --rtol, --atol, --method, --initial, --set, --input,\n"
               "--about, --lqr, --stop-at, --event, --max-steps, --no-project, --no-speeds,\n"
               "--native, --precision; qdot simulate --help).",
    .opts = opts,
    .groups = groups,
    .min_pos = 1,
    .max_pos = 1,
    .pos_name = "FILE",
};

/* ---- the points (qd_scene_choose) and their outputs ----------------------- */

/* What the page draws (qd_scene), and the arrays it points to, owned here. */
typedef struct an_scene {
    qd_scene view;
    qd_scene_point *pts;
    double *mass;
    qd_scene_frames fr;
    qd_scene_link *links;
    size_t *springs, nsprings; /* the ends of each --spring (qd_scene_pairs) */
    size_t *traces;
} an_scene;

/* The points --draw chooses, --trace and --spring name, their masses, and
 * their places as outputs of the run. */
static int scene_points(cli_sim *c, an_scene *s, const an_args *p) {
    size_t n = 0;
    if (qd_scene_choose(c->ctx, c->mf.model, p->draws.items, p->draws.n, &s->pts, &n) != QD_OK) {
        const qd_diag *d = qd_ctx_diag(c->ctx);
        if (d->name[0] || d->status == QD_ERR_NOMEM)
            return cli_diag_ctx(c->ctx);
        cli_diag_error("%s: %s", p->a.file, d->message); /* nothing to draw in the file */
        return QD_EXIT_USAGE;
    }
    s->view.pts = s->pts;
    s->view.npts = n;
    s->mass = malloc((n + 1) * sizeof *s->mass);
    s->traces = malloc((p->traces.n + 1) * sizeof *s->traces);
    s->springs = malloc((2 * p->springs.n + 1) * sizeof *s->springs);
    if (!s->mass || !s->traces || !s->springs)
        return QD_EXIT_FAIL;
    if (qd_scene_masses(c->ctx, s->pts, n, c->st.n, c->st.syms, c->st.vals, s->mass) != QD_OK ||
        qd_scene_named(c->ctx, s->pts, n, p->traces.items, p->traces.n, s->traces) != QD_OK ||
        qd_scene_pairs(c->ctx, s->pts, n, p->springs.items, p->springs.n, s->springs) != QD_OK ||
        qd_scene_add_outputs(c->ctx, c->s, c->mf.model, s->pts, n) != QD_OK)
        return cli_diag_ctx(c->ctx);
    s->view.mass = s->mass;
    s->view.traces = s->traces;
    s->view.ntraces = p->traces.n;
    s->nsprings = p->springs.n;
    return QD_EXIT_OK;
}

/* The springs, the rods and the drawing plane of the motion (qd_scene_links). */
static int scene_links(an_scene *s) {
    qd_status st = qd_scene_links(NULL, s->fr.pos, s->fr.nframes, s->view.npts, s->springs,
                                  s->nsprings, &s->links, &s->view.nlinks, s->view.plane);
    if (st != QD_OK) {
        cli_diag_error("the scene's positions could not be analysed (%s)", qd_status_str(st));
        return QD_EXIT_FAIL;
    }
    s->view.links = s->links;
    return QD_EXIT_OK;
}

/* ---- the run: rows kept, then sampled at the frames (qd_scene_sample) ------- */

typedef struct an_rows {
    size_t width, n, cap; /* every column of the run */
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
    memcpy(r->v + r->n++ * r->width, row, r->width * sizeof *row);
    cli_progress_update(&r->bar, (row[0] - r->t0) / (r->t_end - r->t0), row[0]);
    return 0;
}

static size_t column(const cli_sim *c, const char *name) {
    size_t n = qd_sim_columns(c->s, c->opts.method, NULL, 0);
    const char **names = malloc((n + 1) * sizeof *names);
    size_t at = QD_SCENE_NONE;
    if (names) {
        qd_sim_columns(c->s, c->opts.method, names, n);
        for (size_t i = 0; i < n && at == QD_SCENE_NONE; i++)
            if (!strcmp(names[i], name))
                at = i;
    }
    free(names);
    return at;
}

static int run(cli_sim *c, an_scene *s) {
    size_t width = qd_sim_columns(c->s, c->opts.method, NULL, 0);
    an_rows r = {.width = width, .t0 = c->opts.t0, .t_end = c->opts.t_end};
    /* an adaptive method writes its rows at the frames (dense output); its
     * --dt would only be another output grid */
    if (qd_sim_method_adaptive(c->opts.method))
        c->opts.dt = (c->opts.t_end - c->opts.t0) /
                     (double)(qd_scene_nframes(c->opts.t0, c->opts.t_end) - 1);
    qd_sim_stats st;
    cli_progress_start(&r.bar, "animate");
    qd_status rs = qd_sim_run(c->s, &c->opts, keep_row, &r, &st, NULL);
    double wall = cli_progress_end(&r.bar);
    int rc = r.nomem ? QD_EXIT_FAIL : rs != QD_OK ? cli_sim_fail(c, rs) : QD_EXIT_OK;
    if (r.nomem)
        cli_diag_error("out of memory keeping the run's %zu rows", r.n);
    if (rc == QD_EXIT_OK && r.n == 0)
        rc = QD_EXIT_FAIL;
    if (rc == QD_EXIT_OK) {
        r.t_end = r.v[(r.n - 1) * r.width]; /* a stop or a contact ends the run early */
        size_t first = width - qd_scene_noutputs(s->pts, s->view.npts);
        if (qd_scene_sample(c->ctx, s->pts, s->view.npts, r.v, r.n, column(c, "energy"), first,
                            width, c->opts.t0, r.t_end, &s->fr) != QD_OK)
            rc = cli_diag_ctx(c->ctx);
    }
    if (rc == QD_EXIT_OK) {
        s->view.fr = &s->fr;
        s->view.energy_error_max = st.energy_error_max;
        s->view.conservative = qd_sim_conservative(c->s);
        s->view.method = qd_sim_method_name(c->opts.method);
        fprintf(stderr, "qdot: animate: %s, t = %g..%g: %zu frames from %zu steps, %.3g s; "
                        "energy error %.3g\n", s->view.method, c->opts.t0, r.t_end, s->fr.nframes,
                st.steps, wall, st.energy_error_max);
    }
    free(r.v);
    return rc;
}

static void scene_free(an_scene *s) {
    qd_scene_points_free(s->pts);
    qd_scene_frames_free(&s->fr);
    free(s->mass);
    free(s->links);
    free(s->springs);
    free(s->traces);
}

static int write_page(const an_scene *s, const char *path) {
    int rc = QD_EXIT_OK;
    FILE *f = cli_out_open(path, &rc);
    if (!f)
        return rc;
    rc = cli_animate_write(f, &s->view);
    int err = ferror(f) ? errno : 0;
    int crc = cli_out_close(f, path, err);
    return rc != QD_EXIT_OK && !err ? rc : crc;
}

int cli_cmd_animate(int argc, char **argv) {
    an_args p = {0};
    const char *pos[1];
    int rc = cli_parse(&spec, argc, argv, &p, pos);
    p.a.file = pos[0];
    const char *html = p.a.out;
    if (rc == QD_EXIT_OK && !html) {
        cli_diag_error("-o FILE.html is missing (qdot animate --help)");
        rc = QD_EXIT_USAGE;
    } else if (rc == QD_EXIT_OK && p.a.output) {
        cli_diag_error("--output is simulate's: it adds columns to its rows; animate writes "
                       "its page with -o FILE.html");
        rc = QD_EXIT_USAGE;
    }
    if (rc != QD_EXIT_OK)
        return rc;
    p.a.out = NULL; /* the page, not the rows */
    if (!p.a.t_end)
        p.a.t_end = DEFAULT_T_END;
    cli_sim c = {0};
    an_scene s = {.view = {.model = p.a.file}};
    rc = cli_sim_setup(&c, &p.a);
    if (rc == QD_EXIT_OK)
        rc = scene_points(&c, &s, &p);
    if (rc == QD_EXIT_OK)
        rc = run(&c, &s);
    if (rc == QD_EXIT_OK)
        rc = scene_links(&s);
    if (rc == QD_EXIT_OK)
        rc = write_page(&s, html);
    if (rc == QD_EXIT_OK)
        fprintf(stderr, "qdot: animate: wrote %s (%zu point%s, %zu link%s, %s)\n", html,
                s.view.npts, s.view.npts == 1 ? "" : "s", s.view.nlinks,
                s.view.nlinks == 1 ? "" : "s", s.view.plane[0] < 0 ? "3-D" : "in a plane");
    scene_free(&s);
    cli_sim_free(&c);
    return rc;
}
