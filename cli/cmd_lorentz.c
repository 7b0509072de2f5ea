/*
 * cli/cmd_lorentz.c - `qdot lorentz --frame "Vx, Vy, Vz"`: the Lorentz
 * transformation to the frame moving with V of an event, a velocity, an
 * acceleration, a four-momentum; composition, dilation, contraction and
 * proper time (qd_lorentz_read/run/render, qdot/relativity.h).
 */
#include "driver.h"

#include "opt_diag.h"

typedef struct lz_args {
    cli_run c; /* the options follow */
    qd_lorentz_text t;
    const char *format, *out;
} lz_args;

#define T(field) offsetof(lz_args, t.field)
static const cli_opt opts[] = {
    {"--frame", NULL, CLI_TEXT, T(frame), "\"Vx, Vy, Vz\"",
     "the velocity V of the new frame S' relative to S", NULL, NULL},
    {"--c", NULL, CLI_TEXT, T(c), "C", "the speed of light (default 1)", NULL, NULL},
    {"--event", NULL, CLI_TEXT, T(event), "\"t, x, y, z\"", "an event to transform", NULL, NULL},
    {"--velocity", NULL, CLI_TEXT, T(velocity), "\"vx, vy, vz\"", "a particle's velocity",
     NULL, NULL},
    {"--acceleration", NULL, CLI_TEXT, T(acceleration), "\"ax, ay, az\"",
     "its acceleration (with --velocity)", NULL, NULL},
    {"--momentum", NULL, CLI_TEXT, T(momentum), "\"E, px, py, pz\"",
     "a four-momentum, or \"m=M, v=(vx, vy, vz)\"", NULL, NULL},
    {"--compose", NULL, CLI_TEXT, T(compose), "\"vx, vy, vz\"",
     "V (+) v and v (+) V, and the Thomas-Wigner angle", NULL, NULL},
    {"--dilate", NULL, CLI_TEXT, T(dilate), "DTAU",
     "a proper interval of a clock moving with V, as S sees it", NULL, NULL},
    {"--contract", NULL, CLI_TEXT, T(contract), "\"dx, dy, dz\"",
     "a displacement at rest in S', measured in S", NULL, NULL},
    {"--proper-time", NULL, CLI_TEXT, T(proper_time), "\"vx(t), vy(t), vz(t)\"",
     "the proper time along this worldline (with --t)", NULL, NULL},
    {"--t", NULL, CLI_TEXT, T(t), "T0:T1", "the span of --proper-time", NULL, NULL},
    CLI_OPT_FORMAT(lz_args, format),
    CLI_OPT_OUT(lz_args, out),
    {0},
};
#undef T

static const cli_spec spec = {
    "lorentz", "--frame \"Vx, Vy, Vz\" [options] | --proper-time \"v(t)\" --t T0:T1",
    "the Lorentz transformation to a moving frame (values may use c: 0.6*c)", opts, NULL, 0, 0,
    NULL, false};

static int run(cli_run *c) {
    const lz_args *a = (lz_args *)c;
    qd_lorentz_in in;
    qd_lorentz_out out;
    qd_buf b = QD_BUF_INIT;
    qd_status st = qd_lorentz_read(c->ctx, &a->t, &in);
    if (st == QD_OK)
        st = qd_lorentz_run(c->ctx, &in, &out);
    if (st == QD_OK)
        st = qd_lorentz_render(c->ctx, &in, &out, cli_json(a->format), &b);
    int rc = st == QD_OK ? cli_out_emit(&b, a->out) : cli_diag_opts(c->ctx, &spec, a);
    qd_buf_free(&b);
    return rc;
}

CLI_COMMAND(lorentz, lz_args, &spec, 0, 0, NULL, run, NULL)
