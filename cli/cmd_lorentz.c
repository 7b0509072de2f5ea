/*
 * cli/cmd_lorentz.c - `qdot lorentz --frame "Vx, Vy, Vz"`: the Lorentz
 * transformation to the frame moving with V (qdot/relativity.h, Desloge
 * ch. 86-91) of an event, a velocity, an acceleration (with its velocity)
 * and a four-momentum; the 4x4 boost and its check O^T g O = g; velocity
 * composition in both orders; time dilation, the contraction of a
 * displacement and proper time along a worldline v(t).
 */
#include "cli.h"

#include <stdlib.h>
#include <string.h>
#include "qdot/json.h"
#include "model_cli.h"
#include "rel_cli.h"
#include "state.h"

typedef struct lz_args {
    const char *c_s, *frame, *event, *vel, *acc, *mom, *compose, *dilate, *contract, *tau, *span;
    bool json;
} lz_args;

typedef struct lz_run {
    qd_ctx *ctx;
    double c, V[3], G, O[16], err;
    double ev[4], v[3], a[3], E, p[3], m, u[3], dtau, d[3], span[2];
    double ev1[4], v1[3], g1, a1[3], E1, p1[3], uv[3], vu[3], wigner, dt, d1[3];
    qd_rel_tau tau;
} lz_run;

static const char usage_text[] =
    "usage: qdot lorentz --frame \"Vx, Vy, Vz\" [--c C] [--event \"t, x, y, z\"]\n"
    "         [--velocity \"vx, vy, vz\" [--acceleration \"ax, ay, az\"]]\n"
    "         [--momentum \"E, px, py, pz\" | --momentum \"m=M, v=(vx, vy, vz)\"]\n"
    "         [--compose \"vx, vy, vz\"] [--dilate DTAU] [--contract \"dx, dy, dz\"]\n"
    "         [--format text|json]\n"
    "       qdot lorentz --proper-time \"vx(t), vy(t), vz(t)\" --t T0:T1 [--c C]";

static int parse_option(int argc, char **argv, int *i, lz_args *a) {
    static const struct { const char *name; size_t off; } opts[] = {
        {"--c", offsetof(lz_args, c_s)}, {"--frame", offsetof(lz_args, frame)},
        {"--event", offsetof(lz_args, event)}, {"--velocity", offsetof(lz_args, vel)},
        {"--acceleration", offsetof(lz_args, acc)}, {"--momentum", offsetof(lz_args, mom)},
        {"--compose", offsetof(lz_args, compose)}, {"--dilate", offsetof(lz_args, dilate)},
        {"--contract", offsetof(lz_args, contract)}, {"--proper-time", offsetof(lz_args, tau)},
        {"--t", offsetof(lz_args, span)}};
    const char *v;
    if ((v = cli_value(argc, argv, i, "--format")) && (!strcmp(v, "text") || !strcmp(v, "json"))) {
        a->json = !strcmp(v, "json");
        return QD_EXIT_OK;
    }
    for (size_t k = 0; k < sizeof opts / sizeof opts[0]; k++) {
        const char **slot = (const char **)((char *)a + opts[k].off);
        if (!*slot && (v = cli_value(argc, argv, i, opts[k].name))) {
            *slot = v;
            return QD_EXIT_OK;
        }
    }
    cli_diag_error("bad, repeated or incomplete option '%s'\n%s", argv[*i], usage_text);
    return QD_EXIT_USAGE;
}

static int parse_args(int argc, char **argv, lz_args *a) {
    for (int i = 0; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            printf("%s\n", usage_text);
            exit(QD_EXIT_OK);
        }
        int rc = parse_option(argc, argv, &i, a);
        if (rc != QD_EXIT_OK)
            return rc;
    }
    bool transform = a->event || a->vel || a->mom || a->compose || a->dilate || a->contract;
    const char *why = !a->frame && (transform || !a->tau) ? "--frame is missing"
                      : a->acc && !a->vel                 ? "--acceleration needs --velocity"
                      : !a->tau != !a->span               ? "--proper-time and --t go together"
                                                          : NULL;
    if (why) {
        cli_diag_error("%s\n%s", why, usage_text);
        return QD_EXIT_USAGE;
    }
    return QD_EXIT_OK;
}

