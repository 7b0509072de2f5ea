/*
 * tests/mech/test_reaction.c - `reaction [LABEL:] CON on r`: the Cartesian
 * force of a constraint at a point (qd_eom_reaction), against the books:
 *   bead on a uniformly rotating wire (Goldstein sec. 1.6 ex. 3, reference
 *     seed-goldstein-britannica.md G03 and pitfall P2; Byerly Art. 6b TC07):
 *     the wire pushes with 2 m omega r' along its normal (-sin wt, cos wt);
 *   Atwood machine (Goldstein sec. 1.6 ex. 2): the rope pulls each mass up
 *     with the tension 2 m1 m2 g/(m1 + m2), and the rope also acts on the
 *     other mass (a nonzero residual);
 *   ladder on a smooth wall and floor, from rest (Desloge ch. 50 P8,
 *     seed-desloge-A.md T19): N_w = (3/4) m g sin th cos th horizontally at
 *     the top, N_f = m g (1 - (3/4) sin^2 th) vertically at the foot;
 *   bead on a helix (Desloge ch. 51 ex. 1, T15): the point moves on a
 *     cylinder (rank 2), so only the tangential and axial components are
 *     determined: F_z = -m g a^2/(a^2 + b^2), F_ph = m g a b/(a^2 + b^2),
 *     and the radial one is reported as 0;
 *   particle on a sphere: F = 2 lambda r (the gradient of the constraint).
 * Every force also satisfies the virtual-work equations F . dr/dq_j = R_j
 * (checked by finite differences of r).  Random states, fixed seed.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/mech.h"
#include "qdot/model.h"
#include "util/randexpr.h"
#include "util/system.h"

#define SEED 20260510u
#define NSTATES 10
#define MAXSYM 32

typedef qt_system fixture;

static int teardown(void **state) { return qt_system_teardown(state); }

static fixture *derive_opts(void **state, const char *text, bool eliminate) {
    return qt_system_derive(state, text, eliminate);
}

static fixture *derive(void **state, const char *text) { return derive_opts(state, text, false); }

typedef struct pt {
    size_t n;
    const qd_expr *syms[MAXSYM];
    double vals[MAXSYM];
} pt;

static void set(fixture *fx, pt *s, const char *name, double v) {
    s->syms[s->n] = qt_symbol(fx, name);
    s->vals[s->n++] = v;
}

/* Every parameter at its value in the model. */
static void params(fixture *fx, pt *s) {
    s->n = 0;
    for (size_t i = 0; i < qd_model_nparams(fx->model); i++) {
        s->syms[s->n] = qd_model_param(fx->model, i);
        s->vals[s->n++] = qd_number_value(qd_model_param_value(fx->model, i));
    }
}

static double param(fixture *fx, const char *name) {
    for (size_t i = 0; i < qd_model_nparams(fx->model); i++)
        if (!strcmp(qd_expr_name(qd_model_param(fx->model, i)), name))
            return qd_number_value(qd_model_param_value(fx->model, i));
    fail_msg("no parameter %s", name);
    return 0;
}

static bool close_to(double a, double b, double scale) {
    return fabs(a - b) <= 1e-9 * (scale + fabs(a) + fabs(b));
}

static void assert_vec(const double *got, const double *want, const char *what, int k) {
    double scale = 1 + fabs(want[0]) + fabs(want[1]) + fabs(want[2]);
    for (int i = 0; i < 3; i++)
        if (!close_to(got[i], want[i], scale))
            fail_msg("%s: F = (%.17g, %.17g, %.17g), expected (%.17g, %.17g, %.17g) "
                     "(state %d, seed %u)", what, got[0], got[1], got[2], want[0], want[1],
                     want[2], k, SEED);
}

/* The reaction i of the model at the state s; lambda and R from qd_eom_eval. */
static void reaction(fixture *fx, const pt *s, size_t i, double F[3], double *res, double *R) {
    const qd_eom *e = fx->eom;
    double lambda[8];
    assert_true(e->ncon <= 8);
    assert_int_equal(qd_eom_eval(fx->ctx, e, s->n, s->syms, s->vals, NULL, NULL, NULL, lambda, R),
                     QD_OK);
    const qd_expr *r[3];
    for (unsigned k = 0; k < 3; k++)
        r[k] = qd_model_reaction_point(fx->model, i, k);
    if (qd_eom_reaction(fx->ctx, e, qd_model_reaction_constraint(fx->model, i), r, s->n, s->syms,
                        s->vals, lambda, F, res) != QD_OK)
        fail_msg("reaction %s: %s", qd_model_reaction_name(fx->model, i),
                 qd_ctx_message(fx->ctx));
}

/* Virtual work: F . dr/dq_j = R_j (the whole R when the constraint has one
 * reaction), dr/dq_j by central differences of the model's point. */
