/*
 * tests/mech/test_lagrange.c - Lagrange's equations M q'' = f of textbook
 * systems against their closed forms (Goldstein, Classical Mechanics, 3rd
 * ed., ch. 1-2; Taylor, Classical Mechanics, ch. 7), at random states.
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
#include "qdot/mech.h"
#include "qdot/model.h"
#include "util/randexpr.h"
#include "util/system.h"

#define SEED 20240612u
#define NSTATES 20
#define MAXSYM 64

typedef qt_system fixture;

static int teardown(void **state) { return qt_system_teardown(state); }

/* Parse and derive; the fixture is torn down by the test's teardown. */
static fixture *derive(void **state, const char *text) { return qt_system_derive(state, text, false); }

static const qd_expr *S(fixture *fx, const char *name) { return qt_symbol(fx, name); }

static bool close_to(double a, double b) { return fabs(a - b) <= 1e-9 * (1 + fabs(a) + fabs(b)); }

/* A random state: every symbol of M and f (and more) at syms/vals. */
typedef struct pt {
    size_t n;
    const qd_expr *syms[MAXSYM];
    double vals[MAXSYM];
} pt;

static void set(pt *s, const qd_expr *sym, double v) {
    s->syms[s->n] = sym;
    s->vals[s->n++] = v;
}

static double get(const pt *s, const qd_expr *sym) {
    for (size_t i = 0; i < s->n; i++)
        if (s->syms[i] == sym)
            return s->vals[i];
    fail_msg("symbol %s not in the state", qd_expr_name(sym));
    return 0;
}

/* Coordinates and velocities in [-2, 2], parameters in [0.5, 2], t. */
static void random_state(fixture *fx, qt_rng *r, pt *s) {
    s->n = 0;
    for (size_t j = 0; j < qd_model_ncoords(fx->model); j++) {
        const qd_expr *q = qd_model_coord(fx->model, j);
        set(s, q, qt_uniform(r, -2, 2));
        set(s, qd_jet(fx->ctx, q, 1), qt_uniform(r, -2, 2));
    }
    for (size_t i = 0; i < qd_model_nparams(fx->model); i++)
        set(s, qd_model_param(fx->model, i), qt_uniform(r, 0.5, 2));
    set(s, qd_time(fx->ctx), qt_uniform(r, -2, 2));
}

static double value(fixture *fx, const pt *s, const qd_expr *e) {
    double v;
    qd_status st = qd_eval(fx->ctx, e, s->n, s->syms, s->vals, &v);
    if (st != QD_OK)
        fail_msg("eval: %s", qd_ctx_message(fx->ctx));
    return v;
}

/* Are a and b equal at NSTATES random states? */
static void assert_same(fixture *fx, const qd_expr *a, const qd_expr *b, const char *what) {
    qt_rng r = {SEED};
    pt s;
    for (int k = 0; k < NSTATES; k++) {
        random_state(fx, &r, &s);
        double x = value(fx, &s, a), y = value(fx, &s, b);
        if (!close_to(x, y))
            fail_msg("%s: %.17g != %.17g (state %d, seed %u)", what, x, y, k, SEED);
    }
}

/* ---- one degree of freedom ---------------------------------------------- */

static const char *pendulum = "coordinates theta\n"
                              "parameters m = 1, l = 1, g = 9.81\n"
                              "x = l*sin(theta)\n"
                              "y = -l*cos(theta)\n"
                              "T = m/2*(x'^2 + y'^2)\n"
                              "V = m*g*y\n";

