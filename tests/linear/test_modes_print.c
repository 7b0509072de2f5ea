/*
 * tests/linear/test_modes_print.c - the printed small oscillations
 * (qd_modes_print, qdot/modes.h; qd_symmetry_print, qd_symmetry_json,
 * qd_cyclic_json_modes, qdot/symmetry.h; qd_equilibrium_put_value,
 * qdot/equilibria.h): the numbers read back from the JSON and the text
 * against closed forms.
 *
 *   two equal masses m between two walls, three equal springs k (Goldstein
 *     ch. 6, the coupled oscillators of sec. 6.4): w^2 = k/m (in phase,
 *     x1 = x2) and 3k/m (in opposition, x1 = -x2), each simple, shape
 *     components 1/sqrt(2m) (a^T M a = 1), period 2 pi/w; the equilibrium
 *     x = 0 the library chose, a minimum; the exact w^2 read back from the
 *     JSON evaluate to k/m and 3k/m; the initial normal coordinates;
 *   a 2-D isotropic oscillator: w^2 = k/m twice (multiplicity 2);
 *   a damped oscillator: not conservative, the roots s = -c/2m +- i w_d;
 *   the equilateral triangle of springs (Desloge ch. 66 worked example,
 *     App. 30 eq. 22): C3v of order 6, classes E, 2C3, 3sigma, the
 *     reducible character (6, 0, 0), Gamma = A1 + A2 + 2E, the E row
 *     (2, -1, 0), w^2 = 3k/m for A1 and 3k/(2m) for E, both character
 *     orthogonality relations on the printed table;
 *   a ring of N = 48 equal masses and springs: the cyclic fast path chosen
 *     (qd_symmetry_fast_cell), w^2 = (4k/m) sin^2(pi k/N) by harmonic k,
 *     multiplicity 1 for k = 0 and N/2, else 2; a ring of 6 takes the
 *     group.
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
#include "qdot/json.h"
#include "qdot/modes.h"
#include "qdot/symmetry.h"
#include "../util/system.h"

static const double PI = 3.14159265358979323846;

/* Goldstein's coupled oscillators: wall - k - m - k - m - k - wall, x1 and
 * x2 the masses' displacements from rest. */
#define COUPLED                                                                                \
    "coordinates x1, x2\nparameters m = 2, k = 5\n"                                            \
    "T = m/2*(x1'^2 + x2'^2)\n"                                                                \
    "V = k/2*(x1^2 + (x2 - x1)^2 + x2^2)\n"                                                    \
    "initial x1 = 0.1, x2 = 0\n"

#define ISOTROPIC                                                                              \
    "coordinates x, y\nparameters m = 3, k = 12\n"                                             \
    "T = m/2*(x'^2 + y'^2)\nV = k/2*(x^2 + y^2)\n"

#define DAMPED                                                                                 \
    "coordinates x\nparameters m = 2, k = 8, c = 1\n"                                          \
    "T = m/2*x'^2\nV = k/2*x^2\ndissipation = c/2*x'^2\n"

#define TRIANGLE                                                                               \
    "coordinates x1, y1, x2, y2, x3, y3\nparameters m = 2, k = 5, a = 1\n"                     \
    "d12 = sqrt((x1 - x2)^2 + (y1 - y2)^2)\nd23 = sqrt((x2 - x3)^2 + (y2 - y3)^2)\n"           \
    "d31 = sqrt((x3 - x1)^2 + (y3 - y1)^2)\n"                                                  \
    "particle m at (x1, y1)\nparticle m at (x2, y2)\nparticle m at (x3, y3)\n"                 \
    "V = k/2*((d12 - a)^2 + (d23 - a)^2 + (d31 - a)^2)\n"

/* ---- reading the JSON back ----------------------------------------------------- */

