/*
 * tests/render/test_hamiltonian_render.c - qd_render_hamiltonian and
 * qd_ham_point_eval on a particle in a central potential, in polar
 * coordinates (Goldstein ch. 8 sec. 3; Desloge ch. 71):
 *     L = m/2 (r'^2 + r^2 th'^2) - V(r),  V = -k/r + c r^2,
 *     H = p_r^2/(2m) + p_th^2/(2 m r^2) + V(r),
 *     dr/dt = p_r/m, dth/dt = p_th/(m r^2),
 *     dp_r/dt = p_th^2/(m r^3) - dV/dr, dp_th/dt = 0 (th cyclic).
 * The JSON's expression strings are read back and evaluated at points
 * against these closed forms; at a point the numbers are the closed forms'
 * values and "at" holds the point.  The same particle given by its H
 * (`momenta`, `H = ...`) has the inverse Legendre transform L above.  The
 * text says H = T + V and H conserved; LaTeX rows end in \\; SymPy starts
 * with the import and binds every name; C is refused.
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
#include "util/check.h"

static const char polar[] =
    "coordinates r, th\n"
    "parameters m = 2, k = 3, c = 1/4\n"
    "T = m/2*(r'^2 + r^2*th'^2)\n"
    "V = -k/r + c*r^2\n";

static const char polar_H[] =
    "coordinates r, th\n"
    "momenta p_r, p_th\n"
    "parameters m = 2, k = 3, c = 1/4\n"
    "H = p_r^2/(2*m) + p_th^2/(2*m*r^2) - k/r + c*r^2\n";

static const double M = 2, K = 3, C = 0.25;

/* The closed forms at (r, th, p_r, p_th). */
static double H_of(double r, double pr, double pth) {
    return pr * pr / (2 * M) + pth * pth / (2 * M * r * r) - K / r + C * r * r;
}
static double dpr_of(double r, double pth) {
    return pth * pth / (M * r * r * r) - (K / (r * r) + 2 * C * r);
}

/* The JSON string value after "key": (the first one at or after from),
 * unescaped (the expressions carry no escapes but quotes never appear). */
static char *string_after(const char *from, const char *key) {
    const char *p = strstr(from, key);
    assert_non_null(p);
    p = strchr(p + strlen(key), '"');
    assert_non_null(p);
    const char *q = strchr(p + 1, '"');
    assert_non_null(q);
    char *s = malloc((size_t)(q - p));
    assert_non_null(s);
    memcpy(s, p + 1, (size_t)(q - p - 1));
    s[q - p - 1] = '\0';
    return s;
}

/* The number after "key": in a JSON text. */
static double number_after(const char *from, const char *key) {
    const char *p = strstr(from, key);
    assert_non_null(p);
    return strtod(p + strlen(key), NULL);
}

/* text read as an expression and evaluated with every name bound by name
 * (the parameters at their values). */
static double eval_text(qd_ctx *ctx, const char *text, double r, double th, double pr,
                        double pth) {
    const qd_read_opts o = {.new_symbols = true};
    const qd_expr *x = qd_read(ctx, text, &o, NULL);
    assert_non_null(x);
    const qd_expr *syms[16];
    double vals[16];
    size_t n = qd_free_symbols(ctx, x, syms, 16);
    assert_true(n <= 16);
    static const char *const names[] = {"r", "th", "p_r", "p_th", "m", "k", "c"};
    const double v[] = {r, th, pr, pth, M, K, C};
    for (size_t i = 0; i < n; i++) {
        size_t k = 0;
        while (k < 7 && strcmp(qd_expr_name(syms[i]), names[k]))
            k++;
        if (k == 7)
            fail_msg("unexpected name %s in %s", qd_expr_name(syms[i]), text);
        vals[i] = v[k];
    }
    double y = NAN;
    assert_int_equal(qd_eval(ctx, x, n, syms, vals, &y), QD_OK);
    return y;
}

/* The i-th string of the array under key. */
static char *array_item(const char *json, const char *key, int i) {
    const char *p = strstr(json, key);
    assert_non_null(p);
    p = strchr(p, '[');
    assert_non_null(p);
    for (int k = 0; k < i; k++) {
        p = strchr(p + 1, '"'); /* open */
        p = strchr(p + 1, '"'); /* close */
        assert_non_null(p);
    }
    return string_after(i ? p + 1 : p, "");
}

typedef struct world {
    qd_ctx *ctx;
    qd_model *m;
    qd_eom *e;
    qd_ham *h;
} world;