/* Goldstein 1.4: m l^2 theta'' = -m g l sin(theta). */
static void test_pendulum(void **state) {
    fixture *fx = derive(state, pendulum);
    qd_ctx *c = fx->ctx;
    const qd_expr *m = S(fx, "m"), *l = S(fx, "l"), *g = S(fx, "g"), *th = S(fx, "theta");
    assert_int_equal(fx->eom->n, 1);
    assert_ptr_equal(fx->eom->M[0], qd_mul(c, m, qd_powi(c, l, 2)));
    const qd_expr *f =
        qd_neg(c, qd_mul_n(c, 4, (const qd_expr *[]){m, g, l, qd_fn(c, QD_SIN, th)}));
    assert_same(fx, fx->eom->f[0], f, "f");
    assert_ptr_equal(fx->eom->f[0], f);
    /* scleronomic: T = T2 = m l^2 theta'^2 / 2 */
    assert_true(qd_is_zero(fx->eom->T1) && qd_is_zero(fx->eom->T0));
    const qd_expr *thd = qd_jet(c, th, 1);
    assert_same(
        fx, fx->eom->T2,
        qd_mul_n(c, 3, (const qd_expr *[]){qd_rat(c, 1, 2), fx->eom->M[0], qd_powi(c, thd, 2)}),
        "T2");
    assert_int_equal(qd_eom_solve(c, fx->eom, 100), QD_OK);
    assert_same(fx, fx->eom->acc[0], qd_div(c, f, fx->eom->M[0]), "theta''");
}

/* Goldstein 1.4 (Atwood's machine): (m1 + m2) x'' = (m1 - m2) g. */
static void test_atwood(void **state) {
    fixture *fx = derive(state, "coordinates x\n"
                                "parameters m1 = 2, m2 = 1, g = 9.81, l = 3\n"
                                "T = (m1 + m2)/2*x'^2\n"
                                "V = -m1*g*x - m2*g*(l - x)\n");
    qd_ctx *c = fx->ctx;
    const qd_expr *m1 = S(fx, "m1"), *m2 = S(fx, "m2"), *g = S(fx, "g");
    assert_ptr_equal(fx->eom->M[0], qd_add(c, m1, m2));
    assert_same(fx, fx->eom->f[0], qd_mul(c, qd_sub(c, m1, m2), g), "f");
    assert_false(qd_has(fx->eom->f[0], S(fx, "l")));
}

/* Taylor 7.6 (bead on a wire turning at omega): T0 = m omega^2 r^2 / 2,
 * T1 = 0, r'' = omega^2 r. */
static void test_rotating_wire(void **state) {
    fixture *fx = derive(state, "coordinates r\n"
                                "parameters m = 1, omega = 2\n"
                                "x = r*cos(omega*t)\n"
                                "y = r*sin(omega*t)\n"
                                "T = m/2*(x'^2 + y'^2)\n"
                                "V = 0\n");
    qd_ctx *c = fx->ctx;
    const qd_expr *m = S(fx, "m"), *w = S(fx, "omega"), *r = S(fx, "r");
    const qd_expr *half_m = qd_mul(c, qd_rat(c, 1, 2), m);
    assert_ptr_equal(fx->eom->M[0], m);
    assert_true(qd_is_zero(fx->eom->T1));
    assert_false(qd_is_zero(fx->eom->T0));
    assert_same(fx, fx->eom->T0,
                qd_mul_n(c, 3, (const qd_expr *[]){half_m, qd_powi(c, w, 2), qd_powi(c, r, 2)}),
                "T0");
    assert_same(fx, fx->eom->T2, qd_mul(c, half_m, qd_powi(c, qd_jet(c, r, 1), 2)), "T2");
    assert_same(fx, fx->eom->f[0], qd_mul_n(c, 3, (const qd_expr *[]){m, qd_powi(c, w, 2), r}),
                "f");
    assert_false(qd_has(fx->eom->f[0], qd_time(c)));
}

/* Taylor 5.4 with Rayleigh's function D = c theta'^2 / 2: the damping
 * force -c theta' joins f. */
static void test_damped_pendulum(void **state) {
    fixture *fx = derive(state, "coordinates theta\n"
                                "parameters m = 1, l = 1, g = 9.81, c = 0.5\n"
                                "x = l*sin(theta)\n"
                                "y = -l*cos(theta)\n"
                                "T = m/2*(x'^2 + y'^2)\n"
                                "V = m*g*y\n"
                                "dissipation = c/2*theta'^2\n");
    qd_ctx *c = fx->ctx;
    const qd_expr *m = S(fx, "m"), *l = S(fx, "l"), *g = S(fx, "g"), *th = S(fx, "theta");
    const qd_expr *f =
        qd_neg(c, qd_mul_n(c, 4, (const qd_expr *[]){m, g, l, qd_fn(c, QD_SIN, th)}));
    f = qd_sub(c, f, qd_mul(c, S(fx, "c"), qd_jet(c, th, 1)));
    assert_same(fx, fx->eom->f[0], f, "f");
}

