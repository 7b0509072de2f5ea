/*
 * src/rel/collide.c - collisions and decays by the conservation of
 * four-momentum (Desloge vol. 2 ch. 88-91; reference seed-desloge-D.md C7,
 * T16, pitfall P11: rest mass is not additive).
 *
 * Every final state is built in the centre-of-momentum frame, where the
 * two momenta are opposite and the energies are fixed by the masses, and
 * boosted back to the lab by -V_cm (a pure boost's inverse), so energy and
 * momentum balance to round-off by construction.
 */
#include "base/args.h"
#include "rel.h"

#include <math.h>
#include <string.h>

#define PI 3.14159265358979323846 /* M_PI is not C11 */

qd_status qd_rel_particle_make(qd_ctx *ctx, double c, double m, const double v[3],
                               qd_rel_particle *out) {
    QD_ARGS_CTX(ctx, ctx && v && out);
    *out = (qd_rel_particle){.m = m};
    memcpy(out->v, v, sizeof out->v);
    return qd_rel_momentum(ctx, c, m, v, &out->E, out->p);
}

qd_status qd_rel_particle_from_momentum(qd_ctx *ctx, double c, double E, const double p[3],
                                        qd_rel_particle *out) {
    QD_ARGS_CTX(ctx, ctx && p && out);
    *out = (qd_rel_particle){.E = E};
    memcpy(out->p, p, sizeof out->p);
    qd_status st = qd_rel_mass(ctx, c, E, p, &out->m);
    for (int i = 0; st == QD_OK && i < 3; i++)
        out->v[i] = p[i] * c * c / E;
    return st;
}

qd_status qd_rel_total(qd_ctx *ctx, double c, size_t n, const qd_rel_particle *in,
                       qd_rel_particle *out) {
    QD_ARGS_CTX(ctx, ctx && (n == 0 || in) && out);
    double E = 0, p[3] = {0, 0, 0};
    for (size_t k = 0; k < n; k++) {
        E += in[k].E;
        for (int i = 0; i < 3; i++)
            p[i] += in[k].p[i];
    }
    return qd_rel_particle_from_momentum(ctx, c, E, p, out);
}

/* e2, e3: an orthonormal pair perpendicular to the unit e1, e2 from the
 * first axis least aligned with e1. */
static void perpendicular(const double e1[3], double e2[3], double e3[3]) {
    int a = 0;
    for (int i = 1; i < 3; i++)
        if (fabs(e1[i]) < fabs(e1[a]))
            a = i;
    double x[3] = {0, 0, 0};
    x[a] = 1;
    double d = qd__rel_dot(x, e1), len = 0;
    for (int i = 0; i < 3; i++) {
        e2[i] = x[i] - d * e1[i];
        len += e2[i] * e2[i];
    }
    for (int i = 0; i < 3; i++)
        e2[i] /= sqrt(len);
    e3[0] = e1[1] * e2[2] - e1[2] * e2[1];
    e3[1] = e1[2] * e2[0] - e1[0] * e2[2];
    e3[2] = e1[0] * e2[1] - e1[1] * e2[0];
}

/* The unit vector at chi from e1 (unit), azimuth phi about it. */
static void direction(const double e1[3], double chi, double phi, double out[3]) {
    double e2[3], e3[3];
    perpendicular(e1, e2, e3);
    for (int i = 0; i < 3; i++)
        out[i] = cos(chi) * e1[i] + sin(chi) * (cos(phi) * e2[i] + sin(phi) * e3[i]);
}

/* Particle of mass m with (E, p) in the frame moving with W, in the lab. */
static qd_status to_lab(qd_ctx *ctx, double c, const double W[3], double m, double E,
                        const double p[3], qd_rel_particle *out) {
    double mW[3] = {-W[0], -W[1], -W[2]};
    *out = (qd_rel_particle){.m = m};
    qd_status st = qd_lorentz_momentum(ctx, c, mW, E, p, &out->E, out->p);
    for (int i = 0; st == QD_OK && i < 3; i++)
        out->v[i] = out->p[i] * c * c / out->E;
    return st;
}

