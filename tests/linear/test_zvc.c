/*
 * tests/linear/test_zvc.c - contours and zero-velocity curves (qdot/zvc.h).
 *
 *   marching squares on level sets known exactly: x^2 + y^2 = 1 (one closed
 *     circle, radius and enclosed area pi to the grid's O(h^2)), two
 *     concentric circles of (r^2 - 1)(r^2 - 4) = 0, a circle of radius 1.8
 *     cut by the box [-1.5, 1.5]^2 into four open arcs ending on the box;
 *   the restricted three-body problem, mu = 0.01 (Desloge ch. 62,
 *     seed-desloge-B.md C6, T27, pitfall 8): Jacobi's integral at rest is
 *     W = -(x^2 + y^2)/2 - (1 - mu)/rho1 - mu/rho2 (U_std); the collinear
 *     points, found here by bisection of dW/dx on the three intervals,
 *     have T27's Om^2 = (1 - mu)/|x + mu|^3 + mu/|x - 1 + mu|^3
 *     (5.0652478406, 3.2352741919, 1.0087902754); L4, L5 have
 *     W = -3/2 + mu (1 - mu)/2 (C_J = -2W = 3 - mu (1 - mu));
 *     the curve at W(L1) passes through L1, and the two ovals round the
 *     primaries below that level become one above it (the pinch);
 *   errors: a driven system whose Jacobi integral is not conserved.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/zvc.h"
#include "../util/system.h"

static const double PI = 3.14159265358979323846;
static const double MU = 0.01;

#define THREE_BODY                                                                             \
    "coordinates x, y\nparameters mu = 0.01\n"                                                 \
    "T = 1/2*((x' - y)^2 + (y' + x)^2)\n"                                                      \
    "V = -(1 - mu)/sqrt((x + mu)^2 + y^2) - mu/sqrt((x - 1 + mu)^2 + y^2)\n"

typedef double (*field)(double x, double y);

/* f on the grid of [lo, hi]^2, n cells each way (malloc'd). */
static double *grid(field f, size_t n, double lo, double hi) {
    double *v = malloc((n + 1) * (n + 1) * sizeof *v);
    assert_non_null(v);
    for (size_t j = 0; j <= n; j++)
        for (size_t i = 0; i <= n; i++)
            v[i + j * (n + 1)] = f(lo + (hi - lo) * (double)i / (double)n,
                                   lo + (hi - lo) * (double)j / (double)n);
    return v;
}

static double r2(double x, double y) { return x * x + y * y; }
static double two_rings(double x, double y) { return (r2(x, y) - 1) * (r2(x, y) - 4); }

static double area(const qd_polyline *p) {
    double a = 0;
    for (size_t i = 0; i + 1 < p->count; i++)
        a += p->x[i] * p->y[i + 1] - p->x[i + 1] * p->y[i];
    return fabs(a) / 2;
}

static void circle(void **state) {
    qd_ctx *ctx = qd_ctx_new();
    *state = ctx;
    size_t n = 100;
    double *f = grid(r2, n, -2, 2);
    qd_contour c;
    assert_int_equal(qd_contour_grid(ctx, n, n, f, -2, 2, -2, 2, 1, &c), QD_OK);
    assert_int_equal(c.count, 1);
    const qd_polyline *p = &c.lines[0];
    assert_true(p->closed);
    assert_true(p->x[0] == p->x[p->count - 1] && p->y[0] == p->y[p->count - 1]);
    for (size_t i = 0; i < p->count; i++)
        assert_true(fabs(hypot(p->x[i], p->y[i]) - 1) < 1e-3);
    assert_true(fabs(area(p) - PI) < 5e-3);
    qd_contour_free(&c);
    free(f);
}

static void rings_and_arcs(void **state) {
    qd_ctx *ctx = qd_ctx_new();
    *state = ctx;
    size_t n = 150;
    double *f = grid(two_rings, n, -2.5, 2.5);
    qd_contour c;
    assert_int_equal(qd_contour_grid(ctx, n, n, f, -2.5, 2.5, -2.5, 2.5, 0, &c), QD_OK);
    assert_int_equal(c.count, 2);
    double radii[2];
    for (size_t k = 0; k < 2; k++) {
        assert_true(c.lines[k].closed);
        radii[k] = sqrt(area(&c.lines[k]) / PI);
    }
    assert_true(fabs(fmin(radii[0], radii[1]) - 1) < 2e-3);
    assert_true(fabs(fmax(radii[0], radii[1]) - 2) < 2e-3);
    qd_contour_free(&c);
    free(f);

    f = grid(r2, n, -1.5, 1.5);
    assert_int_equal(qd_contour_grid(ctx, n, n, f, -1.5, 1.5, -1.5, 1.5, 1.8 * 1.8, &c), QD_OK);
    assert_int_equal(c.count, 4);
    for (size_t k = 0; k < 4; k++) {
        const qd_polyline *p = &c.lines[k];
        assert_false(p->closed);
        size_t ends[2] = {0, p->count - 1};
        for (int e = 0; e < 2; e++)   /* each end on the box */
            assert_true(fabs(fmax(fabs(p->x[ends[e]]), fabs(p->y[ends[e]])) - 1.5) < 1e-12);
    }
    qd_contour_free(&c);
    free(f);
}

