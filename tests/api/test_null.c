/*
 * tests/api/test_null.c - every public function given NULL in each pointer
 * argument (issue 30): the documented error value, never a crash.
 *
 * Written by tests/api/gen_null_test.py from the headers in include/qdot/;
 * do not edit:
 * run `python3 tests/api/gen_null_test.py --root .` after changing a header
 * (the ctest api/check_null_coverage fails until then).
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>
#include "qdot/qdot.h"
#include "qdot/action.h"
#include "qdot/canonical.h"
#include "qdot/certify.h"
#include "qdot/codegen.h"
#include "qdot/conlin.h"
#include "qdot/constrained.h"
#include "qdot/contour.h"
#include "qdot/control.h"
#include "qdot/equilibria.h"
#include "qdot/eval.h"
#include "qdot/expr.h"
#include "qdot/field.h"
#include "qdot/form.h"
#include "qdot/hamilton.h"
#include "qdot/hj.h"
#include "qdot/impulse.h"
#include "qdot/integrals.h"
#include "qdot/json.h"
#include "qdot/linpoint.h"
#include "qdot/lyapunov.h"
#include "qdot/mech.h"
#include "qdot/metric.h"
#include "qdot/model.h"
#include "qdot/modes.h"
#include "qdot/orbit.h"
#include "qdot/path.h"
#include "qdot/plot.h"
#include "qdot/print.h"
#include "qdot/read.h"
#include "qdot/relativity.h"
#include "qdot/render.h"
#include "qdot/routh.h"
#include "qdot/scanplot.h"
#include "qdot/scatter.h"
#include "qdot/scene.h"
#include "qdot/sim.h"
#include "qdot/simsetup.h"
#include "qdot/speeds.h"
#include "qdot/stability.h"
#include "qdot/state.h"
#include "qdot/statespace.h"
#include "qdot/status.h"
#include "qdot/sweep.h"
#include "qdot/symmetry.h"
#include "qdot/tangent.h"
#include "qdot/version.h"
#include "qdot/zvc.h"

#if defined(__GNUC__)
#pragma GCC diagnostic ignored "-Wformat"
#pragma GCC diagnostic ignored "-Wnonnull"
#pragma GCC diagnostic ignored "-Wformat-extra-args"
#endif

typedef struct fixture {
    qd_ctx *ctx;
    qd_model *model;
    qd_eom *eom;
    qd_sim *sim;
    qd_plot *plot;
    qd_prog *prog;
    const qd_expr *q;
    qd_buf buf;
    double d[512];
    size_t z[64];
    bool b[64];
    int i[64];
    unsigned u[64];
    long l[64];
    uint64_t u64[64];
    qd_status st[64];
    char c[512];
    const qd_expr *e[64];
    const char *names[64];
    void *p[64];
    max_align_t blob[1024];
} fixture;

static const char MODEL[] =
    "coordinates q\n"
    "parameters m = 1, k = 1\n"
    "T = m/2*q'^2\n"
    "V = k/2*q^2\n";

/* Fresh values for the next call: what a call wrote is gone, no error kept. */
static void reset(fixture *f)
{
    qd_ctx_clear_error(f->ctx);
    qd_buf_clear(&f->buf);
    memset(f->d, 0, sizeof f->d);
    memset(f->z, 0, sizeof f->z);
    memset(f->b, 0, sizeof f->b);
    memset(f->i, 0, sizeof f->i);
    memset(f->u, 0, sizeof f->u);
    memset(f->l, 0, sizeof f->l);
    memset(f->u64, 0, sizeof f->u64);
    memset(f->st, 0, sizeof f->st);
    memset(f->c, 0, sizeof f->c);
    memset(f->p, 0, sizeof f->p);
    memset(f->blob, 0, sizeof f->blob);
    for (size_t k = 0; k < 64; k++) {
        f->e[k] = f->q;
        f->names[k] = "q";
    }
}

static void setup(fixture *f)
{
    memset(f, 0, sizeof *f);
    f->ctx = qd_ctx_new();
    assert_non_null(f->ctx);
    f->model = qd_model_parse(f->ctx, MODEL, NULL);
    assert_non_null(f->model);
    f->eom = qd_eom_derive(f->ctx, f->model);
    assert_non_null(f->eom);
    f->q = qd_model_coord(f->model, 0);
    f->sim = qd_sim_new(f->ctx, f->model, f->eom);
    assert_non_null(f->sim);
    f->plot = qd_plot_new(f->ctx, 200, 200);
    assert_non_null(f->plot);
    f->prog = qd_prog_new(f->ctx, 1, &f->q, 1, &f->q);
    assert_non_null(f->prog);
    f->buf = (qd_buf)QD_BUF_INIT;
    reset(f);
}

static void teardown(fixture *f)
{
    qd_buf_free(&f->buf);
    qd_prog_free(f->prog);
    qd_plot_free(f->plot);
    qd_sim_free(f->sim);
    qd_eom_free(f->eom);
    qd_model_free(f->model);
    qd_ctx_free(f->ctx);
}

static void null_action(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_action_at */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_action_at(NULL, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, (qd_action *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_action_at(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, NULL, (qd_action *)(void *)F.blob));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_action_at(F.ctx, F.model, 1, NULL, F.d, NULL, (qd_action *)(void *)F.blob));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_action_at(F.ctx, F.model, 1, (const qd_expr * const *)F.e, NULL, NULL, (qd_action *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_action_at(F.ctx, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, NULL));
    reset(&F);
    /* ---- qd_action_state_read */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_action_state_read(NULL, F.model, "q", NULL));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_action_state_read(F.ctx, NULL, "q", NULL));
    reset(&F);
    /* st NULL */
    assert_int_equal(QD_ERR_ARG, qd_action_state_read(F.ctx, F.model, "q", NULL));
    reset(&F);
    /* ---- qd_action_of_sep */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_action_of_sep(NULL, NULL, F.b, 1, (const qd_expr * const *)F.e, F.d, NULL, (qd_action *)(void *)F.blob));
    reset(&F);
    /* h NULL */
    assert_int_equal(QD_ERR_ARG, qd_action_of_sep(F.ctx, NULL, F.b, 1, (const qd_expr * const *)F.e, F.d, NULL, (qd_action *)(void *)F.blob));
    reset(&F);
    /* angle NULL */
    assert_int_equal(QD_ERR_ARG, qd_action_of_sep(F.ctx, NULL, NULL, 1, (const qd_expr * const *)F.e, F.d, NULL, (qd_action *)(void *)F.blob));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_action_of_sep(F.ctx, NULL, F.b, 1, NULL, F.d, NULL, (qd_action *)(void *)F.blob));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_action_of_sep(F.ctx, NULL, F.b, 1, (const qd_expr * const *)F.e, NULL, NULL, (qd_action *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_action_of_sep(F.ctx, NULL, F.b, 1, (const qd_expr * const *)F.e, F.d, NULL, NULL));
    reset(&F);
    /* ---- qd_action_free */
    /* a NULL */
    qd_action_free(NULL);
    reset(&F);
    /* ---- qd_action_print */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_action_print(NULL, NULL, false, &F.buf));
    reset(&F);
    /* a NULL */
    assert_int_equal(QD_ERR_ARG, qd_action_print(F.ctx, NULL, false, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_action_print(F.ctx, NULL, false, NULL));
    reset(&F);
    teardown(&F);
}

static void null_canonical(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_bracket */
    /* ctx NULL */
    assert_null(qd_bracket(NULL, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, F.q, F.q));
    reset(&F);
    /* q NULL */
    assert_null(qd_bracket(F.ctx, 1, NULL, (const qd_expr * const *)F.e, F.q, F.q));
    reset(&F);
    /* p NULL */
    assert_null(qd_bracket(F.ctx, 1, (const qd_expr * const *)F.e, NULL, F.q, F.q));
    reset(&F);
    /* F NULL */
    assert_null(qd_bracket(F.ctx, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, NULL, F.q));
    reset(&F);
    /* G NULL */
    assert_null(qd_bracket(F.ctx, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, F.q, NULL));
    reset(&F);
    /* ---- qd_canonical_check */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_canonical_check(NULL, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, F.q, (qd_canon_verdict *)(void *)F.blob));
    reset(&F);
    /* q NULL */
    assert_int_equal(QD_ERR_ARG, qd_canonical_check(F.ctx, 1, NULL, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, F.q, (qd_canon_verdict *)(void *)F.blob));
    reset(&F);
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_canonical_check(F.ctx, 1, (const qd_expr * const *)F.e, NULL, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, F.q, (qd_canon_verdict *)(void *)F.blob));
    reset(&F);
    /* Q NULL */
    assert_int_equal(QD_ERR_ARG, qd_canonical_check(F.ctx, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, NULL, (const qd_expr * const *)F.e, F.q, (qd_canon_verdict *)(void *)F.blob));
    reset(&F);
    /* P NULL */
    assert_int_equal(QD_ERR_ARG, qd_canonical_check(F.ctx, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, NULL, F.q, (qd_canon_verdict *)(void *)F.blob));
    reset(&F);
    /* v NULL */
    assert_int_equal(QD_ERR_ARG, qd_canonical_check(F.ctx, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, F.q, NULL));
    reset(&F);
    /* ---- qd_generate */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_generate(NULL, (qd_gen_type){0}, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, F.q, F.q, F.q, (qd_gen_result *)(void *)F.blob));
    reset(&F);
    /* old_q NULL */
    assert_int_equal(QD_ERR_ARG, qd_generate(F.ctx, (qd_gen_type){0}, 1, NULL, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, F.q, F.q, F.q, (qd_gen_result *)(void *)F.blob));
    reset(&F);
    /* old_p NULL */
    assert_int_equal(QD_ERR_ARG, qd_generate(F.ctx, (qd_gen_type){0}, 1, (const qd_expr * const *)F.e, NULL, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, F.q, F.q, F.q, (qd_gen_result *)(void *)F.blob));
    reset(&F);
    /* new_Q NULL */
    assert_int_equal(QD_ERR_ARG, qd_generate(F.ctx, (qd_gen_type){0}, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, NULL, (const qd_expr * const *)F.e, F.q, F.q, F.q, (qd_gen_result *)(void *)F.blob));
    reset(&F);
    /* new_P NULL */
    assert_int_equal(QD_ERR_ARG, qd_generate(F.ctx, (qd_gen_type){0}, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, NULL, F.q, F.q, F.q, (qd_gen_result *)(void *)F.blob));
    reset(&F);
    /* F NULL */
    assert_int_equal(QD_ERR_ARG, qd_generate(F.ctx, (qd_gen_type){0}, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, NULL, F.q, F.q, (qd_gen_result *)(void *)F.blob));
    reset(&F);
    /* t NULL */
    assert_int_equal(QD_ERR_ARG, qd_generate(F.ctx, (qd_gen_type){0}, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, F.q, NULL, F.q, (qd_gen_result *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_generate(F.ctx, (qd_gen_type){0}, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, F.q, F.q, F.q, NULL));
    reset(&F);
    /* ---- qd_generate_f2 */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_generate_f2(NULL, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, F.q, F.q, F.q, (qd_gen_result *)(void *)F.blob));
    reset(&F);
    /* q NULL */
    assert_int_equal(QD_ERR_ARG, qd_generate_f2(F.ctx, 1, NULL, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, F.q, F.q, F.q, (qd_gen_result *)(void *)F.blob));
    reset(&F);
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_generate_f2(F.ctx, 1, (const qd_expr * const *)F.e, NULL, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, F.q, F.q, F.q, (qd_gen_result *)(void *)F.blob));
    reset(&F);
    /* Q NULL */
    assert_int_equal(QD_ERR_ARG, qd_generate_f2(F.ctx, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, NULL, (const qd_expr * const *)F.e, F.q, F.q, F.q, (qd_gen_result *)(void *)F.blob));
    reset(&F);
    /* P NULL */
    assert_int_equal(QD_ERR_ARG, qd_generate_f2(F.ctx, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, NULL, F.q, F.q, F.q, (qd_gen_result *)(void *)F.blob));
    reset(&F);
    /* F2 NULL */
    assert_int_equal(QD_ERR_ARG, qd_generate_f2(F.ctx, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, NULL, F.q, F.q, (qd_gen_result *)(void *)F.blob));
    reset(&F);
    /* t NULL */
    assert_int_equal(QD_ERR_ARG, qd_generate_f2(F.ctx, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, F.q, NULL, F.q, (qd_gen_result *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_generate_f2(F.ctx, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, F.q, F.q, F.q, NULL));
    reset(&F);
    /* ---- qd_gen_result_free */
    /* r NULL */
    qd_gen_result_free(NULL);
    reset(&F);
    /* ---- qd_lagrange_bracket */
    /* ctx NULL */
    assert_null(qd_lagrange_bracket(NULL, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, F.q, F.q));
    reset(&F);
    /* Q NULL */
    assert_null(qd_lagrange_bracket(F.ctx, 1, NULL, (const qd_expr * const *)F.e, F.q, F.q));
    reset(&F);
    /* P NULL */
    assert_null(qd_lagrange_bracket(F.ctx, 1, (const qd_expr * const *)F.e, NULL, F.q, F.q));
    reset(&F);
    /* u NULL */
    assert_null(qd_lagrange_bracket(F.ctx, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, NULL, F.q));
    reset(&F);
    /* v NULL */
    assert_null(qd_lagrange_bracket(F.ctx, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, F.q, NULL));
    reset(&F);
    /* ---- qd_lagrange_brackets */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_lagrange_brackets(NULL, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (qd_lagrange_result *)(void *)F.blob));
    reset(&F);
    /* q NULL */
    assert_int_equal(QD_ERR_ARG, qd_lagrange_brackets(F.ctx, 1, NULL, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (qd_lagrange_result *)(void *)F.blob));
    reset(&F);
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_lagrange_brackets(F.ctx, 1, (const qd_expr * const *)F.e, NULL, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (qd_lagrange_result *)(void *)F.blob));
    reset(&F);
    /* Q NULL */
    assert_int_equal(QD_ERR_ARG, qd_lagrange_brackets(F.ctx, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, NULL, (const qd_expr * const *)F.e, (qd_lagrange_result *)(void *)F.blob));
    reset(&F);
    /* P NULL */
    assert_int_equal(QD_ERR_ARG, qd_lagrange_brackets(F.ctx, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, NULL, (qd_lagrange_result *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_lagrange_brackets(F.ctx, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, NULL));
    reset(&F);
    /* ---- qd_lagrange_result_free */
    /* r NULL */
    qd_lagrange_result_free(NULL);
    reset(&F);
    /* ---- qd_transformed_hamiltonian */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_transformed_hamiltonian(NULL, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, F.q, F.q, (qd_newham *)(void *)F.blob));
    reset(&F);
    /* q NULL */
    assert_int_equal(QD_ERR_ARG, qd_transformed_hamiltonian(F.ctx, 1, NULL, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, F.q, F.q, (qd_newham *)(void *)F.blob));
    reset(&F);
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_transformed_hamiltonian(F.ctx, 1, (const qd_expr * const *)F.e, NULL, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, F.q, F.q, (qd_newham *)(void *)F.blob));
    reset(&F);
    /* Q NULL */
    assert_int_equal(QD_ERR_ARG, qd_transformed_hamiltonian(F.ctx, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, NULL, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, F.q, F.q, (qd_newham *)(void *)F.blob));
    reset(&F);
    /* P NULL */
    assert_int_equal(QD_ERR_ARG, qd_transformed_hamiltonian(F.ctx, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, NULL, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, F.q, F.q, (qd_newham *)(void *)F.blob));
    reset(&F);
    /* newQ NULL */
    assert_int_equal(QD_ERR_ARG, qd_transformed_hamiltonian(F.ctx, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, NULL, (const qd_expr * const *)F.e, F.q, F.q, (qd_newham *)(void *)F.blob));
    reset(&F);
    /* newP NULL */
    assert_int_equal(QD_ERR_ARG, qd_transformed_hamiltonian(F.ctx, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, NULL, F.q, F.q, (qd_newham *)(void *)F.blob));
    reset(&F);
    /* t NULL */
    assert_int_equal(QD_ERR_ARG, qd_transformed_hamiltonian(F.ctx, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, NULL, F.q, (qd_newham *)(void *)F.blob));
    reset(&F);
    /* H NULL */
    assert_int_equal(QD_ERR_ARG, qd_transformed_hamiltonian(F.ctx, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, F.q, NULL, (qd_newham *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_transformed_hamiltonian(F.ctx, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, F.q, F.q, NULL));
    reset(&F);
    /* ---- qd_newham_free */
    /* k NULL */
    qd_newham_free(NULL);
    reset(&F);
    /* ---- qd_phase_init */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_phase_init(NULL, F.model, (qd_phase *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_phase_init(F.ctx, NULL, (qd_phase *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_phase_init(F.ctx, F.model, NULL));
    reset(&F);
    /* ---- qd_phase_new_vars */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_phase_new_vars(NULL, NULL));
    reset(&F);
    /* ph NULL */
    assert_int_equal(QD_ERR_ARG, qd_phase_new_vars(F.ctx, NULL));
    reset(&F);
    /* ---- qd_phase_read */
    /* ctx NULL */
    assert_null(qd_phase_read(NULL, NULL, "q", (qd_diag *)(void *)F.blob));
    reset(&F);
    /* ph NULL */
    assert_null(qd_phase_read(F.ctx, NULL, "q", (qd_diag *)(void *)F.blob));
    reset(&F);
    /* text NULL */
    assert_null(qd_phase_read(F.ctx, NULL, NULL, (qd_diag *)(void *)F.blob));
    reset(&F);
    /* err NULL */
    assert_null(qd_phase_read(F.ctx, NULL, "q", NULL));
    reset(&F);
    /* ---- qd_phase_read_h */
    /* ctx NULL */
    assert_null(qd_phase_read_h(NULL, NULL, "q", (qd_diag *)(void *)F.blob));
    reset(&F);
    /* ph NULL */
    assert_null(qd_phase_read_h(F.ctx, NULL, "q", (qd_diag *)(void *)F.blob));
    reset(&F);
    /* text NULL */
    assert_null(qd_phase_read_h(F.ctx, NULL, NULL, (qd_diag *)(void *)F.blob));
    reset(&F);
    /* err NULL */
    assert_null(qd_phase_read_h(F.ctx, NULL, "q", NULL));
    reset(&F);
    /* ---- qd_phase_read_list */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_phase_read_list(NULL, NULL, "q", (const qd_expr * *)F.e, (qd_diag *)(void *)F.blob));
    reset(&F);
    /* ph NULL */
    assert_int_equal(QD_ERR_ARG, qd_phase_read_list(F.ctx, NULL, "q", (const qd_expr * *)F.e, (qd_diag *)(void *)F.blob));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_phase_read_list(F.ctx, NULL, NULL, (const qd_expr * *)F.e, (qd_diag *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_phase_read_list(F.ctx, NULL, "q", NULL, (qd_diag *)(void *)F.blob));
    reset(&F);
    /* err NULL */
    assert_int_equal(QD_ERR_ARG, qd_phase_read_list(F.ctx, NULL, "q", (const qd_expr * *)F.e, NULL));
    reset(&F);
    /* ---- qd_phase_ham */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_phase_ham(NULL, NULL, false));
    reset(&F);
    /* ph NULL */
    assert_int_equal(QD_ERR_ARG, qd_phase_ham(F.ctx, NULL, false));
    reset(&F);
    /* ---- qd_phase_dt */
    /* ctx NULL */
    assert_null(qd_phase_dt(NULL, NULL, F.q));
    reset(&F);
    /* ph NULL */
    assert_null(qd_phase_dt(F.ctx, NULL, F.q));
    reset(&F);
    /* F NULL */
    assert_null(qd_phase_dt(F.ctx, NULL, NULL));
    reset(&F);
    /* ---- qd_phase_free */
    /* ph NULL */
    qd_phase_free(NULL);
    reset(&F);
    /* ---- qd_phase_bracket_print */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_phase_bracket_print(NULL, NULL, F.q, F.q, F.q, (qd_format){0}, false, &F.buf));
    reset(&F);
    /* ph NULL */
    assert_int_equal(QD_ERR_ARG, qd_phase_bracket_print(F.ctx, NULL, F.q, F.q, F.q, (qd_format){0}, false, &F.buf));
    reset(&F);
    /* F NULL */
    assert_int_equal(QD_ERR_ARG, qd_phase_bracket_print(F.ctx, NULL, NULL, F.q, F.q, (qd_format){0}, false, &F.buf));
    reset(&F);
    /* r NULL */
    assert_int_equal(QD_ERR_ARG, qd_phase_bracket_print(F.ctx, NULL, F.q, F.q, NULL, (qd_format){0}, false, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_phase_bracket_print(F.ctx, NULL, F.q, F.q, F.q, (qd_format){0}, false, NULL));
    reset(&F);
    /* ---- qd_canon_kind_name */
    /* no pointer argument */
    /* ---- qd_canonical_examine */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_canonical_examine(NULL, NULL, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, false, false, (qd_canon_report *)(void *)F.blob));
    reset(&F);
    /* ph NULL */
    assert_int_equal(QD_ERR_ARG, qd_canonical_examine(F.ctx, NULL, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, false, false, (qd_canon_report *)(void *)F.blob));
    reset(&F);
    /* Q NULL */
    assert_int_equal(QD_ERR_ARG, qd_canonical_examine(F.ctx, NULL, NULL, (const qd_expr * const *)F.e, false, false, (qd_canon_report *)(void *)F.blob));
    reset(&F);
    /* P NULL */
    assert_int_equal(QD_ERR_ARG, qd_canonical_examine(F.ctx, NULL, (const qd_expr * const *)F.e, NULL, false, false, (qd_canon_report *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_canonical_examine(F.ctx, NULL, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, false, false, NULL));
    reset(&F);
    /* ---- qd_canon_report_free */
    /* r NULL */
    qd_canon_report_free(NULL);
    reset(&F);
    /* ---- qd_canon_report_print */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_canon_report_print(NULL, NULL, NULL, false, &F.buf));
    reset(&F);
    /* ph NULL */
    assert_int_equal(QD_ERR_ARG, qd_canon_report_print(F.ctx, NULL, NULL, false, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_canon_report_print(F.ctx, NULL, NULL, false, NULL));
    reset(&F);
    /* ---- qd_gen_result_print */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_gen_result_print(NULL, NULL, (qd_gen_type){0}, F.q, NULL, false, &F.buf));
    reset(&F);
    /* ph NULL */
    assert_int_equal(QD_ERR_ARG, qd_gen_result_print(F.ctx, NULL, (qd_gen_type){0}, F.q, NULL, false, &F.buf));
    reset(&F);
    /* F NULL */
    assert_int_equal(QD_ERR_ARG, qd_gen_result_print(F.ctx, NULL, (qd_gen_type){0}, NULL, NULL, false, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_gen_result_print(F.ctx, NULL, (qd_gen_type){0}, F.q, NULL, false, NULL));
    reset(&F);
    /* ---- qd_condensed_new */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_condensed_new(NULL, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, F.q, (qd_condensed *)(void *)F.blob));
    reset(&F);
    /* q NULL */
    assert_int_equal(QD_ERR_ARG, qd_condensed_new(F.ctx, 1, NULL, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, F.q, (qd_condensed *)(void *)F.blob));
    reset(&F);
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_condensed_new(F.ctx, 1, (const qd_expr * const *)F.e, NULL, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, F.q, (qd_condensed *)(void *)F.blob));
    reset(&F);
    /* Q NULL */
    assert_int_equal(QD_ERR_ARG, qd_condensed_new(F.ctx, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, NULL, (const qd_expr * const *)F.e, F.q, (qd_condensed *)(void *)F.blob));
    reset(&F);
    /* P NULL */
    assert_int_equal(QD_ERR_ARG, qd_condensed_new(F.ctx, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, NULL, F.q, (qd_condensed *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_condensed_new(F.ctx, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, F.q, NULL));
    reset(&F);
    /* ---- qd_condensed_free */
    /* c NULL */
    qd_condensed_free(NULL);
    reset(&F);
    /* ---- qd_phase_condensed */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_phase_condensed(NULL, NULL, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (qd_condensed *)(void *)F.blob));
    reset(&F);
    /* ph NULL */
    assert_int_equal(QD_ERR_ARG, qd_phase_condensed(F.ctx, NULL, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (qd_condensed *)(void *)F.blob));
    reset(&F);
    /* Q NULL */
    assert_int_equal(QD_ERR_ARG, qd_phase_condensed(F.ctx, NULL, NULL, (const qd_expr * const *)F.e, (qd_condensed *)(void *)F.blob));
    reset(&F);
    /* P NULL */
    assert_int_equal(QD_ERR_ARG, qd_phase_condensed(F.ctx, NULL, (const qd_expr * const *)F.e, NULL, (qd_condensed *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_phase_condensed(F.ctx, NULL, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, NULL));
    reset(&F);
    /* ---- qd_condensed_print */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_condensed_print(NULL, NULL, false, &F.buf));
    reset(&F);
    /* c NULL */
    assert_int_equal(QD_ERR_ARG, qd_condensed_print(F.ctx, NULL, false, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_condensed_print(F.ctx, NULL, false, NULL));
    reset(&F);
    teardown(&F);
}

static void null_certify(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_zero_test */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_zero_test(NULL, F.q, (qd_zero_result *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_zero_test(F.ctx, NULL, (qd_zero_result *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_zero_test(F.ctx, F.q, NULL));
    reset(&F);
    /* ---- qd_equal_test */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_equal_test(NULL, F.q, F.q, (qd_zero_result *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_equal_test(F.ctx, NULL, F.q, (qd_zero_result *)(void *)F.blob));
    reset(&F);
    /* target NULL */
    assert_int_equal(QD_ERR_ARG, qd_equal_test(F.ctx, F.q, NULL, (qd_zero_result *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_equal_test(F.ctx, F.q, F.q, NULL));
    reset(&F);
    /* ---- qd_zero_kind_name */
    /* no pointer argument */
    /* ---- qd_zero_result_print */
    /* out NULL */
    qd_zero_result_print(NULL, NULL);
    reset(&F);
    /* z NULL */
    qd_zero_result_print(&F.buf, NULL);
    reset(&F);
    /* ---- qd_zero_result_note */
    /* out NULL */
    qd_zero_result_note(NULL, NULL);
    reset(&F);
    /* z NULL */
    qd_zero_result_note(&F.buf, NULL);
    reset(&F);
    /* ---- qd_zero_result_json */
    /* j NULL */
    qd_zero_result_json(NULL, NULL);
    reset(&F);
    teardown(&F);
}

static void null_codegen(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_codegen_prefix_valid */
    /* prefix NULL */
    assert_true(qd_codegen_prefix_valid(NULL) == 0);
    reset(&F);
    /* ---- qd_codegen_prefix_from_path */
    /* path NULL */
    assert_int_equal(QD_ERR_ARG, qd_codegen_prefix_from_path(NULL, F.c, 1));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_codegen_prefix_from_path("q", NULL, 1));
    reset(&F);
    /* ---- qd_codegen_c */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_codegen_c(NULL, F.model, F.eom, "q", &F.buf, &F.buf));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_codegen_c(F.ctx, NULL, F.eom, "q", &F.buf, &F.buf));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_codegen_c(F.ctx, F.model, NULL, "q", &F.buf, &F.buf));
    reset(&F);
    /* prefix NULL */
    assert_int_equal(QD_ERR_ARG, qd_codegen_c(F.ctx, F.model, F.eom, NULL, &F.buf, &F.buf));
    reset(&F);
    /* c_text NULL */
    assert_int_equal(QD_ERR_ARG, qd_codegen_c(F.ctx, F.model, F.eom, "q", NULL, &F.buf));
    reset(&F);
    /* ---- qd_codegen_speeds_c */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_codegen_speeds_c(NULL, F.model, NULL, "q", &F.buf, &F.buf));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_codegen_speeds_c(F.ctx, NULL, NULL, "q", &F.buf, &F.buf));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_codegen_speeds_c(F.ctx, F.model, NULL, "q", &F.buf, &F.buf));
    reset(&F);
    /* prefix NULL */
    assert_int_equal(QD_ERR_ARG, qd_codegen_speeds_c(F.ctx, F.model, NULL, NULL, &F.buf, &F.buf));
    reset(&F);
    /* c_text NULL */
    assert_int_equal(QD_ERR_ARG, qd_codegen_speeds_c(F.ctx, F.model, NULL, "q", NULL, &F.buf));
    reset(&F);
    /* ---- qd_codegen_model_c */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_codegen_model_c(NULL, F.model, false, "q", &F.buf, &F.buf));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_codegen_model_c(F.ctx, NULL, false, "q", &F.buf, &F.buf));
    reset(&F);
    /* c_text NULL */
    assert_int_equal(QD_ERR_ARG, qd_codegen_model_c(F.ctx, F.model, false, "q", NULL, &F.buf));
    reset(&F);
    /* ---- qd_native_load */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_native_load(NULL, F.model, F.eom, "q", (qd_native *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_native_load(F.ctx, NULL, F.eom, "q", (qd_native *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_native_load(F.ctx, F.model, NULL, "q", (qd_native *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_native_load(F.ctx, F.model, F.eom, "q", NULL));
    reset(&F);
    /* ---- qd_native_load_run */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_native_load_run(NULL, F.model, F.eom, "q", (qd_native *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_native_load_run(F.ctx, NULL, F.eom, "q", (qd_native *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_native_load_run(F.ctx, F.model, NULL, "q", (qd_native *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_native_load_run(F.ctx, F.model, F.eom, "q", NULL));
    reset(&F);
    /* ---- qd_native_unload */
    /* nat NULL */
    qd_native_unload(NULL);
    reset(&F);
    teardown(&F);
}

static void null_conlin(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_conlin_about */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_about(NULL, F.eom, F.model, NULL, "q", (qd_conlin *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_about(F.ctx, NULL, F.model, NULL, "q", (qd_conlin *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_about(F.ctx, F.eom, NULL, NULL, "q", (qd_conlin *)(void *)F.blob));
    reset(&F);
    /* pt NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_about(F.ctx, F.eom, F.model, NULL, "q", (qd_conlin *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_about(F.ctx, F.eom, F.model, NULL, "q", NULL));
    reset(&F);
    /* ---- qd_conlin_free */
    /* c NULL */
    qd_conlin_free(NULL);
    reset(&F);
    /* ---- qd_conlin_keep_core */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_keep_core(NULL, NULL));
    reset(&F);
    /* c NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_keep_core(F.ctx, NULL));
    reset(&F);
    /* ---- qd_conlin_point */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_point(NULL, F.model, (qd_linpoint *)(void *)F.blob, "q"));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_point(F.ctx, NULL, (qd_linpoint *)(void *)F.blob, "q"));
    reset(&F);
    /* pt NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_point(F.ctx, F.model, NULL, "q"));
    reset(&F);
    /* ---- qd_conlin_start */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_start(NULL, F.eom, F.model, (qd_linpoint *)(void *)F.blob, "q", NULL));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_start(F.ctx, NULL, F.model, (qd_linpoint *)(void *)F.blob, "q", NULL));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_start(F.ctx, F.eom, NULL, (qd_linpoint *)(void *)F.blob, "q", NULL));
    reset(&F);
    /* pt NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_start(F.ctx, F.eom, F.model, NULL, "q", NULL));
    reset(&F);
    /* about NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_start(F.ctx, F.eom, F.model, (qd_linpoint *)(void *)F.blob, NULL, NULL));
    reset(&F);
    /* choice NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_start(F.ctx, F.eom, F.model, (qd_linpoint *)(void *)F.blob, "q", NULL));
    reset(&F);
    /* ---- qd_conlin_require_ignorable */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_require_ignorable(NULL, NULL, "q"));
    reset(&F);
    /* c NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_require_ignorable(F.ctx, NULL, "q"));
    reset(&F);
    /* names NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_require_ignorable(F.ctx, NULL, NULL));
    reset(&F);
    /* ---- qd_conlin_scan_run */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_scan_run(NULL, F.eom, F.model, (qd_linpoint *)(void *)F.blob, "q", "q", "q", 1, 1, 1, (qd_conlin_scan *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_scan_run(F.ctx, NULL, F.model, (qd_linpoint *)(void *)F.blob, "q", "q", "q", 1, 1, 1, (qd_conlin_scan *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_scan_run(F.ctx, F.eom, NULL, (qd_linpoint *)(void *)F.blob, "q", "q", "q", 1, 1, 1, (qd_conlin_scan *)(void *)F.blob));
    reset(&F);
    /* pt NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_scan_run(F.ctx, F.eom, F.model, NULL, "q", "q", "q", 1, 1, 1, (qd_conlin_scan *)(void *)F.blob));
    reset(&F);
    /* name NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_scan_run(F.ctx, F.eom, F.model, (qd_linpoint *)(void *)F.blob, "q", "q", NULL, 1, 1, 1, (qd_conlin_scan *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_scan_run(F.ctx, F.eom, F.model, (qd_linpoint *)(void *)F.blob, "q", "q", "q", 1, 1, 1, NULL));
    reset(&F);
    /* ---- qd_conlin_scan_free */
    /* s NULL */
    qd_conlin_scan_free(NULL);
    reset(&F);
    /* ---- qd_conlin_print */
    /* c NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_print(NULL, false, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_print(NULL, false, NULL));
    reset(&F);
    /* ---- qd_conlin_render */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_render(NULL, NULL, NULL, (qd_ss_format){0}, &F.buf));
    reset(&F);
    /* c NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_render(F.ctx, NULL, NULL, (qd_ss_format){0}, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_render(F.ctx, NULL, NULL, (qd_ss_format){0}, NULL));
    reset(&F);
    /* ---- qd_conlin_modes_print */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_modes_print(NULL, NULL, false, &F.buf));
    reset(&F);
    /* c NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_modes_print(F.ctx, NULL, false, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_modes_print(F.ctx, NULL, false, NULL));
    reset(&F);
    /* ---- qd_conlin_needed */
    /* e NULL */
    assert_true(qd_conlin_needed(NULL) == 0);
    reset(&F);
    /* ---- qd_conlin_scan_print */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_scan_print(NULL, "q", false, &F.buf));
    reset(&F);
    /* name NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_scan_print(NULL, NULL, false, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_scan_print(NULL, "q", false, NULL));
    reset(&F);
    teardown(&F);
}

static void null_constrained(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_constrained_linear_about */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_linear_about(NULL, F.eom, 1, (const qd_expr * const *)F.e, F.d, F.z, NULL));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_linear_about(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, F.z, NULL));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_linear_about(F.ctx, F.eom, 1, NULL, F.d, F.z, NULL));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_linear_about(F.ctx, F.eom, 1, (const qd_expr * const *)F.e, NULL, F.z, NULL));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_linear_about(F.ctx, F.eom, 1, (const qd_expr * const *)F.e, F.d, F.z, NULL));
    reset(&F);
    /* ---- qd_constrained_linear_free */
    /* c NULL */
    qd_constrained_linear_free(NULL);
    reset(&F);
    /* ---- qd_constrained_state_matrix */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_state_matrix(NULL, NULL, F.d));
    reset(&F);
    /* c NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_state_matrix(F.ctx, NULL, F.d));
    reset(&F);
    /* A NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_state_matrix(F.ctx, NULL, NULL));
    reset(&F);
    /* ---- qd_constrained_input_matrix */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_input_matrix(NULL, F.eom, NULL, 1, (const qd_expr * const *)F.e, 1, (const qd_expr * const *)F.e, F.d, F.d));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_input_matrix(F.ctx, NULL, NULL, 1, (const qd_expr * const *)F.e, 1, (const qd_expr * const *)F.e, F.d, F.d));
    reset(&F);
    /* c NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_input_matrix(F.ctx, F.eom, NULL, 1, (const qd_expr * const *)F.e, 1, (const qd_expr * const *)F.e, F.d, F.d));
    reset(&F);
    /* u NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_input_matrix(F.ctx, F.eom, NULL, 1, NULL, 1, (const qd_expr * const *)F.e, F.d, F.d));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_input_matrix(F.ctx, F.eom, NULL, 1, (const qd_expr * const *)F.e, 1, NULL, F.d, F.d));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_input_matrix(F.ctx, F.eom, NULL, 1, (const qd_expr * const *)F.e, 1, (const qd_expr * const *)F.e, NULL, F.d));
    reset(&F);
    /* B NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_input_matrix(F.ctx, F.eom, NULL, 1, (const qd_expr * const *)F.e, 1, (const qd_expr * const *)F.e, F.d, NULL));
    reset(&F);
    /* ---- qd_constrained_at_solve */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_at_solve(NULL, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, F.z, false, NULL));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_at_solve(F.ctx, NULL, F.model, 1, (const qd_expr * const *)F.e, F.d, F.z, false, NULL));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_at_solve(F.ctx, F.eom, NULL, 1, (const qd_expr * const *)F.e, F.d, F.z, false, NULL));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_at_solve(F.ctx, F.eom, F.model, 1, NULL, F.d, F.z, false, NULL));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_at_solve(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, NULL, F.z, false, NULL));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_at_solve(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, F.z, false, NULL));
    reset(&F);
    /* ---- qd_constrained_at_free */
    /* a NULL */
    qd_constrained_at_free(NULL);
    reset(&F);
    /* ---- qd_constrained_indep_read */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_indep_read(NULL, F.eom, "q", F.z));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_indep_read(F.ctx, NULL, "q", F.z));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_indep_read(F.ctx, F.eom, NULL, F.z));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_indep_read(F.ctx, F.eom, "q", NULL));
    reset(&F);
    /* ---- qd_constrained_modes_print */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_modes_print(NULL, F.eom, NULL, NULL, false, &F.buf));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_modes_print(F.ctx, NULL, NULL, NULL, false, &F.buf));
    reset(&F);
    /* c NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_modes_print(F.ctx, F.eom, NULL, NULL, false, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_modes_print(F.ctx, F.eom, NULL, NULL, false, NULL));
    reset(&F);
    /* ---- qd_constrained_equilibria_find */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_equilibria_find(NULL, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, (qd_equilibria *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_equilibria_find(F.ctx, NULL, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, (qd_equilibria *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_equilibria_find(F.ctx, F.eom, NULL, 1, (const qd_expr * const *)F.e, F.d, NULL, (qd_equilibria *)(void *)F.blob));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_equilibria_find(F.ctx, F.eom, F.model, 1, NULL, F.d, NULL, (qd_equilibria *)(void *)F.blob));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_equilibria_find(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, NULL, NULL, (qd_equilibria *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_constrained_equilibria_find(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, NULL));
    reset(&F);
    teardown(&F);
}

static void null_contour(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_contour_grid */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_contour_grid(NULL, 1, 1, F.d, 1, 1, 1, 1, 1, (qd_contour *)(void *)F.blob));
    reset(&F);
    /* f NULL */
    assert_int_equal(QD_ERR_ARG, qd_contour_grid(F.ctx, 1, 1, NULL, 1, 1, 1, 1, 1, (qd_contour *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_contour_grid(F.ctx, 1, 1, F.d, 1, 1, 1, 1, 1, NULL));
    reset(&F);
    /* ---- qd_contour_free */
    /* c NULL */
    qd_contour_free(NULL);
    reset(&F);
    teardown(&F);
}

static void null_control(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_care_solve */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_care_solve(NULL, 1, 1, F.d, F.d, F.d, F.d, (qd_care_result *)(void *)F.blob));
    reset(&F);
    /* A NULL */
    assert_int_equal(QD_ERR_ARG, qd_care_solve(F.ctx, 1, 1, NULL, F.d, F.d, F.d, (qd_care_result *)(void *)F.blob));
    reset(&F);
    /* B NULL */
    assert_int_equal(QD_ERR_ARG, qd_care_solve(F.ctx, 1, 1, F.d, NULL, F.d, F.d, (qd_care_result *)(void *)F.blob));
    reset(&F);
    /* Q NULL */
    assert_int_equal(QD_ERR_ARG, qd_care_solve(F.ctx, 1, 1, F.d, F.d, NULL, F.d, (qd_care_result *)(void *)F.blob));
    reset(&F);
    /* R NULL */
    assert_int_equal(QD_ERR_ARG, qd_care_solve(F.ctx, 1, 1, F.d, F.d, F.d, NULL, (qd_care_result *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_care_solve(F.ctx, 1, 1, F.d, F.d, F.d, F.d, NULL));
    reset(&F);
    /* ---- qd_care_result_free */
    /* r NULL */
    qd_care_result_free(NULL);
    reset(&F);
    /* ---- qd_lqr_weights_read */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_lqr_weights_read(NULL, "q", 1, 1, F.d, F.d));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_lqr_weights_read(F.ctx, NULL, 1, 1, F.d, F.d));
    reset(&F);
    /* Q NULL */
    assert_int_equal(QD_ERR_ARG, qd_lqr_weights_read(F.ctx, "q", 1, 1, NULL, F.d));
    reset(&F);
    /* R NULL */
    assert_int_equal(QD_ERR_ARG, qd_lqr_weights_read(F.ctx, "q", 1, 1, F.d, NULL));
    reset(&F);
    /* ---- qd_matrix_read */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_matrix_read(NULL, "q", (qd_matrix *)(void *)F.blob));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_matrix_read(F.ctx, NULL, (qd_matrix *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_matrix_read(F.ctx, "q", NULL));
    reset(&F);
    /* ---- qd_matrix_free */
    /* m NULL */
    qd_matrix_free(NULL);
    reset(&F);
    /* ---- qd_lqr_system_read */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_lqr_system_read(NULL, "q", "q", "q", (qd_lqr_system *)(void *)F.blob));
    reset(&F);
    /* A NULL */
    assert_int_equal(QD_ERR_ARG, qd_lqr_system_read(F.ctx, NULL, "q", "q", (qd_lqr_system *)(void *)F.blob));
    reset(&F);
    /* B NULL */
    assert_int_equal(QD_ERR_ARG, qd_lqr_system_read(F.ctx, "q", NULL, "q", (qd_lqr_system *)(void *)F.blob));
    reset(&F);
    /* weights NULL */
    assert_int_equal(QD_ERR_ARG, qd_lqr_system_read(F.ctx, "q", "q", NULL, (qd_lqr_system *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_lqr_system_read(F.ctx, "q", "q", "q", NULL));
    reset(&F);
    /* ---- qd_lqr_system_free */
    /* s NULL */
    qd_lqr_system_free(NULL);
    reset(&F);
    /* ---- qd_lqr_design */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_lqr_design(NULL, NULL, "q", (qd_care_result *)(void *)F.blob));
    reset(&F);
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_lqr_design(F.ctx, NULL, "q", (qd_care_result *)(void *)F.blob));
    reset(&F);
    /* weights NULL */
    assert_int_equal(QD_ERR_ARG, qd_lqr_design(F.ctx, NULL, NULL, (qd_care_result *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_lqr_design(F.ctx, NULL, "q", NULL));
    reset(&F);
    /* ---- qd_lqr_feedback */
    /* ctx NULL */
    assert_null(qd_lqr_feedback(NULL, NULL, NULL, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, 1));
    reset(&F);
    /* s NULL */
    assert_null(qd_lqr_feedback(F.ctx, NULL, NULL, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, 1));
    reset(&F);
    /* ---- qd_lqr_print */
    /* r NULL */
    assert_int_equal(QD_ERR_ARG, qd_lqr_print(NULL, NULL, (qd_lqr_format){0}, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_lqr_print(NULL, NULL, (qd_lqr_format){0}, NULL));
    reset(&F);
    /* ---- qd_lqr_json */
    /* j NULL */
    qd_lqr_json(NULL, NULL, NULL);
    reset(&F);
    teardown(&F);
}

static void null_equilibria(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_eq_kind_name */
    /* no pointer argument */
    /* ---- qd_equilibria_default_box */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibria_default_box(NULL, F.eom, F.model, F.b, F.d, F.d));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibria_default_box(F.ctx, NULL, F.model, F.b, F.d, F.d));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibria_default_box(F.ctx, F.eom, NULL, F.b, F.d, F.d));
    reset(&F);
    /* angle NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibria_default_box(F.ctx, F.eom, F.model, NULL, F.d, F.d));
    reset(&F);
    /* lo NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibria_default_box(F.ctx, F.eom, F.model, F.b, NULL, F.d));
    reset(&F);
    /* hi NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibria_default_box(F.ctx, F.eom, F.model, F.b, F.d, NULL));
    reset(&F);
    /* ---- qd_equilibria_find */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibria_find(NULL, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, (qd_equilibria *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibria_find(F.ctx, NULL, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, (qd_equilibria *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibria_find(F.ctx, F.eom, NULL, 1, (const qd_expr * const *)F.e, F.d, NULL, (qd_equilibria *)(void *)F.blob));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibria_find(F.ctx, F.eom, F.model, 1, NULL, F.d, NULL, (qd_equilibria *)(void *)F.blob));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibria_find(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, NULL, NULL, (qd_equilibria *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibria_find(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, NULL));
    reset(&F);
    /* ---- qd_equilibria_free */
    /* r NULL */
    qd_equilibria_free(NULL);
    reset(&F);
    /* ---- qd_equilibria_find_text */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibria_find_text(NULL, NULL, "q", "q", (qd_equilibria *)(void *)F.blob, (const char * *)F.names));
    reset(&F);
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibria_find_text(F.ctx, NULL, "q", "q", (qd_equilibria *)(void *)F.blob, (const char * *)F.names));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibria_find_text(F.ctx, NULL, "q", "q", NULL, (const char * *)F.names));
    reset(&F);
    /* ---- qd_equilibria_choose */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibria_choose(NULL, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, (qd_equilibrium_choice *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibria_choose(F.ctx, NULL, F.model, 1, (const qd_expr * const *)F.e, F.d, (qd_equilibrium_choice *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibria_choose(F.ctx, F.eom, NULL, 1, (const qd_expr * const *)F.e, F.d, (qd_equilibrium_choice *)(void *)F.blob));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibria_choose(F.ctx, F.eom, F.model, 1, NULL, F.d, (qd_equilibrium_choice *)(void *)F.blob));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibria_choose(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, NULL, (qd_equilibrium_choice *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibria_choose(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL));
    reset(&F);
    /* ---- qd_equilibrium_choice_free */
    /* c NULL */
    qd_equilibrium_choice_free(NULL);
    reset(&F);
    /* ---- qd_eq_chosen_name */
    /* no pointer argument */
    /* ---- qd_eq_chosen_code */
    /* no pointer argument */
    /* ---- qd_equilibrium_put_value */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibrium_put_value(NULL, NULL, 1, &F.buf));
    reset(&F);
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibrium_put_value(F.ctx, NULL, 1, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibrium_put_value(F.ctx, NULL, 1, NULL));
    reset(&F);
    /* ---- qd_equilibria_print */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibria_print(NULL, F.eom, NULL, false, &F.buf));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibria_print(F.ctx, NULL, NULL, false, &F.buf));
    reset(&F);
    /* eq NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibria_print(F.ctx, F.eom, NULL, false, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibria_print(F.ctx, F.eom, NULL, false, NULL));
    reset(&F);
    /* ---- qd_equilibrium_choice_note */
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibrium_choice_note(NULL, NULL, &F.buf));
    reset(&F);
    /* c NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibrium_choice_note(F.eom, NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_equilibrium_choice_note(F.eom, NULL, NULL));
    reset(&F);
    /* ---- qd_eom_rest_residual */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_rest_residual(NULL, F.eom, 1, (const qd_expr * const *)F.e, F.d, F.d));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_rest_residual(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, F.d));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_rest_residual(F.ctx, F.eom, 1, NULL, F.d, F.d));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_rest_residual(F.ctx, F.eom, 1, (const qd_expr * const *)F.e, NULL, F.d));
    reset(&F);
    /* res NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_rest_residual(F.ctx, F.eom, 1, (const qd_expr * const *)F.e, F.d, NULL));
    reset(&F);
    /* ---- qd_equilibrium_exact_in_parameters */
    /* ctx NULL */
    assert_true(qd_equilibrium_exact_in_parameters(NULL, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, (const qd_expr * const *)F.e) == 0);
    reset(&F);
    /* e NULL */
    assert_true(qd_equilibrium_exact_in_parameters(F.ctx, NULL, F.model, 1, (const qd_expr * const *)F.e, F.d, (const qd_expr * const *)F.e) == 0);
    reset(&F);
    /* m NULL */
    assert_true(qd_equilibrium_exact_in_parameters(F.ctx, F.eom, NULL, 1, (const qd_expr * const *)F.e, F.d, (const qd_expr * const *)F.e) == 0);
    reset(&F);
    /* syms NULL */
    assert_true(qd_equilibrium_exact_in_parameters(F.ctx, F.eom, F.model, 1, NULL, F.d, (const qd_expr * const *)F.e) == 0);
    reset(&F);
    /* vals NULL */
    assert_true(qd_equilibrium_exact_in_parameters(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, NULL, (const qd_expr * const *)F.e) == 0);
    reset(&F);
    /* q0 NULL */
    assert_true(qd_equilibrium_exact_in_parameters(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL) == 0);
    reset(&F);
    /* ---- qd_speeds_equilibria_find */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_equilibria_find(NULL, NULL, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, (qd_speeds_equilibria *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_equilibria_find(F.ctx, NULL, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, (qd_speeds_equilibria *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_equilibria_find(F.ctx, NULL, NULL, 1, (const qd_expr * const *)F.e, F.d, NULL, (qd_speeds_equilibria *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_equilibria_find(F.ctx, NULL, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, NULL));
    reset(&F);
    /* ---- qd_speeds_equilibria_free */
    /* r NULL */
    qd_speeds_equilibria_free(NULL);
    reset(&F);
    /* ---- qd_speeds_equilibria_choose */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_equilibria_choose(NULL, NULL, F.model, 1, (const qd_expr * const *)F.e, F.d, F.b));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_equilibria_choose(F.ctx, NULL, F.model, 1, (const qd_expr * const *)F.e, F.d, F.b));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_equilibria_choose(F.ctx, NULL, NULL, 1, (const qd_expr * const *)F.e, F.d, F.b));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_equilibria_choose(F.ctx, NULL, F.model, 1, NULL, F.d, F.b));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_equilibria_choose(F.ctx, NULL, F.model, 1, (const qd_expr * const *)F.e, NULL, F.b));
    reset(&F);
    /* found NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_equilibria_choose(F.ctx, NULL, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL));
    reset(&F);
    /* ---- qd_speeds_equilibria_print */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_equilibria_print(NULL, NULL, NULL, false, &F.buf));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_equilibria_print(F.ctx, NULL, NULL, false, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_equilibria_print(F.ctx, NULL, NULL, false, NULL));
    reset(&F);
    teardown(&F);
}

