/*
 * tests/mech/test_legendre_nonquad.c - the Legendre transform of
 * Lagrangians that are not quadratic in the velocities (qd_ham_derive,
 * qd_ham_velocities_at, qd_legendre_inverse).
 *
 * Textbook cases: the relativistic particle, Desloge ch. 93 Thm 1 and
 * seed-desloge-D.md C5, T22, T23: L = -m c^2 sqrt(1 - v^2/c^2) - U gives
 * H = sqrt(m^2 c^4 + c^2 (p - e A)^2) + e phi (rest energy included, P5, P6),
 * in 1-D, in 3-D Cartesian coordinates with fields, and in polar
 * coordinates (T19's relativistic Kepler Hamiltonian).  Each H is compared
 * by value with the hand-written one at random points; the round trip
 * q'(q, p(q, q')) = q' and dp/dt = dL/dq (Lagrange's equations in p) are
 * checked at random slow states (|v| < c).  Appendix 20 (Euler's theorem)
 * and P13: an L of degree 1 in the velocities, or linear in one, has no
 * Hamiltonian.  L = x'^2/2 + x'^4/12 has no closed-form inverse: Newton's
 * method must give q' back to round-off.
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
#include "../util/fault.h"

#define SEED 1793u
#define NPOINTS 12
#define MAXS 64

typedef struct fix {
    qd_ctx *ctx;
    qd_model *m;
    qd_eom *e;
    qd_ham *h;
} fix;

static fix load(const char *text) {
    fix f = {qd_ctx_new(), NULL, NULL, NULL};
    qd_diag d;
    f.m = qd_model_parse(f.ctx, text, &d);
    assert_non_null(f.m);
    if (!qd_model_hamiltonian_given(f.m)) {
        f.e = qd_eom_derive(f.ctx, f.m);
        assert_non_null(f.e);
    }
    f.h = qd_ham_derive(f.ctx, f.m, f.e);
    if (!f.h)
        fprintf(stderr, "qd_ham_derive: %s\n", qd_ctx_message(f.ctx));
    return f;
}

static void unload(fix *f) {
    qd_ham_free(f->h);
    qd_eom_free(f->e);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
}

typedef struct point {
    const qd_expr *syms[MAXS];
    double vals[MAXS];
    size_t n;
} point;

static double uniform(double lo, double hi) { return lo + (hi - lo) * rand() / (double)RAND_MAX; }

static void set(point *pt, const qd_expr *s, double v) {
    for (size_t k = 0; k < pt->n; k++)
        if (pt->syms[k] == s) {
            pt->vals[k] = v;
            return;
        }
    assert_true(pt->n < MAXS);
    pt->syms[pt->n] = s;
    pt->vals[pt->n++] = v;
}

/* Every free symbol of x not yet given a value, in [lo, hi]. */
static void add_syms(qd_ctx *ctx, point *pt, const qd_expr *x, double lo, double hi) {
    const qd_expr *s[MAXS];
    size_t ns = qd_free_symbols(ctx, x, s, MAXS);
    assert_true(ns <= MAXS);
    for (size_t i = 0; i < ns; i++) {
        size_t k = 0;
        while (k < pt->n && pt->syms[k] != s[i])
            k++;
        if (k == pt->n)
            set(pt, s[i], uniform(lo, hi));
    }
}

static double val(qd_ctx *ctx, const point *pt, const qd_expr *x) {
    double v;
    assert_int_equal(qd_eval(ctx, x, pt->n, pt->syms, pt->vals, &v), QD_OK);
    return v;
}

static void assert_close(double a, double b, double rel, const char *what) {
    if (!(fabs(a - b) <= rel * (1 + fabs(a) + fabs(b))))
        fail_msg("%s: %.17g != %.17g (seed %u)", what, a, b, SEED);
}

static const qd_expr *read_expr(qd_ctx *ctx, const char *text) {
    qd_read_error err;
    const qd_read_opts opts = {.new_symbols = true};
    const qd_expr *x = qd_read(ctx, text, &opts, &err);
    assert_non_null(x);
    return x;
}

/* H equals `expected` (in q, p and the parameters) at random points: the
 * parameters in [1, 2] and the coordinates and momenta in [-1.5, 1.5]. */
