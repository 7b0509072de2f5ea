/*
 * tests/sim/test_taylor_native.c - the taylor method's recurrences as
 * generated C (src/sym/taylor_emit.c, qd_sim_load_native_taylor): every
 * operation's coefficients equal to the interpreter's to the bit, a run
 * with them equal to the interpreted run row for row, and the object found
 * in the cache the second time.  Skipped when no C compiler runs.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "sim_fixture.h"
#include "qdot/read.h"
#include "codegen/cg.h"
#include "sym/sym_export.h"

#include <dirent.h>
#include <dlfcn.h>
#include <stdlib.h>
#include <unistd.h>

#define ORDER 24

static char cache[64];

static int make_cache(void **state) {
    (void)state;
    strcpy(cache, "/tmp/qdot-tnat-XXXXXX");
    return mkdtemp(cache) ? 0 : -1;
}

static int drop_cache(void **state) {
    (void)state;
    DIR *d = opendir(cache);
    for (struct dirent *e; d && (e = readdir(d));) {
        char path[512];
        snprintf(path, sizeof path, "%s/%s", cache, e->d_name);
        if (e->d_name[0] != '.')
            unlink(path);
    }
    if (d)
        closedir(d);
    return rmdir(cache);
}

/* x varies, a is a parameter (flat): between them every operation with a
 * recurrence, the flat-operand forms (x*a, x/a, a^x) included. */
static const char *const OPS[] = {
    "sqrt(x)", "x^2.5", "x^a", "a^x", "x^x", "tan(x)", "tanh(x)", "asin(x/3)",
    "acos(x/3)", "atan(x)", "atan2(x, 1 + x^2)", "exp(x)", "log(x)", "sinh(x)*cosh(x)",
    "sin(x)/cos(x)", "1/(1 + x)", "abs(sin(x) - 5)", "exp(x)/a", "a*log(x) - x", "-exp(x) - sin(x)",
};
#define NOPS (sizeof OPS / sizeof *OPS)

/* The helpers the emitted text must call: the program reaches them all. */
static const char *const FNS[] = {
    "t_add", "t_sub", "t_mul", "t_div", "t_neg", "t_recip", "t_sqrt", "t_powc",
    "t_sincos", "t_sinhcosh", "t_tan", "t_tanh", "t_asin", "t_acos", "t_atan",
    "t_atan2", "t_exp", "t_log", "t_abs", "t_mulc", "t_divc",
};

static qd__tay *every_op(qd_ctx *ctx, qd_prog **p) {
    qd_read_opts ro = {.new_symbols = true};
    const qd_expr *e[NOPS], *in[2] = {qd_symbol(ctx, "x"), qd_symbol(ctx, "a")};
    for (size_t i = 0; i < NOPS; i++)
        assert_non_null(e[i] = qd_read(ctx, OPS[i], &ro, NULL));
    assert_non_null(*p = qd_prog_new(ctx, 2, in, NOPS, e));
    const qd_prog *ps[1] = {*p};
    bool var[2] = {true, false};
    qd__tay *tp = qd__tay_new(ctx, 1, ps, var, ORDER, QD__TAY_DOUBLE);
    assert_non_null(tp);
    double *x = qd__tay_in(tp, 0), *a = qd__tay_in(tp, 1);
    x[0] = 0.6;
    x[1] = 1;
    a[0] = 1.7;
    for (size_t k = 0; k <= ORDER; k++)
        qd__tay_run(tp, k);
    return tp;
}

