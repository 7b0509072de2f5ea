/*
 * tests/fault/test_fault_gmp.c - GMP's and FLINT's allocations made to fail
 * too (issue 30).  Their requests of QD_GMP_PROBE_MIN (1024) bytes or more
 * inside qd_expand, qd_cancel, the factoring and the folding of a number's
 * power are first asked of the context's allocator (src/sym/gmpmem.c), so
 * the loop of tests/util/fault.h refuses them like any other request; each
 * run must end with the right answer or a clean QD_ERR_NOMEM.
 *
 * Bodies and the answers they must give:
 *   big coefficients: (2^4000 x + 3^3000 y + 1)^4 has binomial(6, 2) = 15
 *     terms and at x = y = 1 the value (2^4000 + 3^3000 + 1)^4;
 *   FLINT: (1 + x + y + z)^15 (the fmpz_mpoly path), binomial(18, 3) = 816
 *     terms, 4^15 at x = y = z = 1;
 *   folding: 7^20000 (56,000 bits) times 7^-19999 is 7.
 * Besides the loops, an allocator that refuses only requests of 4096 bytes
 * or more shows that a refusal reaches GMP itself: 7^20000 needs one such
 * block, from GMP, and nothing else that large.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdlib.h>
#include <string.h>

#include "qdot/qdot.h"
#include "util/fault.h"

static qd_status fail_status(qd_ctx *ctx) {
    qd_status st = qd_ctx_status(ctx);
    return st != QD_OK ? st : QD_ERR_ARG;
}

/* e at every symbol of syms equal to 1. */
static const qd_expr *at_ones(qd_ctx *ctx, const qd_expr *e, size_t n, const qd_expr *const *syms) {
    const qd_expr *ones[3] = {qd_int(ctx, 1), qd_int(ctx, 1), qd_int(ctx, 1)};
    return qd_subs(ctx, e, n, syms, ones);
}

static qd_status big_coefficients_body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)f, (void)data;
    const qd_expr *A = qd_powi(ctx, qd_int(ctx, 2), 4000), *B = qd_powi(ctx, qd_int(ctx, 3), 3000);
    const qd_expr *x = qd_symbol(ctx, "x"), *y = qd_symbol(ctx, "y");
    const qd_expr *s[3] = {qd_mul(ctx, A, x), qd_mul(ctx, B, y), qd_int(ctx, 1)};
    const qd_expr *e = qd_expand(ctx, qd_powi(ctx, qd_add_n(ctx, 3, s), 4));
    const qd_expr *syms[2] = {x, y};
    const qd_expr *v = at_ones(ctx, e, 2, syms);
    const qd_expr *t[3] = {A, B, qd_int(ctx, 1)};
    const qd_expr *want = qd_powi(ctx, qd_add_n(ctx, 3, t), 4);
    if (!v || !want)
        return fail_status(ctx);
    assert_int_equal(qd_expr_kind(e), QD_ADD);
    assert_int_equal(qd_expr_nargs(e), 15);
    assert_ptr_equal(v, want);
    return QD_OK;
}

static qd_status flint_body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)f, (void)data;
    const qd_expr *e = qd_read(ctx, "(1 + x + y + z)^15", NULL, NULL);
    const qd_expr *x = qd_expand(ctx, e);
    const qd_expr *syms[3] = {qd_symbol(ctx, "x"), qd_symbol(ctx, "y"), qd_symbol(ctx, "z")};
    const qd_expr *v = at_ones(ctx, x, 3, syms);
    const qd_expr *want = qd_powi(ctx, qd_int(ctx, 4), 15);
    if (!v || !want)
        return fail_status(ctx);
    assert_int_equal(qd_expr_nargs(x), 816);
    assert_ptr_equal(v, want);
    return QD_OK;
}

static qd_status folding_body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)f, (void)data;
    const qd_expr *seven = qd_int(ctx, 7);
    const qd_expr *big = qd_powi(ctx, seven, 20000);
    const qd_expr *r = qd_mul(ctx, big, qd_powi(ctx, seven, -19999));
    if (!r)
        return fail_status(ctx);
    assert_int_equal(qd_expr_kind(big), QD_RATIONAL);
    assert_ptr_equal(r, seven);
    return QD_OK;
}

static void test_big_coefficients(void **state) {
    (void)state;
    assert_true(qt_fault_loop("big coefficients", big_coefficients_body, NULL, 1).allocs > 10);
}

static void test_flint(void **state) {
    (void)state;
    assert_true(qt_fault_loop("FLINT power", flint_body, NULL, 1).allocs > 10);
}

static void test_folding(void **state) {
    (void)state;
    assert_true(qt_fault_loop("folding", folding_body, NULL, 1).allocs > 2);
}

/* ---- a refusal that only GMP meets ----------------------------------------- */

typedef struct bigonly {
    size_t limit;
    long refused;
} bigonly;

static void *big_malloc(void *user, size_t size) {
    bigonly *b = user;
    if (size >= b->limit) {
        b->refused++;
        return NULL;
    }
    return malloc(size);
}

static void *big_realloc(void *user, void *p, size_t size) {
    bigonly *b = user;
    if (size >= b->limit) {
        b->refused++;
        return NULL;
    }
    return realloc(p, size);
}

static void big_free(void *user, void *p) {
    (void)user;
    free(p);
}

static void test_refusal_reaches_gmp(void **state) {
    (void)state;
    bigonly b = {SIZE_MAX, 0};
    qd_allocator a = {big_malloc, big_realloc, big_free, &b};
    qd_ctx *ctx = qd_ctx_new_with(&a); /* its tables are larger than 4096 bytes */
    assert_non_null(ctx);
    b.limit = 4096;
    const qd_expr *small = qd_powi(ctx, qd_int(ctx, 7), 200); /* 562 bits: no big block */
    assert_non_null(small);
    assert_int_equal(b.refused, 0);
    assert_null(qd_powi(ctx, qd_int(ctx, 7), 20000));
    assert_true(b.refused > 0);
    assert_int_equal(qd_ctx_status(ctx), QD_ERR_NOMEM);
    qd_ctx_clear_error(ctx);
    /* the context stays usable */
    assert_ptr_equal(qd_mul(ctx, small, qd_powi(ctx, qd_int(ctx, 7), -199)), qd_int(ctx, 7));
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_refusal_reaches_gmp),
        cmocka_unit_test(test_folding),
        cmocka_unit_test(test_big_coefficients),
        cmocka_unit_test(test_flint),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
