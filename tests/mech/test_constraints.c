/*
 * tests/mech/test_constraints.c - Lagrange's equations with multipliers,
 * M q'' = f + A^T lambda and A q'' = b, against the references:
 *   Atwood machine (Goldstein, Classical Mechanics, sec. 1.6; seed
 *     seed-goldstein-britannica.md sec. 1.6): the rope's tension is
 *     2 m1 m2 g/(m1 + m2), the acceleration (m1 - m2) g/(m1 + m2);
 *   bead on a uniformly rotating wire (seed G03): the wire's force is
 *     2 m omega r' (Goldstein's printed m r omega^2 e^(omega t) is wrong);
 *   particle on a smooth sphere (seed-desloge-A T27, seed G25): the normal
 *     force is m g (3 cos th - 2), so it leaves at cos th = 2/3;
 *   inconsistent constraints, reported by name (redundant ones are left
 *     out by rank: test_redundant.c);
 *   --eliminate (Desloge ch. 50): the Atwood machine reduces to
 *     (m1 + m2) x'' = (m1 - m2) g.
 * Values at random states (fixed seed).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/mech.h"
#include "qdot/model.h"
#include "util/randexpr.h"
#include "util/system.h"

#define SEED 20240617u
#define NSTATES 20
#define MAXSYM 32

typedef qt_system fixture;

static int teardown(void **state) { return qt_system_teardown(state); }

static fixture *setup(void **state, const char *text) { return qt_system_parse(state, text); }

static fixture *derive_opts(void **state, const char *text, bool eliminate) {
    return qt_system_derive(state, text, eliminate);
}

static fixture *derive(void **state, const char *text) { return derive_opts(state, text, false); }

static const qd_expr *S(fixture *fx, const char *name) { return qt_symbol(fx, name); }

static bool close_to(double a, double b) { return fabs(a - b) <= 1e-9 * (1 + fabs(a) + fabs(b)); }

typedef struct pt {
    size_t n;
    const qd_expr *syms[MAXSYM];
    double vals[MAXSYM];
} pt;

static void set(fixture *fx, pt *s, const char *name, double v) {
    s->syms[s->n] = S(fx, name);
    s->vals[s->n++] = v;
}

static double value(fixture *fx, const pt *s, const qd_expr *e) {
    double v;
    if (qd_eval(fx->ctx, e, s->n, s->syms, s->vals, &v) != QD_OK)
        fail_msg("eval: %s", qd_ctx_message(fx->ctx));
    return v;
}

/* Every entry of x and y (n of them) agree. */
static void assert_close(const double *x, const double *y, size_t n, const char *what, int k) {
    for (size_t i = 0; i < n; i++)
        if (!close_to(x[i], y[i]))
            fail_msg("%s[%zu] = %.17g, expected %.17g (state %d, seed %u)", what, i, x[i], y[i],
                     k, SEED);
}

/* ---- Atwood machine --------------------------------------------------------- */

/* x1, x2 measured down from the pulley; the rope keeps x1 + x2 = l. */
static const char *atwood = "coordinates x1, x2\n"
                            "parameters m1 = 2, m2 = 1, g = 9.81, l = 5\n"
                            "T = m1/2*x1'^2 + m2/2*x2'^2\n"
                            "V = -m1*g*x1 - m2*g*x2\n"
                            "constraint rope: x1 + x2 = l\n";

static void atwood_state(fixture *fx, qt_rng *r, pt *s, double *m1, double *m2, double *g) {
    double x1 = qt_uniform(r, 0, 5), v = qt_uniform(r, -2, 2);
    s->n = 0;
    *m1 = qt_uniform(r, 0.5, 3);
    *m2 = qt_uniform(r, 0.5, 3);
    *g = qt_uniform(r, 1, 10);
    set(fx, s, "m1", *m1);
    set(fx, s, "m2", *m2);
    set(fx, s, "g", *g);
    set(fx, s, "l", 5);
    set(fx, s, "x1", x1);
    set(fx, s, "x2", 5 - x1);
    set(fx, s, "x1'", v);
    set(fx, s, "x2'", -v);
}

/* Multiplier convention: R_j = lambda a_j is the generalized constraint
 * force.  The rope pulls each mass up (against x), so lambda = -tension. */
