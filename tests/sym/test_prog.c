/*
 * tests/sym/test_prog.c - compiled programs (qdot/eval.h) against the tree
 * evaluator qd_eval, the size of programs over shared DAGs, and errors.
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

#include "qdot/qdot.h"
#include "util/randexpr.h"

#define SEED 20240611u
#define ROUNDS 300  /* x 4 random outputs = 1200 expressions */
#define NOUT 6
#define NPOINTS 3

/* Relative 1e-12, or absolute 1e-12 near zero; NaN only against NaN. */
static bool close_enough(double a, double b) {
    if (isnan(a) || isnan(b))
        return isnan(a) && isnan(b);
    if (isinf(a) || isinf(b))
        return a == b;
    double d = fabs(a - b);
    return d <= 1e-12 || d <= 1e-12 * fmax(fabs(a), fabs(b));
}

/* A plain prefix dump over the public inspection API, for failure reports
 * that do not depend on the printer. */
static void dump(const qd_expr *e, FILE *f) {
    static const char *kinds[] = {"rat", "float", "const", "sym", "fn",
                                  "ufunc", "uderiv", "pow", "mul", "add"};
    qd_kind k = qd_expr_kind(e);
    if (qd_is_number(e)) {
        fprintf(f, "%.17g", qd_number_value(e));
        return;
    }
    if (k == QD_SYMBOL) {
        fputs(qd_expr_name(e), f);
        return;
    }
    fprintf(f, "(%s", k == QD_FUNC ? qd_func_name(qd_expr_func(e)) : kinds[k]);
    if (k == QD_CONSTANT)
        fputs(qd_expr_constant(e) == QD_PI ? " pi" : " e", f);
    for (size_t i = 0; i < qd_expr_nargs(e); i++) {
        fputc(' ', f);
        dump(qd_expr_arg(e, i), f);
    }
    fputc(')', f);
}

/* Runs p at vals and compares every output with qd_eval; false on mismatch. */
static bool check_point(qd_ctx *ctx, qd_prog *p, size_t nin, const qd_expr *const *in,
                        size_t nout, const qd_expr *const *out, const double *vals) {
    double got[NOUT + 2], want;
    qd_prog_run(p, vals, got);
    for (size_t k = 0; k < nout; k++) {
        assert_int_equal(qd_eval(ctx, out[k], nin, in, vals, &want), QD_OK);
        if (!close_enough(got[k], want)) {
            printf("output %zu: program %.17g, qd_eval %.17g\n  ", k, got[k], want);
            dump(out[k], stdout);
            printf("\n");
            return false;
        }
    }
    return true;
}

static void random_round(qt_rng *rng, unsigned round) {
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *s[4] = {qd_symbol(ctx, "x"), qd_symbol(ctx, "y"), qd_symbol(ctx, "z"),
                           qd_symbol(ctx, "w")};
    /* inputs in another order than the symbols, plus one unused */
    const qd_expr *in[5] = {s[2], s[0], qd_symbol(ctx, "unused"), s[3], s[1]};
    const qd_expr *out[NOUT];
    for (int k = 0; k < 4; k++)
        out[k] = qt_random_expr(ctx, rng, s, 4, 4, QT_ALL);
    /* outputs sharing whole subexpressions with the others */
    out[4] = qd_add(ctx, out[0], qd_mul(ctx, out[1], out[2]));
    out[5] = qd_sub(ctx, out[3], qd_powi(ctx, out[0], 2));
    for (int k = 0; k < NOUT; k++)
        assert_non_null(out[k]);
    qd_prog *p = qd_prog_new(ctx, 5, in, NOUT, out);
    assert_non_null(p);
    for (int t = 0; t < NPOINTS; t++) {
        double v[5];
        for (int i = 0; i < 5; i++)
            v[i] = qt_uniform(rng, -1, 1);
        if (!check_point(ctx, p, 5, in, NOUT, out, v))
            fail_msg("seed %u, round %u, point %d", SEED, round, t);
    }
    qd_prog_free(p);
    qd_ctx_free(ctx);
}

