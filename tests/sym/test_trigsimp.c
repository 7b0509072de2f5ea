/*
 * tests/sym/test_trigsimp.c - trigonometric identities.
 *
 * Each identity is checked by building both sides with the constructors and
 * asserting one node; larger sums check that the rules find their pairs
 * among unrelated terms, and random sums of products are compared by value.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "qdot/qdot.h"
#include "util/randexpr.h"

typedef struct fix {
    qd_ctx *ctx;
    const qd_expr *x, *y, *z, *a, *b;
} fix;

static int setup(void **state) {
    static fix f;
    f.ctx = qd_ctx_new();
    f.x = qd_symbol(f.ctx, "x");
    f.y = qd_symbol(f.ctx, "y");
    f.z = qd_symbol(f.ctx, "z");
    f.a = qd_symbol(f.ctx, "a");
    f.b = qd_symbol(f.ctx, "b");
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
#define A (((fix *)*state)->a)
#define B (((fix *)*state)->b)
#define I(n) qd_int(C, n)
#define SIN(u) qd_fn(C, QD_SIN, u)
#define COS(u) qd_fn(C, QD_COS, u)
#define SQ(u) qd_powi(C, u, 2)
#define MUL(...) qd_mul_n(C, sizeof((const qd_expr *[]){__VA_ARGS__}) / sizeof(void *), \
                          (const qd_expr *[]){__VA_ARGS__})
#define ADD(...) qd_add_n(C, sizeof((const qd_expr *[]){__VA_ARGS__}) / sizeof(void *), \
                          (const qd_expr *[]){__VA_ARGS__})

static void pythagoras(void **state) {
    assert_ptr_equal(qd_trigsimp(C, ADD(SQ(SIN(X)), SQ(COS(X)))), I(1));
    /* c*A*sin^2 + c*A*cos^2 = c*A */
    const qd_expr *ca = MUL(qd_rat(C, -3, 2), A, qd_powi(C, B, 3));
    assert_ptr_equal(qd_trigsimp(C, ADD(MUL(ca, SQ(SIN(X))), MUL(ca, SQ(COS(X))))), ca);
    /* a compound angle, and higher powers: s^4 c + s^2 c^3 = s^2 c */
    const qd_expr *u = qd_add(C, X, qd_mul(C, I(2), Y));
    assert_ptr_equal(qd_trigsimp(C, ADD(MUL(A, SQ(SIN(u))), MUL(A, SQ(COS(u))))), A);
    assert_ptr_equal(qd_trigsimp(C, ADD(MUL(qd_powi(C, SIN(X), 4), COS(X)),
                                        MUL(SQ(SIN(X)), qd_powi(C, COS(X), 3)))),
                     MUL(SQ(SIN(X)), COS(X)));
    /* 1 - sin^2 = cos^2, a - a*cos^2 = a*sin^2 */
    assert_ptr_equal(qd_trigsimp(C, qd_sub(C, I(1), SQ(SIN(X)))), SQ(COS(X)));
    assert_ptr_equal(qd_trigsimp(C, qd_sub(C, A, MUL(A, SQ(COS(X))))), MUL(A, SQ(SIN(X))));
    /* different coefficients: 2 sin^2 + cos^2 = 1 + sin^2 */
    assert_ptr_equal(qd_trigsimp(C, ADD(MUL(I(2), SQ(SIN(X))), SQ(COS(X)))),
                     ADD(I(1), SQ(SIN(X))));
    /* a symbolic coefficient on one side only, or different angles: nothing to do */
    const qd_expr *e = ADD(MUL(A, SQ(SIN(X))), SQ(COS(X)));
    assert_ptr_equal(qd_trigsimp(C, e), e);
    e = ADD(SQ(SIN(X)), SQ(COS(Y)));
    assert_ptr_equal(qd_trigsimp(C, e), e);
}

