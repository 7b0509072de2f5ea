/*
 * tests/linear/test_choose_initial.c - the equilibrium search on big systems
 * (issue 34): qd_equilibria_choose takes the model's initial state when it is
 * a minimum-like equilibrium (QD_EQ_CHOSEN_INITIAL_STATE, no multistart);
 * affine equations with a singular Jacobian get one damped Newton run
 * (method "linear", a continuum); the multistart reports its progress to the
 * context and stops when asked.
 *
 * Models, each with its textbook answer:
 *   the ring of N masses m on a circle of radius R (arc coordinate s_i from
 *     its place at angle 2 pi i/N), neighbours joined by springs k along the
 *     ring: K = k (2 I - S - S^T) with S the cyclic shift, M = m I, so
 *     w_j = 2 sqrt(k/m) |sin(pi j/N)|, j = 0..N-1 (the cyclic group C_N of
 *     Desloge, Classical Mechanics, ch. 66, seed-desloge-B.md ch. 66; the
 *     circulant's eigenvalues 2k - 2k cos(2 pi j/N) = 4k sin^2(pi j/N));
 *     the rotation s_i = c is a family of equilibria (w_0 = 0);
 *   the spring triangle (three masses m joined by springs k of natural
 *     length a, Desloge ch. 66 worked example, seed-desloge-D.md T33):
 *     w^2 = 0 x3, 3k/2m x2, 3k/m about the equilateral triangle of side a,
 *     started on it (no search) or off it (the multistart);
 *   a pendulum started at the top th = pi: an equilibrium but a maximum of
 *     V = -m g l cos th, so the search runs and the bottom th = 0 is chosen.
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
#include "qdot/modes.h"
#include "../util/system.h"

static const double PI = 3.14159265358979323846;

enum { NRING = 20, MAXV = 2 * NRING + 8 };

/* The model's state as the CLI builds it: q, q', t, parameters at their
 * values. */
typedef struct point {
    size_t n;
    const qd_expr *syms[MAXV];
    double vals[MAXV];
} point;

static void state_of(const qt_system *s, point *p) {
    size_t nq = qd_model_ncoords(s->model), np = qd_model_nparams(s->model);
    assert_true(2 * nq + 1 + np <= MAXV);
    for (size_t i = 0; i < nq; i++) {
        p->syms[i] = qd_model_coord(s->model, i);
        p->syms[nq + i] = qd_jet(s->ctx, qd_model_coord(s->model, i), 1);
        p->vals[i] = p->vals[nq + i] = 0;
    }
    p->syms[2 * nq] = qd_time(s->ctx);
    p->vals[2 * nq] = 0;
    for (size_t i = 0; i < np; i++) {
        p->syms[2 * nq + 1 + i] = qd_model_param(s->model, i);
        assert_int_equal(qd_eval(s->ctx, qd_model_param_value(s->model, i), 0, NULL, NULL,
                                 &p->vals[2 * nq + 1 + i]), QD_OK);
    }
    p->n = 2 * nq + 1 + np;
}

static void choose(const qt_system *s, qd_equilibrium_choice *c) {
    point p;
    state_of(s, &p);
    assert_int_equal(qd_equilibria_choose(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, c),
                     QD_OK);
}

/* w^2 of the modes about q (ascending). */
static void omega2_at(const qt_system *s, const double *q, double *w2) {
    point p;
    state_of(s, &p);
    size_t n = s->eom->n;
    for (size_t j = 0; j < n; j++)
        p.vals[j] = q[j];
    qd_linear lin;
    qd_modes_result r;
    assert_int_equal(qd_linear_about(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, &lin), QD_OK);
    assert_int_equal(qd_modes_solve(s->ctx, &lin, &r), QD_OK);
    assert_true(r.conservative);
    for (size_t j = 0; j < n; j++)
        w2[j] = r.omega2[j];
    qd_linear_free(&lin);
    qd_modes_result_free(&r);
}

/* ---- the ring of N masses --------------------------------------------------- */

static const double RING_M = 3, RING_K = 2;

/* The ring's model text; initial: "zero" (every s_i = 0, an equilibrium),
 * "off" (s_1 = 0.1 only: not one) or "" (no initial state). */
