/*
 * src/rel/lorentz.c - the Lorentz transformation in Desloge's general vector
 * form (vol. 2 ch. 86 eqs 6-7, 30, 44; ch. 88 eq 53; ch. 90 eq 2; ch. 91):
 * events, velocities, accelerations, four-momenta, the 4x4 boost on
 * (x, y, z, c t) and its metric check (qdot/relativity.h).
 *
 * (Gamma - 1)(r.V)V/V^2 is written k (r.V) V with k = Gamma^2/((Gamma + 1) c^2),
 * equal to (Gamma - 1)/V^2 and finite at V = 0, so the identity frame needs
 * no special case and small V loses no digits.
 */
#include "base/args.h"
#include "rel.h"

#include <math.h>

double qd__rel_dot(const double a[3], const double b[3]) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

qd_status qd__rel_check(qd_ctx *ctx, double c, const double v[3], const char *what) {
    if (!(c > 0) || !isfinite(c)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the speed of light c must be a positive number, not %g", c);
        return QD_ERR_ARG;
    }
    double v2 = qd__rel_dot(v, v);
    if (!isfinite(v2)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "%s is not finite", what);
        return QD_ERR_ARG;
    }
    if (v2 >= c * c) {
        qd_ctx_error(ctx, QD_ERR_ARG,
                     "%s has speed %.17g, not below c = %.17g: no frame or particle moves at or "
                     "beyond the speed of light (Desloge ch. 85, postulate III)", what, sqrt(v2), c);
        return QD_ERR_ARG;
    }
    return QD_OK;
}

void qd__rel_gk(double c, const double V[3], double *G, double *k) {
    double b2 = qd__rel_dot(V, V) / (c * c);
    *G = 1 / sqrt(1 - b2);
    *k = *G * *G / ((*G + 1) * c * c);
}

qd_status qd_rel_gamma(qd_ctx *ctx, double c, const double v[3], double *gamma) {
    QD_ARGS_CTX(ctx, ctx && v && gamma);
    qd_status st = qd__rel_check(ctx, c, v, "the velocity");
    double k;
    if (st == QD_OK)
        qd__rel_gk(c, v, gamma, &k);
    return st;
}

qd_status qd_lorentz_event(qd_ctx *ctx, double c, const double V[3], const double ev[4],
                           double out[4]) {
    QD_ARGS_CTX(ctx, ctx && V && ev && out);
    qd_status st = qd__rel_check(ctx, c, V, "the frame velocity V");
    if (st != QD_OK)
        return st;
    double G, k, t = ev[0];
    const double *r = ev + 1;
    qd__rel_gk(c, V, &G, &k);
    double rV = qd__rel_dot(r, V);
    for (int i = 0; i < 3; i++)
        out[1 + i] = r[i] + k * rV * V[i] - G * V[i] * t;
    out[0] = G * (t - rV / (c * c));
    return QD_OK;
}

qd_status qd_lorentz_velocity(qd_ctx *ctx, double c, const double V[3], const double v[3],
                              double out[3]) {
    QD_ARGS_CTX(ctx, ctx && V && v && out);
    qd_status st = qd__rel_check(ctx, c, V, "the frame velocity V");
    if (st == QD_OK)
        st = qd__rel_check(ctx, c, v, "the velocity v");
    if (st != QD_OK)
        return st;
    double G, k, vV = qd__rel_dot(v, V);
    qd__rel_gk(c, V, &G, &k);
    double den = G * (1 - vV / (c * c));
    for (int i = 0; i < 3; i++)
        out[i] = (v[i] + k * vV * V[i] - G * V[i]) / den;
    return QD_OK;
}

qd_status qd_lorentz_acceleration(qd_ctx *ctx, double c, const double V[3], const double v[3],
                                  const double a[3], double out[3]) {
    QD_ARGS_CTX(ctx, ctx && V && v && a && out);
    qd_status st = qd__rel_check(ctx, c, V, "the frame velocity V");
    if (st == QD_OK)
        st = qd__rel_check(ctx, c, v, "the velocity v");
    if (st != QD_OK)
        return st;
    double G, k, s = 1 - qd__rel_dot(v, V) / (c * c), Va = qd__rel_dot(V, a);
    qd__rel_gk(c, V, &G, &k);
    double den = G * G * s * s * s;
    for (int i = 0; i < 3; i++) /* (1 - G)/(G V^2) = -k/G */
        out[i] = (s * a[i] + (-k / G * V[i] + v[i] / (c * c)) * Va) / den;
    return QD_OK;
}

qd_status qd_lorentz_momentum(qd_ctx *ctx, double c, const double V[3], double E,
                              const double p[3], double *E_out, double p_out[3]) {
    QD_ARGS_CTX(ctx, ctx && V && p && E_out && p_out);
    qd_status st = qd__rel_check(ctx, c, V, "the frame velocity V");
    if (st != QD_OK)
        return st;
    double G, k, pV = qd__rel_dot(p, V);
    qd__rel_gk(c, V, &G, &k);
    for (int i = 0; i < 3; i++)
        p_out[i] = p[i] + k * pV * V[i] - G * E * V[i] / (c * c);
    *E_out = G * (E - pV);
    return QD_OK;
}

