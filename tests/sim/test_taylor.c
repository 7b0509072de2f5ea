/*
 * tests/sim/test_taylor.c - the Taylor integrator (issue 22): the Taylor
 * mode of compiled programs against known series, the method's order
 * measured by halving the step, its energy error over long runs against
 * dop853's, events at the pendulum's exact quarter periods (complete
 * elliptic integral), and extended precision against a __float128
 * reference.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "sim_fixture.h"
#include "qdot/read.h"
#include "sym/sym_export.h"
#ifdef QD_HAVE_QUADMATH
#include <quadmath.h>
#endif

#define ORDER 24

/* ---- Taylor mode of a program --------------------------------------------- */

/* The coefficients 0..ORDER of text(x) at x = x0 + (t - t0): x the one
 * input, varying. */
static void series(const char *text, double x0, double *c) {
    qd_ctx *ctx = qd_ctx_new();
    qd_read_opts ro = {.new_symbols = true};
    const qd_expr *e = qd_read(ctx, text, &ro, NULL), *x = qd_symbol(ctx, "x");
    assert_non_null(e);
    qd_prog *p = qd_prog_new(ctx, 1, &x, 1, &e);
    assert_non_null(p);
    const qd_prog *ps[1] = {p};
    qd__tay *tp = qd__tay_new(ctx, 1, ps, NULL, ORDER, QD__TAY_DOUBLE);
    assert_non_null(tp);
    double *in = qd__tay_in(tp, 0);
    in[0] = x0;
    in[1] = 1;
    for (size_t k = 0; k <= ORDER; k++)
        qd__tay_run(tp, k);
    memcpy(c, qd__tay_out(tp, 0), (ORDER + 1) * sizeof *c);
    qd__tay_free(tp);
    qd_prog_free(p);
    qd_ctx_free(ctx);
}

/* c against want to 1e-14 of max(1, |want_k|, r^-k), every order: r is
 * the radius of convergence of the series computed on the way (acos(cos x)
 * at 0.6 goes through acos, singular at x = 0), whose round-off grows
 * like r^-k. */
static void expect_r(const char *text, double x0, const double *want, double r) {
    double c[ORDER + 1];
    series(text, x0, c);
    for (size_t k = 0; k <= ORDER; k++)
        if (!(fabs(c[k] - want[k]) <= 1e-14 * fmax(fmax(1, fabs(want[k])), pow(r, -(double)k))))
            fail_msg("%s at %g: coefficient %zu is %.17g, not %.17g", text, x0, k, c[k],
                     want[k]);
}

static void expect(const char *text, double x0, const double *want) {
    expect_r(text, x0, want, 1);
}

static void test_series_elementary(void **state) {
    (void)state;
    double w[ORDER + 1], f = 1;
    /* exp(x) at 0.3: e^0.3 / k! */
    for (size_t k = 0; k <= ORDER; k++, f *= (double)k)
        w[k] = exp(0.3) / f;
    expect("exp(x)", 0.3, w);
    /* sin and cos at 0.7: the derivatives cycle sin, cos, -sin, -cos */
    f = 1;
    for (size_t k = 0; k <= ORDER; k++, f *= (double)k) {
        double d[4] = {sin(0.7), cos(0.7), -sin(0.7), -cos(0.7)};
        w[k] = d[k % 4] / f;
    }
    expect("sin(x)", 0.7, w);
    f = 1;
    for (size_t k = 0; k <= ORDER; k++, f *= (double)k) {
        double d[4] = {cos(0.7), -sin(0.7), -cos(0.7), sin(0.7)};
        w[k] = d[k % 4] / f;
    }
    expect("cos(x)", 0.7, w);
    /* 1/(1 - x) at 0.2: 1/(1 - x0)^(k+1) (a geometric series) */
    for (size_t k = 0; k <= ORDER; k++)
        w[k] = pow(1 / 0.8, (double)k + 1);
    expect("1/(1 - x)", 0.2, w);
    /* sqrt(1 + x) and (1 + x)^(1/3) at 0: the binomial series C(a, k) */
    double a[2] = {0.5, 1.0 / 3};
    const char *txt[2] = {"sqrt(1 + x)", "(1 + x)^(1/3)"};
    for (int i = 0; i < 2; i++) {
        w[0] = 1;
        for (size_t k = 1; k <= ORDER; k++)
            w[k] = w[k - 1] * (a[i] - (double)(k - 1)) / (double)k;
        expect(txt[i], 0, w);
    }
    /* 2^x at 0.4 (a power with a varying exponent): 2^x0 ln(2)^k / k! */
    f = 1;
    for (size_t k = 0; k <= ORDER; k++, f *= (double)k)
        w[k] = pow(2, 0.4) * pow(log(2), (double)k) / f;
    expect("2^x", 0.4, w);
}

