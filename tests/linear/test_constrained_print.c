/*
 * tests/linear/test_constrained_print.c - the printers and the reader of
 * qdot/constrained.h on models that keep their constraints:
 *
 *   - the pendulum x^2 + y^2 = l^2 under V = m g y at the bottom: the modes
 *     JSON is valid and holds w^2 = g/l, w = sqrt(g/l), the point (0, -l),
 *     the multiplier -m g/(2 l) (M q'' = f + A^T lambda: 0 = -m g - 2 l
 *     lambda), M_r = m, K_r = m g/l; the text's w and period are sqrt(g/l)
 *     and 2 pi sqrt(l/g);
 *   - the same pendulum pushed along x by F: the state-space JSON has
 *     A = [[0, 1], [-g/l, 0]], B = [[0], [1/m]], eigenvalues +-i sqrt(g/l);
 *   - with dissipation c (x'^2 + y'^2)/2: not conservative, the roots
 *     s = -c/(2m) +- i sqrt(g/l - c^2/(4 m^2)) of m s^2 + c s + m g/l;
 *   - the double pendulum in Cartesian coordinates (two rods kept): the
 *     textbook normal modes (e.g. Goldstein sec. 6.4, Fowles & Cassiday)
 *         w^2 = g [(m1+m2)(l1+l2) -+ sqrt((m1+m2)((m1+m2)(l1+l2)^2 - 4 m1 l1 l2))]
 *               / (2 m1 l1 l2);
 *   - qd_constrained_indep_read: the indices of the names, ascending; a
 *     name that is not a coordinate, one named twice and a wrong count
 *     refused with the place in the text;
 *   - a reduction printed with another model's modes is refused.
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
#include <stdlib.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/constrained.h"
#include "util/jsonwalk.h"
#include "util/system.h"

static const double M = 1.5, G = 9.81, L = 2, C = 0.3;

static const char pendulum[] = "parameters m = 1.5, g = 9.81, l = 2\ncoordinates x, y\n"
                               "inputs F\nT = m/2*(x'^2 + y'^2)\nV = m*g*y\nQ[x] = F\n"
                               "constraint rod: x^2 + y^2 = l^2\n";
static const char damped[] = "parameters m = 1.5, g = 9.81, l = 2, c = 0.3\ncoordinates x, y\n"
                             "T = m/2*(x'^2 + y'^2)\nV = m*g*y\n"
                             "dissipation = c*(x'^2 + y'^2)/2\n"
                             "constraint rod: x^2 + y^2 = l^2\n";
static const double M1 = 1.0, M2 = 1.5, L1 = 1.0, L2 = 0.7;
static const char double_pendulum[] =
    "parameters m1 = 1.0, m2 = 1.5, g = 9.81, l1 = 1.0, l2 = 0.7\n"
    "coordinates x1, y1, x2, y2\n"
    "T = m1/2*(x1'^2 + y1'^2) + m2/2*(x2'^2 + y2'^2)\nV = m1*g*y1 + m2*g*y2\n"
    "constraint rod1: x1^2 + y1^2 = l1^2\n"
    "constraint rod2: (x2 - x1)^2 + (y2 - y1)^2 = l2^2\n";

/* A reduction of s about q (at rest, t = 0, the parameters at their values,
 * F = 0) with its modes. */
typedef struct reduced {
    size_t n;
    const qd_expr *syms[40];
    double vals[40];
    qd_constrained_linear c;
    qd_modes_result res;
} reduced;

