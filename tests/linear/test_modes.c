/*
 * tests/linear/test_modes.c - equilibria, linearization and normal modes
 * (qdot/equilibria.h, qdot/modes.h) against textbook results.
 *
 *   double pendulum, equal masses and lengths: w^2 = (g/l)(2 -+ sqrt 2),
 *     theta2/theta1 = +-sqrt 2 (Goldstein ch. 6 / seed 002; reference
 *     seed-goldstein-britannica.md: det(C - w^2 A) = 0 for the double
 *     pendulum), and the exact w^2 evaluates to the same;
 *   three equal masses in a ring of three springs, free in the plane:
 *     w^2 = 3k/m once, 3k/(2m) twice, 0 three times (Desloge ch. 66 example,
 *     seed-desloge-D.md T33);
 *   rod on an elastic string: g/w^2 = a/6 twice and 7a/3 (Desloge ch. 65
 *     P11, seed-desloge-B.md T59), equilibrium string length 7a/6;
 *   restricted three-body problem: five equilibria, collinear ones on the
 *     axis, L4 at (1/2 - mu, sqrt 3/2) stable for mu = 0.01 and unstable
 *     for mu = 0.1 (27 mu (1 - mu) < 1; Desloge ch. 62), a maximum of the
 *     effective potential either way;
 *   a damped oscillator: s = -c/2m +- i sqrt(k/m - c^2/4m^2);
 *   three pendulums whose angles springs couple, V = -g sum cos th_i +
 *     k/2 sum (th_{i+1} - th_i)^2: no angle is periodic (a turn by 2 pi
 *     stretches the springs), so every equilibrium listed solves
 *     g sin th_i = k (th_{i+1} - 2 th_i + th_{i-1}) (ends: one spring) to
 *     round-off (issue 33: roots folded into (-pi, pi] were listed with
 *     residuals 2 pi k).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include "qdot/qdot.h"
#include "qdot/equilibria.h"
#include "qdot/modes.h"
#include "../util/system.h"

static const double PI = 3.14159265358979323846;

#define DOUBLE_PENDULUM                                                                        \
    "coordinates theta1, theta2\n"                                                             \
    "parameters m = 1, l = 1, g = 9.81\n"                                                      \
    "x1 = l*sin(theta1)\ny1 = -l*cos(theta1)\n"                                                \
    "x2 = x1 + l*sin(theta2)\ny2 = y1 - l*cos(theta2)\n"                                       \
    "T = m/2*(x1'^2 + y1'^2) + m/2*(x2'^2 + y2'^2)\nV = m*g*y1 + m*g*y2\n"

#define RING                                                                                   \
    "coordinates x1, y1, x2, y2, x3, y3\nparameters m = 2, k = 5, a = 1\n"                     \
    "d12 = sqrt((x1 - x2)^2 + (y1 - y2)^2)\nd23 = sqrt((x2 - x3)^2 + (y2 - y3)^2)\n"           \
    "d31 = sqrt((x3 - x1)^2 + (y3 - y1)^2)\n"                                                  \
    "particle m at (x1, y1)\nparticle m at (x2, y2)\nparticle m at (x3, y3)\n"                 \
    "V = k/2*((d12 - a)^2 + (d23 - a)^2 + (d31 - a)^2)\n"

#define ROD                                                                                    \
    "coordinates r, phi, theta\nparameters M = 2, a = 0.5, g = 9.81\n"                         \
    "P = r*(sin(phi), -cos(phi))\nG = P + a*(sin(theta), -cos(theta))\n"                       \
    "particle M at G\nT = M*a^2/6*theta'^2\nV = M*g*G.y + 3*M*g/a*(r - a)^2\n"

#define THREE_BODY                                                                             \
    "coordinates x, y\nparameters mu = 0.01\n"                                                 \
    "T = 1/2*((x' - y)^2 + (y' + x)^2)\n"                                                      \
    "V = -(1 - mu)/sqrt((x + mu)^2 + y^2) - mu/sqrt((x - 1 + mu)^2 + y^2)\n"

#define SPRUNG_CHAIN                                                                           \
    "coordinates th1, th2, th3\nparameters g = 9.81, k = 2\n"                                  \
    "particle 1 at (sin(th1), -cos(th1))\nparticle 1 at (sin(th2), -cos(th2))\n"              \
    "particle 1 at (sin(th3), -cos(th3))\n"                                                    \
    "V = -g*(cos(th1) + cos(th2) + cos(th3)) + k/2*((th2 - th1)^2 + (th3 - th2)^2)\n"

/* The model's coordinates at q, parameters at their values. */
typedef struct point {
    size_t n;
    const qd_expr *syms[32];
    double vals[32];
} point;

