/*
 * src/scatter/render.c - an answer of qd_scatter_answer_query as text and
 * JSON (qd_scatter_render, scatter.h): the output of `qdot scatter`.
 * Angles in text carry their degrees; an infinite range or cross section
 * is "infinite" (a string in JSON, which has no infinity), a missing one
 * null.
 */
#include "base/args.h"
#include "sct.h"

#include <math.h>

#include "qdot/json.h"

#define PI 3.14159265358979323846 /* M_PI is not C11 */

/* Nine significant digits: the cross sections come from differences of
 * the deflection (good to about 1e-10), so a tenth digit would be noise. */
static void num(qd_buf *b, double x) {
    if (isinf(x))
        qd_buf_puts(b, x > 0 ? "infinite" : "-infinite");
    else
        qd_buf_printf(b, "%.9g", fabs(x) < 1e-13 ? 0.0 : x);
}

static void put(qd_buf *b, const char *before, double x, const char *after) {
    qd_buf_puts(b, before);
    num(b, x);
    qd_buf_puts(b, after);
}

static void angle(qd_buf *b, const char *before, double x, const char *after) {
    put(b, before, x, " (");
    put(b, "", x * 180 / PI, " deg)");
    qd_buf_puts(b, after);
}

static void text_path(const qd_scatter_answer *a, qd_buf *b) {
    const qd_scatter_path *p = &a->path;
    put(b, "impact parameter: ", a->q.b, "");
    qd_buf_printf(b, "\norbit: %s\n", qd_scatter_kind_name(p->kind));
    if (p->kind == QD_SCATTER_CAPTURED)
        return;
    put(b, "closest approach: r0 = ", p->r0, "\n");
    angle(b, "deflection: Theta = ", p->theta, "\n");
    put(b, "deflection_signed: chi = ", p->chi, "\n");
}

static void text_section(const qd_scatter_answer *a, qd_buf *b) {
    const qd_scatter_section *x = &a->section;
    if (!isfinite(x->sigma))
        return;
    put(b, "cross_section: dsigma/dOmega = ", x->sigma, "");
    angle(b, " at Theta = ", x->theta, "");
    qd_buf_printf(b, ", %zu branch%s%s\n", x->nbranch, x->nbranch == 1 ? "" : "es",
                  x->truncated ? " (more not counted: orbiting)" : "");
    for (size_t i = 0; i < x->nbranch; i++) {
        put(b, "  b = ", x->branch[i].b, "");
        put(b, ": chi = ", x->branch[i].chi, "");
        put(b, ", dchi/db = ", x->branch[i].dchi_db, "");
        put(b, ", dsigma/dOmega = ", x->branch[i].sigma, "\n");
    }
}

static void text_features(const qd_scatter_features *f, qd_buf *b) {
    put(b, "range: ", f->range, "\n");
    put(b, "total cross section: ", f->total, "\n");
    for (size_t i = 0; i < f->nrainbow; i++) {
        angle(b, "rainbow: Theta = ", f->rainbow_theta[i], "");
        put(b, " at b = ", f->rainbow_b[i], "\n");
    }
    for (size_t i = 0; i < f->nglory; i++) {
        qd_buf_printf(b, "glory: %s", f->glory_theta[i] == 0 ? "forward" : "backward");
        put(b, " at b = ", f->glory_b[i], "\n");
    }
    if (f->orbiting) {
        put(b, "orbiting: b = ", f->orbit_b, "");
        put(b, " circles at r = ", f->orbit_r, "\n");
    }
    if (f->capture) {
        put(b, "capture: b < ", f->capture_b, "");
        put(b, ", cross section ", PI * f->capture_b * f->capture_b, "\n");
    }
}

/* The recoil's part, when the target is counted too (--recoil). */
static void text_recoil(const qd_scatter_answer *a, qd_buf *b) {
    if (isfinite(a->recoil_sigma))
        put(b, "  of which the recoiling target (counted too): ", a->recoil_sigma, "\n");
}

