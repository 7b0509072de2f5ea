/*
 * src/scatter/ask.c - one question of `qdot scatter` (qd_scatter_read,
 * qd_scatter_answer_query; scatter.h): which of b, Theta and the lab angle
 * is asked, the numbers read in the model's parameters, and the lab frame
 * summed over every CM angle that reaches a lab angle (Desloge ch. 61
 * eqs. 36, 67; pitfall 7 of seed-desloge-B.md: both count when m1 > m2).
 */
#include "base/args.h"
#include "sct.h"

#include <math.h>
#include <string.h>

#define PI 3.14159265358979323846 /* M_PI is not C11 */

static qd_status refuse(qd_ctx *ctx, const char *field, const char *msg) {
    qd_ctx_error(ctx, QD_ERR_ARG, "%s", msg);
    qd_ctx_error_about(ctx, QD_SUBJECT_NONE, 0, field, QD_REASON_NONE, NULL);
    return QD_ERR_ARG;
}

static qd_status number(qd_ctx *ctx, const qd_model *m, const char *field, const char *text,
                        double *out) {
    return text ? qd_model_number_field(ctx, m, field, text, 0, strlen(text), out) : QD_OK;
}

/* "m1, m2": two positive masses. */
static qd_status masses(qd_ctx *ctx, const qd_model *m, const char *text, qd_scatter_query *q) {
    const char *comma = strchr(text, ',');
    if (!comma)
        return refuse(ctx, "masses", "takes m1, m2 (projectile, target)");
    size_t cut = (size_t)(comma - text);
    qd_status st = qd_model_number_field(ctx, m, "masses", text, 0, cut, &q->m1);
    if (st == QD_OK)
        st = qd_model_number_field(ctx, m, "masses", text, cut + 1, strlen(comma + 1), &q->m2);
    if (st == QD_OK && !(q->m1 > 0 && q->m2 > 0))
        return refuse(ctx, "masses", "the masses must be positive");
    q->masses = st == QD_OK;
    return st;
}

qd_status qd_scatter_read(qd_ctx *ctx, const qd_model *m, const qd_scatter_text *t,
                          qd_scatter_query *q) {
    QD_ARGS_CTX(ctx, ctx && m && t && q);
    *q = (qd_scatter_query){.theta = NAN, .lab_theta = NAN};
    if (!t->energy)
        return refuse(ctx, "energy", "the energy at infinity is missing");
    if (!!t->b + !!t->theta + !!t->lab_theta != 1)
        return refuse(ctx, t->b && t->theta ? "theta" : t->lab_theta ? "lab_theta" : "b",
                      "give one of the impact parameter, the centre-of-mass angle and the "
                      "laboratory angle");
    if (t->lab_theta && !t->masses)
        return refuse(ctx, "lab_theta", "the laboratory frame depends on the masses: give them");
    q->at = t->b ? QD_SCATTER_AT_B : t->theta ? QD_SCATTER_AT_THETA : QD_SCATTER_AT_LAB;
    qd_status st = number(ctx, m, "energy", t->energy, &q->E);
    if (st == QD_OK)
        st = number(ctx, m, "b", t->b, &q->b);
    if (st == QD_OK)
        st = number(ctx, m, "theta", t->theta, &q->theta);
    if (st == QD_OK)
        st = number(ctx, m, "lab_theta", t->lab_theta, &q->lab_theta);
    if (st == QD_OK && t->lab_theta && !(q->lab_theta > 0 && q->lab_theta < PI))
        return refuse(ctx, "lab_theta", "the laboratory angle must lie in (0, pi)");
    if (st == QD_OK)
        st = number(ctx, m, "core", t->core, &q->core);
    q->absorbing = t->absorbing;
    q->recoil = t->recoil;
    if (st == QD_OK && t->masses)
        st = masses(ctx, m, t->masses, q);
    return st;
}

/* The target recoils at (pi - Theta)/2 whatever the masses (Desloge ch. 61):
 * counted too (identical particles, both detected: Desloge ch. 61 pb. 3, two
 * protons), it adds sigma_cm(pi - 2 theta_lab) dOmega_cm/dOmega_recoil to
 * the lab cross section below pi/2 and nothing beyond. */
