/*
 * tests/linear/test_statespace_print.c - qd_statespace_render
 * (qdot/statespace.h), the printer of `qdot linearize`, on the pendulum
 * m l^2 th'' = -m g l sin th + tau:
 *
 *   - at the bottom (th = 0) the JSON is valid and holds
 *     A = [[0, 1], [-g/l, 0]], B = [[0], [1/(m l^2)]], the eigenvalues
 *     +-i sqrt(g/l), controllability (rank 2), and A_exact[1][0] an
 *     expression that reads back and evaluates to -g/l; the text's A rows
 *     read back to the same numbers and its eigenvalues are +-i sqrt(g/l);
 *     the C and SymPy forms carry the exact entry, read back as -g/l;
 *   - held upright (th = pi) with an LQR design: the JSON's "lqr" gain is
 *     the hand solution of the Riccati equation for x'' = a x + b u,
 *     a = g/l, b = 1/(m l^2) (tests/linear/test_lqr.c derives it),
 *         p2 = r (a + sqrt(a^2 + b^2 q1/r)) / b^2,  p3 = sqrt(r (2 p2 + q2)) / b,
 *         K = (b/r) [p2, p3],
 *     and the closed loop is stable; text and C print the design after
 *     the matrices;
 *   - refusals leave the buffer as it was: a design with SymPy or Octave, a
 *     format not in qd_ss_format, a number JSON cannot hold.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/control.h"
#include "qdot/statespace.h"
#include "util/jsonwalk.h"

static const double MASS = 2, LEN = 1.5, G = 9.81;

#define PENDULUM                                                                               \
    "coordinates th\nparameters m = 2, l = 1.5, g = 9.81\ninputs tau\n"                        \
    "T = m*l^2*th'^2/2\nV = -m*g*l*cos(th)\nQ[th] = tau\n"

typedef struct lin {
    qd_ctx *ctx;
    qd_model *m;
    qd_eom *e;
    qd_statespace s;
} lin;

/* The pendulum linearized at th = th0 (an expression: "0", "pi"). */
static void linearize(lin *L, const char *th0) {
    L->ctx = qd_ctx_new();
    assert_non_null(L->ctx);
    L->m = qd_model_parse(L->ctx, PENDULUM, NULL);
    assert_non_null(L->m);
    L->e = qd_eom_derive(L->ctx, L->m);
    assert_non_null(L->e);
    qd_read_opts ro = {.new_symbols = false};
    const qd_expr *sym = qd_model_coord(L->m, 0), *val = qd_read(L->ctx, th0, &ro, NULL);
    assert_non_null(val);
    assert_int_equal(qd_linearize(L->ctx, L->e, L->m, 1, &sym, &val, &L->s), QD_OK);
}

static void lin_free(lin *L) {
    qd_statespace_free(&L->s);
    qd_eom_free(L->e);
    qd_model_free(L->m);
    qd_ctx_free(L->ctx);
}

static double num_at(const char *doc, const char *key, size_t i, size_t k) {
    return qt_json_num(qt_json_at(qt_json_at(qt_json_get(doc, key), i), k));
}

/* The numbers of the bracketed row "  [ a b ]" after line "name =" of a text. */
static void text_row(const char *text, const char *name, size_t row, size_t n, double *out) {
    char head[32];
    snprintf(head, sizeof head, "\n%s =\n", name);
    const char *p = strstr(text, head);
    assert_non_null(p);
    p += strlen(head);
    for (size_t i = 0; i < row; i++)
        p = strchr(p, '\n') + 1;
    assert_true(strncmp(p, "  [", 3) == 0);
    p += 3;
    for (size_t k = 0; k < n; k++) {
        char *end;
        out[k] = strtod(p, &end);
        assert_true(end != p);
        p = end;
    }
    assert_true(strncmp(p, " ]\n", 3) == 0);
}

/* The expression text of A[row][0] in the C or SymPy form (after the line
 * that opens A, rows "    {a, b}," or "    [a, b],"), read and evaluated at
 * the parameters' values. */