static void angle_sums(void **state) {
    const qd_expr *k = MUL(I(5), A, B);
    const qd_expr *cc = MUL(k, COS(X), COS(Y)), *ss = MUL(k, SIN(X), SIN(Y));
    const qd_expr *sc = MUL(k, SIN(X), COS(Y)), *cs = MUL(k, COS(X), SIN(Y));
    assert_ptr_equal(qd_trigsimp(C, qd_add(C, cc, ss)), MUL(k, COS(qd_sub(C, X, Y))));
    assert_ptr_equal(qd_trigsimp(C, qd_sub(C, cc, ss)), MUL(k, COS(qd_add(C, X, Y))));
    assert_ptr_equal(qd_trigsimp(C, qd_add(C, sc, cs)), MUL(k, SIN(qd_add(C, X, Y))));
    assert_ptr_equal(qd_trigsimp(C, qd_sub(C, sc, cs)), MUL(k, SIN(qd_sub(C, X, Y))));
    assert_ptr_equal(qd_trigsimp(C, qd_sub(C, cs, sc)), MUL(k, SIN(qd_sub(C, Y, X))));
    /* the same rules on compound angles, and repeated: cos(x-y)cos z + sin(x-y)sin z */
    const qd_expr *u = qd_sub(C, X, Y);
    assert_ptr_equal(qd_trigsimp(C, ADD(MUL(COS(u), COS(Z)), MUL(SIN(u), SIN(Z)))),
                     COS(ADD(X, qd_neg(C, Y), qd_neg(C, Z))));
    /* a rule that fires, then one that fires on its result:
     * cos x cos y cos z - sin x sin y cos z - sin(x+y) sin z = cos(x+y+z) */
    const qd_expr *e = ADD(MUL(COS(X), COS(Y), COS(Z)), qd_neg(C, MUL(SIN(X), SIN(Y), COS(Z))),
                           qd_neg(C, MUL(SIN(qd_add(C, X, Y)), SIN(Z))));
    assert_ptr_equal(qd_trigsimp(C, e), COS(ADD(X, Y, Z)));
}

static void inside_bigger_sums(void **state) {
    /* sin^2 + cos^2 among many unrelated terms, and inside a function and a product */
    const qd_expr *rest[40];
    for (int i = 0; i < 40; i++)
        rest[i] = MUL(qd_int(C, i + 1), qd_powi(C, X, i), SIN(qd_mul(C, qd_int(C, i), Y)));
    const qd_expr *others = qd_add_n(C, 40, rest);
    const qd_expr *e = ADD(others, MUL(A, Z, SQ(SIN(Y))), MUL(A, Z, SQ(COS(Y))), I(3));
    assert_ptr_equal(qd_trigsimp(C, e), ADD(others, MUL(A, Z), I(3)));
    const qd_expr *p = MUL(B, ADD(SQ(SIN(X)), SQ(COS(X)), A));
    assert_ptr_equal(qd_trigsimp(C, qd_fn(C, QD_EXP, p)), qd_fn(C, QD_EXP, MUL(B, ADD(I(1), A))));
}

#define POW(u, k) qd_powi(C, u, k)

