/*
 * tests/sim/test_lqr_input.c - the inputs of a run set up by the library as
 * `qdot simulate` takes them (qdot/simsetup.h, qdot/sim.h):
 *
 *   qd_sim_setup_lqr on the inverted pendulum on a cart (examples/
 *   cart_pendulum.qd, th the tilt from the upward vertical): the feedback
 *   u = u0 - K (x - x0) about the upright point keeps the pendulum up from
 *   th = 0.2 (|th| stays below its start and decays as exp(a t), a < 0 the
 *   closed loop's largest real part), where the open loop falls over; the
 *   note names K's entries as the design has them.
 *
 *   qd_sim_input_table_read on the damped, driven oscillator
 *   m x'' + c x' + k x = F0 cos(W t), F sampled as the text of a CSV file:
 *   the steady amplitude F0 / sqrt((k - m W^2)^2 + (c W)^2) (Goldstein,
 *   Poole & Safko sec. 1.6; Landau & Lifshitz sec. 26).
 */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <setjmp.h>
#include <string.h>
#include <cmocka.h>

#include "qdot/qdot.h"
#include "qdot/simsetup.h"

static const char cart[] =
    "coordinates x, th\nparameters M = 1, m = 0.1, l = 0.5, g = 9.81\ninputs F\n"
    "particle M at (x, 0, 0)\nparticle m at (x - l*sin(th), l*cos(th), 0)\n"
    "V = m*g*l*cos(th)\nQ[x] = F\n";
static const char weights[] = "Q = diag(1, 10, 1, 1), R = 0.1";

typedef struct tilt {
    size_t col;           /* th's column */
    double t_late;        /* rows after this time count in late */
    double worst, late, last, last_t;
} tilt;

static int tilt_sink(void *data, int event, const double *row) {
    (void)event;
    tilt *r = data;
    double a = fabs(row[r->col]);
    r->worst = a > r->worst ? a : r->worst;
    if (row[0] >= r->t_late)
        r->late = a > r->late ? a : r->late;
    r->last = a;
    r->last_t = row[0];
    return 0;
}

/* th's largest |value| over a run of the cart from th = 0.2 (feedback or
 * not), and over t >= t_late; with the feedback, its note into note while
 * the context that holds its names lives. */
static qd_status run_cart(bool lqr, double t_end, tilt *r, qd_sim_lqr *l, qd_buf *note) {
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qd_model_parse(ctx, cart, NULL);
    qd_sim_setup *s = qd_sim_setup_new(ctx, m, false);
    assert_non_null(s);
    assert_int_equal(qd_sim_setup_initial(s, "th = 0.2"), QD_OK);
    if (lqr)
        assert_int_equal(qd_sim_setup_lqr(s, "F", "th=0, th'=0, x=0, x'=0, F=0", weights, l),
                         QD_OK);
    else
        assert_int_equal(qd_sim_setup_input(s, "F", "0", 0, 1), QD_OK);
    char te[32];
    snprintf(te, sizeof te, "%g", t_end);
    qd_sim_setup_opts so = {.t_end = te, .dt = "0.01", .method = "dop853"};
    qd_sim_opts o;
    assert_int_equal(qd_sim_setup_options(s, &so, &o), QD_OK);
    qd_sim *sim = qd_sim_setup_sim(s);
    const char *names[32];
    size_t nc = qd_sim_columns(sim, o.method, names, 32);
    for (r->col = 0; r->col < nc && strcmp(names[r->col], "th"); r->col++)
        ;
    assert_true(r->col < nc);
    qd_sim_stats st;
    qd_status rs = qd_sim_run(sim, &o, tilt_sink, r, &st, NULL);
    if (lqr && note)
        assert_int_equal(qd_sim_lqr_note(l, "p: ", note), QD_OK);
    qd_sim_setup_free(s);
    qd_model_free(m);
    qd_ctx_free(ctx);
    return rs;
}

static void test_lqr_keeps_pendulum_up(void **state) {
    (void)state;
    qd_sim_lqr l;
    tilt r = {.t_late = 8};
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(run_cart(true, 10, &r, &l, &b), QD_OK);
    /* the loop is stable: every closed-loop eigenvalue in the left half plane */
    double a = l.r.eig_re[0];
    for (size_t i = 0; i < l.ss.nx; i++)
        assert_true(l.r.eig_re[i] <= a && l.r.eig_re[i] < 0);
    assert_true(r.last_t > 10 - 1e-9);
    assert_true(r.worst <= 0.2 + 1e-12);            /* never tips further than its start */
    assert_true(r.late < 0.2 * 1e-2);               /* and is upright at the end */
    assert_true(r.last < 0.2 * 50 * exp(a * 10));   /* decaying at the rate of the loop */
    /* the note says the design's gain, entry by entry, in the states' order */
    const char *p = strstr(qd_buf_str(&b), "K =");
    assert_non_null(p);
    p += 3;
    for (size_t j = 0; j < l.ss.nx; j++) {
        char *end;
        double k = strtod(p, &end);
        assert_true(end > p);
        assert_true(fabs(k - l.r.K[l.input * l.ss.nx + j]) <= 1e-5 * fabs(k) + 1e-12);
        p = strchr(end, ')') + 1;
    }
    assert_null(strstr(qd_buf_str(&b), "not an equilibrium")); /* upright is one */
    qd_buf_free(&b);
    qd_sim_lqr_free(&l);
    /* without the feedback it falls: |th| passes pi/2 well within 3 s */
    tilt open = {.t_late = 0};
    assert_int_equal(run_cart(false, 3, &open, NULL, NULL), QD_OK);
    assert_true(open.worst > 1.5);
}

