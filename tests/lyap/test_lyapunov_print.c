/*
 * tests/lyap/test_lyapunov_print.c - the Lyapunov exponents printed
 * (qd_lyap_print, qd_lyap_json, qd_lyap_sum; qdot/lyapunov.h), read back
 * and checked against linear systems whose exponents are known:
 *
 *   - the damped oscillator m x'' + b x' + k x = 0 with k < 0 (an inverted
 *     oscillator, m = 1, b = 1, k = -2) is x' = A x with A = [0 1; 2 -1],
 *     eigenvalues s^2 + s - 2 = 0: s = 1 and -2.  The exponents of a linear
 *     system are the real parts of A's eigenvalues, 1 and -2; their sum is
 *     tr A = -b/m = -1 (Liouville), the JSON's "trace_mean" and "sum";
 *   - the harmonic oscillator (conservative) has both exponents 0, and the
 *     text says the exponents pair (lambda_1 + lambda_2 = 0);
 *   - one exponent of the inverted oscillator: the largest, 1, no "sum".
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "qdot/json.h"
#include "lyap_fixture.h"

static const char inverted[] =
    "coordinates x\nparameters m = 1, b = 1, k = -2\n"
    "T = m/2*x'^2\nV = k/2*x^2\ndissipation = b/2*x'^2\n";
static const char osc[] = "coordinates x\nparameters m = 1, k = 4\nT = m/2*x'^2\nV = k/2*x^2\n";

static const char *member(const char *s, const char *key) {
    char pat[96];
    snprintf(pat, sizeof pat, "\"%s\": ", key);
    const char *p = s ? strstr(s, pat) : NULL;
    return p ? p + strlen(pat) : NULL;
}

/* n numbers of the array that is "key"'s value; false when absent or short. */
static bool numbers(const char *s, const char *key, size_t n, double *out) {
    const char *p = member(s, key);
    if (!p || *p != '[')
        return false;
    p++;
    for (size_t i = 0; i < n; i++) {
        while (*p == ',' || *p == ' ')
            p++;
        char *end;
        out[i] = strtod(p, &end);
        if (end == p)
            return false;
        p = end;
    }
    while (*p == ' ')
        p++;
    return *p == ']';
}

static double number(const char *s, const char *key) {
    const char *p = member(s, key);
    if (!p || !strncmp(p, "null", 4))
        return NAN;
    return strtod(p, NULL);
}

/* A run of k exponents over [0, t_end] after a transient; the report. */
typedef struct run {
    qd_lyap_opts lo;
    qd_lyap_stats st;
    double ex[2], err[2];
    qd_lyap_report r;
} run;

static void lyap_run(lyap_fix *f, size_t k, double t_end, double transient, bool conservative,
                     run *r) {
    double q0[1] = {1}, qd0[1] = {0.5};
    qd_sim_opts o = lf_opts(q0, qd0, t_end);
    r->lo = (qd_lyap_opts){.nexp = k, .renorm = 0.5, .transient = transient};
    assert_int_equal(qd_lyap_run_stats(f->ctx, f->l, &o, &r->lo, r->ex, r->err, &r->st), QD_OK);
    r->r = (qd_lyap_report){.opts = &r->lo, .ndof = qd_lyap_ndof(f->l), .exps = r->ex,
                            .err = r->err, .stats = &r->st, .conservative = conservative,
                            .method = o.method};
}

static void test_inverted_spectrum(void **state) {
    (void)state;
    lyap_fix *f = lf_load(inverted);
    assert_non_null(f);
    run r;
    lyap_run(f, 2, 32, 2, false, &r);
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_lyap_json(&r.r, &b), QD_OK);
    const char *s = qd_buf_str(&b);
    assert_int_equal(s[strlen(s) - 1], '\n');
    double ex[2], err[2];
    assert_true(numbers(s, "exponents", 2, ex));
    assert_true(numbers(s, "errors", 2, err));
    /* the real parts of A's eigenvalues, 1 and -2 */
    assert_true(fabs(ex[0] - 1) < 1e-3);
    assert_true(fabs(ex[1] + 2) < 1e-3);
    /* Liouville: the sum is tr A = -b/m = -1, to the integrator's accuracy */
    assert_true(fabs(number(s, "trace_mean") + 1) < 1e-9);
    assert_true(fabs(number(s, "sum") + 1) < 1e-6);
    assert_true(fabs(qd_lyap_sum(2, r.ex) + 1) < 1e-6);
    assert_true(number(s, "t_avg") == 30);
    assert_true(number(s, "transient") == 2);
    assert_true(number(s, "renorm") == 0.5);
    assert_true(number(s, "renormalizations") == (double)r.st.renorms);
    assert_true(!strncmp(member(s, "method"), "\"dop853\"", 8));
    assert_true(!strncmp(member(s, "conservative"), "false", 5));
    /* the text shows both exponents and the mean trace */
    qd_buf t = QD_BUF_INIT;
    assert_int_equal(qd_lyap_print(&r.r, &t), QD_OK);
    const char *tx = qd_buf_str(&t);
    const char *l1 = strstr(tx, "lambda_1 = "), *l2 = strstr(tx, "lambda_2 = ");
    assert_non_null(l1);
    assert_non_null(l2);
    assert_true(fabs(strtod(l1 + 11, NULL) - ex[0]) < 1e-6);
    assert_true(fabs(strtod(l2 + 11, NULL) - ex[1]) < 1e-6);
    const char *tr = strstr(tx, "mean tr J = ");
    assert_non_null(tr);
    assert_true(fabs(strtod(tr + 12, NULL) + 1) < 1e-6);
    const char *sum = strstr(tx, "sum       = ");
    assert_non_null(sum);
    assert_true(fabs(strtod(sum + 12, NULL) + 1) < 1e-6);
    assert_null(strstr(tx, "conservative:"));
    qd_buf_free(&t);
    qd_buf_free(&b);
    lf_free(f);
}

