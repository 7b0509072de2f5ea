/*
 * tests/fault/test_fault.c - every allocation made to fail, one at a time
 * (SQLite's test/exprfault.test, Lua's testes/memerr.lua).
 *
 * A context gets an allocator (qd_ctx_new_with; tests/util/fault.h) that fails its Nth request;
 * the body runs for N = 1, 2, 3, ... until it gets through without the
 * failure being reached.  Each run must end with the right answer or a clean
 * QD_ERR_NOMEM, and with every block given back (the allocator counts the
 * blocks outstanding; ASan, in the sanitizer run of `make test`, sees the
 * rest: the C library's blocks, use after free, double free).
 *
 * Bodies and the answers they must give:
 *   derivation: parse and Lagrange equations of the double pendulum; the
 *     accelerations M^-1 f at a state against Goldstein ch. 1 Exercise 22
 *     (seed 002; examples/double_pendulum.qd has the textbook equations);
 *   constrained derivation: a pendulum in Cartesian coordinates with its rod
 *     as a constraint, solved for q'' and the multiplier (qd_eom_solve); the
 *     accelerations against r'' = -g e_y + r (g y - v^2) / l^2;
 *   simulation: a pendulum, dop853 over 1 s, the final state against a
 *     classical RK4 of th'' = -(g/l) sin th written here, energy conserved;
 *   modes: the double pendulum with equal masses and lengths about th = 0,
 *     w^2 = (g/l)(2 -+ sqrt 2) (Goldstein ch. 6, reference
 *     seed-goldstein-britannica.md);
 *   degrees of freedom (qdot check): the two disks on an axle
 *     (examples/two_disks_axle.qd), 4 configurational and 2 motional
 *     (Desloge ch. 52 Problem 5, seed 000), by qd_eom_dof;
 *   heavy top derivation: a body with an orientation (the parser checks it is a
 *     rotation), its mass matrix in Euler angles against Goldstein sec. 5.7;
 *   steady motions: the heavy top (examples/heavy_top.qd) at th = 0.5 with
 *     C n = p_psi = 24, both precession rates of
 *     A cos th phi'^2 - C n phi' + M g h = 0 (Goldstein sec. 5.7; Britannica
 *     sec. 5 (29)-(30), seed 004), by qd_steady_find_all;
 *   impulse: the rhombus hitting a wall (Desloge ch. 57 Ex. 1), by
 *     qd_impulse_solve with the closed form.
 * The simulation, modes, degrees-of-freedom and steady bodies derive first with the failures off, so
 * their loops fail only the allocations of the run itself.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "qdot/qdot.h"
#include "util/fault.h"

/* ---- shared set-up -------------------------------------------------------- */

#define DOUBLE_PENDULUM                                                                        \
    "coordinates theta1, theta2\n"                                                             \
    "parameters m1 = 1, m2 = 3, l1 = 2, l2 = 1, g = 9.81\n"                                    \
    "x1 = l1*sin(theta1)\ny1 = -l1*cos(theta1)\n"                                              \
    "x2 = x1 + l2*sin(theta2)\ny2 = y1 - l2*cos(theta2)\n"                                     \
    "T = m1/2*(x1'^2 + y1'^2) + m2/2*(x2'^2 + y2'^2)\nV = m1*g*y1 + m2*g*y2\n"

#define EQUAL_PENDULUM                                                                         \
    "coordinates theta1, theta2\n"                                                             \
    "parameters m = 1, l = 1, g = 9.81\n"                                                      \
    "x1 = l*sin(theta1)\ny1 = -l*cos(theta1)\n"                                                \
    "x2 = x1 + l*sin(theta2)\ny2 = y1 - l*cos(theta2)\n"                                       \
    "T = m/2*(x1'^2 + y1'^2) + m/2*(x2'^2 + y2'^2)\nV = m*g*y1 + m*g*y2\n"

#define PENDULUM                                                                               \
    "coordinates th\nparameters m = 1, l = 2, g = 9.81\n"                                      \
    "particle m at (l*sin(th), -l*cos(th))\nV = -m*g*l*cos(th)\n"

