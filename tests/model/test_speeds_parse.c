/*
 * tests/model/test_speeds_parse.c - the `speeds` statement: what a speed
 * means in the model, its initial value, where it stands, and every
 * diagnostic (message, line and column asserted exactly).
 *
 * The rigid body's speeds are the body components of its angular velocity
 * with z-x-z Euler angles, which Desloge ch. 68 Ex. 2 (seed-desloge-C.md)
 * and Goldstein (3rd ed., eq. 4.87) write out:
 *
 *   w1 = phi' sin(theta) sin(psi) + theta' cos(psi)
 *   w2 = phi' sin(theta) cos(psi) - theta' sin(psi)
 *   w3 = phi' cos(theta) + psi'
 *
 * and the kinetic energy about principal axes is (A w1^2 + B w2^2 + C w3^2)/2
 * (Euler; Desloge ch. 64).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/model.h"
#include "util/fault.h"

#define EULER_W1 "phi'*sin(theta)*sin(psi) + theta'*cos(psi)"
#define EULER_W2 "phi'*sin(theta)*cos(psi) - theta'*sin(psi)"
#define EULER_W3 "phi'*cos(theta) + psi'"

#define RIGID_BODY                                                                         \
    "coordinates phi, theta, psi\n"                                                        \
    "parameters A = 1, B = 2, C = 3\n"                                                     \
    "body b mass 1 inertia (A, B, C) at (0, 0, 0) orientation euler(phi, theta, psi)\n"    \
    "speeds w1 = omega(b).x, w2 = omega(b).y, w3 = omega(b).z\n"

static qd_model *parse_ok(qd_ctx *ctx, const char *text) {
    qd_diag d;
    memset(&d, 0, sizeof d);
    qd_model *m = qd_model_parse(ctx, text, &d);
    if (!m)
        fail_msg("%zu:%zu: %s [hint: %s]\n%s", d.line, d.col, d.message, d.hint, text);
    return m;
}

static void assert_same(qd_ctx *ctx, const qd_expr *a, const qd_expr *b) {
    assert_non_null(a);
    assert_non_null(b);
    const qd_expr *d = qd_simplify(ctx, qd_sub(ctx, a, b));
    if (!d || !qd_is_zero(d)) {
        qd_buf x = QD_BUF_INIT, y = QD_BUF_INIT;
        qd_print(ctx, a, QD_FMT_TEXT, &x);
        qd_print(ctx, b, QD_FMT_TEXT, &y);
        fail_msg("%s != %s", qd_buf_str(&x), qd_buf_str(&y));
    }
}

/* e equals the model-language text want (the model's symbols by name). */
static void assert_is(qd_ctx *ctx, const qd_expr *e, const char *want) {
    qd_read_error err;
    const qd_read_opts opts = {.new_symbols = true};
    const qd_expr *w = qd_read(ctx, want, &opts, &err);
    if (!w)
        fail_msg("cannot read %s", want);
    assert_same(ctx, e, w);
}