static void test_atwood(void **state) {
    fixture *fx = derive(state, atwood);
    qt_rng r = {SEED};
    pt s;
    assert_int_equal(fx->eom->ncon, 1);
    assert_string_equal(fx->eom->con[0].name, "rope");
    assert_int_equal(fx->eom->con[0].kind, QD_CON_HOLONOMIC);
    assert_ptr_equal(fx->eom->con[0].lambda, qd_lookup(fx->ctx, "lambda_rope"));
    for (int k = 0; k < NSTATES; k++) {
        double m1, m2, g, qdd[2], lambda, R[2];
        atwood_state(fx, &r, &s, &m1, &m2, &g);
        assert_int_equal(
            qd_eom_eval(fx->ctx, fx->eom, s.n, s.syms, s.vals, NULL, NULL, qdd, &lambda, R),
            QD_OK);
        double tension = 2 * m1 * m2 * g / (m1 + m2), a = (m1 - m2) * g / (m1 + m2);
        assert_close(&lambda, (double[]){-tension}, 1, "lambda_rope", k);
        assert_close(R, (double[]){-tension, -tension}, 2, "R", k);
        assert_close(qdd, (double[]){a, -a}, 2, "q''", k);
    }
}

/* The symbolic solution of the saddle-point system agrees. */
static void test_atwood_solve(void **state) {
    fixture *fx = derive(state, atwood);
    qt_rng r = {SEED + 1};
    pt s;
    assert_int_equal(qd_eom_solve(fx->ctx, fx->eom, 400), QD_OK);
    assert_non_null(fx->eom->mult);
    for (int k = 0; k < NSTATES; k++) {
        double m1, m2, g;
        atwood_state(fx, &r, &s, &m1, &m2, &g);
        double got[3] = {value(fx, &s, fx->eom->acc[0]), value(fx, &s, fx->eom->acc[1]),
                         value(fx, &s, fx->eom->mult[0])};
        double a = (m1 - m2) * g / (m1 + m2);
        assert_close(got, (double[]){a, -a, -2 * m1 * m2 * g / (m1 + m2)}, 3, "solved", k);
    }
}

/* Goldstein sec. 1.6: with x2 = l - x1, (m1 + m2) x1'' = (m1 - m2) g. */
static void test_atwood_eliminate(void **state) {
    fixture *fx = derive_opts(state, atwood, true);
    qd_ctx *c = fx->ctx;
    const qd_eom *e = fx->eom;
    assert_int_equal(e->n, 1);
    assert_int_equal(e->ncon, 0);
    assert_int_equal(e->nelim, 1);
    assert_ptr_equal(e->q[0], S(fx, "x1"));
    assert_ptr_equal(e->elim[0].q, S(fx, "x2"));
    assert_string_equal(e->elim[0].con, "rope");
    assert_ptr_equal(e->elim[0].value, qd_sub(c, S(fx, "l"), S(fx, "x1")));
    assert_ptr_equal(e->M[0], qd_add(c, S(fx, "m1"), S(fx, "m2")));
    const qd_expr *f = qd_mul(c, S(fx, "g"), qd_sub(c, S(fx, "m1"), S(fx, "m2")));
    assert_ptr_equal(qd_simplify(c, qd_sub(c, e->f[0], f)), qd_int(c, 0));
}

/* ---- bead on a rotating wire ---------------------------------------------------- */

/* The wire turns about z at omega: y cos(omega t) - x sin(omega t) = 0. */
static const char *bead = "coordinates x, y\n"
                          "parameters m = 1, omega = 2\n"
                          "T = m/2*(x'^2 + y'^2)\n"
                          "constraint wire: y*cos(omega*t) - x*sin(omega*t) = 0\n";

/* On the wire: x = r cos(omega t), y = r sin(omega t) with r, r' random.
 * The force of the wire is perpendicular to it, of size 2 m omega r' in
 * the sense of the rotation, and the radial motion is r'' = omega^2 r
 * (no radial force): seed G03. */
static void test_rotating_wire(void **state) {
    fixture *fx = derive(state, bead);
    qt_rng r = {SEED + 2};
    for (int k = 0; k < NSTATES; k++) {
        double m = qt_uniform(&r, 0.5, 2), w = qt_uniform(&r, 0.5, 3), t = qt_uniform(&r, -2, 2);
        double rho = qt_uniform(&r, 0.1, 2), rd = qt_uniform(&r, -2, 2), th = w * t;
        double c = cos(th), sn = sin(th), qdd[2], lambda, R[2], f[2];
        pt s = {0};
        set(fx, &s, "m", m);
        set(fx, &s, "omega", w);
        set(fx, &s, "t", t);
        set(fx, &s, "x", rho * c);
        set(fx, &s, "y", rho * sn);
        set(fx, &s, "x'", rd * c - rho * w * sn);
        set(fx, &s, "y'", rd * sn + rho * w * c);
        assert_int_equal(
            qd_eom_eval(fx->ctx, fx->eom, s.n, s.syms, s.vals, NULL, f, qdd, &lambda, R),
            QD_OK);
        double normal = -R[0] * sn + R[1] * c, radial = R[0] * c + R[1] * sn;
        assert_close((double[]){normal, radial, hypot(R[0], R[1])},
                     (double[]){2 * m * w * rd, 0, fabs(2 * m * w * rd)}, 3, "wire force", k);
        /* radial acceleration r'' - r omega^2 = 0 in the rotating frame */
        assert_close((double[]){qdd[0] * c + qdd[1] * sn}, (double[]){0}, 1, "radial", k);
        /* m q'' = f + R */
        assert_close((double[]){m * qdd[0], m * qdd[1]}, (double[]){f[0] + R[0], f[1] + R[1]},
                     2, "M q''", k);
    }
}

