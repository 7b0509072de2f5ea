/*
 * cli/cmd_animate.c - `qdot animate FILE [simulate options] -o FILE.html`:
 * simulate the model (the setup of sim_cli.c), sample the positions of its
 * particles and bodies at the frames (outputs of the run: the model's own
 * position and rotation expressions, evaluated by libqdot), and write one
 * self-contained HTML page that plays the motion (qd_scene_html).
 */
#include "cli.h"

#include <math.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/scene.h"
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

/* ---- the run, sampled at the frames (qd_scene_record) ---------------------- */

typedef struct an_progress {
    cli_progress bar;
    double t0, t_end;
} an_progress;

static void progress(void *data, double t) {
    an_progress *p = data;
    cli_progress_update(&p->bar, (t - p->t0) / (p->t_end - p->t0), t);
}

static int run(cli_sim *c, an_scene *s) {
    an_progress pr = {.t0 = c->opts.t0, .t_end = c->opts.t_end};
    qd_sim_stats st;
    cli_progress_start(&pr.bar, "animate");
    qd_status rs = qd_scene_record(c->ctx, c->s, &c->opts, s->pts, s->view.npts, progress, &pr,
                                   &s->fr, &st);
    double wall = cli_progress_end(&pr.bar);
    if (rs != QD_OK)
        return rs == QD_ERR_NOMEM ? cli_diag_ctx(c->ctx) : cli_sim_fail(c, rs);
    s->view.fr = &s->fr;
    s->view.energy_error_max = st.energy_error_max;
    s->view.conservative = qd_sim_conservative(c->s);
    s->view.method = qd_sim_method_name(c->opts.method);
    fprintf(stderr, "qdot: animate: %s, t = %g..%g: %zu frames from %zu steps, %.3g s; "
                    "energy error %.3g over the rows (%.3g at the steps)\n", s->view.method,
            c->opts.t0, s->fr.t[s->fr.nframes - 1], s->fr.nframes, st.steps, wall,
            st.energy_error_max, st.energy_error_steps);
    return QD_EXIT_OK;
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
    qd_buf b = QD_BUF_INIT;
    if (qd_scene_html(&s->view, &b) != QD_OK) {
        qd_buf_free(&b);
        cli_diag_error("out of memory writing the page");
        return QD_EXIT_FAIL;
    }
    int rc = QD_EXIT_OK, err = 0;
    FILE *f = cli_out_open(path, &rc);
    if (f)
        cli_out_write(f, qd_buf_str(&b), b.len, &err);
    qd_buf_free(&b);
    return f ? cli_out_close(f, path, err) : rc;
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
