/*
 * tests/rel/test_lorentz.c - qdot/relativity.h against the worked cases of
 * Desloge vol. 2 ch. 86-91 (seed 000_46d037099a6cfcd7.txt; reference
 * /work/shared/reference/seed-desloge-D.md C6, C7, T11, T13, T15, T16, T21,
 * pitfalls P7-P11) and the invariants every Lorentz transformation keeps:
 * O^T g O = g, E^2 - p^2 c^2, the inverse boost, the ordered composition.
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

static void near(double got, double want, double tol) {
    if (!(fabs(got - want) <= tol * (1 + fabs(want))))
        fail_msg("got %.17g, want %.17g (tol %g)", got, want, tol);
}

static void near3(const double *got, double x, double y, double z, double tol) {
    near(got[0], x, tol);
    near(got[1], y, tol);
    near(got[2], z, tol);
}

static double rnd(void) { return 2.0 * rand() / RAND_MAX - 1; }

/* A random velocity of speed below 0.95 c. */
static void rnd_velocity(double c, double v[3]) {
    double s = 0.95 * c * fabs(rnd()) / sqrt(3);
    for (int i = 0; i < 3; i++)
        v[i] = s * rnd();
}

/* T11 (ch. 86 eq 30, eq 49; ch. 87 eq 2): v = (0, 0.5, 0), V = (0.6, 0, 0). */
static void velocity_T11(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    double V[3] = {0.6, 0, 0}, v[3] = {0, 0.5, 0}, w[3], g, G, gw;
    assert_int_equal(qd_lorentz_velocity(ctx, 1, V, v, w), QD_OK);
    near3(w, -0.6, 0.4, 0, 1e-15);
    assert_int_equal(qd_rel_gamma(ctx, 1, w, &gw), QD_OK);
    near(gw, 5 * sqrt(3) / 6, 1e-15);
    assert_int_equal(qd_rel_gamma(ctx, 1, v, &g), QD_OK);
    assert_int_equal(qd_rel_gamma(ctx, 1, V, &G), QD_OK);
    near(gw, G * g * (1 - 0), 1e-15); /* gamma' = G gamma (1 - v.V/c^2) */
    /* collinear addition 0.5 (+) 0.5 = 0.8, also with c = 3 (1.5 (+) 1.5 = 2.4) */
    double u[3] = {0.5, 0, 0}, s[3];
    assert_int_equal(qd_rel_compose(ctx, 1, u, u, s), QD_OK);
    near3(s, 0.8, 0, 0, 1e-15);
    double u3[3] = {1.5, 0, 0};
    assert_int_equal(qd_rel_compose(ctx, 3, u3, u3, s), QD_OK);
    near3(s, 2.4, 0, 0, 1e-15);
    qd_ctx_free(ctx);
}

/* T13, the twin paradox (ch. 87 Ex. 1 eqs 23-28): V = 0.8, tau = 3. */
static void twin_paradox_T13(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    double G = 5.0 / 3, V = 0.8, tau = 3, out[4];
    double back[3] = {-V, 0, 0};                      /* S'' moves with -V */
    double turn[4] = {G * tau, G * V * tau, 0, 0};     /* eq 24 */
    assert_int_equal(qd_lorentz_event(ctx, 1, back, turn, out), QD_OK);
    near(out[1], 40.0 / 3, 1e-14);                     /* eq 25: 2 G^2 V tau */
    near(out[0], 41.0 / 3, 1e-14);                     /* G^2 (1 + V^2) tau */
    double land[4] = {2 * G * tau, 0, 0, 0};           /* eq 28 */
    assert_int_equal(qd_lorentz_event(ctx, 1, back, land, out), QD_OK);
    near(out[0], 50.0 / 3, 1e-14);                     /* eq 27: 2 G^2 tau */
    near(out[1], 40.0 / 3, 1e-14);                     /* eq 26 */
    /* twin B's clock: proper time along |v| = 0.8 for 2 G tau = 10 is 2 tau = 6 */
    const qd_expr *v[3] = {qd_float(ctx, 0.8), qd_int(ctx, 0), qd_int(ctx, 0)};
    qd_rel_tau r;
    assert_int_equal(qd_rel_proper_time(ctx, 1, v, 0, 10, 0, &r), QD_OK);
    near(r.tau, 6, 1e-13);
    double dt, W[3] = {V, 0, 0};
    assert_int_equal(qd_rel_dilate(ctx, 1, W, 2 * tau, &dt), QD_OK); /* A ages 2 G tau */
    near(dt, 10, 1e-14);
    qd_ctx_free(ctx);
}

