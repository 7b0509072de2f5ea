/*
 * tests/mech/test_redundant.c - dependent constraints (issue 33): redundant
 * but consistent ones are left out by rank (named in qd_eom.reduced), only
 * inconsistent ones are refused, with a witness.
 *
 *   A disk of radius a rolling on the plane z = 0, its axle (length L)
 *   pivoted at a fixed ball joint at height h: the material contact point
 *   moves perpendicular to its arm from the pivot, so the two rolling rows
 *   and the contact's velocity form are dependent at every state.  The same
 *   system written with independent constraints (the contact, and rolling
 *   along the circle the contact describes, radius R = L sin(th) + a cos(th))
 *   has the same accelerations, and the degrees of freedom agree: 1
 *   configurational, 1 motional (Desloge ch. 49: the contact fixes th, the
 *   rolling ties psi to ph).  Steady motion: th = const forces uniform
 *   precession ph'' = 0 with spin psi' = -(R/a) ph' (the edge mill / rolling
 *   cone: T is a constant times ph'^2 and V is constant; Goldstein, Poole,
 *   Safko ch. 1 Derivation 5 for the rolling condition, seed 002).
 *   Two ropes x1 + x2 = l written twice: the Atwood machine, with or
 *   without --eliminate, x1'' = (m1 - m2) g/(m1 + m2) (Goldstein sec. 1.6).
 *   Inconsistent pairs: x1 + x2 = l and 2 x1 + 2 x2 = 2 l + 1 (no
 *   configuration), x' + y' = 0 and 2 x' + 2 y' = 1 (no velocity).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/mech.h"
#include "qdot/model.h"
#include "util/system.h"

static int teardown(void **state) { return qt_system_teardown(state); }

#define AXLE_HEAD                                                                                \
    "coordinates ph, th, psi\n"                                                                  \
    "parameters m = 1.3, a = 0.3, L = 1, g = 9.81, h = 0.5\n"                                    \
    "body disk mass m inertia disk(m, a) at (L*sin(th)*sin(ph), -L*sin(th)*cos(ph), "            \
    "h + L*cos(th)) orientation euler(ph, th, psi)\n"                                            \
    "V = m*g*(h + L*cos(th))\n"

static const char *axle_rolls = AXLE_HEAD "rolls disk on plane((0, 0, 1), (0, 0, 0)) as disk(a)\n";
static const char *axle_hand = AXLE_HEAD "constraint contact: h + L*cos(th) - a*sin(th) = 0\n"
                                         "constraint roll: (L*sin(th) + a*cos(th))*ph' + a*psi' = 0\n";

/* qdd of e at (ph, th, 0, w, 0, psi') with the model's parameters. */
static void accel(qt_system *s, double ph, double th, double w, double psid, double *qdd) {
    static const char *names[] = {"ph", "th", "psi", "ph'", "th'", "psi'",
                                  "m",  "a",  "L",   "g",   "h"};
    double vals[] = {ph, th, 0.4, w, 0, psid, 1.3, 0.3, 1, 9.81, 0.5};
    const qd_expr *syms[11];
    for (size_t i = 0; i < 11; i++)
        syms[i] = qt_symbol(s, names[i]);
    if (qd_eom_eval(s->ctx, s->eom, 11, syms, vals, NULL, NULL, qdd, NULL, NULL) != QD_OK)
        fail_msg("eval: %s", qd_ctx_message(s->ctx));
}

