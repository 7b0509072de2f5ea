/*
 * tests/lyap/test_flow_render.c - the flow Jacobian printed (qd_flow_json,
 * qd_flow_print, qd_flow_column_name, qd_flow_sim_opts; qdot/lyapunov.h),
 * read back and checked against the textbook flows:
 *
 *   - the harmonic oscillator x'' = -w^2 x (w = 2) is isochronous: over one
 *     period pi its monodromy matrix is the identity and both Floquet
 *     multipliers are 1, the orbit closes, the flow is symplectic;
 *   - over a time t its flow is the rotation-like matrix
 *     [cos wt, sin(wt)/w; -w sin wt, cos wt], with eigenvalues e^(+-i w t),
 *     entry by entry under the column names of the flow's rows;
 *   - given a wrong period (1 for pi), the run does not return to its start
 *     (closure max(|cos w - 1|, |w sin w|)) and the text says so;
 *   - the damped oscillator m x'' = -k x - b x' shrinks phase volume as
 *     det = exp(-b t/m) (Liouville), and is not Hamiltonian.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "qdot/json.h"
#include "lyap_fixture.h"

#define PI 3.14159265358979323846

static const char osc[] = "coordinates x\nparameters m = 1, k = 4\nT = m/2*x'^2\nV = k/2*x^2\n";

/* ---- reading the JSON back ------------------------------------------------------- */

static const char *member(const char *s, const char *key) {
    char pat[96];
    snprintf(pat, sizeof pat, "\"%s\": ", key);
    const char *p = s ? strstr(s, pat) : NULL;
    return p ? p + strlen(pat) : NULL;
}

/* n numbers of the (nested) array that is "key"'s value; false when absent,
 * null or short. */
static bool numbers(const char *s, const char *key, size_t n, double *out) {
    const char *p = member(s, key);
    if (!p || *p != '[')
        return false;
    for (size_t i = 0; i < n; i++) {
        while (*p == '[' || *p == ',' || *p == ' ' || *p == ']' || *p == '\n')
            p++;
        char *end;
        out[i] = strtod(p, &end);
        if (end == p)
            return false;
        p = end;
    }
    return true;
}

static double number(const char *s, const char *key) {
    const char *p = member(s, key);
    if (!p || !strncmp(p, "null", 4))
        return NAN;
    return strtod(p, NULL);
}

/* The flow of f from (x0, v0) over [0, t] and its JSON {...} into b. */
static void flow_json(lyap_fix *f, double x0, double v0, double t, double period, qd_flow *fl,
                      qd_buf *b) {
    double q0[1] = {x0}, qd0[1] = {v0};
    qd_sim_opts o = lf_opts(q0, qd0, t);
    assert_int_equal(qd_flow_run(f->ctx, f->l, &o, NULL, fl), QD_OK);
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    assert_int_equal(qd_flow_json(&j, fl, f->e, o.method, period), QD_OK);
    qd_json_end_object(&j);
    assert_true(qd_json_ok(&j));
}

/* ---- the oscillator over one period ------------------------------------------------ */

static void test_monodromy_identity(void **state) {
    (void)state;
    lyap_fix *f = lf_load(osc);
    assert_non_null(f);
    qd_flow fl;
    qd_buf b = QD_BUF_INIT;
    flow_json(f, 1, 0.5, PI, PI, &fl, &b);
    const char *s = qd_buf_str(&b);
    double M[4], mu[4];
    assert_true(numbers(s, "monodromy", 4, M));
    for (int i = 0; i < 2; i++)
        for (int k = 0; k < 2; k++)
            assert_true(fabs(M[2 * i + k] - (i == k)) < 1e-8);
    assert_true(numbers(s, "multipliers", 4, mu));
    for (int i = 0; i < 2; i++)
        assert_true(fabs(mu[2 * i] - 1) < 1e-8 && fabs(mu[2 * i + 1]) < 1e-8);
    assert_true(number(s, "period") == PI);
    assert_true(number(s, "closure") < 1e-8);
    assert_true(fabs(number(s, "flow_det") - 1) < 1e-8);
    assert_true(fabs(number(s, "liouville_det") - 1) < 1e-12); /* tr J = 0 exactly */
    assert_true(!strncmp(member(s, "hamiltonian"), "true", 4));
    assert_true(number(s, "symplectic_error") < 1e-8);
    /* the state's names: (x, x') */
    const char *st = member(member(s, "variational"), "state");
    assert_non_null(st);
    assert_true(!strncmp(st, "[\"x\", \"x'\"]", 11));
    /* the text: the multipliers of a period, a closed orbit */
    qd_buf t = QD_BUF_INIT;
    assert_int_equal(qd_flow_print(&fl, PI, "# ", &t), QD_OK);
    assert_non_null(strstr(qd_buf_str(&t), "\n# Floquet multipliers: "));
    assert_non_null(strstr(qd_buf_str(&t), "\n# closure max |y(t0 + T) - y(t0)| = "));
    assert_null(strstr(qd_buf_str(&t), "not periodic"));
    qd_buf_free(&t);
    qd_flow_free(&fl);
    qd_buf_free(&b);
    lf_free(f);
}

