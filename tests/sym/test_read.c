/*
 * tests/sym/test_read.c - qd_read: the text printer's output reads back to
 * the same node, the grammar's precedence, exact numbers, jets, d/dt, and
 * the error reports for malformed input.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <string.h>

#include "util/randexpr.h"

typedef struct world {
    qd_ctx *ctx;
    const qd_expr *x, *y, *z, *q, *qd, *qdd, *m, *t;
    const qd_expr *leaves[16];
    size_t nleaves;
} world;

static int setup(void **state) {
    static world w;
    memset(&w, 0, sizeof w);
    w.ctx = qd_ctx_new();
    w.x = qd_symbol(w.ctx, "x");
    w.y = qd_symbol(w.ctx, "y");
    w.z = qd_symbol(w.ctx, "z");
    w.q = qd_coord(w.ctx, "theta1");
    w.qd = qd_jet(w.ctx, w.q, 1);
    w.qdd = qd_jet(w.ctx, w.q, 2);
    w.m = qd_param(w.ctx, "m_1");
    w.t = qd_time(w.ctx);
    const qd_expr *xy[2] = {w.x, w.q};
    unsigned s1[1] = {0}, s2[2] = {0, 1}, s3[2] = {1, 1}, s00[2] = {0, 0};
    const qd_expr *l[] = {
        w.x, w.y, w.q, w.qd, w.qdd, w.m, w.t,
        qd_ufunc(w.ctx, "V", 1, &w.x),
        qd_uderiv(w.ctx, "V", 1, s1, 1, &w.q),
        qd_uderiv(w.ctx, "V", 2, s00, 1, &w.y),
        qd_ufunc(w.ctx, "W", 2, xy),
        qd_uderiv(w.ctx, "W", 2, s2, 2, xy),
        qd_uderiv(w.ctx, "W", 2, s3, 2, xy),
    };
    for (size_t i = 0; i < sizeof l / sizeof l[0]; i++)
        if (l[i])
            w.leaves[w.nleaves++] = l[i];
    *state = &w;
    return 0;
}

static int teardown(void **state) {
    world *w = *state;
    qd_ctx_free(w->ctx);
    return 0;
}

static const qd_expr *rd(world *w, const char *s) {
    qd_read_error err;
    const qd_expr *e = qd_read(w->ctx, s, NULL, &err);
    if (!e)
        fail_msg("reading '%s': %s at %zu (%s)", s, err.message, err.offset, err.hint);
    return e;
}

/* Print e as text, read it back, demand the same node. */
static void roundtrip(world *w, const qd_expr *e, const char *what) {
    qd_buf b = QD_BUF_INIT, b2 = QD_BUF_INIT;
    assert_non_null(e);
    assert_int_equal(qd_print(w->ctx, e, QD_FMT_TEXT, &b), QD_OK);
    qd_read_error err;
    qd_read_opts strict = {false};
    const qd_expr *r = qd_read(w->ctx, qd_buf_str(&b), &strict, &err);
    if (r != e) {
        if (r)
            qd_print(w->ctx, r, QD_FMT_TEXT, &b2);
        fail_msg("%s: printed '%s', read back %s'%s' [%s at %zu]", what, qd_buf_str(&b),
                 r ? "as " : "nothing ", qd_buf_str(&b2), r ? "" : err.message,
                 r ? 0 : err.offset);
    }
    qd_buf_free(&b);
    qd_buf_free(&b2);
}

static void test_roundtrip_random(void **state) {
    world *w = *state;
    char what[64];
    for (uint64_t seed = 1; seed <= 1500; seed++) {
        qt_rng r = {seed * 7919};
        const qd_expr *e = qt_random_expr(w->ctx, &r, w->leaves, w->nleaves, 5, QT_ALL);
        snprintf(what, sizeof what, "seed %llu", (unsigned long long)seed);
        roundtrip(w, e, what);
        if (seed % 5 == 0) {
            snprintf(what, sizeof what, "d/dt, seed %llu", (unsigned long long)seed);
            roundtrip(w, qd_dt(w->ctx, e), what);
        }
    }
}

