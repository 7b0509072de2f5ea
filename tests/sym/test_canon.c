/*
 * tests/sym/test_canon.c - canonical forms and hash-consing.
 *
 * Each test builds the same mathematical value two ways and asserts one node
 * (pointer equality), or checks a folding rule against exact arithmetic.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "qdot/qdot.h"
#include "util/randexpr.h"

#define PI 3.14159265358979323846

typedef struct fix {
    qd_ctx *ctx;
    const qd_expr *x, *y, *z;
} fix;

static int setup(void **state) {
    static fix f;
    f.ctx = qd_ctx_new();
    f.x = qd_symbol(f.ctx, "x");
    f.y = qd_symbol(f.ctx, "y");
    f.z = qd_symbol(f.ctx, "z");
    *state = &f;
    return f.ctx ? 0 : -1;
}

static int teardown(void **state) {
    qd_ctx_free(((fix *)*state)->ctx);
    return 0;
}

#define C (((fix *)*state)->ctx)
#define X (((fix *)*state)->x)
#define Y (((fix *)*state)->y)
#define Z (((fix *)*state)->z)
#define I(n) qd_int(C, n)

static void hash_consing(void **state) {
    assert_ptr_equal(qd_add(C, X, Y), qd_add(C, Y, X));
    assert_ptr_equal(qd_mul(C, qd_add(C, X, Y), Z), qd_mul(C, Z, qd_add(C, Y, X)));
    assert_ptr_equal(qd_fn(C, QD_SIN, X), qd_fn(C, QD_SIN, X));
    assert_ptr_equal(qd_symbol(C, "x"), X);
    assert_ptr_equal(qd_rat(C, 6, 4), qd_rat(C, 3, 2));
    assert_ptr_equal(qd_rat(C, -6, -4), qd_rat(C, 3, 2));
    assert_ptr_equal(qd_float(C, -0.0), qd_float(C, 0.0));
    assert_ptr_not_equal(qd_float(C, 1.0), I(1)); /* inexact and exact stay distinct */
}

static void sums(void **state) {
    /* like terms combine, constants fold, zero terms vanish */
    assert_ptr_equal(qd_add(C, X, X), qd_mul(C, I(2), X));
    assert_ptr_equal(qd_sub(C, X, X), I(0));
    assert_ptr_equal(qd_add_n(C, 3, (const qd_expr *[]){I(1), X, I(2)}), qd_add(C, X, I(3)));
    const qd_expr *s = qd_add_n(C, 3, (const qd_expr *[]){X, Y, Z});
    assert_ptr_equal(qd_add(C, qd_add(C, X, Y), Z), s);
    assert_ptr_equal(qd_add(C, X, qd_add(C, Z, Y)), s);
    assert_int_equal(qd_expr_kind(s), QD_ADD);
    assert_int_equal(qd_expr_nargs(s), 3);
    /* 3xy - 3yx = 0 */
    const qd_expr *xy = qd_mul(C, X, Y);
    assert_ptr_equal(qd_sub(C, qd_mul(C, I(3), xy), qd_mul(C, qd_mul(C, Y, I(3)), X)), I(0));
    /* a rational times a single sum is distributed */
    assert_ptr_equal(qd_mul(C, I(2), qd_add(C, X, Y)),
                     qd_add(C, qd_mul(C, I(2), X), qd_mul(C, I(2), Y)));
    /* a symbol times a sum stays a product */
    assert_int_equal(qd_expr_kind(qd_mul(C, Z, qd_add(C, X, Y))), QD_MUL);
}