/* ---- the oscillator's flow at a time t ------------------------------------------- */

/* Phi(t) of x'' = -w^2 x in (x, x'), row-major. */
static void rotation(double w, double t, double *P) {
    P[0] = cos(w * t);
    P[1] = sin(w * t) / w;
    P[2] = -w * sin(w * t);
    P[3] = cos(w * t);
}

static void test_flow_at_t(void **state) {
    (void)state;
    lyap_fix *f = lf_load(osc);
    assert_non_null(f);
    const double w = 2, t = 1;
    qd_flow fl;
    qd_buf b = QD_BUF_INIT;
    flow_json(f, 0.3, -1, t, 0, &fl, &b);
    const char *s = qd_buf_str(&b);
    double P[4], want[4], mu[4];
    rotation(w, t, want);
    assert_true(numbers(s, "flow_jacobian", 4, P));
    for (int i = 0; i < 4; i++)
        assert_true(fabs(P[i] - want[i]) < 1e-9);
    assert_null(member(s, "monodromy"));
    assert_true(isnan(number(s, "period")));
    /* eigenvalues e^(+-i w t) */
    assert_true(numbers(s, "multipliers", 4, mu));
    assert_true(fabs(mu[0] - cos(w * t)) < 1e-9 && fabs(mu[2] - cos(w * t)) < 1e-9);
    assert_true(fabs(fabs(mu[1]) - sin(w * t)) < 1e-9 && fabs(mu[1] + mu[3]) < 1e-12);
    /* the columns of the flow's rows: t, x, x', then d y_i/d y_j(t0) by
     * columns; each name points at the entry of Phi the layout promises */
    const char *const state_names[] = {"x", "x'"};
    for (size_t k = 0; k < 1 + 2 + 4; k++) {
        qd_buf nb = QD_BUF_INIT;
        assert_int_equal(qd_flow_column_name(f->e, k, &nb), QD_OK);
        const char *name = qd_buf_str(&nb);
        if (k == 0)
            assert_string_equal(name, "t");
        else if (k <= 2)
            assert_string_equal(name, state_names[k - 1]);
        else {
            size_t i = (k - 3) % 2, j = (k - 3) / 2; /* column j, row i */
            char want_name[32];
            snprintf(want_name, sizeof want_name, "d%s/d%s0", state_names[i], state_names[j]);
            assert_string_equal(name, want_name);
            assert_true(fabs(fl.phi[i * 2 + j] - want[i * 2 + j]) < 1e-9);
        }
        qd_buf_free(&nb);
    }
    qd_buf nb = QD_BUF_INIT;
    assert_int_equal(qd_flow_column_name(f->e, 7, &nb), QD_ERR_ARG);
    assert_int_equal(qd_flow_state_name(f->e, 2, &nb), QD_ERR_ARG);
    qd_buf_free(&nb);
    /* the text without a period: eigenvalues, no closure */
    qd_buf txt = QD_BUF_INIT;
    assert_int_equal(qd_flow_print(&fl, 0, NULL, &txt), QD_OK);
    assert_non_null(strstr(qd_buf_str(&txt), "\neigenvalues: "));
    assert_null(strstr(qd_buf_str(&txt), "closure"));
    qd_buf_free(&txt);
    qd_flow_free(&fl);
    qd_buf_free(&b);
    lf_free(f);
}

