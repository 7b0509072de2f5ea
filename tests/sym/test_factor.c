/*
 * tests/sym/test_factor.c - polynomial factorization in the simplifier
 * (src/sym/factor_poly.c through qd_simplify).
 *
 * Known factorizations (perfect squares, a difference of squares, the same
 * with sines and cosines as generators), the heavy symmetric top's effective
 * potential against Desloge's form (Desloge, Classical Mechanics vol. 2,
 * ch. 64 Example 1; reference seed-desloge-B.md C10:
 * V_eff = (A/2)((alpha - beta cos th)/sin th)^2 + M g h cos th with
 * A alpha = p_phi, A beta = p_psi, plus the constant p_psi^2/(2C) that the
 * Routhian keeps), quotients whose numerator and denominator factor, and
 * random products of polynomials: simplify keeps the value at random points
 * and never makes an expression longer.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <time.h>

#include "qdot/qdot.h"
#include "util/randexpr.h"

static qd_ctx *ctx;

static int setup(void **state) {
    (void)state;
    ctx = qd_ctx_new();
    return ctx ? 0 : -1;
}

static int teardown(void **state) {
    (void)state;
    qd_ctx_free(ctx);
    return 0;
}

static const qd_expr *R(const char *text) {
    const qd_expr *e = qd_read(ctx, text, NULL, NULL);
    if (!e)
        fail_msg("cannot read %s", text);
    return e;
}

/* a and b agree at random points of their symbols (in (0.2, 1.2): clear of
 * the zeros of the denominators used here). */
static void assert_same_value(const qd_expr *a, const qd_expr *b, uint64_t seed) {
    const qd_expr *syms[32];
    size_t n = qd_free_symbols(ctx, qd_add(ctx, a, b), syms, 32);
    assert_true(n <= 32);
    qt_rng r = {seed};
    for (int k = 0; k < 5; k++) {
        double v[32], va, vb;
        for (size_t i = 0; i < n; i++)
            v[i] = qt_uniform(&r, 0.2, 1.2);
        assert_int_equal(qd_eval(ctx, a, n, syms, v, &va), QD_OK);
        assert_int_equal(qd_eval(ctx, b, n, syms, v, &vb), QD_OK);
        if (fabs(va - vb) > 1e-9 * (1 + fabs(va)))
            fail_msg("%.17g != %.17g", va, vb);
    }
}

/* simplify(in) is want, and shorter than in; the values compared when eval */
static void check_as(const char *in, const char *want, bool eval) {
    const qd_expr *e = R(in), *w = R(want), *s = qd_simplify(ctx, e);
    assert_non_null(s);
    if (s != w) {
        qd_buf b = QD_BUF_INIT;
        qd_print(ctx, s, QD_FMT_TEXT, &b);
        fail_msg("simplify(%s) = %s, expected %s", in, qd_buf_str(&b), want);
    }
    assert_true(qd_count_ops(s) < qd_count_ops(e));
    if (eval)
        assert_same_value(e, s, 7);
}

static void check(const char *in, const char *want) {
    check_as(in, want, true);
}

static void perfect_squares(void **state) {
    (void)state;
    check("a^2 - 2*a*b + b^2", "(a - b)^2");
    check("a^2 + 2*a*b + b^2", "(a + b)^2");
    check("4*x^2 + 12*x*y + 9*y^2", "(2*x + 3*y)^2");
    check("x^3 + 3*x^2*y + 3*x*y^2 + y^3", "(x + y)^3");
    /* with a rational content: (a - b)^2/2 */
    check("a^2/2 - a*b + b^2/2", "(a - b)^2/2");
    /* a sum that is already short is left alone */
    const qd_expr *e = R("a^2 + b^2");
    assert_ptr_equal(qd_simplify(ctx, e), e);
}

static void difference_of_squares(void **state) {
    (void)state;
    /* (x + y)^2 - z^2, expanded */
    check("x^2 + 2*x*y + y^2 - z^2", "(x + y - z)*(x + y + z)");
    /* a tie is not a gain: a^2 - b^2 stays (SymPy's count_ops: 3 against 3) */
    const qd_expr *e = R("a^2 - b^2");
    assert_ptr_equal(qd_simplify(ctx, e), e);
    /* but over a + b it cancels */
    check("(a^2 - b^2)/(a + b)", "a - b");
}

static void trig_generators(void **state) {
    (void)state;
    check("sin(x)^2 - 2*sin(x)*cos(y) + cos(y)^2", "(sin(x) - cos(y))^2");
    check("atan(x)^2 + 2*atan(x)*exp(y) + exp(y)^2", "(atan(x) + exp(y))^2");
    check("u^2*sqrt(y + 1) + 2*u*sqrt(y + 1)*cos(v) + sqrt(y + 1)*cos(v)^2",
          "sqrt(y + 1)*(u + cos(v))^2");
    /* user functions (no numeric value) */
    check_as("f(x)^2 - 2*f(x)*g(y) + g(y)^2 + 3", "3 + (f(x) - g(y))^2", false);
}

/* Partial factoring: the terms over one denominator, the rest as they are. */
static void partial(void **state) {
    (void)state;
    check("a^2 - 2*a*b + b^2 + c", "c + (a - b)^2");
    check("x^2/z + 2*x*y/z + y^2/z + w", "w + (x + y)^2/z");
    /* two groups, each a square over its own denominator */
    check("(a^2 + 2*a*b + b^2)/u + (c^2 - 2*c*d + d^2)/v", "(a + b)^2/u + (c - d)^2/v");
}