static void rigid_body_speeds(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse_ok(ctx, RIGID_BODY);
    assert_int_equal(qd_model_nspeeds(m), 3);
    static const char *const names[] = {"w1", "w2", "w3"};
    static const char *const euler[] = {EULER_W1, EULER_W2, EULER_W3};
    for (size_t k = 0; k < 3; k++) {
        const qd_expr *u = qd_model_speed(m, k);
        assert_string_equal(qd_expr_name(u), names[k]);
        /* a function of t: its rate exists, and it is no coordinate */
        const qd_expr *ud = qd_jet(ctx, u, 1);
        assert_non_null(ud);
        assert_true(qd_has(qd_dt(ctx, u), ud));
        for (size_t j = 0; j < qd_model_ncoords(m); j++)
            assert_ptr_not_equal(qd_model_coord(m, j), u);
        assert_same(ctx, qd_model_speed_definition(m, k), qd_model_body_omega(m, 0, (unsigned)k));
        assert_is(ctx, qd_model_speed_definition(m, k), euler[k]);
        assert_null(qd_model_speed_initial(m, k));
        assert_null(qd_model_speed_initial_definition(m, k));
    }
    assert_null(qd_model_speed(m, 3));
    assert_null(qd_model_speed_definition(m, 3));
    assert_null(qd_model_speed_initial(m, 3));
    qd_model_free(m);
    /* no speeds statement, no speeds */
    m = parse_ok(ctx, "coordinates x\nT = x'^2/2\n");
    assert_int_equal(qd_model_nspeeds(m), 0);
    assert_null(qd_model_speed(m, 0));
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* A speed's name stands for its definition: T in the speeds is Euler's
 * T of the body, and the same as with the definitions written out. */
static void speed_names_in_expressions(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *body = parse_ok(ctx, RIGID_BODY);
    qd_model *in_speeds = parse_ok(ctx,
        "coordinates phi, theta, psi\nparameters A = 1, B = 2, C = 3\n"
        "speeds w1 = " EULER_W1 ", w2 = " EULER_W2 ", w3 = " EULER_W3 "\n"
        "T = (A*w1^2 + B*w2^2 + C*w3^2)/2\n"
        "a3 = w3'\n");
    qd_model *written = parse_ok(ctx,
        "coordinates phi, theta, psi\nparameters A = 1, B = 2, C = 3\n"
        "T = (A*(" EULER_W1 ")^2 + B*(" EULER_W2 ")^2 + C*(" EULER_W3 ")^2)/2\n");
    assert_same(ctx, qd_model_kinetic(in_speeds), qd_model_kinetic(written));
    assert_same(ctx, qd_model_kinetic(in_speeds), qd_model_kinetic(body));
    /* the prime of a speed's name: the time derivative of its definition */
    assert_is(ctx, qd_model_definition(in_speeds, "a3"),
              "phi''*cos(theta) - phi'*theta'*sin(theta) + psi''");
    /* the speed's own symbol does not leak into the model's expressions */
    assert_false(qd_has(qd_model_kinetic(in_speeds), qd_model_speed(in_speeds, 0)));
    qd_model_free(body);
    qd_model_free(in_speeds);
    qd_model_free(written);
    qd_ctx_free(ctx);
}

/* Several statements add up, a later speed may use an earlier one, and
 * linearity is judged after the algebra: (x' + y')*cos(x) is linear, the
 * non-integrable r*phi' (Desloge ch. 67: the areal velocity's kin) is a
 * speed like any other. */
static void speeds_add_up(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse_ok(ctx, "coordinates r, phi\nparameters k = 1\n"
                                "speeds u1 = r', u2 = r*phi'\n"
                                "T = (u1^2 + u2^2)/2\n"
                                "speeds s = (u1 + phi')*cos(phi) + k*t\n");
    assert_int_equal(qd_model_nspeeds(m), 3);
    assert_string_equal(qd_expr_name(qd_model_speed(m, 2)), "s");
    assert_is(ctx, qd_model_speed_definition(m, 1), "r*phi'");
    assert_is(ctx, qd_model_speed_definition(m, 2), "(r' + phi')*cos(phi) + k*t");
    assert_is(ctx, qd_model_kinetic(m), "(r'^2 + r^2*phi'^2)/2");
    qd_diag w;
    assert_true(qd_model_where(m, "speed:s", &w));
    assert_int_equal(w.line, 5);
    assert_int_equal(w.col, 8);
    assert_int_equal(w.length, 1);
    assert_false(qd_model_where(m, "speed:r", &w));
    qd_model_free(m);
    /* a long name is found whole (the place's key once kept 63 bytes) */
    char text[400], key[160], name[101];
    memset(name, 'u', 100);
    name[100] = '\0';
    snprintf(text, sizeof text, "coordinates x\nT = x'^2/2\nspeeds %s = x'\n", name);
    snprintf(key, sizeof key, "speed:%s", name);
    m = parse_ok(ctx, text);
    assert_true(qd_model_where(m, key, &w));
    assert_int_equal(w.length, 100);
    key[70] = '\0';
    assert_false(qd_model_where(m, key, NULL));
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* `initial` of a speed: as written and as a number, following the
 * parameters (qd_model_set_param, and --set given to the parse). */
static void speed_initial_follows_set(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const char *text = RIGID_BODY "initial w1 = A/2, theta = 1, w3 = 0.3\n";
    qd_model *m = parse_ok(ctx, text);
    assert_is(ctx, qd_model_speed_initial_definition(m, 0), "A/2");
    assert_is(ctx, qd_model_speed_initial(m, 0), "1/2");
    assert_null(qd_model_speed_initial(m, 1));
    assert_is(ctx, qd_model_speed_initial(m, 2), "3/10");
    assert_is(ctx, qd_model_initial(m, 1, 0), "1");
    assert_int_equal(qd_model_set_param(ctx, m, "A", qd_int(ctx, 5)), QD_OK);
    assert_is(ctx, qd_model_speed_initial(m, 0), "5/2");
    assert_is(ctx, qd_model_speed_initial_definition(m, 0), "A/2");
    assert_is(ctx, qd_model_speed_initial(m, 2), "3/10");
    qd_model_free(m);

    const qd_param_value set[] = {{"A", qd_int(ctx, 7)}};
    const qd_model_opts opts = {set, 1, false};
    qd_diag d;
    m = qd_model_parse_opts(ctx, text, &opts, &d);
    assert_non_null(m);
    assert_is(ctx, qd_model_speed_initial(m, 0), "7/2");
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* A derivation's error about speed 1 points at its name in `speeds`. */
static void locate_speed(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse_ok(ctx, RIGID_BODY);
    qd_diag d;
    memset(&d, 0, sizeof d);
    d.subject = QD_SUBJECT_SPEED;
    d.index = 1;
    assert_true(qd_model_locate(m, &d));
    assert_int_equal(d.line, 4);
    assert_int_equal(d.col, 25);
    assert_int_equal(d.length, 2);
    memset(&d, 0, sizeof d);
    d.subject = QD_SUBJECT_SPEED;
    snprintf(d.name, sizeof d.name, "w3");
    assert_true(qd_model_locate(m, &d));
    assert_int_equal(d.col, 42);
    memset(&d, 0, sizeof d);
    d.subject = QD_SUBJECT_SPEED;
    d.index = 3;
    assert_false(qd_model_locate(m, &d));
    assert_false(d.located);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* qd_model_add_statement adds speeds, and a failed statement leaves the
 * speeds and their initial values as they were. */
static void add_statement(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse_ok(ctx, "coordinates x, y\nT = (x'^2 + y'^2)/2\n");
    qd_diag d;
    assert_int_equal(qd_model_add_statement(m, "speeds u = x' + y'", &d), QD_OK);
    assert_int_equal(qd_model_nspeeds(m), 1);
    qd_diag w;
    assert_true(qd_model_where(m, "speed:u", &w));
    assert_int_equal(w.line, 1);
    assert_int_equal(w.col, 8);
    assert_int_equal(qd_model_add_statement(m, "initial u = 2", &d), QD_OK);
    assert_is(ctx, qd_model_speed_initial(m, 0), "2");
    /* fails after replacing u's initial value: put back */
    assert_int_equal(qd_model_add_statement(m, "initial u = 3, x = y", &d), QD_ERR_PARSE);
    assert_is(ctx, qd_model_speed_initial(m, 0), "2");
    /* fails after adding v: v is gone, and its name free again */
    assert_int_equal(qd_model_add_statement(m, "speeds v = y', w = x'^2", &d), QD_ERR_PARSE);
    assert_int_equal(d.line, 1);
    assert_int_equal(d.col, 20);
    assert_int_equal(qd_model_nspeeds(m), 1);
    assert_false(qd_model_where(m, "speed:v", NULL));
    assert_int_equal(qd_model_add_statement(m, "speeds v = x' - y'", &d), QD_OK);
    assert_int_equal(qd_model_nspeeds(m), 2);
    assert_int_equal(qd_model_add_statement(m, "speeds = 2", &d), QD_OK); /* a definition */
    assert_is(ctx, qd_model_definition(m, "speeds"), "2");
    qd_model_free(m);
    qd_ctx_free(ctx);
}

typedef struct bad {
    const char *text;
    size_t line, col, length;
    const char *message;  /* the start of the message */
    const char *hint;     /* a part of the hint, or NULL */
} bad;

#define XY "coordinates x, y\nparameters k = 1\nT = (x'^2 + y'^2)/2\n"
#define LINEAR "u = a(q) q' + b(q, t)"

static const bad bad_models[] = {
    {XY "speeds u = x'^2\n", 4, 12, 4,
     "a speed must be linear in the velocities, but x' enters nonlinearly", LINEAR},
    {XY "speeds u = y', v = x'*y' + k\n", 4, 20, 9,
     "a speed must be linear in the velocities, but x' enters nonlinearly", LINEAR},
    /* a call's caret stops at its ')' (it ran on over the blank after it) */
    {XY "speeds u = sin(y') \n", 4, 12, 7,
     "a speed must be linear in the velocities, but y' enters nonlinearly", LINEAR},
    /* its derivative is 0, yet it is not linear */
    {XY "speeds u = step(x') + y'\n", 4, 12, 13,
     "a speed must be linear in the velocities, but x' enters nonlinearly", LINEAR},
    {XY "speeds u = x\n", 4, 12, 1,
     "a speed must contain a velocity, but this is a function of the coordinates and t only",
     LINEAR},
    {XY "speeds u = k*t + x*y\n", 4, 12, 9, "a speed must contain a velocity", LINEAR},
    /* the coefficient of x' is zero once simplified */
    {XY "speeds u = x'*(sin(x)^2 + cos(x)^2 - 1) + x\n", 4, 12, 32,
     "a speed must contain a velocity", LINEAR},
    {XY "speeds u = x'' + y'\n", 4, 12, 8, "a speed cannot depend on an acceleration (x'')",
     LINEAR},
    {XY "speeds u = y' + x'''\n", 4, 12, 9, "a speed cannot depend on an acceleration (x''')",
     LINEAR},
    {XY "speeds x = x'\n", 4, 8, 1, "'x' is already a coordinate", "choose another name for the speed"},
    {XY "speeds k = x'\n", 4, 8, 1, "'k' is already a parameter", NULL},
    {XY "d = 2\nspeeds d = x'\n", 5, 8, 1, "'d' is already a definition", NULL},
    {XY "speeds T = x'\n", 4, 8, 1, "'T' is already a reserved name", NULL},
    {XY "speeds u = x', u = y'\n", 4, 16, 1, "'u' is already a speed", NULL},
    {XY "speeds u = x'\nspeeds v = y', u = x' + y'\n", 5, 16, 1, "'u' is already a speed", NULL},
    {XY "speeds u = x'\nu = 2\n", 5, 1, 1, "'u' is already a speed", "another name for the definition"},
    {XY "speeds u = x'\nparameters u = 2\n", 5, 12, 1, "'u' is already a speed", NULL},
    {XY "speeds u = (x', y')\n", 4, 12, 8, "a vector where a scalar is needed for a speed", NULL},
    {XY "speeds u\n", 4, 8, 1, "speed 'u' has no definition", "speeds u1 = EXPR"},
    {XY "speeds 2 = x'\n", 4, 8, 1, "expected a speed's name, found a number", "speeds u1 = EXPR"},
    {XY "speeds u = x',\n", 4, 15, 1, "expected a speed's name, found the end of the line", NULL},
    {XY "speeds u = x' y'\n", 4, 15, 1, "unexpected a name after the statement", NULL},
    {XY "speeds u = u + x'\n", 4, 12, 1, "unknown name 'u'", NULL},
    /* a speed's name before its statement, as a definition's */
    {XY "T2 = 2*u\nspeeds w = y', u = x'\n", 4, 8, 1, "'u' is used before it is defined",
     "move the definition of 'u' (line 5) above this line"},
    {XY "speeds w1 = x'\ninitial w2 = 1\n", 5, 9, 2, "'w2' is not a coordinate or a speed",
     "did you mean 'w1'?"},
    {XY "speeds u = x'\ninitial u' = 1\n", 5, 10, 1, "an initial value is for a speed, not its rate",
     "initial u1 = 0.3"},
    {XY "speeds u = x'\ninitial u = y\n", 5, 13, 1,
     "an initial value must be a number, but it depends on 'y'", NULL},
    {XY "speeds u = x'\ninitial u 1\n", 5, 11, 1, "expected '='", NULL},
    /* a model given by H, in either order */
    {"coordinates x\nmomenta p\nH = p^2/2\nspeeds u = x'\n", 4, 1, 6,
     "speeds cannot be given with H (line 3)", "energies T and V"},
    {"coordinates x\nmomenta p\nspeeds u = x'\nH = p^2/2\n", 4, 1, 1,
     "H cannot be given with speeds (line 3)", "energies T and V"},
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
            strncmp(d.message, b->message, strlen(b->message)) ||
            (b->hint && !strstr(d.hint, b->hint)))
            fail_msg("case %zu: got %zu:%zu+%zu: %s [hint: %s]; want %zu:%zu+%zu: %s [hint: %s]",
                     i, d.line, d.col, d.length, d.message, d.hint, b->line, b->col, b->length,
                     b->message, b->hint ? b->hint : "-");
        assert_int_equal(d.status, QD_ERR_PARSE);
        qd_ctx_free(ctx);
    }
}

/* Every allocation of the parse, an added speed and a failed addition made
 * to fail in turn: the right speeds or a clean out of memory, nothing
 * leaked (the loop counts the blocks). */
static qd_status speeds_under_faults(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)data;
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, RIGID_BODY "initial w2 = B/4\n", &d);
    if (!m)
        return qd_ctx_status(ctx);
    qd_status st = qd_model_add_statement(m, "speeds s = theta' + w1", &d);
    if (st == QD_OK)
        st = qd_model_add_statement(m, "speeds v = theta'^2", &d);
    if (st == QD_ERR_PARSE) /* the second must fail, and leave the model as it was */
        st = qd_model_nspeeds(m) == 4 ? QD_OK : QD_ERR_ARG;
    else if (st == QD_OK)
        st = QD_ERR_ARG;
    if (st == QD_OK) { /* the checks allocate too: not under test */
        qt_fault_hold(f);
        assert_string_equal(qd_expr_name(qd_model_speed(m, 3)), "s");
        assert_is(ctx, qd_model_speed_definition(m, 3), "theta' + " EULER_W1);
        assert_is(ctx, qd_model_speed_initial(m, 1), "1/2");
    }
    qd_model_free(m);
    if (st == QD_ERR_ARG)
        fail_msg("the failed speeds statement was kept");
    return st;
}

static void out_of_memory(void **state) {
    (void)state;
    qt_fault_loop("speeds", speeds_under_faults, NULL, 1);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(rigid_body_speeds),
        cmocka_unit_test(speed_names_in_expressions),
        cmocka_unit_test(speeds_add_up),
        cmocka_unit_test(speed_initial_follows_set),
        cmocka_unit_test(locate_speed),
        cmocka_unit_test(add_statement),
        cmocka_unit_test(diagnostics),
        cmocka_unit_test(out_of_memory),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
