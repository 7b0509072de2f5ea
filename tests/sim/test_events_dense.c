/*
 * tests/sim/test_events_dense.c - crossings that fit inside one step
 * (issue 33): a force-free particle grazing the unit disc, whose step grows
 * past the whole crossing, so that the event function has the same sign at
 * both ends of the step.
 *
 *   x(t) = -5 + t, y = b: the circle x^2 + y^2 = 1 is crossed at
 *   t = 5 -+ sqrt(1 - b^2); a smooth disc (restitution 1) reflects the
 *   velocity (1, 0) specularly about the normal n = (x_c, b) at the contact
 *   x_c = -sqrt(1 - b^2): v+ = v - 2 (v.n) n = (1 - 2 x_c^2, -2 x_c b).
 *
 * Every method: the adaptive ones with a tolerance, the fixed-step ones with
 * one step over the whole flight (their interpolant is the cubic Hermite,
 * exact for a straight line).  And an event function oscillating faster than
 * any sampling, sin(1e6 t), is reported in stats.events_unresolved.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "qdot/read.h"
#include "qdot/simsetup.h"
#include "sim_fixture.h"

static const qd_sim_method all[] = {QD_SIM_DOPRI5, QD_SIM_DOP853, QD_SIM_TAYLOR, QD_SIM_BDF,
                                    QD_SIM_GL2,    QD_SIM_GL4,    QD_SIM_GL6,    QD_SIM_VERLET,
                                    QD_SIM_YOSHIDA4};

static sim_fix *particle(double b, bool disc) {
    char text[512];
    snprintf(text, sizeof text,
             "coordinates x, y\nparameters m = 1\nparticle m at (x, y)\n%s"
             "initial x = -5, y = %.17g, x' = 1, y' = 0\n",
             disc ? "impact disc: sqrt(x^2 + y^2) - 1 >= 0 restitution 1\n" : "", b);
    sim_fix *f = sf_load(text);
    assert_non_null(f);
    return f;
}

static qd_status run_method(sim_fix *f, qd_sim_method m) {
    bool adaptive = qd_sim_method_adaptive(m);
    /* bdf's own error is about its tolerance: a looser one keeps it fast */
    double rtol = m == QD_SIM_BDF ? 1e-8 : 1e-10;
    return sf_run(f, m, 10, adaptive ? 0 : 10, adaptive ? rtol : 0, false);
}

static double tol_of(qd_sim_method m) { return m == QD_SIM_BDF ? 1e-6 : 1e-9; }

/* The impact happens and the final velocity is the specular reflection. */
static void check_disc(double b) {
    double xc = -sqrt(1 - b * b), vx = 1 - 2 * xc * xc, vy = -2 * xc * b;
    for (size_t i = 0; i < sizeof all / sizeof *all; i++) {
        qd_sim_method m = all[i];
        sim_fix *f = particle(b, true);
        assert_int_equal(qd_sim_nevents(f->s), 0); /* the contact is no added event */
        assert_int_equal(run_method(f, m), QD_OK);
        int cx = sf_col(f, m, "x'"), cy = sf_col(f, m, "y'");
        if (f->stats.impacts != 1 || !(fabs(f->last[cx] - vx) < tol_of(m)) ||
            !(fabs(f->last[cy] - vy) < tol_of(m)))
            fail_msg("%s, b = %g: %zu impacts, final velocity (%.17g, %.17g), want 1 and "
                     "(%.17g, %.17g)", qd_sim_method_name(m), b, f->stats.impacts, f->last[cx],
                     f->last[cy], vx, vy);
        /* the contact's time: t = 5 + x_c */
        assert_true(f->nev == 2 && fabs(f->ev_t[0] - (5 + xc)) < tol_of(m));
        /* the impact's two rows (before, after) sit at the contact point
         * (x_c, b) on the circle, the row after already carries the
         * reflected velocity, and restitution 1 keeps h = |v|^2 / 2 = 1/2
         * (a missed or doubled impact, or a wrong normal, breaks one) */
        int px = sf_col(f, m, "x"), py = sf_col(f, m, "y"), ce = sf_col(f, m, "energy");
        assert_true(px >= 0 && py >= 0 && ce >= 0);
        for (int j = 0; j < 2; j++)
            if (!(fabs(f->ev_row[j][px] - xc) < tol_of(m)) ||
                !(fabs(f->ev_row[j][py] - b) < tol_of(m)))
                fail_msg("%s, b = %g: impact row %d at (%.17g, %.17g), want (%.17g, %.17g)",
                         qd_sim_method_name(m), b, j, f->ev_row[j][px], f->ev_row[j][py], xc, b);
        assert_true(fabs(f->ev_row[1][cx] - vx) < tol_of(m) &&
                    fabs(f->ev_row[1][cy] - vy) < tol_of(m));
        if (!(fabs(f->ev_row[1][ce] - 0.5) < tol_of(m)) || !(fabs(f->last[ce] - 0.5) < tol_of(m)) ||
            !(fabs(f->stats.impact_energy_lost) < tol_of(m)))
            fail_msg("%s, b = %g: energy %.17g after the impact, %.17g at the end, lost %g; "
                     "want 0.5, 0.5, 0", qd_sim_method_name(m), b, f->ev_row[1][ce], f->last[ce],
                     f->stats.impact_energy_lost);
        sf_free(f);
    }
}

