/*
 * tests/sweep/test_sweep.c - many runs of one compiled system (qdot/sweep.h):
 *
 *   - the specs' errors (N = 0, A > B, unknown and duplicate names,
 *     malformed text), each located in the text;
 *   - the grid's order (first axis slowest, ends exact) and the random
 *     draw (inside the box, a function of (seed, run) alone, mean 1/2);
 *   - the harmonic oscillator swept over its parameters: the event
 *     measure gives the period 2 pi sqrt(m/k) (a parameter defined from a
 *     swept one follows it), poincare-count the number of whole periods,
 *     final the closed form x = x0 cos(w t) + v0/w sin(w t), max the
 *     amplitude v0/w;
 *   - escape of a free particle (x = v t leaves x < 1 at t = 1/v);
 *   - a run whose mass matrix is singular fails alone, its reason in its
 *     row, the others go on;
 *   - the lyapunov measures (qdot/lyapunov.h) over a parameter: the
 *     inverted oscillator x'' = a^2 x has exponents +a and -a (the motion
 *     grows as exp(a t)) within the estimator's error, the spectrum of a
 *     Hamiltonian system sums to 0; the oscillator's largest is 0;
 *   - rows identical, bit for bit, on 1 and 2 threads.
 */
#include <pthread.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <setjmp.h>
#include <cmocka.h>

#include "qdot/sweep.h"
#include "sim/sim_fixture.h"

/* k and m swept; w defined from them, so the equations see w follow. */
static const char osc[] = "coordinates x\nparameters k = 1, m = 1, w = sqrt(k/m)\n"
                          "T = m*x'^2/2\nV = m*w^2*x^2/2\ninitial x = 0, x' = 1\n";

static qd_sweep *sweep_of(sim_fix *f) {
    assert_int_equal(qd_sim_compile(f->s), QD_OK);
    qd_sweep *w = qd_sweep_new(f->ctx, f->s, f->m);
    assert_non_null(w);
    return w;
}

static qd_sim_opts opts_of(sim_fix *f, double t_end) {
    return (qd_sim_opts){.method = QD_SIM_DOP853, .t_end = t_end, .rtol = 1e-12, .atol = 1e-14,
                         .q0 = f->q0, .qd0 = f->qd0};
}

/* ---- specs ------------------------------------------------------------------ */

static void expect_error(qd_sweep *w, sim_fix *f, const char *spec, qd_status st, size_t col) {
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_sweep_grid(w, spec), st);
    const qd_diag *d = qd_ctx_diag(f->ctx);
    assert_true(d->located);
    assert_int_equal(d->col, col);
    assert_int_equal(qd_sweep_nruns(w), 0);
}

static void test_spec_errors(void **state) {
    (void)state;
    sim_fix *f = sf_load(osc);
    qd_sweep *w = sweep_of(f);
    expect_error(w, f, "x=0:1:0", QD_ERR_ARG, 7);             /* N = 0 */
    expect_error(w, f, "x=0:1:2, k=2:1:3", QD_ERR_ARG, 12);   /* A > B */
    expect_error(w, f, "x=0:1:2, y=0:1:2", QD_ERR_ARG, 10);   /* unknown */
    expect_error(w, f, "k=1:2:2, k=1:3:2", QD_ERR_ARG, 10);   /* duplicate */
    expect_error(w, f, "x=0:1", QD_ERR_PARSE, 3);             /* no N */
    expect_error(w, f, "x=0:1:2.5", QD_ERR_PARSE, 7);         /* N not whole */
    expect_error(w, f, "x 0:1:2", QD_ERR_PARSE, 1);           /* no '=' */
    expect_error(w, f, "x=a:1:2", QD_ERR_PARSE, 3);           /* not a number */
    /* A > B is a single point's business only when N = 1 */
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_sweep_grid(w, "x=2:1:1"), QD_OK);
    assert_int_equal(qd_sweep_nruns(w), 1);
    assert_int_equal(qd_sweep_random(w, "x=1:0", 4, 1), QD_ERR_ARG);
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_sweep_measures(w, "final, maximum:x"), QD_ERR_ARG);
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_sweep_measures(w, "max:nothere"), QD_ERR_ARG);
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_sweep_measures(w, "escape:x=1"), QD_ERR_PARSE);
    qd_ctx_clear_error(f->ctx);
    qd_sweep_free(w);
    sf_free(f);
}