static void at(const qt_system *s, const double *q, point *p) {
    size_t nq = qd_model_ncoords(s->model), np = qd_model_nparams(s->model);
    p->n = nq + np;
    for (size_t i = 0; i < nq; i++) {
        p->syms[i] = qd_model_coord(s->model, i);
        p->vals[i] = q ? q[i] : 0;
    }
    for (size_t i = 0; i < np; i++) {
        p->syms[nq + i] = qd_model_param(s->model, i);
        assert_int_equal(qd_eval(s->ctx, qd_model_param_value(s->model, i), 0, NULL, NULL,
                                 &p->vals[nq + i]), QD_OK);
    }
}

static void modes_at(const qt_system *s, const double *q, qd_linear *lin, qd_modes_result *r) {
    point p;
    at(s, q, &p);
    assert_int_equal(qd_linear_about(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, lin), QD_OK);
    assert_int_equal(qd_modes_solve(s->ctx, lin, r), QD_OK);
}

static void test_double_pendulum(void **state) {
    qt_system *s = qt_system_derive(state, DOUBLE_PENDULUM, false);
    qd_linear lin;
    qd_modes_result r;
    modes_at(s, NULL, &lin, &r);
    assert_true(r.conservative);
    assert_int_equal(r.stable, 1);
    double g = 9.81;
    assert_true(fabs(r.omega2[0] - g * (2 - sqrt(2))) < 1e-10);
    assert_true(fabs(r.omega2[1] - g * (2 + sqrt(2))) < 1e-10);
    assert_true(fabs(r.shapes[2] / r.shapes[0] - sqrt(2)) < 1e-10); /* mode 1: theta2/theta1 */
    assert_true(fabs(r.shapes[3] / r.shapes[1] + sqrt(2)) < 1e-10); /* mode 2 */
    /* a^T M a = 1 */
    for (size_t j = 0; j < 2; j++) {
        double q = 0;
        for (size_t a = 0; a < 2; a++)
            for (size_t b = 0; b < 2; b++)
                q += r.shapes[a * 2 + j] * lin.M[a * 2 + b] * r.shapes[b * 2 + j];
        assert_true(fabs(q - 1) < 1e-12);
    }
    /* the exact w^2 evaluate to the same numbers */
    const qd_expr *q0[2] = {qd_int(s->ctx, 0), qd_int(s->ctx, 0)}, *K[4], *M[4], *w2[2];
    assert_int_equal(qd_linear_symbolic(s->ctx, s->eom, q0, K, M), QD_OK);
    assert_int_equal(qd_modes_symbolic_omega2(s->ctx, 2, K, M, w2), QD_OK);
    point p;
    at(s, NULL, &p);
    for (size_t j = 0; j < 2; j++) {
        double v;
        assert_int_equal(qd_eval(s->ctx, w2[j], p.n, p.syms, p.vals, &v), QD_OK);
        assert_true(fabs(v - r.omega2[j]) < 1e-10);
    }
    qd_linear_free(&lin);
    qd_modes_result_free(&r);
    /* the four equilibria, exactly: (0,0) minimum, (pi,pi) maximum, two saddles */
    qd_equilibria eq;
    assert_int_equal(qd_equilibria_find(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, NULL, &eq),
                     QD_OK);
    assert_true(eq.exact);
    assert_int_equal(eq.count, 4);
    assert_int_equal(eq.pts[0].kind, QD_EQ_MINIMUM);
    assert_int_equal(eq.pts[1].kind, QD_EQ_SADDLE);
    assert_int_equal(eq.pts[2].kind, QD_EQ_SADDLE);
    assert_int_equal(eq.pts[3].kind, QD_EQ_MAXIMUM);
    assert_true(fabs(eq.pts[3].q[0] - PI) < 1e-15 && fabs(eq.pts[3].q[1] - PI) < 1e-15);
    qd_equilibria_free(&eq);
}

