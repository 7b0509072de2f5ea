/*
 * tests/model/test_parse.c - the model language: what it means, and every
 * diagnostic it must give (message, line, column asserted exactly, jq style).
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
#include "util/randexpr.h"

/* Issue 3's double pendulum, verbatim. */
static const char *double_pendulum =
    "# Double pendulum\n"
    "coordinates theta1, theta2\n"
    "parameters m1 = 1, m2 = 1, l1 = 1, l2 = 1, g = 9.81\n"
    "\n"
    "x1 = l1*sin(theta1)\n"
    "y1 = -l1*cos(theta1)\n"
    "x2 = x1 + l2*sin(theta2)\n"
    "y2 = y1 - l2*cos(theta2)\n"
    "\n"
    "T = m1/2*(x1'^2 + y1'^2) + m2/2*(x2'^2 + y2'^2)\n"
    "V = m1*g*y1 + m2*g*y2\n"
    "\n"
    "initial theta1 = 0.5, theta2 = 0, theta1' = 0, theta2' = 0\n";

static double value_at(qd_ctx *ctx, const qd_expr *e, size_t n, const qd_expr *const *s,
                       const double *v) {
    double r = NAN;
    assert_int_equal(qd_eval(ctx, e, n, s, v, &r), QD_OK);
    return r;
}

/* T of the double pendulum equals the textbook form (Goldstein ch. 1;
 * reference seed-goldstein-britannica.md): T = (m1+m2)/2 l1^2 t1'^2 +
 * m2/2 l2^2 t2'^2 + m2 l1 l2 t1' t2' cos(t1 - t2); V = -(m1+m2) g l1 cos t1 - m2 g l2 cos t2. */