static void test_random(void **state) {
    (void)state;
    qt_rng rng = {SEED};
    for (unsigned r = 0; r < ROUNDS; r++)
        random_round(&rng, r);
}

/* Every operation the program knows, at a point where each is defined. */
static void test_operations(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *x = qd_symbol(ctx, "x"), *y = qd_symbol(ctx, "y");
    const qd_expr *in[2] = {x, y};
    const qd_expr *out[64];
    size_t n = 0;
    for (int f = 0; f < QD_FUNC_COUNT; f++)
        if (f != QD_ATAN2)
            out[n++] = qd_fn(ctx, (qd_func)f, qd_mul(ctx, qd_rat(ctx, 1, 3), x));
    out[n++] = qd_fn2(ctx, QD_ATAN2, y, x);
    out[n++] = qd_fn(ctx, QD_SIGN, qd_neg(ctx, y));
    static const long pw[][2] = {{2, 1}, {3, 1}, {-1, 1}, {-2, 1}, {-3, 1}, {7, 1}, {-8, 1},
                                 {1, 2}, {-1, 2}, {3, 2}, {-5, 2}, {1, 3}, {-2, 7}, {64, 1},
                                 {65, 1}, {-65, 1}};
    for (size_t i = 0; i < sizeof pw / sizeof pw[0]; i++)
        out[n++] = qd_pow(ctx, x, qd_rat(ctx, pw[i][0], pw[i][1]));
    out[n++] = qd_pow(ctx, x, y);
    out[n++] = qd_pow(ctx, x, qd_float(ctx, 0.37));
    out[n++] = qd_mul(ctx, qd_const(ctx, QD_PI), qd_pow(ctx, qd_const(ctx, QD_E), y));
    out[n++] = qd_sub(ctx, qd_rat(ctx, -7, 3), qd_mul(ctx, x, y));
    out[n++] = qd_neg(ctx, qd_add(ctx, x, y));
    out[n++] = qd_sub(ctx, qd_mul(ctx, qd_int(ctx, -3), x), qd_div(ctx, y, x));
    out[n++] = qd_div(ctx, qd_int(ctx, 5), qd_mul(ctx, qd_powi(ctx, x, 2), qd_sqrt(ctx, y)));
    out[n++] = qd_div(ctx, qd_neg(ctx, y), qd_powi(ctx, x, 3));
    const qd_expr *z = qd_mul(ctx, x, y);
    out[n++] = qd_div(ctx, qd_int(ctx, 1), qd_mul(ctx, qd_mul(ctx, x, qd_fn(ctx, QD_COS, y)),
                                                 qd_add(ctx, x, qd_int(ctx, 2))));
    out[n++] = qd_sub(ctx, qd_neg(ctx, qd_add(ctx, x, qd_mul(ctx, qd_float(ctx, 2.5), z))),
                      qd_add(ctx, qd_powi(ctx, y, 3), qd_int(ctx, 2)));
    out[n++] = qd_sub(ctx, qd_add(ctx, x, y), qd_add(ctx, qd_mul(ctx, qd_int(ctx, 3), z),
                                                     qd_fn(ctx, QD_EXP, z)));
    out[n++] = qd_mul(ctx, qd_mul(ctx, qd_int(ctx, -2), z), qd_fn(ctx, QD_TANH, x));
    out[n++] = x;                 /* an input as output */
    out[n++] = qd_rat(ctx, 3, 4); /* a constant as output */
    out[n++] = qd_const(ctx, QD_PI);
    out[n++] = qd_sqrt(ctx, x);   /* the same node twice */
    assert_true(n <= 64);
    for (size_t k = 0; k < n; k++)
        assert_non_null(out[k]);
    qd_prog *p = qd_prog_new(ctx, 2, in, n, out);
    assert_non_null(p);
    const double pts[][2] = {{0.7, 0.4}, {1.3, -0.6}, {0.25, 2.5}};
    double got[64], want;
    for (size_t t = 0; t < 3; t++) {
        qd_prog_run(p, pts[t], got);
        for (size_t k = 0; k < n; k++) {
            assert_int_equal(qd_eval(ctx, out[k], 2, in, pts[t], &want), QD_OK);
            if (!close_enough(got[k], want))
                fail_msg("output %zu at point %zu: %.17g vs %.17g", k, t, got[k], want);
        }
    }
    qd_prog_free(p);
    qd_ctx_free(ctx);
}

