/*
 * tests/path/test_path_iso.c - isoperimetric two-point problems and free end
 * points in qd_path_find against closed forms (Desloge vol. 2 App. 32,
 * Thm 5 and Ex. 2, seed-desloge-D.md C15 and P19, P23; Byerly ch. IV;
 * Gelfand and Fomin ch. 1 sec. 6 for the natural boundary condition):
 *
 *   the hanging chain of length l between (xa, ya) and (xb, yb):
 *     L = w y sqrt(1 + y'^2) - lambda sqrt(1 + y'^2) (variational.c adds
 *     -lambda G), so y = lambda/w + a cosh((x - x0)/a) with
 *     sqrt(l^2 - h^2) = 2 a sinh(d/(2a)) (d = xb - xa, h = yb - ya; a found
 *     here by bisection), x0 = (xa + xb)/2 - a atanh(h/l) (from h/l =
 *     tanh((mid - x0)/a)), and lambda = w (ya - a cosh((xa - x0)/a)): the
 *     multiplier is w times the height of the catenary's directrix;
 *     integral F dx = w (c l + a^2/2 [u + sinh u cosh u]) over u = (x - x0)/a;
 *   a length shorter than the chord: refused before solving;
 *   the oscillator m x'' = -k x with x(T) free: m x'(T) = 0 gives
 *     v0 = a w tan(wT); with x(0) free: x'(0) = 0, x(0) = b / cos(wT);
 *   the chain whose right end slides on the line x = 1: (w y - lambda) y' /
 *     sqrt(1 + y'^2) = 0 there, so the vertex is at x = 1, l = a sinh(1/a);
 *   integral y'^2 dx = -1, which no curve has (the integrand is a square):
 *     no convergence, and the message names the condition.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <string.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "qdot/path.h"

/* A model and its equations (no simulator: a multiplier is no input of one). */
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

#define assert_double_equal(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

static const char *chain = "independent x\ncoordinates y\nparameters w = 2, l = 3\n"
                           "L = w*y*sqrt(1 + y'^2)\n"
                           "constraint length: integral(sqrt(1 + y'^2)) = l\n";

/* a with f(a) = 2 a sinh(s/a) = r, by bisection (f falls from inf to 2s). */
static double half_width(double r, double s) {
    double lo = 1e-3, hi = 1e3;
    for (int i = 0; i < 300; i++) {
        double a = sqrt(lo * hi);
        if (2 * a * sinh(s / a) > r)
            lo = a;
        else
            hi = a;
    }
    return sqrt(lo * hi);
}

typedef struct catenary {
    double a, x0, c;  /* y = c + a cosh((x - x0)/a) */
} catenary;

static catenary catenary_through(double xa, double ya, double xb, double yb, double l) {
    double d = xb - xa, h = yb - ya;
    catenary k;
    k.a = half_width(sqrt(l * l - h * h), d / 2);
    k.x0 = (xa + xb) / 2 - k.a * atanh(h / l);
    k.c = ya - k.a * cosh((xa - k.x0) / k.a);
    return k;
}

static double cat_y(const catenary *k, double x) { return k->c + k->a * cosh((x - k->x0) / k->a); }

static double cat_F(const catenary *k, double w, double l, double xa, double xb) {
    double ua = (xa - k->x0) / k->a, ub = (xb - k->x0) / k->a;
    return w * (k->c * l + k->a * k->a / 2 * (ub - ua + sinh(ub) * cosh(ub) - sinh(ua) * cosh(ua)));
}

static void test_catenary_length(void **state) {
    (void)state;
    fix *f = load(chain);
    assert_non_null(f);
    double w = 2, l = 3, xa = 0, ya = 0, xb = 2, yb = 1;  /* off-centre: x0 != mid */
    qd_path_opts o = {.t0 = xa, .t1 = xb, .q0 = &ya, .q1 = &yb};
    qd_path_set ps;
    assert_int_equal(qd_path_find(f->ctx, f->m, f->e, &o, &ps), QD_OK);
    assert_int_equal(ps.count, 1);
    const qd_path *p = &ps.paths[0];
    catenary k = catenary_through(xa, ya, xb, yb, l);
    assert_double_equal(sqrt(l * l - 1) - 2 * k.a * sinh(1 / k.a), 0, 1e-12);
    assert_int_equal(p->nmult, 1);
    assert_double_equal(p->mult[0], w * k.c, 1e-8);
    assert_double_equal(p->v0[0], sinh((xa - k.x0) / k.a), 1e-8);
    double worst = 0;
    for (size_t i = 0; i < p->nsamples; i++)
        worst = fmax(worst, fabs(p->q[i] - cat_y(&k, p->t[i])));
    assert_true(worst < 1e-8);
    assert_double_equal(p->action, cat_F(&k, w, l, xa, xb), 1e-8);
    assert_false(p->examined);
    qd_path_set_free(&ps);
    unload(f);
}