static void double_pendulum_meaning(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, double_pendulum, &d);
    assert_non_null(m);
    assert_int_equal(qd_model_ncoords(m), 2);
    assert_int_equal(qd_model_nparams(m), 5);
    assert_ptr_equal(qd_model_param_value(m, 4), qd_rat(ctx, 981, 100)); /* 9.81 is exact */
    assert_ptr_equal(qd_model_initial(m, 0, 0), qd_rat(ctx, 1, 2));
    assert_null(qd_model_initial(m, 0, 2));
    const qd_expr *q1 = qd_model_coord(m, 0), *q2 = qd_model_coord(m, 1);
    const qd_expr *s[9] = {q1, q2, qd_jet(ctx, q1, 1), qd_jet(ctx, q2, 1), qd_model_param(m, 0),
                           qd_model_param(m, 1), qd_model_param(m, 2), qd_model_param(m, 3),
                           qd_model_param(m, 4)};
    qt_rng r = {11};
    for (int k = 0; k < 20; k++) {
        double v[9];
        for (int i = 0; i < 9; i++)
            v[i] = qt_uniform(&r, i < 4 ? -3 : 0.5, i < 4 ? 3 : 2);
        double t1 = v[0], t2 = v[1], w1 = v[2], w2 = v[3], m1 = v[4], m2 = v[5], l1 = v[6],
               l2 = v[7], g = v[8];
        double T = (m1 + m2) / 2 * l1 * l1 * w1 * w1 + m2 / 2 * l2 * l2 * w2 * w2 +
                   m2 * l1 * l2 * w1 * w2 * cos(t1 - t2);
        double V = -(m1 + m2) * g * l1 * cos(t1) - m2 * g * l2 * cos(t2);
        assert_true(fabs(value_at(ctx, qd_model_kinetic(m), 9, s, v) - T) < 1e-12 * (1 + fabs(T)));
        assert_true(fabs(value_at(ctx, qd_model_potential(m), 9, s, v) - V) < 1e-12 * (1 + fabs(V)));
        assert_true(fabs(value_at(ctx, qd_model_lagrangian(m), 9, s, v) - (T - V)) <
                    1e-12 * (1 + fabs(T - V)));
    }
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* Vectors, particles, forces, U, dissipation, Q[...], functions, continuation. */
static void language_features(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const char *text =
        "coordinates x, y\n"
        "parameters m = 2, c = 1/2, k = 3, e = 5\n"
        "functions W\n"
        "r = (x, y)        # a planar position: z = 0\n"
        "particle m at r\n"
        "V = k/2*dot(r, r) + W(norm(r))\n"
        "U = e*dot(cross((0, 0, 1), r), r')\n"
        "dissipation = c/2*(x'^2 +\n"
        "    y'^2)\n"
        "force (0, -m) at r + (1, 0, 0)\n"
        "Q[x] = -x'^3\n";
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, text, &d);
    if (!m)
        fail_msg("%zu:%zu: %s", d.line, d.col, d.message);
    const qd_expr *x = qd_model_coord(m, 0), *y = qd_model_coord(m, 1);
    const qd_expr *xd = qd_jet(ctx, x, 1), *yd = qd_jet(ctx, y, 1);
    const qd_expr *mm = qd_lookup(ctx, "m"), *k = qd_lookup(ctx, "k"), *e = qd_lookup(ctx, "e");
    assert_int_equal(qd_symbol_role(e), QD_ROLE_PARAM); /* a parameter named e shadows the constant */
    /* T = m/2 (x'^2 + y'^2) exactly */
    const qd_expr *T = qd_mul_n(ctx, 3, (const qd_expr *[]){qd_rat(ctx, 1, 2), mm,
        qd_add(ctx, qd_powi(ctx, xd, 2), qd_powi(ctx, yd, 2))});
    assert_ptr_equal(qd_expand(ctx, qd_model_kinetic(m)), qd_expand(ctx, T));
    /* U = e (z x r) . r' = e (x y' - y x') */
    const qd_expr *U = qd_mul(ctx, e, qd_sub(ctx, qd_mul(ctx, x, yd), qd_mul(ctx, y, xd)));
    assert_ptr_equal(qd_expand(ctx, qd_model_gen_potential(m)), qd_expand(ctx, U));
    /* Q_y from the force (0, -m): -m; Q_x from Q[x] = -x'^3 only */
    assert_ptr_equal(qd_model_force(m, 1), qd_neg(ctx, mm));
    assert_ptr_equal(qd_model_force(m, 0), qd_neg(ctx, qd_powi(ctx, xd, 3)));
    assert_non_null(qd_model_dissipation(m));
    /* V contains the user function W of the radius */
    const qd_expr *rad = qd_sqrt(ctx, qd_add(ctx, qd_powi(ctx, x, 2), qd_powi(ctx, y, 2)));
    const qd_expr *W = qd_ufunc(ctx, "W", 1, &rad);
    assert_true(qd_has(qd_model_potential(m), W));
    (void)k;
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* Constraints: named or numbered, stored as lhs - rhs, located. */
static void constraints(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const char *text = "coordinates x1, x2, y\nparameters l = 3\nT = x1'^2 + x2'^2 + y'^2\n"
                       "constraint rope: x1 + x2 = l\n"
                       "constraint y' = x1*x2'\n"
                       "constraint x1*t\n";
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, text, &d);
    if (!m)
        fail_msg("%zu:%zu: %s", d.line, d.col, d.message);
    assert_int_equal(qd_model_nconstraints(m), 3);
    assert_string_equal(qd_model_constraint_name(m, 0), "rope");
    assert_string_equal(qd_model_constraint_name(m, 1), "c2");
    assert_string_equal(qd_model_constraint_name(m, 2), "c3");
    const qd_expr *x1 = qd_model_coord(m, 0), *x2 = qd_model_coord(m, 1), *y = qd_model_coord(m, 2);
    assert_ptr_equal(qd_model_constraint(m, 0),
                     qd_sub(ctx, qd_add(ctx, x1, x2), qd_lookup(ctx, "l")));
    assert_ptr_equal(qd_model_constraint(m, 1),
                     qd_sub(ctx, qd_jet(ctx, y, 1), qd_mul(ctx, x1, qd_jet(ctx, x2, 1))));
    assert_true(qd_model_where(m, "constraint:rope", &d));
    assert_int_equal(d.line, 4);
    assert_int_equal(d.col, 12);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* A rheonomic model: a bead on a wire turning as omega*t. */
