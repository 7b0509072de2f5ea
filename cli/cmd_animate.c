/*
 * cli/cmd_animate.c - `qdot animate FILE [simulate options] -o FILE.html`:
 * simulate the model (the setup of sim_cli.c), sample the positions of its
 * particles and bodies at the frames (qd_scene_setup_new, _record: the
 * model's own position and rotation expressions as outputs of the run; the
 * bodies' shapes and grounds from the model, qd_scene_looks), and
 * write one self-contained HTML page that plays the motion (qd_scene_html).
 */
#include "cli.h"

#include <stdio.h>

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
               "motion.  -o, --out FILE.html is the page.  What is drawn: every particle and\n"
               "body, or the named positions (x1 = ..., y1 = ...; P1 = (x, y, z)) of a model\n"
               "with neither; --draw particles|bodies|positions|NAME chooses (repeatable).  A\n"
               "body is drawn as the model's `shape BODY as rod(l)|disk(a)|ring(a)|sphere(a)|\n"
               "box(a, b, c) [along x|y|z]` says (docs/language.md), else as a rod when its\n"
               "inertia is a slender rod's, else as a dot with its axes; the plane a `rolls`\n"
               "names is drawn as the ground; rods where two points keep their distance;\n"
               "--spring A,B a zigzag; --trace NAME a path.  Every option of qdot simulate\n"
               "that shapes the motion applies too (--t-end, default 10, --dt, --rtol, --atol,\n"
               "--method, --initial, --set, --input, --about, --lqr, --stop-at, --event,\n"
               "--max-steps, --no-project, --no-speeds, --native, --precision; qdot simulate\n"
               "--help).",
    .opts = opts,
    .groups = groups,
    .min_pos = 1,
    .max_pos = 1,
    .pos_name = "FILE",
};

/* ---- the scene (qd_scene_setup_new), the run sampled at its frames ------- */

/* The points --draw chooses, --trace and --spring name (qd_scene_setup_new). */
static int scene_points(cli_sim *c, const an_args *p, qd_scene_setup **sc) {
    qd_scene_spec sp = {p->draws.items, p->draws.n, p->traces.items, p->traces.n,
                        p->springs.items, p->springs.n, p->a.file};
    *sc = qd_scene_setup_new(c->ctx, c->set, c->mf.model, &sp);
    const qd_diag *d = qd_ctx_diag(c->ctx);
    if (*sc || d->name[0] || d->status != QD_ERR_ARG)
        return *sc ? QD_EXIT_OK : cli_diag_ctx(c->ctx);
    return cli_usage_error("%s: %s", p->a.file, d->message); /* nothing to draw in the file */
}

typedef struct an_progress {
    cli_progress bar;
    double t0, t_end;
} an_progress;

static int progress(void *data, double t) {
    an_progress *p = data;
    cli_progress_update(&p->bar, (t - p->t0) / (p->t_end - p->t0), t);
    return cli_interrupted(); /* ^C: the page of the motion so far */
}

static int run(cli_sim *c, qd_scene_setup *sc, bool *interrupted) {
    an_progress pr = {.t0 = c->opts.t0, .t_end = c->opts.t_end};
    qd_sim_stats st;
    cli_progress_start(&pr.bar, "animate");
    cli_interrupt_begin();
    qd_status rs = qd_scene_setup_record(sc, &c->opts, progress, &pr, &st);
    *interrupted = cli_interrupted();
    cli_interrupt_end();
    double wall = cli_progress_end(&pr.bar);
    if (rs != QD_OK)
        return cli_sim_fail(c, rs);
    const qd_scene *v = qd_scene_setup_scene(sc);
    if (*interrupted)
        fprintf(stderr, "qdot: animate: interrupted at t = %.17g; the page shows the motion "
                        "up to that time\n", v->fr->t[v->fr->nframes - 1]);
    fprintf(stderr, "qdot: animate: %s, t = %g..%g: %zu frames from %zu steps, %.3g s; "
                    "energy error %.3g over the rows (%.3g at the steps)\n", v->method,
            c->opts.t0, v->fr->t[v->fr->nframes - 1], v->fr->nframes, st.steps, wall,
            st.energy_error_max, st.energy_error_steps);
    return QD_EXIT_OK;
}

static int write_page(const qd_scene *s, const char *path) {
    qd_buf b = QD_BUF_INIT;
    if (qd_scene_html(s, &b) == QD_OK)
        return cli_out_emit(&b, path);
    qd_buf_free(&b);
    cli_diag_error("out of memory writing the page");
    return QD_EXIT_FAIL;
}

int cli_cmd_animate(int argc, char **argv) {
    an_args p = {0};
    const char *pos[1];
    int rc = cli_parse(&spec, argc, argv, &p, pos);
    p.a.file = pos[0];
    const char *html = p.a.out;
    if (rc == QD_EXIT_OK && !html)
        rc = cli_usage_error("-o FILE.html is missing (qdot animate --help)");
    else if (rc == QD_EXIT_OK && p.a.output)
        rc = cli_usage_error("--output is simulate's: it adds columns to its rows; animate "
                             "writes its page with -o FILE.html");
    if (rc != QD_EXIT_OK)
        return rc;
    p.a.out = NULL; /* the page, not the rows */
    if (!p.a.t_end)
        p.a.t_end = DEFAULT_T_END;
    cli_sim c = {0};
    qd_scene_setup *sc = NULL;
    rc = cli_sim_setup(&c, &p.a);
    if (rc == QD_EXIT_OK)
        rc = scene_points(&c, &p, &sc);
    bool interrupted = false;
    if (rc == QD_EXIT_OK)
        rc = run(&c, sc, &interrupted);
    const qd_scene *v = qd_scene_setup_scene(sc);
    if (rc == QD_EXIT_OK)
        rc = write_page(v, html);
    if (rc == QD_EXIT_OK && interrupted)
        rc = CLI_EXIT_INTERRUPTED;
    if (rc == QD_EXIT_OK || rc == CLI_EXIT_INTERRUPTED)
        fprintf(stderr, "qdot: animate: wrote %s (%zu point%s, %zu link%s, %s)\n", html,
                v->npts, v->npts == 1 ? "" : "s", v->nlinks, v->nlinks == 1 ? "" : "s",
                v->plane[0] < 0 ? "3-D" : "in a plane");
    qd_scene_setup_free(sc);
    cli_sim_free(&c);
    return rc;
}
