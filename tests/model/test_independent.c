/*
 * tests/model/test_independent.c - the calculus of variations in the model
 * language: `independent x` and isoperimetric constraints
 * `constraint NAME: integral(G) = l`.
 *
 * The Euler-Lagrange equations qdot derives for these models are checked
 * against the textbook extremals, which must satisfy them at every point:
 *   - the hanging chain, y = lambda/w + a*cosh((x - b)/a) (Desloge vol. 2,
 *     App. 32, Thm 5: an isoperimetric constraint has a constant
 *     multiplier; seed-desloge-D.md P19);
 *   - the brachistochrone's cycloid x = R(th - sin th), y = R(1 - cos th)
 *     (Desloge App. 32 Ex. 2, pp. 979-980; seed-desloge-D.md T35);
 *   - the sphere's great circles cot(theta) = k*cos(phi) (Byerly Art. 48
 *     and Appendix B; Desloge App. 32 Thm 3, Case 1).
 * y'' is taken from qd_eom_eval at the extremal's (x, y, y') and compared
 * with the closed form's own y''.  Diagnostics: message, line, column, span
 * and hint asserted exactly.
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
#include "qdot/mech.h"

static qd_model *parse_ok(qd_ctx *ctx, const char *text) {
    qd_diag d;
    memset(&d, 0, sizeof d);
    qd_model *m = qd_model_parse(ctx, text, &d);
    if (!m)
        fail_msg("%zu:%zu: %s [hint: %s]", d.line, d.col, d.message, d.hint);
    return m;
}

/* The y'' the model's Euler-Lagrange equation gives at (x, y, y'), with the
 * extra symbols (parameters, multipliers) set as given. */
static double ypp(qd_ctx *ctx, qd_eom *e, double x, double y, double yp, size_t nextra,
                  const qd_expr *const *extra, const double *xv) {
    const qd_expr *syms[8] = {e->q[0], e->qd[0], qd_time(ctx)};
    double vals[8] = {y, yp, x};
    for (size_t i = 0; i < nextra; i++) {
        syms[3 + i] = extra[i];
        vals[3 + i] = xv[i];
    }
    double acc = NAN;
    assert_int_equal(qd_eom_eval(ctx, e, 3 + nextra, syms, vals, NULL, NULL, &acc, NULL, NULL),
                     QD_OK);
    return acc;
}

static const char catenary[] = "independent x\n"
                               "coordinates y\n"
                               "parameters w = 2, l = 3\n"
                               "L = w*y*sqrt(1 + y'^2)\n"
                               "constraint length: integral(sqrt(1 + y'^2)) = l\n";

/* The half-width a of the chain of length l between (-d, 0) and (d, 0):
 * l = 2a sinh(d/a), by bisection (the left side falls from inf to 2d). */
static double catenary_a(double l, double d) {
    double lo = 0.05, hi = 100;
    for (int i = 0; i < 200; i++) {
        double a = (lo + hi) / 2;
        if (2 * a * sinh(d / a) > l)
            lo = a;
        else
            hi = a;
    }
    return (lo + hi) / 2;
}

/* The multiplier's residual on the curve y = c + a cosh((x - b)/a), as the
 * relative error of y''. */
static double catenary_residual(qd_ctx *ctx, qd_eom *e, const qd_model *m, double lambda,
                                double c, double a, double b) {
    const qd_expr *extra[] = {qd_model_param(m, 0), qd_model_isoperimetric_multiplier(m, 0)};
    const double xv[] = {2, lambda};
    double worst = 0;
    for (double x = -1; x <= 1.01; x += 0.25) {
        double u = (x - b) / a, want = cosh(u) / a;
        double got = ypp(ctx, e, x, c + a * cosh(u), sinh(u), 2, extra, xv);
        worst = fmax(worst, fabs(got - want) / fabs(want));
    }
    return worst;
}