static void null_eval(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_prog_new */
    /* no pointer argument */
    /* ---- qd_prog_free */
    /* no pointer argument */
    /* ---- qd_prog_run */
    /* no pointer argument */
    /* ---- qd_prog_work_size */
    /* p NULL */
    assert_true(qd_prog_work_size(NULL) == 0);
    reset(&F);
    /* ---- qd_prog_work_init */
    /* p NULL */
    qd_prog_work_init(NULL, F.d);
    reset(&F);
    /* work NULL */
    qd_prog_work_init(F.prog, NULL);
    reset(&F);
    /* ---- qd_prog_eval */
    /* p NULL */
    qd_prog_eval(NULL, F.d, F.d, F.d);
    reset(&F);
    /* work NULL */
    qd_prog_eval(F.prog, NULL, F.d, F.d);
    reset(&F);
    /* in NULL */
    qd_prog_eval(F.prog, F.d, NULL, F.d);
    reset(&F);
    /* out NULL */
    qd_prog_eval(F.prog, F.d, F.d, NULL);
    reset(&F);
    /* ---- qd_prog_ninstr */
    /* no pointer argument */
    /* ---- qd_prog_jit */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_prog_jit(NULL, F.prog));
    reset(&F);
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_prog_jit(F.ctx, NULL));
    reset(&F);
    /* ---- qd_prog_jitted */
    /* p NULL */
    assert_true(qd_prog_jitted(NULL) == 0);
    reset(&F);
    teardown(&F);
}

static void null_expr(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_ctx_new */
    /* no pointer argument */
    /* ---- qd_ctx_free */
    /* ctx NULL */
    qd_ctx_free(NULL);
    reset(&F);
    /* ---- qd_ctx_new_with */
    /* no pointer argument */
    /* ---- qd_ctx_status */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_ctx_status(NULL));
    reset(&F);
    /* ---- qd_ctx_message */
    /* ctx NULL */
    (void)qd_ctx_message(NULL);
    reset(&F);
    /* ---- qd_ctx_diag */
    /* ctx NULL */
    assert_null(qd_ctx_diag(NULL));
    reset(&F);
    /* ---- qd_ctx_clear_error */
    /* ctx NULL */
    qd_ctx_clear_error(NULL);
    reset(&F);
    /* ---- qd_ctx_error */
    /* ctx NULL */
    qd_ctx_error(NULL, (qd_status){0}, "q");
    reset(&F);
    /* fmt NULL */
    qd_ctx_error(F.ctx, (qd_status){0}, NULL);
    reset(&F);
    /* ---- qd_ctx_error_about */
    /* ctx NULL */
    qd_ctx_error_about(NULL, (qd_subject){0}, 1, "q", (qd_reason){0}, "q");
    reset(&F);
    /* ---- qd_ctx_error_at */
    /* ctx NULL */
    qd_ctx_error_at(NULL, "q", 1, 1);
    reset(&F);
    /* text NULL */
    qd_ctx_error_at(F.ctx, NULL, 1, 1);
    reset(&F);
    /* ---- qd_ctx_node_count */
    /* ctx NULL */
    assert_true(qd_ctx_node_count(NULL) == 0);
    reset(&F);
    /* ---- qd_ctx_set_progress */
    /* ctx NULL */
    qd_ctx_set_progress(NULL, NULL, NULL);
    reset(&F);
    /* ---- qd_int */
    /* ctx NULL */
    assert_null(qd_int(NULL, 1));
    reset(&F);
    /* ---- qd_rat */
    /* ctx NULL */
    assert_null(qd_rat(NULL, 1, 1));
    reset(&F);
    /* ---- qd_rat_str */
    /* ctx NULL */
    assert_null(qd_rat_str(NULL, "q"));
    reset(&F);
    /* text NULL */
    assert_null(qd_rat_str(F.ctx, NULL));
    reset(&F);
    /* ---- qd_float */
    /* ctx NULL */
    assert_null(qd_float(NULL, 1));
    reset(&F);
    /* ---- qd_const */
    /* ctx NULL */
    assert_null(qd_const(NULL, (qd_constant){0}));
    reset(&F);
    /* ---- qd_symbol */
    /* ctx NULL */
    assert_null(qd_symbol(NULL, "q"));
    reset(&F);
    /* name NULL */
    assert_null(qd_symbol(F.ctx, NULL));
    reset(&F);
    /* ---- qd_param */
    /* ctx NULL */
    assert_null(qd_param(NULL, "q"));
    reset(&F);
    /* name NULL */
    assert_null(qd_param(F.ctx, NULL));
    reset(&F);
    /* ---- qd_symbol_positive */
    /* ctx NULL */
    assert_null(qd_symbol_positive(NULL, "q", (qd_role){0}));
    reset(&F);
    /* name NULL */
    assert_null(qd_symbol_positive(F.ctx, NULL, (qd_role){0}));
    reset(&F);
    /* ---- qd_symbol_is_positive */
    /* e NULL */
    assert_true(qd_symbol_is_positive(NULL) == 0);
    reset(&F);
    /* ---- qd_time */
    /* ctx NULL */
    assert_null(qd_time(NULL));
    reset(&F);
    /* ---- qd_coord */
    /* ctx NULL */
    assert_null(qd_coord(NULL, "q"));
    reset(&F);
    /* name NULL */
    assert_null(qd_coord(F.ctx, NULL));
    reset(&F);
    /* ---- qd_jet */
    /* ctx NULL */
    assert_null(qd_jet(NULL, F.q, 1));
    reset(&F);
    /* coord NULL */
    assert_null(qd_jet(F.ctx, NULL, 1));
    reset(&F);
    /* ---- qd_lookup */
    /* ctx NULL */
    assert_null(qd_lookup(NULL, "q"));
    reset(&F);
    /* name NULL */
    assert_null(qd_lookup(F.ctx, NULL));
    reset(&F);
    /* ---- qd_add */
    /* ctx NULL */
    assert_null(qd_add(NULL, F.q, F.q));
    reset(&F);
    /* a NULL */
    assert_null(qd_add(F.ctx, NULL, F.q));
    reset(&F);
    /* b NULL */
    assert_null(qd_add(F.ctx, F.q, NULL));
    reset(&F);
    /* ---- qd_sub */
    /* ctx NULL */
    assert_null(qd_sub(NULL, F.q, F.q));
    reset(&F);
    /* a NULL */
    assert_null(qd_sub(F.ctx, NULL, F.q));
    reset(&F);
    /* b NULL */
    assert_null(qd_sub(F.ctx, F.q, NULL));
    reset(&F);
    /* ---- qd_mul */
    /* ctx NULL */
    assert_null(qd_mul(NULL, F.q, F.q));
    reset(&F);
    /* a NULL */
    assert_null(qd_mul(F.ctx, NULL, F.q));
    reset(&F);
    /* b NULL */
    assert_null(qd_mul(F.ctx, F.q, NULL));
    reset(&F);
    /* ---- qd_div */
    /* ctx NULL */
    assert_null(qd_div(NULL, F.q, F.q));
    reset(&F);
    /* a NULL */
    assert_null(qd_div(F.ctx, NULL, F.q));
    reset(&F);
    /* b NULL */
    assert_null(qd_div(F.ctx, F.q, NULL));
    reset(&F);
    /* ---- qd_neg */
    /* ctx NULL */
    assert_null(qd_neg(NULL, F.q));
    reset(&F);
    /* a NULL */
    assert_null(qd_neg(F.ctx, NULL));
    reset(&F);
    /* ---- qd_pow */
    /* ctx NULL */
    assert_null(qd_pow(NULL, F.q, F.q));
    reset(&F);
    /* base NULL */
    assert_null(qd_pow(F.ctx, NULL, F.q));
    reset(&F);
    /* exponent NULL */
    assert_null(qd_pow(F.ctx, F.q, NULL));
    reset(&F);
    /* ---- qd_powi */
    /* ctx NULL */
    assert_null(qd_powi(NULL, F.q, 1));
    reset(&F);
    /* base NULL */
    assert_null(qd_powi(F.ctx, NULL, 1));
    reset(&F);
    /* ---- qd_sqrt */
    /* ctx NULL */
    assert_null(qd_sqrt(NULL, F.q));
    reset(&F);
    /* a NULL */
    assert_null(qd_sqrt(F.ctx, NULL));
    reset(&F);
    /* ---- qd_add_n */
    /* ctx NULL */
    assert_null(qd_add_n(NULL, 1, (const qd_expr * const *)F.e));
    reset(&F);
    /* terms NULL */
    assert_null(qd_add_n(F.ctx, 1, NULL));
    reset(&F);
    /* ---- qd_mul_n */
    /* ctx NULL */
    assert_null(qd_mul_n(NULL, 1, (const qd_expr * const *)F.e));
    reset(&F);
    /* factors NULL */
    assert_null(qd_mul_n(F.ctx, 1, NULL));
    reset(&F);
    /* ---- qd_fn */
    /* ctx NULL */
    assert_null(qd_fn(NULL, (qd_func){0}, F.q));
    reset(&F);
    /* a NULL */
    assert_null(qd_fn(F.ctx, (qd_func){0}, NULL));
    reset(&F);
    /* ---- qd_fn2 */
    /* ctx NULL */
    assert_null(qd_fn2(NULL, (qd_func){0}, F.q, F.q));
    reset(&F);
    /* a NULL */
    assert_null(qd_fn2(F.ctx, (qd_func){0}, NULL, F.q));
    reset(&F);
    /* b NULL */
    assert_null(qd_fn2(F.ctx, (qd_func){0}, F.q, NULL));
    reset(&F);
    /* ---- qd_func_name */
    /* no pointer argument */
    /* ---- qd_func_from_name */
    /* name NULL */
    assert_true(qd_func_from_name(NULL, (qd_func *)(void *)F.blob) == 0);
    reset(&F);
    /* out NULL */
    assert_true(qd_func_from_name("q", NULL) == 0);
    reset(&F);
    /* ---- qd_ufunc */
    /* ctx NULL */
    assert_null(qd_ufunc(NULL, "q", 1, (const qd_expr * const *)F.e));
    reset(&F);
    /* name NULL */
    assert_null(qd_ufunc(F.ctx, NULL, 1, (const qd_expr * const *)F.e));
    reset(&F);
    /* ---- qd_uderiv */
    /* ctx NULL */
    assert_null(qd_uderiv(NULL, "q", 1, F.u, 1, (const qd_expr * const *)F.e));
    reset(&F);
    /* name NULL */
    assert_null(qd_uderiv(F.ctx, NULL, 1, F.u, 1, (const qd_expr * const *)F.e));
    reset(&F);
    /* slots NULL */
    assert_null(qd_uderiv(F.ctx, "q", 1, NULL, 1, (const qd_expr * const *)F.e));
    reset(&F);
    /* args NULL */
    assert_null(qd_uderiv(F.ctx, "q", 1, F.u, 1, NULL));
    reset(&F);
    /* ---- qd_expr_kind */
    /* e NULL */
    (void)qd_expr_kind(NULL);
    reset(&F);
    /* ---- qd_expr_nargs */
    /* e NULL */
    assert_true(qd_expr_nargs(NULL) == 0);
    reset(&F);
    /* ---- qd_expr_arg */
    /* e NULL */
    assert_null(qd_expr_arg(NULL, 1));
    reset(&F);
    /* ---- qd_expr_hash */
    /* e NULL */
    (void)qd_expr_hash(NULL);
    reset(&F);
    /* ---- qd_expr_cmp */
    /* a NULL */
    (void)qd_expr_cmp(NULL, F.q);
    reset(&F);
    /* b NULL */
    (void)qd_expr_cmp(F.q, NULL);
    reset(&F);
    /* ---- qd_expr_name */
    /* e NULL */
    assert_null(qd_expr_name(NULL));
    reset(&F);
    /* ---- qd_symbol_role */
    /* e NULL */
    (void)qd_symbol_role(NULL);
    reset(&F);
    /* ---- qd_symbol_order */
    /* e NULL */
    (void)qd_symbol_order(NULL);
    reset(&F);
    /* ---- qd_symbol_coord */
    /* e NULL */
    assert_null(qd_symbol_coord(NULL));
    reset(&F);
    /* ---- qd_expr_func */
    /* e NULL */
    (void)qd_expr_func(NULL);
    reset(&F);
    /* ---- qd_expr_constant */
    /* e NULL */
    (void)qd_expr_constant(NULL);
    reset(&F);
    /* ---- qd_uderiv_nslots */
    /* e NULL */
    assert_true(qd_uderiv_nslots(NULL) == 0);
    reset(&F);
    /* ---- qd_uderiv_slot */
    /* e NULL */
    (void)qd_uderiv_slot(NULL, 1);
    reset(&F);
    /* ---- qd_is_number */
    /* e NULL */
    assert_true(qd_is_number(NULL) == 0);
    reset(&F);
    /* ---- qd_is_zero */
    /* e NULL */
    assert_true(qd_is_zero(NULL) == 0);
    reset(&F);
    /* ---- qd_is_one */
    /* e NULL */
    assert_true(qd_is_one(NULL) == 0);
    reset(&F);
    /* ---- qd_is_integer */
    /* e NULL */
    assert_true(qd_is_integer(NULL) == 0);
    reset(&F);
    /* ---- qd_number_sign */
    /* e NULL */
    (void)qd_number_sign(NULL);
    reset(&F);
    /* ---- qd_number_value */
    /* e NULL */
    assert_true(isnan(qd_number_value(NULL)));
    reset(&F);
    /* ---- qd_rational_get */
    /* e NULL */
    assert_true(qd_rational_get(NULL, F.l, F.l) == 0);
    reset(&F);
    /* num NULL */
    assert_true(qd_rational_get(F.q, NULL, F.l) == 0);
    reset(&F);
    /* den NULL */
    assert_true(qd_rational_get(F.q, F.l, NULL) == 0);
    reset(&F);
    /* ---- qd_rational_str */
    /* ctx NULL */
    assert_null(qd_rational_str(NULL, F.q));
    reset(&F);
    /* e NULL */
    assert_null(qd_rational_str(F.ctx, NULL));
    reset(&F);
    /* ---- qd_has */
    /* e NULL */
    assert_true(qd_has(NULL, F.q) == 0);
    reset(&F);
    /* x NULL */
    assert_true(qd_has(F.q, NULL) == 0);
    reset(&F);
    /* ---- qd_free_symbols */
    /* ctx NULL */
    assert_true(qd_free_symbols(NULL, F.q, (const qd_expr * *)F.e, 1) == 0);
    reset(&F);
    /* e NULL */
    assert_true(qd_free_symbols(F.ctx, NULL, (const qd_expr * *)F.e, 1) == 0);
    reset(&F);
    /* ---- qd_diff */
    /* ctx NULL */
    assert_null(qd_diff(NULL, F.q, F.q));
    reset(&F);
    /* e NULL */
    assert_null(qd_diff(F.ctx, NULL, F.q));
    reset(&F);
    /* sym NULL */
    assert_null(qd_diff(F.ctx, F.q, NULL));
    reset(&F);
    /* ---- qd_diff_n */
    /* ctx NULL */
    assert_null(qd_diff_n(NULL, F.q, F.q, 1));
    reset(&F);
    /* e NULL */
    assert_null(qd_diff_n(F.ctx, NULL, F.q, 1));
    reset(&F);
    /* sym NULL */
    assert_null(qd_diff_n(F.ctx, F.q, NULL, 1));
    reset(&F);
    /* ---- qd_dt */
    /* ctx NULL */
    assert_null(qd_dt(NULL, F.q));
    reset(&F);
    /* e NULL */
    assert_null(qd_dt(F.ctx, NULL));
    reset(&F);
    /* ---- qd_subs */
    /* ctx NULL */
    assert_null(qd_subs(NULL, F.q, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e));
    reset(&F);
    /* e NULL */
    assert_null(qd_subs(F.ctx, NULL, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e));
    reset(&F);
    /* from NULL */
    assert_null(qd_subs(F.ctx, F.q, 1, NULL, (const qd_expr * const *)F.e));
    reset(&F);
    /* to NULL */
    assert_null(qd_subs(F.ctx, F.q, 1, (const qd_expr * const *)F.e, NULL));
    reset(&F);
    /* ---- qd_expand */
    /* ctx NULL */
    assert_null(qd_expand(NULL, F.q));
    reset(&F);
    /* e NULL */
    assert_null(qd_expand(F.ctx, NULL));
    reset(&F);
    /* ---- qd_expand_kept */
    /* ctx NULL */
    assert_null(qd_expand_kept(NULL, F.q));
    reset(&F);
    /* e NULL */
    assert_null(qd_expand_kept(F.ctx, NULL));
    reset(&F);
    /* ---- qd_linear_coeffs */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_linear_coeffs(NULL, F.q, 1, (const qd_expr * const *)F.e, (const qd_expr * *)F.e, (const qd_expr * *)F.e));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_linear_coeffs(F.ctx, NULL, 1, (const qd_expr * const *)F.e, (const qd_expr * *)F.e, (const qd_expr * *)F.e));
    reset(&F);
    /* xs NULL */
    assert_int_equal(QD_ERR_ARG, qd_linear_coeffs(F.ctx, F.q, 1, NULL, (const qd_expr * *)F.e, (const qd_expr * *)F.e));
    reset(&F);
    /* coeffs NULL */
    assert_int_equal(QD_ERR_ARG, qd_linear_coeffs(F.ctx, F.q, 1, (const qd_expr * const *)F.e, NULL, (const qd_expr * *)F.e));
    reset(&F);
    /* rest NULL */
    assert_int_equal(QD_ERR_ARG, qd_linear_coeffs(F.ctx, F.q, 1, (const qd_expr * const *)F.e, (const qd_expr * *)F.e, NULL));
    reset(&F);
    /* ---- qd_coeff */
    /* ctx NULL */
    assert_null(qd_coeff(NULL, F.q, F.q, 1));
    reset(&F);
    /* e NULL */
    assert_null(qd_coeff(F.ctx, NULL, F.q, 1));
    reset(&F);
    /* x NULL */
    assert_null(qd_coeff(F.ctx, F.q, NULL, 1));
    reset(&F);
    /* ---- qd_collect */
    /* ctx NULL */
    assert_null(qd_collect(NULL, F.q, F.q));
    reset(&F);
    /* e NULL */
    assert_null(qd_collect(F.ctx, NULL, F.q));
    reset(&F);
    /* x NULL */
    assert_null(qd_collect(F.ctx, F.q, NULL));
    reset(&F);
    /* ---- qd_simplify */
    /* ctx NULL */
    assert_null(qd_simplify(NULL, F.q));
    reset(&F);
    /* e NULL */
    assert_null(qd_simplify(F.ctx, NULL));
    reset(&F);
    /* ---- qd_trigsimp */
    /* ctx NULL */
    assert_null(qd_trigsimp(NULL, F.q));
    reset(&F);
    /* e NULL */
    assert_null(qd_trigsimp(F.ctx, NULL));
    reset(&F);
    /* ---- qd_cancel */
    /* ctx NULL */
    assert_null(qd_cancel(NULL, F.q));
    reset(&F);
    /* e NULL */
    assert_null(qd_cancel(F.ctx, NULL));
    reset(&F);
    /* ---- qd_factor_terms */
    /* ctx NULL */
    assert_null(qd_factor_terms(NULL, F.q));
    reset(&F);
    /* e NULL */
    assert_null(qd_factor_terms(F.ctx, NULL));
    reset(&F);
    /* ---- qd_count_ops */
    /* e NULL */
    assert_true(qd_count_ops(NULL) == 0);
    reset(&F);
    /* ---- qd_dag_size */
    /* ctx NULL */
    assert_true(qd_dag_size(NULL, F.q) == 0);
    reset(&F);
    /* e NULL */
    assert_true(qd_dag_size(F.ctx, NULL) == 0);
    reset(&F);
    /* ---- qd_integrate */
    /* ctx NULL */
    assert_null(qd_integrate(NULL, F.q, F.q));
    reset(&F);
    /* e NULL */
    assert_null(qd_integrate(F.ctx, NULL, F.q));
    reset(&F);
    /* x NULL */
    assert_null(qd_integrate(F.ctx, F.q, NULL));
    reset(&F);
    /* ---- qd_eval */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_eval(NULL, F.q, 1, (const qd_expr * const *)F.e, F.d, F.d));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_eval(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, F.d));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_eval(F.ctx, F.q, 1, (const qd_expr * const *)F.e, F.d, NULL));
    reset(&F);
    teardown(&F);
}

