/*
 * tests/codegen/test_native.c - the generated C, compiled with the system
 * compiler and loaded (qd_native_load), against the library's own numbers
 * and against calculus:
 *   mass, forcing and q'' equal qd_eom_eval's at random states and random
 *     parameter values (the parameters are arguments of the generated code);
 *   the Jacobian equals central finite differences of the generated rhs
 *     (relative 1e-6);
 *   energy equals the model's T + V evaluated with qd_eval (double pendulum,
 *     Goldstein ch. 1 ex. 22, seed 002_3e07e211eebc00b9.txt), and for the bead
 *     on a uniformly rotating wire (Goldstein sec. 1.6, seed G03), a rheonomic
 *     system, the Jacobi integral h = m/2 (r'^2 - omega^2 r^2), which T + V
 *     is not;
 *   a constrained model (the Cartesian pendulum, rod x^2 + y^2 = l^2): q''
 *     from the saddle-point system equals qd_eom_eval's, the constraint's
 *     second derivative x x'' + y y'' + x'^2 + y'^2 vanishes;
 *   a 5-link pendulum, where the angle-difference expansion is used;
 *   a singular mass matrix (polar coordinates at r = 0) makes rhs return 1;
 *   the second load reuses the cached object; a missing compiler is an
 *   error with the reason, not a crash.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "qdot/qdot.h"
#include "qdot/codegen.h"
#include "util/system.h"

#define NMAX 8
#define NSTATES 12

static char cache[256];

static int group_setup(void **state) {
    (void)state;
    snprintf(cache, sizeof cache, "/tmp/qdot-test-native-XXXXXX");
    return mkdtemp(cache) ? 0 : -1;
}

static int group_teardown(void **state) {
    (void)state;
    char cmd[300];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", cache);
    return system(cmd) == 0 ? 0 : -1;
}

static int teardown(void **state) { return qt_system_teardown(state); }

static uint64_t rng = 0x9e3779b97f4a7c15ULL;
static double uniform(double lo, double hi) {
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return lo + (hi - lo) * (double)(rng >> 11) / 9007199254740992.0;
}

static bool close_to(double a, double b, double tol) {
    return fabs(a - b) <= tol * (1 + fabs(a) + fabs(b));
}

/* A random state for a loaded system and the matching qd_eom_eval inputs:
 * q, q', t, then the parameters (each a random factor of its default). */
typedef struct point {
    double t, y[2 * NMAX], par[16];
    size_t nsyms;
    const qd_expr *syms[2 * NMAX + 17];
    double vals[2 * NMAX + 17];
} point;

static void random_point(const qt_system *s, const qd_native *nat, point *p) {
    const qd_eom *e = s->eom;
    size_t n = e->n, k = 0;
    p->t = uniform(0, 2);
    for (size_t j = 0; j < 2 * n; j++)
        p->y[j] = uniform(-1.5, 1.5);
    for (size_t i = 0; i < nat->npar; i++)
        p->par[i] = nat->par_default[i] * uniform(0.5, 1.5);
    for (size_t j = 0; j < n; j++) {
        p->syms[k] = e->q[j];
        p->vals[k++] = p->y[j];
        p->syms[k] = e->qd[j];
        p->vals[k++] = p->y[n + j];
    }
    p->syms[k] = qd_time(s->ctx);
    p->vals[k++] = p->t;
    for (size_t i = 0; i < nat->npar; i++) {
        p->syms[k] = qd_model_param(s->model, i);
        p->vals[k++] = p->par[i];
    }
    p->nsyms = k;
}

static void load(const qt_system *s, qd_native *nat) {
    qd_status st = qd_native_load(s->ctx, s->model, s->eom, cache, nat);
    if (st != QD_OK)
        fail_msg("qd_native_load: %s", qd_ctx_message(s->ctx));
    assert_int_equal(nat->n, s->eom->n);
    assert_int_equal(nat->npar, qd_model_nparams(s->model));
}

