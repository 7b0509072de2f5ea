/*
 * tests/mech/test_canonical.c - the canonicity test and generating functions
 * (Goldstein ch. 9; seed /work/shared/reference/seed-desloge-C.md: C4, C5,
 * T27, T29, T31, T33).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "qdot/qdot.h"
#include "qdot/canonical.h"

static const qd_expr *S(qd_ctx *ctx, const char *name) { return qd_symbol(ctx, name); }

static qd_canon_verdict check(qd_ctx *ctx, size_t n, const qd_expr *const *q,
                              const qd_expr *const *p, const qd_expr *const *Q,
                              const qd_expr *const *P) {
    qd_canon_verdict v;
    assert_int_equal(qd_canonical_check(ctx, n, q, p, Q, P, qd_time(ctx), &v), QD_OK);
    return v;
}

static bool same(qd_ctx *ctx, const qd_expr *a, const qd_expr *b) {
    return qd_is_zero(qd_simplify(ctx, qd_sub(ctx, a, b)));
}

/* Q = q^a cos(b p), P = q^a sin(b p): [Q, P] = a b q^(2a - 1) by hand, so
 * canonical only for a = 1/2, b = 2, scaled by a b when a = 1/2. */
static void test_power_trig(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *q = S(ctx, "q"), *p = S(ctx, "p");
    struct { long an, ad, bn, bd; qd_canon_kind kind; } cases[] = {
        {1, 2, 2, 1, QD_CANON_YES},    {1, 2, 1, 1, QD_CANON_SCALED},
        {1, 2, 4, 1, QD_CANON_SCALED}, {1, 1, 1, 1, QD_CANON_NO},
        {1, 1, 2, 1, QD_CANON_NO},     {3, 2, 2, 3, QD_CANON_NO},
        {1, 3, 3, 1, QD_CANON_NO},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        const qd_expr *a = qd_rat(ctx, cases[k].an, cases[k].ad);
        const qd_expr *b = qd_rat(ctx, cases[k].bn, cases[k].bd);
        const qd_expr *qa = qd_pow(ctx, q, a), *bp = qd_mul(ctx, b, p);
        const qd_expr *Q = qd_mul(ctx, qa, qd_fn(ctx, QD_COS, bp));
        const qd_expr *P = qd_mul(ctx, qa, qd_fn(ctx, QD_SIN, bp));
        qd_canon_verdict v = check(ctx, 1, &q, &p, &Q, &P);
        assert_int_equal(v.kind, cases[k].kind);
        if (v.kind == QD_CANON_NO) {
            assert_int_equal(v.pair, QD_PAIR_QP);
            assert_true(same(ctx, v.value, qd_mul(ctx, qd_mul(ctx, a, b),
                                                  qd_pow(ctx, q, qd_sub(ctx, qd_mul(ctx, qd_int(ctx, 2), a), qd_int(ctx, 1))))));
        } else {
            assert_ptr_equal(v.scale, qd_mul(ctx, a, b));
        }
    }
    qd_ctx_free(ctx);
}