/* ---- the restricted three-body problem ------------------------------------------- */

static double W3(double x, double y) {
    return -(x * x + y * y) / 2 - (1 - MU) / hypot(x + MU, y) - MU / hypot(x - 1 + MU, y);
}

static double dWdx(double x) {
    double a = x + MU, b = x - 1 + MU;
    return -x + (1 - MU) * a / pow(fabs(a), 3) + MU * b / pow(fabs(b), 3);
}

/* The root of dW/dx on the axis in (lo, hi), by bisection (pitfall 8). */
static double collinear(double lo, double hi) {
    double flo = dWdx(lo);
    for (int k = 0; k < 200; k++) {
        double mid = (lo + hi) / 2, fm = dWdx(mid);
        if ((fm > 0) == (flo > 0)) {
            lo = mid;
            flo = fm;
        } else {
            hi = mid;
        }
    }
    return (lo + hi) / 2;
}

static int inside(const qd_polyline *p, double x, double y) {
    int in = 0;
    for (size_t i = 0, j = p->count - 1; i < p->count; j = i++)
        if ((p->y[i] > y) != (p->y[j] > y) &&
            x < (p->x[j] - p->x[i]) * (y - p->y[i]) / (p->y[j] - p->y[i]) + p->x[i])
            in = !in;
    return in;
}

/* How many closed curves contain (x, y). */
static size_t around(const qd_contour *c, double x, double y) {
    size_t k = 0;
    for (size_t i = 0; i < c->count; i++)
        k += c->lines[i].closed && inside(&c->lines[i], x, y);
    return k;
}

static double W_at(qt_system *s, const qd_zvc *z, double x, double y) {
    const qd_expr *syms[3] = {qt_symbol(s, "x"), qt_symbol(s, "y"), qt_symbol(s, "mu")};
    double vals[3] = {x, y, MU}, w;
    assert_int_equal(qd_eval(s->ctx, z->W, 3, syms, vals, &w), QD_OK);
    return w;
}

static void jacobi_constants(void **state) {
    qt_system *s = qt_system_derive(state, THREE_BODY, false);
    qd_zvc z;
    assert_int_equal(qd_zvc_derive(s->ctx, s->model, s->eom, &z), QD_OK);
    double L[3] = {collinear(-MU + 1e-9, 1 - MU - 1e-9), collinear(1 - MU + 1e-9, 2),
                   collinear(-2, -MU - 1e-9)};
    double om2[3] = {5.0652478406, 3.2352741919, 1.0087902754};   /* T27 */
    for (int k = 0; k < 3; k++) {
        double a = fabs(L[k] + MU), b = fabs(L[k] - 1 + MU);
        assert_true(fabs((1 - MU) / (a * a * a) + MU / (b * b * b) - om2[k]) < 1e-9);
        assert_true(fabs(W_at(s, &z, L[k], 0) - W3(L[k], 0)) < 1e-13);
    }
    double w45 = -1.5 + MU * (1 - MU) / 2;
    assert_true(fabs(W_at(s, &z, 0.5 - MU, sqrt(3) / 2) - w45) < 1e-14);
    assert_true(fabs(W_at(s, &z, 0.5 - MU, -sqrt(3) / 2) - w45) < 1e-14);
    /* the order of the levels: L1 lowest, then L2, L3, L4 = L5 */
    assert_true(W3(L[0], 0) < W3(L[1], 0) && W3(L[1], 0) < W3(L[2], 0) && W3(L[2], 0) < w45);
}