/* An input may be any node (as in qd_eval): here sin(y) is given, y is not. */
static void test_compound_input(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *x = qd_symbol(ctx, "x"), *sy = qd_fn(ctx, QD_SIN, qd_symbol(ctx, "y"));
    const qd_expr *in[2] = {sy, x};
    const qd_expr *e = qd_add(ctx, qd_mul(ctx, x, sy), qd_powi(ctx, sy, 2));
    qd_prog *p = qd_prog_new(ctx, 2, in, 1, &e);
    assert_non_null(p);
    double v[2] = {0.3, -1.5}, got, want;
    qd_prog_run(p, v, &got);
    assert_int_equal(qd_eval(ctx, e, 2, in, v, &want), QD_OK);
    assert_true(close_enough(got, want));
    assert_true(close_enough(got, -1.5 * 0.3 + 0.09));
    qd_prog_free(p);
    qd_ctx_free(ctx);
}

/* e = x + y; e = e*e + sin(e), 30 times: a tree of size ~3^30, a DAG of ~100. */
static void test_sharing_is_linear(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *x = qd_symbol(ctx, "x"), *y = qd_symbol(ctx, "y");
    const qd_expr *in[2] = {x, y};
    const qd_expr *e = qd_add(ctx, x, y);
    for (int i = 0; i < 30; i++)
        e = qd_add(ctx, qd_mul(ctx, e, e), qd_fn(ctx, QD_SIN, e));
    assert_non_null(e);
    size_t dag = qd_dag_size(ctx, e);
    qd_prog *p = qd_prog_new(ctx, 2, in, 1, &e);
    assert_non_null(p);
    assert_true(qd_prog_ninstr(p) <= dag);
    assert_true(qd_prog_ninstr(p) >= 3 * 30); /* each round does + * sin */
    double v[2] = {0.01, -0.03}, got, want;
    qd_prog_run(p, v, &got);
    assert_int_equal(qd_eval(ctx, e, 2, in, v, &want), QD_OK);
    assert_true(close_enough(got, want));
    /* the same by hand */
    double h = v[0] + v[1];
    for (int i = 0; i < 30; i++)
        h = h * h + sin(h);
    assert_true(close_enough(got, h));
    qd_prog_free(p);
    qd_ctx_free(ctx);
}

/* A chain far deeper than any recursion could follow. */
static void test_deep_chain(void **state) {
    (void)state;
    enum { DEPTH = 200000 };
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *x = qd_symbol(ctx, "x");
    const qd_expr *e = x;
    for (int i = 0; i < DEPTH; i++)
        e = qd_fn(ctx, QD_SIN, e);
    assert_non_null(e);
    qd_prog *p = qd_prog_new(ctx, 1, &x, 1, &e);
    assert_non_null(p);
    assert_int_equal(qd_prog_ninstr(p), DEPTH);
    double v = 0.9, got, h = v;
    qd_prog_run(p, &v, &got);
    for (int i = 0; i < DEPTH; i++)
        h = sin(h);
    assert_true(got == h);
    qd_prog_free(p);
    qd_ctx_free(ctx);
}

/* Negative terms subtract, negative powers divide, integer powers multiply,
 * a sum or product of more than two operands is one instruction. */
