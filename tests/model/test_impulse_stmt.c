/*
 * tests/model/test_impulse_stmt.c - the statements of impulsive motion:
 * `impulse`, `Qhat[q]`, `impact constraint`, `impact` (contacts),
 * `prescribe`, and the particles the model keeps; what they mean and
 * every diagnostic they give (message, line and column asserted exactly).
 *
 * The generalized impulses are checked against Desloge ch. 57 Ex. 1 (the
 * rhombus of four rods hitting a wall, pp. 590-591: an impulse f at the
 * vertex C gives Qhat_x = f, Qhat_th = 2 a f sin th) and against the
 * virtual work of a couple on a turning body, G . dw/dq'.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <string.h>

#include "qdot/qdot.h"

static qd_model *parse_ok(qd_ctx *ctx, const char *text) {
    qd_diag d;
    memset(&d, 0, sizeof d);
    qd_model *m = qd_model_parse(ctx, text, &d);
    if (!m)
        fail_msg("%zu:%zu: %s [hint: %s]", d.line, d.col, d.message, d.hint);
    return m;
}

static void assert_is(qd_ctx *ctx, const qd_expr *e, const char *want) {
    qd_read_error err;
    const qd_read_opts opts = {.new_symbols = true};
    const qd_expr *w = qd_read(ctx, want, &opts, &err);
    assert_non_null(w);
    assert_non_null(e);
    const qd_expr *d = qd_simplify(ctx, qd_sub(ctx, e, w));
    if (!qd_is_zero(d)) {
        qd_buf b = QD_BUF_INIT;
        qd_print(ctx, e, QD_FMT_TEXT, &b);
        fail_msg("got %s, want %s", qd_buf_str(&b), want);
    }
}

/* The rhombus ABCD of Desloge ch. 57 Ex. 1: x the distance of its centre
 * from the wall, th the half-angle at C; the wall's impulse f at C. */
static const char rhombus[] =
    "coordinates x, th\n"
    "parameters m = 1, a = 1, f = 1, v = 1, al = pi/6\n"
    "T = 2*m*x'^2 + 8/3*m*a^2*th'^2\n"
    "C = (x - 2*a*cos(th), 0, 0)\n"
    "impulse (f, 0, 0) at C\n"
    "impact constraint wall: C.x = 0\n"
    "reaction wall on C\n"
    "initial x = 2*a*cos(al), th = al, x' = -v, th' = 0\n";