static void reduce(const qt_system *s, const double *q, const size_t *indep, reduced *r) {
    size_t nq = qd_model_ncoords(s->model), np = qd_model_nparams(s->model);
    assert_true(2 * nq + 1 + np <= 40);
    r->n = 0;
    for (size_t i = 0; i < nq; i++) {
        r->syms[r->n] = qd_model_coord(s->model, i);
        r->vals[r->n++] = q[i];
        r->syms[r->n] = qd_jet(s->ctx, qd_model_coord(s->model, i), 1);
        r->vals[r->n++] = 0;
    }
    r->syms[r->n] = qd_time(s->ctx);
    r->vals[r->n++] = 0;
    for (size_t i = 0; i < np; i++) {
        r->syms[r->n] = qd_model_param(s->model, i);
        assert_int_equal(qd_eval(s->ctx, qd_model_param_value(s->model, i), 0, NULL, NULL,
                                 &r->vals[r->n++]), QD_OK);
    }
    assert_int_equal(qd_constrained_linear_about(s->ctx, s->eom, r->n, r->syms, r->vals, indep,
                                                 &r->c), QD_OK);
    assert_int_equal(qd_modes_solve(s->ctx, &r->c.lin, &r->res), QD_OK);
}

static void reduced_free(reduced *r) {
    qd_modes_result_free(&r->res);
    qd_constrained_linear_free(&r->c);
}

static double num2(const char *doc, const char *key, size_t i, size_t k) {
    return qt_json_num(qt_json_at(qt_json_at(qt_json_get(doc, key), i), k));
}

static double after(const char *text, const char *key) {
    const char *p = strstr(text, key);
    assert_non_null(p);
    return strtod(p + strlen(key), NULL);
}

static void pendulum_modes(void **state) {
    qt_system *s = qt_system_derive(state, pendulum, false);
    const double q[2] = {0, -1.9}; /* off the circle: y is put back on it */
    reduced r;
    reduce(s, q, NULL, &r);
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_constrained_modes_print(s->ctx, s->eom, &r.c, &r.res, true, &b), QD_OK);
    const char *doc = qd_buf_str(&b);
    assert_true(qt_json_valid(doc));
    assert_true(qt_json_str_is(qt_json_at(qt_json_get(doc, "independent"), 0), "x"));
    assert_true(qt_json_str_is(qt_json_at(qt_json_get(doc, "dependent"), 0), "y"));
    const char *eq = qt_json_get(doc, "equilibrium");
    assert_true(fabs(qt_json_num(qt_json_get(eq, "x"))) < 1e-12);
    assert_true(fabs(qt_json_num(qt_json_get(eq, "y")) + L) < 1e-12);
    double lambda = qt_json_num(qt_json_get(qt_json_get(doc, "multipliers"), "lambda_rod"));
    assert_true(fabs(lambda + M * G / (2 * L)) < 1e-12);
    assert_true(qt_json_get(doc, "conservative")[0] == 't');
    assert_true(fabs(num2(doc, "mass_matrix", 0, 0) - M) < 1e-12);
    assert_true(fabs(num2(doc, "stiffness_matrix", 0, 0) - M * G / L) < 1e-12);
    const char *modes = qt_json_get(doc, "modes");
    assert_int_equal(qt_json_len(modes), 1);
    const char *m0 = qt_json_at(modes, 0);
    assert_true(fabs(qt_json_num(qt_json_get(m0, "omega2")) - G / L) < 1e-12);
    assert_true(fabs(qt_json_num(qt_json_get(m0, "omega")) - sqrt(G / L)) < 1e-12);
    /* the shape, normalized a^T M_r a = 1 */
    double a = qt_json_num(qt_json_get(qt_json_get(m0, "shape"), "x"));
    assert_true(fabs(M * a * a - 1) < 1e-12);
    assert_true(qt_json_str_is(qt_json_get(doc, "verdict"), "stable"));
    assert_true(qt_json_get(doc, "stable")[0] == 't');
    qd_buf_free(&b);
    /* text: w and the period of the pendulum, the point and the multiplier */
    b = (qd_buf)QD_BUF_INIT;
    assert_int_equal(qd_constrained_modes_print(s->ctx, s->eom, &r.c, &r.res, false, &b), QD_OK);
    const char *t = qd_buf_str(&b);
    assert_true(fabs(after(t, "w^2 = ") - G / L) < 1e-11);
    assert_true(fabs(after(t, ", w = ") - sqrt(G / L)) < 1e-9);
    assert_true(fabs(after(t, "period = ") - 2 * M_PI * sqrt(L / G)) < 1e-9);
    assert_true(fabs(after(t, ", y = ") + L) < 1e-11);
    assert_true(fabs(after(t, "lambda_rod = ") + M * G / (2 * L)) < 1e-11);
    assert_non_null(strstr(t, "verdict: stable\n"));
    qd_buf_free(&b);
    reduced_free(&r);
}

