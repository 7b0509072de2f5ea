/*
 * tests/render/test_render.c - the renderers of whole systems (qdot/render.h)
 * against mechanics:
 *   the pendulum ml^2 theta'' = -m g l sin(theta) (Goldstein ch. 1): at a
 *     state the text and JSON give theta'' = -(g/l) sin(theta), and the
 *     symbolic text, read back by qd_read, is M and f themselves;
 *   a bead on a hoop, a particle constrained to x^2 + y^2 = l^2 in a
 *     plane under gravity at rest at angle th from the bottom: the multiplier
 *     balances gravity's normal part, lambda = m g cos(th) / (2 l), and
 *     R = A^T lambda = 2 lambda (x, y);
 *   a mass matrix that vanishes at a state (x^2 x''): QD_ERR_SINGULAR with
 *     the state in the message, and nothing else claimed;
 *   Euler's free body in its speeds: A w1' = (B - C) w2 w3 at a state;
 *   every format of every renderer is given a 1-byte allocation budget
 *     elsewhere (fault tests); here, the formats a state cannot take.
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
#include "qdot/render.h"
#include "util/system.h"

static int teardown(void **state) { return qt_system_teardown(state); }

#define PENDULUM "coordinates theta\nparameters m = 2, l = 1.5, g = 9.81\n" \
                 "T = m/2*l^2*theta'^2\nV = -m*g*l*cos(theta)\n"

/* The number after "key" in s (the first occurrence). */
static double number_after(const char *s, const char *key) {
    const char *p = strstr(s, key);
    assert_non_null(p);
    return strtod(p + strlen(key), NULL);
}

static void test_pendulum_at_state(void **state) {
    qt_system *s = qt_system_derive(state, PENDULUM, false);
    const qd_expr *syms[] = {qt_symbol(s, "theta"), qt_symbol(s, "theta'"), qd_time(s->ctx)};
    double vals[] = {0.7, -0.4, 0};
    qd_render_opts o = {.source = "pendulum.qd", .nstate = 3, .syms = syms, .vals = vals};
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(QD_OK, qd_render_eom(s->ctx, s->model, s->eom, &o, QD_RENDER_TEXT, &b));
    double want = -9.81 / 1.5 * sin(0.7);
    assert_true(fabs(number_after(qd_buf_str(&b), "theta'' = ") - want) <= 1e-15 * fabs(want));
    /* M = m l^2 as a number, and the state echoed */
    assert_true(fabs(number_after(qd_buf_str(&b), "M[theta,theta] = ") - 2 * 1.5 * 1.5) < 1e-14);
    assert_non_null(strstr(qd_buf_str(&b), "at: theta = 0.7, theta' = -0.4, t = 0"));
    qd_buf_clear(&b);
    assert_int_equal(QD_OK, qd_render_eom(s->ctx, s->model, s->eom, &o, QD_RENDER_JSON, &b));
    assert_true(fabs(number_after(qd_buf_str(&b), "\"accelerations\": [") - want) <=
                1e-15 * fabs(want));
    assert_non_null(strstr(qd_buf_str(&b), "\"model\": \"pendulum.qd\""));
    qd_buf_free(&b);
}

/* The symbolic text's entries read back (qd_read) are M and f. */
static void test_pendulum_text_reads_back(void **state) {
    qt_system *s = qt_system_derive(state, PENDULUM, false);
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(QD_OK, qd_render_eom(s->ctx, s->model, s->eom, NULL, QD_RENDER_TEXT, &b));
    const char *keys[] = {"M[theta,theta] = ", "f[theta] = "};
    const qd_expr *want[] = {s->eom->M[0], s->eom->f[0]};
    for (int k = 0; k < 2; k++) {
        const char *p = strstr(qd_buf_str(&b), keys[k]);
        assert_non_null(p);
        p += strlen(keys[k]);
        char line[256];
        size_t len = strcspn(p, "\n");
        assert_true(len < sizeof line);
        memcpy(line, p, len);
        line[len] = '\0';
        qd_read_opts ro = {.new_symbols = true};
        qd_diag d;
        const qd_expr *x = qd_read(s->ctx, line, &ro, &d);
        assert_non_null(x);
        assert_true(qd_is_zero(qd_simplify(s->ctx, qd_sub(s->ctx, x, want[k]))));
    }
    assert_non_null(strstr(qd_buf_str(&b), "model: model\n")); /* no source given */
    qd_buf_free(&b);
}