/* The k-th (0-based) occurrence of "key": in s, just past the colon. */
static const char *value_of(const char *s, const char *key, size_t k) {
    char pat[64];
    snprintf(pat, sizeof pat, "\"%s\": ", key);
    const char *p = s;
    for (size_t i = 0; i <= k; i++) {
        p = strstr(p, pat);
        assert_non_null(p);
        p += strlen(pat);
    }
    return p;
}

static double number_of(const char *s, const char *key, size_t k) {
    char *end;
    double x = strtod(value_of(s, key, k), &end);
    assert_true(end != value_of(s, key, k));
    return x;
}

static size_t count_of(const char *s, const char *key) {
    char pat[64];
    snprintf(pat, sizeof pat, "\"%s\": ", key);
    size_t n = 0;
    for (const char *p = strstr(s, pat); p; p = strstr(p + 1, pat))
        n++;
    return n;
}

/* The numbers of the flat array at p ("[1, 2, 3]"), at most cap. */
static size_t array_at(const char *p, double *x, size_t cap) {
    assert_int_equal(*p, '[');
    size_t n = 0;
    p++;
    while (*p != ']') {
        char *end;
        double v = strtod(p, &end);
        assert_true(end != p);
        assert_true(n < cap);
        x[n++] = v;
        p = end;
        while (*p == ',' || *p == ' ')
            p++;
    }
    return n;
}

/* The string value at p ("\"...\""), into out. */
static void string_at(const char *p, char *out, size_t cap) {
    assert_int_equal(*p, '"');
    const char *q = strchr(p + 1, '"');
    assert_non_null(q);
    assert_true((size_t)(q - p - 1) < cap);
    memcpy(out, p + 1, (size_t)(q - p - 1));
    out[q - p - 1] = 0;
}

/* A copy of the buffer's text (the caller frees it). */
static char *take(qd_buf *b) {
    size_t n = strlen(qd_buf_str(b));
    char *s = malloc(n + 1);
    assert_non_null(s);
    memcpy(s, qd_buf_str(b), n + 1);
    qd_buf_free(b);
    return s;
}

static bool close_to(double a, double b, double tol) {
    return fabs(a - b) <= tol * (1 + fabs(b));
}

/* ---- a model at a point ---------------------------------------------------------- */

typedef struct point {
    size_t n;
    const qd_expr *syms[64];
    double vals[64];
} point;

static void at(const qt_system *s, const double *q, point *p) {
    size_t nq = qd_model_ncoords(s->model), np = qd_model_nparams(s->model);
    p->n = nq + np;
    for (size_t i = 0; i < nq; i++) {
        p->syms[i] = qd_model_coord(s->model, i);
        p->vals[i] = q ? q[i] : 0;
    }
    for (size_t i = 0; i < np; i++) {
        p->syms[nq + i] = qd_model_param(s->model, i);
        assert_int_equal(qd_eval(s->ctx, qd_model_param_value(s->model, i), 0, NULL, NULL,
                                 &p->vals[nq + i]), QD_OK);
    }
}

/* qd_modes_print into a fresh string (the caller frees it). */
static char *print(const qt_system *s, const qd_modes_report *r, bool json) {
    qd_buf b = QD_BUF_INIT;
    qd_status st = qd_modes_print(s->ctx, r, json, &b);
    if (st != QD_OK)
        fail_msg("%s", qd_ctx_message(s->ctx));
    return take(&b);
}

/* The value of the exact expression text at the model's parameter values. */
static double evaluate(const qt_system *s, const char *text) {
    const qd_expr *x = qd_read(s->ctx, text, NULL, NULL);
    assert_non_null(x);
    point p;
    at(s, NULL, &p);
    double v;
    assert_int_equal(qd_eval(s->ctx, x, p.n, p.syms, p.vals, &v), QD_OK);
    return v;
}

/* ---- the coupled oscillators ----------------------------------------------------- */