static void text_lab(const qd_scatter_answer *a, qd_buf *b) {
    const qd_scatter_lab *l = &a->lab_map;
    put(b, "lab frame (target at rest, gamma = m1/m2 = ", l->gamma, "):\n");
    angle(b, "  lab_angle: ", l->theta_lab, "\n");
    put(b, "  energy after / before: ", l->energy_ratio, "");
    if (isfinite(a->lab_sigma)) {
        put(b, "\n  lab_cross_section: ", a->lab_sigma, "");
        qd_buf_printf(b, " (%zu CM angle%s)", a->lab_ncm, a->lab_ncm == 1 ? "" : "s");
    }
    angle(b, "\n  recoil: angle ", l->recoil_angle, "");
    put(b, ", energy / projectile's ", l->recoil_ratio, "\n");
    if (isfinite(a->lab_sigma))
        text_recoil(a, b);
}

static void text_lab_angles(const qd_scatter_answer *a, qd_buf *b) {
    put(b, "lab frame (target at rest, gamma = m1/m2 = ", a->q.m1 / a->q.m2, "):\n");
    angle(b, "  lab_angle: ", a->q.lab_theta, "\n");
    for (size_t k = 0; k < a->ncm; k++) {
        angle(b, "  CM angle ", a->cm[k], "");
        put(b, ": dsigma/dOmega = ", a->cm_sigma[k], "");
        put(b, ", dOmega_cm/dOmega_lab = ", a->cm_jacobian[k], "\n");
    }
    put(b, "  lab_cross_section: ", a->lab_sigma, "");
    qd_buf_printf(b, " (%zu CM angle%s%s)\n", a->ncm, a->ncm == 1 ? "" : "s",
                  a->ncm ? "" : ": beyond the largest lab angle, asin(m2/m1)");
    text_recoil(a, b);
}

static qd_status text(qd_ctx *ctx, const qd_scatter *s, const qd_scatter_answer *a,
                      const char *model, qd_buf *b) {
    qd_buf_printf(b, "model: %s\npotential: V = ", model);
    qd_status st = qd_print(ctx, qd_scatter_potential(s), QD_FMT_TEXT, b);
    put(b, "\nenergy: ", a->q.E, "\n");
    if (a->q.at == QD_SCATTER_AT_B)
        text_path(a, b);
    text_section(a, b);
    if (a->q.at == QD_SCATTER_AT_LAB)
        text_lab_angles(a, b);
    text_features(&a->features, b);
    if (a->lab)
        text_lab(a, b);
    return st;
}

/* ---- JSON ---------------------------------------------------------------- */

static void jnum(qd_json *j, const char *key, double x) {
    qd_json_key(j, key);
    if (isfinite(x))
        qd_json_number(j, x);
    else if (isinf(x))
        qd_json_string(j, x > 0 ? "infinite" : "-infinite");
    else
        qd_json_null(j);
}

static void json_pairs(qd_json *j, const char *key, size_t n, const double *bs,
                       const double *th) {
    qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t i = 0; i < n; i++) {
        qd_json_begin_object(j);
        jnum(j, "b", bs[i]);
        jnum(j, "angle", th[i]);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
}