static void open_world(world *w, const char *text, bool given) {
    w->ctx = qd_ctx_new();
    assert_non_null(w->ctx);
    w->m = qt_parse_ok(w->ctx, text);
    w->e = given ? NULL : qd_eom_derive(w->ctx, w->m);
    assert_true(given || w->e);
    w->h = qd_ham_derive(w->ctx, w->m, w->e);
    if (!w->h)
        fail_msg("qd_ham_derive: %s", qd_ctx_message(w->ctx));
}

static void close_world(world *w) {
    qd_ham_free(w->h);
    qd_eom_free(w->e);
    qd_model_free(w->m);
    qd_ctx_free(w->ctx);
}

static char *render(world *w, const qd_ham_point *at, qd_render_format fmt) {
    qd_buf b = QD_BUF_INIT;
    qd_status st = qd_render_hamiltonian(w->ctx, w->m, w->h, "polar", at, fmt, &b);
    if (st != QD_OK)
        fail_msg("qd_render_hamiltonian: %s", qd_ctx_message(w->ctx));
    char *s = malloc(b.len + 1);
    assert_non_null(s);
    memcpy(s, qd_buf_str(&b), b.len + 1);
    qd_buf_free(&b);
    return s;
}

/* The JSON's H, dq_dt and dp_dt against the closed forms at a few points. */
static void check_symbolic_json(world *w, const char *json) {
    static const double pts[3][4] = {{1.3, 0.4, 0.7, 1.1}, {0.6, -2, -0.3, 2.5}, {2.2, 1, 0, -0.8}};
    char *H = string_after(json, "\"H\":");
    char *dr = array_item(json, "\"dq_dt\"", 0), *dth = array_item(json, "\"dq_dt\"", 1);
    char *dpr = array_item(json, "\"dp_dt\"", 0), *dpth = array_item(json, "\"dp_dt\"", 1);
    for (int i = 0; i < 3; i++) {
        double r = pts[i][0], th = pts[i][1], pr = pts[i][2], pth = pts[i][3];
        double tol = 1e-12 * (1 + fabs(H_of(r, pr, pth)));
        assert_true(fabs(eval_text(w->ctx, H, r, th, pr, pth) - H_of(r, pr, pth)) < tol);
        assert_true(fabs(eval_text(w->ctx, dr, r, th, pr, pth) - pr / M) < 1e-12);
        assert_true(fabs(eval_text(w->ctx, dth, r, th, pr, pth) - pth / (M * r * r)) < 1e-12);
        assert_true(fabs(eval_text(w->ctx, dpr, r, th, pr, pth) - dpr_of(r, pth)) <
                    1e-12 * (1 + fabs(dpr_of(r, pth))));
        assert_true(fabs(eval_text(w->ctx, dpth, r, th, pr, pth)) < 1e-12);
    }
    free(H);
    free(dr);
    free(dth);
    free(dpr);
    free(dpth);
}

static void polar_from_L(void **state) {
    (void)state;
    world w;
    open_world(&w, polar, false);
    char *json = render(&w, NULL, QD_RENDER_JSON);
    check_symbolic_json(&w, json);
    /* p_r = m r', p_th = m r^2 th': the definitions */
    char *pth = array_item(json, "\"definitions\"", 1);
    qt_assert_is(w.ctx, qd_read(w.ctx, pth, &(qd_read_opts){.new_symbols = true}, NULL),
                 "m*r^2*th'");
    free(pth);
    /* T = T2 and V from a potential: H is the energy and is conserved */
    assert_non_null(strstr(json, "\"H_is_energy\": true"));
    assert_non_null(strstr(json, "\"conserved\": true"));
    assert_non_null(strstr(json, "\"model\": \"polar\""));
    free(json);

    char *text = render(&w, NULL, QD_RENDER_TEXT);
    assert_non_null(strstr(text, "H = T + V: yes\n"));
    assert_non_null(strstr(text, "H conserved: yes\n"));
    free(text);
    char *tex = render(&w, NULL, QD_RENDER_LATEX);
    assert_non_null(strstr(tex, "% qdot hamiltonian polar\n"));
    assert_non_null(strstr(tex, " \\\\\n"));
    free(tex);
    char *py = render(&w, NULL, QD_RENDER_SYMPY);
    assert_true(!strncmp(py, "# qdot hamiltonian polar\nfrom sympy import *\n", 44));
    assert_non_null(strstr(py, "\nr = Function('r')\np_r = Symbol('p_r')\n"));
    assert_non_null(strstr(py, "\nm = Symbol('m')\n"));
    assert_non_null(strstr(py, "\ndp_dt = ["));
    free(py);

    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_render_hamiltonian(w.ctx, w.m, w.h, NULL, NULL, QD_RENDER_C, &b),
                     QD_ERR_ARG);
    assert_int_equal(b.len, 0); /* nothing appended */
    qd_buf_free(&b);
    close_world(&w);
}