/* T15, rod and cylinder (ch. 87 Prob. 2; answer p. 991): V = sqrt(3)/2 c, G = 2. */
static void rod_cylinder_T15(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    double a = 1, c = 1, V[3] = {sqrt(3) / 2, 0, 0}, ev[4] = {0, -2 * a, 0, 0}, out[4];
    assert_int_equal(qd_lorentz_event(ctx, c, V, ev, out), QD_OK);
    near(out[1], -4 * a, 1e-15);
    near(out[0], 2 * sqrt(3) * a / c, 1e-15);
    /* the rod (proper length 4a, at rest in R') measures 2a in R; only the
     * component along V contracts (an oblique rod keeps its y extent) */
    double d[3] = {4 * a, 3 * a, 0}, l[3];
    assert_int_equal(qd_rel_contract(ctx, c, V, d, l), QD_OK);
    near3(l, 2 * a, 3 * a, 0, 1e-15);
    double Vo[3] = {0.3, 0.4, 0}, e[3] = {0, 0, 1}, lo[3]; /* perpendicular: unchanged */
    assert_int_equal(qd_rel_contract(ctx, c, Vo, e, lo), QD_OK);
    near3(lo, 0, 0, 1, 0);
    qd_ctx_free(ctx);
}

/* T21 (ch. 91): the boost matrix for V = 0.6 along x, O^T g O = g exactly;
 * random oblique frames keep the metric to round-off, and the matrix acts
 * on (x, y, z, ct) as the vector-form event transformation does. */
