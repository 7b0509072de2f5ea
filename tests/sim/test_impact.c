/*
 * tests/sim/test_impact.c - unilateral impacts in qd_sim (`impact NAME:
 * GAP >= 0 restitution E`), checked against closed forms:
 *
 *   - the bouncing ball (Newton's law of restitution, Desloge ch. 61;
 *     Byerly ch. III art. 33): a drop from h falls for t1 = sqrt(2h/g),
 *     the n-th rebound leaves at E^n sqrt(2gh), so the apexes are
 *     E^(2n) h, the impacts at t_n = t1 (1 + 2E + ... + 2E^(n-1)), and the
 *     series of flights sums to the accumulation time t* = t1 (1+E)/(1-E),
 *     where the run ends at rest in contact (chattering);
 *   - a pendulum striking a wall at its lowest point: each rebound is -E
 *     times the approach, so 1 - cos(amplitude) falls by E^2 per impact
 *     (energy), and the impacts are a quarter, then half periods apart
 *     (T = 4 sqrt(l/g) K(sin(a/2)));
 *   - a particle held on a circle by a multiplier striking a stop: the
 *     constraint holds through the impact and the speed along the circle
 *     reverses by -E (the law with the constraint's impulsive multiplier);
 *   - the rhombus of four rods hitting an inelastic wall (Desloge ch. 57
 *     ex. 1, reference T55): th'+ = 3/7, x'+ = -3/7 for al = 30 deg,
 *     a = v = 1, and the rhombus leaves the wall again;
 *   - a rod falling flat onto a ledge: the angular momentum about the
 *     ledge kept, and the run ending in sustained contact, still moving;
 *   - a rod falling flat onto the floor: both ends struck together;
 *   - the errors: a gap negative at t0, a restitution outside [0, 1].
 *
 * The flights under constant gravity are quadratics, which every method
 * integrates exactly: the tolerances below are round-off over tens of
 * located impacts (and BDF's own error, 1e-8, for that method).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "sim_fixture.h"

#define G 9.81
#define MAXROWS 512

/* The rows of a run that carry an event: apexes (a user event) and the
 * impacts' before/after pairs. */
typedef struct rows {
    size_t n, ncols;
    int ev[MAXROWS];
    double row[MAXROWS][16];
} rows;

static int keep(void *data, int event, const double *row) {
    rows *r = data;
    if (event >= 0 && r->n < MAXROWS) {
        r->ev[r->n] = event;
        memcpy(r->row[r->n++], row, r->ncols * sizeof *row);
    }
    return 0;
}

static qd_status run(sim_fix *f, qd_sim_method method, double t_end, double dt, double rtol,
                     rows *r) {
    qd_sim_opts o = {.method = method, .t0 = 0, .t_end = t_end, .dt = dt, .rtol = rtol,
                     .atol = rtol * 1e-2, .q0 = f->q0, .qd0 = f->qd0};
    memset(r, 0, sizeof *r);
    r->ncols = qd_sim_columns(f->s, method, NULL, 0);
    assert_true(r->ncols <= 16);
    qd_status st = qd_sim_run(f->s, &o, keep, r, &f->stats, f->last);
    if (st != QD_OK)
        fprintf(stderr, "run (%s): %s\n", qd_sim_method_name(method), qd_ctx_message(f->ctx));
    return st;
}

static double rel(double a, double b) { return fabs(a - b) / fabs(b); }

static void near(double got, double want, double tol, const char *what, size_t k) {
    if (!(rel(got, want) <= tol))
        fail_msg("%s %zu: %.17g vs %.17g (relative %.3g > %.3g)", what, k, got, want,
                 rel(got, want), tol);
}

/* The ball of mass m dropped from h onto the floor y = 0. */
static sim_fix *ball(double E, double h) {
    char text[512];
    snprintf(text, sizeof text,
             "coordinates y\nparameters m = 2, g = %.17g, e = %.17g\n"
             "particle m at (0, y, 0)\nV = m*g*y\n"
             "impact floor: y >= 0 restitution e\n"
             "initial y = %.17g, y' = 0\n", G, E, h);
    sim_fix *f = sf_load(text);
    assert_non_null(f);
    return f;
}

/* Apexes (another event: y' = 0 falling through) and impacts (event
 * imp_ev, pairs before/after) against E^(2n) h and t1 (1 + 2E + ... + 2E^(n-1)). */