static void assert_virtual_work(fixture *fx, pt *s, size_t i, const double F[3],
                                const double *R, int k) {
    const qd_eom *e = fx->eom;
    for (size_t j = 0; j < e->n; j++) {
        size_t at = 0;
        while (at < s->n && s->syms[at] != e->q[j])
            at++;
        assert_true(at < s->n);
        double old = s->vals[at], h = 1e-6 * (1 + fabs(old)), w = 0;
        for (unsigned c = 0; c < 3; c++) {
            double rp, rm;
            const qd_expr *x = qd_model_reaction_point(fx->model, i, c);
            s->vals[at] = old + h;
            assert_int_equal(qd_eval(fx->ctx, x, s->n, s->syms, s->vals, &rp), QD_OK);
            s->vals[at] = old - h;
            assert_int_equal(qd_eval(fx->ctx, x, s->n, s->syms, s->vals, &rm), QD_OK);
            w += F[c] * (rp - rm) / (2 * h);
        }
        s->vals[at] = old;
        if (fabs(w - R[j]) > 1e-6 * (1 + fabs(R[j])))
            fail_msg("F . dr/d%s = %.12g, R = %.12g (state %d)", qd_expr_name(e->q[j]), w, R[j],
                     k);
    }
}

/* ---- bead on a rotating wire ------------------------------------------------ */

static const char *bead = "coordinates x, y\n"
                          "parameters m = 1.5, omega = 2.2\n"
                          "particle m at (x, y)\n"
                          "constraint wire: y*cos(omega*t) - x*sin(omega*t) = 0\n"
                          "reaction wire on (x, y, 0)\n";

static void test_bead_wire(void **state) {
    fixture *fx = derive(state, bead);
    qt_rng rng = {SEED};
    double m = param(fx, "m"), w = param(fx, "omega");
    assert_int_equal(qd_model_nreactions(fx->model), 1);
    assert_string_equal(qd_model_reaction_name(fx->model, 0), "wire");
    assert_string_equal(qd_model_reaction_constraint(fx->model, 0), "wire");
    for (int k = 0; k < NSTATES; k++) {
        double t = qt_uniform(&rng, 0, 3), r = qt_uniform(&rng, -2, 2);
        double rd = qt_uniform(&rng, -2, 2), c = cos(w * t), s = sin(w * t);
        pt p;
        params(fx, &p);
        set(fx, &p, "t", t);
        set(fx, &p, "x", r * c);
        set(fx, &p, "y", r * s);
        set(fx, &p, "x'", rd * c - r * w * s);
        set(fx, &p, "y'", rd * s + r * w * c);
        double F[3], res, R[2], N = 2 * m * w * rd;
        reaction(fx, &p, 0, F, &res, R);
        assert_vec(F, (double[]){-N * s, N * c, 0}, "wire", k);
        assert_true(res < 1e-12);
        assert_virtual_work(fx, &p, 0, F, R, k);
    }
}

/* ---- Atwood machine ----------------------------------------------------------- */

static const char *atwood = "coordinates x1, x2\n"
                            "parameters m1 = 3, m2 = 1.25, l = 2, g = 9.81\n"
                            "particle m1 at (0, -x1)\n"
                            "particle m2 at (0, -x2)\n"
                            "V = -m1*g*x1 - m2*g*x2\n"
                            "constraint rope: x1 + x2 = l\n"
                            "reaction on_m1: rope on (0, -x1, 0)\n"
                            "reaction on_m2: rope on (0, -x2, 0)\n";

static void test_atwood(void **state) {
    fixture *fx = derive(state, atwood);
    qt_rng rng = {SEED + 1};
    double m1 = param(fx, "m1"), m2 = param(fx, "m2"), g = param(fx, "g");
    double T = 2 * m1 * m2 * g / (m1 + m2);
    assert_int_equal(qd_model_nreactions(fx->model), 2);
    assert_string_equal(qd_model_reaction_name(fx->model, 1), "on_m2");
    assert_string_equal(qd_model_reaction_constraint(fx->model, 1), "rope");
    assert_null(qd_model_reaction_name(fx->model, 2));
    assert_null(qd_model_reaction_point(fx->model, 0, 3));
    for (int k = 0; k < NSTATES; k++) {
        double x1 = qt_uniform(&rng, 0, 2), v = qt_uniform(&rng, -2, 2);
        pt p;
        params(fx, &p);
        set(fx, &p, "x1", x1);
        set(fx, &p, "x2", 2 - x1);
        set(fx, &p, "x1'", v);
        set(fx, &p, "x2'", -v);
        for (size_t i = 0; i < 2; i++) {
            double F[3], res, R[2];
            reaction(fx, &p, i, F, &res, R);
            assert_vec(F, (double[]){0, T, 0}, "rope", k); /* up, on either mass */
            /* R = (-T, -T); the force on one mass accounts for one entry */
            assert_true(fabs(res - sqrt(0.5)) < 1e-9);
        }
    }
}