static void test_ring(void **state) {
    qt_system *s = qt_system_derive(state, RING, false);
    double q[6] = {0, 0, 1, 0, 0.5, sqrt(3) / 2}, k = 5, m = 2;
    qd_linear lin;
    qd_modes_result r;
    modes_at(s, q, &lin, &r);
    double want[6] = {0, 0, 0, 1.5 * k / m, 1.5 * k / m, 3 * k / m};
    for (size_t j = 0; j < 6; j++)
        assert_true(fabs(r.omega2[j] - want[j]) < 1e-10);
    assert_int_equal(r.stable, -1); /* zero modes: borderline */
    qd_linear_free(&lin);
    qd_modes_result_free(&r);
}

static void test_rod(void **state) {
    qt_system *s = qt_system_derive(state, ROD, false);
    point p;
    at(s, NULL, &p);
    double a = 0.5, g = 9.81;
    qd_equilibria eq;
    assert_int_equal(qd_equilibria_find(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, NULL, &eq),
                     QD_OK);
    size_t k = 0;
    while (k < eq.count && eq.pts[k].kind != QD_EQ_MINIMUM)
        k++;
    assert_true(k < eq.count);
    assert_true(fabs(eq.pts[k].q[0] - 7 * a / 6) < 1e-12); /* string length 7a/6 */
    qd_linear lin;
    qd_modes_result r;
    modes_at(s, eq.pts[k].q, &lin, &r);
    /* equivalent lengths g/w^2, ascending w: 7a/3, a/6, a/6 */
    assert_true(fabs(g / r.omega2[0] - 7 * a / 3) < 1e-10);
    assert_true(fabs(g / r.omega2[1] - a / 6) < 1e-10);
    assert_true(fabs(g / r.omega2[2] - a / 6) < 1e-10);
    qd_equilibria_free(&eq);
    qd_linear_free(&lin);
    qd_modes_result_free(&r);
}

static void three_body(void **state, double mu, int stable) {
    qt_system *s = qt_system_derive(state, THREE_BODY, false);
    assert_int_equal(qd_model_set_param(s->ctx, s->model, "mu", qd_float(s->ctx, mu)), QD_OK);
    point p;
    at(s, NULL, &p);
    qd_equilibria eq;
    double lo[2] = {-2, -2}, hi[2] = {2, 2};
    qd_equilibria_opts o = {.lo = lo, .hi = hi, .numeric_only = true};
    assert_int_equal(qd_equilibria_find(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, &o, &eq),
                     QD_OK);
    assert_int_equal(eq.count, 5);
    size_t naxis = 0, l4 = SIZE_MAX;
    for (size_t i = 0; i < eq.count; i++) {
        assert_true(eq.pts[i].residual < 1e-10);
        if (fabs(eq.pts[i].q[1]) < 1e-12) {
            naxis++;
            assert_int_equal(eq.pts[i].kind, QD_EQ_SADDLE);
        } else if (eq.pts[i].q[1] > 0) {
            l4 = i;
        }
    }
    assert_int_equal(naxis, 3);
    /* one collinear point in each interval between and beyond the primaries */
    assert_true(eq.pts[0].q[0] < -mu);
    assert_true(eq.pts[3].q[0] > -mu && eq.pts[3].q[0] < 1 - mu);
    assert_true(eq.pts[4].q[0] > 1 - mu);
    assert_true(l4 != SIZE_MAX);
    assert_true(fabs(eq.pts[l4].q[0] - (0.5 - mu)) < 1e-10);
    assert_true(fabs(eq.pts[l4].q[1] - sqrt(3) / 2) < 1e-10);
    assert_int_equal(eq.pts[l4].kind, QD_EQ_MAXIMUM);
    qd_linear lin;
    qd_modes_result r;
    modes_at(s, eq.pts[l4].q, &lin, &r);
    assert_false(r.conservative);
    assert_true(fabs(lin.G[1] + 2) < 1e-12 && fabs(lin.G[2] - 2) < 1e-12); /* Coriolis */
    assert_int_equal(r.stable, stable);
    qd_linear_free(&lin);
    qd_modes_result_free(&r);
    /* the collinear points are unstable */
    modes_at(s, eq.pts[3].q, &lin, &r);
    assert_int_equal(r.stable, 0);
    qd_linear_free(&lin);
    qd_modes_result_free(&r);
    qd_equilibria_free(&eq);
}

