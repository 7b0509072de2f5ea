/*
 * tests/mech/test_metric.c - the tensors of generalized coordinates
 * (qd_metric_new, qdot/metric.h) against Desloge vol. 2 (seed 000).
 *
 * - Spherical coordinates, one particle (ch. 55 pp. 570-572; reference
 *   seed-desloge-A.md T49): g = m diag(1, r^2, r^2 sin^2 th) and the six
 *   nonzero Gamma^l_ij: Gamma^r_thth = -r, Gamma^r_phph = -r sin^2 th,
 *   Gamma^th_rth = 1/r, Gamma^th_phph = -sin th cos th, Gamma^ph_rph = 1/r,
 *   Gamma^ph_thph = cot th; every other one 0; [ij,l] = g_lk Gamma^k_ij
 *   (App. 23 eq. 23); det J = r^2 sin th, singular at r = 0 and th = k pi.
 * - Generalized force components (ch. 47 Ex. 1, eqs. 24-26; T01): for
 *   physical components (F_r, F_th, F_ph), G = (F_r, r F_th, r sin th F_ph),
 *   and the scale factors 1, r, r sin th of the unweighted space give back
 *   the physical components (eq. 18), whatever the mass.
 * - Oblique axes x = u + v cos(al), y = v sin(al) (ch. 47 Fig. 1: physical
 *   against ordinary components): for a constant force (Fx, Fy), G = (Fx,
 *   Fx cos al + Fy sin al); the physical components are those projections,
 *   the ordinary ones the parallelogram's sides (Fx - Fy cot al, Fy / sin al).
 * - The geodesic form equals Lagrange's equations (ch. 55 eqs. 6, 12):
 *   g_lk (geodesic_k) = M_l. q'' - f_l at random states, for the double
 *   pendulum (seed 002 Exercise 22: a metric that depends on q), and for a
 *   bead in a tube turning at omega (T1 = 0, T0 = m omega^2 r^2/2: not in the
 *   metric, a centrifugal force in Q).
 * - Polar coordinates: det J = r, singular at r = 0.
 * - A relativistic L (not quadratic in the velocities) has no metric.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include "qdot/qdot.h"

typedef struct fix {
    qd_ctx *ctx;
    qd_model *m;
    qd_metric *g;
} fix;

static fix load(const char *text) {
    fix f = {.ctx = qd_ctx_new()};
    assert_non_null(f.ctx);
    qd_diag d;
    f.m = qd_model_parse(f.ctx, text, &d);
    if (!f.m)
        fail_msg("parse: %s", d.message);
    f.g = qd_metric_new(f.ctx, f.m);
    if (!f.g)
        fail_msg("metric: %s", qd_ctx_message(f.ctx));
    return f;
}

/* The model's parameters appended to syms/vals at k; the new count. */
static size_t with_params(const fix *f, size_t k, const qd_expr **syms, double *vals) {
    for (size_t i = 0; i < qd_model_nparams(f->m); i++) {
        syms[k] = qd_model_param(f->m, i);
        assert_int_equal(qd_model_param_number(f->m, i, &vals[k]), QD_OK);
        k++;
    }
    return k;
}

static void unload(fix *f) {
    qd_metric_free(f->g);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
}

/* x simplifies to the expression in text (read in f's context). */
static void assert_is(fix *f, const qd_expr *x, const char *text) {
    const qd_expr *want = qd_read(f->ctx, text, NULL, NULL);
    assert_non_null(want);
    const qd_expr *d = qd_simplify(f->ctx, qd_sub(f->ctx, x, want));
    assert_non_null(d);
    if (!qd_is_zero(d)) {
        qd_buf b = QD_BUF_INIT;
        qd_print(f->ctx, x, QD_FMT_TEXT, &b);
        fail_msg("got %s, want %s", qd_buf_str(&b), text);
    }
}

static const char spherical[] =
    "coordinates r, th, ph\n"
    "parameters m = 2, k = 1\n"
    "particle m at (r*sin(th)*cos(ph), r*sin(th)*sin(ph), r*cos(th))\n"
    "V = -k/r\n";

