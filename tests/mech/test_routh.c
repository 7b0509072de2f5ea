/*
 * tests/mech/test_routh.c - Routh's reduction (qd_routh_derive) against
 * textbook Routhians, effective potentials and periods, and against the
 * full Lagrange equations.
 *
 * - The curve a^3 y = x^4 on a wire turning about the vertical y axis
 *   (Desloge ch. 54 P6, seed 000; reference seed-desloge-A.md pitfall 7,
 *   T42/T44): about the steady motion at x = a the period is
 *   2 pi sqrt(17a/8g) when the rotation is driven and 2 pi sqrt(17a/24g)
 *   when it is free.  The driven one comes from the model with phi = Omega t,
 *   the free one from the Routhian; putting p_phi into L before
 *   differentiating (the classic error) gives no steady motion at x = a and
 *   a third "frequency", 0.
 * - The heavy symmetric top (Desloge ch. 72 Example 2, eq. 36, seed 000;
 *   Goldstein sec. 5.7): R = -A theta'^2/2 + (p_phi - p_psi cos)^2/(2 A
 *   sin^2) + p_psi^2/(2C) + M g h cos, so V_eff = (p_phi - p_psi cos)^2/(2 A
 *   sin^2) + M g h cos + p_psi^2/(2C).
 * - The particle on the paraboloid z = c rho^2 (Desloge ch. 72 P2;
 *   seed-desloge-C.md T19, there c = 1).
 * - The spherical pendulum: V_eff = -m g a cos + p^2/(2 m a^2 sin^2), a
 *   positive centrifugal barrier (the documented sign).
 * - The Britannica 2+1 system (seed-goldstein-britannica.md B07): the
 *   gyroscopic coefficient (1,2) = d beta1/dq2 - d beta2/dq1 of [B]'s R
 *   (= -ours), and the reduced accelerations equal the full ones at random
 *   states (p_c = dL/dc' there).
 * - Coordinates that are not cyclic, unknown names, constraints: errors.
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
#include "qdot/routh.h"

#define MAXS 64
#define TOL 1e-9
#define PI 3.14159265358979323846

typedef struct fix {
    qd_ctx *ctx;
    qd_model *m;
    qd_eom *e;
    qd_routh *r;
} fix;

static fix load(const char *text) {
    fix f = {qd_ctx_new(), NULL, NULL, NULL};
    qd_diag d;
    f.m = qd_model_parse(f.ctx, text, &d);
    assert_non_null(f.m);
    f.e = qd_eom_derive(f.ctx, f.m);
    if (!f.e)
        fprintf(stderr, "qd_eom_derive: %s\n", qd_ctx_message(f.ctx));
    assert_non_null(f.e);
    return f;
}

/* Reduce by the comma-free list of names (NULL-terminated). */
static qd_routh *reduce(fix *f, const char *const *names) {
    const qd_expr *ign[8];
    size_t n = 0;
    for (; names[n]; n++) {
        ign[n] = qd_routh_lookup(f->ctx, f->m, names[n]);
        assert_non_null(ign[n]);
    }
    f->r = qd_routh_derive(f->ctx, f->m, f->e, n, ign);
    if (!f->r)
        fprintf(stderr, "qd_routh_derive: %s\n", qd_ctx_message(f->ctx));
    return f->r;
}

static void unload(fix *f) {
    qd_routh_free(f->r);
    qd_eom_free(f->e);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
}

/* Values of named symbols; every other free symbol gets a pseudo-random value. */
typedef struct point {
    const qd_expr *syms[MAXS];
    double vals[MAXS];
    size_t n;
} point;

static void set(fix *f, point *p, const char *name, double v) {
    const qd_expr *s = qd_lookup(f->ctx, name);
    assert_non_null(s);
    for (size_t i = 0; i < p->n; i++)
        if (p->syms[i] == s) {
            p->vals[i] = v;
            return;
        }
    assert_true(p->n < MAXS);
    p->syms[p->n] = s;
    p->vals[p->n++] = v;
}

