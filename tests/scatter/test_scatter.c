/*
 * tests/scatter/test_scatter.c - classical scattering (qdot/scatter.h)
 * against the closed forms of Desloge ch. 60-61 (seed 000_46d037099a6cfcd7,
 * reference seed-desloge-B.md C4, C5, T15, T19, T21, T23, T25) and
 * Landau & Lifshitz, Mechanics, sec. 18 problem 2 (the refracting sphere).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "qdot/qdot.h"

#define PI 3.14159265358979323846

static void assert_close(double got, double want, double rel) {
    if (!(fabs(got - want) <= rel * fmax(fabs(want), 1e-300))) {
        print_error("got %.17g, want %.17g (rel %.3g)\n", got, want, fabs(got - want) / fabs(want));
        fail();
    }
}

/* A scatterer for V(r) read from text (numbers only). */
static qd_scatter *make(qd_ctx *c, const char *V, double core) {
    const qd_expr *e = qd_read(c, V, NULL, NULL);
    qd_scatter *s = qd_scatter_new(c, e, qd_symbol(c, "r"), core);
    if (!s)
        print_error("%s\n", qd_ctx_message(c));
    assert_non_null(s);
    return s;
}

static double chi(qd_ctx *c, qd_scatter *s, double E, double b) {
    qd_scatter_path p;
    assert_int_equal(qd_scatter_deflect(c, s, E, b, &p), QD_OK);
    return p.chi;
}

/* T15 (Desloge ch. 60 ex. 2): V = k/r, tan(Theta/2) = k/(2 E b), and the
 * seed's quadrature values at k = 1, E = 2; attraction turns the other way. */
static void test_rutherford_deflection(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    qd_scatter *s = make(c, "1/r", 0);
    assert_close(chi(c, s, 2, 0.1), 2.380579899, 1e-9);
    assert_close(chi(c, s, 2, 0.5), 0.927295218, 1e-9);
    assert_close(chi(c, s, 2, 2.0), 0.248709989, 1e-9);
    const double bs[] = {1e-3, 0.03, 0.7, 5, 300};
    for (size_t i = 0; i < 5; i++)
        assert_close(chi(c, s, 2, bs[i]), 2 * atan(1.0 / (4 * bs[i])), 1e-11);
    assert_true(isinf(qd_scatter_range(s)));
    qd_scatter_free(s);
    s = make(c, "-3/r", 0);
    assert_close(chi(c, s, 0.5, 1.2), -2 * atan(3.0 / (2 * 0.5 * 1.2)), 1e-11);
    qd_scatter_free(s);
    qd_ctx_free(c);
}

/* dsigma/dOmega = (k/(4E))^2 / sin^4(Theta/2): one branch, at several angles. */
static void test_rutherford_section(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    qd_scatter *s = make(c, "3/2/r", 0);
    const double E = 0.8, th[] = {0.2, 1.0, 2.0, 3.0};
    for (size_t i = 0; i < 4; i++) {
        qd_scatter_section x;
        assert_int_equal(qd_scatter_section_at(c, s, E, th[i], &x), QD_OK);
        assert_int_equal(x.nbranch, 1);
        double want = pow(1.5 / (4 * E), 2) / pow(sin(th[i] / 2), 4);
        assert_close(x.sigma, want, 1e-7);
        assert_close(x.branch[0].b, 1.5 / (2 * E) / tan(th[i] / 2), 1e-10);
    }
    qd_scatter_features f;
    assert_int_equal(qd_scatter_features_at(c, s, E, &f), QD_OK);
    assert_true(isinf(f.total));
    assert_int_equal(f.nrainbow, 0);
    assert_false(f.orbiting);
    qd_scatter_free(s);
    qd_ctx_free(c);
}

/* Hard sphere (Desloge ch. 60 ex. 1): chi = 2 acos(b/a), sigma = a^2/4 at
 * every angle, total pi a^2; a step it cannot climb is the same wall. */
