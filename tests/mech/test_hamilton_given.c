/*
 * tests/mech/test_hamilton_given.c - models given by their Hamiltonian
 * (`momenta ...`, `H = ...`): Hamilton's equations straight from H, and the
 * inverse Legendre transform back to L (qd_legendre_inverse).
 *
 * Textbook cases: the Kepler problem in polar coordinates, seed-desloge-B.md
 * C3 (H = p_r^2/2m + p_theta^2/(2 m r^2) - k/r, L = m/2 (r'^2 + r^2
 * theta'^2) + k/r), given once by L and once by H: the two must give the same
 * Hamilton's equations, and the inverse transform the original L.  The
 * charged particle in a uniform magnetic field, Desloge ch. 71 Ex. 1 eqs.
 * (12) and (16) (reference seed-desloge-C.md C1): H = |p - qA|^2/2m back to
 * L = m v^2/2 + q v.A.  Desloge ch. 71 P1 (T7), whose H has a cross term.
 * A damped oscillator m x'' = -k x - b x' given by H and a dissipation
 * function.  And the failures: H = p_x is not regular (no Lagrangian), an H
 * quartic in p has no closed-form inverse.
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

#define SEED 7117u
#define NPOINTS 8
#define MAXS 64

typedef struct fix {
    qd_ctx *ctx;
    qd_model *m;
    qd_eom *e;   /* L models only */
    qd_ham *h;
} fix;

static fix load(qd_ctx *ctx, const char *text) {
    fix f = {ctx, NULL, NULL, NULL};
    qd_diag d;
    f.m = qd_model_parse(ctx, text, &d);
    if (!f.m)
        fail_msg("%zu:%zu: %s", d.line, d.col, d.message);
    if (!qd_model_hamiltonian_given(f.m)) {
        f.e = qd_eom_derive(ctx, f.m);
        assert_non_null(f.e);
    }
    f.h = qd_ham_derive(ctx, f.m, f.e);
    if (!f.h)
        fail_msg("qd_ham_derive: %s", qd_ctx_message(ctx));
    return f;
}

static void unload(fix *f) {
    qd_ham_free(f->h);
    qd_eom_free(f->e);
    qd_model_free(f->m);
}

static const qd_expr *read_expr(qd_ctx *ctx, const char *text) {
    qd_read_error err;
    const qd_read_opts opts = {.new_symbols = true};
    const qd_expr *x = qd_read(ctx, text, &opts, &err);
    assert_non_null(x);
    return x;
}

/* a == b, both simplified (the kernel's canonical form decides). */
static void assert_same(qd_ctx *ctx, const qd_expr *a, const qd_expr *b, const char *what) {
    assert_non_null(a);
    assert_non_null(b);
    const qd_expr *d = qd_simplify(ctx, qd_sub(ctx, a, b));
    if (!d || !qd_is_zero(d)) {
        qd_buf s = QD_BUF_INIT;
        qd_print(ctx, a, QD_FMT_TEXT, &s);
        qd_buf_puts(&s, "  vs  ");
        qd_print(ctx, b, QD_FMT_TEXT, &s);
        fail_msg("%s: %s", what, qd_buf_str(&s));
    }
}

#define KEPLER_PARAMS "coordinates r, theta\nparameters m = 1.3, k = 4\n"

static void kepler_H_equals_L_model(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    fix L = load(ctx, KEPLER_PARAMS "particle m at r*(cos(theta), sin(theta))\nV = -k/r\n");
    fix H = load(ctx, KEPLER_PARAMS "momenta p_r, p_theta\n"
                                    "H = p_r^2/(2*m) + p_theta^2/(2*m*r^2) - k/r\n");
    assert_true(H.h->H_given);
    assert_false(L.h->H_given);
    assert_null(L.h->L_from_H);
    assert_int_equal(H.h->n, 2);
    for (size_t j = 0; j < 2; j++) {
        assert_ptr_equal(H.h->q[j], L.h->q[j]);
        assert_ptr_equal(H.h->p[j], L.h->p[j]); /* p_r, p_theta: the same symbols */
        assert_ptr_equal(H.h->qd[j], L.h->qd[j]);
        assert_same(ctx, H.h->dq[j], L.h->dq[j], "dq/dt");
        assert_same(ctx, H.h->dp[j], L.h->dp[j], "dp/dt");
        assert_same(ctx, H.h->pdef[j], L.h->pdef[j], "p(q, q')");
    }
    assert_same(ctx, H.h->H, L.h->H, "H");
    assert_true(H.h->conserved);
    assert_true(qd_is_zero(H.h->dp[1])); /* theta is cyclic (Desloge ch. 71 Thm 4) */
    assert_null(H.h->H_minus_E);          /* no T to compare with */
    /* the inverse Legendre transform gives back the L the L model used */
    assert_same(ctx, H.h->L_from_H, L.e->L, "L from H");
    assert_same(ctx, qd_legendre_inverse(ctx, H.m), L.e->L, "qd_legendre_inverse");
    unload(&L);
    unload(&H);
    qd_ctx_free(ctx);
}

