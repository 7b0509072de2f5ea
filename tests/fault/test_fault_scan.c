/*
 * tests/fault/test_fault_scan.c - every allocation of a scan and of a
 * contour made to fail, one at a time (the loop of tests/util/fault.h: each run
 * ends with the right answer or a clean QD_ERR_NOMEM, every block given
 * back, and a success never leaves out-of-memory recorded).
 *
 * Bodies and the answers they must give:
 *   modes scan: L4 of the restricted three-body problem followed from
 *     (1/2 - mu, sqrt 3/2), its transition at Routh's value
 *     (1 - sqrt(23/27))/2 (Desloge ch. 62, seed-desloge-B.md C6);
 *   stability scan: the sleeping top with nu = 3 along g, unstable from
 *     g = nu^2/(4 A M h) = 4.5 (Britannica sec. 6 (1), seed 004; B11);
 *   zero-velocity curves: a harmonic oscillator's W = (x^2 + y^2)/2 at the
 *     level 1/2: one closed curve of radius 1 (Jacobi's integral is the
 *     energy).
 * The models derive with the failures off, so the loops fail only the
 * allocations of the scan or the contour; the scans' loops fail every 2nd
 * (modes) and 97th (stability) allocation only, to keep them to seconds.
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
#include "util/fault.h"

/* Parse and derive with the failures off; then arm them. */
static void derive(qd_ctx *ctx, qt_faulty *f, const char *text, qd_model **m, qd_eom **e) {
    long armed = f->fail_at;
    f->fail_at = 0;
    *m = qd_model_parse(ctx, text, NULL);
    assert_non_null(*m);
    *e = qd_eom_derive(ctx, *m);
    assert_non_null(*e);
    f->fail_at = f->count + armed;
}

#define THREE_BODY                                                                             \
    "coordinates x, y\nparameters mu = 0.01\n"                                                 \
    "T = 1/2*((x' - y)^2 + (y' + x)^2)\n"                                                      \
    "V = -(1 - mu)/sqrt((x + mu)^2 + y^2) - mu/sqrt((x - 1 + mu)^2 + y^2)\n"

static qd_status modes_scan_body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)data;
    qd_model *m;
    qd_eom *e;
    long armed = f->fail_at;
    f->fail_at = 0;
    derive(ctx, f, THREE_BODY, &m, &e);
    const qd_expr *about[2] = {qd_read(ctx, "1/2 - mu", NULL, NULL),
                               qd_read(ctx, "sqrt(3)/2", NULL, NULL)};
    assert_non_null(about[0]);
    assert_non_null(about[1]);
    f->fail_at = f->count + armed;
    qd_scan_opts o = {.steps = 3, .about = about};
    qd_scan sc;
    qd_status st = qd_modes_scan(ctx, e, m, "mu", 0.02, 0.05, &o, &sc);
    if (st == QD_OK) {
        assert_int_equal(sc.ntrans, 1);
        assert_true(fabs(sc.trans[0].value - (1 - sqrt(23.0 / 27.0)) / 2) < 1e-10);
    }
    qd_scan_free(&sc);
    qd_eom_free(e);
    qd_model_free(m);
    return st;
}

static void test_modes_scan(void **state) {
    (void)state;
    assert_true(qt_fault_loop("modes scan", modes_scan_body, NULL, 2).allocs > 20);
}

#define SLEEPING_TOP                                                                           \
    "coordinates a, b, psi\nparameters M = 1, h = 1/2, g = 2, A = 1, C = 1/2\n"                \
    "R = rot_x(a)*rot_y(b)*rot_z(psi)\n"                                                       \
    "body top mass M inertia (A - M*h^2, A - M*h^2, C) at R*(0, 0, h) orientation R\n"         \
    "V = M*g*position(top).z\n"

static qd_status stability_scan_body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)data;
    qd_model *m;
    qd_eom *e;
    long armed = f->fail_at;
    f->fail_at = 0;
    derive(ctx, f, SLEEPING_TOP, &m, &e);
    const qd_expr *psi = qd_lookup(ctx, "psi");
    qd_steady *s = qd_steady_derive(ctx, m, e, 1, &psi, false);
    assert_non_null(s);
    f->fail_at = f->count + armed;
    double x[2] = {0, 0}, w[1] = {1}, p[1] = {3};
    bool xfix[2] = {false, false}, wfix[1] = {false}, pfix[1] = {true};
    qd_steady_point start = {x, w, p};
    qd_scan_opts o = {.steps = 3};
    qd_scan sc;
    qd_status st = qd_stability_scan(ctx, s, m, "g", 1, 8, xfix, wfix, pfix, NULL, &start, &o,
                                     &sc);
    if (st == QD_OK) {
        assert_int_equal(sc.ntrans, 1);
        assert_true(fabs(sc.trans[0].value - 4.5) < 1e-10);
    }
    qd_scan_free(&sc);
    qd_steady_free(s);
    qd_eom_free(e);
    qd_model_free(m);
    return st;
}

static void test_stability_scan(void **state) {
    (void)state;
    /* some 50,000 allocations (each step's steady-motion search): every 97th is failed,
     * which keeps the loop to seconds and still reaches every kind of call */
    assert_true(qt_fault_loop("stability scan", stability_scan_body, NULL, 97).allocs > 20);
}

static qd_status zvc_body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)data;
    qd_model *m;
    qd_eom *e;
    derive(ctx, f, "coordinates x, y\nT = (x'^2 + y'^2)/2\nV = (x^2 + y^2)/2\n", &m, &e);
    qd_zvc z;
    qd_contour c = {0};
    qd_zvc_box box = {0, 1, {-2, -2}, {2, 2}, 40, 40};
    qd_status st = qd_zvc_derive(ctx, m, e, &z);
    if (st == QD_OK)
        st = qd_zvc_curves(ctx, e, &z, &box, 0, NULL, NULL, 0.5, &c);
    if (st == QD_OK) {
        assert_int_equal(c.count, 1);
        assert_true(c.lines[0].closed);
        for (size_t i = 0; i < c.lines[0].count; i++)
            assert_true(fabs(hypot(c.lines[0].x[i], c.lines[0].y[i]) - 1) < 1e-2);
    }
    qd_contour_free(&c);
    qd_eom_free(e);
    qd_model_free(m);
    return st;
}

static void test_zvc(void **state) {
    (void)state;
    assert_true(qt_fault_loop("zero-velocity curves", zvc_body, NULL, 1).allocs > 5);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_modes_scan),
        cmocka_unit_test(test_stability_scan),
        cmocka_unit_test(test_zvc),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
