/*
 * tests/mech/test_hamilton.c - the Legendre transform (qd_ham_derive)
 * against textbook Hamiltonians and against Lagrange's equations.
 *
 * Textbook cases (../shared/reference/): the bead on a rotating wire,
 * seed-goldstein-britannica.md G03 (H = p^2/2m - m omega^2 r^2/2, conserved
 * but not T + V); the Kepler problem in polar coordinates,
 * seed-desloge-B.md C3 (H = p_r^2/2m + p_theta^2/(2 m r^2) - k/r); the
 * charged particle, seed-goldstein-britannica.md C3 and seed-desloge-A.md
 * T35 (H = (p - qA)^2/2m + q phi); the free body in Euler angles,
 * seed-desloge-C.md C11 (H from the body's angular momentum), and a chain
 * of springs in relative coordinates.  Each is compared by value at random
 * points.  The consistency test: at random (q, q'), with p = dL/dq',
 * dH/dp gives q' back and dp/dt equals dL/dq + Q - dD/dq' (Lagrange's
 * equations written for p).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "qdot/qdot.h"

#define SEED 7713u
#define NPOINTS 10
#define MAXS 64

typedef struct fix {
    qd_ctx *ctx;
    qd_model *m;
    qd_eom *e;
    qd_ham *h;
} fix;

static fix load(const char *text) {
    fix f = {qd_ctx_new(), NULL, NULL, NULL};
    qd_diag d;
    f.m = qd_model_parse(f.ctx, text, &d);
    assert_non_null(f.m);
    f.e = qd_eom_derive(f.ctx, f.m);
    assert_non_null(f.e);
    f.h = qd_ham_derive(f.ctx, f.m, f.e);
    if (!f.h)
        fprintf(stderr, "qd_ham_derive: %s\n", qd_ctx_message(f.ctx));
    return f;
}

static void unload(fix *f) {
    qd_ham_free(f->h);
    qd_eom_free(f->e);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
}

/* A random state: every free symbol of the listed expressions in [0.3, 1.8). */
typedef struct point {
    const qd_expr *syms[MAXS];
    double vals[MAXS];
    size_t n;
} point;

static void add_syms(qd_ctx *ctx, point *pt, const qd_expr *x) {
    const qd_expr *s[MAXS];
    size_t ns = qd_free_symbols(ctx, x, s, MAXS);
    assert_true(ns <= MAXS);
    for (size_t i = 0; i < ns; i++) {
        size_t k = 0;
        while (k < pt->n && pt->syms[k] != s[i])
            k++;
        if (k == pt->n) {
            assert_true(pt->n < MAXS);
            pt->syms[pt->n] = s[i];
            pt->vals[pt->n++] = 0.3 + 1.5 * rand() / (double)RAND_MAX;
        }
    }
}

static double val(qd_ctx *ctx, const point *pt, const qd_expr *x) {
    double v;
    assert_int_equal(qd_eval(ctx, x, pt->n, pt->syms, pt->vals, &v), QD_OK);
    return v;
}

static void assert_close(double a, double b, const char *what) {
    if (fabs(a - b) > 1e-9 * (1 + fabs(a) + fabs(b)))
        fail_msg("%s: %.17g != %.17g (seed %u)", what, a, b, SEED);
}

/* H equals the expression `expected` (model language, in q, p, t and the
 * parameters) at random points. */
static void assert_H(fix *f, const char *expected) {
    qd_read_error err;
    const qd_read_opts opts = {.new_symbols = true};
    const qd_expr *x = qd_read(f->ctx, expected, &opts, &err);
    assert_non_null(x);
    for (int k = 0; k < NPOINTS; k++) {
        point pt = {.n = 0};
        add_syms(f->ctx, &pt, f->h->H);
        add_syms(f->ctx, &pt, x);
        assert_close(val(f->ctx, &pt, f->h->H), val(f->ctx, &pt, x), expected);
    }
}

static void test_bead_rotating_wire(void **state) {
    (void)state;
    fix f = load("coordinates r\nparameters m = 1.5, omega = 2.2\n"
                 "particle m at (r*cos(omega*t), r*sin(omega*t))\n");
    assert_non_null(f.h);
    assert_string_equal(qd_expr_name(f.h->p[0]), "p_r");
    assert_H(&f, "p_r^2/(2*m) - m*omega^2*r^2/2");
    assert_true(f.h->conserved);
    assert_false(f.h->is_energy);
    assert_non_null(f.h->H_minus_E); /* H - E = -m omega^2 r^2 */
    unload(&f);
}

