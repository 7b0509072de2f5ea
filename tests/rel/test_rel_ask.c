/*
 * tests/rel/test_rel_ask.c - the questions of `qdot lorentz` and `qdot
 * collide` as library calls (relativity.h: qd_lorentz_read/run,
 * qd_collide_read/run, qd_rel_read_*): values written with c, each part
 * against Desloge vol. 2 ch. 86-91 (reference seed-desloge-D.md T11, T13,
 * T15, T16, P7, P11), and every refusal an error record naming the field
 * and located in the text.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "qdot/qdot.h"

static void near(double got, double want, double tol) {
    if (!(fabs(got - want) <= tol * (1 + fabs(want))))
        fail_msg("got %.17g, want %.17g (tol %g)", got, want, tol);
}

/* T11 and P7: v = (0, 0.5, 0) from V = (0.6, 0, 0); V (+) v and v (+) V
 * have one speed and two directions. */
static void lorentz_T11(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_lorentz_text t = {.frame = "0.6*c, 0, 0", .velocity = "(0, c/2, 0)",
                               .compose = "0, 0.5, 0"};
    qd_lorentz_in in;
    qd_lorentz_out o;
    assert_int_equal(qd_lorentz_read(ctx, &t, &in), QD_OK);
    assert_int_equal(in.ask, QD_LORENTZ_FRAME | QD_LORENTZ_VELOCITY | QD_LORENTZ_COMPOSE);
    assert_int_equal(qd_lorentz_run(ctx, &in, &o), QD_OK);
    near(o.gamma, 1.25, 1e-15);
    near(o.velocity[0], -0.6, 1e-15);
    near(o.velocity[1], 0.4, 1e-15);
    near(o.particle_gamma, 5 * sqrt(3) / 6, 1e-15);
    near(o.composed[0], 0.6, 1e-15);
    near(o.composed[1], 0.4, 1e-15);
    near(hypot(o.composed[0], o.composed[1]), hypot(o.composed_reverse[0], o.composed_reverse[1]),
         1e-15);
    assert_true(o.wigner_angle > 0.17);
    assert_true(o.metric_error < 1e-15);
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_lorentz_render(ctx, &in, &o, true, &b), QD_OK);
    assert_int_equal(qd_lorentz_render(ctx, &in, &o, false, &b), QD_OK);
    qd_buf_free(&b);
    qd_ctx_free(ctx);
}

/* T15 (ch. 87 Prob. 2), c = 2: V = sqrt(3)/2 c, the event (0, -2) goes to
 * x' = -4, t' = sqrt(3); T13: the twin's proper time over 10 at 0.8 c is 6. */
static void lorentz_T15_T13(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_lorentz_text t = {.c = "2", .frame = "sqrt(3)/2*c, 0, 0", .event = "0, -2, 0, 0",
                               .proper_time = "0.8*c, 0, 0", .t = "0:10"};
    qd_lorentz_in in;
    qd_lorentz_out o;
    assert_int_equal(qd_lorentz_read(ctx, &t, &in), QD_OK);
    near(in.c, 2, 0);
    assert_int_equal(qd_lorentz_run(ctx, &in, &o), QD_OK);
    near(o.event[0], sqrt(3), 1e-14);
    near(o.event[1], -4, 1e-14);
    near(o.tau.tau, 6, 1e-13);
    qd_ctx_free(ctx);
}

/* The error just made: status, field and, when located, the span. */
static void refused(qd_ctx *ctx, qd_status st, const char *field, bool located, size_t off,
                    size_t len) {
    const qd_diag *d = qd_ctx_diag(ctx);
    assert_int_equal(st, QD_ERR_ARG);
    assert_int_equal(d->status, QD_ERR_ARG);
    assert_string_equal(d->name, field);
    assert_int_equal(d->located, located);
    if (located) {
        assert_int_equal(d->offset, off);
        assert_int_equal(d->length, len);
    }
    qd_ctx_clear_error(ctx);
}

static void lorentz_refusals(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_lorentz_in in;
    qd_lorentz_out o;
    double x[3];
    /* the unknown name q, under the caret in "0.1, q, 0" */
    refused(ctx, qd_rel_read_numbers(ctx, 1, "frame", "0.1, q, 0", 3, x), "frame", true, 5, 1);
    refused(ctx, qd_rel_read_numbers(ctx, 1, "frame", "0.1, 0", 3, x), "frame", true, 0, 6);
    refused(ctx, qd_rel_read_c(ctx, "c", "-1", x), "c", true, 0, 2);
    const qd_lorentz_text acc = {.frame = "0, 0, 0", .acceleration = "1, 0, 0"};
    assert_int_equal(qd_lorentz_read(ctx, &acc, &in), QD_OK);
    refused(ctx, qd_lorentz_run(ctx, &in, &o), "acceleration", false, 0, 0);
    const qd_lorentz_text nov = {.event = "0, 0, 0, 0"};
    assert_int_equal(qd_lorentz_read(ctx, &nov, &in), QD_OK);
    refused(ctx, qd_lorentz_run(ctx, &in, &o), "frame", false, 0, 0);
    const qd_lorentz_text span = {.proper_time = "0.8, 0, 0"};
    refused(ctx, qd_lorentz_read(ctx, &span, &in), "t", false, 0, 0);
    /* V = c: no frame moves at the speed of light (ch. 85, postulate III) */
    const qd_lorentz_text fast = {.frame = "c, 0, 0"};
    assert_int_equal(qd_lorentz_read(ctx, &fast, &in), QD_OK);
    assert_int_equal(qd_lorentz_run(ctx, &in, &o), QD_ERR_ARG);
    qd_ctx_free(ctx);
}

