/*
 * tests/sym/test_rewrite.c - the identities of qd_simplify's second path
 * (src/sym/rewrite.c, issue 33), each compared by node with the expected
 * result read from text (hash-consing: equal means the same node), and each
 * checked to keep its value at a point where the input is defined.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "qdot/qdot.h"

static void expect(qd_ctx *ctx, const char *in, const char *want) {
    const qd_expr *e = qd_read(ctx, in, NULL, NULL);
    const qd_expr *w = qd_read(ctx, want, NULL, NULL);
    assert_non_null(e);
    assert_non_null(w);
    const qd_expr *s = qd_simplify(ctx, e);
    if (s != w) {
        qd_buf b = QD_BUF_INIT;
        qd_print(ctx, s, QD_FMT_TEXT, &b);
        print_error("simplify(%s) = %s, want %s\n", in, b.s ? b.s : "?", want);
        qd_buf_free(&b);
        fail();
    }
    /* the value is kept: Q, a, b, x, y, K, p, q all at 0.3 .. 1.0 */
    const qd_expr *syms[16];
    size_t n = qd_free_symbols(ctx, e, syms, 16);
    double vals[16], v1 = 0, v2 = 0;
    for (size_t i = 0; i < n; i++)
        vals[i] = 0.3 + 0.1 * (double)i;
    assert_int_equal(QD_OK, qd_eval(ctx, e, n, syms, vals, &v1));
    assert_int_equal(QD_OK, qd_eval(ctx, s, n, syms, vals, &v2));
    assert_true(fabs(v1 - v2) <= 1e-12 * (1 + fabs(v1)));
}

static void tan_squared(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    expect(ctx, "1 + tan(x)^2", "1/cos(x)^2");
    expect(ctx, "cos(p)^2*(tan(p)^2 + 1)", "1");
    /* the bracket of Q = log(sin(p)/q), P = q/tan(p) */
    expect(ctx, "(1 + tan(p)^2)/tan(p)^2 - cos(p)/(sin(p)*tan(p))", "1");
    qd_ctx_free(ctx);
}

static void exponentials(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    expect(ctx, "exp(a)*exp(b)", "exp(a + b)");
    expect(ctx, "exp(2*Q) - exp(Q)^2", "0");
    expect(ctx, "exp(a)^3*exp(-a)", "exp(2*a)");
    qd_ctx_free(ctx);
}

static void nested_quotient(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    expect(ctx, "x/(y/x + 1)", "x^2/(x + y)");
    qd_ctx_free(ctx);
}

static void roots(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    expect(ctx, "sqrt(2*Q)*sqrt(1 - K^2*q^2/(2*Q))", "sqrt(2*Q - K^2*q^2)");
    expect(ctx, "K*(2*K^2*q^2 - 4*Q)/(2*sqrt(2*Q - K^2*q^2))", "-K*sqrt(2*Q - K^2*q^2)");
    /* dF/dq of the oscillator's F1 = -(K/2) q sqrt(2Q - K^2 q^2) - Q asin(K q/sqrt(2Q)) */
    const qd_expr *F = qd_read(ctx, "-(K/2)*q*sqrt(2*Q - K^2*q^2) - Q*asin(K*q/sqrt(2*Q))", NULL,
                               NULL);
    const qd_expr *q = qd_symbol(ctx, "q");
    const qd_expr *d = qd_simplify(ctx, qd_diff(ctx, F, q));
    assert_ptr_equal(d, qd_read(ctx, "-K*sqrt(2*Q - K^2*q^2)", NULL, NULL));
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(tan_squared),
        cmocka_unit_test(exponentials),
        cmocka_unit_test(nested_quotient),
        cmocka_unit_test(roots),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
