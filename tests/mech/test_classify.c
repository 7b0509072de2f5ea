/*
 * tests/mech/test_classify.c - Pfaffian constraints: exact, integrable
 * after a factor, or nonholonomic (Desloge, Classical Mechanics, ch. 49;
 * ../shared/reference/seed-desloge-A.md C6, T09 and pitfall 4), one at a
 * time and several together (Frobenius).
 *
 * An integral phi is checked for what it must be, d phi = mu w: its
 * gradient in (q, t) equals the factor times the coefficients at random
 * points, and it is not constant.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "qdot/qdot.h"
#include "qdot/mech.h"
#include "mech/mech.h"
#include "util/randexpr.h"

#define SEED 4901u
#define NPOINTS 8
#define MAXQ 8

typedef struct sys {
    qd_ctx *ctx;
    size_t n;
    const qd_expr *q[MAXQ];
    const qd_expr *a[4][MAXQ]; /* coefficient storage of up to 4 constraints */
    qd_con con[4];
} sys;

static sys *sys_new(void **state, size_t n, const char *const *names) {
    sys *s = calloc(1, sizeof *s);
    *state = s;
    s->ctx = qd_ctx_new();
    s->n = n;
    for (size_t j = 0; j < n; j++)
        s->q[j] = qd_coord(s->ctx, names[j]);
    return s;
}

static int teardown(void **state) {
    sys *s = *state;
    if (s)
        qd_ctx_free(s->ctx);
    free(s);
    *state = NULL;
    return 0;
}

/* Constraint k: sum_j a[j] q'_j + a0 = 0. */
static qd_con *con(sys *s, size_t k, const char *name, const qd_expr *const *a,
                   const qd_expr *a0) {
    qd_con *c = &s->con[k];
    for (size_t j = 0; j < s->n; j++)
        s->a[k][j] = a[j];
    *c = (qd_con){.name = name, .kind = QD_CON_HOLONOMIC, .a = s->a[k], .a0 = a0};
    return c;
}

static qd_con *classify(sys *s, qd_con *c) {
    qd_status st = qd__mech_con_classify(s->ctx, s->n, s->q, c);
    if (st != QD_OK)
        fail_msg("%s: %s", c->name, qd_ctx_message(s->ctx));
    return c;
}

static const qd_expr *P(sys *s, const char *name) { return qd_param(s->ctx, name); }
static const qd_expr *I(sys *s, long v) { return qd_int(s->ctx, v); }

/* e at one point. */
static double at(sys *s, const qd_expr *e, const qd_expr **syms, const double *vals, size_t ns) {
    double v;
    if (qd_eval(s->ctx, e, ns, syms, vals, &v) != QD_OK)
        fail_msg("eval: %s", qd_ctx_message(s->ctx));
    return v;
}

/* d integral = factor * w at NPOINTS points, and the integral not constant. */
static void assert_integral(sys *s, const qd_con *c) {
    qd_ctx *ctx = s->ctx;
    if (!c->integral || !c->factor)
        fail_msg("%s: integrable, but no integral/factor", c->name);
    const qd_expr *syms[32];
    double vals[32];
    const qd_expr *all = qd_add(ctx, c->integral, c->factor);
    for (size_t j = 0; j < s->n; j++)
        all = qd_add(ctx, all, qd_mul(ctx, qd_jet(ctx, s->q[j], 1), c->a[j]));
    all = qd_add(ctx, all, c->a0);
    size_t ns = qd_free_symbols(ctx, all, syms, 32);
    assert_true(ns <= 32);
    qt_rng r = {SEED};
    bool moves = false;
    for (int k = 0; k < NPOINTS; k++) {
        for (size_t i = 0; i < ns; i++)
            vals[i] = qt_uniform(&r, 0.5, 2);
        for (size_t j = 0; j <= s->n; j++) {
            const qd_expr *x = j < s->n ? s->q[j] : qd_time(ctx);
            const qd_expr *w = j < s->n ? c->a[j] : c->a0;
            double g = at(s, qd_diff(ctx, c->integral, x), syms, vals, ns);
            double m = at(s, qd_mul(ctx, c->factor, w), syms, vals, ns);
            if (fabs(g - m) > 1e-9 * (1 + fabs(g) + fabs(m)))
                fail_msg("%s: d integral/d %s = %.17g but factor * a = %.17g (point %d)",
                         c->name, qd_expr_name(x), g, m, k);
            moves = moves || fabs(g) > 1e-6;
        }
    }
    assert_true(moves);
}

