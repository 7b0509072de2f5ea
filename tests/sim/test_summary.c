/*
 * tests/sim/test_summary.c - the summary of a run (qd_sim_summary_json,
 * qd_sim_summary_print, qd_stop_name; qdot/sim.h), read back and checked
 * against the physics of the run:
 *
 *   - the harmonic oscillator x'' = -(k/m) x from x = 1 at rest: energy
 *     k/2 conserved to the tolerance asked, the final row x = cos(w t),
 *     x' = -w sin(w t), w = sqrt(k/m), at t = t_end, and no stop record
 *     (the run reached t_end);
 *   - a body dropped from y = h stopped by a terminal event at y = 0: the
 *     stop record says "event" at t = sqrt(2 h/g) (Galileo);
 *   - runs made to fail: the blow-up x'' = 4 x^3 from x = 1 at rest
 *     reaches infinity at t = K(1/sqrt 2)/2 = 0.92704 (dop853: step size
 *     underflow there), and from x' = 1 at t = 0.7531 (verlet with a fixed
 *     step: the first non-finite state), each with its code and time;
 *   - the bouncing ball (restitution E = 1/2 from h = 1) ends at rest in
 *     contact at the accumulation time t1 (1 + E)/(1 - E), t1 = sqrt(2h/g),
 *     having lost its energy m g h to the impacts.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "qdot/json.h"
#include "sim_fixture.h"

/* ---- reading the JSON back ------------------------------------------------------- */

/* Where the value of "key" starts in s (at or after s), or NULL. */
static const char *member(const char *s, const char *key) {
    char pat[96];
    snprintf(pat, sizeof pat, "\"%s\": ", key);
    const char *p = s ? strstr(s, pat) : NULL;
    return p ? p + strlen(pat) : NULL;
}

/* The number that is "key"'s value (NaN when absent or null). */
static double number(const char *s, const char *key) {
    const char *p = member(s, key);
    if (!p || !strncmp(p, "null", 4))
        return NAN;
    char *end;
    double x = strtod(p, &end);
    return end == p ? NAN : x;
}

/* "key"'s value is the string want. */
static bool string_is(const char *s, const char *key, const char *want) {
    const char *p = member(s, key);
    size_t n = strlen(want);
    return p && p[0] == '"' && !strncmp(p + 1, want, n) && p[1 + n] == '"';
}

/* The JSON document {summary} of the run f made with o (final: its last row). */
static void render(const sim_fix *f, const qd_sim_opts *o, const double *final, qd_buf *b) {
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    qd_sim_report r = {.s = f->s, .opts = o, .stats = &f->stats, .final = final, .wall = 0.5};
    assert_int_equal(qd_sim_summary_json(&j, &r), QD_OK);
    qd_json_end_object(&j);
    assert_true(qd_json_ok(&j));
}

/* ---- a run that reached t_end --------------------------------------------------------- */

static const char osc[] = "coordinates x\nparameters m = 1, k = 4\nT = m/2*x'^2\n"
                          "V = k/2*x^2\ninitial x = 1\n";

static void test_oscillator(void **state) {
    (void)state;
    sim_fix *f = sf_load(osc);
    assert_non_null(f);
    const double rtol = 1e-10, t_end = 10, w = 2;
    qd_sim_opts o = {.method = QD_SIM_DOP853, .t_end = t_end, .rtol = rtol, .atol = 1e-12,
                     .q0 = f->q0, .qd0 = f->qd0};
    double final[8];
    assert_int_equal(qd_sim_run(f->s, &o, NULL, NULL, &f->stats, final), QD_OK);
    qd_buf b = QD_BUF_INIT;
    render(f, &o, final, &b);
    const char *s = qd_buf_str(&b);
    /* energy k x0^2/2 = 2 kept to the tolerance asked */
    double err = number(s, "energy_error_max");
    assert_true(err >= 0 && err < rtol);
    assert_true(number(s, "energy_error_steps") <= err);
    const char *fin = member(s, "final");
    assert_non_null(fin);
    assert_true(number(fin, "t") == t_end);
    assert_true(fabs(number(fin, "x") - cos(w * t_end)) < 1e-8);
    assert_true(fabs(number(fin, "x'") + w * sin(w * t_end)) < 1e-8);
    assert_true(fabs(number(fin, "energy") - 2) < 2 * rtol);
    /* reached t_end: no stop record; the method and the counts as run */
    assert_null(member(s, "stop"));
    assert_true(string_is(s, "method", "dop853"));
    assert_true(number(s, "steps") == (double)f->stats.steps && f->stats.steps > 0);
    assert_true(number(s, "wall_s") == 0.5);
    assert_true(number(s, "events") == 0);
    assert_null(member(s, "impacts")); /* no impacts, no friction in the model */
    assert_null(member(s, "transitions"));
    /* the text: every line prefixed, the energy error the same number */
    qd_buf t = QD_BUF_INIT;
    qd_sim_report r = {.s = f->s, .opts = &o, .stats = &f->stats, .final = final, .wall = 0.5};
    assert_int_equal(qd_sim_summary_print(&r, "> ", &t), QD_OK);
    const char *txt = qd_buf_str(&t);
    assert_true(!strncmp(txt, "> dop853, t = 0..10: ", 21));
    for (const char *p = strchr(txt, '\n'); p && p[1]; p = strchr(p + 1, '\n'))
        assert_true(!strncmp(p + 1, "> ", 2));
    const char *e = strstr(txt, "energy error ");
    assert_non_null(e);
    assert_true(fabs(strtod(e + 13, NULL) - err) <= 1e-3 * err); /* %.3g */
    assert_null(strstr(txt, "stopped early"));
    qd_buf_free(&t);
    qd_buf_free(&b);
    sf_free(f);
}

