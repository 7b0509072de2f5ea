/*
 * tests/model/test_params.c - parameters as input: a parameter defined from
 * earlier ones follows them whether the value comes from the text, from
 * qd_model_parse_opts (the command line's --set) or from qd_model_set_param;
 * statements added to a parsed model (qd_model_add_statement); the names a
 * parameter or function may share with an energy (L, V).
 *
 * The physics asserted: a simple pendulum of length l has w^2 = g/l for
 * small swings (Desloge ch. 22; Goldstein sec. 1.6), so with l = 2*a and a
 * given as 3 the frequency must be g/6: the stale l = 2 of a patched model
 * would give g/2.
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
    "parameters m = 1, a = 1, l = 2*a, g = 9.81\n"
    "initial th = a/10\n"
    "T = m/2*l^2*th'^2\n"
    "V = -m*g*l*cos(th)\n";

static qd_model *parse(qd_ctx *ctx, const char *text, const qd_model_opts *o) {
    qd_diag d;
    memset(&d, 0, sizeof d);
    qd_model *m = qd_model_parse_opts(ctx, text, o, &d);
    if (!m)
        fail_msg("%zu:%zu: %s [hint: %s]", d.line, d.col, d.message, d.hint);
    return m;
}

static double num(qd_ctx *ctx, const qd_expr *x) {
    double v = NAN;
    assert_int_equal(qd_eval(ctx, x, 0, NULL, NULL, &v), QD_OK);
    return v;
}

static double param(qd_ctx *ctx, const qd_model *m, const char *name) {
    for (size_t i = 0; i < qd_model_nparams(m); i++)
        if (!strcmp(qd_expr_name(qd_model_param(m, i)), name))
            return num(ctx, qd_model_param_value(m, i));
    fail_msg("no parameter %s", name);
    return NAN;
}

/* w^2 = V''(0) / (d^2 T / d th'^2) with every parameter at its value. */
static double omega2(qd_ctx *ctx, const qd_model *m) {
    size_t n = qd_model_nparams(m);
    const qd_expr *syms[8];
    double vals[8];
    assert_true(n + 1 <= 8);
    for (size_t i = 0; i < n; i++) {
        syms[i] = qd_model_param(m, i);
        vals[i] = num(ctx, qd_model_param_value(m, i));
    }
    const qd_expr *th = qd_model_coord(m, 0), *w = qd_jet(ctx, th, 1);
    syms[n] = th;
    vals[n] = 0;
    const qd_expr *K = qd_diff_n(ctx, qd_model_potential(m), th, 2);
    const qd_expr *M = qd_diff_n(ctx, qd_model_kinetic(m), w, 2);
    double k, mm;
    assert_int_equal(qd_eval(ctx, K, n + 1, syms, vals, &k), QD_OK);
    assert_int_equal(qd_eval(ctx, M, n + 1, syms, vals, &mm), QD_OK);
    return k / mm;
}