static void effective_potential(void **state) {
    (void)state;
    /* what the Routhian's velocity-free part expands to (qdot routh
     * examples/heavy_top.qd --ignore phi,psi, before factoring) */
    const qd_expr *e = R("-p_phi*p_psi*cos(theta)/(A*sin(theta)^2) + p_phi^2/(2*A*sin(theta)^2)"
                         " + p_psi^2*cos(theta)^2/(2*A*sin(theta)^2) + p_psi^2/(2*C)"
                         " + M*g*h*cos(theta)");
    /* Desloge's form with alpha = p_phi/A, beta = p_psi/A */
    const qd_expr *desloge = R("(A/2)*((p_phi/A - p_psi/A*cos(theta))/sin(theta))^2"
                               " + p_psi^2/(2*C) + M*g*h*cos(theta)");
    const qd_expr *textbook = R("(p_phi - p_psi*cos(theta))^2/(2*A*sin(theta)^2)"
                                " + p_psi^2/(2*C) + M*g*h*cos(theta)");
    assert_same_value(e, desloge, 11);
    const qd_expr *s = qd_simplify(ctx, e);
    assert_ptr_equal(s, textbook);
    assert_int_equal(qd_count_ops(s), qd_count_ops(textbook));
    assert_true(qd_count_ops(s) < qd_count_ops(e));
    assert_same_value(s, desloge, 12);
    /* and from Desloge's own form */
    s = qd_simplify(ctx, desloge);
    assert_true(qd_count_ops(s) <= qd_count_ops(textbook));
    assert_same_value(s, desloge, 13);
}

static void quotients(void **state) {
    (void)state;
    /* numerator and denominator factored apart, nothing in common */
    check("(a^2 + 2*a*b + b^2)/(c^2 - 2*c*d + d^2)", "(a + b)^2/(c - d)^2");
    /* a common factor cancelled, the rest of the numerator factored:
     * (x + 1)^2 (y - 2)/(x^2 - 1) = (x + 1)(y - 2)/(x - 1) */
    check("(x^2*y - 2*x^2 + 2*x*y - 4*x + y - 2)/(x^2 - 1)", "(x + 1)*(y - 2)/(x - 1)");
    /* a square in the denominator: 1/(x^2 - 2*x*y + y^2) */
    check("z/(x^2 - 2*x*y + y^2)", "z/(x - y)^2");
}

/* Random products of random polynomials, expanded and over random
 * denominators, plus random terms: simplify keeps the value and never makes
 * the expression longer. */
static void random_products(void **state) {
    (void)state;
    const qd_expr *syms[3] = {qd_symbol(ctx, "x"), qd_symbol(ctx, "y"), qd_symbol(ctx, "z")};
    qt_rng r = {2718};
    int shorter = 0;
    clock_t t0 = clock();
    for (int n = 0; n < 300; n++) {
        unsigned fl = n % 2 ? QT_POLY | QT_TRIG : QT_POLY;
        const qd_expr *u = qt_random_expr(ctx, &r, syms, 3, 2, fl);
        const qd_expr *v = qt_random_expr(ctx, &r, syms, 3, 2, fl);
        const qd_expr *w = qt_random_expr(ctx, &r, syms, 3, 2, QT_POLY);
        const qd_expr *p = qd_expand(ctx, qd_mul(ctx, qd_powi(ctx, u, 1 + (int)qt_below(&r, 2)), v));
        const qd_expr *den = qd_add(ctx, qd_int(ctx, 2), qd_powi(ctx, w, 2));
        const qd_expr *e = n % 3 == 0 ? p : qd_div(ctx, p, den);
        if (n % 4 == 1)
            e = qd_add(ctx, e, qt_random_expr(ctx, &r, syms, 3, 3, QT_POLY | QT_TRIG | QT_DIV));
        const qd_expr *s = qd_simplify(ctx, e);
        qd_buf b = QD_BUF_INIT;
        qd_print(ctx, e, QD_FMT_TEXT, &b);
        if (!s)
            fail_msg("case %d: simplify failed on %s: %s", n, qd_buf_str(&b), qd_ctx_message(ctx));
        size_t ne = qd_count_ops(e), ns = qd_count_ops(s);
        if (ns > ne)
            fail_msg("case %d: longer after simplify: %s", n, qd_buf_str(&b));
        shorter += ns < ne;
        for (int k = 0; k < 3; k++) {
            double val[3], ve, vs;
            for (int i = 0; i < 3; i++)
                val[i] = qt_uniform(&r, -1, 1);
            if (qd_eval(ctx, e, 3, syms, val, &ve) != QD_OK || !isfinite(ve))
                continue;
            assert_int_equal(qd_eval(ctx, s, 3, syms, val, &vs), QD_OK);
            if (fabs(ve - vs) > 1e-8 * (1 + fabs(ve)))
                fail_msg("case %d: %.17g != %.17g for %s", n, ve, vs, qd_buf_str(&b));
        }
        qd_buf_free(&b);
    }
    print_message("random products: %d of 300 shorter, %.1f ms\n", shorter,
                  1e3 * (double)(clock() - t0) / CLOCKS_PER_SEC);
    assert_true(shorter > 100);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(perfect_squares),
        cmocka_unit_test(difference_of_squares),
        cmocka_unit_test(trig_generators),
        cmocka_unit_test(partial),
        cmocka_unit_test(effective_potential),
        cmocka_unit_test(quotients),
        cmocka_unit_test(random_products),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
