/*
 * tests/linear/test_conlin.c - linearization on the state manifold
 * (qdot/conlin.h) through the library: the rolling disc and the non-minimal
 * pendulum against their closed forms, the choice of states, and every
 * allocation made to fail (tests/util/fault.h): the right answer or a clean
 * QD_ERR_NOMEM, every block given back.
 *
 *   rolling disc (m = r = g = 1, upright, spin w): six eigenvalues 0 and
 *     s^2 = 4/5 - 12 w^2/5 (SymPy's test_linearize.py, A_sol of
 *     test_linearize_rolling_disc_kane; Neimark and Fufaev, Dynamics of
 *     Nonholonomic Systems, ch. III);
 *   non-minimal pendulum q1^2 + q2^2 = L^2 hanging along +q1: over (q2, q2'),
 *     A = [0 1; -g/L 0] (Desloge ch. 62, seed-desloge-B.md C6);
 *   forward-mode Jacobian (qdot/tangent.h) of the disc's compiled M: the
 *     fault loop of qd_tangent_new and qd_tangent_jacobian.
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
#include "qdot/conlin.h"
#include "qdot/tangent.h"
#include "util/fault.h"

#define DISC                                                                                   \
    "parameters m = 1, r = 1, g = 1, w = 0.8\n"                                                \
    "coordinates q1, q2, q3, x, y, z\n"                                                        \
    "body disc mass m inertia (m*r^2/4, m*r^2/4, m*r^2/2) at (x, y, z) orientation "           \
    "rot_z(q1)*rot_x(q2)*rot_y(q3)*rot_x(-pi/2)\n"                                             \
    "V = m*g*z\n"                                                                              \
    "rolls disc on plane((0, 0, 1), (0, 0, 0)) as disk(r)\n"                                   \
    "initial q1 = 0, q2 = 0, q3 = 0, x = 0, y = 0, z = r, q3' = w\n"

#define PENDULUM                                                                               \
    "parameters m = 0.9, g = 9.8, L = 1.3\n"                                                   \
    "coordinates q1, q2\n"                                                                     \
    "T = m/2*(q1'^2 + q2'^2)\n"                                                                \
    "V = -m*g*q1\n"                                                                            \
    "constraint rod: q1^2 + q2^2 = L^2\n"                                                      \
    "initial q1 = 1.2, q2 = 0\n"

static qd_status load(qd_ctx *ctx, const char *text, qd_model **m, qd_eom **e,
                      qd_linpoint *pt) {
    qd_diag d;
    *e = NULL;
    *pt = (qd_linpoint){0};
    if (!(*m = qd_model_parse(ctx, text, &d)))
        return qd_ctx_status(ctx);
    qd_eom_opts o = {.eliminate = true};
    if (!(*e = qd_eom_derive_opts(ctx, *m, &o)))
        return qd_ctx_status(ctx);
    qd_status st = qd_linpoint_init(ctx, *m, *e, pt);
    return st == QD_OK ? qd_conlin_point(ctx, *m, pt, NULL) : st;
}

static void unload(qd_model *m, qd_eom *e, qd_linpoint *pt) {
    qd_linpoint_free(pt);
    qd_eom_free(e);
    qd_model_free(m);
}

/* The disc at w = 0.8: the core's eigenvalues +-i sqrt(12 w^2/5 - 4/5), the
 * spin kept independent (given), five ignorable states. */
static void check_disc(const qd_conlin *c) {
    double w = 0.8, b = sqrt(12 * w * w / 5 - 4.0 / 5);
    assert_int_equal(c->nx, 8);
    size_t zeros = 0, small = 0, pair = 0;
    for (size_t k = 0; k < c->nx; k++) {
        double re = c->ss.eig_re[k], im = c->ss.eig_im[k];
        zeros += re == 0 && im == 0;
        small += hypot(re, im) < 1e-12;
        pair += fabs(re) < 1e-12 && fabs(fabs(im) - b) < 1e-12;
    }
    /* five ignorable (exactly 0) and the core's yaw-rate mode (0 to round-off) */
    assert_int_equal(zeros, c->nx - c->ncore);
    assert_int_equal(c->nx - c->ncore, 5);
    assert_int_equal(small, 6);
    assert_int_equal(pair, 2);
    bool spin = false;
    for (size_t i = 0; i < c->nx; i++)
        spin = spin || c->indep[i] == c->n + 2; /* q3' */
    assert_true(spin);
    assert_true(fabs(c->z[c->n + 3] - w) < 1e-14); /* x' = r w */
}