static void test_roundtrip_special(void **state) {
    world *w = *state;
    qd_ctx *c = w->ctx;
    const qd_expr *x = w->x, *y = w->y, *z = w->z;
    const qd_expr *apb = qd_add(c, x, y);
    const qd_expr *cases[] = {
        qd_float(c, 2.5), qd_float(c, -0.1), qd_float(c, 1e300), qd_float(c, -3e-20),
        qd_float(c, 3.0), qd_mul(c, qd_float(c, 1.0), x), qd_mul(c, qd_float(c, -1.0), x),
        qd_rat_str(c, "123456789012345678901234567890/7"), qd_rat(c, -3, 4),
        qd_pow(c, qd_int(c, -2), x), qd_pow(c, qd_rat(c, 3, 4), x),
        qd_pow(c, x, qd_rat(c, -1, 2)), qd_pow(c, x, qd_rat(c, -3, 2)),
        qd_pow(c, qd_int(c, 2), qd_rat(c, -1, 2)), qd_pow(c, qd_int(c, 2), qd_rat(c, 3, 2)),
        qd_pow(c, qd_int(c, -2), qd_rat(c, 1, 2)), qd_pow(c, qd_float(c, -2), qd_float(c, 0.5)),
        qd_mul(c, qd_int(c, 3), qd_pow(c, qd_int(c, 2), qd_rat(c, -1, 2))),
        qd_mul_n(c, 3, (const qd_expr *[]){qd_int(c, 2), apb, z}),
        qd_mul_n(c, 3, (const qd_expr *[]){qd_int(c, -2), apb, z}),
        qd_div(c, x, qd_mul(c, qd_int(c, 2), apb)),
        qd_div(c, qd_int(c, 3), qd_mul(c, qd_int(c, 4), apb)),
        qd_div(c, x, qd_mul_n(c, 3, (const qd_expr *[]){qd_int(c, 2), apb, z})),
        qd_div(c, qd_neg(c, x), qd_mul(c, y, z)),
        qd_pow(c, x, qd_neg(c, y)), qd_pow(c, x, qd_float(c, 2.5)),
        qd_pow(c, x, qd_float(c, -2.5)), qd_pow(c, qd_pow(c, x, y), z),
        qd_pow(c, x, qd_pow(c, y, z)), qd_pow(c, apb, qd_rat(c, 1, 3)),
        qd_pow(c, qd_mul(c, x, y), qd_rat(c, -3, 2)), qd_pow(c, qd_pow(c, x, qd_int(c, 2)), qd_rat(c, 1, 2)),
        qd_pow(c, qd_const(c, QD_E), x), qd_mul(c, qd_const(c, QD_PI), x),
        qd_fn2(c, QD_ATAN2, x, qd_neg(c, y)), qd_fn(c, QD_SIGN, x), qd_fn(c, QD_ABS, apb),
        qd_sub(c, qd_int(c, 1), x), qd_sub(c, qd_neg(c, x), qd_mul(c, qd_int(c, 2), y)),
        qd_jet(c, w->q, 3), qd_pow(c, w->qd, qd_int(c, 2)),
        qd_mul(c, qd_rat(c, 1, 2), qd_mul(c, w->m, qd_pow(c, w->qd, qd_int(c, 2)))),
        qd_add(c, qd_float(c, 0.5), qd_mul(c, qd_float(c, -2.0), apb)),
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char what[32];
        snprintf(what, sizeof what, "case %zu", i);
        roundtrip(w, cases[i], what);
    }
}

static void test_precedence(void **state) {
    world *w = *state;
    qd_ctx *c = w->ctx;
    const qd_expr *a = qd_symbol(c, "a"), *b = qd_symbol(c, "b"), *cc = qd_symbol(c, "c");
    assert_ptr_equal(rd(w, "-x^2"), qd_neg(c, qd_powi(c, w->x, 2)));
    assert_ptr_equal(rd(w, "2^3^2"), qd_int(c, 512));
    assert_ptr_equal(rd(w, "(2^3)^2"), qd_int(c, 64));
    assert_ptr_equal(rd(w, "a/b/c"), qd_div(c, qd_div(c, a, b), cc));
    assert_ptr_equal(rd(w, "a - b - c"), qd_sub(c, qd_sub(c, a, b), cc));
    assert_ptr_equal(rd(w, "a*-b"), qd_neg(c, qd_mul(c, a, b)));
    assert_ptr_equal(rd(w, "x^-2"), qd_powi(c, w->x, -2));
    assert_ptr_equal(rd(w, "2^-1"), qd_rat(c, 1, 2));
    assert_ptr_equal(rd(w, "- - x"), w->x);
    assert_ptr_equal(rd(w, "+x"), w->x);
    assert_ptr_equal(rd(w, "a + b*c^2"), qd_add(c, a, qd_mul(c, b, qd_powi(c, cc, 2))));
    assert_ptr_equal(rd(w, "1/2*x"), qd_mul(c, qd_rat(c, 1, 2), w->x));
    assert_ptr_equal(rd(w, "sqrt(x)"), qd_sqrt(c, w->x));
    assert_ptr_equal(rd(w, "atan2(y, x)"), qd_fn2(c, QD_ATAN2, w->y, w->x));
    assert_ptr_equal(rd(w, "pi + e"), qd_add(c, qd_const(c, QD_PI), qd_const(c, QD_E)));
    assert_ptr_equal(rd(w, "t"), w->t);
    assert_ptr_equal(rd(w, " ( x \n +\n y ) \n"), qd_add(c, w->x, w->y));
}

