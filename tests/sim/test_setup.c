/*
 * tests/sim/test_setup.c - the simulation set-up (qdot/simsetup.h) against
 * closed forms: the oscillator m x'' = -k x (x = cos 2t + sin(2t)/4 from
 * x = 1, x' = 1/2, w = sqrt(k/m) = 2; Goldstein sec. 1.6) run for one
 * period given as text in the parameters, its energy (a definition) kept
 * and its rate 0, the first downward zero of x at t = (pi - atan 4)/2;
 * Desloge ch. 78's H = p^2 - q with the momentum given (q = 2 p0 t + t^2,
 * p = p0 + t); and the errors located in the text they are about.  A
 * vector definition read by component (qd_model_read_expr behind
 * qd_sim_setup_read): the circular orbit r = 1 of V = k r^2/2 with theta' =
 * sqrt(k/m) = 1 has P = (cos t, sin t), |P'|^2 = 1 and P'.x = -sin t, and
 * an event on P.x = 0 finds t = pi/2.
 */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <string.h>
#include <cmocka.h>

#include "qdot/qdot.h"
#include "qdot/simsetup.h"

#define PI 3.14159265358979323846

static const char osc[] = "coordinates x\nparameters m = 2, k = 8, omega = 2\n"
                          "T = m/2*x'^2\nV = k/2*x^2\nE = m/2*x'^2 + k/2*x^2\n";

typedef struct rows {
    double last[16], event_t;
    size_t events, ncols;
    double worst_e, worst_rate; /* |E - 4.25|, |E'| over the rows */
} rows;

static int sink(void *data, int event, const double *row) {
    rows *r = data;
    memcpy(r->last, row, r->ncols * sizeof *row);
    if (event == 0 && r->events++ == 0)
        r->event_t = row[0];
    double e = fabs(row[r->ncols - 2] - 4.25), rate = fabs(row[r->ncols - 1]);
    r->worst_e = e > r->worst_e ? e : r->worst_e;
    r->worst_rate = rate > r->worst_rate ? rate : r->worst_rate;
    return 0;
}

