/*
 * tests/orbit/test_orbit.c - qd_orbit_solve against closed forms, each
 * cited (reference /work/shared/reference/seed-desloge-B.md, seed 000 is
 * Desloge vol. 2):
 *
 * - Kepler (Desloge ch. 58, C3 "Kepler closed forms"): the ellipse's
 *   turning points a(1 -+ e), p = h^2/(m k), e = sqrt(1 + 2 E h^2/(m k^2)),
 *   radial period 2 pi sqrt(m a^3/k), advance 2 pi; the hyperbola and the
 *   parabola unbound with one turning point p/(1 + e), turning by 2 acos(-1/e)
 *   between the asymptotes; the circle; Rutherford's repulsive hyperbola
 *   (C3's form p/(e cos - 1), its periapsis, T15's deflection).
 * - Desloge ch. 58 P8: the apsidal speeds in the ratio b/a and the speed
 *   (b^2 - a^2) v^2 = 2 a^2 int_a^r f + 2 b^2 int_r^b f.
 * - Power laws, force -k r^n (Desloge ch. 59 eq. 31, C3 and pitfall 10):
 *   the near-circular apsidal angle pi/sqrt(n + 3), by the general formula
 *   and by Bertrand's; Hooke's law (n = 1) closes with apsidal angle pi/2
 *   at every amplitude (Bertrand's theorem, ch. 59).
 * - Desloge ch. 58 P9 (T09 b): inverse-square plus inverse-cube force; the
 *   orbit 3a/(2r) = 1 + cos(sqrt(3) phi/2)/2 in closed form and by the
 *   quadrature (advance 4 pi/sqrt 3).
 * - Desloge ch. 58, the r^-4 potential V = -a/(4 r^4): at E = 0 the orbit
 *   is a circle through the centre, r = d cos(phi), d = sqrt(m a/2)/h: the
 *   particle falls in after phi turns by pi/2, in time (m d^2/h) pi/4; at
 *   E = h^4/(4a) (P10 b) the orbits b tanh(phi/sqrt 2) and b coth(phi/sqrt 2)
 *   creep towards the unstable circle r = b (kind asymptotic).
 * - Radial infall (T04, ch. 58 P1): fall time T/(4 sqrt 2).
 * - T07 (ch. 58 P7) Yukawa near-circular beta^2 = (1 + x - x^2)/(1 + x);
 *   T11 (ch. 58 P11) elastic string, apsidal angle 1.404962946.
 * - The spherical pendulum (Byerly Art. 5 Ex. 3, seed 001; examples/
 *   spherical_pendulum.qd): turning angles, radial period and advance of
 *   phi against a direct simulation (qd_sim) of the full model.
 *   With phi' = 0 it is a planar pendulum through theta = 0: period
 *   4 K(sin(theta0/2)) sqrt(a/g).
 * - The heavy top released with phi' = 0 (Goldstein sec. 5.7; Desloge
 *   ch. 64 Ex. 1, C8): the lower turning angle from the quadratic
 *   2 A M g h (1 - u^2) = p_psi^2 (u0 - u), u = cos(theta).
 * - Errors: no ignored coordinate, one not cyclic, two left, the energy
 *   below the minimum of V_eff, the period of an unbound orbit.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "qdot/orbit.h"
#include "qdot/qdot.h"
#include "sim/sim_fixture.h"

#define PI 3.14159265358979323846
#define MAXV 32

typedef struct fix {
    qd_ctx *ctx;
    qd_model *m;
    qd_eom *e;
    qd_orbit *o;
    qd_orbit_result r;
    size_t n;
    const qd_expr *syms[MAXV];
    double vals[MAXV];
} fix;

static void load(fix *f, const char *text) {
    memset(f, 0, sizeof *f);
    f->ctx = qd_ctx_new();
    qd_diag d;
    f->m = qd_model_parse(f->ctx, text, &d);
    if (!f->m)
        fprintf(stderr, "parse: %s\n", d.message);
    assert_non_null(f->m);
    f->e = qd_eom_derive(f->ctx, f->m);
    assert_non_null(f->e);
    for (size_t i = 0; i < qd_model_nparams(f->m); i++) {
        f->syms[f->n] = qd_model_param(f->m, i);
        f->vals[f->n++] = sf_number(f->ctx, qd_model_param_value(f->m, i));
    }
}

/* Reduce by the names (NULL-terminated); the status. */
static qd_status reduce(fix *f, const char *const *names) {
    const qd_expr *ign[8];
    size_t n = 0;
    for (; names[n]; n++)
        assert_non_null(ign[n] = qd_routh_lookup(f->ctx, f->m, names[n]));
    f->o = qd_orbit_derive(f->ctx, f->m, f->e, n, ign);
    return f->o ? QD_OK : qd_ctx_status(f->ctx);
}

static void set(fix *f, const char *name, double v) {
    const qd_expr *s = qd_lookup(f->ctx, name);
    assert_non_null(s);
    for (size_t i = 0; i < f->n; i++)
        if (f->syms[i] == s) {
            f->vals[i] = v;
            return;
        }
    f->syms[f->n] = s;
    f->vals[f->n++] = v;
}