/* ---- the runs' inputs ----------------------------------------------------- */

static void test_grid_order(void **state) {
    (void)state;
    sim_fix *f = sf_load(osc);
    qd_sweep *w = sweep_of(f);
    assert_int_equal(qd_sweep_grid(w, "x = -pi/2 : 1 : 3, x' = 0.1 : 0.3 : 2"), QD_OK);
    assert_int_equal(qd_sweep_measures(w, "energy_error"), QD_OK);
    assert_int_equal(qd_sweep_nruns(w), 6);
    assert_int_equal(qd_sweep_ncols(w), 3);
    assert_string_equal(qd_sweep_col(w, 0), "x");
    assert_string_equal(qd_sweep_col(w, 1), "x'");
    assert_string_equal(qd_sweep_col(w, 2), "energy_error");
    qd_sim_opts o = opts_of(f, 0.1);
    double row[3];
    const double want[6][2] = {{-SF_PI / 2, 0.1}, {-SF_PI / 2, 0.3},
                               {0.5 * (1 - SF_PI / 2), 0.1}, {0.5 * (1 - SF_PI / 2), 0.3},
                               {1, 0.1}, {1, 0.3}};
    for (size_t i = 0; i < 6; i++) {
        assert_int_equal(qd_sweep_run_one(f->ctx, w, &o, i, row, NULL), QD_OK);
        assert_true(row[0] == want[i][0] || fabs(row[0] - want[i][0]) < 1e-15);
        assert_true(row[1] == want[i][1]);
        assert_true(row[2] < 1e-10);
    }
    qd_sweep_free(w);
    sf_free(f);
}

static void test_random_draw(void **state) {
    (void)state;
    sim_fix *f = sf_load(osc);
    qd_sweep *w = sweep_of(f), *w2 = sweep_of(f);
    enum { N = 4000 };
    assert_int_equal(qd_sweep_random(w, "x=-1:3, k=2:2.5", N, 7), QD_OK);
    assert_int_equal(qd_sweep_random(w2, "x=-1:3, k=2:2.5", N, 8), QD_OK);
    assert_int_equal(qd_sweep_measures(w, "energy_error"), QD_OK);
    assert_int_equal(qd_sweep_measures(w2, "energy_error"), QD_OK);
    qd_sim_opts o = opts_of(f, 0.01);
    double sum = 0, row[3], again[3], other[3];
    size_t same = 0;
    for (size_t i = 0; i < N; i += 1) {
        assert_int_equal(qd_sweep_run_one(f->ctx, w, &o, i, row, NULL), QD_OK);
        assert_true(row[0] >= -1 && row[0] < 3 && row[1] >= 2 && row[1] < 2.5);
        sum += (row[0] + 1) / 4;
        if (i % 97 == 0) { /* the draw of run i does not depend on what ran before */
            assert_int_equal(qd_sweep_run_one(f->ctx, w, &o, i, again, NULL), QD_OK);
            assert_memory_equal(row, again, sizeof row);
        }
        assert_int_equal(qd_sweep_run_one(f->ctx, w2, &o, i, other, NULL), QD_OK);
        same += row[0] == other[0];
    }
    /* uniform on [0, 1): mean 1/2, standard error 1/sqrt(12 N) = 0.0046 */
    assert_true(fabs(sum / N - 0.5) < 4 * 0.0046);
    assert_int_equal(same, 0);
    qd_sweep_free(w);
    qd_sweep_free(w2);
    sf_free(f);
}

/* ---- measures -------------------------------------------------------------- */

/* The section x = 0 going up (x' > 0): once a period. */
static void add_section(sim_fix *f) {
    const qd_expr *g = qd_model_coord(f->m, 0), *up = f->e->qd[0];
    assert_int_equal(qd_sim_add_event(f->s, g, 1, &up, false), QD_OK);
}