static void pinch_at_l1(void **state) {
    qt_system *s = qt_system_derive(state, THREE_BODY, false);
    qd_zvc z;
    assert_int_equal(qd_zvc_derive(s->ctx, s->model, s->eom, &z), QD_OK);
    double l1 = collinear(-MU + 1e-9, 1 - MU - 1e-9), h1 = W3(l1, 0);
    qd_zvc_box box = {0, 1, {-1.6, -1.6}, {1.6, 1.6}, 320, 320};
    const qd_expr *syms[1] = {qt_symbol(s, "mu")};
    double vals[1] = {MU}, cell = 3.2 / 320;
    qd_contour below, at, above;
    assert_int_equal(qd_zvc_curves(s->ctx, s->eom, &z, &box, 1, syms, vals, h1 - 0.003, &below),
                     QD_OK);
    assert_int_equal(qd_zvc_curves(s->ctx, s->eom, &z, &box, 1, syms, vals, h1, &at), QD_OK);
    assert_int_equal(qd_zvc_curves(s->ctx, s->eom, &z, &box, 1, syms, vals, h1 + 0.003, &above),
                     QD_OK);
    /* below: an oval round each primary, neither round the other, and L1
     * outside both; above: one curve round both */
    double m1 = -MU, m2 = 1 - MU;
    size_t c1 = 0, c2 = 0, both_below = 0, both_above = 0;
    for (size_t i = 0; i < below.count; i++) {
        const qd_polyline *p = &below.lines[i];
        int a = p->closed && inside(p, m1, 0.001), b = p->closed && inside(p, m2, 0.001);
        c1 += a && !b && inside(p, -0.5, 0) && !inside(p, l1, 0);
        c2 += b && !a && !inside(p, l1, 0);
        both_below += a && b;
    }
    for (size_t i = 0; i < above.count; i++) {
        const qd_polyline *p = &above.lines[i];
        both_above += p->closed && inside(p, m1, 0.001) && inside(p, m2, 0.001);
    }
    assert_int_equal(c1, 1);
    assert_int_equal(c2, 1);
    assert_int_equal(both_below, 1);    /* only the outer curve, far out */
    assert_int_equal(both_above, 2);    /* the merged inner curve and the outer one */
    assert_true(around(&above, l1, 0) >= 1);
    /* at W(L1) the curve goes through L1 (to the grid's resolution) */
    double dmin = INFINITY;
    for (size_t i = 0; i < at.count; i++)
        for (size_t k = 0; k < at.lines[i].count; k++)
            dmin = fmin(dmin, hypot(at.lines[i].x[k] - l1, at.lines[i].y[k]));
    assert_true(dmin < 2 * cell);
    qd_contour_free(&below);
    qd_contour_free(&at);
    qd_contour_free(&above);
}

/* Past W(L2) the region round the primaries opens to the outside: what is
 * left forbidden is one horseshoe round L4, L3 and L5; past W(L3) it breaks
 * into two tadpoles, one round each of L4 and L5. */
static void horseshoe_and_tadpoles(void **state) {
    qt_system *s = qt_system_derive(state, THREE_BODY, false);
    qd_zvc z;
    assert_int_equal(qd_zvc_derive(s->ctx, s->model, s->eom, &z), QD_OK);
    double l2 = collinear(1 - MU + 1e-9, 2), l3 = collinear(-2, -MU - 1e-9);
    double h2 = W3(l2, 0), h3 = W3(l3, 0), h4 = -1.5 + MU * (1 - MU) / 2;
    double y4 = sqrt(3) / 2, x4 = 0.5 - MU;
    qd_zvc_box box = {0, 1, {-1.6, -1.6}, {1.6, 1.6}, 320, 320};
    const qd_expr *syms[1] = {qt_symbol(s, "mu")};
    double vals[1] = {MU};
    qd_contour c;
    assert_int_equal(qd_zvc_curves(s->ctx, s->eom, &z, &box, 1, syms, vals, (h2 + h3) / 2, &c),
                     QD_OK);
    assert_int_equal(c.count, 1);
    assert_true(c.lines[0].closed);
    assert_true(inside(&c.lines[0], x4, y4) && inside(&c.lines[0], x4, -y4) &&
                inside(&c.lines[0], l3, 0));
    assert_false(inside(&c.lines[0], -MU, 0.001) || inside(&c.lines[0], 1 - MU, 0.001));
    qd_contour_free(&c);
    assert_int_equal(qd_zvc_curves(s->ctx, s->eom, &z, &box, 1, syms, vals, (h3 + h4) / 2, &c),
                     QD_OK);
    assert_int_equal(c.count, 2);
    assert_int_equal(around(&c, x4, y4), 1);
    assert_int_equal(around(&c, x4, -y4), 1);
    assert_int_equal(around(&c, l3, 0), 0);
    qd_contour_free(&c);
}

static void not_conserved(void **state) {
    qt_system *s = qt_system_derive(state, "coordinates x\nparameters k = 1, w = 2\n"
                                           "T = x'^2/2\nV = k/2*x^2 - x*cos(w*t)\n", false);
    qd_zvc z;
    assert_int_equal(qd_zvc_derive(s->ctx, s->model, s->eom, &z), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(s->ctx), "not conserved"));
}

static int free_ctx(void **state) {
    qd_ctx_free(*state);
    return 0;
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(circle, free_ctx),
        cmocka_unit_test_teardown(rings_and_arcs, free_ctx),
        cmocka_unit_test_teardown(jacobi_constants, qt_system_teardown),
        cmocka_unit_test_teardown(pinch_at_l1, qt_system_teardown),
        cmocka_unit_test_teardown(horseshoe_and_tadpoles, qt_system_teardown),
        cmocka_unit_test_teardown(not_conserved, qt_system_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
