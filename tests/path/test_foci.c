/*
 * tests/path/test_foci.c - kinetic foci (qd_path_foci) against the textbook
 * second variation (Desloge ch. 84, seed-desloge-D.md "kinetic foc";
 * Gelfand and Fomin ch. 5 sec. 26-27):
 *
 *   the harmonic oscillator x'' = -(k/m) x: the Jacobi equation is the
 *   equation itself, J = sin(w (t - t0))/w, so the foci fall at exactly
 *   t0 + j pi/w (every half period) whatever the amplitude;
 *   the pendulum from its stable equilibrium with a small velocity: the
 *   first focus tends to pi sqrt(l/g) (the linearized pendulum) and moves
 *   later with the amplitude, where it is checked against d theta/d v0
 *   measured by finite differences of two RK4 solutions of the motion;
 *   two coupled oscillators (masses m, springs k - k - k; Desloge's normal
 *   modes w1 = sqrt(k/m), w2 = sqrt(3k/m)): J = P diag(sin(w_i t)/w_i) P^T,
 *   det J = sin(w1 t) sin(w2 t)/(w1 w2), foci at j pi/w1 and j pi/w2 merged;
 *   the free particle: J = (t - t0) I, no focus;
 *   a negative mass: the Legendre condition fails;
 *   a constrained model: QD_ERR_ARG, not a wrong answer.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/qdot.h"

#define PI 3.14159265358979323846

typedef struct fix {
    qd_ctx *ctx;
    qd_model *m;
    qd_eom *e;
} fix;

static void load(fix *f, const char *text) {
    f->ctx = qd_ctx_new();
    assert_non_null(f->ctx);
    f->m = qd_model_parse(f->ctx, text, NULL);
    assert_non_null(f->m);
    f->e = qd_eom_derive(f->ctx, f->m);
    assert_non_null(f->e);
}

static void unload(fix *f) {
    qd_eom_free(f->e);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
}

/* The first zero after t = 0 of d theta(t)/d v0 for theta'' = -w^2 sin(theta),
 * theta(0) = 0, by central differences of two classical RK4 solutions of the
 * motion itself (no Jacobi equation): the focus measured independently. */
static double pendulum_focus_fd(double w, double v0, double tmax) {
    const size_t N = 200000;
    double dv = 1e-5 * v0, h = tmax / (double)N, y[2][2] = {{0, v0 + dv}, {0, v0 - dv}};
    double prev = 0;
    for (size_t s = 0; s < N; s++) {
        for (int c = 0; c < 2; c++) {
            double q = y[c][0], v = y[c][1];
            double k1q = v, k1v = -w * w * sin(q);
            double k2q = v + h / 2 * k1v, k2v = -w * w * sin(q + h / 2 * k1q);
            double k3q = v + h / 2 * k2v, k3v = -w * w * sin(q + h / 2 * k2q);
            double k4q = v + h * k3v, k4v = -w * w * sin(q + h * k3q);
            y[c][0] += h / 6 * (k1q + 2 * k2q + 2 * k3q + k4q);
            y[c][1] += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
        }
        double d = (y[0][0] - y[1][0]) / (2 * dv);
        if (s > 0 && (d > 0) != (prev > 0))
            return h * ((double)s + prev / (prev - d)); /* between steps s-1 and s, linear */
        prev = d;
    }
    return NAN;
}

/* Every half period, exactly, at any amplitude (w = sqrt(k/m) = 2). */
static void test_oscillator_half_period(void **state) {
    (void)state;
    fix f;
    load(&f, "coordinates x\nparameters m = 0.5, k = 2\nT = m*x'^2/2\nV = k*x^2/2\n");
    const double amp[] = {1e-3, 1, 250};
    for (size_t a = 0; a < 3; a++) {
        double q0 = 0.3 * amp[a], v0 = amp[a], *foci = NULL;
        size_t nf = 0;
        bool leg = false;
        assert_int_equal(qd_path_foci(f.ctx, f.m, f.e, 0.25, &q0, &v0, 0.25 + 3.3 * PI / 2,
                                      &foci, &nf, &leg),
                         QD_OK);
        assert_int_equal(nf, 3); /* pi/2, pi, 3 pi/2 after t0 */
        for (size_t j = 0; j < nf; j++)
            assert_true(fabs(foci[j] - (0.25 + (double)(j + 1) * PI / 2)) < 1e-9);
        assert_true(leg);
        qd_path_foci_free(f.ctx, foci);
    }
    unload(&f);
}

/* From theta = 0 with a small velocity: the focus tends to pi sqrt(l/g)
 * (Desloge ch. 84; the linearized pendulum's half period).  At finite
 * amplitude it comes later than half the libration's period 2 K(k)/w
 * (the neighbouring paths come back to theta = 0 at different times, the
 * longer for the larger v0): against the finite-difference measurement. */