static void test_three_body_stable(void **state) { three_body(state, 0.01, 1); }
static void test_three_body_unstable(void **state) { three_body(state, 0.1, 0); }

static void test_damped(void **state) {
    qt_system *s = qt_system_derive(state, "coordinates x\nparameters m = 2, k = 8, c = 1\n"
                                           "T = m/2*x'^2\nV = k/2*x^2\n"
                                           "dissipation = c/2*x'^2\n", false);
    qd_linear lin;
    qd_modes_result r;
    modes_at(s, NULL, &lin, &r);
    assert_false(r.conservative);
    assert_true(fabs(lin.C[0] - 1) < 1e-14);
    double re = -1.0 / 4, im = sqrt(4 - 1.0 / 16);
    assert_true(fabs(r.eig_re[0] - re) < 1e-12 && fabs(fabs(r.eig_im[0]) - im) < 1e-12);
    assert_int_equal(r.stable, 1);
    qd_linear_free(&lin);
    qd_modes_result_free(&r);
}

/* A follower (circulatory) force Q = -c (y, -x) with no damping: K is not
 * symmetric and s^2 = -k -+ i c, so one root of each pair has Re s > 0
 * (flutter; Ziegler's paradox, Bolotin, Nonconservative Problems ch. 1).
 * Read as a symmetric problem it would look stable. */
static void test_circulatory(void **state) {
    qt_system *s = qt_system_derive(state, "coordinates x, y\nparameters m = 1, k = 4, c = 1\n"
                                           "T = m/2*(x'^2 + y'^2)\nV = k/2*(x^2 + y^2)\n"
                                           "Q[x] = -c*y\nQ[y] = c*x\n", false);
    qd_linear lin;
    qd_modes_result r;
    modes_at(s, NULL, &lin, &r);
    assert_false(r.conservative);
    assert_int_equal(r.stable, 0);
    double maxre = 0;
    for (size_t i = 0; i < r.neig; i++)
        maxre = fmax(maxre, r.eig_re[i]);
    /* sqrt(-4 - i) = 0.2462 - 2.0308i up to sign: Re s = +-0.24615... */
    double want = sqrt((sqrt(17.0) - 4) / 2);
    assert_true(fabs(maxre - want) < 1e-12);
    qd_linear_free(&lin);
    qd_modes_result_free(&r);
}

/* Newton from a guess, and a nonconvergent one: the error is named. */
static void test_newton(void **state) {
    qt_system *s = qt_system_derive(state, ROD, false);
    point p;
    at(s, NULL, &p);
    double near[3] = {0.6, 0.1, -0.1};
    qd_equilibria_opts o = {.near = near};
    qd_equilibria eq;
    assert_int_equal(qd_equilibria_find(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, &o, &eq),
                     QD_OK);
    assert_int_equal(eq.count, 1);
    assert_true(fabs(eq.pts[0].q[0] - 7 * 0.5 / 6) < 1e-12);
    assert_true(fabs(eq.pts[0].q[1]) < 1e-12 && fabs(eq.pts[0].q[2]) < 1e-12);
    qd_equilibria_free(&eq);
}