/* A free particle seen from a frame turning at w (Goldstein 4.10): T1 =
 * m w (X Y' - Y X'), T0 = m w^2 (X^2 + Y^2)/2, and the Coriolis and
 * centrifugal forces m X'' = 2 m w Y' + m w^2 X, m Y'' = -2 m w X' + m w^2 Y. */
static void test_rotating_frame(void **state) {
    fixture *fx = derive(state, "coordinates X, Y\n"
                                "parameters m = 1, w = 1\n"
                                "x = X*cos(w*t) - Y*sin(w*t)\n"
                                "y = X*sin(w*t) + Y*cos(w*t)\n"
                                "T = m/2*(x'^2 + y'^2)\n");
    qd_ctx *c = fx->ctx;
    const qd_expr *m = S(fx, "m"), *w = S(fx, "w"), *X = S(fx, "X"), *Y = S(fx, "Y");
    const qd_expr *Xd = qd_jet(c, X, 1), *Yd = qd_jet(c, Y, 1), *mw = qd_mul(c, m, w);
    const qd_expr *mw2 = qd_mul(c, mw, w), *two = qd_int(c, 2);
    assert_ptr_equal(fx->eom->M[0], m);
    assert_true(qd_is_zero(fx->eom->M[1]));
    assert_same(fx, fx->eom->T1, qd_mul(c, mw, qd_sub(c, qd_mul(c, X, Yd), qd_mul(c, Y, Xd))),
                "T1");
    assert_same(fx, fx->eom->T0,
                qd_mul_n(c, 3,
                         (const qd_expr *[]){qd_rat(c, 1, 2), mw2,
                                             qd_add(c, qd_powi(c, X, 2), qd_powi(c, Y, 2))}),
                "T0");
    assert_same(fx, fx->eom->f[0],
                qd_add(c, qd_mul_n(c, 3, (const qd_expr *[]){two, mw, Yd}), qd_mul(c, mw2, X)),
                "f1");
    assert_same(fx, fx->eom->f[1],
                qd_sub(c, qd_mul(c, mw2, Y), qd_mul_n(c, 3, (const qd_expr *[]){two, mw, Xd})),
                "f2");
}

/* A charge in a uniform field B along z through U = -e dot(A, r'), A = B/2
 * (-y, x): m x'' = e B y', m y'' = -e B x' (Goldstein 1.5). */
static void test_magnetic_potential(void **state) {
    fixture *fx = derive(state, "coordinates x, y\n"
                                "parameters m = 1, e = 1, B = 1\n"
                                "T = m/2*(x'^2 + y'^2)\n"
                                "U = -e*B/2*(x*y' - y*x')\n");
    qd_ctx *c = fx->ctx;
    const qd_expr *eB = qd_mul(c, S(fx, "e"), S(fx, "B"));
    assert_ptr_equal(fx->eom->M[0], S(fx, "m"));
    assert_ptr_equal(fx->eom->f[0], qd_mul(c, eB, qd_jet(c, S(fx, "y"), 1)));
    assert_ptr_equal(fx->eom->f[1], qd_neg(c, qd_mul(c, eB, qd_jet(c, S(fx, "x"), 1))));
}

/* L given without T: no split; a total derivative k x x' changes nothing. */
static void test_lagrangian_given(void **state) {
    fixture *fx = derive(state, "coordinates x\n"
                                "parameters m = 1, k = 1, a = 1\n"
                                "L = m/2*x'^2 - k/2*x^2 + a*x*x'\n");
    qd_ctx *c = fx->ctx;
    assert_null(fx->eom->T2);
    assert_ptr_equal(fx->eom->M[0], S(fx, "m"));
    assert_ptr_equal(fx->eom->f[0], qd_neg(c, qd_mul(c, S(fx, "k"), S(fx, "x"))));
}

/* ---- the double pendulum -------------------------------------------------- */

