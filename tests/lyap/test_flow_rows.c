/*
 * tests/lyap/test_flow_rows.c - the flow Jacobian along a run as CSV rows
 * (qd_flow_run_csv, `qdot simulate --variational columns`), read back, on
 * the harmonic oscillator m x'' = -k x, w = sqrt(k/m) = 2, from x = 1:
 *     Phi(t) = [[cos w t, sin(w t)/w], [-w sin(w t), cos w t]]
 * (Arnold, Mathematical Methods of Classical Mechanics, sec. 25: the
 * variational equations of a linear system are the system), and the
 * state x = cos w t, x' = -w sin w t.  The rows are t, x, x', then Phi
 * column by column (dx/dx0, dx'/dx0, dx/dx'0, dx'/dx'0); the first is t0
 * with Phi = I, then every 0.25 to t_end; without a spacing the run's
 * own (its dt), else 100 rows after the first; a write that fails is
 * QD_ERR_IO.
 */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <setjmp.h>
#include <string.h>
#include <cmocka.h>

#include "qdot/qdot.h"
#include "qdot/lyapunov.h"
#include "qdot/simsetup.h"

static const char osc[] = "coordinates x\nparameters m = 2, k = 8\n"
                          "T = m/2*x'^2\nV = k/2*x^2\ninitial x = 1\n";

typedef struct sunk {
    qd_buf b;
    size_t writes, fail_after;
} sunk;

static int put(void *data, const char *bytes, size_t len) {
    sunk *k = data;
    if (k->fail_after && k->writes >= k->fail_after)
        return 1;
    k->writes++;
    qd_buf_putn(&k->b, bytes, len);
    return 0;
}

typedef struct fixture {
    qd_ctx *ctx;
    qd_model *m;
    qd_sim_setup *set;
    qd_lyap *l;
    qd_sim_opts o;
} fixture;

static void open_fixture(fixture *f) {
    f->ctx = qd_ctx_new();
    f->m = qd_model_parse(f->ctx, osc, NULL);
    f->set = qd_sim_setup_new(f->ctx, f->m, false);
    assert_non_null(f->set);
    qd_sim_setup_opts so = {.t_end = "5", .rtol = "1e-12", .atol = "1e-14"};
    qd_sim_opts o;
    assert_int_equal(qd_sim_setup_options(f->set, &so, &o), QD_OK);
    assert_int_equal(qd_flow_sim_opts(&o, &f->o), QD_OK);
    f->l = qd_lyap_new(f->ctx, f->m, qd_sim_setup_eom(f->set));
    assert_non_null(f->l);
}

static void close_fixture(fixture *f) {
    qd_lyap_free(f->l);
    qd_sim_setup_free(f->set);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
}

/* The rows of text after the header checked against Phi(t); their count. */
static size_t check_rows(const char *text) {
    const double w = 2;
    const char *p = strchr(text, '\n');
    size_t n = 0;
    for (; p && p[1]; p = strchr(p, '\n'), n++) {
        double r[7];
        p++;
        for (int i = 0; i < 7; i++) {
            char *end;
            r[i] = strtod(p, &end);
            assert_true(end > p);
            p = end + (*end == ',');
        }
        double c = cos(w * r[0]), s = sin(w * r[0]);
        const double want[7] = {r[0], c, -w * s, c, -w * s, s / w, c};
        for (int i = 1; i < 7; i++)
            assert_true(fabs(r[i] - want[i]) < 1e-9);
    }
    return n;
}

static void test_rows(void **state) {
    (void)state;
    fixture f;
    open_fixture(&f);
    const qd_eom *e = qd_sim_setup_eom(f.set);
    sunk k = {QD_BUF_INIT, 0, 0};
    qd_flow fl;
    assert_int_equal(qd_flow_run_csv(f.ctx, f.l, e, &f.o, 0.25, put, &k, &fl), QD_OK);
    const char *text = qd_buf_str(&k.b);
    assert_true(!strncmp(text, "t,x,x',dx/dx0,dx'/dx0,dx/dx'0,dx'/dx'0\n", 39));
    assert_true(!strncmp(strchr(text, '\n') + 1, "0,1,0,1,0,0,1\n", 14)); /* t0, Phi = I */
    assert_int_equal(check_rows(text), 21); /* t = 0, 0.25, ..., 5 */
    /* the flow is that of the run: det Phi = 1 (Liouville) */
    assert_true(fabs(fl.det - 1) < 1e-9);
    qd_flow_free(&fl);
    qd_buf_free(&k.b);
    /* no spacing: 100 rows after the first */
    k = (sunk){QD_BUF_INIT, 0, 0};
    assert_int_equal(qd_flow_run_csv(f.ctx, f.l, e, &f.o, 0, put, &k, &fl), QD_OK);
    assert_int_equal(check_rows(qd_buf_str(&k.b)), 101);
    qd_flow_free(&fl);
    qd_buf_free(&k.b);
    /* none asked, but the run has its rows' spacing (--dt 0.5): that one */
    qd_sim_opts od = f.o;
    od.dt = 0.5;
    k = (sunk){QD_BUF_INIT, 0, 0};
    assert_int_equal(qd_flow_run_csv(f.ctx, f.l, e, &od, 0, put, &k, &fl), QD_OK);
    assert_int_equal(check_rows(qd_buf_str(&k.b)), 11);
    qd_flow_free(&fl);
    qd_buf_free(&k.b);
    close_fixture(&f);
}

static void test_lost_rows(void **state) {
    (void)state;
    fixture f;
    open_fixture(&f);
    const qd_eom *e = qd_sim_setup_eom(f.set);
    for (size_t after = 1; after <= 3; after++) { /* the header, t0's row, a row of the run */
        sunk k = {QD_BUF_INIT, 0, after};
        qd_flow fl;
        assert_int_equal(qd_flow_run_csv(f.ctx, f.l, e, &f.o, 0.25, put, &k, &fl), QD_ERR_IO);
        assert_int_equal(qd_ctx_status(f.ctx), QD_ERR_IO);
        assert_int_equal(k.writes, after);
        qd_ctx_clear_error(f.ctx);
        qd_flow_free(&fl);
        qd_buf_free(&k.b);
    }
    close_fixture(&f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rows),
        cmocka_unit_test(test_lost_rows),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
