/*
 * tests/mech/test_phase.c - a model's phase space (qd_phase, qdot/canonical.h;
 * issue 31): the momenta named as hamilton.h names them, functions on phase
 * space read from text (a velocity refused at its place), dF/dt along the
 * motion against Hamilton's equations by hand (Goldstein ch. 9.5: dF/dt =
 * [F, H] + dF/dt|explicit), the new variables' names, and the given
 * symmetries and integrals of qdot/integrals.h (Noether's angular momentum
 * of the Kepler problem, its energy and Runge-Lenz vector conserved).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <string.h>

#include "qdot/qdot.h"
#include "qdot/canonical.h"
#include "qdot/integrals.h"
#include "qdot/read.h"

static qd_model *parse(qd_ctx *ctx, const char *text) {
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, text, &d);
    assert_non_null(m);
    return m;
}

/* a - b simplifies to 0, b read from text in ctx's names */
static void assert_same(qd_ctx *ctx, const qd_expr *a, const char *b) {
    qd_read_opts o = {.new_symbols = true};
    const qd_expr *x = qd_read(ctx, b, &o, NULL);
    assert_non_null(a);
    assert_non_null(x);
    assert_true(qd_is_zero(qd_simplify(ctx, qd_sub(ctx, a, x))));
}

static const char FREE[] = "coordinates x, y, z\nparameters m = 1\nparticle m at (x, y, z)\n";
static const char OSC[] = "coordinates x\nparameters m = 2, k = 3\nT = m/2*x'^2\nV = k/2*x^2\n";

