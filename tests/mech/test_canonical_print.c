/*
 * tests/mech/test_canonical_print.c - the answers of `qdot canonical` as
 * the library writes them (qd_canonical_examine, qd_canon_report_print,
 * qd_gen_result_print; the witness printers of qdot/certify.h), read back
 * and checked against the mathematics (Goldstein, Classical Mechanics, 3rd
 * ed., ch. 9; Desloge ch. 74-80):
 *
 *   Q = log(sin(p)/q), P = q cot(p) (Goldstein ch. 9) and the point
 *   transformation Q = q^2, P = p/(2q) are canonical: the Lagrange brackets
 *   [q, p] = 1, [q, q] = [p, p] = 0, and K = H;
 *   Q = q, P = 2p is a scaled map of valence 2: [Q, P] = 2, F = 0, K = 2H;
 *   Q = q^2, P = p is not: [Q, P] = 2q, and the witness point q0 has
 *   [Q, P] - 1 = 2 q0 - 1 equal to the witness's value (in the JSON and in
 *   the text); in two degrees of freedom Q1 = x, Q2 = p_x fails at
 *   [Q1, Q2] = 1;
 *   F1 = q Q generates the exchange Q = p, P = -q (Goldstein eq. 9.19), with
 *   [Q, P] = 1 and K(Q, P) = H(-P, Q).
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
#include "qdot/canonical.h"

static const char ONE[] = "coordinates q\nparameters m = 1, k = 2\nT = m/2*q'^2\nV = k/2*q^2\n";
static const char TWO[] = "coordinates x, y\nparameters m = 1\nparticle m at (x, y)\n"
                          "V = x^2 + y^2\n";

typedef struct fix {
    qd_ctx *ctx;
    qd_model *m;
    qd_phase ph;
    const qd_expr *Q[4], *P[4];
    qd_canon_report rep;
} fix;

static void fix_open(fix *f, const char *model, const char *Q, const char *P) {
    memset(f, 0, sizeof *f);
    f->ctx = qd_ctx_new();
    qd_diag d;
    f->m = qd_model_parse(f->ctx, model, &d);
    assert_non_null(f->m);
    assert_int_equal(qd_phase_init(f->ctx, f->m, &f->ph), QD_OK);
    assert_int_equal(qd_phase_read_list(f->ctx, &f->ph, Q, f->Q, &d), QD_OK);
    assert_int_equal(qd_phase_read_list(f->ctx, &f->ph, P, f->P, &d), QD_OK);
}

static void fix_close(fix *f) {
    qd_canon_report_free(&f->rep);
    qd_phase_free(&f->ph);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
}

/* The report written out (JSON or text); the caller frees the string. */
static char *written(fix *f, bool json) {
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_canon_report_print(f->ctx, &f->ph, &f->rep, json, &b), QD_OK);
    char *s = malloc(b.len + 1);
    assert_non_null(s);
    memcpy(s, qd_buf_str(&b), b.len + 1);
    qd_buf_free(&b);
    return s;
}

/* The string member "key": "..." of a JSON text (NULL for null). */
static char *string_at(const char *json, const char *key) {
    char k[64];
    snprintf(k, sizeof k, "\"%s\": ", key);
    const char *p = strstr(json, k);
    assert_non_null(p);
    p += strlen(k);
    if (!strncmp(p, "null", 4))
        return NULL;
    assert_int_equal(*p, '"');
    size_t len = strcspn(p + 1, "\"");
    char *s = malloc(len + 1);
    memcpy(s, p + 1, len);
    s[len] = 0;
    return s;
}

/* The number after "key": in a JSON text. */
static double number_at(const char *json, const char *key) {
    char k[64];
    snprintf(k, sizeof k, "\"%s\": ", key);
    const char *p = strstr(json, k);
    assert_non_null(p);
    return strtod(p + strlen(k), NULL);
}

/* The expression member key read back on the phase space. */
static const qd_expr *expr_at(fix *f, const char *json, const char *key) {
    char *s = string_at(json, key);
    assert_non_null(s);
    qd_diag d;
    const qd_expr *x = qd_phase_read(f->ctx, &f->ph, s, &d);
    free(s);
    assert_non_null(x);
    return x;
}