static void test_oscillator_parameters(void **state) {
    (void)state;
    sim_fix *f = sf_load(osc);
    add_section(f);
    qd_sweep *w = sweep_of(f);
    assert_int_equal(qd_sweep_grid(w, "k = 1:9:3, m = 0.5:2:2"), QD_OK);
    assert_int_equal(qd_sweep_measures(w, "event, poincare-count, final, max:x"), QD_OK);
    assert_int_equal(qd_sweep_set_section(w, 0), QD_OK);
    assert_int_equal(qd_sweep_ncols(w), 2 + 3 + 1 + 2 + 1);
    assert_string_equal(qd_sweep_col(w, 2), "event_t");
    assert_string_equal(qd_sweep_col(w, 5), "poincare-count");
    assert_string_equal(qd_sweep_col(w, 7), "final_x'");
    assert_string_equal(qd_sweep_col(w, 8), "max:x");
    double t_end = 10.25;
    qd_sim_opts o = opts_of(f, t_end);
    double row[9];
    for (size_t i = 0; i < qd_sweep_nruns(w); i++) {
        assert_int_equal(qd_sweep_run_one(f->ctx, w, &o, i, row, NULL), QD_OK);
        double k = row[0], m = row[1], om = sqrt(k / m), period = 2 * SF_PI / om;
        assert_true(fabs(row[2] - period) < 1e-9 * period);
        assert_true(fabs(row[3]) < 1e-9 && fabs(row[4] - 1) < 1e-9); /* x = 0, x' = 1 there */
        assert_true(row[5] == floor(t_end / period));
        assert_true(fabs(row[6] - sin(om * t_end) / om) < 1e-8);
        assert_true(fabs(row[7] - cos(om * t_end)) < 1e-8);
        /* the largest x at the steps: the amplitude 1/w, sampled */
        assert_true(row[8] <= 1 / om + 1e-9 && row[8] > 0.99 / om);
    }
    qd_sweep_free(w);
    sf_free(f);
}

static void test_escape(void **state) {
    (void)state;
    sim_fix *f = sf_load("coordinates x\nparameters m = 1\nT = m*x'^2/2\ninitial x = 0\n");
    qd_sweep *w = sweep_of(f);
    assert_int_equal(qd_sweep_grid(w, "x' = 0.5:2:4"), QD_OK);
    assert_int_equal(qd_sweep_measures(w, "escape:x>1, escape:x<-1"), QD_OK);
    qd_sim_opts o = opts_of(f, 2.5);
    double row[3];
    for (size_t i = 0; i < 4; i++) {
        assert_int_equal(qd_sweep_run_one(f->ctx, w, &o, i, row, NULL), QD_OK);
        assert_true(fabs(row[1] - 1 / row[0]) < 1e-12); /* x = v t: linear, so exact */
        assert_true(isnan(row[2]));                    /* never below -1 */
    }
    qd_sweep_free(w);
    sf_free(f);
}

/* T = x^2 x'^2 / 2: the mass matrix x^2 is singular at x = 0. */
static void test_failure_recorded(void **state) {
    (void)state;
    sim_fix *f = sf_load("coordinates x\nT = x^2*x'^2/2\nV = x^2/2\ninitial x = 1\n");
    qd_sweep *w = sweep_of(f);
    assert_int_equal(qd_sweep_grid(w, "x = -1:1:3"), QD_OK);
    assert_int_equal(qd_sweep_measures(w, "final"), QD_OK);
    qd_sim_opts o = opts_of(f, 0.5);
    double rows[3 * 3];
    qd_sweep_outcome out[3];
    assert_int_equal(qd_sweep_run(f->ctx, w, &o, 0, 3, 2, rows, out, NULL, NULL), QD_OK);
    assert_int_equal(out[0].status, QD_OK);
    assert_int_equal(out[1].status, QD_ERR_SINGULAR);
    assert_int_equal(out[2].status, QD_OK);
    /* the reason as data: the integration stopped at t = 0 on a singular M,
     * the others reached t_end; the sentence is worded from the code */
    assert_int_equal(out[1].stop.code, QD_STOP_SINGULAR);
    assert_true(out[1].stop.t == 0);
    assert_int_equal(out[0].stop.code, QD_STOP_END);
    assert_true(out[2].stop.t == 0.5);
    char why[QD_SWEEP_OUTCOME_MAX];
    assert_string_equal(qd_sweep_outcome_str(&out[1], why, sizeof why),
                        "singular equations at t = 0");
    assert_string_equal(qd_sweep_outcome_str(&out[0], why, sizeof why), "ok");
    assert_true(rows[3] == 0 && isnan(rows[4]) && isnan(rows[5])); /* the inputs only */
    assert_true(!isnan(rows[1]) && !isnan(rows[7]));
    /* V and T even in x: the run from -1 mirrors the run from 1 */
    assert_true(rows[1] == -rows[7] && rows[2] == -rows[8]);
    qd_sweep_free(w);
    sf_free(f);
}

