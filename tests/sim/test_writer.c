/*
 * tests/sim/test_writer.c - a run's rows written as `qdot simulate` writes
 * them (qd_sim_writer, qd_sim_csv_header, qd_sim_csv_row, qd_sim_json_row;
 * src/sim/writer.c), read back and checked against the motion, on the
 * oscillator m x'' = -k x with w = sqrt(k/m) = 2 from x = 1 at rest:
 * x = cos 2t, x' = -2 sin 2t (Goldstein sec. 1.6), energy
 * h = m x'^2/2 + k x^2/2 = 4 for all t (the Jacobi integral, conserved):
 *   - the CSV header names t, x, x', energy and the lines read back to
 *     those values at their times (to the tolerance), the energy column
 *     4 throughout; every number reads back to the double written;
 *   - an event x = 0 adds the event column: 1 on the crossing rows, whose
 *     times are the quarter periods pi/4 + k pi/2, 0 on the grid's;
 *   - JSON rows carry the same numbers;
 *   - a write that fails ends the run as a sink's failure, the header and
 *     rows written before it kept, nothing after it;
 *   - the tap sees every row written and can end the run early.
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
#include "qdot/simsetup.h"
#include "util/jsonwalk.h"

static const char osc[] = "coordinates x\nparameters m = 2, k = 8\n"
                          "T = m/2*x'^2\nV = k/2*x^2\ninitial x = 1\n";
static const double PI = 3.14159265358979323846;

typedef struct setup {
    qd_ctx *ctx;
    qd_model *m;
    qd_sim_setup *set;
    qd_sim *s;
    qd_sim_opts o;
} setup;

static void open_setup(setup *u, const char *event) {
    u->ctx = qd_ctx_new();
    u->m = qd_model_parse(u->ctx, osc, NULL);
    assert_non_null(u->m);
    u->set = qd_sim_setup_new(u->ctx, u->m, false);
    assert_non_null(u->set);
    if (event)
        assert_int_equal(qd_sim_setup_event(u->set, event, false), QD_OK);
    qd_sim_setup_opts so = {.t_end = "3", .dt = "0.1", .rtol = "1e-12", .atol = "1e-14"};
    assert_int_equal(qd_sim_setup_options(u->set, &so, &u->o), QD_OK);
    u->s = qd_sim_setup_sim(u->set);
}

static void close_setup(setup *u) {
    qd_sim_setup_free(u->set);
    qd_model_free(u->m);
    qd_ctx_free(u->ctx);
}

/* The bytes written, in one buffer; fail_after > 0: that many writes
 * succeed, the next ones are lost. */
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

/* Rows of CSV text after its header, each line's numbers read back. */
static size_t read_rows(const char *text, size_t ncols, double *rows, size_t cap) {
    const char *p = strchr(text, '\n');
    size_t n = 0;
    while (p && p[1] && n < cap) {
        p++;
        for (size_t i = 0; i < ncols; i++) {
            char *end;
            rows[n * ncols + i] = strtod(p, &end);
            assert_true(end > p && (*end == ',' || *end == '\n'));
            p = end + (*end == ',');
        }
        n++;
        p = strchr(p, '\n');
    }
    return n;
}

static void test_csv_oscillator(void **state) {
    (void)state;
    setup u;
    open_setup(&u, NULL);
    sunk k = {QD_BUF_INIT, 0, 0};
    qd_sim_writer w = {.write = put, .data = &k};
    assert_int_equal(qd_sim_writer_init(&w, u.s, u.o.method), QD_OK);
    assert_int_equal(w.ncols, 4);
    assert_false(w.event_column);
    qd_sim_stats st;
    assert_int_equal(qd_sim_run(u.s, &u.o, qd_sim_writer_sink, &w, &st, NULL), QD_OK);
    const char *text = qd_buf_str(&k.b);
    assert_true(!strncmp(text, "t,x,x',energy\n", 14));
    double rows[40 * 4];
    size_t n = read_rows(text, 4, rows, 40);
    assert_int_equal(n, 31); /* t = 0, 0.1, ..., 3 */
    assert_int_equal(w.rows, n);
    assert_true(w.last_t == 3);
    for (size_t i = 0; i < n; i++) {
        const double *r = rows + 4 * i;
        assert_true(fabs(r[0] - 0.1 * (double)i) < 1e-12);
        assert_true(fabs(r[1] - cos(2 * r[0])) < 1e-9);
        assert_true(fabs(r[2] + 2 * sin(2 * r[0])) < 1e-9);
        assert_true(fabs(r[3] - 4) < 1e-9); /* h = m x'^2/2 + k x^2/2, conserved */
    }
    /* each line is the shortest text of its numbers: it reads back exactly */
    qd_buf line = QD_BUF_INIT;
    const double r[3] = {0.1, 1.0 / 3, -2.5e-300};
    assert_int_equal(qd_sim_csv_row(3, r, true, 1, &line), QD_OK);
    assert_string_equal(qd_buf_str(&line), "0.1,0.3333333333333333,-2.5e-300,2\n");
    qd_buf_free(&line);
    qd_sim_writer_free(&w);
    qd_buf_free(&k.b);
    close_setup(&u);
}