/* Parse and derive; the status of whichever failed. */
static qd_status derive(qd_ctx *ctx, const char *text, qd_model **m, qd_eom **e) {
    qd_diag d;
    *e = NULL;
    *m = qd_model_parse(ctx, text, &d);
    if (!*m)
        return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_PARSE;
    *e = qd_eom_derive(ctx, *m);
    if (!*e)
        return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_ARG;
    return QD_OK;
}

/* Evaluate x at the model's parameter values and the given (symbol, value)s. */
typedef struct env {
    size_t n;
    const qd_expr *syms[16];
    double vals[16];
} env;

static void env_params(qd_ctx *ctx, const qd_model *m, env *v) {
    for (size_t i = 0; i < qd_model_nparams(m); i++) {
        v->syms[v->n] = qd_model_param(m, i);
        qd_eval(ctx, qd_model_param_value(m, i), 0, NULL, NULL, &v->vals[v->n]);
        v->n++;
    }
}

/* ---- derivation ------------------------------------------------------------ */

/* Goldstein ch. 1 Ex. 22: M th'' = f with
 *   M = [(m1+m2) l1^2, m2 l1 l2 c; m2 l1 l2 c, m2 l2^2], c = cos(th1 - th2),
 *   f1 = -m2 l1 l2 th2'^2 s - (m1+m2) g l1 sin th1, s = sin(th1 - th2),
 *   f2 =  m2 l1 l2 th1'^2 s - m2 g l2 sin th2. */
static void textbook_acc(const double *x, double *acc) {
    double m1 = 1, m2 = 3, l1 = 2, l2 = 1, g = 9.81;
    double c = cos(x[0] - x[1]), s = sin(x[0] - x[1]);
    double M[4] = {(m1 + m2) * l1 * l1, m2 * l1 * l2 * c, m2 * l1 * l2 * c, m2 * l2 * l2};
    double f[2] = {-m2 * l1 * l2 * x[3] * x[3] * s - (m1 + m2) * g * l1 * sin(x[0]),
                   m2 * l1 * l2 * x[2] * x[2] * s - m2 * g * l2 * sin(x[1])};
    double det = M[0] * M[3] - M[1] * M[2];
    acc[0] = (M[3] * f[0] - M[1] * f[1]) / det;
    acc[1] = (M[0] * f[1] - M[2] * f[0]) / det;
}

static qd_status check_acc(qd_ctx *ctx, const qd_model *m, const qd_eom *e) {
    static const double x[4] = {0.7, -0.4, 1.3, -0.8}; /* th1, th2, th1', th2' */
    env v = {0, {0}, {0}};
    for (size_t j = 0; j < 2; j++) {
        v.syms[v.n] = e->q[j], v.vals[v.n++] = x[j];
        v.syms[v.n] = e->qd[j], v.vals[v.n++] = x[2 + j];
    }
    env_params(ctx, m, &v);
    double M[4], f[2], acc[2], want[2];
    for (size_t k = 0; k < 4; k++) {
        qd_status st = qd_eval(ctx, e->M[k], v.n, v.syms, v.vals, &M[k]);
        if (st != QD_OK)
            return st;
    }
    for (size_t k = 0; k < 2; k++) {
        qd_status st = qd_eval(ctx, e->f[k], v.n, v.syms, v.vals, &f[k]);
        if (st != QD_OK)
            return st;
    }
    double det = M[0] * M[3] - M[1] * M[2];
    acc[0] = (M[3] * f[0] - M[1] * f[1]) / det;
    acc[1] = (M[0] * f[1] - M[2] * f[0]) / det;
    textbook_acc(x, want);
    assert_true(fabs(acc[0] - want[0]) < 1e-12 * (1 + fabs(want[0])));
    assert_true(fabs(acc[1] - want[1]) < 1e-12 * (1 + fabs(want[1])));
    return QD_OK;
}

static qd_status derivation_body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)f, (void)data;
    qd_model *m;
    qd_eom *e;
    qd_status st = derive(ctx, DOUBLE_PENDULUM, &m, &e);
    if (st == QD_OK)
        st = check_acc(ctx, m, e);
    qd_eom_free(e);
    qd_model_free(m);
    return st;
}

static void test_derivation(void **state) {
    (void)state;
    qt_fault_stats ls = qt_fault_loop("derivation", derivation_body, NULL, 1);
    assert_true(ls.allocs > 10);
}

/* ---- a constrained derivation, solved --------------------------------------------- */

