/*
 * tests/linear/test_conlin_outputs.c - what qd_conlin_about gives beyond A
 * and B (qdot/conlin.h): outputs' C and D along the manifold, the
 * multipliers, the verdict, and the point qd_conlin_start takes.
 *
 * The pendulum q1^2 + q2^2 = L^2 (gravity along +q1, a force F on q2), the
 * independent states (q2, q2'), with outputs height = q1 (a dependent
 * coordinate) and mix = q1 q2' + 3 F:
 *   C = d(h)/dz T: on the circle dq1/dq2 = -q2/q1, so C = [-q2/q1, 0;
 *   -q2 q2'/q1, q1], D = [0; 3]; and C equals central differences of the
 *   nonlinear outputs y0 taken at points put back on the manifold (the
 *   independent state moved by +-h, the dependent ones solved again);
 *   the multiplier at rest hanging: m q1'' = m g + 2 q1 lambda = 0, so
 *   lambda = -m g / (2 L) (Desloge ch. 62: the rod's tension m g over 2L);
 *   verdicts: hanging, +-i sqrt(g/L): marginally stable; upright (q1 = -L),
 *   s = +-sqrt(g/L): unstable; a point that moves (q2 != 0 at rest): not steady.
 * The pendulum in x, y with no `initial`: qd_conlin_start takes the
 * minimum of V on the rod, y = -l (what `qdot modes` takes).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>

#include "qdot/qdot.h"

#define PEND_OUT                                                                               \
    "parameters m = 0.9, g = 9.8, L = 1.3\n"                                                   \
    "inputs F\n"                                                                               \
    "coordinates q1, q2\n"                                                                     \
    "T = m/2*(q1'^2 + q2'^2)\n"                                                                \
    "V = -m*g*q1\n"                                                                            \
    "Q[q2] = F\n"                                                                              \
    "constraint rod: q1^2 + q2^2 = L^2\n"                                                      \
    "outputs height = q1, mix = q1*q2' + 3*F\n"                                                \
    "initial q1 = L, q2 = 0\n"

#define PEND_XY                                                                                \
    "parameters m = 1, g = 9.81, l = 2\n"                                                      \
    "coordinates x, y\n"                                                                       \
    "T = m/2*(x'^2 + y'^2)\n"                                                                  \
    "V = m*g*y\n"                                                                              \
    "constraint rod: x^2 + y^2 = l^2\n"

typedef struct fixture {
    qd_ctx *ctx;
    qd_model *m;
    qd_eom *e;
    qd_linpoint pt;
} fixture;

static void load(fixture *f, const char *text) {
    qd_diag d;
    f->ctx = qd_ctx_new();
    assert_non_null(f->m = qd_model_parse(f->ctx, text, &d));
    qd_eom_opts o = {.eliminate = true};
    assert_non_null(f->e = qd_eom_derive_opts(f->ctx, f->m, &o));
    assert_int_equal(qd_linpoint_init(f->ctx, f->m, f->e, &f->pt), QD_OK);
}

static void unload(fixture *f) {
    qd_linpoint_free(&f->pt);
    qd_eom_free(f->e);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
}

/* The linearization about the point "q2 = Q2, q2' = V" (independent q2, q2'). */
static void about(fixture *f, double q2, double v, qd_conlin *c) {
    char text[128];
    snprintf(text, sizeof text, "q2 = %.17g, q2' = %.17g", q2, v);
    assert_int_equal(qd_conlin_point(f->ctx, f->m, &f->pt, text), QD_OK);
    assert_int_equal(qd_conlin_about(f->ctx, f->e, f->m, &f->pt, "q2, q2'", c), QD_OK);
}

