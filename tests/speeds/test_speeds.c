/*
 * tests/speeds/test_speeds.c - the equations in generalized speeds
 * (qdot/speeds.h): textbook results of Desloge ch. 67-70 by each of the
 * three methods, and every model checked against Lagrange's equations with
 * multipliers (qd_eom) at random states: the speeds' rates must be the
 * derivative of their definitions along the same motion, and the recovered
 * multipliers qd_eom's.
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
#include "util/check.h"

static const qd_speeds_method METHODS[] = {QD_SPEEDS_KANE, QD_SPEEDS_APPELL, QD_SPEEDS_HAMEL};

static qd_speeds_eom *derive(qd_ctx *ctx, const qd_model *m, qd_speeds_method method,
                             bool appell, bool mult) {
    qd_speeds_opts o = {.method = method, .appell = appell, .multipliers = mult};
    qd_speeds_eom *e = qd_speeds_derive(ctx, m, &o);
    if (!e)
        fail_msg("%s: %s", qd_speeds_method_name(method), qd_ctx_message(ctx));
    return e;
}

/* ---- the kinematics invert the definitions ------------------------------- */

static void check_kinematics(qd_ctx *ctx, const qd_speeds_eom *e) {
    for (size_t r = 0; r < e->m; r++) {
        const qd_expr *back = qd_subs(ctx, e->def[r], e->n, e->qd, e->kin);
        const qd_expr *d = qd_simplify(ctx, qd_sub(ctx, back, e->u[r]));
        assert_non_null(d);
        assert_true(qd_is_zero(d) || qt_same_numeric(ctx, back, e->u[r], 0.3, 1.3, 4, 1e-12));
    }
}

/* ---- against Lagrange's equations with multipliers -----------------------
 * At a random state (q, u): q' from the kinematics, q'' and lambda from
 * qd_eom_eval; then u'_r must be d/dt of u_r's definition at (q, q', q''),
 * and the speeds' multipliers qd_eom's. */
typedef struct state {
    size_t ns;
    const qd_expr *syms[96];
    double vals[96];
} state;

static void put(state *s, const qd_expr *x, double v) {
    s->syms[s->ns] = x;
    s->vals[s->ns++] = v;
}

static void check_vs_lagrange(qd_ctx *ctx, const qd_model *m, const qd_speeds_eom *se,
                              unsigned seed) {
    qd_eom *e = qd_eom_derive(ctx, m);
    assert_non_null(e);
    srand(seed);
    for (int trial = 0; trial < 4; trial++) {
        state s = {0};
        for (size_t i = 0; i < qd_model_nparams(m); i++) {
            double x;
            assert_int_equal(qd_model_param_number(m, i, &x), QD_OK);
            put(&s, qd_model_param(m, i), x);
        }
        put(&s, qd_time(ctx), 0.4 + 0.3 * trial);
        for (size_t j = 0; j < se->n; j++)
            put(&s, se->q[j], 0.45 + 0.7 * (rand() / (double)RAND_MAX));
        for (size_t r = 0; r < se->m; r++)
            put(&s, se->u[r], -1 + 2 * (rand() / (double)RAND_MAX));
        double qd[16], ud[16], lam[16], qdd[16], lam_e[16];
        assert_int_equal(qd_speeds_eval(ctx, se, s.ns, s.syms, s.vals, qd, ud,
                                        se->mult ? lam : NULL), QD_OK);
        size_t base = s.ns;
        for (size_t j = 0; j < se->n; j++)
            put(&s, se->qd[j], qd[j]);
        assert_int_equal(qd_eom_eval(ctx, e, s.ns, s.syms, s.vals, NULL, NULL, qdd, lam_e, NULL),
                         QD_OK);
        for (size_t j = 0; j < se->n; j++)
            put(&s, e->qdd[j], qdd[j]);
        for (size_t r = 0; r < se->m; r++) {
            double want;
            assert_int_equal(qd_eval(ctx, qd_dt(ctx, se->def[r]), s.ns, s.syms, s.vals, &want),
                             QD_OK);
            if (fabs(ud[r] - want) > 1e-9 * (1 + fabs(want)))
                fail_msg("%s' = %.15g from the speeds, %.15g from Lagrange", qd_expr_name(se->u[r]),
                         ud[r], want);
        }
        for (size_t k = 0; se->mult && k < se->ncon; k++)
            if (fabs(lam[k] - lam_e[k]) > 1e-9 * (1 + fabs(lam_e[k])))
                fail_msg("lambda_%s = %.15g from the speeds, %.15g from Lagrange", se->con[k].name,
                         lam[k], lam_e[k]);
        (void)base;
    }
    qd_eom_free(e);
}