static void time_dependent(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const char *text = "coordinates r\nparameters m = 1, omega = 2\n"
                       "particle m at (r*cos(omega*t), r*sin(omega*t))\n";
    qd_model *m = qd_model_parse(ctx, text, NULL);
    assert_non_null(m);
    const qd_expr *r = qd_model_coord(m, 0), *om = qd_lookup(ctx, "omega");
    const qd_expr *mm = qd_lookup(ctx, "m");
    /* T = m/2 (r'^2 + r^2 omega^2) */
    const qd_expr *T = qd_mul_n(ctx, 3, (const qd_expr *[]){qd_rat(ctx, 1, 2), mm,
        qd_add(ctx, qd_powi(ctx, qd_jet(ctx, r, 1), 2),
               qd_mul(ctx, qd_powi(ctx, r, 2), qd_powi(ctx, om, 2)))});
    assert_ptr_equal(qd_simplify(ctx, qd_model_kinetic(m)), qd_simplify(ctx, T));
    qd_model_free(m);
    qd_ctx_free(ctx);
}

typedef struct bad {
    const char *text;
    size_t line, col;
    const char *message;  /* the start of the message */
    const char *hint;     /* a part of the hint, or NULL */
} bad;

static const bad bad_models[] = {
    /* unknown name, with the nearest known name suggested */
    {"coordinates theta\nparameters m = 1, l = 1\nT = m/2*(l*thta')^2\n", 3, 12,
     "unknown name 'thta'", "did you mean 'theta'?"},
    /* misspelled keyword */
    {"coordinates q\nparamters m = 1\nT = m/2*q'^2\n", 2, 1, "unknown statement 'paramters'",
     "did you mean 'parameters'?"},
    {"coordinate q\nT = q'^2\n", 1, 1, "unknown statement 'coordinate'", "did you mean 'coordinates'?"},
    /* unbalanced brackets */
    {"coordinates q\nT = (q'^2\nV = q\n", 2, 5, "unclosed '('", "a ')' is missing"},
    {"coordinates q\nT = q'^2)\n", 2, 9, "unmatched ')'", NULL},
    {"coordinates q\nT = sin(q'\n", 2, 8, "unclosed '('", NULL},
    /* a definition used before it exists */
    {"coordinates q\nT = x'^2\nx = 2*q\n", 2, 5, "'x' is used before it is defined",
     "move the definition of 'x' (line 3)"},
    /* circular definitions */
    {"coordinates q\na = b + q\nb = a*2\nT = a'^2\n", 2, 5, "circular definition", NULL},
    /* a coordinate declared twice */
    {"coordinates q, p, q\nT = q'^2\n", 1, 19, "coordinate 'q' is declared twice", NULL},
    /* a parameter without a value */
    {"coordinates q\nparameters m, k = 1\nT = m*q'^2\n", 2, 12, "parameter 'm' has no value",
     "give a default value"},
    /* neither T nor L */
    {"coordinates q\nV = q^2\n", 3, 1, "neither T nor L is given", NULL},
    /* a vector where a scalar is needed */
    {"coordinates x, y\nr = (x, y)\nT = r'^2\n", 3, 5, "a vector where a scalar is needed",
     "dot"},
    {"coordinates x, y\nr = (x, y)\nT = r*r\n", 3, 7, "a vector where a scalar is needed",
     "dot(a, b)"},
    {"coordinates x\nparticle 1 at x\n", 2, 15, "a scalar where a vector is needed", NULL},
    /* other mistakes */
    {"coordinates q\nT = q'^2 +\n", 2, 11, "expected an expression", NULL},
    {"coordinates q\nT = q'^2\nT = q^2\n", 3, 1, "T is given twice (first on line 2)", NULL},
    {"coordinates q\nparameters g = 9.81\nT = q'^2\nV = g*sn(q)\n", 4, 7, "unknown function 'sn'",
     "did you mean 'sin'?"},
    {"coordinates q\nparameters k = q\nT = q'^2\n", 2, 16, "a parameter's value must be a number",
     NULL},
    {"coordinates q\nT = q'^2 $\n", 2, 10, "unexpected character '$'", NULL},
    {"coordinates sin\n", 1, 13, "'sin' is already a built-in name", NULL},
    {"coordinates q\nT = q'^2\ninitial p = 1\n", 3, 9, "'p' is not a coordinate", NULL},
    {"", 1, 1, "no coordinates are declared", NULL},
    /* constraints */
    {"coordinates x, y\nT = x'^2 + y'^2\nconstraint a: x = y\nconstraint a: x' = 0\n", 4, 12,
     "constraint 'a' is named twice", NULL},
    {"coordinates x\nT = x'^2\nconstraint 1 = 1\n", 3, 12, "this constraint always holds", NULL},
    {"coordinates x\nT = x'^2\nconstraint r: (x, 0) = 0\n", 3, 15,
     "a vector where a scalar is needed", NULL},
    {"coordinates q\nT = q'^2\nV = sin(q)'''''\n", 3, 15, "a time derivative of order above 4",
     NULL},
    /* matrices where something else is needed, and malformed matrices */
    {"coordinates q\nR = rot_z(q)\nT = R\n", 3, 5, "a matrix where a scalar is needed: T is a scalar",
     NULL},
    {"coordinates q\nparticle 1 at rot_z(q)\n", 2, 15,
     "a matrix where a vector is needed: a position is a vector", "R*(x, y, z)"},
    {"coordinates q\nv = (1, 0, 0)*rot_z(q)\nT = q'^2\n", 2, 15,
     "a matrix cannot multiply a vector from the right", "transpose(R)*v"},
    {"coordinates q\nR = rot_z((q, 0))\nT = q'^2\n", 2, 11,
     "a vector where a scalar is needed as an angle", NULL},
    {"coordinates q\nR = euler(q, q)\nT = q'^2\n", 2, 5, "euler takes 3 arguments, not 2", NULL},
    {"coordinates q\nR = rot_z(q) + (1, 0, 0)\nT = q'^2\n", 2, 16,
     "cannot add a vector to a matrix", NULL},
    {"coordinates q\nx = rot_z(q).x\nT = q'^2\n", 2, 5, "a matrix where a vector is needed", NULL},
    {"coordinates q\nR = transpose((1, 2, 3))\nT = q'^2\n", 2, 15,
     "a vector where a matrix is needed as the argument of transpose", NULL},
    {"coordinates q\nM = [[1, 2, 3], [4, 5]]\nT = q'^2\n", 2, 22,
     "a row of a matrix has three entries; found ']' after 2", NULL},
    {"coordinates q\nM = [[1, 2, 3], [4, 5, 6]]\nT = q'^2\n", 2, 26,
     "a matrix has three rows; found ']' after 2", NULL},
    {"coordinates q\nM = [[1, 2, 3], [4, 5, 6], [7, 8, 9]\nT = q'^2\n", 2, 5, "unclosed '['",
     "a ']' is missing"},
    {"coordinates q\nM = [[1, (2, 0), 3], [4, 5, 6], [7, 8, 9]]\nT = q'^2\n", 2, 10,
     "a vector where a scalar is needed as a matrix entry", NULL},
    {"coordinates q\nR = rot_z(q)\nT = q'^2*R^2\n", 3, 10,
     "a matrix where a scalar is needed as a base", NULL},
    {"coordinates q\nR = rot_z(q)\nT = q'^2\nV = dot(R, R)\n", 4, 9,
     "dot needs vectors; this is a matrix", NULL},
    {"coordinates q\nR = rot_z(q)\nT = sin(R)\n", 3, 9,
     "a matrix where a scalar is needed as a function argument", NULL},
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
        if (d.line != b->line || d.col != b->col || strncmp(d.message, b->message, strlen(b->message)) ||
            (b->hint && !strstr(d.hint, b->hint)))
            fail_msg("case %zu: got %zu:%zu: %s [hint: %s]; want %zu:%zu: %s [hint: %s]", i, d.line,
                     d.col, d.message, d.hint, b->line, b->col, b->message, b->hint ? b->hint : "-");
        /* a value of the wrong kind carries its reason code, so that a
         * caller (sim/names.c: "give a component: P.x") need not read English */
        bool kind = strstr(d.message, " where a ") && strstr(d.message, " is needed");
        if ((d.reason == QD_REASON_WRONG_KIND) != kind)
            fail_msg("case %zu: reason %d for '%s'", i, (int)d.reason, d.message);
        qd_ctx_free(ctx);
    }
}

