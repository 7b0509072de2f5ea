/*
 * tests/model/test_state.c - a model's state and its reader (qdot/state.h).
 *
 * The numbers asserted are computed here independently of the reader: a
 * value "2*pi" must be 2*PI, "r=r0" the parameter's number, and the energy
 * of a pendulum evaluated at a state read from text must be the textbook
 * E = m l^2 th'^2 / 2 - m g l cos(th) at those numbers.  The errors are
 * asserted by where they point (offset and length of the misspelt name,
 * found in the text by the test) and by the nearest name they suggest.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "qdot/qdot.h"

#define PI 3.14159265358979323846

static const char pendulum[] =
    "coordinates theta, r\n"
    "parameters m = 2, l = 3/2, g = 9.81, r0 = 1/4\n"
    "initial theta = pi/6, r' = r0\n"
    "T = m/2*(l^2*theta'^2 + r'^2)\n"
    "V = -m*g*l*cos(theta) + r^2\n";

typedef struct fx {
    qd_ctx *ctx;
    qd_model *m;
    qd_state st;
} fx;

static int setup(void **state) {
    static fx f;
    memset(&f, 0, sizeof f);
    f.ctx = qd_ctx_new();
    qd_diag d;
    f.m = f.ctx ? qd_model_parse(f.ctx, pendulum, &d) : NULL;
    if (!f.m || qd_state_init(f.ctx, f.m, &f.st) != QD_OK)
        return -1;
    *state = &f;
    return 0;
}

static int teardown(void **state) {
    fx *f = *state;
    qd_state_free(&f->st);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
    return 0;
}

/* The value of the slot of sym. */
static double at(const fx *f, const qd_expr *sym) {
    size_t k = qd_state_find(&f->st, sym);
    assert_true(k < f->st.n);
    return f->st.vals[k];
}

static const qd_expr *coord(const fx *f, size_t j) { return qd_model_coord(f->m, j); }

/* The layout: q, q', t, the parameters, each symbol where qd_slot_* says. */
static void layout(void **state) {
    fx *f = *state;
    size_t nq = 2, np = 4;
    assert_int_equal(f->st.n, qd_slot_count(nq, np));
    assert_int_equal(qd_slot_count(nq, np), 2 * nq + 1 + np);
    for (size_t j = 0; j < nq; j++) {
        assert_ptr_equal(f->st.syms[qd_slot_coord(nq, j)], coord(f, j));
        assert_ptr_equal(f->st.syms[qd_slot_velocity(nq, j)], qd_jet(f->ctx, coord(f, j), 1));
    }
    assert_ptr_equal(f->st.syms[qd_slot_time(nq)], qd_time(f->ctx));
    assert_ptr_equal(f->st.syms[qd_slot_param(nq, 3)], qd_model_param(f->m, 3));
    /* parameters at their values, the rest 0 */
    assert_true(f->st.vals[qd_slot_param(nq, 1)] == 1.5);
    assert_true(f->st.vals[qd_slot_param(nq, 2)] == 9.81);
    assert_true(f->st.vals[qd_slot_time(nq)] == 0);
    /* initial: theta = pi/6, r' = r0 */
    assert_int_equal(qd_state_initial(f->ctx, f->m, &f->st), QD_OK);
    assert_true(fabs(at(f, coord(f, 0)) - PI / 6) < 1e-15);
    assert_true(at(f, qd_jet(f->ctx, coord(f, 1), 1)) == 0.25);
    /* appended slots come after the parameters */
    const qd_expr *p = qd_symbol(f->ctx, "p_theta");
    double v = 0.5;
    assert_int_equal(qd_state_append(f->ctx, &f->st, 1, &p, &v), QD_OK);
    assert_int_equal(qd_state_find(&f->st, p), qd_slot_count(nq, np));
    assert_true(at(f, p) == 0.5);
    assert_int_equal(qd_state_find(&f->st, qd_symbol(f->ctx, "nothing")), f->st.n);
}

