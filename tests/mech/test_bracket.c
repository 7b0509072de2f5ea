/*
 * tests/mech/test_bracket.c - Poisson brackets (Desloge ch. 80-81; seed
 * /work/shared/reference/seed-desloge-C.md, C3): the angular-momentum
 * algebra, the Jacobi identity on random functions, Poisson's theorem.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>

#include "qdot/qdot.h"
#include "qdot/canonical.h"
#include "util/randexpr.h"

#define SEED 20250305u
#define NJACOBI 200

typedef struct cart {
    qd_ctx *ctx;
    const qd_expr *q[3], *p[3], *L[3];
} cart;

static const qd_expr *S(qd_ctx *ctx, const char *name) { return qd_symbol(ctx, name); }

/* L = r x p in Cartesian coordinates, written out by hand. */
static void cart_init(cart *c) {
    qd_ctx *ctx = c->ctx = qd_ctx_new();
    assert_non_null(ctx);
    const char *qn[3] = {"x", "y", "z"}, *pn[3] = {"p_x", "p_y", "p_z"};
    for (int i = 0; i < 3; i++) {
        c->q[i] = S(ctx, qn[i]);
        c->p[i] = S(ctx, pn[i]);
    }
    for (int i = 0; i < 3; i++) {
        int j = (i + 1) % 3, k = (i + 2) % 3;
        c->L[i] = qd_sub(ctx, qd_mul(ctx, c->q[j], c->p[k]), qd_mul(ctx, c->q[k], c->p[j]));
    }
}

static void test_fundamental(void **state) {
    (void)state;
    cart c;
    cart_init(&c);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            assert_true(qd_is_zero(qd_bracket(c.ctx, 3, c.q, c.p, c.q[i], c.q[j])));
            assert_true(qd_is_zero(qd_bracket(c.ctx, 3, c.q, c.p, c.p[i], c.p[j])));
            const qd_expr *b = qd_bracket(c.ctx, 3, c.q, c.p, c.q[i], c.p[j]);
            assert_ptr_equal(b, qd_int(c.ctx, i == j));
        }
    qd_ctx_free(c.ctx);
}

/* [L_x, L_y] = L_z and cyclically; [L_i, L^2] = 0. */
static void test_angular_momentum(void **state) {
    (void)state;
    cart c;
    cart_init(&c);
    qd_ctx *ctx = c.ctx;
    const qd_expr *L2 = qd_int(ctx, 0);
    for (int i = 0; i < 3; i++)
        L2 = qd_add(ctx, L2, qd_powi(ctx, c.L[i], 2));
    for (int i = 0; i < 3; i++) {
        const qd_expr *b = qd_bracket(ctx, 3, c.q, c.p, c.L[i], c.L[(i + 1) % 3]);
        assert_ptr_equal(qd_simplify(ctx, qd_sub(ctx, b, c.L[(i + 2) % 3])), qd_int(ctx, 0));
        assert_true(qd_is_zero(qd_bracket(ctx, 3, c.q, c.p, c.L[i], L2)));
        /* antisymmetry */
        const qd_expr *r = qd_bracket(ctx, 3, c.q, c.p, c.L[(i + 1) % 3], c.L[i]);
        assert_true(qd_is_zero(qd_simplify(ctx, qd_add(ctx, b, r))));
    }
    /* [x, L_z] = -y, [p_x, L_z] = -p_y */
    assert_ptr_equal(qd_bracket(ctx, 3, c.q, c.p, c.q[0], c.L[2]), qd_neg(ctx, c.q[1]));
    assert_ptr_equal(qd_bracket(ctx, 3, c.q, c.p, c.p[0], c.L[2]), qd_neg(ctx, c.p[1]));
    assert_int_equal(qd_ctx_status(ctx), QD_OK);
    qd_ctx_free(ctx);
}

/* Poisson's theorem: L_x and L_y are integrals of a particle in a central
 * potential V(r), so [L_x, L_y] = L_z is one too: [L_z, H] = 0. */
