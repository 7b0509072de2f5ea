/*
 * cli/cmd_collide.c - `qdot collide --particle "m=..., v=(...)" ...`: the
 * four-momenta of particles and their sum (qdot/relativity.h, Desloge
 * ch. 88-91): the invariant mass M = sqrt(E^2 - p^2 c^2)/c^2 and the
 * velocity V = p c^2/E of the centre-of-momentum frame, which a perfectly
 * inelastic merge (--merge) keeps; elastic final states of two particles
 * for a lab angle of particle 1 (--elastic --angle, every solution) or a
 * centre-of-momentum angle (--cm-angle); the threshold of a reaction on
 * particle 2 at rest (--threshold "M1, M2, ..."); a two-body decay of one
 * particle (--decay "m1, m2").
 */
#include "cli.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "qdot/json.h"
#include "model_cli.h"
#include "rel_cli.h"
#include "state.h"

#define MAX_PARTICLES QD_CLI_MAX_LIST
#define MAX_PRODUCTS 16

typedef struct cl_args {
    const char *particle[MAX_PARTICLES];
    size_t n;
    const char *c_s, *angle, *cm_angle, *azimuth, *threshold, *decay;
    bool merge, elastic, json;
} cl_args;

typedef struct cl_run {
    qd_ctx *ctx;
    double c, chi[2], phi, theta, prod[MAX_PRODUCTS];
    size_t nsol, nprod;
    qd_rel_particle in[MAX_PARTICLES], tot, out[2][2];
    double err;         /* largest four-momentum imbalance of a final state */
    qd_rel_threshold th;
    double prod_mass, pstar;
} cl_run;

static const char usage_text[] =
    "usage: qdot collide --particle \"m=M, v=(vx, vy, vz)\" [--particle ...] [--c C] [--merge]\n"
    "         [--elastic (--angle TH | --cm-angle CHI [--azimuth PHI])]\n"
    "         [--threshold \"M1, M2, ...\"] [--decay \"m1, m2\" [--cm-angle CHI]]\n"
    "         [--format text|json]";

static int parse_option(int argc, char **argv, int *i, cl_args *a) {
    const char *v;
    if ((v = cli_value(argc, argv, i, "--particle")))
        return cli_push("--particle", a->particle, &a->n, MAX_PARTICLES, v);
    if ((v = cli_value(argc, argv, i, "--format")) && (!strcmp(v, "text") || !strcmp(v, "json")))
        a->json = !strcmp(v, "json");
    else if (!strcmp(argv[*i], "--merge"))
        a->merge = true;
    else if (!strcmp(argv[*i], "--elastic"))
        a->elastic = true;
    else if ((v = cli_value(argc, argv, i, "--c")) && !a->c_s)
        a->c_s = v;
    else if ((v = cli_value(argc, argv, i, "--angle")) && !a->angle)
        a->angle = v;
    else if ((v = cli_value(argc, argv, i, "--cm-angle")) && !a->cm_angle)
        a->cm_angle = v;
    else if ((v = cli_value(argc, argv, i, "--azimuth")) && !a->azimuth)
        a->azimuth = v;
    else if ((v = cli_value(argc, argv, i, "--threshold")) && !a->threshold)
        a->threshold = v;
    else if ((v = cli_value(argc, argv, i, "--decay")) && !a->decay)
        a->decay = v;
    else {
        cli_diag_error("bad, repeated or incomplete option '%s'\n%s", argv[*i], usage_text);
        return QD_EXIT_USAGE;
    }
    return QD_EXIT_OK;
}

static const char *check_args(const cl_args *a) {
    if (!a->n)
        return "give at least one --particle";
    if (a->elastic && a->n != 2)
        return "--elastic needs exactly two particles";
    if (a->elastic && !a->angle == !a->cm_angle)
        return "--elastic needs one of --angle (lab) and --cm-angle";
    if (a->angle && !a->elastic)
        return "--angle goes with --elastic";
    if (a->threshold && a->n != 2)
        return "--threshold needs exactly two particles (the second is the target)";
    if (a->decay && a->n != 1)
        return "--decay needs exactly one particle (the parent)";
    if (a->decay && a->elastic)
        return "give either --decay or --elastic";
    if (a->cm_angle && !a->elastic && !a->decay)
        return "--cm-angle goes with --elastic or --decay";
    return NULL;
}

static int parse_args(int argc, char **argv, cl_args *a) {
    for (int i = 0; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            printf("%s\n", usage_text);
            exit(QD_EXIT_OK);
        }
        int rc = parse_option(argc, argv, &i, a);
        if (rc != QD_EXIT_OK)
            return rc;
    }
    const char *why = check_args(a);
    if (why) {
        cli_diag_error("%s\n%s", why, usage_text);
        return QD_EXIT_USAGE;
    }
    return QD_EXIT_OK;
}

static int lib(cl_run *r, qd_status st) {
    if (st == QD_OK)
        return QD_EXIT_OK;
    int rc = cli_diag_ctx(r->ctx);
    return st == QD_ERR_ARG ? QD_EXIT_USAGE : rc;
}