static void test_lyapunov(void **state) {
    (void)state;
    sim_fix *f = sf_load("coordinates x\nparameters a = 1\nT = x'^2/2\nV = -a^2*x^2/2\n"
                         "initial x = 0, x' = 1\n");
    qd_sweep *w = sweep_of(f);
    qd_lyap *l = qd_lyap_new(f->ctx, f->m, f->e);
    assert_non_null(l);
    assert_int_equal(qd_sweep_grid(w, "a = 0.5:2:4"), QD_OK);
    assert_int_equal(qd_sweep_measures(w, "lyapunov, lyapunov-spectrum"), QD_OK);
    qd_sim_opts o = opts_of(f, 20);
    double row[5];
    assert_int_equal(qd_sweep_run_one(f->ctx, w, &o, 0, row, NULL), QD_ERR_ARG); /* no qd_lyap yet */
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_sweep_set_lyap(w, l, NULL), QD_OK);
    assert_string_equal(qd_sweep_col(w, 2), "lyapunov_error");
    assert_string_equal(qd_sweep_col(w, 4), "lyapunov_2");
    for (size_t i = 0; i < 4; i++) {
        assert_int_equal(qd_sweep_run_one(f->ctx, w, &o, i, row, NULL), QD_OK);
        double a = row[0];
        assert_true(fabs(row[1] - a) <= row[2] && row[2] < 0.15 * a);
        assert_true(fabs(row[3] - row[1]) < 1e-9 && fabs(row[3] + row[4]) < 1e-9);
    }
    qd_lyap_free(l);
    qd_sweep_free(w);
    sf_free(f);
    /* the oscillator: regular, largest exponent 0 within its error */
    f = sf_load(osc);
    w = sweep_of(f);
    l = qd_lyap_new(f->ctx, f->m, f->e);
    assert_int_equal(qd_sweep_set_lyap(w, l, NULL), QD_OK);
    assert_int_equal(qd_sweep_grid(w, "k = 1:4:2"), QD_OK);
    assert_int_equal(qd_sweep_measures(w, "lyapunov"), QD_OK);
    o = opts_of(f, 200);
    for (size_t i = 0; i < 2; i++) {
        assert_int_equal(qd_sweep_run_one(f->ctx, w, &o, i, row, NULL), QD_OK);
        assert_true(fabs(row[1]) <= row[2] + 1e-12 && row[2] < 0.01);
    }
    qd_lyap_free(l);
    qd_sweep_free(w);
    sf_free(f);
}

/* ---- threads --------------------------------------------------------------- */

static size_t calls, last_done;

static int count_progress(void *data, size_t done, size_t total) {
    (void)data;
    assert_true(done <= total && done >= last_done);
    last_done = done;
    calls++;
    return 0;
}

/* Stop once a run is done (as Python's ^C does). */
static int stop_progress(void *data, size_t done, size_t total) {
    (void)data;
    (void)total;
    return done >= 1;
}