static void test_event_column(void **state) {
    (void)state;
    setup u;
    open_setup(&u, "x = 0");
    qd_buf h = QD_BUF_INIT;
    assert_int_equal(qd_sim_csv_header(u.s, u.o.method, &h), QD_OK);
    assert_string_equal(qd_buf_str(&h), "t,x,x',energy,event\n");
    qd_buf_free(&h);
    sunk k = {QD_BUF_INIT, 0, 0};
    qd_sim_writer w = {.write = put, .data = &k};
    qd_sim_writer_init(&w, u.s, u.o.method);
    assert_true(w.event_column);
    qd_sim_stats st;
    assert_int_equal(qd_sim_run(u.s, &u.o, qd_sim_writer_sink, &w, &st, NULL), QD_OK);
    double rows[64 * 5];
    size_t n = read_rows(qd_buf_str(&k.b), 5, rows, 64), crossings = 0;
    for (size_t i = 0; i < n; i++) {
        const double *r = rows + 5 * i;
        if (r[4] == 1) { /* x = cos 2t = 0 at t = pi/4 + k pi/2 */
            double kk = (r[0] - PI / 4) / (PI / 2);
            assert_true(fabs(kk - round(kk)) < 1e-9 && fabs(r[1]) < 1e-9);
            crossings++;
        } else {
            assert_true(r[4] == 0);
        }
    }
    assert_int_equal(crossings, 2); /* pi/4, 3 pi/4 within [0, 3] */
    qd_sim_writer_free(&w);
    qd_buf_free(&k.b);
    close_setup(&u);
}

static void test_json_rows(void **state) {
    (void)state;
    setup u;
    open_setup(&u, NULL);
    qd_buf b = QD_BUF_INIT;
    qd_json j;
    qd_json_init(&j, &b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "rows");
    qd_json_begin_array(&j);
    qd_sim_writer w = {.json = &j};
    qd_sim_writer_init(&w, u.s, u.o.method);
    qd_sim_stats st;
    assert_int_equal(qd_sim_run(u.s, &u.o, qd_sim_writer_sink, &w, &st, NULL), QD_OK);
    qd_json_end_array(&j);
    qd_json_end_object(&j);
    assert_true(qt_json_valid(qd_buf_str(&b)));
    const char *rows = qt_json_get(qd_buf_str(&b), "rows");
    assert_int_equal(qt_json_len(rows), 31);
    for (size_t i = 0; i < 31; i++) {
        const char *r = qt_json_at(rows, i);
        double t = qt_json_num(qt_json_at(r, 0));
        assert_true(fabs(qt_json_num(qt_json_at(r, 1)) - cos(2 * t)) < 1e-9);
        assert_true(fabs(qt_json_num(qt_json_at(r, 3)) - 4) < 1e-9);
    }
    qd_sim_writer_free(&w);
    qd_buf_free(&b);
    close_setup(&u);
}

/* Ends the run after five rows. */
static int five(void *data, int event, const double *row) {
    (void)event;
    (void)row;
    return ++*(size_t *)data == 5;
}

static void test_failed_write_and_tap(void **state) {
    (void)state;
    setup u;
    open_setup(&u, NULL);
    /* the header and two rows go out (header and first row are one write) */
    sunk k = {QD_BUF_INIT, 0, 2};
    qd_sim_writer w = {.write = put, .data = &k};
    qd_sim_writer_init(&w, u.s, u.o.method);
    qd_sim_stats st;
    assert_int_equal(qd_sim_run(u.s, &u.o, qd_sim_writer_sink, &w, &st, NULL), QD_ERR_ARG);
    assert_true(w.failed);
    assert_int_equal(w.rows, 2);
    double rows[8];
    assert_int_equal(read_rows(qd_buf_str(&k.b), 4, rows, 2), 2);
    assert_true(fabs(rows[4] - 0.1) < 1e-12); /* the second row, t = 0.1 */
    qd_sim_writer_free(&w);
    qd_buf_free(&k.b);
    qd_ctx_clear_error(u.ctx);
    /* the tap ends the run after the fifth row, which is written */
    size_t seen = 0;
    k = (sunk){QD_BUF_INIT, 0, 0};
    w = (qd_sim_writer){.write = put, .data = &k, .tap = five, .tap_data = &seen};
    qd_sim_writer_init(&w, u.s, u.o.method);
    assert_int_equal(qd_sim_run(u.s, &u.o, qd_sim_writer_sink, &w, &st, NULL), QD_OK);
    assert_int_equal(seen, 5);
    assert_int_equal(w.rows, 5);
    assert_true(fabs(w.last_t - 0.4) < 1e-12);
    qd_sim_writer_free(&w);
    qd_buf_free(&k.b);
    close_setup(&u);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_csv_oscillator),
        cmocka_unit_test(test_event_column),
        cmocka_unit_test(test_json_rows),
        cmocka_unit_test(test_failed_write_and_tap),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