/* Values are constant expressions in the parameters, evaluated at them. */
static void good_states(void **state) {
    fx *f = *state;
    bool given[16] = {false};
    const qd_expr *exact[16] = {NULL};
    qd_state_read_opts o = {.given = given, .exact = exact};
    const char *text = "theta = 2*pi, r=r0, theta'=-sqrt(g/l),, t = 1e-3, m=5, r'=atan2(1, 1) ";
    assert_int_equal(qd_state_read(f->ctx, f->m, &f->st, text, &o), QD_OK);
    assert_true(fabs(at(f, coord(f, 0)) - 2 * PI) < 1e-15);
    assert_true(at(f, coord(f, 1)) == 0.25);
    assert_true(fabs(at(f, qd_jet(f->ctx, coord(f, 0), 1)) + sqrt(9.81 / 1.5)) < 1e-14);
    assert_true(fabs(at(f, qd_jet(f->ctx, coord(f, 1), 1)) - PI / 4) < 1e-15);
    assert_true(at(f, qd_time(f->ctx)) == 1e-3);
    assert_true(at(f, qd_model_param(f->m, 0)) == 5);
    size_t all = 0;
    for (size_t k = 0; k < f->st.n; k++)
        all += given[k];
    assert_int_equal(all, 6); /* every slot but l, g and r0 */
    /* exact: 2*pi stays 2*pi, r0 stays the parameter */
    size_t k = qd_state_find(&f->st, coord(f, 0));
    assert_false(qd_is_number(exact[k]));
    assert_ptr_equal(exact[qd_state_find(&f->st, coord(f, 1))], qd_model_param(f->m, 3));
}

/* The physics: the energy at a state read from text is the textbook one. */
static void energy_at_state(void **state) {
    fx *f = *state;
    const char *text = "theta=pi/3, theta'=1/2";
    assert_int_equal(qd_state_read(f->ctx, f->m, &f->st, text, NULL), QD_OK);
    const qd_expr *E = qd_add(f->ctx, qd_model_kinetic(f->m), qd_model_potential(f->m));
    double e;
    assert_int_equal(qd_eval(f->ctx, E, f->st.n, f->st.syms, f->st.vals, &e), QD_OK);
    double m = 2, l = 1.5, g = 9.81;
    double want = m / 2 * l * l * 0.25 - m * g * l * cos(PI / 3);
    assert_true(fabs(e - want) < 1e-12);
}

/* The error record of the last call: located at text[off, off + len). */
static void expect_at(const fx *f, const char *text, const char *where, size_t len,
                      const char *message, const char *hint) {
    const qd_diag *d = qd_ctx_diag(f->ctx);
    const char *p = strstr(text, where);
    assert_non_null(p);
    assert_true(d->located);
    assert_int_equal(d->offset, (size_t)(p - text));
    assert_int_equal(d->length, len);
    assert_int_equal(d->line, 1);
    assert_int_equal(d->col, (size_t)(p - text) + 1);
    if (!strstr(d->message, message))
        fail_msg("message '%s' lacks '%s'", d->message, message);
    if (hint && strcmp(d->hint, hint))
        fail_msg("hint '%s', not '%s'", d->hint, hint);
}

static void read_fails(fx *f, const char *text, qd_status want) {
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_state_read(f->ctx, f->m, &f->st, text, NULL), want);
}

/* A model with speeds read in q, q' (qd_state_init: no speed slots, as
 * Python's Model.eom(at=) reads its Lagrange form): a speed named is
 * refused as one, under its name, and an unknown name's list of names does
 * not offer the speeds the state cannot take. */
static void speeds_not_slots(void **state) {
    (void)state;
    static const char sleigh[] = "coordinates x, th\n"
                                 "T = (x'^2 + th'^2)/2\n"
                                 "speeds v = x', w = th'\n";
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, sleigh, &d);
    assert_non_null(m);
    fx f = {ctx, m, {0}};
    assert_int_equal(qd_state_init(ctx, m, &f.st), QD_OK);
    read_fails(&f, "x=1, w=2", QD_ERR_ARG);
    expect_at(&f, "x=1, w=2", "w", 1, "'w' is a speed: this state is of the coordinates and "
              "their velocities", NULL);
    read_fails(&f, "ww=2", QD_ERR_ARG);
    expect_at(&f, "ww=2", "ww", 2, "unknown name 'ww'", NULL);
    assert_null(strstr(qd_ctx_diag(ctx)->message, "speeds"));
    /* with the speeds appended (qd_state_append) they are slots again */
    const qd_expr *u[2] = {qd_model_speed(m, 0), qd_model_speed(m, 1)};
    assert_int_equal(qd_state_append(ctx, &f.st, 2, u, NULL), QD_OK);
    qd_ctx_clear_error(ctx);
    assert_int_equal(qd_state_read(ctx, m, &f.st, "w=2", NULL), QD_OK);
    assert_true(at(&f, u[1]) == 2.0);
    read_fails(&f, "ww=2", QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_diag(ctx)->message, "the speeds are v, w"));
    qd_state_free(&f.st);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* A misspelt name: a caret under it and the nearest name, as in model files. */
