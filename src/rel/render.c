/*
 * src/rel/render.c - the results of qd_lorentz_run and qd_collide_run as
 * text and JSON (qd_lorentz_render, qd_collide_render; relativity.h): the
 * output of `qdot lorentz` and `qdot collide`, keys as docs/cli.md lists.
 * Text shows computed results by the one digit rule (qd_result_format:
 * 12 digits, 0 at or below 1e-12 of a vector's largest component); JSON
 * every digit.
 */
#include "base/args.h"
#include "rel.h"

#include <math.h>
#include <stdio.h>

#include "qdot/json.h"

static void num(qd_buf *b, double x) { qd_buf_put_result(b, x, 1); }

/* A vector's components against its largest (the digit rule's scale). */
static void vec(qd_buf *b, const double *v, size_t n) {
    double big = 0;
    for (size_t i = 0; i < n; i++)
        big = fmax(big, fabs(v[i]));
    qd_buf_puts(b, "(");
    for (size_t i = 0; i < n; i++) {
        if (i)
            qd_buf_puts(b, ", ");
        qd_buf_put_result(b, v[i], big);
    }
    qd_buf_puts(b, ")");
}

static void value(qd_buf *b, const char *label, double x, const char *after) {
    qd_buf_puts(b, label);
    num(b, x);
    qd_buf_puts(b, after);
}

static void jnum(qd_json *j, const char *key, double x) {
    qd_json_key(j, key);
    qd_json_number(j, x);
}

static void jvec(qd_json *j, const char *key, const double *v, size_t n) {
    if (key)
        qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t i = 0; i < n; i++)
        qd_json_number(j, v[i]);
    qd_json_end_array(j);
}

/* The document closed and checked; QD_ERR_NUMERIC for a non-finite number. */
static qd_status finish(qd_ctx *ctx, qd_json *j, qd_buf *b) {
    qd_json_end_object(j);
    qd_buf_puts(b, "\n");
    if (!qd_json_ok(j) || b->failed) {
        qd_ctx_error(ctx, j->nomem || b->failed ? QD_ERR_NOMEM : QD_ERR_NUMERIC,
                     "the result cannot be written: %s", qd_json_why(j));
        return qd_ctx_status(ctx);
    }
    return QD_OK;
}

/* ---- lorentz ----------------------------------------------------------- */

static void lz_json_frame(const qd_lorentz_in *in, const qd_lorentz_out *o, qd_json *j) {
    jvec(j, "frame", in->frame, 3);
    jnum(j, "gamma", o->gamma);
    qd_json_key(j, "boost");
    qd_json_begin_array(j);
    for (int i = 0; i < 4; i++)
        jvec(j, NULL, o->boost + 4 * i, 4);
    qd_json_end_array(j);
    jnum(j, "metric_error", o->metric_error);
}

static qd_status lz_json(qd_ctx *ctx, const qd_lorentz_in *in, const qd_lorentz_out *o,
                         qd_buf *b) {
    unsigned ask = in->ask;
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    jnum(&j, "c", in->c);
    if (ask & QD_LORENTZ_FRAME)
        lz_json_frame(in, o, &j);
    if (ask & QD_LORENTZ_EVENT)
        jvec(&j, "event", o->event, 4);
    if (ask & QD_LORENTZ_VELOCITY) {
        jvec(&j, "velocity", o->velocity, 3);
        jnum(&j, "particle_gamma", o->particle_gamma);
    }
    if (ask & QD_LORENTZ_ACCELERATION)
        jvec(&j, "acceleration", o->acceleration, 3);
    if (ask & QD_LORENTZ_MOMENTUM) {
        jnum(&j, "energy", o->energy);
        jvec(&j, "momentum", o->momentum, 3);
        jnum(&j, "invariant_mass", o->invariant_mass);
    }
    if (ask & QD_LORENTZ_COMPOSE) {
        jvec(&j, "composed", o->composed, 3);
        jvec(&j, "composed_reverse", o->composed_reverse, 3);
        jnum(&j, "wigner_angle", o->wigner_angle);
    }
    if (ask & QD_LORENTZ_DILATE)
        jnum(&j, "dilated", o->dilated);
    if (ask & QD_LORENTZ_CONTRACT)
        jvec(&j, "contracted", o->contracted, 3);
    if (ask & QD_LORENTZ_PROPER_TIME) {
        jnum(&j, "proper_time", o->tau.tau);
        jnum(&j, "proper_time_error", o->tau.error);
        jnum(&j, "max_speed", o->tau.vmax);
    }
    return finish(ctx, &j, b);
}