/* Even powers of one angle, reduced modulo sin^2 + cos^2 = 1. */
static void even_powers(void **state) {
    const qd_expr *s = SIN(X), *c = COS(X);
    /* (sin^2 + cos^2)^2 = 1, and cubed */
    const qd_expr *e = ADD(POW(s, 4), MUL(I(2), SQ(s), SQ(c)), POW(c, 4));
    assert_ptr_equal(qd_trigsimp(C, e), I(1));
    assert_ptr_equal(qd_simplify(C, e), I(1));
    e = qd_expand(C, POW(ADD(SQ(s), SQ(c)), 3));
    assert_int_equal(qd_expr_kind(e), QD_ADD);
    assert_ptr_equal(qd_trigsimp(C, e), I(1));
    /* sin^4 - cos^4 = (sin^2 - cos^2)(sin^2 + cos^2) = 2 sin^2 - 1 = 1 - 2 cos^2 */
    e = qd_sub(C, POW(s, 4), POW(c, 4));
    const qd_expr *forms[3] = {qd_sub(C, SQ(s), SQ(c)), qd_sub(C, MUL(I(2), SQ(s)), I(1)),
                               qd_sub(C, I(1), MUL(I(2), SQ(c)))};
    const qd_expr *r = qd_trigsimp(C, e), *rs = qd_simplify(C, e);
    assert_true(r == forms[0] || r == forms[1] || r == forms[2]);
    assert_true(rs == forms[0] || rs == forms[1] || rs == forms[2]);
    assert_true(qd_count_ops(r) <= qd_count_ops(forms[0]));
    /* with a common factor, other terms and a compound angle */
    const qd_expr *u = qd_add(C, X, Y), *k = MUL(A, qd_powi(C, B, 3));
    e = qd_expand(C, ADD(MUL(k, POW(ADD(SQ(SIN(u)), SQ(COS(u))), 2)), Z));
    assert_ptr_equal(qd_trigsimp(C, e), ADD(k, Z));
    /* sin^4 cos^2 + sin^2 cos^4 = sin^2 cos^2 (odd factors ride along too) */
    e = ADD(MUL(POW(s, 5), SQ(c)), MUL(POW(s, 3), POW(c, 4)));
    assert_ptr_equal(qd_trigsimp(C, e), MUL(POW(s, 3), SQ(c)));
    /* negative powers are other factors: left alone, value kept */
    e = ADD(POW(s, -2), MUL(POW(c, 2), POW(s, -2)));
    assert_ptr_equal(qd_trigsimp(C, e), e);
}

/* A random polynomial in x, y and the sines and cosines of x and y. */
static const qd_expr *random_poly(void **state, qt_rng *r, int nterms) {
    const qd_expr *atoms[6] = {X, Y, SIN(X), COS(X), SIN(Y), COS(Y)};
    const qd_expr *e = I(0);
    for (int i = 0; i < nterms; i++) {
        const qd_expr *t = qd_int(C, (long)qt_below(r, 7) - 3);
        for (unsigned k = qt_below(r, 5); k > 0; k--)
            t = qd_mul(C, t, atoms[qt_below(r, 6)]);
        e = qd_add(C, e, t);
    }
    return e;
}

/* Anything times (sin^2 + cos^2 - 1), expanded, is 0: the reduction finds
 * the normal form, whichever angles and powers the multipliers bring. */
static void ideal_vanishes(void **state) {
    qt_rng r = {977};
    const qd_expr *one_x = ADD(SQ(SIN(X)), SQ(COS(X)), I(-1));
    const qd_expr *one_y = ADD(SQ(SIN(Y)), SQ(COS(Y)), I(-1));
    for (int n = 0; n < 200; n++) {
        const qd_expr *p = random_poly(state, &r, 6), *q = random_poly(state, &r, 4);
        const qd_expr *e = qd_expand(C, qd_add(C, qd_mul(C, p, one_x), qd_mul(C, q, one_y)));
        const qd_expr *s = qd_trigsimp(C, e);
        if (s != I(0)) {
            qd_buf b = QD_BUF_INIT;
            qd_print(C, e, QD_FMT_TEXT, &b);
            fail_msg("case %d (seed 977): not 0: %s", n, qd_buf_str(&b));
        }
    }
}

/* Random sums of products of sines, cosines (to integer powers lo..hi)
 * and symbols: the same value after, never longer. */