static void test_hard_sphere(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    const double a = 1.5;
    qd_scatter *hard = make(c, "0", a);
    qd_scatter *wall = make(c, "4*step(3/2 - r)", 0);
    qd_scatter *both[2] = {hard, wall};
    for (int k = 0; k < 2; k++) {
        qd_scatter *s = both[k];
        assert_close(chi(c, s, 1, 0.9), 2 * acos(0.9 / a), 1e-12);
        assert_close(qd_scatter_range(s), a, 1e-15);
        const double th[] = {0.3, 1.7, 2.9};
        for (size_t i = 0; i < 3; i++) {
            qd_scatter_section x;
            assert_int_equal(qd_scatter_section_at(c, s, 1, th[i], &x), QD_OK);
            assert_int_equal(x.nbranch, 1);
            assert_close(x.sigma, a * a / 4, 1e-7);
        }
        qd_scatter_features f;
        assert_int_equal(qd_scatter_features_at(c, s, 1, &f), QD_OK);
        assert_close(f.total, PI * a * a, 1e-14);
    }
    qd_scatter_path p;
    assert_int_equal(qd_scatter_deflect(c, hard, 1, 0.5, &p), QD_OK);
    assert_int_equal(p.kind, QD_SCATTER_REFLECTED);
    assert_true(p.r0 == a);
    qd_scatter_free(hard);
    qd_scatter_free(wall);
    qd_ctx_free(c);
}

/* The refracting sphere, V = -V0 inside r < a (Desloge ch. 60 problems;
 * Landau sec. 18 pb. 2): n = sqrt(1 + V0/E), Theta = 2 (asin(b/a) -
 * asin(b/(n a))), and
 *   dsigma/dOmega = n^2 a^2 (n cos(T/2) - 1)(n - cos(T/2)) /
 *                   (4 cos(T/2) (1 + n^2 - 2 n cos(T/2))^2)
 * below cos(T_max/2) = 1/n; nothing beyond. */
static void test_refracting_sphere(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    const double a = 2, V0 = 3, E = 1, n = sqrt(1 + V0 / E);
    qd_scatter *s = make(c, "-3*step(2 - r)", 0);
    assert_int_equal(qd_scatter_njumps(s), 1);
    assert_true(qd_scatter_jump(s, 0) == 2);
    const double bs[] = {0.1, 1.0, 1.9, 1.999};
    for (size_t i = 0; i < 4; i++)
        assert_close(-chi(c, s, E, bs[i]), 2 * (asin(bs[i] / a) - asin(bs[i] / (n * a))), 1e-11);
    assert_true(fabs(chi(c, s, E, 2.5)) < 1e-14); /* outside the sphere: no force */
    const double th[] = {0.3, 1.0, 1.5};
    for (size_t i = 0; i < 3; i++) {
        double ch = cos(th[i] / 2);
        double want = n * n * a * a * (n * ch - 1) * (n - ch) /
                      (4 * ch * pow(1 + n * n - 2 * n * ch, 2));
        qd_scatter_section x;
        assert_int_equal(qd_scatter_section_at(c, s, E, th[i], &x), QD_OK);
        assert_int_equal(x.nbranch, 1);
        assert_close(x.sigma, want, 1e-7);
    }
    qd_scatter_section x; /* beyond T_max = 2 acos(1/n) = 2 pi/3 nothing arrives */
    assert_int_equal(qd_scatter_section_at(c, s, E, 2.2, &x), QD_OK);
    assert_int_equal(x.nbranch, 0);
    qd_scatter_free(s);
    qd_ctx_free(c);
}

/* A repulsive step, V = V0 for r < a with V0 = 3E/4 (Desloge ch. 60
 * problems): index n = sqrt(1 - V0/E) = 1/2 < 1, so b < n a refract,
 * Theta = 2 (asin(b/(n a)) - asin(b/a)), and n a < b < a meet the jump as
 * a wall (total reflection): Theta = 2 acos(b/a), as off a hard sphere. */