/* ---- ladder --------------------------------------------------------------------- */

static const char *ladder =
    "coordinates x, y, theta\n"
    "parameters m = 2, l = 3, g = 9.81\n"
    "body rod mass m inertia rod(m, l) at (x, y, 0) orientation rot_z(theta)*rot_x(-pi/2)\n"
    "V = m*g*y\n"
    "constraint wall: x - l/2*sin(theta) = 0\n"
    "constraint floor: y - l/2*cos(theta) = 0\n"
    "reaction wall on (x - l/2*sin(theta), y + l/2*cos(theta), 0)\n"
    "reaction foot: floor on (x + l/2*sin(theta), y - l/2*cos(theta), 0)\n";

static void test_ladder(void **state) {
    fixture *fx = derive(state, ladder);
    qt_rng rng = {SEED + 2};
    double m = param(fx, "m"), l = param(fx, "l"), g = param(fx, "g");
    assert_string_equal(qd_model_reaction_name(fx->model, 1), "foot");
    assert_string_equal(qd_model_reaction_constraint(fx->model, 1), "floor");
    for (int k = 0; k < NSTATES; k++) {
        double th = qt_uniform(&rng, 0.1, 1.4), s = sin(th), c = cos(th);
        pt p;
        params(fx, &p);
        set(fx, &p, "x", l / 2 * s);
        set(fx, &p, "y", l / 2 * c);
        set(fx, &p, "theta", th);
        double F[3], res, R[3];
        reaction(fx, &p, 0, F, &res, R);
        assert_vec(F, (double[]){0.75 * m * g * s * c, 0, 0}, "wall", k);
        assert_true(res < 1e-12);
        reaction(fx, &p, 1, F, &res, R);
        assert_vec(F, (double[]){0, m * g * (1 - 0.75 * s * s), 0}, "floor", k);
        assert_true(res < 1e-12);
    }
}

/* ---- bead on a helix: rank 2 ------------------------------------------------------ */

static const char *helix = "coordinates ph, z\n"
                           "parameters m = 0.5, a = 1.3, b = 0.7, g = 9.81\n"
                           "particle m at (a*cos(ph), a*sin(ph), z)\n"
                           "V = -m*g*z\n"
                           "constraint helix: z - b*ph = 0\n"
                           "reaction helix on (a*cos(ph), a*sin(ph), z)\n";

static void test_helix(void **state) {
    fixture *fx = derive(state, helix);
    qt_rng rng = {SEED + 3};
    double m = param(fx, "m"), a = param(fx, "a"), b = param(fx, "b"), g = param(fx, "g");
    double D = a * a + b * b, Fz = -m * g * a * a / D, Fph = m * g * a * b / D;
    for (int k = 0; k < NSTATES; k++) {
        double ph = qt_uniform(&rng, -3, 3), v = qt_uniform(&rng, -2, 2);
        pt p;
        params(fx, &p);
        set(fx, &p, "ph", ph);
        set(fx, &p, "z", b * ph);
        set(fx, &p, "ph'", v);
        set(fx, &p, "z'", b * v);
        double F[3], res, R[2];
        reaction(fx, &p, 0, F, &res, R);
        assert_vec(F, (double[]){-Fph * sin(ph), Fph * cos(ph), Fz}, "helix", k);
        assert_true(res < 1e-12);
        assert_virtual_work(fx, &p, 0, F, R, k);
    }
}

/* ---- sphere, and a coordinate eliminated from the point --------------------------- */

static const char *sphere = "coordinates x, y, z\n"
                            "parameters m = 0.8, a = 1.3, g = 9.81\n"
                            "particle m at (x, y, z)\n"
                            "V = m*g*z\n"
                            "constraint plane: z = 0\n"
                            "constraint ring: x^2 + y^2 + z^2 = a^2\n"
                            "reaction ring on (x, y, z)\n"
                            "reaction plane on (x, y, z)\n";

static void sphere_state(fixture *fx, qt_rng *rng, pt *p, double *th, double *w) {
    double a = param(fx, "a");
    *th = qt_uniform(rng, -3, 3);
    *w = qt_uniform(rng, -2, 2);
    params(fx, p);
    set(fx, p, "x", a * cos(*th));
    set(fx, p, "y", a * sin(*th));
    set(fx, p, "z", 0);
    set(fx, p, "x'", -a * *w * sin(*th));
    set(fx, p, "y'", a * *w * cos(*th));
}

/* A particle on a horizontal ring: the ring pulls it in with m a w^2, the
 * plane holds it up with m g. */