/* (Q, P) = A (q, p): canonical iff det A = 1, scaled by det A otherwise. */
static void test_linear_1d(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *q = S(ctx, "q"), *p = S(ctx, "p");
    long A[][4] = {{1, 0, 0, 1}, {2, 1, 1, 1}, {1, 2, 3, 4}, {3, 0, 0, 1}, {1, 1, 1, 1}, {0, 1, -1, 0}};
    for (size_t k = 0; k < sizeof A / sizeof A[0]; k++) {
        const long *a = A[k];
        const qd_expr *Q = qd_add(ctx, qd_mul(ctx, qd_int(ctx, a[0]), q), qd_mul(ctx, qd_int(ctx, a[1]), p));
        const qd_expr *P = qd_add(ctx, qd_mul(ctx, qd_int(ctx, a[2]), q), qd_mul(ctx, qd_int(ctx, a[3]), p));
        long det = a[0] * a[3] - a[1] * a[2];
        qd_canon_verdict v = check(ctx, 1, &q, &p, &Q, &P);
        assert_int_equal(v.kind, det == 1 ? QD_CANON_YES : det == 0 ? QD_CANON_NO : QD_CANON_SCALED);
        if (det != 0)
            assert_ptr_equal(v.scale, qd_int(ctx, det));
    }
    /* symbolic entries: the scale is a d - b c */
    const qd_expr *a = qd_param(ctx, "a"), *b = qd_param(ctx, "b"), *c = qd_param(ctx, "c"),
                  *d = qd_param(ctx, "d");
    const qd_expr *Q = qd_add(ctx, qd_mul(ctx, a, q), qd_mul(ctx, b, p));
    const qd_expr *P = qd_add(ctx, qd_mul(ctx, c, q), qd_mul(ctx, d, p));
    qd_canon_verdict v = check(ctx, 1, &q, &p, &Q, &P);
    assert_int_equal(v.kind, QD_CANON_SCALED);
    assert_true(same(ctx, v.scale, qd_sub(ctx, qd_mul(ctx, a, d), qd_mul(ctx, b, c))));
    qd_ctx_free(ctx);
}

/* Q = A q, P = B p (T31): canonical iff B = (A^-1)^T. */
static void test_linear_2d(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *q[2] = {S(ctx, "q1"), S(ctx, "q2")}, *p[2] = {S(ctx, "p1"), S(ctx, "p2")};
    const qd_expr *a = qd_param(ctx, "a"), *b = qd_param(ctx, "b"), *c = qd_param(ctx, "c"),
                  *d = qd_param(ctx, "d");
    const qd_expr *det = qd_sub(ctx, qd_mul(ctx, a, d), qd_mul(ctx, b, c));
    const qd_expr *A[4] = {a, b, c, d};
    /* (A^-1)^T = [[d, -c], [-b, a]] / det, by hand */
    const qd_expr *Binv[4] = {qd_div(ctx, d, det), qd_div(ctx, qd_neg(ctx, c), det),
                              qd_div(ctx, qd_neg(ctx, b), det), qd_div(ctx, a, det)};
    const qd_expr *Btwo[4], *Bbad[4] = {a, b, c, d};
    for (int i = 0; i < 4; i++)
        Btwo[i] = qd_mul(ctx, qd_int(ctx, 2), Binv[i]);
    const qd_expr *const *Bs[3] = {Binv, Btwo, Bbad};
    qd_canon_kind want[3] = {QD_CANON_YES, QD_CANON_SCALED, QD_CANON_NO};
    for (int k = 0; k < 3; k++) {
        const qd_expr *Q[2], *P[2];
        for (int i = 0; i < 2; i++) {
            Q[i] = qd_add(ctx, qd_mul(ctx, A[2 * i], q[0]), qd_mul(ctx, A[2 * i + 1], q[1]));
            P[i] = qd_add(ctx, qd_mul(ctx, Bs[k][2 * i], p[0]), qd_mul(ctx, Bs[k][2 * i + 1], p[1]));
        }
        qd_canon_verdict v = check(ctx, 2, q, p, Q, P);
        assert_int_equal(v.kind, want[k]);
        if (k == 1)
            assert_ptr_equal(v.scale, qd_int(ctx, 2));
        if (k == 2)
            assert_int_equal(v.pair, QD_PAIR_QP);
    }
    qd_ctx_free(ctx);
}