/* A chain shorter than the chord: no curve, said before any shooting. */
static void test_catenary_too_short(void **state) {
    (void)state;
    fix *f = load(chain);
    assert_non_null(f);
    double ya = 0, yb = 2.5;  /* chord sqrt(4 + 6.25) = 3.2 > l = 3 */
    qd_path_opts o = {.t0 = 0, .t1 = 2, .q0 = &ya, .q1 = &yb};
    qd_path_set ps;
    assert_int_equal(qd_path_find(f->ctx, f->m, f->e, &o, &ps), QD_ERR_ARG);
    assert_int_equal(ps.count, 0);
    assert_non_null(strstr(qd_ctx_message(f->ctx), "the length l = 3 is shorter than the distance "
                                                   "3.201562119 between the end points: no curve"));
    /* the chord exactly: only the straight line, no finite multiplier */
    qd_ctx_clear_error(f->ctx);
    yb = sqrt(5);
    assert_int_equal(qd_path_find(f->ctx, f->m, f->e, &o, &ps), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(f->ctx), "equals the distance"));
    unload(f);
}

static void test_oscillator_free_end(void **state) {
    (void)state;
    fix *f = load("coordinates x\nparameters m = 3, k = 12\nT = m*x'^2/2\nV = k*x^2/2\n");
    assert_non_null(f);
    double w = 2, a = 0.3, T = 0.6, guess = 0;
    bool fr[1] = {true};
    qd_path_opts o = {.t0 = 0, .t1 = T, .q0 = &a, .q1 = &guess, .free1 = fr};
    qd_path_set ps;
    assert_int_equal(qd_path_find(f->ctx, f->m, f->e, &o, &ps), QD_OK);
    assert_int_equal(ps.count, 1);
    const qd_path *p = &ps.paths[0];
    assert_double_equal(p->v0[0], a * w * tan(w * T), 1e-8);
    assert_double_equal(p->q[p->nsamples - 1], a / cos(w * T), 1e-8);
    assert_int_equal(p->nmult, 0);
    assert_false(p->examined);
    qd_path_set_free(&ps);
    /* the start free instead: x = b cos(w t)/cos(wT) */
    double b = -0.4, g0 = 0;
    qd_path_opts o2 = {.t0 = 0, .t1 = T, .q0 = &g0, .q1 = &b, .free0 = fr};
    assert_int_equal(qd_path_find(f->ctx, f->m, f->e, &o2, &ps), QD_OK);
    p = &ps.paths[0];
    assert_double_equal(p->v0[0], 0, 1e-8);
    assert_double_equal(p->q[0], b / cos(w * T), 1e-8);
    assert_double_equal(p->q[p->nsamples - 1], b, 1e-10);
    qd_path_set_free(&ps);
    /* a free end at fixed energy is refused */
    assert_int_equal(qd_path_find_energy(f->ctx, f->m, f->e, 1, &o, &ps), QD_ERR_ARG);
    unload(f);
}

/* The chain from (0, 0) whose right end slides on x = 1: horizontal there. */
static void test_chain_sliding_end(void **state) {
    (void)state;
    fix *f = load(chain);
    assert_non_null(f);
    double w = 2, l = 3, y0 = 0, guess = 0;
    bool fr[1] = {true};
    qd_path_opts o = {.t0 = 0, .t1 = 1, .q0 = &y0, .q1 = &guess, .free1 = fr};
    qd_path_set ps;
    assert_int_equal(qd_path_find(f->ctx, f->m, f->e, &o, &ps), QD_OK);
    const qd_path *p = &ps.paths[0];
    double a = half_width(2 * l, 1), c = -a * cosh(1 / a);  /* l = a sinh(1/a) */
    assert_double_equal(p->mult[0], w * c, 1e-8);
    assert_double_equal(p->q[p->nsamples - 1], c + a, 1e-8);
    assert_double_equal(p->v0[0], -sinh(1 / a), 1e-7);
    qd_path_set_free(&ps);
    unload(f);
}

static void test_inconsistent_integral(void **state) {
    (void)state;
    fix *f = load("independent x\ncoordinates y\nL = y'^2/2\n"
                  "constraint e: integral(y'^2) = -1\n");
    assert_non_null(f);
    double y0 = 0, y1 = 1;
    qd_path_opts o = {.t0 = 0, .t1 = 1, .q0 = &y0, .q1 = &y1};
    qd_path_set ps;
    assert_int_equal(qd_path_find(f->ctx, f->m, f->e, &o, &ps), QD_ERR_NUMERIC);
    assert_int_equal(ps.count, 0);
    assert_non_null(strstr(qd_ctx_message(f->ctx), "integral of constraint e minus its value"));
    unload(f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_catenary_length),
        cmocka_unit_test(test_catenary_too_short),
        cmocka_unit_test(test_oscillator_free_end),
        cmocka_unit_test(test_chain_sliding_end),
        cmocka_unit_test(test_inconsistent_integral),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
