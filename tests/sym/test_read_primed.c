/*
 * tests/sym/test_read_primed.c - issue 33: outside a model an undeclared
 * name is a plain symbol, a constant whose rate is 0, so `m/2*r'^2` read as
 * 0.  A name the text writes with a prime is made a coordinate instead: r'
 * is then a symbol of its own, wherever in the text the prime stands.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <setjmp.h>
#include <cmocka.h>

#include "qdot/qdot.h"

static const qd_expr *rd(qd_ctx *c, const char *s) {
    qd_read_error err;
    const qd_expr *e = qd_read(c, s, NULL, &err);
    if (!e)
        fail_msg("reading '%s': %s at %zu", s, err.message, err.offset);
    return e;
}

/* d/dr of m/2 (r'^2 + r^2 th'^2) is m r th'^2, d/dr' is m r' (not 0). */
static void test_polar_kinetic(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    const qd_expr *T = rd(c, "m/2*(r'^2 + r^2*th'^2)");
    const qd_expr *r = qd_lookup(c, "r"), *th = qd_lookup(c, "th"), *m = qd_lookup(c, "m");
    assert_non_null(r);
    assert_non_null(th);
    assert_int_equal(qd_symbol_role(r), QD_ROLE_COORD);
    assert_int_equal(qd_symbol_role(th), QD_ROLE_COORD);
    assert_int_equal(qd_symbol_role(m), QD_ROLE_PLAIN);
    const qd_expr *rd1 = qd_jet(c, r, 1), *thd = qd_jet(c, th, 1);
    const qd_expr *want = qd_mul(c, m, qd_mul(c, r, qd_powi(c, thd, 2)));
    assert_ptr_equal(qd_diff(c, T, r), want);
    assert_ptr_equal(qd_diff(c, T, rd1), qd_mul(c, m, rd1));
    qd_ctx_free(c);
}

/* The name before its primed use is the same coordinate. */
static void test_prime_later(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    const qd_expr *e = rd(c, "r^2*r' + V'(r)");
    const qd_expr *r = qd_lookup(c, "r");
    assert_int_equal(qd_symbol_role(r), QD_ROLE_COORD);
    assert_ptr_equal(qd_diff(c, e, qd_jet(c, r, 1)), qd_powi(c, r, 2));
    /* V'(r) is a function's derivative: V stays no symbol */
    assert_null(qd_lookup(c, "V"));
    /* the pendulum's kinetic term is kept */
    const qd_expr *L = rd(c, "m/2*(l*theta')^2");
    const qd_expr *th = qd_lookup(c, "theta");
    assert_false(qd_is_zero(qd_diff(c, L, qd_jet(c, th, 1))));
    qd_ctx_free(c);
}

/* The rate of an expression: its unknown names written with a prime are
 * coordinates, so (r^2*r')' = 2 r r'^2 + r^2 r''; one only ever written
 * inside the derivative is refused, named, not taken as constant (issue 33,
 * Goldstein ch. 1 seed 002: (x*y)' read as 0). */
static void test_rate_of_expression(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    const qd_expr *e = rd(c, "(r^2*r')'");
    const qd_expr *r = qd_lookup(c, "r");
    const qd_expr *r1 = qd_jet(c, r, 1), *r2 = qd_jet(c, r, 2);
    assert_ptr_equal(e, qd_add(c, qd_mul(c, qd_int(c, 2), qd_mul(c, r, qd_powi(c, r1, 2))),
                               qd_mul(c, qd_powi(c, r, 2), r2)));
    qd_read_error err;
    assert_null(qd_read(c, "(x*y)'", NULL, &err));
    assert_int_equal(err.offset, 0);
    assert_non_null(strstr(err.message, "'x' is a plain symbol"));
    qd_ctx_clear_error(c);
    assert_null(qd_read(c, "1 + sin(z)'", NULL, &err));
    assert_int_equal(err.offset, 4);
    qd_ctx_clear_error(c);
    qd_ctx_free(c);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_polar_kinetic),
        cmocka_unit_test(test_prime_later),
        cmocka_unit_test(test_rate_of_expression),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
