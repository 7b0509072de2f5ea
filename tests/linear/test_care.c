/*
 * tests/linear/test_care.c - the Riccati equation and the LQR gain
 * (qdot/control.h) against closed forms, its own residual and its
 * failures.
 *
 *   scalar x' = a x + b u: a x*2 - x^2 b^2 / r + q = 0, whose stabilizing
 *     root is x = (a + sqrt(a^2 + b^2 q / r)) r / b^2, with the closed loop
 *     s = a - b K = -sqrt(a^2 + b^2 q / r);
 *   the double integrator x'' = u, Q = I, R = 1: X = [sqrt 3, 1; 1, sqrt 3],
 *     K = [1, sqrt 3], closed loop s^2 + sqrt 3 s + 1 = 0 (Anderson & Moore,
 *     "Optimal Control: Linear Quadratic Methods", the double-integrator
 *     example; checked by hand: the (1,1), (1,2), (2,2) entries of the
 *     equation give x12^2 = 1, x11 = x12 x22, 2 x12 - x22^2 + 1 = 0);
 *   an uncontrollable but stable mode decoupled from a controllable one:
 *     X = diag(q / 2|a1|, scalar root), nothing across;
 *   random stabilizable systems, n = 1..8, m = 1..3: the residual, computed
 *     here rather than trusted from the library, below 1e-10 relative, X
 *     symmetric positive semidefinite, every closed-loop Re s < 0;
 *   no stabilizing solution: an unstable (and a marginal, s = 0) mode B does
 *     not reach, one it barely reaches (U11 ill-conditioned), the double integrator with Q = 0 (s = 0 unseen), R not
 *     positive definite, Q indefinite: each named in out->failure and the
 *     message;
 *   every allocation refused in turn (tests/util/fault.h).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/control.h"
#include "util/fault.h"

static void scalar_closed_form(void **state) {
    (void)state;
    const double cases[][4] = {{1, 1, 1, 1}, {-2, 0.5, 3, 0.1}, {0, 2, 1, 4}, {5, -1, 0.01, 2}};
    qd_ctx *ctx = qd_ctx_new();
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        double a = cases[c][0], b = cases[c][1], q = cases[c][2], r = cases[c][3];
        double root = sqrt(a * a + b * b * q / r), x = (a + root) * r / (b * b);
        qd_care_result res;
        assert_int_equal(qd_care_solve(ctx, 1, 1, &a, &b, &q, &r, &res), QD_OK);
        assert_true(fabs(res.X[0] - x) <= 1e-13 * fabs(x));
        assert_true(fabs(res.K[0] - b * x / r) <= 1e-13 * fabs(b * x / r));
        assert_true(fabs(res.eig_re[0] + root) <= 1e-13 * root);
        assert_true(res.eig_im[0] == 0);
        assert_int_equal(res.failure, QD_CARE_OK);
        qd_care_result_free(&res);
    }
    qd_ctx_free(ctx);
}

static qd_status double_integrator(qd_ctx *ctx) {
    const double A[] = {0, 1, 0, 0}, B[] = {0, 1}, Q[] = {1, 0, 0, 1}, R[] = {1};
    const double s3 = sqrt(3.0);
    qd_care_result res;
    qd_status st = qd_care_solve(ctx, 2, 1, A, B, Q, R, &res);
    if (st != QD_OK)
        return st;
    const double X[] = {s3, 1, 1, s3};
    for (int k = 0; k < 4; k++)
        assert_true(fabs(res.X[k] - X[k]) <= 1e-14 * 2);
    assert_true(fabs(res.K[0] - 1) <= 1e-14 && fabs(res.K[1] - s3) <= 1e-14);
    for (int k = 0; k < 2; k++)
        assert_true(fabs(res.eig_re[k] + s3 / 2) <= 1e-14);
    assert_true(fabs(res.eig_im[0] - 0.5) <= 1e-14 && fabs(res.eig_im[1] + 0.5) <= 1e-14);
    assert_true(res.residual < 1e-14);
    assert_true(res.rcond > 0.1);
    qd_care_result_free(&res);
    return QD_OK;
}

static void double_integrator_gain(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    assert_int_equal(double_integrator(ctx), QD_OK);
    qd_ctx_free(ctx);
}

/* x1' = -2 x1 (no input reaches it), x2' = x2 + u: X = diag(1/4, 1 + sqrt 2). */
static void stable_uncontrollable_mode(void **state) {
    (void)state;
    const double A[] = {-2, 0, 0, 1}, B[] = {0, 1}, Q[] = {1, 0, 0, 1}, R[] = {1};
    qd_ctx *ctx = qd_ctx_new();
    qd_care_result res;
    assert_int_equal(qd_care_solve(ctx, 2, 1, A, B, Q, R, &res), QD_OK);
    assert_true(fabs(res.X[0] - 0.25) <= 1e-14);
    assert_true(fabs(res.X[1]) <= 1e-14 && fabs(res.X[2]) <= 1e-14);
    assert_true(fabs(res.X[3] - (1 + sqrt(2.0))) <= 1e-14 * 3);
    assert_true(fabs(res.eig_re[0] + sqrt(2.0)) <= 1e-14 * 2 && fabs(res.eig_re[1] + 2) <= 1e-14);
    qd_care_result_free(&res);
    qd_ctx_free(ctx);
}