static qd_status solve(fix *f, const double *energy) {
    qd_status st = qd_orbit_solve(f->ctx, f->o, f->n, f->syms, f->vals, energy, &f->r);
    if (st != QD_OK)
        fprintf(stderr, "solve: %s\n", qd_ctx_message(f->ctx));
    return st;
}

static void unload(fix *f) {
    qd_orbit_result_free(&f->r);
    qd_orbit_free(f->o);
    qd_eom_free(f->e);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
}

static void near(double got, double want, double rel) {
    if (!(fabs(got - want) <= rel * fmax(1, fabs(want)))) {
        fprintf(stderr, "got %.17g, want %.17g (tol %g)\n", got, want, rel);
        fail();
    }
}

static const char *const THETA[] = {"theta", NULL};
static const char *const PHI[] = {"phi", NULL};

/* ---- Kepler ------------------------------------------------------------------ */

static const char kepler[] =
    "coordinates r, theta\nparameters m = 1.3, k = 4\n"
    "particle m at r*(cos(theta), sin(theta))\nV = -k/r\n";

typedef struct kep { double E, h, p, e, a; } kep;

/* The closed forms at r, r', theta' (seed-desloge-B.md C3; h = m r^2 theta'). */
static kep kepler_expect(double r, double rd, double td) {
    double m = 1.3, k = 4;
    kep K;
    K.h = m * r * r * td;
    K.E = m * (rd * rd + r * r * td * td) / 2 - k / r;
    K.p = K.h * K.h / (m * k);
    K.e = sqrt(1 + 2 * K.E * K.h * K.h / (m * k * k));
    K.a = K.p / (1 - K.e * K.e);
    return K;
}

static void kepler_at(fix *f, double r, double rd, double td) {
    load(f, kepler);
    assert_int_equal(reduce(f, THETA), QD_OK);
    assert_true(f->o->kepler && f->o->central);
    set(f, "r", r);
    set(f, "r'", rd);
    set(f, "theta'", td);
    assert_int_equal(solve(f, NULL), QD_OK);
}

static void test_kepler_ellipse(void **state) {
    (void)state;
    fix f;
    kepler_at(&f, 1.0, 0.4, 1.5);
    kep K = kepler_expect(1.0, 0.4, 1.5);
    assert_int_equal(f.r.kind, QD_ORBIT_BOUND);
    assert_int_equal(f.r.nturn, 2);
    near(f.r.energy, K.E, 1e-15);
    near(f.r.momenta[0], K.h, 1e-15);
    near(f.r.turn[0], K.a * (1 - K.e), 1e-13);
    near(f.r.turn[1], K.a * (1 + K.e), 1e-13);
    near(f.r.period, 2 * PI * sqrt(1.3 * K.a * K.a * K.a / 4), 1e-12);
    near(f.r.advance[0], 2 * PI, 1e-12);
    near(f.r.apsidal[0], PI, 1e-12);
    near(f.r.precession[0], 0, 1e-11);
    assert_true(f.r.conic);
    near(f.r.p, K.p, 1e-14);
    near(f.r.e, K.e, 1e-14);
    near(f.r.a, K.a, 1e-13);
    near(f.r.nu, 1, 1e-15);
    /* the conic through the state: r = p/(1 + e cos(0 - periapsis)), moving outwards */
    near(K.p / (1 + K.e * cos(-f.r.periapsis)), 1.0, 1e-13);
    assert_true(sin(-f.r.periapsis) > 0);
    /* the circle at this h: r = p, stable, omega^2 = k/(m p^3) */
    assert_int_equal(f.r.ncircle, 1);
    near(f.r.circle[0].x, K.p, 1e-13);
    assert_int_equal(f.r.circle[0].stable, 1);
    near(f.r.circle[0].omega, sqrt(4 / (1.3 * K.p * K.p * K.p)), 1e-12);
    near(f.r.circle[0].apsidal[0], PI, 1e-12);
    near(f.r.circle[0].bertrand, PI, 1e-12);
    unload(&f);
}

/* Retrograde: the same ellipse run the other way round. */
static void test_kepler_retrograde(void **state) {
    (void)state;
    fix f;
    kepler_at(&f, 1.0, 0.4, -1.5);
    kep K = kepler_expect(1.0, 0.4, -1.5);
    near(f.r.momenta[0], K.h, 1e-15);
    near(f.r.advance[0], -2 * PI, 1e-12);
    near(f.r.apsidal[0], PI, 1e-12);
    near(f.r.precession[0], 0, 1e-11);
    near(f.r.period, 2 * PI * sqrt(1.3 * K.a * K.a * K.a / 4), 1e-12);
    near(K.p / (1 + K.e * cos(-f.r.periapsis)), 1.0, 1e-13);
    unload(&f);
}

static void test_kepler_hyperbola(void **state) {
    (void)state;
    fix f;
    kepler_at(&f, 1.0, -1.0, 3.0);
    kep K = kepler_expect(1.0, -1.0, 3.0);
    assert_true(K.E > 0);
    assert_int_equal(f.r.kind, QD_ORBIT_UNBOUND);
    assert_int_equal(f.r.nturn, 1);
    near(f.r.turn[0], K.p / (1 + K.e), 1e-13);
    assert_true(isinf(f.r.hi));
    assert_true(f.r.conic);
    near(f.r.e, K.e, 1e-14);
    near(f.r.a, K.a, 1e-13);
    assert_true(f.r.a < 0);
    double T;
    assert_int_equal(qd_orbit_period(f.ctx, f.o, &f.r, &T), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(f.ctx), "unbound"));
    assert_true(isnan(f.r.period));
    /* the whole turn between the asymptotes, r -> inf at cos(theta) = -1/e */
    near(f.r.advance[0], 2 * acos(-1 / K.e), 1e-12);
    unload(&f);
}

