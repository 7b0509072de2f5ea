/*
 * tests/sym/test_read_variable.c - a variable to differentiate by, read
 * from text (qd_read_variable, qdot/read.h, what `qdot diff` reads),
 * checked by the derivatives it gives and by where its errors point:
 *
 *   in phi = r^2 theta' (twice the areal velocity) the rate theta' read
 *   from "theta'" gives d(phi)/d(theta') = r^2 (the angular momentum per
 *   unit mass), and "r" gives d(phi)/dr = 2 r theta'; a mixed second
 *   derivative d^2(phi)/dr d(theta') = 2 r either way round (Schwarz);
 *   a name absent from phi, a name the context does not know, and text
 *   that is no name are each QD_ERR_ARG located under the whole text.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <string.h>

#include "qdot/qdot.h"
#include "qdot/read.h"
#include "util/check.h"

static void test_derivatives(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    const qd_expr *phi = qd_read(ctx, "r^2*theta'", NULL, &d);
    assert_non_null(phi);
    const qd_expr *w = qd_read_variable(ctx, "theta'", phi, &d);
    const qd_expr *r = qd_read_variable(ctx, "r", phi, &d);
    assert_non_null(w);
    assert_non_null(r);
    assert_int_equal(qd_expr_kind(w), QD_SYMBOL);
    qt_assert_is(ctx, qd_diff(ctx, phi, w), "r^2");
    qt_assert_is(ctx, qd_diff(ctx, phi, r), "2*r*theta'");
    qt_assert_is(ctx, qd_diff(ctx, qd_diff(ctx, phi, r), w), "2*r");
    qt_assert_is(ctx, qd_diff(ctx, qd_diff(ctx, phi, w), r), "2*r");
    qd_ctx_free(ctx);
}

static void refused(qd_ctx *ctx, const qd_expr *within, const char *text) {
    qd_diag d;
    assert_null(qd_read_variable(ctx, text, within, &d));
    assert_int_equal(d.status, QD_ERR_ARG);
    assert_true(d.located);
    assert_int_equal(d.offset, 0);
    assert_int_equal(d.length, strlen(text));
    assert_non_null(strstr(d.message, "does not occur in the expression"));
    assert_int_equal(qd_ctx_status(ctx), QD_ERR_ARG);
    qd_ctx_clear_error(ctx);
}

static void test_refused(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    const qd_expr *phi = qd_read(ctx, "r^2*theta'", NULL, &d);
    qd_read(ctx, "y", NULL, &d); /* known, but not in phi */
    refused(ctx, phi, "y");
    refused(ctx, phi, "never_seen");
    refused(ctx, phi, "r + ");
    refused(ctx, phi, "2*r");
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_derivatives),
        cmocka_unit_test(test_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
