/*
 * tests/linear/test_lqr.c - LQR from text and on a model (qdot/control.h):
 *
 *   - the weights reader qd_lqr_weights_read: each form of Q and R, the
 *     errors located at their place; the matrix reader qd_matrix_read; the
 *     double integrator's weights read from text giving K = [1, sqrt 3]
 *     (tests/linear/test_care.c derives it), K read back from the C printer;
 *   - qd_lqr_design on the pendulum m l^2 th'' = -m g l sin th + tau held
 *     upright (th = pi): x'' = a x + b u with a = g/l, b = 1/(m l^2), whose
 *     Riccati equation with Q = diag(q1, q2), R = r solves by hand:
 *         p2 = r (a + sqrt(a^2 + b^2 q1/r)) / b^2,  p3 = sqrt(r (2 p2 + q2)) / b,
 *         K = (b/r) [p2, p3];
 *     its feedback u = u0 - K (x - x0) (qd_lqr_feedback) evaluated off the
 *     point, and exact at it; a model with no inputs refused.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif
#include <stdlib.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/control.h"

static void forms(void **state) {
    (void)state;
    double Q[16], R[4];
    qd_ctx *ctx = qd_ctx_new();
    assert_int_equal(qd_lqr_weights_read(ctx, "Q = diag(1, 1, 10, 1), R = 0.1", 4, 1, Q, R),
                     QD_OK);
    const double Qd[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 10, 0, 0, 0, 0, 1};
    assert_memory_equal(Q, Qd, sizeof Qd);
    assert_true(R[0] == 0.1);
    /* either order, a scalar Q, a full R, exponents and signs */
    assert_int_equal(qd_lqr_weights_read(ctx, " R=[[2, -5e-1],[ -0.5 ,1]] ,Q=3 ", 2, 2, Q, R),
                     QD_OK);
    const double Qs[4] = {3, 0, 0, 3}, Rf[4] = {2, -0.5, -0.5, 1};
    assert_memory_equal(Q, Qs, sizeof Qs);
    assert_memory_equal(R, Rf, sizeof Rf);
    qd_ctx_free(ctx);
}

static void weights_to_gain(void **state) {
    (void)state;
    const double A[] = {0, 1, 0, 0}, B[] = {0, 1};
    double Q[4], R[1];
    qd_ctx *ctx = qd_ctx_new();
    assert_int_equal(qd_lqr_weights_read(ctx, "Q = [[1, 0], [0, 1]], R = 1", 2, 1, Q, R), QD_OK);
    qd_care_result res;
    assert_int_equal(qd_care_solve(ctx, 2, 1, A, B, Q, R, &res), QD_OK);
    assert_true(fabs(res.K[0] - 1) < 1e-14 && fabs(res.K[1] - sqrt(3.0)) < 1e-14);
    /* the C printer writes every digit: K reads back to the same doubles */
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_lqr_print(NULL, &res, QD_LQR_C, &b), QD_OK);
    const char *row = strstr(qd_buf_str(&b), "{") ? strstr(strstr(qd_buf_str(&b), "= {") + 3, "{")
                                                  : NULL;
    assert_non_null(row);
    char *end;
    double k1 = strtod(row + 1, &end);
    double k2 = strtod(end + 1, NULL);
    assert_true(k1 == res.K[0] && k2 == res.K[1]);
    qd_buf_free(&b);
    /* a number that is not finite: refused, nothing written */
    res.K[1] = NAN;
    assert_int_equal(qd_lqr_print(NULL, &res, QD_LQR_TEXT, &b), QD_ERR_NUMERIC);
    assert_int_equal(b.len, 0);
    qd_care_result_free(&res);
    qd_ctx_free(ctx);
}

static void expect_error(const char *text, size_t n, size_t m, const char *message, size_t at) {
    double Q[16], R[16];
    qd_ctx *ctx = qd_ctx_new();
    assert_int_equal(qd_lqr_weights_read(ctx, text, n, m, Q, R), QD_ERR_PARSE);
    const qd_diag *d = qd_ctx_diag(ctx);
    if (strcmp(d->message, message) || !d->located || d->offset != at || d->col != at + 1)
        fail_msg("'%s': got '%s' at %zu, wanted '%s' at %zu", text, d->message, d->offset,
                 message, at);
    qd_ctx_free(ctx);
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
    qd_ctx *ctx = qd_ctx_new();
    qd_matrix M;
    assert_int_equal(qd_matrix_read(ctx, " [[0], [1.5], [-2e3]] ", &M), QD_OK);
    assert_int_equal(M.rows, 3);
    assert_int_equal(M.cols, 1);
    assert_true(M.a[0] == 0 && M.a[1] == 1.5 && M.a[2] == -2000);
    qd_matrix_free(&M);
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
        M.a = (double *)&M; /* must come back NULL */
        qd_ctx_clear_error(ctx);
        assert_int_equal(qd_matrix_read(ctx, bad[k].text, &M), QD_ERR_PARSE);
        assert_null(M.a);
        const qd_diag *d = qd_ctx_diag(ctx);
        if (strcmp(d->message, bad[k].message) || d->offset != bad[k].at)
            fail_msg("'%s': got '%s' at %zu", bad[k].text, d->message, d->offset);
    }
    qd_ctx_free(ctx);
}

