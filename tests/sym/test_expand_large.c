/*
 * tests/sym/test_expand_large.c - expansions big enough to go through
 * FLINT (poly_flint.c): rational coefficients, negative exponents and
 * coefficients beyond 64 bits, against the multinomial theorem written out
 * with the constructors.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <gmp.h>
#include <stdlib.h>

#include "qdot/qdot.h"

typedef struct fix {
    qd_ctx *ctx;
    const qd_expr *x, *y, *z;
} fix;

static int setup(void **state) {
    fix *f = calloc(1, sizeof *f);
    f->ctx = qd_ctx_new();
    f->x = qd_symbol(f->ctx, "x");
    f->y = qd_symbol(f->ctx, "y");
    f->z = qd_symbol(f->ctx, "z");
    *state = f;
    return 0;
}

static int teardown(void **state) {
    fix *f = *state;
    qd_ctx_free(f->ctx);
    free(f);
    return 0;
}

static const qd_expr *mpz_node(qd_ctx *c, const mpz_t z) {
    char *text = mpz_get_str(NULL, 10, z);
    const qd_expr *r = qd_rat_str(c, text);
    free(text);
    return r;
}

/* (t[0] + t[1] + t[2] + t[3])^n term by term: the sum over i+j+k+l = n of
 * n!/(i! j! k! l!) t0^i t1^j t2^k t3^l, each term made by the constructors. */
static const qd_expr *multinomial(qd_ctx *c, const qd_expr *const t[4], unsigned n) {
    size_t cap = (size_t)(n + 1) * (n + 1) * (n + 1), len = 0;
    const qd_expr **terms = malloc(cap * sizeof *terms);
    mpz_t m, d;
    mpz_inits(m, d, NULL);
    for (unsigned i = 0; i <= n; i++)
        for (unsigned j = 0; i + j <= n; j++)
            for (unsigned k = 0; i + j + k <= n; k++) {
                unsigned e[4] = {i, j, k, n - i - j - k};
                mpz_fac_ui(m, n);
                const qd_expr *f[5];
                for (int v = 0; v < 4; v++) {
                    mpz_fac_ui(d, e[v]);
                    mpz_divexact(m, m, d);
                    f[v + 1] = qd_powi(c, t[v], (long)e[v]);
                }
                f[0] = mpz_node(c, m);
                terms[len++] = qd_mul_n(c, 5, f);
            }
    const qd_expr *r = qd_add_n(c, len, terms);
    mpz_clears(m, d, NULL);
    free(terms);
    return r;
}

/* x/2 + 2y/3 + 1/z - 1: rational coefficients and a negative exponent. */
static void laurent_base(fix *f, const qd_expr *t[4]) {
    qd_ctx *c = f->ctx;
    t[0] = qd_mul(c, qd_rat(c, 1, 2), f->x);
    t[1] = qd_mul(c, qd_rat(c, 2, 3), f->y);
    t[2] = qd_powi(c, f->z, -1);
    t[3] = qd_int(c, -1);
}

static void test_pow_laurent_rational(void **state) {
    fix *f = *state;
    qd_ctx *c = f->ctx;
    const qd_expr *t[4];
    laurent_base(f, t);
    const qd_expr *p = qd_add_n(c, 4, t);
    const qd_expr *e = qd_expand(c, qd_powi(c, p, 18));
    assert_ptr_equal(e, multinomial(c, t, 18));
    assert_int_equal(qd_expr_nargs(e), 1330);
}

/* e^9 * e^8 multiplies two expanded sums of 220 and 165 terms. */
static void test_mul_laurent_rational(void **state) {
    fix *f = *state;
    qd_ctx *c = f->ctx;
    const qd_expr *t[4];
    laurent_base(f, t);
    const qd_expr *p = qd_add_n(c, 4, t);
    const qd_expr *a = qd_expand(c, qd_powi(c, p, 9)), *b = qd_expand(c, qd_powi(c, p, 8));
    assert_int_equal(qd_expr_nargs(a), 220);
    assert_int_equal(qd_expr_nargs(b), 165);
    assert_ptr_equal(qd_expand(c, qd_mul(c, a, b)), multinomial(c, t, 17));
    /* and a product that cancels to a short result: (e^9 - 1)(e^8 + 1) */
    const qd_expr *one = qd_int(c, 1);
    const qd_expr *lhs = qd_mul(c, qd_sub(c, a, one), qd_add(c, b, one));
    const qd_expr *want = qd_add_n(c, 4, (const qd_expr *[]){
        multinomial(c, t, 17), a, qd_neg(c, b), qd_int(c, -1)});
    assert_ptr_equal(qd_expand(c, lhs), qd_expand(c, want));
}

/* (3x + 5y + 7z + 11)^25: coefficients of 100 bits and more. */
static void test_pow_big_coeffs(void **state) {
    fix *f = *state;
    qd_ctx *c = f->ctx;
    const qd_expr *t[4] = {qd_mul(c, qd_int(c, 3), f->x), qd_mul(c, qd_int(c, 5), f->y),
                           qd_mul(c, qd_int(c, 7), f->z), qd_int(c, 11)};
    const qd_expr *e = qd_expand(c, qd_powi(c, qd_add_n(c, 4, t), 25));
    assert_ptr_equal(e, multinomial(c, t, 25));
}

/* Many generators (sin and cos of 12 angles): our own path. */
static void test_many_generators(void **state) {
    fix *f = *state;
    qd_ctx *c = f->ctx;
    const qd_expr *g[24], *sq[24 * 25 / 2];
    for (int i = 0; i < 12; i++) {
        const qd_expr *a = qd_mul(c, qd_int(c, i + 1), f->x);
        g[2 * i] = qd_fn(c, QD_SIN, a);
        g[2 * i + 1] = qd_fn(c, QD_COS, a);
    }
    size_t n = 0;
    for (int i = 0; i < 24; i++)
        for (int j = i; j < 24; j++)
            sq[n++] = qd_mul_n(c, 3, (const qd_expr *[]){qd_int(c, i == j ? 1 : 2), g[i], g[j]});
    const qd_expr *e = qd_expand(c, qd_powi(c, qd_add_n(c, 24, g), 2));
    assert_ptr_equal(e, qd_add_n(c, n, sq));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_pow_laurent_rational, setup, teardown),
        cmocka_unit_test_setup_teardown(test_mul_laurent_rational, setup, teardown),
        cmocka_unit_test_setup_teardown(test_pow_big_coeffs, setup, teardown),
        cmocka_unit_test_setup_teardown(test_many_generators, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
