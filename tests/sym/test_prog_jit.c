/*
 * tests/sym/test_prog_jit.c - the JIT (qd_prog_jit, modules/llvm.c) gives
 * the interpreter's numbers bit for bit: every operation the program
 * knows (the opcodes of src/sym/prog_int.h, sums and products of every
 * length, signs of zero, NaN and infinities), random programs over shared
 * subexpressions, and a program evaluated from several threads at once;
 * the mass matrix's program jitted with its Cholesky solve
 * (qd__prog_jit_spd) gives qd__num_solve_spd's solution bit for bit and
 * fails exactly where solve_mass would go on to its own decision.
 * Without the module (a build without LLVM) the test is a skip (77).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/qdot.h"
#include "num/num.h"
#include "sym/sym_export.h"
#include "util/randexpr.h"

#define SEED 20261204u

/* An interpreted twin of p (the same expressions compiled again) beside
 * the jitted p: their outputs compared bit for bit at each point. */
static void compare(qd_ctx *ctx, size_t nin, const qd_expr *const *in, size_t nout,
                    const qd_expr *const *out, size_t npts, const double *pts, const char *what) {
    qd_prog *interp = qd_prog_new(ctx, nin, in, nout, out), *jit = qd_prog_new(ctx, nin, in,
                                                                               nout, out);
    assert_non_null(interp);
    assert_non_null(jit);
    assert_int_equal(qd_prog_jit(ctx, jit), QD_OK);
    assert_true(qd_prog_jitted(jit) && !qd_prog_jitted(interp));
    double *a = malloc(nout * sizeof *a), *b = malloc(nout * sizeof *b);
    for (size_t t = 0; t < npts; t++) {
        qd_prog_run(interp, pts + t * nin, a);
        qd_prog_run(jit, pts + t * nin, b);
        for (size_t k = 0; k < nout; k++)
            if (memcmp(&a[k], &b[k], sizeof a[k]) != 0)
                fail_msg("%s: output %zu at point %zu: interpreted %a, jit %a", what, k, t, a[k],
                         b[k]);
    }
    free(a);
    free(b);
    qd_prog_free(interp);
    qd_prog_free(jit);
}

/* Every function, powers of every kind, sums and products long and short,
 * with points at 0, -0, NaN, infinities and outside the real domains. */
static void test_operations(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *x = qd_symbol(ctx, "x"), *y = qd_symbol(ctx, "y");
    const qd_expr *in[2] = {x, y}, *out[96];
    size_t n = 0;
    for (int f = 0; f < QD_FUNC_COUNT; f++)
        if (f != QD_ATAN2)
            out[n++] = qd_fn(ctx, (qd_func)f, x);
    out[n++] = qd_fn2(ctx, QD_ATAN2, y, x);
    static const long pw[][2] = {{2, 1}, {3, 1}, {-1, 1}, {-2, 1}, {-3, 1}, {7, 1}, {-8, 1},
                                 {1, 2}, {-1, 2}, {3, 2}, {-5, 2}, {1, 3}, {-2, 7}, {64, 1},
                                 {65, 1}, {-65, 1}};
    for (size_t i = 0; i < sizeof pw / sizeof pw[0]; i++)
        out[n++] = qd_pow(ctx, x, qd_rat(ctx, pw[i][0], pw[i][1]));
    out[n++] = qd_pow(ctx, x, y);
    out[n++] = qd_pow(ctx, y, qd_float(ctx, 0.37));
    out[n++] = qd_neg(ctx, qd_add(ctx, x, y));
    out[n++] = qd_sub(ctx, qd_mul(ctx, qd_int(ctx, -3), x), qd_div(ctx, y, x));
    out[n++] = qd_div(ctx, qd_int(ctx, 5), qd_mul(ctx, qd_powi(ctx, x, 2), qd_sqrt(ctx, y)));
    /* sums and products of 2 to 9 terms, some subtracted, some divided */
    const qd_expr *terms[9];
    for (int k = 0; k < 9; k++)
        terms[k] = qd_fn(ctx, k % 2 ? QD_SIN : QD_COS, qd_mul(ctx, qd_int(ctx, k + 1), y));
    for (int len = 2; len <= 9; len++) {
        const qd_expr *s = terms[0], *m = terms[0];
        for (int k = 1; k < len; k++) {
            s = k % 3 ? qd_add(ctx, s, terms[k]) : qd_sub(ctx, s, terms[k]);
            m = k % 3 ? qd_mul(ctx, m, terms[k]) : qd_div(ctx, m, terms[k]);
        }
        out[n++] = s;
        out[n++] = m;
        out[n++] = qd_neg(ctx, s);
    }
    out[n++] = x;
    out[n++] = qd_rat(ctx, 3, 4);
    out[n++] = qd_const(ctx, QD_PI);
    assert_true(n <= 96);
    for (size_t k = 0; k < n; k++)
        assert_non_null(out[k]);
    const double pts[][2] = {{0.7, 0.4},       {1.3, -0.6},   {0.25, 2.5},    {0.0, -0.0},
                             {-0.0, 0.0},      {-1.5, 3.0},   {NAN, 1.0},     {1.0, NAN},
                             {INFINITY, -2.0}, {-INFINITY, 2}, {1e-310, 1e300}, {-7.25, -1e-3}};
    compare(ctx, 2, in, n, out, sizeof pts / sizeof pts[0], &pts[0][0], "operations");
    qd_ctx_free(ctx);
}