/* The model's parameters at their values. */
static void model_params(fix *f, point *p) {
    for (size_t i = 0; i < qd_model_nparams(f->m); i++)
        set(f, p, qd_expr_name(qd_model_param(f->m, i)),
            qd_number_value(qd_model_param_value(f->m, i)));
}

static void fill(fix *f, point *p, const qd_expr *x) {
    const qd_expr *s[MAXS];
    size_t ns = qd_free_symbols(f->ctx, x, s, MAXS);
    assert_true(ns <= MAXS);
    for (size_t i = 0; i < ns; i++) {
        size_t k = 0;
        while (k < p->n && p->syms[k] != s[i])
            k++;
        if (k == p->n) {
            assert_true(p->n < MAXS);
            p->syms[p->n] = s[i];
            p->vals[p->n++] = 0.3 + 1.2 * rand() / (double)RAND_MAX;
        }
    }
}

static double val(fix *f, point *p, const qd_expr *x) {
    double v = NAN;
    fill(f, p, x);
    assert_int_equal(qd_eval(f->ctx, x, p->n, p->syms, p->vals, &v), QD_OK);
    return v;
}

static void assert_close(double a, double b, double tol) {
    if (fabs(a - b) > tol * (1 + fabs(a) + fabs(b))) {
        fprintf(stderr, "%.15g != %.15g\n", a, b);
        fail();
    }
}

/* ---- a^3 y = x^4: driven vs free rotation --------------------------------- */

static const char wire_free[] =
    "coordinates x, phi\n"
    "parameters m = 1.3, a = 0.7, g = 9.81\n"
    "particle m at (x*cos(phi), x^4/a^3, x*sin(phi))\n"
    "V = m*g*x^4/a^3\n";

/* The same wire made to turn at Omega: no phi, one degree of freedom. */
static const char wire_driven[] =
    "coordinates x\n"
    "parameters m = 1.3, a = 0.7, g = 9.81, Omega = 1\n"
    "particle m at (x*cos(Omega*t), x^4/a^3, x*sin(Omega*t))\n"
    "V = m*g*x^4/a^3\n";

static const double M_ = 1.3, A_ = 0.7, G_ = 9.81;

/* omega^2 = -(df/dx)/M at (x = a, x' = 0) for one equation M x'' = f, and
 * f there (0 at a steady motion). */
static void linearize(fix *f, point *p, const qd_expr *M, const qd_expr *rhs, const qd_expr *x,
                      double *w2, double *f0) {
    set(f, p, "x", A_);
    set(f, p, "x'", 0);
    set(f, p, "t", 0.37);
    double Mv = val(f, p, M);
    *f0 = val(f, p, rhs);
    *w2 = -val(f, p, qd_diff(f->ctx, rhs, x)) / Mv;
    assert_close(Mv, 17 * M_, TOL); /* m (1 + 16 x^6/a^6) at x = a */
}

static void params(fix *f, point *p) {
    set(f, p, "m", M_);
    set(f, p, "a", A_);
    set(f, p, "g", G_);
}