static void derived_follows_given(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    /* the text alone: l = 2, w^2 = g/2 */
    qd_model *m = parse(ctx, pendulum, NULL);
    assert_true(fabs(omega2(ctx, m) - 9.81 / 2) < 1e-12);
    qd_model_free(m);
    /* a = 3 given from outside, kept symbolic: l follows, w^2 = g/6 */
    qd_param_value set[] = {{"a", qd_int(ctx, 7)}, {"a", qd_int(ctx, 3)}}; /* the last wins */
    qd_model_opts o = {set, 2, false};
    m = parse(ctx, pendulum, &o);
    assert_true(param(ctx, m, "l") == 6);
    assert_true(fabs(omega2(ctx, m) - 9.81 / 6) < 1e-12);
    assert_true(qd_has(qd_model_potential(m), qd_lookup(ctx, "a")) ||
                qd_has(qd_model_potential(m), qd_lookup(ctx, "l")));
    /* the definition is kept as written; the initial value follows too */
    const qd_expr *two_a = qd_mul(ctx, qd_int(ctx, 2), qd_lookup(ctx, "a"));
    assert_ptr_equal(qd_model_param_definition(m, 2), two_a);
    assert_true(fabs(num(ctx, qd_model_initial(m, 0, 0)) - 0.3) < 1e-15);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

static void fixed_is_written_in(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_param_value set[] = {{"l", qd_rat(ctx, 1, 2)}};
    qd_model_opts o = {set, 1, true};
    qd_model *m = parse(ctx, pendulum, &o);
    const qd_expr *l = qd_lookup(ctx, "l");
    assert_false(qd_has(qd_model_kinetic(m), l));
    assert_false(qd_has(qd_model_potential(m), l));
    assert_true(fabs(omega2(ctx, m) - 9.81 / 0.5) < 1e-12);
    /* a fixed parameter is a constant of this model */
    assert_int_equal(qd_model_set_param(ctx, m, "l", qd_int(ctx, 1)), QD_ERR_ARG);
    qd_ctx_clear_error(ctx);
    qd_model_free(m);
    /* a parameter defined from a fixed one is fixed too: l = 2*a, a = 3 */
    qd_param_value a3[] = {{"a", qd_int(ctx, 3)}};
    o.params = a3;
    m = parse(ctx, pendulum, &o);
    assert_true(qd_model_param_fixed(m, 1) && qd_model_param_fixed(m, 2));
    assert_false(qd_model_param_fixed(m, 0) || qd_model_param_fixed(m, 3));
    assert_false(qd_has(qd_model_kinetic(m), l) || qd_has(qd_model_kinetic(m), qd_lookup(ctx, "a")));
    assert_true(fabs(omega2(ctx, m) - 9.81 / 6) < 1e-12);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

static void set_after_parse(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse(ctx, pendulum, NULL);
    assert_int_equal(qd_model_set_param(ctx, m, "a", qd_rat(ctx, 5, 2)), QD_OK);
    assert_true(param(ctx, m, "l") == 5);
    assert_true(fabs(omega2(ctx, m) - 9.81 / 5) < 1e-12);
    assert_true(fabs(num(ctx, qd_model_initial(m, 0, 0)) - 0.25) < 1e-15);
    /* setting l itself replaces its definition: a no longer moves it */
    assert_int_equal(qd_model_set_param(ctx, m, "l", qd_int(ctx, 1)), QD_OK);
    assert_int_equal(qd_model_set_param(ctx, m, "a", qd_int(ctx, 4)), QD_OK);
    assert_true(param(ctx, m, "l") == 1);
    /* an unknown name suggests the nearest; a value that is not a number */
    assert_int_equal(qd_model_set_param(ctx, m, "gg", qd_int(ctx, 1)), QD_ERR_ARG);
    assert_string_equal(qd_ctx_message(ctx), "unknown parameter 'gg'");
    qd_ctx_clear_error(ctx);
    assert_int_equal(qd_model_set_param(ctx, m, "g", qd_model_coord(m, 0)), QD_ERR_ARG);
    qd_ctx_clear_error(ctx);
    qd_model_free(m);
    /* a value that leaves a later parameter without a finite value is refused
     * and changes nothing */
    m = parse(ctx, "coordinates x\nparameters a = 2, b = sqrt(a - 1)\nT = b*x'^2\n", NULL);
    assert_int_equal(qd_model_set_param(ctx, m, "a", qd_int(ctx, 0)), QD_ERR_ARG);
    qd_ctx_clear_error(ctx);
    assert_true(param(ctx, m, "a") == 2 && param(ctx, m, "b") == 1);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

static void given_errors(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    /* a name no parameter has: not in the text (line 0), with the nearest */
    qd_param_value bad[] = {{"lenght", qd_int(ctx, 1)}};
    qd_model_opts o = {bad, 1, false};
    memset(&d, 0, sizeof d);
    assert_null(qd_model_parse_opts(ctx, "coordinates x\nparameters length = 1\nT = length*x'^2\n",
                                    &o, &d));
    assert_false(d.located);
    assert_string_equal(d.message, "unknown parameter 'lenght'; did you mean 'length'?");
    assert_int_equal(qd_ctx_status(ctx), QD_ERR_ARG);
    qd_ctx_clear_error(ctx);
    /* a value that is not a number */
    qd_param_value sym[] = {{"g", qd_lookup(ctx, "a")}};
    o.params = sym;
    assert_null(qd_model_parse_opts(ctx, pendulum, &o, &d));
    assert_false(d.located);
    qd_ctx_clear_error(ctx);
    /* a later parameter without a finite value: located at its value */
    qd_param_value zero[] = {{"a", qd_int(ctx, 0)}};
    o.params = zero;
    assert_null(qd_model_parse_opts(ctx, "coordinates x\nparameters a = 2, b = sqrt(a - 1)\n"
                                         "T = b*x'^2\n", &o, &d));
    assert_int_equal(d.line, 2);
    assert_int_equal(d.col, 23);
    assert_string_equal(d.message, "a parameter's value must be a finite real number");
    qd_ctx_clear_error(ctx);
    qd_ctx_free(ctx);
}

static void add_statements(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse(ctx, "coordinates x, y\nparameters m = 2\nT = m/2*(x'^2 + y'^2)\n", NULL);
    qd_diag d;
    memset(&d, 0, sizeof d);
    /* a rotation: xi = (-y, x), the generator of Lz = m (x y' - y x') */
    assert_int_equal(qd_model_add_statement(m, "symmetry rot: x -> x*cos(eps) - y*sin(eps), "
                                               "y -> x*sin(eps) + y*cos(eps)", &d), QD_OK);
    assert_int_equal(qd_model_nsymmetries(m), 1);
    assert_string_equal(qd_model_symmetry_name(m, 0), "rot");
    const qd_expr *x = qd_model_coord(m, 0), *y = qd_model_coord(m, 1);
    assert_ptr_equal(qd_model_symmetry_field(m, 0, 0), qd_neg(ctx, y));
    assert_ptr_equal(qd_model_symmetry_field(m, 0, 1), x);
    assert_int_equal(qd_model_add_statement(m, "integral Lz: m*(x*y' - y*x')", &d), QD_OK);
    assert_int_equal(qd_model_nintegrals(m), 1);
    assert_true(qd_model_where(m, "integral:Lz", &d) && d.line == 1 && d.col == 10);
    /* an error is located in the added text, and the model is as it was */
    const qd_expr *L = qd_model_lagrangian(m);
    assert_int_equal(qd_model_add_statement(m, "integral bad: x''", &d), QD_ERR_PARSE);
    assert_int_equal(d.line, 1);
    assert_int_equal(d.col, 15);
    assert_int_equal(qd_model_add_statement(m, "V = x^2 + (y", &d), QD_ERR_PARSE);
    assert_int_equal(qd_model_add_statement(m, "constraint c: x = y\nintegral I: x", &d),
                     QD_ERR_PARSE);
    assert_string_equal(d.message, "a second statement");
    assert_int_equal(qd_model_add_statement(m, "coordinates z", &d), QD_ERR_PARSE);
    assert_int_equal(qd_model_nintegrals(m), 1);
    assert_int_equal(qd_model_nconstraints(m), 0);
    assert_null(qd_model_potential(m));
    assert_ptr_equal(qd_model_lagrangian(m), L);
    /* an energy added after the parse enters L = T - V */
    assert_int_equal(qd_model_add_statement(m, "V = m*x^2", &d), QD_OK);
    const qd_expr *want = qd_sub(ctx, qd_model_kinetic(m), qd_model_potential(m));
    assert_true(qd_is_zero(qd_simplify(ctx, qd_sub(ctx, qd_model_lagrangian(m), want))));
    /* L made from T - V is not "given": L = ... may still be added, once */
    assert_false(qd_model_lagrangian_given(m));
    assert_int_equal(qd_model_add_statement(m, "L = m*x'^2", &d), QD_OK);
    assert_true(qd_model_lagrangian_given(m));
    assert_int_equal(qd_model_add_statement(m, "L = x'^2", &d), QD_ERR_PARSE);
    assert_string_equal(d.message, "L is given twice (first on line 1)");
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* docs/language.md: `functions V` with V = V(r), and a length called L. */
static void energy_names(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse(ctx, "coordinates r, th\nparameters m = 1\nfunctions V\n"
                             "T = m/2*(r'^2 + r^2*th'^2)\nV = V(r)\n", NULL);
    const qd_expr *r = qd_model_coord(m, 0);
    assert_true(qd_has(qd_model_potential(m), r));
    assert_false(qd_is_zero(qd_diff(ctx, qd_model_potential(m), r)));
    qd_model_free(m);
    /* a parameter L; `L = ...` is still the Lagrangian, made with it */
    m = parse(ctx, "coordinates th\nparameters m = 1, L = 2, g = 9.81\n"
                   "L = m/2*L^2*th'^2 + m*g*L*cos(th)\n", NULL);
    assert_true(qd_model_lagrangian_given(m));
    assert_true(qd_has(qd_model_lagrangian(m), qd_lookup(ctx, "L")));
    qd_model_free(m);
    m = parse(ctx, pendulum, NULL);
    qd_model_free(m);
    /* a coordinate still may not be called T: it would name a statement */
    qd_diag d;
    assert_null(qd_model_parse(ctx, "coordinates T\nL = T'^2\n", &d));
    assert_string_equal(d.message, "'T' is already a reserved name");
    qd_ctx_free(ctx);
}

/* A parameter positive when read is assumed positive: the double pendulum's
 * w^2 has sqrt(g^2*l1^2*l2^2*m2^2*...) (Desloge ch. 64), which must read
 * g*l1*l2*m2*sqrt(...) as in the books, not abs(g)*abs(l1)*...  A parameter
 * read as negative (a charge) stays real; a later change of sign is refused. */
static void positive_parameters(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse(ctx, "coordinates x\nparameters k = 4, m = 1\n"
                             "T = m/2*x'^2\nV = sqrt(k^2*m^2)/(2*m)*x^2\n", NULL);
    const qd_expr *k = qd_lookup(ctx, "k"), *x = qd_lookup(ctx, "x");
    assert_true(qd_symbol_is_positive(k));
    /* V = k x^2 / 2 exactly: the spring's potential */
    const qd_expr *want = qd_mul(ctx, qd_mul(ctx, qd_rat(ctx, 1, 2), k), qd_pow(ctx, x, qd_int(ctx, 2)));
    assert_ptr_equal(qd_model_potential(m), want);
    /* k = 4 -> -4 would break that: refused, nothing changed */
    assert_int_equal(qd_model_set_param(ctx, m, "k", qd_int(ctx, -4)), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(ctx), "positive"));
    qd_ctx_clear_error(ctx);
    assert_ptr_equal(qd_model_param_value(m, 0), qd_int(ctx, 4));
    assert_int_equal(qd_model_set_param(ctx, m, "k", qd_int(ctx, 9)), QD_OK);
    qd_model_free(m);
    /* the same name read as negative in the same context: a located error */
    qd_diag d;
    memset(&d, 0, sizeof d);
    assert_null(qd_model_parse(ctx, "coordinates x\nparameters k = -4\nT = x'^2\n", &d));
    assert_true(d.located);
    assert_int_equal(d.line, 2);
    assert_int_equal(d.col, 12);
    qd_ctx_free(ctx);
    /* in a context of its own, a negative value is real of either sign */
    ctx = qd_ctx_new();
    qd_model_opts o = {(qd_param_value[]){{"k", qd_int(ctx, -4)}}, 1, false};
    m = parse(ctx, "coordinates x\nparameters k = 4, m = 1\n"
                   "T = m/2*x'^2\nV = sqrt(k^2*m^2)/(2*m)*x^2\n", &o);
    k = qd_lookup(ctx, "k");
    x = qd_lookup(ctx, "x");
    assert_false(qd_symbol_is_positive(k));
    want = qd_mul(ctx, qd_mul(ctx, qd_rat(ctx, 1, 2), qd_fn(ctx, QD_ABS, k)),
                  qd_pow(ctx, x, qd_int(ctx, 2)));
    assert_ptr_equal(qd_model_potential(m), want);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(derived_follows_given),
        cmocka_unit_test(fixed_is_written_in),
        cmocka_unit_test(set_after_parse),
        cmocka_unit_test(given_errors),
        cmocka_unit_test(add_statements),
        cmocka_unit_test(energy_names),
        cmocka_unit_test(positive_parameters),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