static void check_keeps_value(void **state, uint64_t seed, long lo, long hi) {
    qt_rng r = {seed};
    const qd_expr *syms[3] = {X, Y, Z};
    const qd_expr *trig[6] = {SIN(X), COS(X), SIN(Y), COS(Y), SIN(Z), COS(Z)};
    for (int n = 0; n < 300; n++) {
        const qd_expr *terms[8];
        for (int i = 0; i < 8; i++) {
            const qd_expr *t = qd_int(C, (long)qt_below(&r, 3) + 1);
            for (unsigned k = qt_below(&r, 4); k > 0; k--)
                t = qd_mul(C, t, qd_powi(C, trig[qt_below(&r, 6)],
                                         lo + (long)qt_below(&r, (unsigned)(hi - lo + 1))));
            terms[i] = qd_mul(C, t, syms[qt_below(&r, 3)]);
        }
        const qd_expr *e = qd_add_n(C, 8, terms), *s = qd_trigsimp(C, e);
        assert_non_null(s);
        assert_true(qd_count_ops(s) <= qd_count_ops(e));
        double v[3] = {qt_uniform(&r, -2, 2), qt_uniform(&r, -2, 2), qt_uniform(&r, -2, 2)};
        double ve, vs;
        assert_int_equal(qd_eval(C, e, 3, syms, v, &ve), QD_OK);
        assert_int_equal(qd_eval(C, s, 3, syms, v, &vs), QD_OK);
        if (fabs(ve - vs) > 1e-9 * (1 + fabs(ve)))
            fail_msg("case %d (seed %llu): %g != %g", n, (unsigned long long)seed, ve, vs);
    }
}

static void keeps_value(void **state) { check_keeps_value(state, 20240611, 1, 1); }

/* With negative powers too (sec, tan, cot as the kinematics bring them). */
static void keeps_value_negative(void **state) { check_keeps_value(state, 20261126, -2, 2); }

/* The identities hold for any integer powers: with a negative power of
 * cos (tan, sec, as the kinematics of a body's angular velocity bring them)
 * the same pairs combine.  Before, a negative power blocked the angle and
 * 1 + sin^2/cos^2 stayed as it was (the bicycle's f_u, issue 15). */
static void negative_powers(void **state) {
    const qd_expr *k2 = qd_powi(C, COS(X), -2), *k3 = qd_powi(C, COS(X), -3);
    /* 1 + sin^2/cos^2 = 1/cos^2 */
    assert_ptr_equal(qd_trigsimp(C, ADD(I(1), MUL(SQ(SIN(X)), k2))), k2);
    /* 1 + (sin^2 - 1)/cos^2 = 0, term by term: 1 + s^2 k^-2 - k^-2 */
    assert_ptr_equal(qd_trigsimp(C, ADD(I(1), MUL(SQ(SIN(X)), k2), qd_neg(C, k2))), I(0));
    /* a s^3/k^3 + a s/k = a s/k^3 (the disk's f_u3 coefficient, grouped) */
    assert_ptr_equal(qd_trigsimp(C, ADD(MUL(A, qd_powi(C, SIN(X), 3), k3),
                                        MUL(A, SIN(X), qd_powi(C, COS(X), -1)))),
                     MUL(A, SIN(X), k3));
    /* sin(x)/sin(y) products with negative powers on the other angle's
     * functions: cos x cos y/sin z + sin x sin y/sin z = cos(x - y)/sin z */
    const qd_expr *iz = qd_powi(C, SIN(Z), -1);
    assert_ptr_equal(qd_trigsimp(C, ADD(MUL(COS(X), COS(Y), iz), MUL(SIN(X), SIN(Y), iz))),
                     MUL(COS(qd_sub(C, X, Y)), iz));
    /* a fractional power still blocks: sqrt(cos) is not an integer power */
    const qd_expr *e = ADD(I(1), MUL(SQ(SIN(X)), qd_pow(C, COS(X), qd_rat(C, -1, 2))));
    assert_ptr_equal(qd_trigsimp(C, e), e);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(pythagoras, setup, teardown),
        cmocka_unit_test_setup_teardown(angle_sums, setup, teardown),
        cmocka_unit_test_setup_teardown(inside_bigger_sums, setup, teardown),
        cmocka_unit_test_setup_teardown(keeps_value, setup, teardown),
        cmocka_unit_test_setup_teardown(even_powers, setup, teardown),
        cmocka_unit_test_setup_teardown(ideal_vanishes, setup, teardown),
        cmocka_unit_test_setup_teardown(negative_powers, setup, teardown),
        cmocka_unit_test_setup_teardown(keeps_value_negative, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
