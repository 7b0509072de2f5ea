/*
 * tests/mech/test_routh_implicit.c - the implicit Routhian (issue 17,
 * qdot/routh.h): Routh's reduction of Lagrangians whose ignored velocity has
 * no closed form, p_c = dL/dc' kept implicit and solved by Newton at a point.
 *
 * Why these checks can fail: the reduced equations are Lagrange's equations
 * of -R at fixed p with c'' eliminated through dp/dt = 0 (envelope theorem,
 * Desloge ch. 72 thm 2 extended beyond quadratic L as in Desloge Appendix 22
 * for H).  They are compared with the full Lagrange equations of the same
 * L, derived and solved independently (qd_eom_derive, qd_eom_eval), at
 * random states where p is computed from c'; a wrong sign in the envelope,
 * a forgotten c'' term or a wrong Schur complement changes the kept
 * accelerations at O(1).  R is compared with p c' - L and the Jacobi
 * integral of -R with the full energy sum q' dL/dq' - L (they are equal
 * since p c' + k' dL/dk' = sum q' dL/dq').
 *
 * Models (each Hessian regular on the sampled states):
 * - L = cosh(x') + y'^2/2 + x' y' y/2 - y^2: det = cosh x' - y^2/4 > 0 for
 *   |y| < 2; x' from p = sinh x' + y' y/2 is transcendental.
 * - L = x'^2/2 + x'^4/12 + x' (y z' - z y')/2 + (y'^2 + z'^2)/2
 *   - (y^2 + 2 z^2)/2: p = x' + x'^3/3 + (y z' - z y')/2 is a cubic (no
 *   cubic solver in the kernel), and the two kept coordinates are coupled
 *   through x' (a gyroscopic-like term, not a split by degree).
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

#define SEED 2717u
#define NPOINTS 16
#define MAXN 4
#define MAXS 16

static const char cosh_model[] = "coordinates x, y\n"
                                 "L = cosh(x') + y'^2/2 + x'*y'*y/2 - y^2\n";

static const char cubic_model[] = "coordinates x, y, z\n"
                                  "L = x'^2/2 + x'^4/12 + x'*(y*z' - z*y')/2 + (y'^2 + z'^2)/2"
                                  " - (y^2 + 2*z^2)/2\n";

typedef struct fix {
    qd_ctx *ctx;
    qd_model *m;
    qd_eom *e;
    qd_routh *r;
} fix;

static fix load(const char *text, bool implicit_ok) {
    fix f = {qd_ctx_new(), NULL, NULL, NULL};
    qd_diag d;
    f.m = qd_model_parse(f.ctx, text, &d);
    assert_non_null(f.m);
    f.e = qd_eom_derive(f.ctx, f.m);
    assert_non_null(f.e);
    const qd_expr *x = qd_routh_lookup(f.ctx, f.m, "x");
    assert_non_null(x);
    qd_routh_opts opts = {.implicit = implicit_ok};
    f.r = qd_routh_derive_opts(f.ctx, f.m, f.e, 1, &x, &opts);
    if (!f.r && implicit_ok)
        fprintf(stderr, "qd_routh_derive_opts: %s\n", qd_ctx_message(f.ctx));
    return f;
}

static void unload(fix *f) {
    qd_routh_free(f->r);
    qd_eom_free(f->e);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
}

static double uniform(double lo, double hi) { return lo + (hi - lo) * rand() / (double)RAND_MAX; }

static double eval(const fix *f, const qd_expr *x, size_t n, const qd_expr *const *s,
                   const double *v) {
    double out = NAN;
    assert_int_equal(qd_eval(f->ctx, x, n, s, v, &out), QD_OK);
    return out;
}

/* Small dense solve A x = b (n <= MAXN), Gaussian elimination with pivoting. */
static void solve(size_t n, double *A, double *b) {
    for (size_t k = 0; k < n; k++) {
        size_t p = k;
        for (size_t i = k + 1; i < n; i++)
            if (fabs(A[i * n + k]) > fabs(A[p * n + k]))
                p = i;
        for (size_t c = 0; c < n; c++) {
            double t = A[k * n + c];
            A[k * n + c] = A[p * n + c];
            A[p * n + c] = t;
        }
        double t = b[k];
        b[k] = b[p];
        b[p] = t;
        assert_true(fabs(A[k * n + k]) > 1e-12);
        for (size_t i = k + 1; i < n; i++) {
            double m = A[i * n + k] / A[k * n + k];
            for (size_t c = k; c < n; c++)
                A[i * n + c] -= m * A[k * n + c];
            b[i] -= m * b[k];
        }
    }
    for (size_t k = n; k-- > 0;) {
        for (size_t c = k + 1; c < n; c++)
            b[k] -= A[k * n + c] * b[c];
        b[k] /= A[k * n + k];
    }
}