static double code_entry(lin *L, const char *code, const char *open, size_t row) {
    const char *p = strstr(code, open);
    assert_non_null(p);
    for (size_t i = 0; i <= row; i++)
        p = strchr(p, '\n') + 1;
    assert_true(strncmp(p, "    ", 4) == 0 && (p[4] == '{' || p[4] == '['));
    p += 5;
    char text[128];
    size_t n = strcspn(p, ",");
    assert_true(n < sizeof text);
    memcpy(text, p, n);
    text[n] = '\0';
    qd_read_opts ro = {.new_symbols = false};
    const qd_expr *x = qd_read(L->ctx, text, &ro, NULL);
    assert_non_null(x);
    const qd_expr *ps[3] = {qd_model_param(L->m, 0), qd_model_param(L->m, 1),
                            qd_model_param(L->m, 2)};
    double pv[3] = {MASS, LEN, G}, v = NAN;
    assert_int_equal(qd_eval(L->ctx, x, 3, ps, pv, &v), QD_OK);
    return v;
}

static void bottom_json(void **state) {
    (void)state;
    lin L;
    linearize(&L, "0");
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_statespace_render(L.ctx, &L.s, NULL, QD_SS_JSON, &b), QD_OK);
    const char *doc = qd_buf_str(&b);
    assert_true(qt_json_valid(doc));
    size_t len = strlen(doc); /* the walk is strict: a document cut short is none */
    char *cut = malloc(len + 1);
    assert_non_null(cut);
    memcpy(cut, doc, len - 3);
    cut[len - 3] = '\0';
    assert_false(qt_json_valid(cut));
    free(cut);
    assert_true(qt_json_str_is(qt_json_at(qt_json_get(doc, "states"), 0), "th"));
    assert_true(qt_json_str_is(qt_json_at(qt_json_get(doc, "states"), 1), "th'"));
    assert_true(qt_json_str_is(qt_json_at(qt_json_get(doc, "inputs"), 0), "tau"));
    assert_int_equal(qt_json_len(qt_json_get(doc, "outputs")), 0);
    /* A = [[0, 1], [-g/l, 0]], B = [[0], [1/(m l^2)]] */
    assert_true(num_at(doc, "A", 0, 0) == 0 && num_at(doc, "A", 0, 1) == 1);
    assert_true(fabs(num_at(doc, "A", 1, 0) + G / LEN) < 1e-13);
    assert_true(fabs(num_at(doc, "A", 1, 1)) < 1e-15);
    assert_true(num_at(doc, "B", 0, 0) == 0);
    assert_true(fabs(num_at(doc, "B", 1, 0) - 1 / (MASS * LEN * LEN)) < 1e-15);
    /* an equilibrium: x' = 0 there */
    assert_true(num_at(doc, "xdot0", 0, 0) == 0 && fabs(num_at(doc, "xdot0", 0, 1)) < 1e-15);
    /* the eigenvalues +-i sqrt(g/l): an undamped oscillation at the pendulum's frequency */
    const char *eig = qt_json_get(doc, "eigenvalues");
    assert_int_equal(qt_json_len(eig), 2);
    double w = sqrt(G / LEN), im[2];
    for (size_t k = 0; k < 2; k++) {
        assert_true(fabs(num_at(doc, "eigenvalues", k, 0)) < 1e-12);
        im[k] = num_at(doc, "eigenvalues", k, 1);
        assert_true(fabs(fabs(im[k]) - w) < 1e-12);
    }
    assert_true(im[0] * im[1] < 0); /* a conjugate pair */
    /* one input reaches both states */
    assert_true(qt_json_get(doc, "controllable")[0] == 't');
    assert_true(qt_json_num(qt_json_get(doc, "controllability_rank")) == 2);
    assert_int_equal(qt_json_len(qt_json_get(doc, "uncontrollable_modes")), 0);
    /* the exact entry dth''/dth reads back as -g/l in the parameters */
    char text[256];
    assert_true(qt_json_str(qt_json_at(qt_json_at(qt_json_get(doc, "A_exact"), 1), 0), text,
                            sizeof text));
    qd_read_opts ro = {.new_symbols = false};
    const qd_expr *a10 = qd_read(L.ctx, text, &ro, NULL);
    assert_non_null(a10);
    const qd_expr *ps[3] = {qd_model_param(L.m, 0), qd_model_param(L.m, 1),
                            qd_model_param(L.m, 2)};
    double pv[3] = {MASS, LEN, G}, v = 0;
    assert_int_equal(qd_eval(L.ctx, a10, 3, ps, pv, &v), QD_OK);
    assert_true(fabs(v + G / LEN) < 1e-13);
    pv[1] = 2 * LEN; /* and in the parameters, not a number: halve g/l */
    assert_int_equal(qd_eval(L.ctx, a10, 3, ps, pv, &v), QD_OK);
    assert_true(fabs(v + G / (2 * LEN)) < 1e-13);
    qd_buf_free(&b);
    lin_free(&L);
}