/* "M1, M2, ..." into r->prod. */
static int read_masses(cl_run *r, const char *what, const char *text, size_t min) {
    size_t n = 1;
    for (size_t i = cli_item_end(text, 0); text[i]; i = cli_item_end(text, i + 1))
        n++;
    if (n < min || n > MAX_PRODUCTS) {
        cli_diag_error("%s takes %zu to %d masses, not '%s'", what, min, MAX_PRODUCTS, text);
        return QD_EXIT_USAGE;
    }
    r->nprod = n;
    return rel_list(r->ctx, r->c, what, text, n, r->prod, NULL);
}

static int read_inputs(cl_run *r, const cl_args *a) {
    int rc = a->c_s ? rel_speed_of_light(r->ctx, a->c_s, &r->c) : QD_EXIT_OK;
    for (size_t k = 0; rc == QD_EXIT_OK && k < a->n; k++)
        rc = rel_particle(r->ctx, r->c, "--particle", a->particle[k], &r->in[k]);
    if (rc == QD_EXIT_OK && a->angle)
        rc = rel_read(r->ctx, r->c, "--angle", a->angle, false, NULL, &r->theta);
    if (rc == QD_EXIT_OK && a->cm_angle)
        rc = rel_read(r->ctx, r->c, "--cm-angle", a->cm_angle, false, NULL, &r->chi[0]);
    if (rc == QD_EXIT_OK && a->azimuth)
        rc = rel_read(r->ctx, r->c, "--azimuth", a->azimuth, false, NULL, &r->phi);
    if (rc == QD_EXIT_OK && a->threshold)
        rc = read_masses(r, "--threshold", a->threshold, 1);
    if (rc == QD_EXIT_OK && a->decay)
        rc = read_masses(r, "--decay", a->decay, 2);
    if (rc == QD_EXIT_OK && a->decay && r->nprod != 2) {
        cli_diag_error("--decay takes the two products' masses, not '%s'", a->decay);
        rc = QD_EXIT_USAGE;
    }
    return rc;
}

/* The largest imbalance of E and p between in (n) and out (2). */
static int balance(cl_run *r, const qd_rel_particle *in, size_t n, const qd_rel_particle *out) {
    qd_rel_particle a, b;
    int rc = lib(r, qd_rel_total(r->ctx, r->c, n, in, &a));
    if (rc == QD_EXIT_OK)
        rc = lib(r, qd_rel_total(r->ctx, r->c, 2, out, &b));
    if (rc == QD_EXIT_OK) {
        r->err = fmax(r->err, fabs(a.E - b.E));
        for (int i = 0; i < 3; i++)
            r->err = fmax(r->err, fabs(a.p[i] - b.p[i]) * r->c);
    }
    return rc;
}

static int elastic(cl_run *r, const cl_args *a) {
    int rc = QD_EXIT_OK;
    if (a->angle)
        rc = lib(r, qd_rel_elastic_lab(r->ctx, r->c, r->in, r->theta, r->chi, &r->nsol));
    else
        r->nsol = 1;
    for (size_t k = 0; rc == QD_EXIT_OK && k < r->nsol; k++) {
        rc = lib(r, qd_rel_elastic(r->ctx, r->c, r->in, r->chi[k], a->angle ? 0 : r->phi,
                                   r->out[k]));
        if (rc == QD_EXIT_OK)
            rc = balance(r, r->in, 2, r->out[k]);
    }
    return rc;
}

static int compute(cl_run *r, const cl_args *a) {
    int rc = lib(r, qd_rel_total(r->ctx, r->c, a->n, r->in, &r->tot));
    if (rc == QD_EXIT_OK && a->elastic)
        rc = elastic(r, a);
    for (size_t k = 0; a->threshold && k < r->nprod; k++)
        r->prod_mass += r->prod[k];
    if (rc == QD_EXIT_OK && a->threshold)
        rc = lib(r, qd_rel_threshold_of(r->ctx, r->c, r->in[0].m, r->in[1].m, r->prod_mass,
                                        &r->th));
    if (rc == QD_EXIT_OK && a->decay) {
        r->nsol = 1;
        rc = lib(r, qd_rel_decay(r->ctx, r->c, &r->in[0], r->prod[0], r->prod[1], r->chi[0],
                                 r->phi, r->out[0], &r->pstar));
        if (rc == QD_EXIT_OK)
            rc = balance(r, r->in, 1, r->out[0]);
    }
    return rc;
}

static void num(qd_json *j, const char *key, double x) {
    qd_json_key(j, key);
    qd_json_number(j, x);
}