static void null_field(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_field_declared */
    /* text NULL */
    assert_true(qd_field_declared(NULL) == 0);
    reset(&F);
    /* ---- qd_field_parse */
    /* ctx NULL */
    assert_null(qd_field_parse(NULL, "q", NULL, (qd_diag *)(void *)F.blob));
    reset(&F);
    /* text NULL */
    assert_null(qd_field_parse(F.ctx, NULL, NULL, (qd_diag *)(void *)F.blob));
    reset(&F);
    /* ---- qd_field_free */
    /* f NULL */
    qd_field_free(NULL);
    reset(&F);
    /* ---- qd_field_model */
    /* f NULL */
    assert_null(qd_field_model(NULL));
    reset(&F);
    /* ---- qd_field_name */
    /* f NULL */
    assert_null(qd_field_name(NULL));
    reset(&F);
    /* ---- qd_field_space */
    /* f NULL */
    assert_null(qd_field_space(NULL));
    reset(&F);
    /* ---- qd_field_density */
    /* f NULL */
    assert_null(qd_field_density(NULL));
    reset(&F);
    /* ---- qd_field_interval */
    /* f NULL */
    assert_int_equal(QD_ERR_ARG, qd_field_interval(NULL, F.d, F.d));
    reset(&F);
    /* a NULL */
    assert_int_equal(QD_ERR_ARG, qd_field_interval(NULL, NULL, F.d));
    reset(&F);
    /* b NULL */
    assert_int_equal(QD_ERR_ARG, qd_field_interval(NULL, F.d, NULL));
    reset(&F);
    /* ---- qd_field_boundary */
    /* f NULL */
    (void)qd_field_boundary(NULL, 1);
    reset(&F);
    /* ---- qd_field_equation */
    /* ctx NULL */
    assert_null(qd_field_equation(NULL, NULL));
    reset(&F);
    /* f NULL */
    assert_null(qd_field_equation(F.ctx, NULL));
    reset(&F);
    /* ---- qd_field_modes_compute */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_field_modes_compute(NULL, NULL, NULL, (qd_field_modes *)(void *)F.blob));
    reset(&F);
    /* f NULL */
    assert_int_equal(QD_ERR_ARG, qd_field_modes_compute(F.ctx, NULL, NULL, (qd_field_modes *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_field_modes_compute(F.ctx, NULL, NULL, NULL));
    reset(&F);
    /* ---- qd_field_modes_free */
    /* r NULL */
    qd_field_modes_free(NULL);
    reset(&F);
    /* ---- qd_field_equation_print */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_field_equation_print(NULL, NULL, F.q, &F.buf));
    reset(&F);
    /* f NULL */
    assert_int_equal(QD_ERR_ARG, qd_field_equation_print(F.ctx, NULL, F.q, &F.buf));
    reset(&F);
    /* E NULL */
    assert_int_equal(QD_ERR_ARG, qd_field_equation_print(F.ctx, NULL, NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_field_equation_print(F.ctx, NULL, F.q, NULL));
    reset(&F);
    /* ---- qd_field_equation_json */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_field_equation_json(NULL, NULL, F.q, &F.buf));
    reset(&F);
    /* f NULL */
    assert_int_equal(QD_ERR_ARG, qd_field_equation_json(F.ctx, NULL, F.q, &F.buf));
    reset(&F);
    /* E NULL */
    assert_int_equal(QD_ERR_ARG, qd_field_equation_json(F.ctx, NULL, NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_field_equation_json(F.ctx, NULL, F.q, NULL));
    reset(&F);
    /* ---- qd_field_modes_print */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_field_modes_print(NULL, NULL, NULL, &F.buf));
    reset(&F);
    /* f NULL */
    assert_int_equal(QD_ERR_ARG, qd_field_modes_print(F.ctx, NULL, NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_field_modes_print(F.ctx, NULL, NULL, NULL));
    reset(&F);
    /* ---- qd_field_modes_json */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_field_modes_json(NULL, NULL, NULL, &F.buf));
    reset(&F);
    /* f NULL */
    assert_int_equal(QD_ERR_ARG, qd_field_modes_json(F.ctx, NULL, NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_field_modes_json(F.ctx, NULL, NULL, NULL));
    reset(&F);
    teardown(&F);
}

static void null_form(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_qform_reduce */
    /* ctx NULL */
    assert_null(qd_qform_reduce(NULL, F.q, 1, (const qd_expr * const *)F.e));
    reset(&F);
    /* phi NULL */
    assert_null(qd_qform_reduce(F.ctx, NULL, 1, (const qd_expr * const *)F.e));
    reset(&F);
    /* x NULL */
    assert_null(qd_qform_reduce(F.ctx, F.q, 1, NULL));
    reset(&F);
    /* ---- qd_qform_reduce_matrix */
    /* ctx NULL */
    assert_null(qd_qform_reduce_matrix(NULL, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e));
    reset(&F);
    /* a NULL */
    assert_null(qd_qform_reduce_matrix(F.ctx, 1, NULL, (const qd_expr * const *)F.e));
    reset(&F);
    /* x NULL */
    assert_null(qd_qform_reduce_matrix(F.ctx, 1, (const qd_expr * const *)F.e, NULL));
    reset(&F);
    /* ---- qd_qform_free */
    /* f NULL */
    qd_qform_free(NULL);
    reset(&F);
    /* ---- qd_qform_vars_read */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_qform_vars_read(NULL, "q", (const qd_expr * *)F.e, 1, F.z));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_qform_vars_read(F.ctx, NULL, (const qd_expr * *)F.e, 1, F.z));
    reset(&F);
    /* x NULL */
    assert_int_equal(QD_ERR_ARG, qd_qform_vars_read(F.ctx, "q", NULL, 1, F.z));
    reset(&F);
    /* n NULL */
    assert_int_equal(QD_ERR_ARG, qd_qform_vars_read(F.ctx, "q", (const qd_expr * *)F.e, 1, NULL));
    reset(&F);
    /* ---- qd_homogeneity */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_homogeneity(NULL, F.q, 1, (const qd_expr * const *)F.e, (qd_homog *)(void *)F.blob));
    reset(&F);
    /* f NULL */
    assert_int_equal(QD_ERR_ARG, qd_homogeneity(F.ctx, NULL, 1, (const qd_expr * const *)F.e, (qd_homog *)(void *)F.blob));
    reset(&F);
    /* x NULL */
    assert_int_equal(QD_ERR_ARG, qd_homogeneity(F.ctx, F.q, 1, NULL, (qd_homog *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_homogeneity(F.ctx, F.q, 1, (const qd_expr * const *)F.e, NULL));
    reset(&F);
    /* ---- qd_homog_verdict_name */
    /* no pointer argument */
    /* ---- qd_periods_reduce */
    /* ctx NULL */
    assert_null(qd_periods_reduce(NULL, F.q, 1, (const qd_expr * const *)F.e, 1, (const qd_expr * const *)F.e));
    reset(&F);
    /* x NULL */
    assert_null(qd_periods_reduce(F.ctx, F.q, 1, NULL, 1, (const qd_expr * const *)F.e));
    reset(&F);
    /* w NULL */
    assert_null(qd_periods_reduce(F.ctx, F.q, 1, (const qd_expr * const *)F.e, 1, NULL));
    reset(&F);
    /* ---- qd_periods_free */
    /* p NULL */
    qd_periods_free(NULL);
    reset(&F);
    /* ---- qd_periods_vectors_read */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_periods_vectors_read(NULL, "q", 1, F.z, NULL));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_periods_vectors_read(F.ctx, NULL, 1, F.z, NULL));
    reset(&F);
    /* g NULL */
    assert_int_equal(QD_ERR_ARG, qd_periods_vectors_read(F.ctx, "q", 1, NULL, NULL));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_periods_vectors_read(F.ctx, "q", 1, F.z, NULL));
    reset(&F);
    /* ---- qd_periods_vectors_free */
    /* w NULL */
    qd_periods_vectors_free(NULL);
    reset(&F);
    /* ---- qd_gram_schmidt */
    /* ctx NULL */
    assert_null(qd_gram_schmidt(NULL, 1, (const qd_expr * const *)F.e, 1, (const qd_expr * const *)F.e));
    reset(&F);
    /* a NULL */
    assert_null(qd_gram_schmidt(F.ctx, 1, (const qd_expr * const *)F.e, 1, NULL));
    reset(&F);
    /* ---- qd_gram_free */
    /* g NULL */
    qd_gram_free(NULL);
    reset(&F);
    /* ---- qd_fourier_series */
    /* ctx NULL */
    assert_null(qd_fourier_series(NULL, F.q, 1, (const qd_expr * const *)F.e));
    reset(&F);
    /* f NULL */
    assert_null(qd_fourier_series(F.ctx, NULL, 1, (const qd_expr * const *)F.e));
    reset(&F);
    /* x NULL */
    assert_null(qd_fourier_series(F.ctx, F.q, 1, NULL));
    reset(&F);
    /* ---- qd_fourier_free */
    /* f NULL */
    qd_fourier_free(NULL);
    reset(&F);
    /* ---- qd_change_vars */
    /* ctx NULL */
    assert_null(qd_change_vars(NULL, F.q, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e));
    reset(&F);
    /* x NULL */
    assert_null(qd_change_vars(F.ctx, F.q, 1, NULL, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e));
    reset(&F);
    /* y NULL */
    assert_null(qd_change_vars(F.ctx, F.q, 1, (const qd_expr * const *)F.e, NULL, (const qd_expr * const *)F.e));
    reset(&F);
    /* map NULL */
    assert_null(qd_change_vars(F.ctx, F.q, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, NULL));
    reset(&F);
    /* ---- qd_change_free */
    /* c NULL */
    qd_change_free(NULL);
    reset(&F);
    /* ---- qd_change_read */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_change_read(NULL, "q", 1, (const qd_expr * const *)F.e, (const qd_expr * *)F.e));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_change_read(F.ctx, NULL, 1, (const qd_expr * const *)F.e, (const qd_expr * *)F.e));
    reset(&F);
    /* x NULL */
    assert_int_equal(QD_ERR_ARG, qd_change_read(F.ctx, "q", 1, NULL, (const qd_expr * *)F.e));
    reset(&F);
    /* map NULL */
    assert_int_equal(QD_ERR_ARG, qd_change_read(F.ctx, "q", 1, (const qd_expr * const *)F.e, NULL));
    reset(&F);
    /* ---- qd_qform_positive_read */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_qform_positive_read(NULL, "q", (const qd_expr * *)F.e, 1, F.z));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_qform_positive_read(F.ctx, NULL, (const qd_expr * *)F.e, 1, F.z));
    reset(&F);
    /* x NULL */
    assert_int_equal(QD_ERR_ARG, qd_qform_positive_read(F.ctx, "q", NULL, 1, F.z));
    reset(&F);
    /* n NULL */
    assert_int_equal(QD_ERR_ARG, qd_qform_positive_read(F.ctx, "q", (const qd_expr * *)F.e, 1, NULL));
    reset(&F);
    teardown(&F);
}

static void null_hamilton(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_ham_derive */
    /* ctx NULL */
    assert_null(qd_ham_derive(NULL, F.model, F.eom));
    reset(&F);
    /* m NULL */
    assert_null(qd_ham_derive(F.ctx, NULL, F.eom));
    reset(&F);
    /* ---- qd_ham_free */
    /* h NULL */
    qd_ham_free(NULL);
    reset(&F);
    /* ---- qd_ham2_derive */
    /* ctx NULL */
    assert_null(qd_ham2_derive(NULL, F.model, F.eom));
    reset(&F);
    /* m NULL */
    assert_null(qd_ham2_derive(F.ctx, NULL, F.eom));
    reset(&F);
    /* e NULL */
    assert_null(qd_ham2_derive(F.ctx, F.model, NULL));
    reset(&F);
    /* ---- qd_legendre_inverse */
    /* ctx NULL */
    assert_null(qd_legendre_inverse(NULL, F.model));
    reset(&F);
    /* m NULL */
    assert_null(qd_legendre_inverse(F.ctx, NULL));
    reset(&F);
    /* ---- qd_legendre_inverse_p */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_legendre_inverse_p(NULL, F.model, (const qd_expr * *)F.e, (const qd_expr * *)F.e));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_legendre_inverse_p(F.ctx, NULL, (const qd_expr * *)F.e, (const qd_expr * *)F.e));
    reset(&F);
    /* L NULL */
    assert_int_equal(QD_ERR_ARG, qd_legendre_inverse_p(F.ctx, F.model, (const qd_expr * *)F.e, NULL));
    reset(&F);
    /* ---- qd_ham_regular */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_ham_regular(NULL, F.model));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_ham_regular(F.ctx, NULL));
    reset(&F);
    /* ---- qd_ham_velocities_at */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_ham_velocities_at(NULL, NULL, 1, (const qd_expr * const *)F.e, F.d, F.d));
    reset(&F);
    /* h NULL */
    assert_int_equal(QD_ERR_ARG, qd_ham_velocities_at(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, F.d));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_ham_velocities_at(F.ctx, NULL, 1, NULL, F.d, F.d));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_ham_velocities_at(F.ctx, NULL, 1, (const qd_expr * const *)F.e, NULL, F.d));
    reset(&F);
    /* qd_out NULL */
    assert_int_equal(QD_ERR_ARG, qd_ham_velocities_at(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, NULL));
    reset(&F);
    /* ---- qd_ham_require_closed */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_ham_require_closed(NULL, NULL, "q"));
    reset(&F);
    /* h NULL */
    assert_int_equal(QD_ERR_ARG, qd_ham_require_closed(F.ctx, NULL, "q"));
    reset(&F);
    /* what NULL */
    assert_int_equal(QD_ERR_ARG, qd_ham_require_closed(F.ctx, NULL, NULL));
    reset(&F);
    teardown(&F);
}

static void null_hj(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_hj_derive */
    /* ctx NULL */
    assert_null(qd_hj_derive(NULL, F.model, NULL));
    reset(&F);
    /* m NULL */
    assert_null(qd_hj_derive(F.ctx, NULL, NULL));
    reset(&F);
    /* ---- qd_hj_free */
    /* h NULL */
    qd_hj_free(NULL);
    reset(&F);
    /* ---- qd_hj_solve */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_hj_solve(NULL, NULL));
    reset(&F);
    /* h NULL */
    assert_int_equal(QD_ERR_ARG, qd_hj_solve(F.ctx, NULL));
    reset(&F);
    /* ---- qd_hj_print */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_hj_print(NULL, NULL, F.model, "q", (qd_format){0}, &F.buf));
    reset(&F);
    /* h NULL */
    assert_int_equal(QD_ERR_ARG, qd_hj_print(F.ctx, NULL, F.model, "q", (qd_format){0}, &F.buf));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_hj_print(F.ctx, NULL, NULL, "q", (qd_format){0}, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_hj_print(F.ctx, NULL, F.model, "q", (qd_format){0}, NULL));
    reset(&F);
    /* ---- qd_hj_json */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_hj_json(NULL, NULL, "q", &F.buf));
    reset(&F);
    /* h NULL */
    assert_int_equal(QD_ERR_ARG, qd_hj_json(F.ctx, NULL, "q", &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_hj_json(F.ctx, NULL, "q", NULL));
    reset(&F);
    teardown(&F);
}

static void null_impulse(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_impulse_solve */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_impulse_solve(NULL, F.model, NULL, (qd_impulse *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_impulse_solve(F.ctx, NULL, NULL, (qd_impulse *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_impulse_solve(F.ctx, F.model, NULL, NULL));
    reset(&F);
    /* ---- qd_impulse_free */
    /* r NULL */
    qd_impulse_free(NULL);
    reset(&F);
    /* ---- qd_impulse_state_read */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_impulse_state_read(NULL, F.model, "q", (const qd_expr * *)F.e, (const qd_expr * *)F.e, (const qd_expr * *)F.e));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_impulse_state_read(F.ctx, NULL, "q", (const qd_expr * *)F.e, (const qd_expr * *)F.e, (const qd_expr * *)F.e));
    reset(&F);
    /* q NULL */
    assert_int_equal(QD_ERR_ARG, qd_impulse_state_read(F.ctx, F.model, "q", NULL, (const qd_expr * *)F.e, (const qd_expr * *)F.e));
    reset(&F);
    /* qd NULL */
    assert_int_equal(QD_ERR_ARG, qd_impulse_state_read(F.ctx, F.model, "q", (const qd_expr * *)F.e, NULL, (const qd_expr * *)F.e));
    reset(&F);
    /* t NULL */
    assert_int_equal(QD_ERR_ARG, qd_impulse_state_read(F.ctx, F.model, "q", (const qd_expr * *)F.e, (const qd_expr * *)F.e, NULL));
    reset(&F);
    teardown(&F);
}

static void null_integrals(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_integrals_derive */
    /* ctx NULL */
    assert_null(qd_integrals_derive(NULL, F.model, F.eom, NULL));
    reset(&F);
    /* m NULL */
    assert_null(qd_integrals_derive(F.ctx, NULL, F.eom, NULL));
    reset(&F);
    /* e NULL */
    assert_null(qd_integrals_derive(F.ctx, F.model, NULL, NULL));
    reset(&F);
    /* ---- qd_integrals_free */
    /* I NULL */
    qd_integrals_free(NULL);
    reset(&F);
    /* ---- qd_integrals_cyclic */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_integrals_cyclic(NULL, F.model, F.eom, (qd_int_cyclic *)(void *)F.blob, F.z));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_integrals_cyclic(F.ctx, NULL, F.eom, (qd_int_cyclic *)(void *)F.blob, F.z));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_integrals_cyclic(F.ctx, F.model, NULL, (qd_int_cyclic *)(void *)F.blob, F.z));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_integrals_cyclic(F.ctx, F.model, F.eom, NULL, F.z));
    reset(&F);
    /* ncyclic NULL */
    assert_int_equal(QD_ERR_ARG, qd_integrals_cyclic(F.ctx, F.model, F.eom, (qd_int_cyclic *)(void *)F.blob, NULL));
    reset(&F);
    /* ---- qd_integrals_noether */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_integrals_noether(NULL, NULL, "q", (const qd_expr * const *)F.e, (qd_noether *)(void *)F.blob));
    reset(&F);
    /* I NULL */
    assert_int_equal(QD_ERR_ARG, qd_integrals_noether(F.ctx, NULL, "q", (const qd_expr * const *)F.e, (qd_noether *)(void *)F.blob));
    reset(&F);
    /* name NULL */
    assert_int_equal(QD_ERR_ARG, qd_integrals_noether(F.ctx, NULL, NULL, (const qd_expr * const *)F.e, (qd_noether *)(void *)F.blob));
    reset(&F);
    /* xi NULL */
    assert_int_equal(QD_ERR_ARG, qd_integrals_noether(F.ctx, NULL, "q", NULL, (qd_noether *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_integrals_noether(F.ctx, NULL, "q", (const qd_expr * const *)F.e, NULL));
    reset(&F);
    /* ---- qd_noether_clear */
    /* nt NULL */
    qd_noether_clear(NULL);
    reset(&F);
    /* ---- qd_integrals_check */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_integrals_check(NULL, NULL, "q", F.q, (qd_int_proposed *)(void *)F.blob));
    reset(&F);
    /* I NULL */
    assert_int_equal(QD_ERR_ARG, qd_integrals_check(F.ctx, NULL, "q", F.q, (qd_int_proposed *)(void *)F.blob));
    reset(&F);
    /* name NULL */
    assert_int_equal(QD_ERR_ARG, qd_integrals_check(F.ctx, NULL, NULL, F.q, (qd_int_proposed *)(void *)F.blob));
    reset(&F);
    /* expr NULL */
    assert_int_equal(QD_ERR_ARG, qd_integrals_check(F.ctx, NULL, "q", NULL, (qd_int_proposed *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_integrals_check(F.ctx, NULL, "q", F.q, NULL));
    reset(&F);
    /* ---- qd_integrals_given_derive */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_integrals_given_derive(NULL, NULL, F.model, (qd_integrals_given *)(void *)F.blob));
    reset(&F);
    /* I NULL */
    assert_int_equal(QD_ERR_ARG, qd_integrals_given_derive(F.ctx, NULL, F.model, (qd_integrals_given *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_integrals_given_derive(F.ctx, NULL, NULL, (qd_integrals_given *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_integrals_given_derive(F.ctx, NULL, F.model, NULL));
    reset(&F);
    /* ---- qd_integrals_given_free */
    /* g NULL */
    qd_integrals_given_free(NULL);
    reset(&F);
    /* ---- qd_integrals_print */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_integrals_print(NULL, NULL, NULL, "q", &F.buf));
    reset(&F);
    /* I NULL */
    assert_int_equal(QD_ERR_ARG, qd_integrals_print(F.ctx, NULL, NULL, "q", &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_integrals_print(F.ctx, NULL, NULL, "q", NULL));
    reset(&F);
    /* ---- qd_integrals_latex */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_integrals_latex(NULL, NULL, NULL, &F.buf));
    reset(&F);
    /* I NULL */
    assert_int_equal(QD_ERR_ARG, qd_integrals_latex(F.ctx, NULL, NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_integrals_latex(F.ctx, NULL, NULL, NULL));
    reset(&F);
    /* ---- qd_integrals_json */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_integrals_json(NULL, NULL, NULL, "q", &F.buf));
    reset(&F);
    /* I NULL */
    assert_int_equal(QD_ERR_ARG, qd_integrals_json(F.ctx, NULL, NULL, "q", &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_integrals_json(F.ctx, NULL, NULL, "q", NULL));
    reset(&F);
    teardown(&F);
}

static void null_json(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_json_init */
    /* j NULL */
    qd_json_init(NULL, &F.buf);
    reset(&F);
    /* out NULL */
    qd_json_init(NULL, NULL);
    reset(&F);
    /* ---- qd_json_begin_object */
    /* j NULL */
    qd_json_begin_object(NULL);
    reset(&F);
    /* ---- qd_json_end_object */
    /* j NULL */
    qd_json_end_object(NULL);
    reset(&F);
    /* ---- qd_json_begin_array */
    /* j NULL */
    qd_json_begin_array(NULL);
    reset(&F);
    /* ---- qd_json_end_array */
    /* j NULL */
    qd_json_end_array(NULL);
    reset(&F);
    /* ---- qd_json_key */
    /* j NULL */
    qd_json_key(NULL, "q");
    reset(&F);
    /* key NULL */
    qd_json_key(NULL, NULL);
    reset(&F);
    /* ---- qd_json_string */
    /* j NULL */
    qd_json_string(NULL, "q");
    reset(&F);
    /* ---- qd_json_number */
    /* j NULL */
    assert_true(qd_json_number(NULL, 1) == 0);
    reset(&F);
    /* ---- qd_json_number_or_null */
    /* j NULL */
    qd_json_number_or_null(NULL, 1);
    reset(&F);
    /* ---- qd_json_bool */
    /* j NULL */
    qd_json_bool(NULL, false);
    reset(&F);
    /* ---- qd_json_null */
    /* j NULL */
    qd_json_null(NULL);
    reset(&F);
    /* ---- qd_json_expr */
    /* j NULL */
    qd_json_expr(NULL, F.ctx, F.q);
    reset(&F);
    /* ctx NULL */
    qd_json_expr(NULL, NULL, F.q);
    reset(&F);
    /* ---- qd_json_matrix */
    /* j NULL */
    assert_true(qd_json_matrix(NULL, "q", 1, 1, F.d) == 0);
    reset(&F);
    /* key NULL */
    assert_true(qd_json_matrix(NULL, NULL, 1, 1, F.d) == 0);
    reset(&F);
    /* x NULL */
    assert_true(qd_json_matrix(NULL, "q", 1, 1, NULL) == 0);
    reset(&F);
    /* ---- qd_json_vector */
    /* j NULL */
    assert_true(qd_json_vector(NULL, "q", 1, F.d) == 0);
    reset(&F);
    /* key NULL */
    assert_true(qd_json_vector(NULL, NULL, 1, F.d) == 0);
    reset(&F);
    /* x NULL */
    assert_true(qd_json_vector(NULL, "q", 1, NULL) == 0);
    reset(&F);
    /* ---- qd_json_frequency */
    /* j NULL */
    qd_json_frequency(NULL, 1);
    reset(&F);
    /* ---- qd_json_expr_result */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_json_expr_result(NULL, "q", "q", 1, (const char * const *)F.names, F.q, &F.buf));
    reset(&F);
    /* operation NULL */
    assert_int_equal(QD_ERR_ARG, qd_json_expr_result(F.ctx, NULL, "q", 1, (const char * const *)F.names, F.q, &F.buf));
    reset(&F);
    /* input NULL */
    assert_int_equal(QD_ERR_ARG, qd_json_expr_result(F.ctx, "q", NULL, 1, (const char * const *)F.names, F.q, &F.buf));
    reset(&F);
    /* vars NULL */
    assert_int_equal(QD_ERR_ARG, qd_json_expr_result(F.ctx, "q", "q", 1, NULL, F.q, &F.buf));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_json_expr_result(F.ctx, "q", "q", 1, (const char * const *)F.names, NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_json_expr_result(F.ctx, "q", "q", 1, (const char * const *)F.names, F.q, NULL));
    reset(&F);
    /* ---- qd_json_add_model */
    /* doc NULL */
    assert_int_equal(QD_ERR_ARG, qd_json_add_model(NULL, "q"));
    reset(&F);
    /* ---- qd_json_ok */
    /* j NULL */
    assert_true(qd_json_ok(NULL) == 0);
    reset(&F);
    /* ---- qd_json_why */
    /* j NULL */
    assert_null(qd_json_why(NULL));
    reset(&F);
    /* ---- qd_json_commit */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_json_commit(NULL, &F.buf, NULL, &F.buf));
    reset(&F);
    /* b NULL */
    assert_int_equal(QD_ERR_ARG, qd_json_commit(F.ctx, NULL, NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_json_commit(F.ctx, &F.buf, NULL, NULL));
    reset(&F);
    teardown(&F);
}

static void null_linpoint(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_linpoint_init */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_linpoint_init(NULL, F.model, F.eom, (qd_linpoint *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_linpoint_init(F.ctx, NULL, F.eom, (qd_linpoint *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_linpoint_init(F.ctx, F.model, NULL, (qd_linpoint *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_linpoint_init(F.ctx, F.model, F.eom, NULL));
    reset(&F);
    /* ---- qd_linpoint_free */
    /* p NULL */
    qd_linpoint_free(NULL);
    reset(&F);
    /* ---- qd_linpoint_set */
    /* p NULL */
    qd_linpoint_set(NULL, F.d, F.d);
    reset(&F);
    /* q NULL */
    qd_linpoint_set(NULL, NULL, F.d);
    reset(&F);
    /* ---- qd_linpoint_read */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_linpoint_read(NULL, NULL, "q", F.d, F.d));
    reset(&F);
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_linpoint_read(F.ctx, NULL, "q", F.d, F.d));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_linpoint_read(F.ctx, NULL, NULL, F.d, F.d));
    reset(&F);
    /* q NULL */
    assert_int_equal(QD_ERR_ARG, qd_linpoint_read(F.ctx, NULL, "q", NULL, F.d));
    reset(&F);
    /* ---- qd_linpoint_read_coords */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_linpoint_read_coords(NULL, NULL, "q", F.d));
    reset(&F);
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_linpoint_read_coords(F.ctx, NULL, "q", F.d));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_linpoint_read_coords(F.ctx, NULL, NULL, F.d));
    reset(&F);
    /* q NULL */
    assert_int_equal(QD_ERR_ARG, qd_linpoint_read_coords(F.ctx, NULL, "q", NULL));
    reset(&F);
    /* ---- qd_linpoint_read_box */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_linpoint_read_box(NULL, NULL, "q", F.d, F.d));
    reset(&F);
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_linpoint_read_box(F.ctx, NULL, "q", F.d, F.d));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_linpoint_read_box(F.ctx, NULL, NULL, F.d, F.d));
    reset(&F);
    /* lo NULL */
    assert_int_equal(QD_ERR_ARG, qd_linpoint_read_box(F.ctx, NULL, "q", NULL, F.d));
    reset(&F);
    /* hi NULL */
    assert_int_equal(QD_ERR_ARG, qd_linpoint_read_box(F.ctx, NULL, "q", F.d, NULL));
    reset(&F);
    /* ---- qd_linpoint_read_exact */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_linpoint_read_exact(NULL, NULL, "q", (const qd_expr * *)F.e));
    reset(&F);
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_linpoint_read_exact(F.ctx, NULL, "q", (const qd_expr * *)F.e));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_linpoint_read_exact(F.ctx, NULL, NULL, (const qd_expr * *)F.e));
    reset(&F);
    /* about NULL */
    assert_int_equal(QD_ERR_ARG, qd_linpoint_read_exact(F.ctx, NULL, "q", NULL));
    reset(&F);
    teardown(&F);
}