static void test_every_operation(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_prog *p1;
    qd__tay *ti = every_op(ctx, &p1);
    qd_buf text = QD_BUF_INIT;
    assert_int_equal(qd__tay_emit_c(ti, &text), QD_OK);
    for (size_t i = 0; i < sizeof FNS / sizeof *FNS; i++) {
        char call[32];
        snprintf(call, sizeof call, "I(%s,", FNS[i]);
        if (!strstr(qd_buf_str(&text), call))
            fail_msg("the program does not reach %s", FNS[i]);
    }
    char path[4096];
    bool cached;
    void *h;
    if (qd__cg_native_object(ctx, qd_buf_str(&text), "test", cache, path, &cached, &h) ==
        QD_ERR_UNSUPPORTED) {
        qd_buf_free(&text);
        skip(); /* no C compiler here */
    }
    assert_non_null(h);
    void *sym = dlsym(h, "qdt_orderk");
    assert_non_null(sym);
    qd__tay_native fn;
    memcpy(&fn, &sym, sizeof sym);
    /* a second workspace of the same program, its orders >= 1 native */
    const qd_prog *ps[1] = {p1};
    bool var[2] = {true, false};
    qd__tay *tn = qd__tay_new(ctx, 1, ps, var, ORDER, QD__TAY_DOUBLE);
    assert_non_null(tn);
    qd__tay_set_native(tn, fn);
    double *x = qd__tay_in(tn, 0), *a = qd__tay_in(tn, 1);
    x[0] = 0.6;
    x[1] = 1;
    a[0] = 1.7;
    for (size_t k = 0; k <= ORDER; k++)
        qd__tay_run(tn, k);
    for (size_t j = 0; j < NOPS; j++) {
        const double *ci = qd__tay_out(ti, j), *cn = qd__tay_out(tn, j);
        for (size_t k = 0; k <= ORDER; k++)
            if (memcmp(&ci[k], &cn[k], sizeof ci[k]) != 0)
                fail_msg("%s: coefficient %zu is %.17g native, %.17g interpreted", OPS[j], k,
                         cn[k], ci[k]);
        /* a live series, not a flat one compared with itself */
        if (!(ci[ORDER] != 0))
            fail_msg("%s: coefficient %d is 0", OPS[j], ORDER);
    }
    dlclose(h);
    qd__tay_free(ti);
    qd__tay_free(tn);
    qd_prog_free(p1);
    qd_buf_free(&text);
    qd_ctx_free(ctx);
}

/* The double pendulum from (pi/2, pi/2) (bench/run_taylor.py's). */
static const char dpend[] =
    "coordinates th1, th2\nparameters m1 = 1, m2 = 1, l1 = 1, l2 = 1, g = 9.81\n"
    "T = (m1 + m2)/2*l1^2*th1'^2 + m2/2*l2^2*th2'^2 + m2*l1*l2*th1'*th2'*cos(th1 - th2)\n"
    "V = -(m1 + m2)*g*l1*cos(th1) - m2*g*l2*cos(th2)\n"
    "initial th1 = 1.5707963267948966, th2 = 1.5707963267948966\n";

static int rows_n;
static double rows[2][4096][8];

static int keep_row(void *data, int event, const double *row) {
    int *which = data;
    if (event < 0 && rows_n < 4096)
        memcpy(rows[*which][rows_n++], row, 5 * sizeof *row);
    return 0;
}

/* Every step's row, interpreted (which 0) or native (1). */
static int run_rows(sim_fix *f, int which, qd_sim_stats *st) {
    qd_sim_opts o = {.method = QD_SIM_TAYLOR, .t_end = 20, .rtol = 1e-15, .atol = 1e-15,
                     .q0 = f->q0, .qd0 = f->qd0};
    rows_n = 0;
    assert_int_equal(qd_sim_run(f->s, &o, keep_row, &which, st, NULL), QD_OK);
    return rows_n;
}

static void test_run_identical(void **state) {
    (void)state;
    sim_fix *fi = sf_load(dpend), *fn = sf_load(dpend), *again = sf_load(dpend);
    assert_true(fi && fn && again);
    bool cached = true;
    qd_status st = qd_sim_load_native_taylor(fn->s, cache, &cached);
    if (st == QD_ERR_UNSUPPORTED) {
        sf_free(fi);
        sf_free(fn);
        sf_free(again);
        skip();
    }
    assert_int_equal(st, QD_OK);
    assert_false(cached); /* test_every_operation's object is another text */
    qd_sim_stats si, sn;
    int ni = run_rows(fi, 0, &si), nn = run_rows(fn, 1, &sn);
    assert_int_equal(ni, nn);
    assert_true(ni > 100 && ni < 4096);
    assert_memory_equal(rows[0], rows[1], (size_t)ni * sizeof rows[0][0]);
    /* and the run is right: the energy kept to round-off over 20 s of chaos */
    if (!(sn.energy_error_max < 1e-13))
        fail_msg("energy error %.3g", sn.energy_error_max);
    /* another qd_sim of the same model finds the object */
    assert_int_equal(qd_sim_load_native_taylor(again->s, cache, &cached), QD_OK);
    assert_true(cached);
    sf_free(fi);
    sf_free(fn);
    sf_free(again);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_operation),
        cmocka_unit_test(test_run_identical),
    };
    return cmocka_run_group_tests(tests, make_cache, drop_cache);
}