/* At (r, th, p_r, p_th) = (1.5, 0.2, -0.4, 0.9): the numbers are the closed
 * forms', the JSON's "at" is the point. */
static void polar_at_point(void **state) {
    (void)state;
    world w;
    open_world(&w, polar, false);
    qd_state st;
    assert_int_equal(qd_state_init(w.ctx, w.m, &st), QD_OK);
    assert_int_equal(qd_state_append(w.ctx, &st, w.h->n, w.h->p, NULL), QD_OK);
    assert_int_equal(qd_state_read(w.ctx, w.m, &st, "r=1.5, th=0.2, p_r=-0.4, p_th=0.9", NULL),
                     QD_OK);
    qd_ham_point pt;
    assert_int_equal(qd_ham_point_eval(w.ctx, w.h, st.n, st.syms, st.vals, &pt), QD_OK);
    assert_int_equal(pt.n, 2);
    assert_false(pt.solved);
    double r = 1.5, pr = -0.4, pth = 0.9;
    assert_true(fabs(pt.H - H_of(r, pr, pth)) < 1e-14 * (1 + fabs(pt.H)));
    assert_true(fabs(pt.qd[0] - pr / M) < 1e-15 && fabs(pt.qd[1] - pth / (M * r * r)) < 1e-15);
    assert_true(fabs(pt.dq[0] - pr / M) < 1e-15 && fabs(pt.dq[1] - pth / (M * r * r)) < 1e-15);
    assert_true(fabs(pt.dp[0] - dpr_of(r, pth)) < 1e-14 && fabs(pt.dp[1]) < 1e-15);

    char *json = render(&w, &pt, QD_RENDER_JSON);
    assert_true(fabs(number_after(json, "\"H\": ") - H_of(r, pr, pth)) < 1e-14);
    const char *at = strstr(json, "\"at\": {");
    assert_non_null(at);
    assert_true(number_after(at, "\"r\": ") == 1.5 && number_after(at, "\"p_th\": ") == 0.9);
    assert_true(number_after(at, "\"t\": ") == 0);
    assert_true(fabs(number_after(strstr(json, "\"dp_dt\""), "[") - dpr_of(r, pth)) < 1e-14);
    assert_null(strstr(json, "\"L\":")); /* L is not a model given by H's here */
    free(json);
    char *text = render(&w, &pt, QD_RENDER_TEXT);
    assert_non_null(strstr(text, "Hamiltonian at the point\n"));
    free(text);

    /* a point of another size is refused; a point without p_th too */
    qd_ham_point bad = pt;
    bad.n = 1;
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_render_hamiltonian(w.ctx, w.m, w.h, NULL, &bad, QD_RENDER_JSON, &b),
                     QD_ERR_ARG);
    qd_buf_free(&b);
    qd_ham_point_free(&pt);
    qd_ctx_clear_error(w.ctx);
    assert_int_equal(qd_ham_point_eval(w.ctx, w.h, st.n - 1, st.syms, st.vals, &pt), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(w.ctx), "p_th"));
    qd_ham_point_free(&pt);
    qd_state_free(&st);
    close_world(&w);
}

/* The particle given by H: the same equations, and L from the inverse
 * Legendre transform, m/2 (r'^2 + r^2 th'^2) + k/r - c r^2. */
static void polar_given_H(void **state) {
    (void)state;
    world w;
    open_world(&w, polar_H, true);
    char *json = render(&w, NULL, QD_RENDER_JSON);
    check_symbolic_json(&w, json);
    assert_non_null(strstr(json, "\"H_given\": true"));
    assert_non_null(strstr(json, "\"L_error\": null"));
    char *L = string_after(json, "\"L\":");
    qt_assert_is(w.ctx, qd_read(w.ctx, L, &(qd_read_opts){.new_symbols = true}, NULL),
                 "m/2*(r'^2 + r^2*th'^2) + k/r - c*r^2");
    free(L);
    free(json);
    char *text = render(&w, NULL, QD_RENDER_TEXT);
    assert_non_null(strstr(text, "Lagrangian (inverse Legendre transform)\n"));
    assert_non_null(strstr(text, "H = T + V: unknown (the model gives H, not T and V)\n"));
    free(text);
    close_world(&w);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(polar_from_L),
        cmocka_unit_test(polar_at_point),
        cmocka_unit_test(polar_given_H),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