static void products(void **state) {
    assert_ptr_equal(qd_mul(C, X, X), qd_powi(C, X, 2));
    assert_ptr_equal(qd_mul(C, X, qd_powi(C, X, -1)), I(1));
    assert_ptr_equal(qd_div(C, qd_mul(C, X, Y), X), Y);
    assert_ptr_equal(qd_mul(C, qd_powi(C, X, 2), qd_powi(C, X, 3)), qd_powi(C, X, 5));
    assert_ptr_equal(qd_mul(C, I(0), X), I(0));
    assert_ptr_equal(qd_mul(C, qd_sqrt(C, X), qd_sqrt(C, X)), X);
    assert_ptr_equal(qd_mul(C, qd_sqrt(C, I(2)), qd_sqrt(C, I(2))), I(2));
    /* symbolic exponents add */
    const qd_expr *a = qd_symbol(C, "a");
    assert_ptr_equal(qd_mul(C, qd_pow(C, X, a), qd_pow(C, X, Y)), qd_pow(C, X, qd_add(C, a, Y)));
    /* the order is structural: the same whatever the construction order */
    assert_ptr_equal(qd_mul_n(C, 3, (const qd_expr *[]){Z, X, Y}),
                     qd_mul_n(C, 3, (const qd_expr *[]){Y, Z, X}));
}

static void powers(void **state) {
    assert_ptr_equal(qd_pow(C, I(4), qd_rat(C, 1, 2)), I(2));
    assert_ptr_equal(qd_pow(C, qd_rat(C, 8, 27), qd_rat(C, 2, 3)), qd_rat(C, 4, 9));
    assert_ptr_equal(qd_powi(C, I(2), -3), qd_rat(C, 1, 8));
    assert_int_equal(qd_expr_kind(qd_sqrt(C, I(2))), QD_POW);
    assert_ptr_equal(qd_powi(C, X, 0), I(1));
    assert_ptr_equal(qd_powi(C, X, 1), X);
    /* (2xy)^3 = 8 x^3 y^3 and (x^2)^3 = x^6 for integer exponents */
    assert_ptr_equal(qd_powi(C, qd_mul_n(C, 3, (const qd_expr *[]){I(2), X, Y}), 3),
                     qd_mul_n(C, 3, (const qd_expr *[]){I(8), qd_powi(C, X, 3), qd_powi(C, Y, 3)}));
    assert_ptr_equal(qd_powi(C, qd_powi(C, X, 2), 3), qd_powi(C, X, 6));
    /* but (x^2)^(1/2) is |x|, not x (symbols are real of either sign) */
    assert_ptr_equal(qd_sqrt(C, qd_powi(C, X, 2)), qd_fn(C, QD_ABS, X));
    /* exact big numbers: 3^200 never overflows */
    const qd_expr *big = qd_powi(C, I(3), 200);
    assert_non_null(big);
    assert_ptr_equal(qd_mul(C, big, qd_powi(C, I(3), -200)), I(1));
    assert_true(strlen(qd_rational_str(C, big)) == 96); /* 3^200 has 96 digits */
    /* 0^-1 is an error, reported in the context */
    assert_null(qd_powi(C, I(0), -1));
    assert_int_equal(qd_ctx_status(C), QD_ERR_DIVZERO);
    qd_ctx_clear_error(C);
    assert_null(qd_div(C, X, I(0)));
    qd_ctx_clear_error(C);
}

static void numbers(void **state) {
    assert_ptr_equal(qd_rat_str(C, "2.5"), qd_rat(C, 5, 2));
    assert_ptr_equal(qd_rat_str(C, "-3/4"), qd_rat(C, -3, 4));
    assert_ptr_equal(qd_rat_str(C, "1e-3"), qd_rat(C, 1, 1000));
    assert_ptr_equal(qd_rat_str(C, "1.5E+2"), I(150));
    assert_null(qd_rat_str(C, "1.2.3"));
    qd_ctx_clear_error(C);
    assert_null(qd_rat_str(C, "3/0"));
    qd_ctx_clear_error(C);
    /* exact + float = float */
    const qd_expr *f = qd_add(C, qd_rat(C, 1, 2), qd_float(C, 0.25));
    assert_int_equal(qd_expr_kind(f), QD_FLOAT);
    assert_true(qd_number_value(f) == 0.75);
    assert_null(qd_float(C, NAN));
    qd_ctx_clear_error(C);
    long n, d;
    assert_true(qd_rational_get(qd_rat(C, -10, 4), &n, &d));
    assert_int_equal(n, -5);
    assert_int_equal(d, 2);
}