static void boost_matrix_T21(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    double O[16], V[3] = {0.6, 0, 0};
    assert_int_equal(qd_lorentz_boost(ctx, 1, V, O), QD_OK);
    const double want[16] = {1.25, 0, 0, -0.75, 0, 1, 0, 0, 0, 0, 1, 0, -0.75, 0, 0, 1.25};
    for (int i = 0; i < 16; i++)
        near(O[i], want[i], 1e-15);
    assert_true(qd_lorentz_metric_error(O) == 0);
    srand(35);
    for (int n = 0; n < 200; n++) {
        double c = 0.5 + 3 * fabs(rnd()), W[3], ev[4], out[4], X[4];
        rnd_velocity(c, W);
        for (int i = 0; i < 4; i++)
            ev[i] = rnd();
        assert_int_equal(qd_lorentz_boost(ctx, c, W, O), QD_OK);
        assert_true(qd_lorentz_metric_error(O) < 1e-12);
        assert_int_equal(qd_lorentz_event(ctx, c, W, ev, out), QD_OK);
        double x[4] = {ev[1], ev[2], ev[3], c * ev[0]};
        for (int i = 0; i < 4; i++) {
            X[i] = 0;
            for (int j = 0; j < 4; j++)
                X[i] += O[4 * i + j] * x[j];
        }
        near(X[3], c * out[0], 1e-12);
        near3(X, out[1], out[2], out[3], 1e-12);
    }
    /* a wrong matrix is caught: the Galilean transformation is not Lorentz */
    double gal[16] = {1, 0, 0, -0.6, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    assert_true(qd_lorentz_metric_error(gal) > 0.3);
    qd_ctx_free(ctx);
}

/* Invariants on random data: E^2 - p^2 c^2 and the interval are kept, the
 * boost by -V undoes the boost by V, and ch. 86 eq 30 agrees with the
 * four-momentum boost (v' = p' c^2/E'). */
static void invariants(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    srand(86);
    for (int n = 0; n < 500; n++) {
        double c = 0.5 + 3 * fabs(rnd()), V[3], v[3], mV[3], m = 0.1 + fabs(rnd());
        rnd_velocity(c, V);
        rnd_velocity(c, v);
        for (int i = 0; i < 3; i++)
            mV[i] = -V[i];
        double E, p[3], E1, p1[3], w[3], m1;
        assert_int_equal(qd_rel_momentum(ctx, c, m, v, &E, p), QD_OK);
        assert_int_equal(qd_lorentz_momentum(ctx, c, V, E, p, &E1, p1), QD_OK);
        assert_int_equal(qd_rel_mass(ctx, c, E1, p1, &m1), QD_OK);
        near(m1, m, 1e-11);
        assert_int_equal(qd_lorentz_velocity(ctx, c, V, v, w), QD_OK);
        near3(w, p1[0] * c * c / E1, p1[1] * c * c / E1, p1[2] * c * c / E1, 1e-11);
        double ev[4] = {rnd(), rnd(), rnd(), rnd()}, e1[4], e2[4];
        assert_int_equal(qd_lorentz_event(ctx, c, V, ev, e1), QD_OK);
        assert_int_equal(qd_lorentz_event(ctx, c, mV, e1, e2), QD_OK);
        for (int i = 0; i < 4; i++)
            near(e2[i], ev[i], 1e-11);
        double s0 = ev[1] * ev[1] + ev[2] * ev[2] + ev[3] * ev[3] - c * c * ev[0] * ev[0];
        double s1 = e1[1] * e1[1] + e1[2] * e1[2] + e1[3] * e1[3] - c * c * e1[0] * e1[0];
        near(s1, s0, 1e-10);
        /* composition is the inverse velocity transformation */
        double back[3];
        assert_int_equal(qd_rel_compose(ctx, c, V, w, back), QD_OK);
        near3(back, v[0], v[1], v[2], 1e-11);
    }
    qd_ctx_free(ctx);
}

/* Ch. 86 eq 44 against a finite difference of eq 30 along v(t) = v + a t:
 * a' = (dv'/dt)/(dt'/dt), dt'/dt = G (1 - v.V/c^2); and the instantaneous
 * rest frame (v = V, ch. 86 Prob. 1, pitfall P10): a'_par = G^3 a_par,
 * a'_perp = G^2 a_perp. */
static void acceleration(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    srand(44);
    for (int n = 0; n < 100; n++) {
        double c = 1, V[3], v[3], a[3], ap[3], G;
        rnd_velocity(c, V);
        rnd_velocity(c, v);
        for (int i = 0; i < 3; i++)
            a[i] = rnd();
        assert_int_equal(qd_lorentz_acceleration(ctx, c, V, v, a, ap), QD_OK);
        double h = 1e-5, vp[3], vm[3], wp[3], wm[3];
        for (int i = 0; i < 3; i++) {
            vp[i] = v[i] + a[i] * h;
            vm[i] = v[i] - a[i] * h;
        }
        assert_int_equal(qd_lorentz_velocity(ctx, c, V, vp, wp), QD_OK);
        assert_int_equal(qd_lorentz_velocity(ctx, c, V, vm, wm), QD_OK);
        assert_int_equal(qd_rel_gamma(ctx, c, V, &G), QD_OK);
        double rate = G * (1 - (v[0] * V[0] + v[1] * V[1] + v[2] * V[2]) / (c * c));
        for (int i = 0; i < 3; i++)
            near(ap[i], (wp[i] - wm[i]) / (2 * h) / rate, 1e-6);
    }
    double V[3] = {0.6, 0, 0}, a[3] = {1, 2, 3}, ap[3];
    assert_int_equal(qd_lorentz_acceleration(ctx, 1, V, V, a, ap), QD_OK);
    near3(ap, pow(1.25, 3), 2 * 1.25 * 1.25, 3 * 1.25 * 1.25, 1e-14);
    qd_ctx_free(ctx);
}

/* Pitfall P7 (ch. 87 eq 1): u (+) v and v (+) u have the same speed and
 * different directions; the angle between them is the Thomas-Wigner angle,
 * for perpendicular u and v cos th = (g1 + g2)/(1 + g1 g2). */
static void composition_order(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    double u[3] = {0.6, 0, 0}, v[3] = {0, 0.5, 0}, uv[3], vu[3], th;
    assert_int_equal(qd_rel_compose(ctx, 1, u, v, uv), QD_OK);
    assert_int_equal(qd_rel_compose(ctx, 1, v, u, vu), QD_OK);
    near3(uv, 0.6, 0.4, 0, 1e-15);
    near3(vu, 0.6 * sqrt(0.75), 0.5, 0, 1e-15);
    near(sqrt(uv[0] * uv[0] + uv[1] * uv[1]), sqrt(vu[0] * vu[0] + vu[1] * vu[1]), 1e-15);
    assert_int_equal(qd_rel_wigner_angle(ctx, 1, u, v, &th), QD_OK);
    double g1 = 1.25, g2 = 1 / sqrt(0.75);
    near(cos(th), (g1 + g2) / (1 + g1 * g2), 1e-14);
    assert_true(th > 0.17);
    qd_ctx_free(ctx);
}

/* Proper time of hyperbolic motion (ch. 89 Prob. 2 from rest, c = 1):
 * v = g t/sqrt(1 + (g t)^2) gives tau = asinh(g t)/g. */
static void proper_time(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    const qd_expr *vx = qd_read(ctx, "t/sqrt(1 + t^2)", NULL, &d);
    const qd_expr *v[3] = {vx, qd_int(ctx, 0), qd_int(ctx, 0)};
    qd_rel_tau r;
    assert_int_equal(qd_rel_proper_time(ctx, 1, v, 0, 2, 1e-13, &r), QD_OK);
    near(r.tau, asinh(2.0), 1e-12);
    assert_true(r.error < 1e-10);
    near(r.vmax, 2 / sqrt(5.0), 1e-6);
    /* a worldline that reaches c is refused, naming the time */
    const qd_expr *fast = qd_read(ctx, "t/2", NULL, &d);
    const qd_expr *w[3] = {fast, qd_int(ctx, 0), qd_int(ctx, 0)};
    assert_int_equal(qd_rel_proper_time(ctx, 1, w, 0, 3, 0, &r), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(ctx), "reaches c"));
    qd_ctx_clear_error(ctx);
    qd_ctx_free(ctx);
}