static void test_pendulum_focus(void **state) {
    (void)state;
    fix f;
    load(&f, "coordinates th\nparameters m = 1.3, l = 0.8, g = 9.81\n"
             "T = m*l^2*th'^2/2\nV = -m*g*l*cos(th)\n");
    double w = sqrt(9.81 / 0.8), prev = 0;
    const double v[] = {1e-4, 0.5 * w, 1.2 * w};
    for (size_t i = 0; i < 3; i++) {
        double q0 = 0, v0 = v[i], *foci = NULL;
        size_t nf = 0;
        bool leg = false;
        assert_int_equal(qd_path_foci(f.ctx, f.m, f.e, 0, &q0, &v0, 1.5 * PI / w * 1.6, &foci,
                                      &nf, &leg),
                         QD_OK);
        assert_true(nf >= 1);
        if (i == 0)
            assert_true(fabs(foci[0] - PI / w) < 1e-8);
        else
            assert_true(fabs(foci[0] - pendulum_focus_fd(w, v0, foci[0] * 1.3)) < 1e-6);
        assert_true(foci[0] > prev); /* later with the amplitude */
        prev = foci[0];
        assert_true(leg);
        qd_path_foci_free(f.ctx, foci);
    }
    unload(&f);
}

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* A and B not diagonal: the modes mix x and y, det J still factors. */
static void test_coupled_oscillators(void **state) {
    (void)state;
    fix f;
    load(&f, "coordinates x, y\nparameters m = 1.5, k = 6\nT = m*(x'^2 + y'^2)/2\n"
             "V = k*(x^2 + (y - x)^2 + y^2)/2\n");
    double w1 = 2, w2 = sqrt(12.0), t1 = 4.5, want[16];
    size_t nw = 0;
    for (int j = 1; j * PI / w1 <= t1; j++)
        want[nw++] = j * PI / w1;
    for (int j = 1; j * PI / w2 <= t1; j++)
        want[nw++] = j * PI / w2;
    qsort(want, nw, sizeof *want, cmp_double);
    double q0[2] = {0.3, -0.1}, v0[2] = {1, 2}, *foci = NULL;
    size_t nf = 0;
    bool leg = false;
    assert_int_equal(qd_path_foci(f.ctx, f.m, f.e, 0, q0, v0, t1, &foci, &nf, &leg), QD_OK);
    assert_int_equal(nf, nw); /* 2 of w1, 4 of w2 */
    for (size_t j = 0; j < nf; j++)
        assert_true(fabs(foci[j] - want[j]) < 1e-9);
    assert_true(leg);
    qd_path_foci_free(f.ctx, foci);
    unload(&f);
}

/* A free particle in the plane: J = (t - t0) I never singular again. */
static void test_free_particle(void **state) {
    (void)state;
    fix f;
    load(&f, "coordinates x, y\nparameters m = 2\nT = m*(x'^2 + y'^2)/2\n");
    double q0[2] = {1, -2}, v0[2] = {3, 0.5}, *foci = NULL;
    size_t nf = 7;
    bool leg = false;
    assert_int_equal(qd_path_foci(f.ctx, f.m, f.e, 0, q0, v0, 50, &foci, &nf, &leg), QD_OK);
    assert_int_equal(nf, 0);
    assert_true(leg);
    qd_path_foci_free(f.ctx, foci);
    unload(&f);
}

/* m < 0: M = m is not positive definite, the path is no minimum. */
static void test_legendre_negative_mass(void **state) {
    (void)state;
    fix f;
    load(&f, "coordinates x\nparameters m = -1, k = -4\nT = m*x'^2/2\nV = k*x^2/2\n");
    double q0 = 0, v0 = 1, *foci = NULL;
    size_t nf = 0;
    bool leg = true;
    assert_int_equal(qd_path_foci(f.ctx, f.m, f.e, 0, &q0, &v0, 2, &foci, &nf, &leg), QD_OK);
    assert_false(leg);
    /* w = sqrt(k/m) = 2 still: a focus at pi/2 */
    assert_int_equal(nf, 1);
    assert_true(fabs(foci[0] - PI / 2) < 1e-9);
    qd_path_foci_free(f.ctx, foci);
    unload(&f);
}

static void test_constrained_refused(void **state) {
    (void)state;
    fix f;
    load(&f, "coordinates x, y\nparameters m = 1, l = 1, g = 9.81\nparticle m at (x, y)\n"
             "V = m*g*y\nconstraint rod: x^2 + y^2 = l^2\n");
    double q0[2] = {0, -1}, v0[2] = {0.1, 0}, *foci = NULL;
    size_t nf = 0;
    assert_int_equal(qd_path_foci(f.ctx, f.m, f.e, 0, q0, v0, 1, &foci, &nf, NULL), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(f.ctx), "constrained"));
    assert_null(foci);
    unload(&f);
}

static void test_bad_times(void **state) {
    (void)state;
    fix f;
    load(&f, "coordinates x\nT = x'^2/2\n");
    double q0 = 0, v0 = 1, *foci = NULL;
    size_t nf = 0;
    assert_int_equal(qd_path_foci(f.ctx, f.m, f.e, 1, &q0, &v0, 1, &foci, &nf, NULL), QD_ERR_ARG);
    unload(&f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_oscillator_half_period),
        cmocka_unit_test(test_pendulum_focus),
        cmocka_unit_test(test_coupled_oscillators),
        cmocka_unit_test(test_free_particle),
        cmocka_unit_test(test_legendre_negative_mass),
        cmocka_unit_test(test_constrained_refused),
        cmocka_unit_test(test_bad_times),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
