/*
 * tests/linear/test_speeds_fault.c - every allocation of the speeds'
 * equilibria, linearization, scan and generated C made to fail, one at a
 * time (the loop of tests/util/fault.h: the right answer or a clean
 * QD_ERR_NOMEM, every block given back).  The model is the rolling disk of
 * test_speeds_modes.c, parsed and derived with the failures off; answers:
 * theta = +-pi/2 with four free coordinates, the upright disk stable at spin
 * 6 and its threshold sqrt(g/(3a)) from a scan (Neimark and Fufaev ch. III),
 * and C text that declares the rhs.  Strides (every 2nd, 4th, 7th, 41st
 * allocation) keep each loop near 15 s under ASan; with stride 1 all four
 * were clean there (ASAN_OPTIONS=detect_leaks=1).
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
#include "qdot/codegen.h"
#include "util/fault.h"

#define DISK                                                                                   \
    "coordinates x, y, phi, theta, psi\nparameters m = 1.4, a = 0.35, g = 9.81\n"              \
    "body disk mass m inertia disk(m, a) at (x, y, a*sin(theta)) "                             \
    "orientation euler(phi, theta, psi)\nV = m*g*a*sin(theta)\n"                               \
    "rolls disk on plane((0, 0, 1), (0, 0, 0)) as disk(a)\n"                                   \
    "speeds u1 = theta', u2 = omega_space(disk).z, u3 = omega(disk).z\n"

static const double PI = 3.14159265358979323846;

typedef struct setup {
    qd_model *m;
    qd_speeds_eom *e;
    const qd_expr *syms[12];
    double vals[12];
    size_t k;
} setup;

/* Parse and derive with the failures off; the state: parameters, theta =
 * pi/2, u3 = 6. */
static void prepare(qd_ctx *ctx, qt_faulty *f, setup *s) {
    long to_go = qt_fault_hold(f);
    s->m = qd_model_parse(ctx, DISK, NULL);
    assert_non_null(s->m);
    s->e = qd_speeds_derive(ctx, s->m, NULL);
    assert_non_null(s->e);
    s->k = 0;
    for (size_t i = 0; i < qd_model_nparams(s->m); i++) {
        s->syms[s->k] = qd_model_param(s->m, i);
        assert_int_equal(qd_model_param_number(s->m, i, &s->vals[s->k]), QD_OK);
        s->k++;
    }
    s->syms[s->k] = s->e->q[3];
    s->vals[s->k++] = PI / 2;
    s->syms[s->k] = s->e->u[2];
    s->vals[s->k++] = 6;
    qt_fault_release(f, to_go);
}

static void done(setup *s) {
    qd_speeds_eom_free(s->e);
    qd_model_free(s->m);
}

static qd_status equilibria_body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)data;
    setup s;
    prepare(ctx, f, &s);
    qd_speeds_equilibria eq;
    qd_status st = qd_speeds_equilibria_find(ctx, s.e, s.m, 3, s.syms, s.vals, NULL, &eq);
    if (st == QD_OK) {
        assert_int_equal(eq.nsolved, 1);
        assert_int_equal(eq.eq.count, 2);
        assert_true(fabs(eq.eq.pts[1].q[0] - PI / 2) < 1e-12);
        qd_speeds_equilibria_free(&eq);
    }
    done(&s);
    return st;
}

static qd_status modes_body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)data;
    setup s;
    prepare(ctx, f, &s);
    qd_speeds_linear lin;
    qd_modes_result res;
    qd_status st = qd_speeds_linear_about(ctx, s.e, s.k, s.syms, s.vals, &lin);
    if (st == QD_OK) {
        st = qd_speeds_modes_solve(ctx, &lin, &res);
        if (st == QD_OK) {
            assert_int_equal(res.stable, 1);
            qd_modes_result_free(&res);
        }
        qd_speeds_linear_free(&lin);
    }
    done(&s);
    return st;
}

static qd_status scan_body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)data;
    setup s;
    prepare(ctx, f, &s);
    qd_scan sc;
    qd_scan_opts o = {.steps = 4};
    qd_status st = qd_speeds_modes_scan(ctx, s.e, s.k, s.syms, s.vals, s.e->u[2], 1, 6, &o, &sc);
    if (st == QD_OK) {
        assert_int_equal(sc.ntrans, 1);
        assert_true(fabs(sc.trans[0].value - sqrt(9.81 / (3 * 0.35))) < 1e-8);
    }
    qd_scan_free(&sc);
    done(&s);
    return st;
}

static qd_status codegen_body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)data;
    setup s;
    prepare(ctx, f, &s);
    qd_buf c = QD_BUF_INIT, h = QD_BUF_INIT;
    qd_status st = qd_codegen_speeds_c(ctx, s.m, s.e, "disk", &c, &h);
    if (st == QD_OK)
        assert_non_null(strstr(qd_buf_str(&h), "int disk_rhs("));
    qd_buf_free(&c);
    qd_buf_free(&h);
    done(&s);
    return st;
}

static void test_equilibria(void **state) {
    (void)state;
    assert_true(qt_fault_loop("speeds equilibria", equilibria_body, NULL, 2).allocs > 10);
}

static void test_modes(void **state) {
    (void)state;
    assert_true(qt_fault_loop("speeds modes", modes_body, NULL, 4).allocs > 10);
}

static void test_scan(void **state) {
    (void)state;
    assert_true(qt_fault_loop("speeds scan", scan_body, NULL, 7).allocs > 10);
}

static void test_codegen(void **state) {
    (void)state;
    assert_true(qt_fault_loop("speeds codegen", codegen_body, NULL, 41).allocs > 10);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_equilibria),
        cmocka_unit_test(test_modes),
        cmocka_unit_test(test_scan),
        cmocka_unit_test(test_codegen),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
