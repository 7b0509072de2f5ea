/*
 * tests/model/test_friction_parse.c - the friction clauses of the model
 * language (issue 18): what qd_model_ncontacts and the contact queries
 * report for `constraint ... friction`, `static ... kinetic ...`, a normal
 * given as an expression or a constraint's name (before or after), `rolls
 * ... friction` (its normal the gap constraint's multiplier when there is
 * one), `friction MU on POINT against CONSTRAINT` (its tangent slip
 * constraints and |grad S|), and the diagnostics with line and column.
 *
 * The point on the sphere x^2 + y^2 + z^2 = R^2 checks the geometry of
 * src/model/friction_point.c: |grad S| = 2R on the surface, and the two
 * slip velocities are the components of r' on an orthonormal tangent
 * frame, so s1^2 + s2^2 = |r'|^2 for any tangent r' at a point of it.
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
#include "qdot/model.h"

static qd_model *parse(qd_ctx *ctx, const char *text) {
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, text, &d);
    if (!m)
        fail_msg("%zu:%zu: %s [hint: %s]\n%s", d.line, d.col, d.message, d.hint, text);
    return m;
}

static double value(qd_ctx *ctx, const qd_expr *e, size_t n, const qd_expr **syms,
                    const double *vals) {
    double x = NAN;
    assert_int_equal(qd_eval(ctx, e, n, syms, vals, &x), QD_OK);
    return x;
}

static const qd_expr *param(const qd_model *m, const char *name) {
    for (size_t i = 0; i < qd_model_nparams(m); i++)
        if (!strcmp(qd_expr_name(qd_model_param(m, i)), name))
            return qd_model_param(m, i);
    fail_msg("no parameter %s", name);
    return NULL;
}

static void constraint_clause(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse(ctx, "coordinates x, y, phi\n"
                             "parameters m = 1, a = 0.1, g = 9.81, ms = 0.5, mk = 0.3\n"
                             "T = m/2*(x'^2 + y'^2) + m*a^2/5*phi'^2\n"
                             "constraint slip: x' - a*phi' = 0 friction static ms kinetic mk "
                             "normal floor\n"
                             "constraint floor: y = a\n"
                             "constraint other: y' = 0 friction 2*ms normal m*g\n");
    assert_int_equal(qd_model_ncontacts(m), 2);
    assert_string_equal(qd_model_contact_name(m, 0), "slip");
    assert_int_equal(qd_model_contact_kind(m, 0), QD_CONTACT_CONSTRAINT);
    size_t con[2];
    assert_int_equal(qd_model_contact_constraints(m, 0, con), 1);
    assert_int_equal(con[0], 0);
    assert_ptr_equal(qd_model_contact_mu(m, 0, false), param(m, "ms"));
    assert_ptr_equal(qd_model_contact_mu(m, 0, true), param(m, "mk"));
    assert_null(qd_model_contact_normal(m, 0));
    assert_string_equal(qd_model_contact_normal_constraint(m, 0), "floor");
    /* friction MU: both coefficients MU; N an expression */
    assert_ptr_equal(qd_model_contact_mu(m, 1, false), qd_model_contact_mu(m, 1, true));
    assert_null(qd_model_contact_normal_constraint(m, 1));
    const qd_expr *syms[] = {param(m, "m"), param(m, "g")};
    double vals[] = {1, 9.81};
    assert_true(value(ctx, qd_model_contact_normal(m, 1), 2, syms, vals) == 9.81);
    assert_null(qd_model_contact_name(m, 2));
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* rolls ... friction: both slip constraints, the normal BODY_contact's
 * multiplier when the gap is not identically 0 (here the ball's height
 * is a coordinate). */
