/*
 * tests/path/test_brachistochrone.c - the brachistochrone as a two-point
 * problem (qd_path_find on `independent x`), and what the search says when
 * it finds no path (issue 33: it named only a residual).
 *
 * Desloge App. 32 Ex. 2, pp. 979-980 (seed-desloge-D.md T35, pitfall P23):
 * gravity along +y, release from rest at the origin, the time
 * integral sqrt((1 + y'^2)/(2 g y)) dx; the Beltrami identity gives the
 * cycloid x = a (th - sin th), y = a (1 - cos th), and the time of descent
 * from the cusp to the point th is sqrt(a/g) th, so from th0 to th1 on the
 * same cycloid it is sqrt(a/g) (th1 - th0).  The reference's endpoint
 * (1, 1): th_e = 2.41201114391, a = 0.572917037532, T = 0.583192782972 s
 * from the cusp (mpmath there).
 *
 *   - from a point of the cycloid a = 1 (th0 = pi/3) to (pi, 2): the time
 *     sqrt(1/g) 2 pi/3, and every sample on the cycloid;
 *   - from th0 = 0.6 on the cycloid through (1, 1): the time plus
 *     sqrt(a/g) 0.6 is the reference's 0.583192782972;
 *   - from the cusp itself, y = 0: L is infinite at every slope, no shot
 *     can start; the error names the singular start, not a residual;
 *   - the same cusp in mechanics: a projectile at the energy of rest at
 *     its start (Maupertuis, the speed vanishes there), an end out of reach
 *     of the energy, and a radial Kepler path through the singular centre
 *     that "converges" only on the coarse steps (unsettled).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/path.h"

#define PI 3.14159265358979323846
#define G 9.8

typedef struct fix {
    qd_ctx *ctx;
    qd_model *m;
    qd_eom *e;
} fix;

static fix *load(const char *text) {
    fix *f = calloc(1, sizeof *f);
    qd_diag d;
    f->ctx = qd_ctx_new();
    f->m = qd_model_parse(f->ctx, text, &d);
    f->e = f->m ? qd_eom_derive(f->ctx, f->m) : NULL;
    if (!f->e)
        fprintf(stderr, "load: %s\n", f->m ? qd_ctx_message(f->ctx) : d.message);
    return f->e ? f : NULL;
}

static void unload(fix *f) {
    qd_eom_free(f->e);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
    free(f);
}

static const char *brach = "independent x\ncoordinates y\nparameters g = 9.8\n"
                           "L = sqrt((1 + y'^2)/(2*g*y))\n";

/* The path from th0 to th1 on the cycloid of radius a: its time, and each
 * sample (x, y) on the cycloid (th from y: the arc rises to th = pi). */
static double cycloid_time(fix *f, double a, double th0, double th1) {
    double x0 = a * (th0 - sin(th0)), y0 = a * (1 - cos(th0));
    double x1 = a * (th1 - sin(th1)), y1 = a * (1 - cos(th1));
    qd_path_opts o = {.t0 = x0, .t1 = x1, .q0 = &y0, .q1 = &y1};
    qd_path_set ps;
    if (qd_path_find(f->ctx, f->m, f->e, &o, &ps) != QD_OK)
        fail_msg("path: %s", qd_ctx_message(f->ctx));
    assert_int_equal(ps.count, 1);
    const qd_path *p = &ps.paths[0];
    for (size_t k = 0; k < p->nsamples; k++) {
        double th = acos(1 - p->q[k] / a);
        if (fabs(p->t[k] - a * (th - sin(th))) > 1e-6)
            fail_msg("sample %zu (%g, %g) off the cycloid: x = %.12g there", k, p->t[k], p->q[k],
                     a * (th - sin(th)));
    }
    assert_true(p->minimum); /* a least time (Desloge App. 32) */
    double T = p->action;
    qd_path_set_free(&ps);
    return T;
}

