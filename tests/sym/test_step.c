/*
 * tests/sym/test_step.c - Heaviside's step(x): the kernel function that
 * writes step potentials (a refracting sphere, V = -V0 step(a - r); Desloge
 * ch. 60, seed-desloge-B.md C4): its values (1/2 at 0, SymPy's Heaviside),
 * reading, every printer, its derivative and both evaluators.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "qdot/qdot.h"

static const qd_expr *rd(qd_ctx *c, const char *text) {
    const qd_expr *e = qd_read(c, text, NULL, NULL);
    assert_non_null(e);
    return e;
}

static void assert_prints(qd_ctx *c, const qd_expr *e, qd_format f, const char *want) {
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_print(c, e, f, &b), QD_OK);
    assert_string_equal(qd_buf_str(&b), want);
    qd_buf_free(&b);
}

/* Numbers fold: H(-3) = 0, H(0) = 1/2, H(5/2) = 1, a float argument too. */
static void test_fold(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    assert_ptr_equal(qd_fn(c, QD_STEP, qd_int(c, -3)), qd_int(c, 0));
    assert_ptr_equal(qd_fn(c, QD_STEP, qd_int(c, 0)), qd_rat(c, 1, 2));
    assert_ptr_equal(qd_fn(c, QD_STEP, qd_rat(c, 5, 2)), qd_int(c, 1));
    assert_ptr_equal(qd_fn(c, QD_STEP, qd_float(c, -0.25)), qd_float(c, 0.0));
    assert_ptr_equal(rd(c, "step(2 - 3)"), qd_int(c, 0));
    qd_ctx_free(c);
}

/* The name reads back, and each printer spells it its own way. */
static void test_print(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    const qd_expr *e = rd(c, "V0*step(a - r)");
    qd_func f;
    assert_true(qd_func_from_name("step", &f));
    assert_int_equal(f, QD_STEP);
    assert_prints(c, e, QD_FMT_TEXT, "V0*step(a - r)");
    assert_ptr_equal(rd(c, "V0*step(a - r)"), e);
    assert_prints(c, e, QD_FMT_SYMPY, "V0*Heaviside(a - r)");
    assert_prints(c, e, QD_FMT_LATEX, "V_{0} \\theta{\\left(a - r \\right)}");
    assert_prints(c, qd_fn(c, QD_STEP, qd_symbol(c, "x")), QD_FMT_C,
                  "(((x > 0) + (x >= 0))*0.5)");
    qd_ctx_free(c);
}

/* d/dr step(a - r) = 0 away from r = a (the kernel has no delta): a
 * step potential exerts no force except at the jump, which scattering
 * handles exactly as a refraction, never by differentiating. */
static void test_diff(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    const qd_expr *x = qd_symbol(c, "x");
    assert_ptr_equal(qd_diff(c, rd(c, "x^2*step(a - x)"), x), rd(c, "2*x*step(a - x)"));
    assert_ptr_equal(qd_diff(c, rd(c, "step(x)"), x), qd_int(c, 0));
    qd_ctx_free(c);
}

/* Tree evaluation and compiled programs agree: 0, 1/2, 1 either side of
 * the jump, and the sphere's V = -V0 inside, 0 outside. */
static void test_eval(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    const qd_expr *in[3] = {qd_symbol(c, "r"), qd_symbol(c, "a"), qd_symbol(c, "V0")};
    const qd_expr *out[2] = {rd(c, "step(r - a)"), rd(c, "-V0*step(a - r)")};
    qd_prog *p = qd_prog_new(c, 3, in, 2, out);
    assert_non_null(p);
    const double r[3] = {0.5, 1.0, 1.5}, want_h[3] = {0.0, 0.5, 1.0}, want_v[3] = {-2.0, -1.0, 0.0};
    for (int k = 0; k < 3; k++) {
        double vals[3] = {r[k], 1.0, 2.0}, got[2], tree;
        qd_prog_run(p, vals, got);
        assert_true(got[0] == want_h[k]);
        assert_true(got[1] == want_v[k]);
        assert_int_equal(qd_eval(c, out[0], 3, in, vals, &tree), QD_OK);
        assert_true(tree == want_h[k]);
    }
    qd_prog_free(p);
    qd_ctx_free(c);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_fold),
        cmocka_unit_test(test_print),
        cmocka_unit_test(test_diff),
        cmocka_unit_test(test_eval),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