static void line(qd_buf *b, const char *label, const double *x, size_t n, const double *y) {
    qd_buf_puts(b, label);
    vec(b, x, n);
    qd_buf_puts(b, " -> ");
    vec(b, y, n);
    qd_buf_puts(b, "\n");
}

static void lz_text_frame(const qd_lorentz_in *in, const qd_lorentz_out *o, qd_buf *b) {
    qd_buf_puts(b, "frame V = ");
    vec(b, in->frame, 3);
    value(b, ", c = ", in->c, "");
    value(b, ", gamma = ", o->gamma, "\nboost on (x, y, z, c t):\n");
    for (int i = 0; i < 4; i++) {
        qd_buf_puts(b, "  ");
        vec(b, o->boost + 4 * i, 4);
        qd_buf_puts(b, "\n");
    }
    qd_buf_printf(b, "O^T g O = g, g = diag(1, 1, 1, -1): max error %.3g\n", o->metric_error);
}

static void lz_text(const qd_lorentz_in *in, const qd_lorentz_out *o, qd_buf *b) {
    unsigned ask = in->ask;
    if (ask & QD_LORENTZ_FRAME)
        lz_text_frame(in, o, b);
    if (ask & QD_LORENTZ_EVENT)
        line(b, "event (t, x, y, z): ", in->event, 4, o->event);
    if (ask & QD_LORENTZ_VELOCITY) {
        line(b, "velocity: ", in->velocity, 3, o->velocity);
        value(b, "  gamma' = ", o->particle_gamma, "\n");
    }
    if (ask & QD_LORENTZ_ACCELERATION)
        line(b, "acceleration: ", in->acceleration, 3, o->acceleration);
    if (ask & QD_LORENTZ_MOMENTUM) {
        const double *p = in->momentum, *q = o->momentum;
        double x[4] = {in->energy, p[0], p[1], p[2]}, y[4] = {o->energy, q[0], q[1], q[2]};
        line(b, "four-momentum (E, px, py, pz): ", x, 4, y);
        value(b, "  invariant mass sqrt(E^2 - p^2 c^2)/c^2 = ", o->invariant_mass, "\n");
    }
    if (ask & QD_LORENTZ_COMPOSE) {
        qd_buf_puts(b, "V (+) v = ");
        vec(b, o->composed, 3);
        qd_buf_puts(b, "\nv (+) V = ");
        vec(b, o->composed_reverse, 3);
        value(b, "\n  angle between them (Thomas-Wigner rotation) = ", o->wigner_angle, "\n");
    }
    if (ask & QD_LORENTZ_DILATE)
        value(b, "dilated: a proper interval of a clock moving with V lasts ", o->dilated, "\n");
    if (ask & QD_LORENTZ_CONTRACT)
        line(b, "contracted (at rest in the moving frame, measured in the rest frame): ",
             in->contract, 3, o->contracted);
    if (ask & QD_LORENTZ_PROPER_TIME) {
        value(b, "proper time = ", o->tau.tau, "");
        qd_buf_printf(b, " (error estimate %.2g; largest speed ", o->tau.error);
        value(b, "", o->tau.vmax, ")\n");
    }
}