#define CARTESIAN_PENDULUM                                                                     \
    "coordinates x, y\nparameters m = 0.6, l = 1.4, g = 9.81\n"                                \
    "particle m at (x, y)\nV = m*g*y\nconstraint rod: x^2 + y^2 = l^2\n"

/* A pendulum in Cartesian coordinates (examples/pendulum_cartesian.qd):
 * m r'' = -m g e_y + 2 lambda r with x x'' + y y'' + v^2 = 0 give
 * r'' = -g e_y + r (g y - v^2) / l^2. */
static qd_status check_cartesian(qd_ctx *ctx, const qd_model *m, const qd_eom *e) {
    const double l = 1.4, g = 9.81, th = 0.8, w = 1.7;
    const double x[4] = {l * sin(th), -l * cos(th), w * l * cos(th), w * l * sin(th)};
    env v = {0, {0}, {0}};
    for (size_t j = 0; j < 2; j++) {
        v.syms[v.n] = e->q[j], v.vals[v.n++] = x[j];
        v.syms[v.n] = e->qd[j], v.vals[v.n++] = x[2 + j];
    }
    env_params(ctx, m, &v);
    double acc[2], k = (g * x[1] - x[2] * x[2] - x[3] * x[3]) / (l * l);
    for (size_t j = 0; j < 2; j++) {
        qd_status st = qd_eval(ctx, e->acc[j], v.n, v.syms, v.vals, &acc[j]);
        if (st != QD_OK)
            return st;
    }
    assert_true(fabs(acc[0] - x[0] * k) < 1e-12);
    assert_true(fabs(acc[1] - (-g + x[1] * k)) < 1e-12);
    return QD_OK;
}

static qd_status constrained_body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)f, (void)data;
    qd_model *m;
    qd_eom *e;
    qd_status st = derive(ctx, CARTESIAN_PENDULUM, &m, &e);
    if (st == QD_OK) {
        assert_int_equal(e->ncon, 1);
        st = qd_eom_solve(ctx, e, 100000);
    }
    if (st == QD_OK)
        st = check_cartesian(ctx, m, e);
    qd_eom_free(e);
    qd_model_free(m);
    return st;
}

static void test_constrained(void **state) {
    (void)state;
    qt_fault_stats ls = qt_fault_loop("constrained derivation", constrained_body, NULL, 1);
    assert_true(ls.allocs > 10);
}

/* ---- simulation -------------------------------------------------------------- */

/* th'' = -(g/l) sin th by classical RK4, h = 1e-4: error ~1e-14 over 1 s. */
static void rk4_pendulum(double th, double w, double t_end, double *out) {
    const double k = 9.81 / 2, h = 1e-4;
    for (long i = 0, n = lround(t_end / h); i < n; i++) {
        double a1 = w, b1 = -k * sin(th);
        double a2 = w + h / 2 * b1, b2 = -k * sin(th + h / 2 * a1);
        double a3 = w + h / 2 * b2, b3 = -k * sin(th + h / 2 * a2);
        double a4 = w + h * b3, b4 = -k * sin(th + h * a3);
        th += h / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
        w += h / 6 * (b1 + 2 * b2 + 2 * b3 + b4);
    }
    out[0] = th, out[1] = w;
}

static int sink_none(void *data, int event, const double *row) {
    (void)data, (void)event, (void)row;
    return 0;
}

static qd_status sim_run(qd_ctx *ctx, qt_faulty *f, double *final) {
    qd_model *m;
    qd_eom *e;
    long armed = f->fail_at;
    f->fail_at = 0; /* the derivation has its own loop */
    qd_status st = derive(ctx, PENDULUM, &m, &e);
    assert_int_equal(st, QD_OK);
    f->fail_at = f->count + armed;
    qd_sim *s = qd_sim_new(ctx, m, e);
    if (!s) {
        st = qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_ARG; /* NULL says why */
    } else {
        double q0 = 1.2, qd0 = 0.3;
        qd_sim_opts o = {.method = QD_SIM_DOP853, .t0 = 0, .t_end = 1, .dt = 0.25,
                         .rtol = 1e-12, .atol = 1e-12, .q0 = &q0, .qd0 = &qd0};
        qd_sim_stats stats;
        st = qd_sim_run(s, &o, sink_none, NULL, &stats, final);
        if (st == QD_OK)
            assert_true(stats.energy_error_max < 1e-10);
    }
    qd_sim_free(s);
    qd_eom_free(e);
    qd_model_free(m);
    return st;
}

