/*
 * tests/model/test_definitions.c - a model's named definitions listed
 * through the public API (qd_model_ndefinitions and the rest, issue 31:
 * src/scene reads them so, no longer the parser's structs), and the model's
 * context (qd_model_ctx).
 *
 * The mathematics asserted: the bob of a pendulum of length l,
 * r = l (sin th, -cos th, 0), stays at distance l from the pivot, and the
 * rotation rot_z(th) = [[cos, -sin, 0], [sin, cos, 0], [0, 0, 1]] (the
 * table of docs/language.md, "Rotations"; Goldstein sec. 4.4) is orthogonal,
 * R R^T = I, at every angle: both checked numerically on the components
 * read back, at a few angles.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/model.h"

static const char pendulum[] =
    "coordinates th\n"
    "parameters m = 1, l = 2, g = 9.81\n"
    "x1 = l*sin(th)\n"
    "y1 = -l*cos(th)\n"
    "P1 = (x1, y1)\n"
    "R = rot_z(th)\n"
    "T = m/2*l^2*th'^2\n"
    "V = m*g*y1\n";

static double at(qd_ctx *ctx, const qd_model *m, const qd_expr *x, double th) {
    const qd_expr *syms[2] = {qd_model_coord(m, 0), qd_param(ctx, "l")};
    double vals[2] = {th, 2}, v = NAN;
    assert_non_null(x);
    assert_int_equal(qd_eval(ctx, x, 2, syms, vals, &v), QD_OK);
    return v;
}

static void test_definitions_listed(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qd_model_parse(ctx, pendulum, NULL);
    assert_non_null(m);
    assert_ptr_equal(qd_model_ctx(m), ctx);
    /* x1, y1, P1, R in the order written (T and V are energies) */
    size_t n = qd_model_ndefinitions(m), ix = n, ip = n, ir = n;
    for (size_t i = 0; i < n; i++) {
        const char *name = qd_model_definition_name(m, i);
        assert_non_null(name);
        if (!strcmp(name, "x1"))
            ix = i;
        else if (!strcmp(name, "P1"))
            ip = i;
        else if (!strcmp(name, "R"))
            ir = i;
    }
    assert_true(ix < ip && ip < ir && ir < n);
    assert_int_equal(qd_model_definition_size(m, ix), 1);
    assert_int_equal(qd_model_definition_size(m, ip), 3);
    assert_int_equal(qd_model_definition_size(m, ir), 9);
    /* a scalar's one component is qd_model_definition's value */
    assert_ptr_equal(qd_model_definition_component(m, ix, 0), qd_model_definition(m, "x1"));
    for (double th = -2.5; th < 3; th += 1.1) {
        /* |r| = l: the bob stays on its circle */
        double r2 = 0;
        for (size_t k = 0; k < 3; k++) {
            double c = at(ctx, m, qd_model_definition_component(m, ip, k), th);
            r2 += c * c;
        }
        assert_true(fabs(r2 - 4) < 1e-13);
        /* R R^T = I, R by rows */
        double R[9];
        for (size_t k = 0; k < 9; k++)
            R[k] = at(ctx, m, qd_model_definition_component(m, ir, k), th);
        for (size_t i = 0; i < 3; i++)
            for (size_t j = 0; j < 3; j++) {
                double s = 0;
                for (size_t k = 0; k < 3; k++)
                    s += R[3 * i + k] * R[3 * j + k];
                assert_true(fabs(s - (i == j)) < 1e-14);
            }
        assert_true(fabs(R[3] - sin(th)) < 1e-15); /* row 2, column 1: +sin, active */
    }
    /* out of range: nothing */
    assert_null(qd_model_definition_name(m, n));
    assert_int_equal(qd_model_definition_size(m, n), 0);
    assert_null(qd_model_definition_component(m, n, 0));
    assert_null(qd_model_definition_component(m, ix, 1));
    assert_null(qd_model_definition_component(m, ip, 3));
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_definitions_listed),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
