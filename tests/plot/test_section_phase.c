/*
 * tests/plot/test_section_phase.c - the coordinate a Poincare section
 * leaves free (qd_plot_section_phase, qdot/plot.h): a section through
 * x = 0 of a motion in (x, y) is the plane x = 0 of phase space, on which
 * the state is (y, y'), so the plot shows y; the section y = 0 shows x; a
 * name is a whole word (x is not named by x2 = 0, and is by x' > 0 or
 * 2*x = 1); a section naming every coordinate falls back to the first;
 * the phase picked is one qd_plot_pick_columns accepts (y' against y).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <string.h>

#include "qdot/qdot.h"
#include "qdot/plot.h"

static const char *const names[] = {"t", "x", "y", "x'", "y'", "energy"};
static const char *const chain[] = {"t", "x", "x2", "x'", "x2'"};

static void test_free_coordinate(void **state) {
    (void)state;
    assert_string_equal(qd_plot_section_phase("x = 0, x' > 0", names, 2), "y");
    assert_string_equal(qd_plot_section_phase("y = 0, y' > 0", names, 2), "x");
    assert_string_equal(qd_plot_section_phase("2*x = 1", names, 2), "y");
    assert_string_equal(qd_plot_section_phase("x' = 0", names, 2), "y");
    assert_string_equal(qd_plot_section_phase("x2 = 0", chain, 2), "x");
    assert_string_equal(qd_plot_section_phase("x = 0", chain, 2), "x2");
    assert_string_equal(qd_plot_section_phase("x_1 + y = 0", names, 2), "x");
    /* every coordinate named: the first */
    assert_string_equal(qd_plot_section_phase("x = y", names, 2), "x");
    assert_null(qd_plot_section_phase("x = 0", names, 0));
    assert_null(qd_plot_section_phase(NULL, names, 2));
    /* the phase it gives: y' against y */
    qd_ctx *ctx = qd_ctx_new();
    qd_plot_pick pk;
    assert_int_equal(qd_plot_pick_columns(ctx, NULL, qd_plot_section_phase("x = 0", names, 2),
                                          names, 6, 2, &pk), QD_OK);
    assert_true(pk.phase && pk.x == 2 && pk.ny == 1 && pk.y[0] == 4);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_free_coordinate),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
