/*
 * tests/sweep/test_sweep_setup.c - a whole sweep set up from its texts
 * (qd_sweep_setup_new, as qdot sweep takes it):
 *
 *   - the pendulum's period against the amplitude: from rest at theta0 the
 *     first downward crossing of theta = 0 is a quarter period,
 *     T/4 = sqrt(l/g) K(sin(theta0/2)) (Landau & Lifshitz, Mechanics,
 *     sec. 11, problem 1; K the complete elliptic integral of the first
 *     kind, here by the arithmetic-geometric mean, K(k) = pi / (2
 *     AGM(1, sqrt(1 - k^2)))), the `event` measure over a grid of theta0;
 *   - poincare-count of the oscillator (w = 1) with the section x = 0,
 *     x' > 0: one crossing a period, floor(t_end / 2 pi) of them from x = 1;
 *   - the Lyapunov measures made by the set-up: the oscillator's largest
 *     exponent is 0 (an integrable motion, Lichtenberg & Lieberman sec.
 *     5.2), the spectrum sums to 0 (Liouville), from a list of runs;
 *   - --map over x0 and v0 of the oscillator: final_x is x0 cos t + v0 sin t
 *     at t_end, drawn to an SVG file;
 *     a grid of one axis refused naming "map";
 *   - a sweep whose every run fails (a singular mass matrix, m = 0) is no
 *     answer; one run that goes through is;
 *   - the refusals, each naming the field it is about: `event` with no
 *     event, poincare-count with no section, the Lyapunov measures of a
 *     model given by H, an error in the grid's or the measures' text
 *     located there.
 */
#define _POSIX_C_SOURCE 200809L /* mkstemp */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>

#include "qdot/qdot.h"
#include "qdot/simsetup.h"
#include "qdot/sweep.h"

#define PI 3.14159265358979323846

static const char pendulum[] = "coordinates theta\nparameters g = 9.81, l = 2\n"
                               "T = l^2*theta'^2/2\nV = -g*l*cos(theta)\n";
static const char osc[] = "coordinates x\nT = x'^2/2\nV = x^2/2\ninitial x = 1\n";

typedef struct fix {
    qd_ctx *ctx;
    qd_model *m;
    qd_sim_setup *set;
} fix;

static fix load(const char *text) {
    fix f = {qd_ctx_new(), NULL, NULL};
    f.m = qd_model_parse(f.ctx, text, NULL);
    assert_non_null(f.m);
    f.set = qd_sim_setup_new(f.ctx, f.m, false);
    assert_non_null(f.set);
    return f;
}

static qd_sim_opts options(fix *f, const char *t_end) {
    qd_sim_setup_opts so = {.t_end = t_end, .rtol = "1e-11", .atol = "1e-13"};
    qd_sim_opts o;
    assert_int_equal(qd_sim_setup_options(f->set, &so, &o), QD_OK);
    return o;
}

static void unload(fix *f) {
    qd_sim_setup_free(f->set);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
}

static double K(double k) {
    double a = 1, b = sqrt(1 - k * k);
    for (int i = 0; i < 40; i++) {
        double m = (a + b) / 2;
        b = sqrt(a * b);
        a = m;
    }
    return PI / (2 * a);
}

static void test_pendulum_period(void **state) {
    (void)state;
    fix f = load(pendulum);
    assert_int_equal(qd_sim_setup_event(f.set, "theta = 0, theta' < 0", false), QD_OK);
    qd_sim_opts o = options(&f, "10");
    qd_sweep_spec sp = {.grid = "theta = 0.1:2.9:8", .measures = "event", .nevents = 1};
    const char *where = "x";
    qd_sweep *w = qd_sweep_setup_new(f.ctx, f.set, f.m, &sp, &where);
    assert_non_null(w);
    assert_null(where);
    qd_sweep_result r;
    assert_int_equal(qd_sweep_result_run(f.ctx, w, &o, 2, NULL, NULL, &r), QD_OK);
    assert_int_equal(r.nruns, 8);
    assert_int_equal(r.failed, 0);
    assert_int_equal(r.threads, 2);
    assert_int_equal(qd_sweep_result_check(f.ctx, &r), QD_OK);
    for (size_t i = 0; i < r.nruns; i++) {
        double th0 = r.rows[i * r.ncols], quarter = sqrt(2 / 9.81) * K(sin(th0 / 2));
        assert_true(fabs(r.rows[i * r.ncols + 1] - quarter) < 1e-8 * quarter);
    }
    qd_sweep_result_free(&r);
    qd_sweep_free(w);
    unload(&f);
}