static void test_wire_driven_vs_free(void **state) {
    (void)state;
    double Omega = sqrt(4 * G_ / A_); /* the steady rotation at x = a */

    fix d = load(wire_driven);
    point pd = {.n = 0};
    params(&d, &pd);
    set(&d, &pd, "Omega", Omega);
    double w2_driven, f0;
    linearize(&d, &pd, d.e->M[0], d.e->f[0], d.e->q[0], &w2_driven, &f0);
    assert_close(f0, 0, TOL);
    assert_close(2 * PI / sqrt(w2_driven), 2 * PI * sqrt(17 * A_ / (8 * G_)), TOL);
    unload(&d);

    fix fr = load(wire_free);
    qd_routh *r = reduce(&fr, (const char *const[]){"phi", NULL});
    assert_non_null(r);
    assert_int_equal(r->nkeep, 1);
    point pf = {.n = 0};
    params(&fr, &pf);
    set(&fr, &pf, "p_phi", M_ * A_ * A_ * Omega); /* m x^2 phi' at x = a */
    double w2_free;
    linearize(&fr, &pf, r->M[0], r->f[0], r->keep[0], &w2_free, &f0);
    assert_close(f0, 0, TOL);
    assert_close(2 * PI / sqrt(w2_free), 2 * PI * sqrt(17 * A_ / (24 * G_)), TOL);
    /* The barrier: V_eff = m g x^4/a^3 + p^2/(2 m x^2), V_eff'' = 24 m g/a. */
    assert_close(val(&fr, &pf, qd_diff_n(fr.ctx, r->Veff, r->keep[0], 2)), 24 * M_ * G_ / A_,
                 TOL);

    /* The classic error: p_phi put into L, L used as the Lagrangian. */
    const qd_expr *phid = fr.e->qd[1];
    assert_ptr_equal(fr.e->q[1], r->ign[0]);
    const qd_expr *Ln = qd_subs(fr.ctx, fr.e->L, 1, &phid, r->ignvel);
    const qd_expr *E = qd_sub(fr.ctx, qd_dt(fr.ctx, qd_diff(fr.ctx, Ln, r->keepd[0])),
                              qd_diff(fr.ctx, Ln, r->keep[0]));
    const qd_expr *Mn = NULL, *rest = NULL;
    assert_int_equal(qd_linear_coeffs(fr.ctx, E, 1, r->keepdd, &Mn, &rest), QD_OK);
    double w2_naive, f0_naive;
    linearize(&fr, &pf, Mn, qd_neg(fr.ctx, rest), r->keep[0], &w2_naive, &f0_naive);
    /* No steady motion at x = a at all: -4 m g x^3/a^3 - p^2/(m x^3), both inwards. */
    assert_close(f0_naive, -4 * M_ * G_ - M_ * A_ * Omega * Omega, TOL);
    assert_true(fabs(f0_naive) > 1);
    assert_close(w2_naive, 0, 1e-9); /* 12 g/a - 3 Omega^2 */
    assert_true(fabs(w2_naive - w2_free) > 1 && fabs(w2_naive - w2_driven) > 1);
    unload(&fr);
}

/* ---- the heavy symmetric top ------------------------------------------------ */

static const char top[] =
    "coordinates phi, theta, psi\n"
    "parameters M = 1.2, h = 0.3, A = 0.5, C = 0.8, g = 9.81\n"
    "body top mass M inertia (A - M*h^2, A - M*h^2, C) at h*(sin(theta)*sin(phi), "
    "-sin(theta)*cos(phi), cos(theta)) orientation euler(phi, theta, psi)\n"
    "V = M*g*h*cos(theta)\n";