static void assert_H(fix *f, const char *expected) {
    const qd_expr *x = read_expr(f->ctx, expected);
    for (int k = 0; k < NPOINTS; k++) {
        point pt = {.n = 0};
        for (size_t j = 0; j < f->h->n; j++) {
            set(&pt, f->h->q[j], uniform(0.5, 1.5));
            set(&pt, f->h->p[j], uniform(-1.5, 1.5));
        }
        add_syms(f->ctx, &pt, f->h->H, 1, 2);
        add_syms(f->ctx, &pt, x, 1, 2);
        assert_close(val(f->ctx, &pt, f->h->H), val(f->ctx, &pt, x), 1e-11, expected);
    }
}

/* A random slow state: parameters in [1, 2] (so c >= 1), coordinates in
 * [0.5, 1.5], velocities in [-0.25, 0.25] (|v| < c in three dimensions
 * with any metric factor up to 1.5^2), and p = dL/dq' there. */
static point slow_state(fix *f) {
    point pt = {.n = 0};
    const qd_ham *h = f->h;
    for (size_t j = 0; j < h->n; j++) {
        set(&pt, h->q[j], uniform(0.5, 1.5));
        set(&pt, h->qd[j], uniform(-0.25, 0.25));
    }
    for (size_t j = 0; j < h->n; j++)
        add_syms(f->ctx, &pt, h->pdef[j], 1, 2);
    add_syms(f->ctx, &pt, f->e->L, 1, 2);
    double p[MAXS];
    for (size_t j = 0; j < h->n; j++)
        p[j] = val(f->ctx, &pt, h->pdef[j]);
    for (size_t j = 0; j < h->n; j++)
        set(&pt, h->p[j], p[j]);
    return pt;
}

/* At random slow states: q'(q, p(q, q')) = q' (closed form or Newton),
 * dH/dp = q', and dp/dt = -dH/dq = dL/dq (Lagrange's equation for p). */
static void check_round_trip(fix *f) {
    const qd_ham *h = f->h;
    for (int k = 0; k < NPOINTS; k++) {
        point pt = slow_state(f);
        double want[MAXS], got[MAXS];
        for (size_t j = 0; j < h->n; j++)
            want[j] = val(f->ctx, &pt, h->qd[j]);
        if (h->implicit) {
            point cold = pt; /* Newton from q' = 0, not from the answer */
            for (size_t j = 0; j < h->n; j++)
                set(&cold, h->qd[j], 0);
            assert_int_equal(qd_ham_velocities_at(f->ctx, h, cold.n, cold.syms, cold.vals, got),
                             QD_OK);
        } else {
            for (size_t j = 0; j < h->n; j++)
                got[j] = val(f->ctx, &pt, h->vel[j]);
        }
        for (size_t j = 0; j < h->n; j++) {
            assert_close(got[j], want[j], 1e-12, "q'(q, p(q, q')) = q'");
            assert_close(val(f->ctx, &pt, h->dq[j]), want[j], 1e-12, "dH/dp = q'");
            const qd_expr *dLdq = qd_diff(f->ctx, f->e->L, h->q[j]);
            assert_close(val(f->ctx, &pt, h->dp[j]), val(f->ctx, &pt, dLdq), 1e-11,
                         "-dH/dq = dL/dq");
        }
    }
}

/* seed-desloge-D.md T25: the relativistic oscillator. */
static void test_relativistic_1d(void **state) {
    (void)state;
    fix f = load("coordinates x\nparameters m = 1, c = 1, k = 1\n"
                 "L = -m*c^2*sqrt(1 - x'^2/c^2) - k*x^2/2\n");
    assert_non_null(f.h);
    assert_false(f.h->implicit);
    /* H in closed form: what needs one may use it */
    assert_int_equal(qd_ham_require_closed(f.ctx, f.h, "the action variables"), QD_OK);
    assert_H(&f, "sqrt(m^2*c^4 + c^2*p_x^2) + k*x^2/2");
    assert_true(f.h->conserved);
    check_round_trip(&f);
    unload(&f);
}

/* Desloge ch. 93, with the EM potentials of ch. 92 (seed-desloge-D.md T22,
 * P6): H is written in the canonical momentum p = m gamma v + e A. */