static void check_bounces(const rows *r, int imp_ev, double E, double h, size_t nmax,
                          double tol) {
    double t1 = sqrt(2 * h / G), tn = t1, apex = h;
    size_t napex = 0, nimp = 0;
    for (size_t k = 0; k < r->n && nimp < nmax; k++) {
        if (r->ev[k] != imp_ev) {
            apex *= E * E;
            near(r->row[k][1], apex, 1e-8, "apex", ++napex);
            continue;
        }
        /* an impact: the row before, then the row after */
        assert_true(k + 1 < r->n && r->ev[k + 1] == imp_ev);
        nimp++;
        near(r->row[k][0], tn, tol, "impact time", nimp);
        assert_true(fabs(r->row[k][1]) < 1e-14 * h);
        near(r->row[k + 1][2], -E * r->row[k][2], 1e-12, "rebound", nimp);
        tn += 2 * t1 * pow(E, (double)nimp);
        k++;
    }
    assert_int_equal(nimp, nmax);
}

static void add_apex_event(sim_fix *f) {
    const qd_expr *y = qd_lookup(f->ctx, "y"), *yd = qd_jet(f->ctx, y, 1);
    assert_int_equal(qd_sim_add_event(f->s, yd, 0, NULL, false), QD_OK);
}

/* E = 0.6, h = 1.5: apexes, impact times, and the end at t* in contact
 * after the impact whose rebound falls below sqrt(rtol) of the first. */
static void ball_chatters(void **state) {
    (void)state;
    double E = 0.6, h = 1.5, m = 2, rtol = 1e-12;
    sim_fix *f = ball(E, h);
    add_apex_event(f);
    rows r;
    assert_int_equal(run(f, QD_SIM_DOP853, 10, 0, rtol, &r), QD_OK);
    check_bounces(&r, 1, E, h, 12, 1e-12);
    double t1 = sqrt(2 * h / G), tstar = t1 * (1 + E) / (1 - E);
    assert_true(f->stats.in_contact && f->stats.at_rest && f->stats.chattering);
    assert_int_equal(f->stats.contact, 0);
    near(f->stats.t, tstar, 1e-12, "accumulation time", 0);
    assert_true(f->last[0] == f->stats.t);
    assert_true(fabs(f->last[1]) < 1e-14 && f->last[2] == 0);
    /* the first n with E^n <= sqrt(rtol): 0.6^27 = 1.03e-6, 0.6^28 = 6.1e-7 */
    assert_int_equal(f->stats.impacts, 28);
    near(f->stats.impact_energy_lost, m * G * h, 1e-12, "energy lost", 0);
    assert_true(f->stats.energy_error_max < 1e-13);
    sf_free(f);
}

/* Every method locates the impacts, restarts and sums the series. */
static void ball_every_method(void **state) {
    (void)state;
    double E = 0.5, h = 1, tstar = sqrt(2 * h / G) * (1 + E) / (1 - E);
    for (int mi = 0; mi < QD_SIM_METHOD_COUNT; mi++) {
        qd_sim_method method = (qd_sim_method)mi;
        sim_fix *f = ball(E, h);
        bool adaptive = qd_sim_method_adaptive(method);
        rows r;
        assert_int_equal(run(f, method, 5, adaptive ? 0 : 1e-3, 1e-12, &r), QD_OK);
        double tol = method == QD_SIM_BDF ? 1e-7 : 1e-12;
        check_bounces(&r, 0, E, h, 8, method == QD_SIM_BDF ? 1e-9 : 1e-12);
        if (!(f->stats.in_contact && f->stats.at_rest && rel(f->stats.t, tstar) <= tol))
            fail_msg("%s: at rest %d at t = %.17g, t* = %.17g", qd_sim_method_name(method),
                     f->stats.at_rest, f->stats.t, tstar);
        assert_true(fabs(f->last[1]) < 1e-12);
        sf_free(f);
    }
}

/* E = 1 conserves the energy over many bounces: every apex is h. */
static void ball_elastic(void **state) {
    (void)state;
    double h = 0.8, t1 = sqrt(2 * h / G);
    sim_fix *f = ball(1, h);
    add_apex_event(f);
    rows r;
    assert_int_equal(run(f, QD_SIM_DOP853, 24 * t1, 0, 1e-12, &r), QD_OK);
    check_bounces(&r, 1, 1, h, 12, 1e-12);
    assert_false(f->stats.in_contact);
    assert_int_equal(f->stats.impacts, 12);
    assert_true(fabs(f->stats.impact_energy_lost) < 1e-13);
    assert_true(f->stats.energy_error_max < 1e-12);
    sf_free(f);
}