static void test_section_count(void **state) {
    (void)state;
    fix f = load(osc);
    assert_int_equal(qd_sim_setup_event(f.set, "x = 0, x' > 0", false), QD_OK);
    qd_sim_opts o = options(&f, "1"); /* each run's own t_end below */
    qd_sweep_spec sp = {.random = "x' = -0.5:0.5", .n = 6, .seed = 3,
                        .measures = "poincare-count, final", .section = true};
    qd_sweep *w = qd_sweep_setup_new(f.ctx, f.set, f.m, &sp, NULL);
    assert_non_null(w);
    o.t_end = 20.5; /* 3 periods and a quarter plus: 3 upward crossings of x = 0 */
    qd_sweep_result r;
    assert_int_equal(qd_sweep_result_run(f.ctx, w, &o, 1, NULL, NULL, &r), QD_OK);
    assert_int_equal(r.nruns, 6);
    for (size_t i = 0; i < r.nruns; i++) {
        /* x = cos t + v sin t = A cos(t - phi): an upward zero each period */
        double v = r.rows[i * r.ncols], phi = atan2(v, 1), n = 0;
        for (int k = 0; k < 10; k++) {
            double t = phi + 3 * PI / 2 + 2 * PI * (k - 1);
            n += t > 0 && t < o.t_end;
        }
        assert_true(r.rows[i * r.ncols + 1] == n);
    }
    qd_sweep_result_free(&r);
    qd_sweep_free(w);
    unload(&f);
}

static void test_lyapunov(void **state) {
    (void)state;
    fix f = load(osc);
    qd_sim_opts o = options(&f, "200");
    qd_sweep_spec sp = {.list_csv = "x,x'\n1,0\n0.5,0.5\n", .measures = "lyapunov, "
                        "lyapunov-spectrum", .renorm = 1, .transient = 10};
    qd_sweep *w = qd_sweep_setup_new(f.ctx, f.set, f.m, &sp, NULL);
    assert_non_null(w);
    qd_sweep_result r;
    assert_int_equal(qd_sweep_result_run(f.ctx, w, &o, 1, NULL, NULL, &r), QD_OK);
    assert_int_equal(r.failed, 0);
    assert_int_equal(r.ncols, 2 + 2 + 2);  /* x, x', lyapunov, its error, lambda_1, lambda_2 */
    for (size_t i = 0; i < r.nruns; i++) {
        const double *row = r.rows + i * r.ncols;
        assert_true(fabs(row[2]) < 0.05);            /* ~ log(t)/t of a linear shear */
        assert_true(fabs(row[4] + row[5]) < 1e-8); /* Liouville */
    }
    qd_sweep_result_free(&r);
    qd_sweep_free(w);
    unload(&f);
}

/* --map: the grid of two axes drawn to a file of its own; a grid of one
 * axis and a path of no known format refused before any run. */
static void test_map(void **state) {
    (void)state;
    fix f = load(osc);
    qd_sim_opts o = options(&f, "3");
    qd_sweep_spec sp = {.grid = "x = 0.5:1:3, x' = 0:1:2", .measures = "final"};
    qd_sweep *w = qd_sweep_setup_new(f.ctx, f.set, f.m, &sp, NULL);
    assert_non_null(w);
    size_t col = 0;
    assert_int_equal(qd_sweep_map_check(w, "m.xyz", NULL, &col), QD_ERR_ARG);
    qd_ctx_clear_error(f.ctx);
    assert_int_equal(qd_sweep_map_check(w, "m.svg", "final_x", &col), QD_OK);
    assert_int_equal(col, 2);
    qd_sweep_result r;
    assert_int_equal(qd_sweep_result_run(f.ctx, w, &o, 1, NULL, NULL, &r), QD_OK);
    for (size_t i = 0; i < r.nruns; i++) { /* x(3) = x0 cos 3 + v0 sin 3 */
        const double *row = r.rows + i * r.ncols;
        assert_true(fabs(row[2] - (row[0] * cos(3) + row[1] * sin(3))) < 1e-9);
    }
    char path[] = "/tmp/qdot_sweep_mapXXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    char svg[64];
    snprintf(svg, sizeof svg, "%s.svg", path);
    assert_int_equal(qd_sweep_map_file(w, r.rows, col, "osc", svg), QD_OK);
    FILE *fp = fopen(svg, "r");
    char head[8] = "";
    assert_non_null(fp);
    assert_true(fread(head, 1, 5, fp) == 5);
    assert_true(!memcmp(head, "<?xml", 5) || !memcmp(head, "<svg", 4));
    fclose(fp);
    remove(svg);
    remove(path);
    qd_sweep_result_free(&r);
    qd_sweep_free(w);
    qd_sweep_spec one = {.grid = "x = 0.5:1:3", .measures = "final"};
    w = qd_sweep_setup_new(f.ctx, f.set, f.m, &one, NULL);
    assert_non_null(w);
    assert_int_equal(qd_sweep_map_check(w, "m.png", NULL, &col), QD_ERR_ARG);
    assert_string_equal(qd_ctx_diag(f.ctx)->name, "map");
    qd_sweep_free(w);
    unload(&f);
}

