/*
 * tests/mech/test_diag.c - what a failed derivation says it is about.
 *
 * The derivations record the subject of their error (which constraint,
 * which statement, which coordinate), the reason and a hint in the
 * context's error record; qd_model_locate turns the subject into a byte
 * range of the model text.  The CLI used to find the constraint by searching
 * the English message for its name, so a constraint named `no` took the
 * caret from "no motion satisfies them all"; here only data is asserted.
 *
 * The mechanics behind each case:
 * - x' + y' = 0 and x' + y' = 1 together: no velocity satisfies both
 *   (inconsistent); x' + y' = 0 and 2x' + 2y' = 0: the second repeats the
 *   first, so the multipliers are not unique (redundant) (Greenwood,
 *   Advanced Dynamics, sec. 2.4, independent constraint equations).
 * - x'^2 + y'^2 = 1 is not linear in the velocities: not Pfaffian, outside
 *   the Lagrange-multiplier form sum_j a_j q'_j + a0 = 0.
 * - T = x'^2/2 with coordinates x, y: M = diag(1, 0) is singular.
 * - H = p^4/4 + V: dH/dp = p^3 cannot be solved for p in closed form by a
 *   linear solve, so the inverse Legendre transform has no quadratic L.
 * - L = x'^2/2 + y'^4/4 - x^2: p_y = y'^3 is not linear in y'; that is no
 *   longer an error (H is kept implicit, q' from Newton's method), but
 *   L = x' y - y'^4/4 is linear in x', so its Hessian in the velocities is
 *   singular and there is no Hamiltonian (Desloge Appendix 22,
 *   seed-desloge-D.md P13): the error is about the coordinate x.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <string.h>

#include "qdot/qdot.h"

static qd_model *parse_ok(qd_ctx *ctx, const char *text) {
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, text, &d);
    if (!m)
        fail_msg("%zu:%zu: %s", d.line, d.col, d.message);
    return m;
}

/* Derive the equations of text, which must fail; the record, located. */
static qd_diag derive_fail(qd_ctx *ctx, const char *text, qd_model **m) {
    *m = parse_ok(ctx, text);
    qd_eom *e = qd_eom_derive(ctx, *m);
    if (e)
        fail_msg("derived but must fail: %s", text);
    qd_diag d = *qd_ctx_diag(ctx);
    assert_int_not_equal(d.status, QD_OK);
    assert_false(d.located); /* a derivation knows no text ... */
    assert_true(qd_model_locate(*m, &d)); /* ... the model places it */
    assert_true(d.located);
    return d;
}

/* The offset of needle in text, which must hold it. */
static size_t at(const char *text, const char *needle) {
    const char *p = strstr(text, needle);
    assert_non_null(p);
    return (size_t)(p - text);
}

