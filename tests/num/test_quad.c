/*
 * tests/num/test_quad.c - the double-exponential quadrature of src/num/quad.c
 * on integrals known in closed form, above all those with the
 * inverse-square-root end points of orbits:
 *
 *   int_0^1 dx/sqrt(x) = 2, int_-1^1 dx/sqrt(1 - x^2) = pi,
 *   int_0^1 log x dx = -1, int_0^pi sin x dx = 2,
 *   the radial half-period of a Kepler ellipse,
 *     int_r1^r2 r dr / sqrt((r - r1)(r2 - r)) = pi (r1 + r2)/2
 *   (Goldstein sec. 3.7; the substitution r = (r1 + r2)/2 - (r2 - r1)/2 cos u
 *   gives it at once), and on [a, inf):
 *   int_0^inf e^-x dx = 1, int_1^inf dx/x^2 = 1,
 *   int_0^inf dx/(1 + x^2) = pi/2, int_0^inf x^-1/2 e^-x dx = sqrt(pi).
 *
 * The end-point distance xc is what keeps the singular ones accurate: the
 * tests form 1 - x^2 as (1 - x)(1 + x) from it, the way an orbit forms
 * E - V_eff near a turning point.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "num/num.h"

#define PI 3.14159265358979323846 /* PI is not C11 */

static double inv_sqrt(void *d, double x, double xc) {
    (void)d;
    return 1 / sqrt(xc >= 0 ? xc : x); /* x - 0 exact near 0; the end 1 is regular */
}

static double arcsine(void *d, double x, double xc) {
    (void)d, (void)x;
    /* 1 - x^2 = (1 - x)(1 + x) with the factor at the nearer end exact */
    double one_minus = xc < 0 ? -xc : 2 - xc, one_plus = xc >= 0 ? xc : 2 + xc;
    return 1 / sqrt(one_minus * one_plus);
}

static double logx(void *d, double x, double xc) {
    (void)d;
    return log(xc >= 0 ? xc : x);
}

static double sinx(void *d, double x, double xc) {
    (void)d, (void)xc;
    return sin(x);
}

typedef struct { double r1, r2; } ellipse;

static double radial(void *d, double r, double xc) {
    const ellipse *e = d;
    /* the distance to the far end as (r2 - r1) - |xc|: r2 - r would lose
     * the digits of a thin ellipse */
    double w = e->r2 - e->r1, a = xc >= 0 ? xc : w + xc, b = xc < 0 ? -xc : w - xc;
    return r / sqrt(a * b);
}

static double expm(void *d, double x, double xc) { (void)d, (void)xc; return exp(-x); }
static double inv_sq(void *d, double x, double xc) { (void)d, (void)xc; return 1 / (x * x); }
static double lorentz(void *d, double x, double xc) { (void)d, (void)xc; return 1 / (1 + x * x); }
static double gamma_half(void *d, double x, double xc) {
    (void)d;
    return exp(-x) / sqrt(xc);
}

/* 1/(1 + x), whose integral diverges, cut to 0 beyond x = 1e300 where the
 * far points' weights overflow: every level is taken */
static double cutoff(void *d, double x, double xc) {
    (void)d, (void)xc;
    return x > 1e300 ? 0 : 1 / (1 + x);
}

static void check(bool ok, const qd__num_quad *r, double want, double tol) {
    if (!ok)
        fail_msg("not converged: %.17g (want %.17g), error %g, %zu evaluations", r->value, want,
                 r->error, r->evals);
    assert_true(r->converged);
    if (fabs(r->value - want) > tol * fmax(1, fabs(want)))
        fail_msg("got %.17g, want %.17g (error estimate %g, %zu evaluations)", r->value, want,
                 r->error, r->evals);
    assert_true(r->error <= 1e-12 * fmax(1, fabs(want)));
}

static void finite_interval(void **state) {
    (void)state;
    qd__num_quad r;
    check(qd__num_quad_finite(inv_sqrt, NULL, 0, 1, 0, &r), &r, 2, 1e-14);
    check(qd__num_quad_finite(arcsine, NULL, -1, 1, 0, &r), &r, PI, 1e-14);
    check(qd__num_quad_finite(logx, NULL, 0, 1, 0, &r), &r, -1, 1e-14);
    check(qd__num_quad_finite(sinx, NULL, 0, PI, 0, &r), &r, 2, 1e-14);
    /* smooth integrands are cheap */
    assert_true(r.evals < 400);
}

/* A Kepler ellipse with r1 = 1, r2 = 1e3 (e close to 1): the turning
 * points are three decades apart, the integrand singular at both. */
static void kepler_half_period(void **state) {
    (void)state;
    qd__num_quad r;
    ellipse e[] = {{1, 3}, {1, 1e3}, {0.5, 0.5000001}};
    for (size_t i = 0; i < sizeof e / sizeof e[0]; i++)
        check(qd__num_quad_finite(radial, &e[i], e[i].r1, e[i].r2, 0, &r), &r,
              PI * (e[i].r1 + e[i].r2) / 2, 1e-13);
}

static void upper_interval(void **state) {
    (void)state;
    qd__num_quad r;
    check(qd__num_quad_upper(expm, NULL, 0, 0, &r), &r, 1, 1e-14);
    check(qd__num_quad_upper(inv_sq, NULL, 1, 0, &r), &r, 1, 1e-14);
    check(qd__num_quad_upper(lorentz, NULL, 0, 0, &r), &r, PI / 2, 1e-14);
    check(qd__num_quad_upper(gamma_half, NULL, 0, 0, &r), &r, sqrt(PI), 1e-13);
    /* a weight that overflows where the integrand is 0 adds 0, not
     * inf * 0 = NaN (found by the orbit work on a parabola's turn): the
     * divergent integral ends unconverged with a finite last estimate */
    assert_false(qd__num_quad_upper(cutoff, NULL, 0, 0, &r));
    assert_true(isfinite(r.value) && r.value > 100);
}

static double nan_inside(void *d, double x, double xc) {
    (void)d, (void)xc;
    return x > 0.3 && x < 0.4 ? NAN : 1;
}

/* A NaN away from the ends is the integrand's fault, not a singularity. */
static void failures(void **state) {
    (void)state;
    qd__num_quad r;
    assert_false(qd__num_quad_finite(sinx, NULL, 1, 1, 0, &r));
    assert_true(isnan(r.value));
    assert_false(qd__num_quad_finite(sinx, NULL, 0, INFINITY, 0, &r));
    assert_false(qd__num_quad_finite(nan_inside, NULL, 0, 1, 0, &r));
    assert_true(isnan(r.value));
    assert_false(qd__num_quad_upper(nan_inside, NULL, 0, 0, &r));
    assert_false(qd__num_quad_upper(expm, NULL, NAN, 0, &r));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(finite_interval),
        cmocka_unit_test(kepler_half_period),
        cmocka_unit_test(upper_interval),
        cmocka_unit_test(failures),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