/* A deterministic generator (xorshift64*), normal-ish by summing twelve. */
static uint64_t rng_state = 88172645463325252u;
static double uniform(void) {
    rng_state ^= rng_state >> 12, rng_state ^= rng_state << 25, rng_state ^= rng_state >> 27;
    return (double)((rng_state * 2685821657736338717u) >> 11) / 9007199254740992.0;
}
static double gauss(void) {
    double s = -6;
    for (int k = 0; k < 12; k++)
        s += uniform();
    return s;
}

/* M^T M (+ shift I): symmetric positive semidefinite (definite if shift > 0). */
static void gram(size_t rows, size_t n, const double *M, double shift, double *out) {
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++) {
            double s = i == j ? shift : 0;
            for (size_t k = 0; k < rows; k++)
                s += M[k * n + i] * M[k * n + j];
            out[i * n + j] = s;
        }
}

/* ||A^T X + X A - X B R^-1 B^T X + Q||_F over the size of its terms, with
 * R^-1 B^T X = K, so X B K is the quadratic term: the test's own residual. */
static double own_residual(size_t n, size_t m, const double *A, const double *B,
                           const double *Q, const double *X, const double *K) {
    double num = 0, den = 0;
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++) {
            double lin = 0, quad = 0;
            for (size_t k = 0; k < n; k++)
                lin += A[k * n + i] * X[k * n + j] + X[i * n + k] * A[k * n + j];
            for (size_t k = 0; k < n; k++)
                for (size_t l = 0; l < m; l++)
                    quad += X[i * n + k] * B[k * m + l] * K[l * n + j];
            double r = lin - quad + Q[i * n + j];
            num += r * r;
            den += lin * lin + quad * quad + Q[i * n + j] * Q[i * n + j];
        }
    return sqrt(num / den);
}

static void random_systems(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    double A[64], B[24], C[64], Q[64], D[9], R[9], worst = 0;
    for (int trial = 0; trial < 200; trial++) {
        size_t n = 1 + (size_t)trial % 8, m = 1 + (size_t)(trial / 8) % 3, p = 1 + (size_t)trial % 5;
        for (size_t k = 0; k < n * n; k++)
            A[k] = gauss();
        for (size_t k = 0; k < n * m; k++)
            B[k] = gauss();
        for (size_t k = 0; k < p * n; k++)
            C[k] = gauss();
        for (size_t k = 0; k < m * m; k++)
            D[k] = gauss();
        gram(p, n, C, trial % 2 ? 0 : 1e-3, Q); /* odd trials: Q singular if p < n */
        gram(m, m, D, 0.5, R);
        qd_care_result res;
        qd_status st = qd_care_solve(ctx, n, m, A, B, Q, R, &res);
        if (st != QD_OK)
            fail_msg("trial %d (n %zu, m %zu): %s", trial, n, m, qd_ctx_message(ctx));
        double r = own_residual(n, m, A, B, Q, res.X, res.K);
        worst = fmax(worst, r);
        if (!(r < 1e-10))
            fail_msg("trial %d (n %zu, m %zu): residual %.3g (library %.3g, rcond %.3g)", trial,
                     n, m, r, res.residual, res.rcond);
        assert_true(res.residual < 1e-10);
        for (size_t k = 0; k < n; k++)
            assert_true(res.eig_re[k] < 0);
        double big = 0;
        for (size_t k = 0; k < n * n; k++)
            big = fmax(big, fabs(res.X[k]));
        for (size_t i = 0; i < n; i++) {
            assert_true(res.X[i * n + i] >= -1e-12 * big); /* X >= 0 has no negative diagonal */
            for (size_t j = 0; j < n; j++)
                assert_true(res.X[i * n + j] == res.X[j * n + i]);
        }
        qd_care_result_free(&res);
    }
    printf("random systems: worst relative residual %.3g\n", worst);
    qd_ctx_free(ctx);
}

static void expect_failure(size_t n, size_t m, const double *A, const double *B, const double *Q,
                           const double *R, qd_care_failure why, const char *words) {
    qd_ctx *ctx = qd_ctx_new();
    qd_care_result res;
    assert_int_equal(qd_care_solve(ctx, n, m, A, B, Q, R, &res), QD_ERR_ARG);
    assert_int_equal(res.failure, why);
    assert_null(res.X);
    if (!strstr(qd_ctx_message(ctx), words))
        fail_msg("'%s' lacks '%s'", qd_ctx_message(ctx), words);
    qd_ctx_free(ctx);
}