static void null_lyapunov(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_lyap_new */
    /* ctx NULL */
    assert_null(qd_lyap_new(NULL, F.model, F.eom));
    reset(&F);
    /* m NULL */
    assert_null(qd_lyap_new(F.ctx, NULL, F.eom));
    reset(&F);
    /* e NULL */
    assert_null(qd_lyap_new(F.ctx, F.model, NULL));
    reset(&F);
    /* ---- qd_lyap_free */
    /* l NULL */
    qd_lyap_free(NULL);
    reset(&F);
    /* ---- qd_lyap_ndof */
    /* l NULL */
    assert_true(qd_lyap_ndof(NULL) == 0);
    reset(&F);
    /* ---- qd_lyap_run */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_lyap_run(NULL, NULL, NULL, NULL, F.d, F.d));
    reset(&F);
    /* l NULL */
    assert_int_equal(QD_ERR_ARG, qd_lyap_run(F.ctx, NULL, NULL, NULL, F.d, F.d));
    reset(&F);
    /* exps NULL */
    assert_int_equal(QD_ERR_ARG, qd_lyap_run(F.ctx, NULL, NULL, NULL, NULL, F.d));
    reset(&F);
    /* ---- qd_lyap_run_stats */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_lyap_run_stats(NULL, NULL, NULL, NULL, F.d, F.d, (qd_lyap_stats *)(void *)F.blob));
    reset(&F);
    /* l NULL */
    assert_int_equal(QD_ERR_ARG, qd_lyap_run_stats(F.ctx, NULL, NULL, NULL, F.d, F.d, (qd_lyap_stats *)(void *)F.blob));
    reset(&F);
    /* exps NULL */
    assert_int_equal(QD_ERR_ARG, qd_lyap_run_stats(F.ctx, NULL, NULL, NULL, NULL, F.d, (qd_lyap_stats *)(void *)F.blob));
    reset(&F);
    /* ---- qd_flow_run */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_flow_run(NULL, NULL, NULL, NULL, (qd_flow *)(void *)F.blob));
    reset(&F);
    /* l NULL */
    assert_int_equal(QD_ERR_ARG, qd_flow_run(F.ctx, NULL, NULL, NULL, (qd_flow *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_flow_run(F.ctx, NULL, NULL, NULL, NULL));
    reset(&F);
    /* ---- qd_flow_free */
    /* f NULL */
    qd_flow_free(NULL);
    reset(&F);
    /* ---- qd_flow_sim_opts */
    /* in NULL */
    assert_int_equal(QD_ERR_ARG, qd_flow_sim_opts(NULL, (qd_sim_opts *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_flow_sim_opts(NULL, NULL));
    reset(&F);
    /* ---- qd_flow_state_name */
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_flow_state_name(NULL, 1, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_flow_state_name(F.eom, 1, NULL));
    reset(&F);
    /* ---- qd_flow_column_name */
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_flow_column_name(NULL, 1, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_flow_column_name(F.eom, 1, NULL));
    reset(&F);
    /* ---- qd_flow_run_csv */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_flow_run_csv(NULL, NULL, F.eom, NULL, 1, NULL, NULL, (qd_flow *)(void *)F.blob));
    reset(&F);
    /* l NULL */
    assert_int_equal(QD_ERR_ARG, qd_flow_run_csv(F.ctx, NULL, F.eom, NULL, 1, NULL, NULL, (qd_flow *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_flow_run_csv(F.ctx, NULL, NULL, NULL, 1, NULL, NULL, (qd_flow *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_flow_run_csv(F.ctx, NULL, F.eom, NULL, 1, NULL, NULL, NULL));
    reset(&F);
    /* ---- qd_flow_print */
    /* f NULL */
    assert_int_equal(QD_ERR_ARG, qd_flow_print(NULL, 1, "q", &F.buf));
    reset(&F);
    /* prefix NULL */
    assert_int_equal(QD_ERR_ARG, qd_flow_print(NULL, 1, NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_flow_print(NULL, 1, "q", NULL));
    reset(&F);
    /* ---- qd_flow_json */
    /* j NULL */
    assert_int_equal(QD_ERR_ARG, qd_flow_json(NULL, NULL, F.eom, (qd_sim_method){0}, 1));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_flow_json(NULL, NULL, NULL, (qd_sim_method){0}, 1));
    reset(&F);
    /* ---- qd_lyap_sum */
    /* exps NULL */
    assert_true(isnan(qd_lyap_sum(1, NULL)));
    reset(&F);
    /* ---- qd_lyap_print */
    /* r NULL */
    assert_int_equal(QD_ERR_ARG, qd_lyap_print(NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_lyap_print(NULL, NULL));
    reset(&F);
    /* ---- qd_lyap_json */
    /* r NULL */
    assert_int_equal(QD_ERR_ARG, qd_lyap_json(NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_lyap_json(NULL, NULL));
    reset(&F);
    /* ---- qd_poincare_run */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_poincare_run(NULL, NULL, NULL, NULL));
    reset(&F);
    /* opts NULL */
    assert_int_equal(QD_ERR_ARG, qd_poincare_run(F.sim, NULL, NULL, NULL));
    reset(&F);
    /* ---- qd_poincare_json_begin */
    /* j NULL */
    assert_int_equal(QD_ERR_ARG, qd_poincare_json_begin(NULL, "q", 1, (const char * const *)F.names, false));
    reset(&F);
    /* ---- qd_poincare_json_end */
    /* j NULL */
    assert_int_equal(QD_ERR_ARG, qd_poincare_json_end(NULL, F.sim, NULL, NULL, NULL, 1, false));
    reset(&F);
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_poincare_json_end(NULL, NULL, NULL, NULL, NULL, 1, false));
    reset(&F);
    /* ---- qd_poincare_orbits_check */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_poincare_orbits_check(NULL, NULL, NULL, NULL, F.z));
    reset(&F);
    /* set NULL */
    assert_int_equal(QD_ERR_ARG, qd_poincare_orbits_check(F.ctx, NULL, NULL, NULL, F.z));
    reset(&F);
    /* at NULL */
    assert_int_equal(QD_ERR_ARG, qd_poincare_orbits_check(F.ctx, NULL, NULL, NULL, NULL));
    reset(&F);
    /* ---- qd_poincare_orbits_run */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_poincare_orbits_run(NULL, NULL, NULL, NULL, NULL, NULL, F.z));
    reset(&F);
    /* set NULL */
    assert_int_equal(QD_ERR_ARG, qd_poincare_orbits_run(F.ctx, NULL, NULL, NULL, NULL, NULL, F.z));
    reset(&F);
    /* at NULL */
    assert_int_equal(QD_ERR_ARG, qd_poincare_orbits_run(F.ctx, NULL, NULL, NULL, NULL, NULL, NULL));
    reset(&F);
    /* ---- qd_poincare_csv */
    /* names NULL */
    assert_int_equal(QD_ERR_ARG, qd_poincare_csv(1, NULL, F.d, 1, 1, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_poincare_csv(1, (const char * const *)F.names, F.d, 1, 1, NULL));
    reset(&F);
    /* ---- qd_poincare_print */
    /* r NULL */
    assert_int_equal(QD_ERR_ARG, qd_poincare_print(NULL, 1, (qd_sim_method){0}, 1, "q", "q", &F.buf));
    reset(&F);
    /* prefix NULL */
    assert_int_equal(QD_ERR_ARG, qd_poincare_print(NULL, 1, (qd_sim_method){0}, 1, NULL, "q", &F.buf));
    reset(&F);
    /* t_end_name NULL */
    assert_int_equal(QD_ERR_ARG, qd_poincare_print(NULL, 1, (qd_sim_method){0}, 1, "q", NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_poincare_print(NULL, 1, (qd_sim_method){0}, 1, "q", "q", NULL));
    reset(&F);
    /* ---- qd_lyap_setup_run */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_lyap_setup_run(NULL, NULL, F.model, NULL, NULL, NULL));
    reset(&F);
    /* set NULL */
    assert_int_equal(QD_ERR_ARG, qd_lyap_setup_run(F.ctx, NULL, F.model, NULL, NULL, NULL));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_lyap_setup_run(F.ctx, NULL, NULL, NULL, NULL, NULL));
    reset(&F);
    /* ---- qd_lyap_result_free */
    /* r NULL */
    qd_lyap_result_free(NULL);
    reset(&F);
    /* ---- qd_flow_setup_run */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_flow_setup_run(NULL, NULL, F.model, NULL, NULL, NULL, NULL, NULL));
    reset(&F);
    /* set NULL */
    assert_int_equal(QD_ERR_ARG, qd_flow_setup_run(F.ctx, NULL, F.model, NULL, NULL, NULL, NULL, NULL));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_flow_setup_run(F.ctx, NULL, NULL, NULL, NULL, NULL, NULL, NULL));
    reset(&F);
    teardown(&F);
}

static void null_mech(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_eom_derive */
    /* ctx NULL */
    assert_null(qd_eom_derive(NULL, F.model));
    reset(&F);
    /* m NULL */
    assert_null(qd_eom_derive(F.ctx, NULL));
    reset(&F);
    /* ---- qd_eom_free */
    /* e NULL */
    qd_eom_free(NULL);
    reset(&F);
    /* ---- qd_eom_derive_opts */
    /* ctx NULL */
    assert_null(qd_eom_derive_opts(NULL, F.model, NULL));
    reset(&F);
    /* m NULL */
    assert_null(qd_eom_derive_opts(F.ctx, NULL, NULL));
    reset(&F);
    /* ---- qd_eom_solve */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_solve(NULL, F.eom, 1));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_solve(F.ctx, NULL, 1));
    reset(&F);
    /* ---- qd_eom_eval */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_eval(NULL, F.eom, 1, (const qd_expr * const *)F.e, F.d, F.d, F.d, F.d, F.d, F.d));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_eval(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, F.d, F.d, F.d, F.d, F.d));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_eval(F.ctx, F.eom, 1, NULL, F.d, F.d, F.d, F.d, F.d, F.d));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_eval(F.ctx, F.eom, 1, (const qd_expr * const *)F.e, NULL, F.d, F.d, F.d, F.d, F.d));
    reset(&F);
    /* ---- qd_eom_compile */
    /* ctx NULL */
    assert_null(qd_eom_compile(NULL, F.eom));
    reset(&F);
    /* e NULL */
    assert_null(qd_eom_compile(F.ctx, NULL));
    reset(&F);
    /* ---- qd_eom_prog_free */
    /* p NULL */
    qd_eom_prog_free(NULL);
    reset(&F);
    /* ---- qd_eom_work_new */
    /* ctx NULL */
    assert_null(qd_eom_work_new(NULL, NULL));
    reset(&F);
    /* p NULL */
    assert_null(qd_eom_work_new(F.ctx, NULL));
    reset(&F);
    /* ---- qd_eom_work_free */
    /* w NULL */
    qd_eom_work_free(NULL);
    reset(&F);
    /* ---- qd_eom_prog_eval */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_prog_eval(NULL, NULL, NULL, 1, (const qd_expr * const *)F.e, F.d, F.d, F.d, F.d, F.d, F.d));
    reset(&F);
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_prog_eval(F.ctx, NULL, NULL, 1, (const qd_expr * const *)F.e, F.d, F.d, F.d, F.d, F.d, F.d));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_prog_eval(F.ctx, NULL, NULL, 1, NULL, F.d, F.d, F.d, F.d, F.d, F.d));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_prog_eval(F.ctx, NULL, NULL, 1, (const qd_expr * const *)F.e, NULL, F.d, F.d, F.d, F.d, F.d));
    reset(&F);
    /* ---- qd_eom_reaction */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_reaction(NULL, F.eom, "q", (const qd_expr * const *)F.e, 1, (const qd_expr * const *)F.e, F.d, F.d, F.d, F.d));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_reaction(F.ctx, NULL, "q", (const qd_expr * const *)F.e, 1, (const qd_expr * const *)F.e, F.d, F.d, F.d, F.d));
    reset(&F);
    /* con NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_reaction(F.ctx, F.eom, NULL, (const qd_expr * const *)F.e, 1, (const qd_expr * const *)F.e, F.d, F.d, F.d, F.d));
    reset(&F);
    /* r NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_reaction(F.ctx, F.eom, "q", NULL, 1, (const qd_expr * const *)F.e, F.d, F.d, F.d, F.d));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_reaction(F.ctx, F.eom, "q", (const qd_expr * const *)F.e, 1, NULL, F.d, F.d, F.d, F.d));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_reaction(F.ctx, F.eom, "q", (const qd_expr * const *)F.e, 1, (const qd_expr * const *)F.e, NULL, F.d, F.d, F.d));
    reset(&F);
    /* lambda NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_reaction(F.ctx, F.eom, "q", (const qd_expr * const *)F.e, 1, (const qd_expr * const *)F.e, F.d, NULL, F.d, F.d));
    reset(&F);
    /* F NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_reaction(F.ctx, F.eom, "q", (const qd_expr * const *)F.e, 1, (const qd_expr * const *)F.e, F.d, F.d, NULL, F.d));
    reset(&F);
    /* ---- qd_eom_dof */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_dof(NULL, F.eom, (qd_dof *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_dof(F.ctx, NULL, (qd_dof *)(void *)F.blob));
    reset(&F);
    /* d NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_dof(F.ctx, F.eom, NULL));
    reset(&F);
    /* ---- qd_eom_audit */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_audit(NULL, F.model, F.eom, (qd_audit *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_audit(F.ctx, NULL, F.eom, (qd_audit *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_audit(F.ctx, F.model, NULL, (qd_audit *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_audit(F.ctx, F.model, F.eom, NULL));
    reset(&F);
    /* ---- qd_isolate */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_isolate(NULL, F.q, F.q, (const qd_expr * *)F.e));
    reset(&F);
    /* eq NULL */
    assert_int_equal(QD_ERR_ARG, qd_isolate(F.ctx, NULL, F.q, (const qd_expr * *)F.e));
    reset(&F);
    /* y NULL */
    assert_int_equal(QD_ERR_ARG, qd_isolate(F.ctx, F.q, NULL, (const qd_expr * *)F.e));
    reset(&F);
    /* sol NULL */
    assert_int_equal(QD_ERR_ARG, qd_isolate(F.ctx, F.q, F.q, NULL));
    reset(&F);
    teardown(&F);
}

static void null_metric(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_metric_new */
    /* ctx NULL */
    assert_null(qd_metric_new(NULL, F.model));
    reset(&F);
    /* m NULL */
    assert_null(qd_metric_new(F.ctx, NULL));
    reset(&F);
    /* ---- qd_metric_free */
    /* g NULL */
    qd_metric_free(NULL);
    reset(&F);
    /* ---- qd_metric_gram_schmidt */
    /* ctx NULL */
    assert_null(qd_metric_gram_schmidt(NULL, NULL));
    reset(&F);
    /* g NULL */
    assert_null(qd_metric_gram_schmidt(F.ctx, NULL));
    reset(&F);
    /* ---- qd_metric_force */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_metric_force(NULL, NULL, (const qd_expr * const *)F.e, (const qd_expr * *)F.e, (const qd_expr * *)F.e, (const qd_expr * *)F.e));
    reset(&F);
    /* g NULL */
    assert_int_equal(QD_ERR_ARG, qd_metric_force(F.ctx, NULL, (const qd_expr * const *)F.e, (const qd_expr * *)F.e, (const qd_expr * *)F.e, (const qd_expr * *)F.e));
    reset(&F);
    /* G NULL */
    assert_int_equal(QD_ERR_ARG, qd_metric_force(F.ctx, NULL, NULL, (const qd_expr * *)F.e, (const qd_expr * *)F.e, (const qd_expr * *)F.e));
    reset(&F);
    /* ---- qd_metric_force_read */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_metric_force_read(NULL, NULL, "q", (const qd_expr * *)F.e));
    reset(&F);
    /* g NULL */
    assert_int_equal(QD_ERR_ARG, qd_metric_force_read(F.ctx, NULL, "q", (const qd_expr * *)F.e));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_metric_force_read(F.ctx, NULL, NULL, (const qd_expr * *)F.e));
    reset(&F);
    /* G NULL */
    assert_int_equal(QD_ERR_ARG, qd_metric_force_read(F.ctx, NULL, "q", NULL));
    reset(&F);
    /* ---- qd_metric_lower */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_metric_lower(NULL, NULL, (const qd_expr * const *)F.e, (const qd_expr * *)F.e));
    reset(&F);
    /* g NULL */
    assert_int_equal(QD_ERR_ARG, qd_metric_lower(F.ctx, NULL, (const qd_expr * const *)F.e, (const qd_expr * *)F.e));
    reset(&F);
    /* A NULL */
    assert_int_equal(QD_ERR_ARG, qd_metric_lower(F.ctx, NULL, NULL, (const qd_expr * *)F.e));
    reset(&F);
    /* low NULL */
    assert_int_equal(QD_ERR_ARG, qd_metric_lower(F.ctx, NULL, (const qd_expr * const *)F.e, NULL));
    reset(&F);
    /* ---- qd_metric_print */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_metric_print(NULL, NULL, (const qd_expr * const *)F.e, (qd_format){0}, &F.buf));
    reset(&F);
    /* g NULL */
    assert_int_equal(QD_ERR_ARG, qd_metric_print(F.ctx, NULL, (const qd_expr * const *)F.e, (qd_format){0}, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_metric_print(F.ctx, NULL, (const qd_expr * const *)F.e, (qd_format){0}, NULL));
    reset(&F);
    /* ---- qd_metric_json */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_metric_json(NULL, NULL, (const qd_expr * const *)F.e, &F.buf));
    reset(&F);
    /* g NULL */
    assert_int_equal(QD_ERR_ARG, qd_metric_json(F.ctx, NULL, (const qd_expr * const *)F.e, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_metric_json(F.ctx, NULL, (const qd_expr * const *)F.e, NULL));
    reset(&F);
    teardown(&F);
}

static void null_model(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_model_parse */
    /* ctx NULL */
    assert_null(qd_model_parse(NULL, "q", (qd_diag *)(void *)F.blob));
    reset(&F);
    /* text NULL */
    assert_null(qd_model_parse(F.ctx, NULL, (qd_diag *)(void *)F.blob));
    reset(&F);
    /* ---- qd_model_parse_opts */
    /* ctx NULL */
    assert_null(qd_model_parse_opts(NULL, "q", NULL, (qd_diag *)(void *)F.blob));
    reset(&F);
    /* text NULL */
    assert_null(qd_model_parse_opts(F.ctx, NULL, NULL, (qd_diag *)(void *)F.blob));
    reset(&F);
    /* ---- qd_model_opts_for */
    /* opts NULL */
    assert_int_equal(QD_ERR_ARG, qd_model_opts_for(NULL, "q"));
    reset(&F);
    /* derivation NULL */
    assert_int_equal(QD_ERR_ARG, qd_model_opts_for(NULL, NULL));
    reset(&F);
    /* ---- qd_model_add_statement */
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_model_add_statement(NULL, "q", (qd_diag *)(void *)F.blob));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_model_add_statement(F.model, NULL, (qd_diag *)(void *)F.blob));
    reset(&F);
    /* ---- qd_model_add_given */
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_model_add_given(NULL, "q", "q", "q", (qd_diag *)(void *)F.blob));
    reset(&F);
    /* keyword NULL */
    assert_int_equal(QD_ERR_ARG, qd_model_add_given(F.model, NULL, "q", "q", (qd_diag *)(void *)F.blob));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_model_add_given(F.model, "q", "q", NULL, (qd_diag *)(void *)F.blob));
    reset(&F);
    /* ---- qd_model_free */
    /* m NULL */
    qd_model_free(NULL);
    reset(&F);
    /* ---- qd_model_ctx */
    /* m NULL */
    assert_null(qd_model_ctx(NULL));
    reset(&F);
    /* ---- qd_model_ncoords */
    /* m NULL */
    assert_true(qd_model_ncoords(NULL) == 0);
    reset(&F);
    /* ---- qd_model_coord */
    /* m NULL */
    assert_null(qd_model_coord(NULL, 1));
    reset(&F);
    /* ---- qd_model_coord_unit */
    /* ctx NULL */
    assert_null(qd_model_coord_unit(NULL, F.model, 1));
    reset(&F);
    /* m NULL */
    assert_null(qd_model_coord_unit(F.ctx, NULL, 1));
    reset(&F);
    /* ---- qd_model_column_unit */
    /* ctx NULL */
    assert_null(qd_model_column_unit(NULL, F.model, "q"));
    reset(&F);
    /* m NULL */
    assert_null(qd_model_column_unit(F.ctx, NULL, "q"));
    reset(&F);
    /* name NULL */
    assert_null(qd_model_column_unit(F.ctx, F.model, NULL));
    reset(&F);
    /* ---- qd_model_nparams */
    /* m NULL */
    assert_true(qd_model_nparams(NULL) == 0);
    reset(&F);
    /* ---- qd_model_nfunctions */
    /* m NULL */
    assert_true(qd_model_nfunctions(NULL) == 0);
    reset(&F);
    /* ---- qd_model_function_name */
    /* m NULL */
    assert_null(qd_model_function_name(NULL, 1));
    reset(&F);
    /* ---- qd_model_param */
    /* m NULL */
    assert_null(qd_model_param(NULL, 1));
    reset(&F);
    /* ---- qd_model_param_value */
    /* m NULL */
    assert_null(qd_model_param_value(NULL, 1));
    reset(&F);
    /* ---- qd_model_param_number */
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_model_param_number(NULL, 1, F.d));
    reset(&F);
    /* x NULL */
    assert_int_equal(QD_ERR_ARG, qd_model_param_number(F.model, 1, NULL));
    reset(&F);
    /* ---- qd_model_param_definition */
    /* m NULL */
    assert_null(qd_model_param_definition(NULL, 1));
    reset(&F);
    /* ---- qd_model_param_fixed */
    /* m NULL */
    assert_true(qd_model_param_fixed(NULL, 1) == 0);
    reset(&F);
    /* ---- qd_model_set_param */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_model_set_param(NULL, F.model, "q", F.q));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_model_set_param(F.ctx, NULL, "q", F.q));
    reset(&F);
    /* name NULL */
    assert_int_equal(QD_ERR_ARG, qd_model_set_param(F.ctx, F.model, NULL, F.q));
    reset(&F);
    /* value NULL */
    assert_int_equal(QD_ERR_ARG, qd_model_set_param(F.ctx, F.model, "q", NULL));
    reset(&F);
    /* ---- qd_model_kinetic */
    /* m NULL */
    assert_null(qd_model_kinetic(NULL));
    reset(&F);
    /* ---- qd_model_potential */
    /* m NULL */
    assert_null(qd_model_potential(NULL));
    reset(&F);
    /* ---- qd_model_gen_potential */
    /* m NULL */
    assert_null(qd_model_gen_potential(NULL));
    reset(&F);
    /* ---- qd_model_lagrangian */
    /* m NULL */
    assert_null(qd_model_lagrangian(NULL));
    reset(&F);
    /* ---- qd_model_lagrangian_given */
    /* m NULL */
    assert_true(qd_model_lagrangian_given(NULL) == 0);
    reset(&F);
    /* ---- qd_model_dissipation */
    /* m NULL */
    assert_null(qd_model_dissipation(NULL));
    reset(&F);
    /* ---- qd_model_force */
    /* m NULL */
    assert_null(qd_model_force(NULL, 1));
    reset(&F);
    /* ---- qd_model_nconstraints */
    /* m NULL */
    assert_true(qd_model_nconstraints(NULL) == 0);
    reset(&F);
    /* ---- qd_model_constraint_name */
    /* m NULL */
    assert_null(qd_model_constraint_name(NULL, 1));
    reset(&F);
    /* ---- qd_model_constraint */
    /* m NULL */
    assert_null(qd_model_constraint(NULL, 1));
    reset(&F);
    /* ---- qd_model_independent */
    /* m NULL */
    assert_null(qd_model_independent(NULL));
    reset(&F);
    /* ---- qd_model_nisoperimetric */
    /* m NULL */
    assert_true(qd_model_nisoperimetric(NULL) == 0);
    reset(&F);
    /* ---- qd_model_isoperimetric_name */
    /* m NULL */
    assert_null(qd_model_isoperimetric_name(NULL, 1));
    reset(&F);
    /* ---- qd_model_isoperimetric */
    /* m NULL */
    assert_null(qd_model_isoperimetric(NULL, 1));
    reset(&F);
    /* ---- qd_model_isoperimetric_value */
    /* m NULL */
    assert_null(qd_model_isoperimetric_value(NULL, 1));
    reset(&F);
    /* ---- qd_model_isoperimetric_multiplier */
    /* m NULL */
    assert_null(qd_model_isoperimetric_multiplier(NULL, 1));
    reset(&F);
    /* ---- qd_model_nreactions */
    /* m NULL */
    assert_true(qd_model_nreactions(NULL) == 0);
    reset(&F);
    /* ---- qd_model_reaction_name */
    /* m NULL */
    assert_null(qd_model_reaction_name(NULL, 1));
    reset(&F);
    /* ---- qd_model_reaction_constraint */
    /* m NULL */
    assert_null(qd_model_reaction_constraint(NULL, 1));
    reset(&F);
    /* ---- qd_model_reaction_point */
    /* m NULL */
    assert_null(qd_model_reaction_point(NULL, 1, 1));
    reset(&F);
    /* ---- qd_model_nbodies */
    /* m NULL */
    assert_true(qd_model_nbodies(NULL) == 0);
    reset(&F);
    /* ---- qd_model_body_name */
    /* m NULL */
    assert_null(qd_model_body_name(NULL, 1));
    reset(&F);
    /* ---- qd_model_body_mass */
    /* m NULL */
    assert_null(qd_model_body_mass(NULL, 1));
    reset(&F);
    /* ---- qd_model_body_inertia */
    /* m NULL */
    assert_null(qd_model_body_inertia(NULL, 1, 1, 1));
    reset(&F);
    /* ---- qd_model_body_position */
    /* m NULL */
    assert_null(qd_model_body_position(NULL, 1, 1));
    reset(&F);
    /* ---- qd_model_body_rotation */
    /* m NULL */
    assert_null(qd_model_body_rotation(NULL, 1, 1, 1));
    reset(&F);
    /* ---- qd_model_body_omega */
    /* m NULL */
    assert_null(qd_model_body_omega(NULL, 1, 1));
    reset(&F);
    /* ---- qd_model_body_omega_space */
    /* m NULL */
    assert_null(qd_model_body_omega_space(NULL, 1, 1));
    reset(&F);
    /* ---- qd_model_body_shape */
    /* m NULL */
    (void)qd_model_body_shape(NULL, 1, (const qd_expr * *)F.e, F.i);
    reset(&F);
    /* size NULL */
    (void)qd_model_body_shape(F.model, 1, NULL, F.i);
    reset(&F);
    /* axis NULL */
    (void)qd_model_body_shape(F.model, 1, (const qd_expr * *)F.e, NULL);
    reset(&F);
    /* ---- qd_model_body_ground */
    /* m NULL */
    assert_true(qd_model_body_ground(NULL, 1, (const qd_expr * *)F.e, (const qd_expr * *)F.e) == 0);
    reset(&F);
    /* n NULL */
    assert_true(qd_model_body_ground(F.model, 1, NULL, (const qd_expr * *)F.e) == 0);
    reset(&F);
    /* r0 NULL */
    assert_true(qd_model_body_ground(F.model, 1, (const qd_expr * *)F.e, NULL) == 0);
    reset(&F);
    /* ---- qd_model_hamiltonian_given */
    /* m NULL */
    assert_true(qd_model_hamiltonian_given(NULL) == 0);
    reset(&F);
    /* ---- qd_model_hamiltonian */
    /* m NULL */
    assert_null(qd_model_hamiltonian(NULL));
    reset(&F);
    /* ---- qd_model_momentum */
    /* m NULL */
    assert_null(qd_model_momentum(NULL, 1));
    reset(&F);
    /* ---- qd_model_nsymmetries */
    /* m NULL */
    assert_true(qd_model_nsymmetries(NULL) == 0);
    reset(&F);
    /* ---- qd_model_symmetry_name */
    /* m NULL */
    assert_null(qd_model_symmetry_name(NULL, 1));
    reset(&F);
    /* ---- qd_model_symmetry_field */
    /* m NULL */
    assert_null(qd_model_symmetry_field(NULL, 1, 1));
    reset(&F);
    /* ---- qd_model_nintegrals */
    /* m NULL */
    assert_true(qd_model_nintegrals(NULL) == 0);
    reset(&F);
    /* ---- qd_model_integral_name */
    /* m NULL */
    assert_null(qd_model_integral_name(NULL, 1));
    reset(&F);
    /* ---- qd_model_integral */
    /* m NULL */
    assert_null(qd_model_integral(NULL, 1));
    reset(&F);
    /* ---- qd_model_nparticles */
    /* m NULL */
    assert_true(qd_model_nparticles(NULL) == 0);
    reset(&F);
    /* ---- qd_model_particle_mass */
    /* m NULL */
    assert_null(qd_model_particle_mass(NULL, 1));
    reset(&F);
    /* ---- qd_model_particle_position */
    /* m NULL */
    assert_null(qd_model_particle_position(NULL, 1, 1));
    reset(&F);
    /* ---- qd_model_nblows */
    /* m NULL */
    assert_true(qd_model_nblows(NULL) == 0);
    reset(&F);
    /* ---- qd_model_blow_label */
    /* m NULL */
    assert_null(qd_model_blow_label(NULL, 1));
    reset(&F);
    /* ---- qd_model_blow */
    /* m NULL */
    assert_null(qd_model_blow(NULL, 1, 1));
    reset(&F);
    /* ---- qd_model_impulse */
    /* m NULL */
    assert_null(qd_model_impulse(NULL, 1));
    reset(&F);
    /* ---- qd_model_nimpact_constraints */
    /* m NULL */
    assert_true(qd_model_nimpact_constraints(NULL) == 0);
    reset(&F);
    /* ---- qd_model_impact_constraint_name */
    /* m NULL */
    assert_null(qd_model_impact_constraint_name(NULL, 1));
    reset(&F);
    /* ---- qd_model_impact_constraint */
    /* m NULL */
    assert_null(qd_model_impact_constraint(NULL, 1));
    reset(&F);
    /* ---- qd_model_impact_constraint_restitution */
    /* m NULL */
    assert_null(qd_model_impact_constraint_restitution(NULL, 1));
    reset(&F);
    /* ---- qd_model_nimpacts */
    /* m NULL */
    assert_true(qd_model_nimpacts(NULL) == 0);
    reset(&F);
    /* ---- qd_model_impact_name */
    /* m NULL */
    assert_null(qd_model_impact_name(NULL, 1));
    reset(&F);
    /* ---- qd_model_impact_gap */
    /* m NULL */
    assert_null(qd_model_impact_gap(NULL, 1));
    reset(&F);
    /* ---- qd_model_impact_restitution */
    /* m NULL */
    assert_null(qd_model_impact_restitution(NULL, 1));
    reset(&F);
    /* ---- qd_model_nprescribed */
    /* m NULL */
    assert_true(qd_model_nprescribed(NULL) == 0);
    reset(&F);
    /* ---- qd_model_prescribed_name */
    /* m NULL */
    assert_null(qd_model_prescribed_name(NULL, 1));
    reset(&F);
    /* ---- qd_model_prescribed */
    /* m NULL */
    assert_null(qd_model_prescribed(NULL, 1));
    reset(&F);
    /* ---- qd_model_nspeeds */
    /* m NULL */
    assert_true(qd_model_nspeeds(NULL) == 0);
    reset(&F);
    /* ---- qd_model_speed */
    /* m NULL */
    assert_null(qd_model_speed(NULL, 1));
    reset(&F);
    /* ---- qd_model_speed_definition */
    /* m NULL */
    assert_null(qd_model_speed_definition(NULL, 1));
    reset(&F);
    /* ---- qd_model_speed_initial */
    /* m NULL */
    assert_null(qd_model_speed_initial(NULL, 1));
    reset(&F);
    /* ---- qd_model_speed_initial_definition */
    /* m NULL */
    assert_null(qd_model_speed_initial_definition(NULL, 1));
    reset(&F);
    /* ---- qd_model_ninputs */
    /* m NULL */
    assert_true(qd_model_ninputs(NULL) == 0);
    reset(&F);
    /* ---- qd_model_input */
    /* m NULL */
    assert_null(qd_model_input(NULL, 1));
    reset(&F);
    /* ---- qd_model_noutputs */
    /* m NULL */
    assert_true(qd_model_noutputs(NULL) == 0);
    reset(&F);
    /* ---- qd_model_output_name */
    /* m NULL */
    assert_null(qd_model_output_name(NULL, 1));
    reset(&F);
    /* ---- qd_model_output */
    /* m NULL */
    assert_null(qd_model_output(NULL, 1));
    reset(&F);
    /* ---- qd_model_initial */
    /* m NULL */
    assert_null(qd_model_initial(NULL, 1, 1));
    reset(&F);
    /* ---- qd_model_initial_definition */
    /* m NULL */
    assert_null(qd_model_initial_definition(NULL, 1, 1));
    reset(&F);
    /* ---- qd_model_definition */
    /* m NULL */
    assert_null(qd_model_definition(NULL, "q"));
    reset(&F);
    /* name NULL */
    assert_null(qd_model_definition(F.model, NULL));
    reset(&F);
    /* ---- qd_model_ndefinitions */
    /* m NULL */
    assert_true(qd_model_ndefinitions(NULL) == 0);
    reset(&F);
    /* ---- qd_model_definition_name */
    /* m NULL */
    assert_null(qd_model_definition_name(NULL, 1));
    reset(&F);
    /* ---- qd_model_definition_size */
    /* m NULL */
    assert_true(qd_model_definition_size(NULL, 1) == 0);
    reset(&F);
    /* ---- qd_model_definition_component */
    /* m NULL */
    assert_null(qd_model_definition_component(NULL, 1, 1));
    reset(&F);
    /* ---- qd_model_read_expr */
    /* ctx NULL */
    assert_null(qd_model_read_expr(NULL, F.model, "q", 1, 1));
    reset(&F);
    /* m NULL */
    assert_null(qd_model_read_expr(F.ctx, NULL, "q", 1, 1));
    reset(&F);
    /* text NULL */
    assert_null(qd_model_read_expr(F.ctx, F.model, NULL, 1, 1));
    reset(&F);
    /* ---- qd_model_where */
    /* m NULL */
    assert_true(qd_model_where(NULL, "q", NULL) == 0);
    reset(&F);
    /* what NULL */
    assert_true(qd_model_where(F.model, NULL, NULL) == 0);
    reset(&F);
    /* ---- qd_model_locate */
    /* m NULL */
    assert_true(qd_model_locate(NULL, (qd_diag *)(void *)F.blob) == 0);
    reset(&F);
    /* d NULL */
    assert_true(qd_model_locate(F.model, NULL) == 0);
    reset(&F);
    /* ---- qd_model_ncontacts */
    /* m NULL */
    assert_true(qd_model_ncontacts(NULL) == 0);
    reset(&F);
    /* ---- qd_model_contact_name */
    /* m NULL */
    assert_null(qd_model_contact_name(NULL, 1));
    reset(&F);
    /* ---- qd_model_contact_kind */
    /* m NULL */
    (void)qd_model_contact_kind(NULL, 1);
    reset(&F);
    /* ---- qd_model_contact_constraints */
    /* m NULL */
    assert_true(qd_model_contact_constraints(NULL, 1, F.z) == 0);
    reset(&F);
    /* con NULL */
    assert_true(qd_model_contact_constraints(F.model, 1, NULL) == 0);
    reset(&F);
    /* ---- qd_model_contact_mu */
    /* m NULL */
    assert_null(qd_model_contact_mu(NULL, 1, false));
    reset(&F);
    /* ---- qd_model_contact_normal */
    /* m NULL */
    assert_null(qd_model_contact_normal(NULL, 1));
    reset(&F);
    /* ---- qd_model_contact_normal_constraint */
    /* m NULL */
    assert_null(qd_model_contact_normal_constraint(NULL, 1));
    reset(&F);
    /* ---- qd_model_contact_normal_scale */
    /* m NULL */
    assert_null(qd_model_contact_normal_scale(NULL, 1));
    reset(&F);
    /* ---- qd_model_number */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_model_number(NULL, F.model, "q", F.d));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_model_number(F.ctx, NULL, "q", F.d));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_model_number(F.ctx, F.model, NULL, F.d));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_model_number(F.ctx, F.model, "q", NULL));
    reset(&F);
    /* ---- qd_model_number_field */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_model_number_field(NULL, F.model, "q", "q", 1, 1, F.d));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_model_number_field(F.ctx, NULL, "q", "q", 1, 1, F.d));
    reset(&F);
    /* field NULL */
    assert_int_equal(QD_ERR_ARG, qd_model_number_field(F.ctx, F.model, NULL, "q", 1, 1, F.d));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_model_number_field(F.ctx, F.model, "q", NULL, 1, 1, F.d));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_model_number_field(F.ctx, F.model, "q", "q", 1, 1, NULL));
    reset(&F);
    teardown(&F);
}