static bool same(qd_ctx *ctx, const qd_expr *a, const qd_expr *b) {
    return qd_is_zero(qd_simplify(ctx, qd_sub(ctx, a, b)));
}

static bool same_text(fix *f, const qd_expr *a, const char *b) {
    qd_diag d;
    const qd_expr *x = qd_phase_read(f->ctx, &f->ph, b, &d);
    assert_non_null(x);
    return same(f->ctx, a, x);
}

/* "lagrange": [["0", "1"], ["-1", "0"]]: the Lagrange brackets of (q, p)
 * under a canonical map, each entry read back. */
static void assert_lagrange_symplectic(fix *f, const char *json) {
    const char *p = strstr(json, "\"lagrange\": ");
    assert_non_null(p);
    p += strlen("\"lagrange\": ");
    static const char *const want[] = {"0", "1", "-1", "0"};
    for (int e = 0; e < 4; e++) {
        p = strchr(p, '"');
        assert_non_null(p);
        size_t len = strcspn(p + 1, "\"");
        char s[128];
        assert_true(len < sizeof s);
        memcpy(s, p + 1, len);
        s[len] = 0;
        qd_diag d;
        const qd_expr *x = qd_phase_read(f->ctx, &f->ph, s, &d);
        assert_non_null(x);
        assert_true(same_text(f, x, want[e]));
        p += len + 2;
    }
}

/* Goldstein's map is canonical: [Q, P] = 1 ("scale"), the Lagrange
 * brackets are the symplectic unit, L^T PB = I, and K = H (no time, F's
 * dF/dt = 0). */
static void test_goldstein(void **state) {
    (void)state;
    fix f;
    fix_open(&f, ONE, "log(sin(p_q)/q)", "q/tan(p_q)");
    assert_int_equal(qd_canonical_examine(f.ctx, &f.ph, f.Q, f.P, true, true, &f.rep), QD_OK);
    assert_true(same(f.ctx, qd_bracket(f.ctx, 1, f.ph.q, f.ph.p, f.Q[0], f.P[0]),
                     qd_int(f.ctx, 1)));
    char *j = written(&f, true);
    char *v = string_at(j, "verdict");
    assert_string_equal(v, "canonical");
    free(v);
    assert_true(same_text(&f, expr_at(&f, j, "scale"), "1"));
    assert_null(string_at(j, "bracket"));
    assert_null(string_at(j, "witness"));
    assert_lagrange_symplectic(&f, j);
    assert_non_null(strstr(j, "\"duality\": true"));
    assert_true(same_text(&f, expr_at(&f, j, "valence"), "1"));
    assert_true(same(f.ctx, expr_at(&f, j, "K_old"), f.ph.h->H));
    free(j);
    char *t = written(&f, false);
    assert_true(!strncmp(t, "canonical\n", 10) || !strncmp(t, "canonical (verified", 19));
    assert_non_null(strstr(t, "duality: [L]^T (P) = 1 holds"));
    free(t);
    fix_close(&f);
}

/* The point transformation Q = q^2 with P = p/(2q) (dQ/dq P = p). */
static void test_point_transformation(void **state) {
    (void)state;
    fix f;
    fix_open(&f, ONE, "q^2", "p_q/(2*q)");
    assert_int_equal(qd_canonical_examine(f.ctx, &f.ph, f.Q, f.P, true, false, &f.rep), QD_OK);
    char *j = written(&f, true);
    char *v = string_at(j, "verdict");
    assert_string_equal(v, "canonical");
    free(v);
    assert_true(same_text(&f, expr_at(&f, j, "scale"), "1"));
    assert_lagrange_symplectic(&f, j);
    assert_null(strstr(j, "\"K\""));
    free(j);
    fix_close(&f);
}

/* Q = q, P = 2p: [Q, P] = 2 everywhere, a scaled map (Goldstein's extended
 * canonical transformation): valence 2, F = 0 and K = 2 H. */
