/*
 * tests/action/test_action_print.c - the action-angle variables as
 * qd_action_print writes them, read back from the JSON and the text and
 * checked against the textbook (Goldstein sec. 10.6; Desloge ch. 79), in
 * qdot's convention J = oint p dq (qdot/action.h):
 *
 *   the oscillator    J = 2 pi E / omega, omega = 2 pi dE/dJ (the
 *                     difference quotient of two printed states: H is linear
 *                     in J), the turning points +-sqrt(2 E / k), H(J) linear;
 *   the pendulum      the period 2 pi / omega = 4 K(k) sqrt(l/g),
 *                     k = sin(theta0/2), K by the arithmetic-geometric mean
 *                     (A&S 17.6), independently of the library.
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
#include "qdot/action.h"
#include "qdot/read.h"

#define PI 3.14159265358979323846

static const char OSC[] = "coordinates x\nparameters m = 1.7, k = 3.2\n"
                          "T = m/2*x'^2\nV = k/2*x^2\n";
static const char PEND[] = "coordinates theta\nparameters m = 1.1, l = 1.3, g = 9.81\n"
                           "T = m/2*l^2*theta'^2\nV = -m*g*l*cos(theta)\n";

/* The number after "key": in a JSON text. */
static double number_at(const char *json, const char *key) {
    char k[64];
    snprintf(k, sizeof k, "\"%s\": ", key);
    const char *p = strstr(json, k);
    assert_non_null(p);
    return strtod(p + strlen(k), NULL);
}

/* The number after text in s. */
static double number_after(const char *s, const char *text) {
    const char *p = strstr(s, text);
    assert_non_null(p);
    return strtod(p + strlen(text), NULL);
}

static void close_to(const char *what, double got, double want, double tol) {
    if (!(fabs(got - want) <= tol * fmax(1e-300, fabs(want))))
        fail_msg("%s: got %.17g, want %.17g", what, got, want);
}

/* Model text at the state (coordinate q0, velocity v0, the parameters at
 * their values) written out by qd_action_print; the caller frees it. */
static char *printed(const char *model, const char *q, double q0, double v0, bool json) {
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, model, &d);
    assert_non_null(m);
    const qd_expr *syms[8];
    double vals[8];
    size_t n = 0;
    for (size_t i = 0; i < qd_model_nparams(m); i++) {
        syms[n] = qd_model_param(m, i);
        assert_int_equal(qd_eval(ctx, qd_model_param_value(m, i), 0, NULL, NULL, &vals[n++]),
                         QD_OK);
    }
    char qd[32];
    snprintf(qd, sizeof qd, "%s'", q);
    syms[n] = qd_read(ctx, q, NULL, NULL);
    vals[n++] = q0;
    syms[n] = qd_read(ctx, qd, NULL, NULL);
    vals[n++] = v0;
    qd_action a;
    if (qd_action_at(ctx, m, n, syms, vals, NULL, &a) != QD_OK)
        fail_msg("qd_action_at: %s", qd_ctx_message(ctx));
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_action_print(ctx, &a, json, &b), QD_OK);
    char *s = malloc(b.len + 1);
    assert_non_null(s);
    memcpy(s, qd_buf_str(&b), b.len + 1);
    qd_buf_free(&b);
    qd_action_free(&a);
    qd_model_free(m);
    qd_ctx_free(ctx);
    return s;
}