/* ---- runs that stopped early ------------------------------------------------------ */

static void test_terminal_event(void **state) {
    (void)state;
    static const char fall[] = "coordinates y\nparameters g = 9.81\nT = y'^2/2\nV = g*y\n"
                               "initial y = 5\n";
    sim_fix *f = sf_load(fall);
    assert_non_null(f);
    const qd_expr *g = qd_read(f->ctx, "y", NULL, NULL);
    assert_int_equal(qd_sim_add_event(f->s, g, 0, NULL, true), QD_OK);
    qd_sim_opts o = {.method = QD_SIM_DOP853, .t_end = 2, .rtol = 1e-12, .q0 = f->q0,
                     .qd0 = f->qd0};
    double final[8];
    assert_int_equal(qd_sim_run(f->s, &o, NULL, NULL, &f->stats, final), QD_OK);
    qd_buf b = QD_BUF_INIT;
    render(f, &o, final, &b);
    const char *s = qd_buf_str(&b);
    const char *stop = member(s, "stop");
    assert_non_null(stop);
    assert_true(string_is(stop, "code", "event"));
    assert_true(!strncmp(member(stop, "ok"), "true", 4)); /* ended as asked */
    double tf = sqrt(2 * 5 / 9.81);
    assert_true(fabs(number(stop, "t") - tf) < 1e-9);
    assert_true(number(stop, "value") == 0); /* the first event added */
    assert_true(fabs(number(member(s, "final"), "y")) < 1e-9);
    qd_buf_free(&b);
    sf_free(f);
}

/* A run that fails: its status, then the stop record in JSON (code, time)
 * and the stop line in text. */
static void failed(const char *text, qd_sim_opts o, const char *code, double t_blow,
                   double tol) {
    sim_fix *f = sf_load(text);
    assert_non_null(f);
    o.q0 = f->q0;
    o.qd0 = f->qd0;
    assert_int_not_equal(qd_sim_run(f->s, &o, NULL, NULL, &f->stats, NULL), QD_OK);
    qd_buf b = QD_BUF_INIT;
    render(f, &o, NULL, &b);
    const char *s = qd_buf_str(&b);
    const char *stop = member(s, "stop");
    if (!stop || !string_is(stop, "code", code))
        fail_msg("want stop code %s in %s", code, s);
    assert_true(!strncmp(member(stop, "ok"), "false", 5));
    assert_true(string_is(stop, "reason", qd_stop_str(f->stats.stop.code)));
    if (!(fabs(number(stop, "t") - t_blow) < tol))
        fail_msg("%s: stopped at t = %.17g, the blow-up is at %.17g", code, number(stop, "t"),
                 t_blow);
    assert_null(member(s, "final"));
    /* the text says it too, with the time to every digit */
    qd_buf t = QD_BUF_INIT;
    qd_sim_report r = {.s = f->s, .opts = &o, .stats = &f->stats, .wall = 0};
    assert_int_equal(qd_sim_summary_print(&r, NULL, &t), QD_OK);
    const char *line = strstr(qd_buf_str(&t), "\nstopped early: ");
    assert_non_null(line);
    const char *at = strstr(line, " at t = ");
    assert_non_null(at);
    assert_true(strtod(at + 8, NULL) == f->stats.stop.t);
    qd_buf_free(&t);
    qd_buf_free(&b);
    sf_free(f);
}