static void test_coupled(void **state) {
    qt_system *s = qt_system_derive(state, COUPLED, true);
    const double m = 2, k = 5;
    point p;
    at(s, NULL, &p);
    qd_equilibrium_choice ch;
    assert_int_equal(qd_equilibria_choose(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, &ch),
                     QD_OK);
    assert_non_null(ch.pt);
    assert_int_equal(ch.pt->kind, QD_EQ_MINIMUM);
    assert_int_equal(ch.reason, QD_EQ_CHOSEN_NEAREST_MINIMUM);
    at(s, ch.pt->q, &p);
    qd_linear lin;
    qd_modes_result res;
    assert_int_equal(qd_linear_about(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, &lin), QD_OK);
    assert_int_equal(qd_modes_solve(s->ctx, &lin, &res), QD_OK);
    /* the search found x = 0 numerically (each equation at rest has both
     * unknowns): the exact w^2 about the exact point 0 */
    const qd_expr *w2[2], *zero[2] = {qd_int(s->ctx, 0), qd_int(s->ctx, 0)};
    bool in_params = false;
    assert_int_equal(qd_modes_exact_omega2(s->ctx, s->eom, s->model, p.n, p.syms, p.vals,
                                           zero, w2, &in_params), QD_OK);
    /* the motion from x1 = 0.1, at rest: Q_j = a_j^T M (q - q0) */
    double q0[2] = {0, 0}, q[2] = {0.1, 0}, qd[2] = {0, 0}, Q[2], Qd[2];
    assert_int_equal(qd_modes_normal_coords(&lin, &res, q0, q, qd, Q, Qd), QD_OK);
    qd_modes_report rep = {.e = s->eom, .q0 = ch.pt->q, .pt = ch.pt, .choice = &ch,
                           .residual = 0, .lin = &lin, .res = &res, .w2exact = w2,
                           .w2exact_in_params = in_params, .Q = Q, .Qd = Qd};
    char *j = print(s, &rep, true);

    /* w^2 = k/m (in phase) and 3k/m (in opposition), each once */
    assert_int_equal(count_of(j, "omega2"), 2);
    assert_true(close_to(number_of(j, "omega2", 0), k / m, 1e-12));
    assert_true(close_to(number_of(j, "omega2", 1), 3 * k / m, 1e-12));
    assert_true(number_of(j, "multiplicity", 0) == 1);
    assert_true(number_of(j, "multiplicity", 1) == 1);
    double w[4];
    assert_int_equal(array_at(value_of(j, "frequencies", 0), w, 4), 2);
    assert_true(close_to(w[0], sqrt(k / m), 1e-12));
    assert_true(close_to(w[1], sqrt(3 * k / m), 1e-12));
    assert_true(close_to(number_of(j, "period", 0), 2 * PI / sqrt(k / m), 1e-12));
    /* shapes: x1 = x2, then x1 = -x2, each 1/sqrt(2m) in size (a^T M a = 1) */
    double a11 = number_of(j, "x1", 1), a21 = number_of(j, "x2", 1);
    double a12 = number_of(j, "x1", 2), a22 = number_of(j, "x2", 2);
    assert_true(close_to(a11, a21, 1e-12) && close_to(fabs(a11), 1 / sqrt(2 * m), 1e-12));
    assert_true(close_to(a12, -a22, 1e-12) && close_to(fabs(a12), 1 / sqrt(2 * m), 1e-12));
    /* the exact w^2, read back, in the parameters */
    char text[128];
    string_at(value_of(j, "omega2_exact", 0), text, sizeof text);
    assert_true(close_to(evaluate(s, text), k / m, 1e-14));
    string_at(value_of(j, "omega2_exact", 1), text, sizeof text);
    assert_true(close_to(evaluate(s, text), 3 * k / m, 1e-14));
    assert_non_null(strstr(value_of(j, "omega2_exact_in_parameters", 0), "true"));
    /* q(0) = sum_j a_j Q_j(0): the initial displacement back from the printed Q0 */
    double Q1 = number_of(j, "Q0", 0), Q2 = number_of(j, "Q0", 1);
    assert_true(close_to(a11 * Q1 + a12 * Q2, 0.1, 1e-12));
    assert_true(fabs(a21 * Q1 + a22 * Q2) < 1e-12);
    assert_true(number_of(j, "Q0_dot", 0) == 0);
    /* the point, the choice, the matrices and the verdict */
    assert_true(number_of(j, "x1", 0) == 0 && number_of(j, "x2", 0) == 0);
    string_at(value_of(j, "reason", 0), text, sizeof text);
    assert_string_equal(text, qd_eq_chosen_name(QD_EQ_CHOSEN_NEAREST_MINIMUM));
    assert_non_null(strstr(value_of(j, "mass_matrix", 0), "[[2, 0], [0, 2]]"));
    assert_non_null(strstr(value_of(j, "stiffness_matrix", 0), "[[10, -5], [-5, 10]]"));
    assert_non_null(strstr(value_of(j, "stable", 0), "true"));
    string_at(value_of(j, "verdict", 0), text, sizeof text);
    assert_string_equal(text, "stable");
    free(j);

    /* text: the exact equilibrium, each w^2 and period, the verdict last */
    char *t = print(s, &rep, false);
    assert_non_null(strstr(t, "equilibrium: x1 = 0, x2 = 0 (minimum of the potential)\n"));
    char want[160];
    snprintf(want, sizeof want, "mode 1: w^2 = 2.5, w = %.10g rad/s, period = %.10g s",
             sqrt(k / m), 2 * PI / sqrt(k / m));
    assert_non_null(strstr(t, want));
    snprintf(want, sizeof want, "mode 2: w^2 = 7.5, w = %.10g rad/s", sqrt(3 * k / m));
    assert_non_null(strstr(t, want));
    assert_null(strstr(t, "repeated"));
    size_t len = strlen(t);
    assert_true(len > 7 && !strcmp(t + len - 7, "stable\n"));
    free(t);

    /* an incomplete report is refused */
    qd_modes_report bad = rep;
    bad.lin = NULL;
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_modes_print(s->ctx, &bad, true, &b), QD_ERR_ARG);
    assert_int_equal(b.len, 0);
    qd_ctx_clear_error(s->ctx);
    qd_buf_free(&b);
    qd_linear_free(&lin);
    qd_modes_result_free(&res);
    qd_equilibrium_choice_free(&ch);
}