static void test_top(void **state) {
    (void)state;
    fix f = load(top);
    qd_routh *r = reduce(&f, (const char *const[]){"phi", "psi", NULL});
    assert_non_null(r);
    assert_int_equal(r->nkeep, 1);
    assert_string_equal(qd_expr_name(r->keep[0]), "theta");
    assert_string_equal(qd_expr_name(r->beta[0]), "p_phi");
    assert_string_equal(qd_expr_name(r->beta[1]), "p_psi");
    assert_true(qd_is_zero(r->R1));
    assert_true(qd_is_zero(r->G[0]));
    for (int k = 0; k < 8; k++) {
        point p = {.n = 0};
        model_params(&f, &p);
        double A = 0.5, C = 0.8, Mgh = 1.2 * 9.81 * 0.3;
        double th = 0.2 + 0.35 * k, thd = 0.7 - 0.3 * k, pf = 1.1 - 0.4 * k, ps = 0.3 + 0.2 * k;
        set(&f, &p, "theta", th);
        set(&f, &p, "theta'", thd);
        set(&f, &p, "p_phi", pf);
        set(&f, &p, "p_psi", ps);
        double s = sin(th), c = cos(th), u = pf - ps * c;
        /* Goldstein sec. 5.7 / Desloge (36): the textbook V_eff plus the constant p_psi^2/2C. */
        double veff = u * u / (2 * A * s * s) + Mgh * c;
        assert_close(val(&f, &p, r->Veff), veff + ps * ps / (2 * C), TOL);
        assert_close(val(&f, &p, r->R2), -A * thd * thd / 2, TOL);
        /* Quadratures: phi' = u/(A sin^2), psi' = p_psi/C - phi' cos. */
        double phid = u / (A * s * s);
        assert_close(val(&f, &p, r->ignvel[0]), phid, TOL);
        assert_close(val(&f, &p, r->ignvel[1]), ps / C - phid * c, TOL);
        /* Desloge (40): A theta'' = -dV_eff/dtheta. */
        double dveff = -u * u * c / (A * s * s * s) + u * ps / (A * s) - Mgh * s;
        assert_close(val(&f, &p, r->M[0]), A, TOL);
        assert_close(val(&f, &p, r->f[0]), -dveff, TOL);
    }
    unload(&f);
}

/* ---- the paraboloid --------------------------------------------------------- */

static const char paraboloid[] =
    "coordinates rho, ph\n"
    "parameters m = 0.6, c = 0.75, g = 9.81\n"
    "particle m at (rho*cos(ph), rho*sin(ph), c*rho^2)\n"
    "V = m*g*c*rho^2\n";

static void test_paraboloid(void **state) {
    (void)state;
    fix f = load(paraboloid);
    qd_routh *r = reduce(&f, (const char *const[]){"ph", NULL});
    assert_non_null(r);
    for (int k = 0; k < 6; k++) {
        point p = {.n = 0};
        model_params(&f, &p);
        double m = 0.6, c = 0.75, g = 9.81;
        double rho = 0.3 + 0.3 * k, rd = 0.9 - 0.35 * k, pp = 0.4 + 0.25 * k;
        set(&f, &p, "rho", rho);
        set(&f, &p, "rho'", rd);
        set(&f, &p, "p_ph", pp);
        double k2 = 1 + 4 * c * c * rho * rho;
        /* Desloge ch. 72 P2 (c = 1 there): R = p^2/(2 m rho^2) - m/2 (1 + 4 rho^2) rho'^2
         * + m g rho^2, and m (1 + 4 rho^2) rho'' + 4 m rho rho'^2 - p^2/(m rho^3) + 2 m g rho = 0. */
        double R = pp * pp / (2 * m * rho * rho) - m / 2 * k2 * rd * rd + m * g * c * rho * rho;
        assert_close(val(&f, &p, r->R), R, TOL);
        assert_close(val(&f, &p, r->M[0]), m * k2, TOL);
        double fr = -4 * m * c * c * rho * rd * rd + pp * pp / (m * rho * rho * rho) -
                    2 * m * g * c * rho;
        assert_close(val(&f, &p, r->f[0]), fr, TOL);
        assert_close(val(&f, &p, r->ignvel[0]), pp / (m * rho * rho), TOL);
    }
    unload(&f);
}

/* ---- the spherical pendulum: the sign of V_eff and the Jacobi integral ------- */

static const char spherical[] =
    "coordinates theta, phi\n"
    "parameters m = 1.1, a = 0.9, g = 9.81\n"
    "particle m at a*(sin(theta)*cos(phi), sin(theta)*sin(phi), -cos(theta))\n"
    "V = -m*g*a*cos(theta)\n";