/* b = -(sum_j a_j' q'_j + a0') for a holonomic constraint: phi'' - A q''. */
static void test_closing_row(void **state) {
    fixture *fx = derive(state, bead);
    qd_ctx *c = fx->ctx;
    const qd_eom *e = fx->eom;
    const qd_expr *phi = e->con[0].expr, *dd = qd_dt(c, qd_dt(c, phi));
    for (size_t j = 0; j < 2; j++)
        dd = qd_sub(c, dd, qd_mul(c, e->A[j], e->qdd[j]));
    assert_ptr_equal(qd_simplify(c, qd_add(c, dd, e->b[0])), qd_int(c, 0));
    /* a frozen-time gradient: dphi/dt is in a0, not in A */
    assert_ptr_equal(e->A[1], qd_fn(c, QD_COS, qd_mul(c, S(fx, "omega"), S(fx, "t"))));
}

/* ---- particle on a smooth sphere ----------------------------------------------- */

/* th from the upward vertical, in the vertical plane; the constraint r = a
 * keeps it on the sphere.  lambda is the outward normal force. */
static const char *sphere = "coordinates r, theta\n"
                            "parameters m = 1, g = 9.81, a = 2\n"
                            "T = m/2*(r'^2 + r^2*theta'^2)\n"
                            "V = m*g*r*cos(theta)\n"
                            "constraint surface: r = a\n";

/* From rest at the top, theta'^2 = 2 g (1 - cos theta)/a. */
static double normal_force(fixture *fx, double th, double m, double g, double a) {
    double lambda, qdd[2];
    pt s = {0};
    set(fx, &s, "m", m);
    set(fx, &s, "g", g);
    set(fx, &s, "a", a);
    set(fx, &s, "r", a);
    set(fx, &s, "theta", th);
    set(fx, &s, "theta'", sqrt(2 * g * (1 - cos(th)) / a));
    assert_int_equal(qd_eom_eval(fx->ctx, fx->eom, s.n, s.syms, s.vals, NULL, NULL, qdd, &lambda,
                                 NULL),
                     QD_OK);
    return lambda;
}

/* N = m g (3 cos th - 2) (seed-desloge-A T27): it changes sign at
 * cos th = 2/3, where the particle leaves. */
static void test_sphere(void **state) {
    fixture *fx = derive(state, sphere);
    qt_rng r = {SEED + 3};
    for (int k = 0; k < NSTATES; k++) {
        double m = qt_uniform(&r, 0.5, 2), g = qt_uniform(&r, 1, 10), a = qt_uniform(&r, 0.5, 3);
        double th = qt_uniform(&r, 0, 1.5);
        double N = normal_force(fx, th, m, g, a);
        assert_close(&N, (double[]){m * g * (3 * cos(th) - 2)}, 1, "N", k);
    }
    double lo = 0.1, hi = 1.5; /* N > 0 at lo, < 0 at hi */
    assert_true(normal_force(fx, lo, 1, 9.81, 2) > 0 && normal_force(fx, hi, 1, 9.81, 2) < 0);
    for (int i = 0; i < 60; i++) {
        double mid = (lo + hi) / 2;
        *(normal_force(fx, mid, 1, 9.81, 2) > 0 ? &lo : &hi) = mid;
    }
    assert_true(fabs(cos(lo) - 2.0 / 3.0) < 1e-12);
}

/* ---- what cannot be met ------------------------------------------------------------ */

static void expect_error(void **state, const char *text, bool eliminate, qd_status st,
                         const char *const *needles) {
    fixture *fx = setup(state, text);
    qd_eom_opts opts = {.eliminate = eliminate};
    fx->eom = qd_eom_derive_opts(fx->ctx, fx->model, &opts);
    assert_null(fx->eom);
    assert_int_equal(qd_ctx_status(fx->ctx), st);
    for (; *needles; needles++)
        if (!strstr(qd_ctx_message(fx->ctx), *needles))
            fail_msg("message \"%s\" lacks \"%s\"", qd_ctx_message(fx->ctx), *needles);
}

static const char *two_ropes = "coordinates x1, x2\n"
                               "parameters m1 = 2, m2 = 1, g = 9.81, l = 5\n"
                               "T = m1/2*x1'^2 + m2/2*x2'^2\n"
                               "V = -m1*g*x1 - m2*g*x2\n"
                               "constraint rope: x1 + x2 = l\n"
                               "constraint rope2: 2*x1 + 2*x2 = 2*l%s\n";