static void test_spherical_christoffel(void **state) {
    (void)state;
    fix f = load(spherical);
    const qd_metric *g = f.g;
    assert_int_equal(g->n, 3);
    static const char *const metric[9] = {"m", "0", "0", "0", "m*r^2", "0",
                                          "0", "0", "m*r^2*sin(th)^2"};
    for (size_t i = 0; i < 9; i++)
        assert_is(&f, g->g[i], metric[i]);
    /* Gamma^l_ij at [l][i][j]: r = 0, th = 1, ph = 2 */
    const char *want[27];
    for (size_t i = 0; i < 27; i++)
        want[i] = "0";
    want[(0 * 3 + 1) * 3 + 1] = "-r";
    want[(0 * 3 + 2) * 3 + 2] = "-r*sin(th)^2";
    want[(1 * 3 + 0) * 3 + 1] = want[(1 * 3 + 1) * 3 + 0] = "1/r";
    want[(1 * 3 + 2) * 3 + 2] = "-sin(th)*cos(th)";
    want[(2 * 3 + 0) * 3 + 2] = want[(2 * 3 + 2) * 3 + 0] = "1/r";
    want[(2 * 3 + 1) * 3 + 2] = want[(2 * 3 + 2) * 3 + 1] = "cos(th)/sin(th)";
    for (size_t i = 0; i < 27; i++)
        assert_is(&f, g->second[i], want[i]);
    /* the first kind is the second lowered: [ij,l] = g_ll Gamma^l_ij (g diagonal) */
    for (size_t l = 0; l < 3; l++)
        for (size_t ij = 0; ij < 9; ij++) {
            const qd_expr *low = qd_mul(f.ctx, g->g[l * 3 + l], g->second[l * 9 + ij]);
            const qd_expr *d = qd_simplify(f.ctx, qd_sub(f.ctx, g->first[l * 9 + ij], low));
            assert_true(qd_is_zero(d));
        }
    assert_is(&f, g->det, "m^3*r^4*sin(th)^2");
    assert_non_null(g->jac_det);
    assert_is(&f, g->jac_det, "r^2*sin(th)");
    assert_int_equal(g->nsing, 2);
    assert_is(&f, g->sing[0].lhs, "r");
    assert_is(&f, g->sing[0].rhs, "0");
    assert_null(g->sing[0].period);
    assert_is(&f, g->sing[1].lhs, "th");
    assert_is(&f, g->sing[1].rhs, "0");
    assert_is(&f, g->sing[1].period, "pi");
    assert_true(g->orthogonal);
    assert_true(g->scale_geometric);
    unload(&f);
}

static void test_spherical_components(void **state) {
    (void)state;
    fix f = load("coordinates r, th, ph\nparameters m = 3, Fr = 1, Ft = 2, Fp = 5\n"
                 "particle m at (r*sin(th)*cos(ph), r*sin(th)*sin(ph), r*cos(th))\n");
    const qd_expr *G[3] = {qd_read(f.ctx, "Fr", NULL, NULL), qd_read(f.ctx, "r*Ft", NULL, NULL),
                           qd_read(f.ctx, "r*sin(th)*Fp", NULL, NULL)};
    const qd_expr *up[3], *phys[3], *ord[3];
    assert_int_equal(qd_metric_force(f.ctx, f.g, G, up, phys, ord), QD_OK);
    /* r > 0, 0 < th < pi: |r| = r, |sin th| = sin th */
    const qd_expr *syms[16] = {qd_lookup(f.ctx, "r"), qd_lookup(f.ctx, "th")};
    double vals[16] = {1.7, 0.9};
    size_t ns = with_params(&f, 2, syms, vals);
    static const double want[3] = {1, 2, 5};
    for (int i = 0; i < 3; i++) {
        double p, o;
        assert_int_equal(qd_eval(f.ctx, phys[i], ns, syms, vals, &p), QD_OK);
        assert_int_equal(qd_eval(f.ctx, ord[i], ns, syms, vals, &o), QD_OK);
        assert_true(fabs(p - want[i]) < 1e-14);
        assert_true(fabs(o - want[i]) < 1e-14);
    }
    /* contravariant: G^i = g^ii G_i = G_i / (m h_i^2) */
    assert_is(&f, up[1], "Ft/(m*r)");
    unload(&f);
}

static void test_oblique_components(void **state) {
    (void)state;
    fix f = load("coordinates u, v\nparameters m = 1, al = 1.1, Fx = 0.7, Fy = -0.4\n"
                 "particle m at (u + v*cos(al), v*sin(al))\n");
    assert_false(f.g->orthogonal);
    const qd_expr *G[2] = {qd_read(f.ctx, "Fx", NULL, NULL),
                           qd_read(f.ctx, "Fx*cos(al) + Fy*sin(al)", NULL, NULL)};
    const qd_expr *phys[2], *ord[2];
    assert_int_equal(qd_metric_force(f.ctx, f.g, G, NULL, phys, ord), QD_OK);
    double al = 1.1, Fx = 0.7, Fy = -0.4, x[4], vals[8];
    const qd_expr *syms[8];
    size_t ns = with_params(&f, 0, syms, vals);
    for (int i = 0; i < 2; i++) {
        assert_int_equal(qd_eval(f.ctx, phys[i], ns, syms, vals, &x[i]), QD_OK);
        assert_int_equal(qd_eval(f.ctx, ord[i], ns, syms, vals, &x[2 + i]), QD_OK);
    }
    assert_true(fabs(x[0] - Fx) < 1e-14);
    assert_true(fabs(x[1] - (Fx * cos(al) + Fy * sin(al))) < 1e-14);
    assert_true(fabs(x[2] - (Fx - Fy * cos(al) / sin(al))) < 1e-14);
    assert_true(fabs(x[3] - Fy / sin(al)) < 1e-14);
    /* the chart is linear: det J = sin(al), nowhere singular */
    assert_int_equal(f.g->nsing, 0);
    unload(&f);
}