/* T16 (ch. 88 Prob. 1): m1 = 1 at +0.6 meets m2 = 2 at -0.8 and they
 * coalesce: M = sqrt(E^2 - p^2 c^2)/c^2 = sqrt(2496)/12 > m1 + m2 (P11),
 * V = p c^2/E = -23/55. */
static void merge_T16(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_rel_particle in[2], tot;
    double v1[3] = {0.6, 0, 0}, v2[3] = {-0.8, 0, 0};
    assert_int_equal(qd_rel_particle_make(ctx, 1, 1, v1, &in[0]), QD_OK);
    assert_int_equal(qd_rel_particle_make(ctx, 1, 2, v2, &in[1]), QD_OK);
    assert_int_equal(qd_rel_total(ctx, 1, 2, in, &tot), QD_OK);
    near(tot.E, 55.0 / 12, 1e-15);
    near(tot.m, sqrt(2496.0) / 12, 1e-15);
    near3(tot.v, -23.0 / 55, 0, 0, 1e-15);
    assert_true(tot.m > 3);
    qd_ctx_free(ctx);
}

/* Elastic collisions: four-momentum kept for any angle; equal masses on a
 * target at rest leave with tan th1 tan th2 = 2/(gamma1 + 1) (the
 * relativistic opening angle, below 90 degrees); the lab-angle solver
 * returns CM angles that give the lab angle asked for, and m1 > m2 has a
 * largest lab angle sin th_max = m2/m1. */
static void elastic(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_rel_particle in[2], out[2], t0, t1;
    double v1[3] = {0.8, 0, 0}, z[3] = {0, 0, 0};
    assert_int_equal(qd_rel_particle_make(ctx, 1, 1, v1, &in[0]), QD_OK);
    assert_int_equal(qd_rel_particle_make(ctx, 1, 1, z, &in[1]), QD_OK);
    for (double chi = 0.1; chi < 3.1; chi += 0.3) {
        assert_int_equal(qd_rel_elastic(ctx, 1, in, chi, 0.7, out), QD_OK);
        assert_int_equal(qd_rel_total(ctx, 1, 2, in, &t0), QD_OK);
        assert_int_equal(qd_rel_total(ctx, 1, 2, out, &t1), QD_OK);
        near(t1.E, t0.E, 1e-14);
        near3(t1.p, t0.p[0], t0.p[1], t0.p[2], 1e-14);
        near(out[0].m, 1, 0);
        double th1 = qd_rel_lab_angle(in, out, 0), th2 = qd_rel_lab_angle(in, out, 1);
        near(tan(th1) * tan(th2), 2 / (5.0 / 3 + 1), 1e-12);
    }
    /* equal masses: one CM angle per lab angle (chi = pi leaves particle 1
     * at rest in the lab, a jump of its direction that is no root) */
    double one[2];
    size_t n1;
    assert_int_equal(qd_rel_elastic_lab(ctx, 1, in, 0.5, one, &n1), QD_OK);
    assert_int_equal(n1, 1);
    /* m1 = 2 on m2 = 1 at rest: sin th_max = 1/2 */
    double v[3] = {0.9, 0, 0}, chi[2];
    size_t n;
    assert_int_equal(qd_rel_particle_make(ctx, 1, 2, v, &in[0]), QD_OK);
    assert_int_equal(qd_rel_elastic_lab(ctx, 1, in, 0.4, chi, &n), QD_OK);
    assert_int_equal(n, 2);
    for (size_t k = 0; k < n; k++) {
        assert_int_equal(qd_rel_elastic(ctx, 1, in, chi[k], 0, out), QD_OK);
        near(qd_rel_lab_angle(in, out, 0), 0.4, 1e-12);
    }
    assert_int_equal(qd_rel_elastic_lab(ctx, 1, in, asin(0.5) + 1e-6, chi, &n), QD_OK);
    assert_int_equal(n, 0);
    assert_int_equal(qd_rel_elastic_lab(ctx, 1, in, asin(0.5) - 1e-4, chi, &n), QD_OK);
    assert_int_equal(n, 2);
    qd_ctx_free(ctx);
}

