/*
 * tests/form/test_gram.c - Gram-Schmidt orthogonalization (qd_gram_schmidt,
 * qdot/form.h) against Desloge vol. 2 App. 21 (pp. 915-917; seed
 * 000_46d037099a6cfcd7.txt, reference seed-desloge-D.md App. 21):
 *
 *   Thm 1 (eqs. 1a-1b, 2), worked by hand: a = (1,1,0), (1,0,1), (0,1,1)
 *   give b1 = (1,1,0), b2 = a2 - 1/2 b1 = (1/2,-1/2,1), b3 = a3 - 1/2 b1 -
 *   1/3 b2 = (-2/3,2/3,2/3), with b.b = 2, 3/2, 4/3; each pair's dot product
 *   recomputed here is 0 and each a(r) is b(r) plus its components (they
 *   span the same space);
 *   Thm 2 (eqs. 3a-3b, 4) with T the double pendulum's kinetic metric
 *   g = [[(m1+m2) l1^2, m2 l1 l2 c], [m2 l1 l2 c, m2 l2^2]], c = cos(th1 -
 *   th2): b2 = e2 - g12/g11 e1 and b2^T g b2 = det g / g11 (the Schur
 *   complement), = l2^2 m2 (m1 + m2 sin^2)/(m1 + m2);
 *   the errors: a vector dependent on those before it (b = 0, named), a null
 *   vector of an indefinite T (diag(1, -1), a = (1, 1)), an asymmetric T,
 *   more vectors than components.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <string.h>

#include "qdot/qdot.h"
#include "qdot/form.h"
#include "util/check.h"

static const qd_expr *expr(qd_ctx *ctx, const char *text) {
    qd_diag d;
    const qd_expr *x = qd_read(ctx, text, NULL, &d);
    if (!x)
        fail_msg("cannot read %s: %s", text, d.message);
    return x;
}

static void read_all(qd_ctx *ctx, size_t k, const char *const *text, const qd_expr **out) {
    for (size_t i = 0; i < k; i++)
        out[i] = expr(ctx, text[i]);
}

/* u^T T v, recomputed here (T NULL: the identity). */
static const qd_expr *dot(qd_ctx *ctx, size_t n, const qd_expr *const *T, const qd_expr *const *u,
                          const qd_expr *const *v) {
    const qd_expr *s = qd_int(ctx, 0);
    for (size_t i = 0; i < n; i++)
        for (size_t k = 0; k < n; k++)
            s = qd_add(ctx, s, qd_mul(ctx, qd_mul(ctx, u[i], v[k]),
                                      T ? T[i * n + k] : qd_int(ctx, i == k)));
    return s;
}

static void test_thm1_by_hand(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    static const char *const a_text[] = {"1", "1", "0", "1", "0", "1", "0", "1", "1"};
    static const char *const b_want[] = {"1", "1", "0", "1/2", "-1/2", "1", "-2/3", "2/3", "2/3"};
    static const char *const norm_want[] = {"2", "3/2", "4/3"};
    const qd_expr *a[9];
    read_all(ctx, 9, a_text, a);
    qd_gram *g = qd_gram_schmidt(ctx, 3, NULL, 3, a);
    assert_non_null(g);
    assert_true(g->euclidean);
    assert_int_equal(g->check, QD_ZERO_PROVEN);
    for (size_t i = 0; i < 9; i++)
        qt_assert_is(ctx, g->b[i], b_want[i]);
    for (size_t r = 0; r < 3; r++)
        qt_assert_is(ctx, g->norm[r], norm_want[r]);
    qt_assert_is(ctx, g->coef[1 * 3 + 0], "1/2"); /* a2.b1/b1.b1 */
    qt_assert_is(ctx, g->coef[2 * 3 + 1], "1/3"); /* a3.b2/b2.b2 = (1/2)/(3/2) */
    for (size_t i = 0; i < 3; i++)
        for (size_t j = i + 1; j < 3; j++)
            qt_assert_is(ctx, dot(ctx, 3, NULL, g->b + 3 * i, g->b + 3 * j), "0"); /* eq. 2 */
    for (size_t r = 0; r < 3; r++)  /* a(r) = b(r) + sum_j coef b(j): the same span */
        for (size_t i = 0; i < 3; i++) {
            const qd_expr *s = g->b[r * 3 + i];
            for (size_t j = 0; j < r; j++)
                s = qd_add(ctx, s, qd_mul(ctx, g->coef[r * 3 + j], g->b[j * 3 + i]));
            qt_assert_is(ctx, qd_sub(ctx, s, a[r * 3 + i]), "0");
        }
    qd_gram_free(g);
    qd_ctx_free(ctx);
}

