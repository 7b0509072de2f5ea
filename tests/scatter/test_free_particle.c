/*
 * tests/scatter/test_free_particle.c - V = 0 and no core (issue 30): a free
 * particle is not deflected, chi(b) = 0 for every b, so no impact parameter
 * reaches any angle theta in (0, pi): dsigma/dOmega = 0 there and the total
 * cross section pi range^2 is 0.  The section's grid was sized by 0/0 and
 * overflowed the heap (piece_points); under ASan that failed here.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>
#include "qdot/qdot.h"

static const double PI = 3.14159265358979323846;

static qd_scatter *free_particle(qd_ctx *ctx) {
    qd_scatter *s = qd_scatter_new(ctx, qd_int(ctx, 0), qd_symbol(ctx, "r"), 0);
    assert_non_null(s);
    assert_true(qd_scatter_range(s) == 0);
    return s;
}

static void no_deflection(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_scatter *s = free_particle(ctx);
    for (double b = 0.25; b < 10; b *= 2) {
        qd_scatter_path p;
        assert_int_equal(QD_OK, qd_scatter_deflect(ctx, s, 1.0, b, &p));
        assert_int_equal(QD_SCATTER_DEFLECTED, p.kind);
        assert_true(fabs(p.chi) < 1e-12);
        assert_true(fabs(p.r0 - b) < 1e-12 * b);  /* closest approach: b itself */
    }
    qd_scatter_free(s);
    qd_ctx_free(ctx);
}

static void section_is_zero(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_scatter *s = free_particle(ctx);
    const double thetas[] = {1e-3, PI / 3, PI / 2, PI - 1e-3};
    for (size_t i = 0; i < sizeof thetas / sizeof thetas[0]; i++) {
        qd_scatter_section sec;
        assert_int_equal(QD_OK, qd_scatter_section_at(ctx, s, 1.0, thetas[i], &sec));
        assert_int_equal(0, sec.nbranch);
        assert_true(sec.sigma == 0);
    }
    qd_scatter_features f;
    assert_int_equal(QD_OK, qd_scatter_features_at(ctx, s, 2.0, &f));
    assert_true(f.total == 0);
    assert_int_equal(0, f.nrainbow);
    assert_int_equal(0, f.nglory);
    assert_false(f.orbiting);
    qd_scatter_free(s);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(no_deflection),
        cmocka_unit_test(section_is_zero),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