#define PENDULUM                                                                               \
    "coordinates th\nparameters m = 2, l = 1.5, g = 9.81\ninputs tau\n"                        \
    "T = m*l^2*th'^2/2\nV = -m*g*l*cos(th)\nQ[th] = tau\n"

static const qd_expr *sym(qd_ctx *ctx, const char *text) {
    const qd_read_opts ro = {.new_symbols = false};
    const qd_expr *x = qd_read(ctx, text, &ro, NULL);
    assert_non_null(x);
    return x;
}

/* The pendulum upright under LQR: K by hand, the feedback off and at the point. */
static void design_on_model(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qd_model_parse(ctx, PENDULUM, NULL);
    assert_non_null(m);
    qd_eom *e = qd_eom_derive(ctx, m);
    assert_non_null(e);
    const qd_expr *syms[2] = {sym(ctx, "th"), sym(ctx, "tau")};
    const qd_expr *vals[2] = {sym(ctx, "pi"), sym(ctx, "3/2")};
    qd_statespace s;
    assert_int_equal(qd_linearize(ctx, e, m, 2, syms, vals, &s), QD_OK);
    qd_care_result r;
    assert_int_equal(qd_lqr_design(ctx, &s, "Q = diag(2, 0.5), R = 0.25", &r), QD_OK);
    double g = 9.81, l = 1.5, mm = 2, a = g / l, b = 1 / (mm * l * l), q1 = 2, q2 = 0.5, rr = 0.25;
    double p2 = rr * (a + sqrt(a * a + b * b * q1 / rr)) / (b * b);
    double p3 = sqrt(rr * (2 * p2 + q2)) / b;
    double k1 = b * p2 / rr, k2 = b * p3 / rr;
    assert_true(fabs(r.K[0] - k1) < 1e-10 * k1 && fabs(r.K[1] - k2) < 1e-10 * k2);
    const qd_expr *u = qd_lqr_feedback(ctx, &s, &r, 2, syms, vals, 0);
    assert_non_null(u);
    /* u = 3/2 - k1 (th - pi) - k2 th' at th = pi + 0.1, th' = -0.2 */
    const qd_expr *at[2] = {s.states[0], s.states[1]};
    double x[2] = {M_PI + 0.1, -0.2}, v = 0;
    assert_int_equal(qd_eval(ctx, u, 2, at, x, &v), QD_OK);
    assert_true(fabs(v - (1.5 - 0.1 * k1 + 0.2 * k2)) < 1e-12 * k1);
    /* at the point itself the input is u0 (the point's pi is kept exact) */
    const qd_expr *to[2] = {vals[0], qd_int(ctx, 0)};
    assert_int_equal(qd_eval(ctx, qd_subs(ctx, u, 2, at, to), 0, NULL, NULL, &v), QD_OK);
    assert_true(v == 1.5);
    /* out of range: refused */
    assert_null(qd_lqr_feedback(ctx, &s, &r, 2, syms, vals, 1));
    assert_int_equal(qd_ctx_status(ctx), QD_ERR_ARG);
    qd_care_result_free(&r);
    qd_statespace_free(&s);
    qd_eom_free(e);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* No inputs: nothing to feed back, said with the field's name. */
static void no_inputs(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qd_model_parse(ctx, "coordinates x\nparameters k = 1\nT = x'^2/2\n"
                                      "V = k*x^2/2\n", NULL);
    qd_eom *e = qd_eom_derive(ctx, m);
    qd_statespace s;
    assert_int_equal(qd_linearize(ctx, e, m, 0, NULL, NULL, &s), QD_OK);
    qd_care_result r;
    assert_int_equal(qd_lqr_design(ctx, &s, "Q = 1, R = 1", &r), QD_ERR_ARG);
    assert_string_equal(qd_ctx_diag(ctx)->name, "lqr");
    assert_non_null(strstr(qd_ctx_message(ctx), "no inputs"));
    qd_statespace_free(&s);
    qd_eom_free(e);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(forms),
        cmocka_unit_test(weights_to_gain),
        cmocka_unit_test(errors),
        cmocka_unit_test(matrices),
        cmocka_unit_test(design_on_model),
        cmocka_unit_test(no_inputs),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