/* The library's refusal (a speed at or beyond c) as bad input. */
static int lib(lz_run *r, qd_status st) {
    if (st == QD_OK)
        return QD_EXIT_OK;
    int rc = cli_diag_ctx(r->ctx);
    return st == QD_ERR_ARG ? QD_EXIT_USAGE : rc;
}

/* --momentum: "E, px, py, pz" or "m=..., v=(...)". */
static int read_momentum(lz_run *r, const char *text) {
    if (strchr(text, '=')) {
        qd_rel_particle pt;
        int rc = rel_particle(r->ctx, r->c, "--momentum", text, &pt);
        r->E = pt.E;
        memcpy(r->p, pt.p, sizeof r->p);
        return rc;
    }
    double x[4];
    int rc = rel_list(r->ctx, r->c, "--momentum", text, 4, x, NULL);
    r->E = x[0];
    memcpy(r->p, x + 1, sizeof r->p);
    return rc;
}

static int read_span(lz_run *r, const char *text) {
    const char *colon = strchr(text, ':');
    char *a = colon ? malloc((size_t)(colon - text) + 1) : NULL;
    int rc = QD_EXIT_USAGE;
    if (!colon)
        cli_diag_error("--t takes T0:T1, not '%s'", text);
    else if (a) {
        memcpy(a, text, (size_t)(colon - text));
        a[colon - text] = '\0';
        rc = rel_read(r->ctx, r->c, "--t", a, false, NULL, &r->span[0]);
        if (rc == QD_EXIT_OK)
            rc = rel_read(r->ctx, r->c, "--t", colon + 1, false, NULL, &r->span[1]);
    }
    free(a);
    return rc;
}

static int read_inputs(lz_run *r, const lz_args *a) {
    int rc = a->c_s ? rel_speed_of_light(r->ctx, a->c_s, &r->c) : QD_EXIT_OK;
    if (rc == QD_EXIT_OK && a->frame)
        rc = rel_list(r->ctx, r->c, "--frame", a->frame, 3, r->V, NULL);
    if (rc == QD_EXIT_OK && a->event)
        rc = rel_list(r->ctx, r->c, "--event", a->event, 4, r->ev, NULL);
    if (rc == QD_EXIT_OK && a->vel)
        rc = rel_list(r->ctx, r->c, "--velocity", a->vel, 3, r->v, NULL);
    if (rc == QD_EXIT_OK && a->acc)
        rc = rel_list(r->ctx, r->c, "--acceleration", a->acc, 3, r->a, NULL);
    if (rc == QD_EXIT_OK && a->mom)
        rc = read_momentum(r, a->mom);
    if (rc == QD_EXIT_OK && a->compose)
        rc = rel_list(r->ctx, r->c, "--compose", a->compose, 3, r->u, NULL);
    if (rc == QD_EXIT_OK && a->dilate)
        rc = rel_read(r->ctx, r->c, "--dilate", a->dilate, false, NULL, &r->dtau);
    if (rc == QD_EXIT_OK && a->contract)
        rc = rel_list(r->ctx, r->c, "--contract", a->contract, 3, r->d, NULL);
    if (rc == QD_EXIT_OK && a->span)
        rc = read_span(r, a->span);
    return rc;
}

static int proper_time(lz_run *r, const char *text) {
    const qd_expr *v[3];
    int rc = rel_list(r->ctx, r->c, "--proper-time", text, 3, NULL, v);
    if (rc == QD_EXIT_OK)
        rc = lib(r, qd_rel_proper_time(r->ctx, r->c, v, r->span[0], r->span[1], 0, &r->tau));
    return rc;
}

