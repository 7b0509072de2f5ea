/*
 * src/rel/text.c - the questions of `qdot lorentz` and `qdot collide` read
 * from the text of their options (qd_lorentz_read, qd_collide_read;
 * relativity.h).  c is read first, since every other value may use it.
 */
#include "base/args.h"
#include "rel.h"

#include <stdlib.h>
#include <string.h>

/* --momentum: "E, px, py, pz" or "m=..., v=(...)". */
static qd_status momentum(qd_ctx *ctx, double c, const char *text, qd_lorentz_in *in) {
    if (strchr(text, '=')) {
        qd_rel_particle pt;
        qd_status st = qd_rel_read_particle(ctx, c, "momentum", text, &pt);
        in->energy = pt.E;
        memcpy(in->momentum, pt.p, sizeof in->momentum);
        return st;
    }
    double x[4] = {0, 0, 0, 0};
    qd_status st = qd_rel_read_numbers(ctx, c, "momentum", text, 4, x);
    in->energy = x[0];
    memcpy(in->momentum, x + 1, sizeof in->momentum);
    return st;
}

/* "T0:T1". */
static qd_status span(qd_ctx *ctx, double c, const char *text, double *t0, double *t1) {
    const char *colon = strchr(text, ':');
    if (!colon)
        return qd__rel_refuse(ctx, "t", "takes T0:T1, not '%s'", text);
    size_t n = (size_t)(colon - text);
    char *a = malloc(n + 1);
    if (!a) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        return QD_ERR_NOMEM;
    }
    memcpy(a, text, n);
    a[n] = '\0';
    qd_status st = qd_rel_read_number(ctx, c, "t", a, t0);
    if (st == QD_OK)
        st = qd_rel_read_number(ctx, c, "t", colon + 1, t1);
    free(a);
    return st;
}

/* A list of n numbers into out, and bit into *ask, when text is given. */
static qd_status part(qd_ctx *ctx, double c, const char *field, const char *text, size_t n,
                      double *out, unsigned bit, unsigned *ask) {
    if (!text)
        return QD_OK;
    *ask |= bit;
    return n == 1 ? qd_rel_read_number(ctx, c, field, text, out)
                  : qd_rel_read_numbers(ctx, c, field, text, n, out);
}

qd_status qd_lorentz_read(qd_ctx *ctx, const qd_lorentz_text *t, qd_lorentz_in *in) {
    QD_ARGS_CTX(ctx, ctx && t && in);
    *in = (qd_lorentz_in){.c = 1};
    qd_status st = t->c ? qd_rel_read_c(ctx, "c", t->c, &in->c) : QD_OK;
    double c = in->c;
    unsigned *ask = &in->ask;
    if (st == QD_OK)
        st = part(ctx, c, "frame", t->frame, 3, in->frame, QD_LORENTZ_FRAME, ask);
    if (st == QD_OK)
        st = part(ctx, c, "event", t->event, 4, in->event, QD_LORENTZ_EVENT, ask);
    if (st == QD_OK)
        st = part(ctx, c, "velocity", t->velocity, 3, in->velocity, QD_LORENTZ_VELOCITY, ask);
    if (st == QD_OK)
        st = part(ctx, c, "acceleration", t->acceleration, 3, in->acceleration,
                  QD_LORENTZ_ACCELERATION, ask);
    if (st == QD_OK && t->momentum) {
        *ask |= QD_LORENTZ_MOMENTUM;
        st = momentum(ctx, c, t->momentum, in);
    }
    if (st == QD_OK)
        st = part(ctx, c, "compose", t->compose, 3, in->compose, QD_LORENTZ_COMPOSE, ask);
    if (st == QD_OK)
        st = part(ctx, c, "dilate", t->dilate, 1, &in->dilate, QD_LORENTZ_DILATE, ask);
    if (st == QD_OK)
        st = part(ctx, c, "contract", t->contract, 3, in->contract, QD_LORENTZ_CONTRACT, ask);
    if (st == QD_OK && !t->proper_time != !t->t)
        st = qd__rel_refuse(ctx, t->t ? "proper_time" : "t",
                            "the proper time needs both the worldline v(t) and the span T0:T1");
    if (st == QD_OK && t->proper_time) {
        *ask |= QD_LORENTZ_PROPER_TIME;
        st = qd__rel_read_exprs(ctx, c, "proper_time", t->proper_time, in->worldline);
        if (st == QD_OK)
            st = span(ctx, c, t->t, &in->t0, &in->t1);
    }
    return st;
}