/* [L_x, L_y] = L_z read from text, in the momenta p_x, p_y, p_z. */
static void test_read_and_bracket(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse(ctx, FREE);
    qd_phase ph;
    assert_int_equal(qd_phase_init(ctx, m, &ph), QD_OK);
    assert_int_equal(ph.n, 3);
    assert_string_equal(qd_expr_name(ph.p[1]), "p_y");
    qd_diag err;
    const qd_expr *Lx = qd_phase_read(ctx, &ph, "y*p_z - z*p_y", &err);
    const qd_expr *Ly = qd_phase_read(ctx, &ph, "z*p_x - x*p_z", &err);
    assert_same(ctx, qd_bracket(ctx, ph.n, ph.q, ph.p, Lx, Ly), "x*p_y - y*p_x");
    /* an unknown name and a velocity are errors, the velocity at its place */
    assert_null(qd_phase_read(ctx, &ph, "w*x", &err));
    qd_ctx_clear_error(ctx);
    assert_null(qd_phase_read(ctx, &ph, "p_x + y'", &err));
    assert_int_equal(err.status, QD_ERR_ARG);
    assert_true(err.located);
    assert_int_equal(err.offset, 6);
    assert_int_equal(err.length, 2);
    assert_non_null(strstr(err.message, "velocity"));
    qd_phase_free(&ph);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* A list needs one expression per coordinate; an item's error is located
 * in the whole list. */
static void test_read_list(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse(ctx, FREE);
    qd_phase ph;
    assert_int_equal(qd_phase_init(ctx, m, &ph), QD_OK);
    const qd_expr *out[3];
    qd_diag err;
    assert_int_equal(qd_phase_read_list(ctx, &ph, "x + y, atan2(y, x), z", out, &err), QD_OK);
    assert_same(ctx, out[0], "x + y");
    assert_same(ctx, out[2], "z");
    assert_int_equal(qd_phase_read_list(ctx, &ph, "x, y", out, &err), QD_ERR_ARG);
    assert_int_not_equal(qd_phase_read_list(ctx, &ph, "x, y, z'", out, &err), QD_OK);
    assert_int_equal(err.offset, 6); /* z' in the third item */
    qd_phase_free(&ph);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* The oscillator H = p^2/(2m) + k x^2/2: d/dt(x p) = p^2/m - k x^2 (the
 * virial), d/dt H = 0, and with a damping D = b x'^2/2 the energy decays at
 * dH/dt = -b p^2/m^2 (the dissipated power b x'^2). */
static void test_dt(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse(ctx, OSC);
    qd_phase ph;
    qd_diag err;
    assert_int_equal(qd_phase_init(ctx, m, &ph), QD_OK);
    assert_same(ctx, qd_phase_dt(ctx, &ph, qd_phase_read(ctx, &ph, "x*p_x", &err)),
                "p_x^2/m - k*x^2");
    assert_same(ctx, qd_phase_dt(ctx, &ph, ph.h->H), "0");
    assert_int_equal(qd_phase_ham(ctx, &ph, true), QD_OK); /* a closed-form H */
    qd_phase_free(&ph);
    qd_model_free(m);
    qd_model *md = parse(ctx, "coordinates x\nparameters m = 2, k = 3, b = 1\n"
                              "T = m/2*x'^2\nV = k/2*x^2\ndissipation = b/2*x'^2\n");
    assert_int_equal(qd_phase_init(ctx, md, &ph), QD_OK);
    const qd_expr *E = qd_phase_read(ctx, &ph, "p_x^2/(2*m) + k*x^2/2", &err);
    assert_same(ctx, qd_phase_dt(ctx, &ph, E), "-b*p_x^2/m^2");
    qd_phase_free(&ph);
    qd_model_free(md);
    qd_ctx_free(ctx);
}

/* The name H in a bracket's operand is the model's Hamiltonian (audit,
 * Desloge C T57): [x, H] = p/m and [p, H] = -k x for the oscillator
 * (Hamilton's equations, Goldstein ch. 9.5); a parameter named H keeps its
 * meaning, and other unknown names are still refused. */
static void test_read_h(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse(ctx, OSC);
    qd_phase ph;
    qd_diag err;
    assert_int_equal(qd_phase_init(ctx, m, &ph), QD_OK);
    const qd_expr *H = qd_phase_read_h(ctx, &ph, "H", &err);
    const qd_expr *x = qd_phase_read_h(ctx, &ph, "x", &err);
    const qd_expr *p = qd_phase_read_h(ctx, &ph, "p_x", &err);
    assert_same(ctx, qd_bracket(ctx, 1, ph.q, ph.p, x, H), "p_x/m");
    assert_same(ctx, qd_bracket(ctx, 1, ph.q, ph.p, p, H), "-k*x");
    assert_null(qd_phase_read_h(ctx, &ph, "Hz", &err));
    qd_phase_free(&ph);
    qd_model_free(m);
    qd_ctx_free(ctx);
    ctx = qd_ctx_new(); /* a fresh context: the name H is a symbol in the old one */
    qd_model *mh = parse(ctx, "coordinates x\nparameters H = 2\nT = x'^2/2\nV = H*x\n");
    assert_int_equal(qd_phase_init(ctx, mh, &ph), QD_OK);
    assert_same(ctx, qd_phase_read_h(ctx, &ph, "H*x", &err), "H*x");
    qd_phase_free(&ph);
    qd_model_free(mh);
    qd_ctx_free(ctx);
}

/* A parameter fixed when the model is read stands for its number in what
 * is read beside it; the new variables are Q, P or Q1.., P1... */
static void test_fixed_and_new_vars(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_param_value pv = {"m", qd_int(ctx, 5)};
    qd_model_opts o = {.params = &pv, .nparams = 1, .fix_params = true};
    qd_diag d;
    qd_model *m = qd_model_parse_opts(ctx, OSC, &o, &d);
    assert_non_null(m);
    qd_phase ph;
    qd_diag err;
    assert_int_equal(qd_phase_init(ctx, m, &ph), QD_OK);
    assert_ptr_equal(qd_phase_read(ctx, &ph, "m*x", &err),
                     qd_mul(ctx, qd_int(ctx, 5), ph.q[0]));
    assert_null(qd_phase_read(ctx, &ph, "Q", &err)); /* not made yet */
    qd_ctx_clear_error(ctx);
    assert_int_equal(qd_phase_new_vars(ctx, &ph), QD_OK);
    assert_string_equal(qd_expr_name(ph.Q[0]), "Q");
    assert_string_equal(qd_expr_name(ph.P[0]), "P");
    assert_non_null(qd_phase_read(ctx, &ph, "x*P", &err));
    qd_phase_free(&ph);
    qd_model_free(m);
    qd_model *f = parse(ctx, FREE);
    assert_int_equal(qd_phase_init(ctx, f, &ph), QD_OK);
    assert_int_equal(qd_phase_new_vars(ctx, &ph), QD_OK);
    assert_string_equal(qd_expr_name(ph.Q[2]), "Q3");
    assert_string_equal(qd_expr_name(ph.P[0]), "P1");
    qd_phase_free(&ph);
    qd_model_free(f);
    qd_ctx_free(ctx);
}

/* Kepler (examples/kepler_cartesian.qd): the rotation's Noether integral is
 * the angular momentum m (x y' - y x'); energy and Runge-Lenz conserved, a
 * wrong "integral" (x alone) not. */
static void test_given(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse(ctx, "coordinates x, y\nparameters m = 1.3, k = 4\nr = (x, y)\n"
                             "particle m at r\nV = -k/norm(r)\n"
                             "symmetry rot: delta x = -y, delta y = x\n"
                             "integral energy: m/2*(x'^2 + y'^2) - k/sqrt(x^2 + y^2)\n"
                             "integral Ax: m*y'*m*(x*y' - y*x') - m*k*x/sqrt(x^2 + y^2)\n"
                             "integral wrong: x\n");
    qd_eom *e = qd_eom_derive(ctx, m);
    assert_non_null(e);
    qd_integrals *I = qd_integrals_derive(ctx, m, e, NULL);
    assert_non_null(I);
    qd_integrals_given g;
    assert_int_equal(qd_integrals_given_derive(ctx, I, m, &g), QD_OK);
    assert_int_equal(g.nnoether, 1);
    assert_true(g.noether[0].invariant && g.noether[0].conserved);
    assert_same(ctx, g.noether[0].integral, "m*(x*y' - y*x')");
    assert_int_equal(g.nproposed, 3);
    assert_true(g.proposed[0].conserved);
    assert_true(g.proposed[1].conserved);
    assert_false(g.proposed[2].conserved);
    assert_string_equal(g.proposed[2].name, "wrong");
    /* the whole analysis renders (its content is checked by the docs replay) */
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_integrals_json(ctx, I, &g, "kepler.qd", &b), QD_OK);
    assert_int_equal(qd_integrals_print(ctx, I, NULL, NULL, &b), QD_OK);
    qd_buf_free(&b);
    qd_integrals_given_free(&g);
    qd_integrals_free(I);
    qd_eom_free(e);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_read_and_bracket),
        cmocka_unit_test(test_read_list),
        cmocka_unit_test(test_dt),
        cmocka_unit_test(test_read_h),
        cmocka_unit_test(test_fixed_and_new_vars),
        cmocka_unit_test(test_given),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