/* The formatted diagnostic: FILE:LINE:COL, the line, a caret under the span. */
static void formatted(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const char *text = "coordinates theta\nT = m*theta'^2\n";
    qd_diag d;
    assert_null(qd_model_parse(ctx, text, &d));
    qd_buf b = QD_BUF_INIT;
    qd_diag_format(&d, "pend.qd", text, &b);
    assert_string_equal(qd_buf_str(&b), "pend.qd:2:5: error: unknown name 'm'\n"
                                        "  T = m*theta'^2\n"
                                        "      ^\n"
                                        "  hint: declare it under 'coordinates' or 'parameters', "
                                        "or define it with 'm = ...'\n");
    qd_buf_free(&b);
    qd_ctx_free(ctx);
}

/* The kernel's text printer speaks the model language: 1000 random
 * expressions printed and read back as a definition are the same node. */
static void printed_text_reads_back(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *q = qd_coord(ctx, "q");
    const qd_expr *syms[5] = {q, qd_jet(ctx, q, 1), qd_param(ctx, "a"), qd_param(ctx, "b"),
                              qd_time(ctx)};
    qt_rng r = {424242};
    qd_buf text = QD_BUF_INIT, b = QD_BUF_INIT;
    for (int i = 0; i < 1000; i++) {
        const qd_expr *e = qt_random_expr(ctx, &r, syms, 5, 5, QT_ALL & ~QT_FLOAT);
        if (i % 3 == 0)
            e = qd_dt(ctx, e);
        qd_buf_clear(&b);
        assert_int_equal(qd_print(ctx, e, QD_FMT_TEXT, &b), QD_OK);
        qd_buf_clear(&text);
        qd_buf_printf(&text, "coordinates q\nparameters a = 1, b = 2\nE = %s\nT = q'^2\n",
                      qd_buf_str(&b));
        qd_diag d;
        qd_model *m = qd_model_parse(ctx, qd_buf_str(&text), &d);
        if (!m)
            fail_msg("case %d: %s does not read: %zu:%zu %s", i, qd_buf_str(&b), d.line, d.col,
                     d.message);
        if (qd_model_definition(m, "E") != e)
            fail_msg("case %d: %s reads back as another node", i, qd_buf_str(&b));
        qd_model_free(m);
    }
    qd_buf_free(&text);
    qd_buf_free(&b);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(double_pendulum_meaning),
        cmocka_unit_test(language_features),
        cmocka_unit_test(time_dependent),
        cmocka_unit_test(constraints),
        cmocka_unit_test(diagnostics),
        cmocka_unit_test(formatted),
        cmocka_unit_test(printed_text_reads_back),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