/* T27, T29 canonical; a time-dependent scale is not; the failing pair. */
static void test_desloge_and_failures(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *q = S(ctx, "q"), *p = S(ctx, "p"), *t = qd_time(ctx);
    const qd_expr *lp = qd_fn(ctx, QD_LOG, p);
    const qd_expr *Q1 = lp, *P1 = qd_neg(ctx, qd_mul(ctx, qd_add(ctx, qd_add(ctx, qd_int(ctx, 1), q), lp), p));
    assert_int_equal(check(ctx, 1, &q, &p, &Q1, &P1).kind, QD_CANON_YES);
    const qd_expr *Q2 = qd_add(ctx, q, qd_mul(ctx, t, qd_fn(ctx, QD_EXP, p))), *P2 = p;
    assert_int_equal(check(ctx, 1, &q, &p, &Q2, &P2).kind, QD_CANON_YES);
    const qd_expr *Q3 = qd_mul(ctx, t, q);
    qd_canon_verdict v = check(ctx, 1, &q, &p, &Q3, &p);
    assert_int_equal(v.kind, QD_CANON_NO);
    assert_ptr_equal(v.value, t);
    /* Q = q, P = (p1, p2 + q1): [P1, P2] = -1 */
    const qd_expr *qq[2] = {S(ctx, "q1"), S(ctx, "q2")}, *pp[2] = {S(ctx, "p1"), S(ctx, "p2")};
    const qd_expr *PP[2] = {pp[0], qd_add(ctx, pp[1], qq[0])};
    v = check(ctx, 2, qq, pp, qq, PP);
    assert_int_equal(v.kind, QD_CANON_NO);
    assert_int_equal(v.pair, QD_PAIR_PP);
    assert_int_equal(v.i, 0);
    assert_int_equal(v.j, 1);
    assert_ptr_equal(v.value, qd_int(ctx, -1));
    qd_ctx_free(ctx);
}

typedef struct vars {
    const qd_expr *q[2], *p[2], *Q[2], *P[2], *t;
} vars;

static vars mkvars(qd_ctx *ctx, int n) {
    vars v;
    const char *names[4][2] = {{"q", "q2"}, {"p", "p2"}, {"Q", "Q2"}, {"P", "P2"}};
    if (n == 2) {
        names[0][0] = "q1"; names[1][0] = "p1"; names[2][0] = "Q1"; names[3][0] = "P1";
    }
    for (int i = 0; i < 2; i++) {
        v.q[i] = S(ctx, names[0][i]);
        v.p[i] = S(ctx, names[1][i]);
        v.Q[i] = S(ctx, names[2][i]);
        v.P[i] = S(ctx, names[3][i]);
    }
    v.t = qd_time(ctx);
    return v;
}

/* All four types on the identity and the exchange, with H an oscillator. */
static void test_generators_1d(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    vars x = mkvars(ctx, 1);
    const qd_expr *q = x.q[0], *p = x.p[0], *Q = x.Q[0], *P = x.P[0], *h = qd_rat(ctx, 1, 2);
    const qd_expr *H = qd_mul(ctx, h, qd_add(ctx, qd_powi(ctx, p, 2), qd_powi(ctx, q, 2)));
    const qd_expr *Hnew = qd_mul(ctx, h, qd_add(ctx, qd_powi(ctx, P, 2), qd_powi(ctx, Q, 2)));
    struct { qd_gen_type type; const qd_expr *F, *wantQ, *wantP; } cases[] = {
        {QD_GEN_F1, qd_mul(ctx, q, Q), p, qd_neg(ctx, q)},
        {QD_GEN_F2, qd_mul(ctx, q, P), q, p},
        {QD_GEN_F3, qd_neg(ctx, qd_mul(ctx, p, Q)), q, p},
        {QD_GEN_F4, qd_mul(ctx, p, P), p, qd_neg(ctx, q)},
    };
    for (size_t k = 0; k < 4; k++) {
        qd_gen_result r;
        assert_int_equal(qd_generate(ctx, cases[k].type, 1, x.q, x.p, x.Q, x.P, cases[k].F, x.t, H, &r), QD_OK);
        assert_ptr_equal(r.Q[0], cases[k].wantQ);
        assert_ptr_equal(r.P[0], cases[k].wantP);
        assert_ptr_equal(r.K_old, qd_simplify(ctx, H));
        assert_non_null(r.K_new);
        assert_true(same(ctx, r.K_new, Hnew));
        qd_gen_result_free(&r);
    }
    qd_ctx_free(ctx);
}

/* F2 = q P + eps P^2: Q = q + 2 eps p, P = p; F2 = q P + eps q^2: P = p -
 * 2 eps q; F2 = (q + v t) P (a moving frame): Q = q + v t, K = H + v P. */
