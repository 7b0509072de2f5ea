/*
 * src/scatter/lab.c - centre-of-mass angles to the laboratory, target at
 * rest (Desloge ch. 61, eqs. 59-67; seed-desloge-B.md C5).  With s* the
 * projectile's CM speed after the collision and w the CM's speed, the
 * projectile leaves the lab along n + gamma e3 (gamma = w/s*, m1/m2 when
 * elastic) with speed s* sqrt(1 + gamma^2 + 2 gamma cos Theta).
 */
#include "sct.h"
#include "../base/args.h"

#include <math.h>

#define PI 3.14159265358979323846 /* M_PI is not C11 */

void qd_scatter_lab_gamma(double gamma, double theta, double *theta_lab, double *jacobian) {
    QD_ARGS(, theta_lab && jacobian);
    double c = cos(theta), w2 = 1 + gamma * gamma + 2 * gamma * c;
    *theta_lab = atan2(sin(theta), c + gamma);
    /* q = Q (1 + gamma cos)/(w2)^(3/2): dOmega_cm/dOmega_lab = w2^(3/2)/|1 + gamma cos| */
    *jacobian = pow(w2, 1.5) / fabs(1 + gamma * c);
}

qd_status qd_scatter_lab_map(qd_ctx *ctx, double m1, double m2, double theta,
                             qd_scatter_lab *out) {
    QD_ARGS_CTX(ctx, ctx && out);
    if (!(m1 > 0) || !(m2 > 0) || !isfinite(m1) || !isfinite(m2) || !(theta >= 0 && theta <= PI)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the lab frame needs masses > 0 and an angle in [0, pi]");
        return QD_ERR_ARG;
    }
    double g = m1 / m2, M = m1 + m2, half = 0.5 * theta;
    out->gamma = g;
    qd_scatter_lab_gamma(g, theta, &out->theta_lab, &out->jacobian);
    /* v1'^2/v^2 = (m2/M)^2 (1 + g^2 + 2 g cos Theta) */
    out->energy_ratio = (m2 / M) * (m2 / M) * (1 + g * g + 2 * g * cos(theta));
    out->recoil_angle = 0.5 * (PI - theta);
    out->recoil_ratio = 4 * m1 * m2 / (M * M) * sin(half) * sin(half);
    out->recoil_jacobian = 4 * sin(half);
    return QD_OK;
}

static bool maps_to(double gamma, double cm, double theta_lab) {
    double s = sin(cm), c = cos(cm) + gamma;
    return fabs(s) + fabs(c) > 1e-12 && fabs(atan2(s, c) - theta_lab) <= 1e-9;
}

size_t qd_scatter_lab_to_cm(double gamma, double theta_lab, double cm[2]) {
    QD_ARGS(0, cm);
    /* sin(Theta - theta_lab) = gamma sin theta_lab (Desloge eq. 36) */
    double x = gamma * sin(theta_lab);
    if (!(fabs(x) <= 1))
        return 0;
    double a = asin(x);
    size_t n = 0;
    double c1 = theta_lab + a, c2 = theta_lab + PI - a;
    /* a root of the sine relation must map back to theta_lab: gamma = 1
     * beyond pi/2 gives Theta = pi, where the projectile stops (no angle) */
    if (c1 >= 0 && c1 <= PI && maps_to(gamma, c1, theta_lab))
        cm[n++] = c1;
    if (gamma > 1 && c2 >= 0 && c2 <= PI && c2 != c1 && maps_to(gamma, c2, theta_lab))
        cm[n++] = c2;
    return n;
}
