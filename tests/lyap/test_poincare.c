/*
 * tests/lyap/test_poincare.c - a Poincare surface of section
 * (qd_poincare_run) of an integrable system, the two-dimensional
 * anisotropic oscillator x'' = -x, y'' = -w^2 y (Lichtenberg & Lieberman,
 * Regular and Chaotic Dynamics, sec. 1.2b: the motion lies on a torus, and
 * its section on a curve):
 *
 *   - on the section x = 0, x' > 0 each crossing lies on the ellipse
 *     y'^2 + w^2 y^2 = 2 E_y (E_y is kept apart from E_x), with x' =
 *     sqrt(2 E_x); from x = 0, x' > 0 (x = 0.8 sin t) the k-th crossing is
 *     at t = 2 pi k, the start not counted;
 *   - the run ends at the want-th crossing; fewer by t_end is no failure;
 *   - rows other than crossings reach the sink too, marked, and a sink
 *     that says stop ends the run with its crossing counted.
 */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "qdot/qdot.h"
#include "qdot/lyapunov.h"
#include "qdot/simsetup.h"

#define PI 3.14159265358979323846

static const char osc2[] = "coordinates x, y\nparameters w = 1.6180339887\n"
                           "T = (x'^2 + y'^2)/2\nV = (x^2 + w^2*y^2)/2\n"
                           "initial x = 0, x' = 0.8, y = 0.3, y' = 0.5\n";

typedef struct seen {
    size_t crossings, others, stop_at;
    double worst_ellipse, worst_xd, worst_t;
} seen;

static int sink(void *data, const double *row, bool crossing) {
    seen *s = data;
    if (!crossing) {
        s->others++;
        return 0;
    }
    /* row: t, x, y, x', y' (Lagrange's state, q then q') */
    double w = 1.6180339887, ey = 0.5 * 0.5 + w * w * 0.3 * 0.3;
    double e = fabs(row[4] * row[4] + w * w * row[2] * row[2] - ey);
    double xd = fabs(row[3] - 0.8), t = fabs(row[0] - 2 * PI * (double)(s->crossings + 1));
    s->worst_ellipse = fmax(s->worst_ellipse, e);
    s->worst_xd = fmax(s->worst_xd, xd);
    s->worst_t = fmax(s->worst_t, t);
    return ++s->crossings == s->stop_at;
}

static qd_poincare_result run(size_t want, const char *t_end, seen *s) {
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qd_model_parse(ctx, osc2, NULL);
    qd_sim_setup *set = qd_sim_setup_new(ctx, m, false);
    assert_non_null(set);
    assert_int_equal(qd_sim_setup_event(set, "x = 0, x' > 0", false), QD_OK);
    qd_sim_setup_opts so = {.t_end = t_end, .rtol = "1e-12", .atol = "1e-14"};
    qd_sim_opts o;
    assert_int_equal(qd_sim_setup_options(set, &so, &o), QD_OK);
    qd_poincare_opts po = {.event = 0, .want = want, .sink = sink, .data = s};
    qd_poincare_result r;
    assert_int_equal(qd_poincare_run(qd_sim_setup_sim(set), &o, &po, &r), QD_OK);
    qd_sim_setup_free(set);
    qd_model_free(m);
    qd_ctx_free(ctx);
    return r;
}

static void test_integrable_curve(void **state) {
    (void)state;
    seen s = {0};
    qd_poincare_result r = run(50, "1e6", &s);
    assert_int_equal(r.got, 50);
    assert_int_equal(s.crossings, 50);
    assert_true(s.others > 50);               /* the steps' rows, marked */
    assert_true(s.worst_ellipse < 1e-9);      /* on the curve E_y = const */
    assert_true(s.worst_xd < 1e-9);           /* x' = sqrt(2 E_x) */
    assert_true(s.worst_t < 1e-8);            /* a period of x apart: t = 2 pi k */
    assert_true(fabs(r.last_t - 100 * PI) < 1e-8);
    assert_true(r.stats.t < 100 * PI + 2); /* ended in the step of the 50th, not at t_end */
}

static void test_fewer_and_stop(void **state) {
    (void)state;
    seen s = {0};
    qd_poincare_result r = run(50, "20", &s); /* 3 crossings by t = 20 */
    assert_int_equal(r.got, 3);
    assert_true(fabs(r.last_t - 6 * PI) < 1e-8);
    seen s2 = {.stop_at = 2};
    r = run(50, "1e6", &s2);
    assert_int_equal(r.got, 2);
    assert_true(fabs(r.last_t - 4 * PI) < 1e-8);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_integrable_curve),
        cmocka_unit_test(test_fewer_and_stop),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