static void test_relativistic_fields(void **state) {
    (void)state;
    fix f = load("coordinates x, y, z\n"
                 "parameters m = 1.3, e = 0.8, c = 3, Ex = 0.5, Ey = -1.2, Ez = 0.3, "
                 "Bx = 0.4, By = 0.7, Bz = 2\n"
                 "r = (x, y, z)\nphi = -dot((Ex, Ey, Ez), r)\nA = cross((Bx, By, Bz), r)/2\n"
                 "L = -m*c^2*sqrt(1 - dot(r', r')/c^2) - e*phi + e*dot(A, r')\n");
    assert_non_null(f.h);
    assert_false(f.h->implicit);
    assert_H(&f, "sqrt(m^2*c^4 + c^2*((p_x - e*(By*z - Bz*y)/2)^2 + (p_y - e*(Bz*x - Bx*z)/2)^2"
                 " + (p_z - e*(Bx*y - By*x)/2)^2)) - e*(Ex*x + Ey*y + Ez*z)");
    assert_true(f.h->conserved);
    check_round_trip(&f);
    unload(&f);
}

/* seed-desloge-D.md T19, T23: polar coordinates, G = diag(m, m r^2)/2. */
static void test_relativistic_polar(void **state) {
    (void)state;
    fix f = load("coordinates r, theta\nparameters m = 1, c = 1, k = 0.1\n"
                 "L = -m*c^2*sqrt(1 - (r'^2 + r^2*theta'^2)/c^2) + k/r\n");
    assert_non_null(f.h);
    assert_false(f.h->implicit);
    assert_H(&f, "sqrt(p_r^2*c^2 + p_theta^2*c^2/r^2 + m^2*c^4) - k/r");
    assert_true(qd_is_zero(f.h->dp[1])); /* theta is cyclic */
    check_round_trip(&f);
    unload(&f);
}

/* The low-speed limit (P5): H - m c^2 -> p^2/(2m) + V as c grows. */
static void test_newtonian_limit(void **state) {
    (void)state;
    fix f = load("coordinates x\nparameters m = 1.7, c = 1, k = 2\n"
                 "L = -m*c^2*sqrt(1 - x'^2/c^2) - k*x^2/2\n");
    assert_non_null(f.h);
    const qd_expr *syms[5] = {f.h->q[0], f.h->p[0], qd_lookup(f.ctx, "m"), qd_lookup(f.ctx, "c"),
                              qd_lookup(f.ctx, "k")};
    double v[5] = {0.4, 0.9, 1.7, 1e4, 2}, H;
    assert_int_equal(qd_eval(f.ctx, f.h->H, 5, syms, v, &H), QD_OK);
    assert_close(H - 1.7e8, 0.9 * 0.9 / 3.4 + 0.16, 1e-7, "H - m c^2");
    unload(&f);
}

/* No closed form: x' + x'^3/3 = p is a cubic; Newton gives x' back. */
static void test_implicit_quartic(void **state) {
    (void)state;
    fix f = load("coordinates x, y\nparameters k = 1.3\n"
                 "L = x'^2/2 + x'^4/12 + y'^2/2 + x'*y'/3 - k*(x^2 + y^2)/2 + x*y'\n");
    assert_non_null(f.h);
    assert_true(f.h->implicit);
    check_round_trip(&f);
    /* a cubic in x' has no closed-form inverse here: what needs H as a
     * formula is told so, and by name */
    assert_int_equal(qd_ham_require_closed(f.ctx, f.h, "the Hamilton-Jacobi equation"),
                     QD_ERR_NONLINEAR);
    assert_non_null(strstr(qd_ctx_message(f.ctx), "the Hamilton-Jacobi equation needs H"));
    qd_ctx_clear_error(f.ctx);
    unload(&f);
    /* the Hessian 3 y'^2 vanishes at Newton's first guess y' = 0 */
    f = load("coordinates x, y\nL = x'^2/2 + y'^4/4 - x^2\n");
    assert_non_null(f.h);
    assert_true(f.h->implicit);
    check_round_trip(&f);
    unload(&f);
}

/* Routh with phi ignored (seed-desloge-D.md T19): R = sqrt(1 - r'^2/c^2)
 * sqrt(m^2 c^4 + c^2 p_phi^2/r^2) - k/r; at a state (r, r', phi') with
 * p_phi = dL/dphi', the quadrature gives phi' back, the Jacobi integral of
 * -R is the energy m gamma c^2 - k/r, and the reduced equation's r'' is the
 * full equations' r''. */