static int compute(lz_run *r, const lz_args *a) {
    qd_ctx *ctx = r->ctx;
    int rc = QD_EXIT_OK;
    if (a->frame && (rc = lib(r, qd_lorentz_boost(ctx, r->c, r->V, r->O))) == QD_EXIT_OK) {
        r->err = qd_lorentz_metric_error(r->O);
        rc = lib(r, qd_rel_gamma(ctx, r->c, r->V, &r->G));
    }
    if (rc == QD_EXIT_OK && a->event)
        rc = lib(r, qd_lorentz_event(ctx, r->c, r->V, r->ev, r->ev1));
    if (rc == QD_EXIT_OK && a->vel)
        rc = lib(r, qd_lorentz_velocity(ctx, r->c, r->V, r->v, r->v1));
    if (rc == QD_EXIT_OK && a->vel)
        rc = lib(r, qd_rel_gamma(ctx, r->c, r->v1, &r->g1));
    if (rc == QD_EXIT_OK && a->acc)
        rc = lib(r, qd_lorentz_acceleration(ctx, r->c, r->V, r->v, r->a, r->a1));
    if (rc == QD_EXIT_OK && a->mom)
        rc = lib(r, qd_lorentz_momentum(ctx, r->c, r->V, r->E, r->p, &r->E1, r->p1));
    if (rc == QD_EXIT_OK && a->mom)
        rc = lib(r, qd_rel_mass(ctx, r->c, r->E, r->p, &r->m));
    if (rc == QD_EXIT_OK && a->compose)
        rc = lib(r, qd_rel_compose(ctx, r->c, r->V, r->u, r->uv));
    if (rc == QD_EXIT_OK && a->compose)
        rc = lib(r, qd_rel_compose(ctx, r->c, r->u, r->V, r->vu));
    if (rc == QD_EXIT_OK && a->compose)
        rc = lib(r, qd_rel_wigner_angle(ctx, r->c, r->V, r->u, &r->wigner));
    if (rc == QD_EXIT_OK && a->dilate)
        rc = lib(r, qd_rel_dilate(ctx, r->c, r->V, r->dtau, &r->dt));
    if (rc == QD_EXIT_OK && a->contract)
        rc = lib(r, qd_rel_contract(ctx, r->c, r->V, r->d, r->d1));
    if (rc == QD_EXIT_OK && a->tau)
        rc = proper_time(r, a->tau);
    return rc;
}

static void num(qd_json *j, const char *key, double x) {
    qd_json_key(j, key);
    qd_json_number(j, x);
}

static void write_json(const lz_run *r, const lz_args *a, qd_buf *b) {
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    num(&j, "c", r->c);
    if (a->frame) {
        rel_json_vec(&j, "frame", r->V, 3);
        num(&j, "gamma", r->G);
        qd_json_key(&j, "boost");
        qd_json_begin_array(&j);
        for (int i = 0; i < 4; i++)
            rel_json_vec(&j, NULL, r->O + 4 * i, 4);
        qd_json_end_array(&j);
        num(&j, "metric_error", r->err);
    }
    if (a->event)
        rel_json_vec(&j, "event", r->ev1, 4);
    if (a->vel) {
        rel_json_vec(&j, "velocity", r->v1, 3);
        num(&j, "particle_gamma", r->g1);
    }
    if (a->acc)
        rel_json_vec(&j, "acceleration", r->a1, 3);
    if (a->mom) {
        num(&j, "energy", r->E1);
        rel_json_vec(&j, "momentum", r->p1, 3);
        num(&j, "invariant_mass", r->m);
    }
    if (a->compose) {
        rel_json_vec(&j, "composed", r->uv, 3);
        rel_json_vec(&j, "composed_reverse", r->vu, 3);
        num(&j, "wigner_angle", r->wigner);
    }
    if (a->dilate)
        num(&j, "dilated", r->dt);
    if (a->contract)
        rel_json_vec(&j, "contracted", r->d1, 3);
    if (a->tau) {
        num(&j, "proper_time", r->tau.tau);
        num(&j, "proper_time_error", r->tau.error);
        num(&j, "max_speed", r->tau.vmax);
    }
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    b->failed = b->failed || !qd_json_ok(&j);
}

