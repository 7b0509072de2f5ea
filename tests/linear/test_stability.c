/*
 * tests/linear/test_stability.c - steady motions and their stability
 * (qdot/stability.h) against the textbooks' closed forms.
 *
 * Sources: Britannica 1911 "Dynamics" sec. 5-6 (seed 004_89e868a35cdf1de6.txt) and the
 * reference notes seed-goldstein-britannica.md (B08/B09 power-law orbits, B11 sleeping top,
 * B13 rotating bowl with friction, B15 ellipsoidal bowl, pitfalls P4-P6); Desloge ch. 59
 * eqs. 1-7 (seed 000, reference seed-desloge-B.md T13).
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

#include "qdot/stability.h"
#include "util/system.h"

#define QT_PI 3.14159265358979323846

#define CLOSE(a, b, tol)                                                                         \
    do {                                                                                         \
        double a_ = (a), b_ = (b);                                                               \
        if (!(fabs(a_ - b_) <= (tol) * (1 + fabs(b_))))                                          \
            fail_msg("%s = %.15g, expected %.15g", #a, a_, b_);                                  \
    } while (0)

/* One analysis: the system, its steady motion and the verdicts. */
typedef struct run {
    qt_system *sys;
    qd_steady *s;
    qd_steady_point pt;
    double x[4], w[4], p[4];
    bool xfix[4], wfix[4], pfix[4];
    const qd_expr *syms[32];
    double vals[32];
    size_t nvals;
    qd_stability an;
} run;

static void params(run *r) {
    const qd_model *m = r->sys->model;
    r->nvals = qd_model_nparams(m);
    assert_true(r->nvals <= 32);
    for (size_t i = 0; i < r->nvals; i++) {
        r->syms[i] = qd_model_param(m, i);
        assert_int_equal(qd_eval(r->sys->ctx, qd_model_param_value(m, i), 0, NULL, NULL,
                                 &r->vals[i]), QD_OK);
    }
}

/* Derive text, prepare with the named cyclic coordinate. */
static void start(void **state, run *r, const char *text, const char *cyc, bool driven) {
    memset(r, 0, sizeof *r);
    r->sys = qt_system_derive(state, text, false);
    const qd_expr *c = qt_symbol(r->sys, cyc);
    r->s = qd_steady_derive(r->sys->ctx, r->sys->model, r->sys->eom, 1, &c, driven);
    if (!r->s)
        fail_msg("qd_steady_derive: %s", qd_ctx_message(r->sys->ctx));
    r->pt = (qd_steady_point){r->x, r->w, r->p};
    r->w[0] = 1;
    params(r);
}

static void analyze(run *r) {
    double res;
    qd_status st = qd_steady_find(r->sys->ctx, r->s, r->nvals, r->syms, r->vals, r->xfix,
                                  r->wfix, r->pfix, &r->pt, &res);
    if (st != QD_OK)
        fail_msg("qd_steady_find: %s", qd_ctx_message(r->sys->ctx));
    st = qd_stability_analyze(r->sys->ctx, r->s, r->nvals, r->syms, r->vals, &r->pt, &r->an);
    if (st != QD_OK)
        fail_msg("qd_stability_analyze: %s", qd_ctx_message(r->sys->ctx));
}

static void finish(void **state, run *r) {
    qd_stability_free(&r->an);
    qd_steady_free(r->s);
    qt_system_teardown(state);
}

/* ---- power-law orbits: free (n > -3) versus driven (n > 1) ---------------------------- */

static const char *power_law(char *buf, size_t cap, int n) {
    snprintf(buf, cap,
             "coordinates r, theta\n"
             "parameters m = 3/2, k = 2, n = %d\n"
             "particle m at (r*cos(theta), r*sin(theta))\n"
             "V = k*r^(n + 1)/(n + 1)\n", n);
    return buf;
}

/* Britannica sec. 5-6, reference B08: the circle r0 = 1.3 with free angular momentum needs
 * theta'^2 = k r0^(n-1)/m, and V_eff'' = k (n + 3) r0^(n-1): stable iff n > -3. */