static void test_f2_examples(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    vars x = mkvars(ctx, 1);
    const qd_expr *q = x.q[0], *p = x.p[0], *Q = x.Q[0], *P = x.P[0], *t = x.t;
    const qd_expr *eps = qd_param(ctx, "eps"), *m = qd_param(ctx, "m"), *vel = qd_param(ctx, "v");
    const qd_expr *two = qd_int(ctx, 2), *qP = qd_mul(ctx, q, P);
    const qd_expr *H = qd_div(ctx, qd_powi(ctx, p, 2), qd_mul(ctx, two, m));
    qd_gen_result r;
    const qd_expr *F = qd_add(ctx, qP, qd_mul(ctx, eps, qd_powi(ctx, P, 2)));
    assert_int_equal(qd_generate_f2(ctx, 1, x.q, x.p, x.Q, x.P, F, t, H, &r), QD_OK);
    assert_true(same(ctx, r.Q[0], qd_add(ctx, q, qd_mul(ctx, qd_mul(ctx, two, eps), p))));
    assert_ptr_equal(r.P[0], p);
    assert_int_equal(check(ctx, 1, x.q, x.p, r.Q, r.P).kind, QD_CANON_YES);
    assert_true(same(ctx, r.K_new, qd_div(ctx, qd_powi(ctx, P, 2), qd_mul(ctx, two, m))));
    qd_gen_result_free(&r);

    F = qd_add(ctx, qP, qd_mul(ctx, eps, qd_powi(ctx, q, 2)));
    assert_int_equal(qd_generate_f2(ctx, 1, x.q, x.p, x.Q, x.P, F, t, H, &r), QD_OK);
    assert_ptr_equal(r.Q[0], q);
    assert_true(same(ctx, r.P[0], qd_sub(ctx, p, qd_mul(ctx, qd_mul(ctx, two, eps), q))));
    assert_int_equal(check(ctx, 1, x.q, x.p, r.Q, r.P).kind, QD_CANON_YES);
    /* K(Q, P) = (P + 2 eps Q)^2 / 2m */
    const qd_expr *pn = qd_add(ctx, P, qd_mul(ctx, qd_mul(ctx, two, eps), Q));
    assert_true(same(ctx, r.K_new, qd_div(ctx, qd_powi(ctx, pn, 2), qd_mul(ctx, two, m))));
    qd_gen_result_free(&r);

    F = qd_mul(ctx, qd_add(ctx, q, qd_mul(ctx, vel, t)), P);
    assert_int_equal(qd_generate_f2(ctx, 1, x.q, x.p, x.Q, x.P, F, t, H, &r), QD_OK);
    assert_true(same(ctx, r.Q[0], qd_add(ctx, q, qd_mul(ctx, vel, t))));
    assert_ptr_equal(r.P[0], p);
    assert_true(same(ctx, r.K_old, qd_add(ctx, H, qd_mul(ctx, vel, p))));
    assert_true(same(ctx, r.K_new, qd_add(ctx, qd_div(ctx, qd_powi(ctx, P, 2), qd_mul(ctx, two, m)),
                                          qd_mul(ctx, vel, P))));
    qd_gen_result_free(&r);
    qd_ctx_free(ctx);
}

/* T33: F2 = q1^2 P1 + (q1 + q2) P2 gives Q1 = q1^2, Q2 = q1 + q2,
 * P1 = (p1 - p2)/(2 q1), P2 = p2, and H = ((p1 - p2)/(2 q1))^2 + p2 +
 * (q1 + q2)^2 becomes P1^2 + P2 + Q2^2 (q1 = sqrt(Q1) is not linear, so
 * K_new is left NULL and K is checked in the old variables). */
