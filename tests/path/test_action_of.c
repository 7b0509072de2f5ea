/*
 * tests/path/test_action_of.c - the action of trial paths and the size of
 * their first variation (qd_path_action_of) against closed forms worked by
 * hand from Desloge ch. 83 (seed-desloge-D.md T1, T3, T9):
 *
 *   T1 (ch. 83 Prob. 1) a falling body, L = m z'^2/2 - m g z, on [0, T] the
 *      trial paths z = -g t^2/2 + a t (t - T) (all from rest at z = 0 to the
 *      same end): S(a) = m T^3 (a^2 + 2 g^2)/6, least at the true path a = 0;
 *      Lagrange's residual m z'' + m g = 2 m a, so the first variation's
 *      size (its L2 norm) is 2 m |a| sqrt(T);
 *   T3 (ch. 83 Prob. 3) L = x'^2/2 - x^2/2 on [0, pi/8], x = A (sin t +
 *      c sin 8t): S(c) = sqrt(2) A^2/8 + (63 pi/32) A^2 c^2, residual
 *      x'' + x = -63 A c sin 8t, norm 63 A |c| sqrt(pi/16);
 *   T9 the oscillator's true path from q = 0 to q = 1 in T = 1 (m = w = 1):
 *      S = cot(1)/2, first variation 0.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "qdot/qdot.h"

#define PI 3.14159265358979323846

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

static qd_status action_of(fix *f, const char *path, double t0, double t1, double *S,
                           double *dS) {
    const qd_expr *p = qd_read(f->ctx, path, NULL, NULL);
    assert_non_null(p);
    return qd_path_action_of(f->ctx, f->m, f->e, &p, t0, t1, S, dS);
}

static void test_falling_body_trials(void **state) {
    (void)state;
    fix f;
    load(&f, "coordinates z\nparameters m = 2, g = 9.81\nT = m*z'^2/2\nV = m*g*z\n");
    const double T = 1.7, m = 2, g = 9.81, as[] = {0, 0.5, -3, 12};
    double S0 = 0;
    for (size_t i = 0; i < 4; i++) {
        char path[128];
        snprintf(path, sizeof path, "-g*t^2/2 + (%.17g)*t*(t - %.17g)", as[i], T);
        double S, dS;
        assert_int_equal(action_of(&f, path, 0, T, &S, &dS), QD_OK);
        double a = as[i], want = m * T * T * T * (a * a + 2 * g * g) / 6;
        assert_true(fabs(S - want) < 1e-11 * want);
        assert_true(fabs(dS - 2 * m * fabs(a) * sqrt(T)) < 1e-10 * (1 + dS));
        if (i == 0)
            S0 = S;
        else
            assert_true(S > S0); /* the true path has the least action */
    }
    assert_true(fabs(S0 - m * g * g * T * T * T / 3) < 1e-11 * S0);
    unload(&f);
}

static void test_oscillator_perturbed(void **state) {
    (void)state;
    fix f;
    load(&f, "coordinates x\nL = x'^2/2 - x^2/2\n");
    const double A = 1.3, cs[] = {0, 0.01, -0.2};
    for (size_t i = 0; i < 3; i++) {
        char path[128];
        snprintf(path, sizeof path, "%.17g*(sin(t) + (%.17g)*sin(8*t))", A, cs[i]);
        double S, dS, c = cs[i];
        assert_int_equal(action_of(&f, path, 0, PI / 8, &S, &dS), QD_OK);
        double want = sqrt(2) * A * A / 8 + 63 * PI / 32 * A * A * c * c;
        assert_true(fabs(S - want) < 1e-12 * (1 + want));
        assert_true(fabs(dS - 63 * A * fabs(c) * sqrt(PI / 16)) < 1e-10 * (1 + dS));
    }
    unload(&f);
}

static void test_oscillator_true_path(void **state) {
    (void)state;
    fix f;
    load(&f, "coordinates q\nparameters m = 1, w = 1\nT = m*q'^2/2\nV = m*w^2*q^2/2\n");
    double S, dS;
    assert_int_equal(action_of(&f, "sin(w*t)/sin(w)", 0, 1, &S, &dS), QD_OK);
    assert_true(fabs(S - 0.5 / tan(1.0)) < 1e-13);
    assert_true(dS < 1e-12);
    unload(&f);
}

/* Two coordinates: the free projectile, L = m (x'^2 + y'^2)/2 - m g y, its
 * true path (residual 0) and the straight line between the same ends. */
static void test_projectile_line(void **state) {
    (void)state;
    fix f;
    load(&f, "coordinates x, y\nparameters m = 1.5, g = 9.81\nparticle m at (x, y)\nV = m*g*y\n");
    const qd_expr *p[2] = {qd_read(f.ctx, "3*t", NULL, NULL),
                           qd_read(f.ctx, "4*t - g*t^2/2", NULL, NULL)};
    double S, dS, Sl, dSl;
    assert_int_equal(qd_path_action_of(f.ctx, f.m, f.e, p, 0, 2, &S, &dS), QD_OK);
    assert_true(dS < 1e-11);
    /* the straight line to y(2) = 8 - 2 g, uniform velocity (3, 4 - g) */
    p[1] = qd_read(f.ctx, "(4 - g)*t", NULL, NULL);
    assert_int_equal(qd_path_action_of(f.ctx, f.m, f.e, p, 0, 2, &Sl, &dSl), QD_OK);
    assert_true(Sl > S);
    /* residual m y'' + m g = m g along it: norm m g sqrt(2) */
    assert_true(fabs(dSl - 1.5 * 9.81 * sqrt(2)) < 1e-10 * dSl);
    /* S along the line by hand: m/2 (9 + (4-g)^2) 2 - m g (4-g) 2 */
    double g = 9.81, want = 1.5 * (9 + (4 - g) * (4 - g)) - 1.5 * g * (4 - g) * 2;
    assert_true(fabs(Sl - want) < 1e-11 * fabs(want));
    unload(&f);
}

static void test_errors(void **state) {
    (void)state;
    fix f;
    load(&f, "coordinates x, y\nparameters m = 1\nT = m*(x'^2 + y'^2)/2\n");
    const qd_expr *p[2] = {qd_read(f.ctx, "t", NULL, NULL), qd_read(f.ctx, "x + t", NULL, NULL)};
    double S, dS;
    assert_int_equal(qd_path_action_of(f.ctx, f.m, f.e, p, 0, 1, &S, &dS), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(f.ctx), "names x"));
    qd_ctx_clear_error(f.ctx);
    p[1] = qd_read(f.ctx, "t", NULL, NULL);
    assert_int_equal(qd_path_action_of(f.ctx, f.m, f.e, p, 1, 0, &S, &dS), QD_ERR_ARG);
    qd_ctx_clear_error(f.ctx);
    /* a path singular inside the interval */
    p[1] = qd_read(f.ctx, "1/(t - 1/2)", NULL, NULL);
    assert_int_not_equal(qd_path_action_of(f.ctx, f.m, f.e, p, 0, 1, &S, &dS), QD_OK);
    unload(&f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_falling_body_trials),
        cmocka_unit_test(test_oscillator_perturbed),
        cmocka_unit_test(test_oscillator_true_path),
        cmocka_unit_test(test_projectile_line),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