static void test_numbers(void **state) {
    world *w = *state;
    qd_ctx *c = w->ctx;
    assert_ptr_equal(rd(w, "2.5"), qd_rat(c, 5, 2));
    assert_ptr_equal(rd(w, "0.1"), qd_rat(c, 1, 10));
    assert_ptr_equal(rd(w, "1e-3"), qd_rat(c, 1, 1000));
    assert_ptr_equal(rd(w, "1.5E+2"), qd_int(c, 150));
    assert_ptr_equal(rd(w, ".5"), qd_rat(c, 1, 2));
    assert_ptr_equal(rd(w, "2.5f"), qd_float(c, 2.5));
    assert_ptr_equal(rd(w, "0.1f"), qd_float(c, 0.1));
    assert_ptr_equal(rd(w, "3f"), qd_float(c, 3.0));
    assert_ptr_equal(rd(w, "-1e-20f"), qd_float(c, -1e-20));
    assert_ptr_equal(rd(w, "100000000000000000000000"), qd_rat_str(c, "100000000000000000000000"));
}

static void test_jets_and_dt(void **state) {
    world *w = *state;
    qd_ctx *c = w->ctx;
    assert_ptr_equal(rd(w, "theta1'"), w->qd);
    assert_ptr_equal(rd(w, "theta1''"), w->qdd);
    assert_ptr_equal(rd(w, "theta1'''"), qd_jet(c, w->q, 3));
    assert_ptr_equal(rd(w, "theta1'^2"), qd_powi(c, w->qd, 2));
    const qd_expr *xq = qd_mul(c, w->x, w->q);
    assert_ptr_equal(rd(w, "(x*theta1)'"), qd_dt(c, xq));
    assert_ptr_equal(rd(w, "(x*theta1)''"), qd_dt(c, qd_dt(c, xq)));
    assert_ptr_equal(rd(w, "sin(theta1)'"), qd_dt(c, qd_fn(c, QD_SIN, w->q)));
    assert_ptr_equal(rd(w, "t'"), qd_int(c, 1));
    const qd_expr *xy[2] = {w->x, w->y};
    unsigned s12[2] = {0, 1}, s22[2] = {1, 1}, s00[2] = {0, 0};
    assert_ptr_equal(rd(w, "V'(x)"), qd_uderiv(c, "V", 1, s12, 1, &w->x));
    assert_ptr_equal(rd(w, "V''(x)"), qd_uderiv(c, "V", 2, s00, 1, &w->x));
    assert_ptr_equal(rd(w, "W'[1,2](x, y)"), qd_uderiv(c, "W", 2, s12, 2, xy));
    assert_ptr_equal(rd(w, "W'[2, 1](x, y)"), qd_uderiv(c, "W", 2, s12, 2, xy));
    assert_ptr_equal(rd(w, "W'[2,2](x, y)"), qd_uderiv(c, "W", 2, s22, 2, xy));
    assert_ptr_equal(rd(w, "W(x, y)"), qd_ufunc(c, "W", 2, xy));
    assert_ptr_equal(rd(w, "U()"), qd_ufunc(c, "U", 0, NULL));
}

typedef struct bad {
    const char *text;
    size_t offset;
    const char *message; /* a part of the message */
    const char *hint;    /* a part of the hint, or NULL */
    bool strict;         /* new_symbols false */
} bad;