static void json_section(const qd_scatter_section *x, qd_json *j) {
    jnum(j, "cross_section", x->sigma);
    qd_json_key(j, "branches");
    qd_json_begin_array(j);
    for (size_t i = 0; isfinite(x->sigma) && i < x->nbranch; i++) {
        qd_json_begin_object(j);
        jnum(j, "b", x->branch[i].b);
        jnum(j, "deflection_signed", x->branch[i].chi);
        jnum(j, "dchi_db", x->branch[i].dchi_db);
        jnum(j, "cross_section", x->branch[i].sigma);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
}

static void json_features(const qd_scatter_features *f, qd_json *j) {
    jnum(j, "range", f->range);
    jnum(j, "total_cross_section", f->total);
    json_pairs(j, "rainbows", f->nrainbow, f->rainbow_b, f->rainbow_theta);
    json_pairs(j, "glories", f->nglory, f->glory_b, f->glory_theta);
    qd_json_key(j, "orbiting");
    if (f->orbiting) {
        qd_json_begin_object(j);
        jnum(j, "b", f->orbit_b);
        jnum(j, "r", f->orbit_r);
        qd_json_end_object(j);
    } else {
        qd_json_null(j);
    }
    jnum(j, "capture_cross_section", f->capture ? PI * f->capture_b * f->capture_b : 0);
}

static void json_lab(const qd_scatter_answer *a, qd_json *j) {
    const qd_scatter_lab *l = &a->lab_map;
    jnum(j, "gamma", l->gamma);
    jnum(j, "lab_angle", l->theta_lab);
    jnum(j, "lab_energy_ratio", l->energy_ratio);
    jnum(j, "lab_cross_section", a->lab_sigma);
    if (isfinite(a->recoil_sigma))
        jnum(j, "recoil_cross_section", a->recoil_sigma);
    jnum(j, "recoil_angle", l->recoil_angle);
    jnum(j, "recoil_energy_ratio", l->recoil_ratio);
}

static void json_lab_angles(const qd_scatter_answer *a, qd_json *j) {
    jnum(j, "gamma", a->q.m1 / a->q.m2);
    jnum(j, "lab_angle", a->q.lab_theta);
    qd_json_key(j, "cm_angles");
    qd_json_begin_array(j);
    for (size_t k = 0; k < a->ncm; k++) {
        qd_json_begin_object(j);
        jnum(j, "angle", a->cm[k]);
        jnum(j, "cross_section", a->cm_sigma[k]);
        jnum(j, "jacobian", a->cm_jacobian[k]);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
    jnum(j, "lab_cross_section", a->lab_sigma);
    if (isfinite(a->recoil_sigma))
        jnum(j, "recoil_cross_section", a->recoil_sigma);
}

static void json_path(const qd_scatter_answer *a, qd_json *j) {
    jnum(j, "b", a->q.b);
    qd_json_key(j, "kind");
    qd_json_string(j, qd_scatter_kind_name(a->path.kind));
    jnum(j, "closest_approach", a->path.r0);
    jnum(j, "deflection", a->path.theta);
    jnum(j, "deflection_signed", a->path.chi);
}

static qd_status json(qd_ctx *ctx, const qd_scatter *s, const qd_scatter_answer *a,
                      const char *model, qd_buf *b) {
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "model");
    qd_json_string(&j, model);
    qd_json_key(&j, "potential");
    qd_json_expr(&j, ctx, qd_scatter_potential(s));
    qd_json_key(&j, "radius");
    qd_json_string(&j, qd_expr_name(qd_scatter_radius(s)));
    jnum(&j, "energy", a->q.E);
    if (a->q.at == QD_SCATTER_AT_B)
        json_path(a, &j);
    else if (a->q.at == QD_SCATTER_AT_THETA)
        jnum(&j, "deflection", a->q.theta);
    if (a->q.at == QD_SCATTER_AT_LAB)
        json_lab_angles(a, &j);
    else
        json_section(&a->section, &j);
    json_features(&a->features, &j);
    if (a->lab)
        json_lab(a, &j);
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    if (!qd_json_ok(&j)) {
        qd_ctx_error(ctx, j.nomem ? QD_ERR_NOMEM : QD_ERR_NUMERIC,
                     "the scattering cannot be written: %s", qd_json_why(&j));
        return qd_ctx_status(ctx);
    }
    return QD_OK;
}

qd_status qd_scatter_render(qd_ctx *ctx, const qd_scatter *s, const qd_scatter_answer *a,
                            const char *model, bool as_json, qd_buf *b) {
    QD_ARGS_CTX(ctx, ctx && s && a && model && b);
    qd_status st = as_json ? json(ctx, s, a, model, b) : text(ctx, s, a, model, b);
    if (st == QD_OK && b->failed) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        st = QD_ERR_NOMEM;
    }
    return st;
}