static void test_axle(void **state) {
    qt_system *r = qt_system_derive(state, axle_rolls, false);
    assert_int_equal(r->eom->nreduced, 1);
    assert_int_equal(r->eom->ncon, 2);
    qd_dof d;
    assert_int_equal(qd_eom_dof(r->ctx, r->eom, &d), QD_OK);
    assert_int_equal(d.configurational, 1);
    assert_int_equal(d.motional, 1);
    double rolls[8][3];
    /* th on the contact: h + L cos(th) = a sin(th) */
    double th = acos(-0.5 / sqrt(1 + 0.09)) - atan(0.3), R = sin(th) + 0.3 * cos(th);
    assert_true(fabs(0.5 + cos(th) - 0.3 * sin(th)) < 1e-14);
    for (int k = 0; k < 8; k++) {
        double ph = 0.7 * k - 2, w = 0.3 + 0.4 * k;
        accel(r, ph, th, w, -R / 0.3 * w, rolls[k]);
        for (int j = 0; j < 3; j++) /* uniform precession */
            if (!(fabs(rolls[k][j]) < 1e-9 * (1 + w * w)))
                fail_msg("q''[%d] = %g at ph = %g, ph' = %g", j, rolls[k][j], ph, w);
    }
    qt_system_teardown(state);
    qt_system *hand = qt_system_derive(state, axle_hand, false);
    assert_int_equal(hand->eom->nreduced, 0);
    assert_int_equal(qd_eom_dof(hand->ctx, hand->eom, &d), QD_OK);
    assert_int_equal(d.configurational, 1);
    assert_int_equal(d.motional, 1);
    for (int k = 0; k < 8; k++) { /* the same accelerations */
        double qdd[3];
        accel(hand, 0.7 * k - 2, th, 0.3 + 0.4 * k, -R / 0.3 * (0.3 + 0.4 * k), qdd);
        for (int j = 0; j < 3; j++)
            assert_true(fabs(qdd[j] - rolls[k][j]) < 1e-9 * (1 + fabs(qdd[j])));
    }
}

static const char *ropes = "coordinates x1, x2\n"
                           "parameters m1 = 2, m2 = 1, g = 9.81, l = 5\n"
                           "T = m1/2*x1'^2 + m2/2*x2'^2\n"
                           "V = -m1*g*x1 - m2*g*x2\n"
                           "constraint rope: x1 + x2 = l\n"
                           "constraint rope2: 2*x1 + 2*x2 = 2*l%s\n";

static void atwood(void **state, bool eliminate) {
    char text[512];
    snprintf(text, sizeof text, ropes, "");
    qt_system *s = qt_system_derive(state, text, eliminate);
    assert_int_equal(s->eom->nreduced, 1);
    assert_string_equal(s->eom->reduced[0], eliminate ? "rope2" : "rope");
    const char *names[] = {"x1", "x2", "m1", "m2", "g", "l"};
    double vals[] = {2, 3, 2, 1, 9.81, 5}, qdd[2];
    const qd_expr *syms[6];
    for (size_t i = 0; i < 6; i++)
        syms[i] = qt_symbol(s, names[i]);
    /* x2 is no coordinate once eliminated; its value is then unused */
    assert_int_equal(qd_eom_eval(s->ctx, s->eom, 6, syms, vals, NULL, NULL, qdd, NULL, NULL), QD_OK);
    assert_true(fabs(qdd[0] - 9.81 / 3) < 1e-12);
}

static void test_ropes(void **state) { atwood(state, false); }
static void test_ropes_eliminated(void **state) { atwood(state, true); }

static void refused(void **state, const char *text, const char *needle) {
    qt_system *s = qt_system_parse(state, text);
    s->eom = qd_eom_derive(s->ctx, s->model);
    assert_null(s->eom);
    assert_int_equal(qd_ctx_status(s->ctx), QD_ERR_SINGULAR);
    const char *msg = qd_ctx_message(s->ctx);
    if (!strstr(msg, "inconsistent") || !strstr(msg, needle))
        fail_msg("message \"%s\" lacks \"%s\"", msg, needle);
}

static void test_inconsistent(void **state) {
    char text[512];
    snprintf(text, sizeof text, ropes, " + 1");
    refused(state, text, "the least-squares one");
}

static void test_inconsistent_velocities(void **state) {
    refused(state,
            "coordinates x, y\nT = (x'^2 + y'^2)/2\n"
            "constraint c1: x' + y' = 0\nconstraint c2: 2*x' + 2*y' - 1 = 0\n",
            "a combination of their velocity forms is -0.5");
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(test_axle, teardown),
        cmocka_unit_test_teardown(test_ropes, teardown),
        cmocka_unit_test_teardown(test_ropes_eliminated, teardown),
        cmocka_unit_test_teardown(test_inconsistent, teardown),
        cmocka_unit_test_teardown(test_inconsistent_velocities, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