static void test_f2_point_transformation(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    vars x = mkvars(ctx, 2);
    const qd_expr *q1 = x.q[0], *q2 = x.q[1], *p1 = x.p[0], *p2 = x.p[1];
    const qd_expr *s = qd_add(ctx, q1, q2);
    const qd_expr *F = qd_add(ctx, qd_mul(ctx, qd_powi(ctx, q1, 2), x.P[0]), qd_mul(ctx, s, x.P[1]));
    const qd_expr *P1 = qd_div(ctx, qd_sub(ctx, p1, p2), qd_mul(ctx, qd_int(ctx, 2), q1));
    const qd_expr *H = qd_add(ctx, qd_add(ctx, qd_powi(ctx, P1, 2), p2), qd_powi(ctx, s, 2));
    qd_gen_result r;
    assert_int_equal(qd_generate_f2(ctx, 2, x.q, x.p, x.Q, x.P, F, x.t, H, &r), QD_OK);
    assert_ptr_equal(r.Q[0], qd_powi(ctx, q1, 2));
    assert_ptr_equal(r.Q[1], qd_simplify(ctx, s));
    assert_true(same(ctx, r.P[0], P1));
    assert_ptr_equal(r.P[1], p2);
    assert_int_equal(check(ctx, 2, x.q, x.p, r.Q, r.P).kind, QD_CANON_YES);
    const qd_expr *K = qd_add(ctx, qd_add(ctx, qd_powi(ctx, r.P[0], 2), r.P[1]), qd_powi(ctx, r.Q[1], 2));
    assert_true(same(ctx, r.K_old, K));
    /* q1 = sqrt(Q1) (the positive root) is isolated: K = P1^2 + P2 + Q2^2 */
    assert_non_null(r.K_new);
    const qd_expr *Knew = qd_add(ctx, qd_add(ctx, qd_powi(ctx, x.P[0], 2), x.P[1]),
                                 qd_powi(ctx, x.Q[1], 2));
    assert_true(same(ctx, r.K_new, Knew));
    assert_int_equal(qd_ctx_status(ctx), QD_OK);
    qd_gen_result_free(&r);
    qd_ctx_free(ctx);
}

/* F2 = q^2 has no P: the map is not defined (singular mixed Hessian).
 * F2 = q (P + e^P) gives p = P + e^P, which has no closed-form inverse
 * (Lambert's W): a named error, not a wrong answer. */
static void test_f2_degenerate(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    vars x = mkvars(ctx, 1);
    qd_gen_result r;
    assert_int_equal(qd_generate_f2(ctx, 1, x.q, x.p, x.Q, x.P, qd_powi(ctx, x.q[0], 2), x.t, NULL, &r),
                     QD_ERR_SINGULAR);
    assert_null(r.Q);
    qd_ctx_clear_error(ctx);
    const qd_expr *F = qd_mul(ctx, x.q[0], qd_add(ctx, x.P[0], qd_fn(ctx, QD_EXP, x.P[0])));
    assert_int_equal(qd_generate_f2(ctx, 1, x.q, x.p, x.Q, x.P, F, x.t, NULL, &r), QD_ERR_NONLINEAR);
    assert_null(r.Q);
    assert_string_equal(qd_ctx_message(ctx),
                        "cannot solve p = dF/dq for P in closed form: qdot isolates a new "
                        "variable that occurs once (through sums, products, powers, sin, cos, "
                        "tan, exp, log and their inverses), sin and cos of it as a ratio, or one "
                        "subexpression of it repeated");
    qd_ctx_free(ctx);
}

/* |a - b| small at random points of the symbols (q, p positive). */
static void assert_close_at(qd_ctx *ctx, const qd_expr *a, const qd_expr *b) {
    const qd_expr *syms[16];
    double vals[16], va, vb;
    size_t ns = qd_free_symbols(ctx, a, syms, 8);
    assert_true(ns <= 8);
    ns += qd_free_symbols(ctx, b, syms + ns, 8);
    assert_true(ns <= 16);
    for (int k = 0; k < 5; k++) {
        for (size_t i = 0; i < ns; i++) /* by symbol, so that a repeated one agrees */
            vals[i] = 0.4 + 0.3 * (double)((qd_expr_hash(syms[i]) + 7u * (unsigned)k) % 5u);
        assert_int_equal(qd_eval(ctx, a, ns, syms, vals, &va), QD_OK);
        assert_int_equal(qd_eval(ctx, b, ns, syms, vals, &vb), QD_OK);
        assert_true(fabs(va - vb) <= 1e-12 * (1 + fabs(va)));
    }
}

