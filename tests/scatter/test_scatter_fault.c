/*
 * tests/scatter/test_scatter_fault.c - scattering with every allocation
 * made to fail in turn (the habit of tests/fault/test_fault.c, whose
 * failing allocator and loop are tests/util/fault.h): each run must give the
 * right answer or a clean QD_ERR_NOMEM, with every block given back.
 *
 * Body: the refracting sphere V = -3 step(2 - r) at E = 1 (n = 2; Desloge
 * ch. 60 problems, Landau sec. 18 pb. 2): the deflection at b = 1 against
 * Snell's 2 (asin(b/a) - asin(b/(n a))), and dsigma/dOmega at Theta = 1
 * against n^2 a^2 (n c - 1)(n - c)/(4 c (1 + n^2 - 2 n c)^2), c = cos(1/2).
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

static qd_status sphere_body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)f, (void)data;
    const double a = 2, n = 2, c = cos(0.5);
    const qd_expr *V = qd_read(ctx, "-3*step(2 - r)", NULL, NULL);
    qd_scatter *s = qd_scatter_new(ctx, V, qd_symbol(ctx, "r"), 0);
    if (!s)
        return qd_ctx_status(ctx);
    qd_scatter_path p;
    qd_scatter_section x;
    qd_status st = qd_scatter_deflect(ctx, s, 1, 1, &p);
    if (st == QD_OK) {
        assert_true(fabs(-p.chi - 2 * (asin(1 / a) - asin(1 / (n * a)))) < 1e-11);
        st = qd_scatter_section_at(ctx, s, 1, 1, &x);
    }
    if (st == QD_OK) {
        double want = n * n * a * a * (n * c - 1) * (n - c) / (4 * c * pow(1 + n * n - 2 * n * c, 2));
        assert_int_equal(x.nbranch, 1);
        assert_true(fabs(x.sigma - want) < 1e-7 * want);
    }
    qd_scatter_free(s);
    return st;
}

static void test_sphere(void **state) {
    (void)state;
    qt_fault_stats ls = qt_fault_loop("refracting sphere", sphere_body, NULL, 1);
    assert_true(ls.runs > 6); /* more than five refused, then the run that got through */
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sphere),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