/* qd_equilibrium_put_value: the exact value, else the number. */
static void test_put_value(void **state) {
    qt_system *s = qt_system_derive(state, COUPLED, true);
    double q[2] = {0.25, -1.0 / 3};
    const qd_expr *exact[2] = {qd_read(s->ctx, "1/4", NULL, NULL), NULL};
    qd_equilibrium pt = {.q = q, .exact = exact, .kind = QD_EQ_MINIMUM};
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_equilibrium_put_value(s->ctx, &pt, 0, &b), QD_OK);
    qd_buf_puts(&b, " ");
    assert_int_equal(qd_equilibrium_put_value(s->ctx, &pt, 1, &b), QD_OK);
    assert_string_equal(qd_buf_str(&b), "1/4 -0.333333333333");
    qd_buf_free(&b);
}

/* Equal stiffness in x and y: one w^2, twice. */
static void test_isotropic(void **state) {
    qt_system *s = qt_system_derive(state, ISOTROPIC, true);
    point p;
    at(s, NULL, &p);
    qd_linear lin;
    qd_modes_result res;
    assert_int_equal(qd_linear_about(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, &lin), QD_OK);
    assert_int_equal(qd_modes_solve(s->ctx, &lin, &res), QD_OK);
    double q0[2] = {0, 0};
    qd_modes_report rep = {.e = s->eom, .q0 = q0, .lin = &lin, .res = &res};
    char *j = print(s, &rep, true);
    for (size_t k = 0; k < 2; k++) {
        assert_true(close_to(number_of(j, "omega2", k), 12.0 / 3, 1e-12));
        assert_true(number_of(j, "multiplicity", k) == 2);
    }
    assert_null(strstr(j, "\"choice\""));
    free(j);
    char *t = print(s, &rep, false);
    assert_non_null(strstr(t, "about: x = 0, y = 0\n"));
    assert_non_null(strstr(t, "[repeated x2:"));
    free(t);
    qd_linear_free(&lin);
    qd_modes_result_free(&res);
}

