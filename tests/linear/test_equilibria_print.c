/*
 * tests/linear/test_equilibria_print.c - what `qdot equilibria` prints, as
 * the library writes it (qd_equilibria_print, qdot/equilibria.h), read back
 * and checked against the mechanics:
 *
 *   the plane pendulum, V = -m g l cos(theta): exactly two equilibria in
 *   (-pi, pi], theta = 0 hanging (a minimum of V, V'' = m g l > 0) and
 *   theta = pi upright (a maximum), found exactly ("exact": true and the
 *   exact values 0 and pi in the JSON, their numbers 0 and 3.14159...);
 *   K = -dF/dq is 1x1, so each Hessian has one sign and K is symmetric;
 *   the text says "2 equilibria", names the kinds and the complete set;
 *   the 2D oscillator with a free direction (V = k/2 x^2, y cyclic) is a
 *   family: "continuum" in the JSON and the note in the text;
 *   equilibria not over the equations' coordinates are refused.
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
#include "qdot/equilibria.h"
#include "qdot/state.h"
#include "util/check.h"
#include "util/jsonwalk.h"

static const double PI = 3.14159265358979323846;

static const char PENDULUM[] = "coordinates theta\nparameters m = 1.5, l = 2, g = 9.81\n"
                               "particle m at (l*sin(theta), -l*cos(theta))\nV = m*g*(-l*cos(theta))\n";
static const char FREE_Y[] = "coordinates x, y\nparameters m = 1, k = 4\nparticle m at (x, y)\n"
                             "V = k/2*x^2\n";

typedef struct fix {
    qd_ctx *ctx;
    qd_model *m;
    qd_eom *e;
    qd_state st;
    qd_equilibria eq;
} fix;

static void fix_open(fix *f, const char *model) {
    memset(f, 0, sizeof *f);
    f->ctx = qd_ctx_new();
    assert_non_null(f->ctx);
    f->m = qt_parse_ok(f->ctx, model);
    f->e = qd_eom_derive(f->ctx, f->m);
    assert_non_null(f->e);
    assert_int_equal(qd_state_init(f->ctx, f->m, &f->st), QD_OK);
    qd_status st = qd_equilibria_find(f->ctx, f->e, f->m, f->st.n, f->st.syms, f->st.vals, NULL,
                                      &f->eq);
    if (st != QD_OK)
        fail_msg("qd_equilibria_find: %s", qd_ctx_message(f->ctx));
}

static void fix_close(fix *f) {
    qd_equilibria_free(&f->eq);
    qd_state_free(&f->st);
    qd_eom_free(f->e);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
}

static char *print(fix *f, bool json) {
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_equilibria_print(f->ctx, f->e, &f->eq, json, &b), QD_OK);
    char *s = malloc(b.len + 1);
    assert_non_null(s);
    memcpy(s, qd_buf_str(&b), b.len + 1);
    qd_buf_free(&b);
    return s;
}

/* The JSON string member key of obj read back as an expression. */
static const qd_expr *expr_member(qd_ctx *ctx, const char *obj, const char *key) {
    char text[256];
    assert_true(qt_json_str(qt_json_get(obj, key), text, sizeof text));
    qd_diag d;
    const qd_expr *x = qd_read(ctx, text, NULL, &d);
    if (!x)
        fail_msg("cannot read '%s': %s", text, d.message);
    return x;
}

/* The equilibrium of the JSON whose theta is near want. */
static const char *point_near(const char *doc, double want) {
    const char *arr = qt_json_get(doc, "equilibria");
    for (size_t i = 0; i < qt_json_len(arr); i++) {
        const char *p = qt_json_at(arr, i);
        if (fabs(qt_json_num(qt_json_get(qt_json_get(p, "equilibrium"), "theta")) - want) < 1e-9)
            return p;
    }
    fail_msg("no equilibrium at theta = %g in %s", want, doc);
    return NULL;
}

