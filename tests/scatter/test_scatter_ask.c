/*
 * tests/scatter/test_scatter_ask.c - one question of `qdot scatter` as
 * library calls (scatter.h: qd_scatter_read, qd_scatter_answer_query),
 * values in the model's parameters, against Rutherford's closed forms
 * (Desloge ch. 60 ex. 2: dsigma/dOmega = (k/4E)^2/sin^4(Theta/2)) taken to
 * the laboratory by ch. 61 (tan theta_lab = sin Theta/(cos Theta + gamma),
 * sigma_lab = sigma (1 + gamma^2 + 2 gamma cos Theta)^(3/2)/|1 + gamma cos
 * Theta|, both CM angles Theta = theta + asin(gamma sin theta) and
 * theta + pi - asin(gamma sin theta) counting when gamma > 1).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "qdot/qdot.h"

#define PI 3.14159265358979323846

static const char rutherford[] = "coordinates r, phi\nparameters k = 1, mu = 1, E0 = 2\n"
                                 "particle mu at r*(cos(phi), sin(phi))\nV = k/r\n";

static void near(double got, double want, double tol) {
    if (!(fabs(got - want) <= tol * (1 + fabs(want))))
        fail_msg("got %.17g, want %.17g (tol %g)", got, want, tol);
}

static double sigma_cm(double E, double th) { /* k = 1 */
    double s = sin(th / 2);
    return 1 / (16 * E * E * s * s * s * s);
}

static double jacobian(double g, double th) {
    return pow(1 + g * g + 2 * g * cos(th), 1.5) / fabs(1 + g * cos(th));
}

typedef struct fix {
    qd_ctx *ctx;
    qd_model *m;
    qd_eom *e;
    qd_scatter *s;
    qd_scatter_query q;
    qd_scatter_answer a;
} fix;

static qd_status ask(fix *f, const qd_scatter_text *t) {
    memset(f, 0, sizeof *f);
    f->ctx = qd_ctx_new();
    f->m = qd_model_parse(f->ctx, rutherford, NULL);
    assert_non_null(f->m);
    f->e = qd_eom_derive(f->ctx, f->m);
    qd_status st = qd_scatter_read(f->ctx, f->m, t, &f->q);
    if (st != QD_OK)
        return st;
    f->s = qd_scatter_from_model(f->ctx, f->m, f->e, NULL, f->q.core, NULL);
    assert_non_null(f->s);
    return qd_scatter_answer_query(f->ctx, f->s, &f->q, &f->a);
}

static void done(fix *f) {
    qd_scatter_free(f->s);
    qd_eom_free(f->e);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
}

static void theta_and_lab(void **state) {
    (void)state;
    fix f;
    const qd_scatter_text t = {.energy = "E0", .theta = "pi/3", .masses = "mu, 2*mu"};
    assert_int_equal(ask(&f, &t), QD_OK);
    near(f.a.section.sigma, sigma_cm(2, PI / 3), 1e-8);
    assert_true(f.a.lab);
    double g = 0.5, tl = atan2(sin(PI / 3), cos(PI / 3) + g);
    near(f.a.lab_map.theta_lab, tl, 1e-14);
    near(f.a.lab_sigma, sigma_cm(2, PI / 3) * jacobian(g, PI / 3), 1e-8);
    assert_int_equal(f.a.lab_ncm, 1);
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_scatter_render(f.ctx, f.s, &f.a, "r.qd", true, &b), QD_OK);
    assert_int_equal(qd_scatter_render(f.ctx, f.s, &f.a, "r.qd", false, &b), QD_OK);
    qd_buf_free(&b);
    done(&f);
}

