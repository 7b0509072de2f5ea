/*
 * src/rel/ask.c - several transformations, or a whole collision, asked at
 * once (qd_lorentz_run, qd_collide_run; relativity.h): the one place that
 * decides which parts need which inputs, for the program and for Python.
 */
#include "base/args.h"
#include "rel.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

qd_status qd__rel_refuse(qd_ctx *ctx, const char *field, const char *fmt, ...) {
    char msg[256];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    qd_ctx_error(ctx, QD_ERR_ARG, "%s", msg);
    qd_ctx_error_about(ctx, QD_SUBJECT_NONE, 0, field, QD_REASON_NONE, NULL);
    return QD_ERR_ARG;
}

/* The parts with V: the frame's own numbers, then each image under it. */
static qd_status boosted(qd_ctx *ctx, const qd_lorentz_in *in, qd_lorentz_out *o) {
    double c = in->c;
    const double *V = in->frame;
    unsigned ask = in->ask;
    qd_status st = qd_lorentz_boost(ctx, c, V, o->boost);
    if (st == QD_OK) {
        o->metric_error = qd_lorentz_metric_error(o->boost);
        st = qd_rel_gamma(ctx, c, V, &o->gamma);
    }
    if (st == QD_OK && (ask & QD_LORENTZ_EVENT))
        st = qd_lorentz_event(ctx, c, V, in->event, o->event);
    if (st == QD_OK && (ask & QD_LORENTZ_VELOCITY))
        st = qd_lorentz_velocity(ctx, c, V, in->velocity, o->velocity);
    if (st == QD_OK && (ask & QD_LORENTZ_VELOCITY))
        st = qd_rel_gamma(ctx, c, o->velocity, &o->particle_gamma);
    if (st == QD_OK && (ask & QD_LORENTZ_ACCELERATION))
        st = qd_lorentz_acceleration(ctx, c, V, in->velocity, in->acceleration, o->acceleration);
    if (st == QD_OK && (ask & QD_LORENTZ_MOMENTUM))
        st = qd_lorentz_momentum(ctx, c, V, in->energy, in->momentum, &o->energy, o->momentum);
    if (st == QD_OK && (ask & QD_LORENTZ_MOMENTUM))
        st = qd_rel_mass(ctx, c, in->energy, in->momentum, &o->invariant_mass);
    if (st == QD_OK && (ask & QD_LORENTZ_COMPOSE))
        st = qd_rel_compose(ctx, c, V, in->compose, o->composed);
    if (st == QD_OK && (ask & QD_LORENTZ_COMPOSE))
        st = qd_rel_compose(ctx, c, in->compose, V, o->composed_reverse);
    if (st == QD_OK && (ask & QD_LORENTZ_COMPOSE))
        st = qd_rel_wigner_angle(ctx, c, V, in->compose, &o->wigner_angle);
    if (st == QD_OK && (ask & QD_LORENTZ_DILATE))
        st = qd_rel_dilate(ctx, c, V, in->dilate, &o->dilated);
    if (st == QD_OK && (ask & QD_LORENTZ_CONTRACT))
        st = qd_rel_contract(ctx, c, V, in->contract, o->contracted);
    return st;
}

qd_status qd_lorentz_run(qd_ctx *ctx, const qd_lorentz_in *in, qd_lorentz_out *out) {
    QD_ARGS_CTX(ctx, ctx && in && out);
    *out = (qd_lorentz_out){.gamma = NAN};
    unsigned ask = in->ask, needs_v = ask & ~(unsigned)QD_LORENTZ_PROPER_TIME;
    if (!ask)
        return qd__rel_refuse(ctx, "frame", "nothing to transform: give the frame velocity V "
                                            "or a worldline for the proper time");
    if (needs_v && !(ask & QD_LORENTZ_FRAME))
        return qd__rel_refuse(ctx, "frame", "the frame velocity V is missing");
    if ((ask & QD_LORENTZ_ACCELERATION) && !(ask & QD_LORENTZ_VELOCITY))
        return qd__rel_refuse(ctx, "acceleration", "an acceleration transforms with the "
                                                   "particle's velocity (ch. 86 eq 44): give it");
    qd_status st = needs_v ? boosted(ctx, in, out) : QD_OK;
    if (st == QD_OK && (ask & QD_LORENTZ_PROPER_TIME))
        st = qd_rel_proper_time(ctx, in->c, in->worldline, in->t0, in->t1, 0, &out->tau);
    return st;
}

/* ---- collisions -------------------------------------------------------- */