static void grazing_disc(void **state) {
    (void)state;
    check_disc(0.9);
}

static void near_tangent_disc(void **state) {
    (void)state;
    check_disc(0.999999);
}

/* --event "x^2 + y^2 = 1": two crossings at 5 -+ sqrt(1 - b^2). */
static void check_circle(double b) {
    double w = sqrt(1 - b * b);
    for (size_t i = 0; i < sizeof all / sizeof *all; i++) {
        qd_sim_method m = all[i];
        sim_fix *f = particle(b, false);
        const qd_expr *g = qd_read(f->ctx, "x^2 + y^2 - 1", NULL, NULL);
        assert_non_null(g);
        assert_int_equal(qd_sim_add_event(f->s, g, 0, NULL, false), QD_OK);
        assert_int_equal(qd_sim_nevents(f->s), 1);
        assert_int_equal(run_method(f, m), QD_OK);
        if (f->nev != 2 || f->stats.events != 2 || !(fabs(f->ev_t[0] - (5 - w)) < tol_of(m)) ||
            !(fabs(f->ev_t[1] - (5 + w)) < tol_of(m)))
            fail_msg("%s, b = %g: %zu events (%.17g, %.17g), want 2 at %.17g, %.17g",
                     qd_sim_method_name(m), b, f->nev, f->nev ? f->ev_t[0] : NAN,
                     f->nev > 1 ? f->ev_t[1] : NAN, 5 - w, 5 + w);
        assert_int_equal(f->stats.events_unresolved, 0);
        sf_free(f);
    }
}

static void circle_event(void **state) {
    (void)state;
    check_circle(0.9);
}

static void circle_event_near_tangent(void **state) {
    (void)state;
    check_circle(0.999999);
}

/* sin(t) = 0 over [0, 10] in steps that span several crossings: pi, 2 pi,
 * 3 pi, each once, and nothing reported unresolved. */
static void several_in_a_step(void **state) {
    (void)state;
    for (size_t i = 0; i < sizeof all / sizeof *all; i++) {
        qd_sim_method m = all[i];
        sim_fix *f = particle(0.5, false);
        const qd_expr *g = qd_read(f->ctx, "sin(t)", NULL, NULL);
        assert_int_equal(qd_sim_add_event(f->s, g, 0, NULL, false), QD_OK);
        assert_int_equal(run_method(f, m), QD_OK);
        if (f->nev != 3)
            fail_msg("%s: %zu crossings of sin(t) = 0, want 3", qd_sim_method_name(m), f->nev);
        for (size_t k = 0; k < 3; k++)
            assert_true(fabs(f->ev_t[k] - (double)(k + 1) * SF_PI) < 1e-9);
        assert_int_equal(f->stats.events_unresolved, 0);
        sf_free(f);
    }
}

/* sin(1e6 t): no sampling of a step resolves it; the run says so. */
static void too_fast_is_reported(void **state) {
    (void)state;
    for (size_t i = 0; i < sizeof all / sizeof *all; i++) {
        qd_sim_method m = all[i];
        sim_fix *f = particle(0.5, false);
        const qd_expr *g = qd_read(f->ctx, "sin(1000000*t)", NULL, NULL);
        assert_int_equal(qd_sim_add_event(f->s, g, 0, NULL, false), QD_OK);
        assert_int_equal(run_method(f, m), QD_OK);
        if (!(f->stats.events_unresolved > 0 && f->stats.events_unresolved_spacing > 1e-3 &&
              f->stats.events_unresolved_event == 0))
            fail_msg("%s: unresolved %zu, spacing %g", qd_sim_method_name(m),
                     f->stats.events_unresolved, f->stats.events_unresolved_spacing);
        sf_free(f);
    }
}

/* ---- events that read q'' or a multiplier --------------------------------
 *
 * The samples evaluate the event functions alone (qd__sim_ev_eval), which
 * must solve for the accelerations and multipliers first when an event
 * reads them (a guard alone does not make the event program need them). */

typedef struct ev_rows {
    size_t n, ncols;
    double rows[8][8];
} ev_rows;

static int keep_events(void *data, int event, const double *row) {
    ev_rows *k = data;
    if (event >= 0 && k->n < 8)
        memcpy(k->rows[k->n], row, k->ncols * sizeof *row);
    k->n += event >= 0;
    return 0;
}

/* model with event text run by method m to t_end (fixed step dt for the
 * fixed-step methods, rtol 1e-10 else): the event rows in *k; column
 * indices of names[] into col[]. */