static void misspelt(void **state) {
    fx *f = *state;
    read_fails(f, "r=1, thetta=0.3", QD_ERR_ARG);
    expect_at(f, "r=1, thetta=0.3", "thetta", 6, "unknown name 'thetta'",
              "did you mean 'theta'?");
    read_fails(f, "thetaa' = 1", QD_ERR_ARG);
    expect_at(f, "thetaa' = 1", "thetaa'", 7, "unknown name", "did you mean 'theta''?");
    read_fails(f, "r00 = 1", QD_ERR_ARG);
    expect_at(f, "r00 = 1", "r00", 3, "unknown name 'r00'", "did you mean 'r0'?");
    /* in a value: the parameters are the candidates */
    read_fails(f, "r = 2*rr0", QD_ERR_ARG);
    expect_at(f, "r = 2*rr0", "rr0", 3, "unknown name 'rr0'", "did you mean 'r0'?");
    read_fails(f, "r = theta", QD_ERR_ARG);
    expect_at(f, "r = theta", "theta", 5, "not a constant", NULL);
}

static void bad_items(void **state) {
    fx *f = *state;
    read_fails(f, "theta=1, r=2, theta = 3", QD_ERR_ARG);
    expect_at(f, "theta=1, r=2, theta = 3", "theta = 3", 5, "'theta' is given twice", NULL);
    read_fails(f, "theta=1, r", QD_ERR_ARG);
    expect_at(f, "theta=1, r", "r", 1, "expected NAME=VALUE, not 'r'", NULL);
    read_fails(f, "theta''=1", QD_ERR_ARG);
    expect_at(f, "theta''=1", "theta''", 7, "acceleration", NULL);
    read_fails(f, "r=2*/3", QD_ERR_PARSE);
    expect_at(f, "r=2*/3", "/", 1, "expected an expression", NULL);
    read_fails(f, "r=1e400", QD_ERR_ARG);
    expect_at(f, "r=1e400", "1e400", 5, "too large", NULL);
    read_fails(f, "r=sqrt(-g)", QD_ERR_ARG);
    expect_at(f, "r=sqrt(-g)", "sqrt(-g)", 8, "finite", NULL);
}

/* What a caller refuses, and coordinates a constraint eliminated. */
static void refusals(void **state) {
    fx *f = *state;
    qd_state_read_opts o = {.refuse = QD_STATE_VELOCITIES | QD_STATE_TIME | QD_STATE_PARAMS};
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_state_read(f->ctx, f->m, &f->st, "r=1, theta'=2", &o), QD_ERR_ARG);
    expect_at(f, "r=1, theta'=2", "theta'", 6, "a point at rest", NULL);
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_state_read(f->ctx, f->m, &f->st, "t=2", &o), QD_ERR_ARG);
    expect_at(f, "t=2", "t", 1, "not the time t", NULL);
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_state_read(f->ctx, f->m, &f->st, " g=2", &o), QD_ERR_ARG);
    expect_at(f, " g=2", "g", 1, "g is a parameter", NULL);
    const qd_expr *indep[1] = {coord(f, 0)};
    qd_state_read_opts e = {.independent = indep, .nindependent = 1};
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_state_read(f->ctx, f->m, &f->st, "theta=1, r'=2", &e), QD_ERR_ARG);
    expect_at(f, "theta=1, r'=2", "r'", 2, "r is not an independent coordinate", NULL);
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_state_read(f->ctx, f->m, &f->st, "theta=0.5", &e), QD_OK);
    assert_true(at(f, coord(f, 0)) == 0.5);
}

/* One value alone, without a model: pi and e only. */
static void values(void **state) {
    fx *f = *state;
    const qd_expr *x;
    double v;
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_state_value(f->ctx, NULL, "k=2*pi", 2, 4, &x, &v), QD_OK);
    assert_true(fabs(v - 2 * PI) < 1e-15);
    assert_int_equal(qd_state_value(f->ctx, NULL, "k=9.81", 2, 4, &x, &v), QD_OK);
    assert_true(v == 9.81 && qd_is_number(x));
    assert_int_equal(qd_state_value(f->ctx, NULL, "k=nan", 2, 3, &x, &v), QD_ERR_ARG);
    expect_at(f, "k=nan", "nan", 3, "unknown name 'nan'", NULL);
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_state_value(f->ctx, f->m, "2*pi/r0", 0, 7, &x, &v), QD_OK);
    assert_true(fabs(v - 8 * PI) < 1e-14);
    assert_int_equal(qd_state_item_end("a=f(1, 2), b=3", 0), 9);
}

