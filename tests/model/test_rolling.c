/*
 * tests/model/test_rolling.c - the rolls statement: the no-slip constraints
 * it generates, against the books' constraints evaluated at random states,
 * and its diagnostics.
 *
 * Expected values are written out here: the rolling sphere's
 * x' - a w_y = 0, y' + a w_x = 0 (Desloge ch. 64 Ex. 2, seed-desloge-B.md
 * C11; Byerly Art. 10a), the upright disk's x1' + a psi' cos(ph) = 0,
 * x2' + a psi' sin(ph) = 0 (Desloge ch. 49 Ex. 1, seed-desloge-A.md T09),
 * the turntable's x' - a w_y + Omega y = 0 (Desloge ch. 70 Ex. 1,
 * seed-desloge-C.md T5), and for the leaning disk v_c + w x (p - c) computed
 * in doubles from the Euler angles (Desloge ch. 63 eq. 12).
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
#include "util/randexpr.h"

typedef const qd_expr *E;

#define MAXV 16
#define POINTS 25

static qd_model *parse(qd_ctx *ctx, const char *text) {
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, text, &d);
    if (!m)
        fail_msg("%zu:%zu: %s [hint: %s]\n%s", d.line, d.col, d.message, d.hint, text);
    return m;
}

static E constraint(const qd_model *m, const char *name) {
    for (size_t i = 0; i < qd_model_nconstraints(m); i++)
        if (!strcmp(qd_model_constraint_name(m, i), name))
            return qd_model_constraint(m, i);
    fail_msg("no constraint '%s'", name);
    return NULL;
}

/* A state: values for named symbols ("x", "x'", "a"), drawn at random. */
typedef struct state {
    size_t n;
    const char *names[MAXV];
    double v[MAXV];
} state;

static double val(const state *s, const char *name) {
    for (size_t i = 0; i < s->n; i++)
        if (!strcmp(s->names[i], name))
            return s->v[i];
    fail_msg("no value for '%s'", name);
    return 0;
}

static void draw(state *s, qt_rng *r, const char *const *names, size_t n) {
    s->n = n;
    for (size_t i = 0; i < n; i++) {
        s->names[i] = names[i];
        s->v[i] = qt_uniform(r, -1.5, 1.5);
    }
}

static double eval_at(qd_ctx *ctx, E e, const state *s) {
    E syms[MAXV];
    for (size_t i = 0; i < s->n; i++) {
        syms[i] = qd_lookup(ctx, s->names[i]);
        assert_non_null(syms[i]);
    }
    double x;
    if (qd_eval(ctx, e, s->n, syms, s->v, &x) != QD_OK)
        fail_msg("cannot evaluate: %s", qd_ctx_message(ctx));
    return x;
}

static void near(double got, double want, const char *what, int point) {
    if (!(fabs(got - want) <= 1e-11 * (1 + fabs(want))))
        fail_msg("%s at point %d: %.17g, expected %.17g", what, point, got, want);
}

/* Desloge ch. 63 eq. 12: the space angular velocity of euler(phi, theta, psi). */
static void omega_space(const state *s, double w[3]) {
    double ph = val(s, "phi"), th = val(s, "theta");
    double phd = val(s, "phi'"), thd = val(s, "theta'"), psd = val(s, "psi'");
    w[0] = thd * cos(ph) + psd * sin(ph) * sin(th);
    w[1] = thd * sin(ph) - psd * cos(ph) * sin(th);
    w[2] = phd + psd * cos(th);
}

