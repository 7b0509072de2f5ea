/*
 * tests/linear/test_choice_note.c - the automatic choice of an equilibrium
 * (qd_equilibria_choose) and its line (qd_equilibrium_choice_note,
 * qdot/equilibria.h): the plane pendulum started near the bottom has two
 * equilibria, theta = 0 and theta = pi; the one chosen is the bottom, the
 * minimum of V = -m g l cos(theta) nearest the initial state, and the line
 * says theta = 0, that reason, and the one other equilibrium (the top).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "qdot/qdot.h"

static const char pendulum[] = "coordinates theta\nparameters m = 1.3, l = 0.8, g = 9.81\n"
                               "particle m at l*(sin(theta), -cos(theta))\n"
                               "V = -m*g*l*cos(theta)\ninitial theta = 0.4\n";

static void bottom_chosen(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qd_model_parse(ctx, pendulum, NULL);
    assert_non_null(m);
    qd_eom *e = qd_eom_derive(ctx, m);
    assert_non_null(e);
    const qd_expr *syms[3] = {qd_param(ctx, "m"), qd_param(ctx, "l"), qd_param(ctx, "g")};
    double vals[3] = {1.3, 0.8, 9.81};
    qd_equilibrium_choice ch = {0};
    assert_int_equal(qd_equilibria_choose(ctx, e, m, 3, syms, vals, &ch), QD_OK);
    assert_non_null(ch.pt);
    assert_true(fabs(ch.pt->q[0]) < 1e-12);           /* the bottom */
    assert_int_equal(ch.reason, QD_EQ_CHOSEN_NEAREST_MINIMUM);
    assert_int_equal(ch.found.count, 2);               /* bottom and top */
    assert_int_equal(ch.others, 1);
    for (size_t k = 0; k < ch.found.count; k++)        /* the other is the top, |theta| = pi */
        if (&ch.found.pts[k] != ch.pt)
            assert_true(fabs(fabs(ch.found.pts[k].q[0]) - 3.14159265358979) < 1e-9);
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_equilibrium_choice_note(e, &ch, &b), QD_OK);
    const char *t = qd_buf_str(&b);
    assert_int_equal(strncmp(t, "theta = 0, ", 11), 0);
    assert_non_null(strstr(t, qd_eq_chosen_name(ch.reason)));
    assert_non_null(strstr(t, "; 1 other equilibrium found"));
    assert_null(strstr(t, "not isolated"));
    qd_buf_free(&b);
    qd_equilibrium_choice none = {0};                  /* no point: nothing to say */
    assert_int_equal(qd_equilibrium_choice_note(e, &none, &b), QD_ERR_ARG);
    qd_buf_free(&b);
    qd_equilibrium_choice_free(&ch);
    qd_eom_free(e);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(bottom_chosen),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
