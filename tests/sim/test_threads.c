/*
 * tests/sim/test_threads.c - compile once, evaluate on many threads
 * (docs/design.md, thread safety).  Two threads share one compiled object
 * and must get, bit for bit, the single-threaded results:
 *
 *   - qd_eom_prog_eval of the rod pendulum in Cartesian coordinates (the
 *     saddle-point solve: q'' and the multiplier) at a set of states, each
 *     thread with its own qd_eom_work and context;
 *   - qd_sim_run_with on one compiled qd_sim of the double pendulum (Goldstein
 *     ch. 1 ex. 22, seed 002) with an output column: dop853 on one thread,
 *     gl4 and gl6 (the canonical form, Newton iterations) on two
 *     more, each against the same run made alone; and two runs of the rod
 *     pendulum (projection onto the constraint, per-run scratch).
 *
 * make test-tsan builds this program with ThreadSanitizer (-DQDOT_TSAN=ON),
 * which reports any unsynchronised access to shared state as a failure.
 */
#include <pthread.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "sim_fixture.h"

#define NSTATES 64
#define REPEAT 20

static const char rod[] = "coordinates x, y\nparameters m = 0.6, l = 1.4, g = 9.81\n"
                          "particle m at (x, y)\nV = m*g*y\n"
                          "constraint rod: x^2 + y^2 = l^2\n"
                          "initial x = 0.67, y = -1.23, x' = 0.3, y' = 0.1634\n";

static const char dp[] =
    "coordinates a, b\nparameters g = 9.81, l = 1\n"
    "T = a'^2 + b'^2/2 + a'*b'*cos(a - b)\nV = -2*g*cos(a) - g*cos(b)\n"
    "initial a = 1, b = 0.5, a' = 0.2\n";

/* ---- qd_eom_prog_eval ------------------------------------------------------- */

typedef struct eval_job {
    const qd_eom_prog *prog;
    size_t nsyms;
    const qd_expr *const *syms;
    const double (*vals)[6];
    double out[NSTATES][3]; /* x'', y'', lambda */
    qd_status st;
} eval_job;

static void *eval_all(void *arg) {
    eval_job *j = arg;
    qd_ctx *ctx = qd_ctx_new();
    qd_eom_work *w = ctx ? qd_eom_work_new(ctx, j->prog) : NULL;
    j->st = ctx && w ? QD_OK : QD_ERR_NOMEM;
    for (int r = 0; r < REPEAT && j->st == QD_OK; r++)
        for (size_t k = 0; k < NSTATES && j->st == QD_OK; k++)
            j->st = qd_eom_prog_eval(ctx, j->prog, w, j->nsyms, j->syms, j->vals[k], NULL, NULL,
                                     j->out[k], j->out[k] + 2, NULL);
    qd_eom_work_free(w);
    qd_ctx_free(ctx);
    return NULL;
}

static void test_eom_two_threads(void **state) {
    (void)state;
    sim_fix *f = sf_load(rod);
    assert_non_null(f);
    qd_eom_prog *prog = qd_eom_compile(f->ctx, f->e);
    assert_non_null(prog);
    const qd_expr *syms[6] = {f->e->q[0],  f->e->q[1],  f->e->qd[0],
                              f->e->qd[1], qd_model_param(f->m, 0), qd_model_param(f->m, 1)};
    static double vals[NSTATES][6];
    for (size_t k = 0; k < NSTATES; k++) {
        /* on the circle of radius l, moving along it */
        double th = 0.1 * (double)k, l = 1 + 0.01 * (double)k, w = 0.5 - 0.02 * (double)k;
        double v[6] = {l * sin(th), -l * cos(th), l * w * cos(th), l * w * sin(th), 0.6, l};
        memcpy(vals[k], v, sizeof v);
    }
    eval_job alone = {.prog = prog, .nsyms = 6, .syms = syms, .vals = (const double (*)[6])vals};
    eval_all(&alone);
    assert_int_equal(alone.st, QD_OK);
    /* the physics: g is not given, so 0, and the bob moves freely along
     * the circle: no tangential acceleration, a centripetal one l w^2 */
    for (size_t k = 0; k < NSTATES; k++) {
        double th = 0.1 * (double)k, l = 1 + 0.01 * (double)k, w = 0.5 - 0.02 * (double)k;
        double at = alone.out[k][0] * cos(th) + alone.out[k][1] * sin(th);
        double ar = alone.out[k][0] * sin(th) - alone.out[k][1] * cos(th);
        assert_true(fabs(at) < 1e-12 && fabs(ar + l * w * w) < 1e-12);
    }
    eval_job job[2] = {alone, alone};
    pthread_t th[2];
    for (int i = 0; i < 2; i++) {
        memset(job[i].out, 0, sizeof job[i].out);
        assert_int_equal(pthread_create(&th[i], NULL, eval_all, &job[i]), 0);
    }
    for (int i = 0; i < 2; i++) {
        pthread_join(th[i], NULL);
        assert_int_equal(job[i].st, QD_OK);
        assert_memory_equal(job[i].out, alone.out, sizeof alone.out);
    }
    qd_eom_prog_free(prog);
    sf_free(f);
}

