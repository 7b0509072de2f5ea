/*
 * tests/path/test_path_ends.c - one end of a path read from the text the
 * command line and Python give (qd_path_end_read, qdot/path.h):
 *
 *   - values are constant expressions in pi and the parameters, the time t
 *     (or the model's independent name) is read when given and left alone
 *     when not, and `y=free` marks a free end without touching its value;
 *   - every error is located in the caller's text, also after a `free`
 *     item (the reader sees a copy of the same length): a misspelt value,
 *     `free` on a parameter, a velocity at an end;
 *   - a trial path (qd_path_trial_read) for qd_path_action_of: the falling
 *     body y = t (1 - t) over [0, 1] (Desloge ch. 83's trial paths) has
 *     S = integral of m/2 y'^2 - m g y = m/6 - m g/6, the interval read by
 *     qd_state_range from "0:h/3"; a coordinate twice, a name that is not
 *     one and a missing coordinate are located errors;
 *   - the whole problem (qd_path_ends_read): the body thrown from (0, 0) to
 *     (1, 0) in t = 1 starts with (x', y') = (1, g/2), from y = v t - g t^2/2;
 *     with y free at the end, dL/dy' = m y' = 0 there (the natural boundary
 *     condition, Gelfand & Fomin sec. 6), so y'(0) = g; each refusal names
 *     its field.
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

static void test_trial_path(void **state) {
    (void)state;
    fix f;
    load(&f, "coordinates y\nparameters m = 2, g = 9.81, h = 3\nT = m/2*y'^2\nV = m*g*y\n");
    const qd_expr *q[1];
    assert_int_equal(qd_path_trial_read(f.ctx, f.m, "y = t*(1 - t)", q), QD_OK);
    double t0, t1, S, dS;
    const char *range = "0:h/3";
    assert_int_equal(qd_state_range(f.ctx, f.m, range, 0, strlen(range), &t0, &t1), QD_OK);
    assert_true(t0 == 0 && t1 == 1);
    assert_int_equal(qd_path_action_of(f.ctx, f.m, f.e, q, t0, t1, &S, &dS), QD_OK);
    assert_true(fabs(S - (2.0 / 6 - 2 * 9.81 / 6)) < 1e-9);
    assert_true(dS > 1); /* not the true path: y'' = -g, not -2 */
    /* located errors */
    assert_int_not_equal(qd_path_trial_read(f.ctx, f.m, "y = t, z = t", q), QD_OK);
    assert_true(qd_ctx_diag(f.ctx)->located && qd_ctx_diag(f.ctx)->offset == 7);
    qd_ctx_clear_error(f.ctx);
    assert_int_not_equal(qd_path_trial_read(f.ctx, f.m, "y = t, y = 2*t", q), QD_OK);
    assert_non_null(strstr(qd_ctx_message(f.ctx), "given twice"));
    assert_true(qd_ctx_diag(f.ctx)->offset == 7);
    qd_ctx_clear_error(f.ctx);
    assert_int_not_equal(qd_path_trial_read(f.ctx, f.m, "y = t*(1-/t)", q), QD_OK);
    assert_true(qd_ctx_diag(f.ctx)->located && qd_ctx_diag(f.ctx)->offset == 9);
    qd_ctx_clear_error(f.ctx);
    assert_int_not_equal(qd_path_trial_read(f.ctx, f.m, " ", q), QD_OK);
    assert_non_null(strstr(qd_ctx_message(f.ctx), "no trial path for y"));
    qd_ctx_clear_error(f.ctx);
    assert_int_not_equal(qd_state_range(f.ctx, f.m, "0,1", 0, 3, &t0, &t1), QD_OK);
    assert_non_null(strstr(qd_ctx_message(f.ctx), "expected a range A:B"));
    qd_ctx_clear_error(f.ctx);
    unload(&f);
}

static void test_problem(void **state) {
    (void)state;
    fix f;
    load(&f, plane);
    qd_path_ends ends;
    qd_path_opts o = {.all = false};
    const char *guess[] = {"x'=1, y'=4"};
    assert_int_equal(qd_path_ends_read(f.ctx, f.m, f.e, "x=0, y=0", "x=1, y=0, t=1", 1, guess,
                                       false, &ends, &o), QD_OK);
    assert_true(o.t0 == 0 && o.t1 == 1 && !o.free0 && !o.free1 && o.nguess == 1);
    assert_true(o.guess[0] == 1 && o.guess[1] == 4);
    qd_path_set ps;
    assert_int_equal(qd_path_find(f.ctx, f.m, f.e, &o, &ps), QD_OK);
    assert_true(fabs(ps.paths[0].v0[0] - 1) < 1e-8 && fabs(ps.paths[0].v0[1] - 9.81 / 2) < 1e-8);
    qd_path_set_free(&ps);
    qd_path_ends_free(&ends);
    /* a free end starts from the other end's value and ends at rest in y */
    assert_int_equal(qd_path_ends_read(f.ctx, f.m, f.e, "x=0, y=2", "x=1, y=free, t=1", 0, NULL,
                                       false, &ends, &o), QD_OK);
    assert_true(o.free1 && o.free1[1] && !o.free1[0] && o.q1[1] == 2 && !o.guess);
    assert_int_equal(qd_path_find(f.ctx, f.m, f.e, &o, &ps), QD_OK);
    assert_true(fabs(ps.paths[0].v0[1] - 9.81) < 1e-8);
    qd_path_set_free(&ps);
    qd_path_ends_free(&ends);
    unload(&f);
}

/* Each refusal names the field it is about. */
static void test_problem_refused(void **state) {
    (void)state;
    const struct { const char *from, *to, *guess; bool energy; const char *field; } bad[] = {
        {"x=0, y=0", "x=1, y=free, t=1", NULL, true, "energy"},
        {"x=0, y=0", "x=1, y=0", NULL, false, "to"},
        {"x=0, y=0, t=2", "x=1, y=0, t=1", NULL, false, "to"},
        {"x=0, yy=0", "x=1, y=0, t=1", NULL, false, "from"},
        {"x=0, y=0", "x=1, y=0, t=1", "x'=1, zz'=0", false, "guess"},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        fix f;
        load(&f, plane);
        qd_path_ends ends;
        qd_path_opts o = {0};
        const char *guess[] = {"y'=0", bad[k].guess};
        assert_int_equal(qd_path_ends_read(f.ctx, f.m, f.e, bad[k].from, bad[k].to,
                                           bad[k].guess ? 2 : 0, guess, bad[k].energy, &ends,
                                           &o), QD_ERR_ARG);
        assert_string_equal(qd_ctx_diag(f.ctx)->name, bad[k].field);
        if (bad[k].guess)
            assert_true(qd_ctx_diag(f.ctx)->index == 1 && qd_ctx_diag(f.ctx)->located);
        qd_path_ends_free(&ends);
        unload(&f);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_values_time_free),
        cmocka_unit_test(test_errors_located),
        cmocka_unit_test(test_independent_name),
        cmocka_unit_test(test_trial_path),
        cmocka_unit_test(test_problem),
        cmocka_unit_test(test_problem_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