static void null_modes(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_linear_about */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_linear_about(NULL, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, (qd_linear *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_linear_about(F.ctx, NULL, F.model, 1, (const qd_expr * const *)F.e, F.d, (qd_linear *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_linear_about(F.ctx, F.eom, NULL, 1, (const qd_expr * const *)F.e, F.d, (qd_linear *)(void *)F.blob));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_linear_about(F.ctx, F.eom, F.model, 1, NULL, F.d, (qd_linear *)(void *)F.blob));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_linear_about(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, NULL, (qd_linear *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_linear_about(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL));
    reset(&F);
    /* ---- qd_modes_solve */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_solve(NULL, NULL, (qd_modes_result *)(void *)F.blob));
    reset(&F);
    /* lin NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_solve(F.ctx, NULL, (qd_modes_result *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_solve(F.ctx, NULL, NULL));
    reset(&F);
    /* ---- qd_linear_free */
    /* l NULL */
    qd_linear_free(NULL);
    reset(&F);
    /* ---- qd_modes_result_free */
    /* r NULL */
    qd_modes_result_free(NULL);
    reset(&F);
    /* ---- qd_modes_multiplicity */
    /* r NULL */
    assert_true(qd_modes_multiplicity(NULL, 1) == 0);
    reset(&F);
    /* ---- qd_linear_symbolic */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_linear_symbolic(NULL, F.eom, (const qd_expr * const *)F.e, (const qd_expr * *)F.e, (const qd_expr * *)F.e));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_linear_symbolic(F.ctx, NULL, (const qd_expr * const *)F.e, (const qd_expr * *)F.e, (const qd_expr * *)F.e));
    reset(&F);
    /* q0 NULL */
    assert_int_equal(QD_ERR_ARG, qd_linear_symbolic(F.ctx, F.eom, NULL, (const qd_expr * *)F.e, (const qd_expr * *)F.e));
    reset(&F);
    /* Kout NULL */
    assert_int_equal(QD_ERR_ARG, qd_linear_symbolic(F.ctx, F.eom, (const qd_expr * const *)F.e, NULL, (const qd_expr * *)F.e));
    reset(&F);
    /* Mout NULL */
    assert_int_equal(QD_ERR_ARG, qd_linear_symbolic(F.ctx, F.eom, (const qd_expr * const *)F.e, (const qd_expr * *)F.e, NULL));
    reset(&F);
    /* ---- qd_modes_symbolic_omega2 */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_symbolic_omega2(NULL, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * *)F.e));
    reset(&F);
    /* K NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_symbolic_omega2(F.ctx, 1, NULL, (const qd_expr * const *)F.e, (const qd_expr * *)F.e));
    reset(&F);
    /* M NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_symbolic_omega2(F.ctx, 1, (const qd_expr * const *)F.e, NULL, (const qd_expr * *)F.e));
    reset(&F);
    /* w2 NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_symbolic_omega2(F.ctx, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, NULL));
    reset(&F);
    /* ---- qd_modes_normal_coords */
    /* lin NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_normal_coords(NULL, NULL, F.d, F.d, F.d, F.d, F.d));
    reset(&F);
    /* q0 NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_normal_coords(NULL, NULL, NULL, F.d, F.d, F.d, F.d));
    reset(&F);
    /* q NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_normal_coords(NULL, NULL, F.d, NULL, F.d, F.d, F.d));
    reset(&F);
    /* qd NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_normal_coords(NULL, NULL, F.d, F.d, NULL, F.d, F.d));
    reset(&F);
    /* Q NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_normal_coords(NULL, NULL, F.d, F.d, F.d, NULL, F.d));
    reset(&F);
    /* Qd NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_normal_coords(NULL, NULL, F.d, F.d, F.d, F.d, NULL));
    reset(&F);
    /* ---- qd_modes_frequencies */
    /* r NULL */
    assert_true(qd_modes_frequencies(NULL, F.d) == 0);
    reset(&F);
    /* w NULL */
    assert_true(qd_modes_frequencies(NULL, NULL) == 0);
    reset(&F);
    /* ---- qd_modes_exact_omega2 */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_exact_omega2(NULL, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, (const qd_expr * const *)F.e, (const qd_expr * *)F.e, F.b));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_exact_omega2(F.ctx, NULL, F.model, 1, (const qd_expr * const *)F.e, F.d, (const qd_expr * const *)F.e, (const qd_expr * *)F.e, F.b));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_exact_omega2(F.ctx, F.eom, NULL, 1, (const qd_expr * const *)F.e, F.d, (const qd_expr * const *)F.e, (const qd_expr * *)F.e, F.b));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_exact_omega2(F.ctx, F.eom, F.model, 1, NULL, F.d, (const qd_expr * const *)F.e, (const qd_expr * *)F.e, F.b));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_exact_omega2(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, NULL, (const qd_expr * const *)F.e, (const qd_expr * *)F.e, F.b));
    reset(&F);
    /* q0 NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_exact_omega2(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, (const qd_expr * *)F.e, F.b));
    reset(&F);
    /* w2 NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_exact_omega2(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, (const qd_expr * const *)F.e, NULL, F.b));
    reset(&F);
    /* in_params NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_exact_omega2(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, (const qd_expr * const *)F.e, (const qd_expr * *)F.e, NULL));
    reset(&F);
    /* ---- qd_modes_at_point */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_at_point(NULL, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, F.d, 1, (qd_modes_at *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_at_point(F.ctx, NULL, F.model, 1, (const qd_expr * const *)F.e, F.d, F.d, 1, (qd_modes_at *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_at_point(F.ctx, F.eom, NULL, 1, (const qd_expr * const *)F.e, F.d, F.d, 1, (qd_modes_at *)(void *)F.blob));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_at_point(F.ctx, F.eom, F.model, 1, NULL, F.d, F.d, 1, (qd_modes_at *)(void *)F.blob));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_at_point(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, NULL, F.d, 1, (qd_modes_at *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_at_point(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, F.d, 1, NULL));
    reset(&F);
    /* ---- qd_modes_at_solve */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_at_solve(NULL, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_at_solve(F.ctx, NULL, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_at_solve(F.ctx, F.eom, NULL, 1, (const qd_expr * const *)F.e, F.d, NULL));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_at_solve(F.ctx, F.eom, F.model, 1, NULL, F.d, NULL));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_at_solve(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, NULL, NULL));
    reset(&F);
    /* at NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_at_solve(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL));
    reset(&F);
    /* ---- qd_modes_at_free */
    /* at NULL */
    qd_modes_at_free(NULL);
    reset(&F);
    /* ---- qd_modes_at_choose */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_at_choose(NULL, NULL, "q", 1, (qd_modes_at *)(void *)F.blob));
    reset(&F);
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_at_choose(F.ctx, NULL, "q", 1, (qd_modes_at *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_at_choose(F.ctx, NULL, "q", 1, NULL));
    reset(&F);
    /* ---- qd_modes_at_initial */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_at_initial(NULL, NULL, NULL, "q", F.d, F.d));
    reset(&F);
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_at_initial(F.ctx, NULL, NULL, "q", F.d, F.d));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_at_initial(F.ctx, NULL, NULL, NULL, F.d, F.d));
    reset(&F);
    /* Q NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_at_initial(F.ctx, NULL, NULL, "q", NULL, F.d));
    reset(&F);
    /* Qd NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_at_initial(F.ctx, NULL, NULL, "q", F.d, NULL));
    reset(&F);
    /* ---- qd_modes_rest_note */
    /* no pointer argument */
    /* ---- qd_modes_print */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_print(NULL, NULL, false, &F.buf));
    reset(&F);
    /* r NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_print(F.ctx, NULL, false, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_print(F.ctx, NULL, false, NULL));
    reset(&F);
    /* ---- qd_modes_scan */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_scan(NULL, F.eom, F.model, "q", 1, 1, NULL, (qd_scan *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_scan(F.ctx, NULL, F.model, "q", 1, 1, NULL, (qd_scan *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_scan(F.ctx, F.eom, NULL, "q", 1, 1, NULL, (qd_scan *)(void *)F.blob));
    reset(&F);
    /* param NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_scan(F.ctx, F.eom, F.model, NULL, 1, 1, NULL, (qd_scan *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_scan(F.ctx, F.eom, F.model, "q", 1, 1, NULL, NULL));
    reset(&F);
    /* ---- qd_scan_free */
    /* s NULL */
    qd_scan_free(NULL);
    reset(&F);
    /* ---- qd_scan_print */
    /* v NULL */
    assert_int_equal(QD_ERR_ARG, qd_scan_print(NULL, NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_scan_print(NULL, NULL, NULL));
    reset(&F);
    /* ---- qd_scan_json */
    /* v NULL */
    assert_int_equal(QD_ERR_ARG, qd_scan_json(NULL, NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_scan_json(NULL, NULL, NULL));
    reset(&F);
    /* ---- qd_modes_scan_text */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_scan_text(NULL, NULL, "q", "q", 1, false, &F.buf, (const char * *)F.names));
    reset(&F);
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_scan_text(F.ctx, NULL, "q", "q", 1, false, &F.buf, (const char * *)F.names));
    reset(&F);
    /* range NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_scan_text(F.ctx, NULL, NULL, "q", 1, false, &F.buf, (const char * *)F.names));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_scan_text(F.ctx, NULL, "q", "q", 1, false, NULL, (const char * *)F.names));
    reset(&F);
    /* ---- qd_speeds_linear_about */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_linear_about(NULL, NULL, 1, (const qd_expr * const *)F.e, F.d, (qd_speeds_linear *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_linear_about(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, (qd_speeds_linear *)(void *)F.blob));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_linear_about(F.ctx, NULL, 1, NULL, F.d, (qd_speeds_linear *)(void *)F.blob));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_linear_about(F.ctx, NULL, 1, (const qd_expr * const *)F.e, NULL, (qd_speeds_linear *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_linear_about(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, NULL));
    reset(&F);
    /* ---- qd_speeds_linear_free */
    /* l NULL */
    qd_speeds_linear_free(NULL);
    reset(&F);
    /* ---- qd_speeds_modes_solve */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_modes_solve(NULL, NULL, (qd_modes_result *)(void *)F.blob));
    reset(&F);
    /* lin NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_modes_solve(F.ctx, NULL, (qd_modes_result *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_modes_solve(F.ctx, NULL, NULL));
    reset(&F);
    /* ---- qd_speeds_modes_scan */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_modes_scan(NULL, NULL, 1, (const qd_expr * const *)F.e, F.d, F.q, 1, 1, NULL, (qd_scan *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_modes_scan(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, F.q, 1, 1, NULL, (qd_scan *)(void *)F.blob));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_modes_scan(F.ctx, NULL, 1, NULL, F.d, F.q, 1, 1, NULL, (qd_scan *)(void *)F.blob));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_modes_scan(F.ctx, NULL, 1, (const qd_expr * const *)F.e, NULL, F.q, 1, 1, NULL, (qd_scan *)(void *)F.blob));
    reset(&F);
    /* what NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_modes_scan(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, NULL, 1, 1, NULL, (qd_scan *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_modes_scan(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, F.q, 1, 1, NULL, NULL));
    reset(&F);
    /* ---- qd_speeds_modes_scan_text */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_modes_scan_text(NULL, NULL, 1, (const qd_expr * const *)F.e, F.d, "q", "q", 1, false, &F.buf, (const char * *)F.names));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_modes_scan_text(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, "q", "q", 1, false, &F.buf, (const char * *)F.names));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_modes_scan_text(F.ctx, NULL, 1, NULL, F.d, "q", "q", 1, false, &F.buf, (const char * *)F.names));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_modes_scan_text(F.ctx, NULL, 1, (const qd_expr * const *)F.e, NULL, "q", "q", 1, false, &F.buf, (const char * *)F.names));
    reset(&F);
    /* range NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_modes_scan_text(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, NULL, "q", 1, false, &F.buf, (const char * *)F.names));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_modes_scan_text(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, "q", "q", 1, false, NULL, (const char * *)F.names));
    reset(&F);
    /* ---- qd_speeds_modes_print */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_modes_print(NULL, NULL, 1, (const qd_expr * const *)F.e, F.d, NULL, NULL, false, &F.buf));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_modes_print(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, NULL, NULL, false, &F.buf));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_modes_print(F.ctx, NULL, 1, NULL, F.d, NULL, NULL, false, &F.buf));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_modes_print(F.ctx, NULL, 1, (const qd_expr * const *)F.e, NULL, NULL, NULL, false, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_modes_print(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, NULL, NULL, false, NULL));
    reset(&F);
    /* ---- qd_modes_picture_make */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_picture_make(NULL, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, (qd_modes_picture *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_picture_make(F.ctx, NULL, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, (qd_modes_picture *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_picture_make(F.ctx, F.eom, NULL, 1, (const qd_expr * const *)F.e, F.d, NULL, (qd_modes_picture *)(void *)F.blob));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_picture_make(F.ctx, F.eom, F.model, 1, NULL, F.d, NULL, (qd_modes_picture *)(void *)F.blob));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_picture_make(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, NULL, NULL, (qd_modes_picture *)(void *)F.blob));
    reset(&F);
    /* res NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_picture_make(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, (qd_modes_picture *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_picture_make(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, NULL));
    reset(&F);
    /* ---- qd_modes_picture_free */
    /* pic NULL */
    qd_modes_picture_free(NULL);
    reset(&F);
    /* ---- qd_modes_plot */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_plot(NULL, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, "q", NULL));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_plot(F.ctx, NULL, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, "q", NULL));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_plot(F.ctx, F.eom, NULL, 1, (const qd_expr * const *)F.e, F.d, NULL, "q", NULL));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_plot(F.ctx, F.eom, F.model, 1, NULL, F.d, NULL, "q", NULL));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_plot(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, NULL, NULL, "q", NULL));
    reset(&F);
    /* res NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_plot(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, "q", NULL));
    reset(&F);
    /* title NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_plot(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, NULL, NULL));
    reset(&F);
    teardown(&F);
}

static void null_orbit(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_orbit_derive */
    /* ctx NULL */
    assert_null(qd_orbit_derive(NULL, F.model, F.eom, 1, (const qd_expr * const *)F.e));
    reset(&F);
    /* m NULL */
    assert_null(qd_orbit_derive(F.ctx, NULL, F.eom, 1, (const qd_expr * const *)F.e));
    reset(&F);
    /* e NULL */
    assert_null(qd_orbit_derive(F.ctx, F.model, NULL, 1, (const qd_expr * const *)F.e));
    reset(&F);
    /* ---- qd_orbit_free */
    /* o NULL */
    qd_orbit_free(NULL);
    reset(&F);
    /* ---- qd_orbit_kind_name */
    /* no pointer argument */
    /* ---- qd_orbit_solve */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_orbit_solve(NULL, NULL, 1, (const qd_expr * const *)F.e, F.d, F.d, (qd_orbit_result *)(void *)F.blob));
    reset(&F);
    /* o NULL */
    assert_int_equal(QD_ERR_ARG, qd_orbit_solve(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, F.d, (qd_orbit_result *)(void *)F.blob));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_orbit_solve(F.ctx, NULL, 1, NULL, F.d, F.d, (qd_orbit_result *)(void *)F.blob));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_orbit_solve(F.ctx, NULL, 1, (const qd_expr * const *)F.e, NULL, F.d, (qd_orbit_result *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_orbit_solve(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, F.d, NULL));
    reset(&F);
    /* ---- qd_orbit_result_free */
    /* r NULL */
    qd_orbit_result_free(NULL);
    reset(&F);
    /* ---- qd_orbit_period */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_orbit_period(NULL, NULL, NULL, F.d));
    reset(&F);
    /* o NULL */
    assert_int_equal(QD_ERR_ARG, qd_orbit_period(F.ctx, NULL, NULL, F.d));
    reset(&F);
    /* period NULL */
    assert_int_equal(QD_ERR_ARG, qd_orbit_period(F.ctx, NULL, NULL, NULL));
    reset(&F);
    /* ---- qd_orbit_equation */
    /* ctx NULL */
    assert_null(qd_orbit_equation(NULL, NULL, NULL, (const qd_expr * *)F.e));
    reset(&F);
    /* o NULL */
    assert_null(qd_orbit_equation(F.ctx, NULL, NULL, (const qd_expr * *)F.e));
    reset(&F);
    /* lhs NULL */
    assert_null(qd_orbit_equation(F.ctx, NULL, NULL, NULL));
    reset(&F);
    /* ---- qd_orbit_solve_text */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_orbit_solve_text(NULL, NULL, F.model, NULL, (qd_orbit_result *)(void *)F.blob));
    reset(&F);
    /* o NULL */
    assert_int_equal(QD_ERR_ARG, qd_orbit_solve_text(F.ctx, NULL, F.model, NULL, (qd_orbit_result *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_orbit_solve_text(F.ctx, NULL, NULL, NULL, (qd_orbit_result *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_orbit_solve_text(F.ctx, NULL, F.model, NULL, NULL));
    reset(&F);
    /* ---- qd_orbit_render */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_orbit_render(NULL, NULL, NULL, "q", false, false, &F.buf));
    reset(&F);
    /* o NULL */
    assert_int_equal(QD_ERR_ARG, qd_orbit_render(F.ctx, NULL, NULL, "q", false, false, &F.buf));
    reset(&F);
    /* model NULL */
    assert_int_equal(QD_ERR_ARG, qd_orbit_render(F.ctx, NULL, NULL, NULL, false, false, &F.buf));
    reset(&F);
    /* b NULL */
    assert_int_equal(QD_ERR_ARG, qd_orbit_render(F.ctx, NULL, NULL, "q", false, false, NULL));
    reset(&F);
    teardown(&F);
}

static void null_path(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_path_find */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_find(NULL, F.model, F.eom, NULL, (qd_path_set *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_find(F.ctx, NULL, F.eom, NULL, (qd_path_set *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_find(F.ctx, F.model, NULL, NULL, (qd_path_set *)(void *)F.blob));
    reset(&F);
    /* opts NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_find(F.ctx, F.model, F.eom, NULL, (qd_path_set *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_find(F.ctx, F.model, F.eom, NULL, NULL));
    reset(&F);
    /* ---- qd_path_set_free */
    /* s NULL */
    qd_path_set_free(NULL);
    reset(&F);
    /* ---- qd_path_foci */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_foci(NULL, F.model, F.eom, 1, F.d, F.d, 1, (double * *)(void *)F.p, F.z, F.b));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_foci(F.ctx, NULL, F.eom, 1, F.d, F.d, 1, (double * *)(void *)F.p, F.z, F.b));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_foci(F.ctx, F.model, NULL, 1, F.d, F.d, 1, (double * *)(void *)F.p, F.z, F.b));
    reset(&F);
    /* q0 NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_foci(F.ctx, F.model, F.eom, 1, NULL, F.d, 1, (double * *)(void *)F.p, F.z, F.b));
    reset(&F);
    /* v0 NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_foci(F.ctx, F.model, F.eom, 1, F.d, NULL, 1, (double * *)(void *)F.p, F.z, F.b));
    reset(&F);
    /* foci NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_foci(F.ctx, F.model, F.eom, 1, F.d, F.d, 1, NULL, F.z, F.b));
    reset(&F);
    /* nfoci NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_foci(F.ctx, F.model, F.eom, 1, F.d, F.d, 1, (double * *)(void *)F.p, NULL, F.b));
    reset(&F);
    /* ---- qd_path_foci_free */
    /* no pointer argument */
    /* ---- qd_path_foci_mult */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_foci_mult(NULL, F.model, F.eom, 1, F.d, F.d, 1, (double * *)(void *)F.p, (size_t * *)(void *)F.p, F.z, F.b));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_foci_mult(F.ctx, NULL, F.eom, 1, F.d, F.d, 1, (double * *)(void *)F.p, (size_t * *)(void *)F.p, F.z, F.b));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_foci_mult(F.ctx, F.model, NULL, 1, F.d, F.d, 1, (double * *)(void *)F.p, (size_t * *)(void *)F.p, F.z, F.b));
    reset(&F);
    /* q0 NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_foci_mult(F.ctx, F.model, F.eom, 1, NULL, F.d, 1, (double * *)(void *)F.p, (size_t * *)(void *)F.p, F.z, F.b));
    reset(&F);
    /* v0 NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_foci_mult(F.ctx, F.model, F.eom, 1, F.d, NULL, 1, (double * *)(void *)F.p, (size_t * *)(void *)F.p, F.z, F.b));
    reset(&F);
    /* foci NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_foci_mult(F.ctx, F.model, F.eom, 1, F.d, F.d, 1, NULL, (size_t * *)(void *)F.p, F.z, F.b));
    reset(&F);
    /* nfoci NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_foci_mult(F.ctx, F.model, F.eom, 1, F.d, F.d, 1, (double * *)(void *)F.p, (size_t * *)(void *)F.p, NULL, F.b));
    reset(&F);
    /* ---- qd_path_foci_mult_free */
    /* mult NULL */
    qd_path_foci_mult_free(F.ctx, NULL);
    reset(&F);
    /* ---- qd_path_find_energy */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_find_energy(NULL, F.model, F.eom, 1, NULL, (qd_path_set *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_find_energy(F.ctx, NULL, F.eom, 1, NULL, (qd_path_set *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_find_energy(F.ctx, F.model, NULL, 1, NULL, (qd_path_set *)(void *)F.blob));
    reset(&F);
    /* opts NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_find_energy(F.ctx, F.model, F.eom, 1, NULL, (qd_path_set *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_find_energy(F.ctx, F.model, F.eom, 1, NULL, NULL));
    reset(&F);
    /* ---- qd_path_action_of */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_action_of(NULL, F.model, F.eom, (const qd_expr * const *)F.e, 1, 1, F.d, F.d));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_action_of(F.ctx, NULL, F.eom, (const qd_expr * const *)F.e, 1, 1, F.d, F.d));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_action_of(F.ctx, F.model, NULL, (const qd_expr * const *)F.e, 1, 1, F.d, F.d));
    reset(&F);
    /* path NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_action_of(F.ctx, F.model, F.eom, NULL, 1, 1, F.d, F.d));
    reset(&F);
    /* action NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_action_of(F.ctx, F.model, F.eom, (const qd_expr * const *)F.e, 1, 1, NULL, F.d));
    reset(&F);
    /* first_variation NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_action_of(F.ctx, F.model, F.eom, (const qd_expr * const *)F.e, 1, 1, F.d, NULL));
    reset(&F);
    /* ---- qd_path_action_of_print */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_action_of_print(NULL, "q", 1, 1, 1, 1, false, &F.buf));
    reset(&F);
    /* source NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_action_of_print(F.ctx, NULL, 1, 1, 1, 1, false, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_action_of_print(F.ctx, "q", 1, 1, 1, 1, false, NULL));
    reset(&F);
    /* ---- qd_path_end_read */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_end_read(NULL, F.model, F.eom, "q", F.d, F.d, F.b));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_end_read(F.ctx, NULL, F.eom, "q", F.d, F.d, F.b));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_end_read(F.ctx, F.model, NULL, "q", F.d, F.d, F.b));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_end_read(F.ctx, F.model, F.eom, NULL, F.d, F.d, F.b));
    reset(&F);
    /* q NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_end_read(F.ctx, F.model, F.eom, "q", NULL, F.d, F.b));
    reset(&F);
    /* t NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_end_read(F.ctx, F.model, F.eom, "q", F.d, NULL, F.b));
    reset(&F);
    /* is_free NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_end_read(F.ctx, F.model, F.eom, "q", F.d, F.d, NULL));
    reset(&F);
    /* ---- qd_path_ends_read */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_ends_read(NULL, F.model, F.eom, "q", "q", 1, (const char * const *)F.names, false, NULL, NULL));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_ends_read(F.ctx, NULL, F.eom, "q", "q", 1, (const char * const *)F.names, false, NULL, NULL));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_ends_read(F.ctx, F.model, NULL, "q", "q", 1, (const char * const *)F.names, false, NULL, NULL));
    reset(&F);
    /* from NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_ends_read(F.ctx, F.model, F.eom, NULL, "q", 1, (const char * const *)F.names, false, NULL, NULL));
    reset(&F);
    /* to NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_ends_read(F.ctx, F.model, F.eom, "q", NULL, 1, (const char * const *)F.names, false, NULL, NULL));
    reset(&F);
    /* guess NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_ends_read(F.ctx, F.model, F.eom, "q", "q", 1, NULL, false, NULL, NULL));
    reset(&F);
    /* ends NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_ends_read(F.ctx, F.model, F.eom, "q", "q", 1, (const char * const *)F.names, false, NULL, NULL));
    reset(&F);
    /* ---- qd_path_ends_free */
    /* ends NULL */
    qd_path_ends_free(NULL);
    reset(&F);
    /* ---- qd_path_trial_read */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_trial_read(NULL, F.model, "q", (const qd_expr * *)F.e));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_trial_read(F.ctx, NULL, "q", (const qd_expr * *)F.e));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_trial_read(F.ctx, F.model, NULL, (const qd_expr * *)F.e));
    reset(&F);
    /* q NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_trial_read(F.ctx, F.model, "q", NULL));
    reset(&F);
    /* ---- qd_path_print */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_print(NULL, NULL, F.model, F.eom, NULL, &F.buf));
    reset(&F);
    /* ps NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_print(F.ctx, NULL, F.model, F.eom, NULL, &F.buf));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_print(F.ctx, NULL, NULL, F.eom, NULL, &F.buf));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_print(F.ctx, NULL, F.model, NULL, NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_print(F.ctx, NULL, F.model, F.eom, NULL, NULL));
    reset(&F);
    /* ---- qd_path_json */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_json(NULL, NULL, F.model, F.eom, &F.buf));
    reset(&F);
    /* ps NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_json(F.ctx, NULL, F.model, F.eom, &F.buf));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_json(F.ctx, NULL, NULL, F.eom, &F.buf));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_json(F.ctx, NULL, F.model, NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_path_json(F.ctx, NULL, F.model, F.eom, NULL));
    reset(&F);
    teardown(&F);
}

static void null_plot(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_plot_math_text */
    /* text NULL */
    assert_true(qd_plot_math_text(NULL, F.c, 1) == 0);
    reset(&F);
    /* ---- qd_plot_format_of */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_format_of(NULL, "q", (qd_plot_format *)(void *)F.blob));
    reset(&F);
    /* path NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_format_of(F.ctx, NULL, (qd_plot_format *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_format_of(F.ctx, "q", NULL));
    reset(&F);
    /* ---- qd_plot_new */
    /* ctx NULL */
    assert_null(qd_plot_new(NULL, 1, 1));
    reset(&F);
    /* ---- qd_plot_free */
    /* p NULL */
    qd_plot_free(NULL);
    reset(&F);
    /* ---- qd_plot_panels */
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_panels(NULL, 1, 1));
    reset(&F);
    /* ---- qd_plot_npanels */
    /* p NULL */
    assert_true(qd_plot_npanels(NULL) == 0);
    reset(&F);
    /* ---- qd_plot_select */
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_select(NULL, 1));
    reset(&F);
    /* ---- qd_plot_set_title */
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_set_title(NULL, "q"));
    reset(&F);
    /* title NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_set_title(F.plot, NULL));
    reset(&F);
    /* ---- qd_plot_set_xlabel */
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_set_xlabel(NULL, "q"));
    reset(&F);
    /* label NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_set_xlabel(F.plot, NULL));
    reset(&F);
    /* ---- qd_plot_set_ylabel */
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_set_ylabel(NULL, "q"));
    reset(&F);
    /* label NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_set_ylabel(F.plot, NULL));
    reset(&F);
    /* ---- qd_plot_set_equal_axes */
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_set_equal_axes(NULL, false));
    reset(&F);
    /* ---- qd_plot_add */
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_add(NULL, "q", (qd_plot_style){0}, 1, F.d, F.d, F.z));
    reset(&F);
    /* x NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_add(F.plot, "q", (qd_plot_style){0}, 1, NULL, F.d, F.z));
    reset(&F);
    /* y NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_add(F.plot, "q", (qd_plot_style){0}, 1, F.d, NULL, F.z));
    reset(&F);
    /* ---- qd_plot_nseries */
    /* p NULL */
    assert_true(qd_plot_nseries(NULL) == 0);
    reset(&F);
    /* ---- qd_plot_add_mark */
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_add_mark(NULL, (qd_plot_mark){0}, 1, 1, 1, 1));
    reset(&F);
    /* ---- qd_plot_set_heading */
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_set_heading(NULL, "q"));
    reset(&F);
    /* ---- qd_plot_set_note */
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_set_note(NULL, "q"));
    reset(&F);
    /* ---- qd_plot_share_legend */
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_share_legend(NULL, false));
    reset(&F);
    /* ---- qd_plot_set_dpi */
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_set_dpi(NULL, 1));
    reset(&F);
    /* ---- qd_plot_dpi_check */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_dpi_check(NULL, 1));
    reset(&F);
    /* ---- qd_plot_set_point_size */
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_set_point_size(NULL, 1));
    reset(&F);
    /* ---- qd_plot_set_size */
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_set_size(NULL, 1, 1));
    reset(&F);
    /* ---- qd_plot_color */
    /* p NULL */
    (void)qd_plot_color(NULL, 1);
    reset(&F);
    /* ---- qd_plot_layout */
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_layout(NULL));
    reset(&F);
    /* ---- qd_plot_to_pixel */
    /* p NULL */
    assert_true(qd_plot_to_pixel(NULL, 1, 1, 1, F.d, F.d) == 0);
    reset(&F);
    /* px NULL */
    assert_true(qd_plot_to_pixel(F.plot, 1, 1, 1, NULL, F.d) == 0);
    reset(&F);
    /* py NULL */
    assert_true(qd_plot_to_pixel(F.plot, 1, 1, 1, F.d, NULL) == 0);
    reset(&F);
    /* ---- qd_plot_ranges */
    /* p NULL */
    assert_true(qd_plot_ranges(NULL, 1, F.d, F.d, F.d, F.d) == 0);
    reset(&F);
    /* x0 NULL */
    assert_true(qd_plot_ranges(F.plot, 1, NULL, F.d, F.d, F.d) == 0);
    reset(&F);
    /* x1 NULL */
    assert_true(qd_plot_ranges(F.plot, 1, F.d, NULL, F.d, F.d) == 0);
    reset(&F);
    /* y0 NULL */
    assert_true(qd_plot_ranges(F.plot, 1, F.d, F.d, NULL, F.d) == 0);
    reset(&F);
    /* y1 NULL */
    assert_true(qd_plot_ranges(F.plot, 1, F.d, F.d, F.d, NULL) == 0);
    reset(&F);
    /* ---- qd_plot_write */
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_write(NULL, "q"));
    reset(&F);
    /* path NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_write(F.plot, NULL));
    reset(&F);
    /* ---- qd_plot_nice_ticks */
    /* step NULL */
    assert_true(qd_plot_nice_ticks(1, 1, 1, NULL, F.d) == 0);
    reset(&F);
    /* first NULL */
    assert_true(qd_plot_nice_ticks(1, 1, 1, F.d, NULL) == 0);
    reset(&F);
    /* ---- qd_plot_add_map */
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_add_map(NULL, "q", 1, 1, F.d, F.d, F.d));
    reset(&F);
    /* x NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_add_map(F.plot, "q", 1, 1, NULL, F.d, F.d));
    reset(&F);
    /* y NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_add_map(F.plot, "q", 1, 1, F.d, NULL, F.d));
    reset(&F);
    /* z NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_add_map(F.plot, "q", 1, 1, F.d, F.d, NULL));
    reset(&F);
    /* ---- qd_plot_map_color */
    /* no pointer argument */
    /* ---- qd_plot_labels */
    /* p NULL */
    assert_true(qd_plot_labels(NULL, 1, (const char * *)F.names, (const char * *)F.names, (const char * *)F.names) == 0);
    reset(&F);
    /* xlabel NULL */
    assert_true(qd_plot_labels(F.plot, 1, NULL, (const char * *)F.names, (const char * *)F.names) == 0);
    reset(&F);
    /* ylabel NULL */
    assert_true(qd_plot_labels(F.plot, 1, (const char * *)F.names, NULL, (const char * *)F.names) == 0);
    reset(&F);
    /* bar NULL */
    assert_true(qd_plot_labels(F.plot, 1, (const char * *)F.names, (const char * *)F.names, NULL) == 0);
    reset(&F);
    /* ---- qd_plot_map_range */
    /* p NULL */
    assert_true(qd_plot_map_range(NULL, 1, F.d, F.d) == 0);
    reset(&F);
    /* zmin NULL */
    assert_true(qd_plot_map_range(F.plot, 1, NULL, F.d) == 0);
    reset(&F);
    /* zmax NULL */
    assert_true(qd_plot_map_range(F.plot, 1, F.d, NULL) == 0);
    reset(&F);
    /* ---- qd_plot_pick_columns */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_pick_columns(NULL, "q", "q", (const char * const *)F.names, 1, 1, NULL));
    reset(&F);
    /* names NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_pick_columns(F.ctx, "q", "q", NULL, 1, 1, NULL));
    reset(&F);
    /* pk NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_pick_columns(F.ctx, "q", "q", (const char * const *)F.names, 1, 1, NULL));
    reset(&F);
    /* ---- qd_plot_pick_units */
    /* pk NULL */
    qd_plot_pick_units(NULL, (const char * const *)F.names, 1, false);
    reset(&F);
    /* units NULL */
    qd_plot_pick_units(NULL, NULL, 1, false);
    reset(&F);
    /* ---- qd_plot_section_phase */
    /* section NULL */
    assert_null(qd_plot_section_phase(NULL, (const char * const *)F.names, 1));
    reset(&F);
    /* names NULL */
    assert_null(qd_plot_section_phase("q", NULL, 1));
    reset(&F);
    /* ---- qd_plot_size_of */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_size_of(NULL, "q", F.i, F.i));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_size_of(F.ctx, NULL, F.i, F.i));
    reset(&F);
    /* width NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_size_of(F.ctx, "q", NULL, F.i));
    reset(&F);
    /* height NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_size_of(F.ctx, "q", F.i, NULL));
    reset(&F);
    /* ---- qd_plot_apply */
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_apply(NULL, NULL));
    reset(&F);
    /* o NULL */
    assert_int_equal(QD_ERR_ARG, qd_plot_apply(F.plot, NULL));
    reset(&F);
    /* ---- qd_plot_run */
    /* ctx NULL */
    assert_null(qd_plot_run(NULL, NULL, (const char * const *)F.names, F.d, 1, 1, NULL));
    reset(&F);
    /* pk NULL */
    assert_null(qd_plot_run(F.ctx, NULL, (const char * const *)F.names, F.d, 1, 1, NULL));
    reset(&F);
    /* names NULL */
    assert_null(qd_plot_run(F.ctx, NULL, NULL, F.d, 1, 1, NULL));
    reset(&F);
    /* rows NULL */
    assert_null(qd_plot_run(F.ctx, NULL, (const char * const *)F.names, NULL, 1, 1, NULL));
    reset(&F);
    teardown(&F);
}