static void catenary_extremal(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse_ok(ctx, catenary);
    assert_string_equal(qd_model_independent(m), "x");
    assert_int_equal(qd_model_nisoperimetric(m), 1);
    assert_string_equal(qd_model_isoperimetric_name(m, 0), "length");
    assert_string_equal(qd_expr_name(qd_model_isoperimetric_multiplier(m, 0)), "lambda_length");
    assert_null(qd_model_isoperimetric(m, 1));
    double l;
    assert_int_equal(qd_eval(ctx, qd_model_isoperimetric_value(m, 0), 0, NULL, NULL, &l), QD_OK);
    assert_true(l == 3);
    qd_eom *e = qd_eom_derive(ctx, m);
    assert_non_null(e);
    /* a chain of length 3 between (-1, 0) and (1, 0): b = 0, and y(1) = 0
     * gives lambda = -w a cosh(1/a) */
    double a = catenary_a(3, 1), w = 2, lambda = -w * a * cosh(1 / a);
    assert_true(fabs(2 * a * sinh(1 / a) - 3) < 1e-12);
    assert_true(catenary_residual(ctx, e, m, lambda, lambda / w, a, 0) < 1e-10);
    /* an off-centre chain too: any a, b with c = lambda/w */
    assert_true(catenary_residual(ctx, e, m, 0.7, 0.35, 1.3, 0.2) < 1e-10);
    /* the multiplier's sign matters: c = -lambda/w is not an extremal */
    assert_true(catenary_residual(ctx, e, m, 0.7, -0.35, 1.3, 0.2) > 1e-2);
    qd_eom_free(e);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* A parameter named lambda_NAME is the multiplier, so numeric work can
 * give it a value (--set lambda_length=...). */
static void parameter_multiplier(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse_ok(ctx, "independent x\ncoordinates y\n"
                                "parameters w = 2, lambda_length = 1/2\n"
                                "L = w*y*sqrt(1 + y'^2)\n"
                                "constraint length: integral(sqrt(1 + y'^2)) = 3\n");
    assert_true(qd_model_isoperimetric_multiplier(m, 0) == qd_model_param(m, 1));
    qd_eom *e = qd_eom_derive(ctx, m);
    assert_non_null(e);
    const qd_expr *extra[] = {qd_model_param(m, 0), qd_model_param(m, 1)};
    const double xv[] = {2, 0.25};
    /* (w y - lambda) y'' = w (1 + y'^2) at y = 1, y' = 1/2 */
    double got = ypp(ctx, e, 0.3, 1, 0.5, 2, extra, xv), want = 2 * 1.25 / (2 - 0.25);
    assert_true(fabs(got - want) < 1e-14);
    qd_eom_free(e);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* Desloge App. 32 Ex. 2: y'' = -1/(R (1 - cos th)^2) along the cycloid. */
static void brachistochrone_cycloid(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse_ok(ctx, "independent x\ncoordinates y\nparameters g = 9.8\n"
                                "L = sqrt((1 + y'^2)/(2*g*y))\n");
    qd_eom *e = qd_eom_derive(ctx, m);
    assert_non_null(e);
    const qd_expr *g = qd_model_param(m, 0);
    const double gv = 9.8, R = 1.3;
    for (double th = 0.5; th < 3.1; th += 0.6) {
        double c = 1 - cos(th), x = R * (th - sin(th)), y = R * c, yp = sin(th) / c;
        double want = -1 / (R * c * c), got = ypp(ctx, e, x, y, yp, 1, &g, &gv);
        if (fabs(got - want) > 1e-10 * fabs(want))
            fail_msg("th = %g: y'' = %.17g, the cycloid's is %.17g", th, got, want);
    }
    qd_eom_free(e);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* The great circle cot(theta) = k cos(phi): phi = acos(cot(theta)/k). */
static double circle_dphi(double th, double k) {
    double c = cos(th) / sin(th) / k;
    return 1 / (k * sin(th) * sin(th) * sqrt(1 - c * c));
}

static void sphere_great_circles(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse_ok(ctx, "independent theta\ncoordinates phi\nparameters R = 1.7\n"
                                "L = R*sqrt(1 + sin(theta)^2*phi'^2)\n");
    assert_string_equal(qd_model_independent(m), "theta");
    qd_eom *e = qd_eom_derive(ctx, m);
    assert_non_null(e);
    const qd_expr *R = qd_model_param(m, 0);
    const double Rv = 1.7, k = 2, h = 1e-5;
    for (double th = 0.7; th < 2.5; th += 0.4) {
        double phi = acos(cos(th) / sin(th) / k), dphi = circle_dphi(th, k);
        double want = (circle_dphi(th + h, k) - circle_dphi(th - h, k)) / (2 * h);
        double got = ypp(ctx, e, th, phi, dphi, 1, &R, &Rv);
        if (fabs(got - want) > 1e-7 * (1 + fabs(want)))
            fail_msg("theta = %g: phi'' = %.17g, the great circle's is %.17g", th, got, want);
    }
    /* a small circle (theta = const is not a geodesic off the equator):
     * phi' = const there, but the equation wants phi'' != 0 */
    assert_true(fabs(ypp(ctx, e, 0.8, 0, 1, 1, &R, &Rv)) > 0.1);
    qd_eom_free(e);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* The independent variable is the time symbol: a mechanical model written
 * with `independent s` has the same equations in s as in t. */
static void renamed_time(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *a = parse_ok(ctx, "coordinates q\nT = q'^2/2\nV = q^2/2 - q*cos(t)\n");
    qd_model *b = parse_ok(ctx, "independent s\ncoordinates q\nT = q'^2/2\nV = q^2/2 - q*cos(s)\n");
    assert_null(qd_model_independent(a));
    assert_true(qd_expr_cmp(qd_model_lagrangian(a), qd_model_lagrangian(b)) == 0);
    qd_model_free(a);
    qd_model_free(b);
    qd_ctx_free(ctx);
}

/* Isoperimetric terms stay in L (once) when a statement is added later. */
static void added_statement(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse_ok(ctx, "independent x\ncoordinates y\nT = y'^2/2\n"
                                "constraint area: integral(y) = 1\n");
    const qd_expr *L = qd_model_lagrangian(m);
    assert_true(qd_has(L, qd_model_isoperimetric_multiplier(m, 0)));
    assert_int_equal(qd_model_add_statement(m, "initial y = 1", NULL), QD_OK);
    assert_true(qd_expr_cmp(qd_model_lagrangian(m), L) == 0);
    qd_diag d;
    memset(&d, 0, sizeof d);
    assert_int_equal(qd_model_add_statement(m, "constraint c2: integral(y^2) = 1", &d),
                     QD_ERR_PARSE);
    assert_string_equal(d.message, "an isoperimetric constraint cannot be added to a model already read");
    assert_int_equal(qd_model_nisoperimetric(m), 1);
    assert_true(qd_expr_cmp(qd_model_lagrangian(m), L) == 0);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

typedef struct bad {
    const char *text;
    size_t line, col, length;
    const char *message, *hint;
} bad;

static const bad bad_models[] = {
    {"independent x\nindependent s\ncoordinates y\nL = y'^2\n", 2, 1, 13,
     "the independent variable is declared twice", "declared on line 1"},
    {"independent x\ncoordinates x\nL = x'^2\n", 2, 13, 1,
     "'x' is already an independent variable", "choose another name for the coordinate"},
    {"coordinates y\nindependent x\nL = y'^2\n", 2, 1, 13,
     "the independent variable must be declared before the coordinates",
     "move it above the coordinates"},
    {"independent t\ncoordinates y\nL = y'^2\n", 1, 13, 1, "'t' is already a built-in name",
     "choose another name for the independent variable"},
    {"independent theta\ncoordinates y\nL = y'^2 + thet\n", 3, 12, 4, "unknown name 'thet'",
     "did you mean 'theta'?"},
    {"independent x\ncoordinates y\nL = y*integral(y)\n", 3, 7, 8,
     "integral() is only meaningful in a constraint", "constraint length: integral("},
    {"independent x\ncoordinates y\nL = y'^2\nconstraint c: integral(2*3) = 1\n", 4, 24, 3,
     "this integral does not depend on the path", "a function of the coordinates"},
    {"independent x\ncoordinates y\nL = y'^2\nconstraint c: integral(y)\n", 4, 26, 1,
     "expected '=' and the integral's value", "integral(sqrt(1 + y'^2)) = l"},
    {"independent x\ncoordinates y\nL = y'^2\nconstraint c: integral(y) = y\n", 4, 29, 1,
     "an isoperimetric value must be a number, but it depends on 'y'", NULL},
    {"independent x\ncoordinates y\nL = y'^2\nconstraint c: integral(y) = 1\n"
     "constraint c: y = 2\n", 5, 12, 1, "constraint 'c' is named twice", "its own name"},
    {"coordinates y\nmomenta p\nH = p^2/2\nconstraint c: integral(y) = 1\n", 4, 15, 8,
     "an isoperimetric constraint needs a Lagrangian, not H", "L = ..."},
    {"coordinates y\nconstraint c: integral(y) = 1\nmomenta p\nH = p^2/2\n", 4, 1, 1,
     "an isoperimetric constraint needs a Lagrangian, not H", "L = ..."},
};

static void diagnostics(void **state) {
    (void)state;
    for (size_t i = 0; i < sizeof bad_models / sizeof bad_models[0]; i++) {
        const bad *b = &bad_models[i];
        qd_ctx *ctx = qd_ctx_new();
        qd_diag d;
        memset(&d, 0, sizeof d);
        qd_model *m = qd_model_parse(ctx, b->text, &d);
        if (m)
            fail_msg("case %zu parsed but must fail: %s", i, b->text);
        if (d.line != b->line || d.col != b->col || d.length != b->length ||
            strcmp(d.message, b->message) || (b->hint && !strstr(d.hint, b->hint)))
            fail_msg("case %zu: got %zu:%zu+%zu: %s [hint: %s]; want %zu:%zu+%zu: %s [hint: %s]",
                     i, d.line, d.col, d.length, d.message, d.hint, b->line, b->col, b->length,
                     b->message, b->hint ? b->hint : "-");
        qd_ctx_free(ctx);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(catenary_extremal),
        cmocka_unit_test(parameter_multiplier),
        cmocka_unit_test(brachistochrone_cycloid),
        cmocka_unit_test(sphere_great_circles),
        cmocka_unit_test(renamed_time),
        cmocka_unit_test(added_statement),
        cmocka_unit_test(diagnostics),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
