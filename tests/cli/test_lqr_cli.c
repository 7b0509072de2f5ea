/*
 * tests/cli/test_lqr_cli.c - the reader of the --lqr weights
 * (cli/lqr_cli.c, compiled into this test by tests/CMakeLists.txt): each
 * form of Q and R, the errors with their place, the matrix reader of
 * `qdot lqr`, and the double integrator's
 * weights read from text giving K = [1, sqrt 3] (tests/linear/test_care.c
 * derives it).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
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
    expect_error("Q = diag(1, 2, 3, 4, 5), R = 1", 4, 1, "the diagonal has more than 4 entries", 21);
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

/* The matrix reader of `qdot lqr`: any shape, rows of equal length. */
static void matrices(void **state) {
    (void)state;
    char err[200];
    size_t rows, cols, where;
    double *M;
    assert_true(cli_matrix_parse(" [[0], [1.5], [-2e3]] ", &rows, &cols, &M, err, sizeof err,
                                 &where));
    assert_int_equal(rows, 3);
    assert_int_equal(cols, 1);
    assert_true(M[0] == 0 && M[1] == 1.5 && M[2] == -2000);
    free(M);
    static const struct {
        const char *text, *message;
        size_t at;
    } bad[] = {
        {"[[1, 2], [3]]", "row 2 has 1 entries, row 1 has 2", 12},
        {"[]", "'[' expected to open a row", 1},
        {"[[1, 2], [3, 4]", "']' expected to close the matrix", 15},
        {"1", "'[' expected to open the matrix, as in [[1, 0], [0, 1]]", 0},
        {"[[1, 2]] [[3]]", "the end expected after the matrix", 9},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        M = (double *)&rows; /* must come back NULL */
        assert_false(cli_matrix_parse(bad[k].text, &rows, &cols, &M, err, sizeof err, &where));
        assert_null(M);
        if (strcmp(err, bad[k].message) || where != bad[k].at)
            fail_msg("'%s': got '%s' at %zu", bad[k].text, err, where);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(forms),
        cmocka_unit_test(weights_to_gain),
        cmocka_unit_test(errors),
        cmocka_unit_test(matrices),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
