/*
 * tests/path/test_path_ends.c - one end of a path read from the text the
 * command line and Python give (qd_path_end_read, qdot/path.h):
 *
 *   - values are constant expressions in pi and the parameters, the time t
 *     (or the model's independent name) is read when given and left alone
 *     when not, and `y=free` marks a free end without touching its value;
 *   - every error is located in the caller's text, also after a `free`
 *     item (the reader sees a copy of the same length): a misspelt value,
 *     `free` on a parameter, a velocity at an end.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>

#include "qdot/qdot.h"

static const double PI = 3.14159265358979323846;

typedef struct fix {
    qd_ctx *ctx;
    qd_model *m;
    qd_eom *e;
} fix;

static void load(fix *f, const char *text) {
    f->ctx = qd_ctx_new();
    assert_non_null(f->ctx);
    f->m = qd_model_parse(f->ctx, text, NULL);
    assert_non_null(f->m);
    f->e = qd_eom_derive(f->ctx, f->m);
    assert_non_null(f->e);
}

static void unload(fix *f) {
    qd_eom_free(f->e);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
}

static const char *plane = "coordinates x, y\nparameters m = 2, g = 9.81, h = 3\n"
                           "T = m/2*(x'^2 + y'^2)\nV = m*g*y\n";

static void test_values_time_free(void **state) {
    (void)state;
    fix f;
    load(&f, plane);
    double q[2] = {-7, -7}, t = -7;
    bool fr[2] = {false, false};
    assert_int_equal(qd_path_end_read(f.ctx, f.m, f.e, "x = pi/2, y=free, t = h/2", q, &t, fr),
                     QD_OK);
    assert_true(fabs(q[0] - PI / 2) < 1e-15);
    assert_true(q[1] == -7 && fr[1] && !fr[0]); /* free: the value is not touched */
    assert_true(t == 1.5);                      /* h/2 at h = 3 */
    /* no time given: t stays */
    t = 42;
    fr[1] = false;
    assert_int_equal(qd_path_end_read(f.ctx, f.m, f.e, "y=h", q, &t, fr), QD_OK);
    assert_true(t == 42 && q[1] == 3 && !fr[1]);
    unload(&f);
}

/* The error's column in text, which must be the caller's own. */
static void expect_error_at(fix *f, const char *text, size_t offset, const char *words) {
    double q[2] = {0, 0}, t = 0;
    bool fr[2] = {false, false};
    assert_int_not_equal(qd_path_end_read(f->ctx, f->m, f->e, text, q, &t, fr), QD_OK);
    const qd_diag *d = qd_ctx_diag(f->ctx);
    if (!d->located || d->offset != offset || !strstr(d->message, words))
        fail_msg("'%s': %s at %zu (located %d), wanted '%s' at %zu", text, d->message,
                 d->offset, (int)d->located, words, offset);
    qd_ctx_clear_error(f->ctx);
}

static void test_errors_located(void **state) {
    (void)state;
    fix f;
    load(&f, plane);
    /* after a free item the reader's own error keeps its column: '/' at 16 */
    expect_error_at(&f, "y = free, x = 2*/3", 16, "");
    expect_error_at(&f, "x = 1, g=free", 7, "only a coordinate can be free");
    expect_error_at(&f, "x' = 1", 0, "x'");
    expect_error_at(&f, "x = 1, m = 3", 7, "parameter");
    expect_error_at(&f, "x = 1, xx = 2", 7, "unknown name 'xx'");
    unload(&f);
}

/* `independent s`: the ends' time is written s=... */
static void test_independent_name(void **state) {
    (void)state;
    fix f;
    load(&f, "independent s\ncoordinates y\nL = sqrt(1 + y'^2)\n");
    double q[1] = {0}, t = 0;
    bool fr[1] = {false};
    assert_int_equal(qd_path_end_read(f.ctx, f.m, f.e, "y=1, s=2", q, &t, fr), QD_OK);
    assert_true(q[0] == 1 && t == 2);
    unload(&f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_values_time_free),
        cmocka_unit_test(test_errors_located),
        cmocka_unit_test(test_independent_name),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