static void json_final(const cl_run *r, const cl_args *a, qd_json *j) {
    qd_json_key(j, a->decay ? "products" : "final");
    qd_json_begin_array(j);
    for (size_t k = 0; k < r->nsol; k++) {
        qd_json_begin_object(j);
        num(j, "cm_angle", r->chi[k]);
        double lab[2] = {qd_rel_lab_angle(r->in, r->out[k], 0),
                         qd_rel_lab_angle(r->in, r->out[k], 1)};
        if (!a->decay)
            rel_json_vec(j, "lab_angles", lab, 2);
        qd_json_key(j, "particles");
        qd_json_begin_array(j);
        rel_json_particle(j, &r->out[k][0]);
        rel_json_particle(j, &r->out[k][1]);
        qd_json_end_array(j);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
    num(j, "conservation_error", r->err);
    if (a->decay)
        num(j, "pstar", r->pstar);
}

static void write_json(const cl_run *r, const cl_args *a, qd_buf *b) {
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    num(&j, "c", r->c);
    qd_json_key(&j, "particles");
    qd_json_begin_array(&j);
    for (size_t k = 0; k < a->n; k++)
        rel_json_particle(&j, &r->in[k]);
    qd_json_end_array(&j);
    num(&j, "energy", r->tot.E);
    rel_json_vec(&j, "momentum", r->tot.p, 3);
    num(&j, "invariant_mass", r->tot.m);
    rel_json_vec(&j, "velocity", r->tot.v, 3);
    if (a->merge) {
        qd_json_key(&j, "merged");
        rel_json_particle(&j, &r->tot);
    }
    if (a->elastic || a->decay)
        json_final(r, a, &j);
    if (a->threshold) {
        qd_json_key(&j, "threshold");
        qd_json_begin_object(&j);
        num(&j, "products_mass", r->prod_mass);
        num(&j, "kinetic_energy", r->th.K);
        num(&j, "energy", r->th.E);
        num(&j, "speed", r->th.speed);
        qd_json_key(&j, "allowed");
        qd_json_bool(&j, r->tot.m >= r->prod_mass);
        qd_json_end_object(&j);
    }
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    b->failed = b->failed || !qd_json_ok(&j);
}

static void value(qd_buf *b, const char *label, double x) {
    qd_buf_puts(b, label);
    cli_state_put_result(b, x);
}

static void text_final(const cl_run *r, const cl_args *a, qd_buf *b) {
    if (a->elastic && !r->nsol)
        value(b, "no elastic final state: particle 1 never leaves at the lab angle ", r->theta);
    if (a->decay)
        value(b, "decay: momentum in the parent's rest frame p* = ", r->pstar);
    if (a->decay || (a->elastic && !r->nsol))
        qd_buf_puts(b, "\n");
    for (size_t k = 0; k < r->nsol; k++) {
        value(b, a->decay ? "products at the rest-frame angle " : "elastic: centre-of-momentum angle ",
              r->chi[k]);
        if (!a->decay) {
            value(b, ", lab angles ", qd_rel_lab_angle(r->in, r->out[k], 0));
            value(b, " and ", qd_rel_lab_angle(r->in, r->out[k], 1));
        }
        qd_buf_puts(b, "\n");
        rel_text_particle(b, "  1", &r->out[k][0]);
        rel_text_particle(b, "  2", &r->out[k][1]);
    }
    if (r->nsol)
        qd_buf_printf(b, "four-momentum conserved to %.2g\n", r->err);
}

static void write_text(const cl_run *r, const cl_args *a, qd_buf *b) {
    char label[32];
    value(b, "c = ", r->c);
    qd_buf_puts(b, "\n");
    for (size_t k = 0; k < a->n; k++) {
        snprintf(label, sizeof label, "particle %zu", k + 1);
        rel_text_particle(b, label, &r->in[k]);
    }
    value(b, "total: E = ", r->tot.E);
    qd_buf_puts(b, ", p = ");
    rel_put_vec(b, r->tot.p, 3);
    value(b, "\ninvariant mass M = sqrt(E^2 - p^2 c^2)/c^2 = ", r->tot.m);
    qd_buf_puts(b, "\ncentre-of-momentum velocity V = p c^2/E = ");
    rel_put_vec(b, r->tot.v, 3);
    qd_buf_puts(b, "\n");
    if (a->merge)
        rel_text_particle(b, "merged (perfectly inelastic)", &r->tot);
    text_final(r, a, b);
    if (a->threshold) {
        value(b, "threshold on particle 2 at rest for products of mass ", r->prod_mass);
        value(b, ": kinetic energy K = ", r->th.K);
        value(b, ", E = ", r->th.E);
        value(b, ", speed ", r->th.speed);
        qd_buf_printf(b, "\n  this collision is %s threshold\n",
                      r->tot.m >= r->prod_mass ? "at or above" : "below");
    }
}

int cli_cmd_collide(int argc, char **argv) {
    cl_args a = {0};
    int rc = parse_args(argc, argv, &a);
    if (rc != QD_EXIT_OK)
        return rc;
    cl_run *r = calloc(1, sizeof *r);
    if (!r || !(r->ctx = qd_ctx_new())) {
        free(r);
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    r->c = 1;
    rc = read_inputs(r, &a);
    if (rc == QD_EXIT_OK)
        rc = compute(r, &a);
    if (rc == QD_EXIT_OK) {
        qd_buf b = QD_BUF_INIT;
        if (a.json)
            write_json(r, &a, &b);
        else
            write_text(r, &a, &b);
        rc = cli_emit(&b, "collision");
    }
    qd_ctx_free(r->ctx);
    free(r);
    return rc;
}