/* T16 (ch. 88 Prob. 1): 1 at +0.6 c and 2 at -0.8 c merge into
 * M = sqrt(2496)/12 > 3 (P11) moving with -23/55 c. */
static void collide_T16(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const char *ps[] = {"m=1, v=(0.6, 0, 0)", "m=2, v=(-0.8*c, 0, 0)"};
    const qd_collide_text t = {.n = 2, .particle = ps, .merge = true};
    qd_collide_in in;
    qd_collide_out o;
    assert_int_equal(qd_collide_read(ctx, &t, &in), QD_OK);
    assert_int_equal(qd_collide_run(ctx, &in, &o), QD_OK);
    near(o.total.m, sqrt(2496) / 12, 1e-14);
    near(o.total.v[0], -23.0 / 55, 1e-14);
    assert_int_equal(o.nfinal, 0);
    qd_ctx_free(ctx);
}

/* Equal masses, one at rest: the lab angles after an elastic collision
 * satisfy tan th1 tan th2 = 2/(gamma + 1) (Desloge ch. 89); the antiproton
 * threshold p + p -> 3p + pbar is 6 m c^2; pi -> mu nu has
 * p* = (M^2 - m^2) c/(2 M). */
static void collide_final_states(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const char *two[] = {"m=1, v=(0.8, 0, 0)", "m=1"};
    qd_collide_text t = {.n = 2, .particle = two, .elastic = true, .angle = "0.5"};
    qd_collide_in in;
    qd_collide_out o;
    assert_int_equal(qd_collide_read(ctx, &t, &in), QD_OK);
    assert_int_equal(qd_collide_run(ctx, &in, &o), QD_OK);
    assert_int_equal(o.nfinal, 1);
    near(o.lab_angles[0][0], 0.5, 1e-12);
    near(tan(o.lab_angles[0][0]) * tan(o.lab_angles[0][1]), 2 / (5.0 / 3 + 1), 1e-11);
    assert_true(o.conservation_error < 1e-14);
    const char *fast[] = {"m=1, v=(0.99, 0, 0)", "m=1"};
    t = (qd_collide_text){.n = 2, .particle = fast, .threshold = "1, 1, 1, 1"};
    assert_int_equal(qd_collide_read(ctx, &t, &in), QD_OK);
    assert_int_equal(qd_collide_run(ctx, &in, &o), QD_OK);
    near(o.threshold.K, 6, 1e-15);
    assert_true(o.allowed);
    const char *pion[] = {"m=139.57039, v=(0.5, 0, 0)"};
    t = (qd_collide_text){.n = 1, .particle = pion, .decay = "105.6583755, 0",
                          .cm_angle = "pi/3"};
    assert_int_equal(qd_collide_read(ctx, &t, &in), QD_OK);
    assert_int_equal(qd_collide_run(ctx, &in, &o), QD_OK);
    near(o.pstar, (139.57039 * 139.57039 - 105.6583755 * 105.6583755) / (2 * 139.57039), 1e-13);
    assert_true(o.conservation_error < 1e-12);
    qd_ctx_free(ctx);
}

static void collide_refusals(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_collide_in in;
    qd_collide_out o;
    const char *ps[] = {"m=1", "v=(0.1, 0, 0)", "m=1"};
    qd_collide_text t = {.n = 2, .particle = ps};
    qd_status st = qd_collide_read(ctx, &t, &in);
    assert_int_equal(qd_ctx_diag(ctx)->index, 1); /* the second particle has no mass */
    refused(ctx, st, "particle", true, 0, 13);
    qd_rel_particle p;
    refused(ctx, qd_rel_read_particle(ctx, 2, "particle", "m=1, v=(2, 0, 0)", &p), "particle",
            true, 0, 16);
    t = (qd_collide_text){.n = 3, .particle = (const char *[]){"m=1", "m=1", "m=1"},
                          .elastic = true, .cm_angle = "1"};
    assert_int_equal(qd_collide_read(ctx, &t, &in), QD_OK);
    refused(ctx, qd_collide_run(ctx, &in, &o), "elastic", false, 0, 0);
    t = (qd_collide_text){.n = 1, .particle = ps, .decay = "0.6, 0.6"};
    assert_int_equal(qd_collide_read(ctx, &t, &in), QD_OK);
    assert_int_equal(qd_collide_run(ctx, &in, &o), QD_ERR_ARG);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(lorentz_T11),      cmocka_unit_test(lorentz_T15_T13),
        cmocka_unit_test(lorentz_refusals), cmocka_unit_test(collide_T16),
        cmocka_unit_test(collide_final_states), cmocka_unit_test(collide_refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