static void test_routh_central(void **state) {
    (void)state;
    fix f = load("coordinates r, phi\nparameters m = 1, c = 1, k = 0.1\n"
                 "L = -m*c^2*sqrt(1 - (r'^2 + r^2*phi'^2)/c^2) + k/r\n");
    const qd_expr *phi = qd_lookup(f.ctx, "phi");
    qd_routh *R = qd_routh_derive(f.ctx, f.m, f.e, 1, &phi);
    if (!R)
        fail_msg("qd_routh_derive: %s", qd_ctx_message(f.ctx));
    const qd_expr *want = read_expr(f.ctx, "sqrt(1 - r'^2/c^2)*sqrt(m^2*c^4 + c^2*p_phi^2/r^2) - k/r");
    const qd_expr *E = read_expr(f.ctx, "m*c^2/sqrt(1 - (r'^2 + r^2*phi'^2)/c^2) - k/r");
    for (int k = 0; k < NPOINTS; k++) {
        point pt = slow_state(&f);
        set(&pt, R->beta[0], val(f.ctx, &pt, R->pdef[0]));
        assert_close(val(f.ctx, &pt, R->R), val(f.ctx, &pt, want), 1e-12, "R");
        assert_close(val(f.ctx, &pt, R->ignvel[0]), val(f.ctx, &pt, f.e->qd[1]), 1e-12,
                     "phi' from p_phi");
        assert_close(val(f.ctx, &pt, R->h), val(f.ctx, &pt, E), 1e-12, "h = m gamma c^2 - k/r");
        double M[4], F[2];
        for (size_t i = 0; i < 4; i++)
            M[i] = val(f.ctx, &pt, f.e->M[i]);
        for (size_t i = 0; i < 2; i++)
            F[i] = val(f.ctx, &pt, f.e->f[i]);
        double rdd = (F[0] * M[3] - M[1] * F[1]) / (M[0] * M[3] - M[1] * M[2]);
        assert_close(val(f.ctx, &pt, R->f[0]) / val(f.ctx, &pt, R->M[0]), rdd, 1e-10,
                     "reduced r''");
    }
    qd_routh_free(R);
    unload(&f);
}

/* The inverse (Appendix 22, the involution): H = sqrt(m^2 c^4 + c^2 p^2) + V
 * gives L = -m c^2 sqrt(1 - v^2/c^2) - V and p = m gamma v. */
static void test_inverse_from_H(void **state) {
    (void)state;
    fix f = load("coordinates x, y\nparameters m = 1, c = 2, k = 1\nmomenta p_x, p_y\n"
                 "H = sqrt(m^2*c^4 + c^2*(p_x^2 + p_y^2)) + k*(x^2 + y^2)/2\n");
    assert_non_null(f.h);
    if (!f.h->L_from_H)
        fail_msg("no L: %s", f.h->L_why);
    const qd_expr *L = read_expr(f.ctx, "-m*c^2*sqrt(1 - (x'^2 + y'^2)/c^2) - k*(x^2 + y^2)/2");
    const qd_expr *px = read_expr(f.ctx, "m*x'/sqrt(1 - (x'^2 + y'^2)/c^2)");
    for (int k = 0; k < NPOINTS; k++) {
        point pt = {.n = 0};
        for (size_t j = 0; j < 2; j++) {
            set(&pt, f.h->q[j], uniform(-1, 1));
            set(&pt, f.h->qd[j], uniform(-0.6, 0.6));
        }
        add_syms(f.ctx, &pt, L, 1, 2);
        assert_close(val(f.ctx, &pt, f.h->L_from_H), val(f.ctx, &pt, L), 1e-12, "L from H");
        assert_close(val(f.ctx, &pt, f.h->pdef[0]), val(f.ctx, &pt, px), 1e-12, "p_x(x', y')");
    }
    assert_non_null(qd_legendre_inverse(f.ctx, f.m));
    unload(&f);
}