static const char *double_pendulum = "# Double pendulum\n"
                                     "coordinates theta1, theta2\n"
                                     "parameters m1 = 1, m2 = 1, l1 = 1, l2 = 1, g = 9.81\n"
                                     "\n"
                                     "x1 = l1*sin(theta1)\n"
                                     "y1 = -l1*cos(theta1)\n"
                                     "x2 = x1 + l2*sin(theta2)\n"
                                     "y2 = y1 - l2*cos(theta2)\n"
                                     "\n"
                                     "T = m1/2*(x1'^2 + y1'^2) + m2/2*(x2'^2 + y2'^2)\n"
                                     "V = m1*g*y1 + m2*g*y2\n"
                                     "\n"
                                     "initial theta1 = 0.5, theta2 = 0, theta1' = 0, theta2' = 0\n";

/* Goldstein's closed form of M and f. */
static void textbook(fixture *fx, const pt *s, double *M, double *f) {
    double m1 = get(s, S(fx, "m1")), m2 = get(s, S(fx, "m2")), l1 = get(s, S(fx, "l1"));
    double l2 = get(s, S(fx, "l2")), g = get(s, S(fx, "g"));
    double t1 = get(s, S(fx, "theta1")), t2 = get(s, S(fx, "theta2"));
    double w1 = get(s, S(fx, "theta1'")), w2 = get(s, S(fx, "theta2'"));
    M[0] = (m1 + m2) * l1 * l1;
    M[1] = M[2] = m2 * l1 * l2 * cos(t1 - t2);
    M[3] = m2 * l2 * l2;
    f[0] = -m2 * l1 * l2 * w2 * w2 * sin(t1 - t2) - (m1 + m2) * g * l1 * sin(t1);
    f[1] = m2 * l1 * l2 * w1 * w1 * sin(t1 - t2) - m2 * g * l2 * sin(t2);
}

static void test_double_pendulum(void **state) {
    fixture *fx = derive(state, double_pendulum);
    qd_ctx *c = fx->ctx;
    qt_rng r = {SEED};
    pt s;
    for (int k = 0; k < NSTATES; k++) {
        double M[4], f[2], qdd[2], Mt[4], ft[2];
        random_state(fx, &r, &s);
        assert_int_equal(qd_eom_eval(c, fx->eom, s.n, s.syms, s.vals, M, f, qdd, NULL, NULL), QD_OK);
        textbook(fx, &s, Mt, ft);
        for (int i = 0; i < 4; i++)
            if (!close_to(M[i], Mt[i]))
                fail_msg("M[%d] = %.17g, textbook %.17g (state %d)", i, M[i], Mt[i], k);
        for (int i = 0; i < 2; i++)
            if (!close_to(f[i], ft[i]))
                fail_msg("f[%d] = %.17g, textbook %.17g (state %d)", i, f[i], ft[i], k);
        /* the accelerations solve M q'' = f */
        for (int i = 0; i < 2; i++)
            assert_true(close_to(M[2 * i] * qdd[0] + M[2 * i + 1] * qdd[1], f[i]));
    }
    const qd_expr *t1 = S(fx, "theta1"), *t2 = S(fx, "theta2");
    const qd_expr *cos12 = qd_fn(c, QD_COS, qd_sub(c, t1, t2));
    const qd_expr *m12 =
        qd_mul_n(c, 4, (const qd_expr *[]){S(fx, "m2"), S(fx, "l1"), S(fx, "l2"), cos12});
    assert_ptr_equal(fx->eom->M[1], m12);
    assert_ptr_equal(fx->eom->M[2], m12);
}

/* The planar chain of n links (masses m_i at the ends of lengths l_i):
 * with S_i = m_i + ... + m_n, M_jk = S_max(j,k) l_j l_k cos(th_j - th_k) and
 * f_j = -sum_k S_max(j,k) l_j l_k sin(th_j - th_k) th_k'^2 - g S_j l_j sin th_j. */