qd_status qd_lorentz_boost(qd_ctx *ctx, double c, const double V[3], double O[16]) {
    QD_ARGS_CTX(ctx, ctx && V && O);
    qd_status st = qd__rel_check(ctx, c, V, "the frame velocity V");
    if (st != QD_OK)
        return st;
    double G, k;
    qd__rel_gk(c, V, &G, &k);
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++)
            O[4 * i + j] = (i == j) + k * V[i] * V[j];
        O[4 * i + 3] = O[12 + i] = -G * V[i] / c;
    }
    O[15] = G;
    return QD_OK;
}

double qd_lorentz_metric_error(const double O[16]) {
    QD_ARGS(NAN, O);
    static const double g[4] = {1, 1, 1, -1};
    double err = 0;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double s = 0;
            for (int l = 0; l < 4; l++)
                s += O[4 * l + i] * g[l] * O[4 * l + j];
            err = fmax(err, fabs(s - (i == j) * g[i]));
        }
    return err;
}

qd_status qd_rel_momentum(qd_ctx *ctx, double c, double m, const double v[3], double *E,
                          double p[3]) {
    QD_ARGS_CTX(ctx, ctx && v && E && p);
    qd_status st = qd__rel_check(ctx, c, v, "the velocity v");
    if (st == QD_OK && !(m >= 0 && isfinite(m))) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the rest mass must be a number >= 0, not %g", m);
        st = QD_ERR_ARG;
    }
    if (st != QD_OK)
        return st;
    double G, k;
    qd__rel_gk(c, v, &G, &k);
    for (int i = 0; i < 3; i++)
        p[i] = m * G * v[i];
    *E = m * G * c * c;
    return QD_OK;
}

qd_status qd_rel_mass(qd_ctx *ctx, double c, double E, const double p[3], double *m) {
    QD_ARGS_CTX(ctx, ctx && p && m);
    double pc = sqrt(qd__rel_dot(p, p)) * c;
    if (!(c > 0) || !isfinite(c) || !(E > 0) || !isfinite(E) || !isfinite(pc)) {
        qd_ctx_error(ctx, QD_ERR_ARG,
                     "a four-momentum needs E > 0 and finite p, and c > 0 (E = %g, c = %g)", E, c);
        return QD_ERR_ARG;
    }
    double m2 = (E - pc) * (E + pc); /* E^2 - p^2 c^2 without the cancellation of squares */
    if (m2 < -1e-12 * E * E) {
        qd_ctx_error(ctx, QD_ERR_ARG,
                     "E = %.17g is below |p| c = %.17g: no particle has this four-momentum "
                     "(E^2 = p^2 c^2 + m^2 c^4, Desloge ch. 90)", E, pc);
        return QD_ERR_ARG;
    }
    *m = sqrt(fmax(m2, 0)) / (c * c);
    return QD_OK;
}

qd_status qd_rel_compose(qd_ctx *ctx, double c, const double u[3], const double v[3],
                         double w[3]) {
    QD_ARGS_CTX(ctx, ctx && u && v && w);
    qd_status st = qd__rel_check(ctx, c, u, "the frame velocity u");
    if (st == QD_OK)
        st = qd__rel_check(ctx, c, v, "the velocity v");
    if (st != QD_OK)
        return st;
    double G, k, uv = qd__rel_dot(u, v);
    qd__rel_gk(c, u, &G, &k);
    double den = G * (1 + uv / (c * c));
    for (int i = 0; i < 3; i++) /* the boost by -u of ch. 86 eq 30 */
        w[i] = (v[i] + k * uv * u[i] + G * u[i]) / den;
    return QD_OK;
}

qd_status qd_rel_wigner_angle(qd_ctx *ctx, double c, const double u[3], const double v[3],
                              double *angle) {
    QD_ARGS_CTX(ctx, ctx && u && v && angle);
    double a[3], b[3];
    qd_status st = qd_rel_compose(ctx, c, u, v, a);
    if (st == QD_OK)
        st = qd_rel_compose(ctx, c, v, u, b);
    if (st != QD_OK)
        return st;
    double x[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                   a[0] * b[1] - a[1] * b[0]};
    *angle = atan2(sqrt(qd__rel_dot(x, x)), qd__rel_dot(a, b));
    return QD_OK;
}

qd_status qd_rel_dilate(qd_ctx *ctx, double c, const double V[3], double dtau, double *dt) {
    QD_ARGS_CTX(ctx, ctx && V && dt);
    double G;
    qd_status st = qd_rel_gamma(ctx, c, V, &G);
    if (st == QD_OK)
        *dt = G * dtau;
    return st;
}

qd_status qd_rel_contract(qd_ctx *ctx, double c, const double V[3], const double d[3],
                          double out[3]) {
    QD_ARGS_CTX(ctx, ctx && V && d && out);
    double G;
    qd_status st = qd_rel_gamma(ctx, c, V, &G);
    if (st != QD_OK)
        return st;
    double V2 = qd__rel_dot(V, V), dV = qd__rel_dot(d, V);
    for (int i = 0; i < 3; i++) /* d - (1 - 1/G) d_par */
        out[i] = V2 > 0 ? d[i] - (1 - 1 / G) * dV / V2 * V[i] : d[i];
    return QD_OK;
}
