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
 *   the damped oscillator m x'' + b x' + k x = 0 (B = -b/m is what moves
 *   the foci): J = exp(-b t/(2m)) sin(W t)/W, W = sqrt(k/m - b^2/(4 m^2)),
 *   foci at j pi/W, later than the undamped j pi sqrt(m/k);
 *   the free particle: J = (t - t0) I, no focus;
 *   a negative mass: the Legendre condition fails;
 *   foci of higher multiplicity (isotropic oscillators: 2 in the plane,
 *   where det J does not change sign, 3 in space), close simple ones kept
 *   apart, and holonomic constraints with multipliers (geodesics on the
 *   2- and 3-sphere, the pendulum on a rod) against the same motion in
 *   free coordinates; nonholonomic constraints refused; every allocation
 *   failed in turn.
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
#include "util/fault.h"

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

/* B = d(x'')/dx' = -b/m: the zeros of J move from j pi/w to j pi/W. */
static void test_damped_oscillator(void **state) {
    (void)state;
    fix f;
    load(&f, "coordinates x\nparameters m = 1.2, k = 3, b = 0.9\nT = m/2*x'^2\nV = k/2*x^2\n"
             "dissipation = b/2*x'^2\n");
    double W = sqrt(3 / 1.2 - 0.81 / (4 * 1.44)), q0 = 1, v0 = 0, *foci = NULL;
    size_t nf = 0;
    assert_int_equal(qd_path_foci(f.ctx, f.m, f.e, 0, &q0, &v0, 2.5 * PI / W, &foci, &nf, NULL),
                     QD_OK);
    assert_int_equal(nf, 2);
    for (size_t j = 0; j < nf; j++)
        assert_true(fabs(foci[j] - (double)(j + 1) * PI / W) < 1e-9);
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

/* qd_path_foci_mult on the model text from (t0 = 0, q0, v0) up to t1. */
typedef struct found {
    double *foci;
    size_t *mult, n;
    bool legendre;
} found;

static void foci_of(const char *text, const double *q0, const double *v0, double t1,
                    found *out) {
    fix f;
    load(&f, text);
    assert_int_equal(qd_path_foci_mult(f.ctx, f.m, f.e, 0, q0, v0, t1, &out->foci, &out->mult,
                                       &out->n, &out->legendre),
                     QD_OK);
    qd_path_foci_free(f.ctx, NULL); /* freeing nothing is harmless */
    unload(&f);
}

static void found_free(found *fd) {
    qd_path_foci_free(NULL, fd->foci);
    qd_path_foci_mult_free(NULL, fd->mult);
}

/* The isotropic plane oscillator (Gelfand and Fomin ch. 5 sec. 27: every
 * solution from the origin returns at t = pi/w): J = sin(w t)/w I, det J =
 * (sin(w t)/w)^2 touches 0 without a sign change, each focus of
 * multiplicity 2, at j pi/w whatever q0 and v0.  Before foci of even
 * multiplicity were sought this found none. */
static void test_isotropic_plane(void **state) {
    (void)state;
    const double q0[2] = {0.4, -0.2}, v0[2] = {1.5, 0.7}, w = 1.5;
    found fd;
    foci_of("coordinates x, y\nparameters m = 2, k = 4.5\nT = m*(x'^2 + y'^2)/2\n"
            "V = k*(x^2 + y^2)/2\n", q0, v0, 2.5 * PI / w, &fd);
    assert_int_equal(fd.n, 2);
    for (size_t j = 0; j < fd.n; j++) {
        assert_true(fabs(fd.foci[j] - (double)(j + 1) * PI / w) < 1e-9);
        assert_int_equal(fd.mult[j], 2);
    }
    assert_true(fd.legendre);
    found_free(&fd);
}

/* In space, three Jacobi fields vanish together at pi/w: an odd focus
 * that det J (~ (t - tc)^3) did see, now once with multiplicity 3. */
static void test_isotropic_space(void **state) {
    (void)state;
    const double q0[3] = {0.1, 0.2, 0.3}, v0[3] = {-1, 0.5, 2}, w = 3;
    found fd;
    foci_of("coordinates x, y, z\nparameters m = 1, k = 9\nT = m*(x'^2 + y'^2 + z'^2)/2\n"
            "V = k*(x^2 + y^2 + z^2)/2\n", q0, v0, 1.2 * PI / w, &fd);
    assert_int_equal(fd.n, 1);
    assert_true(fabs(fd.foci[0] - PI / w) < 1e-9);
    assert_int_equal(fd.mult[0], 3);
    found_free(&fd);
}

/* Anisotropic, w1 = 2 and w2 = 2.02: det J = sin(w1 t) sin(w2 t)/(w1 w2),
 * two simple foci 0.0156 apart (pi/w2 first), which must not merge into
 * one of multiplicity 2. */
static void test_anisotropic_close(void **state) {
    (void)state;
    const double q0[2] = {0.3, 0.1}, v0[2] = {1, -1}, w1 = 2, w2 = 2.02;
    found fd;
    foci_of("coordinates x, y\nparameters m = 1, k1 = 4, k2 = 4.0804\nT = m*(x'^2 + y'^2)/2\n"
            "V = (k1*x^2 + k2*y^2)/2\n", q0, v0, 1.1 * PI / w1, &fd);
    assert_int_equal(fd.n, 2);
    assert_true(fabs(fd.foci[0] - PI / w2) < 1e-9);
    assert_true(fabs(fd.foci[1] - PI / w1) < 1e-9);
    assert_int_equal(fd.mult[0], 1);
    assert_int_equal(fd.mult[1], 1);
    found_free(&fd);
}

/* The path past an even focus is no minimum either (Desloge ch. 84): the
 * isotropic oscillator from (1, 0) to (0, 1) over 0.6 of a period passes
 * the double focus at half a period; over 0.4 it is a minimum. */
static void test_isotropic_path_minimum(void **state) {
    (void)state;
    fix f;
    load(&f, "coordinates x, y\nparameters m = 1, k = 1\nT = m*(x'^2 + y'^2)/2\n"
             "V = k*(x^2 + y^2)/2\n");
    const double q0[2] = {1, 0}, q1[2] = {0, 1}, frac[2] = {0.4, 0.6};
    for (int i = 0; i < 2; i++) {
        qd_path_opts o = {.t0 = 0, .t1 = frac[i] * 2 * PI, .q0 = q0, .q1 = q1};
        qd_path_set ps;
        assert_int_equal(qd_path_find(f.ctx, f.m, f.e, &o, &ps), QD_OK);
        assert_int_equal(ps.paths[0].nfoci, (size_t)i);
        assert_true(ps.paths[0].minimum == (i == 0));
        if (i == 1) {
            assert_true(fabs(ps.paths[0].foci[0] - PI) < 1e-8);
            assert_non_null(ps.paths[0].foci_mult);
            assert_int_equal(ps.paths[0].foci_mult[0], 2);
        }
        qd_path_set_free(&ps);
    }
    unload(&f);
}

#define SPHERE2 "coordinates x, y, z\nparameters m = 1.5, l = 1.3\nparticle m at (x, y, z)\n" \
                "constraint sphere: x^2 + y^2 + z^2 = l^2\n"

/* Geodesics on a sphere of radius l at speed v, written in Cartesian
 * coordinates with a multiplier: the antipode at t = pi l/v (Gelfand and
 * Fomin ch. 5 sec. 27).  Of the 2 admissible directions of v0, the change
 * of speed moves q(t) along the great circle and never vanishes: the focus
 * is simple (det J ~ t sin(v t/l)).  The same in spherical angles, started
 * on the equator along a great circle tilted by a (no pole on the way). */
static void test_sphere_cartesian(void **state) {
    (void)state;
    const double l = 1.3, v = 0.9, a = 0.5, tf = PI * l / v;
    const double q0[3] = {l, 0, 0}, v0[3] = {0, v * cos(a), v * sin(a)};
    found fc, fa;
    foci_of(SPHERE2, q0, v0, 1.5 * tf, &fc);
    assert_int_equal(fc.n, 1);
    assert_true(fabs(fc.foci[0] - tf) < 1e-8);
    assert_int_equal(fc.mult[0], 1);
    assert_true(fc.legendre);
    const double a0[2] = {PI / 2, 0}, av[2] = {-v * sin(a) / l, v * cos(a) / l};
    foci_of("coordinates th, ph\nparameters m = 1.5, l = 1.3\n"
            "particle m at l*(sin(th)*cos(ph), sin(th)*sin(ph), cos(th))\n", a0, av, 1.5 * tf,
            &fa);
    assert_int_equal(fa.n, 1);
    assert_true(fabs(fa.foci[0] - fc.foci[0]) < 1e-8);
    found_free(&fc);
    found_free(&fa);
}

/* The 3-sphere x^2 + y^2 + z^2 + w^2 = l^2: two normal Jacobi fields
 * sin(v t/l) vanish together at the antipode, a focus of multiplicity 2
 * (det of the 3 x 3 restricted J ~ t sin^2(v t/l) keeps its sign). */
static void test_three_sphere(void **state) {
    (void)state;
    const double l = 0.7, v = 1.1, tf = PI * l / v, s = sqrt(1.0 / 3);
    const double q0[4] = {0, 0, 0, l}, v0[4] = {v * s, -v * s, v * s, 0};
    found fd;
    foci_of("coordinates x, y, z, w\nparameters m = 2, l = 0.7\n"
            "T = m*(x'^2 + y'^2 + z'^2 + w'^2)/2\n"
            "constraint sphere: x^2 + y^2 + z^2 + w^2 = l^2\n", q0, v0, 2.2 * tf, &fd);
    assert_int_equal(fd.n, 2);
    assert_true(fabs(fd.foci[0] - tf) < 1e-8);
    assert_true(fabs(fd.foci[1] - 2 * tf) < 1e-8);
    assert_int_equal(fd.mult[0], 2);
    assert_int_equal(fd.mult[1], 2);
    found_free(&fd);
}

/* The pendulum as a point on a rod, x^2 + y^2 = l^2: from the stable
 * equilibrium its focus is the angle model's, pi sqrt(l/g) at small
 * amplitude (Desloge ch. 84) and the same later one at a large amplitude. */
static void test_pendulum_cartesian(void **state) {
    (void)state;
    const double l = 0.8, w = sqrt(9.81 / l), amp[2] = {1e-4, 0.7};
    for (int i = 0; i < 2; i++) {
        double v = amp[i] * w * l, q0[2] = {0, -l}, v0[2] = {v, 0}, th0 = 0, thd = v / l;
        found fc, fa;
        foci_of("coordinates x, y\nparameters m = 1.3, l = 0.8, g = 9.81\n"
                "particle m at (x, y)\nV = m*g*y\nconstraint rod: x^2 + y^2 = l^2\n", q0, v0,
                1.4 * PI / w, &fc);
        foci_of("coordinates th\nparameters m = 1.3, l = 0.8, g = 9.81\n"
                "particle m at l*(sin(th), -cos(th))\nV = -m*g*l*cos(th)\n", &th0, &thd,
                1.4 * PI / w, &fa);
        assert_int_equal(fc.n, 1);
        assert_int_equal(fa.n, 1);
        assert_int_equal(fc.mult[0], 1);
        assert_true(fabs(fc.foci[0] - fa.foci[0]) < 1e-8);
        if (i == 0)
            assert_true(fabs(fc.foci[0] - PI / w) < 1e-6);
        else
            assert_true(fc.foci[0] > PI / w + 1e-3); /* later with the amplitude */
        found_free(&fc);
        found_free(&fa);
    }
}

/* Legendre's condition asks M > 0 on the admissible velocities only
 * (Gelfand and Fomin ch. 5 sec. 29): T = (x'^2 - z'^2)/2 is indefinite,
 * but z = 0 leaves x' alone, with M = 1 there; a negative mass fails on
 * the tangent space too.  Foci at j pi/w either way (w = 2). */
static void test_legendre_on_tangent_space(void **state) {
    (void)state;
    const double q0[2] = {0.3, 0}, v0[2] = {1, 0};
    const char *model[2] = {"coordinates x, z\nparameters m = 1, k = 4\n"
                            "T = m*(x'^2 - z'^2)/2\nV = k*x^2/2\nconstraint flat: z = 0\n",
                            "coordinates x, z\nparameters m = -1, k = -4\n"
                            "T = m*(x'^2 + z'^2)/2\nV = k*x^2/2\nconstraint flat: z = 0\n"};
    for (int i = 0; i < 2; i++) {
        found fd;
        foci_of(model[i], q0, v0, 2, &fd);
        assert_true(fd.legendre == (i == 0));
        assert_int_equal(fd.n, 1);
        assert_true(fabs(fd.foci[0] - PI / 2) < 1e-8);
        found_free(&fd);
    }
}

/* The Chaplygin sleigh's blade is nonholonomic: its motions are not
 * stationary paths of the action, so they have no foci to report. */
static void test_nonholonomic_refused(void **state) {
    (void)state;
    fix f;
    load(&f, "coordinates x, y, th\nparameters m = 1, Ic = 0.2, a = 0.5\n"
             "body sled mass m inertia (0, 0, Ic) at (x + a*cos(th), y + a*sin(th)) "
             "orientation rot_z(th)\nconstraint blade: -x'*sin(th) + y'*cos(th) = 0\n");
    double q0[3] = {0, 0, 0}, v0[3] = {0.1, 0, 1}, *foci = NULL;
    size_t nf = 0;
    assert_int_equal(qd_path_foci(f.ctx, f.m, f.e, 0, q0, v0, 1, &foci, &nf, NULL), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(f.ctx), "nonholonomic"));
    assert_null(foci);
    unload(&f);
}