/* M, f and q'' against qd_eom_eval at one point. */
static void check_eval(const qt_system *s, const qd_native *nat, const point *p) {
    size_t n = s->eom->n, nc = s->eom->ncon;
    double M[NMAX * NMAX], f[NMAX], qdd[NMAX], gM[NMAX * NMAX], gf[NMAX], dydt[2 * NMAX];
    double lambda[NMAX];
    assert_int_equal(qd_eom_eval(s->ctx, s->eom, p->nsyms, p->syms, p->vals, M, f, qdd,
                                 nc ? lambda : NULL, NULL),
                     QD_OK);
    nat->mass(p->t, p->y, p->par, gM);
    nat->forcing(p->t, p->y, p->y + n, p->par, gf);
    assert_int_equal(nat->rhs(p->t, p->y, p->par, dydt), 0);
    for (size_t i = 0; i < n * n; i++)
        assert_true(close_to(gM[i], M[i], 1e-12));
    for (size_t i = 0; i < n; i++) {
        assert_true(close_to(gf[i], f[i], 1e-12));
        assert_true(close_to(dydt[i], p->y[n + i], 0));
        if (!close_to(dydt[n + i], qdd[i], 1e-9))
            fail_msg("q''[%zu]: generated %.17g, qd_eom_eval %.17g", i, dydt[n + i], qdd[i]);
    }
}

/* The Jacobian against central differences of rhs. */
static void check_jacobian(const qd_native *nat, const point *p) {
    size_t n = nat->n, w = 2 * n;
    double J[4 * NMAX * NMAX], y[2 * NMAX], fp[2 * NMAX], fm[2 * NMAX];
    nat->jacobian(p->t, p->y, p->par, J);
    for (size_t k = 0; k < w; k++) {
        memcpy(y, p->y, w * sizeof *y);
        double h = 1e-6 * (1 + fabs(y[k]));
        y[k] = p->y[k] + h;
        assert_int_equal(nat->rhs(p->t, y, p->par, fp), 0);
        y[k] = p->y[k] - h;
        assert_int_equal(nat->rhs(p->t, y, p->par, fm), 0);
        double scale = 0;
        for (size_t i = 0; i < w; i++)
            scale = fmax(scale, fabs(J[i * w + k]));
        for (size_t i = 0; i < w; i++) {
            double fd = (fp[i] - fm[i]) / (2 * h);
            if (fabs(J[i * w + k] - fd) > 1e-6 * (1 + scale))
                fail_msg("J[%zu][%zu] = %.12g, finite differences %.12g", i, k, J[i * w + k],
                         fd);
        }
    }
}

static void check_energy_TV(const qt_system *s, const qd_native *nat, const point *p) {
    double T, V;
    assert_int_equal(qd_eval(s->ctx, qd_model_kinetic(s->model), p->nsyms, p->syms, p->vals, &T),
                     QD_OK);
    assert_int_equal(
        qd_eval(s->ctx, qd_model_potential(s->model), p->nsyms, p->syms, p->vals, &V), QD_OK);
    double h = nat->energy(p->t, p->y, p->par);
    if (!close_to(h, T + V, 1e-12))
        fail_msg("energy %.17g, T + V %.17g", h, T + V);
}

static const char double_pendulum[] =
    "coordinates theta1, theta2\n"
    "parameters m1 = 1, m2 = 1.5, l1 = 1, l2 = 0.7, g = 9.81\n"
    "x1 = l1*sin(theta1)\ny1 = -l1*cos(theta1)\n"
    "x2 = x1 + l2*sin(theta2)\ny2 = y1 - l2*cos(theta2)\n"
    "T = m1/2*(x1'^2 + y1'^2) + m2/2*(x2'^2 + y2'^2)\n"
    "V = m1*g*y1 + m2*g*y2\n";

