/*
 * tests/form/test_vars_read.c - the variables of a quadratic form read from
 * text (qd_qform_vars_read, qdot/form.h, what `qdot form --vars` reads),
 * checked by the forms they reduce (Desloge App. 27) and by where their
 * errors point:
 *
 *   "x y" (spaces) and "x, y" read the same two symbols, in order, and
 *   x^2 + 2 x y in them has the matrix [[1, 1], [1, 0]], determinant -1 < 0,
 *   so one positive and one negative square (indefinite, Sylvester);
 *   "x,y , z" with x^2 + y^2 + z^2 is positive definite of rank 3;
 *   a name given twice has the caret under its second place, more names
 *   than room under the first one too many, and a list of no name under
 *   the whole text (QD_ERR_ARG each, with a hint).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <string.h>

#include "qdot/qdot.h"
#include "qdot/form.h"
#include "util/check.h"

static const qd_expr *expr(qd_ctx *ctx, const char *text) {
    qd_diag d;
    const qd_expr *x = qd_read(ctx, text, NULL, &d);
    if (!x)
        fail_msg("cannot read %s: %s", text, d.message);
    return x;
}

static void test_indefinite(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *phi = expr(ctx, "x^2 + 2*x*y");
    const qd_expr *x[4], *x2[4];
    size_t n = 9, n2 = 9;
    assert_int_equal(qd_qform_vars_read(ctx, "x y", x, 4, &n), QD_OK);
    assert_int_equal(qd_qform_vars_read(ctx, " x, y,", x2, 4, &n2), QD_OK);
    assert_int_equal(n, 2);
    assert_int_equal(n2, 2);
    assert_ptr_equal(x[0], x2[0]);
    assert_ptr_equal(x[1], x2[1]);
    assert_string_equal(qd_expr_name(x[0]), "x");
    assert_string_equal(qd_expr_name(x[1]), "y");
    qd_qform *f = qd_qform_reduce(ctx, phi, n, x);
    assert_non_null(f);
    qt_assert_is(ctx, f->a[0], "1");
    qt_assert_is(ctx, f->a[1], "1");
    qt_assert_is(ctx, f->a[2], "1");
    qt_assert_is(ctx, f->a[3], "0");
    assert_true(f->decided);
    assert_int_equal(f->npos, 1);
    assert_int_equal(f->nneg, 1);
    assert_string_equal(f->kind, "indefinite");
    qd_qform_free(f);
    qd_ctx_free(ctx);
}

static void test_definite(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *x[3];
    size_t n = 0;
    assert_int_equal(qd_qform_vars_read(ctx, "x,y , z", x, 3, &n), QD_OK);
    assert_int_equal(n, 3);
    qd_qform *f = qd_qform_reduce(ctx, expr(ctx, "x^2 + y^2 + z^2"), n, x);
    assert_non_null(f);
    assert_int_equal(f->nsq, 3);
    assert_int_equal(f->npos, 3);
    assert_string_equal(f->kind, "positive definite");
    qd_qform_free(f);
    qd_ctx_free(ctx);
}

/* x^2 - pi y^2 + e z^2: the coefficients' signs are those of the constants
 * pi > 0 and e > 0, so Sylvester's inertia is decided, (2, 1, 0); it was
 * "undecided (a coefficient of unknown sign)". */
static void test_constant_coefficients(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *x[3];
    size_t n = 0;
    assert_int_equal(qd_qform_vars_read(ctx, "x, y, z", x, 3, &n), QD_OK);
    qd_qform *f = qd_qform_reduce(ctx, expr(ctx, "x^2 - pi*y^2 + e*z^2"), n, x);
    assert_non_null(f);
    assert_true(f->decided);
    assert_int_equal(f->npos, 2);
    assert_int_equal(f->nneg, 1);
    assert_int_equal(f->nzero, 0);
    assert_string_equal(f->kind, "indefinite");
    qd_qform_free(f);
    qd_qform *g = qd_qform_reduce(ctx, expr(ctx, "pi^2*x^2 + 2*y^2"), 2, x);
    assert_non_null(g);
    assert_true(g->decided);
    assert_string_equal(g->kind, "positive definite");
    qd_qform_free(g);
    qd_ctx_free(ctx);
}

static void located(qd_ctx *ctx, const char *text, size_t cap, size_t off, size_t len,
                    const char *msg) {
    const qd_expr *x[4];
    size_t n = 0;
    assert_int_equal(qd_qform_vars_read(ctx, text, x, cap, &n), QD_ERR_ARG);
    const qd_diag *d = qd_ctx_diag(ctx);
    assert_true(d->located);
    assert_int_equal(d->offset, off);
    assert_int_equal(d->length, len);
    assert_non_null(strstr(d->message, msg));
    assert_true(d->hint[0] != '\0');
    qd_ctx_clear_error(ctx);
}

static void test_errors(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    located(ctx, "x, theta, x", 4, 10, 1, "'x' is given twice");
    located(ctx, "a b c", 2, 4, 1, "more than 2 variables");
    located(ctx, " , ,", 4, 0, 4, "no variable");
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_indefinite),
        cmocka_unit_test(test_definite),
        cmocka_unit_test(test_constant_coefficients),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