static void test_ring(void **state) {
    fixture *fx = derive(state, sphere);
    qt_rng rng = {SEED + 4};
    double m = param(fx, "m"), a = param(fx, "a"), g = param(fx, "g");
    for (int k = 0; k < NSTATES; k++) {
        double th, w, F[3], res, R[3];
        pt p;
        sphere_state(fx, &rng, &p, &th, &w);
        reaction(fx, &p, 0, F, &res, R);
        double N = m * a * w * w;
        assert_vec(F, (double[]){-N * cos(th), -N * sin(th), 0}, "ring", k);
        reaction(fx, &p, 1, F, &res, R);
        assert_vec(F, (double[]){0, 0, m * g}, "plane", k);
    }
}

/* With --eliminate, z = 0 is substituted: the ring keeps its multiplier and
 * its reaction; the plane has none and says so. */
static void test_ring_eliminated(void **state) {
    fixture *fx = derive_opts(state, sphere, true);
    qt_rng rng = {SEED + 5};
    double m = param(fx, "m"), a = param(fx, "a");
    assert_int_equal(fx->eom->nelim, 1);
    assert_int_equal(fx->eom->ncon, 1);
    for (int k = 0; k < NSTATES; k++) {
        double th, w, F[3], res, R[3];
        pt p;
        sphere_state(fx, &rng, &p, &th, &w);
        reaction(fx, &p, 0, F, &res, R);
        double N = m * a * w * w;
        assert_vec(F, (double[]){-N * cos(th), -N * sin(th), 0}, "ring", k);
    }
    const qd_expr *r[3] = {qd_int(fx->ctx, 0), qd_int(fx->ctx, 0), qd_int(fx->ctx, 0)};
    double lambda[1] = {1}, F[3];
    pt p;
    params(fx, &p);
    assert_int_equal(qd_eom_reaction(fx->ctx, fx->eom, "plane", r, p.n, p.syms, p.vals, lambda,
                                     F, NULL),
                     QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(fx->ctx), "eliminate"));
    qd_ctx_clear_error(fx->ctx);
    assert_int_equal(qd_eom_reaction(fx->ctx, fx->eom, "nosuch", r, p.n, p.syms, p.vals, lambda,
                                     F, NULL),
                     QD_ERR_ARG);
    qd_ctx_clear_error(fx->ctx);
}

/* ---- the statement's errors ------------------------------------------------------ */

static void parse_fails(const char *text, size_t line, const char *message) {
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, text, &d);
    if (m)
        fail_msg("parsed, but should fail: %s", text);
    assert_int_equal(d.line, line);
    if (!strstr(d.message, message))
        fail_msg("message '%s' lacks '%s'", d.message, message);
    qd_ctx_free(ctx);
}

static void test_errors(void **state) {
    (void)state;
    const char *head = "coordinates x, y\nparticle 1 at (x, y)\nconstraint c: x = y\n";
    char text[512];
    struct { const char *line, *message; } cases[] = {
        {"reaction d on (x, y, 0)\n", "'d' is not a constraint"},
        {"reaction c on (x', y, 0)\n", "depends on x'"},
        {"reaction c at (x, y, 0)\n", "expected 'on'"},
        {"reaction c on (x, y, 0)\nreaction c on (x, 0, 0)\n", "already given"},
        {"reaction c on x\n", "a position"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        snprintf(text, sizeof text, "%s%s", head, cases[i].line);
        parse_fails(text, i == 3 ? 5 : 4, cases[i].message);
    }
    /* a constraint is declared before its reaction */
    parse_fails("coordinates x\nparticle 1 at (x, 0)\nreaction c on (x, 0, 0)\n"
                "constraint c: x = 1\n", 3, "not a constraint");
    /* labels tell two reactions of one constraint apart */
    snprintf(text, sizeof text, "%sreaction c on (x, y, 0)\nreaction other: c on (x, 0, 0)\n",
             head);
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qd_model_parse(ctx, text, NULL);
    assert_non_null(m);
    assert_int_equal(qd_model_nreactions(m), 2);
    assert_string_equal(qd_model_reaction_name(m, 1), "other");
    qd_model_free(m);
    /* "reaction" stays usable as a name */
    m = qd_model_parse(ctx, "coordinates x\nreaction = 2\nT = reaction*x'^2\n", NULL);
    assert_non_null(m);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(test_bead_wire, teardown),
        cmocka_unit_test_teardown(test_atwood, teardown),
        cmocka_unit_test_teardown(test_ladder, teardown),
        cmocka_unit_test_teardown(test_helix, teardown),
        cmocka_unit_test_teardown(test_ring, teardown),
        cmocka_unit_test_teardown(test_ring_eliminated, teardown),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