static void test_pendulum_json(void **state) {
    (void)state;
    fix f;
    fix_open(&f, PENDULUM);
    char *s = print(&f, true);
    assert_true(qt_json_valid(s));
    assert_int_equal(s[strlen(s) - 1], '\n');
    assert_true(qt_json_str_is(qt_json_get(s, "method"), "exact"));
    assert_true(strncmp(qt_json_get(s, "exact"), "true", 4) == 0);
    assert_true(strncmp(qt_json_get(s, "continuum"), "false", 5) == 0);
    assert_int_equal(qt_json_len(qt_json_get(s, "equilibria")), 2);
    /* hanging: a minimum of V = -m g l cos(theta), V'' = m g l > 0 */
    const char *down = point_near(s, 0);
    assert_true(qt_json_str_is(qt_json_get(down, "kind"), "minimum"));
    qt_assert_is(f.ctx, expr_member(f.ctx, qt_json_get(down, "exact"), "theta"), "0");
    const char *signs = qt_json_get(down, "hessian_signs");
    assert_int_equal(qt_json_len(signs), 3);
    assert_true(qt_json_num(qt_json_at(signs, 0)) == 1 && qt_json_num(qt_json_at(signs, 1)) == 0);
    assert_true(strncmp(qt_json_get(down, "symmetric"), "true", 4) == 0);
    assert_true(qt_json_num(qt_json_get(down, "residual")) < 1e-10);
    /* upright: a maximum, V'' = -m g l */
    const char *up = point_near(s, PI);
    assert_true(qt_json_str_is(qt_json_get(up, "kind"), "maximum"));
    qt_assert_is(f.ctx, expr_member(f.ctx, qt_json_get(up, "exact"), "theta"), "pi");
    signs = qt_json_get(up, "hessian_signs");
    assert_true(qt_json_num(qt_json_at(signs, 0)) == 0 && qt_json_num(qt_json_at(signs, 1)) == 1);
    free(s);
    fix_close(&f);
}

static void test_pendulum_text(void **state) {
    (void)state;
    fix f;
    fix_open(&f, PENDULUM);
    char *s = print(&f, false);
    assert_true(strncmp(s, "2 equilibria (exact: the complete set", 37) == 0);
    /* one numbered line per point, its kind on the line after */
    const char *one = strstr(s, "  1  theta = "), *two = strstr(s, "  2  theta = ");
    assert_non_null(one);
    assert_non_null(two);
    const char *k1 = strstr(one, " of the potential"), *k2 = strstr(two, " of the potential");
    assert_non_null(k1);
    assert_non_null(k2);
    /* the values read back: 0 is the minimum, pi the maximum */
    bool first_is_zero = strncmp(one + 13, "0\n", 2) == 0;
    const char *zero = first_is_zero ? one : two, *pi = first_is_zero ? two : one;
    assert_true(strncmp(zero + 13, "0\n", 2) == 0);
    assert_true(strncmp(pi + 13, "pi (3.14159265359)\n", 19) == 0);
    assert_non_null(strstr(zero, "minimum of the potential (Hessian: 1 positive, 0 negative"));
    assert_non_null(strstr(pi, "maximum of the potential (Hessian: 0 positive, 1 negative"));
    assert_null(strstr(s, "not isolated"));
    free(s);
    fix_close(&f);
}

static void test_family(void **state) {
    (void)state;
    fix f;
    fix_open(&f, FREE_Y);
    assert_true(f.eq.continuum);
    char *s = print(&f, true);
    assert_true(qt_json_valid(s));
    assert_true(strncmp(qt_json_get(s, "continuum"), "true", 4) == 0);
    /* every sample is at x = 0 (F = -k x), y anywhere, degenerate */
    const char *arr = qt_json_get(s, "equilibria");
    assert_true(qt_json_len(arr) >= 1);
    for (size_t i = 0; i < qt_json_len(arr); i++) {
        const char *p = qt_json_at(arr, i);
        assert_true(fabs(qt_json_num(qt_json_get(qt_json_get(p, "equilibrium"), "x"))) < 1e-9);
        assert_true(qt_json_str_is(qt_json_get(p, "kind"), "degenerate"));
    }
    free(s);
    s = print(&f, false);
    assert_non_null(strstr(s, "note: the equilibria are not isolated"));
    free(s);
    fix_close(&f);
}

static void test_refused(void **state) {
    (void)state;
    fix f;
    fix_open(&f, PENDULUM);
    qd_buf b = QD_BUF_INIT;
    f.eq.n++;
    assert_int_equal(qd_equilibria_print(f.ctx, f.e, &f.eq, false, &b), QD_ERR_ARG);
    f.eq.n--;
    assert_int_equal(b.len, 0);
    qd_buf_free(&b);
    fix_close(&f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pendulum_json),
        cmocka_unit_test(test_pendulum_text),
        cmocka_unit_test(test_family),
        cmocka_unit_test(test_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