/* m x'' + c x' + k x = 0: s = -c/2m +- i sqrt(k/m - (c/2m)^2). */
static void test_damped(void **state) {
    qt_system *s = qt_system_derive(state, DAMPED, true);
    const double m = 2, k = 8, c = 1;
    point p;
    at(s, NULL, &p);
    qd_linear lin;
    qd_modes_result res;
    assert_int_equal(qd_linear_about(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, &lin), QD_OK);
    assert_int_equal(qd_modes_solve(s->ctx, &lin, &res), QD_OK);
    double q0[1] = {0};
    qd_modes_report rep = {.e = s->eom, .q0 = q0, .lin = &lin, .res = &res};
    char *j = print(s, &rep, true);
    assert_non_null(strstr(value_of(j, "conservative", 0), "false"));
    double wd = sqrt(k / m - c * c / (4 * m * m)), x[4];
    assert_int_equal(array_at(value_of(j, "frequencies", 0), x, 4), 1);
    assert_true(close_to(x[0], wd, 1e-12));
    const char *e = value_of(j, "eigenvalues", 0);
    assert_int_equal(e[0], '[');
    assert_int_equal(array_at(e + 1, x, 4), 2); /* the first root, [re, im] */
    assert_true(close_to(x[0], -c / (2 * m), 1e-12) && close_to(fabs(x[1]), wd, 1e-12));
    assert_non_null(strstr(value_of(j, "modes", 0), "[]"));
    free(j);
    char *t = print(s, &rep, false);
    assert_non_null(strstr(t, "C0 = [[1]]\n"));
    char want[96];
    snprintf(want, sizeof want, "(frequency %.10g rad/s, damping ratio %.6g)", wd,
             c / (2 * sqrt(k * m)));
    assert_non_null(strstr(t, want));
    free(t);
    qd_linear_free(&lin);
    qd_modes_result_free(&res);
}

/* ---- symmetry ------------------------------------------------------------------- */