static void test_repulsive_step(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    const double a = 2, E = 1, n = 0.5;
    qd_scatter *s = make(c, "3/4*step(2 - r)", 0);
    const double in[] = {0.2, 0.7, 0.99}, out[] = {1.01, 1.5, 1.99};
    for (size_t i = 0; i < 3; i++) {
        assert_close(chi(c, s, E, in[i]), 2 * (asin(in[i] / (n * a)) - asin(in[i] / a)), 1e-11);
        qd_scatter_path p;
        assert_int_equal(qd_scatter_deflect(c, s, E, out[i], &p), QD_OK);
        assert_int_equal(p.kind, QD_SCATTER_REFLECTED);
        assert_true(p.r0 == a);
        assert_close(p.chi, 2 * acos(out[i] / a), 1e-11);
    }
    qd_scatter_free(s);
    qd_ctx_free(c);
}

/* Lennard-Jones, V = 4 (r^-12 - r^-6) at E = 2: the core repels small b, the
 * well pulls larger ones, so chi crosses 0 at a finite b: a forward glory
 * (Desloge ch. 60, seed-desloge-B.md pitfall 5), chi changing sign across it. */
static void test_glory(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    qd_scatter *s = make(c, "4*(r^-12 - r^-6)", 0);
    qd_scatter_features f;
    assert_int_equal(qd_scatter_features_at(c, s, 2, &f), QD_OK);
    assert_int_equal(f.nglory, 1);
    assert_true(f.glory_theta[0] == 0);
    double bg = f.glory_b[0];
    assert_true(fabs(chi(c, s, 2, bg)) < 1e-9);
    assert_true(chi(c, s, 2, bg * 0.99) > 0 && chi(c, s, 2, bg * 1.01) < 0);
    assert_int_equal(f.nrainbow, 1);
    assert_false(f.orbiting);
    qd_scatter_free(s);
    qd_ctx_free(c);
}

/* A Gaussian well, V = -exp(-r^2): chi(b) has one minimum, the rainbow;
 * its angle against a fine direct scan of chi, and dsigma/dOmega summing
 * the two branches on the lit side. */
static void test_rainbow(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    qd_scatter *s = make(c, "-exp(-r^2)", 0);
    const double E = 0.5;
    double best = INFINITY, bbest = 0;
    for (int i = 1; i <= 600; i++) { /* coarse, then fine around the coarse minimum */
        double b = 3.0 * i / 600, x = chi(c, s, E, b);
        if (x < best)
            best = x, bbest = b;
    }
    double lo = bbest - 0.01;
    for (int i = 0; i <= 400; i++) {
        double b = lo + 0.02 * i / 400, x = chi(c, s, E, b);
        if (x < best)
            best = x, bbest = b;
    }
    qd_scatter_features f;
    assert_int_equal(qd_scatter_features_at(c, s, E, &f), QD_OK);
    assert_int_equal(f.nrainbow, 1);
    assert_close(f.rainbow_theta[0], -best, 1e-6);
    assert_close(f.rainbow_b[0], bbest, 1e-3);
    assert_false(f.orbiting);
    double dchi;
    assert_int_equal(qd_scatter_dchi_db(c, s, E, f.rainbow_b[0], &dchi), QD_OK);
    assert_true(fabs(dchi) < 1e-5);
    /* inside the rainbow angle: two branches, each b/(sin T |chi'|) */
    qd_scatter_section x;
    double th = 0.8 * f.rainbow_theta[0];
    assert_int_equal(qd_scatter_section_at(c, s, E, th, &x), QD_OK);
    assert_int_equal(x.nbranch, 2);
    for (size_t k = 0; k < 2; k++) {
        double b = x.branch[k].b, h = 1e-5;
        double d = (chi(c, s, E, b + h) - chi(c, s, E, b - h)) / (2 * h);
        assert_close(x.branch[k].sigma, b / (sin(th) * fabs(d)), 1e-5);
        assert_close(acos(cos(x.branch[k].chi)), th, 1e-9);
    }
    assert_close(x.sigma, x.branch[0].sigma + x.branch[1].sigma, 1e-15);
    qd_scatter_free(s);
    qd_ctx_free(c);
}

/* T19 (Desloge ch. 60 pb. 5): V = -k/r^4 captures b < b_c with
 * r*^4 = k/E and sigma_capture = 2 pi (k/(2E))^(1/2) * 2 ... at k = E = 1
 * the seed's check: r* = 1 and sigma = 2 pi. */
