/*
 * tests/mech/test_isolate.c - solving for an unknown that enters
 * nonlinearly (src/mech/isolate.c), as the relations of a generating
 * function need (Goldstein ch. 9).
 *
 * The property: for e(y) built by a random chain of invertible steps, the
 * solution y* of e(y) = r satisfies e(y*) = r at r = e(y0) for random y0
 * and parameters: a principal branch may give another y than y0 (sqrt of a
 * square), or none at all where y0 lies on another branch (sin(2 + y^2) = r
 * asks for pi - asin(r)), never a wrong one.  Plus the shapes the reductions
 * exist for.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>

#include "qdot/qdot.h"
#include "qdot/print.h"
#include "mech/mech.h"
#include "util/randexpr.h"

#define SEED 7211u
#define CASES 300

/* e as text, for a message (one buffer: one call per message). */
static const char *text(qd_ctx *ctx, const qd_expr *e) {
    static char out[512];
    qd_buf b = QD_BUF_INIT;
    qd_print(ctx, e, QD_FMT_TEXT, &b);
    snprintf(out, sizeof out, "%s", b.failed ? "?" : qd_buf_str(&b));
    qd_buf_free(&b);
    return out;
}

/* e(y) and r at y = y0, a = av: does e(sol) = r?  false when sol has no
 * real value there (another branch), or e(y0) none. */
static bool assert_solves(qd_ctx *ctx, const qd_expr *e, const qd_expr *y, double y0, double av,
                          int which) {
    const qd_expr *r = qd_symbol(ctx, "r"), *a = qd_param(ctx, "a"), *sol;
    const qd_expr *syms[3] = {y, a, r};
    double vals[3] = {y0, av, 0}, rv, back;
    if (qd_eval(ctx, e, 3, syms, vals, &rv) != QD_OK || !isfinite(rv) || fabs(rv) > 1e6) {
        qd_ctx_clear_error(ctx);
        return false;
    }
    const qd_expr *eq = qd_sub(ctx, e, r);
    size_t failed;
    if (qd__mech_isolate(ctx, 1, &eq, &y, &sol, &failed) != QD_OK)
        fail_msg("case %d (seed %u): no solution of %s = r: %s", which, SEED, text(ctx, e),
                 qd_ctx_message(ctx));
    assert_false(qd_has(sol, y));
    vals[2] = rv;
    if (qd_eval(ctx, qd_subs(ctx, e, 1, &y, &sol), 3, syms, vals, &back) != QD_OK ||
        isnan(back)) {
        qd_ctx_clear_error(ctx);
        return false;
    }
    if (!(fabs(back - rv) <= 1e-8 * (1 + fabs(rv))))
        fail_msg("case %d (seed %u): e = %s: e(y*) = %.17g, r = %.17g", which, SEED,
                 text(ctx, e), back, rv);
    return true;
}

/* One invertible step applied to x (a the parameter, y the unknown). */
static const qd_expr *step(qd_ctx *ctx, qt_rng *g, const qd_expr *x) {
    const qd_expr *a = qd_param(ctx, "a"), *k = qd_rat(ctx, (long)qt_below(g, 5) + 1, 3);
    switch (qt_below(g, 10)) {
    case 0: return qd_add(ctx, x, qd_mul(ctx, k, a));
    case 1: return qd_mul(ctx, qd_add(ctx, qd_powi(ctx, a, 2), k), x);
    case 2: return qd_powi(ctx, x, 3);
    case 3: return qd_add(ctx, qd_powi(ctx, x, 2), k); /* then positive: a log may follow */
    case 4: return qd_fn(ctx, QD_SIN, x);
    case 5: return qd_fn(ctx, QD_ATAN, x);
    case 6: return qd_fn(ctx, QD_EXP, qd_mul(ctx, k, x));
    case 7: return qd_fn(ctx, QD_SINH, x);
    case 8: return qd_powi(ctx, x, -1);
    default: return qd_fn(ctx, QD_LOG, qd_add(ctx, qd_powi(ctx, x, 2), k));
    }
}