static void test_triangle(void **state) {
    qt_system *s = qt_system_derive(state, TRIANGLE, true);
    const double m = 2, k = 5;
    double q[6] = {0, 0, 1, 0, 0.5, sqrt(3) / 2};
    point p;
    at(s, q, &p);
    qd_linear lin;
    qd_modes_result res;
    qd_symmetry sym;
    assert_int_equal(qd_linear_about(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, &lin), QD_OK);
    assert_int_equal(qd_modes_solve(s->ctx, &lin, &res), QD_OK);
    assert_int_equal(qd_symmetry_fast_cell(&lin), 0); /* 6 coordinates: the group */
    assert_int_equal(qd_symmetry_find(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, &lin, &sym),
                     QD_OK);
    assert_int_equal(qd_symmetry_reduce(s->ctx, &lin, &sym), QD_OK);
    qd_modes_report rep = {.e = s->eom, .q0 = q, .lin = &lin, .res = &res, .sym = &sym};
    char *j = print(s, &rep, true);
    char text[64];
    string_at(value_of(j, "group", 0), text, sizeof text);
    assert_string_equal(text, "C3v");
    assert_true(number_of(j, "order", 0) == 6);
    /* the classes E, 2C3, 3sigma (in the library's order) and the reducible
     * character: 6 at E, 0 elsewhere */
    double size[3], chi[8];
    size_t c_C3 = 3, c_sigma = 3;
    for (size_t c = 0; c < 3; c++) {
        size[c] = number_of(j, "size", c);
        string_at(value_of(j, "name", c), text, sizeof text);
        if (!strcmp(text, "2C3"))
            c_C3 = c;
        else if (!strcmp(text, "3sigma"))
            c_sigma = c;
        else
            assert_string_equal(text, "E");
    }
    assert_true(c_C3 < 3 && c_sigma < 3);
    assert_true(size[0] == 1 && size[c_C3] == 2 && size[c_sigma] == 3);
    assert_int_equal(array_at(value_of(j, "reducible", 0), chi, 8), 3);
    assert_true(fabs(chi[0] - 6) < 1e-9 && fabs(chi[1]) < 1e-9 && fabs(chi[2]) < 1e-9);
    /* the character table: three irreps, rows orthogonal, sum d^2 = |G| */
    double table[3][3], d2 = 0;
    char label[3][16];
    for (size_t i = 0; i < 3; i++) {
        string_at(value_of(j, "irrep", i), label[i], sizeof label[i]);
        assert_int_equal(array_at(value_of(j, "chi", i), table[i], 3), 3);
        double d = number_of(j, "dimension", i);
        assert_true(fabs(table[i][0] - d) < 1e-12);
        d2 += d * d;
    }
    assert_true(fabs(d2 - 6) < 1e-12);
    for (size_t a = 0; a < 3; a++)
        for (size_t b = 0; b < 3; b++) {
            double sum = 0;
            for (size_t c = 0; c < 3; c++)
                sum += size[c] * table[a][c] * table[b][c];
            assert_true(fabs(sum - (a == b ? 6 : 0)) < 1e-9);
        }
    /* the E row is (2, -1, 0); Gamma = A1 + A2 + 2E */
    for (size_t i = 0; i < 3; i++)
        if (!strcmp(label[i], "E"))
            assert_true(fabs(table[i][c_C3] + 1) < 1e-12 && fabs(table[i][c_sigma]) < 1e-12);
    assert_true(number_of(j, "A1", 0) == 1);
    assert_true(number_of(j, "A2", 0) == 1);
    assert_true(number_of(j, "E", 0) == 2);
    /* the modes by irrep: A1 breathing 3k/m, E 3k/(2m) twice (the vibrations) */
    const char *modes = value_of(j, "modes", 0);
    assert_int_equal(count_of(modes, "omega2"), 6);
    size_t nA1 = 0, nE = 0;
    for (size_t i = 0; i < 6; i++) {
        double w2 = number_of(modes, "omega2", i);
        char kind[24];
        string_at(value_of(modes, "kind", i), kind, sizeof kind);
        string_at(value_of(modes, "irrep", i), text, sizeof text);
        if (strcmp(kind, "vibration"))
            continue;
        if (!strcmp(text, "A1")) {
            nA1++;
            assert_true(close_to(w2, 3 * k / m, 1e-10));
        } else {
            assert_string_equal(text, "E");
            nE++;
            assert_true(close_to(w2, 1.5 * k / m, 1e-10));
            assert_true(number_of(modes, "multiplicity", i) == 2);
        }
    }
    assert_int_equal(nA1, 1);
    assert_int_equal(nE, 2);
    free(j);
    /* text: the group and Gamma's decomposition, whose dimensions add up to n */
    char *t = print(s, &rep, false);
    assert_non_null(strstr(t, "symmetry group: C3v (order 6, 3 classes)\n"));
    const char *g = strstr(t, "Gamma =");
    assert_non_null(g);
    assert_non_null(strstr(g, " A1"));
    assert_non_null(strstr(g, " A2"));
    assert_non_null(strstr(g, " 2E"));
    free(t);
    /* the same text from qd_symmetry_print alone */
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_symmetry_print(&sym, s->eom, &b), QD_OK);
    assert_non_null(strstr(qd_buf_str(&b), "modes by block: K0 a = w^2 M0 a"));
    qd_buf_free(&b);
    qd_symmetry_free(&sym);
    qd_linear_free(&lin);
    qd_modes_result_free(&res);
}