static void test_kepler_parabola(void **state) {
    (void)state;
    fix f;
    /* E = 0: m r^2 theta'^2/2 = k/r at r = 1, r' = 0 */
    double td = sqrt(2 * 4 / 1.3);
    kepler_at(&f, 1.0, 0.0, td);
    assert_int_equal(f.r.kind, QD_ORBIT_UNBOUND);
    near(f.r.e, 1, 1e-14);
    assert_true(isinf(f.r.a));
    near(f.r.turn[0], 1.0, 1e-14); /* the state is the periapsis */
    near(f.r.periapsis, 0, 1e-12);
    near(f.r.advance[0], 2 * PI, 1e-12); /* in along theta = -pi, out along pi */
    unload(&f);
}

static void test_kepler_circle(void **state) {
    (void)state;
    fix f;
    double r = 1.7, td = sqrt(4 / (1.3 * r * r * r));
    kepler_at(&f, r, 0.0, td);
    assert_int_equal(f.r.kind, QD_ORBIT_CIRCULAR);
    near(f.r.period, 2 * PI * sqrt(1.3 * r * r * r / 4), 1e-12);
    near(f.r.advance[0], 2 * PI, 1e-12);
    near(f.r.e, 0, 1e-7);
    unload(&f);
}

/* Rutherford's repulsive k/r (Desloge ch. 60 ex. 2, T15; the conic in C3's
 * repulsive form r = p/(e cos(theta - theta_peri) - 1), p = h^2/(m k)).  The
 * state moves inwards with theta' > 0, so the closest approach p/(e - 1) comes
 * later, at theta_peri > 0, and the orbit turns by 2 acos(1/e) between its
 * asymptotes: the deflection pi - 2 acos(1/e) is Rutherford's tan(Theta/2) =
 * k/(2 E b), b = h/sqrt(2 m E).  Written as p/(1 + e cos) the periapsis came
 * out half a turn away (at -2.76 instead of 0.38 here) with p < 0 and a > 0. */
static void test_kepler_repulsive(void **state) {
    (void)state;
    fix f;
    double m = 1.3, k = 4, r = 1, rd = -1.5, td = 2.5;
    load(&f, "coordinates r, theta\nparameters m = 1.3, k = 4\n"
             "particle m at r*(cos(theta), sin(theta))\nV = k/r\n");
    assert_int_equal(reduce(&f, THETA), QD_OK);
    set(&f, "r", r);
    set(&f, "r'", rd);
    set(&f, "theta'", td);
    assert_int_equal(solve(&f, NULL), QD_OK);
    double h = m * r * r * td, E = m * (rd * rd + r * r * td * td) / 2 + k / r;
    double p = h * h / (m * k), e = sqrt(1 + 2 * E * h * h / (m * k * k));
    assert_int_equal(f.r.kind, QD_ORBIT_UNBOUND);
    assert_true(f.r.conic && f.r.repulsive);
    near(f.r.p, p, 1e-14);
    near(f.r.e, e, 1e-14);
    near(f.r.a, -k / (2 * E), 1e-13);
    near(f.r.turn[0], p / (e - 1), 1e-13);
    assert_true(f.r.periapsis > 0 && f.r.periapsis < PI);
    near(p / (e * cos(f.r.periapsis - f.r.periapsis) - 1), f.r.turn[0], 1e-13);
    near(p / (e * cos(0 - f.r.periapsis) - 1), r, 1e-13); /* through the state */
    near(f.r.advance[0], 2 * acos(1 / e), 1e-12);
    double b = h / sqrt(2 * m * E);
    near(PI - f.r.advance[0], 2 * atan(k / (2 * E * b)), 1e-12);
    unload(&f);
}

/* ---- power laws and Desloge's problems ------------------------------------------ */

static const char power[] =
    "coordinates r, theta\nparameters m = 1, k = 1, n = 2\n"
    "particle m at (r*cos(theta), r*sin(theta))\nV = k*r^(n + 1)/(n + 1)\n";

static void test_power_law_apsidal(void **state) {
    (void)state;
    const double ns[] = {-2.5, -1.5, -0.5, 0.5, 1, 2, 3.5};
    for (size_t i = 0; i < sizeof ns / sizeof *ns; i++) {
        fix f;
        load(&f, power);
        set(&f, "n", ns[i]);
        assert_int_equal(reduce(&f, THETA), QD_OK);
        /* the circle at r = 1 needs theta'^2 = k r^(n-1)/m = 1: nudge r' */
        set(&f, "r", 1);
        set(&f, "theta'", 1);
        set(&f, "r'", 1e-4);
        assert_int_equal(solve(&f, NULL), QD_OK);
        double want = PI / sqrt(ns[i] + 3);
        assert_int_equal(f.r.kind, QD_ORBIT_BOUND);
        assert_int_equal(f.r.ncircle, 1);
        near(f.r.circle[0].x, 1, 1e-12);
        near(f.r.circle[0].apsidal[0], want, 1e-12);
        near(f.r.circle[0].bertrand, want, 1e-12);
        /* amplitude 1e-4: the true apsidal angle is pi/beta + O(amplitude^2) */
        near(f.r.apsidal[0], want, 1e-6);
        unload(&f);
    }
}