static void test_capture(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    qd_scatter *s = make(c, "-1/r^4", 0);
    qd_scatter_features f;
    assert_int_equal(qd_scatter_features_at(c, s, 1, &f), QD_OK);
    assert_true(f.orbiting);
    assert_true(f.capture);
    assert_close(f.orbit_r, 1, 1e-10);
    assert_close(PI * f.capture_b * f.capture_b, 2 * PI, 1e-10);
    qd_scatter_path p;
    assert_int_equal(qd_scatter_deflect(c, s, 1, 0.99 * f.capture_b, &p), QD_OK);
    assert_int_equal(p.kind, QD_SCATTER_CAPTURED);
    /* just outside, it winds: chi below -pi (deflection_signed) */
    assert_int_equal(qd_scatter_deflect(c, s, 1, f.capture_b * (1 + 1e-6), &p), QD_OK);
    assert_int_equal(p.kind, QD_SCATTER_DEFLECTED);
    assert_true(p.chi < -PI);
    qd_scatter_free(s);
    qd_ctx_free(c);
}

/* T19's other branch (Desloge ch. 60 pb. 5): an absorbing sphere of radius
 * a >= r* captures sigma = pi a^2 (1 + k/(E a^n)); inside the barrier (a <
 * r*) the capture is the orbiting one, 2 pi at n = 4, k = E = 1.  Just
 * outside b_c the orbit is deflected, below it captured; a reflecting core
 * of the same radius captures nothing. */
static void test_absorbing_core(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    const double a[] = {1.5, 2.5, 0.5}, E[] = {1, 0.3, 1};
    for (int i = 0; i < 3; i++) {
        qd_scatter *s = make(c, "-1/r^4", a[i]);
        qd_scatter_set_absorbing(s, true);
        qd_scatter_features f;
        assert_int_equal(qd_scatter_features_at(c, s, E[i], &f), QD_OK);
        assert_true(f.capture);
        double rs = pow(2 / (2 * E[i]), 0.25); /* r*^n = (n - 2) k/(2E) */
        double want = a[i] >= rs ? PI * a[i] * a[i] * (1 + 1 / (E[i] * pow(a[i], 4)))
                                 : PI * 4 * pow(2, -0.5) * pow(1 / (2 * E[i]), 0.5);
        assert_close(PI * f.capture_b * f.capture_b, want, 1e-12);
        qd_scatter_path p;
        assert_int_equal(qd_scatter_deflect(c, s, E[i], f.capture_b * (1 - 1e-6), &p), QD_OK);
        assert_int_equal(p.kind, QD_SCATTER_CAPTURED);
        assert_int_equal(qd_scatter_deflect(c, s, E[i], f.capture_b * (1 + 1e-6), &p), QD_OK);
        assert_true(p.kind == QD_SCATTER_DEFLECTED);
        assert_int_equal(qd_scatter_deflect(c, s, E[i], 0, &p), QD_OK);
        assert_int_equal(p.kind, QD_SCATTER_CAPTURED);
        qd_scatter_set_absorbing(s, false);
        assert_int_equal(qd_scatter_deflect(c, s, E[i], 0, &p), QD_OK);
        assert_int_equal(p.kind, QD_SCATTER_REFLECTED);
        qd_scatter_free(s);
    }
    qd_ctx_free(c);
}

/* T25 (Desloge ch. 61 pb. 7), equal masses: the projectile at Theta/2 with
 * speed V cos(Theta/2), the target at (pi - Theta)/2 with V sin(Theta/2). */
static void test_lab_equal_masses(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    const double th[] = {0.4, 1.3, 2.8};
    for (size_t i = 0; i < 3; i++) {
        qd_scatter_lab l;
        assert_int_equal(qd_scatter_lab_map(c, 2, 2, th[i], &l), QD_OK);
        assert_close(l.theta_lab, th[i] / 2, 1e-14);
        assert_close(l.energy_ratio, pow(cos(th[i] / 2), 2), 1e-14);
        assert_close(l.recoil_angle, (PI - th[i]) / 2, 1e-14);
        assert_close(l.recoil_ratio, pow(sin(th[i] / 2), 2), 1e-14);
        assert_close(l.jacobian, 4 * cos(th[i] / 2), 1e-14);
    }
    qd_ctx_free(c);
}

