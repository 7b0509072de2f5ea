/*
 * src/impulse/collision.c - two bodies meeting, described in the lab and
 * in the centre-of-mass frame (Desloge ch. 61; seed-desloge-B C5).
 *
 * The centre-of-mass velocity w = (m1 v1 + m2 v2)/(m1 + m2) does not change
 * in the collision (the impulses are internal); the relative velocity
 * u = v1 - v2 turns by the CM angle theta and its energy
 * eps = m1 m2 |u|^2 / (2 (m1 + m2)) drops by the energy lost.  Body 1's
 * velocity after is w + s* n (n a unit vector, s* its CM speed), so with
 * gamma = |w|/s* and body 2 at rest before, tan theta_lab1 =
 * sin theta/(cos theta + gamma).  The lab energy of translation is the
 * centre of mass's, (m1 + m2) |w|^2/2, plus eps (Koenig), and body 1's CM
 * speed s = m2 |u|/(m1 + m2) goes to s* with s*^2 = s^2 eps+/eps- (the
 * map between the energies in the two frames).  The velocities are those
 * of the centres of mass: the time derivatives of the positions, at the
 * frozen configuration with the velocities before and after.
 */
#include "impulse_priv.h"

#include <math.h>

/* Mass element i: particles first, then bodies. */
static const qd_expr *mass_of(const qd_model *m, size_t i) {
    size_t np = qd_model_nparticles(m);
    return i < np ? qd_model_particle_mass(m, i) : qd_model_body_mass(m, i - np);
}

static const qd_expr *position_of(const qd_model *m, size_t i, unsigned k) {
    size_t np = qd_model_nparticles(m);
    return i < np ? qd_model_particle_position(m, i, k) : qd_model_body_position(m, i - np, k);
}

/* The velocity of element i's centre with the velocities v. */
static qd_status velocity(const qd__imp *s, size_t i, const double *v, double out[3]) {
    qd_status st = QD_OK;
    for (unsigned k = 0; k < 3 && st == QD_OK; k++) {
        const qd_expr *p = position_of(s->m, i, k);
        out[k] = 0;
        if (p)
            st = qd__imp_eval(s, qd_dt(s->ctx, p), v, &out[k]);
    }
    return st;
}

static double dot(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* The angle between a and b, in [0, pi]; 0 when either vanishes. */
static double angle(const double *a, const double *b) {
    double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    return atan2(sqrt(dot(c, c)), dot(a, b));
}

static void describe(qd_collision *c) {
    double M = c->m1 + c->m2, mu = c->m1 * c->m2 / M;
    for (unsigned k = 0; k < 3; k++) {
        c->w[k] = (c->m1 * c->v1[0][k] + c->m2 * c->v2[0][k]) / M;
        for (int t = 0; t < 2; t++)
            c->u[t][k] = c->v1[t][k] - c->v2[t][k];
    }
    for (int t = 0; t < 2; t++)
        c->eps[t] = mu * dot(c->u[t], c->u[t]) / 2;
    c->T_cm = M * dot(c->w, c->w) / 2;
    for (int t = 0; t < 2; t++) { /* v1 - w = m2 u/(m1 + m2) */
        double s1[3] = {c->v1[t][0] - c->w[0], c->v1[t][1] - c->w[1], c->v1[t][2] - c->w[2]};
        c->s[t] = sqrt(dot(s1, s1));
    }
    c->theta_cm = angle(c->u[0], c->u[1]);
    c->theta_lab1 = angle(c->u[0], c->v1[1]);
    c->theta_lab2 = angle(c->u[0], c->v2[1]);
    c->gamma = c->s[1] > 0 ? sqrt(dot(c->w, c->w)) / c->s[1] : 0; /* no CM speed after */
}

/* A collision of the two bodies: the impulses are internal, so the total
 * momentum is the same after (w conserved), and they met (u before is not
 * 0).  A blow from outside, a rolling contact with the ground or a fixed
 * pivot changes the momentum: the centre-of-mass frame then describes
 * nothing, and its angles would be meaningless. */
static bool internal(const qd_collision *c) {
    double M = c->m1 + c->m2, p1[3], top = 0;
    for (unsigned k = 0; k < 3; k++) {
        p1[k] = (c->m1 * c->v1[1][k] + c->m2 * c->v2[1][k]) / M - c->w[k];
        top = fmax(top, fmax(fmax(fabs(c->v1[0][k]), fabs(c->v2[0][k])),
                             fmax(fabs(c->v1[1][k]), fabs(c->v2[1][k]))));
    }
    return sqrt(dot(p1, p1)) <= 1e-9 * top && c->eps[0] > 0;
}

/* Only a contact that closes a gap makes the bodies collide: every sudden
 * row holonomic (impact constraint g(q) = 0 between them), none prescribed.
 * A sudden velocity constraint (a rolling contact that grips, a joint made
 * rigid) or Thomson's prescribed velocities leave the momentum alone too,
 * but the centres' relative velocity then does not turn as in a collision
 * and its CM angles describe nothing (issue 33). */
static bool gap_contacts(const qd__imp *s) {
    for (size_t k = s->nheld; k < s->nheld + s->nsudden; k++)
        if (s->row[k].kind != QD_CON_HOLONOMIC)
            return false;
    return s->nsudden > 0 && s->npre == 0;
}

qd_status qd__imp_collision(const qd__imp *s, qd_impulse *r) {
    const qd_model *m = s->m;
    if (qd_model_nparticles(m) + qd_model_nbodies(m) != 2 || !gap_contacts(s))
        return QD_OK;
    qd_collision *c = &r->col;
    qd_status st = qd__imp_eval(s, mass_of(m, 0), r->qd_before, &c->m1);
    if (st == QD_OK)
        st = qd__imp_eval(s, mass_of(m, 1), r->qd_before, &c->m2);
    for (int t = 0; t < 2 && st == QD_OK; t++) {
        const double *v = t ? r->qd_after : r->qd_before;
        st = velocity(s, 0, v, c->v1[t]);
        if (st == QD_OK)
            st = velocity(s, 1, v, c->v2[t]);
    }
    if (st != QD_OK || !(c->m1 + c->m2 > 0))
        return st;
    describe(c);
    r->collision = internal(c);
    return QD_OK;
}