/* ---- exact ------------------------------------------------------------------ */

/* A disk rolling on a line (Desloge ch. 49; seed C6): x' - a phi' = 0 is
 * exact, x - a phi = const. */
static void test_disk_on_line(void **state) {
    static const char *names[] = {"x", "phi"};
    sys *s = sys_new(state, 2, names);
    const qd_expr *a = P(s, "a"), *w[2] = {I(s, 1), qd_neg(s->ctx, a)};
    qd_con *c = classify(s, con(s, 0, "roll", w, I(s, 0)));
    assert_int_equal(c->kind, QD_CON_INTEGRABLE);
    assert_true(qd_is_one(c->factor));
    assert_integral(s, c);
    const qd_expr *want = qd_sub(s->ctx, s->q[0], qd_mul(s->ctx, a, s->q[1]));
    const qd_expr *d = qd_simplify(s->ctx, qd_sub(s->ctx, c->integral, want));
    assert_true(qd_is_number(d));
}

/* Time in the constraint: x' - c = 0 is x - c t = const; x' - g t = 0 is
 * x - g t^2/2 = const (t is a variable of the form, seed C5). */
static void test_time_dependent_exact(void **state) {
    static const char *names[] = {"x"};
    sys *s = sys_new(state, 1, names);
    qd_ctx *ctx = s->ctx;
    const qd_expr *w[1] = {I(s, 1)}, *t = qd_time(ctx);
    qd_con *c = classify(s, con(s, 0, "drive", w, qd_neg(ctx, P(s, "c"))));
    assert_int_equal(c->kind, QD_CON_INTEGRABLE);
    assert_integral(s, c);
    const qd_expr *d = qd_sub(ctx, c->integral, qd_sub(ctx, s->q[0], qd_mul(ctx, P(s, "c"), t)));
    assert_true(qd_is_number(qd_simplify(ctx, d)));
    c = classify(s, con(s, 1, "fall", w, qd_neg(ctx, qd_mul(ctx, P(s, "g"), t))));
    assert_int_equal(c->kind, QD_CON_INTEGRABLE);
    assert_true(qd_is_one(c->factor));
    assert_integral(s, c);
}

/* ---- integrating factors --------------------------------------------------- */

/* x y' - y x' = 0: y/x = const, with the factor 1/x^2 (or another). */
static void test_factor_quotient(void **state) {
    static const char *names[] = {"x", "y"};
    sys *s = sys_new(state, 2, names);
    const qd_expr *x = s->q[0], *y = s->q[1], *w[2] = {qd_neg(s->ctx, y), x};
    qd_con *c = classify(s, con(s, 0, "ratio", w, I(s, 0)));
    assert_int_equal(c->kind, QD_CON_INTEGRABLE);
    assert_false(qd_is_one(c->factor));
    assert_integral(s, c);
}

/* y' + (y/x) x' = 0: x y = const (factor x); 2 y x' + x y' = 0: x^2 y. */
static void test_factor_products(void **state) {
    static const char *names[] = {"x", "y"};
    sys *s = sys_new(state, 2, names);
    qd_ctx *ctx = s->ctx;
    const qd_expr *x = s->q[0], *y = s->q[1];
    const qd_expr *w1[2] = {qd_div(ctx, y, x), I(s, 1)};
    const qd_expr *w2[2] = {qd_mul(ctx, I(s, 2), y), x};
    qd_con *c = classify(s, con(s, 0, "hyperbola", w1, I(s, 0)));
    assert_int_equal(c->kind, QD_CON_INTEGRABLE);
    assert_integral(s, c);
    c = classify(s, con(s, 1, "cubic", w2, I(s, 0)));
    assert_int_equal(c->kind, QD_CON_INTEGRABLE);
    assert_integral(s, c);
}