static qd_status sim_body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)data;
    double final[8];
    qd_status st = sim_run(ctx, f, final);
    if (st == QD_OK) {
        double want[2];
        rk4_pendulum(1.2, 0.3, 1, want);
        assert_true(fabs(final[0] - 1) < 1e-12);           /* t */
        assert_true(fabs(final[1] - want[0]) < 1e-9);
        assert_true(fabs(final[2] - want[1]) < 1e-9);
    }
    return st;
}

static void test_simulation(void **state) {
    (void)state;
    qt_fault_stats ls = qt_fault_loop("simulation", sim_body, NULL, 1);
    assert_true(ls.allocs > 10);
}

/* ---- modes ----------------------------------------------------------------------- */

static qd_status modes_body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)data;
    qd_model *m;
    qd_eom *e;
    long armed = f->fail_at;
    f->fail_at = 0;
    qd_status st = derive(ctx, EQUAL_PENDULUM, &m, &e);
    assert_int_equal(st, QD_OK);
    f->fail_at = f->count + armed;
    env v = {0, {0}, {0}};
    for (size_t j = 0; j < 2; j++)
        v.syms[v.n] = e->q[j], v.vals[v.n++] = 0;
    env_params(ctx, m, &v);
    qd_linear lin = {0};
    qd_modes_result r = {0};
    st = qd_linear_about(ctx, e, m, v.n, v.syms, v.vals, &lin);
    if (st == QD_OK)
        st = qd_modes_solve(ctx, &lin, &r);
    if (st == QD_OK) {
        double g = 9.81;
        assert_true(r.conservative);
        assert_true(fabs(r.omega2[0] - g * (2 - sqrt(2))) < 1e-10);
        assert_true(fabs(r.omega2[1] - g * (2 + sqrt(2))) < 1e-10);
        assert_true(fabs(r.shapes[2] / r.shapes[0] - sqrt(2)) < 1e-10); /* th2/th1 of mode 1 */
        /* s = +-i w, sorted by Im descending: w2, w1, -w1, -w2 */
        assert_int_equal(r.neig, 4);
        for (size_t i = 0; i < 4; i++)
            assert_true(fabs(r.eig_re[i]) < 1e-12);
        assert_true(fabs(r.eig_im[0] - sqrt(r.omega2[1])) < 1e-10);
        assert_true(fabs(r.eig_im[1] - sqrt(r.omega2[0])) < 1e-10);
        assert_true(fabs(r.eig_im[2] + sqrt(r.omega2[0])) < 1e-10);
        assert_true(fabs(r.eig_im[3] + sqrt(r.omega2[1])) < 1e-10);
    }
    qd_modes_result_free(&r);
    qd_linear_free(&lin);
    qd_eom_free(e);
    qd_model_free(m);
    return st;
}

static void test_modes(void **state) {
    (void)state;
    qt_fault_stats ls = qt_fault_loop("modes", modes_body, NULL, 1);
    assert_true(ls.allocs > 5);
}

/* ---- degrees of freedom ------------------------------------------------------------- */

#define TWO_DISKS_AXLE                                                                         \
    "coordinates x, y, th, phi, psi\nparameters m = 1.2, a = 0.3, b = 0.5\n"                    \
    "T = m*(x'^2 + y'^2) + (m*b^2 + m*a^2/4)*th'^2 + m*a^2/4*(phi'^2 + psi'^2)\n"               \
    "constraint side: x'*cos(th) + y'*sin(th) = 0\n"                                            \
    "constraint roll1: -x'*sin(th) + y'*cos(th) + b*th' - a*phi' = 0\n"                         \
    "constraint roll2: -x'*sin(th) + y'*cos(th) - b*th' - a*psi' = 0\n"

/* No constraint is integrable alone, roll1 - roll2 is: 5 - 1 = 4 configurational, 5 - 3 = 2
 * motional degrees of freedom (Desloge ch. 52 P5). */