static void test_inconsistent(void **state) {
    char text[512];
    snprintf(text, sizeof text, two_ropes, " + 1");
    expect_error(state, text, false, QD_ERR_SINGULAR,
                 (const char *[]){"constraints rope and rope2 are inconsistent", NULL});
}

/* A circle and its tangent line: both hold at (0, 1), where their
 * gradients are parallel: fine at random states, singular there. */
static void test_redundant_at_state(void **state) {
    fixture *fx = derive(state, "coordinates x, y\nparameters m = 1\n"
                                "T = m/2*(x'^2 + y'^2)\n"
                                "constraint circle: x^2 + y^2 = 1\n"
                                "constraint line: y = 1\n");
    pt s = {0};
    double qdd[2];
    set(fx, &s, "y", 1);
    set(fx, &s, "m", 1);
    assert_int_equal(qd_eom_eval(fx->ctx, fx->eom, s.n, s.syms, s.vals, NULL, NULL, qdd, NULL,
                                 NULL),
                     QD_ERR_SINGULAR);
    const char *msg = qd_ctx_message(fx->ctx);
    if (!strstr(msg, "circle and line") || !strstr(msg, "at this state"))
        fail_msg("message \"%s\" does not name circle and line", msg);
}

static void test_nonlinear_velocity(void **state) {
    expect_error(state,
                 "coordinates x, y\nparameters m = 1\nT = m/2*(x'^2 + y'^2)\n"
                 "constraint speed: x'^2 + y'^2 = 1\n",
                 false, QD_ERR_NONLINEAR, (const char *[]){"constraint speed", "x'", NULL});
}

/* ---- Pfaffian constraints -------------------------------------------------------------- */

/* y' = z x' (the classic nonholonomic form): differentiated once, its row
 * is A = (-z, 1, 0) and b = z' x'; --eliminate keeps it. */
static void test_pfaffian(void **state) {
    fixture *fx = derive_opts(state,
                              "coordinates x, y, z\nparameters m = 1\n"
                              "T = m/2*(x'^2 + y'^2 + z'^2)\nV = m*z\n"
                              "constraint knife: y' = z*x'\n",
                              true);
    qd_ctx *c = fx->ctx;
    const qd_eom *e = fx->eom;
    assert_int_equal(e->n, 3);
    assert_int_equal(e->nelim, 0);
    assert_int_equal(e->con[0].kind, QD_CON_NONHOLONOMIC);
    assert_ptr_equal(e->A[0], qd_neg(c, S(fx, "z")));
    assert_ptr_equal(e->A[1], qd_int(c, 1));
    assert_ptr_equal(e->b[0], qd_mul(c, S(fx, "x'"), S(fx, "z'")));
    qt_rng r = {SEED + 4};
    for (int k = 0; k < NSTATES; k++) {
        pt s = {0};
        double qdd[3], lambda, R[3], f[3];
        const char *names[] = {"x", "y", "z", "x'", "z'", "m"};
        for (int i = 0; i < 6; i++)
            set(fx, &s, names[i], qt_uniform(&r, 0.5, 2));
        set(fx, &s, "y'", s.vals[2] * s.vals[3]);
        assert_int_equal(
            qd_eom_eval(c, e, s.n, s.syms, s.vals, NULL, f, qdd, &lambda, R), QD_OK);
        double mm = s.vals[5], z = s.vals[2];
        /* the constraint holds at the acceleration level, and m q'' = f + R */
        assert_close((double[]){qdd[1] - z * qdd[0]}, (double[]){s.vals[4] * s.vals[3]}, 1,
                     "A q'' = b", k);
        for (int i = 0; i < 3; i++)
            assert_close((double[]){mm * qdd[i]}, (double[]){f[i] + R[i]}, 1, "m q''", k);
        assert_close(R, (double[]){-z * lambda, lambda, 0}, 3, "R = A^T lambda", k);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(test_atwood, teardown),
        cmocka_unit_test_teardown(test_atwood_solve, teardown),
        cmocka_unit_test_teardown(test_atwood_eliminate, teardown),
        cmocka_unit_test_teardown(test_rotating_wire, teardown),
        cmocka_unit_test_teardown(test_closing_row, teardown),
        cmocka_unit_test_teardown(test_sphere, teardown),
        cmocka_unit_test_teardown(test_inconsistent, teardown),
        cmocka_unit_test_teardown(test_redundant_at_state, teardown),
        cmocka_unit_test_teardown(test_nonlinear_velocity, teardown),
        cmocka_unit_test_teardown(test_pfaffian, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