/* A mass m = 0 makes the mass matrix singular: that run fails alone; a
 * sweep of such runs only is no answer (qd_sweep_result_check). */
static void test_all_failed(void **state) {
    (void)state;
    const char *grids[] = {"m = 0:1:2", "m = 0:0:1"};
    for (size_t g = 0; g < 2; g++) {
        fix f = load("coordinates x\nparameters m = 1\nT = m*x'^2/2\nV = x^2/2\n"
                     "initial x = 1\n");
        qd_sim_opts o = options(&f, "1");
        qd_sweep_spec sp = {.grid = grids[g], .measures = "final"};
        qd_sweep *w = qd_sweep_setup_new(f.ctx, f.set, f.m, &sp, NULL);
        assert_non_null(w);
        qd_sweep_result r;
        assert_int_equal(qd_sweep_result_run(f.ctx, w, &o, 1, NULL, NULL, &r), QD_OK);
        assert_int_equal(r.failed, 1);
        qd_ctx_clear_error(f.ctx);
        assert_int_equal(qd_sweep_result_check(f.ctx, &r), g ? QD_ERR_NUMERIC : QD_OK);
        if (g)
            assert_non_null(strstr(qd_ctx_message(f.ctx), "every run failed (the first: "));
        qd_sweep_result_free(&r);
        qd_sweep_free(w);
        unload(&f);
    }
}

static void refused(const char *text, const qd_sweep_spec *sp, const char *where,
                    const char *field) {
    fix f = load(text);
    const char *got = "x";
    assert_null(qd_sweep_setup_new(f.ctx, f.set, f.m, sp, &got));
    const qd_diag *d = qd_ctx_diag(f.ctx);
    assert_int_not_equal(qd_ctx_status(f.ctx), QD_OK);
    if (where) {
        assert_non_null(got);
        assert_string_equal(got, where);
        assert_true(d->located);
    } else {
        assert_null(got);
        assert_string_equal(d->name, field);
    }
    unload(&f);
}

static void test_refusals(void **state) {
    (void)state;
    qd_sweep_spec ev = {.grid = "x=0:1:2", .measures = "final, event"};
    refused(osc, &ev, NULL, "event");
    qd_sweep_spec sec = {.grid = "x=0:1:2", .measures = "poincare-count", .nevents = 0};
    refused(osc, &sec, NULL, "section");
    qd_sweep_spec ly = {.grid = "q=0:1:2", .measures = "lyapunov"};
    refused("coordinates q\nmomenta p\nH = p^2/2 + q^2/2\n", &ly, NULL, "no_speeds");
    qd_sweep_spec two = {.grid = "x=0:1:2", .random = "x=0:1", .n = 2, .measures = "final"};
    refused(osc, &two, NULL, "grid");
    qd_sweep_spec grid = {.grid = "y=0:1:2", .measures = "final"};
    refused(osc, &grid, "grid", NULL);
    qd_sweep_spec ms = {.grid = "x=0:1:2", .measures = "max:y"};
    refused(osc, &ms, "measures", NULL);
    qd_sweep_spec peak = {.grid = "x=0:1:2", .measures = "peak"};
    refused(osc, &peak, "measures", NULL);
    qd_sweep_spec list = {.list_csv = "x\n1,2\n", .measures = "final"};
    refused(osc, &list, "list_csv", NULL);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pendulum_period), cmocka_unit_test(test_section_count),
        cmocka_unit_test(test_lyapunov),        cmocka_unit_test(test_map),
        cmocka_unit_test(test_all_failed),      cmocka_unit_test(test_refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
