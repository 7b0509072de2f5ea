/*
 * tests/path/test_path_iso_fault.c - an isoperimetric, free-end path with
 * every allocation of qd_path_find made to fail, one at a time (the loop of
 * tests/util/fault.h; the habit of tests/fault/test_fault.c).
 *
 * Body: the chain of length 3 from (0, 0) whose right end slides on the
 * line x = 1 (Desloge vol. 2 App. 32 Thm 5; the natural condition of Gelfand
 * and Fomin ch. 1 sec. 6): horizontal there, so y = c + a cosh((x - 1)/a)
 * with 3 = a sinh(1/a) and c = -a cosh(1/a), the multiplier lambda = w c.
 * The parse and the derivation are held out of the loop (their own fault
 * tests cover them).  Each run ends with that answer or a clean
 * QD_ERR_NOMEM, every block given back.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdbool.h>

#include "qdot/path.h"
#include "qdot/qdot.h"
#include "util/fault.h"

/* the multiplier starts near its value, and the guess makes the first start
 * converge, so that a run is one Newton iteration's worth of allocations */
static const char chain[] = "independent x\ncoordinates y\n"
                            "parameters w = 2, lambda_length = -3\n"
                            "L = w*y*sqrt(1 + y'^2)\n"
                            "constraint length: integral(sqrt(1 + y'^2)) = 3\n";

static double half_width(void) {  /* a sinh(1/a) = 3, by bisection */
    double lo = 1e-3, hi = 1e3;
    for (int i = 0; i < 300; i++) {
        double a = sqrt(lo * hi);
        if (a * sinh(1 / a) > 3)
            lo = a;
        else
            hi = a;
    }
    return sqrt(lo * hi);
}

static qd_status body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)data;
    long to_go = qt_fault_hold(f);
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, chain, &d);
    qd_eom *e = m ? qd_eom_derive(ctx, m) : NULL;
    qt_fault_release(f, to_go);
    assert_non_null(e);
    double y0 = 0, y1 = 0, a = half_width(), guess = -sinh(1 / a) * 0.9;
    bool fr[1] = {true};
    qd_path_opts o = {.t0 = 0, .t1 = 1, .q0 = &y0, .q1 = &y1, .free1 = fr,
                      .nguess = 1, .guess = &guess};
    qd_path_set ps;
    qd_status st = qd_path_find(ctx, m, e, &o, &ps);
    if (st == QD_OK) {
        const qd_path *p = &ps.paths[0];
        assert_true(fabs(p->mult[0] - 2 * -a * cosh(1 / a)) < 1e-8);
        assert_true(fabs(p->q[p->nsamples - 1] - (a - a * cosh(1 / a))) < 1e-8);
        qd_path_set_free(&ps);
    }
    qd_eom_free(e);
    qd_model_free(m);
    return st;
}

static void test_path_iso_fault(void **state) {
    (void)state;
    assert_true(qt_fault_loop("isoperimetric free-end path", body, NULL, 1).runs > 10);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_path_iso_fault)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