static qd_status dof_body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)data;
    qd_model *m;
    qd_eom *e;
    long armed = f->fail_at;
    f->fail_at = 0;
    qd_status st = derive(ctx, TWO_DISKS_AXLE, &m, &e);
    assert_int_equal(st, QD_OK);
    f->fail_at = f->count + armed;
    qd_dof d;
    st = qd_eom_dof(ctx, e, &d);
    if (st == QD_OK) {
        assert_int_equal(d.coordinates, 5);
        assert_int_equal(d.independent, 3);
        assert_int_equal(d.relations, 1);
        assert_int_equal(d.configurational, 4);
        assert_int_equal(d.motional, 2);
    }
    qd_eom_free(e);
    qd_model_free(m);
    return st;
}

static void test_dof(void **state) {
    (void)state;
    qt_fault_stats ls = qt_fault_loop("degrees of freedom", dof_body, NULL, 7);
    assert_true(ls.allocs > 5);
}

/* ---- steady motions ---------------------------------------------------------------- */

#define HEAVY_TOP                                                                              \
    "coordinates phi, theta, psi\nparameters M = 1.2, h = 0.3, A = 0.5, C = 0.8, g = 9.81\n"    \
    "body top mass M inertia (A - M*h^2, A - M*h^2, C) at "                                     \
    "h*(sin(theta)*sin(phi), -sin(theta)*cos(phi), cos(theta)) orientation euler(phi, theta, psi)\n" \
    "V = M*g*h*cos(theta)\n"

/* A body's kinetic energy about a fixed point: with the Euler angles (phi, theta, psi),
 * T = A/2 (th'^2 + phi'^2 sin^2 th) + C/2 (psi' + phi' cos th)^2 (Goldstein sec. 5.7), so
 * M = [A s^2 + C c^2, 0, C c; 0, A, 0; C c, 0, C].  The parse checks that the orientation
 * is a rotation (model/body.c), the derivation that M is symmetric (Debug). */
static qd_status heavy_top_body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)f, (void)data;
    qd_model *m;
    qd_eom *e;
    qd_status st = derive(ctx, HEAVY_TOP, &m, &e);
    if (st == QD_OK) {
        const double A = 0.5, C = 0.8, th = 0.7, c = cos(th), s = sin(th);
        const double want[9] = {A * s * s + C * c * c, 0, C * c, 0, A, 0, C * c, 0, C};
        env v = {0, {0}, {0}};
        v.syms[v.n] = e->q[1], v.vals[v.n++] = th;
        env_params(ctx, m, &v);
        for (size_t k = 0; k < 9 && st == QD_OK; k++) {
            double x;
            st = qd_eval(ctx, e->M[k], v.n, v.syms, v.vals, &x);
            if (st == QD_OK)
                assert_true(fabs(x - want[k]) < 1e-12);
        }
    }
    qd_eom_free(e);
    qd_model_free(m);
    return st;
}

static void test_heavy_top(void **state) {
    (void)state;
    qt_fault_stats ls = qt_fault_loop("heavy top derivation", heavy_top_body, NULL, 4);
    assert_true(ls.allocs > 10);
}

static void check_precessions(const qd_steady_set *set) {
    const double A = 0.5, C = 0.8, Mgh = 1.2 * 9.81 * 0.3, th = 0.5, Cn = 24;
    double a = A * cos(th), disc = sqrt(Cn * Cn - 4 * a * Mgh);
    double slow = (Cn - disc) / (2 * a), fast = (Cn + disc) / (2 * a);
    assert_int_equal(set->count, 2);
    assert_true(set->complete);
    double r0 = set->pts[0].w[0], r1 = set->pts[1].w[0];
    double lo = r0 < r1 ? r0 : r1, hi = r0 < r1 ? r1 : r0;
    assert_true(fabs(lo - slow) < 1e-9 * (1 + slow));
    assert_true(fabs(hi - fast) < 1e-9 * (1 + fast));
    for (size_t k = 0; k < 2; k++) { /* the spin n = psi' + phi' cos th is C n / C for both */
        assert_true(fabs(set->pts[k].x[0] - th) < 1e-12);
        assert_true(fabs(set->pts[k].w[1] + set->pts[k].w[0] * cos(th) - Cn / C) < 1e-9);
    }
}