static void test_spherical_barrier(void **state) {
    (void)state;
    fix f = load(spherical);
    qd_routh *r = reduce(&f, (const char *const[]){"phi", NULL});
    assert_non_null(r);
    assert_true(r->conserved);
    double m = 1.1, a = 0.9, g = 9.81;
    for (int k = 0; k < 5; k++) {
        point p = {.n = 0};
        model_params(&f, &p);
        double th = 0.3 + 0.5 * k, thd = 0.4 - 0.2 * k, phid = 1.3 - 0.45 * k;
        double pp = m * a * a * sin(th) * sin(th) * phid;
        set(&f, &p, "theta", th);
        set(&f, &p, "theta'", thd);
        set(&f, &p, "p_phi", pp);
        double V = -m * g * a * cos(th), s2 = sin(th) * sin(th);
        assert_close(val(&f, &p, r->Veff), V + pp * pp / (2 * m * a * a * s2), TOL);
        /* h = R0 - R2 is the energy T + V. */
        double E = m * a * a / 2 * (thd * thd + s2 * phid * phid) + V;
        assert_close(val(&f, &p, r->h), E, TOL);
    }
    unload(&f);
}

/* ---- [B] B07: gyroscopic terms, and the reduced equations vs the full ones ---- */

static const char b07[] =
    "coordinates q1, q2, chi\n"
    "T = ((2 + q1^2)*q1'^2 + 2*sin(q2)*q1'*q2' + (3 + q2^2)*q2'^2)/2"
    " + (q2*q1' + q1*q2*q2')*chi' + (1 + q1^2 + q2^2/2)*chi'^2/2\n"
    "V = q1^2/2 + cos(q2)\n"
    "dissipation = q1'^2/5\n";

static void test_b07_gyroscopic(void **state) {
    (void)state;
    fix f = load(b07);
    qd_routh *r = reduce(&f, (const char *const[]){"chi", NULL});
    assert_non_null(r);
    assert_int_equal(r->nkeep, 2);
    assert_false(r->conserved);
    const qd_expr *syms[7] = {f.e->q[0], f.e->q[1], f.e->q[2], f.e->qd[0], f.e->qd[1],
                              f.e->qd[2], qd_time(f.ctx)};
    for (int k = 0; k < 8; k++) {
        point p = {.n = 0};
        model_params(&f, &p);
        double q1 = -0.8 + 0.3 * k, q2 = 0.9 - 0.25 * k, v1 = 0.5 - 0.2 * k, v2 = -0.3 + 0.15 * k,
               kap = 0.7 - 0.3 * k;
        set(&f, &p, "q1", q1);
        set(&f, &p, "q2", q2);
        set(&f, &p, "q1'", v1);
        set(&f, &p, "q2'", v2);
        set(&f, &p, "p_chi", kap);
        double c = 1 + q1 * q1 + q2 * q2 / 2, den = 2 * q1 * q1 + q2 * q2 + 2;
        double b12 = 2 * kap * (2 * q2 * (2 * q1 * q1 - q2) + (1 - q2) * den) / (den * den);
        assert_close(val(&f, &p, r->G[1]), -b12, TOL);
        assert_close(val(&f, &p, r->G[2]), b12, TOL);
        double chid = (kap - q2 * v1 - q1 * q2 * v2) / c;
        assert_close(val(&f, &p, r->ignvel[0]), chid, TOL);
        /* The odd part of f in the velocities is the gyroscopic force G k' (and
         * the dissipation's -2 q1'/5). */
        point pm = p;
        set(&f, &pm, "q1'", -v1);
        set(&f, &pm, "q2'", -v2);
        double odd0 = (val(&f, &p, r->f[0]) - val(&f, &pm, r->f[0])) / 2;
        double odd1 = (val(&f, &p, r->f[1]) - val(&f, &pm, r->f[1])) / 2;
        assert_close(odd0, -b12 * v2 - 0.4 * v1, TOL);
        assert_close(odd1, b12 * v1, TOL);
        /* Reduced accelerations = full ones with chi' = chid. */
        double Mr[4], fr[2];
        for (int i = 0; i < 4; i++)
            Mr[i] = val(&f, &p, r->M[i]);
        fr[0] = val(&f, &p, r->f[0]);
        fr[1] = val(&f, &p, r->f[1]);
        double det = Mr[0] * Mr[3] - Mr[1] * Mr[2];
        double a1 = (fr[0] * Mr[3] - Mr[1] * fr[1]) / det, a2 = (Mr[0] * fr[1] - Mr[2] * fr[0]) / det;
        double vals[7] = {q1, q2, 0.4, v1, v2, chid, 0}, qdd[3];
        assert_int_equal(qd_eom_eval(f.ctx, f.e, 7, syms, vals, NULL, NULL, qdd, NULL, NULL),
                         QD_OK);
        assert_close(a1, qdd[0], 1e-9);
        assert_close(a2, qdd[1], 1e-9);
    }
    unload(&f);
}