qd_status qd_lorentz_render(qd_ctx *ctx, const qd_lorentz_in *in, const qd_lorentz_out *out,
                            bool json, qd_buf *b) {
    QD_ARGS_CTX(ctx, ctx && in && out && b);
    if (json)
        return lz_json(ctx, in, out, b);
    lz_text(in, out, b);
    return b->failed ? (qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory"), QD_ERR_NOMEM) : QD_OK;
}

/* ---- collide ----------------------------------------------------------- */

static void json_particle(qd_json *j, const qd_rel_particle *p) {
    qd_json_begin_object(j);
    jnum(j, "mass", p->m);
    jvec(j, "velocity", p->v, 3);
    jnum(j, "energy", p->E);
    jvec(j, "momentum", p->p, 3);
    qd_json_end_object(j);
}

static void text_particle(qd_buf *b, const char *label, const qd_rel_particle *p) {
    value(b, label, p->m, ", v = ");
    vec(b, p->v, 3);
    value(b, ", E = ", p->E, ", p = ");
    vec(b, p->p, 3);
    qd_buf_puts(b, "\n");
}

static void cl_json_final(const qd_collide_in *in, const qd_collide_out *o, qd_json *j) {
    bool decay = in->final == QD_COLLIDE_DECAY;
    qd_json_key(j, decay ? "products" : "final");
    qd_json_begin_array(j);
    for (size_t k = 0; k < o->nfinal; k++) {
        qd_json_begin_object(j);
        jnum(j, "cm_angle", o->cm_angle[k]);
        if (!decay)
            jvec(j, "lab_angles", o->lab_angles[k], 2);
        qd_json_key(j, "particles");
        qd_json_begin_array(j);
        json_particle(j, &o->final[k][0]);
        json_particle(j, &o->final[k][1]);
        qd_json_end_array(j);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
    jnum(j, "conservation_error", o->conservation_error);
    if (decay)
        jnum(j, "pstar", o->pstar);
}

static qd_status cl_json(qd_ctx *ctx, const qd_collide_in *in, const qd_collide_out *o,
                         qd_buf *b) {
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    jnum(&j, "c", in->c);
    qd_json_key(&j, "particles");
    qd_json_begin_array(&j);
    for (size_t k = 0; k < in->n; k++)
        json_particle(&j, &in->particle[k]);
    qd_json_end_array(&j);
    jnum(&j, "energy", o->total.E);
    jvec(&j, "momentum", o->total.p, 3);
    jnum(&j, "invariant_mass", o->total.m);
    jvec(&j, "velocity", o->total.v, 3);
    if (in->merge) {
        qd_json_key(&j, "merged");
        json_particle(&j, &o->total);
    }
    if (in->final != QD_COLLIDE_NONE)
        cl_json_final(in, o, &j);
    if (in->threshold) {
        qd_json_key(&j, "threshold");
        qd_json_begin_object(&j);
        jnum(&j, "products_mass", o->products_mass);
        jnum(&j, "kinetic_energy", o->threshold.K);
        jnum(&j, "energy", o->threshold.E);
        jnum(&j, "speed", o->threshold.speed);
        qd_json_key(&j, "allowed");
        qd_json_bool(&j, o->allowed);
        qd_json_end_object(&j);
    }
    return finish(ctx, &j, b);
}

static void cl_text_final(const qd_collide_in *in, const qd_collide_out *o, qd_buf *b) {
    bool decay = in->final == QD_COLLIDE_DECAY;
    if (!decay && !o->nfinal)
        value(b, "no elastic final state: particle 1 never leaves at the lab angle ",
              in->lab_angle, "\n");
    if (decay)
        value(b, "decay: momentum in the parent's rest frame p* = ", o->pstar, "\n");
    for (size_t k = 0; k < o->nfinal; k++) {
        value(b, decay ? "products at the rest-frame angle " : "elastic: centre-of-momentum angle ",
              o->cm_angle[k], "");
        if (!decay) {
            value(b, ", lab angles ", o->lab_angles[k][0], "");
            value(b, " and ", o->lab_angles[k][1], "");
        }
        qd_buf_puts(b, "\n");
        text_particle(b, "  1: m = ", &o->final[k][0]);
        text_particle(b, "  2: m = ", &o->final[k][1]);
    }
    if (o->nfinal)
        qd_buf_printf(b, "four-momentum conserved to %.2g\n", o->conservation_error);
}

static void cl_text(const qd_collide_in *in, const qd_collide_out *o, qd_buf *b) {
    value(b, "c = ", in->c, "\n");
    for (size_t k = 0; k < in->n; k++) {
        char label[48];
        snprintf(label, sizeof label, "particle %zu: m = ", k + 1);
        text_particle(b, label, &in->particle[k]);
    }
    value(b, "total: E = ", o->total.E, ", p = ");
    vec(b, o->total.p, 3);
    value(b, "\ninvariant mass M = sqrt(E^2 - p^2 c^2)/c^2 = ", o->total.m,
          "\ncentre-of-momentum velocity V = p c^2/E = ");
    vec(b, o->total.v, 3);
    qd_buf_puts(b, "\n");
    if (in->merge)
        text_particle(b, "merged (perfectly inelastic): m = ", &o->total);
    if (in->final != QD_COLLIDE_NONE)
        cl_text_final(in, o, b);
    if (in->threshold) {
        value(b, "threshold on particle 2 at rest for products of mass ", o->products_mass, "");
        value(b, ": kinetic energy K = ", o->threshold.K, "");
        value(b, ", E = ", o->threshold.E, "");
        value(b, ", speed ", o->threshold.speed, "");
        qd_buf_printf(b, "\n  this collision is %s threshold\n",
                      o->allowed ? "at or above" : "below");
    }
}

qd_status qd_collide_render(qd_ctx *ctx, const qd_collide_in *in, const qd_collide_out *out,
                            bool json, qd_buf *b) {
    QD_ARGS_CTX(ctx, ctx && in && out && b);
    if (json)
        return cl_json(ctx, in, out, b);
    cl_text(in, out, b);
    return b->failed ? (qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory"), QD_ERR_NOMEM) : QD_OK;
}