/* The harmonic oscillator's F1 = (m w q^2/2) cot Q (Goldstein ch. 9, the
 * harmonic oscillator; Desloge ch. 76 P7, seed-desloge-C.md T39): Q enters
 * p = m w q cot Q nonlinearly.  Q = atan(m w q/p), P = (p^2 + m^2 w^2 q^2)
 * / (2 m w) = E/w, canonical, and H = p^2/2m + m w^2 q^2/2 becomes K = w P.
 * cot is written cos/sin, and 1/tan. */
static void test_f1_oscillator(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    vars x = mkvars(ctx, 1);
    const qd_expr *q = x.q[0], *p = x.p[0], *Q = x.Q[0], *P = x.P[0];
    const qd_expr *m = qd_param(ctx, "m"), *w = qd_param(ctx, "w"), *two = qd_int(ctx, 2);
    const qd_expr *mw = qd_mul(ctx, m, w);
    const qd_expr *H = qd_add(ctx, qd_div(ctx, qd_powi(ctx, p, 2), qd_mul(ctx, two, m)),
                              qd_mul(ctx, qd_div(ctx, qd_mul(ctx, m, qd_powi(ctx, w, 2)), two),
                                     qd_powi(ctx, q, 2)));
    const qd_expr *half = qd_div(ctx, qd_mul(ctx, mw, qd_powi(ctx, q, 2)), two);
    const qd_expr *cot[2] = {qd_div(ctx, qd_fn(ctx, QD_COS, Q), qd_fn(ctx, QD_SIN, Q)),
                             qd_powi(ctx, qd_fn(ctx, QD_TAN, Q), -1)};
    for (int k = 0; k < 2; k++) {
        qd_gen_result r;
        const qd_expr *F = qd_mul(ctx, half, cot[k]);
        if (qd_generate(ctx, QD_GEN_F1, 1, x.q, x.p, x.Q, x.P, F, x.t, H, &r) != QD_OK)
            fail_msg("F1 oscillator %d: %s", k, qd_ctx_message(ctx));
        assert_close_at(ctx, qd_fn(ctx, QD_TAN, r.Q[0]), qd_div(ctx, qd_mul(ctx, mw, q), p));
        const qd_expr *E = qd_div(ctx, qd_add(ctx, qd_powi(ctx, p, 2),
                                              qd_mul(ctx, qd_powi(ctx, mw, 2), qd_powi(ctx, q, 2))),
                                  qd_mul(ctx, two, mw));
        assert_true(same(ctx, r.P[0], E));
        assert_int_equal(check(ctx, 1, x.q, x.p, r.Q, r.P).kind, QD_CANON_YES);
        assert_true(same(ctx, r.K_old, H));
        assert_non_null(r.K_new);
        assert_true(same(ctx, r.K_new, qd_mul(ctx, w, P)));
        assert_false(qd_has(r.K_new, Q)); /* Q cyclic: P = E/w conserved */
        qd_gen_result_free(&r);
    }
    qd_ctx_free(ctx);
}

/* F3 = -(e^p - 1) tan Q: q = -dF3/dp = e^p tan Q, so Q = atan(q e^-p), and
 * P = -dF3/dQ = (e^p - 1)/cos^2 Q = (e^p - 1)(1 + q^2 e^-2p); canonical.
 * Back: e^p = 1 + P cos^2 Q, q = (1 + P cos^2 Q) tan Q. */