static void test_errors(void **state) {
    world *w = *state;
    static const bad cases[] = {
        {"", 0, "empty expression", NULL, false},
        {"   ", 3, "empty expression", NULL, false},
        {"sin(x", 5, "missing ')'", "to close '(' at column 4", false},
        {"(x + 1", 6, "missing ')'", "at column 1", false},
        {"2*(x + (y - 1)", 14, "missing ')'", "at column 3", false},
        {"x)", 1, "unmatched ')'", NULL, false},
        {"x +", 3, "expected an operand, found the end of the input", "'+'", false},
        {"x *", 3, "expected an operand", "'*'", false},
        {"x * )", 4, "unmatched ')'", NULL, false},
        {"x y", 2, "expected an operator, found a name", "'*'", false},
        {"2x", 0, "a number cannot run into a name", "2*x", false},
        {"1.2.3", 0, "bad number '1.2.3'", NULL, false},
        {"x ? y", 2, "expected an operator", NULL, false},
        {"x + ?", 4, "expected an expression, found '?'", NULL, false},
        {"1/0", 1, "division by zero", NULL, false},
        {"sin(x, y)", 0, "sin takes 1 argument, not 2", NULL, false},
        {"atan2(x)", 0, "atan2 takes 2 arguments, not 1", NULL, false},
        {"x +\n y", 3, "found the end of the line", NULL, false},
        {"nosuch + 1", 0, "unknown name 'nosuch'", NULL, true},
        {"x + nofunc(x)", 4, "unknown function 'nofunc'", NULL, true},
        {"x(y)", 0, "'x' is a symbol, not a function", "'*'", false},
        {"W'(x, y)", 0, "W has 2 arguments", "W'[1]", false},
        {"W'[3](x, y)", 0, "W has no argument 3", NULL, false},
        {"W'[0](x, y)", 3, "bad argument number", NULL, false},
        {"W'[1(x, y)", 4, "missing ']'", "to close '['", false},
        {"V''[1](x)", 0, "one prime before an argument list", NULL, false},
        /* a plain symbol's rate would be 0 (issue 33): refused, located */
        {"1 + x'", 4, "'x' is a plain symbol: its rate would be 0", "declare it a coordinate", false},
        /* nor may the rate of an expression take an unknown name in it as a
         * constant (issue 33, Goldstein ch. 1 seed 002: (r^2*th')' is not
         * r^2*th''); a plain symbol the caller made (x) stays a constant */
        {"2 + (u*theta1)'", 4, "'u' is a plain symbol: its rate in this derivative would be 0",
         "write its rate out", false},
        {"sin(w2)'", 0, "'w2' is a plain symbol: its rate in this derivative would be 0", NULL, false},
        {"(x*w3^2)''", 0, "'w3' is a plain symbol: its rate in this derivative would be 0", NULL, false},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const bad *b = &cases[i];
        qd_read_error err;
        qd_read_opts opts = {!b->strict};
        const qd_expr *e = qd_read(w->ctx, b->text, &opts, &err);
        if (e || err.offset != b->offset || !strstr(err.message, b->message) ||
            (b->hint && !strstr(err.hint, b->hint)))
            fail_msg("'%s': got %s offset %zu message '%s' hint '%s'; want %zu '%s' '%s'",
                     b->text, e ? "a result," : "", err.offset, err.message, err.hint,
                     b->offset, b->message, b->hint ? b->hint : "");
        assert_int_equal(qd_ctx_status(w->ctx), QD_ERR_PARSE);
        qd_ctx_clear_error(w->ctx);
    }
    /* err may be NULL */
    assert_null(qd_read(w->ctx, "(", NULL, NULL));
    qd_ctx_clear_error(w->ctx);
}

static void test_deep_nesting(void **state) {
    world *w = *state;
    char s[4001];
    memset(s, '(', 2000);
    s[2000] = 'x';
    memset(s + 2001, ')', 2000);
    s[4001 - 1] = '\0';
    qd_read_error err;
    assert_null(qd_read(w->ctx, s, NULL, &err));
    assert_non_null(strstr(err.message, "nested too deeply"));
    qd_ctx_clear_error(w->ctx);
    assert_ptr_equal(rd(w, "((((((((((x))))))))))"), w->x);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_roundtrip_random), cmocka_unit_test(test_roundtrip_special),
        cmocka_unit_test(test_precedence),       cmocka_unit_test(test_numbers),
        cmocka_unit_test(test_jets_and_dt),      cmocka_unit_test(test_errors),
        cmocka_unit_test(test_deep_nesting),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