static void test_random_chains(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *y = qd_symbol(ctx, "y");
    qt_rng g = {SEED};
    int checked = 0;
    for (int i = 0; i < CASES; i++) {
        const qd_expr *e = y;
        for (unsigned d = qt_below(&g, 4) + 1; d > 0; d--)
            e = step(ctx, &g, e);
        checked += assert_solves(ctx, e, y, qt_uniform(&g, -1.2, 1.2), qt_uniform(&g, 0.3, 1.7), i);
    }
    if (checked < CASES * 8 / 10) /* principal branches hold the value most of the time */
        fail_msg("only %d of %d cases had a real solution to check", checked, CASES);
    qd_ctx_free(ctx);
}

/* The reductions: cot as cos/sin (the oscillator's p = m w q cot Q), a
 * repeated subexpression (e^y twice), an odd power, several equations one
 * unknown at a time; and what stays unsolved (Lambert's y + e^y). */
static void test_shapes(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *y = qd_symbol(ctx, "y"), *a = qd_param(ctx, "a");
    const qd_expr *cot = qd_div(ctx, qd_fn(ctx, QD_COS, y), qd_fn(ctx, QD_SIN, y));
    assert_true(assert_solves(ctx, qd_mul(ctx, a, cot), y, 0.7, 1.3, -1));
    const qd_expr *ey = qd_fn(ctx, QD_EXP, y);
    const qd_expr *twice = qd_add(ctx, qd_mul(ctx, ey, qd_fn(ctx, QD_SIN, a)),
                                  qd_mul(ctx, qd_int(ctx, 3), qd_mul(ctx, a, ey)));
    assert_true(assert_solves(ctx, twice, y, -0.4, 0.9, -2));
    /* an odd power of a negative value: the real cube root, not r^(1/3) */
    assert_true(assert_solves(ctx, qd_add(ctx, qd_powi(ctx, qd_sub(ctx, y, a), 3), a), y, -0.8,
                              0.5, -3));
    /* tan(y) with 1/cos(y)^2 is not a ratio, y + e^y has no closed form */
    const qd_expr *bad[2] = {qd_add(ctx, qd_fn(ctx, QD_TAN, y),
                                    qd_powi(ctx, qd_fn(ctx, QD_COS, y), -2)),
                             qd_add(ctx, y, ey)};
    for (int k = 0; k < 2; k++) {
        const qd_expr *sol;
        size_t failed = 9;
        assert_int_equal(qd__mech_isolate(ctx, 1, &bad[k], &y, &sol, &failed), QD_ERR_NONLINEAR);
        assert_int_equal(failed, 0);
        assert_int_equal(qd_ctx_status(ctx), QD_OK);
    }
    /* x^3 + y = 2, e^x = 3: x = log 3 from the second, then y */
    const qd_expr *x = qd_symbol(ctx, "x"), *xs[2] = {y, x}, *sols[2];
    const qd_expr *eqs[2] = {qd_sub(ctx, qd_add(ctx, qd_powi(ctx, x, 3), y), qd_int(ctx, 2)),
                             qd_sub(ctx, qd_fn(ctx, QD_EXP, x), qd_int(ctx, 3))};
    size_t failed;
    assert_int_equal(qd__mech_isolate(ctx, 2, eqs, xs, sols, &failed), QD_OK);
    double vy, vx;
    assert_int_equal(qd_eval(ctx, sols[0], 0, NULL, NULL, &vy), QD_OK);
    assert_int_equal(qd_eval(ctx, sols[1], 0, NULL, NULL, &vx), QD_OK);
    assert_true(fabs(vx - log(3.0)) < 1e-14);
    assert_true(fabs(vy - (2 - pow(log(3.0), 3))) < 1e-13);
    qd_ctx_free(ctx);
}

/* Coupled equations, none with a single unknown: the harmonic oscillator's
 * action-angle map (Desloge ch. 76 P7, seed-desloge-C.md T39, C = 1:
 * Q = atan(q/p), P = (p^2 + q^2)/2) inverted to q = sqrt(2P) sin Q,
 * p = sqrt(2P) cos Q on the principal branch (p > 0); and a pair that
 * stays unsolved (x + e^y = 0, y + e^x = 0: Lambert again), ctx clean. */