/* t x' - x = 0 in (x, t): x/t = const, t entering the factor. */
static void test_factor_with_time(void **state) {
    static const char *names[] = {"x"};
    sys *s = sys_new(state, 1, names);
    const qd_expr *w[1] = {qd_time(s->ctx)};
    qd_con *c = classify(s, con(s, 0, "expand", w, qd_neg(s->ctx, s->q[0])));
    assert_int_equal(c->kind, QD_CON_INTEGRABLE);
    assert_integral(s, c);
}

/* A form in three variables that is integrable but not exact:
 * y z x' + x z y' + 2 x y z' = 0 (w ^ dw = 0; (x y) z^2 = const). */
static void test_factor_three_variables(void **state) {
    static const char *names[] = {"x", "y", "z"};
    sys *s = sys_new(state, 3, names);
    qd_ctx *ctx = s->ctx;
    const qd_expr *x = s->q[0], *y = s->q[1], *z = s->q[2];
    const qd_expr *w[3] = {qd_mul(ctx, y, z), qd_mul(ctx, x, z),
                           qd_mul(ctx, I(s, 2), qd_mul(ctx, x, y))};
    qd_con *c = classify(s, con(s, 0, "surface", w, I(s, 0)));
    assert_int_equal(c->kind, QD_CON_INTEGRABLE);
    assert_integral(s, c);
}

/* ---- nonholonomic ------------------------------------------------------------ */

/* y' = z x' (issue 4): w = dy - z dx, w ^ dw = dx ^ dy ^ dz != 0. */
static void test_y_z_x(void **state) {
    static const char *names[] = {"x", "y", "z"};
    sys *s = sys_new(state, 3, names);
    const qd_expr *w[3] = {qd_neg(s->ctx, s->q[2]), I(s, 1), I(s, 0)};
    qd_con *c = classify(s, con(s, 0, "contact", w, I(s, 0)));
    assert_int_equal(c->kind, QD_CON_NONHOLONOMIC);
    assert_null(c->integral);
    qd_con *one[1] = {c};
    bool ok;
    assert_int_equal(qd__mech_con_frobenius(s->ctx, s->n, s->q, one, 1, &ok), QD_OK);
    assert_false(ok);
}

/* y' - t x' = 0: with t a variable, dy - t dx is not integrable. */
static void test_time_nonholonomic(void **state) {
    static const char *names[] = {"x", "y"};
    sys *s = sys_new(state, 2, names);
    const qd_expr *w[2] = {qd_neg(s->ctx, qd_time(s->ctx)), I(s, 1)};
    qd_con *c = classify(s, con(s, 0, "shear", w, I(s, 0)));
    assert_int_equal(c->kind, QD_CON_NONHOLONOMIC);
}

/* The upright rolling disk (Desloge ch. 49 Ex. 1, seed T09): coordinates
 * (x1, x2, ph, psi), x1' + a cos(ph) psi' = 0, x2' + a sin(ph) psi' = 0:
 * each nonholonomic and the pair too (2 motional, 4 configurational DOF). */
static void test_rolling_disk(void **state) {
    static const char *names[] = {"x1", "x2", "ph", "psi"};
    sys *s = sys_new(state, 4, names);
    qd_ctx *ctx = s->ctx;
    const qd_expr *a = P(s, "a"), *ph = s->q[2];
    const qd_expr *w1[4] = {I(s, 1), I(s, 0), I(s, 0), qd_mul(ctx, a, qd_fn(ctx, QD_COS, ph))};
    const qd_expr *w2[4] = {I(s, 0), I(s, 1), I(s, 0), qd_mul(ctx, a, qd_fn(ctx, QD_SIN, ph))};
    qd_con *c1 = classify(s, con(s, 0, "slip1", w1, I(s, 0)));
    qd_con *c2 = classify(s, con(s, 1, "slip2", w2, I(s, 0)));
    assert_int_equal(c1->kind, QD_CON_NONHOLONOMIC);
    assert_int_equal(c2->kind, QD_CON_NONHOLONOMIC);
    qd_con *both[2] = {c1, c2};
    bool ok = true;
    assert_int_equal(qd__mech_con_frobenius(ctx, s->n, s->q, both, 2, &ok), QD_OK);
    assert_false(ok);
}