/* Every allocation of qd_path_foci_mult failed in turn (tests/util/fault.h)
 * on the sphere in Cartesian coordinates, whose tangent space and
 * Legendre test allocate too: the focus at pi l/v or a clean
 * QD_ERR_NOMEM, nothing leaked.  Parse and derivation run unfailed. */
static qd_status sphere_body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)data;
    long to_go = qt_fault_hold(f);
    qd_model *m = qd_model_parse(ctx, SPHERE2, NULL);
    qd_eom *e = m ? qd_eom_derive(ctx, m) : NULL;
    if (!e)
        fail_msg("parse or derive: %s", qd_ctx_message(ctx));
    const double l = 1.3, v = 4, tf = PI * l / v;
    const double q0[3] = {0, l, 0}, v0[3] = {v, 0, 0};
    double *foci = NULL;
    size_t *mult = NULL, nf = 0;
    qt_fault_release(f, to_go);
    qd_status st = qd_path_foci_mult(ctx, m, e, 0, q0, v0, 1.2 * tf, &foci, &mult, &nf, NULL);
    qt_fault_hold(f);
    if (st == QD_OK && !(nf == 1 && fabs(foci[0] - tf) < 1e-8 && mult[0] == 1))
        fail_msg("wrong foci after %ld allocations: %zu of them", f->count, nf);
    if (st != QD_OK && (foci || mult))
        fail_msg("a failed run left foci behind");
    qd_path_foci_free(ctx, foci);
    qd_path_foci_mult_free(ctx, mult);
    qd_eom_free(e);
    qd_model_free(m);
    return st;
}

static void test_foci_fault(void **state) {
    (void)state;
    assert_true(qt_fault_loop("sphere foci", sphere_body, NULL, 7).runs > 5);
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
        cmocka_unit_test(test_damped_oscillator),
        cmocka_unit_test(test_free_particle),
        cmocka_unit_test(test_legendre_negative_mass),
        cmocka_unit_test(test_isotropic_plane),
        cmocka_unit_test(test_isotropic_space),
        cmocka_unit_test(test_anisotropic_close),
        cmocka_unit_test(test_isotropic_path_minimum),
        cmocka_unit_test(test_sphere_cartesian),
        cmocka_unit_test(test_three_sphere),
        cmocka_unit_test(test_pendulum_cartesian),
        cmocka_unit_test(test_legendre_on_tangent_space),
        cmocka_unit_test(test_nonholonomic_refused),
        cmocka_unit_test(test_foci_fault),
        cmocka_unit_test(test_bad_times),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