static void line(qd_buf *b, const char *label, const double *x, size_t n, const double *y) {
    qd_buf_printf(b, "%s", label);
    rel_put_vec(b, x, n);
    qd_buf_puts(b, " -> ");
    rel_put_vec(b, y, n);
    qd_buf_puts(b, "\n");
}

static void value(qd_buf *b, const char *label, double x) {
    qd_buf_puts(b, label);
    cli_state_put_result(b, x);
    qd_buf_puts(b, "\n");
}

static void write_frame(const lz_run *r, qd_buf *b) {
    qd_buf_puts(b, "frame V = ");
    rel_put_vec(b, r->V, 3);
    qd_buf_puts(b, ", c = ");
    cli_state_put_result(b, r->c);
    value(b, ", gamma = ", r->G);
    qd_buf_puts(b, "boost on (x, y, z, c t):\n");
    for (int i = 0; i < 4; i++) {
        qd_buf_puts(b, "  ");
        rel_put_vec(b, r->O + 4 * i, 4);
        qd_buf_puts(b, "\n");
    }
    qd_buf_printf(b, "O^T g O = g, g = diag(1, 1, 1, -1): max error %.3g\n", r->err);
}

static void write_text(const lz_run *r, const lz_args *a, qd_buf *b) {
    if (a->frame)
        write_frame(r, b);
    if (a->event)
        line(b, "event (t, x, y, z): ", r->ev, 4, r->ev1);
    if (a->vel) {
        line(b, "velocity: ", r->v, 3, r->v1);
        value(b, "  gamma' = ", r->g1);
    }
    if (a->acc)
        line(b, "acceleration: ", r->a, 3, r->a1);
    if (a->mom) {
        double x[4] = {r->E, r->p[0], r->p[1], r->p[2]}, y[4] = {r->E1, r->p1[0], r->p1[1], r->p1[2]};
        line(b, "four-momentum (E, px, py, pz): ", x, 4, y);
        value(b, "  invariant mass sqrt(E^2 - p^2 c^2)/c^2 = ", r->m);
    }
    if (a->compose) {
        qd_buf_puts(b, "V (+) v = ");
        rel_put_vec(b, r->uv, 3);
        qd_buf_puts(b, "\nv (+) V = ");
        rel_put_vec(b, r->vu, 3);
        value(b, "\n  angle between them (Thomas-Wigner rotation) = ", r->wigner);
    }
    if (a->dilate)
        value(b, "dilated: a proper interval of a clock moving with V lasts ", r->dt);
    if (a->contract)
        line(b, "contracted (at rest in the moving frame, measured in the rest frame): ", r->d, 3,
             r->d1);
    if (a->tau) {
        qd_buf_puts(b, "proper time = ");
        cli_state_put_result(b, r->tau.tau);
        qd_buf_printf(b, " (error estimate %.2g; largest speed ", r->tau.error);
        cli_state_put_result(b, r->tau.vmax);
        qd_buf_puts(b, ")\n");
    }
}

int cli_cmd_lorentz(int argc, char **argv) {
    lz_args a = {0};
    int rc = parse_args(argc, argv, &a);
    if (rc != QD_EXIT_OK)
        return rc;
    lz_run r = {.c = 1};
    if (!(r.ctx = qd_ctx_new())) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    rc = read_inputs(&r, &a);
    if (rc == QD_EXIT_OK)
        rc = compute(&r, &a);
    if (rc == QD_EXIT_OK) {
        qd_buf b = QD_BUF_INIT;
        if (a.json)
            write_json(&r, &a, &b);
        else
            write_text(&r, &a, &b);
        rc = cli_emit(&b, "the transformation");
    }
    qd_ctx_free(r.ctx);
    return rc;
}
