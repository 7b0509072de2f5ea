/*
 * tests/cross/gen_care.c - the Riccati solver on systems read from stdin,
 * for the SciPy cross-check (tests/cross/check_care_scipy.py).
 *
 * Input, whitespace-separated, repeated to the end: n m, then A (n*n),
 * B (n*m), Q (n*n), R (m*m), each row-major.  Output, one line per system:
 *   ok <residual> <X, n*n> <K, m*n> <closed-loop Re s, n>
 *   error <failure code> <message>
 * Usage: gen_care < systems.txt
 */
#include <stdio.h>
#include <stdlib.h>

#include "qdot/qdot.h"
#include "qdot/control.h"

static bool read_array(size_t len, double *a) {
    for (size_t k = 0; k < len; k++)
        if (scanf("%lf", &a[k]) != 1)
            return false;
    return true;
}

static void print_array(size_t len, const double *a) {
    for (size_t k = 0; k < len; k++)
        printf(" %.17g", a[k]);
}

static int one_system(qd_ctx *ctx, size_t n, size_t m) {
    double *A = malloc(n * n * sizeof *A), *B = malloc(n * m * sizeof *B);
    double *Q = malloc(n * n * sizeof *Q), *R = malloc(m * m * sizeof *R);
    int rc = 1;
    if (A && B && Q && R && read_array(n * n, A) && read_array(n * m, B) &&
        read_array(n * n, Q) && read_array(m * m, R)) {
        qd_care_result res;
        qd_ctx_clear_error(ctx);
        if (qd_care_solve(ctx, n, m, A, B, Q, R, &res) == QD_OK) {
            printf("ok %.17g", res.residual);
            print_array(n * n, res.X);
            print_array(m * n, res.K);
            print_array(n, res.eig_re);
            printf("\n");
            qd_care_result_free(&res);
        } else {
            printf("error %d %s\n", (int)res.failure, qd_ctx_message(ctx));
        }
        rc = 0;
    }
    free(A), free(B), free(Q), free(R);
    return rc;
}

int main(void) {
    qd_ctx *ctx = qd_ctx_new();
    size_t n, m;
    int rc = ctx ? 0 : 1;
    while (rc == 0 && scanf("%zu %zu", &n, &m) == 2)
        rc = n && m && n <= 64 && m <= 64 ? one_system(ctx, n, m) : 1;
    qd_ctx_free(ctx);
    return rc;
}