static void test_power_law_free(void **state) {
    const int ns[] = {-2, 0, 2, -4, -5};
    for (size_t i = 0; i < sizeof ns / sizeof *ns; i++) {
        char text[256];
        run r;
        int n = ns[i];
        start(state, &r, power_law(text, sizeof text, n), "theta", false);
        r.x[0] = 1.3;
        r.xfix[0] = true;
        analyze(&r);
        double m = 1.5, k = 2, r0 = 1.3, w2 = k * pow(r0, n - 1) / m;
        CLOSE(r.w[0] * r.w[0], w2, 1e-10);
        CLOSE(r.p[0], m * r0 * r0 * r.w[0], 1e-10);
        CLOSE(r.an.hessian[0], k * (n + 3) * pow(r0, n - 1), 1e-9);
        assert_int_equal(r.an.ordinary_stable, n > -3 ? 1 : 0);
        assert_int_equal(r.an.secular_stable, n > -3 ? 1 : 0);
        if (n > -3) {
            assert_int_equal(r.an.nfreq, 1);
            CLOSE(r.an.freq[0] * r.an.freq[0], k * (n + 3) * pow(r0, n - 1) / m, 1e-9);
        }
        finish(state, &r);
    }
}

/* The same orbits with the momentum given: p = m r0^2 w finds r0 back. */
static void test_power_law_momentum(void **state) {
    char text[256];
    run r;
    start(state, &r, power_law(text, sizeof text, 2), "theta", false);
    double m = 1.5, k = 2, r0 = 0.8, w = sqrt(k * r0 / m);
    r.p[0] = m * r0 * r0 * w;
    r.pfix[0] = true;
    r.x[0] = 1;  /* a guess */
    analyze(&r);
    CLOSE(r.x[0], r0, 1e-10);
    CLOSE(r.w[0], w, 1e-10);
    assert_int_equal(r.an.ordinary_stable, 1);
    finish(state, &r);
}

/* Britannica sec. 3 (21)-(23) and sec. 6, reference B09: the bead on a wire driven at
 * Omega, m Omega^2 r0 = k r0^n, (V - T0)'' = k (n - 1) r0^(n-1): stable iff n > 1. */
static void test_power_law_driven(void **state) {
    const int ns[] = {-2, 0, 2, 3};
    for (size_t i = 0; i < sizeof ns / sizeof *ns; i++) {
        char text[256];
        run r;
        int n = ns[i];
        start(state, &r, power_law(text, sizeof text, n), "theta", true);
        double m = 1.5, k = 2, W = 1.7, r0 = pow(m * W * W / k, 1.0 / (n - 1));
        r.w[0] = W;
        r.wfix[0] = true;
        r.x[0] = r0 * 1.1;  /* a guess near the circle */
        analyze(&r);
        CLOSE(r.x[0], r0, 1e-10);
        CLOSE(r.an.hessian[0], k * (n - 1) * pow(r0, n - 1), 1e-9);
        assert_int_equal(r.an.ordinary_stable, n > 1 ? 1 : 0);
        assert_int_equal(r.an.secular_stable, n > 1 ? 1 : 0);
        if (n > 1)
            CLOSE(r.an.freq[0] * r.an.freq[0], k * (n - 1) * pow(r0, n - 1) / m, 1e-9);
        finish(state, &r);
    }
}

/* The borderlines n = -3 (free) and n = 1 (driven): a zero frequency, flagged, not
 * classified (reference pitfall P6: the inverse-cube orbit). */
static void test_power_law_borderline(void **state) {
    char text[256];
    run r;
    start(state, &r, power_law(text, sizeof text, -3), "theta", false);
    r.x[0] = 1.3;
    r.xfix[0] = true;
    analyze(&r);
    assert_int_equal(r.an.ordinary_stable, -1);
    assert_int_equal(r.an.secular_stable, -1);
    assert_non_null(strstr(r.an.verdict, "borderline"));
    finish(state, &r);

    start(state, &r, power_law(text, sizeof text, 1), "theta", true);
    r.x[0] = 1.3;
    r.xfix[0] = true;  /* with n = 1 every radius is steady at Omega^2 = k/m */
    analyze(&r);
    CLOSE(r.w[0] * r.w[0], 2 / 1.5, 1e-10);
    assert_int_equal(r.an.ordinary_stable, -1);
    finish(state, &r);
}