/* Desloge ch. 71 Ex. 1: H = sum (p_i - q A_i)^2/2m + q phi back to eq. (12),
 * L = m v^2/2 - q phi + q v.A; A = B x r/2 of a uniform field B e_z. */
static void charged_particle_inverse(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    fix H = load(ctx, "coordinates x, y, z\nparameters m = 1.3, q = 0.8, B = 2, E = 0.5\n"
                      "momenta p_x, p_y, p_z\n"
                      "H = ((p_x + q*B*y/2)^2 + (p_y - q*B*x/2)^2 + p_z^2)/(2*m) - q*E*x\n");
    assert_same(ctx, H.h->L_from_H,
                read_expr(ctx, "m/2*(x'^2 + y'^2 + z'^2) + q*E*x + q*B/2*(x*y' - y*x')"), "L");
    assert_same(ctx, H.h->pdef[0], read_expr(ctx, "m*x' - q*B*y/2"), "p_x = m x' + q A_x");
    assert_same(ctx, H.h->dq[0], read_expr(ctx, "(p_x + q*B*y/2)/m"), "x' = (p_x - q A_x)/m");
    unload(&H);
    qd_ctx_free(ctx);
}

/* A random state: every free symbol of x in [0.4, 1.6). */
typedef struct point {
    const qd_expr *syms[MAXS];
    double vals[MAXS];
    size_t n;
} point;

static void add_syms(qd_ctx *ctx, point *pt, const qd_expr *x) {
    const qd_expr *s[MAXS];
    size_t ns = qd_free_symbols(ctx, x, s, MAXS);
    for (size_t i = 0; i < ns; i++) {
        size_t k = 0;
        while (k < pt->n && pt->syms[k] != s[i])
            k++;
        if (k == pt->n) {
            assert_true(pt->n < MAXS);
            pt->syms[pt->n] = s[i];
            pt->vals[pt->n++] = 0.4 + 1.2 * rand() / (double)RAND_MAX;
        }
    }
}

static double val(qd_ctx *ctx, const point *pt, const qd_expr *x) {
    double v;
    assert_int_equal(qd_eval(ctx, x, pt->n, pt->syms, pt->vals, &v), QD_OK);
    return v;
}

/* The forward transform of L_from_H gives H back: at random (q, p, t), with
 * q' = dH/dp, dL/dq' = p and p.q' - L = H.  Desloge ch. 71 P1 (T7) has the
 * cross term a*rho^2*phi', so W = d^2H/dp^2 is not diagonal in general;
 * the second H couples two momenta directly. */
static void round_trip(const char *text) {
    qd_ctx *ctx = qd_ctx_new();
    fix f = load(ctx, text);
    const qd_ham *h = f.h;
    assert_non_null(h->L_from_H);
    for (int k = 0; k < NPOINTS; k++) {
        point pt = {.n = 0};
        add_syms(ctx, &pt, h->H);
        for (size_t j = 0; j < h->n; j++) {
            add_syms(ctx, &pt, h->q[j]);
            add_syms(ctx, &pt, h->p[j]);
        }
        double pq = 0;
        for (size_t j = 0; j < h->n; j++) { /* q' = dH/dp at the point */
            double v = val(ctx, &pt, h->dq[j]);
            pt.syms[pt.n] = h->qd[j];
            pt.vals[pt.n++] = v;
            pq += v * val(ctx, &pt, h->p[j]);
        }
        for (size_t j = 0; j < h->n; j++) {
            double p = val(ctx, &pt, h->p[j]);
            double dl = val(ctx, &pt, qd_diff(ctx, h->L_from_H, h->qd[j]));
            if (fabs(p - dl) > 1e-9 * (1 + fabs(p)))
                fail_msg("dL/d%s' = %.17g, p = %.17g", qd_expr_name(h->q[j]), dl, p);
        }
        double H = val(ctx, &pt, h->H), back = pq - val(ctx, &pt, h->L_from_H);
        if (fabs(H - back) > 1e-9 * (1 + fabs(H)))
            fail_msg("p.q' - L = %.17g, H = %.17g", back, H);
    }
    unload(&f);
    qd_ctx_free(ctx);
}

static void round_trips(void **state) {
    (void)state;
    round_trip("coordinates rho, phi, z\nparameters a = 0.7\nmomenta p_rho, p_phi, p_z\n"
               "H = (p_rho^2 + (p_phi - a*rho^2)^2/rho^2 + p_z^2)/2\n");
    round_trip("coordinates q1, q2\nparameters c = 0.3\nmomenta p1, p2\n"
               "H = p1^2/2 + p2^2 + c*cos(q1 - q2)*p1*p2 + t*p2 - cos(q1)\n");
}