static void test_threads_identical(void **state) {
    (void)state;
    /* the double pendulum (Goldstein ch. 1 ex. 22, seed 002): chaotic, so any
     * difference in what a run computes shows in its final state */
    sim_fix *f = sf_load("coordinates a, b\nparameters g = 9.81, l = 1\n"
                         "T = a'^2 + b'^2/2 + a'*b'*cos(a - b)\n"
                         "V = -2*g*cos(a) - g*cos(b)\ninitial a = 1, b = 0.5\n");
    qd_sweep *w = sweep_of(f);
    assert_int_equal(qd_sweep_random(w, "a = -2:2, b = -2:2, g = 5:15", 40, 3), QD_OK);
    assert_int_equal(qd_sweep_measures(w, "final, energy_error, max:b"), QD_OK);
    size_t nc = qd_sweep_ncols(w);
    double *r1 = calloc(40 * nc, sizeof *r1), *r2 = calloc(40 * nc, sizeof *r2);
    qd_sweep_outcome s1[40], s2[40];
    qd_sim_opts o = opts_of(f, 5);
    o.rtol = 1e-9;
    assert_int_equal(qd_sweep_run(f->ctx, w, &o, 0, 40, 1, r1, s1, NULL, NULL), QD_OK);
    calls = last_done = 0;
    assert_int_equal(qd_sweep_run(f->ctx, w, &o, 0, 40, 2, r2, s2, count_progress, NULL),
                     QD_OK);
    assert_true(calls >= 1 && last_done == 40);
    assert_memory_equal(r1, r2, 40 * nc * sizeof *r1);
    for (size_t k = 0; k < 40; k++) /* field by field: a struct's padding is not data */
        assert_true(s1[k].status == s2[k].status && s1[k].stop.code == s2[k].stop.code &&
                    s1[k].stop.t == s2[k].stop.t);
    /* stopped once a run is done, on one thread: the runs that ran keep
     * their rows (the full sweep's), the rest are "stopped" (if the worker
     * finished them all before the stop was heard, nothing is stopped) */
    qd_status st = qd_sweep_run(f->ctx, w, &o, 0, 40, 1, r2, s2, stop_progress, NULL);
    size_t ran = 0;
    for (size_t k = 0; k < 40; k++) {
        bool stopped = s2[k].status == QD_ERR_ARG && s2[k].stop.code == QD_STOP_CALLBACK;
        assert_true(stopped || (s2[k].status == s1[k].status &&
                                memcmp(r1 + k * nc, r2 + k * nc, nc * sizeof *r1) == 0));
        ran += !stopped;
    }
    assert_true(ran >= 1);
    if (ran < 40) {
        assert_int_equal(st, QD_ERR_ARG);
        assert_non_null(strstr(qd_ctx_diag(f->ctx)->message, "stopped after"));
        qd_ctx_clear_error(f->ctx);
    } else {
        assert_int_equal(st, QD_OK);
    }
    /* a part of the runs: the same rows */
    assert_int_equal(qd_sweep_run(f->ctx, w, &o, 10, 5, 2, r2, s2, NULL, NULL), QD_OK);
    assert_memory_equal(r1 + 10 * nc, r2, 5 * nc * sizeof *r1);
    assert_int_equal(qd_sweep_run(f->ctx, w, &o, 38, 5, 2, r2, s2, NULL, NULL), QD_ERR_ARG);
    qd_ctx_clear_error(f->ctx);
    /* the whole sweep into arrays of its own, outside a launcher: the same
     * rows, one process the writer, and the failures counted */
    qd_sweep_result res;
    assert_int_equal(qd_sweep_result_run(f->ctx, w, &o, 2, NULL, NULL, &res), QD_OK);
    assert_true(res.nruns == 40 && res.ncols == nc && res.where.writer && res.where.ranks == 1);
    assert_memory_equal(r1, res.rows, 40 * nc * sizeof *r1);
    size_t failed = 0;
    for (size_t k = 0; k < 40; k++)
        failed += s1[k].status != QD_OK;
    assert_int_equal(res.failed, failed);
    qd_sweep_result_free(&res);
    qd_sweep_result_free(&res); /* twice is fine */
    free(r1);
    free(r2);
    qd_sweep_free(w);
    sf_free(f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_spec_errors),           cmocka_unit_test(test_grid_order),
        cmocka_unit_test(test_random_draw),           cmocka_unit_test(test_oscillator_parameters),
        cmocka_unit_test(test_escape),                cmocka_unit_test(test_failure_recorded),
        cmocka_unit_test(test_lyapunov),             cmocka_unit_test(test_threads_identical),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