static bool angle_ok(qd_ctx *ctx, double chi, double phi) {
    if (chi >= 0 && chi <= PI && isfinite(phi))
        return true;
    qd_ctx_error(ctx, QD_ERR_ARG,
                 "the centre-of-momentum angle must lie in [0, pi] and the azimuth be finite "
                 "(chi = %g, phi = %g)", chi, phi);
    return false;
}

qd_status qd_rel_elastic(qd_ctx *ctx, double c, const qd_rel_particle in[2], double chi,
                         double phi, qd_rel_particle out[2]) {
    QD_ARGS_CTX(ctx, ctx && in && out);
    if (!angle_ok(ctx, chi, phi))
        return QD_ERR_ARG;
    qd_rel_particle tot;
    qd_status st = qd_rel_total(ctx, c, 2, in, &tot);
    double E1, p1[3], E2, p2[3];
    if (st == QD_OK)
        st = qd_lorentz_momentum(ctx, c, tot.v, in[0].E, in[0].p, &E1, p1);
    if (st == QD_OK)
        st = qd_lorentz_momentum(ctx, c, tot.v, in[1].E, in[1].p, &E2, p2);
    if (st != QD_OK)
        return st;
    double ps = sqrt(qd__rel_dot(p1, p1));
    if (!(ps > 0)) { /* at rest together in the CM frame: nothing happens */
        out[0] = in[0];
        out[1] = in[1];
        return QD_OK;
    }
    double e1[3] = {p1[0] / ps, p1[1] / ps, p1[2] / ps}, d[3];
    direction(e1, chi, phi, d);
    for (int i = 0; i < 3; i++) {
        p1[i] = ps * d[i];
        p2[i] = -p1[i];
    }
    st = to_lab(ctx, c, tot.v, in[0].m, E1, p1, &out[0]);
    return st == QD_OK ? to_lab(ctx, c, tot.v, in[1].m, E2, p2, &out[1]) : st;
}

double qd_rel_lab_angle(const qd_rel_particle in[2], const qd_rel_particle out[2], unsigned k) {
    QD_ARGS(NAN, in && out);
    double u[3], x[3];
    for (int i = 0; i < 3; i++)
        u[i] = in[0].v[i] - in[1].v[i];
    const double *w = out[k ? 1 : 0].v;
    x[0] = u[1] * w[2] - u[2] * w[1];
    x[1] = u[2] * w[0] - u[0] * w[2];
    x[2] = u[0] * w[1] - u[1] * w[0];
    return atan2(sqrt(qd__rel_dot(x, x)), qd__rel_dot(u, w));
}

#define LAB_SCAN 720

/* lab angle of particle 1 at CM angle chi, minus theta */
static qd_status lab_miss(qd_ctx *ctx, double c, const qd_rel_particle in[2], double chi,
                          double theta, double *f) {
    qd_rel_particle out[2];
    qd_status st = qd_rel_elastic(ctx, c, in, chi, 0, out);
    if (st == QD_OK)
        *f = qd_rel_lab_angle(in, out, 0) - theta;
    return st;
}