static void nulls(void **state) {
    fx *f = *state;
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_state_read(f->ctx, NULL, &f->st, "r=1", NULL), QD_ERR_ARG);
    qd_ctx_clear_error(f->ctx);
    qd_state small = {.n = 1, .syms = f->st.syms, .vals = f->st.vals};
    assert_int_equal(qd_state_read(f->ctx, f->m, &small, "r=1", NULL), QD_ERR_ARG);
    qd_ctx_clear_error(f->ctx);
}

/* A search box: ranges by name, in the parameters (theta = -pi:pi, r =
 * 0:4 r0 = 0:1; A..B the same), at the slots of the coordinates; the rest untouched; an
 * empty range, a second range of one name and a plain value are located. */
static void ranges(void **state) {
    fx *f = *state;
    size_t n = f->st.n;
    double lo[16], hi[16];
    bool given[16] = {false};
    assert_true(n <= 16);
    for (size_t k = 0; k < n; k++)
        lo[k] = hi[k] = -7;
    qd_state_read_opts o = {.refuse = QD_STATE_TIME | QD_STATE_PARAMS | QD_STATE_VELOCITIES,
                            .given = given};
    assert_int_equal(qd_state_read_ranges(f->ctx, f->m, &f->st, "theta=-pi:pi, r = 0:4*r0", &o,
                                          lo, hi), QD_OK);
    assert_true(lo[0] == -PI && hi[0] == PI && lo[1] == 0 && hi[1] == 1);
    assert_true(given[0] && given[1] && !given[2] && lo[2] == -7);
    /* the old spelling A..B reads the same box (issue 31: A:B is the one
     * written, A..B still read) */
    assert_int_equal(qd_state_read_ranges(f->ctx, f->m, &f->st, "theta=-pi/2..pi/2, r=0..4*r0",
                                          &o, lo, hi), QD_OK);
    assert_true(lo[0] == -PI / 2 && hi[0] == PI / 2 && lo[1] == 0 && hi[1] == 1);
    const char *empty = "theta = 1:0";
    assert_int_not_equal(qd_state_read_ranges(f->ctx, f->m, &f->st, empty, &o, lo, hi), QD_OK);
    assert_non_null(strstr(qd_ctx_message(f->ctx), "empty"));
    assert_int_equal(qd_ctx_diag(f->ctx)->offset, 8);
    qd_ctx_clear_error(f->ctx);
    const char *twice = "r=0:1, r=1:2";
    assert_int_not_equal(qd_state_read_ranges(f->ctx, f->m, &f->st, twice, &o, lo, hi), QD_OK);
    assert_int_equal(qd_ctx_diag(f->ctx)->offset, 7);
    qd_ctx_clear_error(f->ctx);
    const char *value = "r=1";
    assert_int_not_equal(qd_state_read_ranges(f->ctx, f->m, &f->st, value, &o, lo, hi), QD_OK);
    assert_non_null(strstr(qd_ctx_message(f->ctx), "expected a range A:B"));
    qd_ctx_clear_error(f->ctx);
    const char *vel = "r'=0:1";
    assert_int_not_equal(qd_state_read_ranges(f->ctx, f->m, &f->st, vel, &o, lo, hi), QD_OK);
    assert_int_equal(qd_ctx_diag(f->ctx)->offset, 0);
    qd_ctx_clear_error(f->ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(layout, setup, teardown),
        cmocka_unit_test_setup_teardown(good_states, setup, teardown),
        cmocka_unit_test_setup_teardown(energy_at_state, setup, teardown),
        cmocka_unit_test_setup_teardown(misspelt, setup, teardown),
        cmocka_unit_test_setup_teardown(bad_items, setup, teardown),
        cmocka_unit_test_setup_teardown(refusals, setup, teardown),
        cmocka_unit_test_setup_teardown(values, setup, teardown),
        cmocka_unit_test_setup_teardown(ranges, setup, teardown),
        cmocka_unit_test_setup_teardown(nulls, setup, teardown),
        cmocka_unit_test(speeds_not_slots),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