static void test_scaled(void **state) {
    (void)state;
    fix f;
    fix_open(&f, ONE, "q", "2*p_q");
    assert_int_equal(qd_canonical_examine(f.ctx, &f.ph, f.Q, f.P, false, true, &f.rep), QD_OK);
    char *j = written(&f, true);
    char *v = string_at(j, "verdict");
    assert_string_equal(v, "scaled");
    free(v);
    assert_true(same_text(&f, expr_at(&f, j, "scale"), "2"));
    assert_true(same_text(&f, expr_at(&f, j, "valence"), "2"));
    assert_true(same(f.ctx, expr_at(&f, j, "K_old"), qd_mul(f.ctx, qd_int(f.ctx, 2), f.ph.h->H)));
    char *F = string_at(j, "F");
    assert_true(F == NULL || same_text(&f, expr_at(&f, j, "F"), "0"));
    free(F);
    free(j);
    char *t = written(&f, false);
    assert_true(!strncmp(t, "not canonical (a scaled canonical map, c = 2): [Q_i, P_i] = 2", 60));
    free(t);
    fix_close(&f);
}

/* Q = q^2, P = p: [Q, P] = 2q, not 1; at the witness point q0 the
 * difference [Q, P] - 1 = 2 q0 - 1 is the witness's value, nonzero. */
static void test_witness(void **state) {
    (void)state;
    fix f;
    fix_open(&f, ONE, "q^2", "p_q");
    assert_int_equal(qd_canonical_examine(f.ctx, &f.ph, f.Q, f.P, false, true, &f.rep), QD_OK);
    char *j = written(&f, true);
    char *s = string_at(j, "verdict");
    assert_string_equal(s, "not canonical");
    free(s);
    s = string_at(j, "certainty");
    assert_string_equal(s, "nonzero");
    free(s);
    s = string_at(j, "bracket");
    assert_string_equal(s, "[Q, P]");
    free(s);
    const qd_expr *value = expr_at(&f, j, "value"), *target = expr_at(&f, j, "should_be");
    assert_true(same(f.ctx, value, qd_bracket(f.ctx, 1, f.ph.q, f.ph.p, f.Q[0], f.P[0])));
    assert_true(same_text(&f, value, "2*q"));
    assert_true(same_text(&f, target, "1"));
    const char *w = strstr(j, "\"witness\": {");
    assert_non_null(w);
    double q0 = number_at(w, "q"), diff = number_at(w, "value"), rad = number_at(w, "radius");
    double at[2];
    assert_int_equal(qd_eval(f.ctx, value, 1, f.ph.q, &q0, &at[0]), QD_OK);
    assert_int_equal(qd_eval(f.ctx, target, 1, f.ph.q, &q0, &at[1]), QD_OK);
    assert_true(fabs(at[0] - at[1] - diff) <= rad + 1e-15);
    assert_true(fabs(diff) > rad);
    assert_true(fabs(diff - (2 * q0 - 1)) <= rad + 1e-15);
    assert_non_null(strstr(j, "\"K\": null"));
    free(j);
    /* the text: "  witness: at q = q0 the difference is d +- r (...)" */
    char *t = written(&f, false);
    assert_true(!strncmp(t, "not canonical: [Q, P] = 2*q (should be 1)\n", 42));
    const char *line = strstr(t, "  witness: at q = ");
    assert_non_null(line);
    double tq, td;
    assert_int_equal(sscanf(line, "  witness: at q = %lf the difference is %lf", &tq, &td), 2);
    assert_true(tq == q0 && td == diff);
    assert_non_null(strstr(t, "no new Hamiltonian"));
    free(t);
    fix_close(&f);
}

/* Two degrees of freedom: Q1 = x, Q2 = p_x has [Q1, Q2] = [x, p_x] = 1. */
static void test_pair(void **state) {
    (void)state;
    fix f;
    fix_open(&f, TWO, "x, p_x", "p_x, p_y");
    assert_int_equal(qd_canonical_examine(f.ctx, &f.ph, f.Q, f.P, false, false, &f.rep), QD_OK);
    char *j = written(&f, true);
    char *s = string_at(j, "bracket");
    assert_string_equal(s, "[Q1, Q2]");
    free(s);
    assert_true(same_text(&f, expr_at(&f, j, "value"), "1"));
    assert_true(same_text(&f, expr_at(&f, j, "should_be"), "0"));
    const char *w = strstr(j, "\"witness\": {");
    assert_non_null(w);
    assert_true(fabs(number_at(w, "value") - 1) <= number_at(w, "radius") + 1e-15);
    free(j);
    fix_close(&f);
}