/* T23 (Desloge ch. 61 pb. 3): protons of energy E on protons at rest, k/r^2
 * force, both counted: Q = (k/E)^2 (sin^-4 + cos^-4) cos theta.  Built from
 * the computed CM cross section (E_cm = E/2) through the projectile's and
 * the recoil's Jacobians. */
static void test_lab_proton_proton(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    const double k = 1.3, E = 2.0;
    qd_scatter *s = make(c, "13/10/r", 0);
    const double tl[] = {0.3, 0.7, 1.2};
    for (size_t i = 0; i < 3; i++) {
        double cm[2];
        assert_int_equal(qd_scatter_lab_to_cm(1.0, tl[i], cm), 1);
        assert_close(cm[0], 2 * tl[i], 1e-14);
        qd_scatter_section a, b;
        qd_scatter_lab la, lb;
        assert_int_equal(qd_scatter_section_at(c, s, E / 2, cm[0], &a), QD_OK);
        assert_int_equal(qd_scatter_lab_map(c, 1, 1, cm[0], &la), QD_OK);
        /* the recoil reaches theta when the projectile went to pi - 2 theta */
        assert_int_equal(qd_scatter_section_at(c, s, E / 2, PI - 2 * tl[i], &b), QD_OK);
        assert_int_equal(qd_scatter_lab_map(c, 1, 1, PI - 2 * tl[i], &lb), QD_OK);
        assert_close(lb.recoil_angle, tl[i], 1e-14);
        double Q = a.sigma * la.jacobian + b.sigma * lb.recoil_jacobian;
        double want = pow(k / E, 2) * (pow(sin(tl[i]), -4) + pow(cos(tl[i]), -4)) * cos(tl[i]);
        assert_close(Q, want, 1e-6);
    }
    qd_scatter_free(s);
    qd_ctx_free(c);
}

/* T21 (Desloge ch. 61 pb. 1): gamma = 1/sqrt 7, isotropic q = s0/(4 pi):
 * Q = (s0/(4 pi)) [sqrt(6 + cos^2) + cos]^2 / sqrt(7 (6 + cos^2)); and for
 * gamma > 1 two CM angles reach each lab angle inside asin(1/gamma). */
static void test_lab_gamma(void **state) {
    (void)state;
    const double g = 1 / sqrt(7.0), tl[] = {0.2, 1.1, 2.5};
    for (size_t i = 0; i < 3; i++) {
        double cm[2], back, J, C = cos(tl[i]);
        assert_int_equal(qd_scatter_lab_to_cm(g, tl[i], cm), 1);
        qd_scatter_lab_gamma(g, cm[0], &back, &J);
        assert_close(back, tl[i], 1e-14);
        double want = pow(sqrt(6 + C * C) + C, 2) / sqrt(7 * (6 + C * C));
        assert_close(J, want, 1e-13);
    }
    double cm[2], back, J;
    assert_int_equal(qd_scatter_lab_to_cm(2.0, 0.4, cm), 2);
    for (int k = 0; k < 2; k++) {
        qd_scatter_lab_gamma(2.0, cm[k], &back, &J);
        assert_close(back, 0.4, 1e-13);
    }
    assert_int_equal(qd_scatter_lab_to_cm(2.0, asin(0.5) + 0.01, cm), 0);
}

/* The central potential from a model: Routh's reduction ignoring the
 * cyclic angle (examples/kepler_polar.qd's form). */
static void test_from_model(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    qd_model *m = qd_model_parse(c, "coordinates r, phi\nparticle 13/10 at r*(cos(phi), sin(phi))\n"
                                    "V = 2/r - 3*step(1 - r)\n", NULL);
    assert_non_null(m);
    qd_eom *e = qd_eom_derive(c, m);
    assert_non_null(e);
    double mass = 0;
    qd_scatter *s = qd_scatter_from_model(c, m, e, NULL, 0, &mass);
    assert_non_null(s);
    assert_close(mass, 1.3, 1e-15);
    assert_ptr_equal(qd_scatter_potential(s), qd_read(c, "2/r - 3*step(1 - r)", NULL, NULL));
    assert_int_equal(qd_scatter_njumps(s), 1);
    qd_scatter_free(s);
    qd_eom_free(e);
    qd_model_free(m);
    qd_ctx_free(c);
}

