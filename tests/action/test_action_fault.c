/*
 * tests/action/test_action_fault.c - qd_action_at with every allocation
 * made to fail, one at a time (the loop of tests/fault/test_fault.c,
 * SQLite's exprfault.test): each run ends with the right answer or a clean
 * QD_ERR_NOMEM, and every block given back.
 *
 * Bodies and the answers they must give (Desloge ch. 79, seed 004;
 * Goldstein sec. 10.7-10.8, seed 002):
 *   the pendulum at theta0 = 1 from rest: J = 16 m sqrt(g l^3)
 *     [E(k) - (1 - k^2) K(k)], k = sin(1/2) (K, E by the AGM);
 *   Kepler in polar coordinates (through qd_hj_derive): J_r + J_theta =
 *     2 pi k sqrt(m / (-2 E)).
 * The model is parsed with the failures off, so the loops fail the
 * allocations of the derivation, the separation and the quadratures.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "qdot/action.h"
#include "qdot/qdot.h"

#define PI 3.14159265358979323846

typedef struct faulty {
    long count, fail_at, live;
    bool failed, on;
} faulty;

static bool refuse(faulty *f) {
    if (!f->on || ++f->count != f->fail_at)
        return false;
    f->failed = true;
    return true;
}

static void *f_malloc(void *user, size_t size) {
    faulty *f = user;
    if (refuse(f))
        return NULL;
    void *p = malloc(size);
    if (p)
        f->live++;
    return p;
}

static void *f_realloc(void *user, void *p, size_t size) {
    return refuse(user) ? NULL : realloc(p, size);
}

static void f_free(void *user, void *p) {
    faulty *f = user;
    f->live--;
    free(p);
}

/* A model and the state: every parameter at its value, then the extra
 * coordinates and velocities. */
typedef struct body {
    const char *text;
    size_t nset;
    const char *names[8];
    double vals[8];
    double (*answer)(const qd_action *a);
} body;

static double pendulum_answer(const qd_action *a) {
    double k = sin(0.5), x = 1, y = sqrt(1 - k * k), c = k, s = c * c / 2, pw = 0.5;
    for (int i = 0; i < 40 && c > 1e-17; i++) {
        double xn = (x + y) / 2;
        c = (x - y) / 2;
        y = sqrt(x * y);
        x = xn;
        pw *= 2;
        s += pw * c * c;
    }
    double K = PI / (2 * x), E = K * (1 - s);
    return a->c[0].J - 16 * sqrt(9.81 * 8) * (E - (1 - k * k) * K);
}

static double kepler_answer(const qd_action *a) {
    return a->c[0].J + a->c[1].J - 2 * PI * 4 * sqrt(1.3 / (-2 * a->energy));
}

static qd_status run_body(qd_ctx *ctx, faulty *f, const body *b) {
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, b->text, &d);
    if (!m)
        fail_msg("parse: %s", d.message);
    const qd_expr *syms[16];
    double vals[16];
    size_t n = 0;
    for (size_t i = 0; i < qd_model_nparams(m); i++) {
        syms[n] = qd_model_param(m, i);
        qd_eval(ctx, qd_model_param_value(m, i), 0, NULL, NULL, &vals[n++]);
    }
    for (size_t i = 0; i < b->nset; i++) {
        syms[n] = qd_read(ctx, b->names[i], NULL, NULL);
        vals[n++] = b->vals[i];
    }
    f->on = true;
    qd_action a;
    qd_status st = qd_action_at(ctx, m, n, syms, vals, NULL, &a);
    f->on = false;
    if (st == QD_OK && !(fabs(b->answer(&a)) < 1e-10))
        fail_msg("wrong answer after %ld allocations: off by %g", f->count, b->answer(&a));
    qd_action_free(&a);
    qd_model_free(m);
    return st;
}

static void fault_loop(const char *what, const body *b, long stride) {
    long runs = 0, nomem = 0;
    for (long n = 1;; n += stride) {
        faulty f = {0, n, 0, false, false};
        qd_allocator al = {f_malloc, f_realloc, f_free, &f};
        qd_ctx *ctx = qd_ctx_new_with(&al);
        assert_non_null(ctx);
        qd_status st = run_body(ctx, &f, b);
        qd_status recorded = qd_ctx_status(ctx);
        char why[256];
        snprintf(why, sizeof why, "%s", qd_ctx_message(ctx));
        qd_ctx_free(ctx);
        runs++;
        if (f.live != 0)
            fail_msg("%s, allocation %ld failed: %ld blocks leaked", what, n, f.live);
        if (st == QD_OK && recorded == QD_ERR_NOMEM)
            fail_msg("%s, allocation %ld failed: success, but out of memory recorded", what, n);
        if (st != QD_OK) {
            if (st != QD_ERR_NOMEM || !f.failed || recorded != QD_ERR_NOMEM)
                fail_msg("%s, allocation %ld failed: %s instead of out of memory (%s)", what, n,
                         qd_status_str(st), why);
            nomem++;
        }
        if (!f.failed) {
            assert_int_equal(st, QD_OK);
            break;
        }
    }
    printf("%s: %ld runs, %ld out of memory\n", what, runs, nomem);
}

static void test_pendulum_fault(void **state) {
    (void)state;
    body b = {"coordinates th\nparameters m = 1, l = 2, g = 9.81\n"
              "particle m at (l*sin(th), -l*cos(th))\nV = -m*g*l*cos(th)\n",
              2, {"th", "th'"}, {1, 0}, pendulum_answer};
    fault_loop("pendulum action", &b, 1);
}

static void test_kepler_fault(void **state) {
    (void)state;
    body b = {"coordinates r, theta\nparameters m = 1.3, k = 4\n"
              "particle m at r*(cos(theta), sin(theta))\nV = -k/r\n",
              4, {"r", "theta", "r'", "theta'"}, {1, 0.3, 0.4, 1.5}, kepler_answer};
    fault_loop("Kepler action", &b, 7);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pendulum_fault),
        cmocka_unit_test(test_kepler_fault),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