qd_status qd_rel_elastic_lab(qd_ctx *ctx, double c, const qd_rel_particle in[2], double theta,
                             double chi[2], size_t *count) {
    QD_ARGS_CTX(ctx, ctx && in && chi && count);
    *count = 0;
    if (!(theta >= 0 && theta <= PI)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the lab angle must lie in [0, pi], not %g", theta);
        return QD_ERR_ARG;
    }
    double a = 0, fa;
    qd_status st = lab_miss(ctx, c, in, a, theta, &fa);
    for (int s = 1; st == QD_OK && s <= LAB_SCAN && *count < 2; s++) {
        double b = PI * s / LAB_SCAN, fb;
        if ((st = lab_miss(ctx, c, in, b, theta, &fb)) != QD_OK)
            break;
        if (fa == 0 || (fa < 0) != (fb < 0)) { /* a root in [a, b): bisect */
            double lo = a, hi = b, flo = fa;
            for (int it = 0; it < 200 && hi - lo > 1e-15 && flo != 0; it++) {
                double mid = (lo + hi) / 2, fm;
                if ((st = lab_miss(ctx, c, in, mid, theta, &fm)) != QD_OK)
                    break;
                if ((fm < 0) == (flo < 0) && fm != 0)
                    lo = mid, flo = fm;
                else
                    hi = mid;
            }
            double root = flo == 0 ? lo : (lo + hi) / 2, fr;
            if (st == QD_OK && (st = lab_miss(ctx, c, in, root, theta, &fr)) == QD_OK &&
                fabs(fr) < 1e-9) /* a jump (particle 1 at rest in the lab) is no root */
                chi[(*count)++] = root;
        } else if (s == LAB_SCAN && fb == 0) {
            chi[(*count)++] = b;
        }
        a = b, fa = fb;
    }
    return st;
}

qd_status qd_rel_threshold_of(qd_ctx *ctx, double c, double m_a, double m_b, double M,
                              qd_rel_threshold *out) {
    QD_ARGS_CTX(ctx, ctx && out);
    *out = (qd_rel_threshold){0};
    if (!(c > 0) || !(m_a >= 0) || !(m_b > 0) || !(M >= 0) || !isfinite(c + m_a + m_b + M)) {
        qd_ctx_error(ctx, QD_ERR_ARG,
                     "a threshold needs c > 0, a projectile mass >= 0, a target mass > 0 (at "
                     "rest) and products' masses >= 0");
        return QD_ERR_ARG;
    }
    double c2 = c * c, K = (M - m_a - m_b) * (M + m_a + m_b) * c2 / (2 * m_b);
    out->K = fmax(K, 0);
    out->E = m_a * c2 + out->K;
    double r = out->E > 0 ? m_a * c2 / out->E : 0;
    out->speed = c * sqrt(fmax(0, (1 - r) * (1 + r)));
    return QD_OK;
}

qd_status qd_rel_decay(qd_ctx *ctx, double c, const qd_rel_particle *parent, double m1,
                       double m2, double chi, double phi, qd_rel_particle out[2],
                       double *pstar) {
    QD_ARGS_CTX(ctx, ctx && parent && out && pstar);
    double M = parent->m;
    if (!(m1 >= 0) || !(m2 >= 0) || !(M > m1 + m2) || !isfinite(M)) {
        qd_ctx_error(ctx, QD_ERR_ARG,
                     "a decay needs product masses >= 0 with m1 + m2 below the parent's mass "
                     "(%g + %g against %g)", m1, m2, M);
        return QD_ERR_ARG;
    }
    if (!angle_ok(ctx, chi, phi))
        return QD_ERR_ARG;
    qd_status st = qd__rel_check(ctx, c, parent->v, "the parent's velocity");
    if (st != QD_OK)
        return st;
    double c2 = c * c, sp = sqrt(qd__rel_dot(parent->v, parent->v));
    double ps = c * sqrt((M - m1 - m2) * (M + m1 + m2) * (M - m1 + m2) * (M + m1 - m2)) / (2 * M);
    double E1 = (M * M + m1 * m1 - m2 * m2) * c2 / (2 * M), E2 = M * c2 - E1;
    double e1[3] = {1, 0, 0}, d[3], p1[3], p2[3];
    for (int i = 0; sp > 0 && i < 3; i++)
        e1[i] = parent->v[i] / sp;
    direction(e1, chi, phi, d);
    for (int i = 0; i < 3; i++) {
        p1[i] = ps * d[i];
        p2[i] = -p1[i];
    }
    *pstar = ps;
    st = to_lab(ctx, c, parent->v, m1, E1, p1, &out[0]);
    return st == QD_OK ? to_lab(ctx, c, parent->v, m2, E2, p2, &out[1]) : st;
}