static void bottom_text_and_code(void **state) {
    (void)state;
    lin L;
    linearize(&L, "0");
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_statespace_render(L.ctx, &L.s, NULL, QD_SS_TEXT, &b), QD_OK);
    const char *t = qd_buf_str(&b);
    double row[2];
    text_row(t, "A", 0, 2, row);
    assert_true(row[0] == 0 && row[1] == 1);
    text_row(t, "A", 1, 2, row); /* shortest round-trip: the very doubles */
    assert_true(row[0] == L.s.A[2] && row[1] == L.s.A[3]);
    assert_true(fabs(row[0] + G / LEN) < 1e-13);
    text_row(t, "B", 1, 1, row);
    assert_true(fabs(row[0] - 1 / (MASS * LEN * LEN)) < 1e-15);
    /* "eigenvalues of A: 0 + 2.557...i, 0 - 2.557...i" */
    const char *p = strstr(t, "eigenvalues of A: ");
    assert_non_null(p);
    p += strlen("eigenvalues of A: ");
    for (int k = 0; k < 2; k++) {
        char *end;
        double re = strtod(p, &end);
        assert_true(fabs(re) < 1e-12 && (end[1] == '+' || end[1] == '-'));
        double im = strtod(end + 3, &end);
        assert_true(fabs(im - sqrt(G / LEN)) < 1e-12 && *end == 'i');
        p = end + 3; /* past "i, " */
    }
    assert_non_null(strstr(t, "controllable: yes (Kalman rank 2 of 2"));
    assert_null(strstr(t, "observable")); /* no outputs: nothing to observe */
    qd_buf_free(&b);
    /* C and SymPy: the exact entry -g/l in the matrix */
    b = (qd_buf)QD_BUF_INIT;
    assert_int_equal(qd_statespace_render(L.ctx, &L.s, NULL, QD_SS_C, &b), QD_OK);
    assert_non_null(strstr(qd_buf_str(&b), "static const double A[2][2] = {"));
    assert_non_null(strstr(qd_buf_str(&b), "static const double B[2][1] = {"));
    assert_true(fabs(code_entry(&L, qd_buf_str(&b), "double A[2][2] = {", 1) + G / LEN) < 1e-13);
    assert_true(code_entry(&L, qd_buf_str(&b), "double A[2][2] = {", 0) == 0);
    qd_buf_free(&b);
    b = (qd_buf)QD_BUF_INIT;
    assert_int_equal(qd_statespace_render(L.ctx, &L.s, NULL, QD_SS_SYMPY, &b), QD_OK);
    assert_true(fabs(code_entry(&L, qd_buf_str(&b), "A = Matrix([", 1) + G / LEN) < 1e-13);
    qd_buf_free(&b);
    b = (qd_buf)QD_BUF_INIT;
    assert_int_equal(qd_statespace_render(L.ctx, &L.s, NULL, QD_SS_OCTAVE, &b), QD_OK);
    assert_non_null(strstr(qd_buf_str(&b), "% x = [th, th'], u = [tau]"));
    qd_buf_free(&b);
    lin_free(&L);
}