/* ---- a period that is not the orbit's -------------------------------------------- */

static void test_not_periodic(void **state) {
    (void)state;
    lyap_fix *f = lf_load(osc);
    assert_non_null(f);
    const double w = 2, T = 1;
    qd_flow fl;
    qd_buf b = QD_BUF_INIT;
    flow_json(f, 1, 0, T, T, &fl, &b); /* from (1, 0): y(T) = (cos wT, -w sin wT) */
    double closure = fmax(fabs(cos(w * T) - 1), fabs(w * sin(w * T)));
    assert_true(fabs(number(qd_buf_str(&b), "closure") - closure) < 1e-9);
    assert_true(closure > QD_FLOW_CLOSURE_TOL);
    qd_buf t = QD_BUF_INIT;
    assert_int_equal(qd_flow_print(&fl, T, NULL, &t), QD_OK);
    assert_non_null(strstr(qd_buf_str(&t), ": the orbit is not periodic with this T\n"));
    qd_buf_free(&t);
    qd_flow_free(&fl);
    qd_buf_free(&b);
    lf_free(f);
}

/* ---- Liouville ------------------------------------------------------------------ */

static void test_damped(void **state) {
    (void)state;
    lyap_fix *f = lf_load("coordinates x\nparameters m = 1.2, k = 3, b = 0.4\nT = m/2*x'^2\n"
                          "V = k/2*x^2\ndissipation = b/2*x'^2\n");
    assert_non_null(f);
    const double t = 2;
    qd_flow fl;
    qd_buf b = QD_BUF_INIT;
    flow_json(f, 1, 0, t, 0, &fl, &b);
    const char *s = qd_buf_str(&b);
    double want = exp(-0.4 * t / 1.2);
    assert_true(fabs(number(s, "flow_det") - want) < 1e-9);
    assert_true(fabs(number(s, "liouville_det") - want) < 1e-9);
    assert_true(!strncmp(member(s, "hamiltonian"), "false", 5));
    assert_true(isnan(number(s, "symplectic_error"))); /* null */
    assert_null(member(s, "flow_jacobian_canonical"));
    qd_flow_free(&fl);
    qd_buf_free(&b);
    lf_free(f);
}

/* ---- the options and the refusals ----------------------------------------------- */

static void test_opts_and_refusals(void **state) {
    (void)state;
    /* the tangent system runs with the two pairs: others become dop853 */
    qd_sim_opts in = {.method = QD_SIM_GL4, .fixed = true, .dt = 0.1, .t_end = 3}, out;
    assert_int_equal(qd_flow_sim_opts(&in, &out), QD_OK);
    assert_true(out.method == QD_SIM_DOP853 && !out.fixed && out.t_end == 3 && out.dt == 0.1);
    in.method = QD_SIM_DOPRI5;
    assert_int_equal(qd_flow_sim_opts(&in, &out), QD_OK);
    assert_true(out.method == QD_SIM_DOPRI5 && out.fixed);
    /* a flow of another system's size, a flow without its arrays */
    lyap_fix *f = lf_load(lf_henon_heiles);
    assert_non_null(f);
    double y[2] = {0}, phi[4] = {1, 0, 0, 1}, re[2] = {1, 1}, im[2] = {0, 0};
    qd_flow fl = {.d = 2, .y = y, .phi = phi, .det = 1, .mult_re = re, .mult_im = im};
    qd_buf b = QD_BUF_INIT;
    qd_json j;
    qd_json_init(&j, &b);
    qd_json_begin_object(&j);
    assert_int_equal(qd_flow_json(&j, &fl, f->e, QD_SIM_DOP853, 0), QD_ERR_ARG);
    fl.phi = NULL;
    assert_int_equal(qd_flow_print(&fl, 0, NULL, &b), QD_ERR_ARG);
    qd_buf_free(&b);
    lf_free(f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_monodromy_identity), cmocka_unit_test(test_flow_at_t),
        cmocka_unit_test(test_not_periodic),       cmocka_unit_test(test_damped),
        cmocka_unit_test(test_opts_and_refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