/* ---- conical pendulum --------------------------------------------------------------- */

static const char conical[] =
    "coordinates theta, phi\n"
    "parameters m = 2, l = 0.7, g = 9.81\n"
    "particle m at l*(sin(theta)*cos(phi), sin(theta)*sin(phi), -cos(theta))\n"
    "V = m*g*l*(-cos(theta))\n";

/* Free: phi'^2 = g/(l cos theta0) and Omega_osc^2 = (g/(l cos theta0)) (1 + 3 cos^2 theta0)
 * (Britannica sec. 5 kineto-statics with V + K; Byerly Art. 9a). */
static void test_conical_free(void **state) {
    const double th[] = {QT_PI / 3, 0.3, 1.2};
    for (size_t i = 0; i < 3; i++) {
        run r;
        start(state, &r, conical, "phi", false);
        r.x[0] = th[i];
        r.xfix[0] = true;
        analyze(&r);
        double g = 9.81, l = 0.7, c = cos(th[i]);
        CLOSE(r.w[0] * r.w[0], g / (l * c), 1e-10);
        assert_int_equal(r.an.nfreq, 1);
        CLOSE(r.an.freq[0] * r.an.freq[0], g / (l * c) * (1 + 3 * c * c), 1e-9);
        assert_int_equal(r.an.ordinary_stable, 1);
        assert_int_equal(r.an.secular_stable, 1);
        finish(state, &r);
    }
}

/* Driven at the same rate (a bead on a hoop turned at Omega^2 = g/(l cos theta0)): the
 * same steady angle but (V - T0)''/(m l^2) = g cos theta0/l - Omega^2 cos 2 theta0
 * = g sin^2 theta0/(l cos theta0): a different frequency (reference pitfall P4). */
static void test_conical_driven(void **state) {
    run r;
    start(state, &r, conical, "phi", true);
    double th = QT_PI / 3, g = 9.81, l = 0.7, c = cos(th);
    r.x[0] = th;
    r.xfix[0] = true;
    analyze(&r);
    CLOSE(r.w[0] * r.w[0], g / (l * c), 1e-10);
    CLOSE(r.an.freq[0] * r.an.freq[0], g * sin(th) * sin(th) / (l * c), 1e-9);
    finish(state, &r);
}

/* ---- sleeping top --------------------------------------------------------------------- */

static const char *top(char *buf, size_t cap, double k) {
    snprintf(buf, cap,
             "coordinates a, b, psi\n"
             "parameters M = 1, h = 1/2, g = 2, A = 1, C = 1/2, k = %.17g\n"
             "R = rot_x(a)*rot_y(b)*rot_z(psi)\n"
             "body top mass M inertia (A - M*h^2, A - M*h^2, C) at R*(0, 0, h) orientation R\n"
             "V = M*g*position(top).z\n"
             "dissipation = k/2*(a'^2 + b'^2)\n", k);
    return buf;
}

/* Britannica sec. 6 (1), reference B11: A = 1, M g h = 1, nu = 3 gives
 * (nu +- sqrt(nu^2 - 4 A M g h))/(2 A) = 2.6180340 and 0.3819660; V_eff (tilts a, b with
 * the spin's momentum free) is a maximum, so the stability is gyroscopic: ordinary, not
 * secular. */