static void functions(void **state) {
    const qd_expr *pi = qd_const(C, QD_PI);
    assert_ptr_equal(qd_fn(C, QD_SIN, I(0)), I(0));
    assert_ptr_equal(qd_fn(C, QD_COS, I(0)), I(1));
    assert_ptr_equal(qd_fn(C, QD_SIN, pi), I(0));
    assert_ptr_equal(qd_fn(C, QD_COS, pi), I(-1));
    assert_ptr_equal(qd_fn(C, QD_SIN, qd_mul(C, qd_rat(C, 3, 2), pi)), I(-1));
    assert_ptr_equal(qd_fn(C, QD_COS, qd_mul(C, qd_rat(C, 1, 2), pi)), I(0));
    assert_ptr_equal(qd_fn(C, QD_EXP, I(0)), I(1));
    assert_ptr_equal(qd_fn(C, QD_LOG, I(1)), I(0));
    assert_ptr_equal(qd_fn(C, QD_LOG, qd_const(C, QD_E)), I(1));
    assert_ptr_equal(qd_fn(C, QD_LOG, qd_fn(C, QD_EXP, X)), X);
    assert_ptr_equal(qd_fn(C, QD_ABS, I(-3)), I(3));
    /* parity: sin(-x) = -sin(x), cos(y - x) = cos(x - y) */
    assert_ptr_equal(qd_fn(C, QD_SIN, qd_neg(C, X)), qd_neg(C, qd_fn(C, QD_SIN, X)));
    assert_ptr_equal(qd_fn(C, QD_COS, qd_sub(C, Y, X)), qd_fn(C, QD_COS, qd_sub(C, X, Y)));
    assert_ptr_equal(qd_fn(C, QD_SIN, qd_sub(C, Y, X)),
                     qd_neg(C, qd_fn(C, QD_SIN, qd_sub(C, X, Y))));
    /* a float argument is evaluated */
    const qd_expr *s = qd_fn(C, QD_SIN, qd_float(C, 0.5));
    assert_int_equal(qd_expr_kind(s), QD_FLOAT);
    assert_true(qd_number_value(s) == sin(0.5));
    assert_null(qd_fn(C, QD_LOG, I(0)));
    qd_ctx_clear_error(C);
    assert_null(qd_fn(C, QD_ATAN2, X)); /* needs two arguments */
    qd_ctx_clear_error(C);
}

static double value(void **state, const qd_expr *e, double x, double y) {
    const qd_expr *syms[2] = {X, Y};
    double vals[2] = {x, y}, out = NAN;
    assert_int_equal(qd_eval(C, e, 2, syms, vals, &out), QD_OK);
    return out;
}

static const qd_expr *times_pi(void **state, long num, long den) {
    return qd_mul(C, qd_rat(C, num, den), qd_const(C, QD_PI));
}

/* sin, cos, tan at k pi/n for n = 1, 2, 3, 4, 6 in every quadrant (and
 * beyond a period, and negative): exact values with no function left, equal
 * to libm's; tan at odd multiples of pi/2 has no value and stays a call. */