static void cross3(const double a[3], const double b[3], double out[3]) {
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

static const char *const euler6[] = {"x",  "y",  "z",  "phi",  "theta",  "psi",  "x'",
                                     "y'", "z'", "phi'", "theta'", "psi'", "a"};

#define BALL "coordinates x, y, z, phi, theta, psi\nparameters m = 1, a = 0.3\n" \
             "body ball mass m inertia sphere(m, a) at (x, y, z) orientation euler(phi, theta, psi)\n"

/* ---- sphere on a horizontal plane --------------------------------------------- */

static void sphere_on_plane(void **st) {
    (void)st;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse(ctx, BALL "rolls ball on plane((0, 0, 1), (0, 0, 0)) as sphere(a)\n");
    assert_int_equal(qd_model_nconstraints(m), 3);
    E r1 = constraint(m, "ball_roll1"), r2 = constraint(m, "ball_roll2");
    E c = constraint(m, "ball_contact");
    qt_rng r = {11};
    for (int k = 0; k < POINTS; k++) {
        state s;
        draw(&s, &r, euler6, 13);
        double w[3], a = val(&s, "a");
        omega_space(&s, w);
        near(eval_at(ctx, r1, &s), val(&s, "x'") - a * w[1], "x' - a w_y", k);
        near(eval_at(ctx, r2, &s), val(&s, "y'") + a * w[0], "y' + a w_x", k);
        near(eval_at(ctx, c, &s), val(&s, "z") - a, "z - a", k);
    }
    /* the contact is where it is written: at the body's name */
    qd_diag where;
    assert_true(qd_model_where(m, "constraint:ball_roll1", &where));
    assert_int_equal(where.line, 4);
    assert_int_equal(where.col, 7);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* With the centre at height a the contact holds identically and is left out. */
static void contact_built_in(void **st) {
    (void)st;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse(ctx, "coordinates x, y, phi, theta, psi\nparameters m = 1, a = 0.3\n"
                             "body ball mass m inertia sphere(m, a) at (x, y, a) "
                             "orientation euler(phi, theta, psi)\n"
                             "rolls ball on plane(normal (0, 0, 2), through (0, 0, 0)) "
                             "as sphere(a)\n");
    assert_int_equal(qd_model_nconstraints(m), 2);
    assert_string_equal(qd_model_constraint_name(m, 0), "ball_roll1");
    assert_string_equal(qd_model_constraint_name(m, 1), "ball_roll2");
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* ---- the sphere on a turntable: v_surface = Omega e_z x p ----------------------- */

static void sphere_on_turntable(void **st) {
    (void)st;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse(ctx, "coordinates x, y, phi, theta, psi\nparameters a = 0.3, W = 2\n"
                             "body ball mass 1 inertia sphere(1, a) at (x, y, a) "
                             "orientation euler(phi, theta, psi)\n"
                             "rolls ball on plane((0, 0, 1), (0, 0, 0)) turning W as sphere(a)\n");
    assert_int_equal(qd_model_nconstraints(m), 2);
    E r1 = constraint(m, "ball_roll1"), r2 = constraint(m, "ball_roll2");
    static const char *const names[] = {"x", "y", "phi", "theta", "psi", "x'", "y'",
                                        "phi'", "theta'", "psi'", "a", "W"};
    qt_rng r = {12};
    for (int k = 0; k < POINTS; k++) {
        state s;
        draw(&s, &r, names, 12);
        double w[3], a = val(&s, "a"), W = val(&s, "W");
        omega_space(&s, w);
        near(eval_at(ctx, r1, &s), val(&s, "x'") - a * w[1] + W * val(&s, "y"), "roll x", k);
        near(eval_at(ctx, r2, &s), val(&s, "y'") + a * w[0] - W * val(&s, "x"), "roll y", k);
    }
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* ---- disks ----------------------------------------------------------------------- */

static void upright_disk_is_desloge(void **st) {
    (void)st;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse(ctx, "coordinates x1, x2, ph, psi\nparameters m = 1, a = 0.3\n"
                             "body disk mass m inertia disk(m, a) at (x1, x2, a) "
                             "orientation euler(ph, pi/2, psi)\n"
                             "rolls disk on plane((0, 0, 1), (0, 0, 0)) as disk(a)\n");
    assert_int_equal(qd_model_nconstraints(m), 2);
    E r1 = constraint(m, "disk_roll1"), r2 = constraint(m, "disk_roll2");
    static const char *const names[] = {"x1", "x2", "ph", "psi", "x1'", "x2'", "ph'", "psi'", "a"};
    qt_rng r = {13};
    for (int k = 0; k < POINTS; k++) {
        state s;
        draw(&s, &r, names, 9);
        double a = val(&s, "a"), ph = val(&s, "ph"), psd = val(&s, "psi'");
        near(eval_at(ctx, r1, &s), val(&s, "x1'") + a * psd * cos(ph), "T09 first", k);
        near(eval_at(ctx, r2, &s), val(&s, "x2'") + a * psd * sin(ph), "T09 second", k);
    }
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* A leaning disk touches at p = c - a (e_z - cos(theta) k)/sin(theta). */
static void leaning_disk(void **st) {
    (void)st;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse(ctx, "coordinates x, y, z, phi, theta, psi\nparameters m = 1, a = 0.3\n"
                             "body disk mass m inertia disk(m, a) at (x, y, z) "
                             "orientation euler(phi, theta, psi)\n"
                             "rolls disk on plane((0, 0, 1), (0, 0, 0)) as disk(a)\n");
    assert_int_equal(qd_model_nconstraints(m), 3);
    E r1 = constraint(m, "disk_roll1"), r2 = constraint(m, "disk_roll2");
    E c = constraint(m, "disk_contact");
    qt_rng r = {14};
    for (int k = 0; k < POINTS; k++) {
        state s;
        draw(&s, &r, euler6, 13);
        s.v[4] = qt_uniform(&r, 0.2, 2.9); /* theta: leaning, not flat */
        double w[3], spin[3], a = val(&s, "a"), ph = val(&s, "phi"), th = val(&s, "theta");
        double kx[3] = {sin(th) * sin(ph), -sin(th) * cos(ph), cos(th)}, rho[3];
        for (int i = 0; i < 3; i++)
            rho[i] = -a * ((i == 2) - cos(th) * kx[i]) / sin(th);
        omega_space(&s, w);
        cross3(w, rho, spin);
        near(eval_at(ctx, r1, &s), val(&s, "x'") + spin[0], "v_p . e_x", k);
        near(eval_at(ctx, r2, &s), val(&s, "y'") + spin[1], "v_p . e_y", k);
        near(eval_at(ctx, c, &s), val(&s, "z") - a * sin(th), "z - a sin(theta)", k);
    }
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* ---- a cylinder inside a cylinder ------------------------------------------------- */

static void cylinder_inside(void **st) {
    (void)st;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse(ctx, "coordinates r, q, f\nparameters R = 2, b = 0.5\n"
                             "body w mass 1 inertia disk(1, b) at (r*sin(q), -r*cos(q), 0) "
                             "orientation rot_z(f)\n"
                             "rolls w inside cylinder(R, (0, 0, 0), (0, 0, 1)) as cylinder(b)\n");
    /* plane motion: the axial rolling constraint is 0 and left out */
    assert_int_equal(qd_model_nconstraints(m), 2);
    E roll = constraint(m, "w_roll1"), c = constraint(m, "w_contact");
    static const char *const names[] = {"r", "q", "f", "r'", "q'", "f'", "R", "b"};
    qt_rng rng = {15};
    for (int k = 0; k < POINTS; k++) {
        state s;
        draw(&s, &rng, names, 8);
        s.v[0] = qt_uniform(&rng, 0.2, 1.5); /* r > 0 */
        double r = val(&s, "r"), b = val(&s, "b");
        /* the contact point c + b e (e outward) at rest: r q' + b f' = 0 */
        near(eval_at(ctx, roll, &s), r * val(&s, "q'") + b * val(&s, "f'"), "rolling", k);
        near(eval_at(ctx, c, &s), val(&s, "R") - b - r, "gap R - b - r", k);
    }
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* A second rolls line for one body numbers its constraints on. */
static void two_contacts(void **st) {
    (void)st;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse(ctx, BALL "rolls ball on plane((0, 0, 1), (0, 0, 0)) as sphere(a)\n"
                                  "rolls ball on plane((0, 0, -1), (0, 0, 1)) as sphere(a)\n");
    assert_int_equal(qd_model_nconstraints(m), 6);
    assert_string_equal(qd_model_constraint_name(m, 3), "ball_roll3");
    assert_string_equal(qd_model_constraint_name(m, 5), "ball_contact2");
    qt_rng r = {16};
    state s;
    draw(&s, &r, euler6, 13);
    /* the upper plane z = 1, normal down: the gap is 1 - z - a */
    near(eval_at(ctx, constraint(m, "ball_contact2"), &s), 1 - val(&s, "z") - val(&s, "a"),
         "upper gap", 0);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* ---- diagnostics ------------------------------------------------------------------- */

typedef struct bad {
    const char *text;
    size_t line, col;
    const char *message;
    const char *hint;
} bad;

#define PLANE " on plane((0, 0, 1), (0, 0, 0))"
static const bad bad_models[] = {
    {BALL "rolls bal" PLANE " as sphere(a)\n", 4, 7, "'bal' is not a body", "did you mean 'ball'?"},
    {BALL "rolls x" PLANE " as sphere(a)\n", 4, 7, "'x' is not a body", NULL},
    {"coordinates x\nbody b mass 1 inertia (1, 1, 1) at (x, 0, 1)\nrolls b" PLANE " as sphere(1)\n",
     3, 7, "body 'b' has no orientation (it cannot turn), so it cannot roll",
     "orientation euler(phi, theta, psi)"},
    {BALL "rolls ball" PLANE " as ring(a)\n", 4, 46, "unknown rolling shape 'ring'",
     "did you mean 'disk'?"},
    {BALL "rolls ball" PLANE " as spher(a)\n", 4, 46, "unknown rolling shape 'spher'",
     "did you mean 'sphere'?"},
    {BALL "rolls ball" PLANE " as cube(a)\n", 4, 46, "unknown rolling shape 'cube'",
     "sphere(a), disk(a) and cylinder(a)"},
    {BALL "rolls ball" PLANE "\n", 4, 7, "rolls needs the shape", "as sphere(a)"},
    {BALL "rolls ball on table((0, 0, 1), (0, 0, 0)) as sphere(a)\n", 4, 15, "unknown surface",
     NULL},
    {BALL "rolls ball inside plane((0, 0, 1), (0, 0, 0)) as sphere(a)\n", 4, 19,
     "'inside' a plane", NULL},
    {BALL "rolls ball over" PLANE "\n", 4, 12, "expected 'on' or 'inside'", NULL},
    {BALL "rolls ball on plane((0, 0, 1)) as sphere(a)\n", 4, 30, "expected ','", NULL},
    {BALL "rolls ball on plane(1, (0, 0, 0)) as sphere(a)\n", 4, 21,
     "a scalar where a vector is needed", NULL},
    {BALL "rolls ball on plane((0, 0, 0), (0, 0, 0)) as sphere(a)\n", 4, 21,
     "the plane's normal is zero", NULL},
    {BALL "rolls ball" PLANE " as sphere(a) as sphere(a)\n", 4, 56, "the shape is given twice",
     NULL},
    {BALL "rolls ball" PLANE " turning 1 moving (1, 0, 0) as sphere(a)\n", 4, 53,
     "the surface's motion is given twice", NULL},
    {BALL "rolls ball" PLANE " as sphere(a) slipping\n", 4, 56, "expected 'as', 'moving' or "
     "'turning'", NULL},
    {BALL "rolls ball" PLANE " as sphere((a, 0))\n", 4, 53, "a vector where a scalar is needed",
     NULL},
    {"coordinates q\nbody d mass 1 inertia (1, 1, 1) at (0, 0, 0) orientation rot_z(q)\n"
     "rolls d" PLANE " as disk(1)\n", 3, 43, "the disk lies flat", NULL},
    {"coordinates q\nbody d mass 1 inertia (1, 1, 1) at (0, 0, 0) orientation rot_x(q)\n"
     "rolls d" PLANE " as cylinder(1)\n", 3, 43, "the cylinder's axis (body z) is not parallel "
     "to the surface", "as disk(a)"},
    {"coordinates q\nbody d mass 1 inertia (1, 1, 1) at (0, 2, 0) orientation rot_x(q)\n"
     "rolls d on cylinder(1, (0, 0, 0), (0, 0, 1)) as disk(1)\n", 3, 49,
     "the disk's axis (body z) is not parallel to the cylinder's axis", NULL},
    {"coordinates q\nbody d mass 1 inertia (1, 1, 1) at (0, 0, 3) orientation rot_z(q)\n"
     "rolls d on cylinder(1, (0, 0, 0), (0, 0, 1)) as cylinder(1)\n", 3, 7,
     "the body's centre is on the cylinder's axis", NULL},
    {"coordinates q\nbody d mass 1 inertia (1, 1, 1) at (0, 0, 3) orientation rot_z(q)\n"
     "rolls d" PLANE " as sphere(1)\n", 3, 7, "the body can never touch the surface", NULL},
    {BALL "rols ball" PLANE " as sphere(a)\n", 4, 1, "unknown statement 'rols'",
     "did you mean 'rolls'?"},
};

static void diagnostics(void **st) {
    (void)st;
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

/* "rolls" stays usable as a name defined before the statement existed. */
static void rolls_as_a_name(void **st) {
    (void)st;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse(ctx, "coordinates q\nrolls = 2*q\nT = rolls'^2\n");
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(sphere_on_plane),
        cmocka_unit_test(contact_built_in),
        cmocka_unit_test(sphere_on_turntable),
        cmocka_unit_test(upright_disk_is_desloge),
        cmocka_unit_test(leaning_disk),
        cmocka_unit_test(cylinder_inside),
        cmocka_unit_test(two_contacts),
        cmocka_unit_test(diagnostics),
        cmocka_unit_test(rolls_as_a_name),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