static void null_print(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_buf_free */
    /* b NULL */
    qd_buf_free(NULL);
    reset(&F);
    /* ---- qd_buf_clear */
    /* b NULL */
    qd_buf_clear(NULL);
    reset(&F);
    /* ---- qd_buf_puts */
    /* b NULL */
    qd_buf_puts(NULL, "q");
    reset(&F);
    /* s NULL */
    qd_buf_puts(&F.buf, NULL);
    reset(&F);
    /* ---- qd_buf_putn */
    /* b NULL */
    qd_buf_putn(NULL, "q", 1);
    reset(&F);
    /* s NULL */
    qd_buf_putn(&F.buf, NULL, 1);
    reset(&F);
    /* ---- qd_buf_printf */
    /* b NULL */
    qd_buf_printf(NULL, "q");
    reset(&F);
    /* fmt NULL */
    qd_buf_printf(&F.buf, NULL);
    reset(&F);
    /* ---- qd_buf_str */
    /* b NULL */
    (void)qd_buf_str(NULL);
    reset(&F);
    /* ---- qd_double_format */
    /* out NULL */
    assert_true(qd_double_format(NULL, 1) == 0);
    reset(&F);
    /* ---- qd_buf_put_double */
    /* b NULL */
    qd_buf_put_double(NULL, 1);
    reset(&F);
    /* ---- qd_result_format */
    /* out NULL */
    assert_true(qd_result_format(NULL, 1, 1) == 0);
    reset(&F);
    /* ---- qd_buf_put_result */
    /* b NULL */
    qd_buf_put_result(NULL, 1, 1);
    reset(&F);
    /* ---- qd_print */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_print(NULL, F.q, (qd_format){0}, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_print(F.ctx, F.q, (qd_format){0}, NULL));
    reset(&F);
    /* ---- qd_print_set_time_name */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_print_set_time_name(NULL, "q"));
    reset(&F);
    /* name NULL */
    assert_int_equal(QD_ERR_ARG, qd_print_set_time_name(F.ctx, NULL));
    reset(&F);
    /* ---- qd_print_time_name */
    /* ctx NULL */
    assert_null(qd_print_time_name(NULL));
    reset(&F);
    /* ---- qd_print_sympy_functions */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_print_sympy_functions(NULL, 1, (const qd_expr * const *)F.e, &F.buf));
    reset(&F);
    /* exprs NULL */
    assert_int_equal(QD_ERR_ARG, qd_print_sympy_functions(F.ctx, 1, NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_print_sympy_functions(F.ctx, 1, (const qd_expr * const *)F.e, NULL));
    reset(&F);
    /* ---- qd_print_c_block */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_print_c_block(NULL, 1, (const qd_expr * const *)F.e, (const char * const *)F.names, &F.buf));
    reset(&F);
    /* exprs NULL */
    assert_int_equal(QD_ERR_ARG, qd_print_c_block(F.ctx, 1, NULL, (const char * const *)F.names, &F.buf));
    reset(&F);
    /* lhs NULL */
    assert_int_equal(QD_ERR_ARG, qd_print_c_block(F.ctx, 1, (const qd_expr * const *)F.e, NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_print_c_block(F.ctx, 1, (const qd_expr * const *)F.e, (const char * const *)F.names, NULL));
    reset(&F);
    /* ---- qd_tour_print */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_tour_print(NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_tour_print(F.ctx, NULL));
    reset(&F);
    /* ---- qd_c_name */
    /* sym NULL */
    assert_int_equal(QD_ERR_ARG, qd_c_name(NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_c_name(F.q, NULL));
    reset(&F);
    teardown(&F);
}

static void null_read(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_read */
    /* ctx NULL */
    assert_null(qd_read(NULL, "q", NULL, (qd_read_error *)(void *)F.blob));
    reset(&F);
    /* text NULL */
    assert_null(qd_read(F.ctx, NULL, NULL, (qd_read_error *)(void *)F.blob));
    reset(&F);
    /* ---- qd_read_variable */
    /* ctx NULL */
    assert_null(qd_read_variable(NULL, "q", F.q, (qd_read_error *)(void *)F.blob));
    reset(&F);
    /* text NULL */
    assert_null(qd_read_variable(F.ctx, NULL, F.q, (qd_read_error *)(void *)F.blob));
    reset(&F);
    /* within NULL */
    assert_null(qd_read_variable(F.ctx, "q", NULL, (qd_read_error *)(void *)F.blob));
    reset(&F);
    /* ---- qd_diag_format */
    /* d NULL */
    qd_diag_format(NULL, "q", "q", &F.buf);
    reset(&F);
    /* out NULL */
    qd_diag_format(NULL, "q", "q", NULL);
    reset(&F);
    teardown(&F);
}

static void null_relativity(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_rel_gamma */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_gamma(NULL, 1, F.d, F.d));
    reset(&F);
    /* v NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_gamma(F.ctx, 1, NULL, F.d));
    reset(&F);
    /* gamma NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_gamma(F.ctx, 1, F.d, NULL));
    reset(&F);
    /* ---- qd_lorentz_event */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_lorentz_event(NULL, 1, F.d, F.d, F.d));
    reset(&F);
    /* V NULL */
    assert_int_equal(QD_ERR_ARG, qd_lorentz_event(F.ctx, 1, NULL, F.d, F.d));
    reset(&F);
    /* ev NULL */
    assert_int_equal(QD_ERR_ARG, qd_lorentz_event(F.ctx, 1, F.d, NULL, F.d));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_lorentz_event(F.ctx, 1, F.d, F.d, NULL));
    reset(&F);
    /* ---- qd_lorentz_velocity */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_lorentz_velocity(NULL, 1, F.d, F.d, F.d));
    reset(&F);
    /* V NULL */
    assert_int_equal(QD_ERR_ARG, qd_lorentz_velocity(F.ctx, 1, NULL, F.d, F.d));
    reset(&F);
    /* v NULL */
    assert_int_equal(QD_ERR_ARG, qd_lorentz_velocity(F.ctx, 1, F.d, NULL, F.d));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_lorentz_velocity(F.ctx, 1, F.d, F.d, NULL));
    reset(&F);
    /* ---- qd_lorentz_acceleration */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_lorentz_acceleration(NULL, 1, F.d, F.d, F.d, F.d));
    reset(&F);
    /* V NULL */
    assert_int_equal(QD_ERR_ARG, qd_lorentz_acceleration(F.ctx, 1, NULL, F.d, F.d, F.d));
    reset(&F);
    /* v NULL */
    assert_int_equal(QD_ERR_ARG, qd_lorentz_acceleration(F.ctx, 1, F.d, NULL, F.d, F.d));
    reset(&F);
    /* a NULL */
    assert_int_equal(QD_ERR_ARG, qd_lorentz_acceleration(F.ctx, 1, F.d, F.d, NULL, F.d));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_lorentz_acceleration(F.ctx, 1, F.d, F.d, F.d, NULL));
    reset(&F);
    /* ---- qd_lorentz_momentum */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_lorentz_momentum(NULL, 1, F.d, 1, F.d, F.d, F.d));
    reset(&F);
    /* V NULL */
    assert_int_equal(QD_ERR_ARG, qd_lorentz_momentum(F.ctx, 1, NULL, 1, F.d, F.d, F.d));
    reset(&F);
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_lorentz_momentum(F.ctx, 1, F.d, 1, NULL, F.d, F.d));
    reset(&F);
    /* E_out NULL */
    assert_int_equal(QD_ERR_ARG, qd_lorentz_momentum(F.ctx, 1, F.d, 1, F.d, NULL, F.d));
    reset(&F);
    /* p_out NULL */
    assert_int_equal(QD_ERR_ARG, qd_lorentz_momentum(F.ctx, 1, F.d, 1, F.d, F.d, NULL));
    reset(&F);
    /* ---- qd_lorentz_boost */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_lorentz_boost(NULL, 1, F.d, F.d));
    reset(&F);
    /* V NULL */
    assert_int_equal(QD_ERR_ARG, qd_lorentz_boost(F.ctx, 1, NULL, F.d));
    reset(&F);
    /* O NULL */
    assert_int_equal(QD_ERR_ARG, qd_lorentz_boost(F.ctx, 1, F.d, NULL));
    reset(&F);
    /* ---- qd_lorentz_metric_error */
    /* O NULL */
    assert_true(isnan(qd_lorentz_metric_error(NULL)));
    reset(&F);
    /* ---- qd_rel_momentum */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_momentum(NULL, 1, 1, F.d, F.d, F.d));
    reset(&F);
    /* v NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_momentum(F.ctx, 1, 1, NULL, F.d, F.d));
    reset(&F);
    /* E NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_momentum(F.ctx, 1, 1, F.d, NULL, F.d));
    reset(&F);
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_momentum(F.ctx, 1, 1, F.d, F.d, NULL));
    reset(&F);
    /* ---- qd_rel_mass */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_mass(NULL, 1, 1, F.d, F.d));
    reset(&F);
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_mass(F.ctx, 1, 1, NULL, F.d));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_mass(F.ctx, 1, 1, F.d, NULL));
    reset(&F);
    /* ---- qd_rel_compose */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_compose(NULL, 1, F.d, F.d, F.d));
    reset(&F);
    /* u NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_compose(F.ctx, 1, NULL, F.d, F.d));
    reset(&F);
    /* v NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_compose(F.ctx, 1, F.d, NULL, F.d));
    reset(&F);
    /* w NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_compose(F.ctx, 1, F.d, F.d, NULL));
    reset(&F);
    /* ---- qd_rel_wigner_angle */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_wigner_angle(NULL, 1, F.d, F.d, F.d));
    reset(&F);
    /* u NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_wigner_angle(F.ctx, 1, NULL, F.d, F.d));
    reset(&F);
    /* v NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_wigner_angle(F.ctx, 1, F.d, NULL, F.d));
    reset(&F);
    /* angle NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_wigner_angle(F.ctx, 1, F.d, F.d, NULL));
    reset(&F);
    /* ---- qd_rel_dilate */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_dilate(NULL, 1, F.d, 1, F.d));
    reset(&F);
    /* V NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_dilate(F.ctx, 1, NULL, 1, F.d));
    reset(&F);
    /* dt NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_dilate(F.ctx, 1, F.d, 1, NULL));
    reset(&F);
    /* ---- qd_rel_contract */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_contract(NULL, 1, F.d, F.d, F.d));
    reset(&F);
    /* V NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_contract(F.ctx, 1, NULL, F.d, F.d));
    reset(&F);
    /* d NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_contract(F.ctx, 1, F.d, NULL, F.d));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_contract(F.ctx, 1, F.d, F.d, NULL));
    reset(&F);
    /* ---- qd_rel_proper_time */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_proper_time(NULL, 1, (const qd_expr * const *)F.e, 1, 1, 1, (qd_rel_tau *)(void *)F.blob));
    reset(&F);
    /* v NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_proper_time(F.ctx, 1, NULL, 1, 1, 1, (qd_rel_tau *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_proper_time(F.ctx, 1, (const qd_expr * const *)F.e, 1, 1, 1, NULL));
    reset(&F);
    /* ---- qd_rel_particle_make */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_particle_make(NULL, 1, 1, F.d, (qd_rel_particle *)(void *)F.blob));
    reset(&F);
    /* v NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_particle_make(F.ctx, 1, 1, NULL, (qd_rel_particle *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_particle_make(F.ctx, 1, 1, F.d, NULL));
    reset(&F);
    /* ---- qd_rel_particle_from_momentum */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_particle_from_momentum(NULL, 1, 1, F.d, (qd_rel_particle *)(void *)F.blob));
    reset(&F);
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_particle_from_momentum(F.ctx, 1, 1, NULL, (qd_rel_particle *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_particle_from_momentum(F.ctx, 1, 1, F.d, NULL));
    reset(&F);
    /* ---- qd_rel_total */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_total(NULL, 1, 1, NULL, (qd_rel_particle *)(void *)F.blob));
    reset(&F);
    /* in NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_total(F.ctx, 1, 1, NULL, (qd_rel_particle *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_total(F.ctx, 1, 1, NULL, NULL));
    reset(&F);
    /* ---- qd_rel_elastic */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_elastic(NULL, 1, NULL, 1, 1, (qd_rel_particle *)(void *)F.blob));
    reset(&F);
    /* in NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_elastic(F.ctx, 1, NULL, 1, 1, (qd_rel_particle *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_elastic(F.ctx, 1, NULL, 1, 1, NULL));
    reset(&F);
    /* ---- qd_rel_lab_angle */
    /* in NULL */
    assert_true(isnan(qd_rel_lab_angle(NULL, NULL, 1)));
    reset(&F);
    /* ---- qd_rel_elastic_lab */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_elastic_lab(NULL, 1, NULL, 1, F.d, F.z));
    reset(&F);
    /* in NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_elastic_lab(F.ctx, 1, NULL, 1, F.d, F.z));
    reset(&F);
    /* chi NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_elastic_lab(F.ctx, 1, NULL, 1, NULL, F.z));
    reset(&F);
    /* count NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_elastic_lab(F.ctx, 1, NULL, 1, F.d, NULL));
    reset(&F);
    /* ---- qd_rel_threshold_of */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_threshold_of(NULL, 1, 1, 1, 1, (qd_rel_threshold *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_threshold_of(F.ctx, 1, 1, 1, 1, NULL));
    reset(&F);
    /* ---- qd_rel_decay */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_decay(NULL, 1, NULL, 1, 1, 1, 1, (qd_rel_particle *)(void *)F.blob, F.d));
    reset(&F);
    /* parent NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_decay(F.ctx, 1, NULL, 1, 1, 1, 1, (qd_rel_particle *)(void *)F.blob, F.d));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_decay(F.ctx, 1, NULL, 1, 1, 1, 1, NULL, F.d));
    reset(&F);
    /* pstar NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_decay(F.ctx, 1, NULL, 1, 1, 1, 1, (qd_rel_particle *)(void *)F.blob, NULL));
    reset(&F);
    /* ---- qd_rel_read_c */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_read_c(NULL, "q", "q", F.d));
    reset(&F);
    /* field NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_read_c(F.ctx, NULL, "q", F.d));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_read_c(F.ctx, "q", NULL, F.d));
    reset(&F);
    /* c NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_read_c(F.ctx, "q", "q", NULL));
    reset(&F);
    /* ---- qd_rel_read_number */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_read_number(NULL, 1, "q", "q", F.d));
    reset(&F);
    /* field NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_read_number(F.ctx, 1, NULL, "q", F.d));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_read_number(F.ctx, 1, "q", NULL, F.d));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_read_number(F.ctx, 1, "q", "q", NULL));
    reset(&F);
    /* ---- qd_rel_read_numbers */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_read_numbers(NULL, 1, "q", "q", 1, F.d));
    reset(&F);
    /* field NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_read_numbers(F.ctx, 1, NULL, "q", 1, F.d));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_read_numbers(F.ctx, 1, "q", NULL, 1, F.d));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_read_numbers(F.ctx, 1, "q", "q", 1, NULL));
    reset(&F);
    /* ---- qd_rel_read_particle */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_read_particle(NULL, 1, "q", "q", (qd_rel_particle *)(void *)F.blob));
    reset(&F);
    /* field NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_read_particle(F.ctx, 1, NULL, "q", (qd_rel_particle *)(void *)F.blob));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_read_particle(F.ctx, 1, "q", NULL, (qd_rel_particle *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_rel_read_particle(F.ctx, 1, "q", "q", NULL));
    reset(&F);
    /* ---- qd_lorentz_run */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_lorentz_run(NULL, NULL, (qd_lorentz_out *)(void *)F.blob));
    reset(&F);
    /* in NULL */
    assert_int_equal(QD_ERR_ARG, qd_lorentz_run(F.ctx, NULL, (qd_lorentz_out *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_lorentz_run(F.ctx, NULL, NULL));
    reset(&F);
    /* ---- qd_lorentz_read */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_lorentz_read(NULL, NULL, NULL));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_lorentz_read(F.ctx, NULL, NULL));
    reset(&F);
    /* ---- qd_lorentz_render */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_lorentz_render(NULL, NULL, NULL, false, &F.buf));
    reset(&F);
    /* in NULL */
    assert_int_equal(QD_ERR_ARG, qd_lorentz_render(F.ctx, NULL, NULL, false, &F.buf));
    reset(&F);
    /* b NULL */
    assert_int_equal(QD_ERR_ARG, qd_lorentz_render(F.ctx, NULL, NULL, false, NULL));
    reset(&F);
    /* ---- qd_collide_run */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_collide_run(NULL, NULL, (qd_collide_out *)(void *)F.blob));
    reset(&F);
    /* in NULL */
    assert_int_equal(QD_ERR_ARG, qd_collide_run(F.ctx, NULL, (qd_collide_out *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_collide_run(F.ctx, NULL, NULL));
    reset(&F);
    /* ---- qd_collide_read */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_collide_read(NULL, NULL, NULL));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_collide_read(F.ctx, NULL, NULL));
    reset(&F);
    /* ---- qd_collide_render */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_collide_render(NULL, NULL, NULL, false, &F.buf));
    reset(&F);
    /* in NULL */
    assert_int_equal(QD_ERR_ARG, qd_collide_render(F.ctx, NULL, NULL, false, &F.buf));
    reset(&F);
    /* b NULL */
    assert_int_equal(QD_ERR_ARG, qd_collide_render(F.ctx, NULL, NULL, false, NULL));
    reset(&F);
    teardown(&F);
}

static void null_render(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_render_format_name */
    /* no pointer argument */
    /* ---- qd_render_format_parse */
    /* name NULL */
    assert_true(qd_render_format_parse(NULL, (qd_render_format *)(void *)F.blob) == 0);
    reset(&F);
    /* out NULL */
    assert_true(qd_render_format_parse("q", NULL) == 0);
    reset(&F);
    /* ---- qd_con_kind_name */
    /* no pointer argument */
    /* ---- qd_render_eom */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_eom(NULL, F.model, F.eom, NULL, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_eom(F.ctx, NULL, F.eom, NULL, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_eom(F.ctx, F.model, NULL, NULL, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_eom(F.ctx, F.model, F.eom, NULL, (qd_render_format){0}, NULL));
    reset(&F);
    /* ---- qd_render_speeds */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_speeds(NULL, F.model, NULL, NULL, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_speeds(F.ctx, NULL, NULL, NULL, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_speeds(F.ctx, F.model, NULL, NULL, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_speeds(F.ctx, F.model, NULL, NULL, (qd_render_format){0}, NULL));
    reset(&F);
    /* ---- qd_render_hamel */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_hamel(NULL, NULL, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_hamel(F.ctx, NULL, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_hamel(F.ctx, NULL, (qd_render_format){0}, NULL));
    reset(&F);
    /* ---- qd_eom_request_render */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_request_render(NULL, F.model, NULL, &F.buf, &F.buf, NULL));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_request_render(F.ctx, NULL, NULL, &F.buf, &F.buf, NULL));
    reset(&F);
    /* rq NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_request_render(F.ctx, F.model, NULL, &F.buf, &F.buf, NULL));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_request_render(F.ctx, F.model, NULL, NULL, &F.buf, NULL));
    reset(&F);
    /* notes NULL */
    assert_int_equal(QD_ERR_ARG, qd_eom_request_render(F.ctx, F.model, NULL, &F.buf, NULL, NULL));
    reset(&F);
    /* ---- qd_check_verdict_of */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_check_verdict_of(NULL, F.model, F.eom, (qd_check_verdict *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_check_verdict_of(F.ctx, NULL, F.eom, (qd_check_verdict *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_check_verdict_of(F.ctx, F.model, NULL, (qd_check_verdict *)(void *)F.blob));
    reset(&F);
    /* v NULL */
    assert_int_equal(QD_ERR_ARG, qd_check_verdict_of(F.ctx, F.model, F.eom, NULL));
    reset(&F);
    /* ---- qd_render_check */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_check(NULL, F.model, F.eom, NULL, NULL, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_check(F.ctx, NULL, F.eom, NULL, NULL, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_check(F.ctx, F.model, NULL, NULL, NULL, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* v NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_check(F.ctx, F.model, F.eom, NULL, NULL, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_check(F.ctx, F.model, F.eom, NULL, NULL, (qd_render_format){0}, NULL));
    reset(&F);
    /* ---- qd_render_qform */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_qform(NULL, F.q, NULL, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* phi NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_qform(F.ctx, NULL, NULL, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* f NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_qform(F.ctx, F.q, NULL, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_qform(F.ctx, F.q, NULL, (qd_render_format){0}, NULL));
    reset(&F);
    /* ---- qd_render_homog */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_homog(NULL, NULL, 1, (const qd_expr * const *)F.e, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* h NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_homog(F.ctx, NULL, 1, (const qd_expr * const *)F.e, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* x NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_homog(F.ctx, NULL, 1, NULL, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_homog(F.ctx, NULL, 1, (const qd_expr * const *)F.e, (qd_render_format){0}, NULL));
    reset(&F);
    /* ---- qd_render_periods */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_periods(NULL, F.q, NULL, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_periods(F.ctx, F.q, NULL, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* x NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_periods(F.ctx, F.q, NULL, NULL, (const qd_expr * const *)F.e, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* w NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_periods(F.ctx, F.q, NULL, (const qd_expr * const *)F.e, NULL, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_periods(F.ctx, F.q, NULL, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (qd_render_format){0}, NULL));
    reset(&F);
    /* ---- qd_render_gram */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_gram(NULL, NULL, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* g NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_gram(F.ctx, NULL, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_gram(F.ctx, NULL, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (qd_render_format){0}, NULL));
    reset(&F);
    /* ---- qd_render_change */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_change(NULL, NULL, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* c NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_change(F.ctx, NULL, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_change(F.ctx, NULL, (qd_render_format){0}, NULL));
    reset(&F);
    /* ---- qd_render_fourier */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_fourier(NULL, NULL, F.q, (const qd_expr * const *)F.e, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* f NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_fourier(F.ctx, NULL, F.q, (const qd_expr * const *)F.e, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* fx NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_fourier(F.ctx, NULL, NULL, (const qd_expr * const *)F.e, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* x NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_fourier(F.ctx, NULL, F.q, NULL, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_fourier(F.ctx, NULL, F.q, (const qd_expr * const *)F.e, (qd_render_format){0}, NULL));
    reset(&F);
    /* ---- qd_render_impulse */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_impulse(NULL, F.model, NULL, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_impulse(F.ctx, NULL, NULL, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* r NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_impulse(F.ctx, F.model, NULL, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_impulse(F.ctx, F.model, NULL, (qd_render_format){0}, NULL));
    reset(&F);
    /* ---- qd_ham_point_eval */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_ham_point_eval(NULL, NULL, 1, (const qd_expr * const *)F.e, F.d, (qd_ham_point *)(void *)F.blob));
    reset(&F);
    /* h NULL */
    assert_int_equal(QD_ERR_ARG, qd_ham_point_eval(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, (qd_ham_point *)(void *)F.blob));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_ham_point_eval(F.ctx, NULL, 1, NULL, F.d, (qd_ham_point *)(void *)F.blob));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_ham_point_eval(F.ctx, NULL, 1, (const qd_expr * const *)F.e, NULL, (qd_ham_point *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_ham_point_eval(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, NULL));
    reset(&F);
    /* ---- qd_ham_point_free */
    /* pt NULL */
    qd_ham_point_free(NULL);
    reset(&F);
    /* ---- qd_ham_point_at */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_ham_point_at(NULL, F.model, NULL, "q", (qd_ham_point *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_ham_point_at(F.ctx, NULL, NULL, "q", (qd_ham_point *)(void *)F.blob));
    reset(&F);
    /* h NULL */
    assert_int_equal(QD_ERR_ARG, qd_ham_point_at(F.ctx, F.model, NULL, "q", (qd_ham_point *)(void *)F.blob));
    reset(&F);
    /* at NULL */
    assert_int_equal(QD_ERR_ARG, qd_ham_point_at(F.ctx, F.model, NULL, NULL, (qd_ham_point *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_ham_point_at(F.ctx, F.model, NULL, "q", NULL));
    reset(&F);
    /* ---- qd_render_hamiltonian */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_hamiltonian(NULL, F.model, NULL, "q", NULL, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_hamiltonian(F.ctx, NULL, NULL, "q", NULL, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* h NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_hamiltonian(F.ctx, F.model, NULL, "q", NULL, (qd_render_format){0}, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_render_hamiltonian(F.ctx, F.model, NULL, "q", NULL, (qd_render_format){0}, NULL));
    reset(&F);
    teardown(&F);
}

static void null_routh(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_routh_derive */
    /* ctx NULL */
    assert_null(qd_routh_derive(NULL, F.model, F.eom, 1, (const qd_expr * const *)F.e));
    reset(&F);
    /* m NULL */
    assert_null(qd_routh_derive(F.ctx, NULL, F.eom, 1, (const qd_expr * const *)F.e));
    reset(&F);
    /* e NULL */
    assert_null(qd_routh_derive(F.ctx, F.model, NULL, 1, (const qd_expr * const *)F.e));
    reset(&F);
    /* ign NULL */
    assert_null(qd_routh_derive(F.ctx, F.model, F.eom, 1, NULL));
    reset(&F);
    /* ---- qd_routh_derive_opts */
    /* ctx NULL */
    assert_null(qd_routh_derive_opts(NULL, F.model, F.eom, 1, (const qd_expr * const *)F.e, NULL));
    reset(&F);
    /* m NULL */
    assert_null(qd_routh_derive_opts(F.ctx, NULL, F.eom, 1, (const qd_expr * const *)F.e, NULL));
    reset(&F);
    /* e NULL */
    assert_null(qd_routh_derive_opts(F.ctx, F.model, NULL, 1, (const qd_expr * const *)F.e, NULL));
    reset(&F);
    /* ign NULL */
    assert_null(qd_routh_derive_opts(F.ctx, F.model, F.eom, 1, NULL, NULL));
    reset(&F);
    /* ---- qd_routh_velocities_at */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_routh_velocities_at(NULL, NULL, F.eom, 1, (const qd_expr * const *)F.e, F.d, F.d));
    reset(&F);
    /* r NULL */
    assert_int_equal(QD_ERR_ARG, qd_routh_velocities_at(F.ctx, NULL, F.eom, 1, (const qd_expr * const *)F.e, F.d, F.d));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_routh_velocities_at(F.ctx, NULL, NULL, 1, (const qd_expr * const *)F.e, F.d, F.d));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_routh_velocities_at(F.ctx, NULL, F.eom, 1, NULL, F.d, F.d));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_routh_velocities_at(F.ctx, NULL, F.eom, 1, (const qd_expr * const *)F.e, NULL, F.d));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_routh_velocities_at(F.ctx, NULL, F.eom, 1, (const qd_expr * const *)F.e, F.d, NULL));
    reset(&F);
    /* ---- qd_routh_free */
    /* r NULL */
    qd_routh_free(NULL);
    reset(&F);
    /* ---- qd_routh_print */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_routh_print(NULL, NULL, F.model, F.eom, "q", (qd_format){0}, &F.buf));
    reset(&F);
    /* r NULL */
    assert_int_equal(QD_ERR_ARG, qd_routh_print(F.ctx, NULL, F.model, F.eom, "q", (qd_format){0}, &F.buf));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_routh_print(F.ctx, NULL, NULL, F.eom, "q", (qd_format){0}, &F.buf));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_routh_print(F.ctx, NULL, F.model, NULL, "q", (qd_format){0}, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_routh_print(F.ctx, NULL, F.model, F.eom, "q", (qd_format){0}, NULL));
    reset(&F);
    /* ---- qd_routh_json */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_routh_json(NULL, NULL, F.model, F.eom, "q", &F.buf));
    reset(&F);
    /* r NULL */
    assert_int_equal(QD_ERR_ARG, qd_routh_json(F.ctx, NULL, F.model, F.eom, "q", &F.buf));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_routh_json(F.ctx, NULL, NULL, F.eom, "q", &F.buf));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_routh_json(F.ctx, NULL, F.model, NULL, "q", &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_routh_json(F.ctx, NULL, F.model, F.eom, "q", NULL));
    reset(&F);
    /* ---- qd_routh_lookup */
    /* ctx NULL */
    assert_null(qd_routh_lookup(NULL, F.model, "q"));
    reset(&F);
    /* m NULL */
    assert_null(qd_routh_lookup(F.ctx, NULL, "q"));
    reset(&F);
    /* name NULL */
    assert_null(qd_routh_lookup(F.ctx, F.model, NULL));
    reset(&F);
    /* ---- qd_routh_not_cyclic */
    /* ctx NULL */
    assert_null(qd_routh_not_cyclic(NULL, F.model, F.eom, 1, (const char * *)F.names));
    reset(&F);
    /* m NULL */
    assert_null(qd_routh_not_cyclic(F.ctx, NULL, F.eom, 1, (const char * *)F.names));
    reset(&F);
    /* e NULL */
    assert_null(qd_routh_not_cyclic(F.ctx, F.model, NULL, 1, (const char * *)F.names));
    reset(&F);
    /* why NULL */
    assert_null(qd_routh_not_cyclic(F.ctx, F.model, F.eom, 1, NULL));
    reset(&F);
    /* ---- qd_routh_ignore_read */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_routh_ignore_read(NULL, F.model, F.eom, "q", (const qd_expr * *)F.e, 1, F.z, (const char * *)F.names));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_routh_ignore_read(F.ctx, NULL, F.eom, "q", (const qd_expr * *)F.e, 1, F.z, (const char * *)F.names));
    reset(&F);
    /* list NULL */
    assert_int_equal(QD_ERR_ARG, qd_routh_ignore_read(F.ctx, F.model, F.eom, NULL, (const qd_expr * *)F.e, 1, F.z, (const char * *)F.names));
    reset(&F);
    /* ign NULL */
    assert_int_equal(QD_ERR_ARG, qd_routh_ignore_read(F.ctx, F.model, F.eom, "q", NULL, 1, F.z, (const char * *)F.names));
    reset(&F);
    /* n NULL */
    assert_int_equal(QD_ERR_ARG, qd_routh_ignore_read(F.ctx, F.model, F.eom, "q", (const qd_expr * *)F.e, 1, NULL, (const char * *)F.names));
    reset(&F);
    teardown(&F);
}

static void null_scanplot(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_conlin_scan_plot */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_scan_plot(NULL, NULL, "q", "q", NULL));
    reset(&F);
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_scan_plot(F.ctx, NULL, "q", "q", NULL));
    reset(&F);
    /* name NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_scan_plot(F.ctx, NULL, NULL, "q", NULL));
    reset(&F);
    /* title NULL */
    assert_int_equal(QD_ERR_ARG, qd_conlin_scan_plot(F.ctx, NULL, "q", NULL, NULL));
    reset(&F);
    teardown(&F);
}

static void null_scatter(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_scatter_new */
    /* ctx NULL */
    assert_null(qd_scatter_new(NULL, F.q, F.q, 1));
    reset(&F);
    /* V NULL */
    assert_null(qd_scatter_new(F.ctx, NULL, F.q, 1));
    reset(&F);
    /* r NULL */
    assert_null(qd_scatter_new(F.ctx, F.q, NULL, 1));
    reset(&F);
    /* ---- qd_scatter_from_model */
    /* ctx NULL */
    assert_null(qd_scatter_from_model(NULL, F.model, F.eom, "q", 1, F.d));
    reset(&F);
    /* m NULL */
    assert_null(qd_scatter_from_model(F.ctx, NULL, F.eom, "q", 1, F.d));
    reset(&F);
    /* e NULL */
    assert_null(qd_scatter_from_model(F.ctx, F.model, NULL, "q", 1, F.d));
    reset(&F);
    /* ---- qd_scatter_free */
    /* s NULL */
    qd_scatter_free(NULL);
    reset(&F);
    /* ---- qd_scatter_set_absorbing */
    /* s NULL */
    qd_scatter_set_absorbing(NULL, false);
    reset(&F);
    /* ---- qd_scatter_potential */
    /* s NULL */
    assert_null(qd_scatter_potential(NULL));
    reset(&F);
    /* ---- qd_scatter_radius */
    /* s NULL */
    assert_null(qd_scatter_radius(NULL));
    reset(&F);
    /* ---- qd_scatter_njumps */
    /* s NULL */
    assert_true(qd_scatter_njumps(NULL) == 0);
    reset(&F);
    /* ---- qd_scatter_jump */
    /* s NULL */
    assert_true(isnan(qd_scatter_jump(NULL, 1)));
    reset(&F);
    /* ---- qd_scatter_range */
    /* s NULL */
    assert_true(isnan(qd_scatter_range(NULL)));
    reset(&F);
    /* ---- qd_scatter_kind_name */
    /* no pointer argument */
    /* ---- qd_scatter_deflect */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_scatter_deflect(NULL, NULL, 1, 1, (qd_scatter_path *)(void *)F.blob));
    reset(&F);
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_scatter_deflect(F.ctx, NULL, 1, 1, (qd_scatter_path *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_scatter_deflect(F.ctx, NULL, 1, 1, NULL));
    reset(&F);
    /* ---- qd_scatter_dchi_db */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_scatter_dchi_db(NULL, NULL, 1, 1, F.d));
    reset(&F);
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_scatter_dchi_db(F.ctx, NULL, 1, 1, F.d));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_scatter_dchi_db(F.ctx, NULL, 1, 1, NULL));
    reset(&F);
    /* ---- qd_scatter_features_at */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_scatter_features_at(NULL, NULL, 1, (qd_scatter_features *)(void *)F.blob));
    reset(&F);
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_scatter_features_at(F.ctx, NULL, 1, (qd_scatter_features *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_scatter_features_at(F.ctx, NULL, 1, NULL));
    reset(&F);
    /* ---- qd_scatter_section_at */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_scatter_section_at(NULL, NULL, 1, 1, (qd_scatter_section *)(void *)F.blob));
    reset(&F);
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_scatter_section_at(F.ctx, NULL, 1, 1, (qd_scatter_section *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_scatter_section_at(F.ctx, NULL, 1, 1, NULL));
    reset(&F);
    /* ---- qd_scatter_lab_map */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_scatter_lab_map(NULL, 1, 1, 1, (qd_scatter_lab *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_scatter_lab_map(F.ctx, 1, 1, 1, NULL));
    reset(&F);
    /* ---- qd_scatter_lab_gamma */
    /* theta_lab NULL */
    qd_scatter_lab_gamma(1, 1, NULL, F.d);
    reset(&F);
    /* jacobian NULL */
    qd_scatter_lab_gamma(1, 1, F.d, NULL);
    reset(&F);
    /* ---- qd_scatter_lab_to_cm */
    /* cm NULL */
    assert_true(qd_scatter_lab_to_cm(1, 1, NULL) == 0);
    reset(&F);
    /* ---- qd_scatter_read */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_scatter_read(NULL, F.model, NULL, (qd_scatter_query *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_scatter_read(F.ctx, NULL, NULL, (qd_scatter_query *)(void *)F.blob));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_scatter_read(F.ctx, F.model, NULL, (qd_scatter_query *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_scatter_read(F.ctx, F.model, NULL, NULL));
    reset(&F);
    /* ---- qd_scatter_answer_query */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_scatter_answer_query(NULL, NULL, NULL, (qd_scatter_answer *)(void *)F.blob));
    reset(&F);
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_scatter_answer_query(F.ctx, NULL, NULL, (qd_scatter_answer *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_scatter_answer_query(F.ctx, NULL, NULL, NULL));
    reset(&F);
    /* ---- qd_scatter_render */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_scatter_render(NULL, NULL, NULL, "q", false, &F.buf));
    reset(&F);
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_scatter_render(F.ctx, NULL, NULL, "q", false, &F.buf));
    reset(&F);
    /* model NULL */
    assert_int_equal(QD_ERR_ARG, qd_scatter_render(F.ctx, NULL, NULL, NULL, false, &F.buf));
    reset(&F);
    /* b NULL */
    assert_int_equal(QD_ERR_ARG, qd_scatter_render(F.ctx, NULL, NULL, "q", false, NULL));
    reset(&F);
    teardown(&F);
}

static void null_scene(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_scene_points */
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_points(F.ctx, NULL, 1, NULL, F.z));
    reset(&F);
    /* pts NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_points(F.ctx, F.model, 1, NULL, F.z));
    reset(&F);
    /* n NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_points(F.ctx, F.model, 1, NULL, NULL));
    reset(&F);
    /* ---- qd_scene_points_free */
    /* pts NULL */
    qd_scene_points_free(NULL);
    reset(&F);
    /* ---- qd_scene_point_is */
    /* p NULL */
    assert_true(qd_scene_point_is(NULL, "q", 1) == 0);
    reset(&F);
    /* name NULL */
    assert_true(qd_scene_point_is(NULL, NULL, 1) == 0);
    reset(&F);
    /* ---- qd_scene_analyse */
    /* pos NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_analyse(F.ctx, NULL, 1, 1, F.z, 1, (qd_scene_shape *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_analyse(F.ctx, F.d, 1, 1, F.z, 1, NULL));
    reset(&F);
    /* ---- qd_scene_shape_free */
    /* s NULL */
    qd_scene_shape_free(NULL);
    reset(&F);
    /* ---- qd_scene_choose */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_choose(NULL, F.model, (const char * const *)F.names, 1, NULL, F.z));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_choose(F.ctx, NULL, (const char * const *)F.names, 1, NULL, F.z));
    reset(&F);
    /* words NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_choose(F.ctx, F.model, NULL, 1, NULL, F.z));
    reset(&F);
    /* pts NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_choose(F.ctx, F.model, (const char * const *)F.names, 1, NULL, F.z));
    reset(&F);
    /* n NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_choose(F.ctx, F.model, (const char * const *)F.names, 1, NULL, NULL));
    reset(&F);
    /* ---- qd_scene_find */
    /* pts NULL */
    assert_true(qd_scene_find(NULL, 1, "q", 1, F.z) == 0);
    reset(&F);
    /* name NULL */
    assert_true(qd_scene_find(NULL, 1, NULL, 1, F.z) == 0);
    reset(&F);
    /* at NULL */
    assert_true(qd_scene_find(NULL, 1, "q", 1, NULL) == 0);
    reset(&F);
    /* ---- qd_scene_named */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_named(NULL, NULL, 1, (const char * const *)F.names, 1, F.z));
    reset(&F);
    /* pts NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_named(F.ctx, NULL, 1, (const char * const *)F.names, 1, F.z));
    reset(&F);
    /* names NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_named(F.ctx, NULL, 1, NULL, 1, F.z));
    reset(&F);
    /* at NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_named(F.ctx, NULL, 1, (const char * const *)F.names, 1, NULL));
    reset(&F);
    /* ---- qd_scene_pairs */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_pairs(NULL, NULL, 1, (const char * const *)F.names, 1, F.z));
    reset(&F);
    /* pts NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_pairs(F.ctx, NULL, 1, (const char * const *)F.names, 1, F.z));
    reset(&F);
    /* pairs NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_pairs(F.ctx, NULL, 1, NULL, 1, F.z));
    reset(&F);
    /* ends NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_pairs(F.ctx, NULL, 1, (const char * const *)F.names, 1, NULL));
    reset(&F);
    /* ---- qd_scene_noutputs */
    /* pts NULL */
    assert_true(qd_scene_noutputs(NULL, 1) == 0);
    reset(&F);
    /* ---- qd_scene_add_outputs */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_add_outputs(NULL, F.sim, F.model, NULL, 1));
    reset(&F);
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_add_outputs(F.ctx, NULL, F.model, NULL, 1));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_add_outputs(F.ctx, F.sim, NULL, NULL, 1));
    reset(&F);
    /* pts NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_add_outputs(F.ctx, F.sim, F.model, NULL, 1));
    reset(&F);
    /* ---- qd_scene_nframes */
    /* no pointer argument */
    /* ---- qd_scene_sample */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_sample(NULL, NULL, 1, F.d, 1, 1, 1, 1, 1, 1, (qd_scene_frames *)(void *)F.blob));
    reset(&F);
    /* pts NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_sample(F.ctx, NULL, 1, F.d, 1, 1, 1, 1, 1, 1, (qd_scene_frames *)(void *)F.blob));
    reset(&F);
    /* rows NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_sample(F.ctx, NULL, 1, NULL, 1, 1, 1, 1, 1, 1, (qd_scene_frames *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_sample(F.ctx, NULL, 1, F.d, 1, 1, 1, 1, 1, 1, NULL));
    reset(&F);
    /* ---- qd_scene_frames_free */
    /* f NULL */
    qd_scene_frames_free(NULL);
    reset(&F);
    /* ---- qd_scene_record */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_record(NULL, F.sim, NULL, NULL, 1, NULL, NULL, NULL, (qd_sim_stats *)(void *)F.blob));
    reset(&F);
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_record(F.ctx, NULL, NULL, NULL, 1, NULL, NULL, NULL, (qd_sim_stats *)(void *)F.blob));
    reset(&F);
    /* opts NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_record(F.ctx, F.sim, NULL, NULL, 1, NULL, NULL, NULL, (qd_sim_stats *)(void *)F.blob));
    reset(&F);
    /* stats NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_record(F.ctx, F.sim, NULL, NULL, 1, NULL, NULL, NULL, NULL));
    reset(&F);
    /* ---- qd_scene_masses */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_masses(NULL, NULL, 1, 1, (const qd_expr * const *)F.e, F.d, F.d));
    reset(&F);
    /* pts NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_masses(F.ctx, NULL, 1, 1, (const qd_expr * const *)F.e, F.d, F.d));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_masses(F.ctx, NULL, 1, 1, NULL, F.d, F.d));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_masses(F.ctx, NULL, 1, 1, (const qd_expr * const *)F.e, NULL, F.d));
    reset(&F);
    /* mass NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_masses(F.ctx, NULL, 1, 1, (const qd_expr * const *)F.e, F.d, NULL));
    reset(&F);
    /* ---- qd_scene_looks */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_looks(NULL, NULL, 1, 1, (const qd_expr * const *)F.e, F.d, (qd_scene_look *)(void *)F.blob));
    reset(&F);
    /* pts NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_looks(F.ctx, NULL, 1, 1, (const qd_expr * const *)F.e, F.d, (qd_scene_look *)(void *)F.blob));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_looks(F.ctx, NULL, 1, 1, NULL, F.d, (qd_scene_look *)(void *)F.blob));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_looks(F.ctx, NULL, 1, 1, (const qd_expr * const *)F.e, NULL, (qd_scene_look *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_looks(F.ctx, NULL, 1, 1, (const qd_expr * const *)F.e, F.d, NULL));
    reset(&F);
    /* ---- qd_scene_walls */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_walls(NULL, NULL, NULL, NULL, 1, F.i, NULL, F.z));
    reset(&F);
    /* pts NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_walls(F.ctx, NULL, NULL, NULL, 1, F.i, NULL, F.z));
    reset(&F);
    /* plane NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_walls(F.ctx, NULL, NULL, NULL, 1, NULL, NULL, F.z));
    reset(&F);
    /* nwalls NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_walls(F.ctx, NULL, NULL, NULL, 1, F.i, NULL, NULL));
    reset(&F);
    /* ---- qd_scene_links */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_links(NULL, F.d, 1, 1, F.z, 1, NULL, F.z, F.i));
    reset(&F);
    /* pos NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_links(F.ctx, NULL, 1, 1, F.z, 1, NULL, F.z, F.i));
    reset(&F);
    /* springs NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_links(F.ctx, F.d, 1, 1, NULL, 1, NULL, F.z, F.i));
    reset(&F);
    /* links NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_links(F.ctx, F.d, 1, 1, F.z, 1, NULL, F.z, F.i));
    reset(&F);
    /* nlinks NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_links(F.ctx, F.d, 1, 1, F.z, 1, NULL, NULL, F.i));
    reset(&F);
    /* plane NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_links(F.ctx, F.d, 1, 1, F.z, 1, NULL, F.z, NULL));
    reset(&F);
    /* ---- qd_scene_json */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_json(NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_json(NULL, NULL));
    reset(&F);
    /* ---- qd_scene_html */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_html(NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_html(NULL, NULL));
    reset(&F);
    /* ---- qd_scene_setup_new */
    /* ctx NULL */
    assert_null(qd_scene_setup_new(NULL, NULL, F.model, NULL));
    reset(&F);
    /* set NULL */
    assert_null(qd_scene_setup_new(F.ctx, NULL, F.model, NULL));
    reset(&F);
    /* m NULL */
    assert_null(qd_scene_setup_new(F.ctx, NULL, NULL, NULL));
    reset(&F);
    /* ---- qd_scene_setup_record */
    /* sc NULL */
    assert_int_equal(QD_ERR_ARG, qd_scene_setup_record(NULL, NULL, NULL, NULL, (qd_sim_stats *)(void *)F.blob));
    reset(&F);
    /* ---- qd_scene_setup_scene */
    /* sc NULL */
    assert_null(qd_scene_setup_scene(NULL));
    reset(&F);
    /* ---- qd_scene_setup_free */
    /* sc NULL */
    qd_scene_setup_free(NULL);
    reset(&F);
    teardown(&F);
}

