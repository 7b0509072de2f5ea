/*
 * tests/model/test_given.c - statements given apart from the model's text
 * (qd_model_add_given: `qdot integrals --symmetry`, `qdot impulse
 * --prescribe`): they mean what the same line in the file means, and an
 * error is located in the text as given.
 *
 * The rotation about z has the field xi = (-y, x) (Goldstein sec. 13.7,
 * Desloge ch. 56); a prescribed velocity x' = 1 is the constraint
 * x' - 1 = 0 that Thomson's problem holds after the blow (Byerly ch. III).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <string.h>

#include "qdot/qdot.h"
#include "qdot/model.h"
#include "util/check.h"

static const char *PLANE = "coordinates x, y\nparameters m = 3, k = 1\n"
                           "T = m/2*(x'^2 + y'^2)\nV = -k/sqrt(x^2 + y^2)\n";

static qd_model *plane(qd_ctx *ctx) { return qt_parse_ok(ctx, PLANE); }

/* A label is added unless the text has its own; the field is the rotation's. */
static void labelled(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = plane(ctx);
    qd_diag d;
    assert_int_equal(qd_model_add_given(m, "symmetry", "S1", "delta x = -y, delta y = x", &d),
                     QD_OK);
    assert_int_equal(qd_model_add_given(m, "symmetry", "S2", " rot : x -> x*cos(eps) - "
                                        "y*sin(eps), y -> x*sin(eps) + y*cos(eps)", &d), QD_OK);
    assert_int_equal(qd_model_add_given(m, "integral", "J1", "m*(x*y' - y*x')", NULL), QD_OK);
    assert_int_equal(qd_model_nsymmetries(m), 2);
    assert_string_equal(qd_model_symmetry_name(m, 0), "S1");
    assert_string_equal(qd_model_symmetry_name(m, 1), "rot");
    for (size_t i = 0; i < 2; i++) {
        qt_assert_is(ctx, qd_model_symmetry_field(m, i, 0), "-y");
        qt_assert_is(ctx, qd_model_symmetry_field(m, i, 1), "x");
    }
    assert_int_equal(qd_model_nintegrals(m), 1);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* With no label each comma-separated item is a statement of its own;
 * commas in brackets do not split. */
static void items(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = plane(ctx);
    qd_diag d;
    assert_int_equal(qd_model_add_given(m, "prescribe", NULL, "x' = 1, up: y' = atan2(x, y)*x'",
                                        &d), QD_OK);
    assert_int_equal(qd_model_nprescribed(m), 2);
    assert_string_equal(qd_model_prescribed_name(m, 1), "up");
    qt_assert_is(ctx, qd_model_prescribed(m, 0), "x' - 1");
    qt_assert_is(ctx, qd_model_prescribed(m, 1), "y' - atan2(x, y)*x'");
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* Errors sit in the text given, not in the statement built around it. */
static void located(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = plane(ctx);
    qd_diag d;
    const char *bad = "delta x = -y, delta zz = x";
    assert_int_equal(qd_model_add_given(m, "symmetry", "S1", bad, &d), QD_ERR_PARSE);
    assert_true(d.located);
    assert_int_equal(d.offset, strstr(bad, "zz") - bad);
    assert_int_equal(qd_model_nsymmetries(m), 0); /* the model as it was */
    const char *note = "delta x = -y # a note";
    assert_int_equal(qd_model_add_given(m, "symmetry", "S1", note, &d), QD_ERR_ARG);
    assert_int_equal(d.offset, strchr(note, '#') - note);
    assert_non_null(strstr(d.message, "one statement"));
    const char *empty = "x' = 1, , y' = 0";
    assert_int_equal(qd_model_add_given(m, "prescribe", NULL, empty, &d), QD_ERR_ARG);
    assert_int_equal(d.offset, 7);
    assert_non_null(strstr(d.message, "empty item"));
    const char *two = "x' = 1, y' = q'";
    assert_int_equal(qd_model_add_given(m, "prescribe", NULL, two, &d), QD_ERR_PARSE);
    assert_true(d.offset >= 8 && d.offset < strlen(two)); /* in the second item */
    assert_int_equal(qd_model_add_given(NULL, "prescribe", NULL, two, &d), QD_ERR_ARG);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(labelled),
        cmocka_unit_test(items),
        cmocka_unit_test(located),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