static void trig_exact_values(void **state) {
    static const long dens[5] = {1, 2, 3, 4, 6};
    static const qd_func fs[3] = {QD_SIN, QD_COS, QD_TAN};
    for (int i = 0; i < 5; i++)
        for (long k = -3 * dens[i]; k <= 3 * dens[i]; k++)
            for (int j = 0; j < 3; j++) {
                double a = PI * (double)k / (double)dens[i];
                bool pole = fs[j] == QD_TAN && 2 * k % dens[i] == 0 && (2 * k / dens[i]) % 2;
                const qd_expr *v = qd_fn(C, fs[j], times_pi(state, k, dens[i]));
                assert_non_null(v);
                if (pole) {
                    assert_int_equal(qd_expr_kind(v), QD_FUNC);
                    continue;
                }
                double want = fs[j] == QD_SIN ? sin(a) : fs[j] == QD_COS ? cos(a) : tan(a);
                if (qd_has(v, qd_const(C, QD_PI)) || fabs(value(state, v, 0, 0) - want) > 1e-14)
                    fail_msg("%s(%ld*pi/%ld) = %g, want %.17g", qd_func_name(fs[j]), k, dens[i],
                             value(state, v, 0, 0), want);
            }
    /* the values, as nodes: sin(pi/6) = 1/2, cos(pi/6) = sqrt(3)/2, ... */
    const qd_expr *half = qd_rat(C, 1, 2);
    assert_ptr_equal(qd_fn(C, QD_SIN, times_pi(state, 1, 6)), half);
    assert_ptr_equal(qd_fn(C, QD_COS, times_pi(state, 1, 6)), qd_mul(C, half, qd_sqrt(C, I(3))));
    assert_ptr_equal(qd_fn(C, QD_SIN, times_pi(state, 1, 4)), qd_mul(C, half, qd_sqrt(C, I(2))));
    assert_ptr_equal(qd_fn(C, QD_TAN, times_pi(state, 1, 3)), qd_sqrt(C, I(3)));
    /* other denominators reduce to the first quadrant: sin(7 pi/5) = -sin(2 pi/5) */
    assert_ptr_equal(qd_fn(C, QD_SIN, times_pi(state, 7, 5)),
                     qd_neg(C, qd_fn(C, QD_SIN, times_pi(state, 2, 5))));
    assert_ptr_equal(qd_fn(C, QD_COS, times_pi(state, 5, 7)),
                     qd_neg(C, qd_fn(C, QD_COS, times_pi(state, 2, 7))));
    assert_ptr_equal(qd_fn(C, QD_TAN, times_pi(state, -3, 5)), qd_fn(C, QD_TAN, times_pi(state, 2, 5)));
}

/* Whole quarter turns come out of a sum's pi term: sin(x + 2 pi) = sin x,
 * sin(pi - x) = sin x, sin(x + pi/2) = cos x, cos(pi/2 - th) = sin th, and
 * every shift k pi/12 keeps the value (checked at two points). */
static void trig_shifts(void **state) {
    const qd_expr *pi = qd_const(C, QD_PI), *sx = qd_fn(C, QD_SIN, X), *cx = qd_fn(C, QD_COS, X);
    const qd_expr *half_pi = times_pi(state, 1, 2);
    assert_ptr_equal(qd_fn(C, QD_SIN, qd_add(C, X, times_pi(state, 2, 1))), sx);
    assert_ptr_equal(qd_fn(C, QD_SIN, qd_sub(C, pi, X)), sx);
    assert_ptr_equal(qd_fn(C, QD_SIN, qd_add(C, X, half_pi)), cx);
    assert_ptr_equal(qd_fn(C, QD_SIN, qd_sub(C, half_pi, X)), cx);
    assert_ptr_equal(qd_fn(C, QD_COS, qd_sub(C, half_pi, Y)), qd_fn(C, QD_SIN, Y));
    assert_ptr_equal(qd_fn(C, QD_COS, qd_add(C, X, pi)), qd_neg(C, cx));
    assert_ptr_equal(qd_fn(C, QD_SIN, qd_sub(C, X, half_pi)), qd_neg(C, cx));
    assert_ptr_equal(qd_fn(C, QD_TAN, qd_add(C, X, pi)), qd_fn(C, QD_TAN, X));
    assert_ptr_equal(qd_fn(C, QD_TAN, qd_add(C, X, half_pi)),
                     qd_neg(C, qd_powi(C, qd_fn(C, QD_TAN, X), -1)));
    /* through a product: sin(2 (x + pi/4)) = cos(2 x) */
    assert_ptr_equal(qd_fn(C, QD_SIN, qd_mul(C, I(2), qd_add(C, X, times_pi(state, 1, 4)))),
                     qd_fn(C, QD_COS, qd_mul(C, I(2), X)));
    static const qd_func fs[3] = {QD_SIN, QD_COS, QD_TAN};
    for (long k = -30; k <= 30; k++)
        for (int j = 0; j < 3; j++) {
            const qd_expr *arg = qd_add_n(C, 3, (const qd_expr *[]){I(1), qd_sub(C, X, Y),
                                                                    times_pi(state, k, 12)});
            const qd_expr *v = qd_fn(C, fs[j], arg);
            for (int pt = 0; pt < 2; pt++) {
                double x = pt ? -1.3 : 0.37, y = pt ? 0.4 : 2.1, a = 1 + x - y + PI * k / 12.0;
                double want = fs[j] == QD_SIN ? sin(a) : fs[j] == QD_COS ? cos(a) : tan(a);
                double got = value(state, v, x, y);
                if (fabs(got - want) > 1e-12 * (1 + fabs(want)))
                    fail_msg("%s(1 + x - y + %ld pi/12) at x = %g: %.17g, want %.17g",
                             qd_func_name(fs[j]), k, x, got, want);
            }
        }
}