static void test_double_pendulum(void **state) {
    qt_system *s = qt_system_derive(state, double_pendulum, false);
    qd_native nat;
    load(s, &nat);
    assert_false(nat.cached);
    assert_true(close_to(nat.par_default[4], 9.81, 0));
    assert_true(close_to(nat.par_default[3], 0.7, 0));
    for (int k = 0; k < NSTATES; k++) {
        point p;
        random_point(s, &nat, &p);
        check_eval(s, &nat, &p);
        check_jacobian(&nat, &p);
        check_energy_TV(s, &nat, &p);
    }
    /* The same equations again: the object is reused. */
    qd_native again;
    load(s, &again);
    assert_true(again.cached);
    assert_string_equal(again.path, nat.path);
    qd_native_unload(&again);
    qd_native_unload(&nat);
    assert_null(nat.handle);
}

static void test_constrained(void **state) {
    qt_system *s = qt_system_derive(state,
                                    "coordinates x, y\nparameters m = 0.6, l = 1.4, g = 9.81\n"
                                    "particle m at (x, y)\nV = m*g*y\n"
                                    "constraint rod: x^2 + y^2 = l^2\n",
                                    false);
    assert_int_equal(s->eom->ncon, 1);
    qd_native nat;
    load(s, &nat);
    for (int k = 0; k < NSTATES; k++) {
        point p;
        random_point(s, &nat, &p);
        check_eval(s, &nat, &p);
        check_jacobian(&nat, &p);
        check_energy_TV(s, &nat, &p);
        double d[4];
        assert_int_equal(nat.rhs(p.t, p.y, p.par, d), 0);
        double x = p.y[0], y = p.y[1], vx = p.y[2], vy = p.y[3];
        assert_true(close_to(x * d[2] + y * d[3] + vx * vx + vy * vy, 0, 1e-12));
    }
    qd_native_unload(&nat);
}

/* Goldstein sec. 1.6: r'' = omega^2 r; h = m/2 (r'^2 - omega^2 r^2). */
static void test_rheonomic_energy(void **state) {
    qt_system *s = qt_system_derive(state,
                                    "coordinates r\nparameters m = 1.5, omega = 2.2\n"
                                    "particle m at (r*cos(omega*t), r*sin(omega*t))\n",
                                    false);
    qd_native nat;
    load(s, &nat);
    for (int k = 0; k < NSTATES; k++) {
        point p;
        random_point(s, &nat, &p);
        double m = p.par[0], w = p.par[1], r = p.y[0], v = p.y[1], d[2];
        assert_true(close_to(nat.energy(p.t, p.y, p.par), m / 2 * (v * v - w * w * r * r), 1e-12));
        assert_int_equal(nat.rhs(p.t, p.y, p.par, d), 0);
        assert_true(close_to(d[1], w * w * r, 1e-12));
        check_jacobian(&nat, &p);
    }
    qd_native_unload(&nat);
}

