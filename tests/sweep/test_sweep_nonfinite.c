/*
 * tests/sweep/test_sweep_nonfinite.c - a sweep's runs are the library's
 * runs (issue 30): a run that would give NaN rows fails with its reason,
 * and the thread count is bounded and reported as started.
 *
 *   - x'' = 1/(2 sqrt(x)) from x = 1 and x' = -5, -4.5: x reaches 0 (and
 *     sqrt of a negative number beyond) at t = 0.2028, 0.2260; dop853 once
 *     took the NaN error estimate there as 0 and reported "ok" with NaN
 *     final values; now each run fails (step size underflow) and its row
 *     keeps only the inputs;
 *   - more threads than QD_SWEEP_MAX_THREADS are refused; the pool is
 *     qd_sweep_threads(n, runs): n (0: the cores), at most the runs.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "qdot/sweep.h"
#include "sim/sim_fixture.h"

static const char root[] = "coordinates x\nT = x'^2/2\nV = -sqrt(x)\ninitial x = 1, x' = -5\n";

static void test_nan_run_fails(void **state) {
    (void)state;
    sim_fix *f = sf_load(root);
    assert_non_null(f);
    assert_int_equal(qd_sim_compile(f->s), QD_OK);
    qd_sweep *w = qd_sweep_new(f->ctx, f->s, f->m);
    assert_non_null(w);
    assert_int_equal(qd_sweep_grid(w, "x' = -5:-4.5:2"), QD_OK);
    assert_int_equal(qd_sweep_measures(w, "final, energy_error"), QD_OK);
    assert_int_equal(qd_sweep_ncols(w), 4);
    qd_sim_opts o = {.method = QD_SIM_DOP853, .t_end = 2, .q0 = f->q0, .qd0 = f->qd0};
    double rows[2 * 4];
    qd_sweep_outcome out[2];
    assert_int_equal(qd_sweep_run(f->ctx, w, &o, 0, 2, 2, rows, out, NULL, NULL), QD_OK);
    char why[QD_SWEEP_OUTCOME_MAX];
    for (size_t k = 0; k < 2; k++) {
        qd_sweep_outcome_str(&out[k], why, sizeof why);
        if (out[k].status != QD_ERR_NUMERIC || out[k].stop.code != QD_STOP_STEP_UNDERFLOW ||
            !strstr(why, "step size underflow at t = 0.2"))
            fail_msg("run %zu: status %d, stop %d, '%s'", k, (int)out[k].status,
                     (int)out[k].stop.code, why);
        assert_true(isnan(rows[4 * k + 1]) && isnan(rows[4 * k + 3]));
    }
    qd_sweep_free(w);
    sf_free(f);
}

static void test_threads_bounded(void **state) {
    (void)state;
    sim_fix *f = sf_load(root);
    assert_non_null(f);
    assert_int_equal(qd_sim_compile(f->s), QD_OK);
    qd_sweep *w = qd_sweep_new(f->ctx, f->s, f->m);
    assert_non_null(w);
    assert_int_equal(qd_sweep_grid(w, "x' = 1:2:3"), QD_OK);
    assert_int_equal(qd_sweep_measures(w, "final"), QD_OK);
    qd_sim_opts o = {.method = QD_SIM_DOP853, .t_end = 0.1, .q0 = f->q0, .qd0 = f->qd0};
    double rows[3 * 3];
    qd_sweep_outcome st[3];
    /* (unsigned)1e12 = 3567587328, what --threads 1e12 once reached */
    assert_int_equal(qd_sweep_run(f->ctx, w, &o, 0, 3, 3567587328u, rows, st, NULL, NULL),
                     QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(f->ctx), "at most 1024"));
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_sweep_run(f->ctx, w, &o, 0, 3, QD_SWEEP_MAX_THREADS, rows, st, NULL,
                                  NULL), QD_OK);
    assert_int_equal(qd_sweep_threads(QD_SWEEP_MAX_THREADS, 3), 3);
    assert_int_equal(qd_sweep_threads(2, 3), 2);
    assert_int_equal(qd_sweep_threads(QD_SWEEP_MAX_THREADS + 1, 3), 0);
    assert_true(qd_sweep_threads(0, 1000) >= 1);
    assert_int_equal(qd_sweep_threads(0, 1), 1);
    qd_sweep_free(w);
    sf_free(f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_nan_run_fails),
        cmocka_unit_test(test_threads_bounded),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