static void test_outputs(void **state) {
    (void)state;
    fixture f;
    load(&f, PEND_OUT);
    double q2 = 0.6, v = 0.5, h = 1e-5;
    qd_conlin c = {0};
    about(&f, q2, v, &c);
    const qd_statespace *s = &c.ss;
    assert_int_equal(s->ny, 2);
    assert_int_equal(s->nx, 2);
    double q1 = sqrt(1.3 * 1.3 - q2 * q2);
    assert_true(fabs(c.z[0] - q1) < 1e-14);
    const double C[4] = {-q2 / q1, 0, -q2 * v / q1, q1};
    for (size_t k = 0; k < 4; k++)
        assert_true(fabs(s->C[k] - C[k]) < 1e-13);
    assert_true(fabs(s->D[0]) < 1e-15 && fabs(s->D[1] - 3) < 1e-15);
    assert_true(fabs(s->y0[0] - q1) < 1e-14 && fabs(s->y0[1] - q1 * v) < 1e-14);
    /* central differences of y along the manifold, one independent state at a time */
    double fd[4];
    for (int j = 0; j < 2; j++) {
        qd_conlin p = {0}, n = {0};
        about(&f, q2 + (j == 0 ? h : 0), v + (j == 1 ? h : 0), &p);
        about(&f, q2 - (j == 0 ? h : 0), v - (j == 1 ? h : 0), &n);
        for (int i = 0; i < 2; i++)
            fd[i * 2 + j] = (p.ss.y0[i] - n.ss.y0[i]) / (2 * h);
        qd_conlin_free(&p);
        qd_conlin_free(&n);
    }
    for (size_t k = 0; k < 4; k++)
        assert_true(fabs(s->C[k] - fd[k]) < 1e-8);
    /* moving (q2 != 0 at rest): not a steady motion, so no verdict */
    assert_false(c.steady);
    assert_false(c.stable);
    qd_conlin_free(&c);
    unload(&f);
}

static void test_verdict(void **state) {
    (void)state;
    fixture f;
    load(&f, PEND_OUT);
    qd_conlin c = {0};
    about(&f, 0, 0, &c);
    double w = sqrt(9.8 / 1.3);
    assert_true(c.steady && c.stable && c.marginal);
    assert_true(fabs(c.lambda[0] + 0.9 * 9.8 / (2 * 1.3)) < 1e-13);
    assert_true(fabs(fabs(c.core_im[0]) - w) < 1e-12);
    qd_conlin_free(&c);
    /* upright: q1 = -L is reached from q1 = -1 (the independent q2 = 0 held) */
    assert_int_equal(qd_conlin_point(f.ctx, f.m, &f.pt, "q1 = -1"), QD_OK);
    assert_int_equal(qd_conlin_about(f.ctx, f.e, f.m, &f.pt, "q2, q2'", &c), QD_OK);
    assert_true(fabs(c.z[0] + 1.3) < 1e-14);
    assert_true(c.steady && !c.stable && !c.marginal);
    assert_true(fabs(c.margin - w) < 1e-12);
    qd_conlin_free(&c);
    unload(&f);
}

static void test_start(void **state) {
    (void)state;
    fixture f;
    load(&f, PEND_XY);
    qd_equilibrium_choice ch;
    assert_int_equal(qd_conlin_start(f.ctx, f.e, f.m, &f.pt, NULL, &ch), QD_OK);
    assert_non_null(ch.pt);
    qd_conlin c = {0};
    assert_int_equal(qd_conlin_about(f.ctx, f.e, f.m, &f.pt, NULL, &c), QD_OK);
    assert_true(fabs(c.z[0]) < 1e-12 && fabs(c.z[1] + 2) < 1e-12);
    assert_true(fabs(c.ss.A[2] + 9.81 / 2) < 1e-12); /* x'' = -(g/l) x */
    qd_conlin_free(&c);
    qd_equilibrium_choice_free(&ch);
    /* with --about the point is the one given, no search */
    assert_int_equal(qd_conlin_start(f.ctx, f.e, f.m, &f.pt, "x = 0, y = 2", &ch), QD_OK);
    assert_null(ch.pt);
    qd_equilibrium_choice_free(&ch);
    unload(&f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_outputs),
        cmocka_unit_test(test_verdict),
        cmocka_unit_test(test_start),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