static void test_f3_exp_tan(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    vars x = mkvars(ctx, 1);
    const qd_expr *q = x.q[0], *p = x.p[0], *Q = x.Q[0], *P = x.P[0], *one = qd_int(ctx, 1);
    const qd_expr *ep = qd_fn(ctx, QD_EXP, p);
    const qd_expr *F = qd_neg(ctx, qd_mul(ctx, qd_sub(ctx, ep, one), qd_fn(ctx, QD_TAN, Q)));
    const qd_expr *H = qd_div(ctx, qd_add(ctx, qd_powi(ctx, p, 2), qd_powi(ctx, q, 2)), qd_int(ctx, 2));
    qd_gen_result r;
    if (qd_generate(ctx, QD_GEN_F3, 1, x.q, x.p, x.Q, x.P, F, x.t, H, &r) != QD_OK)
        fail_msg("F3: %s", qd_ctx_message(ctx));
    assert_close_at(ctx, qd_fn(ctx, QD_TAN, r.Q[0]), qd_div(ctx, q, ep));
    assert_close_at(ctx, r.P[0], qd_mul(ctx, qd_sub(ctx, ep, one),
                                        qd_add(ctx, one, qd_div(ctx, qd_powi(ctx, q, 2),
                                                                qd_powi(ctx, ep, 2)))));
    assert_int_equal(check(ctx, 1, x.q, x.p, r.Q, r.P).kind, QD_CANON_YES);
    /* K(Q, P) = H(q(Q, P), p(Q, P)) */
    const qd_expr *e = qd_add(ctx, one, qd_mul(ctx, P, qd_powi(ctx, qd_fn(ctx, QD_COS, Q), 2)));
    const qd_expr *qb = qd_mul(ctx, e, qd_fn(ctx, QD_TAN, Q)), *pb = qd_fn(ctx, QD_LOG, e);
    assert_non_null(r.K_new);
    assert_close_at(ctx, r.K_new, qd_div(ctx, qd_add(ctx, qd_powi(ctx, pb, 2), qd_powi(ctx, qb, 2)),
                                         qd_int(ctx, 2)));
    qd_gen_result_free(&r);
    qd_ctx_free(ctx);
}

/* Two oscillators at once, F1 = sum q_i^2 cot(Q_i)/2: each relation has
 * its own unknown; canonical, K = P1 + P2 for H = sum (p_i^2 + q_i^2)/2. */
static void test_f1_two_oscillators(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    vars x = mkvars(ctx, 2);
    const qd_expr *F = qd_int(ctx, 0), *H = qd_int(ctx, 0), *h = qd_rat(ctx, 1, 2);
    for (int i = 0; i < 2; i++) {
        const qd_expr *cot = qd_div(ctx, qd_fn(ctx, QD_COS, x.Q[i]), qd_fn(ctx, QD_SIN, x.Q[i]));
        F = qd_add(ctx, F, qd_mul(ctx, qd_mul(ctx, h, qd_powi(ctx, x.q[i], 2)), cot));
        H = qd_add(ctx, H, qd_mul(ctx, h, qd_add(ctx, qd_powi(ctx, x.p[i], 2), qd_powi(ctx, x.q[i], 2))));
    }
    qd_gen_result r;
    if (qd_generate(ctx, QD_GEN_F1, 2, x.q, x.p, x.Q, x.P, F, x.t, H, &r) != QD_OK)
        fail_msg("two oscillators: %s", qd_ctx_message(ctx));
    assert_int_equal(check(ctx, 2, x.q, x.p, r.Q, r.P).kind, QD_CANON_YES);
    assert_true(same(ctx, r.K_new, qd_add(ctx, x.P[0], x.P[1])));
    qd_gen_result_free(&r);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_power_trig),
        cmocka_unit_test(test_linear_1d),
        cmocka_unit_test(test_linear_2d),
        cmocka_unit_test(test_desloge_and_failures),
        cmocka_unit_test(test_generators_1d),
        cmocka_unit_test(test_f2_examples),
        cmocka_unit_test(test_f2_point_transformation),
        cmocka_unit_test(test_f2_degenerate),
        cmocka_unit_test(test_f1_oscillator),
        cmocka_unit_test(test_f3_exp_tan),
        cmocka_unit_test(test_f1_two_oscillators),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