static void test_hooke_closes(void **state) {
    (void)state;
    fix f;
    load(&f, power);
    set(&f, "n", 1);
    assert_int_equal(reduce(&f, THETA), QD_OK);
    set(&f, "r", 1);
    set(&f, "theta'", 0.3);
    set(&f, "r'", 2);
    assert_int_equal(solve(&f, NULL), QD_OK);
    assert_int_equal(f.r.kind, QD_ORBIT_BOUND);
    near(f.r.apsidal[0], PI / 2, 1e-12);
    near(f.r.period, PI, 1e-12); /* half the period 2 pi/omega of the ellipse, omega = 1 */
    unload(&f);
}

/* T09 (b): F = -(h0^2/m)(2/(a r^2) + 1/r^3), restarted at r = a with h = 2 h0. */
static void test_inverse_cube(void **state) {
    (void)state;
    fix f;
    load(&f, "coordinates r, phi\nparameters m = 1.5, a = 0.8, h0 = 1.1\n"
             "particle m at r*(cos(phi), sin(phi))\n"
             "V = -2*h0^2/(m*a*r) - h0^2/(2*m*r^2)\n");
    assert_int_equal(reduce(&f, PHI), QD_OK);
    assert_true(f.o->kepler);
    set(&f, "r", 0.8);
    set(&f, "phi'", 2 * 1.1 / (1.5 * 0.8 * 0.8));
    assert_int_equal(solve(&f, NULL), QD_OK);
    assert_int_equal(f.r.kind, QD_ORBIT_BOUND);
    near(f.r.nu, sqrt(3) / 2, 1e-14);
    near(f.r.e, 0.5, 1e-14);
    near(f.r.p, 1.5 * 0.8, 1e-14);
    near(f.r.periapsis, 0, 1e-14);
    near(f.r.turn[0], 0.8, 1e-14);
    near(f.r.turn[1], 3 * 0.8, 1e-13); /* 3a/(2r) = 1/2 */
    near(f.r.advance[0], 4 * PI / sqrt(3), 1e-12);
    near(f.r.precession[0], 4 * PI / sqrt(3) - 2 * PI, 1e-11);
    unload(&f);
}

/* Desloge ch. 58 P8 (seed 000): with two apsidal distances a < b the apsidal
 * speeds are in the ratio b/a, and the speed at r obeys
 *     (b^2 - a^2) v^2 = 2 a^2 int_a^r f dr + 2 b^2 int_r^b f dr
 * (unit mass, f = dV/dr the attraction; from energy and h = a v_a = b v_b; the
 * seed's OCR drops the 2s).  Here f = k r^n (power law n = 2, V = k r^3/3)
 * and the Yukawa V = -A e^(-B r)/r, with the speeds at the apsides taken from
 * the energy alone, sqrt(2 (E - V)), so both turning points are checked as the
 * places where the whole speed is transverse. */
static void apsidal_speeds(const char *model, double (*V)(double), double r0, double rd0,
                           double td0) {
    fix f;
    load(&f, model);
    assert_int_equal(reduce(&f, PHI), QD_OK);
    set(&f, "r", r0);
    set(&f, "r'", rd0);
    set(&f, "phi'", td0);
    assert_int_equal(solve(&f, NULL), QD_OK);
    assert_int_equal(f.r.kind, QD_ORBIT_BOUND);
    double a = f.r.turn[0], b = f.r.turn[1], E = f.r.energy;
    near(E, (rd0 * rd0 + r0 * r0 * td0 * td0) / 2 + V(r0), 1e-14);
    double va = sqrt(2 * (E - V(a))), vb = sqrt(2 * (E - V(b)));
    near(va / vb, b / a, 1e-12);
    double v2 = rd0 * rd0 + r0 * r0 * td0 * td0;
    /* int f dr = V: 2 a^2 (V(r) - V(a)) + 2 b^2 (V(b) - V(r)) */
    near((b * b - a * a) * v2, 2 * a * a * (V(r0) - V(a)) + 2 * b * b * (V(b) - V(r0)), 1e-12);
    unload(&f);
}

static double V_cubic(double r) { return r * r * r / 3; }
static double V_yukawa(double r) { return -2 * exp(-0.6 * r) / r; }

static void test_apsidal_speeds(void **state) {
    (void)state;
    apsidal_speeds("coordinates r, phi\nparameters m = 1\n"
                   "particle m at r*(cos(phi), sin(phi))\nV = r^3/3\n",
                   V_cubic, 1.2, 0.7, 0.9);
    apsidal_speeds("coordinates r, phi\nparameters m = 1\n"
                   "particle m at r*(cos(phi), sin(phi))\nV = -2*exp(-0.6*r)/r\n",
                   V_yukawa, 1.0, 0.3, 1.1);
}