/* Random expressions over shared subexpressions (test_prog.c's generator). */
static void test_random(void **state) {
    (void)state;
    qt_rng rng = {SEED};
    for (unsigned round = 0; round < 40; round++) {
        qd_ctx *ctx = qd_ctx_new();
        const qd_expr *s[4] = {qd_symbol(ctx, "x"), qd_symbol(ctx, "y"), qd_symbol(ctx, "z"),
                               qd_symbol(ctx, "w")};
        const qd_expr *out[12];
        for (int k = 0; k < 10; k++)
            out[k] = qt_random_expr(ctx, &rng, s, 4, 5, QT_ALL);
        out[10] = qd_add(ctx, out[0], qd_mul(ctx, out[1], out[2]));
        out[11] = qd_sub(ctx, out[3], qd_powi(ctx, out[0], 2));
        double pts[5 * 4];
        for (int i = 0; i < 20; i++)
            pts[i] = qt_uniform(&rng, -2, 2);
        char what[32];
        snprintf(what, sizeof what, "round %u", round);
        compare(ctx, 4, s, 12, out, 5, pts, what);
        qd_ctx_free(ctx);
    }
}

/* One jitted program run by four threads at once, each with its own
 * workspace: each gets the interpreter's numbers (the code is pure). */
typedef struct job {
    const qd_prog *p;
    double x, want[3], got[3];
} job;

static void *run_job(void *arg) {
    job *j = arg;
    double *w = malloc(qd_prog_work_size(j->p) * sizeof *w), in[2] = {j->x, 1 - j->x};
    qd_prog_work_init(j->p, w);
    for (int r = 0; r < 2000; r++)
        qd_prog_eval(j->p, w, in, j->got);
    free(w);
    return NULL;
}

static void test_threads(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *x = qd_symbol(ctx, "x"), *y = qd_symbol(ctx, "y"), *in[2] = {x, y};
    const qd_expr *out[3] = {qd_mul(ctx, qd_fn(ctx, QD_SIN, x), qd_fn(ctx, QD_COS, y)),
                             qd_add(ctx, qd_powi(ctx, x, 3), qd_fn(ctx, QD_EXP, y)),
                             qd_div(ctx, x, qd_add(ctx, qd_int(ctx, 2), y))};
    qd_prog *interp = qd_prog_new(ctx, 2, in, 3, out), *p = qd_prog_new(ctx, 2, in, 3, out);
    assert_int_equal(qd_prog_jit(ctx, p), QD_OK);
    job jobs[4];
    pthread_t tid[4];
    for (int k = 0; k < 4; k++) {
        jobs[k] = (job){.p = p, .x = 0.1 + 0.2 * k};
        double v[2] = {jobs[k].x, 1 - jobs[k].x};
        qd_prog_run(interp, v, jobs[k].want);
        assert_int_equal(pthread_create(&tid[k], NULL, run_job, &jobs[k]), 0);
    }
    for (int k = 0; k < 4; k++) {
        pthread_join(tid[k], NULL);
        assert_memory_equal(jobs[k].want, jobs[k].got, sizeof jobs[k].want);
    }
    qd_prog_free(interp);
    qd_prog_free(p);
    qd_ctx_free(ctx);
}

/* The interpreter's path of src/sim/system.c's solve_mass up to the LU:
 * every entry of M finite, then qd__num_solve_spd on copies. */
static bool c_solve(size_t n, const double *M, const double *f, double *x) {
    for (size_t k = 0; k < n * n; k++)
        if (!isfinite(M[k]))
            return false;
    double A[64];
    memcpy(A, M, n * n * sizeof *A);
    memcpy(x, f, n * sizeof *x);
    return qd__num_solve_spd(n, A, x, 1e-10);
}

/* M = B B^T + shift I (row-major), f random: SPD for shift > 0 and
 * indefinite for a shift below minus B's smallest singular value squared. */
