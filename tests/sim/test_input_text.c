/*
 * tests/sim/test_input_text.c - an input's source from one text
 * (qd_sim_setup_input_text, src/sim/input_text.c), as `qdot simulate
 * --input` gives it, on the driven oscillator m x'' = -k x + F (m = 2,
 * k = 8):
 *   - "F = 8*x" cancels the spring: x'' = 0, so from x = 1, x' = 0.5 the
 *     motion is x = 1 + t/2 (Newton's first law), read at every row;
 *   - F=ramp.csv and "F = lqr" are told apart and left to the caller,
 *     the value's place trimmed of blanks;
 *   - an input named twice, whatever the sources, and a text without
 *     "NAME =" are refused (QD_ERR_ARG).
 */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <setjmp.h>
#include <string.h>
#include <cmocka.h>

#include "qdot/qdot.h"
#include "qdot/simsetup.h"

static const char osc[] = "coordinates x\nparameters m = 2, k = 8\ninputs F\n"
                          "T = m*x'^2/2\nV = k*x^2/2\nQ[x] = F\ninitial x = 1, x' = 0.5\n";

typedef struct setup {
    qd_ctx *ctx;
    qd_model *m;
    qd_sim_setup *set;
} setup;

static void open_setup(setup *u) {
    u->ctx = qd_ctx_new();
    u->m = qd_model_parse(u->ctx, osc, NULL);
    assert_non_null(u->m);
    u->set = qd_sim_setup_new(u->ctx, u->m, false);
    assert_non_null(u->set);
}

static void close_setup(setup *u) {
    qd_sim_setup_free(u->set);
    qd_model_free(u->m);
    qd_ctx_free(u->ctx);
}

static int free_flight(void *data, int event, const double *row) {
    (void)event;
    double *worst = data;
    *worst = fmax(*worst, fabs(row[1] - (1 + row[0] / 2)) + fabs(row[2] - 0.5));
    return 0;
}

static void test_expression(void **state) {
    (void)state;
    setup u;
    open_setup(&u);
    char name[16];
    qd_sim_input_kind kind;
    size_t a, b;
    const char *text = " F = 8*x ";
    assert_int_equal(qd_sim_setup_input_text(u.set, text, &kind, name, sizeof name, &a, &b),
                     QD_OK);
    assert_int_equal(kind, QD_SIM_INPUT_EXPR);
    assert_string_equal(name, "F");
    assert_true(a == 5 && b == 8); /* "8*x" */
    qd_sim_setup_opts so = {.t_end = "4", .dt = "0.25", .rtol = "1e-12"};
    qd_sim_opts o;
    assert_int_equal(qd_sim_setup_options(u.set, &so, &o), QD_OK);
    double worst = 0;
    qd_sim_stats st;
    assert_int_equal(qd_sim_run(qd_sim_setup_sim(u.set), &o, free_flight, &worst, &st, NULL),
                     QD_OK);
    assert_true(worst < 1e-9);
    /* F again, as a table this time: named twice */
    assert_int_equal(qd_sim_setup_input_text(u.set, "F=ramp.csv", &kind, name, sizeof name, &a,
                                             &b),
                     QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(u.ctx), "F is given twice"));
    close_setup(&u);
}

static void test_kinds(void **state) {
    (void)state;
    setup u;
    open_setup(&u);
    char name[16];
    qd_sim_input_kind kind;
    size_t a, b;
    const char *table = "F= ramp.csv ";
    assert_int_equal(qd_sim_setup_input_text(u.set, table, &kind, name, sizeof name, &a, &b),
                     QD_OK);
    assert_int_equal(kind, QD_SIM_INPUT_TABLE);
    assert_true(b - a == 8 && !strncmp(table + a, "ramp.csv", 8));
    close_setup(&u);
    open_setup(&u);
    assert_int_equal(qd_sim_setup_input_text(u.set, "F = lqr", &kind, name, sizeof name, &a, &b),
                     QD_OK);
    assert_int_equal(kind, QD_SIM_INPUT_LQR);
    assert_int_equal(qd_sim_setup_input_text(u.set, "F", &kind, name, sizeof name, &a, &b),
                     QD_ERR_ARG);
    qd_ctx_clear_error(u.ctx);
    assert_int_equal(qd_sim_setup_input_text(u.set, " = 1", &kind, name, sizeof name, &a, &b),
                     QD_ERR_ARG);
    close_setup(&u);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_expression),
        cmocka_unit_test(test_kinds),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