static void assert_singular(const char *model, const char *want) {
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, model, &d);
    assert_non_null(m);
    assert_int_equal(qd_ham_regular(ctx, m), QD_ERR_SINGULAR);
    if (!strstr(qd_ctx_message(ctx), want))
        fail_msg("message \"%s\" lacks \"%s\"", qd_ctx_message(ctx), want);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* P13: singular Hessians; a regular one passes. */
static void test_singular(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, "coordinates x\nL = -sqrt(1 - x'^2)\n", &d);
    assert_int_equal(qd_ham_regular(ctx, m), QD_OK);
    qd_model_free(m);
    qd_ctx_free(ctx);
    assert_singular("coordinates x, y\nparameters m = 1, c = 1\n"
                    "L = -m*c^2*sqrt(1 - y'^2/c^2) + x'*y - x^2/2\n",
                    "L is linear in x': its Hessian in the velocities is singular, so there "
                    "is no Hamiltonian (p_x = y does not depend on x')");
    /* Appendix 20, T27: -m c sqrt(c^2 t'^2 - x'^2) is of degree 1 */
    assert_singular("coordinates s, x\nparameters m = 1, c = 1\n"
                    "L = -m*c*sqrt(c^2*s'^2 - x'^2)\n",
                    "homogeneous of degree 1");
}

/* Every allocation of the transform refused in turn (tests/util/fault.h):
 * the closed form in fields, Newton on the implicit quartic, the inverse
 * from H.  Each run ends with the right H (checked at one point) or a clean
 * QD_ERR_NOMEM, nothing leaked. */
static const char *const FAULT_MODELS[] = {
    ("coordinates x, y\nparameters m = 1.3, e = 0.8, c = 3, B = 2\n"
     "L = -m*c^2*sqrt(1 - (x'^2 + y'^2)/c^2) + e*B*(x*y' - y*x')/2\n"),
    "coordinates x\nL = x'^2/2 + x'^4/12 - x^2/2\n",
    "coordinates x\nparameters m = 1, c = 2\nmomenta p\nH = sqrt(m^2*c^4 + c^2*p^2) + x^2/2\n",
};

static qd_status fault_body(qd_ctx *ctx, qt_faulty *fl, void *data) {
    const char *text = *(const char *const *)data;
    long to_go = qt_fault_hold(fl);
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, text, &d);
    assert_non_null(m);
    qd_eom *e = qd_model_hamiltonian_given(m) ? NULL : qd_eom_derive(ctx, m);
    qt_fault_release(fl, to_go);
    qd_status st = qd_ham_regular(ctx, m);
    qd_ham *h = st == QD_OK ? qd_ham_derive(ctx, m, e) : NULL;
    if (st == QD_OK && !h)
        st = qd_ctx_status(ctx);
    double v[2] = {0, 0};
    if (h && h->implicit) {
        const qd_expr *syms[2] = {h->q[0], h->p[0]};
        const double vals[2] = {0.3, 0.5 + 0.125 / 3}; /* p at x' = 1/2 */
        st = qd_ham_velocities_at(ctx, h, 2, syms, vals, v);
        if (st == QD_OK)
            assert_true(fabs(v[0] - 0.5) < 1e-12);
    } else if (h) {
        assert_non_null(h->H);
        assert_non_null(h->vel[0]);
        if (h->H_given)
            assert_non_null(h->L_from_H);
    }
    qd_ham_free(h);
    qd_eom_free(e);
    qd_model_free(m);
    return st;
}

static void test_fault(void **state) {
    (void)state;
    static const long stride[] = {7, 1, 1}; /* the fields' model: ~10^4 requests */
    for (size_t i = 0; i < sizeof FAULT_MODELS / sizeof *FAULT_MODELS; i++) {
        const char *text = FAULT_MODELS[i];
        qt_fault_stats ls = qt_fault_loop("non-quadratic Legendre transform", fault_body,
                                          &text, stride[i]);
        assert_true(ls.allocs > 10);
    }
}

int main(void) {
    srand(SEED);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_relativistic_1d),
        cmocka_unit_test(test_relativistic_fields),
        cmocka_unit_test(test_relativistic_polar),
        cmocka_unit_test(test_newtonian_limit),
        cmocka_unit_test(test_implicit_quartic),
        cmocka_unit_test(test_routh_central),
        cmocka_unit_test(test_inverse_from_H),
        cmocka_unit_test(test_singular),
        cmocka_unit_test(test_fault),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