static void test_hoop_multiplier(void **state) {
    qt_system *s = qt_system_derive(state,
        "coordinates x, y\nparameters m = 1.5, g = 9.81, l = 2\n"
        "T = m/2*(x'^2 + y'^2)\nV = m*g*y\nconstraint hoop: x^2 + y^2 = l^2\n", false);
    double th = 0.4, l = 2, m = 1.5, g = 9.81;
    const qd_expr *syms[] = {qt_symbol(s, "x"), qt_symbol(s, "y"), qt_symbol(s, "x'"),
                             qt_symbol(s, "y'"), qd_time(s->ctx)};
    double vals[] = {l * sin(th), -l * cos(th), 0, 0, 0};
    qd_render_opts o = {.nstate = 5, .syms = syms, .vals = vals};
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(QD_OK, qd_render_eom(s->ctx, s->model, s->eom, &o, QD_RENDER_TEXT, &b));
    /* at rest the normal force balances gravity's normal part: |R| = m g cos(th),
     * R = 2 lambda (x, y) with |(x, y)| = l, pointing to the centre (lambda < 0
     * under the sign convention M q'' = f + A^T lambda with A = (2x, 2y)) */
    double lam = number_after(qd_buf_str(&b), "lambda_hoop = ");
    assert_true(fabs(fabs(lam) - m * g * cos(th) / (2 * l)) < 1e-12);
    double Rx = number_after(qd_buf_str(&b), "R[x] = ");
    assert_true(fabs(Rx - 2 * lam * vals[0]) < 1e-12);
    qd_buf_free(&b);
}

static void test_singular_at_state(void **state) {
    qt_system *s = qt_system_derive(state,
        "coordinates x\nparameters m = 1\nT = m/2*x^2*x'^2\nV = x^2\n", false);
    const qd_expr *syms[] = {qt_symbol(s, "x"), qt_symbol(s, "x'"), qd_time(s->ctx)};
    double vals[] = {0, 1, 0};
    qd_render_opts o = {.nstate = 3, .syms = syms, .vals = vals};
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(QD_ERR_SINGULAR,
                     qd_render_eom(s->ctx, s->model, s->eom, &o, QD_RENDER_TEXT, &b));
    assert_non_null(strstr(qd_ctx_message(s->ctx), "singular at x=0, x'=1, t=0"));
    qd_buf_free(&b);
}

static void test_euler_speeds(void **state) {
    qt_system *s = qt_system_parse(state,
        "coordinates phi, theta, psi\nparameters A = 1, B = 2, C = 3\n"
        "body b mass 1 inertia (A, B, C) at (0, 0, 0) orientation euler(phi, theta, psi)\n"
        "speeds w1 = omega(b).x, w2 = omega(b).y, w3 = omega(b).z\n");
    qd_speeds_eom *e = qd_speeds_derive(s->ctx, s->model, NULL);
    assert_non_null(e);
    const qd_expr *syms[] = {qt_symbol(s, "phi"), qt_symbol(s, "theta"), qt_symbol(s, "psi"),
                             qd_time(s->ctx), e->u[0], e->u[1], e->u[2]};
    double vals[] = {0.1, 1, 0.2, 0, 0.2, 1, 0.5};
    qd_render_opts o = {.nstate = 7, .syms = syms, .vals = vals};
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(QD_OK, qd_render_speeds(s->ctx, s->model, e, &o, QD_RENDER_TEXT, &b));
    assert_true(fabs(number_after(qd_buf_str(&b), "w1' = ") - (2 - 3) * 1 * 0.5 / 1.0) < 1e-14);
    assert_true(fabs(number_after(qd_buf_str(&b), "w3' = ") - (1 - 2) * 0.2 * 1 / 3.0) < 1e-14);
    /* theta' = w1 cos(psi) - w2 sin(psi) (the kinematics) */
    assert_true(fabs(number_after(qd_buf_str(&b), "theta' = ") - (0.2 * cos(0.2) - sin(0.2))) <
                1e-14);
    qd_buf_clear(&b);
    /* the symbols at a state are numbers: no LaTeX, SymPy or C of them */
    assert_int_equal(QD_ERR_ARG, qd_render_speeds(s->ctx, s->model, e, &o, QD_RENDER_LATEX, &b));
    qd_ctx_clear_error(s->ctx);
    assert_int_equal(QD_OK, qd_render_speeds(s->ctx, s->model, e, NULL, QD_RENDER_SYMPY, &b));
    assert_non_null(strstr(qd_buf_str(&b), "M = Matrix(["));
    qd_buf_clear(&b);
    assert_int_equal(QD_OK, qd_render_hamel(s->ctx, e, QD_RENDER_TEXT, &b));
    assert_non_null(strstr(qd_buf_str(&b), "gamma[w1,w2,w3] = -1")); /* gamma = -eps */
    qd_buf_free(&b);
    qd_speeds_eom_free(e);
}

static void test_format_names(void **state) {
    (void)state;
    for (int f = QD_RENDER_TEXT; f <= QD_RENDER_C; f++) {
        qd_render_format back = QD_RENDER_TEXT;
        assert_true(qd_render_format_parse(qd_render_format_name((qd_render_format)f), &back));
        assert_int_equal(f, back);
    }
    qd_render_format out = QD_RENDER_C;
    assert_false(qd_render_format_parse("tex", &out));
    assert_int_equal(QD_RENDER_C, out);
    assert_null(qd_render_format_name((qd_render_format)99));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(test_pendulum_at_state, teardown),
        cmocka_unit_test_teardown(test_pendulum_text_reads_back, teardown),
        cmocka_unit_test_teardown(test_hoop_multiplier, teardown),
        cmocka_unit_test_teardown(test_singular_at_state, teardown),
        cmocka_unit_test_teardown(test_euler_speeds, teardown),
        cmocka_unit_test(test_format_names),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