static void chain_text(char *buf, size_t cap, int n) {
    size_t o = (size_t)snprintf(buf, cap, "coordinates th1");
    for (int i = 2; i <= n; i++)
        o += (size_t)snprintf(buf + o, cap - o, ", th%d", i);
    o += (size_t)snprintf(buf + o, cap - o, "\nparameters g = 9.81");
    for (int i = 1; i <= n; i++)
        o += (size_t)snprintf(buf + o, cap - o, ", m%d = 1, l%d = 1", i, i);
    o += (size_t)snprintf(buf + o, cap - o, "\nx0 = 0\ny0 = 0\n");
    for (int i = 1; i <= n; i++)
        o += (size_t)snprintf(buf + o, cap - o,
                              "x%d = x%d + l%d*sin(th%d)\ny%d = y%d - l%d*cos(th%d)\n", i, i - 1, i,
                              i, i, i - 1, i, i);
    o += (size_t)snprintf(buf + o, cap - o, "T = 0");
    for (int i = 1; i <= n; i++)
        o += (size_t)snprintf(buf + o, cap - o, " + m%d/2*(x%d'^2 + y%d'^2)", i, i, i);
    o += (size_t)snprintf(buf + o, cap - o, "\nV = 0");
    for (int i = 1; i <= n; i++)
        o += (size_t)snprintf(buf + o, cap - o, " + m%d*g*y%d", i, i);
    snprintf(buf + o, cap - o, "\n");
}

static double sym_val(fixture *fx, const pt *s, const char *fmt, int i) {
    char name[32];
    snprintf(name, sizeof name, fmt, i);
    return get(s, S(fx, name));
}

static void chain_textbook(fixture *fx, const pt *s, int n, double *M, double *f) {
    double sum[17] = {0}, l[17], th[17], w[17], g = get(s, S(fx, "g"));
    for (int i = n; i >= 1; i--) {
        sum[i] = (i < n ? sum[i + 1] : 0) + sym_val(fx, s, "m%d", i);
        l[i] = sym_val(fx, s, "l%d", i);
        th[i] = sym_val(fx, s, "th%d", i);
        w[i] = sym_val(fx, s, "th%d'", i);
    }
    for (int j = 1; j <= n; j++) {
        f[j - 1] = -g * sum[j] * l[j] * sin(th[j]);
        for (int k = 1; k <= n; k++) {
            double Sjk = sum[j > k ? j : k] * l[j] * l[k];
            M[(j - 1) * n + k - 1] = Sjk * cos(th[j] - th[k]);
            f[j - 1] -= Sjk * sin(th[j] - th[k]) * w[k] * w[k];
        }
    }
}

static void test_chain(void **state) {
    enum { N = 5 };
    char text[4096];
    chain_text(text, sizeof text, N);
    fixture *fx = derive(state, text);
    qt_rng r = {SEED + 2};
    pt s;
    for (int k = 0; k < NSTATES; k++) {
        double M[N * N], f[N], Mt[N * N], ft[N];
        random_state(fx, &r, &s);
        assert_int_equal(qd_eom_eval(fx->ctx, fx->eom, s.n, s.syms, s.vals, M, f, NULL, NULL, NULL), QD_OK);
        chain_textbook(fx, &s, N, Mt, ft);
        for (int i = 0; i < N * N; i++)
            if (!close_to(M[i], Mt[i]))
                fail_msg("M[%d] = %.17g, textbook %.17g (state %d)", i, M[i], Mt[i], k);
        for (int i = 0; i < N; i++)
            if (!close_to(f[i], ft[i]))
                fail_msg("f[%d] = %.17g, textbook %.17g (state %d)", i, f[i], ft[i], k);
    }
}

/* Symbolic accelerations agree with the numeric solution. */
static void test_double_pendulum_solve(void **state) {
    fixture *fx = derive(state, double_pendulum);
    qd_ctx *c = fx->ctx;
    assert_int_equal(qd_eom_solve(c, fx->eom, 400), QD_OK);
    qt_rng r = {SEED + 1};
    pt s;
    for (int k = 0; k < NSTATES; k++) {
        double qdd[2];
        random_state(fx, &r, &s);
        assert_int_equal(qd_eom_eval(c, fx->eom, s.n, s.syms, s.vals, NULL, NULL, qdd, NULL, NULL), QD_OK);
        for (int i = 0; i < 2; i++) {
            double a = value(fx, &s, fx->eom->acc[i]);
            if (!close_to(a, qdd[i]))
                fail_msg("q''[%d]: symbolic %.17g, numeric %.17g (state %d)", i, a, qdd[i], k);
        }
    }
    /* a limit too small to hold them */
    assert_int_equal(qd_eom_solve(c, fx->eom, 5), QD_ERR_TOOBIG);
    qd_ctx_clear_error(c);
    /* no limit: SIZE_MAX once overflowed the intermediate limit to a tiny one */
    assert_int_equal(qd_eom_solve(c, fx->eom, SIZE_MAX), QD_OK);
}