static void pendulum_statespace(void **state) {
    /* the reduced A and B (qd_constrained_state_matrix, _input_matrix) at the bottom:
     * x'' = -(g/l) x + F/m; their printing is qdot/conlin.h's now */
    qt_system *s = qt_system_derive(state, pendulum, false);
    const double q[2] = {0, -2};
    reduced r;
    reduce(s, q, NULL, &r);
    double A[4], B[2];
    const qd_expr *u = qd_model_input(s->model, 0);
    assert_int_equal(qd_constrained_state_matrix(s->ctx, &r.c, A), QD_OK);
    assert_int_equal(qd_constrained_input_matrix(s->ctx, s->eom, &r.c, 1, &u, r.n, r.syms, r.vals,
                                                 B), QD_OK);
    assert_true(A[0] == 0 && A[1] == 1);
    assert_true(fabs(A[2] + G / L) < 1e-12 && A[3] == 0);
    assert_true(fabs(B[0]) < 1e-15 && fabs(B[1] - 1 / M) < 1e-12);
    reduced_free(&r);
}

static void damped_roots(void **state) {
    qt_system *s = qt_system_derive(state, damped, false);
    const double q[2] = {0, -2};
    reduced r;
    reduce(s, q, NULL, &r);
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_constrained_modes_print(s->ctx, s->eom, &r.c, &r.res, true, &b), QD_OK);
    const char *doc = qd_buf_str(&b);
    assert_true(qt_json_valid(doc));
    assert_true(qt_json_get(doc, "conservative")[0] == 'f');
    assert_null(qt_json_get(doc, "modes"));
    assert_true(fabs(num2(doc, "damping_matrix", 0, 0) - C) < 1e-12);
    double re = -C / (2 * M), im = sqrt(G / L - C * C / (4 * M * M));
    assert_int_equal(qt_json_len(qt_json_get(doc, "eigenvalues")), 2);
    for (size_t k = 0; k < 2; k++) {
        assert_true(fabs(num2(doc, "eigenvalues", k, 0) - re) < 1e-12);
        assert_true(fabs(fabs(num2(doc, "eigenvalues", k, 1)) - im) < 1e-12);
    }
    assert_true(qt_json_str_is(qt_json_get(doc, "verdict"), "stable"));
    qd_buf_free(&b);
    b = (qd_buf)QD_BUF_INIT;
    assert_int_equal(qd_constrained_modes_print(s->ctx, s->eom, &r.c, &r.res, false, &b), QD_OK);
    const char *t = qd_buf_str(&b);
    assert_true(fabs(after(t, "  s = ") - re) < 1e-9);
    assert_null(strstr(t, "mode 1"));
    qd_buf_free(&b);
    reduced_free(&r);
}

