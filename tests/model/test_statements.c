/*
 * tests/model/test_statements.c - the statements `momenta`, `H =`,
 * `symmetry` and `integral`: what they mean, and every diagnostic they give
 * (message, line and column asserted exactly).
 *
 * The symmetry fields are checked against the generators a textbook writes
 * for them: a rotation x -> x cos eps - y sin eps, y -> x sin eps + y cos eps
 * has xi = (-y, x) (Desloge ch. 56, the invariance behind the angular
 * momentum; Goldstein sec. 13.7), a translation xi = 1, a scaling
 * x -> x exp(eps) has xi = x.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <string.h>

#include "qdot/qdot.h"
#include "qdot/model.h"

static qd_model *parse_ok(qd_ctx *ctx, const char *text) {
    qd_diag d;
    memset(&d, 0, sizeof d);
    qd_model *m = qd_model_parse(ctx, text, &d);
    if (!m)
        fail_msg("%zu:%zu: %s [hint: %s]", d.line, d.col, d.message, d.hint);
    return m;
}

/* e equals the model-language text want (read with the same symbols). */
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

static void hamiltonian_model(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse_ok(ctx, "coordinates r, theta\nparameters m = 1, k = 2\n"
                                "momenta p_r, p_theta\n"
                                "H = p_r^2/(2*m) + p_theta^2/(2*m*r^2) - k/r\n");
    assert_true(qd_model_hamiltonian_given(m));
    assert_string_equal(qd_expr_name(qd_model_momentum(m, 0)), "p_r");
    assert_string_equal(qd_expr_name(qd_model_momentum(m, 1)), "p_theta");
    assert_null(qd_model_momentum(m, 2));
    assert_is(ctx, qd_model_hamiltonian(m), "p_r^2/(2*m) + p_theta^2/(2*m*r^2) - k/r");
    assert_null(qd_model_kinetic(m));
    assert_null(qd_model_lagrangian(m)); /* the mechanics layer's inverse Legendre */
    assert_false(qd_model_lagrangian_given(m));
    qd_diag w;
    assert_true(qd_model_where(m, "H", &w));
    assert_int_equal(w.line, 4);
    assert_int_equal(w.col, 1);
    assert_true(qd_model_where(m, "momenta", &w));
    assert_int_equal(w.line, 3);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* momenta with T only rename p_<q>; the model is still a Lagrangian one. */
static void momenta_rename(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse_ok(ctx, "coordinates x\nmomenta px\nT = x'^2/2\n");
    assert_false(qd_model_hamiltonian_given(m));
    assert_null(qd_model_hamiltonian(m));
    assert_string_equal(qd_expr_name(qd_model_momentum(m, 0)), "px");
    assert_non_null(qd_model_lagrangian(m));
    qd_model_free(m);
    m = parse_ok(ctx, "coordinates x\nT = x'^2/2\n");
    assert_null(qd_model_momentum(m, 0));
    assert_int_equal(qd_model_nsymmetries(m), 0);
    assert_int_equal(qd_model_nintegrals(m), 0);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

static void symmetries(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse_ok(ctx,
        "coordinates x, y, z\nparameters w = 2\nT = (x'^2 + y'^2 + z'^2)/2\n"
        "symmetry rot: x -> x*cos(eps) - y*sin(eps), y -> x*sin(eps) + y*cos(eps)\n"
        "symmetry z -> z + eps\n"
        "symmetry delta x = -y, delta y = x\n"
        "symmetry scale: x -> x*exp(eps), y -> y*exp(eps), z -> z*exp(eps)\n"
        "symmetry screw: z -> z + w*t*eps\n");
    assert_int_equal(qd_model_nsymmetries(m), 5);
    assert_string_equal(qd_model_symmetry_name(m, 0), "rot");
    assert_string_equal(qd_model_symmetry_name(m, 1), "s2");
    assert_string_equal(qd_model_symmetry_name(m, 2), "s3");
    assert_string_equal(qd_model_symmetry_name(m, 3), "scale");
    assert_is(ctx, qd_model_symmetry_field(m, 0, 0), "-y");
    assert_is(ctx, qd_model_symmetry_field(m, 0, 1), "x");
    assert_true(qd_is_zero(qd_model_symmetry_field(m, 0, 2)));
    assert_true(qd_is_zero(qd_model_symmetry_field(m, 1, 0)));
    assert_true(qd_is_one(qd_model_symmetry_field(m, 1, 2)));
    /* the field form gives the rotation's field directly */
    for (size_t j = 0; j < 3; j++)
        assert_ptr_equal(qd_model_symmetry_field(m, 2, j), qd_model_symmetry_field(m, 0, j));
    assert_is(ctx, qd_model_symmetry_field(m, 3, 2), "z");
    assert_is(ctx, qd_model_symmetry_field(m, 4, 2), "w*t");
    assert_null(qd_model_symmetry_field(m, 5, 0));
    assert_null(qd_model_symmetry_field(m, 0, 3));
    assert_null(qd_model_symmetry_name(m, 5));
    qd_diag w;
    assert_true(qd_model_where(m, "symmetry:rot", &w));
    assert_int_equal(w.line, 4);
    assert_int_equal(w.col, 10);
    assert_true(qd_model_where(m, "symmetry:s2", &w));
    assert_int_equal(w.line, 5);
    assert_int_equal(w.col, 10);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

static void integrals(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse_ok(ctx, "coordinates x, y\nparameters m = 3\n"
                                "T = m/2*(x'^2 + y'^2)\n"
                                "integral Lz: m*(x*y' - y*x')\n"
                                "integral m/2*(x'^2 + y'^2)\n");
    assert_int_equal(qd_model_nintegrals(m), 2);
    assert_string_equal(qd_model_integral_name(m, 0), "Lz");
    assert_string_equal(qd_model_integral_name(m, 1), "I2");
    assert_is(ctx, qd_model_integral(m, 0), "m*(x*y' - y*x')");
    assert_null(qd_model_integral(m, 2));
    assert_null(qd_model_integral_name(m, 2));
    qd_diag w;
    assert_true(qd_model_where(m, "integral:Lz", &w));
    assert_int_equal(w.line, 4);
    assert_int_equal(w.col, 10);
    assert_true(qd_model_where(m, "integral:I2", &w));
    assert_int_equal(w.line, 5);
    assert_int_equal(w.col, 10);
    qd_model_free(m);
    /* in a model given by H, integrals are written in the momenta */
    m = parse_ok(ctx, "coordinates r, theta\nmomenta p_r, p_theta\nintegral p_theta\n"
                      "H = p_r^2/2 + p_theta^2/(2*r^2)\n");
    assert_int_equal(qd_model_nintegrals(m), 1);
    assert_string_equal(qd_expr_name(qd_model_integral(m, 0)), "p_theta");
    qd_model_free(m);
    /* the words stay usable as names defined before they were keywords */
    m = parse_ok(ctx, "coordinates x\nintegral = 2\nsymmetry = 3\nmomenta = 4\n"
                      "T = integral*symmetry*momenta*x'^2\n");
    qd_model_free(m);
    qd_ctx_free(ctx);
}

typedef struct bad {
    const char *text;
    size_t line, col;
    const char *message;  /* the start of the message */
    const char *hint;     /* a part of the hint, or NULL */
} bad;

#define KEPLER "coordinates r, theta\nparameters m = 1\n"

static const bad bad_models[] = {
    /* momenta */
    {KEPLER "momenta p_r\nH = p_r^2\n", 3, 9, "1 momentum for 2 coordinates",
     "momenta p_r, p_theta"},
    {KEPLER "momenta p_r, p_theta, p_z\n", 3, 23, "more momenta than coordinates",
     "there are 2 coordinates"},
    {"momenta p\ncoordinates q\n", 1, 1, "momenta before any coordinates", NULL},
    {KEPLER "momenta a, b\nmomenta c, d\n", 4, 1, "momenta are declared twice (first on line 3)",
     NULL},
    {KEPLER "momenta p, p\n", 3, 12, "momentum 'p' is named twice", NULL},
    {KEPLER "momenta m, p\n", 3, 9, "'m' is already a parameter", NULL},
    {KEPLER "momenta p_r, r\n", 3, 14, "'r' is already a coordinate", NULL},
    {KEPLER "momenta p_r, p_theta\ncoordinates z\n", 4, 1, "coordinates after the momenta", NULL},
    {KEPLER "momenta p_r, 3\n", 3, 14, "expected a momentum's name, found a number", NULL},
    {KEPLER "momenta\n", 3, 8, "expected a momentum's name, found the end of the line", NULL},
    {KEPLER "momenta p_r, p_theta\nV = p_r\nT = r'^2\n", 4, 5,
     "'p_r' is a momentum, which means nothing here", "H = ..."},
    /* H */
    {KEPLER "H = r^2\n", 3, 1, "H is given before the momenta", "momenta p_r, p_theta"},
    {KEPLER "T = r'^2\nmomenta p_r, p_theta\nH = p_r^2\n", 5, 1, "H cannot be given with T", NULL},
    {KEPLER "particle m at (r, 0)\nmomenta p_r, p_theta\nH = p_r^2\n", 5, 1,
     "H cannot be given with T (from particles or bodies)", NULL},
    {KEPLER "L = r'^2\nmomenta p_r, p_theta\nH = p_r^2\n", 5, 1, "H cannot be given with L", NULL},
    {KEPLER "momenta p_r, p_theta\nH = p_r^2\nT = r'^2\n", 5, 1,
     "T cannot be given with H (line 4)", "either H"},
    {KEPLER "momenta p_r, p_theta\nH = p_r^2\nV = r\n", 5, 1, "V cannot be given with H (line 4)",
     NULL},
    {KEPLER "momenta p_r, p_theta\nH = p_r^2\nL = r'^2\n", 5, 1,
     "L cannot be given with H (line 4)", NULL},
    {KEPLER "momenta p_r, p_theta\nH = p_r^2\nparticle m at (r, 0)\n", 5, 1,
     "a particle cannot be given with H (line 4)", NULL},
    {KEPLER "momenta p_r, p_theta\nH = p_r^2\nbody b mass m inertia (1, 1, 1) at (r, 0)\n", 5, 1,
     "a body cannot be given with H (line 4)", NULL},
    {KEPLER "momenta p_r, p_theta\nH = p_r^2\nH = p_theta^2\n", 5, 1,
     "H is given twice (first on line 4)", NULL},
    {KEPLER "momenta p_r, p_theta\nH = p_r^2/2 + r'*p_r\n", 4, 5, "H depends on the velocity r'",
     "the momenta (p_r, ...)"},
    {KEPLER "momenta p_r, p_theta\nH = (p_r, p_theta)\n", 4, 5,
     "a vector where a scalar is needed: H is a scalar", NULL},
    {KEPLER "momenta p_r, p_theta\nH = p_x^2\n", 4, 5, "unknown name 'p_x'", "did you mean"},
    {"coordinates q\nV = q^2\n", 3, 1, "neither T nor L is given", "momenta and H"},
    {"H = 1\n", 1, 1, "H is given before the momenta", "coordinates and momenta"},
    /* symmetry */
    {"coordinates x, y\nT = x'^2\nsymmetry x -> 2*x + eps\n", 3, 15, "at eps = 0 this is not x",
     "x -> x + eps*(...)"},
    {"coordinates x, y\nT = x'^2\nsymmetry z -> z + eps\n", 3, 10, "'z' is not a coordinate",
     NULL},
    {"coordinates x, y\nT = x'^2\nsymmetry x -> x + eps, x -> x\n", 3, 24, "'x' is moved twice",
     NULL},
    {"coordinates x, y\nT = x'^2\nsymmetry delta x = 1, y -> y\n", 3, 23,
     "one symmetry mixes 'delta q = ...' with 'q -> ...'", NULL},
    {"coordinates x, y\nT = x'^2\nsymmetry x -> x, y -> y\n", 3, 1, "this symmetry moves nothing",
     NULL},
    {"coordinates x, y\nT = x'^2\nsymmetry delta x = 0\n", 3, 1, "this symmetry moves nothing",
     NULL},
    {"coordinates x, y\nT = x'^2\nsymmetry x -> x + eps*x'\n", 3, 15,
     "a symmetry depends on the velocity x'", NULL},
    {"coordinates x, y\nparameters eps = 1\nT = x'^2\nsymmetry x -> x + eps\n", 4, 1,
     "'eps' is the symmetry's parameter, but the model has a parameter named eps", NULL},
    {"coordinates x, y\nT = x'^2\nsymmetry x = x + eps\n", 3, 12, "expected '->', found '='",
     "delta"},
    {"coordinates x, y\nT = x'^2\nsymmetry a: x -> x + eps\nsymmetry a: y -> y + eps\n", 4, 10,
     "symmetry 'a' is named twice", NULL},
    {"coordinates x, y\nT = x'^2\nsymmetry delta x = eps\n", 3, 20, "unknown name 'eps'", NULL},
    {"coordinates x, y\nT = x'^2 + eps\n", 2, 12, "unknown name 'eps'", NULL},
    {"symmetry x -> x + eps\ncoordinates x\n", 1, 1, "a symmetry before any coordinates", NULL},
    {"coordinates x, y\nT = x'^2\nsymmetry 2 -> x\n", 3, 10, "expected a coordinate, found a number",
     NULL},
    {"coordinates x, y\nT = x'^2\nsymmetry delta x -> 1\n", 3, 18, "expected '=', found '-'",
     "delta x = -y"},
    {"coordinates x, y\nT = x'^2\nsymmetry delta x = 1,\n", 3, 22,
     "expected 'delta q = ...', found the end of the line", NULL},
    {"coordinates x, y\nparameters k = 1\nT = x'^2\nsymmetry x -> x + k*eps\nV = eps\n", 5, 5,
     "unknown name 'eps'", NULL},
    /* integral */
    {"coordinates x\nT = x'^2\nintegral 3\n", 3, 10, "this integral is a constant", NULL},
    {"coordinates x\nT = x'^2\nintegral x''\n", 3, 10,
     "an integral depends on the acceleration x''", NULL},
    {"coordinates x\nT = x'^2\nintegral E: x'^2\nintegral E: x\n", 4, 10,
     "integral 'E' is named twice", NULL},
    {"coordinates x\nmomenta p\nT = x'^2\nintegral P: p\n", 4, 10,
     "an integral depends on the momentum p, but the model gives no H", "velocities"},
    {"coordinates x\nmomenta p\nH = p^2/2\nintegral x'^2 + p\n", 4, 10,
     "an integral of a Hamiltonian model depends on the velocity x'", "momenta"},
    {"coordinates x\nT = x'^2\nintegral (x, x)\n", 3, 10, "a vector where a scalar is needed",
     NULL},
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
        if (d.line != b->line || d.col != b->col ||
            strncmp(d.message, b->message, strlen(b->message)) ||
            (b->hint && !strstr(d.hint, b->hint)))
            fail_msg("case %zu: got %zu:%zu: %s [hint: %s]; want %zu:%zu: %s [hint: %s]", i,
                     d.line, d.col, d.message, d.hint, b->line, b->col, b->message,
                     b->hint ? b->hint : "-");
        qd_ctx_free(ctx);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(hamiltonian_model),
        cmocka_unit_test(momenta_rename),
        cmocka_unit_test(symmetries),
        cmocka_unit_test(integrals),
        cmocka_unit_test(diagnostics),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