/* "M1, M2, ...": between min and QD_COLLIDE_PRODUCTS masses. */
static qd_status masses(qd_ctx *ctx, double c, const char *field, const char *text, size_t min,
                        qd_collide_in *in) {
    size_t n = qd__rel_count(text);
    if (n < min || n > QD_COLLIDE_PRODUCTS)
        return qd__rel_refuse(ctx, field, "takes %zu to %d masses, not '%s'", min,
                              QD_COLLIDE_PRODUCTS, text);
    in->nproducts = n;
    return qd_rel_read_numbers(ctx, c, field, text, n, in->product);
}

/* The options that go together. */
static qd_status combine(qd_ctx *ctx, const qd_collide_text *t) {
    if (t->elastic && !t->angle == !t->cm_angle)
        return qd__rel_refuse(ctx, "elastic", "an elastic final state needs one of the lab "
                                              "angle and the centre-of-momentum angle");
    if (t->angle && !t->elastic)
        return qd__rel_refuse(ctx, "angle", "a lab angle goes with an elastic collision");
    if (t->decay && t->elastic)
        return qd__rel_refuse(ctx, "decay", "give either a decay or an elastic collision");
    if (t->cm_angle && !t->elastic && !t->decay)
        return qd__rel_refuse(ctx, "cm_angle", "a centre-of-momentum angle goes with an "
                                               "elastic collision or a decay");
    return QD_OK;
}

qd_status qd_collide_read(qd_ctx *ctx, const qd_collide_text *t, qd_collide_in *in) {
    QD_ARGS_CTX(ctx, ctx && t && in && (t->n == 0 || t->particle));
    *in = (qd_collide_in){.c = 1, .n = t->n, .merge = t->merge, .threshold = t->threshold != NULL};
    in->final = t->elastic ? QD_COLLIDE_ELASTIC : t->decay ? QD_COLLIDE_DECAY : QD_COLLIDE_NONE;
    in->lab = t->angle != NULL;
    if (!t->n || t->n > QD_COLLIDE_MAX)
        return qd__rel_refuse(ctx, "particle", "give 1 to %d particles, not %zu", QD_COLLIDE_MAX,
                              t->n);
    qd_status st = combine(ctx, t);
    if (st == QD_OK && t->c)
        st = qd_rel_read_c(ctx, "c", t->c, &in->c);
    for (size_t k = 0; st == QD_OK && k < t->n; k++)
        st = qd__rel_read_particle(ctx, in->c, "particle", k, t->particle[k], &in->particle[k]);
    if (st == QD_OK && t->angle)
        st = qd_rel_read_number(ctx, in->c, "angle", t->angle, &in->lab_angle);
    if (st == QD_OK && t->cm_angle)
        st = qd_rel_read_number(ctx, in->c, "cm_angle", t->cm_angle, &in->cm_angle);
    if (st == QD_OK && t->azimuth)
        st = qd_rel_read_number(ctx, in->c, "azimuth", t->azimuth, &in->azimuth);
    if (st == QD_OK && t->threshold)
        st = masses(ctx, in->c, "threshold", t->threshold, 1, in);
    if (st == QD_OK && t->decay)
        st = masses(ctx, in->c, "decay", t->decay, 2, in);
    return st;
}