static void run_setup_event(const char *model, const char *event, qd_sim_method m,
                            const char *t_end, ev_rows *k, const char *const *names, int *col,
                            size_t nnames) {
    qd_ctx *ctx = qd_ctx_new();
    qd_model *md = qd_model_parse(ctx, model, NULL);
    assert_non_null(md);
    qd_sim_setup *u = qd_sim_setup_new(ctx, md, false);
    assert_non_null(u);
    assert_int_equal(qd_sim_setup_event(u, event, false), QD_OK);
    bool adaptive = qd_sim_method_adaptive(m);
    qd_sim_setup_opts so = {.t_end = t_end, .method = qd_sim_method_name(m),
                            .rtol = adaptive ? (m == QD_SIM_BDF ? "1e-8" : "1e-10") : NULL,
                            .dt = adaptive ? NULL : "0.005"};
    qd_sim_opts o;
    assert_int_equal(qd_sim_setup_options(u, &so, &o), QD_OK);
    qd_sim *s = qd_sim_setup_sim(u);
    const char *cn[16];
    k->n = 0;
    k->ncols = qd_sim_columns(s, m, cn, 16);
    assert_true(k->ncols <= 8);
    for (size_t i = 0; i < nnames; i++) {
        col[i] = -1;
        for (size_t j = 0; j < k->ncols; j++)
            if (!strcmp(cn[j], names[i]))
                col[i] = (int)j;
        assert_true(col[i] >= 0);
    }
    qd_sim_stats st;
    assert_int_equal(qd_sim_run(s, &o, keep_events, k, &st, NULL), QD_OK);
    qd_sim_setup_free(u);
    qd_model_free(md);
    qd_ctx_free(ctx);
}

static const qd_sim_method some[] = {QD_SIM_DOPRI5, QD_SIM_DOP853, QD_SIM_TAYLOR, QD_SIM_BDF,
                                     QD_SIM_GL4};

/* x'' = -(k/m) x = -4 cos 2t vanishes where x does: t = pi/4 + j pi/2, and
 * x = 0 there (three times before t = 5). */
static void event_reads_accelerations(void **state) {
    (void)state;
    static const char osc[] = "coordinates x\nparameters m = 1, k = 4\nT = m/2*x'^2\n"
                              "V = k/2*x^2\ninitial x = 1, x' = 0\n";
    static const char *const names[] = {"x"};
    for (size_t i = 0; i < sizeof some / sizeof *some; i++) {
        qd_sim_method m = some[i];
        ev_rows k;
        int col[1];
        run_setup_event(osc, "x'' = 0", m, "5", &k, names, col, 1);
        double tol = m == QD_SIM_BDF ? 1e-6 : 1e-8;
        if (k.n != 3)
            fail_msg("%s: %zu zeros of x'', want 3", qd_sim_method_name(m), k.n);
        for (size_t j = 0; j < 3; j++)
            if (!(fabs(k.rows[j][0] - (SF_PI / 4 + (double)j * SF_PI / 2)) < tol) ||
                !(fabs(k.rows[j][col[0]]) < tol))
                fail_msg("%s: zero %zu of x'' at t = %.17g, x = %g", qd_sim_method_name(m), j,
                         k.rows[j][0], k.rows[j][col[0]]);
    }
}

/* A pendulum on a rod (m = l = g = 1) started at the bottom with speed
 * sqrt(3 g l): its tension m (v^2/l - g y/l) = (m/l)(v0^2 - 3 g (l + y))
 * vanishes at y = l/3, v^2 = g l/3, on the way up and on the way down
 * (it turns at y = l/2): the multiplier lambda_rod changes sign there. */
static void event_reads_multiplier(void **state) {
    (void)state;
    static const char rod[] = "coordinates x, y\nparameters m = 1, l = 1, g = 1\n"
                              "particle m at (x, y)\nV = m*g*y\n"
                              "constraint rod: x^2 + y^2 = l^2\n"
                              "initial x = 0, y = -1, x' = 1.7320508075688772, y' = 0\n";
    static const char *const names[] = {"y", "x'", "y'"};
    for (size_t i = 0; i < sizeof some / sizeof *some; i++) {
        qd_sim_method m = some[i];
        ev_rows k;
        int col[3];
        run_setup_event(rod, "lambda_rod = 0", m, "3", &k, names, col, 3);
        double tol = m == QD_SIM_BDF ? 1e-6 : 1e-8;
        if (k.n != 2)
            fail_msg("%s: %zu zeros of the tension, want 2", qd_sim_method_name(m), k.n);
        for (size_t j = 0; j < 2; j++) {
            const double *r = k.rows[j];
            double v2 = r[col[1]] * r[col[1]] + r[col[2]] * r[col[2]];
            if (!(fabs(r[col[0]] - 1.0 / 3) < tol) || !(fabs(v2 - 1.0 / 3) < tol))
                fail_msg("%s: tension 0 at t = %.17g with y = %.17g, v^2 = %.17g, want 1/3, 1/3",
                         qd_sim_method_name(m), r[0], r[col[0]], v2);
        }
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(grazing_disc),
        cmocka_unit_test(near_tangent_disc),
        cmocka_unit_test(circle_event),
        cmocka_unit_test(circle_event_near_tangent),
        cmocka_unit_test(several_in_a_step),
        cmocka_unit_test(too_fast_is_reported),
        cmocka_unit_test(event_reads_accelerations),
        cmocka_unit_test(event_reads_multiplier),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