static void test_thm2_double_pendulum(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    static const char *const T_text[] = {
        "(m1 + m2)*l1^2", "m2*l1*l2*cos(th1 - th2)", "m2*l1*l2*cos(th1 - th2)", "m2*l2^2"};
    static const char *const e_text[] = {"1", "0", "0", "1"};
    const qd_expr *T[4], *e[4];
    read_all(ctx, 4, T_text, T);
    read_all(ctx, 4, e_text, e);
    qd_gram *g = qd_gram_schmidt(ctx, 2, T, 2, e);
    assert_non_null(g);
    assert_false(g->euclidean);
    qt_assert_is(ctx, g->b[0], "1");
    qt_assert_is(ctx, g->b[1], "0");
    qt_assert_is(ctx, g->b[2], "-m2*l2*cos(th1 - th2)/((m1 + m2)*l1)");
    qt_assert_is(ctx, g->b[3], "1");
    qt_assert_is(ctx, g->norm[0], "(m1 + m2)*l1^2");
    qd_zero_result z;
    const qd_expr *schur = expr(ctx, "l2^2*m2*(m1 + m2*sin(th1 - th2)^2)/(m1 + m2)");
    assert_int_equal(qd_equal_test(ctx, g->norm[1], schur, &z), QD_OK);
    assert_true(z.kind == QD_ZERO_PROVEN || z.kind == QD_ZERO_NUMERIC);
    assert_int_equal(qd_zero_test(ctx, dot(ctx, 2, T, g->b, g->b + 2), &z), QD_OK); /* eq. 4 */
    assert_true(z.kind == QD_ZERO_PROVEN || z.kind == QD_ZERO_NUMERIC);
    qd_gram_free(g);
    qd_ctx_free(ctx);
}

static void test_errors(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    static const char *const dep_text[] = {"1", "2", "0", "0", "1", "1", "2", "4", "0"};
    const qd_expr *a[9];
    read_all(ctx, 9, dep_text, a); /* a3 = 2 a1 */
    assert_null(qd_gram_schmidt(ctx, 3, NULL, 3, a));
    assert_int_equal(qd_ctx_status(ctx), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(ctx), "a3 is a linear combination"));
    qd_ctx_clear_error(ctx);

    static const char *const ind_text[] = {"1", "0", "0", "-1"}, *const null_text[] = {"1", "1"};
    const qd_expr *T[4], *v[2];
    read_all(ctx, 4, ind_text, T);
    read_all(ctx, 2, null_text, v);
    assert_null(qd_gram_schmidt(ctx, 2, T, 1, v)); /* (1,1)^T diag(1,-1) (1,1) = 0 */
    assert_int_equal(qd_ctx_status(ctx), QD_ERR_SINGULAR);
    qd_ctx_clear_error(ctx);

    T[1] = qd_int(ctx, 2); /* T12 = 2, T21 = 0 */
    assert_null(qd_gram_schmidt(ctx, 2, T, 1, v));
    assert_int_equal(qd_ctx_status(ctx), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(ctx), "not symmetric"));
    qd_ctx_clear_error(ctx);

    assert_null(qd_gram_schmidt(ctx, 1, NULL, 2, v)); /* two vectors of one component */
    assert_int_equal(qd_ctx_status(ctx), QD_ERR_ARG);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_thm1_by_hand),
        cmocka_unit_test(test_thm2_double_pendulum),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