/* Two wheels of radius a on an axle of length 2b (seed C6, pitfall 4):
 * coordinates (x, y, th, p1, p2).  No side slip, x' sin th - y' cos th = 0,
 * and rolling, x' cos th + y' sin th - a (p1' + p2')/2 = 0, are
 * nonholonomic; the difference of the wheels, th' - a (p1' - p2')/(2b) = 0,
 * is exact.  Together: not integrable; the exact one alone, and with
 * another exact one, is. */
static void test_axle(void **state) {
    static const char *names[] = {"x", "y", "th", "p1", "p2"};
    sys *s = sys_new(state, 5, names);
    qd_ctx *ctx = s->ctx;
    const qd_expr *a = P(s, "a"), *b = P(s, "b"), *th = s->q[2], *z = I(s, 0);
    const qd_expr *S = qd_fn(ctx, QD_SIN, th), *C = qd_fn(ctx, QD_COS, th);
    const qd_expr *ha = qd_mul(ctx, qd_rat(ctx, -1, 2), a), *k = qd_div(ctx, a, qd_mul(ctx, I(s, 2), b));
    const qd_expr *side[5] = {S, qd_neg(ctx, C), z, z, z};
    const qd_expr *roll[5] = {C, S, z, ha, ha};
    const qd_expr *turn[5] = {z, z, I(s, 1), qd_neg(ctx, k), k};
    const qd_expr *sum[5] = {z, z, z, I(s, 1), I(s, 1)};
    qd_con *c1 = classify(s, con(s, 0, "side", side, z));
    qd_con *c2 = classify(s, con(s, 1, "roll", roll, z));
    qd_con *c3 = classify(s, con(s, 2, "turn", turn, z));
    qd_con *c4 = classify(s, con(s, 3, "sum", sum, z));
    assert_int_equal(c1->kind, QD_CON_NONHOLONOMIC);
    assert_int_equal(c2->kind, QD_CON_NONHOLONOMIC);
    assert_int_equal(c3->kind, QD_CON_INTEGRABLE);
    assert_integral(s, c3);
    bool ok = true;
    qd_con *all[3] = {c1, c2, c3}, *exact[2] = {c3, c4};
    assert_int_equal(qd__mech_con_frobenius(ctx, s->n, s->q, all, 3, &ok), QD_OK);
    assert_false(ok);
    assert_int_equal(qd__mech_con_frobenius(ctx, s->n, s->q, exact, 2, &ok), QD_OK);
    assert_true(ok);
    assert_int_equal(qd__mech_con_frobenius(ctx, s->n, s->q, all + 2, 1, &ok), QD_OK);
    assert_true(ok);
}

/* Frobenius with room for it (four variables, m + 2 = 4): with
 * f1 = z - x y + u and f2 = y u, the pair w1 = df1 + x df2, w2 = df2 spans
 * {df1, df2} and is integrable; w1 with du instead of w2 is not
 * (dw1 ^ w1 ^ du = u dx^dy^dz^du). */
static void test_frobenius_system(void **state) {
    static const char *names[] = {"x", "y", "z", "u"};
    sys *s = sys_new(state, 4, names);
    qd_ctx *ctx = s->ctx;
    const qd_expr *x = s->q[0], *y = s->q[1], *z = s->q[2], *u = s->q[3], *o = I(s, 0);
    const qd_expr *f1 = qd_add(ctx, qd_sub(ctx, z, qd_mul(ctx, x, y)), u);
    const qd_expr *f2 = qd_mul(ctx, y, u), *w1[4], *w2[4], *du[4] = {o, o, o, I(s, 1)};
    for (int j = 0; j < 4; j++) {
        w2[j] = qd_diff(ctx, f2, s->q[j]);
        w1[j] = qd_add(ctx, qd_diff(ctx, f1, s->q[j]), qd_mul(ctx, x, w2[j]));
    }
    qd_con *c1 = con(s, 0, "w1", w1, o), *c2 = con(s, 1, "w2", w2, o);
    qd_con *c3 = con(s, 2, "du", du, o);
    qd_con *pair[2] = {c1, c2}, *other[2] = {c1, c3};
    bool ok = false;
    assert_int_equal(qd__mech_con_frobenius(ctx, s->n, s->q, pair, 2, &ok), QD_OK);
    assert_true(ok);
    assert_int_equal(qd__mech_con_frobenius(ctx, s->n, s->q, other, 2, &ok), QD_OK);
    assert_false(ok);
}

