/*
 * tests/fault/test_fault_scan.c - every allocation of a scan and of a
 * contour made to fail, one at a time (the loop of test_fault.c: each run
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

typedef struct faulty {
    long count;    /* requests so far (malloc and realloc) */
    long fail_at;  /* the request to refuse, 0: none */
    long live;     /* blocks outstanding */
    bool failed;   /* fail_at was reached */
} faulty;

static bool refuse(faulty *f) {
    if (++f->count != f->fail_at)
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

typedef qd_status (*body_fn)(qd_ctx *ctx, faulty *f);

/* Run body failing allocation 1, 1 + stride, ... until it is not reached. */
static long fault_loop(const char *what, body_fn body, long stride) {
    long runs = 0;
    for (long n = 1;; n += stride) {
        faulty f = {0, n, 0, false};
        qd_allocator a = {f_malloc, f_realloc, f_free, &f};
        qd_ctx *ctx = qd_ctx_new_with(&a);
        qd_status st = ctx ? body(ctx, &f) : QD_ERR_NOMEM;
        char why[256];
        snprintf(why, sizeof why, "%s", ctx ? qd_ctx_message(ctx) : "");
        qd_status recorded = ctx ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
        qd_ctx_free(ctx);
        runs++;
        if (f.live != 0)
            fail_msg("%s, allocation %ld failed: %ld blocks leaked", what, n, f.live);
        if (st == QD_OK && recorded == QD_ERR_NOMEM)
            fail_msg("%s, allocation %ld failed: success, but out of memory recorded", what, n);
        if (st != QD_OK && (st != QD_ERR_NOMEM || !f.failed || recorded != QD_ERR_NOMEM))
            fail_msg("%s, allocation %ld failed: status %s, recorded %s (%s)", what, n,
                     qd_status_str(st), qd_status_str(recorded), why);
        if (!f.failed) {
            assert_int_equal(st, QD_OK);
            printf("%s: %ld allocations, %ld runs\n", what, f.count, runs);
            return f.count;
        }
    }
}

/* Parse and derive with the failures off; then arm them. */
static void derive(qd_ctx *ctx, faulty *f, const char *text, qd_model **m, qd_eom **e) {
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

static qd_status modes_scan_body(qd_ctx *ctx, faulty *f) {
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
    assert_true(fault_loop("modes scan", modes_scan_body, 2) > 20);
}

#define SLEEPING_TOP                                                                           \
    "coordinates a, b, psi\nparameters M = 1, h = 1/2, g = 2, A = 1, C = 1/2\n"                \
    "R = rot_x(a)*rot_y(b)*rot_z(psi)\n"                                                       \
    "body top mass M inertia (A - M*h^2, A - M*h^2, C) at R*(0, 0, h) orientation R\n"         \
    "V = M*g*position(top).z\n"

static qd_status stability_scan_body(qd_ctx *ctx, faulty *f) {
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
    assert_true(fault_loop("stability scan", stability_scan_body, 97) > 20);
}

static qd_status zvc_body(qd_ctx *ctx, faulty *f) {
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
    assert_true(fault_loop("zero-velocity curves", zvc_body, 1) > 5);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_modes_scan),
        cmocka_unit_test(test_stability_scan),
        cmocka_unit_test(test_zvc),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