/* E = 0 sticks at the first impact, at t1. */
static void ball_plastic(void **state) {
    (void)state;
    double h = 2, t1 = sqrt(2 * h / G);
    sim_fix *f = ball(0, h);
    rows r;
    assert_int_equal(run(f, QD_SIM_DOP853, 3, 0, 1e-12, &r), QD_OK);
    assert_int_equal(f->stats.impacts, 1);
    assert_true(f->stats.in_contact && f->stats.at_rest && !f->stats.chattering);
    near(f->stats.t, t1, 1e-14, "rest time", 0);
    assert_true(f->last[2] == 0);
    near(f->stats.impact_energy_lost, 2 * G * h, 1e-13, "energy lost", 0);
    sf_free(f);
}

/* The pendulum (l, g) from th0 at rest onto the wall th = 0. */
static void pendulum_wall(void **state) {
    (void)state;
    double l = 1.3, th0 = 0.5, E = 0.8, w = sqrt(G / l);
    char text[512];
    snprintf(text, sizeof text,
             "coordinates th\nparameters m = 1, l = %.17g, g = %.17g\n"
             "T = m/2*l^2*th'^2\nV = -m*g*l*cos(th)\n"
             "impact wall: th >= 0 restitution %.17g\ninitial th = %.17g, th' = 0\n",
             l, G, E, th0);
    sim_fix *f = sf_load(text);
    assert_non_null(f);
    const qd_expr *th = qd_lookup(f->ctx, "th"), *thd = qd_jet(f->ctx, th, 1);
    assert_int_equal(qd_sim_add_event(f->s, thd, 1, &th, false), QD_OK);
    rows r;
    assert_int_equal(run(f, QD_SIM_DOP853, 4.2, 0, 1e-12, &r), QD_OK);
    /* 1 - cos(a_n) = E^(2n) (1 - cos th0); the n-th impact comes half a
     * period of amplitude a_(n-1) after the last (the first a quarter) */
    double a = th0, t = sf_ellipk(sin(th0 / 2)) / w;
    size_t nimp = 0, namp = 0;
    for (size_t k = 0; k < r.n; k++) {
        if (r.ev[k] == 0) {
            near(1 - cos(r.row[k][1]), 1 - cos(a), 1e-10, "amplitude", ++namp);
            continue;
        }
        near(r.row[k][0], t, 1e-11, "impact time", ++nimp);
        near(r.row[k + 1][2], -E * r.row[k][2], 1e-12, "rebound", nimp);
        a = acos(1 - E * E * (1 - cos(a)));
        t += 2 * sf_ellipk(sin(a / 2)) / w;
        k++;
    }
    assert_int_equal(nimp, 4);
    assert_true(namp >= 3);
    assert_false(f->stats.in_contact);
    sf_free(f);
}

/* A particle on the circle x^2 + y^2 = l^2 (a multiplier) swings onto the
 * stop x = l sin(al): the constraint holds through the impact, the
 * velocity stays tangent, the speed reverses by -E, and the energy lost is
 * (1 - E^2) of the kinetic energy before. */
static void circle_stop(void **state) {
    (void)state;
    double l = 1.3, al = 0.2, th0 = 0.6, E = 0.7;
    char text[640];
    snprintf(text, sizeof text,
             "coordinates x, y\nparameters m = 1, l = %.17g, g = %.17g\n"
             "particle m at (x, y, 0)\nV = m*g*y\nconstraint rod: x^2 + y^2 = l^2\n"
             "impact stop: x - l*sin(%.17g) >= 0 restitution %.17g\n"
             "initial x = %.17g, y = %.17g\n",
             l, G, al, E, l * sin(th0), -l * cos(th0));
    sim_fix *f = sf_load(text);
    assert_non_null(f);
    rows r;
    assert_int_equal(run(f, QD_SIM_DOP853, 3, 0, 1e-12, &r), QD_OK);
    assert_true(r.n >= 6);
    double lost = 0;
    for (size_t k = 0; k + 1 < r.n; k += 2) {
        const double *b = r.row[k], *af = r.row[k + 1];
        assert_int_equal(r.ev[k], 0);
        near(b[1], l * sin(al), 1e-13, "at the stop", k);
        /* tangent after: x x' + y y' = 0 */
        assert_true(fabs(af[1] * af[3] + af[2] * af[4]) < 1e-12);
        near(af[3], -E * b[3], 1e-12, "rebound", k);
        double Tb = 0.5 * (b[3] * b[3] + b[4] * b[4]);
        lost += (1 - E * E) * Tb;
    }
    near(f->stats.impact_energy_lost, lost, 1e-11, "energy lost", 0);
    assert_true(qd_sim_constraint_error(f->s, 0) < 1e-12);
    assert_true(f->stats.energy_error_max < 1e-11);
    sf_free(f);
}

