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
 *     that says stop ends the run with its crossing counted;
 *   - several orbits through the section (qd_poincare_orbits_run): each
 *     orbit's crossings on its own ellipse, at x' = its own sqrt(2 E_x),
 *     at t = t0 + 2 pi k from its own t0; a mistake in the second initial
 *     state refused before any row; a sink that stops in the first orbit
 *     leaves the second unrun.
 */
#include <math.h>
#include <string.h>
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

/* Orbit k's crossings: its own torus (x'0, y0, y'0 at x = 0, t0). */
typedef struct orbit_seen {
    size_t k, rows[3], stop_at;
    double worst[3];
} orbit_seen;

static const double orbit_x[3][4] = {{0.8, 0.3, 0.5, 0}, {0.5, 0.1, -0.2, 1}, {0.8, 0.3, 0.5, 0}};

static void orbit_start(void *data, size_t k) {
    ((orbit_seen *)data)->k = k;
}

static int orbit_sink(void *data, const double *row, bool crossing) {
    orbit_seen *s = data;
    if (!crossing)
        return 0;
    const double *a = orbit_x[s->k], w = 1.6180339887;
    double ey = a[2] * a[2] + w * w * a[1] * a[1];
    double e = fabs(row[4] * row[4] + w * w * row[2] * row[2] - ey);
    double t = fabs(row[0] - a[3] - 2 * PI * (double)(++s->rows[s->k]));
    s->worst[s->k] = fmax(s->worst[s->k], fmax(e, fmax(fabs(row[3] - a[0]), t)));
    return s->rows[0] == s->stop_at;
}

static void test_orbits(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qd_model_parse(ctx, osc2, NULL);
    qd_sim_setup *set = qd_sim_setup_new(ctx, m, false);
    assert_non_null(set);
    assert_int_equal(qd_sim_setup_event(set, "x = 0, x' > 0", false), QD_OK);
    qd_sim_setup_opts so = {.t_end = "1e6", .rtol = "1e-12", .atol = "1e-14"};
    qd_sim_opts o;
    assert_int_equal(qd_sim_setup_options(set, &so, &o), QD_OK);
    /* the third orbit is the model's own initial state (NULL) */
    const char *init[] = {"x'=0.8, y=0.3, y'=0.5", "t=1, x'=0.5, y=0.1, y'=-0.2", NULL};
    qd_poincare_orbits orb = {3, init, orbit_start};
    orbit_seen s = {0};
    qd_poincare_opts po = {.event = 0, .want = 20, .sink = orbit_sink, .data = &s};
    qd_poincare_result r[3];
    size_t at = 9;
    assert_int_equal(qd_poincare_orbits_run(ctx, set, &o, &po, &orb, r, &at), QD_OK);
    for (size_t k = 0; k < 3; k++) {
        assert_true(r[k].got == 20 && s.rows[k] == 20);
        assert_true(s.worst[k] < 1e-8);
        assert_true(fabs(r[k].last_t - orbit_x[k][3] - 40 * PI) < 1e-8);
    }
    /* a mistake in the second: refused before the first runs */
    const char *bad[] = {"x'=0.8", "x'=0.5, z=1"};
    orbit_seen s2 = {0};
    po.data = &s2;
    orb = (qd_poincare_orbits){2, bad, orbit_start};
    assert_int_equal(qd_poincare_orbits_run(ctx, set, &o, &po, &orb, r, &at), QD_ERR_ARG);
    assert_true(at == 1 && s2.rows[0] == 0 && qd_ctx_diag(ctx)->located);
    assert_int_equal(qd_ctx_diag(ctx)->offset, 8); /* 'z' in "x'=0.5, z=1" */
    qd_ctx_clear_error(ctx);
    /* a start after t_end, and too many orbits */
    const char *late[] = {"t=2e6"};
    orb = (qd_poincare_orbits){1, late, NULL};
    assert_int_equal(qd_poincare_orbits_check(ctx, set, &o, &orb, &at), QD_ERR_ARG);
    assert_string_equal(qd_ctx_diag(ctx)->name, "t_end");
    qd_ctx_clear_error(ctx);
    orb = (qd_poincare_orbits){QD_POINCARE_MAX_ORBITS + 1, init, NULL};
    assert_int_equal(qd_poincare_orbits_check(ctx, set, &o, &orb, &at), QD_ERR_ARG);
    qd_ctx_clear_error(ctx);
    /* the sink stops in the first orbit: the second is not run */
    orbit_seen s3 = {.stop_at = 5};
    po.data = &s3;
    orb = (qd_poincare_orbits){2, init, orbit_start};
    assert_int_equal(qd_poincare_orbits_run(ctx, set, &o, &po, &orb, r, &at), QD_OK);
    assert_true(r[0].got == 5 && r[1].got == 0 && s3.rows[1] == 0 && at == 0);
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_poincare_print(r, 2, o.method, 5, "P: ", "t_end", &b), QD_OK);
    assert_non_null(strstr(qd_buf_str(&b), "P: orbit 1: dop853, 5 crossings by t = "));
    assert_non_null(strstr(qd_buf_str(&b), "P: note: orbit 2: only 0 of 5 crossings"));
    qd_buf_free(&b);
    qd_sim_setup_free(set);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_integrable_curve),
        cmocka_unit_test(test_fewer_and_stop),
        cmocka_unit_test(test_orbits),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