/* The kept accelerations from the reduced M keep'' = f at the symbols s. */
static void reduced_acc(const fix *f, size_t n, const qd_expr *const *s, const double *v,
                        double *acc) {
    size_t nk = f->r->nkeep;
    double M[MAXN * MAXN];
    for (size_t i = 0; i < nk * nk; i++)
        M[i] = eval(f, f->r->M[i], n, s, v);
    for (size_t k = 0; k < nk; k++)
        acc[k] = eval(f, f->r->f[k], n, s, v);
    solve(nk, M, acc);
}

/* sum q' dL/dq' - L at the full state. */
static double energy(const fix *f, size_t n, const qd_expr *const *s, const double *v) {
    double E = -eval(f, f->e->L, n, s, v);
    for (size_t j = 0; j < f->e->n; j++)
        E += v[f->e->n + j] * eval(f, qd_diff(f->ctx, f->e->L, f->e->qd[j]), n, s, v);
    return E;
}

/* At random states (q, q'): p from c', c' back from p by Newton, the kept
 * accelerations of the reduced equations against the full ones, R against
 * p c' - L, the Jacobi integral against the energy. */
static void against_full(const char *text, double vmax) {
    fix f = load(text, true);
    assert_non_null(f.r);
    assert_true(f.r->implicit);
    size_t n = f.e->n, nk = f.r->nkeep, ci = f.r->ign_index[0];
    const qd_expr *s[MAXS];
    double v[MAXS];
    for (size_t j = 0; j < n; j++) {
        s[j] = f.e->q[j];
        s[n + j] = f.e->qd[j];
    }
    s[2 * n] = f.r->beta[0];
    srand(SEED);
    for (int it = 0; it < NPOINTS; it++) {
        for (size_t j = 0; j < n; j++) {
            v[j] = uniform(-1.2, 1.2);
            v[n + j] = uniform(-vmax, vmax);
        }
        double cd = v[n + ci];
        v[2 * n] = eval(&f, f.r->pdef[0], 2 * n, s, v);
        double full[MAXN];
        assert_int_equal(qd_eom_eval(f.ctx, f.e, 2 * n, s, v, NULL, NULL, full, NULL, NULL),
                         QD_OK);
        double E = energy(&f, 2 * n, s, v), L = eval(&f, f.e->L, 2 * n, s, v);
        v[n + ci] = 0.5; /* a poor guess: Newton must find c' from p alone */
        double cN = NAN;
        assert_int_equal(qd_routh_velocities_at(f.ctx, f.r, f.e, 2 * n + 1, s, v, &cN), QD_OK);
        assert_true(fabs(cN - cd) < 1e-12 * (1 + fabs(cd)));
        v[n + ci] = cN;
        double acc[MAXN];
        reduced_acc(&f, 2 * n + 1, s, v, acc);
        for (size_t k = 0; k < nk; k++) {
            double want = full[f.r->keep_index[k]];
            assert_true(fabs(acc[k] - want) < 1e-10 * (1 + fabs(want)));
        }
        double R = eval(&f, f.r->R, 2 * n + 1, s, v), h = eval(&f, f.r->h, 2 * n + 1, s, v);
        assert_true(fabs(R - (v[2 * n] * cd - L)) < 1e-12 * (1 + fabs(R)));
        assert_true(fabs(h - E) < 1e-12 * (1 + fabs(E)));
    }
    assert_true(f.r->conserved);
    assert_null(f.r->Veff);
    unload(&f);
}

static void test_cosh_one_kept(void **state) {
    (void)state;
    against_full(cosh_model, 2.0);
}

static void test_cubic_two_kept(void **state) {
    (void)state;
    against_full(cubic_model, 1.5);
}

/* Without the option the old contract holds: callers that need V_eff in
 * closed form (orbit, scatter, steady motions) still get QD_ERR_NONLINEAR. */
static void test_default_refuses(void **state) {
    (void)state;
    fix f = load(cosh_model, false);
    assert_null(f.r);
    assert_int_equal(qd_ctx_status(f.ctx), QD_ERR_NONLINEAR);
    unload(&f);
}

/* A quadratic L is never implicit, with or without the option, and Newton
 * agrees with the closed-form quadrature there (L = (x'^2 + y'^2 y^2)/2
 * + x' y' - y^2/2: x' = p - y'). */
static void test_quadratic_stays_closed(void **state) {
    (void)state;
    fix f = load("coordinates x, y\nL = (x'^2 + y'^2*y^2)/2 + x'*y' - y^2/2\n", true);
    assert_non_null(f.r);
    assert_false(f.r->implicit);
    assert_non_null(f.r->Veff);
    const qd_expr *s[] = {f.r->keep[0], f.r->keepd[0], f.r->beta[0]};
    double v[] = {0.7, -0.4, 1.3}, cN = NAN;
    assert_int_equal(qd_routh_velocities_at(f.ctx, f.r, f.e, 3, s, v, &cN), QD_OK);
    assert_true(fabs(cN - eval(&f, f.r->ignvel[0], 3, s, v)) < 1e-12);
    assert_true(fabs(cN - 1.7) < 1e-12);
    unload(&f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cosh_one_kept),
        cmocka_unit_test(test_cubic_two_kept),
        cmocka_unit_test(test_default_refuses),
        cmocka_unit_test(test_quadratic_stays_closed),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