/* ---- qd_sim_run_with -------------------------------------------------------- */

typedef struct run_job {
    const qd_sim *s;
    qd_sim_opts o;
    double final[64];
    qd_sim_stats stats;
    size_t rows;
    qd_status st;
} run_job;

static int count_rows(void *data, int event, const double *row) {
    (void)event;
    (void)row;
    ((run_job *)data)->rows++;
    return 0;
}

static void *run_one(void *arg) {
    run_job *j = arg;
    qd_ctx *ctx = qd_ctx_new();
    j->rows = 0;
    j->st = ctx ? qd_sim_run_with(ctx, j->s, &j->o, count_rows, j, &j->stats, j->final)
                : QD_ERR_NOMEM;
    qd_ctx_free(ctx);
    return NULL;
}

/* Each job alone, then all at once on their own threads: equal bit for bit. */
static void run_alone_then_together(run_job *jobs, size_t n, size_t ncols) {
    run_job alone[4];
    assert_true(n <= 4);
    for (size_t i = 0; i < n; i++) {
        alone[i] = jobs[i];
        run_one(&alone[i]);
        assert_int_equal(alone[i].st, QD_OK);
    }
    pthread_t th[4];
    for (size_t i = 0; i < n; i++)
        assert_int_equal(pthread_create(&th[i], NULL, run_one, &jobs[i]), 0);
    for (size_t i = 0; i < n; i++) {
        pthread_join(th[i], NULL);
        assert_int_equal(jobs[i].st, QD_OK);
        assert_int_equal(jobs[i].rows, alone[i].rows);
        assert_int_equal(jobs[i].stats.steps, alone[i].stats.steps);
        assert_memory_equal(jobs[i].final, alone[i].final, ncols * sizeof(double));
    }
}

static void test_sim_two_threads(void **state) {
    (void)state;
    sim_fix *f = sf_load(dp);
    assert_non_null(f);
    qd_ctx *ctx = f->ctx;
    const qd_expr *a = f->e->q[0], *b = f->e->q[1];
    /* x of the second bob: an output column compiled with the system */
    const qd_expr *x2 = qd_add(ctx, qd_fn(ctx, QD_SIN, a), qd_fn(ctx, QD_SIN, b));
    assert_int_equal(qd_sim_add_output(f->s, "x2", x2), QD_OK);
    qd_sim_opts o = {.t_end = 5, .q0 = f->q0, .qd0 = f->qd0};
    run_job jobs[3] = {{.s = f->s, .o = o}, {.s = f->s, .o = o}, {.s = f->s, .o = o}};
    jobs[0].o.method = QD_SIM_DOP853;
    jobs[0].o.rtol = 1e-10;
    jobs[1].o.method = QD_SIM_GL4;
    jobs[1].o.dt = 0.01;
    jobs[2].o.method = QD_SIM_GL6;
    jobs[2].o.dt = 0.02;
    /* not compiled yet: a shared run is refused */
    run_one(&jobs[0]);
    assert_int_equal(jobs[0].st, QD_ERR_ARG);
    assert_int_equal(qd_sim_compile(f->s), QD_OK);
    size_t ncols = qd_sim_columns(f->s, QD_SIM_GL4, NULL, 0);
    run_alone_then_together(jobs, 3, ncols);
    /* energy kept: the runs are the physics, not only equal */
    for (int i = 0; i < 3; i++)
        assert_true(jobs[i].stats.energy_error_max < 1e-6);
    sf_free(f);
}

static void test_constrained_two_threads(void **state) {
    (void)state;
    sim_fix *f = sf_load(rod);
    assert_non_null(f);
    assert_int_equal(qd_sim_compile(f->s), QD_OK);
    qd_sim_opts o = {.method = QD_SIM_DOP853, .t_end = 3, .rtol = 1e-10, .q0 = f->q0,
                     .qd0 = f->qd0};
    run_job jobs[2] = {{.s = f->s, .o = o}, {.s = f->s, .o = o}};
    jobs[1].o.t_end = 4;
    run_alone_then_together(jobs, 2, qd_sim_columns(f->s, QD_SIM_DOP853, NULL, 0));
    for (int i = 0; i < 2; i++)
        assert_true(jobs[i].stats.constraint_error_max < 1e-12);
    sf_free(f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_eom_two_threads),
        cmocka_unit_test(test_sim_two_threads),
        cmocka_unit_test(test_constrained_two_threads),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
