/*
 * tests/model/test_state_point.c - a scan's texts (qdot modes --scan NAME=A:B
 * --about "..."): qd_state_named_range and qd_state_read_point.
 *
 *   - the Lagrange point L4 of the restricted three-body problem written in
 *     the mass ratio, x = 1/2 - mu, y = sqrt(3)/2 (Murray & Dermott, Solar
 *     System Dynamics, sec. 3.5), kept as expressions: evaluated at several
 *     mu it is an equilibrium of the rotating frame's effective potential
 *     Omega = (x^2 + y^2)/2 + (1 - mu)/r1 + mu/r2 (the primaries at -mu and
 *     1 - mu), its gradient 0 by central differences; a coordinate not
 *     named is 0; the state's own values are untouched;
 *   - velocities, parameters, t and coordinates not among the ones asked
 *     for refused, located in the text;
 *   - NAME=A:B: the name trimmed, A and B constant expressions (pi/2); no
 *     '=', an empty or too long name refused, located.
 */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "qdot/qdot.h"
#include "qdot/state.h"

static const char r3b[] = "coordinates x, y, z\nparameters mu = 0.01\n"
                          "T = (x'^2 + y'^2 + z'^2)/2\nV = -(x^2 + y^2)/2\n";

static double omega(double mu, double x, double y) {
    double r1 = hypot(x + mu, y), r2 = hypot(x - 1 + mu, y);
    return (x * x + y * y) / 2 + (1 - mu) / r1 + mu / r2;
}

typedef struct fx {
    qd_ctx *ctx;
    qd_model *m;
    qd_state st;
    const qd_expr *q[3];
} fx;

static fx load(void) {
    fx f = {qd_ctx_new(), NULL, {0}, {NULL}};
    f.m = qd_model_parse(f.ctx, r3b, NULL);
    assert_non_null(f.m);
    assert_int_equal(qd_state_init(f.ctx, f.m, &f.st), QD_OK);
    for (size_t j = 0; j < 3; j++)
        f.q[j] = qd_model_coord(f.m, j);
    return f;
}

static void unload(fx *f) {
    qd_state_free(&f->st);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
}

static void test_l4(void **state) {
    (void)state;
    fx f = load();
    const qd_expr *at[3];
    const char *text = "x = 1/2 - mu, y = sqrt(3)/2";
    assert_int_equal(qd_state_read_point(f.ctx, f.m, &f.st, text, 3, f.q, at), QD_OK);
    for (size_t k = 0; k < f.st.n; k++)
        assert_true(f.st.vals[k] == 0 || f.st.syms[k] == qd_model_param(f.m, 0));
    const qd_expr *mu = qd_model_param(f.m, 0);
    for (double m = 0.001; m < 0.04; m += 0.01) {
        double x, y, z, h = 1e-5;
        assert_int_equal(qd_eval(f.ctx, at[0], 1, &mu, &m, &x), QD_OK);
        assert_int_equal(qd_eval(f.ctx, at[1], 1, &mu, &m, &y), QD_OK);
        assert_int_equal(qd_eval(f.ctx, at[2], 1, &mu, &m, &z), QD_OK);
        assert_true(z == 0); /* not named */
        double gx = (omega(m, x + h, y) - omega(m, x - h, y)) / (2 * h);
        double gy = (omega(m, x, y + h) - omega(m, x, y - h)) / (2 * h);
        assert_true(fabs(gx) < 1e-8 && fabs(gy) < 1e-8);
    }
    unload(&f);
}

static void refused(const char *text, size_t n, size_t col) {
    fx f = load();
    const qd_expr *at[3];
    assert_int_not_equal(qd_state_read_point(f.ctx, f.m, &f.st, text, n, f.q, at), QD_OK);
    const qd_diag *d = qd_ctx_diag(f.ctx);
    assert_true(d->located);
    assert_int_equal(d->col, col);
    unload(&f);
}

static void test_point_refusals(void **state) {
    (void)state;
    refused("x = 1, x' = 2", 3, 8); /* a velocity: the point is at rest */
    refused("mu = 2", 3, 1);        /* a parameter keeps its value */
    refused("x = 1, w = 1", 3, 8);  /* no such name */
    refused("z = 1", 2, 1);         /* not among the coordinates asked for */
}

static void test_named_range(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    char name[8];
    double a, b;
    assert_int_equal(qd_state_named_range(ctx, NULL, "  mu = 0 : pi/2", name, sizeof name, &a,
                                          &b), QD_OK);
    assert_string_equal(name, "mu");
    assert_true(a == 0 && fabs(b - 1.5707963267948966) < 1e-15);
    const char *bad[] = {"mu 0:1", "=0:1", "abcdefgh=0:1", "mu=0,1"};
    for (size_t i = 0; i < 4; i++) {
        qd_ctx_clear_error(ctx);
        assert_int_not_equal(qd_state_named_range(ctx, NULL, bad[i], name, sizeof name, &a, &b),
                             QD_OK);
        assert_true(qd_ctx_diag(ctx)->located);
    }
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_l4),
        cmocka_unit_test(test_point_refusals),
        cmocka_unit_test(test_named_range),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