/* Thresholds and decays: p + p -> p + p + p + pbar needs K = 6 m c^2 (the
 * classic antiproton threshold); pi+ -> mu+ nu has p* = (M^2 - m^2) c/(2 M);
 * a moving parent's products balance four-momentum; a massless product
 * moves at c. */
static void threshold_decay(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_rel_threshold th;
    assert_int_equal(qd_rel_threshold_of(ctx, 1, 1, 1, 4, &th), QD_OK);
    near(th.K, 6, 1e-15);
    near(th.E, 7, 1e-15);
    near(th.speed, sqrt(48.0) / 7, 1e-15);
    assert_int_equal(qd_rel_threshold_of(ctx, 2, 1, 1, 1.5, &th), QD_OK); /* no threshold */
    near(th.K, 0, 0);
    qd_rel_particle pi, out[2], tot;
    double v[3] = {0.3, -0.5, 0.2}, ps;
    const double Mpi = 139.57039, Mmu = 105.6583755;
    assert_int_equal(qd_rel_particle_make(ctx, 1, Mpi, v, &pi), QD_OK);
    assert_int_equal(qd_rel_decay(ctx, 1, &pi, Mmu, 0, 1.1, 0.3, out, &ps), QD_OK);
    near(ps, (Mpi * Mpi - Mmu * Mmu) / (2 * Mpi), 1e-13);
    assert_int_equal(qd_rel_total(ctx, 1, 2, out, &tot), QD_OK);
    near(tot.E, pi.E, 1e-13);
    near3(tot.p, pi.p[0], pi.p[1], pi.p[2], 1e-12);
    near(sqrt(out[1].v[0] * out[1].v[0] + out[1].v[1] * out[1].v[1] +
              out[1].v[2] * out[1].v[2]), 1, 1e-14);
    assert_int_equal(qd_rel_decay(ctx, 1, &pi, Mmu, 40, 0, 0, out, &ps), QD_ERR_ARG);
    qd_ctx_clear_error(ctx);
    qd_ctx_free(ctx);
}

/* Speeds at or beyond c are refused with a message; so is a spacelike
 * four-momentum and a bad c. */
static void refusals(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    double V[3] = {1, 0, 0}, v[3] = {0, 0, 0}, w[3], E, p[3] = {2, 0, 0}, m;
    assert_int_equal(qd_lorentz_velocity(ctx, 1, V, v, w), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(ctx), "not below c = 1"));
    qd_ctx_clear_error(ctx);
    double fast[3] = {0.6, 0.9, 0};
    assert_int_equal(qd_rel_momentum(ctx, 1, 1, fast, &E, p), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(ctx), "the velocity v has speed"));
    qd_ctx_clear_error(ctx);
    double q[3] = {2, 0, 0};
    assert_int_equal(qd_rel_mass(ctx, 1, 1, q, &m), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(ctx), "no particle has this four-momentum"));
    qd_ctx_clear_error(ctx);
    assert_int_equal(qd_lorentz_velocity(ctx, 0, v, v, w), QD_ERR_ARG);
    qd_ctx_clear_error(ctx);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(velocity_T11),     cmocka_unit_test(twin_paradox_T13),
        cmocka_unit_test(rod_cylinder_T15), cmocka_unit_test(boost_matrix_T21),
        cmocka_unit_test(invariants),       cmocka_unit_test(acceleration),
        cmocka_unit_test(composition_order), cmocka_unit_test(proper_time),
        cmocka_unit_test(merge_T16),        cmocka_unit_test(elastic),
        cmocka_unit_test(threshold_decay),  cmocka_unit_test(refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