/* ---- errors ------------------------------------------------------------------ */

static void expect_error(fix *f, const char *name, const char *needle) {
    const qd_expr *c = qd_lookup(f->ctx, name);
    assert_non_null(c);
    qd_ctx_clear_error(f->ctx);
    assert_null(qd_routh_derive(f->ctx, f->m, f->e, 1, &c));
    assert_int_equal(qd_ctx_status(f->ctx), QD_ERR_ARG);
    if (!strstr(qd_ctx_message(f->ctx), needle) || !strstr(qd_ctx_message(f->ctx), name)) {
        fprintf(stderr, "message: %s\n", qd_ctx_message(f->ctx));
        fail();
    }
}

static void test_errors(void **state) {
    (void)state;
    fix f = load(top);
    expect_error(&f, "theta", "potential energy");
    qd_ctx_clear_error(f.ctx);
    assert_null(qd_routh_lookup(f.ctx, f.m, "phy"));
    assert_non_null(strstr(qd_ctx_message(f.ctx), "did you mean 'phi'"));
    qd_ctx_clear_error(f.ctx);
    assert_null(qd_routh_lookup(f.ctx, f.m, "g"));
    assert_non_null(strstr(qd_ctx_message(f.ctx), "parameter"));
    const qd_expr *all[3] = {f.e->q[0], f.e->q[1], f.e->q[2]};
    qd_ctx_clear_error(f.ctx);
    assert_null(qd_routh_derive(f.ctx, f.m, f.e, 3, all));
    assert_int_equal(qd_ctx_status(f.ctx), QD_ERR_ARG);
    const qd_expr *twice[2] = {f.e->q[0], f.e->q[0]};
    qd_ctx_clear_error(f.ctx);
    assert_null(qd_routh_derive(f.ctx, f.m, f.e, 2, twice));
    assert_non_null(strstr(qd_ctx_message(f.ctx), "twice"));
    unload(&f);

    fix g = load("coordinates r, th\nparameters m = 1, k = 2\n"
                 "particle m at (r*cos(th), r*sin(th))\nV = k*r^2/2\nQ[th] = -th'\n");
    expect_error(&g, "th", "generalized force");
    unload(&g);
    fix h = load("coordinates r, th\nparameters m = 1, k = 2\n"
                 "particle m at (r*cos(th), r*sin(th))\nV = k*r^2/2 + cos(th)\n");
    expect_error(&h, "th", "potential");
    unload(&h);
    fix d = load("coordinates r, th\nparameters m = 1, k = 2\n"
                 "particle m at (r*cos(th), r*sin(th))\nV = k*r^2/2\ndissipation = th'^2\n");
    expect_error(&d, "th", "dissipation");
    unload(&d);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_wire_driven_vs_free),
        cmocka_unit_test(test_top),
        cmocka_unit_test(test_paraboloid),
        cmocka_unit_test(test_spherical_barrier),
        cmocka_unit_test(test_b07_gyroscopic),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