static void test_kepler_polar(void **state) {
    (void)state;
    fix f = load("coordinates r, theta\nparameters m = 1.3, k = 4\n"
                 "particle m at r*(cos(theta), sin(theta))\nV = -k/r\n");
    assert_non_null(f.h);
    assert_H(&f, "p_r^2/(2*m) + p_theta^2/(2*m*r^2) - k/r");
    assert_true(f.h->conserved);
    assert_true(f.h->is_energy);
    assert_true(qd_is_zero(f.h->dp[1])); /* theta is cyclic */
    unload(&f);
}

static void test_charged_particle(void **state) {
    (void)state;
    fix f = load("coordinates x, y, z\n"
                 "parameters m = 1.3, q = 0.8, Ex = 0.5, Ey = -1.2, Ez = 0.3, Bx = 0.4, "
                 "By = 0.7, Bz = 2\n"
                 "r = (x, y, z)\nE = (Ex, Ey, Ez)\nB = (Bx, By, Bz)\n"
                 "phi = -dot(E, r)\nA = cross(B, r)/2\n"
                 "particle m at r\nU = q*phi - q*dot(A, r')\n");
    assert_non_null(f.h);
    assert_H(&f, "((p_x - q*(By*z - Bz*y)/2)^2 + (p_y - q*(Bz*x - Bx*z)/2)^2"
                 " + (p_z - q*(Bx*y - By*x)/2)^2)/(2*m) - q*(Ex*x + Ey*y + Ez*z)");
    assert_true(f.h->conserved);
    assert_true(f.h->is_energy);
    unload(&f);
}

/* Hamilton's equations against Lagrange's at random (q, q'). */
static void check_lagrange(fix *f) {
    const qd_ham *h = f->h;
    const qd_eom *e = f->e;
    const qd_expr *D = qd_model_dissipation(f->m);
    for (int k = 0; k < NPOINTS; k++) {
        point pt = {.n = 0};
        add_syms(f->ctx, &pt, e->L);
        for (size_t j = 0; j < h->n; j++) {
            add_syms(f->ctx, &pt, qd_add(f->ctx, e->q[j], e->qd[j]));
            add_syms(f->ctx, &pt, qd_model_force(f->m, j));
            if (D)
                add_syms(f->ctx, &pt, D);
        }
        size_t base = pt.n;
        for (size_t j = 0; j < h->n; j++) { /* p at (q, q') */
            pt.syms[pt.n] = h->p[j];
            pt.vals[pt.n++] = val(f->ctx, &pt, h->pdef[j]);
        }
        for (size_t j = 0; j < h->n; j++) {
            const qd_expr *lhs = qd_diff(f->ctx, e->L, e->q[j]);
            lhs = qd_add(f->ctx, lhs, qd_model_force(f->m, j));
            if (D)
                lhs = qd_sub(f->ctx, lhs, qd_diff(f->ctx, D, e->qd[j]));
            assert_close(val(f->ctx, &pt, h->dq[j]), val(f->ctx, &pt, e->qd[j]), "dq/dt = q'");
            assert_close(val(f->ctx, &pt, h->dp[j]), val(f->ctx, &pt, lhs), "dp/dt");
        }
        (void)base;
    }
}

static void test_double_pendulum_lagrange(void **state) {
    (void)state;
    fix f = load("coordinates theta1, theta2\n"
                 "parameters m1 = 1, m2 = 1.5, l1 = 1, l2 = 0.7, g = 9.81\n"
                 "x1 = l1*sin(theta1)\ny1 = -l1*cos(theta1)\n"
                 "x2 = x1 + l2*sin(theta2)\ny2 = y1 - l2*cos(theta2)\n"
                 "T = m1/2*(x1'^2 + y1'^2) + m2/2*(x2'^2 + y2'^2)\n"
                 "V = m1*g*y1 + m2*g*y2\n");
    assert_non_null(f.h);
    assert_true(f.h->is_energy);
    check_lagrange(&f);
    unload(&f);
}

static void test_damped_rotating_lagrange(void **state) {
    (void)state;
    fix f = load("coordinates r, theta\nparameters m = 0.5, w = 1.1, g = 9.81, k = 0.35\n"
                 "r0 = (r*cos(theta + w*t), r*sin(theta + w*t))\n"
                 "particle m at r0\nV = m*g*r0.y\n"
                 "dissipation = k/2*dot(r0', r0')\n");
    assert_non_null(f.h);
    assert_false(f.h->conserved);
    check_lagrange(&f);
    unload(&f);
}

/* The free rigid body in Euler angles (z-x-z), Desloge ch. 68 Example 2
 * (seed-desloge-C.md C11): w = J q', p = J^T I w, so the body components
 * of the angular momentum are L1 = sin(psi) (p_phi - cos(theta) p_psi) /
 * sin(theta) + cos(psi) p_theta, L2 = cos(psi) (p_phi - cos(theta) p_psi) /
 * sin(theta) - sin(psi) p_theta, L3 = p_psi, and H = L1^2/2A + L2^2/2B +
 * L3^2/2C.  One 3 x 3 block, inverted by cofactors (legendre_blocks.c). */