static void test_sleeping_top(void **state) {
    const double nus[] = {3, 2.5, 2, 1.5};
    for (size_t i = 0; i < 4; i++) {
        char text[512];
        run r;
        double nu = nus[i], A = 1, Mgh = 1, D = nu * nu - 4 * A * Mgh;
        start(state, &r, top(text, sizeof text, 0), "psi", false);
        r.p[0] = nu;
        r.pfix[0] = true;
        r.x[0] = 0.01;  /* a guess off the upright position */
        r.x[1] = -0.02;
        analyze(&r);
        CLOSE(r.x[0] + 1, 1, 1e-12);
        CLOSE(r.x[1] + 1, 1, 1e-12);
        CLOSE(r.w[0], nu / 0.5, 1e-10);  /* psi' = nu/C at rest */
        assert_int_equal(r.an.secular_stable, 0);
        if (D > 0) {
            assert_int_equal(r.an.ordinary_stable, 1);
            assert_int_equal(r.an.nfreq, 2);
            CLOSE(r.an.freq[0], (nu - sqrt(D)) / (2 * A), 1e-9);
            CLOSE(r.an.freq[1], (nu + sqrt(D)) / (2 * A), 1e-9);
            assert_non_null(strstr(r.an.verdict, "ordinarily stable but secularly unstable"));
        } else if (D == 0) {
            assert_int_equal(r.an.ordinary_stable, -1);  /* double root nu/(2A) */
            assert_non_null(strstr(r.an.verdict, "borderline"));
        } else {
            assert_int_equal(r.an.ordinary_stable, 0);
        }
        if (nu == 3) {
            CLOSE(r.an.freq[0], 0.3819660, 1e-7);
            CLOSE(r.an.freq[1], 2.6180340, 1e-7);
        }
        finish(state, &r);
    }
}

/* Thomson-Tait: damping of the tilts destroys the gyroscopic stability (reference P5). */
static void test_sleeping_top_damped(void **state) {
    char text[512];
    run r;
    start(state, &r, top(text, sizeof text, 0.05), "psi", false);
    r.p[0] = 3;
    r.pfix[0] = true;
    analyze(&r);
    assert_true(r.an.dissipative);
    assert_int_equal(r.an.ordinary_stable, 1);
    assert_int_equal(r.an.damped_stable, 0);
    finish(state, &r);
}

/* ---- the rotating bowl ------------------------------------------------------------------ */

static const char *bowl(char *buf, size_t cap, double k) {
    snprintf(buf, cap,
             "coordinates x, y, phi\n"
             "parameters m = 1, I = 1, a = 1, g = 1, k = %.17g\n"
             "z = a - sqrt(a^2 - x^2 - y^2)\n"
             "particle m at rot_z(phi)*(x, y, z)\n"
             "T = I/2*phi'^2\n"
             "V = m*g*z\n"
             "dissipation = k*m/2*(x'^2 + y'^2 + z'^2)\n", k);
    return buf;
}

static double max_re(const qd_modes_result *m) {
    double x = -INFINITY;
    for (size_t i = 0; i < m->neig; i++)
        x = fmax(x, m->eig_re[i]);
    return x;
}

/* Britannica sec. 6 (2)-(7), reference B13: the lowest point of a smooth bowl turned at
 * omega is ordinarily stable (frequencies |p - omega|, p + omega in the bowl's axes), and
 * secularly stable iff omega < p = sqrt(g/a); with friction k the roots of
 * s^2 + k s + p^2 - i k omega have Re s = -0.024976544 (omega = 0.5, k = 0.1) and
 * +0.049630741 (omega = 2). */
static void test_rotating_bowl(void **state) {
    const double om[] = {0.5, 2};
    for (size_t i = 0; i < 2; i++) {
        for (int fr = 0; fr < 2; fr++) {
            char text[512];
            run r;
            start(state, &r, bowl(text, sizeof text, fr ? 0.1 : 0), "phi", true);
            r.w[0] = om[i];
            r.wfix[0] = true;
            analyze(&r);
            CLOSE(r.x[0] + 1, 1, 1e-12);
            assert_int_equal(r.an.ordinary_stable, 1);
            assert_int_equal(r.an.secular_stable, om[i] < 1 ? 1 : 0);
            assert_int_equal(r.an.nfreq, 2);
            CLOSE(r.an.freq[0], fabs(1 - om[i]), 1e-9);
            CLOSE(r.an.freq[1], 1 + om[i], 1e-9);
            assert_int_equal(r.an.dissipative, fr == 1);
            if (fr) {
                CLOSE(max_re(&r.an.damped), om[i] < 1 ? -0.024976544 : 0.049630741, 1e-7);
                assert_int_equal(r.an.damped_stable, om[i] < 1 ? 1 : 0);
            }
            finish(state, &r);
        }
    }
}

