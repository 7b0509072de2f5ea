/*
 * tests/linear/test_lqr_system.c - a state-space system and its weights
 * read from text (qd_lqr_system_read, qdot/control.h), as `qdot lqr` takes
 * them: the double integrator x'' = u with Q = I, R = 1, whose Riccati
 * equation solves by hand to X = [sqrt 3, 1; 1, sqrt 3] and K = [1, sqrt 3]
 * (closed loop s^2 + sqrt 3 s + 1: both roots -sqrt 3/2 +- i/2); each error
 * named by the text it is about.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "qdot/qdot.h"

static void test_double_integrator(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_lqr_system s;
    assert_int_equal(qd_lqr_system_read(ctx, "[[0, 1], [0, 0]]", "[[0], [1]]", "Q = 1, R = 1",
                                        &s), QD_OK);
    qd_care_result r;
    assert_int_equal(qd_care_solve(ctx, s.A.rows, s.B.cols, s.A.a, s.B.a, s.Q, s.R, &r), QD_OK);
    const double r3 = sqrt(3.0);
    assert_true(fabs(r.K[0] - 1) < 1e-12 && fabs(r.K[1] - r3) < 1e-12);
    assert_true(fabs(r.X[0] - r3) < 1e-12 && fabs(r.X[1] - 1) < 1e-12 && fabs(r.X[3] - r3) < 1e-12);
    for (size_t k = 0; k < 2; k++)
        assert_true(fabs(r.eig_re[k] + r3 / 2) < 1e-12 && fabs(fabs(r.eig_im[k]) - 0.5) < 1e-12);
    qd_care_result_free(&r);
    qd_lqr_system_free(&s);
    qd_ctx_free(ctx);
}

static void expect_error(const char *A, const char *B, const char *w, qd_status st,
                         const char *field, bool located) {
    qd_ctx *ctx = qd_ctx_new();
    qd_lqr_system s;
    assert_int_equal(qd_lqr_system_read(ctx, A, B, w, &s), st);
    assert_string_equal(qd_ctx_diag(ctx)->name, field);
    assert_int_equal(qd_ctx_diag(ctx)->located, located);
    qd_lqr_system_free(&s);
    qd_ctx_free(ctx);
}

static void test_errors(void **state) {
    (void)state;
    expect_error("[[0, 1]]", "[[0]]", "Q = 1, R = 1", QD_ERR_ARG, "A", false);
    expect_error("[[0, 1], [0, 0]", "[[0], [1]]", "Q = 1, R = 1", QD_ERR_PARSE, "A", true);
    expect_error("[[0, 1], [0, 0]]", "[[0]]", "Q = 1, R = 1", QD_ERR_ARG, "B", false);
    expect_error("[[0, 1], [0, 0]]", "[[0], [1]]", "Q = 1, R = x", QD_ERR_PARSE, "weights", true);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_double_integrator),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