static void null_sim(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_sim_method_name */
    /* no pointer argument */
    /* ---- qd_sim_method_from_name */
    /* name NULL */
    assert_true(qd_sim_method_from_name(NULL, NULL) == 0);
    reset(&F);
    /* m NULL */
    assert_true(qd_sim_method_from_name("q", NULL) == 0);
    reset(&F);
    /* ---- qd_sim_method_order */
    /* no pointer argument */
    /* ---- qd_sim_method_adaptive */
    /* no pointer argument */
    /* ---- qd_sim_new */
    /* ctx NULL */
    assert_null(qd_sim_new(NULL, F.model, F.eom));
    reset(&F);
    /* m NULL */
    assert_null(qd_sim_new(F.ctx, NULL, F.eom));
    reset(&F);
    /* e NULL */
    assert_null(qd_sim_new(F.ctx, F.model, NULL));
    reset(&F);
    /* ---- qd_sim_new_hamilton */
    /* ctx NULL */
    assert_null(qd_sim_new_hamilton(NULL, F.model));
    reset(&F);
    /* m NULL */
    assert_null(qd_sim_new_hamilton(F.ctx, NULL));
    reset(&F);
    /* ---- qd_sim_new_speeds */
    /* ctx NULL */
    assert_null(qd_sim_new_speeds(NULL, F.model, NULL));
    reset(&F);
    /* m NULL */
    assert_null(qd_sim_new_speeds(F.ctx, NULL, NULL));
    reset(&F);
    /* e NULL */
    assert_null(qd_sim_new_speeds(F.ctx, F.model, NULL));
    reset(&F);
    /* ---- qd_sim_free */
    /* s NULL */
    qd_sim_free(NULL);
    reset(&F);
    /* ---- qd_sim_add_output */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_add_output(NULL, "q", F.q));
    reset(&F);
    /* name NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_add_output(F.sim, NULL, F.q));
    reset(&F);
    /* x NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_add_output(F.sim, "q", NULL));
    reset(&F);
    /* ---- qd_sim_inputs_ready */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_inputs_ready(NULL, 1, 1));
    reset(&F);
    /* ---- qd_sim_input_expr */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_input_expr(NULL, "q", F.q));
    reset(&F);
    /* name NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_input_expr(F.sim, NULL, F.q));
    reset(&F);
    /* x NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_input_expr(F.sim, "q", NULL));
    reset(&F);
    /* ---- qd_sim_input_table */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_input_table(NULL, "q", 1, F.d, F.d));
    reset(&F);
    /* name NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_input_table(F.sim, NULL, 1, F.d, F.d));
    reset(&F);
    /* t NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_input_table(F.sim, "q", 1, NULL, F.d));
    reset(&F);
    /* v NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_input_table(F.sim, "q", 1, F.d, NULL));
    reset(&F);
    /* ---- qd_sim_input_table_read */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_input_table_read(NULL, "q", "q", 1, F.z));
    reset(&F);
    /* name NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_input_table_read(F.sim, NULL, "q", 1, F.z));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_input_table_read(F.sim, "q", NULL, 1, F.z));
    reset(&F);
    /* bad_line NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_input_table_read(F.sim, "q", "q", 1, NULL));
    reset(&F);
    /* ---- qd_sim_input_callback */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_input_callback(NULL, "q", NULL, NULL));
    reset(&F);
    /* name NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_input_callback(F.sim, NULL, NULL, NULL));
    reset(&F);
    /* fn NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_input_callback(F.sim, "q", NULL, NULL));
    reset(&F);
    /* ---- qd_sim_add_event */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_add_event(NULL, F.q, 1, (const qd_expr * const *)F.e, false));
    reset(&F);
    /* g NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_add_event(F.sim, NULL, 1, (const qd_expr * const *)F.e, false));
    reset(&F);
    /* ---- qd_sim_set_native */
    /* s NULL */
    qd_sim_set_native(NULL, NULL);
    reset(&F);
    /* rhs NULL */
    qd_sim_set_native(F.sim, NULL);
    reset(&F);
    /* ---- qd_sim_load_native_taylor */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_load_native_taylor(NULL, "q", F.b));
    reset(&F);
    /* ---- qd_sim_ndof */
    /* s NULL */
    assert_true(qd_sim_ndof(NULL) == 0);
    reset(&F);
    /* ---- qd_sim_ncon */
    /* s NULL */
    assert_true(qd_sim_ncon(NULL) == 0);
    reset(&F);
    /* ---- qd_sim_nspeeds */
    /* s NULL */
    assert_true(qd_sim_nspeeds(NULL) == 0);
    reset(&F);
    /* ---- qd_sim_nevents */
    /* s NULL */
    assert_true(qd_sim_nevents(NULL) == 0);
    reset(&F);
    /* ---- qd_sim_canonical */
    /* s NULL */
    assert_true(qd_sim_canonical(NULL) == 0);
    reset(&F);
    /* ---- qd_sim_separable */
    /* s NULL */
    assert_true(qd_sim_separable(NULL) == 0);
    reset(&F);
    /* ---- qd_sim_conservative */
    /* s NULL */
    assert_true(qd_sim_conservative(NULL) == 0);
    reset(&F);
    /* ---- qd_sim_default_method */
    /* s NULL */
    (void)qd_sim_default_method(NULL, false);
    reset(&F);
    /* ---- qd_stop_str */
    /* no pointer argument */
    /* ---- qd_stop_ok */
    /* no pointer argument */
    /* ---- qd_sim_constraint_error */
    /* s NULL */
    assert_true(isnan(qd_sim_constraint_error(NULL, 1)));
    reset(&F);
    /* ---- qd_sim_initial_solved */
    /* s NULL */
    assert_true(qd_sim_initial_solved(NULL, 1) == 0);
    reset(&F);
    /* ---- qd_sim_columns */
    /* s NULL */
    assert_true(qd_sim_columns(NULL, (qd_sim_method){0}, (const char * *)F.names, 1) == 0);
    reset(&F);
    /* ---- qd_sim_check_opts */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_check_opts(NULL, NULL));
    reset(&F);
    /* opts NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_check_opts(F.ctx, NULL));
    reset(&F);
    /* ---- qd_sim_compile */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_compile(NULL));
    reset(&F);
    /* ---- qd_sim_jit */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_jit(NULL));
    reset(&F);
    /* ---- qd_sim_compiled */
    /* s NULL */
    assert_true(qd_sim_compiled(NULL) == 0);
    reset(&F);
    /* ---- qd_sim_run */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_run(NULL, NULL, NULL, NULL, (qd_sim_stats *)(void *)F.blob, F.d));
    reset(&F);
    /* opts NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_run(F.sim, NULL, NULL, NULL, (qd_sim_stats *)(void *)F.blob, F.d));
    reset(&F);
    /* ---- qd_sim_run_with */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_run_with(NULL, F.sim, NULL, NULL, NULL, (qd_sim_stats *)(void *)F.blob, F.d));
    reset(&F);
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_run_with(F.ctx, NULL, NULL, NULL, NULL, (qd_sim_stats *)(void *)F.blob, F.d));
    reset(&F);
    /* opts NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_run_with(F.ctx, F.sim, NULL, NULL, NULL, (qd_sim_stats *)(void *)F.blob, F.d));
    reset(&F);
    /* ---- qd_sim_ncontacts */
    /* s NULL */
    assert_true(qd_sim_ncontacts(NULL) == 0);
    reset(&F);
    /* ---- qd_sim_transitions */
    /* s NULL */
    assert_null(qd_sim_transitions(NULL, F.z));
    reset(&F);
    /* n NULL */
    assert_null(qd_sim_transitions(F.sim, NULL));
    reset(&F);
    /* ---- qd_stop_name */
    /* no pointer argument */
    /* ---- qd_sim_stop_json */
    /* j NULL */
    qd_sim_stop_json(NULL, NULL);
    reset(&F);
    /* ---- qd_sim_summary_print */
    /* r NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_summary_print(NULL, "q", &F.buf));
    reset(&F);
    /* prefix NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_summary_print(NULL, NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_summary_print(NULL, "q", NULL));
    reset(&F);
    /* ---- qd_sim_summary_json */
    /* j NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_summary_json(NULL, NULL));
    reset(&F);
    /* ---- qd_sim_event_column */
    /* s NULL */
    assert_true(qd_sim_event_column(NULL) == 0);
    reset(&F);
    /* ---- qd_sim_columns_json */
    /* j NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_columns_json(NULL, F.sim, (qd_sim_method){0}));
    reset(&F);
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_columns_json(NULL, NULL, (qd_sim_method){0}));
    reset(&F);
    /* ---- qd_sim_opts_sample */
    /* o NULL */
    qd_sim_opts_sample(NULL, 1);
    reset(&F);
    /* ---- qd_sim_plot_json */
    /* j NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_plot_json(NULL, "q", 1, F.d));
    reset(&F);
    /* file NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_plot_json(NULL, NULL, 1, F.d));
    reset(&F);
    /* range NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_plot_json(NULL, "q", 1, NULL));
    reset(&F);
    /* ---- qd_sim_csv_header */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_csv_header(NULL, (qd_sim_method){0}, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_csv_header(F.sim, (qd_sim_method){0}, NULL));
    reset(&F);
    /* ---- qd_sim_csv_row */
    /* row NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_csv_row(1, NULL, false, 1, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_csv_row(1, F.d, false, 1, NULL));
    reset(&F);
    /* ---- qd_sim_json_row */
    /* j NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_json_row(NULL, 1, F.d, false, 1));
    reset(&F);
    /* row NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_json_row(NULL, 1, NULL, false, 1));
    reset(&F);
    /* ---- qd_sim_writer_init */
    /* w NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_writer_init(NULL, F.sim, (qd_sim_method){0}));
    reset(&F);
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_writer_init(NULL, NULL, (qd_sim_method){0}));
    reset(&F);
    /* ---- qd_sim_writer_sink */
    /* w NULL */
    (void)qd_sim_writer_sink(NULL, 1, F.d);
    reset(&F);
    /* row NULL */
    (void)qd_sim_writer_sink(NULL, 1, NULL);
    reset(&F);
    /* ---- qd_sim_writer_free */
    /* w NULL */
    qd_sim_writer_free(NULL);
    reset(&F);
    teardown(&F);
}

static void null_simsetup(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_sim_form_of */
    /* m NULL */
    (void)qd_sim_form_of(NULL, false);
    reset(&F);
    /* ---- qd_sim_setup_new */
    /* ctx NULL */
    assert_null(qd_sim_setup_new(NULL, F.model, false));
    reset(&F);
    /* m NULL */
    assert_null(qd_sim_setup_new(F.ctx, NULL, false));
    reset(&F);
    /* ---- qd_sim_setup_free */
    /* s NULL */
    qd_sim_setup_free(NULL);
    reset(&F);
    /* ---- qd_sim_setup_sim */
    /* s NULL */
    assert_null(qd_sim_setup_sim(NULL));
    reset(&F);
    /* ---- qd_sim_setup_form */
    /* s NULL */
    (void)qd_sim_setup_form(NULL);
    reset(&F);
    /* ---- qd_sim_setup_eom */
    /* s NULL */
    assert_null(qd_sim_setup_eom(NULL));
    reset(&F);
    /* ---- qd_sim_setup_speeds_eom */
    /* s NULL */
    assert_null(qd_sim_setup_speeds_eom(NULL));
    reset(&F);
    /* ---- qd_sim_setup_ncon */
    /* s NULL */
    assert_true(qd_sim_setup_ncon(NULL) == 0);
    reset(&F);
    /* ---- qd_sim_setup_con */
    /* s NULL */
    assert_null(qd_sim_setup_con(NULL, 1));
    reset(&F);
    /* ---- qd_sim_setup_state */
    /* s NULL */
    assert_true(qd_sim_setup_state(NULL, NULL, (const double * *)(void *)F.p) == 0);
    reset(&F);
    /* ---- qd_sim_setup_initial */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_initial(NULL, "q"));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_initial(NULL, NULL));
    reset(&F);
    /* ---- qd_sim_setup_restart */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_restart(NULL, "q", (qd_sim_opts *)(void *)F.blob));
    reset(&F);
    /* initial NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_restart(NULL, NULL, (qd_sim_opts *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_restart(NULL, "q", NULL));
    reset(&F);
    /* ---- qd_sim_setup_read */
    /* s NULL */
    assert_null(qd_sim_setup_read(NULL, "q", 1, 1));
    reset(&F);
    /* text NULL */
    assert_null(qd_sim_setup_read(NULL, NULL, 1, 1));
    reset(&F);
    /* ---- qd_sim_setup_outputs */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_outputs(NULL, "q"));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_outputs(NULL, NULL));
    reset(&F);
    /* ---- qd_sim_setup_output */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_output(NULL, "q", "q", 1, 1));
    reset(&F);
    /* name NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_output(NULL, NULL, "q", 1, 1));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_output(NULL, "q", NULL, 1, 1));
    reset(&F);
    /* ---- qd_sim_setup_event */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_event(NULL, "q", false));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_event(NULL, NULL, false));
    reset(&F);
    /* ---- qd_sim_setup_crossing */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_crossing(NULL, "q", 1, 1, 1, 1));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_crossing(NULL, NULL, 1, 1, 1, 1));
    reset(&F);
    /* ---- qd_sim_setup_input */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_input(NULL, "q", "q", 1, 1));
    reset(&F);
    /* name NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_input(NULL, NULL, "q", 1, 1));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_input(NULL, "q", NULL, 1, 1));
    reset(&F);
    /* ---- qd_sim_setup_input_text */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_input_text(NULL, "q", NULL, F.c, 1, F.z, F.z));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_input_text(NULL, NULL, NULL, F.c, 1, F.z, F.z));
    reset(&F);
    /* name NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_input_text(NULL, "q", NULL, NULL, 1, F.z, F.z));
    reset(&F);
    /* a NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_input_text(NULL, "q", NULL, F.c, 1, NULL, F.z));
    reset(&F);
    /* b NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_input_text(NULL, "q", NULL, F.c, 1, F.z, NULL));
    reset(&F);
    /* ---- qd_sim_setup_options */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_options(NULL, NULL, (qd_sim_opts *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_options(NULL, NULL, NULL));
    reset(&F);
    /* ---- qd_sim_setup_period_of */
    /* s NULL */
    assert_true(isnan(qd_sim_setup_period_of(NULL)));
    reset(&F);
    /* ---- qd_sim_setup_period */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_period(NULL, "q", (qd_sim_opts *)(void *)F.blob, F.d));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_period(NULL, NULL, (qd_sim_opts *)(void *)F.blob, F.d));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_period(NULL, "q", NULL, F.d));
    reset(&F);
    /* period NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_period(NULL, "q", (qd_sim_opts *)(void *)F.blob, NULL));
    reset(&F);
    /* ---- qd_sim_setup_native */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_native(NULL, NULL, F.c, 1));
    reset(&F);
    /* ---- qd_sim_setup_jit */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_jit(NULL, F.c, 1));
    reset(&F);
    /* note NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_jit(NULL, NULL, 1));
    reset(&F);
    /* ---- qd_sim_setup_lqr */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_lqr(NULL, "q", "q", "q", (qd_sim_lqr *)(void *)F.blob));
    reset(&F);
    /* name NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_lqr(NULL, NULL, "q", "q", (qd_sim_lqr *)(void *)F.blob));
    reset(&F);
    /* about NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_lqr(NULL, "q", NULL, "q", (qd_sim_lqr *)(void *)F.blob));
    reset(&F);
    /* weights NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_lqr(NULL, "q", "q", NULL, (qd_sim_lqr *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_setup_lqr(NULL, "q", "q", "q", NULL));
    reset(&F);
    /* ---- qd_sim_lqr_note */
    /* l NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_lqr_note(NULL, "q", &F.buf));
    reset(&F);
    /* prefix NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_lqr_note(NULL, NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_sim_lqr_note(NULL, "q", NULL));
    reset(&F);
    /* ---- qd_sim_lqr_free */
    /* l NULL */
    qd_sim_lqr_free(NULL);
    reset(&F);
    teardown(&F);
}

static void null_speeds(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_speeds_method_name */
    /* no pointer argument */
    /* ---- qd_speeds_method_from_name */
    /* name NULL */
    assert_true(qd_speeds_method_from_name(NULL, NULL) == 0);
    reset(&F);
    /* m NULL */
    assert_true(qd_speeds_method_from_name("q", NULL) == 0);
    reset(&F);
    /* ---- qd_speeds_derive */
    /* ctx NULL */
    assert_null(qd_speeds_derive(NULL, F.model, NULL));
    reset(&F);
    /* m NULL */
    assert_null(qd_speeds_derive(F.ctx, NULL, NULL));
    reset(&F);
    /* ---- qd_speeds_eom_free */
    /* e NULL */
    qd_speeds_eom_free(NULL);
    reset(&F);
    /* ---- qd_hamel_coefficients */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_hamel_coefficients(NULL, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (const qd_expr * *)F.e));
    reset(&F);
    /* q NULL */
    assert_int_equal(QD_ERR_ARG, qd_hamel_coefficients(F.ctx, 1, NULL, (const qd_expr * const *)F.e, (const qd_expr * *)F.e));
    reset(&F);
    /* a NULL */
    assert_int_equal(QD_ERR_ARG, qd_hamel_coefficients(F.ctx, 1, (const qd_expr * const *)F.e, NULL, (const qd_expr * *)F.e));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_hamel_coefficients(F.ctx, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, NULL));
    reset(&F);
    /* ---- qd_speeds_hamel_coefficients */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_hamel_coefficients(NULL, NULL, (const qd_expr * *)F.e));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_hamel_coefficients(F.ctx, NULL, (const qd_expr * *)F.e));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_hamel_coefficients(F.ctx, NULL, NULL));
    reset(&F);
    /* ---- qd_speeds_solve */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_solve(NULL, NULL, 1));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_solve(F.ctx, NULL, 1));
    reset(&F);
    /* ---- qd_speeds_eval */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_eval(NULL, NULL, 1, (const qd_expr * const *)F.e, F.d, F.d, F.d, F.d));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_eval(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, F.d, F.d, F.d));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_eval(F.ctx, NULL, 1, NULL, F.d, F.d, F.d, F.d));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_eval(F.ctx, NULL, 1, (const qd_expr * const *)F.e, NULL, F.d, F.d, F.d));
    reset(&F);
    /* ---- qd_speeds_from_velocities */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_from_velocities(NULL, NULL, 1, (const qd_expr * const *)F.e, F.d, F.d));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_from_velocities(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, F.d));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_from_velocities(F.ctx, NULL, 1, NULL, F.d, F.d));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_from_velocities(F.ctx, NULL, 1, (const qd_expr * const *)F.e, NULL, F.d));
    reset(&F);
    /* u NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_from_velocities(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, NULL));
    reset(&F);
    /* ---- qd_speeds_state_read */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_state_read(NULL, F.model, NULL, "q", NULL));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_state_read(F.ctx, NULL, NULL, "q", NULL));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_state_read(F.ctx, F.model, NULL, "q", NULL));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_speeds_state_read(F.ctx, F.model, NULL, NULL, NULL));
    reset(&F);
    teardown(&F);
}

static void null_stability(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_steady_derive */
    /* ctx NULL */
    assert_null(qd_steady_derive(NULL, F.model, F.eom, 1, (const qd_expr * const *)F.e, false));
    reset(&F);
    /* m NULL */
    assert_null(qd_steady_derive(F.ctx, NULL, F.eom, 1, (const qd_expr * const *)F.e, false));
    reset(&F);
    /* e NULL */
    assert_null(qd_steady_derive(F.ctx, F.model, NULL, 1, (const qd_expr * const *)F.e, false));
    reset(&F);
    /* cyc NULL */
    assert_null(qd_steady_derive(F.ctx, F.model, F.eom, 1, NULL, false));
    reset(&F);
    /* ---- qd_steady_free */
    /* s NULL */
    qd_steady_free(NULL);
    reset(&F);
    /* ---- qd_steady_find */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_steady_find(NULL, NULL, 1, (const qd_expr * const *)F.e, F.d, F.b, F.b, F.b, (qd_steady_point *)(void *)F.blob, F.d));
    reset(&F);
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_steady_find(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, F.b, F.b, F.b, (qd_steady_point *)(void *)F.blob, F.d));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_steady_find(F.ctx, NULL, 1, NULL, F.d, F.b, F.b, F.b, (qd_steady_point *)(void *)F.blob, F.d));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_steady_find(F.ctx, NULL, 1, (const qd_expr * const *)F.e, NULL, F.b, F.b, F.b, (qd_steady_point *)(void *)F.blob, F.d));
    reset(&F);
    /* xfix NULL */
    assert_int_equal(QD_ERR_ARG, qd_steady_find(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, NULL, F.b, F.b, (qd_steady_point *)(void *)F.blob, F.d));
    reset(&F);
    /* wfix NULL */
    assert_int_equal(QD_ERR_ARG, qd_steady_find(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, F.b, NULL, F.b, (qd_steady_point *)(void *)F.blob, F.d));
    reset(&F);
    /* pfix NULL */
    assert_int_equal(QD_ERR_ARG, qd_steady_find(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, F.b, F.b, NULL, (qd_steady_point *)(void *)F.blob, F.d));
    reset(&F);
    /* pt NULL */
    assert_int_equal(QD_ERR_ARG, qd_steady_find(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, F.b, F.b, F.b, NULL, F.d));
    reset(&F);
    /* ---- qd_steady_find_all */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_steady_find_all(NULL, NULL, 1, (const qd_expr * const *)F.e, F.d, F.b, F.b, F.b, F.b, NULL, (qd_steady_set *)(void *)F.blob));
    reset(&F);
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_steady_find_all(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, F.b, F.b, F.b, F.b, NULL, (qd_steady_set *)(void *)F.blob));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_steady_find_all(F.ctx, NULL, 1, NULL, F.d, F.b, F.b, F.b, F.b, NULL, (qd_steady_set *)(void *)F.blob));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_steady_find_all(F.ctx, NULL, 1, (const qd_expr * const *)F.e, NULL, F.b, F.b, F.b, F.b, NULL, (qd_steady_set *)(void *)F.blob));
    reset(&F);
    /* xfix NULL */
    assert_int_equal(QD_ERR_ARG, qd_steady_find_all(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, NULL, F.b, F.b, F.b, NULL, (qd_steady_set *)(void *)F.blob));
    reset(&F);
    /* wfix NULL */
    assert_int_equal(QD_ERR_ARG, qd_steady_find_all(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, F.b, NULL, F.b, F.b, NULL, (qd_steady_set *)(void *)F.blob));
    reset(&F);
    /* pfix NULL */
    assert_int_equal(QD_ERR_ARG, qd_steady_find_all(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, F.b, F.b, NULL, F.b, NULL, (qd_steady_set *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_steady_find_all(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, F.b, F.b, F.b, F.b, NULL, NULL));
    reset(&F);
    /* ---- qd_steady_set_free */
    /* set NULL */
    qd_steady_set_free(NULL);
    reset(&F);
    /* ---- qd_steady_derive_named */
    /* ctx NULL */
    assert_null(qd_steady_derive_named(NULL, F.model, F.eom, "q", "q", false));
    reset(&F);
    /* m NULL */
    assert_null(qd_steady_derive_named(F.ctx, NULL, F.eom, "q", "q", false));
    reset(&F);
    /* e NULL */
    assert_null(qd_steady_derive_named(F.ctx, F.model, NULL, "q", "q", false));
    reset(&F);
    /* field NULL */
    assert_null(qd_steady_derive_named(F.ctx, F.model, F.eom, NULL, "q", false));
    reset(&F);
    /* names NULL */
    assert_null(qd_steady_derive_named(F.ctx, F.model, F.eom, "q", NULL, false));
    reset(&F);
    /* ---- qd_steady_given_read */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_steady_given_read(NULL, NULL, F.model, NULL, (qd_steady_given *)(void *)F.blob));
    reset(&F);
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_steady_given_read(F.ctx, NULL, F.model, NULL, (qd_steady_given *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_steady_given_read(F.ctx, NULL, NULL, NULL, (qd_steady_given *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_steady_given_read(F.ctx, NULL, F.model, NULL, NULL));
    reset(&F);
    /* ---- qd_steady_given_free */
    /* g NULL */
    qd_steady_given_free(NULL);
    reset(&F);
    /* ---- qd_stability_analyze */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_analyze(NULL, NULL, 1, (const qd_expr * const *)F.e, F.d, NULL, (qd_stability *)(void *)F.blob));
    reset(&F);
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_analyze(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, NULL, (qd_stability *)(void *)F.blob));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_analyze(F.ctx, NULL, 1, NULL, F.d, NULL, (qd_stability *)(void *)F.blob));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_analyze(F.ctx, NULL, 1, (const qd_expr * const *)F.e, NULL, NULL, (qd_stability *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_analyze(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d, NULL, NULL));
    reset(&F);
    /* ---- qd_stability_free */
    /* st NULL */
    qd_stability_free(NULL);
    reset(&F);
    /* ---- qd_stability_problem_read */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_problem_read(NULL, F.model, F.eom, NULL, (qd_stability_problem *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_problem_read(F.ctx, NULL, F.eom, NULL, (qd_stability_problem *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_problem_read(F.ctx, F.model, NULL, NULL, (qd_stability_problem *)(void *)F.blob));
    reset(&F);
    /* spec NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_problem_read(F.ctx, F.model, F.eom, NULL, (qd_stability_problem *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_problem_read(F.ctx, F.model, F.eom, NULL, NULL));
    reset(&F);
    /* ---- qd_stability_problem_solve */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_problem_solve(NULL, NULL));
    reset(&F);
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_problem_solve(F.ctx, NULL));
    reset(&F);
    /* ---- qd_stability_problem_scan */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_problem_scan(NULL, NULL, F.model, "q", 1, 1, 1, (qd_scan *)(void *)F.blob));
    reset(&F);
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_problem_scan(F.ctx, NULL, F.model, "q", 1, 1, 1, (qd_scan *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_problem_scan(F.ctx, NULL, NULL, "q", 1, 1, 1, (qd_scan *)(void *)F.blob));
    reset(&F);
    /* param NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_problem_scan(F.ctx, NULL, F.model, NULL, 1, 1, 1, (qd_scan *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_problem_scan(F.ctx, NULL, F.model, "q", 1, 1, 1, NULL));
    reset(&F);
    /* ---- qd_stability_scan_write */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_scan_write(NULL, NULL, "q", NULL, false, &F.buf));
    reset(&F);
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_scan_write(F.ctx, NULL, "q", NULL, false, &F.buf));
    reset(&F);
    /* param NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_scan_write(F.ctx, NULL, NULL, NULL, false, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_scan_write(F.ctx, NULL, "q", NULL, false, NULL));
    reset(&F);
    /* ---- qd_stability_problem_free */
    /* p NULL */
    qd_stability_problem_free(NULL);
    reset(&F);
    /* ---- qd_stability_print */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_print(NULL, NULL, false, &F.buf));
    reset(&F);
    /* r NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_print(F.ctx, NULL, false, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_print(F.ctx, NULL, false, NULL));
    reset(&F);
    /* ---- qd_stability_scan */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_scan(NULL, NULL, F.model, "q", 1, 1, F.b, F.b, F.b, F.b, NULL, NULL, (qd_scan *)(void *)F.blob));
    reset(&F);
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_scan(F.ctx, NULL, F.model, "q", 1, 1, F.b, F.b, F.b, F.b, NULL, NULL, (qd_scan *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_scan(F.ctx, NULL, NULL, "q", 1, 1, F.b, F.b, F.b, F.b, NULL, NULL, (qd_scan *)(void *)F.blob));
    reset(&F);
    /* param NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_scan(F.ctx, NULL, F.model, NULL, 1, 1, F.b, F.b, F.b, F.b, NULL, NULL, (qd_scan *)(void *)F.blob));
    reset(&F);
    /* xfix NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_scan(F.ctx, NULL, F.model, "q", 1, 1, NULL, F.b, F.b, F.b, NULL, NULL, (qd_scan *)(void *)F.blob));
    reset(&F);
    /* wfix NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_scan(F.ctx, NULL, F.model, "q", 1, 1, F.b, NULL, F.b, F.b, NULL, NULL, (qd_scan *)(void *)F.blob));
    reset(&F);
    /* pfix NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_scan(F.ctx, NULL, F.model, "q", 1, 1, F.b, F.b, NULL, F.b, NULL, NULL, (qd_scan *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_scan(F.ctx, NULL, F.model, "q", 1, 1, F.b, F.b, F.b, F.b, NULL, NULL, NULL));
    reset(&F);
    /* ---- qd_steady_unknown_name */
    /* s NULL */
    assert_true(qd_steady_unknown_name(NULL, 1, F.c, 1) == 0);
    reset(&F);
    /* out NULL */
    assert_true(qd_steady_unknown_name(NULL, 1, NULL, 1) == 0);
    reset(&F);
    /* ---- qd_stability_scan_followed */
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_scan_followed(NULL, false, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_stability_scan_followed(NULL, false, NULL));
    reset(&F);
    teardown(&F);
}