static void test_cycloid(void **state) {
    (void)state;
    fix *f = load(brach);
    assert_non_null(f);
    double T = cycloid_time(f, 1, PI / 3, PI);
    if (fabs(T - sqrt(1 / G) * (PI - PI / 3)) > 1e-8)
        fail_msg("time %.12g, want sqrt(a/g) (th1 - th0) = %.12g", T, sqrt(1 / G) * 2 * PI / 3);
    /* the reference's endpoint (1, 1): th_e and a from (th - sin th)/(1 - cos th) = 1 */
    double a = 0.572917037532, the = 2.41201114391;
    T = cycloid_time(f, a, 0.6, the);
    if (fabs(T + sqrt(a / G) * 0.6 - 0.583192782972) > 1e-9)
        fail_msg("time from the cusp %.12g, want 0.583192782972", T + sqrt(a / G) * 0.6);
    unload(f);
}

static void expect_error(fix *f, qd_status st, const char *what, const char *hint) {
    const qd_diag *d = qd_ctx_diag(f->ctx);
    if (st != QD_ERR_NUMERIC || !strstr(d->message, what) || (hint && !strstr(d->hint, hint)))
        fail_msg("status %d, message '%s', hint '%s' (want '%s', hint '%s')", st, d->message,
                 d->hint, what, hint ? hint : "");
    qd_ctx_clear_error(f->ctx);
}

static void test_cusp(void **state) {
    (void)state;
    fix *f = load(brach);
    assert_non_null(f);
    double y0 = 0, y1 = 2;
    qd_path_opts o = {.t0 = 0, .t1 = PI, .q0 = &y0, .q1 = &y1, .all = true};
    qd_path_set ps;
    expect_error(f, qd_path_find(f->ctx, f->m, f->e, &o, &ps),
                 "the equations are singular at the start (x = 0, y = 0)", "just off");
    unload(f);
}

static void test_mechanics(void **state) {
    (void)state;
    /* V = -m g x: at E = 0 the speed vanishes at the origin (x' was 7.6e-6 there) */
    fix *f = load("coordinates x, y\nparameters m = 1, g = 1\nparticle m at (x, y)\nV = -m*g*x\n");
    assert_non_null(f);
    double q0[2] = {0, 0}, q1[2] = {1, 0}, far[2] = {-3, 2};
    qd_path_opts o = {.t0 = 0, .q0 = q0, .q1 = q1, .all = true};
    qd_path_set ps;
    expect_error(f, qd_path_find_energy(f->ctx, f->m, f->e, 0, &o, &ps),
                 "the speed vanishes at the start", "above 0");
    /* E = -1: the start itself is out of reach; E = 1: the end at x = -3 (V = 3) */
    expect_error(f, qd_path_find_energy(f->ctx, f->m, f->e, -1, &o, &ps),
                 "the start (x = 0, y = 0) is out of reach at the energy -1", NULL);
    o.q1 = far;
    expect_error(f, qd_path_find_energy(f->ctx, f->m, f->e, 1, &o, &ps),
                 "the end (x = -3, y = 2) is out of reach at the energy 1: the energy at rest "
                 "there is 3", NULL);
    /* just above the energy of rest a path is found, the fall bent toward y = 0.1 */
    double q2[2] = {1, 0.1};
    o.q1 = q2;
    assert_int_equal(qd_path_find_energy(f->ctx, f->m, f->e, 0.5, &o, &ps), QD_OK);
    qd_path_set_free(&ps);
    unload(f);
    /* Kepler, the straight line from (1, 0) to (-1, 0) through the centre: one
     * segment's RK4 steps jump the singularity and converge, then fail to
     * settle when the steps are halved */
    f = load("coordinates x, y\nparameters k = 1\nparticle 1 at (x, y)\nV = -k/sqrt(x^2 + y^2)\n");
    assert_non_null(f);
    double a[2] = {1, 0}, b[2] = {-1, 0};
    qd_path_opts ok = {.t0 = 0, .t1 = 0.8, .q0 = a, .q1 = b, .segments = 1};
    expect_error(f, qd_path_find(f->ctx, f->m, f->e, &ok, &ps),
                 "converged but did not settle when the steps were halved", "--segments 2");
    unload(f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cycloid),
        cmocka_unit_test(test_cusp),
        cmocka_unit_test(test_mechanics),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