/* Desloge ch. 57 ex. 1 (reference T55): four rods of mass m, length 2a,
 * a rhombus sliding at v along AC onto a wall, th = angle BCA = al, T =
 * 2 m x'^2 + (8/3) m a^2 th'^2, C at x - 2a cos th.  E = 0: C stops, then
 * th'+ = 3 v sin al / (2a (1 + 3 sin^2 al)) = 3/7 and x'+ = -3/7 at al =
 * 30 deg, a = v = 1; the energy lost is 2 m v^2 - 6/7 = 8/7 (m = 1); and
 * the free motion opens the gap again, so the run goes on. */
static void rhombus_wall(void **state) {
    (void)state;
    sim_fix *f = sf_load("coordinates x, th\nparameters m = 1, a = 1, v = 1\n"
                         "T = 2*m*x'^2 + 8/3*m*a^2*th'^2\n"
                         "impact C: x - 2*a*cos(th) >= 0 restitution 0\n"
                         "initial x = 2, x' = -v, th = pi/6, th' = 0\n");
    assert_non_null(f);
    rows r;
    assert_int_equal(run(f, QD_SIM_DOP853, 1.5, 0, 1e-12, &r), QD_OK);
    assert_int_equal(f->stats.impacts, 1);
    assert_false(f->stats.in_contact);
    assert_int_equal(r.n, 2);
    near(r.row[0][0], 2 - sqrt(3), 1e-14, "impact time", 0);
    near(r.row[1][3], -3.0 / 7, 1e-13, "x'+", 0);
    near(r.row[1][4], 3.0 / 7, 1e-13, "th'+", 0);
    near(f->stats.impact_energy_lost, 8.0 / 7, 1e-13, "energy lost", 0);
    /* C has left the wall by the end */
    assert_true(f->last[1] - 2 * cos(f->last[2]) > 1e-3);
    sf_free(f);
}

/* A rod (m, 2a) falling flat onto a ledge at d from its centre, E = 0:
 * the angular momentum about the ledge is kept across the impact (the
 * impulse acts there), m v d = (m a^2/3 + m d^2) w, so w = 3 v d /
 * (a^2 + 3 d^2), the centre's y' = -d w, and (m v^2/2) a^2/(a^2 + 3 d^2)
 * is lost.  Gravity presses it onto the ledge, about which it turns: the
 * run ends in sustained contact, not at rest. */
static void rod_ledge(void **state) {
    (void)state;
    double a = 1, d = 0.5, h = 0.2, v = sqrt(2 * G * h), w = 3 * v * d / (a * a + 3 * d * d);
    char text[512];
    snprintf(text, sizeof text,
             "coordinates x, y, th\nparameters m = 1, a = %.17g, d = %.17g, g = %.17g\n"
             "T = m/2*(x'^2 + y'^2) + m*a^2/6*th'^2\nV = m*g*y\n"
             "impact ledge: y*cos(th) - x*sin(th) >= 0 restitution 0\n"
             "initial x = d, y = %.17g, th = 0\n", a, d, G, h);
    sim_fix *f = sf_load(text);
    assert_non_null(f);
    rows r;
    assert_int_equal(run(f, QD_SIM_DOP853, 1, 0, 1e-12, &r), QD_OK);
    assert_int_equal(r.n, 2);
    assert_int_equal(f->stats.impacts, 1);
    assert_true(f->stats.in_contact && !f->stats.at_rest && !f->stats.chattering);
    near(r.row[0][0], sqrt(2 * h / G), 1e-14, "impact time", 0);
    /* columns t, x, y, th, x', y', th', energy */
    assert_true(fabs(r.row[1][4]) < 1e-15);
    near(r.row[1][6], -w, 1e-13, "th'+", 0);
    near(r.row[1][5], -d * w, 1e-13, "y'+", 0);
    near(f->stats.impact_energy_lost, 0.5 * v * v * a * a / (a * a + 3 * d * d), 1e-13,
         "energy lost", 0);
    assert_true(f->last[0] == r.row[0][0]);
    sf_free(f);
}

/* A rod falling flat onto the floor strikes with both ends at once: the
 * two contacts are struck together (one law, two rows), so no turning
 * starts and the rod bounces as the ball does, at rest from t1 (1+E)/(1-E)
 * after 20 impacts of each end (E = 1/2, rtol 1e-12).  Struck one after
 * the other, the first end's impulse would set it rocking.  Every method:
 * the fixed steps end on a rebound shorter than the step, where both ends
 * must come to rest together too. */
