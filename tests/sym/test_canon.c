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
    /* but (x^2)^(1/2) is |x|: left alone */
    assert_ptr_not_equal(qd_sqrt(C, qd_powi(C, X, 2)), X);
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
        cmocka_unit_test_setup_teardown(symbols, setup, teardown),
        cmocka_unit_test_setup_teardown(user_functions, setup, teardown),
        cmocka_unit_test_setup_teardown(order_is_total, setup, teardown),
        cmocka_unit_test(hash_is_deterministic),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
