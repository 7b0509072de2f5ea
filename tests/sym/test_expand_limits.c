/*
 * tests/sym/test_expand_limits.c - expansions beyond the limits (issue 30):
 * an exponent above the expander's 2^24 stays a power instead of recursing
 * until the stack overflows, a power of a sum whose expansion would exceed
 * QD_EXPAND_MAX_BYTES (64 MiB) stays a power, and a product that large is
 * refused with QD_ERR_TOOBIG ("expression too large") before GMP or FLINT
 * is asked for the memory.  qd_expand_kept names the power left, so that
 * `qdot expand` says so (issue 33: "(x + y)^100000" came back as it was,
 * exit 0, as if it were the expansion).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "qdot/qdot.h"

static const qd_expr *rd(qd_ctx *ctx, const char *text) {
    const qd_expr *e = qd_read(ctx, text, NULL, NULL);
    assert_non_null(e);
    return e;
}

/* (x+1)^16777217 is past MAX_EXPAND_EXP: it stays as it is, and a power of
 * it folds with the constructors' rules only. */
static void test_exponent_beyond_limit(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *e = rd(ctx, "(x+1)^16777217");
    assert_ptr_equal(qd_expand(ctx, e), e);
    const qd_expr *p = rd(ctx, "(x+1)^16777217*(x+1)^3 + x");
    assert_ptr_equal(qd_expand(ctx, p), rd(ctx, "(x+1)^16777220 + x"));
    const qd_expr *s = rd(ctx, "((x+1)^16777217)^2*y");
    assert_ptr_equal(qd_expand(ctx, s), rd(ctx, "(x+1)^33554434*y"));
    assert_int_equal(qd_ctx_status(ctx), QD_OK);
    qd_ctx_free(ctx);
}

/* (x+1)^30000 would take 30001 coefficients of up to 30000 bits, over the
 * budget: kept; times y + 1 it distributes over the kept power. */
static void test_large_power_kept(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *e = rd(ctx, "(x+1)^30000");
    assert_ptr_equal(qd_expand(ctx, e), e);
    const qd_expr *p = rd(ctx, "(x+1)^30000*(y+1)");
    assert_ptr_equal(qd_expand(ctx, p), rd(ctx, "(x+1)^30000*y + (x+1)^30000"));
    /* below the budget, the binomial theorem: the coefficient of x^2 of
     * (x+1)^2000 is 2000*1999/2 */
    const qd_expr *w = qd_expand(ctx, rd(ctx, "(x+1)^2000"));
    assert_non_null(w);
    assert_int_equal(qd_expr_kind(w), QD_ADD);
    assert_int_equal(qd_expr_nargs(w), 2001);
    /* what was kept, and nothing when all was expanded */
    assert_ptr_equal(qd_expand_kept(ctx, qd_expand(ctx, e)), e);
    assert_ptr_equal(qd_expand_kept(ctx, qd_expand(ctx, p)), e);
    assert_null(qd_expand_kept(ctx, w));
    const qd_expr *big = rd(ctx, "(x+1)^16777217");
    assert_ptr_equal(qd_expand_kept(ctx, qd_expand(ctx, rd(ctx, "cos((x+1)^16777217) + y"))), big);
    /* a power of a sum with a negative or fractional exponent is expanded as far as it goes */
    assert_null(qd_expand_kept(ctx, qd_expand(ctx, rd(ctx, "(x+1)^-3 + sqrt(x+1)"))));
    assert_int_equal(qd_ctx_status(ctx), QD_OK);
    qd_ctx_free(ctx);
}

/* A number too large to fold stays a power, also as the coefficient of a
 * monomial: (2^100000)^100000 would have 10^10 bits. */
static void test_large_number_power_kept(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *e = rd(ctx, "(2^100000)^100000");
    assert_int_equal(qd_expr_kind(e), QD_POW);
    assert_ptr_equal(qd_expand(ctx, e), e);
    const qd_expr *m = qd_expand(ctx, rd(ctx, "(2^100000*x)^100000"));
    assert_ptr_equal(m, qd_mul(ctx, e, rd(ctx, "x^100000")));
    const qd_expr *i = qd_expand(ctx, rd(ctx, "(2^100000*x)^-100000"));
    assert_ptr_equal(i, qd_pow(ctx, m, qd_int(ctx, -1)));
    assert_int_equal(qd_ctx_status(ctx), QD_OK);
    qd_ctx_free(ctx);
}

/* (x+1)^3000 (y+1)^3000: 9 million terms of up to 6000 bits, refused. */
static void test_large_product_refused(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *e = rd(ctx, "(x+1)^3000*(y+1)^3000");
    assert_null(qd_expand(ctx, e));
    assert_int_equal(qd_ctx_status(ctx), QD_ERR_TOOBIG);
    assert_non_null(strstr(qd_ctx_message(ctx), "expression too large"));
    assert_non_null(strstr(qd_ctx_message(ctx), "64 MiB"));
    qd_ctx_free(ctx);
}

/* The model of the issue: V = (q+1)^100000000 derives to
 * f = -1e8 (q+1)^99999999, -1e8 at q = 0. */
static void test_model_with_huge_power(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, "coordinates q\nT = q'^2/2\nV = (q+1)^100000000\n", &d);
    assert_non_null(m);
    qd_eom *eom = qd_eom_derive(ctx, m);
    assert_non_null(eom);
    const qd_expr *q = qd_model_coord(m, 0);
    double zero = 0, f;
    assert_int_equal(qd_eval(ctx, eom->f[0], 1, &q, &zero, &f), QD_OK);
    assert_true(f == -1e8);
    qd_eom_free(eom);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_exponent_beyond_limit),
        cmocka_unit_test(test_large_power_kept),
        cmocka_unit_test(test_large_number_power_kept),
        cmocka_unit_test(test_large_product_refused),
        cmocka_unit_test(test_model_with_huge_power),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
