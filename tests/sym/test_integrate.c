/*
 * tests/sym/test_integrate.c - qd_integrate: every antiderivative is checked
 * by differentiating it back (qd_diff of the result minus the integrand
 * simplifies to 0 or vanishes at random points), over generated integrands
 * of every form the table covers; and what it must refuse.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>

#include "qdot/qdot.h"
#include "util/randexpr.h"

#define SEED 4049u
#define NCASES 300
#define NPOINTS 6

typedef struct env {
    qd_ctx *ctx;
    const qd_expr *x, *y, *k;
} env;

static env make_env(void) {
    env v;
    v.ctx = qd_ctx_new();
    v.x = qd_symbol(v.ctx, "x");
    v.y = qd_coord(v.ctx, "y");
    v.k = qd_param(v.ctx, "k");
    return v;
}

/* e as text, in one of two alternating buffers (two per message). */
static const char *show(qd_ctx *ctx, const qd_expr *e) {
    static char out[2][512];
    static int k;
    qd_buf b = QD_BUF_INIT;
    qd_print(ctx, e, QD_FMT_TEXT, &b);
    k ^= 1;
    snprintf(out[k], sizeof out[k], "%s", qd_buf_str(&b));
    qd_buf_free(&b);
    return out[k];
}

/* d/dx of F equals f at NPOINTS points with x, y, k in [0.5, 2] (inside
 * every logarithm the generator makes), or F' - f simplifies to 0. */
static void assert_antiderivative(env *v, const qd_expr *f, const qd_expr *F, const char *what) {
    if (!F)
        fail_msg("%s: no antiderivative of %s (%s)", what, show(v->ctx, f),
                 qd_ctx_message(v->ctx));
    const qd_expr *d = qd_sub(v->ctx, qd_diff(v->ctx, F, v->x), f);
    if (qd_is_zero(qd_simplify(v->ctx, d)))
        return;
    qt_rng r = {SEED};
    const qd_expr *syms[3] = {v->x, v->y, v->k};
    for (int i = 0; i < NPOINTS; i++) {
        double vals[3] = {qt_uniform(&r, 0.5, 2), qt_uniform(&r, 0.5, 2), qt_uniform(&r, 0.5, 2)};
        double a, b;
        assert_int_equal(qd_eval(v->ctx, qd_diff(v->ctx, F, v->x), 3, syms, vals, &a), QD_OK);
        assert_int_equal(qd_eval(v->ctx, f, 3, syms, vals, &b), QD_OK);
        if (fabs(a - b) > 1e-9 * (1 + fabs(a) + fabs(b)))
            fail_msg("%s: d/dx %s = %.17g, but %s = %.17g", what, show(v->ctx, F), a,
                     show(v->ctx, f), b);
    }
}

/* A small positive rational: 1/2 .. 3. */
static const qd_expr *pos(env *v, qt_rng *r) {
    return qd_rat(v->ctx, 1 + (long)qt_below(r, 6), 2);
}

/* A coefficient free of x: a rational, k, y, or sin(y). */
static const qd_expr *constant(env *v, qt_rng *r) {
    qd_ctx *c = v->ctx;
    switch (qt_below(r, 4)) {
    case 0: return qd_rat(c, (long)qt_below(r, 9) - 4, 1 + (long)qt_below(r, 3));
    case 1: return v->k;
    case 2: return qd_mul(c, qd_int(c, 3), v->y);
    default: return qd_fn(c, QD_SIN, v->y);
    }
}

/* a x + b with a, b > 0 (b possibly k): its logarithm is defined. */
static const qd_expr *linear(env *v, qt_rng *r) {
    const qd_expr *b = qt_below(r, 3) ? pos(v, r) : v->k;
    return qd_add(v->ctx, qd_mul(v->ctx, pos(v, r), v->x), b);
}

/* One elementary factor of the table. */
static const qd_expr *elementary(env *v, qt_rng *r) {
    static const qd_func fs[5] = {QD_SIN, QD_COS, QD_EXP, QD_SINH, QD_COSH};
    qd_ctx *c = v->ctx;
    switch (qt_below(r, 5)) {
    case 0: return qd_powi(c, v->x, (long)qt_below(r, 9) - 4);
    case 1: return qd_powi(c, linear(v, r), (long)qt_below(r, 7) - 3);
    case 2: return qd_pow(c, linear(v, r), qd_rat(c, 2 * (long)qt_below(r, 3) - 3, 2));
    case 3: return qd_fn(c, fs[qt_below(r, 5)], linear(v, r));
    default: return qd_pow(c, qd_add(c, v->k, qd_int(c, 1)), linear(v, r));
    }
}

/* A sum of constant * elementary terms, sometimes times x + c (to expand):
 * then *hard, since x exp(x) or x/(x + 1) is outside the table. */
