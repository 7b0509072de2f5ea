/*
 * tests/mech/test_bracket_print.c - what `qdot bracket` prints, as the
 * library writes it (qd_phase_bracket_print, qdot/canonical.h), read back
 * and checked against the mathematics (Goldstein, Classical Mechanics, 3rd
 * ed., ch. 9.5-9.6):
 *
 *   a particle in a plane with V = k/2 (x^2 + y^2): the fundamental
 *   brackets [x, p_x] = 1, [x, p_y] = 0, [p_x, p_y] = 0 read from the JSON
 *   "bracket"; the angular momentum L = x p_y - y p_x has [x, L] = -y =
 *   -[L, x] ([x_i, L_j] = eps_ijk x_k) and
 *   is conserved, dL/dt = [L, H] = 0, and dp_x/dt = -dV/dx = -k x (the
 *   JSON's "dF_dt", with "H" = (p_x^2 + p_y^2)/(2m) + V); the text and the
 *   LaTeX lines carry the same value; dF/dt without H and a format other
 *   than text or LaTeX are refused with nothing written.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/canonical.h"
#include "util/check.h"
#include "util/jsonwalk.h"

static const char PLANE[] = "coordinates x, y\nparameters m = 2, k = 3\nparticle m at (x, y)\n"
                            "V = k/2*(x^2 + y^2)\n";

typedef struct fix {
    qd_ctx *ctx;
    qd_model *m;
    qd_phase ph;
} fix;

static void fix_open(fix *f) {
    memset(f, 0, sizeof *f);
    f->ctx = qd_ctx_new();
    assert_non_null(f->ctx);
    f->m = qt_parse_ok(f->ctx, PLANE);
    assert_int_equal(qd_phase_init(f->ctx, f->m, &f->ph), QD_OK);
}

static void fix_close(fix *f) {
    qd_phase_free(&f->ph);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
}

static const qd_expr *fn(fix *f, const char *text) {
    qd_diag d;
    const qd_expr *x = qd_phase_read(f->ctx, &f->ph, text, &d);
    if (!x)
        fail_msg("qd_phase_read(%s): %s", text, d.message);
    return x;
}

/* The JSON member key (a string holding an expression) read back as an
 * expression of the model's symbols. */
static const qd_expr *member(fix *f, const char *doc, const char *key) {
    char text[512];
    if (!qt_json_str(qt_json_get(doc, key), text, sizeof text))
        fail_msg("no string \"%s\" in %s", key, doc);
    return fn(f, text);
}

/* [F, G] as JSON, the document checked and returned (caller frees). */
static char *bracket_json(fix *f, const char *F, const char *G) {
    const qd_expr *a = fn(f, F), *b = G ? fn(f, G) : NULL;
    const qd_expr *r = b ? qd_bracket(f->ctx, f->ph.n, f->ph.q, f->ph.p, a, b)
                         : qd_phase_dt(f->ctx, &f->ph, a);
    assert_non_null(r);
    qd_buf out = QD_BUF_INIT;
    assert_int_equal(qd_phase_bracket_print(f->ctx, &f->ph, a, b, r, QD_FMT_TEXT, true, &out),
                     QD_OK);
    char *s = malloc(out.len + 1);
    if (s)
        memcpy(s, qd_buf_str(&out), out.len + 1);
    qd_buf_free(&out);
    assert_non_null(s);
    assert_true(qt_json_valid(s));
    assert_int_equal(s[strlen(s) - 1], '\n');
    return s;
}