/* Inverse pairs give x back: every coefficient past 1 is 0. */
static void test_series_inverses(void **state) {
    (void)state;
    const char *txt[] = {"atan2(sin(x), cos(x))", "asin(sin(x))", "acos(cos(x))",
                         "atan(tan(x))", "log(exp(x))", "cosh(x)^2 - sinh(x)^2 + x - 1",
                         "tanh(x) - sinh(x)/cosh(x) + x", "abs(x - 5) + 2*x - 5"};
    /* the radius of the series on the way: asin and atan are singular at
     * pi/2, acos(cos x) at 0 */
    double r[] = {1, SF_PI / 2 - 0.6, 0.6, SF_PI / 2 - 0.6, 1, 1, 1, 1};
    for (size_t i = 0; i < sizeof txt / sizeof *txt; i++) {
        double w[ORDER + 1] = {0.6, 1};
        expect_r(txt[i], 0.6, w, r[i]);
    }
}

/* ---- the method ------------------------------------------------------------- */

static const char osc[] = "coordinates x\nparameters m = 1, k = 1\n"
                          "T = m/2*x'^2\nV = k/2*x^2\ninitial x = 1, x' = 0\n";

/* dt > 0: fixed steps dt; dt < 0: adaptive with the output grid -dt. */
static qd_status run(sim_fix *f, double t_end, double dt, double tol, int precision) {
    qd_sim_opts o = {.method = QD_SIM_TAYLOR, .t_end = t_end, .dt = fabs(dt), .fixed = dt > 0,
                     .rtol = tol, .atol = tol, .q0 = f->q0, .qd0 = f->qd0,
                     .precision = precision};
    f->nev = 0;
    f->ncols = qd_sim_columns(f->s, QD_SIM_TAYLOR, NULL, 0);
    qd_status st = qd_sim_run(f->s, &o, sf_sink, f, &f->stats, f->last);
    if (st != QD_OK)
        fprintf(stderr, "taylor: %s\n", qd_ctx_message(f->ctx));
    return st;
}

/* log2 of the error ratio when the step halves: the order p of Jorba and
 * Zou's rule at tol, p = ceil(-ln(tol)/2 + 1) (taylor.c), the local error
 * O(h^(p+1)) summed over 1/h steps. */
static double measured_order(sim_fix *f, double t_end, double h, double tol,
                             const double *exact) {
    double err[2];
    for (int i = 0; i < 2; i++) {
        assert_int_equal(run(f, t_end, h / (1 << i), tol, 0), QD_OK);
        err[i] = 0;
        for (size_t j = 0; j < 4 && exact[j] == exact[j]; j++)
            err[i] = fmax(err[i], fabs(f->last[1 + j] - exact[j]));
    }
    return log2(err[0] / err[1]);
}

static void test_order_oscillator(void **state) {
    (void)state;
    sim_fix *f = sf_load(osc);
    assert_non_null(f);
    /* tol 1e-6: p = ceil(6.91 + 1) = 8; x = cos t */
    double exact[4] = {cos(10), -sin(10), NAN, NAN};
    double p = measured_order(f, 10, 0.5, 1e-6, exact);
    if (fabs(p - 8) > 0.3)
        fail_msg("oscillator: measured order %.3f, not 8", p);
    /* tol 1e-3: p = ceil(3.45 + 1) = 5 */
    p = measured_order(f, 10, 0.25, 1e-3, exact);
    if (fabs(p - 5) > 0.3)
        fail_msg("oscillator: measured order %.3f, not 5", p);
    sf_free(f);
}

/* Kepler, e = 0.5, one period from perihelion: the state comes back
 * (Goldstein, Poole & Safko, sec. 3.7: T = 2 pi a^(3/2) / sqrt(k/m)). */
static void test_order_kepler(void **state) {
    (void)state;
    sim_fix *f = sf_load("coordinates x, y\nparameters m = 1, k = 1\nparticle m at (x, y)\n"
                         "V = -k/sqrt(x^2 + y^2)\ninitial x = 0.5, y = 0, x' = 0, "
                         "y' = 1.7320508075688772\n");
    assert_non_null(f);
    /* a(1 - e) = 0.5, v = sqrt((1 + e)/(a (1 - e))) = sqrt(3): a = 1, T = 2 pi */
    double exact[4] = {0.5, 0, 0, 1.7320508075688772};
    double p = measured_order(f, 2 * SF_PI, 2 * SF_PI / 64, 1e-6, exact);
    if (fabs(p - 8) > 0.5)
        fail_msg("kepler: measured order %.3f, not 8", p);
    sf_free(f);
}

/* The pendulum theta'' = -(g/l) sin(theta) from rest at theta0 = 2: its
 * zero crossings at (2j + 1) T/4, T = 4 sqrt(l/g) K(sin(theta0/2))
 * (Goldstein, Poole & Safko, sec. 3.6, exercise; Abramowitz & Stegun 17.6). */