static void test_five_links(void **state) {
    qd_buf b = QD_BUF_INIT;
    qd_buf_puts(&b, "coordinates a1, a2, a3, a4, a5\nparameters g = 9.81");
    for (int i = 1; i <= 5; i++)
        qd_buf_printf(&b, ", m%d = %g, l%d = %g", i, 1 + 0.1 * i, i, 1 - 0.05 * i);
    qd_buf_puts(&b, "\nx0 = 0\ny0 = 0\n");
    for (int i = 1; i <= 5; i++)
        qd_buf_printf(&b, "x%d = x%d + l%d*sin(a%d)\ny%d = y%d - l%d*cos(a%d)\n", i, i - 1, i, i,
                      i, i - 1, i, i);
    qd_buf_puts(&b, "T = 0");
    for (int i = 1; i <= 5; i++)
        qd_buf_printf(&b, " + m%d/2*(x%d'^2 + y%d'^2)", i, i, i);
    qd_buf_puts(&b, "\nV = 0");
    for (int i = 1; i <= 5; i++)
        qd_buf_printf(&b, " + m%d*g*y%d", i, i);
    qd_buf_puts(&b, "\n");
    qt_system *s = qt_system_derive(state, qd_buf_str(&b), false);
    qd_buf c = QD_BUF_INIT, h = QD_BUF_INIT;
    assert_int_equal(qd_codegen_c(s->ctx, s->model, s->eom, "five", &c, &h), QD_OK);
    /* Expanded: no call on a difference of angles remains. */
    assert_null(strstr(qd_buf_str(&c), "cos(a1 - a2)"));
    assert_non_null(strstr(qd_buf_str(&h), "int five_rhs(double t, const double *y"));
    qd_native nat;
    load(s, &nat);
    for (int k = 0; k < NSTATES; k++) {
        point p;
        random_point(s, &nat, &p);
        check_eval(s, &nat, &p);
        check_jacobian(&nat, &p);
        check_energy_TV(s, &nat, &p);
    }
    /* A run's object (qd_native_load_run): no P_jacobian, a file of its own,
     * and the same q'' to the bit, since P_rhs is the same text */
    qd_native run;
    assert_int_equal(qd_native_load_run(s->ctx, s->model, s->eom, cache, &run), QD_OK);
    assert_null(run.jacobian);
    assert_string_not_equal(run.path, nat.path);
    for (int k = 0; k < NSTATES; k++) {
        point p;
        random_point(s, &nat, &p);
        double a[10], r[10];
        assert_int_equal(nat.rhs(p.t, p.y, p.par, a), run.rhs(p.t, p.y, p.par, r));
        assert_memory_equal(a, r, sizeof a);
    }
    qd_native_unload(&run);
    qd_native_unload(&nat);
    qd_buf_free(&b);
    qd_buf_free(&c);
    qd_buf_free(&h);
}

/* M = diag(m, m r^2) is singular at r = 0. */
static void test_singular(void **state) {
    qt_system *s = qt_system_derive(state,
                                    "coordinates r, theta\nparameters m = 1.3, k = 4\n"
                                    "particle m at r*(cos(theta), sin(theta))\nV = k*r^2\n",
                                    false);
    qd_native nat;
    load(s, &nat);
    double y[4] = {0, 0.3, 0.1, 0.2}, d[4];
    assert_int_not_equal(nat.rhs(0, y, nat.par_default, d), 0);
    y[0] = 0.5;
    assert_int_equal(nat.rhs(0, y, nat.par_default, d), 0);
    qd_native_unload(&nat);
}

static void test_no_compiler(void **state) {
    qt_system *s = qt_system_derive(state,
                                    "coordinates x\nparameters m = 2, k = 3\n"
                                    "particle m at (x, 0)\nV = k*x^2/2 + x^4\n",
                                    false);
    const char *old = getenv("CC");
    char *saved = old ? strdup(old) : NULL;
    setenv("CC", "/nonexistent/qdot-cc", 1);
    qd_native nat;
    qd_status st = qd_native_load(s->ctx, s->model, s->eom, cache, &nat);
    if (saved)
        setenv("CC", saved, 1);
    else
        unsetenv("CC");
    free(saved);
    assert_int_equal(st, QD_ERR_UNSUPPORTED);
    assert_null(nat.handle);
    assert_null(nat.rhs);
    assert_non_null(strstr(qd_ctx_message(s->ctx), "compiler"));
}

static void test_bad_prefix(void **state) {
    qt_system *s = qt_system_derive(state, "coordinates x\nparameters m = 2\n"
                                           "particle m at (x, 0)\n", false);
    qd_buf c = QD_BUF_INIT, h = QD_BUF_INIT;
    assert_int_equal(qd_codegen_c(s->ctx, s->model, s->eom, "9lives", &c, &h), QD_ERR_ARG);
    qd_buf_free(&c);
    qd_buf_free(&h);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(test_double_pendulum, teardown),
        cmocka_unit_test_teardown(test_constrained, teardown),
        cmocka_unit_test_teardown(test_rheonomic_energy, teardown),
        cmocka_unit_test_teardown(test_five_links, teardown),
        cmocka_unit_test_teardown(test_singular, teardown),
        cmocka_unit_test_teardown(test_no_compiler, teardown),
        cmocka_unit_test_teardown(test_bad_prefix, teardown),
    };
    return cmocka_run_group_tests(tests, group_setup, group_teardown);
}