/* Symbols left out of the state are 0: theta1 = theta2 = 0 at rest. */
static void test_eval_defaults(void **state) {
    fixture *fx = derive(state, double_pendulum);
    const qd_expr *syms[] = {S(fx, "m1"), S(fx, "m2"), S(fx, "l1"), S(fx, "l2"), S(fx, "g")};
    double vals[] = {1, 2, 3, 4, 9.81}, M[4], f[2], qdd[2];
    assert_int_equal(qd_eom_eval(fx->ctx, fx->eom, 5, syms, vals, M, f, qdd, NULL, NULL), QD_OK);
    assert_true(close_to(M[0], 27) && close_to(M[1], 24) && close_to(M[3], 32));
    assert_true(f[0] == 0 && f[1] == 0 && qdd[0] == 0 && qdd[1] == 0);
}

/* ---- what cannot be solved --------------------------------------------------- */

static void expect_error(void **state, const char *text, qd_status st, const char *needle) {
    fixture *fx = qt_system_parse(state, text);
    fx->eom = qd_eom_derive(fx->ctx, fx->model);
    assert_null(fx->eom);
    assert_int_equal(qd_ctx_status(fx->ctx), st);
    if (!strstr(qd_ctx_message(fx->ctx), needle))
        fail_msg("message \"%s\" does not name %s", qd_ctx_message(fx->ctx), needle);
}

static void test_singular_row(void **state) {
    expect_error(state,
                 "coordinates x, theta2\nparameters m = 1, k = 1\n"
                 "T = m/2*x'^2\nV = k/2*(x^2 + theta2^2)\n",
                 QD_ERR_SINGULAR, "theta2'");
}

/* Only x' + y' is in T: neither acceleration is determined. */
static void test_singular_combination(void **state) {
    expect_error(state, "coordinates x, y\nparameters m = 1\nT = m/2*(x' + y')^2\n",
                 QD_ERR_SINGULAR, "x'', y''");
}

static void test_nonpolynomial_kinetic(void **state) {
    expect_error(state, "coordinates x\nparameters m = 1\nT = m*cosh(x')\n", QD_ERR_NONLINEAR,
                 "x'");
}

/* M = x^2 is singular only at x = 0: derivable, singular at that state. */
static void test_singular_state(void **state) {
    fixture *fx = derive(state, "coordinates x\nT = x^2*x'^2/2\nV = x^2/2\n");
    const qd_expr *x = S(fx, "x");
    double one = 1, zero = 0, qdd;
    assert_int_equal(qd_eom_eval(fx->ctx, fx->eom, 1, &x, &one, NULL, NULL, &qdd, NULL, NULL), QD_OK);
    assert_true(close_to(qdd, -1)); /* x^2 x'' + x x'^2 = -x */
    assert_int_equal(qd_eom_eval(fx->ctx, fx->eom, 1, &x, &zero, NULL, NULL, &qdd, NULL, NULL),
                     QD_ERR_SINGULAR);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(test_pendulum, teardown),
        cmocka_unit_test_teardown(test_atwood, teardown),
        cmocka_unit_test_teardown(test_rotating_wire, teardown),
        cmocka_unit_test_teardown(test_damped_pendulum, teardown),
        cmocka_unit_test_teardown(test_rotating_frame, teardown),
        cmocka_unit_test_teardown(test_magnetic_potential, teardown),
        cmocka_unit_test_teardown(test_lagrangian_given, teardown),
        cmocka_unit_test_teardown(test_double_pendulum, teardown),
        cmocka_unit_test_teardown(test_double_pendulum_solve, teardown),
        cmocka_unit_test_teardown(test_chain, teardown),
        cmocka_unit_test_teardown(test_eval_defaults, teardown),
        cmocka_unit_test_teardown(test_singular_row, teardown),
        cmocka_unit_test_teardown(test_singular_combination, teardown),
        cmocka_unit_test_teardown(test_nonpolynomial_kinetic, teardown),
        cmocka_unit_test_teardown(test_singular_state, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