/* V = -a/(4 r^4) at E = 0: the circle through the centre. */
static void test_r4_capture(void **state) {
    (void)state;
    fix f;
    double m = 1.2, a = 0.9, h = 0.7, d = sqrt(m * a / 2) / h;
    load(&f, "coordinates r, phi\nparameters m = 1.2, a = 0.9\n"
             "particle m at r*(cos(phi), sin(phi))\nV = -a/(4*r^4)\n");
    assert_int_equal(reduce(&f, PHI), QD_OK);
    set(&f, "r", d);
    set(&f, "phi'", h / (m * d * d));
    assert_int_equal(solve(&f, NULL), QD_OK);
    near(f.r.energy, 0, 1e-14);
    assert_int_equal(f.r.kind, QD_ORBIT_CAPTURE);
    near(f.r.turn[0], d, 1e-14);
    near(f.r.advance[0], PI / 2, 1e-12);
    near(f.r.fall_time, m * d * d / h * PI / 4, 1e-12);
    /* the one circle, r0^2 = m a/h^2, is unstable (T13: V = -k/r^n, n = 4 > 2) */
    assert_int_equal(f.r.ncircle, 1);
    near(f.r.circle[0].x, sqrt(m * a) / h, 1e-12);
    assert_int_equal(f.r.circle[0].stable, 0);
    unload(&f);
}

/* Desloge ch. 58 P10 (b), seed 000 (unit mass): at E = h^4/(4a), the top of
 * V_eff at the unstable circle r = b = sqrt(a)/h, the orbit is r = b tanh(phi/sqrt 2)
 * inside the circle and b coth(phi/sqrt 2) outside: both creep towards r = b
 * while phi grows without end.  The walk used to pass through the double root
 * (E - V_eff touches 0 there without changing sign) and call both unbound over
 * 0 <= r <= inf.  Just below the top the inside orbit is still a capture. */
static void separatrix_at(double r, double E, qd_orbit_kind want, double lo, double hi) {
    double a = 0.9, h = 0.7, b = sqrt(a) / h;
    fix f;
    load(&f, "coordinates r, phi\nparameters m = 1, a = 0.9\n"
             "particle m at r*(cos(phi), sin(phi))\nV = -a/(4*r^4)\n");
    assert_int_equal(reduce(&f, PHI), QD_OK);
    set(&f, "r", r);
    set(&f, "phi'", h / (r * r));
    assert_int_equal(solve(&f, &E), QD_OK);
    assert_int_equal(f.r.kind, want);
    if (want == QD_ORBIT_ASYMPTOTIC) {
        assert_true(f.r.lo >= 0);
        near(f.r.lo, lo, 1e-12);
        if (isinf(hi))
            assert_true(isinf(f.r.hi));
        else
            near(f.r.hi, hi, 1e-12);
        assert_int_equal(f.r.nturn, 0);
        assert_true(isinf(f.r.advance[0]) && f.r.advance[0] > 0);
        assert_true(isnan(f.r.period));
        double T;
        assert_int_equal(qd_orbit_period(f.ctx, f.o, &f.r, &T), QD_ERR_ARG);
    } else {
        assert_true(f.r.turn[0] < b && f.r.turn[0] > 0.99 * b);
    }
    unload(&f);
}

static void test_r4_separatrix(void **state) {
    (void)state;
    double a = 0.9, h = 0.7, b = sqrt(a) / h, top = h * h * h * h / (4 * a);
    separatrix_at(b * tanh(0.5), top, QD_ORBIT_ASYMPTOTIC, 0, b);
    separatrix_at(b / tanh(0.5), top, QD_ORBIT_ASYMPTOTIC, b, INFINITY);
    separatrix_at(b * tanh(0.5), top * (1 - 1e-9), QD_ORBIT_CAPTURE, 0, 0);
}

static void test_radial_infall(void **state) {
    (void)state;
    fix f;
    load(&f, kepler);
    assert_int_equal(reduce(&f, THETA), QD_OK);
    set(&f, "r", 2.5);
    assert_int_equal(solve(&f, NULL), QD_OK);
    assert_int_equal(f.r.kind, QD_ORBIT_CAPTURE);
    double T = 2 * PI * sqrt(1.3 * 2.5 * 2.5 * 2.5 / 4);
    near(f.r.fall_time, T / (4 * sqrt(2)), 1e-12);
    unload(&f);
}

static void test_yukawa_and_string(void **state) {
    (void)state;
    fix f;
    /* T07: x = b r0 = 0.6 at r0 = 1 */
    load(&f, "coordinates r, phi\nparameters m = 1, a = 2, b = 0.6\n"
             "particle m at r*(cos(phi), sin(phi))\nV = -a*exp(-b*r)/r\n");
    assert_int_equal(reduce(&f, PHI), QD_OK);
    set(&f, "r", 1);
    set(&f, "phi'", sqrt(2 * 1.6 * exp(-0.6))); /* h^2 = m a r0 (1 + b r0) e^(-b r0) */
    assert_int_equal(solve(&f, NULL), QD_OK);
    assert_int_equal(f.r.kind, QD_ORBIT_CIRCULAR);
    double x = 0.6, b2 = (1 + x - x * x) / (1 + x);
    near(f.r.apsidal[0], PI / sqrt(b2), 1e-10);
    near(f.r.energy, -2 * (1 - x) * exp(-x) / 2, 1e-14);
    unload(&f);
    /* T11: F = -lam (r - a), circle at b = 2, a = 1 */
    load(&f, "coordinates r, phi\nparameters m = 1, lam = 3, a = 1\n"
             "particle m at r*(cos(phi), sin(phi))\nV = lam*(r - a)^2/2\n");
    assert_int_equal(reduce(&f, PHI), QD_OK);
    set(&f, "r", 2);
    set(&f, "phi'", sqrt(3 * (2 - 1) / 2.0)); /* m r phi'^2 = lam (r - a) */
    assert_int_equal(solve(&f, NULL), QD_OK);
    bool found = false;
    for (size_t i = 0; i < f.r.ncircle; i++)
        if (fabs(f.r.circle[i].x - 2) < 1e-9) {
            near(f.r.circle[i].bertrand, 1.404962946, 1e-9);
            near(f.r.circle[i].apsidal[0], PI * sqrt(1.0 / 5), 1e-12);
            found = true;
        }
    assert_true(found);
    unload(&f);
}