/* The eccentric relative equilibrium cos(theta) = g/(omega^2 a) (Britannica sec. 6): a
 * circle of them in the bowl's axes, so one zero frequency: borderline, flagged. */
static void test_rotating_bowl_eccentric(void **state) {
    char text[512];
    run r;
    start(state, &r, bowl(text, sizeof text, 0), "phi", true);
    r.w[0] = 2;
    r.wfix[0] = true;
    r.x[0] = 0.9;  /* a guess: the steady radius is a sin(acos(1/4)) = 0.9682458 */
    r.xfix[1] = true;
    analyze(&r);
    CLOSE(r.x[0], sqrt(1 - 1.0 / 16), 1e-10);
    assert_int_equal(r.an.ordinary_stable, -1);
    assert_int_equal(r.an.secular_stable, -1);
    finish(state, &r);
}

/* ---- the ellipsoidal bowl, reference B15 (p1 = 1, p2 = 2) ----------------------------- */

static void test_ellipsoidal_bowl(void **state) {
    const double om[] = {0.5, 1.5, 3};
    for (size_t i = 0; i < 3; i++) {
        for (int fr = 0; fr < 2; fr++) {
            char text[512];
            run r;
            snprintf(text, sizeof text,
                     "coordinates x, y, phi\n"
                     "parameters m = 1, I = 1, p1 = 1, p2 = 2, k = %g\n"
                     "particle m at rot_z(phi)*(x, y, 0)\n"
                     "T = I/2*phi'^2\n"
                     "V = m/2*(p1^2*x^2 + p2^2*y^2)\n"
                     "dissipation = k*m/2*(x'^2 + y'^2)\n", fr ? 0.05 : 0.0);
            start(state, &r, text, "phi", true);
            r.w[0] = om[i];
            r.wfix[0] = true;
            analyze(&r);
            if (i == 0) {
                assert_int_equal(r.an.ordinary_stable, 1);
                assert_int_equal(r.an.secular_stable, 1);
                CLOSE(r.an.freq[0], 0.755348, 1e-6);
                CLOSE(r.an.freq[1], 2.22024, 1e-5);
                if (fr)
                    CLOSE(max_re(&r.an.damped), -0.0192641, 1e-6);
            } else if (i == 1) {
                assert_int_equal(r.an.ordinary_stable, 0);
                CLOSE(max_re(&r.an.ordinary), 0.474275, 1e-6);
                if (fr)
                    CLOSE(max_re(&r.an.damped), 0.471847, 1e-6);
            } else {
                assert_int_equal(r.an.ordinary_stable, 1);
                assert_int_equal(r.an.secular_stable, 0);
                CLOSE(r.an.freq[0], 1.37670, 1e-5);
                CLOSE(r.an.freq[1], 4.59398, 1e-5);
                if (fr) {
                    CLOSE(max_re(&r.an.damped), 0.0218379, 1e-6);
                    assert_int_equal(r.an.damped_stable, 0);
                }
            }
            finish(state, &r);
        }
    }
}

/* ---- a bead on a torus: both equators are steady at any rate --------------------------- */

/* examples/torus.qd: m a^2 th'' = -m a (R + a cos th) sin th phi'^2, so th = 0 and th = pi
 * are steady for every phi' = w; free p_phi: V_eff'' = +-m a w^2 (R +- a) (Britannica
 * "Dynamics" sec. 5-6, seed 004: stable where V + K is a minimum). */
static const char torus[] =
    "coordinates th, phi\n"
    "parameters m = 3/2, R = 2, a = 1/2\n"
    "particle m at ((R + a*cos(th))*cos(phi), (R + a*cos(th))*sin(phi), a*sin(th))\n";

/* At th = pi every term of the th residual carries sin(pi) = 1.2e-16: the residual must be
 * judged against the terms' sizes with sin counted as 1, not against themselves (the
 * "relative residual 0.5" that refused the inner equator). */