static void system_at(qt_rng *rng, size_t n, double shift, double *M, double *f) {
    double B[64];
    for (size_t k = 0; k < n * n; k++)
        B[k] = qt_uniform(rng, -1, 1);
    for (size_t i = 0; i < n; i++) {
        f[i] = qt_uniform(rng, -3, 3);
        for (size_t j = 0; j < n; j++) {
            double s = i == j ? shift : 0;
            for (size_t k = 0; k < n; k++)
                s += B[i * n + k] * B[j * n + k];
            M[i * n + j] = s;
        }
    }
}

/* The fused program of an n-by-n system whose outputs are its inputs (M,
 * then f; the extra output 2*f[0] after them, as acc has none but may),
 * against c_solve on SPD, indefinite, nearly singular, zero, huge and
 * non-finite matrices: the same flag, and where it is set the same x. */
static void test_spd_solve(void **state) {
    (void)state;
    qt_rng rng = {SEED + 7};
    for (size_t n = 1; n <= 7; n++) {
        qd_ctx *ctx = qd_ctx_new();
        size_t nin = n * n + n;
        const qd_expr *in[56], *out[57];
        for (size_t k = 0; k < nin; k++) {
            char name[24]; /* "v" and any size_t */
            snprintf(name, sizeof name, "v%zu", k);
            out[k] = in[k] = qd_symbol(ctx, name);
        }
        out[nin] = qd_mul(ctx, qd_int(ctx, 2), in[n * n]);
        qd_prog *p = qd_prog_new(ctx, nin, in, nin + 1, out);
        assert_non_null(p);
        assert_int_equal(qd__prog_jit_spd(ctx, p, n + 1, 1e-10), QD_ERR_ARG); /* too few outputs */
        qd_ctx_clear_error(ctx);
        assert_int_equal(qd__prog_jit_spd(ctx, p, n, 1e-10), QD_OK);
        qd__jit_spd_fn fn = qd__prog_spd(p);
        assert_non_null(fn);
        int agreed_ok = 0, agreed_fail = 0;
        for (int trial = 0; trial < 200; trial++) {
            double v[56], o[57], x[8], xc[8];
            int kind = trial % 10;
            double shift = kind == 1 ? -(double)n : kind == 2 ? 0 : 0.05 + (double)(trial % 3);
            system_at(&rng, n, shift, v, v + n * n);
            if (kind == 2 && n > 1) /* rank one short: a pivot at round-off */
                for (size_t j = 0; j < n; j++)
                    v[(n - 1) * n + j] = v[j * n + n - 1] = v[j];
            if (kind == 3)
                memset(v, 0, n * n * sizeof *v);
            if (kind == 4)
                v[(size_t)trial % (n * n)] = trial % 20 < 10 ? NAN : -INFINITY;
            if (kind == 5)
                for (size_t k = 0; k < n * n; k++)
                    v[k] *= 1e300;
            if (kind == 6)
                v[n * n] = NAN; /* f alone not finite: solved, NaN through */
            if (kind == 7)
                for (size_t k = 0; k < n * n; k++)
                    v[k] *= 1e-300;
            memset(x, 0, sizeof x);
            int ok = fn(v, o, x);
            bool okc = c_solve(n, v, v + n * n, xc);
            assert_int_equal(ok, okc);
            for (size_t k = 0; k < nin; k++)
                assert_memory_equal(&o[k], &v[k], sizeof o[k]);
            double twice = 2 * v[n * n];
            assert_memory_equal(&o[nin], &twice, sizeof twice);
            if (ok) {
                for (size_t k = 0; k < n; k++)
                    if (memcmp(&x[k], &xc[k], sizeof x[k]) != 0)
                        fail_msg("n = %zu, trial %d: x[%zu] jitted %a, C %a", n, trial, k, x[k],
                                 xc[k]);
                agreed_ok++;
            } else {
                agreed_fail++;
            }
        }
        /* both outcomes were exercised at every size */
        assert_true(agreed_ok > 50 && agreed_fail > 20);
        qd_prog_free(p);
        qd_ctx_free(ctx);
    }
}

int main(void) {
    /* no module in this build (no LLVM): a skip, with the library's reason */
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *x = qd_symbol(ctx, "x");
    qd_prog *p = qd_prog_new(ctx, 1, &x, 1, &x);
    qd_status st = qd_prog_jit(ctx, p);
    if (st != QD_OK)
        printf("skip: %s\n", qd_ctx_message(ctx));
    qd_prog_free(p);
    qd_ctx_free(ctx);
    if (st != QD_OK)
        return 77;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_operations),
        cmocka_unit_test(test_random),
        cmocka_unit_test(test_threads),
        cmocka_unit_test(test_spd_solve),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