static void test_euler_free_body(void **state) {
    (void)state;
    fix f = load("coordinates phi, theta, psi\n"
                 "parameters A = 1.1, B = 2.3, C = 2.9, G1 = 0.3, G2 = -0.2, G3 = 0.5\n"
                 "body b mass 1 inertia (A, B, C) at (0, 0, 0) orientation euler(phi, theta, psi)\n"
                 "torque rotation(b)*(G1, G2, G3) on b\n");
    assert_non_null(f.h);
    assert_H(&f, "(sin(psi)*(p_phi - cos(theta)*p_psi)/sin(theta) + cos(psi)*p_theta)^2/(2*A)"
                 " + (cos(psi)*(p_phi - cos(theta)*p_psi)/sin(theta) - sin(psi)*p_theta)^2/(2*B)"
                 " + p_psi^2/(2*C)");
    assert_true(f.h->is_energy);
    check_lagrange(&f);
    unload(&f);
}

/* Two blocks with different determinants (a double pendulum beside a
 * mass on a spring): the equations share the product of both. */
static void test_two_blocks_lagrange(void **state) {
    (void)state;
    fix f = load("coordinates theta1, theta2, x\n"
                 "parameters m1 = 1, m2 = 1.5, m3 = 0.8, l1 = 1, l2 = 0.7, g = 9.81, k = 3\n"
                 "x1 = l1*sin(theta1)\ny1 = -l1*cos(theta1)\n"
                 "x2 = x1 + l2*sin(theta2)\ny2 = y1 - l2*cos(theta2)\n"
                 "T = m1/2*(x1'^2 + y1'^2) + m2/2*(x2'^2 + y2'^2) + m3/2*x'^2\n"
                 "V = m1*g*y1 + m2*g*y2 + k/2*x^2\n");
    assert_non_null(f.h);
    assert_true(f.h->is_energy);
    check_lagrange(&f);
    unload(&f);
}

/* Five masses in a line, each coordinate the stretch of one spring, so
 * x_i = q1 + ... + qi and M is dense: one 5 x 5 block (elimination on it
 * ran past the expansion limit; its cofactors do not).  The momentum conjugate to q_i is the total
 * momentum of masses i..5, so H = sum (p_i - p_i+1)^2 / 2 m_i (p_6 = 0)
 * plus the springs. */
static void test_chain_elimination(void **state) {
    (void)state;
    fix f = load("coordinates q1, q2, q3, q4, q5\n"
                 "parameters m1 = 1, m2 = 1.3, m3 = 0.7, m4 = 2, m5 = 0.9, k = 2.5\n"
                 "x1 = q1\nx2 = x1 + q2\nx3 = x2 + q3\nx4 = x3 + q4\nx5 = x4 + q5\n"
                 "T = m1/2*x1'^2 + m2/2*x2'^2 + m3/2*x3'^2 + m4/2*x4'^2 + m5/2*x5'^2\n"
                 "V = k/2*(q1^2 + q2^2 + q3^2 + q4^2 + q5^2)\n");
    assert_non_null(f.h);
    assert_H(&f, "(p_q1 - p_q2)^2/(2*m1) + (p_q2 - p_q3)^2/(2*m2) + (p_q3 - p_q4)^2/(2*m3)"
                 " + (p_q4 - p_q5)^2/(2*m4) + p_q5^2/(2*m5)"
                 " + k/2*(q1^2 + q2^2 + q3^2 + q4^2 + q5^2)");
    assert_true(f.h->is_energy);
    check_lagrange(&f);
    unload(&f);
}

static void test_constrained_refused(void **state) {
    (void)state;
    fix f = load("coordinates x, y\nparameters m = 0.6, l = 1.4, g = 9.81\n"
                 "particle m at (x, y)\nV = m*g*y\nconstraint rod: x^2 + y^2 = l^2\n");
    assert_null(f.h);
    assert_int_equal(qd_ctx_status(f.ctx), QD_ERR_ARG);
    unload(&f);
}

int main(void) {
    srand(SEED);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bead_rotating_wire),
        cmocka_unit_test(test_kepler_polar),
        cmocka_unit_test(test_charged_particle),
        cmocka_unit_test(test_double_pendulum_lagrange),
        cmocka_unit_test(test_damped_rotating_lagrange),
        cmocka_unit_test(test_euler_free_body),
        cmocka_unit_test(test_two_blocks_lagrange),
        cmocka_unit_test(test_chain_elimination),
        cmocka_unit_test(test_constrained_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