/* ---- the constraints together: relations among the coordinates --------------- */

/* qd__mech_con_closure on the first m constraints of s: the number of
 * independent forms and of relations phi(q, t) = const they imply. */
static void closure(sys *s, size_t m, size_t rank, size_t relations) {
    size_t r, rel;
    if (qd__mech_con_closure(s->ctx, s->n, s->q, s->con, m, &r, &rel) != QD_OK)
        fail_msg("closure: %s", qd_ctx_message(s->ctx));
    if (r != rank || rel != relations)
        fail_msg("closure: %zu forms and %zu relations, expected %zu and %zu", r, rel, rank,
                 relations);
}

/* The two-wheel axle as Desloge ch. 52 Problem 5 (p. 557) gives it (seed
 * 000; examples/two_disks_axle.qd): no side slip, and each wheel rolling,
 * -x' sin th + y' cos th +- b th' - a p' = 0.  No constraint is integrable
 * alone, but roll1 - roll2 is: 3 independent forms, 1 relation (4
 * configurational, 2 motional degrees of freedom, as the book says; counted
 * one constraint at a time it was 5). */
static void test_closure_axle(void **state) {
    static const char *names[] = {"x", "y", "th", "p1", "p2"};
    sys *s = sys_new(state, 5, names);
    qd_ctx *ctx = s->ctx;
    const qd_expr *a = P(s, "a"), *b = P(s, "b"), *th = s->q[2], *z = I(s, 0);
    const qd_expr *S = qd_fn(ctx, QD_SIN, th), *C = qd_fn(ctx, QD_COS, th);
    const qd_expr *side[5] = {C, S, z, z, z};
    const qd_expr *roll1[5] = {qd_neg(ctx, S), C, b, qd_neg(ctx, a), z};
    const qd_expr *roll2[5] = {qd_neg(ctx, S), C, qd_neg(ctx, b), z, qd_neg(ctx, a)};
    assert_int_equal(classify(s, con(s, 0, "side", side, z))->kind, QD_CON_NONHOLONOMIC);
    assert_int_equal(classify(s, con(s, 1, "roll1", roll1, z))->kind, QD_CON_NONHOLONOMIC);
    assert_int_equal(classify(s, con(s, 2, "roll2", roll2, z))->kind, QD_CON_NONHOLONOMIC);
    closure(s, 3, 3, 1);
    closure(s, 2, 2, 0); /* side and one wheel: nothing integrates */
    /* the relation itself: phi with d phi proportional to roll1 - roll2,
     * 2b dth - a dp1 + a dp2 (Goldstein's th = C - (a/b)(phi - phi') for an
     * axle of length b) */
    size_t r, rel, nint;
    const qd_expr *phi[2];
    assert_int_equal(qd__mech_con_relations(ctx, 5, s->q, s->con, 3, &r, &rel, phi, 2, &nint),
                     QD_OK);
    assert_int_equal(nint, 1);
    const qd_expr *d[5];
    for (int j = 0; j < 5; j++)
        d[j] = qd_diff(ctx, phi[0], s->q[j]);
    assert_true(qd_is_zero(qd_simplify(ctx, d[0])) && qd_is_zero(qd_simplify(ctx, d[1])));
    assert_false(qd_is_zero(qd_simplify(ctx, d[3])));
    assert_true(qd_is_zero(qd_simplify(ctx, qd_add(ctx, d[3], d[4]))));
    assert_true(qd_is_zero(qd_simplify(ctx, qd_add(ctx, qd_mul(ctx, a, d[2]),
                                                   qd_mul(ctx, qd_mul(ctx, I(s, 2), b), d[3])))));
}

/* The upright rolling disk (Desloge ch. 49 Ex. 1, p. 536): 2 forms, no
 * relation: 4 configurational and 2 motional degrees of freedom. */