/* P1 by H: the inverse gives Desloge's L (T7) exactly. */
static void desloge71_p1_inverse(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    fix f = load(ctx, "coordinates rho, phi, z\nparameters a = 0.7\nmomenta p_rho, p_phi, p_z\n"
                      "H = (p_rho^2 + (p_phi - a*rho^2)^2/rho^2 + p_z^2)/2\n");
    assert_same(ctx, f.h->L_from_H,
                read_expr(ctx, "(rho'^2 + rho^2*phi'^2 + z'^2)/2 + a*rho^2*phi'"), "T7 L");
    assert_same(ctx, f.h->dp[0], read_expr(ctx, "(p_phi^2 - a^2*rho^4)/rho^3"), "T7 p_rho'");
    unload(&f);
    qd_ctx_free(ctx);
}

static void not_regular(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    fix f = load(ctx, "coordinates x\nmomenta p_x\nH = p_x\n");
    /* Hamilton's equations stand: x' = 1, p_x' = 0 */
    assert_true(qd_is_one(f.h->dq[0]));
    assert_true(qd_is_zero(f.h->dp[0]));
    assert_null(f.h->L_from_H);
    assert_null(f.h->pdef[0]);
    assert_non_null(strstr(f.h->L_why, "d^2H/dp^2 is singular"));
    assert_non_null(strstr(f.h->L_why, "p_x"));
    assert_int_equal(qd_ctx_status(ctx), QD_OK);
    assert_null(qd_legendre_inverse(ctx, f.m));
    assert_int_equal(qd_ctx_status(ctx), QD_ERR_SINGULAR);
    assert_non_null(strstr(qd_ctx_message(ctx), "does not determine p_x"));
    unload(&f);
    qd_ctx_free(ctx);
    /* singular in one direction only: p_y appears linearly */
    ctx = qd_ctx_new();
    f = load(ctx, "coordinates x, y\nmomenta p_x, p_y\nH = p_x^2/2 + x*p_y\n");
    assert_null(f.h->L_from_H);
    assert_non_null(strstr(f.h->L_why, "does not determine p_y"));
    unload(&f);
    qd_ctx_free(ctx);
}

static void not_quadratic(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    fix f = load(ctx, "coordinates x\nmomenta p\nH = p^4/4 + x^2/2\n");
    assert_same(ctx, f.h->dq[0], read_expr(ctx, "p^3"), "x' = p^3");
    assert_null(f.h->L_from_H);
    assert_non_null(strstr(f.h->L_why, "not quadratic in the momenta"));
    assert_null(qd_legendre_inverse(ctx, f.m));
    assert_int_equal(qd_ctx_status(ctx), QD_ERR_NONLINEAR);
    unload(&f);
    qd_ctx_free(ctx);
}

/* m x'' = -k x - b x' (Desloge ch. 72 Ex. 1, T17): with D = b x'^2/2 the
 * momentum equation gains -dD/dx' at x' = dH/dp = p/m. */
static void damped_and_forced(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    fix f = load(ctx, "coordinates x\nparameters m = 2, k = 3, b = 0.5, F = 0.25\n"
                      "momenta p\nH = p^2/(2*m) + k*x^2/2\n"
                      "dissipation = b/2*x'^2\nQ[x] = F*cos(t)\n");
    assert_same(ctx, f.h->dp[0], read_expr(ctx, "-k*x - b*p/m + F*cos(t)"), "p'");
    assert_false(f.h->conserved);
    unload(&f);
    qd_ctx_free(ctx);
}

/* `momenta` with T: qd_ham names the momenta as the model does. */
static void renamed_momenta(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    fix f = load(ctx, KEPLER_PARAMS "momenta pr, pth\nparticle m at r*(cos(theta), sin(theta))\n"
                                    "V = -k/r\n");
    assert_false(f.h->H_given);
    assert_string_equal(qd_expr_name(f.h->p[0]), "pr");
    assert_string_equal(qd_expr_name(f.h->p[1]), "pth");
    assert_same(ctx, f.h->H, read_expr(ctx, "pr^2/(2*m) + pth^2/(2*m*r^2) - k/r"), "H");
    unload(&f);
    qd_ctx_free(ctx);
}

static void refused(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, "coordinates x, y\nmomenta p_x, p_y\n"
                                      "H = (p_x^2 + p_y^2)/2\nconstraint x = y\n", &d);
    assert_non_null(m);
    assert_null(qd_ham_derive(ctx, m, NULL));
    assert_int_equal(qd_ctx_status(ctx), QD_ERR_ARG);
    qd_model_free(m);
    qd_ctx_clear_error(ctx);
    m = qd_model_parse(ctx, "coordinates x\nT = x'^2/2\n", &d);
    assert_null(qd_legendre_inverse(ctx, m)); /* not an H model */
    assert_int_equal(qd_ctx_status(ctx), QD_ERR_ARG);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    srand(SEED);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(kepler_H_equals_L_model),
        cmocka_unit_test(charged_particle_inverse),
        cmocka_unit_test(round_trips),
        cmocka_unit_test(desloge71_p1_inverse),
        cmocka_unit_test(not_regular),
        cmocka_unit_test(not_quadratic),
        cmocka_unit_test(damped_and_forced),
        cmocka_unit_test(renamed_momenta),
        cmocka_unit_test(refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