/* ---- the spherical pendulum against the simulation --------------------------- */

static const char spherical[] =
    "coordinates theta, phi\nparameters m = 1.1, a = 0.9, g = 9.81\n"
    "r = a*(sin(theta)*cos(phi), sin(theta)*sin(phi), -cos(theta))\n"
    "particle m at r\nV = m*g*r.z\n"
    "initial theta = 0.6, phi = 0, theta' = 0, phi' = 3\n";

static void test_spherical_pendulum(void **state) {
    (void)state;
    fix f;
    load(&f, spherical);
    assert_int_equal(reduce(&f, PHI), QD_OK);
    assert_false(f.o->central);
    set(&f, "theta", 0.6);
    set(&f, "phi'", 3);
    assert_int_equal(solve(&f, NULL), QD_OK);
    assert_int_equal(f.r.kind, QD_ORBIT_BOUND);
    sim_fix *s = sf_load(spherical);
    assert_non_null(s);
    const qd_expr *thd = qd_jet(s->ctx, qd_lookup(s->ctx, "theta"), 1);
    assert_int_equal(qd_sim_add_event(s->s, thd, 0, NULL, false), QD_OK);
    s->max_events = 3;
    assert_int_equal(sf_run(s, QD_SIM_DOP853, 20, 0, 1e-13, false), QD_OK);
    assert_true(s->nev >= 2);
    size_t k = s->ev_t[0] < 1e-9 ? 1 : 0; /* the start may count as an event */
    double th1 = s->ev_row[k][1], th2 = s->ev_row[k + 1][1], T = s->ev_t[k + 1];
    near(fmin(th1, th2), f.r.turn[0], 1e-9);
    near(fmax(th1, th2), f.r.turn[1], 1e-9);
    near(f.r.turn[1], 0.6, 1e-14);
    near(f.r.period, T, 1e-9);
    near(f.r.advance[0], s->ev_row[k + 1][2], 1e-9);
    sf_free(s);
    unload(&f);
}

/* With no angular momentum the pendulum swings through theta = 0, where the
 * centrifugal term is 0/0, not a centre of force: the planar pendulum's period
 * 4 K(sin(theta0/2)) sqrt(a/g) (Byerly Art. 5; A&S 17.6 for K). */
static void test_planar_pendulum(void **state) {
    (void)state;
    fix f;
    load(&f, spherical);
    assert_int_equal(reduce(&f, PHI), QD_OK);
    set(&f, "theta", 0.6);
    assert_int_equal(solve(&f, NULL), QD_OK);
    assert_int_equal(f.r.kind, QD_ORBIT_BOUND);
    near(f.r.turn[0], -0.6, 1e-14);
    near(f.r.turn[1], 0.6, 1e-14);
    near(f.r.period, 4 * sf_ellipk(sin(0.3)) * sqrt(0.9 / 9.81), 1e-12);
    near(f.r.advance[0], 0, 1e-15);
    bool hanging = false;
    for (size_t i = 0; i < f.r.ncircle; i++)
        if (fabs(f.r.circle[i].x) < 1e-12) {
            hanging = f.r.circle[i].stable == 1;
            near(f.r.circle[i].omega, sqrt(9.81 / 0.9), 1e-7);
        }
    assert_true(hanging);
    qd_orbit_result_free(&f.r);
    /* at E = m g a, the energy of the upright pendulum, it creeps towards theta =
     * +-pi (the separatrix) and never swings back or over */
    double top = 1.1 * 9.81 * 0.9;
    assert_int_equal(solve(&f, &top), QD_OK);
    assert_int_equal(f.r.kind, QD_ORBIT_ASYMPTOTIC);
    near(f.r.lo, -PI, 1e-12);
    near(f.r.hi, PI, 1e-12);
    near(f.r.advance[0], 0, 0);
    unload(&f);
}

/* ---- the heavy top: nutation between two angles ------------------------------------ */