/* Which coordinates are angles: periodic ones only. */
static void angles_of(void **state, const char *text, size_t n, const bool *want) {
    qt_system *s = qt_system_derive(state, text, false);
    bool angle[4];
    double lo[4], hi[4];
    assert_int_equal(qd_equilibria_default_box(s->ctx, s->eom, s->model, angle, lo, hi), QD_OK);
    for (size_t j = 0; j < n; j++) {
        assert_int_equal(angle[j], want[j]);
        assert_true(want[j] ? hi[j] == PI : hi[j] == 10);
    }
}

static void test_angles(void **state) {
    const bool both[2] = {true, true}, none[3] = {false, false, false};
    angles_of(state, DOUBLE_PENDULUM, 2, both);
    qt_system_teardown(state);
    angles_of(state, SPRUNG_CHAIN, 3, none);
    qt_system_teardown(state);
    /* cos(th/2) has period 4 pi; sin(2 th) and cos(th - phi) are 2 pi-periodic in each */
    const bool half[2] = {false, true};
    angles_of(state, "coordinates th, phi\nT = th'^2/2 + phi'^2/2\n"
                     "V = -cos(th/2) - sin(2*phi) - cos(th - phi)/10\n", 2, half);
    qt_system_teardown(state);
    /* a bare appearance beside a periodic one: th*sin(th) */
    const bool bare[1] = {false};
    angles_of(state, "coordinates th\nT = th'^2/2\nV = th*sin(th)\n", 1, bare);
}

static void test_sprung_chain(void **state) {
    qt_system *s = qt_system_derive(state, SPRUNG_CHAIN, false);
    point p;
    at(s, NULL, &p);
    qd_equilibria eq;
    assert_int_equal(qd_equilibria_find(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, NULL, &eq),
                     QD_OK);
    assert_true(eq.count >= 3);
    const double g = 9.81, k = 2;
    bool wound = false, rest = false;
    for (size_t i = 0; i < eq.count; i++) {
        const double *th = eq.pts[i].q;
        /* dV/dth_i by hand */
        double F[3] = {g * sin(th[0]) - k * (th[1] - th[0]),
                       g * sin(th[1]) + k * (th[1] - th[0]) - k * (th[2] - th[1]),
                       g * sin(th[2]) + k * (th[2] - th[1])};
        for (size_t j = 0; j < 3; j++)
            assert_true(fabs(F[j]) < 1e-9);
        wound = wound || fabs(th[0]) > PI || fabs(th[2]) > PI;
        rest = rest || (fabs(th[0]) + fabs(th[1]) + fabs(th[2]) < 1e-12 &&
                        eq.pts[i].kind == QD_EQ_MINIMUM);
    }
    assert_true(rest);
    assert_true(wound); /* an end pendulum turned past pi, held by the spring */
    qd_equilibria_free(&eq);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(test_angles, qt_system_teardown),
        cmocka_unit_test_teardown(test_sprung_chain, qt_system_teardown),
        cmocka_unit_test_teardown(test_double_pendulum, qt_system_teardown),
        cmocka_unit_test_teardown(test_ring, qt_system_teardown),
        cmocka_unit_test_teardown(test_rod, qt_system_teardown),
        cmocka_unit_test_teardown(test_three_body_stable, qt_system_teardown),
        cmocka_unit_test_teardown(test_three_body_unstable, qt_system_teardown),
        cmocka_unit_test_teardown(test_damped, qt_system_teardown),
        cmocka_unit_test_teardown(test_newton, qt_system_teardown),
        cmocka_unit_test_teardown(test_circulatory, qt_system_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
