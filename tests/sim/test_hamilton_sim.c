/*
 * tests/sim/test_hamilton_sim.c - simulation of models given by H:
 * Hamilton's equations integrated as given (qd_sim_new_hamilton), also
 * when d^2H/dp^2 is singular and H has no Lagrangian.
 *
 *   - H = p x: x' = x, p' = -p, so x = x0 e^t, p = p0 e^-t and H = x p is
 *     kept (a first-order system: Desloge ch. 71 on H linear in p);
 *   - H = p_x y - p_y x: x' = y, y' = -x, the rotation x = cos t,
 *     y = -sin t from (1, 0), with every method;
 *   - the Kepler problem given by H (docs/language.md, models given by H)
 *     against the same model given by T and V (the Lagrangian run):
 *     the same final state, p_theta = m r^2 theta' kept;
 *   - velocities instead of momenta for a singular H: QD_ERR_SINGULAR.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "sim_fixture.h"

typedef struct hfix {
    qd_ctx *ctx;
    qd_model *m;
    qd_sim *s;
    double q0[4], qd0[4], last[32];
    qd_sim_stats stats;
} hfix;

static hfix *hload(const char *text) {
    hfix *f = calloc(1, sizeof *f);
    qd_diag d;
    f->ctx = qd_ctx_new();
    f->m = qd_model_parse(f->ctx, text, &d);
    assert_non_null(f->m);
    f->s = qd_sim_new_hamilton(f->ctx, f->m);
    if (!f->s)
        fail_msg("qd_sim_new_hamilton: %s", qd_ctx_message(f->ctx));
    for (size_t i = 0; i < qd_model_ncoords(f->m); i++) {
        f->q0[i] = sf_number(f->ctx, qd_model_initial(f->m, i, 0));
        f->qd0[i] = sf_number(f->ctx, qd_model_initial(f->m, i, 1));
    }
    return f;
}

static void hfree(hfix *f) {
    qd_sim_free(f->s);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
    free(f);
}

static qd_status hrun(hfix *f, qd_sim_method method, double t_end, double dt, const double *p0) {
    qd_sim_opts o = {.method = method, .t_end = t_end, .dt = dt, .rtol = dt > 0 ? 0 : 1e-12,
                     .atol = 1e-14, .q0 = f->q0, .qd0 = f->qd0, .p0 = p0};
    return qd_sim_run(f->s, &o, NULL, NULL, &f->stats, f->last);
}

static void test_linear_in_p(void **state) {
    (void)state;
    hfix *f = hload("coordinates x\nmomenta p\nH = p*x\ninitial x = 1\n");
    assert_true(qd_sim_canonical(f->s));
    const char *names[8];
    assert_int_equal(qd_sim_columns(f->s, QD_SIM_DOP853, names, 8), 5);
    assert_string_equal(names[3], "p");
    double p0 = 2;
    qd_sim_method ms[] = {QD_SIM_DOP853, QD_SIM_GL6, QD_SIM_BDF};
    for (int i = 0; i < 3; i++) {
        assert_int_equal(hrun(f, ms[i], 1.5, ms[i] == QD_SIM_GL6 ? 0.01 : 0, &p0), QD_OK);
        double x = exp(1.5), p = 2 * exp(-1.5);
        double tol = ms[i] == QD_SIM_BDF ? 1e-6 : 1e-10;
        /* row: t, x, x', p, energy */
        assert_true(fabs(f->last[1] - x) < tol * x);
        assert_true(fabs(f->last[2] - x) < tol * x); /* x' = dH/dp = x */
        assert_true(fabs(f->last[3] - p) < tol * x);
        assert_true(fabs(f->last[4] - 2) < tol * 10);
    }
    /* velocities do not determine p: say so */
    assert_int_equal(hrun(f, QD_SIM_DOP853, 1, 0, NULL), QD_ERR_SINGULAR);
    assert_non_null(strstr(qd_ctx_message(f->ctx), "give the momenta"));
    hfree(f);
}

static void test_rotation(void **state) {
    (void)state;
    hfix *f = hload("coordinates x, y\nmomenta px, py\nH = px*y - py*x\ninitial x = 1\n");
    double p0[2] = {0.5, -0.25};
    qd_sim_method ms[] = {QD_SIM_DOPRI5, QD_SIM_DOP853, QD_SIM_GL4, QD_SIM_GL6};
    for (int i = 0; i < 4; i++) {
        assert_int_equal(hrun(f, ms[i], 3, ms[i] >= QD_SIM_GL2 ? 0.005 : 0, p0), QD_OK);
        /* t, x, y, x', y', px, py, energy */
        double tol = ms[i] == QD_SIM_DOPRI5 ? 1e-9 : 1e-10;
        assert_true(fabs(f->last[1] - cos(3.0)) < tol);
        assert_true(fabs(f->last[2] + sin(3.0)) < tol);
        assert_true(fabs(f->last[3] - f->last[2]) < 1e-15);  /* x' = y */
        /* p rotates the same way: px' = py, py' = -px */
        assert_true(fabs(f->last[5] - (0.5 * cos(3.0) - 0.25 * sin(3.0))) < tol);
        assert_true(fabs(f->last[7] - (0.5 * 0 - (-0.25) * 1)) < 10 * tol);
    }
    hfree(f);
}

static const char kepler_h[] = "coordinates r, theta\nparameters m = 1.3, k = 4\n"
                               "momenta p_r, p_theta\n"
                               "H = p_r^2/(2*m) + p_theta^2/(2*m*r^2) - k/r\n"
                               "initial r = 1, theta = 0, r' = 0.3, theta' = 1.2\n";
static const char kepler_l[] = "coordinates r, theta\nparameters m = 1.3, k = 4\n"
                               "T = m*(r'^2 + r^2*theta'^2)/2\nV = -k/r\n"
                               "initial r = 1, theta = 0, r' = 0.3, theta' = 1.2\n";

static void test_regular_against_lagrangian(void **state) {
    (void)state;
    hfix *h = hload(kepler_h);
    sim_fix *l = sf_load(kepler_l);
    assert_non_null(l);
    /* momenta from the velocities: p_r = m r', p_theta = m r^2 theta' */
    assert_int_equal(hrun(h, QD_SIM_DOP853, 4, 0, NULL), QD_OK);
    qd_sim_opts o = {.method = QD_SIM_DOP853, .t_end = 4, .rtol = 1e-12, .atol = 1e-14,
                     .q0 = l->q0, .qd0 = l->qd0};
    double last[16];
    assert_int_equal(qd_sim_run(l->s, &o, NULL, NULL, NULL, last), QD_OK);
    /* H rows: t, r, theta, r', theta', p_r, p_theta, energy; L rows: t, r,
     * theta, r', theta', energy */
    for (int k = 1; k <= 4; k++)
        assert_true(fabs(h->last[k] - last[k]) < 1e-8 * (1 + fabs(last[k])));
    assert_true(fabs(h->last[7] - last[5]) < 1e-9);
    assert_true(fabs(h->last[6] - 1.3 * 1.2) < 1e-12);
    assert_true(fabs(h->last[5] - 1.3 * h->last[3]) < 1e-12);
    assert_true(h->stats.energy_error_max < 1e-10);
    sf_free(l);
    hfree(h);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_linear_in_p),
        cmocka_unit_test(test_rotation),
        cmocka_unit_test(test_regular_against_lagrangian),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