static void test_closure_rolling_disk(void **state) {
    static const char *names[] = {"x1", "x2", "ph", "psi"};
    sys *s = sys_new(state, 4, names);
    qd_ctx *ctx = s->ctx;
    const qd_expr *a = P(s, "a"), *ph = s->q[2], *z = I(s, 0);
    const qd_expr *w1[4] = {I(s, 1), z, z, qd_mul(ctx, a, qd_fn(ctx, QD_COS, ph))};
    const qd_expr *w2[4] = {z, I(s, 1), z, qd_mul(ctx, a, qd_fn(ctx, QD_SIN, ph))};
    con(s, 0, "roll1", w1, z);
    con(s, 1, "roll2", w2, z);
    closure(s, 2, 2, 0);
}

/* One constraint integrable alone and one not, in separate variables:
 * y' = z x' (Desloge ch. 49's knife edge form) and x u' + u x' = 0
 * (x u = const): exactly 1 relation, 3 configurational degrees of freedom
 * as one at a time gives.  In three coordinates instead, y' = z x' with
 * x y' + y x' = 0 leaves only z free (x' = y' = 0 where y + x z != 0):
 * 2 relations, though one constraint alone is nonholonomic. */
static void test_closure_one_integrable(void **state) {
    static const char *names[] = {"x", "y", "z", "u"};
    sys *s = sys_new(state, 4, names);
    qd_ctx *ctx = s->ctx;
    const qd_expr *x = s->q[0], *y = s->q[1], *z = s->q[2], *u = s->q[3], *o = I(s, 0);
    const qd_expr *knife[4] = {qd_neg(ctx, z), I(s, 1), o, o};
    const qd_expr *hyper[4] = {u, o, o, x}, *hyper3[4] = {y, x, o, o};
    assert_int_equal(classify(s, con(s, 0, "knife", knife, o))->kind, QD_CON_NONHOLONOMIC);
    assert_int_equal(classify(s, con(s, 1, "hyper", hyper, o))->kind, QD_CON_INTEGRABLE);
    closure(s, 2, 2, 1);
    con(s, 1, "hyper3", hyper3, o);
    s->n = 3;
    closure(s, 2, 2, 2);
}

/* x' - y' = 0 split across two constraints, each nonholonomic:
 * c1 = x' - y' + u' - v w', c2 = u' - v w' (u' - v w' is Heisenberg's
 * contact form, never integrable): 1 relation, x - y = const. */
static void test_closure_split(void **state) {
    static const char *names[] = {"x", "y", "u", "v", "w"};
    sys *s = sys_new(state, 5, names);
    qd_ctx *ctx = s->ctx;
    const qd_expr *v = s->q[3], *o = I(s, 0), *one = I(s, 1);
    const qd_expr *c1[5] = {one, qd_neg(ctx, one), one, o, qd_neg(ctx, v)};
    const qd_expr *c2[5] = {o, o, one, o, qd_neg(ctx, v)};
    assert_int_equal(classify(s, con(s, 0, "c1", c1, o))->kind, QD_CON_NONHOLONOMIC);
    assert_int_equal(classify(s, con(s, 1, "c2", c2, o))->kind, QD_CON_NONHOLONOMIC);
    closure(s, 2, 2, 1);
}

/* Time (Goldstein ch. 1 Derivation 6, seed 002): a velocity always
 * pointing at (t, 0), (x - t) y' - y x' = 0, is nonholonomic: no relation;
 * x' - y' - w cos(w t) = 0 is exact in (x, y, t): x - y - sin(w t) = const,
 * 1 relation. */
static void test_closure_time(void **state) {
    static const char *names[] = {"x", "y"};
    sys *s = sys_new(state, 2, names);
    qd_ctx *ctx = s->ctx;
    const qd_expr *x = s->q[0], *y = s->q[1], *t = qd_time(ctx), *w = P(s, "w");
    const qd_expr *aim[2] = {qd_neg(ctx, y), qd_sub(ctx, x, t)};
    con(s, 0, "aim", aim, I(s, 0));
    closure(s, 1, 1, 0);
    const qd_expr *drive[2] = {I(s, 1), I(s, -1)};
    con(s, 0, "drive", drive, qd_neg(ctx, qd_mul(ctx, w, qd_fn(ctx, QD_COS, qd_mul(ctx, w, t)))));
    closure(s, 1, 1, 1);
}