static void double_pendulum_modes(void **state) {
    qt_system *s = qt_system_derive(state, double_pendulum, false);
    const double q[4] = {0, -L1, 0, -L1 - L2};
    reduced r;
    reduce(s, q, NULL, &r);
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_constrained_modes_print(s->ctx, s->eom, &r.c, &r.res, true, &b), QD_OK);
    const char *doc = qd_buf_str(&b);
    assert_true(qt_json_valid(doc));
    assert_int_equal(qt_json_len(qt_json_get(doc, "independent")), 2);
    assert_int_equal(qt_json_len(qt_json_get(doc, "dependent")), 2);
    double ms = M1 + M2, ls = L1 + L2;
    double disc = sqrt(ms * (ms * ls * ls - 4 * M1 * L1 * L2));
    double w2[2] = {G * (ms * ls - disc) / (2 * M1 * L1 * L2),
                    G * (ms * ls + disc) / (2 * M1 * L1 * L2)};
    const char *modes = qt_json_get(doc, "modes");
    assert_int_equal(qt_json_len(modes), 2);
    for (size_t k = 0; k < 2; k++) {
        double got = qt_json_num(qt_json_get(qt_json_at(modes, k), "omega2"));
        assert_true(fabs(got - w2[k]) < 1e-10 * w2[k]);
    }
    qd_buf_free(&b);
    reduced_free(&r);
}

static void expect_refused(const qt_system *s, const char *text, size_t at, size_t len,
                           const char *says) {
    size_t ix[4];
    qd_ctx_clear_error(s->ctx);
    assert_int_equal(qd_constrained_indep_read(s->ctx, s->eom, text, ix), QD_ERR_ARG);
    const qd_diag *d = qd_ctx_diag(s->ctx);
    if (!d->located || d->offset != at || d->length != len || !strstr(d->message, says))
        fail_msg("'%s': '%s' at %zu+%zu, wanted '%s' at %zu+%zu", text, d->message, d->offset,
                 d->length, says, at, len);
}

static void independent_names(void **state) {
    qt_system *s = qt_system_derive(state, double_pendulum, false);
    size_t ix[4] = {9, 9, 9, 9};
    assert_int_equal(qd_constrained_indep_read(s->ctx, s->eom, " y2,x1 ", ix), QD_OK);
    assert_true(ix[0] == 0 && ix[1] == 3); /* ascending: x1, y2 */
    assert_int_equal(qd_constrained_indep_read(s->ctx, s->eom, "x2 y1", ix), QD_OK);
    assert_true(ix[0] == 1 && ix[1] == 2);
    expect_refused(s, "x1, zz", 4, 2, "'zz' is not a coordinate");
    expect_refused(s, "x1, x1", 4, 2, "x1 is named twice");
    expect_refused(s, "x1, y1, x2", 8, 2, "name exactly 2");
    expect_refused(s, "x1", 0, 2, "the 2 constraints leave 2 independent coordinates");
    /* named independent x1, x2 give the same frequencies as the library's choice */
    qd_ctx_clear_error(s->ctx);
    const double q[4] = {0, -L1, 0, -L1 - L2};
    assert_int_equal(qd_constrained_indep_read(s->ctx, s->eom, "x1, x2", ix), QD_OK);
    reduced r, own;
    reduce(s, q, ix, &r);
    reduce(s, q, NULL, &own);
    for (size_t k = 0; k < 2; k++)
        assert_true(fabs(r.res.omega2[k] - own.res.omega2[k]) < 1e-10 * own.res.omega2[k]);
    /* the modes of one model with the reduction of another */
    qd_buf b = QD_BUF_INIT;
    qt_system one = {0};
    one.ctx = s->ctx;
    one.model = qd_model_parse(s->ctx, pendulum, NULL);
    assert_non_null(one.model);
    one.eom = qd_eom_derive(s->ctx, one.model);
    assert_non_null(one.eom);
    assert_int_equal(qd_constrained_modes_print(s->ctx, one.eom, &r.c, &r.res, true, &b),
                     QD_ERR_ARG);
    assert_int_equal(b.len, 0);
    qd_buf_free(&b);
    qd_eom_free(one.eom);
    qd_model_free(one.model);
    reduced_free(&r);
    reduced_free(&own);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(pendulum_modes, qt_system_teardown),
        cmocka_unit_test_teardown(pendulum_statespace, qt_system_teardown),
        cmocka_unit_test_teardown(damped_roots, qt_system_teardown),
        cmocka_unit_test_teardown(double_pendulum_modes, qt_system_teardown),
        cmocka_unit_test_teardown(independent_names, qt_system_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
