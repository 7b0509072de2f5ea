/*
 * tests/mech/test_manifold.c - Pfaffian constraints classified on the
 * manifold the holonomic constraints cut out (Desloge ch. 49; seed
 * seed-desloge-A.md C6 and pitfall 4):
 *   a cylinder rolling on a cylinder: r theta' - b phi' = 0 is nonholonomic
 *     alone but exact once r = a + b, with the integral (a + b) theta - b phi;
 *   y' = z x' (nonholonomic, T09) becomes exact on z = c: y - c x = const;
 *     on z^2 + w^2 = 1 it stays nonholonomic;
 *   a holonomic constraint that cannot be solved for a coordinate
 *     (z^3 + z = 2) still counts through its differential in the Frobenius
 *     test: y' - z x' + w' = 0 is integrable modulo dz, not alone;
 *   the rolling disk with its heading held fixed rolls on a line: both
 *     no-slip conditions are integrable, one by one and together.
 * Integrals are checked for what they must be: on the manifold their
 * gradient is parallel to the reduced form, at random points.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/mech.h"
#include "qdot/model.h"
#include "util/randexpr.h"

#define SEED 77031u

typedef struct fixture {
    qd_ctx *ctx;
    qd_model *model;
    qd_eom *eom;
} fixture;

static int teardown(void **state) {
    fixture *fx = *state;
    if (fx) {
        qd_eom_free(fx->eom);
        qd_model_free(fx->model);
        qd_ctx_free(fx->ctx);
    }
    free(fx);
    *state = NULL;
    return 0;
}

static fixture *derive(void **state, const char *text) {
    fixture *fx = calloc(1, sizeof *fx);
    qd_diag d;
    *state = fx;
    fx->ctx = qd_ctx_new();
    fx->model = qd_model_parse(fx->ctx, text, &d);
    if (!fx->model)
        fail_msg("model does not parse: %zu:%zu: %s\n%s", d.line, d.col, d.message, text);
    fx->eom = qd_eom_derive(fx->ctx, fx->model);
    if (!fx->eom)
        fail_msg("derivation failed: %s", qd_ctx_message(fx->ctx));
    return fx;
}

static const qd_con *con(fixture *fx, const char *name) {
    for (size_t k = 0; k < fx->eom->ncon; k++)
        if (!strcmp(fx->eom->con[k].name, name))
            return &fx->eom->con[k];
    fail_msg("no constraint %s", name);
    return NULL;
}

static const qd_expr *S(fixture *fx, const char *name) {
    const qd_expr *s = qd_lookup(fx->ctx, name);
    if (!s)
        fail_msg("no symbol %s", name);
    return s;
}

/* d(integral)/d x_i = mu w_i for the given variables and form w, one mu, at
 * random points (ns symbols, the others of syms at random values too). */
static void assert_integral(fixture *fx, const qd_expr *phi, size_t nv, const char *const *x,
                            const double *w, size_t ns, const char *const *syms) {
    qt_rng rng = {SEED};
    const qd_expr *s[8];
    double v[8];
    assert_non_null(phi);
    for (size_t i = 0; i < ns; i++)
        s[i] = S(fx, syms[i]);
    for (int k = 0; k < 6; k++) {
        for (size_t i = 0; i < ns; i++)
            v[i] = qt_uniform(&rng, 0.3, 1.7);
        double g[8], mu = 0;
        for (size_t i = 0; i < nv; i++) {
            const qd_expr *d = qd_diff(fx->ctx, phi, S(fx, x[i]));
            assert_int_equal(qd_eval(fx->ctx, d, ns, s, v, &g[i]), QD_OK);
            if (w[i] != 0 && mu == 0)
                mu = g[i] / w[i];
        }
        assert_true(fabs(mu) > 1e-9);
        for (size_t i = 0; i < nv; i++)
            if (fabs(g[i] - mu * w[i]) > 1e-9 * (1 + fabs(g[i])))
                fail_msg("d phi/d %s = %g, expected %g", x[i], g[i], mu * w[i]);
    }
}

static void test_cylinder_on_cylinder(void **state) {
    fixture *fx = derive(state,
        "coordinates r, theta, phi\n"
        "parameters m = 1.2, a = 1.5, b = 0.4, g = 9.81\n"
        "body wheel mass m inertia disk(m, b) at (r*sin(theta), r*cos(theta), 0) "
        "orientation rot_z(-phi)\n"
        "V = m*g*r*cos(theta)\n"
        "constraint contact: r = a + b\n"
        "constraint roll: r*theta' - b*phi' = 0\n");
    const qd_con *roll = con(fx, "roll");
    assert_int_equal(con(fx, "contact")->kind, QD_CON_HOLONOMIC);
    assert_int_equal(roll->kind, QD_CON_INTEGRABLE);
    /* on r = a + b (a = 1.5, b = 0.4 at their values): (a + b) dtheta - b dphi */
    const qd_expr *phi = qd_subs(fx->ctx, roll->integral, 2,
                                 (const qd_expr *[]){S(fx, "a"), S(fx, "b")},
                                 (const qd_expr *[]){qd_rat(fx->ctx, 3, 2), qd_rat(fx->ctx, 2, 5)});
    assert_integral(fx, phi, 3, (const char *[]){"r", "theta", "phi"},
                    (double[]){0, 1.9, -0.4}, 3, (const char *[]){"r", "theta", "phi"});
    /* the multiplier of roll stays: the A row is the constraint as written */
    assert_ptr_equal(fx->eom->A[1 * 3 + 0], qd_int(fx->ctx, 0));
    assert_ptr_equal(fx->eom->A[1 * 3 + 1], S(fx, "r"));
}