/* Fractional powers of powers and products, for real symbols:
 * sqrt(9 a^6 g^2 m^4) = 3 |a|^3 |g| m^2 (the example). */
static void real_roots(void **state) {
    const qd_expr *a = qd_symbol(C, "a"), *g = qd_symbol(C, "g"), *m = qd_symbol(C, "m");
    const qd_expr *radicand =
        qd_mul_n(C, 4, (const qd_expr *[]){I(9), qd_powi(C, a, 6), qd_powi(C, g, 2), qd_powi(C, m, 4)});
    const qd_expr *want = qd_mul_n(C, 4, (const qd_expr *[]){I(3), qd_powi(C, qd_fn(C, QD_ABS, a), 3),
                                                             qd_fn(C, QD_ABS, g), qd_powi(C, m, 2)});
    assert_ptr_equal(qd_sqrt(C, radicand), want);
    const qd_expr *ax = qd_fn(C, QD_ABS, X);
    assert_ptr_equal(qd_sqrt(C, qd_powi(C, X, 4)), qd_powi(C, X, 2));
    assert_ptr_equal(qd_powi(C, ax, 2), qd_powi(C, X, 2));               /* |x|^2 = x^2 */
    assert_ptr_equal(qd_fn(C, QD_ABS, qd_powi(C, X, 2)), qd_powi(C, X, 2)); /* |x^2| = x^2 */
    const qd_expr *one_x2 = qd_add(C, I(1), qd_powi(C, X, 2));
    assert_ptr_equal(qd_fn(C, QD_ABS, one_x2), one_x2);                   /* |1 + x^2| */
    assert_ptr_equal(qd_sqrt(C, qd_mul(C, I(4), Y)), qd_mul(C, I(2), qd_sqrt(C, Y)));
    assert_ptr_equal(qd_pow(C, qd_mul(C, I(9), qd_powi(C, X, 2)), qd_rat(C, 3, 2)),
                     qd_mul(C, I(27), qd_powi(C, ax, 3)));
    /* what has no known sign stays under the root: sqrt(2 x y), sqrt(x^3) */
    assert_int_equal(qd_expr_kind(qd_sqrt(C, qd_mul_n(C, 3, (const qd_expr *[]){I(2), X, Y}))), QD_POW);
    assert_int_equal(qd_expr_kind(qd_sqrt(C, qd_powi(C, X, 3))), QD_POW);
    /* (-x^2)^(1/3) stays: splitting it would leave (-1)^(1/3), which folds to
     * the real cube root -1, not the principal root SymPy means (the
     * cross-check in tests/cross/check_kernel.py found this) */
    const qd_expr *neg_sq = qd_neg(C, qd_powi(C, X, 2));
    assert_ptr_equal(qd_expr_arg(qd_pow(C, neg_sq, qd_rat(C, 1, 3)), 0), neg_sq);
    /* the value is kept at negative points: sqrt(x^2 y), (x^6 y^2)^(1/3), 1/sqrt(9 x^2) */
    const qd_expr *cases[3] = {
        qd_sqrt(C, qd_mul(C, qd_powi(C, X, 2), Y)),
        qd_pow(C, qd_mul(C, qd_powi(C, X, 6), qd_powi(C, Y, 2)), qd_rat(C, 1, 3)),
        qd_pow(C, qd_mul(C, I(9), qd_powi(C, X, 2)), qd_rat(C, -1, 2))};
    const double x = -1.7, y = 0.6;
    const double want3[3] = {sqrt(x * x * y), cbrt(pow(x, 6) * y * y), 1 / sqrt(9 * x * x)};
    for (int i = 0; i < 3; i++)
        assert_true(fabs(value(state, cases[i], x, y) - want3[i]) < 1e-14 * fabs(want3[i]));
}