/* User functions count as generic ones: x' = f(y) z', y' = z x' in three
 * coordinates allow one direction, so 2 relations whatever f is; the
 * rolling disk with cos and sin replaced by f(ph), g(ph) keeps none. */
static void test_closure_user_functions(void **state) {
    static const char *names[] = {"x", "y", "z", "u"};
    sys *s = sys_new(state, 4, names);
    qd_ctx *ctx = s->ctx;
    const qd_expr *y = s->q[1], *z = s->q[2], *o = I(s, 0);
    s->n = 3;
    const qd_expr *fy = qd_ufunc(ctx, "f", 1, &y);
    const qd_expr *c1[3] = {I(s, 1), o, qd_neg(ctx, fy)}, *c2[3] = {qd_neg(ctx, z), I(s, 1), o};
    con(s, 0, "c1", c1, o);
    con(s, 1, "c2", c2, o);
    closure(s, 2, 2, 2);
    /* (x, y, z, u) = (x1, x2, ph, psi) */
    s->n = 4;
    const qd_expr *fz = qd_ufunc(ctx, "f", 1, &z), *gz = qd_ufunc(ctx, "g", 1, &z);
    const qd_expr *r1[4] = {I(s, 1), o, o, fz}, *r2[4] = {o, I(s, 1), o, gz};
    con(s, 0, "roll1", r1, o);
    con(s, 1, "roll2", r2, o);
    closure(s, 2, 2, 0);
}

/* Random relations hidden in combinations: phi1, phi2 random in (q3, q4,
 * t) and the contact form dq5 - q1 dq2; three constraints w = G (dphi1,
 * dphi2, dq5 - q1 dq2) with G a random integer matrix, so that no single
 * one need be integrable: always 3 forms and 2 relations. */
static void test_closure_random(void **state) {
    static const char *names[] = {"q1", "q2", "q3", "q4", "q5"};
    sys *s = sys_new(state, 5, names);
    qd_ctx *ctx = s->ctx;
    const qd_expr *vars[6] = {s->q[0], s->q[1], s->q[2], s->q[3], s->q[4], qd_time(ctx)};
    const qd_expr *own[3] = {s->q[2], s->q[3], qd_time(ctx)};
    qt_rng r = {SEED};
    int ran = 0;
    for (int i = 0; i < 6; i++) {
        const qd_expr *th[3][6];
        for (int f = 0; f < 2; f++) {
            const qd_expr *phi = qt_random_expr(ctx, &r, own, 3, 3, QT_POLY | QT_TRIG);
            for (int j = 0; j < 6; j++)
                th[f][j] = qd_diff(ctx, phi, vars[j]);
        }
        for (int j = 0; j < 6; j++)
            th[2][j] = j == 4 ? I(s, 1) : j == 1 ? qd_neg(ctx, s->q[0]) : I(s, 0);
        long G[3][3];
        for (int k = 0; k < 9; k++)
            G[k / 3][k % 3] = (long)qt_uniform(&r, -3, 4);
        G[0][0] = G[1][1] = G[2][2] = 5; /* diagonally dominant: invertible */
        for (int k = 0; k < 3; k++) {
            const qd_expr *w[6];
            for (int j = 0; j < 6; j++) {
                w[j] = I(s, 0);
                for (int f = 0; f < 3; f++)
                    w[j] = qd_add(ctx, w[j], qd_mul(ctx, I(s, G[k][f]), th[f][j]));
            }
            con(s, (size_t)k, "random", w, w[5]);
        }
        if (qd_is_zero(th[0][2]) && qd_is_zero(th[0][3]))
            continue; /* phi1 of t alone: not a relation among the coordinates */
        if (qd_is_zero(th[1][2]) && qd_is_zero(th[1][3]))
            continue;
        size_t rank, rel;
        if (qd__mech_con_closure(ctx, 5, s->q, s->con, 3, &rank, &rel) != QD_OK)
            fail_msg("case %d (seed %u): %s", i, SEED, qd_ctx_message(ctx));
        if (rank != 3 || rel != 2)
            fail_msg("case %d (seed %u): %zu forms, %zu relations; expected 3 and 2", i, SEED,
                     rank, rel);
        ran++;
    }
    assert_true(ran >= 3);
}