static void test_coupled(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *q = qd_symbol(ctx, "q"), *p = qd_symbol(ctx, "p");
    const qd_expr *Q = qd_symbol(ctx, "Q"), *P = qd_symbol(ctx, "P");
    const qd_expr *two = qd_int(ctx, 2), *xs[2] = {q, p}, *sols[2];
    const qd_expr *eqs[2] = {
        qd_sub(ctx, qd_fn(ctx, QD_ATAN, qd_div(ctx, q, p)), Q),
        qd_sub(ctx, qd_div(ctx, qd_add(ctx, qd_powi(ctx, p, 2), qd_powi(ctx, q, 2)), two), P)};
    size_t failed = 9;
    assert_int_equal(qd__mech_isolate(ctx, 2, eqs, xs, sols, &failed), QD_OK);
    static const double at[][2] = {{0.3, 0.5}, {-1.2, 2.0}, {1.4, 0.01}};
    for (size_t k = 0; k < 3; k++) {
        const qd_expr *syms[2] = {Q, P};
        double v[2] = {at[k][0], at[k][1]}, gq, gp;
        assert_false(qd_has(sols[0], q) || qd_has(sols[0], p));
        assert_false(qd_has(sols[1], q) || qd_has(sols[1], p));
        assert_int_equal(qd_eval(ctx, sols[0], 2, syms, v, &gq), QD_OK);
        assert_int_equal(qd_eval(ctx, sols[1], 2, syms, v, &gp), QD_OK);
        if (!(fabs(gq - sqrt(2 * v[1]) * sin(v[0])) < 1e-13 &&
              fabs(gp - sqrt(2 * v[1]) * cos(v[0])) < 1e-13))
            fail_msg("Q = %g, P = %g: q = %s = %.17g, p = %s", v[0], v[1], text(ctx, sols[0]), gq,
                     text(ctx, sols[1]));
    }
    const qd_expr *x = qd_symbol(ctx, "x"), *y = qd_symbol(ctx, "y"), *ys[2] = {x, y};
    const qd_expr *lam[2] = {qd_add(ctx, x, qd_fn(ctx, QD_EXP, y)),
                             qd_add(ctx, y, qd_fn(ctx, QD_EXP, x))};
    assert_int_equal(qd__mech_isolate(ctx, 2, lam, ys, sols, &failed), QD_ERR_NONLINEAR);
    assert_int_equal(qd_ctx_status(ctx), QD_OK);
    qd_ctx_free(ctx);
}

/* sin, cos, tan of asin, acos, atan written without the inverse: equal
 * values on the principal domains. */
static void test_untrig(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *u = qd_symbol(ctx, "u");
    static const qd_func f[3] = {QD_SIN, QD_COS, QD_TAN}, g[3] = {QD_ASIN, QD_ACOS, QD_ATAN};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            const qd_expr *e = qd_fn(ctx, f[i], qd_fn(ctx, g[j], u));
            const qd_expr *plain = qd__mech_untrig(ctx, e);
            assert_false(qd_has(plain, qd_fn(ctx, g[j], u)));
            static const double at[] = {-0.9, -0.55, -0.2, 0.25, 0.6, 0.85}; /* not 0: tan(acos) */
            for (size_t k = 0; k < sizeof at / sizeof at[0]; k++) {
                double v = at[k];
                double want, got;
                assert_int_equal(qd_eval(ctx, e, 1, &u, &v, &want), QD_OK);
                assert_int_equal(qd_eval(ctx, plain, 1, &u, &v, &got), QD_OK);
                if (!(fabs(want - got) < 1e-12 * (1 + fabs(want))))
                    fail_msg("%s at u = %g: %.17g, written %s: %.17g", qd_func_name(f[i]), v, want,
                             text(ctx, plain), got);
            }
        }
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_random_chains),
        cmocka_unit_test(test_shapes),
        cmocka_unit_test(test_coupled),
        cmocka_unit_test(test_untrig),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