/* Every method on a model: the kinematics, Lagrange, and the methods'
 * M_u and f_u equal (simplified difference 0, else at random points). */
static void check_all_methods(const char *text, unsigned seed) {
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qt_parse_ok(ctx, text);
    qd_speeds_eom *e[3];
    for (int k = 0; k < 3; k++) {
        e[k] = derive(ctx, m, METHODS[k], false, qd_model_nconstraints(m) > 0);
        check_kinematics(ctx, e[k]);
        check_vs_lagrange(ctx, m, e[k], seed);
    }
    size_t nm = e[0]->m;
    for (int k = 1; k < 3; k++) {
        for (size_t i = 0; i < nm * nm + nm; i++) {
            const qd_expr *a = i < nm * nm ? e[0]->M[i] : e[0]->f[i - nm * nm];
            const qd_expr *b = i < nm * nm ? e[k]->M[i] : e[k]->f[i - nm * nm];
            const qd_expr *d = qd_simplify(ctx, qd_sub(ctx, a, b));
            if (!(d && qd_is_zero(d)) && !qt_same_numeric(ctx, a, b, 0.3, 1.3, 4, 1e-11))
                fail_msg("kane and %s differ in entry %zu", qd_speeds_method_name(METHODS[k]), i);
        }
    }
    for (int k = 0; k < 3; k++)
        qd_speeds_eom_free(e[k]);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* ---- Desloge ch. 68 Ex. 2 and ch. 70 thm 2: Euler's equations ------------ */

static const char euler_body[] =
    "coordinates phi, theta, psi\n"
    "parameters A = 1, B = 2, C = 3\n"
    "body b mass 1 inertia (A, B, C) at (0, 0, 0) orientation euler(phi, theta, psi)\n"
    "speeds w1 = omega(b).x, w2 = omega(b).y, w3 = omega(b).z\n";

static void test_euler_equations(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qt_parse_ok(ctx, euler_body);
    static const char *M[9] = {"A", "0", "0", "0", "B", "0", "0", "0", "C"};
    /* A w1' = (B - C) w2 w3 and cyclically (seed-desloge-C.md C13) */
    static const char *f[3] = {"(B - C)*w2*w3", "(C - A)*w3*w1", "(A - B)*w1*w2"};
    for (int k = 0; k < 3; k++) {
        qd_speeds_eom *e = derive(ctx, m, METHODS[k], true, false);
        assert_int_equal(e->n, 3);
        assert_int_equal(e->m, 3);
        for (int i = 0; i < 9; i++)
            qt_assert_is(ctx, e->M[i], M[i]);
        for (int r = 0; r < 3; r++)
            qt_assert_is(ctx, e->f[r], f[r]);
        /* S = 1/2 a.I a + a.(w x I w), terms free of w' dropped */
        qt_assert_is(ctx, e->S,
                     "(A*w1'^2 + B*w2'^2 + C*w3'^2)/2 + w1'*(C - B)*w2*w3 + w2'*(A - C)*w3*w1"
                     " + w3'*(B - A)*w1*w2");
        /* solved: w1' = (B - C) w2 w3 / A, ... */
        assert_int_equal(qd_speeds_solve(ctx, e, 2000), QD_OK);
        for (int r = 0; r < 3; r++) {
            char want[64];
            snprintf(want, sizeof want, "(%s)/%s", f[r], M[4 * r]);
            qt_assert_is(ctx, e->acc[r], want);
        }
        /* too small a limit keeps M and f */
        assert_int_equal(qd_speeds_solve(ctx, e, 2), QD_ERR_TOOBIG);
        qd_ctx_clear_error(ctx);
        /* the inverse of C13's map: theta' = w1 cos(psi) - w2 sin(psi) */
        qt_assert_is(ctx, e->kin[1], "w1*cos(psi) - w2*sin(psi)");
        check_kinematics(ctx, e);
        qd_speeds_eom_free(e);
    }
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* ---- Desloge ch. 68 Ex. 1 and ch. 69 Ex. 1: the areal velocity ----------- */

static const char areal[] =
    "coordinates r, th\n"
    "parameters m = 1\n"
    "functions F\n"
    "particle m at (r*cos(th), r*sin(th))\n"
    "Q[r] = F(r)\n"
    "speeds ur = r', A = r^2*th'/2\n";

static void test_areal_velocity(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qt_parse_ok(ctx, areal);
    for (int k = 0; k < 3; k++) {
        qd_speeds_eom *e = derive(ctx, m, METHODS[k], true, false);
        /* T1: m r'' - 4 m A^2/r^3 = F_r(r), A' = 0 (4 m A'/r^2 = 0) */
        qt_assert_is(ctx, e->M[0], "m");
        qt_assert_is(ctx, e->M[1], "0");
        qt_assert_is(ctx, e->M[3], "4*m/r^2");
        qt_assert_is(ctx, e->f[0], "4*m*A^2/r^3 + F(r)");
        qt_assert_is(ctx, e->f[1], "0");
        /* T3: S = m/2 r''^2 + 2 m A'^2/r^2 - 4 m A^2 r''/r^3 (+ 8 m A^4/r^6, dropped) */
        qt_assert_is(ctx, e->S, "m/2*ur'^2 + 2*m*A'^2/r^2 - 4*m*A^2*ur'/r^3");
        /* T*: m/2 r'^2 + 2 m A^2/r^2 */
        qt_assert_is(ctx, e->T, "m/2*ur^2 + 2*m*A^2/r^2");
        qd_speeds_eom_free(e);
    }
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* ---- Desloge ch. 70 Ex. 1: the sphere on the turntable -------------------- */

static const char turntable[] =
    "coordinates x, y, phi, theta, psi\n"
    "parameters m = 0.9, a = 0.25, Omega = 1.7\n"
    "body ball mass m inertia sphere(m, a) at (x, y, a) orientation euler(phi, theta, psi)\n"
    "constraint roll_x: x' - a*(theta'*sin(phi) - psi'*cos(phi)*sin(theta)) = -Omega*y\n"
    "constraint roll_y: y' + a*(theta'*cos(phi) + psi'*sin(phi)*sin(theta)) = Omega*x\n"
    "speeds vx = x', vy = y', wz = omega_space(ball).z\n";

static void test_sphere_turntable(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qt_parse_ok(ctx, turntable);
    for (int k = 0; k < 3; k++) {
        qd_speeds_eom *e = derive(ctx, m, METHODS[k], false, true);
        /* T5: x'' + w0 y' = 0, y'' - w0 x' = 0, wz' = 0, w0 = 2 Omega/7 for a solid sphere:
         * 7/5 m vx' = -2/5 Omega m vy */
        qt_assert_is(ctx, e->M[0], "7*m/5");
        qt_assert_is(ctx, e->f[0], "-2*Omega*m*vy/5");
        qt_assert_is(ctx, e->f[1], "2*Omega*m*vx/5");
        qt_assert_is(ctx, e->f[2], "0");
        const qd_expr *syms[] = {qd_model_param(m, 0), qd_model_param(m, 1), qd_model_param(m, 2),
                                 qd_lookup(ctx, "x"), qd_lookup(ctx, "y"), qd_lookup(ctx, "phi"),
                                 qd_lookup(ctx, "theta"), e->u[0], e->u[1], e->u[2]};
        double vals[] = {0.9, 0.25, 1.7, 0.3, -0.2, 0.4, 1.1, 0.7, -0.35, 2.0};
        double ud[3], lam[2], w0 = 2 * 1.7 / 7;
        assert_int_equal(qd_speeds_eval(ctx, e, 10, syms, vals, NULL, ud, lam), QD_OK);
        assert_true(fabs(ud[0] + w0 * -0.35) < 1e-13 && fabs(ud[1] - w0 * 0.7) < 1e-13);
        assert_true(fabs(ud[2]) < 1e-13);
        /* the table's friction is the only horizontal force: lambda = m r'' */
        assert_true(fabs(lam[0] - 0.9 * ud[0]) < 1e-13 && fabs(lam[1] - 0.9 * ud[1]) < 1e-13);
        qd_speeds_eom_free(e);
    }
    qd_model_free(m);
    qd_ctx_free(ctx);
    check_all_methods(turntable, 7);
}

/* ---- the rolling disk: 3 dynamic equations, no multipliers --------------- */

static const char disk[] =
    "coordinates x, y, z, phi, theta, psi\n"
    "parameters m = 1.4, a = 0.35, g = 9.81\n"
    "body disk mass m inertia disk(m, a) at (x, y, z) orientation euler(phi, theta, psi)\n"
    "V = m*g*z\n"
    "rolls disk on plane((0, 0, 1), (0, 0, 0)) as disk(a)\n"
    "speeds w1 = omega(disk).x, w2 = omega(disk).y, w3 = omega(disk).z\n";

static void test_rolling_disk(void **state) {
    (void)state;
    check_all_methods(disk, 11);
}

/* ---- the Chaplygin sleigh (T given directly: Appell from T's own terms) --
 * A blade at distance b ahead of the centre of mass along the body axis;
 * v the forward speed, w the yaw rate.  In the body frame the centre's
 * velocity is (v, -b w), so its acceleration is (v' + b w^2, v w - b w');
 * the blade's force is lateral, at +b: m (v' + b w^2) = 0 and
 * I w' = b m (v w - b w'), i.e. m v' = -m b w^2, (I + m b^2) w' = m b v w
 * (Chaplygin 1911; Bloch, Nonholonomic Mechanics, sec. 1.7, with his
 * contact point behind the centre: a = -b). */
static const char sleigh[] =
    "coordinates x, y, th\n"
    "parameters m = 2, I = 0.3, b = 0.4\n"
    "T = m/2*(x'^2 + y'^2) + I/2*th'^2\n"
    "constraint blade: -x'*sin(th) + y'*cos(th) + b*th' = 0\n"
    "speeds v = x'*cos(th) + y'*sin(th), w = th'\n";

static void test_chaplygin_sleigh(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qt_parse_ok(ctx, sleigh);
    for (int k = 0; k < 3; k++) {
        qd_speeds_eom *e = derive(ctx, m, METHODS[k], true, false);
        qt_assert_is(ctx, e->M[0], "m");
        qt_assert_is(ctx, e->M[1], "0");
        qt_assert_is(ctx, e->M[3], "I + m*b^2");
        qt_assert_is(ctx, e->f[0], "-m*b*w^2");
        qt_assert_is(ctx, e->f[1], "m*b*v*w");
        qt_assert_is(ctx, e->S, "m/2*v'^2 + (I + m*b^2)/2*w'^2 + m*b*w^2*v' - m*b*v*w*w'");
        qd_speeds_eom_free(e);
    }
    qd_model_free(m);
    qd_ctx_free(ctx);
    check_all_methods(sleigh, 3);
}

/* ---- a speed that is no coordinate's rate: u = r phi' -------------------- */

static const char rphi[] =
    "coordinates r, ph\n"
    "parameters m = 1.5, k = 2\n"
    "particle m at (r*cos(ph), r*sin(ph))\n"
    "V = k/2*r^2\n"
    "speeds ur = r', uph = r*ph'\n";

static void test_nonintegrable_speed(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qt_parse_ok(ctx, rphi);
    for (int k = 0; k < 3; k++) {
        qd_speeds_eom *e = derive(ctx, m, METHODS[k], false, false);
        /* the polar components of the acceleration: r'' - r ph'^2, r ph'' + 2 r' ph' */
        qt_assert_is(ctx, e->M[0], "m");
        qt_assert_is(ctx, e->M[3], "m");
        qt_assert_is(ctx, e->f[0], "m*uph^2/r - k*r");
        qt_assert_is(ctx, e->f[1], "-m*ur*uph/r");
        qd_speeds_eom_free(e);
    }
    qd_model_free(m);
    qd_ctx_free(ctx);
    check_all_methods(rphi, 5);
}

/* ---- rheonomic and affine speeds, L given, dissipation ------------------- */

static void test_affine_rheonomic(void **state) {
    (void)state;
    /* velocities relative to a frame turning at Omega, a time-dependent
     * spring constant and drag: b(q, t) != 0 in the speeds */
    check_all_methods("coordinates x, y\n"
                      "parameters m = 1.2, k = 3, Omega = 0.7, c = 0.1\n"
                      "particle m at (x, y)\n"
                      "V = k*(1 + t/3)/2*(x^2 + y^2)\n"
                      "dissipation = c/2*(x'^2 + y'^2)\n"
                      "speeds u1 = x' + Omega*y, u2 = y' - Omega*x*cos(t)\n",
                      13);
    /* L given: Appell's S from L's own Lagrange expression */
    check_all_methods("coordinates r, th\n"
                      "parameters m = 1, k = 2\n"
                      "L = m/2*(r'^2 + r^2*th'^2) + k/r\n"
                      "speeds ur = r', h = r^2*th'\n",
                      17);
}

/* ---- errors ---------------------------------------------------------------- */

static void expect_error(const char *text, qd_subject subject, size_t index, size_t line) {
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qt_parse_ok(ctx, text);
    assert_null(qd_speeds_derive(ctx, m, NULL));
    const qd_diag *d = qd_ctx_diag(ctx);
    if (d->status != QD_ERR_SINGULAR || d->subject != subject || d->index != index)
        fail_msg("%s: %s (subject %d index %zu)", text, d->message, (int)d->subject, d->index);
    assert_int_equal(d->reason, QD_REASON_DEPENDENT_SPEEDS);
    assert_int_equal(d->subject, subject);
    assert_int_equal(d->index, index);
    qd_diag where = *d;
    assert_true(qd_model_locate(m, &where));
    assert_int_equal(where.line, line);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

static void test_errors(void **state) {
    (void)state;
    /* a speed that repeats another */
    expect_error("coordinates x, y\nparticle 1 at (x, y)\nspeeds u1 = x', u2 = 2*x'\n",
                 QD_SUBJECT_SPEED, 1, 3);
    /* a speed that repeats a constraint (the blade's own rate) */
    expect_error("coordinates x, y, th\nT = (x'^2 + y'^2 + th'^2)/2\n"
                 "constraint blade: -x'*sin(th) + y'*cos(th) = 0\n"
                 "speeds v = -x'*sin(th) + y'*cos(th), w = th'\n",
                 QD_SUBJECT_CONSTRAINT, 0, 3);
    /* too few speeds for the coordinates left free */
    expect_error("coordinates x, y\nparticle 1 at (x, y)\nspeeds u1 = x'\n", QD_SUBJECT_SPEED, 0,
                 3);
    /* a model without speeds */
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qt_parse_ok(ctx, "coordinates x\nparticle 1 at (x, 0)\n");
    assert_null(qd_speeds_derive(ctx, m, NULL));
    assert_int_equal(qd_ctx_status(ctx), QD_ERR_ARG);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

static void test_method_names(void **state) {
    (void)state;
    qd_speeds_method m;
    for (int k = 0; k < QD_SPEEDS_METHOD_COUNT; k++) {
        assert_true(qd_speeds_method_from_name(qd_speeds_method_name((qd_speeds_method)k), &m));
        assert_int_equal(m, k);
    }
    assert_false(qd_speeds_method_from_name("lagrange", &m));
    assert_null(qd_speeds_method_name(QD_SPEEDS_METHOD_COUNT));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_euler_equations),   cmocka_unit_test(test_areal_velocity),
        cmocka_unit_test(test_sphere_turntable),  cmocka_unit_test(test_rolling_disk),
        cmocka_unit_test(test_chaplygin_sleigh),  cmocka_unit_test(test_nonintegrable_speed),
        cmocka_unit_test(test_affine_rheonomic),  cmocka_unit_test(test_errors),
        cmocka_unit_test(test_method_names),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