static char *ring_model(size_t N, const char *initial) {
    size_t cap = 256 * N + 512, len = 0;
    char *t = malloc(cap);
    assert_non_null(t);
    len += (size_t)snprintf(t + len, cap - len, "coordinates ");
    for (size_t i = 1; i <= N; i++)
        len += (size_t)snprintf(t + len, cap - len, "%ss%zu", i > 1 ? ", " : "", i);
    len += (size_t)snprintf(t + len, cap - len, "\nparameters m = %g, k = %g, R = 1.5\n", RING_M,
                            RING_K);
    for (size_t i = 1; i <= N; i++)
        len += (size_t)snprintf(t + len, cap - len,
                                "particle m at R*(cos(2*pi*%zu/%zu + s%zu/R), "
                                "sin(2*pi*%zu/%zu + s%zu/R))\n", i - 1, N, i, i - 1, N, i);
    len += (size_t)snprintf(t + len, cap - len, "V = k/2*(");
    for (size_t i = 1; i <= N; i++)
        len += (size_t)snprintf(t + len, cap - len, "%s(s%zu - s%zu)^2", i > 1 ? " + " : "",
                                i % N + 1, i);
    len += (size_t)snprintf(t + len, cap - len, ")\n");
    if (!strcmp(initial, "zero")) {
        len += (size_t)snprintf(t + len, cap - len, "initial ");
        for (size_t i = 1; i <= N; i++)
            len += (size_t)snprintf(t + len, cap - len, "%ss%zu = 0", i > 1 ? ", " : "", i);
        len += (size_t)snprintf(t + len, cap - len, "\n");
    } else if (!strcmp(initial, "off")) {
        len += (size_t)snprintf(t + len, cap - len, "initial s1 = 0.1\n");
    }
    assert_true(len < cap);
    return t;
}