static const char pend[] = "coordinates th\nparameters m = 1, l = 1, g = 9.81\n"
                           "T = m/2*l^2*th'^2\nV = -m*g*l*cos(th)\ninitial th = 2, th' = 0\n";

static void test_events_quarter_periods(void **state) {
    (void)state;
    sim_fix *f = sf_load(pend);
    assert_non_null(f);
    qd_read_opts ro = {.new_symbols = false};
    const qd_expr *g = qd_read(f->ctx, "th", &ro, NULL);
    assert_non_null(g);
    assert_int_equal(qd_sim_add_event(f->s, g, 0, NULL, false), QD_OK);
    double T = 4 * sqrt(1 / 9.81) * sf_ellipk(sin(1.0));
    assert_int_equal(run(f, 20 * T, 0, 1e-15, 0), QD_OK);
    assert_int_equal(f->nev, 40);
    for (size_t j = 0; j < f->nev; j++) {
        double want = (2.0 * (double)j + 1) * T / 4;
        if (!(fabs(f->ev_t[j] - want) <= 3e-14 * want))
            fail_msg("crossing %zu at %.17g, not %.17g (%.2g)", j, f->ev_t[j], want,
                     f->ev_t[j] - want);
    }
    sf_free(f);
}

/* The pendulum over 1e4 periods: the energy error stays at round-off, far
 * below dop853's at 1e-12 over a tenth of the time (2e5 steps: a random walk
 * of rounding errors 1e-16 gives 5e-14), and grows no faster
 * than a random walk (sqrt(10) from 1e3 to 1e4 periods), not linearly. */
static void test_energy_long(void **state) {
    (void)state;
    sim_fix *f = sf_load(pend);
    assert_non_null(f);
    double T = 4 * sqrt(1 / 9.81) * sf_ellipk(sin(1.0)), e[2];
    for (int i = 0; i < 2; i++) {
        assert_int_equal(run(f, (i ? 1e4 : 1e3) * T, -1e3 * T, 1e-15, 0), QD_OK);
        e[i] = f->stats.energy_error_max;
    }
    qd_sim_opts o = {.method = QD_SIM_DOP853, .t_end = 1e3 * T, .dt = 1e3 * T,
                     .rtol = 1e-12, .atol = 1e-12, .q0 = f->q0, .qd0 = f->qd0};
    qd_sim_stats ds;
    assert_int_equal(qd_sim_run(f->s, &o, NULL, NULL, &ds, NULL), QD_OK);
    if (!(e[1] < 5e-14 && e[1] < 1e-2 * ds.energy_error_max && e[1] < 6 * fmax(e[0], 1e-16)))
        fail_msg("energy error: taylor %.3g (1e3 periods), %.3g (1e4), dop853 %.3g", e[0],
                 e[1], ds.energy_error_max);
    sf_free(f);
}

/* --precision: 1000 s of the oscillator x = cos t against cos computed
 * in __float128; double's 1e-13 of accumulated round-off is gone in long
 * double and __float128 (the result is then x rounded to double). */
static void test_precision(void **state) {
    (void)state;
#ifdef QD_HAVE_QUADMATH
    sim_fix *f = sf_load(osc);
    assert_non_null(f);
    double want = (double)cosq(1000), err[3];
    int prec[3] = {64, 80, 128};
    for (int i = 0; i < 3; i++) {
        assert_int_equal(run(f, 1000, 0, prec[i] == 128 ? 1e-30 : prec[i] == 80 ? 1e-19 : 1e-16,
                             prec[i]), QD_OK);
        err[i] = fabs(f->last[1] - want);
    }
    if (!(err[2] <= 1.2e-16 && err[1] <= 1e-15 && err[0] > 4 * err[2]))
        fail_msg("x(1000): errors %.3g (64), %.3g (80), %.3g (128)", err[0], err[1], err[2]);
    sf_free(f);
#endif
}

/* A model with inputs has no series for them: refused, naming the reason. */
static void test_refuses_inputs(void **state) {
    (void)state;
    sim_fix *f = sf_load("coordinates x\nparameters m = 1\ninputs F\nT = m/2*x'^2\n"
                         "Q[x] = F\ninitial x = 0, x' = 0\n");
    assert_non_null(f);
    qd_read_opts ro = {.new_symbols = true};
    assert_int_equal(qd_sim_input_expr(f->s, "F", qd_read(f->ctx, "-x", &ro, NULL)), QD_OK);
    assert_int_equal(run(f, 1, 0, 1e-10, 0), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(f->ctx), "taylor cannot integrate a model with inputs"));
    sf_free(f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_series_elementary),
        cmocka_unit_test(test_series_inverses),
        cmocka_unit_test(test_order_oscillator),
        cmocka_unit_test(test_order_kepler),
        cmocka_unit_test(test_events_quarter_periods),
        cmocka_unit_test(test_energy_long),
        cmocka_unit_test(test_precision),
        cmocka_unit_test(test_refuses_inputs),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