static void test_heavy_top(void **state) {
    (void)state;
    fix f;
    load(&f, "coordinates phi, theta, psi\n"
             "parameters M = 1.2, h = 0.3, A = 0.5, C = 0.8, g = 9.81\n"
             "body top mass M inertia (A - M*h^2, A - M*h^2, C) at h*(sin(theta)*sin(phi), "
             "-sin(theta)*cos(phi), cos(theta)) orientation euler(phi, theta, psi)\n"
             "V = M*g*h*cos(theta)\n");
    const char *const ign[] = {"phi", "psi", NULL};
    assert_int_equal(reduce(&f, ign), QD_OK);
    set(&f, "theta", 0.5);
    set(&f, "psi'", 30);
    assert_int_equal(solve(&f, NULL), QD_OK);
    assert_int_equal(f.r.kind, QD_ORBIT_BOUND);
    double p = 0.8 * 30, Mgh = 1.2 * 9.81 * 0.3, A = 0.5, u0 = cos(0.5);
    near(f.r.momenta[1], p, 1e-14);
    /* 2 A M g h u^2 - p^2 u + p^2 u0 - 2 A M g h = 0, the root below u0 */
    double qa = 2 * A * Mgh, qb = -p * p, qc = p * p * u0 - qa;
    double disc = sqrt(qb * qb - 4 * qa * qc);
    double u = 2 * qc / (-qb + disc); /* the smaller root, the one in [-1, 1] */
    assert_true(u < u0 && u > -1);
    near(f.r.turn[0], 0.5, 1e-13);
    near(f.r.turn[1], acos(u), 1e-10);
    unload(&f);
}

/* ---- errors ------------------------------------------------------------------------ */

/* Desloge ch. 58, seed-desloge-C.md T9: V = 2 lam r - mu^2/(2 r^2) with
 * p_theta = mu, so V_eff = 2 lam r: from rest at r = a the particle falls
 * into the centre in sqrt(a/lam) with r' finite there and theta' = mu/r^2,
 * so it turns infinitely often on the way.  The advance is infinite, not a
 * failed quadrature (it was "did not converge", exit 1). */
static void test_cancelled_centrifugal(void **state) {
    (void)state;
    fix f;
    load(&f, "coordinates r, theta\nparameters lam = 0.8, mu = 1.1\n"
             "particle 1 at r*(cos(theta), sin(theta))\nV = 2*lam*r - mu^2/(2*r^2)\n");
    assert_int_equal(reduce(&f, THETA), QD_OK);
    set(&f, "r", 2);
    set(&f, "theta'", 1.1 / 4);
    assert_int_equal(solve(&f, NULL), QD_OK);
    assert_int_equal(f.r.kind, QD_ORBIT_CAPTURE);
    near(f.r.fall_time, sqrt(2 / 0.8), 1e-9);
    assert_true(isinf(f.r.advance[0]) && f.r.advance[0] > 0);
    unload(&f);
}

/* ---- a reduced L not quadratic in r' ----------------------------------------- */

/* The relativistic Kepler problem (seed-desloge-D.md T19; Desloge ch. 89
 * Prob. 1, Sommerfeld): L = -m c^2 sqrt(1 - v^2/c^2) + k/r.  The perihelion
 * advances by 2 pi (1/G - 1) per radial period, G = sqrt(1 - (k/(c l))^2),
 * l = m gamma r^2 theta'; the energy is gamma m c^2 - k/r.  E = M r'^2/2 +
 * V_eff is false here (M = m gamma^3 depends on r'): with it the advance was
 * 0.7877 where 0.78595 is right, with exit 0. */
static const char rel_kepler[] =
    "coordinates r, theta\nparameters m = 1, c = 1, k = 1/5\n"
    "L = -m*c^2*sqrt(1 - (r'^2 + r^2*theta'^2)/c^2) + k/r\n";

static void rel_kepler_at(double rd, double td) {
    fix f;
    load(&f, rel_kepler);
    assert_int_equal(reduce(&f, THETA), QD_OK);
    assert_true(f.o->general && !f.o->kepler);
    set(&f, "r", 1);
    set(&f, "r'", rd);
    set(&f, "theta'", td);
    assert_int_equal(solve(&f, NULL), QD_OK);
    assert_int_equal(f.r.kind, QD_ORBIT_BOUND);
    double gam = 1 / sqrt(1 - rd * rd - td * td), l = gam * td, G = sqrt(1 - 0.04 / (l * l));
    near(f.r.energy, gam - 0.2, 1e-14);
    near(f.r.advance[0], 2 * PI / G, 1e-10);
    near(f.r.precession[0], 2 * PI * (1 / G - 1), 1e-10);
    /* the radial period against the motion itself: three turning points */
    char text[256];
    snprintf(text, sizeof text, "%sinitial r = 1, r' = %.17g, theta' = %.17g\n", rel_kepler, rd, td);
    sim_fix *s = sf_load(text);
    assert_non_null(s);
    const qd_expr *rdot = qd_jet(s->ctx, qd_lookup(s->ctx, "r"), 1);
    assert_int_equal(qd_sim_add_event(s->s, rdot, 0, NULL, false), QD_OK);
    s->max_events = 4;
    assert_int_equal(sf_run(s, QD_SIM_DOP853, 3 * f.r.period, 0, 1e-13, false), QD_OK);
    size_t k = s->ev_t[0] < 1e-9 ? 1 : 0;
    assert_true(s->nev >= k + 3);
    near(s->ev_t[k + 2] - s->ev_t[k], f.r.period, 1e-9);
    sf_free(s);
    unload(&f);
}

static void test_relativistic_kepler(void **state) {
    (void)state;
    rel_kepler_at(0, 0.4);   /* the audit's case: advance 7.06913576838 */
    rel_kepler_at(0.2, 0.4); /* started between the apsides: E from h(r, r') */
}