static void lab_angle_two_branches(void **state) {
    (void)state;
    fix f;
    const qd_scatter_text t = {.energy = "E0", .lab_theta = "0.3", .masses = "2, 1"};
    assert_int_equal(ask(&f, &t), QD_OK);
    double g = 2, th = 0.3, d = asin(g * sin(th)), cm[2] = {th + d, th + PI - d};
    assert_int_equal(f.a.ncm, 2);
    double want = 0;
    for (int k = 0; k < 2; k++) {
        near(f.a.cm[k], fmin(cm[0], cm[1]) + k * fabs(cm[1] - cm[0]), 1e-12);
        want += sigma_cm(2, f.a.cm[k]) * jacobian(g, f.a.cm[k]);
    }
    near(f.a.lab_sigma, want, 1e-8);
    done(&f);
}

/* Identical particles, both counted (Desloge ch. 61 pb. 3, seed-desloge-B.md
 * T23, two protons): equal masses, lab energy E_lab = 2 E (E the relative
 * energy, mu = m/2 here mu = 1, so the proton's m = 2), Q = (k/E_lab)^2
 * (sin^-4 + cos^-4) cos(theta) below pi/2, the recoil's part (k/E_lab)^2
 * cos/cos^4; beyond pi/2 nothing recoils there. */
static void recoil_counted(void **state) {
    (void)state;
    fix f;
    const qd_scatter_text t = {.energy = "E0", .lab_theta = "0.5", .masses = "2, 2",
                               .recoil = true};
    assert_int_equal(ask(&f, &t), QD_OK);
    double El = 4, th = 0.5, c = cos(th), s = sin(th);
    near(f.a.lab_sigma, (1 / (El * El)) * (pow(s, -4) + pow(c, -4)) * c, 1e-8);
    near(f.a.recoil_sigma, (1 / (El * El)) * pow(c, -3), 1e-8);
    done(&f);
    const qd_scatter_text t2 = {.energy = "E0", .lab_theta = "2", .masses = "2, 2",
                                .recoil = true};
    assert_int_equal(ask(&f, &t2), QD_OK);
    assert_int_equal(f.a.ncm, 0);
    near(f.a.recoil_sigma, 0, 0);
    done(&f);
}

/* tan(Theta/2) = k/(2 E b) for one impact parameter. */
static void impact_parameter(void **state) {
    (void)state;
    fix f;
    const qd_scatter_text t = {.energy = "E0", .b = "k/4"};
    assert_int_equal(ask(&f, &t), QD_OK);
    near(f.a.path.theta, 2 * atan(1 / (2 * 2 * 0.25)), 1e-10);
    near(f.a.section.sigma, sigma_cm(2, f.a.path.theta), 1e-8);
    assert_false(f.a.lab);
    done(&f);
}

static void refused(const qd_scatter_text *t, const char *field, bool located, size_t off) {
    fix f;
    assert_int_equal(ask(&f, t), QD_ERR_ARG);
    const qd_diag *d = qd_ctx_diag(f.ctx);
    assert_string_equal(d->name, field);
    assert_int_equal(d->located, located);
    if (located)
        assert_int_equal(d->offset, off);
    done(&f);
}

static void errors(void **state) {
    (void)state;
    refused(&(qd_scatter_text){.energy = "1", .b = "1", .theta = "1"}, "theta", false, 0);
    refused(&(qd_scatter_text){.b = "1"}, "energy", false, 0);
    refused(&(qd_scatter_text){.energy = "1", .lab_theta = "1"}, "lab_theta", false, 0);
    refused(&(qd_scatter_text){.energy = "1", .lab_theta = "4", .masses = "1, 1"}, "lab_theta",
            false, 0);
    refused(&(qd_scatter_text){.energy = "2*kk", .b = "1"}, "energy", true, 2);
    refused(&(qd_scatter_text){.energy = "1", .b = "1", .masses = "1, mu2"}, "masses", true, 3);
    refused(&(qd_scatter_text){.energy = "1", .b = "1", .masses = "1, -1"}, "masses", false, 0);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(theta_and_lab),
        cmocka_unit_test(lab_angle_two_branches),
        cmocka_unit_test(impact_parameter),
        cmocka_unit_test(recoil_counted),
        cmocka_unit_test(errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
