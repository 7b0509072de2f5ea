/*
 * tests/lyap/test_threads.c - one qd_lyap run by two threads at once
 * (qdot/lyapunov.h, thread safety): each thread with its own context
 * computes the Hénon-Heiles spectrum of two orbits and, for a third, the
 * largest exponent with other parameters given per run; every result
 * must equal, bit for bit, the same run made alone.  make test-tsan
 * builds this program under ThreadSanitizer, which fails on any
 * unsynchronised access to shared state.
 */
#include <pthread.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "lyap_fixture.h"

#define NRUNS 3

/* Hénon-Heiles with the strengths of its cubic terms as parameters (1, 1:
 * the original), so that a run may change them through opts.par */
static const char hh_par[] = "coordinates x, y\nparameters c = 1, d = 1\n"
                             "T = (x'^2 + y'^2)/2\n"
                             "V = (x^2 + y^2)/2 + c*x^2*y - d*y^3/3\n";

typedef struct job {
    const qd_lyap *l;
    double out[NRUNS][4];
    qd_status st;
} job;

static qd_status run_one(qd_ctx *ctx, const qd_lyap *l, int i, double *ex) {
    static const double ys[NRUNS] = {-0.25, 0.55, -0.25};
    static const double par[2] = {1.1, 0.9};
    double q[2], qd[2];
    lf_hh_state(0.125, 0, ys[i], 0, q, qd);
    qd_sim_opts o = lf_opts(q, qd, 300);
    o.par = i == 2 ? par : NULL;
    qd_lyap_opts lo = {.nexp = i == 2 ? 1 : 4, .renorm = 0.5, .transient = 10};
    return qd_lyap_run(ctx, l, &o, &lo, ex, NULL);
}

static void *run_all(void *arg) {
    job *j = arg;
    qd_ctx *ctx = qd_ctx_new();
    j->st = ctx ? QD_OK : QD_ERR_NOMEM;
    for (int i = 0; i < NRUNS && j->st == QD_OK; i++)
        j->st = run_one(ctx, j->l, i, j->out[i]);
    qd_ctx_free(ctx);
    return NULL;
}

static void test_two_threads(void **state) {
    (void)state;
    lyap_fix *f = lf_load(hh_par);
    assert_non_null(f->l);
    job alone = {.l = f->l}, a = {.l = f->l}, b = {.l = f->l};
    run_all(&alone);
    assert_int_equal(alone.st, QD_OK);
    pthread_t ta, tb;
    assert_int_equal(pthread_create(&ta, NULL, run_all, &a), 0);
    assert_int_equal(pthread_create(&tb, NULL, run_all, &b), 0);
    pthread_join(ta, NULL);
    pthread_join(tb, NULL);
    assert_int_equal(a.st, QD_OK);
    assert_int_equal(b.st, QD_OK);
    assert_memory_equal(a.out, alone.out, sizeof alone.out);
    assert_memory_equal(b.out, alone.out, sizeof alone.out);
    /* the per-run parameters were used: another orbit, another exponent */
    assert_true(alone.out[2][0] != alone.out[0][0]);
    lf_free(f);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_two_threads)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