static void test_torus_inner_equator(void **state) {
    const double m = 1.5, R = 2, a = 0.5, w = 2;
    run r;
    start(state, &r, torus, "phi", false);
    r.x[0] = QT_PI;
    r.w[0] = w;
    r.xfix[0] = r.wfix[0] = true;
    analyze(&r);
    CLOSE(r.p[0], m * (R - a) * (R - a) * w, 1e-12);
    CLOSE(r.an.lin.K[0], -m * a * w * w * (R - a), 1e-12);
    CLOSE(r.an.ordinary.eig_re[0], w * sqrt((R - a) / a), 1e-12);
    assert_int_equal(r.an.ordinary_stable, 0);
    qd_stability_free(&r.an);
    /* th = 1 is not steady at that rate, and must still be refused */
    r.x[0] = 1;
    assert_int_equal(qd_steady_find(r.sys->ctx, r.s, r.nvals, r.syms, r.vals, r.xfix, r.wfix,
                                    r.pfix, &r.pt, NULL), QD_ERR_NUMERIC);
    qd_ctx_clear_error(r.sys->ctx);
    /* th = pi + 1e-6: no more steady than th = 1 */
    r.x[0] = QT_PI + 1e-6;
    assert_int_equal(qd_steady_find(r.sys->ctx, r.s, r.nvals, r.syms, r.vals, r.xfix, r.wfix,
                                    r.pfix, &r.pt, NULL), QD_ERR_NUMERIC);
    finish(state, &r);
}

/* The rate given, th unknown: every sign change of the th residual over (-pi, pi] is found,
 * both equators, the outer stable (w^2 (R + a)/a), the inner not. */
static void test_torus_all(void **state) {
    const double R = 2, a = 0.5, w = 2;
    run r;
    start(state, &r, torus, "phi", false);
    r.x[0] = 0.3;
    r.w[0] = w;
    r.wfix[0] = true;
    qd_steady_set set;
    assert_int_equal(qd_steady_find_all(r.sys->ctx, r.s, r.nvals, r.syms, r.vals, r.xfix,
                                        r.wfix, r.pfix, NULL, &r.pt, &set), QD_OK);
    assert_int_equal(set.count, 2);
    assert_true(set.complete);
    CLOSE(set.pts[0].x[0], 0, 1e-12);          /* nearest the start th = 0.3 first */
    CLOSE(set.pts[1].x[0], QT_PI, 1e-12);
    assert_int_equal(qd_stability_analyze(r.sys->ctx, r.s, r.nvals, r.syms, r.vals, &set.pts[0],
                                          &r.an), QD_OK);
    assert_int_equal(r.an.ordinary_stable, 1);
    CLOSE(r.an.freq[0] * r.an.freq[0], w * w * (R + a) / a, 1e-12);
    qd_steady_set_free(&set);
    finish(state, &r);
}

/* At th = pi with no rate given every phi' is steady (the kept equation vanishes
 * identically there): a family, said as such, not one member picked by round-off. */
static void test_torus_family(void **state) {
    run r;
    start(state, &r, torus, "phi", false);
    r.x[0] = QT_PI;
    r.xfix[0] = true;
    qd_steady_set set;
    assert_int_equal(qd_steady_find_all(r.sys->ctx, r.s, r.nvals, r.syms, r.vals, r.xfix,
                                        r.wfix, r.pfix, NULL, &r.pt, &set), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(r.sys->ctx), "every value of phi'"));
    finish(state, &r);
}

/* A free particle on the circle r = 1 at rest: the only steady rate is phi' = 0 (a double
 * root of m r sin^2(th) phi'^2 = 0), exactly, and the verdict is borderline: the
 * disturbance drifts linearly (a double zero root), it neither oscillates nor grows
 * exponentially.  Levenberg-Marquardt alone stopped at phi' = 1e-14, whose stiffness of
 * 1e-28 made it "stable" (and the torus's inner equator at p_phi = 0 "unstable"). */