static void test_disc(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m;
    qd_eom *e;
    qd_linpoint pt;
    assert_int_equal(load(ctx, DISC, &m, &e, &pt), QD_OK);
    qd_conlin c = {0};
    assert_int_equal(qd_conlin_about(ctx, e, m, &pt, NULL, &c), QD_OK);
    check_disc(&c);
    qd_conlin_free(&c);
    /* a choice that cannot carry the constraints: x', y' independent, q1', q2', q3'... */
    assert_int_equal(qd_conlin_about(ctx, e, m, &pt, "q1, q2, q3, x, y, x', y', q2'", &c),
                     QD_ERR_ARG);
    assert_true(qd_ctx_diag(ctx)->located || qd_ctx_status(ctx) == QD_ERR_ARG);
    qd_conlin_free(&c);
    qd_ctx_clear_error(ctx);
    assert_int_equal(qd_conlin_about(ctx, e, m, &pt, "q1, q2", &c), QD_ERR_ARG);
    assert_true(qd_ctx_diag(ctx)->located);
    qd_conlin_free(&c);
    unload(m, e, &pt);
    qd_ctx_free(ctx);
}

static void test_pendulum(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m;
    qd_eom *e;
    qd_linpoint pt;
    assert_int_equal(load(ctx, PENDULUM, &m, &e, &pt), QD_OK);
    qd_conlin c = {0};
    assert_int_equal(qd_conlin_about(ctx, e, m, &pt, NULL, &c), QD_OK);
    /* q1 = 1.2 put on the rod by Newton: q1 = L */
    assert_int_equal(c.nx, 2);
    assert_true(fabs(c.z[0] - 1.3) < 1e-14);
    assert_true(fabs(c.ss.A[0] - 0) < 1e-15 && fabs(c.ss.A[1] - 1) < 1e-15);
    assert_true(fabs(c.ss.A[2] + 9.8 / 1.3) < 1e-12 && fabs(c.ss.A[3]) < 1e-15);
    qd_conlin_free(&c);
    /* the coordinate named alone: its velocity chosen, the same A */
    assert_int_equal(qd_conlin_about(ctx, e, m, &pt, "q2", &c), QD_OK);
    assert_int_equal(c.nx, 2);
    assert_true(fabs(c.ss.A[2] + 9.8 / 1.3) < 1e-12 && c.indep[1] == 3);
    qd_conlin_free(&c);
    unload(m, e, &pt);
    qd_ctx_free(ctx);
}

/* ---- every allocation failed in turn ------------------------------------------- */

static qd_status disc_body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)data;
    qd_model *m;
    qd_eom *e;
    qd_linpoint pt;
    long to_go = qt_fault_hold(f);
    assert_int_equal(load(ctx, DISC, &m, &e, &pt), QD_OK);
    qt_fault_release(f, to_go);
    qd_conlin c = {0};
    qd_status st = qd_conlin_about(ctx, e, m, &pt, NULL, &c);
    if (st == QD_OK)
        check_disc(&c);
    qd_conlin_free(&c);
    unload(m, e, &pt);
    return st;
}

static void test_disc_fault(void **state) {
    (void)state;
    qt_fault_stats s = qt_fault_loop("conlin disc", disc_body, NULL, 1);
    assert_true(s.allocs > 20);
}

static qd_status scan_body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)data;
    qd_model *m;
    qd_eom *e;
    qd_linpoint pt;
    long to_go = qt_fault_hold(f);
    assert_int_equal(load(ctx, DISC, &m, &e, &pt), QD_OK);
    qt_fault_release(f, to_go);
    qd_conlin_scan sc = {0};
    qd_status st = qd_conlin_scan_run(ctx, e, m, &pt, NULL, NULL, "w", 0.3, 0.9, 3, &sc);
    if (st == QD_OK) { /* stable (marginally) from w = 1/sqrt(3) */
        assert_int_equal(sc.ncross, 1);
        assert_true(fabs(sc.cross[0].at - 1 / sqrt(3)) < 1e-9);
        assert_true(sc.cross[0].to_stable && sc.cross[0].marginal);
    }
    qd_conlin_scan_free(&sc);
    unload(m, e, &pt);
    return st;
}

static void test_scan_fault(void **state) {
    (void)state;
    qt_fault_loop("conlin scan", scan_body, NULL, 7);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_disc),
        cmocka_unit_test(test_pendulum),
        cmocka_unit_test(test_disc_fault),
        cmocka_unit_test(test_scan_fault),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