/* Symbols assumed positive (SymPy's positive=True): |m| = m, and the
 * issue's root comes out without bars, 3 a^3 g m^2. */
static void positive_symbols(void **state) {
    const qd_expr *a = qd_symbol_positive(C, "a", QD_ROLE_PLAIN);
    const qd_expr *g = qd_symbol_positive(C, "g", QD_ROLE_PARAM);
    const qd_expr *m = qd_symbol_positive(C, "m", QD_ROLE_PARAM);
    assert_non_null(a);
    assert_true(qd_symbol_is_positive(g) && !qd_symbol_is_positive(X));
    assert_ptr_equal(qd_param(C, "g"), g);             /* found by name */
    assert_ptr_equal(qd_symbol_positive(C, "g", QD_ROLE_PARAM), g);
    assert_ptr_equal(qd_fn(C, QD_ABS, m), m);
    assert_ptr_equal(qd_fn(C, QD_ABS, qd_neg(C, m)), m);
    const qd_expr *radicand =
        qd_mul_n(C, 4, (const qd_expr *[]){I(9), qd_powi(C, a, 6), qd_powi(C, g, 2), qd_powi(C, m, 4)});
    assert_ptr_equal(qd_sqrt(C, radicand),
                     qd_mul_n(C, 4, (const qd_expr *[]){I(3), qd_powi(C, a, 3), g, qd_powi(C, m, 2)}));
    /* (m^3)^(1/2) = m^(3/2) for m > 0 */
    assert_ptr_equal(qd_sqrt(C, qd_powi(C, m, 3)), qd_pow(C, m, qd_rat(C, 3, 2)));
    /* the assumption cannot be added to a symbol already made */
    assert_null(qd_symbol_positive(C, "x", QD_ROLE_PLAIN));
    assert_int_equal(qd_ctx_status(C), QD_ERR_ARG);
    qd_ctx_clear_error(C);
    assert_null(qd_symbol_positive(C, "theta", QD_ROLE_COORD));
    qd_ctx_clear_error(C);
}

static void symbols(void **state) {
    const qd_expr *q = qd_coord(C, "theta");
    const qd_expr *qd = qd_jet(C, q, 1), *qdd = qd_jet(C, q, 2);
    assert_string_equal(qd_expr_name(qd), "theta'");
    assert_string_equal(qd_expr_name(qdd), "theta''");
    assert_ptr_equal(qd_jet(C, q, 2), qdd);
    assert_ptr_equal(qd_jet(C, qd, 2), qdd); /* the order counts from the coordinate */
    assert_ptr_equal(qd_symbol_coord(qdd), q);
    assert_int_equal(qd_symbol_order(qdd), 2);
    assert_ptr_equal(qd_lookup(C, "theta''"), qdd);
    assert_null(qd_lookup(C, "nothing"));
    assert_int_equal(qd_symbol_role(qd_time(C)), QD_ROLE_TIME);
    /* one name, one role */
    assert_null(qd_param(C, "theta"));
    assert_int_equal(qd_ctx_status(C), QD_ERR_ARG);
    qd_ctx_clear_error(C);
    assert_null(qd_jet(C, X, 1)); /* a plain symbol has no jet */
    qd_ctx_clear_error(C);
    /* natural order: theta2 before theta10 */
    const qd_expr *a = qd_symbol(C, "theta2"), *b = qd_symbol(C, "theta10");
    assert_true(qd_expr_cmp(a, b) < 0);
    const qd_expr *s = qd_add(C, b, a);
    assert_ptr_equal(qd_expr_arg(s, 0), a);
}