static void test_largest_only(void **state) {
    (void)state;
    lyap_fix *f = lf_load(inverted);
    assert_non_null(f);
    run r;
    lyap_run(f, 1, 32, 2, false, &r);
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_lyap_json(&r.r, &b), QD_OK);
    const char *s = qd_buf_str(&b);
    double ex[1] = {NAN};
    assert_true(numbers(s, "exponents", 1, ex));
    assert_true(fabs(ex[0] - 1) < 1e-3);
    assert_null(member(s, "sum")); /* not all 2n exponents */
    qd_buf t = QD_BUF_INIT;
    assert_int_equal(qd_lyap_print(&r.r, &t), QD_OK);
    assert_null(strstr(qd_buf_str(&t), "lambda_2"));
    assert_null(strstr(qd_buf_str(&t), "sum       = "));
    /* no error estimates: null in the JSON, said in the text */
    r.r.err = NULL;
    qd_buf_clear(&b);
    qd_buf_clear(&t);
    assert_int_equal(qd_lyap_json(&r.r, &b), QD_OK);
    assert_true(!strncmp(member(qd_buf_str(&b), "errors"), "[null]", 6));
    assert_int_equal(qd_lyap_print(&r.r, &t), QD_OK);
    assert_non_null(strstr(qd_buf_str(&t), "no error estimate"));
    qd_buf_free(&t);
    qd_buf_free(&b);
    lf_free(f);
}

static void test_conservative_pairs(void **state) {
    (void)state;
    lyap_fix *f = lf_load(osc);
    assert_non_null(f);
    run r;
    lyap_run(f, 2, 40, 0, true, &r);
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_lyap_json(&r.r, &b), QD_OK);
    const char *s = qd_buf_str(&b);
    double ex[2];
    assert_true(numbers(s, "exponents", 2, ex));
    /* an oscillator's flow is a rotation: no exponential growth */
    assert_true(fabs(ex[0]) < 0.1 && fabs(ex[1]) < 0.1);
    assert_true(fabs(number(s, "sum")) < 1e-6);
    assert_true(fabs(number(s, "trace_mean")) < 1e-12);
    assert_true(!strncmp(member(s, "conservative"), "true", 4));
    qd_buf t = QD_BUF_INIT;
    assert_int_equal(qd_lyap_print(&r.r, &t), QD_OK);
    const char *p = strstr(qd_buf_str(&t), "lambda_i + lambda_3-i = ");
    assert_non_null(p);
    assert_true(fabs(strtod(p + 24, NULL)) < 1e-5); /* lambda_1 + lambda_2 = 0 */
    qd_buf_free(&t);
    qd_buf_free(&b);
    lf_free(f);
}

static void test_refusals(void **state) {
    (void)state;
    qd_buf b = QD_BUF_INIT;
    double ex[2] = {1, -1}, nan2[2] = {NAN, NAN};
    qd_lyap_opts lo = {.nexp = 3};
    qd_lyap_stats st = {.t_avg = 1};
    qd_lyap_report r = {.opts = &lo, .ndof = 1, .exps = ex, .stats = &st};
    assert_int_equal(qd_lyap_print(&r, &b), QD_ERR_ARG); /* 3 > 2n */
    lo.nexp = 2;
    r.exps = nan2;
    assert_int_equal(qd_lyap_json(&r, &b), QD_ERR_NUMERIC);
    assert_int_equal(b.len, 0);
    assert_int_equal(qd_lyap_print(NULL, &b), QD_ERR_ARG);
    assert_true(isnan(qd_lyap_sum(1, NULL)));
    assert_true(qd_lyap_sum(0, NULL) == 0);
    qd_buf_free(&b);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_inverted_spectrum),
        cmocka_unit_test(test_largest_only),
        cmocka_unit_test(test_conservative_pairs),
        cmocka_unit_test(test_refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