static const qd_expr *integrand(env *v, qt_rng *r, bool *hard) {
    qd_ctx *c = v->ctx;
    const qd_expr *f = qd_int(c, 0);
    unsigned n = 1 + qt_below(r, 3);
    for (unsigned i = 0; i < n; i++)
        f = qd_add(c, f, qd_mul(c, constant(v, r), elementary(v, r)));
    *hard = qt_below(r, 4) == 0;
    if (*hard)
        f = qd_mul(c, f, qd_add(c, v->x, constant(v, r)));
    if (qt_below(r, 4) == 0)
        f = qd_add(c, f, constant(v, r));
    return f;
}

static void test_generated(void **state) {
    (void)state;
    env v = make_env();
    qt_rng r = {SEED};
    int done = 0;
    for (int i = 0; i < NCASES; i++) {
        bool hard;
        const qd_expr *f = integrand(&v, &r, &hard);
        assert_non_null(f);
        const qd_expr *F = qd_integrate(v.ctx, f, v.x);
        if (!F && hard) {
            assert_int_equal(qd_ctx_status(v.ctx), QD_ERR_ARG);
            qd_ctx_clear_error(v.ctx);
            continue;
        }
        done++;
        char what[64];
        snprintf(what, sizeof what, "case %d (seed %u)", i, SEED);
        assert_antiderivative(&v, f, F, what);
    }
    if (done < NCASES * 3 / 4)
        fail_msg("only %d of %d integrated", done, NCASES);
    qd_ctx_free(v.ctx);
}

/* The table itself, written out. */
static void test_table(void **state) {
    (void)state;
    env v = make_env();
    qd_ctx *c = v.ctx;
    const qd_expr *x = v.x, *lin = qd_add(c, qd_mul(c, v.k, x), qd_int(c, 2));
    const qd_expr *fs[] = {
        qd_int(c, 3), v.y, x, qd_powi(c, x, 5), qd_powi(c, x, -1), qd_powi(c, x, -3),
        qd_sqrt(c, x), qd_powi(c, lin, -1), qd_powi(c, lin, 4), qd_powi(c, lin, -2),
        qd_fn(c, QD_SIN, x), qd_fn(c, QD_COS, lin), qd_fn(c, QD_EXP, lin),
        qd_fn(c, QD_SINH, lin), qd_fn(c, QD_COSH, x), qd_pow(c, qd_int(c, 2), x),
        qd_pow(c, qd_const(c, QD_E), qd_mul(c, qd_int(c, 3), x)), qd_powi(c, x, 0),
        qd_mul(c, v.y, qd_fn(c, QD_SIN, qd_mul(c, v.y, x))),
        qd_mul(c, x, qd_add(c, x, v.y)), qd_powi(c, qd_add(c, x, v.k), 2),
        /* by parts: u log(u) - u (a generating function's p log p, seed C T27) */
        qd_fn(c, QD_LOG, x), qd_mul(c, v.y, qd_fn(c, QD_LOG, lin)),
    };
    for (size_t i = 0; i < sizeof fs / sizeof fs[0]; i++) {
        char what[32];
        snprintf(what, sizeof what, "table entry %zu", i);
        assert_antiderivative(&v, fs[i], qd_integrate(c, fs[i], x), what);
    }
    /* Free of x: f x exactly; 1/x: log(x). */
    assert_ptr_equal(qd_integrate(c, v.y, x), qd_mul(c, v.y, x));
    assert_ptr_equal(qd_integrate(c, qd_powi(c, x, -1), x), qd_fn(c, QD_LOG, x));
    assert_int_equal(qd_ctx_status(c), QD_OK);
    qd_ctx_free(c);
}

/* Outside the table: NULL and QD_ERR_ARG, every time. */
static void test_refused(void **state) {
    (void)state;
    env v = make_env();
    qd_ctx *c = v.ctx;
    const qd_expr *x = v.x, *x2 = qd_powi(c, x, 2), *arg[1] = {x};
    const qd_expr *fs[] = {
        qd_fn(c, QD_EXP, x2),                                /* no elementary integral */
        qd_fn(c, QD_SIN, x2),
        qd_mul(c, x, qd_fn(c, QD_EXP, x)),                   /* needs parts */
        qd_powi(c, qd_add(c, x2, qd_int(c, 1)), -1),         /* atan: not in the table */
        qd_fn(c, QD_LOG, x2),                                /* log of a non-linear argument */
        qd_fn(c, QD_TAN, x),
        qd_ufunc(c, "f", 1, arg),
        qd_pow(c, x, v.k),                                   /* symbolic n may be -1 */
        qd_mul(c, qd_fn(c, QD_SIN, x), qd_fn(c, QD_COS, x)),
    };
    for (size_t i = 0; i < sizeof fs / sizeof fs[0]; i++) {
        assert_null(qd_integrate(c, fs[i], x));
        if (qd_ctx_status(c) != QD_ERR_ARG)
            fail_msg("entry %zu: status %d, not QD_ERR_ARG", i, (int)qd_ctx_status(c));
        qd_ctx_clear_error(c);
    }
    assert_null(qd_integrate(c, x, qd_add(c, x, v.y))); /* not a symbol */
    assert_int_equal(qd_ctx_status(c), QD_ERR_ARG);
    qd_ctx_free(c);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_table),
        cmocka_unit_test(test_generated),
        cmocka_unit_test(test_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