/* A charge in a uniform field B (L = T + q B r^2 theta'/2, A = B (-y, x)/2):
 * a circle of radius R = v/w_c, w_c = q B/m, run clockwise (the Lorentz
 * force from the velocity-dependent potential, Goldstein sec. 1.5).  Started at r = d + R, theta
 * = 0 with velocity (0, -w_c R) it is centred at (d, 0): the turning points
 * |d - R| and d + R, the radial period 2 pi/w_c.  Off the centre (d > R)
 * theta swings back and forth, advance 0, and the figure is closed:
 * precession 0 (it was -2 pi, "one revolution" assumed; audit, issue 33).
 * Round the centre (d < R) theta loses 2 pi per period: precession 0 too. */
static void test_cyclotron(void **state) {
    (void)state;
    const double m = 1.3, q = 0.8, B = 2, wc = q * B / m, R = 0.5;
    const double d[] = {1.3, 0.3}, adv[] = {0, -2 * PI};
    for (int k = 0; k < 2; k++) {
        fix f;
        load(&f, "coordinates r, theta\nparameters m = 1.3, q = 0.8, B = 2\n"
                 "T = m/2*(r'^2 + r^2*theta'^2)\nU = -q*B/2*r^2*theta'\n");
        assert_int_equal(reduce(&f, THETA), QD_OK);
        set(&f, "r", d[k] + R);
        set(&f, "r'", 0);
        set(&f, "theta'", -wc * R / (d[k] + R));
        assert_int_equal(solve(&f, NULL), QD_OK);
        assert_int_equal(f.r.kind, QD_ORBIT_BOUND);
        near(f.r.turn[0], fabs(d[k] - R), 1e-10);
        near(f.r.turn[1], d[k] + R, 1e-10);
        near(f.r.period, 2 * PI / wc, 1e-9);
        near(f.r.advance[0], adv[k], 1e-9);
        near(f.r.precession[0], 0, 1e-9);
        unload(&f);
    }
}

static void test_errors(void **state) {
    (void)state;
    fix f;
    load(&f, kepler);
    f.o = qd_orbit_derive(f.ctx, f.m, f.e, 0, NULL);
    assert_null(f.o);
    assert_int_equal(qd_ctx_status(f.ctx), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(f.ctx), "cyclic"));
    qd_ctx_clear_error(f.ctx);
    const char *const r[] = {"r", NULL};
    assert_int_equal(reduce(&f, r), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(f.ctx), "r"));
    qd_ctx_clear_error(f.ctx);
    /* energy below the minimum of V_eff, -m k^2/(2 h^2) */
    assert_int_equal(reduce(&f, THETA), QD_OK);
    set(&f, "r", 1);
    set(&f, "theta'", 1.5);
    double E = -20, h = 1.3 * 1.5, Vmin = -1.3 * 16 / (2 * h * h);
    assert_int_equal(qd_orbit_solve(f.ctx, f.o, f.n, f.syms, f.vals, &E, &f.r), QD_ERR_ARG);
    const char *msg = qd_ctx_message(f.ctx);
    char want[64];
    snprintf(want, sizeof want, "%.12g", Vmin);
    if (!strstr(msg, "-20") || !strstr(msg, want)) {
        fprintf(stderr, "message: %s (want %s)\n", msg, want);
        fail();
    }
    qd_ctx_clear_error(f.ctx);
    /* an energy between: the ellipse of that energy */
    E = Vmin / 2;
    assert_int_equal(solve(&f, &E), QD_OK);
    assert_int_equal(f.r.kind, QD_ORBIT_BOUND);
    near(f.r.e, sqrt(1 - 0.5), 1e-13);
    unload(&f);
    /* two coordinates left */
    load(&f, "coordinates r, theta, phi\nparameters m = 1\n"
             "particle m at r*(sin(theta)*cos(phi), sin(theta)*sin(phi), cos(theta))\nV = -1/r\n");
    assert_int_equal(reduce(&f, PHI), QD_ERR_ARG);
    const char *m2 = qd_ctx_message(f.ctx);
    assert_non_null(strstr(m2, "r, theta"));
    unload(&f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_kepler_ellipse),   cmocka_unit_test(test_kepler_retrograde),
        cmocka_unit_test(test_kepler_hyperbola),
        cmocka_unit_test(test_kepler_parabola),  cmocka_unit_test(test_kepler_circle),
        cmocka_unit_test(test_kepler_repulsive), cmocka_unit_test(test_apsidal_speeds),
        cmocka_unit_test(test_power_law_apsidal), cmocka_unit_test(test_hooke_closes),
        cmocka_unit_test(test_inverse_cube),     cmocka_unit_test(test_r4_capture),
        cmocka_unit_test(test_r4_separatrix),
        cmocka_unit_test(test_radial_infall),    cmocka_unit_test(test_yukawa_and_string),
        cmocka_unit_test(test_spherical_pendulum), cmocka_unit_test(test_planar_pendulum),
        cmocka_unit_test(test_heavy_top),        cmocka_unit_test(test_relativistic_kepler),
        cmocka_unit_test(test_cancelled_centrifugal),
        cmocka_unit_test(test_cyclotron),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