static int by_value(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The modes about the chosen point are the ring's: w_j = 2 sqrt(k/m)
 * |sin(pi j/N)| to 1e-10, and the point is a rotation of the ring (every
 * s_i equal: F = 0 there). */
static void assert_ring_modes(const qt_system *s, const qd_equilibrium *pt) {
    size_t N = NRING;
    for (size_t i = 1; i < N; i++)
        assert_true(fabs(pt->q[i] - pt->q[0]) < 1e-9);
    double w2[NRING], want[NRING];
    omega2_at(s, pt->q, w2);
    for (size_t j = 0; j < N; j++) {
        double w = 2 * sqrt(RING_K / RING_M) * fabs(sin(PI * (double)j / (double)N));
        want[j] = w;
    }
    qsort(want, N, sizeof *want, by_value);
    for (size_t j = 0; j < N; j++) {
        double w = sqrt(fmax(w2[j], 0));
        if (fabs(w - want[j]) > 1e-10)
            fail_msg("mode %zu: w = %.17g, want 2 sqrt(k/m)|sin(pi j/N)| = %.17g", j, w, want[j]);
    }
}

/* The initial state s_i = 0 is an equilibrium: taken with no search. */
static void test_ring_initial_state(void **state) {
    char *text = ring_model(NRING, "zero");
    qt_system *s = qt_system_derive(state, text, false);
    free(text);
    qd_equilibrium_choice c;
    choose(s, &c);
    assert_non_null(c.pt);
    assert_int_equal(c.reason, QD_EQ_CHOSEN_INITIAL_STATE);
    assert_int_equal(c.others, 0);
    assert_string_not_equal(c.found.method, "multistart");
    for (size_t i = 0; i < NRING; i++)
        assert_true(fabs(c.pt->q[i]) < 1e-12);
    assert_ring_modes(s, c.pt);
    assert_non_null(strstr(qd_eq_chosen_name(c.reason), "initial state is an equilibrium"));
    assert_string_equal(qd_eq_chosen_code(c.reason), "initial_state");
    qd_equilibrium_choice_free(&c);
}

/* No initial state: affine equations, J singular (the rotation), one damped
 * Newton run gives a point of the family. */
static void test_ring_no_initial(void **state) {
    char *text = ring_model(NRING, "");
    qt_system *s = qt_system_derive(state, text, false);
    free(text);
    qd_equilibrium_choice c;
    choose(s, &c);
    assert_non_null(c.pt);
    assert_int_equal(c.reason, QD_EQ_CHOSEN_LOWEST_MINIMUM);
    assert_string_equal(c.found.method, "linear");
    assert_int_equal(c.found.count, 1);
    assert_true(c.found.continuum);
    assert_int_equal(c.found.pts[0].nzero, 1); /* the rotation only */
    assert_int_equal(c.found.pts[0].npos, NRING - 1);
    assert_ring_modes(s, c.pt);
    qd_equilibrium_choice_free(&c);
}

/* Started off the family: Newton from s_1 = 0.1 reaches a rotation; the
 * ring's modes there. */
static void test_ring_off(void **state) {
    char *text = ring_model(NRING, "off");
    qt_system *s = qt_system_derive(state, text, false);
    free(text);
    qd_equilibrium_choice c;
    choose(s, &c);
    assert_non_null(c.pt);
    assert_int_equal(c.reason, QD_EQ_CHOSEN_NEAREST_MINIMUM);
    assert_string_equal(c.found.method, "linear");
    assert_ring_modes(s, c.pt);
    qd_equilibrium_choice_free(&c);
}

/* ---- the spring triangle: the initial state decides ----------------------- */

static const char triangle[] =
    "coordinates x1, y1, x2, y2, x3, y3\nparameters m = 2, k = 3, a = 1\n"
    "d12 = sqrt((x1 - x2)^2 + (y1 - y2)^2)\nd23 = sqrt((x2 - x3)^2 + (y2 - y3)^2)\n"
    "d31 = sqrt((x3 - x1)^2 + (y3 - y1)^2)\n"
    "particle m at (x1, y1)\nparticle m at (x2, y2)\nparticle m at (x3, y3)\n"
    "V = k/2*((d12 - a)^2 + (d23 - a)^2 + (d31 - a)^2)\n";

/* The point is an equilateral triangle of side a = 1 and its modes are
 * 0 x3, 3k/2m x2, 3k/m with k = 3, m = 2. */
static void assert_equilateral(const qt_system *s, const qd_equilibrium *pt) {
    const double *q = pt->q;
    double d12 = hypot(q[0] - q[2], q[1] - q[3]), d23 = hypot(q[2] - q[4], q[3] - q[5]);
    double d31 = hypot(q[4] - q[0], q[5] - q[1]);
    assert_true(fabs(d12 - 1) < 1e-8 && fabs(d23 - 1) < 1e-8 && fabs(d31 - 1) < 1e-8);
    double w2[6], want[6] = {0, 0, 0, 9.0 / 4, 9.0 / 4, 9.0 / 2};
    omega2_at(s, q, w2);
    for (size_t j = 0; j < 6; j++)
        assert_true(fabs(w2[j] - want[j]) < 1e-8);
}

static void test_triangle_on(void **state) {
    char text[1024];
    snprintf(text, sizeof text, "%sinitial x1 = 0, y1 = 0, x2 = 1, y2 = 0, x3 = 1/2, "
             "y3 = sqrt(3)/2\n", triangle);
    qt_system *s = qt_system_derive(state, text, false);
    qd_equilibrium_choice c;
    choose(s, &c);
    assert_non_null(c.pt);
    assert_int_equal(c.reason, QD_EQ_CHOSEN_INITIAL_STATE);
    assert_string_equal(c.found.method, "none"); /* no search */
    assert_int_equal(c.found.count, 0);
    assert_true(c.pt == &c.from_initial.pts[0]);
    assert_true(fabs(c.pt->q[5] - sqrt(3) / 2) < 1e-12);
    assert_equilateral(s, c.pt);
    qd_equilibrium_choice_free(&c);
}

/* Off the triangle: the multistart, and the nearest minimum is still the
 * equilateral triangle. */
static void test_triangle_off(void **state) {
    char text[1024];
    snprintf(text, sizeof text, "%sinitial x1 = 0.01, y1 = 0, x2 = 1, y2 = 0, x3 = 0.5, "
             "y3 = 0.8\n", triangle);
    qt_system *s = qt_system_derive(state, text, false);
    qd_equilibrium_choice c;
    choose(s, &c);
    assert_non_null(c.pt);
    assert_int_equal(c.reason, QD_EQ_CHOSEN_NEAREST_MINIMUM);
    assert_string_equal(c.found.method, "multistart");
    assert_true(c.found.count > 1);
    assert_equilateral(s, c.pt);
    qd_equilibrium_choice_free(&c);
}

/* Started at the top: an equilibrium, but a maximum, so not taken. */
static void test_pendulum_top(void **state) {
    qt_system *s = qt_system_derive(state,
        "coordinates th\nparameters m = 1, g = 9.81, l = 2\n"
        "particle m at (l*sin(th), -l*cos(th))\nV = -m*g*l*cos(th)\ninitial th = pi\n", false);
    qd_equilibrium_choice c;
    choose(s, &c);
    assert_non_null(c.pt);
    assert_int_not_equal(c.reason, QD_EQ_CHOSEN_INITIAL_STATE);
    assert_true(fabs(c.pt->q[0]) < 1e-12);
    assert_int_equal(c.pt->kind, QD_EQ_MINIMUM);
    double w2;
    omega2_at(s, c.pt->q, &w2);
    assert_true(fabs(w2 - 9.81 / 2) < 1e-10); /* g/l */
    qd_equilibrium_choice_free(&c);
}

/* ---- progress ------------------------------------------------------------- */

typedef struct counter {
    size_t calls, last_done, last_total, stop_at;
    bool monotone;
} counter;

static int count_steps(void *data, const char *what, size_t done, size_t total) {
    counter *k = data;
    assert_non_null(strstr(what, "multistart"));
    k->monotone = k->monotone && done > k->last_done && done <= total;
    k->calls++;
    k->last_done = done;
    k->last_total = total;
    return k->stop_at && k->calls >= k->stop_at;
}

/* The triangle's multistart: every axis scan and start reported once (6
 * scans, 40 n + 40 = 280 starts); asked to stop, the search fails cleanly. */
static void test_progress(void **state) {
    qt_system *s = qt_system_derive(state, triangle, false);
    point p;
    state_of(s, &p);
    counter k = {.monotone = true};
    qd_ctx_set_progress(s->ctx, count_steps, &k);
    qd_equilibria_opts o = {.numeric_only = true};
    qd_equilibria eq;
    assert_int_equal(qd_equilibria_find(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, &o, &eq),
                     QD_OK);
    assert_string_equal(eq.method, "multistart");
    assert_int_equal(k.calls, 6 + 280);
    assert_int_equal(k.last_done, k.last_total);
    assert_int_equal(k.last_total, 6 + 280);
    assert_true(k.monotone);
    qd_equilibria_free(&eq);

    k = (counter){.monotone = true, .stop_at = 10};
    assert_int_equal(qd_equilibria_find(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, &o, &eq),
                     QD_ERR_ARG);
    assert_int_equal(k.calls, 10);
    assert_non_null(strstr(qd_ctx_message(s->ctx), "stopped after 10 of 286"));
    assert_int_equal(eq.count, 0);
    qd_ctx_clear_error(s->ctx);

    qd_ctx_set_progress(s->ctx, NULL, &k); /* off */
    k = (counter){.monotone = true};
    assert_int_equal(qd_equilibria_find(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, &o, &eq),
                     QD_OK);
    assert_int_equal(k.calls, 0);
    qd_equilibria_free(&eq);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(test_ring_initial_state, qt_system_teardown),
        cmocka_unit_test_teardown(test_ring_no_initial, qt_system_teardown),
        cmocka_unit_test_teardown(test_ring_off, qt_system_teardown),
        cmocka_unit_test_teardown(test_triangle_on, qt_system_teardown),
        cmocka_unit_test_teardown(test_triangle_off, qt_system_teardown),
        cmocka_unit_test_teardown(test_pendulum_top, qt_system_teardown),
        cmocka_unit_test_teardown(test_progress, qt_system_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