/* The largest imbalance of E and p c between in (n) and out (2). */
static qd_status balance(qd_ctx *ctx, double c, const qd_rel_particle *in, size_t n,
                         const qd_rel_particle *fin, double *err) {
    qd_rel_particle a, b;
    qd_status st = qd_rel_total(ctx, c, n, in, &a);
    if (st == QD_OK)
        st = qd_rel_total(ctx, c, 2, fin, &b);
    if (st == QD_OK) {
        *err = fmax(*err, fabs(a.E - b.E));
        for (int i = 0; i < 3; i++)
            *err = fmax(*err, fabs(a.p[i] - b.p[i]) * c);
    }
    return st;
}

static qd_status elastic(qd_ctx *ctx, const qd_collide_in *in, qd_collide_out *o) {
    qd_status st = QD_OK;
    o->nfinal = 1;
    o->cm_angle[0] = in->cm_angle;
    if (in->lab)
        st = qd_rel_elastic_lab(ctx, in->c, in->particle, in->lab_angle, o->cm_angle, &o->nfinal);
    for (size_t k = 0; st == QD_OK && k < o->nfinal; k++) {
        st = qd_rel_elastic(ctx, in->c, in->particle, o->cm_angle[k], in->lab ? 0 : in->azimuth,
                            o->final[k]);
        for (unsigned i = 0; i < 2; i++)
            o->lab_angles[k][i] = qd_rel_lab_angle(in->particle, o->final[k], i);
        if (st == QD_OK)
            st = balance(ctx, in->c, in->particle, 2, o->final[k], &o->conservation_error);
    }
    return st;
}

static qd_status decay(qd_ctx *ctx, const qd_collide_in *in, qd_collide_out *o) {
    if (in->nproducts != 2)
        return qd__rel_refuse(ctx, "decay", "a two-body decay takes the two products' masses, "
                                            "not %zu", in->nproducts);
    o->nfinal = 1;
    o->cm_angle[0] = in->cm_angle;
    qd_status st = qd_rel_decay(ctx, in->c, &in->particle[0], in->product[0], in->product[1],
                                in->cm_angle, in->azimuth, o->final[0], &o->pstar);
    for (unsigned i = 0; st == QD_OK && i < 2; i++)
        o->lab_angles[0][i] = qd_rel_lab_angle(in->particle, o->final[0], i);
    if (st == QD_OK)
        st = balance(ctx, in->c, in->particle, 1, o->final[0], &o->conservation_error);
    return st;
}

static qd_status check_collide(qd_ctx *ctx, const qd_collide_in *in) {
    if (in->n < 1 || in->n > QD_COLLIDE_MAX)
        return qd__rel_refuse(ctx, "particle", "give 1 to %d particles, not %zu", QD_COLLIDE_MAX,
                              in->n);
    if (in->final == QD_COLLIDE_ELASTIC && in->n != 2)
        return qd__rel_refuse(ctx, "elastic", "an elastic collision needs exactly two particles");
    if (in->final == QD_COLLIDE_DECAY && in->n != 1)
        return qd__rel_refuse(ctx, "decay", "a decay needs exactly one particle (the parent)");
    if (in->threshold && in->n != 2)
        return qd__rel_refuse(ctx, "threshold", "a threshold needs exactly two particles (the "
                                                "second is the target)");
    if (in->nproducts > QD_COLLIDE_PRODUCTS || (in->threshold && !in->nproducts))
        return qd__rel_refuse(ctx, in->threshold ? "threshold" : "decay",
                              "takes 1 to %d masses, not %zu", QD_COLLIDE_PRODUCTS,
                              in->nproducts);
    return QD_OK;
}

qd_status qd_collide_run(qd_ctx *ctx, const qd_collide_in *in, qd_collide_out *out) {
    QD_ARGS_CTX(ctx, ctx && in && out);
    *out = (qd_collide_out){.pstar = NAN};
    qd_status st = check_collide(ctx, in);
    if (st == QD_OK)
        st = qd_rel_total(ctx, in->c, in->n, in->particle, &out->total);
    if (st == QD_OK && in->final == QD_COLLIDE_ELASTIC)
        st = elastic(ctx, in, out);
    if (st == QD_OK && in->final == QD_COLLIDE_DECAY)
        st = decay(ctx, in, out);
    if (st == QD_OK && in->threshold) {
        for (size_t k = 0; k < in->nproducts; k++)
            out->products_mass += in->product[k];
        st = qd_rel_threshold_of(ctx, in->c, in->particle[0].m, in->particle[1].m,
                                 out->products_mass, &out->threshold);
        out->allowed = out->total.m >= out->products_mass;
    }
    return st;
}