static void null_state(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_state_layout */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_layout(NULL, F.model, 1, (const qd_expr * const *)F.e, (const qd_expr * *)F.e, F.d));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_layout(F.ctx, NULL, 1, (const qd_expr * const *)F.e, (const qd_expr * *)F.e, F.d));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_layout(F.ctx, F.model, 1, (const qd_expr * const *)F.e, NULL, F.d));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_layout(F.ctx, F.model, 1, (const qd_expr * const *)F.e, (const qd_expr * *)F.e, NULL));
    reset(&F);
    /* ---- qd_state_init */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_init(NULL, F.model, NULL));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_init(F.ctx, NULL, NULL));
    reset(&F);
    /* st NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_init(F.ctx, F.model, NULL));
    reset(&F);
    /* ---- qd_state_append */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_append(NULL, NULL, 1, (const qd_expr * const *)F.e, F.d));
    reset(&F);
    /* st NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_append(F.ctx, NULL, 1, (const qd_expr * const *)F.e, F.d));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_append(F.ctx, NULL, 1, NULL, F.d));
    reset(&F);
    /* ---- qd_state_initial */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_initial(NULL, F.model, NULL));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_initial(F.ctx, NULL, NULL));
    reset(&F);
    /* st NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_initial(F.ctx, F.model, NULL));
    reset(&F);
    /* ---- qd_state_find */
    /* st NULL */
    assert_true(qd_state_find(NULL, F.q) == 0);
    reset(&F);
    /* sym NULL */
    assert_true(qd_state_find(NULL, NULL) == 0);
    reset(&F);
    /* ---- qd_state_free */
    /* st NULL */
    qd_state_free(NULL);
    reset(&F);
    /* ---- qd_state_read */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_read(NULL, F.model, NULL, "q", NULL));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_read(F.ctx, NULL, NULL, "q", NULL));
    reset(&F);
    /* st NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_read(F.ctx, F.model, NULL, "q", NULL));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_read(F.ctx, F.model, NULL, NULL, NULL));
    reset(&F);
    /* ---- qd_state_read_ranges */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_read_ranges(NULL, F.model, NULL, "q", NULL, F.d, F.d));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_read_ranges(F.ctx, NULL, NULL, "q", NULL, F.d, F.d));
    reset(&F);
    /* st NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_read_ranges(F.ctx, F.model, NULL, "q", NULL, F.d, F.d));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_read_ranges(F.ctx, F.model, NULL, NULL, NULL, F.d, F.d));
    reset(&F);
    /* lo NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_read_ranges(F.ctx, F.model, NULL, "q", NULL, NULL, F.d));
    reset(&F);
    /* hi NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_read_ranges(F.ctx, F.model, NULL, "q", NULL, F.d, NULL));
    reset(&F);
    /* ---- qd_state_value */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_value(NULL, F.model, "q", 1, 1, (const qd_expr * *)F.e, F.d));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_value(F.ctx, F.model, NULL, 1, 1, (const qd_expr * *)F.e, F.d));
    reset(&F);
    /* exact NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_value(F.ctx, F.model, "q", 1, 1, NULL, F.d));
    reset(&F);
    /* val NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_value(F.ctx, F.model, "q", 1, 1, (const qd_expr * *)F.e, NULL));
    reset(&F);
    /* ---- qd_state_range */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_range(NULL, F.model, "q", 1, 1, F.d, F.d));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_range(F.ctx, NULL, "q", 1, 1, F.d, F.d));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_range(F.ctx, F.model, NULL, 1, 1, F.d, F.d));
    reset(&F);
    /* a NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_range(F.ctx, F.model, "q", 1, 1, NULL, F.d));
    reset(&F);
    /* b NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_range(F.ctx, F.model, "q", 1, 1, F.d, NULL));
    reset(&F);
    /* ---- qd_state_named_range */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_named_range(NULL, F.model, "q", F.c, 1, F.d, F.d));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_named_range(F.ctx, F.model, NULL, F.c, 1, F.d, F.d));
    reset(&F);
    /* name NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_named_range(F.ctx, F.model, "q", NULL, 1, F.d, F.d));
    reset(&F);
    /* a NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_named_range(F.ctx, F.model, "q", F.c, 1, NULL, F.d));
    reset(&F);
    /* b NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_named_range(F.ctx, F.model, "q", F.c, 1, F.d, NULL));
    reset(&F);
    /* ---- qd_state_read_point */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_read_point(NULL, F.model, NULL, "q", 1, (const qd_expr * const *)F.e, (const qd_expr * *)F.e));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_read_point(F.ctx, NULL, NULL, "q", 1, (const qd_expr * const *)F.e, (const qd_expr * *)F.e));
    reset(&F);
    /* st NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_read_point(F.ctx, F.model, NULL, "q", 1, (const qd_expr * const *)F.e, (const qd_expr * *)F.e));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_read_point(F.ctx, F.model, NULL, NULL, 1, (const qd_expr * const *)F.e, (const qd_expr * *)F.e));
    reset(&F);
    /* q NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_read_point(F.ctx, F.model, NULL, "q", 1, NULL, (const qd_expr * *)F.e));
    reset(&F);
    /* at NULL */
    assert_int_equal(QD_ERR_ARG, qd_state_read_point(F.ctx, F.model, NULL, "q", 1, (const qd_expr * const *)F.e, NULL));
    reset(&F);
    /* ---- qd_state_item_end */
    /* text NULL */
    assert_true(qd_state_item_end(NULL, 1) == 0);
    reset(&F);
    teardown(&F);
}

static void null_statespace(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_linearize */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_linearize(NULL, F.eom, F.model, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (qd_statespace *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_linearize(F.ctx, NULL, F.model, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (qd_statespace *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_linearize(F.ctx, F.eom, NULL, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, (qd_statespace *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_linearize(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, (const qd_expr * const *)F.e, NULL));
    reset(&F);
    /* ---- qd_statespace_free */
    /* s NULL */
    qd_statespace_free(NULL);
    reset(&F);
    /* ---- qd_linearize_about */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_linearize_about(NULL, F.eom, F.model, "q", (qd_statespace *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_linearize_about(F.ctx, NULL, F.model, "q", (qd_statespace *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_linearize_about(F.ctx, F.eom, NULL, "q", (qd_statespace *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_linearize_about(F.ctx, F.eom, F.model, "q", NULL));
    reset(&F);
    /* ---- qd_statespace_render */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_statespace_render(NULL, NULL, NULL, (qd_ss_format){0}, &F.buf));
    reset(&F);
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_statespace_render(F.ctx, NULL, NULL, (qd_ss_format){0}, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_statespace_render(F.ctx, NULL, NULL, (qd_ss_format){0}, NULL));
    reset(&F);
    teardown(&F);
}

static void null_status(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_status_str */
    /* no pointer argument */
    /* ---- qd_nearest_name */
    /* word NULL */
    assert_null(qd_nearest_name(NULL, 1, (const char * const *)F.names, 1));
    reset(&F);
    /* names NULL */
    assert_null(qd_nearest_name("q", 1, NULL, 1));
    reset(&F);
    teardown(&F);
}

static void null_sweep(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_sweep_new */
    /* ctx NULL */
    assert_null(qd_sweep_new(NULL, F.sim, F.model));
    reset(&F);
    /* s NULL */
    assert_null(qd_sweep_new(F.ctx, NULL, F.model));
    reset(&F);
    /* m NULL */
    assert_null(qd_sweep_new(F.ctx, F.sim, NULL));
    reset(&F);
    /* ---- qd_sweep_free */
    /* w NULL */
    qd_sweep_free(NULL);
    reset(&F);
    /* ---- qd_sweep_grid */
    /* w NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_grid(NULL, "q"));
    reset(&F);
    /* spec NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_grid(NULL, NULL));
    reset(&F);
    /* ---- qd_sweep_random */
    /* w NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_random(NULL, "q", 1, 1));
    reset(&F);
    /* spec NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_random(NULL, NULL, 1, 1));
    reset(&F);
    /* ---- qd_sweep_list */
    /* w NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_list(NULL, 1, (const char * const *)F.names, 1, F.d));
    reset(&F);
    /* names NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_list(NULL, 1, NULL, 1, F.d));
    reset(&F);
    /* values NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_list(NULL, 1, (const char * const *)F.names, 1, NULL));
    reset(&F);
    /* ---- qd_sweep_list_csv */
    /* w NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_list_csv(NULL, "q"));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_list_csv(NULL, NULL));
    reset(&F);
    /* ---- qd_sweep_measures */
    /* w NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_measures(NULL, "q"));
    reset(&F);
    /* spec NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_measures(NULL, NULL));
    reset(&F);
    /* ---- qd_sweep_set_event */
    /* w NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_set_event(NULL, 1));
    reset(&F);
    /* ---- qd_sweep_set_section */
    /* w NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_set_section(NULL, 1));
    reset(&F);
    /* ---- qd_sweep_set_lyap */
    /* w NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_set_lyap(NULL, NULL, NULL));
    reset(&F);
    /* ---- qd_sweep_needs */
    /* spec NULL */
    assert_true(qd_sweep_needs(F.sim, NULL, NULL, 1, F.u) == 0);
    reset(&F);
    /* flags NULL */
    assert_true(qd_sweep_needs(F.sim, "q", NULL, 1, NULL) == 0);
    reset(&F);
    /* ---- qd_sweep_prepare */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_prepare(NULL, F.sim, "q", NULL, NULL));
    reset(&F);
    /* s NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_prepare(F.ctx, NULL, "q", NULL, NULL));
    reset(&F);
    /* spec NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_prepare(F.ctx, F.sim, NULL, NULL, NULL));
    reset(&F);
    /* ---- qd_sweep_setup_measures */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_setup_measures(NULL, NULL, "q"));
    reset(&F);
    /* set NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_setup_measures(F.ctx, NULL, "q"));
    reset(&F);
    /* spec NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_setup_measures(F.ctx, NULL, NULL));
    reset(&F);
    /* ---- qd_sweep_setup_new */
    /* ctx NULL */
    assert_null(qd_sweep_setup_new(NULL, NULL, F.model, NULL, (const char * *)F.names));
    reset(&F);
    /* set NULL */
    assert_null(qd_sweep_setup_new(F.ctx, NULL, F.model, NULL, (const char * *)F.names));
    reset(&F);
    /* m NULL */
    assert_null(qd_sweep_setup_new(F.ctx, NULL, NULL, NULL, (const char * *)F.names));
    reset(&F);
    /* ---- qd_sweep_map_column */
    /* w NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_map_column(NULL, "q", F.z));
    reset(&F);
    /* col NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_map_column(NULL, "q", NULL));
    reset(&F);
    /* ---- qd_sweep_map */
    /* w NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_map(NULL, F.d, 1, F.plot));
    reset(&F);
    /* rows NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_map(NULL, NULL, 1, F.plot));
    reset(&F);
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_map(NULL, F.d, 1, NULL));
    reset(&F);
    /* ---- qd_sweep_map_check */
    /* w NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_map_check(NULL, "q", "q", F.z));
    reset(&F);
    /* path NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_map_check(NULL, NULL, "q", F.z));
    reset(&F);
    /* col NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_map_check(NULL, "q", "q", NULL));
    reset(&F);
    /* ---- qd_sweep_map_file */
    /* w NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_map_file(NULL, F.d, 1, "q", "q"));
    reset(&F);
    /* rows NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_map_file(NULL, NULL, 1, "q", "q"));
    reset(&F);
    /* path NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_map_file(NULL, F.d, 1, "q", NULL));
    reset(&F);
    /* ---- qd_sweep_nruns */
    /* w NULL */
    assert_true(qd_sweep_nruns(NULL) == 0);
    reset(&F);
    /* ---- qd_sweep_ninputs */
    /* w NULL */
    assert_true(qd_sweep_ninputs(NULL) == 0);
    reset(&F);
    /* ---- qd_sweep_ncols */
    /* w NULL */
    assert_true(qd_sweep_ncols(NULL) == 0);
    reset(&F);
    /* ---- qd_sweep_col */
    /* w NULL */
    assert_null(qd_sweep_col(NULL, 1));
    reset(&F);
    /* ---- qd_sweep_run_one */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_run_one(NULL, NULL, NULL, 1, F.d, NULL));
    reset(&F);
    /* w NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_run_one(F.ctx, NULL, NULL, 1, F.d, NULL));
    reset(&F);
    /* row NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_run_one(F.ctx, NULL, NULL, 1, NULL, NULL));
    reset(&F);
    /* ---- qd_sweep_outcome_str */
    /* o NULL */
    assert_null(qd_sweep_outcome_str(NULL, F.c, 1));
    reset(&F);
    /* out NULL */
    assert_null(qd_sweep_outcome_str(NULL, NULL, 1));
    reset(&F);
    /* ---- qd_sweep_threads */
    /* no pointer argument */
    /* ---- qd_sweep_run */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_run(NULL, NULL, NULL, 1, 1, 1, F.d, NULL, NULL, NULL));
    reset(&F);
    /* w NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_run(F.ctx, NULL, NULL, 1, 1, 1, F.d, NULL, NULL, NULL));
    reset(&F);
    /* rows NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_run(F.ctx, NULL, NULL, 1, 1, 1, NULL, NULL, NULL, NULL));
    reset(&F);
    /* ---- qd_sweep_csv */
    /* w NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_csv(NULL, F.d, NULL, &F.buf));
    reset(&F);
    /* rows NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_csv(NULL, NULL, NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_csv(NULL, F.d, NULL, NULL));
    reset(&F);
    /* ---- qd_sweep_json */
    /* w NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_json(NULL, F.d, NULL, &F.buf));
    reset(&F);
    /* rows NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_json(NULL, NULL, NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_json(NULL, F.d, NULL, NULL));
    reset(&F);
    /* ---- qd_sweep_mpi_launched */
    /* no pointer argument */
    /* ---- qd_sweep_mpi_chunk */
    /* no pointer argument */
    /* ---- qd_sweep_run_all */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_run_all(NULL, NULL, NULL, 1, F.d, NULL, NULL, NULL, NULL));
    reset(&F);
    /* w NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_run_all(F.ctx, NULL, NULL, 1, F.d, NULL, NULL, NULL, NULL));
    reset(&F);
    /* rows NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_run_all(F.ctx, NULL, NULL, 1, NULL, NULL, NULL, NULL, NULL));
    reset(&F);
    /* ---- qd_sweep_result_run */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_result_run(NULL, NULL, NULL, 1, NULL, NULL, NULL));
    reset(&F);
    /* w NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_result_run(F.ctx, NULL, NULL, 1, NULL, NULL, NULL));
    reset(&F);
    /* ---- qd_sweep_result_free */
    /* r NULL */
    qd_sweep_result_free(NULL);
    reset(&F);
    /* ---- qd_sweep_result_check */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_result_check(NULL, NULL));
    reset(&F);
    /* r NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_result_check(F.ctx, NULL));
    reset(&F);
    /* ---- qd_sweep_hdf5_ready */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_hdf5_ready(NULL));
    reset(&F);
    /* ---- qd_sweep_hdf5 */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_hdf5(NULL, NULL, F.d, NULL, 1, (const char * const *)F.names, (const char * const *)F.names, "q"));
    reset(&F);
    /* w NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_hdf5(F.ctx, NULL, F.d, NULL, 1, (const char * const *)F.names, (const char * const *)F.names, "q"));
    reset(&F);
    /* rows NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_hdf5(F.ctx, NULL, NULL, NULL, 1, (const char * const *)F.names, (const char * const *)F.names, "q"));
    reset(&F);
    /* attr_names NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_hdf5(F.ctx, NULL, F.d, NULL, 1, NULL, (const char * const *)F.names, "q"));
    reset(&F);
    /* attr_values NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_hdf5(F.ctx, NULL, F.d, NULL, 1, (const char * const *)F.names, NULL, "q"));
    reset(&F);
    /* path NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_hdf5(F.ctx, NULL, F.d, NULL, 1, (const char * const *)F.names, (const char * const *)F.names, NULL));
    reset(&F);
    /* ---- qd_sweep_hdf5_made */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_hdf5_made(NULL, NULL, NULL, NULL, "q", "q", "q"));
    reset(&F);
    /* w NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_hdf5_made(F.ctx, NULL, NULL, NULL, "q", "q", "q"));
    reset(&F);
    /* path NULL */
    assert_int_equal(QD_ERR_ARG, qd_sweep_hdf5_made(F.ctx, NULL, NULL, NULL, "q", "q", NULL));
    reset(&F);
    teardown(&F);
}

static void null_symmetry(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_mode_kind_name */
    /* no pointer argument */
    /* ---- qd_symmetry_find */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_symmetry_find(NULL, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, (qd_symmetry *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_symmetry_find(F.ctx, NULL, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, (qd_symmetry *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_symmetry_find(F.ctx, F.eom, NULL, 1, (const qd_expr * const *)F.e, F.d, NULL, (qd_symmetry *)(void *)F.blob));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_symmetry_find(F.ctx, F.eom, F.model, 1, NULL, F.d, NULL, (qd_symmetry *)(void *)F.blob));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_symmetry_find(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, NULL, NULL, (qd_symmetry *)(void *)F.blob));
    reset(&F);
    /* lin NULL */
    assert_int_equal(QD_ERR_ARG, qd_symmetry_find(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, (qd_symmetry *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_symmetry_find(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, NULL));
    reset(&F);
    /* ---- qd_symmetry_from_ops */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_symmetry_from_ops(NULL, NULL, 1, F.d, F.d, (qd_symmetry *)(void *)F.blob));
    reset(&F);
    /* lin NULL */
    assert_int_equal(QD_ERR_ARG, qd_symmetry_from_ops(F.ctx, NULL, 1, F.d, F.d, (qd_symmetry *)(void *)F.blob));
    reset(&F);
    /* S NULL */
    assert_int_equal(QD_ERR_ARG, qd_symmetry_from_ops(F.ctx, NULL, 1, NULL, F.d, (qd_symmetry *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_symmetry_from_ops(F.ctx, NULL, 1, F.d, F.d, NULL));
    reset(&F);
    /* ---- qd_symmetry_reduce */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_symmetry_reduce(NULL, NULL, NULL));
    reset(&F);
    /* lin NULL */
    assert_int_equal(QD_ERR_ARG, qd_symmetry_reduce(F.ctx, NULL, NULL));
    reset(&F);
    /* ---- qd_group_characters */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_group_characters(NULL, 1, F.z, F.d, (qd_symmetry *)(void *)F.blob));
    reset(&F);
    /* table NULL */
    assert_int_equal(QD_ERR_ARG, qd_group_characters(F.ctx, 1, NULL, F.d, (qd_symmetry *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_group_characters(F.ctx, 1, F.z, F.d, NULL));
    reset(&F);
    /* ---- qd_symmetry_block_label */
    /* sym NULL */
    qd_symmetry_block_label(NULL, 1, F.c, 1);
    reset(&F);
    /* buf NULL */
    qd_symmetry_block_label(NULL, 1, NULL, 1);
    reset(&F);
    /* ---- qd_symmetry_class_name */
    /* sym NULL */
    qd_symmetry_class_name(NULL, 1, F.c, 1);
    reset(&F);
    /* buf NULL */
    qd_symmetry_class_name(NULL, 1, NULL, 1);
    reset(&F);
    /* ---- qd_symmetry_free */
    /* sym NULL */
    qd_symmetry_free(NULL);
    reset(&F);
    /* ---- qd_cyclic_cell */
    /* lin NULL */
    assert_true(qd_cyclic_cell(NULL) == 0);
    reset(&F);
    /* ---- qd_cyclic_solve */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_cyclic_solve(NULL, NULL, 1, (qd_cyclic_modes *)(void *)F.blob));
    reset(&F);
    /* lin NULL */
    assert_int_equal(QD_ERR_ARG, qd_cyclic_solve(F.ctx, NULL, 1, (qd_cyclic_modes *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_cyclic_solve(F.ctx, NULL, 1, NULL));
    reset(&F);
    /* ---- qd_cyclic_modes_free */
    /* c NULL */
    qd_cyclic_modes_free(NULL);
    reset(&F);
    /* ---- qd_symmetry_fast_cell */
    /* lin NULL */
    assert_true(qd_symmetry_fast_cell(NULL) == 0);
    reset(&F);
    /* ---- qd_modes_symmetry */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_symmetry(NULL, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, NULL, NULL, &F.buf));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_symmetry(F.ctx, NULL, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, NULL, NULL, &F.buf));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_symmetry(F.ctx, F.eom, NULL, 1, (const qd_expr * const *)F.e, F.d, NULL, NULL, NULL, &F.buf));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_symmetry(F.ctx, F.eom, F.model, 1, NULL, F.d, NULL, NULL, NULL, &F.buf));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_symmetry(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, NULL, NULL, NULL, NULL, &F.buf));
    reset(&F);
    /* lin NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_symmetry(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, NULL, NULL, &F.buf));
    reset(&F);
    /* note NULL */
    assert_int_equal(QD_ERR_ARG, qd_modes_symmetry(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, NULL, NULL, NULL));
    reset(&F);
    /* ---- qd_symmetry_print */
    /* sym NULL */
    assert_int_equal(QD_ERR_ARG, qd_symmetry_print(NULL, F.eom, &F.buf));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_symmetry_print(NULL, NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_symmetry_print(NULL, F.eom, NULL));
    reset(&F);
    /* ---- qd_symmetry_json */
    /* j NULL */
    qd_symmetry_json(NULL, NULL, F.eom);
    reset(&F);
    /* e NULL */
    qd_symmetry_json(NULL, NULL, NULL);
    reset(&F);
    /* ---- qd_symmetry_json_modes */
    /* j NULL */
    qd_symmetry_json_modes(NULL, NULL, F.eom);
    reset(&F);
    /* e NULL */
    qd_symmetry_json_modes(NULL, NULL, NULL);
    reset(&F);
    /* ---- qd_cyclic_print */
    /* c NULL */
    assert_int_equal(QD_ERR_ARG, qd_cyclic_print(NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_cyclic_print(NULL, NULL));
    reset(&F);
    /* ---- qd_cyclic_json */
    /* j NULL */
    qd_cyclic_json(NULL, NULL);
    reset(&F);
    /* ---- qd_cyclic_json_modes */
    /* j NULL */
    qd_cyclic_json_modes(NULL, NULL);
    reset(&F);
    /* ---- qd_symmetry_modes_plot */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_symmetry_modes_plot(NULL, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, NULL, "q", NULL));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_symmetry_modes_plot(F.ctx, NULL, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, NULL, "q", NULL));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_symmetry_modes_plot(F.ctx, F.eom, NULL, 1, (const qd_expr * const *)F.e, F.d, NULL, NULL, "q", NULL));
    reset(&F);
    /* syms NULL */
    assert_int_equal(QD_ERR_ARG, qd_symmetry_modes_plot(F.ctx, F.eom, F.model, 1, NULL, F.d, NULL, NULL, "q", NULL));
    reset(&F);
    /* vals NULL */
    assert_int_equal(QD_ERR_ARG, qd_symmetry_modes_plot(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, NULL, NULL, NULL, "q", NULL));
    reset(&F);
    /* res NULL */
    assert_int_equal(QD_ERR_ARG, qd_symmetry_modes_plot(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, NULL, "q", NULL));
    reset(&F);
    /* title NULL */
    assert_int_equal(QD_ERR_ARG, qd_symmetry_modes_plot(F.ctx, F.eom, F.model, 1, (const qd_expr * const *)F.e, F.d, NULL, NULL, NULL, NULL));
    reset(&F);
    teardown(&F);
}

static void null_tangent(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_tangent_new */
    /* ctx NULL */
    assert_null(qd_tangent_new(NULL, 1, (const qd_expr * const *)F.e, F.b, 1, (const qd_expr * const *)F.e));
    reset(&F);
    /* inputs NULL */
    assert_null(qd_tangent_new(F.ctx, 1, NULL, F.b, 1, (const qd_expr * const *)F.e));
    reset(&F);
    /* outputs NULL */
    assert_null(qd_tangent_new(F.ctx, 1, (const qd_expr * const *)F.e, F.b, 1, NULL));
    reset(&F);
    /* ---- qd_tangent_free */
    /* t NULL */
    qd_tangent_free(NULL);
    reset(&F);
    /* ---- qd_tangent_nin */
    /* t NULL */
    assert_true(qd_tangent_nin(NULL) == 0);
    reset(&F);
    /* ---- qd_tangent_nvar */
    /* t NULL */
    assert_true(qd_tangent_nvar(NULL) == 0);
    reset(&F);
    /* ---- qd_tangent_nout */
    /* t NULL */
    assert_true(qd_tangent_nout(NULL) == 0);
    reset(&F);
    /* ---- qd_tangent_eval */
    /* t NULL */
    assert_int_equal(QD_ERR_ARG, qd_tangent_eval(NULL, F.d, F.d));
    reset(&F);
    /* in NULL */
    assert_int_equal(QD_ERR_ARG, qd_tangent_eval(NULL, NULL, F.d));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_tangent_eval(NULL, F.d, NULL));
    reset(&F);
    /* ---- qd_tangent_jacobian */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_tangent_jacobian(NULL, NULL, F.d, F.d, F.d));
    reset(&F);
    /* t NULL */
    assert_int_equal(QD_ERR_ARG, qd_tangent_jacobian(F.ctx, NULL, F.d, F.d, F.d));
    reset(&F);
    /* in NULL */
    assert_int_equal(QD_ERR_ARG, qd_tangent_jacobian(F.ctx, NULL, NULL, F.d, F.d));
    reset(&F);
    /* J NULL */
    assert_int_equal(QD_ERR_ARG, qd_tangent_jacobian(F.ctx, NULL, F.d, F.d, NULL));
    reset(&F);
    teardown(&F);
}

static void null_version(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_version */
    /* no pointer argument */
    teardown(&F);
}

static void null_zvc(void **state)
{
    (void)state;
    static fixture F;
    setup(&F);
    /* ---- qd_zvc_derive */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_derive(NULL, F.model, F.eom, (qd_zvc *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_derive(F.ctx, NULL, F.eom, (qd_zvc *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_derive(F.ctx, F.model, NULL, (qd_zvc *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_derive(F.ctx, F.model, F.eom, NULL));
    reset(&F);
    /* ---- qd_zvc_box_read */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_box_read(NULL, F.model, F.eom, "q", NULL));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_box_read(F.ctx, NULL, F.eom, "q", NULL));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_box_read(F.ctx, F.model, NULL, "q", NULL));
    reset(&F);
    /* text NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_box_read(F.ctx, F.model, F.eom, NULL, NULL));
    reset(&F);
    /* box NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_box_read(F.ctx, F.model, F.eom, "q", NULL));
    reset(&F);
    /* ---- qd_zvc_curves */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_curves(NULL, F.eom, NULL, NULL, 1, (const qd_expr * const *)F.e, F.d, 1, (qd_contour *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_curves(F.ctx, NULL, NULL, NULL, 1, (const qd_expr * const *)F.e, F.d, 1, (qd_contour *)(void *)F.blob));
    reset(&F);
    /* z NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_curves(F.ctx, F.eom, NULL, NULL, 1, (const qd_expr * const *)F.e, F.d, 1, (qd_contour *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_curves(F.ctx, F.eom, NULL, NULL, 1, (const qd_expr * const *)F.e, F.d, 1, NULL));
    reset(&F);
    /* ---- qd_zvc_picture_make */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_picture_make(NULL, F.model, F.eom, NULL, NULL, 1, (const qd_expr * const *)F.e, F.d, 1, false, (qd_zvc_picture *)(void *)F.blob));
    reset(&F);
    /* m NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_picture_make(F.ctx, NULL, F.eom, NULL, NULL, 1, (const qd_expr * const *)F.e, F.d, 1, false, (qd_zvc_picture *)(void *)F.blob));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_picture_make(F.ctx, F.model, NULL, NULL, NULL, 1, (const qd_expr * const *)F.e, F.d, 1, false, (qd_zvc_picture *)(void *)F.blob));
    reset(&F);
    /* z NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_picture_make(F.ctx, F.model, F.eom, NULL, NULL, 1, (const qd_expr * const *)F.e, F.d, 1, false, (qd_zvc_picture *)(void *)F.blob));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_picture_make(F.ctx, F.model, F.eom, NULL, NULL, 1, (const qd_expr * const *)F.e, F.d, 1, false, NULL));
    reset(&F);
    /* ---- qd_zvc_picture_free */
    /* p NULL */
    qd_zvc_picture_free(NULL);
    reset(&F);
    /* ---- qd_zvc_level_read */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_level_read(NULL, NULL, NULL, "q", "q", "q", F.d, F.d, (const char * *)F.names));
    reset(&F);
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_level_read(F.ctx, NULL, NULL, "q", "q", "q", F.d, F.d, (const char * *)F.names));
    reset(&F);
    /* q NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_level_read(F.ctx, NULL, NULL, "q", "q", "q", NULL, F.d, (const char * *)F.names));
    reset(&F);
    /* h NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_level_read(F.ctx, NULL, NULL, "q", "q", "q", F.d, NULL, (const char * *)F.names));
    reset(&F);
    /* ---- qd_zvc_print */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_print(NULL, F.eom, NULL, &F.buf));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_print(F.ctx, NULL, NULL, &F.buf));
    reset(&F);
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_print(F.ctx, F.eom, NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_print(F.ctx, F.eom, NULL, NULL));
    reset(&F);
    /* ---- qd_zvc_csv */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_csv(NULL, F.eom, NULL, &F.buf));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_csv(F.ctx, NULL, NULL, &F.buf));
    reset(&F);
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_csv(F.ctx, F.eom, NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_csv(F.ctx, F.eom, NULL, NULL));
    reset(&F);
    /* ---- qd_zvc_json */
    /* ctx NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_json(NULL, F.eom, NULL, &F.buf));
    reset(&F);
    /* e NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_json(F.ctx, NULL, NULL, &F.buf));
    reset(&F);
    /* p NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_json(F.ctx, F.eom, NULL, &F.buf));
    reset(&F);
    /* out NULL */
    assert_int_equal(QD_ERR_ARG, qd_zvc_json(F.ctx, F.eom, NULL, NULL));
    reset(&F);
    teardown(&F);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(null_action),
        cmocka_unit_test(null_canonical),
        cmocka_unit_test(null_certify),
        cmocka_unit_test(null_codegen),
        cmocka_unit_test(null_conlin),
        cmocka_unit_test(null_constrained),
        cmocka_unit_test(null_contour),
        cmocka_unit_test(null_control),
        cmocka_unit_test(null_equilibria),
        cmocka_unit_test(null_eval),
        cmocka_unit_test(null_expr),
        cmocka_unit_test(null_field),
        cmocka_unit_test(null_form),
        cmocka_unit_test(null_hamilton),
        cmocka_unit_test(null_hj),
        cmocka_unit_test(null_impulse),
        cmocka_unit_test(null_integrals),
        cmocka_unit_test(null_json),
        cmocka_unit_test(null_linpoint),
        cmocka_unit_test(null_lyapunov),
        cmocka_unit_test(null_mech),
        cmocka_unit_test(null_metric),
        cmocka_unit_test(null_model),
        cmocka_unit_test(null_modes),
        cmocka_unit_test(null_orbit),
        cmocka_unit_test(null_path),
        cmocka_unit_test(null_plot),
        cmocka_unit_test(null_print),
        cmocka_unit_test(null_read),
        cmocka_unit_test(null_relativity),
        cmocka_unit_test(null_render),
        cmocka_unit_test(null_routh),
        cmocka_unit_test(null_scanplot),
        cmocka_unit_test(null_scatter),
        cmocka_unit_test(null_scene),
        cmocka_unit_test(null_sim),
        cmocka_unit_test(null_simsetup),
        cmocka_unit_test(null_speeds),
        cmocka_unit_test(null_stability),
        cmocka_unit_test(null_state),
        cmocka_unit_test(null_statespace),
        cmocka_unit_test(null_status),
        cmocka_unit_test(null_sweep),
        cmocka_unit_test(null_symmetry),
        cmocka_unit_test(null_tangent),
        cmocka_unit_test(null_version),
        cmocka_unit_test(null_zvc),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