/* g_lk geodesic_k = M_l. q'' - f_l at random states. */
static void check_against_eom(const char *text) {
    fix f = load(text);
    qd_eom *e = qd_eom_derive(f.ctx, f.m);
    assert_non_null(e);
    size_t n = e->n;
    const qd_expr *syms[64];
    for (size_t i = 0; i < n; i++) {
        syms[i] = e->q[i];
        syms[n + i] = e->qd[i];
        syms[2 * n + i] = e->qdd[i];
    }
    srand(7);
    for (int trial = 0; trial < 5; trial++) {
        double v[64];
        for (size_t i = 0; i < 3 * n; i++)
            v[i] = 2.0 * rand() / RAND_MAX - 1;
        size_t ns = with_params(&f, 3 * n, syms, v);
        syms[ns] = qd_time(f.ctx);
        v[ns++] = 0.37;
        for (size_t l = 0; l < n; l++) {
            double lhs = 0, rhs, fl, Ml;
            for (size_t k = 0; k < n; k++) {
                double gk, geo;
                assert_int_equal(qd_eval(f.ctx, f.g->g[l * n + k], ns, syms, v, &gk), QD_OK);
                assert_int_equal(qd_eval(f.ctx, f.g->geodesic[k], ns, syms, v, &geo), QD_OK);
                lhs += gk * geo;
            }
            assert_int_equal(qd_eval(f.ctx, e->f[l], ns, syms, v, &fl), QD_OK);
            rhs = -fl;
            for (size_t k = 0; k < n; k++) {
                assert_int_equal(qd_eval(f.ctx, e->M[l * n + k], ns, syms, v, &Ml), QD_OK);
                rhs += Ml * v[2 * n + k];
            }
            assert_true(fabs(lhs - rhs) < 1e-12 * (1 + fabs(rhs)));
        }
    }
    qd_eom_free(e);
    unload(&f);
}

static void test_geodesic_is_lagrange(void **state) {
    (void)state;
    check_against_eom("coordinates theta1, theta2\n"
                      "parameters m1 = 1.3, m2 = 0.7, l1 = 1.1, l2 = 0.9, g = 9.81\n"
                      "x1 = l1*sin(theta1)\ny1 = -l1*cos(theta1)\n"
                      "x2 = x1 + l2*sin(theta2)\ny2 = y1 - l2*cos(theta2)\n"
                      "T = m1/2*(x1'^2 + y1'^2) + m2/2*(x2'^2 + y2'^2)\n"
                      "V = m1*g*y1 + m2*g*y2\n");
    /* rheonomic: the tube turns at omega; T0 = m omega^2 r^2 / 2 is a force */
    check_against_eom("coordinates r\nparameters m = 1.5, omega = 2, c = 0.3\n"
                      "particle m at (r*cos(omega*t), r*sin(omega*t), 0)\n"
                      "dissipation = c/2*r'^2\n");
}

static void test_rotating_tube_parts(void **state) {
    (void)state;
    fix f = load("coordinates r\nparameters m = 1.5, omega = 2\n"
                 "particle m at (r*cos(omega*t), r*sin(omega*t), 0)\n");
    assert_is(&f, f.g->g[0], "m");
    assert_is(&f, f.g->T0, "m*omega^2*r^2/2");
    assert_is(&f, f.g->T1, "0");
    assert_is(&f, f.g->Q[0], "m*omega^2*r");
    unload(&f);
}

static void test_polar_chart(void **state) {
    (void)state;
    fix f = load("coordinates r, th\nparameters m = 1\nparticle m at (r*cos(th), r*sin(th))\n");
    assert_int_equal(f.g->npos, 2);
    assert_is(&f, f.g->jac_det, "r");
    assert_int_equal(f.g->nsing, 1);
    assert_is(&f, f.g->sing[0].lhs, "r");
    assert_is(&f, f.g->sing[0].rhs, "0");
    unload(&f);
}

static void test_refusals(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, "coordinates x\nparameters m = 1, c = 1\n"
                                      "L = -m*c^2*sqrt(1 - x'^2/c^2)\n", &d);
    assert_non_null(m);
    assert_null(qd_metric_new(ctx, m));
    assert_int_equal(qd_ctx_status(ctx), QD_ERR_NONLINEAR);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_spherical_christoffel),
        cmocka_unit_test(test_spherical_components),
        cmocka_unit_test(test_oblique_components),
        cmocka_unit_test(test_geodesic_is_lagrange),
        cmocka_unit_test(test_rotating_tube_parts),
        cmocka_unit_test(test_polar_chart),
        cmocka_unit_test(test_refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
