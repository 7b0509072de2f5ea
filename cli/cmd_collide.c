/*
 * cli/cmd_collide.c - `qdot collide --particle "m=..., v=(...)" ...`: the
 * four-momenta of particles and their sum, a perfectly inelastic merge,
 * elastic final states, a reaction's threshold and a two-body decay
 * (qd_collide_read/run/render, qdot/relativity.h).
 */
#include "driver.h"

#include <stdlib.h>
#include "opt_diag.h"

typedef struct cl_args {
    cli_run run; /* the options follow (c is the speed of light) */
    cli_list particle;
    const char *c, *angle, *cm_angle, *azimuth, *threshold, *decay, *format, *out;
    bool merge, elastic;
} cl_args;

#define A(field) offsetof(cl_args, field)
static const cli_opt opts[] = {
    {"--particle", NULL, CLI_LIST, A(particle), "\"m=M, v=(vx, vy, vz)\"",
     "a particle (v defaults to rest); repeat for more", NULL, NULL},
    {"--c", NULL, CLI_TEXT, A(c), "C", "the speed of light (default 1)", NULL, NULL},
    {"--merge", NULL, CLI_FLAG, A(merge), NULL, "the body a perfectly inelastic merge makes",
     NULL, NULL},
    {"--elastic", NULL, CLI_FLAG, A(elastic), NULL,
     "two particles' elastic final states (with --angle or --cm-angle)", NULL, NULL},
    {"--angle", NULL, CLI_TEXT, A(angle), "TH",
     "particle 1's lab angle after (every solution)", NULL, NULL},
    {"--cm-angle", NULL, CLI_TEXT, A(cm_angle), "CHI",
     "the centre-of-momentum angle of --elastic or --decay", NULL, NULL},
    {"--azimuth", NULL, CLI_TEXT, A(azimuth), "PHI", "the azimuth about the incoming direction",
     NULL, NULL},
    {"--threshold", NULL, CLI_TEXT, A(threshold), "\"M1, M2, ...\"",
     "the threshold for these products on particle 2 at rest", NULL, NULL},
    {"--decay", NULL, CLI_TEXT, A(decay), "\"m1, m2\"", "one particle's two-body decay", NULL,
     NULL},
    CLI_OPT_FORMAT(cl_args, format),
    CLI_OPT_OUT(cl_args, out),
    {0},
};
#undef A

static const cli_spec spec = {
    "collide", "--particle \"m=M, v=(vx, vy, vz)\" [--particle ...] [options]",
    "relativistic collisions by the conservation of four-momentum", opts, NULL, 0, 0, NULL,
    false};

static int run(cli_run *c) {
    const cl_args *a = (cl_args *)c;
    qd_collide_in *in = malloc(sizeof *in);
    qd_collide_out *out = in ? malloc(sizeof *out) : NULL;
    int rc = QD_EXIT_FAIL;
    if (!out) {
        cli_diag_error("out of memory");
    } else {
        const qd_collide_text t = {a->c, a->particle.n, a->particle.items, a->merge, a->elastic,
                                   a->angle, a->cm_angle, a->azimuth, a->threshold, a->decay};
        qd_buf b = QD_BUF_INIT;
        qd_status st = qd_collide_read(c->ctx, &t, in);
        if (st == QD_OK)
            st = qd_collide_run(c->ctx, in, out);
        if (st == QD_OK)
            st = qd_collide_render(c->ctx, in, out, cli_json(a->format), &b);
        rc = st == QD_OK ? cli_out_emit(&b, a->out) : cli_diag_opts(c->ctx, &spec, a);
        qd_buf_free(&b);
    }
    free(out);
    free(in);
    return rc;
}

CLI_COMMAND(collide, cl_args, &spec, 0, 0, NULL, run, NULL)