static void rod_flat_method(qd_sim_method method) {
    double E = 0.5, h = 1, tstar = sqrt(2 * h / G) * (1 + E) / (1 - E);
    char text[512];
    snprintf(text, sizeof text,
             "coordinates x, y, th\nparameters m = 1, a = 1, g = %.17g, e = %.17g\n"
             "T = m/2*(x'^2 + y'^2) + m*a^2/6*th'^2\nV = m*g*y\n"
             "impact A: y - a*sin(th) >= 0 restitution e\n"
             "impact B: y + a*sin(th) >= 0 restitution e\n"
             "initial x = 0, y = %.17g, th = 0\n", G, E, h);
    sim_fix *f = sf_load(text);
    assert_non_null(f);
    rows r;
    bool adaptive = qd_sim_method_adaptive(method);
    assert_int_equal(run(f, method, 3, adaptive ? 0 : 1e-3, 1e-12, &r), QD_OK);
    assert_true(f->stats.in_contact && f->stats.at_rest && f->stats.chattering);
    near(f->stats.t, tstar, method == QD_SIM_BDF ? 1e-7 : 1e-12, "accumulation time", 0);
    assert_true(f->stats.impacts % 2 == 0);
    if (method == QD_SIM_DOP853)
        assert_int_equal(f->stats.impacts, 40);
    /* columns t, x, y, th, x', y', th', ...: th and th' stay 0 */
    size_t th = 3, thd = 6;
    for (size_t k = 0; k < r.n; k++)
        if (!(fabs(r.row[k][th]) < 1e-15 && fabs(r.row[k][thd]) < 1e-15))
            fail_msg("%s: the rod turns: th = %g, th' = %g at t = %.17g",
                     qd_sim_method_name(method), r.row[k][th], r.row[k][thd], r.row[k][0]);
    assert_true(fabs(f->last[th]) < 1e-15);
    sf_free(f);
}

static void rod_flat_on_floor(void **state) {
    (void)state;
    for (int mi = 0; mi < QD_SIM_METHOD_COUNT; mi++)
        rod_flat_method((qd_sim_method)mi);
}

static void gap_negative_at_start(void **state) {
    (void)state;
    sim_fix *f = ball(0.5, -0.1);
    rows r;
    assert_int_equal(run(f, QD_SIM_DOP853, 1, 0, 1e-10, &r), QD_ERR_ARG);
    assert_string_equal(qd_ctx_message(f->ctx), "impact 'floor': the gap is negative at t0 "
                                                "(-0.1): the bodies start interpenetrating");
    assert_int_equal(r.n, 0);
    sf_free(f);
}

/* E is checked where the parameters have their values, qd_sim_new: the
 * parser refuses 3/2 in the text, but qd_model_set_param may set it after. */
static void restitution_out_of_range(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, "coordinates y\nparameters e = 1/2\n"
                                      "T = y'^2/2\nV = 9.81*y\n"
                                      "impact floor: y >= 0 restitution e\n", &d);
    assert_non_null(m);
    assert_int_equal(qd_model_set_param(ctx, m, "e", qd_rat(ctx, 3, 2)), QD_OK);
    qd_eom *e = qd_eom_derive(ctx, m);
    assert_non_null(e);
    assert_null(qd_sim_new(ctx, m, e));
    assert_int_equal(qd_ctx_status(ctx), QD_ERR_ARG);
    assert_string_equal(qd_ctx_message(ctx),
                        "impact 'floor': the restitution 1.5 is outside [0, 1]");
    qd_eom_free(e);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* A model given by H has no mass matrix for the law: refused, not ignored. */
static void hamiltonian_model_refused(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, "coordinates x\nmomenta p\nH = p^2/2 + x^2/2\n"
                                      "impact wall: x + 1 >= 0 restitution 1\n", &d);
    assert_non_null(m);
    assert_null(qd_sim_new_hamilton(ctx, m));
    assert_int_equal(qd_ctx_status(ctx), QD_ERR_UNSUPPORTED);
    assert_non_null(strstr(qd_ctx_message(ctx), "impacts on a model given by H"));
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(ball_chatters),        cmocka_unit_test(ball_every_method),
        cmocka_unit_test(ball_elastic),         cmocka_unit_test(ball_plastic),
        cmocka_unit_test(pendulum_wall),        cmocka_unit_test(circle_stop),
        cmocka_unit_test(rhombus_wall),         cmocka_unit_test(rod_ledge),
        cmocka_unit_test(rod_flat_on_floor),
        cmocka_unit_test(gap_negative_at_start),
        cmocka_unit_test(restitution_out_of_range),
        cmocka_unit_test(hamiltonian_model_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
