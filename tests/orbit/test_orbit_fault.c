/*
 * tests/orbit/test_orbit_fault.c - the orbit analysis with every allocation
 * made to fail, one at a time (the habit of tests/fault/test_fault.c; the
 * loop of tests/util/fault.h).
 *
 * Body: Kepler's problem in plane polar coordinates (Desloge ch. 58,
 * reference seed-desloge-B.md C3), derived and solved at r = 1, r' = 0.4,
 * theta' = 1.5.  Each run must end with the right answer (the turning
 * points a(1 -+ e), the radial period 2 pi sqrt(m a^3/k) and the conic's e)
 * or a clean QD_ERR_NOMEM recorded in the context, with every block given
 * back; a success with out of memory recorded (a fallback taken for want of
 * memory, such as a Kepler potential not recognised) is a failure.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "qdot/orbit.h"
#include "qdot/qdot.h"
#include "util/fault.h"

#define PI 3.14159265358979323846

static const char kepler[] =
    "coordinates r, theta\nparameters m = 1.3, k = 4\n"
    "particle m at r*(cos(theta), sin(theta))\nV = -k/r\n";

static void check_answer(const qd_orbit_result *r) {
    double m = 1.3, k = 4, h = m * 1.5, E = m * (0.16 + 2.25) / 2 - k;
    double e = sqrt(1 + 2 * E * h * h / (m * k * k)), a = h * h / (m * k) / (1 - e * e);
    assert_true(fabs(r->turn[0] - a * (1 - e)) < 1e-12);
    assert_true(fabs(r->turn[1] - a * (1 + e)) < 1e-12);
    assert_true(fabs(r->period - 2 * PI * sqrt(m * a * a * a / k)) < 1e-11);
    assert_true(r->conic && fabs(r->e - e) < 1e-13);
}

static qd_status body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)f, (void)data;
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, kepler, &d);
    qd_eom *e = m ? qd_eom_derive(ctx, m) : NULL;
    const qd_expr *theta = e ? qd_routh_lookup(ctx, m, "theta") : NULL;
    qd_orbit *o = theta ? qd_orbit_derive(ctx, m, e, 1, &theta) : NULL;
    qd_status st = qd_ctx_status(ctx);
    if (o) {
        const qd_expr *syms[] = {qd_model_param(m, 0), qd_model_param(m, 1), qd_lookup(ctx, "r"),
                                 qd_jet(ctx, qd_lookup(ctx, "r"), 1),
                                 qd_jet(ctx, qd_lookup(ctx, "theta"), 1)};
        double vals[] = {1.3, 4, 1, 0.4, 1.5};
        qd_orbit_result r;
        st = qd_orbit_solve(ctx, o, 5, syms, vals, NULL, &r);
        if (st == QD_OK) {
            check_answer(&r);
            qd_orbit_result_free(&r);
        }
    }
    qd_orbit_free(o);
    qd_eom_free(e);
    qd_model_free(m);
    return st;
}

static void test_orbit_fault(void **state) {
    (void)state;
    assert_true(qt_fault_loop("Kepler orbit", body, NULL, 1).runs > 10);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_orbit_fault)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