static void test_fundamental(void **state) {
    (void)state;
    fix f;
    fix_open(&f);
    char *s = bracket_json(&f, "x", "p_x");
    const char *mom = qt_json_get(s, "momenta");
    assert_int_equal(qt_json_len(mom), 2);
    assert_true(qt_json_str_is(qt_json_at(mom, 0), "p_x"));
    assert_true(qt_json_str_is(qt_json_at(mom, 1), "p_y"));
    qt_assert_is(f.ctx, member(&f, s, "bracket"), "1");
    qt_assert_is(f.ctx, member(&f, s, "F"), "x");
    qt_assert_is(f.ctx, member(&f, s, "G"), "p_x");
    assert_null(qt_json_get(s, "dF_dt"));
    free(s);
    s = bracket_json(&f, "x", "p_y");
    qt_assert_is(f.ctx, member(&f, s, "bracket"), "0");
    free(s);
    s = bracket_json(&f, "p_x", "p_y");
    qt_assert_is(f.ctx, member(&f, s, "bracket"), "0");
    free(s);
    /* the angular momentum generates rotations: [x, L] = -y, [L, x] = y */
    s = bracket_json(&f, "x", "x*p_y - y*p_x");
    qt_assert_is(f.ctx, member(&f, s, "bracket"), "-y");
    free(s);
    s = bracket_json(&f, "x*p_y - y*p_x", "x");
    qt_assert_is(f.ctx, member(&f, s, "bracket"), "y");
    free(s);
    fix_close(&f);
}

static void test_rates(void **state) {
    (void)state;
    fix f;
    fix_open(&f);
    /* the central force conserves L */
    char *s = bracket_json(&f, "x*p_y - y*p_x", NULL);
    qt_assert_is(f.ctx, member(&f, s, "dF_dt"), "0");
    assert_null(qt_json_get(s, "bracket"));
    assert_null(qt_json_get(s, "implicit"));
    qt_assert_is(f.ctx, member(&f, s, "H"), "(p_x^2 + p_y^2)/(2*m) + k/2*(x^2 + y^2)");
    free(s);
    /* dp_x/dt = -dV/dx */
    s = bracket_json(&f, "p_x", NULL);
    qt_assert_is(f.ctx, member(&f, s, "dF_dt"), "-k*x");
    free(s);
    fix_close(&f);
}

static void test_lines(void **state) {
    (void)state;
    fix f;
    fix_open(&f);
    const qd_expr *x = fn(&f, "x"), *px = fn(&f, "p_x");
    const qd_expr *r = qd_bracket(f.ctx, f.ph.n, f.ph.q, f.ph.p, x, px);
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_phase_bracket_print(f.ctx, &f.ph, x, px, r, QD_FMT_TEXT, false, &b),
                     QD_OK);
    /* "[F, G] = value": the value after " = " reads back as 1 */
    const char *eq = strstr(qd_buf_str(&b), "] = ");
    assert_non_null(eq);
    assert_int_equal(qd_buf_str(&b)[0], '[');
    char text[64];
    snprintf(text, sizeof text, "%s", eq + 4);
    text[strcspn(text, "\n")] = '\0';
    qt_assert_is(f.ctx, fn(&f, text), "1");
    qd_buf_free(&b);
    b = (qd_buf)QD_BUF_INIT;
    assert_int_equal(qd_phase_bracket_print(f.ctx, &f.ph, x, px, r, QD_FMT_LATEX, false, &b),
                     QD_OK);
    assert_non_null(strstr(qd_buf_str(&b), "\\left\\{"));
    assert_non_null(strstr(qd_buf_str(&b), "\\right\\} = 1\n"));
    qd_buf_free(&b);
    fix_close(&f);
}

static void test_refused(void **state) {
    (void)state;
    fix f;
    fix_open(&f);
    const qd_expr *x = fn(&f, "x");
    qd_buf b = QD_BUF_INIT;
    /* dF/dt with H not derived yet */
    assert_int_equal(qd_phase_bracket_print(f.ctx, &f.ph, x, NULL, x, QD_FMT_TEXT, false, &b),
                     QD_ERR_ARG);
    assert_int_equal(b.len, 0);
    qd_ctx_clear_error(f.ctx);
    assert_int_equal(qd_phase_bracket_print(f.ctx, &f.ph, x, x, x, QD_FMT_C, false, &b),
                     QD_ERR_ARG);
    assert_int_equal(b.len, 0);
    qd_buf_free(&b);
    fix_close(&f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_fundamental),
        cmocka_unit_test(test_rates),
        cmocka_unit_test(test_lines),
        cmocka_unit_test(test_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