static void test_failures(void **state) {
    (void)state;
    /* x'' = 4 x^3 from x = 1 at rest: x' = sqrt(2 (x^4 - 1)), the blow-up
     * at integral_1^inf dx / sqrt(2 (x^4 - 1)) = K(1/sqrt 2)/2 */
    static const char rest[] = "coordinates x\nT = x'^2/2\nV = -x^4\ninitial x = 1\n";
    failed(rest, (qd_sim_opts){.method = QD_SIM_DOP853, .t_end = 5, .rtol = 1e-10},
           "step_underflow", 0.9270373386, 1e-3);
    /* from x' = 1: x' = sqrt(2 x^4 - 1), the blow-up at integral_1^inf dx /
     * sqrt(2 x^4 - 1) = 0.7531; a fixed step of 1e-3 meets a non-finite
     * state within a few steps of it */
    static const char moving[] = "coordinates x\nT = x'^2/2\nV = -x^4\ninitial x = 1, x' = 1\n";
    failed(moving, (qd_sim_opts){.method = QD_SIM_VERLET, .t_end = 2, .dt = 1e-3},
           "nonfinite", 0.7531, 1e-2);
}

/* ---- impacts ------------------------------------------------------------------------ */

static void test_bouncing_ball(void **state) {
    (void)state;
    static const char ball[] = "coordinates y\nparameters m = 1, g = 9.81, h = 1, e = 0.5\n"
                               "particle m at (0, y, 0)\nV = m*g*y\n"
                               "impact floor: y >= 0 restitution e\ninitial y = h\n";
    sim_fix *f = sf_load(ball);
    assert_non_null(f);
    qd_sim_opts o = {.method = QD_SIM_DOP853, .t_end = 10, .rtol = 1e-12, .atol = 1e-14,
                     .q0 = f->q0, .qd0 = f->qd0};
    double final[8];
    assert_int_equal(qd_sim_run(f->s, &o, NULL, NULL, &f->stats, final), QD_OK);
    qd_buf b = QD_BUF_INIT;
    render(f, &o, final, &b);
    const char *s = qd_buf_str(&b);
    double t1 = sqrt(2 / 9.81), tstar = t1 * (1 + 0.5) / (1 - 0.5);
    assert_true(fabs(number(s, "impact_energy_lost") - 9.81) < 1e-9); /* m g h */
    assert_true(number(s, "impacts") > 10);
    const char *contact = member(s, "contact");
    assert_non_null(contact);
    assert_true(string_is(contact, "impact", "floor"));
    assert_true(fabs(number(contact, "t") - tstar) < 1e-9);
    assert_true(!strncmp(member(contact, "chattering"), "true", 4));
    assert_true(!strncmp(member(contact, "at_rest"), "true", 4));
    const char *stop = member(s, "stop"); /* ended as asked, before t_end */
    assert_true(string_is(stop, "code", "contact"));
    assert_true(fabs(number(stop, "t") - tstar) < 1e-9);
    assert_true(number(stop, "value") == 0); /* the model's first impact */
    qd_buf_free(&b);
    sf_free(f);
}

/* ---- the stop codes' names -------------------------------------------------------- */

static void test_stop_names(void **state) {
    (void)state;
    /* one word per code, distinct, lower case: a program's key */
    for (int a = QD_STOP_NONE; a <= QD_STOP_FAILURE; a++) {
        const char *na = qd_stop_name((qd_stop_code)a);
        assert_string_not_equal(na, "unknown");
        for (const char *p = na; *p; p++)
            assert_true((*p >= 'a' && *p <= 'z') || *p == '_');
        for (int b = a + 1; b <= QD_STOP_FAILURE; b++)
            assert_string_not_equal(na, qd_stop_name((qd_stop_code)b));
    }
    assert_string_equal(qd_stop_name((qd_stop_code)99), "unknown");
    assert_int_equal(qd_sim_summary_json(NULL, NULL), QD_ERR_ARG);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_oscillator),    cmocka_unit_test(test_terminal_event),
        cmocka_unit_test(test_failures),      cmocka_unit_test(test_bouncing_ball),
        cmocka_unit_test(test_stop_names),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
