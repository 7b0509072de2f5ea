/*
 * tests/lyap/test_lyap_setup.c - the exponents of a run set up as qdot
 * lyapunov takes it (qd_lyap_setup_run):
 *
 *   - the harmonic oscillator x'' = -x: both exponents 0 (a rotation of the
 *     tangent plane; Lichtenberg & Lieberman, Regular and Chaotic Dynamics,
 *     sec. 5.2), pairing lambda_1 + lambda_2 = 0 (Hamiltonian);
 *   - the inverted oscillator x'' = a^2 x (V = -a^2 x^2/2): exponents +a and
 *     -a, deviations growing as exp(a t) (the linear system's own rates);
 *   - the damped oscillator x'' = -x - b x': the exponents sum to the mean
 *     of tr J = -b (Liouville), and the report says the system is not
 *     conservative;
 *   - the refusals, naming their field: a model given by H (no_speeds),
 *     more exponents than 2n (exponents);
 *   - the flow of such a run (qd_flow_setup_run): the oscillator's flow at
 *     t is the rotation [[cos t, sin t], [-sin t, cos t]] of (x, x'), its
 *     determinant 1 (Liouville); a quarter period swaps x and x'.
 */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "qdot/qdot.h"
#include "qdot/lyapunov.h"
#include "qdot/simsetup.h"

typedef struct fix {
    qd_ctx *ctx;
    qd_model *m;
    qd_sim_setup *set;
    qd_sim_opts o;
} fix;

static fix load(const char *text, const char *t_end) {
    fix f = {qd_ctx_new(), NULL, NULL, {0}};
    f.m = qd_model_parse(f.ctx, text, NULL);
    assert_non_null(f.m);
    f.set = qd_sim_setup_new(f.ctx, f.m, false);
    assert_non_null(f.set);
    qd_sim_setup_opts so = {.t_end = t_end, .method = "dop853", .rtol = "1e-11",
                            .atol = "1e-13"};
    assert_int_equal(qd_sim_setup_options(f.set, &so, &f.o), QD_OK);
    return f;
}

static void unload(fix *f) {
    qd_sim_setup_free(f->set);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
}

static qd_lyap_result run(fix *f, size_t nexp, double transient) {
    qd_lyap_opts lo = {.nexp = nexp, .renorm = 0.5, .transient = transient};
    qd_lyap_result r;
    assert_int_equal(qd_lyap_setup_run(f->ctx, f->set, f->m, &f->o, &lo, &r), QD_OK);
    assert_int_equal(r.opts.nexp, nexp ? nexp : 1);
    assert_true(r.report.exps == r.exps && r.report.opts == &r.opts);
    return r;
}

static void test_oscillator(void **state) {
    (void)state;
    fix f = load("coordinates x\nT = x'^2/2\nV = x^2/2\ninitial x = 1\n", "100");
    qd_lyap_result r = run(&f, 2, 0);
    assert_true(fabs(r.exps[0]) < 1e-6 && fabs(r.exps[1]) < 1e-6);
    assert_true(r.report.conservative);
    assert_int_equal(r.report.ndof, 1);
    qd_lyap_result_free(&r);
    r = run(&f, 0, 0); /* the largest alone */
    assert_true(fabs(r.exps[0]) < 1e-6);
    qd_lyap_result_free(&r);
    unload(&f);
}

static void test_inverted(void **state) {
    (void)state;
    fix f = load("coordinates x\nparameters a = 0.7\nT = x'^2/2\nV = -a^2*x^2/2\n"
                 "initial x = 0\n", "60");
    qd_lyap_result r = run(&f, 2, 20); /* the transient: the vectors align first */
    assert_true(fabs(r.exps[0] - 0.7) < 1e-6);
    assert_true(fabs(r.exps[1] + 0.7) < 1e-6);
    qd_lyap_result_free(&r);
    unload(&f);
}

static void test_damped(void **state) {
    (void)state;
    fix f = load("coordinates x\nparameters b = 0.3\nT = x'^2/2\nV = x^2/2\n"
                 "Q[x] = -b*x'\ninitial x = 1\n", "100");
    qd_lyap_result r = run(&f, 2, 0);
    assert_false(r.report.conservative);
    assert_true(fabs(r.stats.trace_mean + 0.3) < 1e-9);
    assert_true(fabs(r.exps[0] + r.exps[1] + 0.3) < 1e-6);
    qd_lyap_result_free(&r);
    unload(&f);
}

static void refused(const char *text, size_t nexp, const char *name) {
    fix f = load(text, "10");
    qd_lyap_opts lo = {.nexp = nexp};
    qd_lyap_result r;
    assert_int_equal(qd_lyap_setup_run(f.ctx, f.set, f.m, &f.o, &lo, &r), QD_ERR_ARG);
    assert_string_equal(qd_ctx_diag(f.ctx)->name, name);
    assert_null(r.exps);
    qd_lyap_result_free(&r);
    unload(&f);
}

static void test_refusals(void **state) {
    (void)state;
    refused("coordinates q\nmomenta p\nH = p^2/2 + q^2/2\ninitial q = 1\n", 1, "no_speeds");
    refused("coordinates x\nT = x'^2/2\nV = x^2/2\ninitial x = 1\n", 3, "exponents");
}

/* The CSV rows' lines, counted. */
static int count_lines(void *data, const char *bytes, size_t len) {
    for (size_t k = 0; k < len; k++)
        *(size_t *)data += bytes[k] == '\n';
    return 0;
}

static void test_flow(void **state) {
    (void)state;
    fix f = load("coordinates x\nT = x'^2/2\nV = x^2/2\ninitial x = 1\n", "pi/2");
    qd_flow fl;
    qd_sim_opts used;
    size_t lines = 0;
    assert_int_equal(qd_flow_setup_run(f.ctx, f.set, f.m, &f.o, count_lines, &lines, &used, &fl),
                     QD_OK);
    const double want[4] = {0, 1, -1, 0};
    for (size_t k = 0; k < 4; k++)
        assert_true(fabs(fl.phi[k] - want[k]) < 1e-8);
    assert_true(fabs(fl.det - 1) < 1e-8);
    assert_true(fabs(fl.y[0]) < 1e-8 && fabs(fl.y[1] + 1) < 1e-8); /* x = cos t, x' = -sin t */
    assert_int_equal(used.method, f.o.method);
    assert_int_equal(lines, 102); /* the header, the row at t0 and 100 more */
    qd_flow_free(&fl);
    unload(&f);
    f = load("coordinates q\nmomenta p\nH = p^2/2 + q^2/2\ninitial q = 1\n", "1");
    assert_int_equal(qd_flow_setup_run(f.ctx, f.set, f.m, &f.o, NULL, NULL, &used, &fl),
                     QD_ERR_ARG);
    assert_string_equal(qd_ctx_diag(f.ctx)->name, "no_speeds");
    qd_flow_free(&fl);
    unload(&f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_oscillator), cmocka_unit_test(test_inverted),
        cmocka_unit_test(test_damped),     cmocka_unit_test(test_refusals),
        cmocka_unit_test(test_flow),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