/* J = 2 pi E / omega and omega = 2 pi dE/dJ from the JSON of two states. */
static void test_oscillator_json(void **state) {
    (void)state;
    double m = 1.7, k = 3.2, w = sqrt(k / m), x0[] = {0.8, 1.1}, E[2], J[2];
    for (int i = 0; i < 2; i++) {
        char *s = printed(OSC, "x", x0[i], 0, true);
        E[i] = number_at(s, "energy");
        close_to("E = k x0^2 / 2", E[i], k / 2 * x0[i] * x0[i], 1e-15);
        const char *c = strstr(s, "\"coordinates\": [");
        assert_non_null(c);
        J[i] = number_at(c, "J");
        close_to("J = 2 pi E / omega", J[i], 2 * PI * E[i] / w, 1e-12);
        close_to("omega", number_at(c, "omega"), w, 1e-11);
        const char *tp = strstr(c, "\"turning_points\": [");
        assert_non_null(tp);
        double lo = strtod(tp + strlen("\"turning_points\": ["), NULL);
        close_to("lower turning point", lo, -sqrt(2 * E[i] / k), 1e-12);
        /* the summary objects carry the same numbers by coordinate name */
        close_to("actions.x", number_at(strstr(s, "\"actions\": {"), "x"), J[i], 0);
        close_to("frequencies.x", number_at(strstr(s, "\"frequencies\": {"), "x"), w, 1e-11);
        assert_non_null(strstr(s, "\"form\": \"sum omega_k J_k/(2 pi)\""));
        assert_non_null(strstr(s, "\"degeneracies\": []"));
        free(s);
    }
    close_to("omega = 2 pi dE/dJ", 2 * PI * (E[1] - E[0]) / (J[1] - J[0]), w, 1e-10);
}

/* The text carries the same: J, omega and the period to 12 digits. */
static void test_oscillator_text(void **state) {
    (void)state;
    double m = 1.7, k = 3.2, w = sqrt(k / m), x0 = 0.8, E = k / 2 * x0 * x0;
    char *s = printed(OSC, "x", x0, 0, false);
    assert_true(!strncmp(s, "separation: ", 12));
    close_to("energy", number_after(s, "\nenergy: "), E, 1e-11);
    close_to("J_x", number_after(s, "J_x = "), 2 * PI * E / w, 1e-11);
    close_to("omega_x", number_after(s, "omega_x = "), w, 1e-11);
    close_to("period", number_after(s, "rad/s, period "), 2 * PI / w, 1e-11);
    close_to("H(J) = omega J / (2 pi)", number_after(s, "H(J) = "), w, 1e-11);
    assert_non_null(strstr(s, "x: libration between "));
    free(s);
}

/* K(k) by the arithmetic-geometric mean: K = pi / (2 agm(1, sqrt(1 - k^2))). */
static double ellip_K(double k) {
    double a = 1, b = sqrt(1 - k * k);
    for (int i = 0; i < 40 && fabs(a - b) > 1e-16 * a; i++) {
        double an = (a + b) / 2;
        b = sqrt(a * b);
        a = an;
    }
    return PI / (2 * a);
}

/* The pendulum's period from the printed omega, against 4 K(k) sqrt(l/g). */
static void test_pendulum(void **state) {
    (void)state;
    double l = 1.3, g = 9.81, th0 = 1.0;
    char *s = printed(PEND, "theta", th0, 0, true);
    double omega = number_at(strstr(s, "\"coordinates\": ["), "omega");
    close_to("period 4 K(k) sqrt(l/g)", 2 * PI / omega, 4 * ellip_K(sin(th0 / 2)) * sqrt(l / g),
             1e-10);
    assert_non_null(strstr(s, "\"H_of_J\": null"));
    free(s);
    s = printed(PEND, "theta", th0, 0, false);
    close_to("period in the text", number_after(s, "rad/s, period "),
             4 * ellip_K(sin(th0 / 2)) * sqrt(l / g), 1e-10);
    free(s);
}

/* An inconsistent result, and one JSON cannot hold, are refused and
 * nothing is written. */
static void test_refused(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_action a = {.n = 1};
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_action_print(ctx, &a, true, &b), QD_ERR_ARG);
    assert_int_equal(b.len, 0);
    /* JSON has no NaN: a result that holds one is refused whole */
    qd_act_coord c = {.q = qd_symbol(ctx, "x"), .constant = qd_symbol(ctx, "E"), .J = NAN};
    a.c = &c;
    assert_int_equal(qd_action_print(ctx, &a, true, &b), QD_ERR_NUMERIC);
    assert_int_equal(b.len, 0);
    qd_buf_free(&b);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_oscillator_json),
        cmocka_unit_test(test_oscillator_text),
        cmocka_unit_test(test_pendulum),
        cmocka_unit_test(test_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