/* ---- errors and properties -------------------------------------------------- */

static void test_no_velocity(void **state) {
    static const char *names[] = {"x"};
    sys *s = sys_new(state, 1, names);
    const qd_expr *w[1] = {I(s, 0)};
    qd_con *c = con(s, 0, "none", w, s->q[0]);
    assert_int_equal(qd__mech_con_classify(s->ctx, 1, s->q, c), QD_ERR_ARG);
}

/* Random phi(q, t) and g(q, t) > 0: g dphi is integrable (never called
 * nonholonomic), and with g = 1 the integral is found with factor 1. */
static void test_random_integrable(void **state) {
    static const char *names[] = {"q1", "q2", "q3"};
    sys *s = sys_new(state, 3, names);
    qd_ctx *ctx = s->ctx;
    const qd_expr *vars[4] = {s->q[0], s->q[1], s->q[2], qd_time(ctx)};
    qt_rng r = {SEED};
    for (int i = 0; i < 12; i++) {
        const qd_expr *phi = qt_random_expr(ctx, &r, vars, 4, 3, QT_POLY | QT_TRIG);
        const qd_expr *g = qd_add(ctx, I(s, 2), qd_fn(ctx, QD_SIN, qt_random_expr(ctx, &r, vars, 4, 2, QT_POLY)));
        bool scaled = i % 2;
        const qd_expr *w[3];
        for (int j = 0; j < 3; j++) {
            w[j] = qd_diff(ctx, phi, vars[j]);
            if (scaled)
                w[j] = qd_mul(ctx, g, w[j]);
        }
        const qd_expr *a0 = qd_diff(ctx, phi, vars[3]);
        if (scaled)
            a0 = qd_mul(ctx, g, a0);
        qd_con *c = con(s, 0, "random", w, a0);
        bool moves = !qd_is_zero(w[0]) || !qd_is_zero(w[1]) || !qd_is_zero(w[2]);
        if (!moves)
            continue;
        if (qd__mech_con_classify(ctx, 3, s->q, c) != QD_OK)
            fail_msg("case %d (seed %u): %s", i, SEED, qd_ctx_message(ctx));
        if (c->kind != QD_CON_INTEGRABLE)
            fail_msg("case %d (seed %u): g dphi called nonholonomic", i, SEED);
        if (!scaled)
            assert_true(qd_is_one(c->factor));
        if (c->integral)
            assert_integral(s, c);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(test_disk_on_line, teardown),
        cmocka_unit_test_teardown(test_time_dependent_exact, teardown),
        cmocka_unit_test_teardown(test_factor_quotient, teardown),
        cmocka_unit_test_teardown(test_factor_products, teardown),
        cmocka_unit_test_teardown(test_factor_with_time, teardown),
        cmocka_unit_test_teardown(test_factor_three_variables, teardown),
        cmocka_unit_test_teardown(test_y_z_x, teardown),
        cmocka_unit_test_teardown(test_time_nonholonomic, teardown),
        cmocka_unit_test_teardown(test_rolling_disk, teardown),
        cmocka_unit_test_teardown(test_axle, teardown),
        cmocka_unit_test_teardown(test_frobenius_system, teardown),
        cmocka_unit_test_teardown(test_closure_axle, teardown),
        cmocka_unit_test_teardown(test_closure_rolling_disk, teardown),
        cmocka_unit_test_teardown(test_closure_one_integrable, teardown),
        cmocka_unit_test_teardown(test_closure_split, teardown),
        cmocka_unit_test_teardown(test_closure_time, teardown),
        cmocka_unit_test_teardown(test_closure_random, teardown),
        cmocka_unit_test_teardown(test_closure_user_functions, teardown),
        cmocka_unit_test_teardown(test_no_velocity, teardown),
        cmocka_unit_test_teardown(test_random_integrable, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