static void user_functions(void **state) {
    const qd_expr *V = qd_ufunc(C, "V", 1, &X);
    assert_ptr_equal(V, qd_ufunc(C, "V", 1, &X));
    assert_null(qd_ufunc(C, "sin", 1, &X)); /* a built-in name */
    qd_ctx_clear_error(C);
    const qd_expr *args[2] = {X, Y};
    unsigned s12[2] = {1, 0}, s21[2] = {0, 1};
    assert_ptr_equal(qd_uderiv(C, "f", 2, s12, 2, args), qd_uderiv(C, "f", 2, s21, 2, args));
    unsigned bad = 2;
    assert_null(qd_uderiv(C, "f", 1, &bad, 2, args));
    qd_ctx_clear_error(C);
}

/* The canonical order is a total order, consistent with equality, on random nodes. */
static void order_is_total(void **state) {
    qt_rng r = {7};
    const qd_expr *syms[3] = {X, Y, Z};
    const qd_expr *e[60];
    for (int i = 0; i < 60; i++)
        e[i] = qt_random_expr(C, &r, syms, 3, 3, QT_ALL);
    for (int i = 0; i < 60; i++)
        for (int j = 0; j < 60; j++) {
            int c = qd_expr_cmp(e[i], e[j]), d = qd_expr_cmp(e[j], e[i]);
            assert_true((c > 0) - (c < 0) == -((d > 0) - (d < 0)));
            assert_true((c == 0) == (e[i] == e[j]));
            for (int k = 0; k < 60; k += 7)
                if (c < 0 && qd_expr_cmp(e[j], e[k]) < 0)
                    assert_true(qd_expr_cmp(e[i], e[k]) < 0);
        }
}

/* Building the same random expression in two contexts gives the same hash:
 * hashes never depend on addresses. */
static void hash_is_deterministic(void **state) {
    (void)state;
    uint64_t h[2];
    for (int k = 0; k < 2; k++) {
        qd_ctx *c = qd_ctx_new();
        if (k == 1) /* make other nodes first so addresses differ */
            for (int i = 0; i < 100; i++)
                qd_int(c, 1000 + i);
        const qd_expr *s[2] = {qd_symbol(c, "a"), qd_coord(c, "q")};
        qt_rng r = {99};
        h[k] = qd_expr_hash(qt_random_expr(c, &r, s, 2, 5, QT_ALL));
        qd_ctx_free(c);
    }
    assert_true(h[0] == h[1]);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(hash_consing, setup, teardown),
        cmocka_unit_test_setup_teardown(sums, setup, teardown),
        cmocka_unit_test_setup_teardown(products, setup, teardown),
        cmocka_unit_test_setup_teardown(powers, setup, teardown),
        cmocka_unit_test_setup_teardown(numbers, setup, teardown),
        cmocka_unit_test_setup_teardown(functions, setup, teardown),
        cmocka_unit_test_setup_teardown(trig_exact_values, setup, teardown),
        cmocka_unit_test_setup_teardown(trig_shifts, setup, teardown),
        cmocka_unit_test_setup_teardown(real_roots, setup, teardown),
        cmocka_unit_test_setup_teardown(positive_symbols, setup, teardown),
        cmocka_unit_test_setup_teardown(symbols, setup, teardown),
        cmocka_unit_test_setup_teardown(user_functions, setup, teardown),
        cmocka_unit_test_setup_teardown(order_is_total, setup, teardown),
        cmocka_unit_test(hash_is_deterministic),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
