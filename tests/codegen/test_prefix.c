/*
 * tests/codegen/test_prefix.c - the prefix of generated C
 * (qd_codegen_prefix_valid, qd_codegen_prefix_from_path, qdot/codegen.h):
 *
 *   a prefix is a C identifier of 1 to QD_CODEGEN_PREFIX_MAX bytes (C11
 *   6.4.2.1: a letter or underscore, then letters, digits, underscores);
 *   a file's name gives an identifier by that rule whatever its bytes
 *   ("dir/double-pendulum.qd" -> double_pendulum, "2body.qd" -> m2body,
 *   "-" -> model, a very long name cut to the limit), and qd_codegen_c
 *   accepts it: the .c it writes includes "<prefix>.h" and the header
 *   declares <prefix>_rhs; a prefix the rule refuses is refused by
 *   qd_codegen_c too.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/codegen.h"
#include "util/check.h"

static void name_of(const char *path, const char *want) {
    char out[QD_CODEGEN_PREFIX_MAX + 1];
    assert_int_equal(qd_codegen_prefix_from_path(path, out, sizeof out), QD_OK);
    assert_string_equal(out, want);
    assert_true(qd_codegen_prefix_valid(out));
}

static void test_rule(void **state) {
    (void)state;
    assert_true(qd_codegen_prefix_valid("pendulum"));
    assert_true(qd_codegen_prefix_valid("_x1"));
    assert_false(qd_codegen_prefix_valid(""));
    assert_false(qd_codegen_prefix_valid("1abc"));
    assert_false(qd_codegen_prefix_valid("a-b"));
    char longest[QD_CODEGEN_PREFIX_MAX + 2];
    memset(longest, 'a', QD_CODEGEN_PREFIX_MAX);
    longest[QD_CODEGEN_PREFIX_MAX] = '\0';
    assert_true(qd_codegen_prefix_valid(longest));
    longest[QD_CODEGEN_PREFIX_MAX] = 'a';
    longest[QD_CODEGEN_PREFIX_MAX + 1] = '\0';
    assert_false(qd_codegen_prefix_valid(longest));
}

static void test_from_path(void **state) {
    (void)state;
    name_of("examples/double-pendulum.qd", "double_pendulum");
    name_of("2body.qd", "m2body");
    name_of("-", "model");
    name_of("dir/", "m");
    name_of("a.b.c", "a");
    char path[200];
    memset(path, 'z', sizeof path - 1);
    path[sizeof path - 1] = '\0';
    char out[QD_CODEGEN_PREFIX_MAX + 1];
    assert_int_equal(qd_codegen_prefix_from_path(path, out, sizeof out), QD_OK);
    assert_int_equal(strlen(out), QD_CODEGEN_PREFIX_MAX);
    assert_true(qd_codegen_prefix_valid(out));
    assert_int_equal(qd_codegen_prefix_from_path(path, out, QD_CODEGEN_PREFIX_MAX), QD_ERR_ARG);
}

static void test_codegen_takes_it(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qt_parse_ok(ctx, "coordinates theta\nparameters g = 9.81, l = 1\n"
                                   "T = l^2/2*theta'^2\nV = -g*l*cos(theta)\n");
    qd_eom *e = qd_eom_derive(ctx, m);
    assert_non_null(e);
    char P[QD_CODEGEN_PREFIX_MAX + 1];
    assert_int_equal(qd_codegen_prefix_from_path("models/simple-pendulum.qd", P, sizeof P), QD_OK);
    qd_buf c = QD_BUF_INIT, h = QD_BUF_INIT;
    assert_int_equal(qd_codegen_c(ctx, m, e, P, &c, &h), QD_OK);
    char want[128];
    snprintf(want, sizeof want, "#include \"%s.h\"", P);
    assert_non_null(strstr(qd_buf_str(&c), want));
    snprintf(want, sizeof want, "%s_rhs(", P);
    assert_non_null(strstr(qd_buf_str(&h), want));
    qd_buf_free(&c);
    qd_buf_free(&h);
    c = (qd_buf)QD_BUF_INIT;
    assert_int_equal(qd_codegen_c(ctx, m, e, "1abc", &c, NULL), QD_ERR_ARG);
    qd_buf_free(&c);
    qd_eom_free(e);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rule),
        cmocka_unit_test(test_from_path),
        cmocka_unit_test(test_codegen_takes_it),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
