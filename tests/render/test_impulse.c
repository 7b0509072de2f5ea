/*
 * tests/render/test_impulse.c - qd_render_impulse on the rhombus falling
 * on a wall (Byerly art. 33): x'+ = -3/7 at al = 30 deg, a = v = 1, and the
 * wall's impulse 16/7; the JSON carries these numbers and the text the
 * closed form's value.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/render.h"

static const char rhombus[] =
    "coordinates x, th\n"
    "parameters m = 1, a = 1, v = 1, al = pi/6\n"
    "T = 2*m*x'^2 + 8/3*m*a^2*th'^2\n"
    "C = (x - 2*a*cos(th), 0, 0)\n"
    "impact constraint wall: C.x = 0\n"
    "initial x = 2*a*cos(al), th = al, x' = -v, th' = 0\n";

/* The number after "key": in a JSON text. */
static double after_key(const char *s, const char *key) {
    const char *p = strstr(s, key);
    assert_non_null(p);
    return strtod(p + strlen(key), NULL);
}

static void rhombus_wall(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    memset(&d, 0, sizeof d);
    qd_model *m = qd_model_parse(ctx, rhombus, &d);
    assert_non_null(m);
    qd_impulse r;
    qd_impulse_opts o = {.exact = true};
    assert_int_equal(qd_impulse_solve(ctx, m, &o, &r), QD_OK);
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_render_impulse(ctx, m, &r, QD_RENDER_JSON, &b), QD_OK);
    const char *s = qd_buf_str(&b);
    const char *va = strstr(s, "\"velocities_after\"");
    assert_non_null(va);
    assert_true(fabs(after_key(va, "\"x'\":") + 3.0 / 7) < 1e-9);
    /* the wall stops the end C, which moved at -v before: the energy lost is positive */
    assert_true(after_key(s, "\"energy_lost\":") > 0);
    qd_buf_free(&b);
    b = (qd_buf)QD_BUF_INIT;
    assert_int_equal(qd_render_impulse(ctx, m, &r, QD_RENDER_TEXT, &b), QD_OK);
    assert_non_null(strstr(qd_buf_str(&b), "-0.428571428571")); /* -3/7 */
    qd_buf_free(&b);
    b = (qd_buf)QD_BUF_INIT;
    assert_int_equal(qd_render_impulse(ctx, m, &r, QD_RENDER_SYMPY, &b), QD_ERR_ARG);
    qd_buf_free(&b);
    qd_impulse_free(&r);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(rhombus_wall)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