/* b = 0, head-on: back along the beam off a wall, straight through a
 * finite well, into a centre where V -> -inf. */
static void test_head_on(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    qd_scatter *hard = make(c, "0", 1), *well = make(c, "-3*step(2 - r)", 0);
    qd_scatter *fall = make(c, "-1/r^4", 0);
    qd_scatter_path p;
    assert_int_equal(qd_scatter_deflect(c, hard, 1, 0, &p), QD_OK);
    assert_int_equal(p.kind, QD_SCATTER_REFLECTED);
    assert_true(p.chi == PI && p.theta == PI);
    assert_int_equal(qd_scatter_deflect(c, well, 1, 0, &p), QD_OK);
    assert_int_equal(p.kind, QD_SCATTER_DEFLECTED);
    assert_true(p.theta == 0);
    assert_int_equal(qd_scatter_deflect(c, fall, 1, 0, &p), QD_OK);
    assert_int_equal(p.kind, QD_SCATTER_CAPTURED);
    assert_true(isnan(p.chi));
    qd_scatter_free(hard);
    qd_scatter_free(well);
    qd_scatter_free(fall);
    qd_ctx_free(c);
}

/* Errors: E <= 0, b < 0, a theta outside (0, pi), V not vanishing at
 * infinity, and models that are not a central potential. */
static void test_errors(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    qd_scatter *s = make(c, "1/r", 0);
    qd_scatter_path p;
    qd_scatter_section x;
    assert_int_equal(qd_scatter_deflect(c, s, 0, 1, &p), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(c), "energy must be positive"));
    qd_ctx_clear_error(c);
    assert_int_equal(qd_scatter_deflect(c, s, 1, -1, &p), QD_ERR_ARG);
    qd_ctx_clear_error(c);
    assert_int_equal(qd_scatter_section_at(c, s, 1, 4, &x), QD_ERR_ARG);
    qd_ctx_clear_error(c);
    qd_scatter_free(s);
    assert_null(qd_scatter_new(c, qd_read(c, "r^2", NULL, NULL), qd_symbol(c, "r"), 0));
    assert_non_null(strstr(qd_ctx_message(c), "does not vanish"));
    qd_ctx_clear_error(c);
    const char *bad[] = {"coordinates x, y\nparticle 1 at (x, y)\nV = x^2\n",
                         "coordinates r, phi\nparticle 1 at r*(cos(phi), sin(phi))\nV = phi/r\n",
                         "coordinates r, phi\nparticle r at r*(cos(phi), sin(phi))\nV = 1/r\n"};
    qd_ctx_free(c);
    for (size_t i = 0; i < 3; i++) { /* a fresh context: r is a coordinate there */
        c = qd_ctx_new();
        qd_model *m = qd_model_parse(c, bad[i], NULL);
        assert_non_null(m);
        qd_eom *e = qd_eom_derive(c, m);
        assert_non_null(e);
        assert_null(qd_scatter_from_model(c, m, e, NULL, 0, NULL));
        assert_int_equal(qd_ctx_status(c), QD_ERR_ARG);
        qd_ctx_clear_error(c);
        qd_eom_free(e);
        qd_model_free(m);
        qd_ctx_free(c);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rutherford_deflection),
        cmocka_unit_test(test_rutherford_section),
        cmocka_unit_test(test_hard_sphere),
        cmocka_unit_test(test_refracting_sphere),
        cmocka_unit_test(test_repulsive_step),
        cmocka_unit_test(test_glory),
        cmocka_unit_test(test_rainbow),
        cmocka_unit_test(test_capture),
        cmocka_unit_test(test_absorbing_core),
        cmocka_unit_test(test_lab_equal_masses),
        cmocka_unit_test(test_lab_proton_proton),
        cmocka_unit_test(test_lab_gamma),
        cmocka_unit_test(test_from_model),
        cmocka_unit_test(test_head_on),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