static void inconsistent_constraints(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const char *text = "coordinates x, y, z\nT = (x'^2 + y'^2 + z'^2)/2\n"
                       "constraint no: z = 0\n"
                       "constraint a: x' + y' = 0\nconstraint b: x' + y' = 1\n";
    qd_model *m;
    qd_diag d = derive_fail(ctx, text, &m);
    assert_int_equal(d.status, QD_ERR_SINGULAR);
    assert_int_equal(d.subject, QD_SUBJECT_CONSTRAINT);
    assert_int_equal(d.index, 1);
    assert_string_equal(d.name, "a");
    assert_int_equal(d.reason, QD_REASON_INCONSISTENT);
    assert_int_equal(d.offset, at(text, "a: x'"));
    assert_int_equal(d.line, 4);
    assert_true(d.hint[0] != '\0');
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* Redundant but consistent (issue 33): no diagnostic, the derivation goes
 * on without one of them (tests/mech/test_redundant.c for the physics). */
static void redundant_constraints(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const char *text = "coordinates x, y, z\nT = (x'^2 + y'^2 + z'^2)/2\n"
                       "constraint a: x' + y' = 0\nconstraint b: 2*x' + 2*y' = 0\n";
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, text, &d);
    assert_non_null(m);
    qd_eom *e = qd_eom_derive(ctx, m);
    assert_non_null(e);
    assert_int_equal(e->ncon, 1);
    assert_int_equal(e->nreduced, 1);
    qd_eom_free(e);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

static void not_pfaffian(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const char *text = "coordinates x, y\nT = (x'^2 + y'^2)/2\nV = y\n"
                       "constraint roll: x'^2 + y'^2 = 1\n";
    qd_model *m;
    qd_diag d = derive_fail(ctx, text, &m);
    assert_int_equal(d.subject, QD_SUBJECT_CONSTRAINT);
    assert_int_equal(d.index, 0);
    assert_string_equal(d.name, "roll");
    assert_int_equal(d.reason, QD_REASON_NOT_PFAFFIAN);
    assert_int_equal(d.offset, at(text, "roll"));
    assert_int_equal(d.length, 4);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

static void singular_mass(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const char *text = "coordinates x, y\nT = x'^2/2\nV = y^2\n";
    qd_model *m;
    qd_diag d = derive_fail(ctx, text, &m);
    assert_int_equal(d.status, QD_ERR_SINGULAR);
    assert_int_equal(d.subject, QD_SUBJECT_STATEMENT);
    assert_string_equal(d.name, "T");
    assert_int_equal(d.reason, QD_REASON_SINGULAR_MASS);
    assert_int_equal(d.offset, at(text, "T ="));
    qd_model_free(m);
    qd_ctx_free(ctx);
}

static void hamiltonian_not_quadratic_in_p(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const char *text = "coordinates x\nmomenta p\nH = p^4/4 + x^2/2\n";
    qd_model *m;
    qd_diag d = derive_fail(ctx, text, &m);
    assert_int_equal(d.subject, QD_SUBJECT_STATEMENT);
    assert_string_equal(d.name, "H");
    assert_int_equal(d.reason, QD_REASON_NOT_QUADRATIC);
    assert_int_equal(d.offset, at(text, "H ="));
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* `qdot hamiltonian` on L quartic in y': was "not linear in y'" with no
 * place and no hint; now H is implicit, and L linear in x' is the error,
 * located at the coordinate. */
static void lagrangian_not_quadratic(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const char *text = "coordinates x, y\nL = x'^2/2 + y'^4/4 - x^2\n";
    qd_model *m = parse_ok(ctx, text);
    qd_eom *e = qd_eom_derive(ctx, m);
    assert_non_null(e); /* 3 y'^2 y'' = 0: still linear in the accelerations */
    qd_ham *h = qd_ham_derive(ctx, m, e);
    assert_non_null(h);
    assert_true(h->implicit);
    qd_ham_free(h);
    qd_eom_free(e);
    qd_model_free(m);
    text = "coordinates y, x\nL = x'*y - y'^4/4\n";
    m = parse_ok(ctx, text);
    assert_int_equal(qd_ham_regular(ctx, m), QD_ERR_SINGULAR);
    qd_diag d = *qd_ctx_diag(ctx);
    assert_int_equal(d.subject, QD_SUBJECT_COORD);
    assert_int_equal(d.index, 1);
    assert_int_equal(d.reason, QD_REASON_SINGULAR_MASS);
    assert_non_null(strstr(d.hint, "x'"));
    assert_true(qd_model_locate(m, &d));
    assert_int_equal(d.offset, at(text, "x\n"));
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* A record with no subject is not placed; the first subject is kept. */
static void subject_rules(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse_ok(ctx, "coordinates x\nT = x'^2/2\n");
    qd_ctx_error(ctx, QD_ERR_ARG, "a bad argument");
    qd_diag d = *qd_ctx_diag(ctx);
    assert_int_equal(d.subject, QD_SUBJECT_NONE);
    assert_false(qd_model_locate(m, &d));
    assert_false(d.located);
    qd_ctx_error_about(ctx, QD_SUBJECT_COORD, 0, NULL, QD_REASON_NONE, "first");
    qd_ctx_error_about(ctx, QD_SUBJECT_STATEMENT, 0, "T", QD_REASON_NONE, "second");
    d = *qd_ctx_diag(ctx);
    assert_int_equal(d.subject, QD_SUBJECT_COORD);
    assert_string_equal(d.hint, "first");
    assert_true(qd_model_locate(m, &d)); /* the coordinate x by its index */
    assert_int_equal(d.offset, 12);
    qd_ctx_clear_error(ctx);
    assert_int_equal(qd_ctx_diag(ctx)->subject, QD_SUBJECT_NONE);
    assert_int_equal(qd_ctx_diag(ctx)->status, QD_OK);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(inconsistent_constraints),
        cmocka_unit_test(redundant_constraints),
        cmocka_unit_test(not_pfaffian),
        cmocka_unit_test(singular_mass),
        cmocka_unit_test(hamiltonian_not_quadratic_in_p),
        cmocka_unit_test(lagrangian_not_quadratic),
        cmocka_unit_test(subject_rules),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