static void rhombus_blow(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse_ok(ctx, rhombus);
    assert_int_equal(qd_model_nblows(m), 1);
    assert_string_equal(qd_model_blow_label(m, 0), "impulse (f, 0, 0) at C");
    assert_is(ctx, qd_model_blow(m, 0, 0), "f");
    assert_is(ctx, qd_model_blow(m, 0, 1), "2*a*f*sin(th)");
    assert_is(ctx, qd_model_impulse(m, 0), "f");
    assert_is(ctx, qd_model_impulse(m, 1), "2*a*f*sin(th)");
    assert_null(qd_model_blow(m, 1, 0));
    assert_null(qd_model_impulse(m, 2));
    /* the sudden constraint: lhs - rhs, restitution 0 by default */
    assert_int_equal(qd_model_nimpact_constraints(m), 1);
    assert_string_equal(qd_model_impact_constraint_name(m, 0), "wall");
    assert_is(ctx, qd_model_impact_constraint(m, 0), "x - 2*a*cos(th)");
    assert_is(ctx, qd_model_impact_constraint_restitution(m, 0), "0");
    assert_int_equal(qd_model_nconstraints(m), 0); /* not an ordinary constraint */
    /* a reaction may name it: its impulse at C */
    assert_int_equal(qd_model_nreactions(m), 1);
    assert_string_equal(qd_model_reaction_constraint(m, 0), "wall");
    /* the state before, as written (exact), and as numbers */
    assert_is(ctx, qd_model_initial_definition(m, 1, 0), "al");
    assert_is(ctx, qd_model_initial_definition(m, 0, 1), "-v");
    assert_is(ctx, qd_model_initial(m, 1, 0), "pi/6");
    assert_is(ctx, qd_model_initial_definition(m, 1, 1), "0");
    assert_null(qd_model_initial_definition(m, 2, 0));
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* A couple G on a body turning about z: Qhat_th = G_z (virtual work
 * G . delta(theta)); Qhat[q] adds directly; the blows add up. */
static void couple_and_direct(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse_ok(ctx, "coordinates x, th\n"
                                "parameters M = 2, G = 3, P = 5\n"
                                "body disk mass M inertia (1, 1, 2) at (x, 0, 0) orientation rot_z(th)\n"
                                "impulse (0, 0, G) on disk\n"
                                "Qhat[x] = P\n"
                                "Qhat[th] = -1\n");
    assert_int_equal(qd_model_nblows(m), 3);
    assert_is(ctx, qd_model_blow(m, 0, 1), "G");
    assert_is(ctx, qd_model_blow(m, 0, 0), "0");
    assert_is(ctx, qd_model_blow(m, 1, 0), "P");
    assert_is(ctx, qd_model_impulse(m, 0), "P");
    assert_is(ctx, qd_model_impulse(m, 1), "G - 1");
    assert_string_equal(qd_model_blow_label(m, 1), "Qhat[x] = P");
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* Contacts: the gap is what must stay >= 0 (<= turns it round); sudden
 * constraints and prescriptions unnamed get k1, v1; restitution in the
 * parameters; particles are kept with their positions. */
static void contacts_and_prescriptions(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse_ok(ctx, "coordinates x, y\n"
                                "parameters m = 1, e = 0.8, h = 2\n"
                                "particle m at (x, y, 0)\n"
                                "particle 2*m at (x + 1, 0, 0)\n"
                                "impact floor: y >= 0 restitution e\n"
                                "impact y <= h restitution 1\n"
                                "impact constraint x' + y' = 0 restitution e/2\n"
                                "prescribe x' = 1, up: y' = 2*x'\n");
    assert_int_equal(qd_model_nimpacts(m), 2);
    assert_string_equal(qd_model_impact_name(m, 0), "floor");
    assert_is(ctx, qd_model_impact_gap(m, 0), "y");
    assert_is(ctx, qd_model_impact_restitution(m, 0), "e");
    assert_string_equal(qd_model_impact_name(m, 1), "contact1");
    assert_is(ctx, qd_model_impact_gap(m, 1), "h - y");
    assert_string_equal(qd_model_impact_constraint_name(m, 0), "k1");
    assert_is(ctx, qd_model_impact_constraint(m, 0), "x' + y'");
    assert_is(ctx, qd_model_impact_constraint_restitution(m, 0), "e/2");
    assert_int_equal(qd_model_nprescribed(m), 2);
    assert_string_equal(qd_model_prescribed_name(m, 0), "v1");
    assert_string_equal(qd_model_prescribed_name(m, 1), "up");
    assert_is(ctx, qd_model_prescribed(m, 1), "y' - 2*x'");
    assert_int_equal(qd_model_nparticles(m), 2);
    assert_is(ctx, qd_model_particle_mass(m, 1), "2*m");
    assert_is(ctx, qd_model_particle_position(m, 1, 0), "x + 1");
    assert_null(qd_model_particle_position(m, 2, 0));
    assert_int_equal(qd_model_nblows(m), 0);
    assert_is(ctx, qd_model_impulse(m, 0), "0");
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* A prescription added after the parse (qdot impulse --prescribe), and one
 * that fails: the model is as it was. */
static void added_prescription(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse_ok(ctx, rhombus);
    qd_diag d;
    assert_int_equal(qd_model_add_statement(m, "prescribe C.x' = 0", &d), QD_OK);
    assert_int_equal(qd_model_nprescribed(m), 1);
    assert_is(ctx, qd_model_prescribed(m, 0), "x' + 2*a*sin(th)*th'");
    assert_int_equal(qd_model_add_statement(m, "prescribe p: th' = 1, q: x^2 = 1", &d), QD_ERR_PARSE);
    assert_int_equal(d.line, 1);
    assert_int_equal(d.col, 26);
    assert_int_equal(qd_model_nprescribed(m), 1);
    assert_int_equal(qd_model_add_statement(m, "impulse (1, 0, 0) at C", &d), QD_OK);
    assert_is(ctx, qd_model_impulse(m, 0), "f + 1");
    assert_int_equal(qd_model_add_statement(m, "impulse (1, 0, 0) at (1, 0, 0)", &d), QD_ERR_PARSE);
    assert_is(ctx, qd_model_impulse(m, 0), "f + 1");
    assert_int_equal(qd_model_nblows(m), 2);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

static void expect_error(const char *line, size_t col, const char *message) {
    qd_ctx *ctx = qd_ctx_new();
    char text[512];
    snprintf(text, sizeof text,
             "coordinates x, th\nparameters m = 1, e = 2\nT = m*x'^2/2 + m*th'^2/2\n"
             "constraint c: x = th\n%s\n", line);
    qd_diag d;
    memset(&d, 0, sizeof d);
    qd_model *m = qd_model_parse(ctx, text, &d);
    if (m)
        fail_msg("parsed: %s", line);
    if (d.line != 5 || d.col != col || strcmp(d.message, message) != 0)
        fail_msg("%s\ngot 5:%zu: %s\nwant 5:%zu: %s", line, d.col, d.message, col, message);
    qd_ctx_free(ctx);
}

static void errors(void **state) {
    (void)state;
    expect_error("impulse (1, 0, 0) at (1, th, 0)", 22,
                 "this impulse does no virtual work: its point does not move with the "
                 "coordinates (or only across the impulse)");
    expect_error("impulse (x', 0, 0) at (x, 0, 0)", 9, "an impulse depends on x'");
    expect_error("impulse (1, 0, 0) on wheel", 22, "'wheel' is not a body");
    expect_error("impact constraint k: x = 1 restitution 1.5", 40,
                 "a restitution coefficient is between 0 and 1, not 1.5");
    expect_error("impact constraint k: x = 1 restitution e", 40,
                 "a restitution coefficient is between 0 and 1, not 2");
    expect_error("impact constraint k: x = 1 restitution x", 40,
                 "a restitution coefficient cannot depend on the coordinates, the velocities or t");
    expect_error("impact constraint c: x = 1", 19, "a constraint named 'c' is already given");
    expect_error("impact constraint k: x'' = 0", 22,
                 "a sudden constraint cannot depend on accelerations (x'')");
    expect_error("impact constraint k: x'*th' = 0", 22,
                 "a sudden constraint must be linear in the velocities: x' enters nonlinearly");
    expect_error("impact constraint k: 1 = 1", 22, "this sudden constraint always holds");
    expect_error("impact floor: x' >= 0", 15, "a contact cannot depend on x'");
    expect_error("impact floor: t >= 1", 15, "this contact does not depend on the coordinates");
    expect_error("impact floor: x = 0", 17, "expected '>=' or '<=', found '='");
    expect_error("impact floor: x > 0", 17, "unexpected character '>'");
    expect_error("prescribe x = 1", 11, "a prescription gives velocities, but this has none");
    expect_error("prescribe x'", 13, "expected '=', found the end of the line");
    expect_error("Qhat[z] = 1", 6, "'z' is not a coordinate");
    expect_error("Qhat[x] = x'", 11, "a generalized impulse depends on x'");
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(rhombus_blow),
        cmocka_unit_test(couple_and_direct),
        cmocka_unit_test(contacts_and_prescriptions),
        cmocka_unit_test(added_prescription),
        cmocka_unit_test(errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