static void upright_lqr(void **state) {
    (void)state;
    lin L;
    linearize(&L, "pi");
    const double q1 = 3, q2 = 0.5, r = 0.2;
    qd_care_result d;
    assert_int_equal(qd_lqr_design(L.ctx, &L.s, "Q = diag(3, 0.5), R = 0.2", &d), QD_OK);
    double a = G / LEN, bb = 1 / (MASS * LEN * LEN);
    double p2 = r * (a + sqrt(a * a + bb * bb * q1 / r)) / (bb * bb);
    double p3 = sqrt(r * (2 * p2 + q2)) / bb;
    double K[2] = {bb / r * p2, bb / r * p3};
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_statespace_render(L.ctx, &L.s, &d, QD_SS_JSON, &b), QD_OK);
    const char *doc = qd_buf_str(&b);
    assert_true(qt_json_valid(doc));
    /* upright: A[1][0] = +g/l, the eigenvalues +-sqrt(g/l), real */
    assert_true(fabs(num_at(doc, "A", 1, 0) - a) < 1e-12);
    const char *lqr = qt_json_get(doc, "lqr");
    assert_non_null(lqr);
    for (size_t k = 0; k < 2; k++) {
        double got = qt_json_num(qt_json_at(qt_json_at(qt_json_get(lqr, "K"), 0), k));
        assert_true(fabs(got - K[k]) < 1e-9 * K[k]);
    }
    const char *cl = qt_json_get(lqr, "closed_loop_eigenvalues");
    assert_int_equal(qt_json_len(cl), 2);
    for (size_t k = 0; k < 2; k++)
        assert_true(qt_json_num(qt_json_at(qt_json_at(cl, k), 0)) < 0);
    qd_buf_free(&b);
    /* text and C: the design follows the state-space form */
    b = (qd_buf)QD_BUF_INIT;
    assert_int_equal(qd_statespace_render(L.ctx, &L.s, &d, QD_SS_TEXT, &b), QD_OK);
    const char *ctrl = strstr(qd_buf_str(&b), "controllable: yes");
    assert_non_null(ctrl);
    assert_non_null(strstr(ctrl, "closed-loop eigenvalues (A - B K):"));
    qd_buf_free(&b);
    b = (qd_buf)QD_BUF_INIT;
    assert_int_equal(qd_statespace_render(L.ctx, &L.s, &d, QD_SS_C, &b), QD_OK);
    const char *Bm = strstr(qd_buf_str(&b), "static const double B[");
    assert_non_null(Bm);
    assert_non_null(strstr(Bm, "K["));
    qd_buf_free(&b);
    /* refusals: nothing appended to what the buffer held */
    b = (qd_buf)QD_BUF_INIT;
    qd_buf_puts(&b, "kept");
    assert_int_equal(qd_statespace_render(L.ctx, &L.s, &d, QD_SS_SYMPY, &b), QD_ERR_ARG);
    assert_int_equal(qd_statespace_render(L.ctx, &L.s, &d, QD_SS_OCTAVE, &b), QD_ERR_ARG);
    assert_int_equal(qd_statespace_render(L.ctx, &L.s, NULL, (qd_ss_format)99, &b), QD_ERR_ARG);
    qd_ctx_clear_error(L.ctx);
    L.s.A[1] = NAN;
    assert_int_equal(qd_statespace_render(L.ctx, &L.s, NULL, QD_SS_JSON, &b), QD_ERR_NUMERIC);
    assert_string_equal(qd_buf_str(&b), "kept");
    qd_buf_free(&b);
    qd_care_result_free(&d);
    lin_free(&L);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(bottom_json),
        cmocka_unit_test(bottom_text_and_code),
        cmocka_unit_test(upright_lqr),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
