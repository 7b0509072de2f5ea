/*
 * tests/cli/test_lqr_cli.c - the reader of the --lqr weights
 * (cli/lqr_cli.c, compiled into this test by tests/CMakeLists.txt): each
 * form of Q and R, the errors with their place, and the double integrator's
 * weights read from text giving K = [1, sqrt 3] (tests/linear/test_care.c
 * derives it).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/control.h"
#include "lqr_cli.h"

static void forms(void **state) {
    (void)state;
    double Q[16], R[4];
    char err[200];
    size_t where;
    assert_true(cli_lqr_parse("Q = diag(1, 1, 10, 1), R = 0.1", 4, 1, Q, R, err, sizeof err,
                              &where));
    const double Qd[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 10, 0, 0, 0, 0, 1};
    assert_memory_equal(Q, Qd, sizeof Qd);
    assert_true(R[0] == 0.1);
    /* either order, a scalar Q, a full R, exponents and signs */
    assert_true(cli_lqr_parse(" R=[[2, -5e-1],[ -0.5 ,1]] ,Q=3 ", 2, 2, Q, R, err, sizeof err,
                              &where));
    const double Qs[4] = {3, 0, 0, 3}, Rf[4] = {2, -0.5, -0.5, 1};
    assert_memory_equal(Q, Qs, sizeof Qs);
    assert_memory_equal(R, Rf, sizeof Rf);
}

static void weights_to_gain(void **state) {
    (void)state;
    const double A[] = {0, 1, 0, 0}, B[] = {0, 1};
    double Q[4], R[1];
    char err[200];
    size_t where;
    assert_true(cli_lqr_parse("Q = [[1, 0], [0, 1]], R = 1", 2, 1, Q, R, err, sizeof err, &where));
    qd_ctx *ctx = qd_ctx_new();
    qd_care_result res;
    assert_int_equal(qd_care_solve(ctx, 2, 1, A, B, Q, R, &res), QD_OK);
    assert_true(fabs(res.K[0] - 1) < 1e-14 && fabs(res.K[1] - sqrt(3.0)) < 1e-14);
    qd_care_result_free(&res);
    qd_ctx_free(ctx);
}

static void expect_error(const char *text, size_t n, size_t m, const char *message, size_t at) {
    double Q[16], R[16];
    char err[200];
    size_t where = 999;
    assert_false(cli_lqr_parse(text, n, m, Q, R, err, sizeof err, &where));
    if (strcmp(err, message) || where != at)
        fail_msg("'%s': got '%s' at %zu, wanted '%s' at %zu", text, err, where, message, at);
}

static void errors(void **state) {
    (void)state;
    expect_error("Q = diag(1, 1, 10), R = 0.1", 4, 1, "diag(...) of Q has 3 entries; Q is 4 by 4",
                 18);
    expect_error("Q = diag(1, 2, 3, 4, 5), R = 1", 4, 1, "the diagonal has more than 4 entries", 22);
    expect_error("Q = I, R = 1", 2, 1, "a number, diag(...) or [[...], ...] expected for Q", 4);
    expect_error("Q = diag(1, 1)", 2, 1, "R is missing (give both: \"Q = diag(...), R = ...\")", 14);
    expect_error("R = 1", 2, 1, "Q is missing (give both: \"Q = diag(...), R = ...\")", 5);
    expect_error("Q = 1, R = 1, Q = 2", 2, 1, "Q is given twice", 14);
    expect_error("Q = 1, R = [[1, 2], [3]]", 2, 2, "row 2 of R has 1 entries; R is 2 by 2", 23);
    expect_error("Q = 1, R = [[1, 2]]", 2, 2, "R has 1 rows; it is 2 by 2", 19);
    expect_error("Q = 1, R = 1 x", 2, 1, "',' or the end expected", 13);
    expect_error("Q = diag(1, nan), R = 1", 2, 1, "a number expected", 12);
    expect_error("Q = 1e999, R = 1", 2, 1, "a finite number expected", 4);
    expect_error("Qx = 1", 2, 1, "Q or R expected", 0);
    expect_error("Q 1, R = 1", 2, 1, "'=' expected after Q", 2);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(forms),
        cmocka_unit_test(weights_to_gain),
        cmocka_unit_test(errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