static qd_status steady_body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)data;
    qd_model *m;
    qd_eom *e;
    long armed = f->fail_at;
    f->fail_at = 0;
    qd_status st = derive(ctx, HEAVY_TOP, &m, &e);
    assert_int_equal(st, QD_OK);
    const qd_expr *cyc[2] = {e->q[0], e->q[2]}; /* phi, psi */
    qd_steady *s = qd_steady_derive(ctx, m, e, 2, cyc, false);
    assert_non_null(s);
    f->fail_at = f->count + armed;
    env v = {0, {0}, {0}};
    env_params(ctx, m, &v);
    double x[1] = {0.5}, w[2] = {1, 1}, p[2] = {0, 24};
    bool xfix[1] = {true}, wfix[2] = {false, false}, pfix[2] = {false, true};
    qd_steady_point start = {x, w, p};
    qd_steady_set set;
    st = qd_steady_find_all(ctx, s, v.n, v.syms, v.vals, xfix, wfix, pfix, NULL, &start, &set);
    if (st == QD_OK)
        check_precessions(&set);
    qd_steady_set_free(&set);
    qd_steady_free(s);
    qd_eom_free(e);
    qd_model_free(m);
    return st;
}

static void test_steady(void **state) {
    (void)state;
    qt_fault_stats ls = qt_fault_loop("steady motions", steady_body, NULL, 2);
    assert_true(ls.allocs > 5);
}

/* ---- impulse ------------------------------------------------------------------ */

/* Desloge ch. 57 Ex. 1 (seed-desloge-A.md T55): the rhombus of four rods
 * hits an inelastic wall at al = 30 deg: th'+ = 3/7, x'+ = -3/7, the wall's
 * impulse 16 m/7, in numbers and in closed form.  Parsed with the failures
 * off; the solve (derivation, rows, saddle, theorems, closed form) fails. */
#define RHOMBUS                                                                                \
    "coordinates x, th\nparameters m = 1, a = 1, v = 1, al = pi/6\n"                         \
    "T = 2*m*x'^2 + 8/3*m*a^2*th'^2\nC = (x - 2*a*cos(th), 0, 0)\n"                         \
    "impact constraint wall: C.x = 0\nreaction wall on C\n"                                   \
    "initial x = 2*a*cos(al), th = al, x' = -v, th' = 0\n"

static qd_status impulse_body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)data;
    long armed = f->fail_at;
    f->fail_at = 0;
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, RHOMBUS, &d);
    assert_non_null(m);
    f->fail_at = f->count + armed;
    qd_impulse r;
    qd_impulse_opts o = {.exact = true};
    qd_status st = qd_impulse_solve(ctx, m, &o, &r);
    if (st == QD_OK) {
        assert_true(fabs(r.qd_after[1] - 3.0 / 7) < 1e-12);
        assert_true(fabs(r.mult[0] - 16.0 / 7) < 1e-12);
        assert_true(fabs(r.react[0][0] - 16.0 / 7) < 1e-12);
        assert_true(r.exact && r.carnot.holds);
        /* the closed form is in the parameters: at their values, 3/7 */
        env v = {0, {0}, {0}};
        double x = 0;
        for (size_t i = 0; i < qd_model_nparams(m) && st == QD_OK; i++) {
            v.syms[v.n] = qd_model_param(m, i);
            st = qd_eval(ctx, qd_model_param_value(m, i), 0, NULL, NULL, &v.vals[v.n++]);
        }
        if (st == QD_OK)
            st = qd_eval(ctx, r.qd_after_exact[1], v.n, v.syms, v.vals, &x);
        if (st == QD_OK)
            assert_true(fabs(x - 3.0 / 7) < 1e-12);
    }
    qd_impulse_free(&r);
    qd_model_free(m);
    return st;
}

static void test_impulse(void **state) {
    (void)state;
    qt_fault_stats ls = qt_fault_loop("impulse", impulse_body, NULL, 2); /* ~25 s under ASan at 1 */
    assert_true(ls.allocs > 10);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_derivation),
        cmocka_unit_test(test_constrained),
        cmocka_unit_test(test_simulation),
        cmocka_unit_test(test_modes),
        cmocka_unit_test(test_dof),
        cmocka_unit_test(test_heavy_top),
        cmocka_unit_test(test_steady),
        cmocka_unit_test(test_impulse),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