/* F1 = q Q: p = dF/dq = Q, P = -dF/dQ = -q, the exchange of coordinate and
 * momentum; [Q, P] = 1 and K(Q, P) = H(q = -P, p = Q). */
static void test_generator(void **state) {
    (void)state;
    fix f;
    fix_open(&f, ONE, "q", "p_q");
    assert_int_equal(qd_phase_new_vars(f.ctx, &f.ph), QD_OK);
    assert_int_equal(qd_phase_ham(f.ctx, &f.ph, true), QD_OK);
    qd_diag d;
    const qd_expr *F = qd_phase_read(f.ctx, &f.ph, "q*Q", &d);
    assert_non_null(F);
    qd_gen_result g = {0};
    assert_int_equal(qd_generate(f.ctx, QD_GEN_F1, 1, f.ph.q, f.ph.p, f.ph.Q, f.ph.P, F,
                                 qd_time(f.ctx), f.ph.h->H, &g),
                     QD_OK);
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_gen_result_print(f.ctx, &f.ph, QD_GEN_F1, F, &g, true, &b), QD_OK);
    const char *j = qd_buf_str(&b);
    char *s = string_at(j, "type");
    assert_string_equal(s, "F1");
    free(s);
    const qd_expr *Q = expr_at(&f, j, "Q"), *P = expr_at(&f, j, "P");
    assert_true(same_text(&f, Q, "p_q"));
    assert_true(same_text(&f, P, "-q"));
    assert_true(same_text(&f, qd_bracket(f.ctx, 1, f.ph.q, f.ph.p, Q, P), "1"));
    assert_true(same(f.ctx, expr_at(&f, j, "K_old"), f.ph.h->H));
    assert_true(same_text(&f, expr_at(&f, j, "K_new"), "Q^2/(2*m) + k*P^2/2"));
    qd_buf_free(&b);
    b = (qd_buf)QD_BUF_INIT;
    assert_int_equal(qd_gen_result_print(f.ctx, &f.ph, QD_GEN_F1, F, &g, false, &b), QD_OK);
    assert_non_null(strstr(qd_buf_str(&b), "generating function F1\n"));
    assert_non_null(strstr(qd_buf_str(&b), "\n  Q = p_q\n"));
    assert_non_null(strstr(qd_buf_str(&b), "\n  P = -q\n"));
    qd_buf_free(&b);
    b = (qd_buf)QD_BUF_INIT;
    assert_int_equal(qd_gen_result_print(f.ctx, &f.ph, (qd_gen_type)7, F, &g, true, &b),
                     QD_ERR_ARG);
    assert_int_equal(b.len, 0);
    qd_buf_free(&b);
    qd_gen_result_free(&g);
    fix_close(&f);
}

/* A phase space without its new variables cannot name a bracket. */
static void test_refused(void **state) {
    (void)state;
    fix f;
    fix_open(&f, ONE, "q^2", "p_q");
    assert_int_equal(qd_canonical_check(f.ctx, 1, f.ph.q, f.ph.p, f.Q, f.P, NULL, &f.rep.v),
                     QD_OK);
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_canon_report_print(f.ctx, &f.ph, &f.rep, true, &b), QD_ERR_ARG);
    assert_int_equal(b.len, 0);
    qd_buf_free(&b);
    assert_string_equal(qd_canon_kind_name(QD_CANON_UNDECIDED), "undecided");
    assert_null(qd_canon_kind_name((qd_canon_kind)9));
    fix_close(&f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_goldstein),  cmocka_unit_test(test_point_transformation),
        cmocka_unit_test(test_scaled),     cmocka_unit_test(test_witness),
        cmocka_unit_test(test_pair),       cmocka_unit_test(test_generator),
        cmocka_unit_test(test_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