static void test_poisson_theorem(void **state) {
    (void)state;
    cart c;
    cart_init(&c);
    qd_ctx *ctx = c.ctx;
    const qd_expr *m = qd_param(ctx, "m"), *k = qd_param(ctx, "k");
    const qd_expr *p2 = qd_int(ctx, 0), *r2 = qd_int(ctx, 0);
    for (int i = 0; i < 3; i++) {
        p2 = qd_add(ctx, p2, qd_powi(ctx, c.p[i], 2));
        r2 = qd_add(ctx, r2, qd_powi(ctx, c.q[i], 2));
    }
    const qd_expr *T = qd_div(ctx, p2, qd_mul(ctx, qd_int(ctx, 2), m));
    const qd_expr *Hs[2] = {T, qd_add(ctx, T, qd_mul(ctx, k, r2))}; /* free, isotropic */
    for (int h = 0; h < 2; h++) {
        const qd_expr *H = Hs[h];
        assert_true(qd_is_zero(qd_bracket(ctx, 3, c.q, c.p, c.L[0], H)));
        assert_true(qd_is_zero(qd_bracket(ctx, 3, c.q, c.p, c.L[1], H)));
        const qd_expr *N = qd_bracket(ctx, 3, c.q, c.p, c.L[0], c.L[1]);
        assert_true(qd_is_zero(qd_bracket(ctx, 3, c.q, c.p, N, H)));
    }
    /* x is not an integral of the free particle: [x, H] = p_x/m */
    const qd_expr *xd = qd_bracket(ctx, 3, c.q, c.p, c.q[0], T);
    assert_ptr_equal(qd_simplify(ctx, qd_sub(ctx, xd, qd_div(ctx, c.p[0], m))), qd_int(ctx, 0));
    qd_ctx_free(ctx);
}

static double at(qd_ctx *ctx, const qd_expr *e, const qd_expr *const *syms, const double *v) {
    double out = NAN;
    assert_int_equal(qd_eval(ctx, e, 4, syms, v, &out), QD_OK);
    return out;
}

static void fail_case(qd_ctx *ctx, int it, const char *what, const qd_expr *const *f) {
    qd_buf b = QD_BUF_INIT;
    for (int i = 0; i < 3; i++) {
        qd_buf_puts(&b, i ? "; " : "");
        qd_print(ctx, f[i], QD_FMT_TEXT, &b);
    }
    print_error("seed %u, case %d: %s for F, G, H = %s\n", SEED, it, what, qd_buf_str(&b));
    qd_buf_free(&b);
    fail();
}

/* [F,[G,H]] + [G,[H,F]] + [H,[F,G]] = 0: exactly for polynomials, and at
 * random points (relative to the size of the terms) with sines and cosines. */
static void test_jacobi(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *q[2] = {S(ctx, "q1"), S(ctx, "q2")}, *p[2] = {S(ctx, "p1"), S(ctx, "p2")};
    const qd_expr *all[4] = {q[0], q[1], p[0], p[1]};
    qt_rng r = {SEED};
    for (int it = 0; it < NJACOBI; it++) {
        unsigned flags = it % 2 ? QT_POLY | QT_TRIG : QT_POLY;
        const qd_expr *f[3];
        for (int i = 0; i < 3; i++)
            f[i] = qt_random_expr(ctx, &r, all, 4, 2, flags);
        const qd_expr *t[3];
        for (int i = 0; i < 3; i++) {
            const qd_expr *inner = qd_bracket(ctx, 2, q, p, f[(i + 1) % 3], f[(i + 2) % 3]);
            t[i] = qd_bracket(ctx, 2, q, p, f[i], inner);
            assert_non_null(t[i]);
        }
        const qd_expr *sum = qd_add(ctx, qd_add(ctx, t[0], t[1]), t[2]);
        if (flags == QT_POLY && !qd_is_zero(qd_simplify(ctx, sum)))
            fail_case(ctx, it, "Jacobi sum not simplified to 0", f);
        for (int k = 0; k < 3; k++) {
            double v[4], scale = 1;
            for (int j = 0; j < 4; j++)
                v[j] = qt_uniform(&r, -1, 1);
            for (int i = 0; i < 3; i++)
                scale += fabs(at(ctx, t[i], all, v));
            double s = at(ctx, sum, all, v);
            if (fabs(s) > 1e-9 * scale)
                fail_case(ctx, it, "Jacobi sum not 0 numerically", f);
        }
    }
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_fundamental),
        cmocka_unit_test(test_angular_momentum),
        cmocka_unit_test(test_poisson_theorem),
        cmocka_unit_test(test_jacobi),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