/* A ring of N equal masses joined by equal springs (arc coordinates). */
static char *ring_model(size_t N) {
    qd_buf b = QD_BUF_INIT;
    qd_buf_puts(&b, "coordinates ");
    for (size_t i = 1; i <= N; i++)
        qd_buf_printf(&b, "%ss%zu", i > 1 ? ", " : "", i);
    qd_buf_puts(&b, "\nparameters m = 0.5, k = 3\nT = m/2*(");
    for (size_t i = 1; i <= N; i++)
        qd_buf_printf(&b, "%ss%zu'^2", i > 1 ? " + " : "", i);
    qd_buf_puts(&b, ")\nV = k/2*(");
    for (size_t i = 1; i <= N; i++)
        qd_buf_printf(&b, "%s(s%zu - s%zu)^2", i > 1 ? " + " : "", i % N + 1, i);
    qd_buf_puts(&b, ")\n");
    return take(&b);
}

static void test_ring_cyclic(void **state) {
    const size_t N = 48;
    const double m = 0.5, k = 3;
    char *text = ring_model(N);
    assert_non_null(text);
    qt_system *s = qt_system_derive(state, text, true);
    free(text);
    point p;
    at(s, NULL, &p);
    qd_linear lin;
    qd_modes_result res;
    assert_int_equal(qd_linear_about(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, &lin), QD_OK);
    assert_int_equal(qd_modes_solve(s->ctx, &lin, &res), QD_OK);
    size_t cell = qd_symmetry_fast_cell(&lin);
    assert_int_equal(cell, 1);
    qd_cyclic_modes cm;
    assert_int_equal(qd_cyclic_solve(s->ctx, &lin, cell, &cm), QD_OK);
    double q0[48] = {0};
    qd_modes_report rep = {.e = s->eom, .q0 = q0, .lin = &lin, .res = &res, .cyc = &cm};
    char *j = print(s, &rep, true);
    assert_non_null(strstr(value_of(j, "fast_path", 0), "true"));
    assert_true(number_of(j, "order", 0) == N);
    assert_int_equal(count_of(j, "harmonic"), N);
    for (size_t i = 0; i < N; i++) {
        double h = number_of(j, "harmonic", i), w2 = number_of(j, "omega2", i);
        double want = 4 * k / m * pow(sin(PI * h / N), 2);
        assert_true(fabs(w2 - want) < 1e-11 * 4 * k / m);
        bool single = h == 0 || h == N / 2;
        assert_true(number_of(j, "multiplicity", i) == (single ? 1 : 2));
    }
    free(j);
    /* the modes array alone, into a caller's document */
    qd_buf b = QD_BUF_INIT;
    qd_json js;
    qd_json_init(&js, &b);
    qd_json_begin_object(&js);
    qd_cyclic_json_modes(&js, &cm);
    qd_json_end_object(&js);
    assert_true(qd_json_ok(&js));
    assert_int_equal(count_of(qd_buf_str(&b), "irrep"), N);
    qd_buf_free(&b);
    qd_cyclic_modes_free(&cm);
    qd_linear_free(&lin);
    qd_modes_result_free(&res);
}

/* Six in a ring: shift-invariant too, but below QD_SYMMETRY_FAST_N the group. */
static void test_ring_small(void **state) {
    char *text = ring_model(6);
    assert_non_null(text);
    qt_system *s = qt_system_derive(state, text, true);
    free(text);
    point p;
    at(s, NULL, &p);
    qd_linear lin;
    assert_int_equal(qd_linear_about(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, &lin), QD_OK);
    assert_int_equal(qd_cyclic_cell(&lin), 1);
    assert_int_equal(qd_symmetry_fast_cell(&lin), 0);
    qd_linear_free(&lin);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(test_coupled, qt_system_teardown),
        cmocka_unit_test_teardown(test_put_value, qt_system_teardown),
        cmocka_unit_test_teardown(test_isotropic, qt_system_teardown),
        cmocka_unit_test_teardown(test_damped, qt_system_teardown),
        cmocka_unit_test_teardown(test_triangle, qt_system_teardown),
        cmocka_unit_test_teardown(test_ring_cyclic, qt_system_teardown),
        cmocka_unit_test_teardown(test_ring_small, qt_system_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