static void test_instruction_counts(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *x = qd_symbol(ctx, "x"), *y = qd_symbol(ctx, "y"), *z = qd_symbol(ctx, "z");
    const qd_expr *in[3] = {x, y, z};
    struct {
        const qd_expr *e;
        size_t n;
    } cases[] = {
        {qd_sub(ctx, x, qd_mul(ctx, y, z)), 2},          /* x - y*z */
        {qd_div(ctx, x, y), 1},                          /* x / y */
        {qd_powi(ctx, x, 8), 3},                         /* three squarings */
        {qd_powi(ctx, x, -2), 2},                        /* 1/(x*x) */
        {qd_sqrt(ctx, x), 1},
        {qd_neg(ctx, qd_add(ctx, x, y)), 1},             /* -x - y, one n-ary sum */
        {qd_div(ctx, qd_mul(ctx, x, y), qd_mul(ctx, z, z)), 2}, /* z*z, x*y/that */
        {qd_add_n(ctx, 4, (const qd_expr *[]){x, y, z, qd_int(ctx, 1)}), 1},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        qd_prog *p = qd_prog_new(ctx, 3, in, 1, &cases[i].e);
        assert_non_null(p);
        if (qd_prog_ninstr(p) != cases[i].n)
            fail_msg("case %zu: %zu instructions, expected %zu", i, qd_prog_ninstr(p),
                     cases[i].n);
        double v[3] = {0.3, -0.7, 1.9}, got, want;
        qd_prog_run(p, v, &got);
        assert_int_equal(qd_eval(ctx, cases[i].e, 3, in, v, &want), QD_OK);
        assert_true(close_enough(got, want));
        qd_prog_free(p);
    }
    qd_ctx_free(ctx);
}

static void test_errors(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *x = qd_symbol(ctx, "x"), *zeta = qd_symbol(ctx, "zeta");
    const qd_expr *e = qd_add(ctx, qd_fn(ctx, QD_SIN, x), zeta);
    assert_null(qd_prog_new(ctx, 1, &x, 1, &e));
    assert_int_equal(qd_ctx_status(ctx), QD_ERR_UNBOUND);
    assert_non_null(strstr(qd_ctx_message(ctx), "zeta"));
    qd_ctx_clear_error(ctx);

    /* a bare unbound symbol as the output */
    assert_null(qd_prog_new(ctx, 1, &x, 1, &zeta));
    assert_int_equal(qd_ctx_status(ctx), QD_ERR_UNBOUND);
    qd_ctx_clear_error(ctx);

    const qd_expr *u = qd_mul(ctx, x, qd_ufunc(ctx, "Vpot", 1, &x));
    assert_null(qd_prog_new(ctx, 1, &x, 1, &u));
    assert_int_equal(qd_ctx_status(ctx), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(ctx), "Vpot"));
    qd_ctx_clear_error(ctx);

    unsigned slot = 0;
    const qd_expr *d = qd_add(ctx, x, qd_uderiv(ctx, "Wpot", 1, &slot, 1, &x));
    assert_null(qd_prog_new(ctx, 1, &x, 1, &d));
    assert_int_equal(qd_ctx_status(ctx), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(ctx), "Wpot"));
    qd_ctx_clear_error(ctx);

    const qd_expr *null_out[2] = {x, NULL};
    assert_null(qd_prog_new(ctx, 1, &x, 2, null_out));
    assert_null(qd_prog_new(ctx, 1, &x, 1, NULL));
    assert_null(qd_prog_new(ctx, 1, NULL, 1, &x));
    assert_null(qd_prog_new(NULL, 1, &x, 1, &x));
    qd_ctx_clear_error(ctx);

    /* NULL program: harmless */
    qd_prog_free(NULL);
    qd_prog_run(NULL, NULL, NULL);
    assert_int_equal(qd_prog_ninstr(NULL), 0);

    /* nothing to compute, no inputs */
    qd_prog *p = qd_prog_new(ctx, 0, NULL, 0, NULL);
    assert_non_null(p);
    assert_int_equal(qd_prog_ninstr(p), 0);
    qd_prog_run(p, NULL, NULL);
    qd_prog_free(p);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_random),
        cmocka_unit_test(test_operations),
        cmocka_unit_test(test_compound_input),
        cmocka_unit_test(test_sharing_is_linear),
        cmocka_unit_test(test_deep_chain),
        cmocka_unit_test(test_instruction_counts),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