static void not_stabilizable(void **state) {
    (void)state;
    const double I2[] = {1, 0, 0, 1}, one[] = {1}, B[] = {0, 1};
    const double unstable[] = {1, 0, 0, -1}, free_mass[] = {0, 0, 0, -1};
    expect_failure(2, 1, unstable, B, I2, one, QD_CARE_NOT_STABILIZABLE,
                   "(A, B) is not stabilizable: the mode s = 1 of A");
    expect_failure(2, 1, free_mass, B, I2, one, QD_CARE_NOT_STABILIZABLE, "the mode s = 0 of A");
    /* an unstable oscillation s = 0.5 +- 2i in states 1-2, the input on 3 only */
    const double A3[] = {0.5, 2, 0, -2, 0.5, 0, 0, 0, -1}, B3[] = {0, 0, 1};
    const double I3[] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    qd_ctx *ctx = qd_ctx_new();
    qd_care_result res;
    assert_int_equal(qd_care_solve(ctx, 3, 1, A3, B3, I3, one, &res), QD_ERR_ARG);
    assert_int_equal(res.failure, QD_CARE_NOT_STABILIZABLE);
    assert_true(fabs(res.mode_re - 0.5) < 1e-12 && fabs(fabs(res.mode_im) - 2) < 1e-12);
    assert_non_null(strstr(qd_ctx_message(ctx), "s = 0.5 +- 2i"));
    qd_ctx_free(ctx);
}

/* B = [1e-7; 1] barely reaches the unstable s = 1, so X11 ~ 2 / b1^2 = 2e14
 * (the scalar closed form): U11 is singular to working precision, and the
 * solver says so instead of returning digits it does not have. */
static void nearly_unstabilizable(void **state) {
    (void)state;
    const double A[] = {1, 0, 0, -1}, B[] = {1e-7, 1}, I2[] = {1, 0, 0, 1}, R[] = {1};
    qd_ctx *ctx = qd_ctx_new();
    qd_care_result res;
    assert_int_equal(qd_care_solve(ctx, 2, 1, A, B, I2, R, &res), QD_ERR_NUMERIC);
    assert_int_equal(res.failure, QD_CARE_ILL_CONDITIONED);
    assert_non_null(strstr(qd_ctx_message(ctx), "U11 of the stable Schur vectors is ill-conditioned"));
    qd_ctx_free(ctx);
}

static void not_detectable(void **state) {
    (void)state;
    const double A[] = {0, 1, 0, 0}, B[] = {0, 1}, Q0[] = {0, 0, 0, 0}, R[] = {1};
    expect_failure(2, 1, A, B, Q0, R, QD_CARE_NOT_DETECTABLE,
                   "(Q, A) is not detectable: the mode s = 0 of A");
}

static void bad_weights(void **state) {
    (void)state;
    const double A[] = {0, 1, 0, 0}, B[] = {0, 1, 1, 0}, I2[] = {1, 0, 0, 1};
    const double R_indef[] = {1, 2, 2, 1}, R_neg[] = {-1}, R_asym[] = {1, 0.5, 0, 1};
    const double Q_indef[] = {1, 0, 0, -1}, B1[] = {0, 1};
    expect_failure(2, 2, A, B, I2, R_indef, QD_CARE_R_NOT_PD,
                   "R is not positive definite (its leading minor of order 2");
    expect_failure(2, 1, A, B1, I2, R_neg, QD_CARE_R_NOT_PD, "R is not positive definite");
    expect_failure(2, 2, A, B, I2, R_asym, QD_CARE_R_NOT_PD, "R is not symmetric");
    expect_failure(2, 1, A, B1, Q_indef, (const double[]){1}, QD_CARE_Q_NOT_PSD,
                   "Q is not positive semidefinite (it has the eigenvalue -1)");
    const double nan_q[] = {NAN, 0, 0, 1};
    expect_failure(2, 1, A, B1, nan_q, (const double[]){1}, QD_CARE_OK, "finite");
}

static qd_status fault_body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)f, (void)data;
    return double_integrator(ctx);
}

static void allocation_failures(void **state) {
    (void)state;
    assert_true(qt_fault_loop("care", fault_body, NULL, 1).allocs > 10);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(scalar_closed_form),
        cmocka_unit_test(double_integrator_gain),
        cmocka_unit_test(stable_uncontrollable_mode),
        cmocka_unit_test(random_systems),
        cmocka_unit_test(not_stabilizable),
        cmocka_unit_test(nearly_unstabilizable),
        cmocka_unit_test(not_detectable),
        cmocka_unit_test(bad_weights),
        cmocka_unit_test(allocation_failures),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