static qd_status recoil_sum(qd_ctx *ctx, qd_scatter *s, const qd_scatter_query *q,
                            double theta_lab, qd_scatter_answer *a) {
    a->recoil_sigma = 0;
    if (!(theta_lab < PI / 2))
        return QD_OK;
    qd_scatter_section x;
    qd_scatter_lab l;
    qd_status st = qd_scatter_section_at(ctx, s, q->E, PI - 2 * theta_lab, &x);
    if (st == QD_OK)
        st = qd_scatter_lab_map(ctx, q->m1, q->m2, PI - 2 * theta_lab, &l);
    if (st != QD_OK)
        return st;
    a->recoil_sigma = x.sigma * l.recoil_jacobian;
    a->lab_sigma += a->recoil_sigma;
    return QD_OK;
}

/* The lab cross section at theta_lab: every CM angle that reaches it, each
 * through its Jacobian (ch. 61 eq. 67), the angles into cm (may be NULL). */
static qd_status lab_sum(qd_ctx *ctx, qd_scatter *s, const qd_scatter_query *q, double theta_lab,
                         qd_scatter_answer *a, bool keep) {
    double cm[2], g = q->m1 / q->m2;
    size_t n = qd_scatter_lab_to_cm(g, theta_lab, cm);
    a->lab_sigma = 0;
    a->lab_ncm = n;
    for (size_t k = 0; k < n; k++) {
        qd_scatter_section x;
        double tl, J;
        qd_status st = qd_scatter_section_at(ctx, s, q->E, cm[k], &x);
        if (st != QD_OK)
            return st;
        qd_scatter_lab_gamma(g, cm[k], &tl, &J);
        a->lab_sigma += x.sigma * J;
        if (keep) {
            a->cm[k] = cm[k];
            a->cm_sigma[k] = x.sigma;
            a->cm_jacobian[k] = J;
        }
    }
    if (keep)
        a->ncm = n;
    return q->recoil ? recoil_sum(ctx, s, q, theta_lab, a) : QD_OK;
}

/* With the masses and a CM angle: the projectile's and the target's lab
 * angles and energies, and the lab cross section at that lab angle. */
static qd_status lab_frame(qd_ctx *ctx, qd_scatter *s, const qd_scatter_query *q, double theta,
                           qd_scatter_answer *a) {
    if (!q->masses || !(theta >= 0) ||
        qd_scatter_lab_map(ctx, q->m1, q->m2, theta, &a->lab_map) != QD_OK) {
        qd_ctx_clear_error(ctx); /* no angle (captured): no lab frame to show */
        return QD_OK;
    }
    a->lab = true;
    if (lab_sum(ctx, s, q, a->lab_map.theta_lab, a, false) != QD_OK) {
        qd_ctx_clear_error(ctx); /* at 0 or pi: no cross section there */
        a->lab_sigma = NAN;
    }
    return QD_OK;
}

qd_status qd_scatter_answer_query(qd_ctx *ctx, qd_scatter *s, const qd_scatter_query *q,
                                  qd_scatter_answer *a) {
    QD_ARGS_CTX(ctx, ctx && s && q && a);
    *a = (qd_scatter_answer){.q = *q, .lab_sigma = NAN, .recoil_sigma = NAN};
    a->section.sigma = NAN;
    double theta = q->theta;
    qd_status st = QD_OK;
    qd_scatter_set_absorbing(s, q->absorbing);
    if (q->at == QD_SCATTER_AT_B) {
        st = qd_scatter_deflect(ctx, s, q->E, q->b, &a->path);
        theta = a->path.theta;
        if (st == QD_OK && theta > 1e-12 && theta < PI - 1e-12) /* it leaves at an angle */
            st = qd_scatter_section_at(ctx, s, q->E, theta, &a->section);
    } else if (q->at == QD_SCATTER_AT_THETA) {
        st = qd_scatter_section_at(ctx, s, q->E, theta, &a->section);
    } else {
        st = lab_sum(ctx, s, q, q->lab_theta, a, true);
    }
    if (st == QD_OK)
        st = qd_scatter_features_at(ctx, s, q->E, &a->features);
    if (st == QD_OK && q->at != QD_SCATTER_AT_LAB)
        st = lab_frame(ctx, s, q, theta, a);
    return st;
}