static void rolls_clause(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse(ctx, "coordinates x, y, z, phi, theta, psi\n"
                             "parameters m = 1, a = 0.2, mu = 0.3\n"
                             "body ball mass m inertia sphere(m, a) at (x, y, z) orientation "
                             "euler(phi, theta, psi)\n"
                             "rolls ball on plane((0, 0, 1), (0, 0, 0)) as sphere(a) friction "
                             "mu\n");
    assert_int_equal(qd_model_ncontacts(m), 1);
    assert_int_equal(qd_model_contact_kind(m, 0), QD_CONTACT_ROLLING);
    size_t con[2];
    assert_int_equal(qd_model_contact_constraints(m, 0, con), 2);
    assert_string_equal(qd_model_constraint_name(m, con[0]), "ball_roll1");
    assert_string_equal(qd_model_constraint_name(m, con[1]), "ball_roll2");
    assert_string_equal(qd_model_contact_normal_constraint(m, 0), "ball_contact");
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* The point on a sphere of radius R: |grad S| = 2R there, and the two
 * slip velocities are an orthonormal frame's components of r'. */
static void point_on_sphere(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse(ctx, "coordinates x, y, z\n"
                             "parameters R = 1.5, mu = 0.2\n"
                             "P = (x, y, z)\n"
                             "particle 1 at P\n"
                             "constraint bowl: x^2 + y^2 + z^2 = R^2\n"
                             "friction mu on P against bowl\n");
    assert_int_equal(qd_model_contact_kind(m, 0), QD_CONTACT_POINT);
    size_t con[2];
    assert_int_equal(qd_model_contact_constraints(m, 0, con), 2);
    const qd_expr *syms[7] = {qd_model_coord(m, 0), qd_model_coord(m, 1), qd_model_coord(m, 2)};
    for (int j = 0; j < 3; j++)
        syms[3 + j] = qd_jet(ctx, syms[j], 1);
    syms[6] = param(m, "R");
    /* a point of the sphere and a tangent velocity there */
    double p[3] = {0.6, -0.9, 0}, u[3] = {0.3, 0.7, -1.1};
    p[2] = -sqrt(1.5 * 1.5 - p[0] * p[0] - p[1] * p[1]);
    double un = (u[0] * p[0] + u[1] * p[1] + u[2] * p[2]) / (1.5 * 1.5);
    for (int j = 0; j < 3; j++)
        u[j] -= un * p[j];
    double vals[7] = {p[0], p[1], p[2], u[0], u[1], u[2], 1.5};
    double s1 = value(ctx, qd_model_constraint(m, con[0]), 7, syms, vals);
    double s2 = value(ctx, qd_model_constraint(m, con[1]), 7, syms, vals);
    double v2 = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    assert_true(fabs(s1 * s1 + s2 * s2 - v2) <= 1e-14 * v2);
    assert_true(fabs(value(ctx, qd_model_contact_normal_scale(m, 0), 7, syms, vals) - 3) <=
                1e-14);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

static void expect_error(const char *text, const char *msg, size_t line, size_t col) {
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, text, &d);
    bool ok = !m && strstr(d.message, msg) && d.line == line && d.col == col && d.hint[0];
    if (!ok)
        fail_msg("%s: got %zu:%zu '%s' (want %zu:%zu '%s')", text, d.line, d.col, d.message,
                 line, col, msg);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

static void diagnostics(void **state) {
    (void)state;
    const char *h = "coordinates x, y\nparameters mu = 0.2\nT = (x'^2 + y'^2)/2\n";
    char t[512];
    snprintf(t, sizeof t, "%sconstraint c: x = y friction mu normal 1\n", h);
    expect_error(t, "friction needs a velocity constraint", 4, 21);
    snprintf(t, sizeof t, "%sconstraint c: x' = y' friction -1 normal 1\n", h);
    expect_error(t, "the friction coefficient is negative (-1)", 4, 32);
    snprintf(t, sizeof t, "%sconstraint c: x' = y' friction static mu normal 1\n", h);
    expect_error(t, "expected 'kinetic'", 4, 42);
    snprintf(t, sizeof t, "%sconstraint c: x' = y' friction mu normal d\nconstraint e: y = 1\n",
             h);
    expect_error(t, "no constraint named 'd' gives the normal force", 4, 42);
    snprintf(t, sizeof t, "%sconstraint c: x' = y' friction mu normal c\n", h);
    expect_error(t, "cannot be its own friction force", 4, 42);
    snprintf(t, sizeof t, "%sP = (x, y, 0)\nconstraint c: x' = 0\nfriction mu on P against c\n",
             h);
    expect_error(t, "'c' is not a surface", 6, 16);
    snprintf(t, sizeof t, "%sP = (x, y, 0)\nconstraint c: x = 1\nfriction mu on P against c "
             "normal 2\n", h);
    expect_error(t, "unexpected", 6, 28);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(constraint_clause), cmocka_unit_test(rolls_clause),
        cmocka_unit_test(point_on_sphere),   cmocka_unit_test(diagnostics),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