static void test_oscillator(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qd_model_parse(ctx, osc, NULL);
    qd_sim_setup *s = qd_sim_setup_new(ctx, m, false);
    assert_non_null(s);
    assert_int_equal(qd_sim_setup_form(s), QD_SIM_FORM_LAGRANGE);
    assert_int_equal(qd_sim_setup_initial(s, "x = 1, x' = k/16"), QD_OK);
    assert_int_equal(qd_sim_setup_outputs(s, "E, E'"), QD_OK);
    assert_int_equal(qd_sim_setup_event(s, "x = 0, x' < 0", false), QD_OK);
    qd_sim_setup_opts so = {.t_end = "2*pi*sqrt(m/k)", .rtol = "1e-12", .atol = "1e-14"};
    qd_sim_opts o;
    assert_int_equal(qd_sim_setup_options(s, &so, &o), QD_OK);
    assert_int_equal(o.method, QD_SIM_DOP853); /* the default with step control */
    rows r = {.ncols = qd_sim_columns(qd_sim_setup_sim(s), o.method, NULL, 0)};
    assert_true(r.ncols == 6); /* t, x, x', energy, E, E' */
    qd_sim_stats st;
    assert_int_equal(qd_sim_run(qd_sim_setup_sim(s), &o, sink, &r, &st, NULL), QD_OK);
    /* one period: back where it started */
    assert_true(fabs(r.last[0] - PI) < 1e-14);
    assert_true(fabs(r.last[1] - 1) < 1e-9 && fabs(r.last[2] - 0.5) < 1e-9);
    /* E = m x'^2/2 + k x^2/2 = (1/2)^2 + 4 at the start, kept */
    assert_true(r.worst_e < 1e-9);
    assert_true(r.worst_rate < 1e-8); /* dE/dt along the motion */
    assert_int_equal(r.events, 1);
    assert_true(fabs(r.event_t - (PI - atan(4)) / 2) < 1e-10);
    qd_sim_setup_free(s);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* H = p^2 - q: q' = 2p, p' = 1, from q = 0 with the momentum p = 1 given. */
static void test_hamilton(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qd_model_parse(ctx, "coordinates q\nmomenta p\nH = p^2 - q\n", NULL);
    assert_int_equal(qd_sim_form_of(m, false), QD_SIM_FORM_HAMILTON);
    qd_sim_setup *s = qd_sim_setup_new(ctx, m, false);
    assert_non_null(s);
    assert_int_equal(qd_sim_setup_initial(s, "p=1"), QD_OK);
    qd_sim_setup_opts so = {.t_end = "1", .rtol = "1e-12"};
    qd_sim_opts o;
    assert_int_equal(qd_sim_setup_options(s, &so, &o), QD_OK);
    assert_non_null(o.p0);
    assert_true(o.p0[0] == 1);
    double final[8];
    qd_sim_stats st;
    assert_int_equal(qd_sim_run(qd_sim_setup_sim(s), &o, NULL, NULL, &st, final), QD_OK);
    assert_true(fabs(final[1] - 3) < 1e-10); /* q = 2 t + t^2 */
    qd_sim_setup_free(s);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

static qd_sim_setup *fresh(qd_ctx *ctx, qd_model **m) {
    qd_ctx_clear_error(ctx);
    *m = qd_model_parse(ctx, osc, NULL);
    return qd_sim_setup_new(ctx, *m, false);
}

static void done(qd_sim_setup *s, qd_model *m) {
    qd_sim_setup_free(s);
    qd_model_free(m);
}

static void test_errors(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m;
    /* a misspelt name in an output: at its place, the nearest suggested */
    qd_sim_setup *s = fresh(ctx, &m);
    assert_int_equal(qd_sim_setup_outputs(s, "x, 2*omgea + 1"), QD_ERR_ARG);
    const qd_diag *d = qd_ctx_diag(ctx);
    assert_true(d->located && d->offset == 5 && d->length == 5);
    assert_non_null(strstr(d->message, "unknown name 'omgea'"));
    assert_non_null(strstr(d->hint, "did you mean 'omega'?"));
    done(s, m);
    /* ... and in the initial state */
    s = fresh(ctx, &m);
    assert_int_equal(qd_sim_setup_initial(s, "x=1, omegaa=2"), QD_ERR_ARG);
    assert_true(d->located && d->offset == 5 && d->length == 6);
    assert_non_null(strstr(d->hint, "did you mean 'omega'?"));
    done(s, m);
    s = fresh(ctx, &m);
    assert_int_equal(qd_sim_setup_initial(s, "x=1, x=2"), QD_ERR_ARG);
    assert_non_null(strstr(d->message, "'x' is given twice"));
    assert_true(d->offset == 5);
    done(s, m);
    /* a parameter is not the state's: a run never changes it (it was
     * taken and ignored, the motion that of the model's k) */
    s = fresh(ctx, &m);
    assert_int_equal(qd_sim_setup_initial(s, "x=1, k=2"), QD_ERR_ARG);
    assert_true(d->located && d->offset == 5 && d->length == 1);
    assert_non_null(strstr(d->message, "'k' is a parameter"));
    assert_non_null(strstr(d->message, "--set k=VALUE"));
    done(s, m);
    /* a value in the parameters, misspelt: located in the whole text */
    s = fresh(ctx, &m);
    assert_int_equal(qd_sim_setup_initial(s, "x=mm"), QD_ERR_ARG);
    assert_true(d->located && d->offset == 2);
    done(s, m);
    /* the grammar of events: the crossing first */
    s = fresh(ctx, &m);
    assert_int_equal(qd_sim_setup_event(s, "x > 0, x = 1", false), QD_ERR_ARG);
    assert_non_null(strstr(d->message, "EXPR = EXPR"));
    done(s, m);
    /* options name their field */
    s = fresh(ctx, &m);
    qd_sim_opts o;
    qd_sim_setup_opts so = {.t_end = "1", .dt = "-m"};
    assert_int_equal(qd_sim_setup_options(s, &so, &o), QD_ERR_ARG);
    assert_string_equal(d->name, "dt");
    assert_non_null(strstr(d->message, "positive"));
    done(s, m);
    s = fresh(ctx, &m);
    so = (qd_sim_setup_opts){.t_end = "1", .method = "verlet"};
    assert_int_equal(qd_sim_setup_options(s, &so, &o), QD_ERR_ARG);
    assert_string_equal(d->name, "step");
    done(s, m);
    s = fresh(ctx, &m);
    so = (qd_sim_setup_opts){.t_end = "-1"};
    assert_int_equal(qd_sim_setup_options(s, &so, &o), QD_ERR_ARG);
    assert_string_equal(d->name, "t_end");
    done(s, m);
    s = fresh(ctx, &m);
    so = (qd_sim_setup_opts){.t_end = "1", .precision = 80};
    assert_int_equal(qd_sim_setup_options(s, &so, &o), QD_ERR_ARG);
    assert_string_equal(d->name, "precision");
    done(s, m);
    /* issue 33: dt is the output spacing, step the fixed step; a fixed-step
     * default (gl4: unconstrained, conservative) only when a step is given */
    static const struct {
        const char *dt, *step, *every, *rtol, *method;
        qd_status st;
        qd_sim_method m;
        double h, every_out; /* qd_sim_opts dt and every */
        const char *field;   /* refused: the field named */
    } rule[] = {
        {"1/64", NULL, NULL, NULL, NULL, QD_OK, QD_SIM_DOP853, 1.0 / 64, 0, NULL},
        {"0.2", NULL, NULL, "1e-10", NULL, QD_OK, QD_SIM_DOP853, 0.2, 0, NULL},
        {NULL, "1/64", NULL, NULL, NULL, QD_OK, QD_SIM_GL4, 1.0 / 64, 0, NULL},
        {"0.5", "1/64", NULL, NULL, NULL, QD_OK, QD_SIM_GL4, 1.0 / 64, 0.5, NULL},
        {"0.5", "0.5", NULL, NULL, NULL, QD_OK, QD_SIM_GL4, 0.5, 0, NULL},
        {"0.01", NULL, NULL, NULL, "gl4", QD_OK, QD_SIM_GL4, 0.01, 0, NULL},
        {"0.01", NULL, "1", NULL, "gl4", QD_OK, QD_SIM_GL4, 0.01, 1, NULL}, /* older spelling */
        {NULL, NULL, "0.2", "1e-10", NULL, QD_OK, QD_SIM_DOP853, 0.2, 0, NULL},
        {"0.1", "0.01", "0.2", NULL, NULL, QD_ERR_ARG, 0, 0, 0, "every"},
        {NULL, "0.01", NULL, "1e-10", NULL, QD_ERR_ARG, 0, 0, 0, "step"},
        {NULL, "0.01", NULL, NULL, "dop853", QD_ERR_ARG, 0, 0, 0, "step"},
        {NULL, NULL, NULL, NULL, "gl4", QD_ERR_ARG, 0, 0, 0, "step"},
    };
    for (size_t i = 0; i < sizeof rule / sizeof rule[0]; i++) {
        s = fresh(ctx, &m);
        so = (qd_sim_setup_opts){.t_end = "1", .dt = rule[i].dt, .step = rule[i].step,
                                 .every = rule[i].every, .rtol = rule[i].rtol,
                                 .method = rule[i].method};
        qd_status st = qd_sim_setup_options(s, &so, &o);
        if (st != rule[i].st)
            fail_msg("rule %zu: status %d (%s)", i, (int)st, d->message);
        if (st == QD_OK && (o.method != rule[i].m || o.dt != rule[i].h ||
                            o.every != rule[i].every_out || o.fixed))
            fail_msg("rule %zu: method %s dt %g every %g", i, qd_sim_method_name(o.method),
                     o.dt, o.every);
        if (st != QD_OK)
            assert_string_equal(d->name, rule[i].field);
        done(s, m);
    }
    qd_ctx_free(ctx);
}

typedef struct orbit_rows {
    size_t ncols, events;
    double worst, event_t;
} orbit_rows;

/* columns: t, r, theta, r', theta', energy, P.x, P'.x, dot(P', P') */
static int orbit_sink(void *data, int event, const double *row) {
    orbit_rows *r = data;
    const double *o = row + r->ncols - 3, t = row[0];
    double e = fmax(fabs(o[0] - cos(t)), fmax(fabs(o[1] + sin(t)), fabs(o[2] - 1)));
    r->worst = fmax(r->worst, e);
    if (event == 0 && r->events++ == 0)
        r->event_t = t;
    return 0;
}

static void test_vector_components(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qd_model_parse(ctx, "coordinates r, theta\nparameters m = 1, k = 1\n"
                                      "P = (r*cos(theta), r*sin(theta), 0)\nparticle m at P\n"
                                      "V = k/2*r^2\n", NULL);
    assert_non_null(m);
    qd_sim_setup *s = qd_sim_setup_new(ctx, m, false);
    assert_non_null(s);
    assert_int_equal(qd_sim_setup_initial(s, "r = 1, theta' = 1"), QD_OK);
    assert_int_equal(qd_sim_setup_outputs(s, "P.x, P'.x, dot(P', P')"), QD_OK);
    assert_int_equal(qd_sim_setup_event(s, "P.x = 0", false), QD_OK);
    qd_sim_setup_opts so = {.t_end = "3", .rtol = "1e-12", .atol = "1e-14"};
    qd_sim_opts o;
    assert_int_equal(qd_sim_setup_options(s, &so, &o), QD_OK);
    orbit_rows r = {.ncols = qd_sim_columns(qd_sim_setup_sim(s), o.method, NULL, 0)};
    qd_sim_stats st;
    assert_int_equal(qd_sim_run(qd_sim_setup_sim(s), &o, orbit_sink, &r, &st, NULL), QD_OK);
    assert_true(r.worst < 1e-9);
    assert_int_equal(r.events, 1);
    assert_true(fabs(r.event_t - PI / 2) < 1e-9);
    /* a component that is none, and a vector where a scalar is needed: located */
    const char *bad = "P.w";
    assert_null(qd_sim_setup_read(s, bad, 0, strlen(bad)));
    assert_true(qd_ctx_diag(ctx)->located && qd_ctx_diag(ctx)->offset == 2);
    assert_non_null(strstr(qd_ctx_message(ctx), "component"));
    qd_ctx_clear_error(ctx);
    const char *vec = "1 + sin(P)";
    assert_null(qd_model_read_expr(ctx, m, vec, 0, strlen(vec)));
    assert_non_null(strstr(qd_ctx_message(ctx), "a vector where a scalar is needed"));
    qd_ctx_clear_error(ctx);
    qd_sim_setup_free(s);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_vector_components),
        cmocka_unit_test(test_oscillator),
        cmocka_unit_test(test_hamilton),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