static void test_yzx_on_plane(void **state) {
    fixture *fx = derive(state,
        "coordinates x, y, z\nparameters c = 2\n"
        "T = (x'^2 + y'^2 + z'^2)/2\n"
        "constraint level: z = c\n"
        "constraint c1: y' = z*x'\n");
    const qd_con *c = con(fx, "c1");
    assert_int_equal(c->kind, QD_CON_INTEGRABLE);
    const qd_expr *phi = qd_subs(fx->ctx, c->integral, 1, (const qd_expr *[]){S(fx, "c")},
                                 (const qd_expr *[]){qd_int(fx->ctx, 2)});
    assert_integral(fx, phi, 2, (const char *[]){"x", "y"}, (double[]){-2, 1}, 3,
                    (const char *[]){"x", "y", "z"});
}

static void test_yzx_on_circle(void **state) {
    fixture *fx = derive(state,
        "coordinates x, y, z, w\n"
        "T = (x'^2 + y'^2 + z'^2 + w'^2)/2\n"
        "constraint circle: z^2 + w^2 = 1\n"
        "constraint c1: y' = z*x'\n");
    assert_int_equal(con(fx, "c1")->kind, QD_CON_NONHOLONOMIC);
    assert_null(con(fx, "c1")->integral);
}

/* z^3 + z = 2 cannot be solved for z by elimination: dz joins the test. */
static void test_modulo_differential(void **state) {
    fixture *fx = derive(state,
        "coordinates x, y, z, w\n"
        "T = (x'^2 + y'^2 + z'^2 + w'^2)/2\n"
        "constraint cubic: z^3 + z = 2\n"
        "constraint c1: y' - z*x' + w' = 0\n");
    assert_int_equal(con(fx, "c1")->kind, QD_CON_INTEGRABLE);
    void *st2 = NULL;
    fixture *alone = derive(&st2, "coordinates x, y, z, w\n"
                         "T = (x'^2 + y'^2 + z'^2 + w'^2)/2\n"
                         "constraint c1: y' - z*x' + w' = 0\n");
    assert_int_equal(con(alone, "c1")->kind, QD_CON_NONHOLONOMIC);
    teardown(&st2);
}

/* The rolling disk (Desloge ch. 49 ex. 1, T09: nonholonomic) with its
 * heading held fixed rolls on a line: both no-slip conditions become exact
 * on ph = c, and together they are integrable as well. */
static void test_disk_fixed_heading(void **state) {
    fixture *fx = derive(state,
        "coordinates x1, x2, ph, psi\nparameters m = 1, a = 0.5, c = 0.7\n"
        "T = m/2*(x1'^2 + x2'^2) + m*a^2/8*(ph'^2 + 2*psi'^2)\n"
        "constraint heading: ph = c\n"
        "constraint roll1: x1' + a*cos(ph)*psi' = 0\n"
        "constraint roll2: x2' + a*sin(ph)*psi' = 0\n");
    assert_int_equal(con(fx, "roll1")->kind, QD_CON_INTEGRABLE);
    assert_int_equal(con(fx, "roll2")->kind, QD_CON_INTEGRABLE);
    double a = 0.5, c = 0.7;
    const qd_expr *from[2] = {S(fx, "a"), S(fx, "c")};
    const qd_expr *to[2] = {qd_float(fx->ctx, a), qd_float(fx->ctx, c)};
    const char *x[3] = {"x1", "x2", "psi"}, *all[4] = {"x1", "x2", "ph", "psi"};
    assert_integral(fx, qd_subs(fx->ctx, con(fx, "roll1")->integral, 2, from, to), 3, x,
                    (double[]){1, 0, a * cos(c)}, 4, all);
    assert_integral(fx, qd_subs(fx->ctx, con(fx, "roll2")->integral, 2, from, to), 3, x,
                    (double[]){0, 1, a * sin(c)}, 4, all);
    void *st2 = NULL;
    fixture *free_disk = derive(&st2,
        "coordinates x1, x2, ph, psi\nparameters m = 1, a = 0.5\n"
        "T = m/2*(x1'^2 + x2'^2) + m*a^2/8*(ph'^2 + 2*psi'^2)\n"
        "constraint roll1: x1' + a*cos(ph)*psi' = 0\n"
        "constraint roll2: x2' + a*sin(ph)*psi' = 0\n");
    assert_int_equal(con(free_disk, "roll1")->kind, QD_CON_NONHOLONOMIC);
    assert_int_equal(con(free_disk, "roll2")->kind, QD_CON_NONHOLONOMIC);
    teardown(&st2);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(test_cylinder_on_cylinder, teardown),
        cmocka_unit_test_teardown(test_yzx_on_plane, teardown),
        cmocka_unit_test_teardown(test_yzx_on_circle, teardown),
        cmocka_unit_test_teardown(test_modulo_differential, teardown),
        cmocka_unit_test_teardown(test_disk_fixed_heading, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