static void test_lqr_errors(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qd_model_parse(ctx, cart, NULL);
    qd_sim_setup *s = qd_sim_setup_new(ctx, m, false);
    qd_sim_lqr l;
    /* a name that is not the model's: located at it in the point's text */
    const char *about = "th=0, thx=0";
    assert_int_equal(qd_sim_setup_lqr(s, "F", about, weights, &l), QD_ERR_ARG);
    assert_string_equal(l.part, "about");
    assert_true(qd_ctx_diag(ctx)->located && qd_ctx_diag(ctx)->offset == 6);
    qd_sim_lqr_free(&l);
    qd_ctx_clear_error(ctx);
    /* a name that is not an input */
    assert_int_equal(qd_sim_setup_lqr(s, "th", "th=0", weights, &l), QD_ERR_ARG);
    assert_string_equal(l.part, "name");
    qd_sim_lqr_free(&l);
    qd_ctx_clear_error(ctx);
    /* Q of the wrong size for the 4 states */
    assert_int_not_equal(qd_sim_setup_lqr(s, "F", "th=0", "Q = diag(1, 2), R = 1", &l), QD_OK);
    assert_string_equal(l.part, "weights");
    qd_sim_lqr_free(&l);
    /* off an equilibrium (the pendulum tilted and held): the note says so */
    qd_ctx_clear_error(ctx);
    assert_int_equal(qd_sim_setup_lqr(s, "F", "th=0.3", weights, &l), QD_OK);
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_sim_lqr_note(&l, "", &b), QD_OK);
    assert_non_null(strstr(qd_buf_str(&b), "not an equilibrium"));
    qd_buf_free(&b);
    qd_sim_lqr_free(&l);
    qd_sim_setup_free(s);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* ---- an input from a table ------------------------------------------------ */

static const char driven[] = "coordinates x\nparameters m = 2, k = 8, c = 0.8\ninputs F\n"
                             "T = m/2*x'^2\nV = k/2*x^2\nQ[x] = F - c*x'\n";

typedef struct amp {
    double from, worst;
} amp;

static int amp_sink(void *data, int event, const double *row) {
    (void)event;
    amp *a = data;
    if (row[0] >= a->from && fabs(row[1]) > a->worst)
        a->worst = fabs(row[1]);
    return 0;
}

static void test_table_drives_oscillator(void **state) {
    (void)state;
    const double F0 = 3, W = 1.3, h = 1e-3, T = 60;
    /* F0 cos(W t) sampled every h, with a header and CR LF line ends */
    size_t n = (size_t)(T / h) + 2, cap = 48 * n + 64, len = 0;
    char *csv = malloc(cap);
    assert_non_null(csv);
    len += (size_t)snprintf(csv, cap, "t,F\r\n");
    for (size_t i = 0; i < n; i++)
        len += (size_t)snprintf(csv + len, cap - len, "%.17g, %.17g\r\n", (double)i * h,
                                F0 * cos(W * (double)i * h));
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qd_model_parse(ctx, driven, NULL);
    qd_sim_setup *s = qd_sim_setup_new(ctx, m, false);
    assert_non_null(s);
    size_t bad = 1;
    assert_int_equal(qd_sim_input_table_read(qd_sim_setup_sim(s), "F", csv, len, &bad), QD_OK);
    assert_int_equal(bad, 0);
    qd_sim_setup_opts so = {.t_end = "60", .dt = "0.01", .method = "dop853", .rtol = "1e-11"};
    qd_sim_opts o;
    assert_int_equal(qd_sim_setup_options(s, &so, &o), QD_OK);
    amp a = {.from = 50}; /* the transient e^(-c t / 2m) is e^(-10) by then */
    qd_sim_stats st;
    assert_int_equal(qd_sim_run(qd_sim_setup_sim(s), &o, amp_sink, &a, &st, NULL), QD_OK);
    double mm = 2, k = 8, c = 0.8;
    double A = F0 / sqrt((k - mm * W * W) * (k - mm * W * W) + (c * W) * (c * W));
    assert_true(fabs(a.worst - A) < 1e-3 * A);
    /* a line that is not a row: its number */
    const char broken[] = "t,F\n0,1\n1,2\n2;3\n";
    assert_int_equal(qd_sim_input_table_read(qd_sim_setup_sim(s), "F", broken,
                                             sizeof broken - 1, &bad), QD_ERR_ARG);
    assert_int_equal(bad, 4);
    free(csv);
    qd_sim_setup_free(s);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lqr_keeps_pendulum_up),
        cmocka_unit_test(test_lqr_errors),
        cmocka_unit_test(test_table_drives_oscillator),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