static void test_free_particle_borderline(void **state) {
    run r;
    start(state, &r, "coordinates r, th, phi\nparameters m = 5/2\n"
                     "particle m at (r*sin(th)*cos(phi), r*sin(th)*sin(phi), r*cos(th))\n",
          "phi", false);
    r.x[0] = 1;
    r.x[1] = QT_PI / 2;
    r.xfix[0] = r.xfix[1] = true;
    qd_steady_set set;
    assert_int_equal(qd_steady_find_all(r.sys->ctx, r.s, r.nvals, r.syms, r.vals, r.xfix,
                                        r.wfix, r.pfix, NULL, &r.pt, &set), QD_OK);
    assert_int_equal(set.count, 1);
    assert_true(set.pts[0].w[0] == 0);
    assert_int_equal(qd_stability_analyze(r.sys->ctx, r.s, r.nvals, r.syms, r.vals, &set.pts[0],
                                          &r.an), QD_OK);
    assert_int_equal(r.an.ordinary_stable, -1);
    assert_non_null(strstr(r.an.verdict, "borderline"));
    qd_steady_set_free(&set);
    qd_stability_free(&r.an);
    /* the momentum given as 0: the same, through the given-momentum equation */
    r.pfix[0] = true;
    r.p[0] = 0;
    analyze(&r);
    assert_true(r.w[0] == 0);
    assert_int_equal(r.an.ordinary_stable, -1);
    finish(state, &r);
}

/* ---- errors ----------------------------------------------------------------------------- */

static void test_errors(void **state) {
    qt_system *s = qt_system_derive(state, conical, false);
    const qd_expr *th = qt_symbol(s, "theta");
    assert_null(qd_steady_derive(s->ctx, s->model, s->eom, 1, &th, false));
    assert_int_equal(qd_ctx_status(s->ctx), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(s->ctx), "not cyclic"));
    qt_system_teardown(state);

    run r;
    start(state, &r, conical, "phi", false);
    /* nothing given: one unknown too many */
    assert_int_equal(qd_steady_find(r.sys->ctx, r.s, r.nvals, r.syms, r.vals, r.xfix, r.wfix,
                                    r.pfix, &r.pt, NULL), QD_ERR_ARG);
    qd_ctx_clear_error(r.sys->ctx);
    /* theta = 2.5 turning at 1: not a steady motion (all given, nothing to solve) */
    r.x[0] = 2.5;
    r.xfix[0] = r.wfix[0] = true;
    assert_int_equal(qd_steady_find(r.sys->ctx, r.s, r.nvals, r.syms, r.vals, r.xfix, r.wfix,
                                    r.pfix, &r.pt, NULL), QD_ERR_NUMERIC);
    finish(state, &r);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(test_power_law_free, qt_system_teardown),
        cmocka_unit_test_teardown(test_power_law_momentum, qt_system_teardown),
        cmocka_unit_test_teardown(test_power_law_driven, qt_system_teardown),
        cmocka_unit_test_teardown(test_power_law_borderline, qt_system_teardown),
        cmocka_unit_test_teardown(test_conical_free, qt_system_teardown),
        cmocka_unit_test_teardown(test_conical_driven, qt_system_teardown),
        cmocka_unit_test_teardown(test_sleeping_top, qt_system_teardown),
        cmocka_unit_test_teardown(test_sleeping_top_damped, qt_system_teardown),
        cmocka_unit_test_teardown(test_rotating_bowl, qt_system_teardown),
        cmocka_unit_test_teardown(test_rotating_bowl_eccentric, qt_system_teardown),
        cmocka_unit_test_teardown(test_ellipsoidal_bowl, qt_system_teardown),
        cmocka_unit_test_teardown(test_torus_inner_equator, qt_system_teardown),
        cmocka_unit_test_teardown(test_torus_all, qt_system_teardown),
        cmocka_unit_test_teardown(test_torus_family, qt_system_teardown),
        cmocka_unit_test_teardown(test_free_particle_borderline, qt_system_teardown),
        cmocka_unit_test_teardown(test_errors, qt_system_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
