/*
 * tests/sim/test_friction.c - Coulomb friction in qd_sim (issue 18),
 * checked against closed forms:
 *
 *   - a sphere set sliding on a rough horizontal plane with speed v0 and no
 *     spin begins to roll at t* = 2 v0/(7 mu g) with speed 5 v0/7, having
 *     slid 12 v0^2/(49 mu g) (Byerly art. 10b; reference seed-byerly TC21,
 *     "Extensions"); a solid cylinder (k^2 = a^2/2) at v0/(3 mu g) with
 *     2 v0/3.  Written as `constraint ... friction` with N an expression,
 *     with N a floor constraint's multiplier, and as `rolls ... friction`;
 *   - the billiard ball in 3-D (TC21): the slip velocity keeps its
 *     direction and its size falls as S0 - (7/2) mu g t, the centre's
 *     velocity changes by mu g t* against S0;
 *   - a sphere set down on an incline rolls iff tan al <= 7 mu/2, else
 *     slides from rest in 2-D;
 *   - a block on an incline of angle al: at rest it sticks when tan al <
 *     mu_s and slides with a = g (sin al - mu_k cos al) when not; pushed up
 *     the slope with mu_k < tan al < mu_s it stops after v0 / (g (sin al +
 *     mu_k cos al)) and stays (static friction holds);
 *   - the stick-slip oscillator on a belt: the switches of its limit
 *     cycle (Den Hartog sec. 8.2);
 *   - two contacts, a block sliding on a block on the floor: the mode
 *     choice when the relative slip stops (stick together, or the top
 *     block slides on ahead: slip -> slip the other way);
 *   - a point on a rough surface (`friction MU on P against CONSTRAINT`):
 *     an incline in a plane (the constraint's gradient not of size 1) and
 *     in space, a spherical bowl where it comes to rest within the
 *     friction cone;
 *   - Painleve's rod (a rod whose end slides on a rough floor, mu = 2 >
 *     4/3, at 1 rad, sliding backwards): no consistent mode; sliding
 *     forwards, two (the floor's multiplier of either sign);
 *   - more than 12 contacts refused;
 *   - runs sharing one compiled system from 4 threads agree bit for bit;
 *   - in every run the energy balance E(t) + dissipated(t) = E(0) to
 *     1e-8, and the dissipated energy against the kinetic energy lost;
 *     on the belt, a moving surface, E + dissipated - surface_work = E(0)
 *     over eight limit cycles, the belt's power k x v while the block
 *     sticks and mu_k m g v while it slips, and a cycle's work in closed
 *     form; a block sliding in a rising lift (a rheonomic holonomic floor
 *     as the normal constraint) gains m g c t from it; on the fixed floor
 *     surface_work is exactly 0 and no column;
 *   - the errors: friction on a holonomic constraint, a negative
 *     coefficient (line and column), an unknown normal constraint, a
 *     symplectic method.
 *
 * Between switches the motions are polynomials in t (uniform
 * deceleration), which the Runge-Kutta methods integrate exactly, and the
 * switches are located to round-off: the tolerances are a few 1e-12.
 */
#include <pthread.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "sim_fixture.h"

#define G 9.81

static double rel(double a, double b) { return fabs(a - b) / fmax(fabs(b), 1e-300); }

static void near(double got, double want, double tol, const char *what) {
    if (!(rel(got, want) <= tol))
        fail_msg("%s: %.17g vs %.17g (relative %.3g > %.3g)", what, got, want, rel(got, want),
                 tol);
}

static sim_fix *load(const char *fmt, ...) {
    char text[2048];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    sim_fix *f = sf_load(text);
    assert_non_null(f);
    return f;
}

static double col(const sim_fix *f, const double *row, const char *name) {
    int c = sf_col(f, QD_SIM_DOP853, name);
    if (c < 0)
        fail_msg("no column %s", name);
    return row[c];
}

/* The one switch of a run: slip -> stick of contact 0 at t, checked. */
static void one_switch(const sim_fix *f, double t) {
    size_t n;
    const qd_sim_transition *tr = qd_sim_transitions(f->s, &n);
    assert_int_equal(n, 1);
    assert_int_equal(f->stats.transitions, 1);
    assert_int_equal(tr[0].contact, 0);
    assert_int_equal(tr[0].from, QD_CONTACT_SLIP);
    assert_int_equal(tr[0].to, QD_CONTACT_STICK);
    near(tr[0].t, t, 1e-12, "switch time");
}

/* A round body (k2 = I / (m a^2)) sliding with v0, no spin: slides at
 * deceleration mu g while its spin grows, rolls from t* = v0 / ((1 + 1/k2)
 * mu g) with speed v0 / (1 + k2) (k2 = 2/5: 2 v0/(7 mu g), 5 v0/7). */
static void check_rolling_start(sim_fix *f, double v0, double mu, double k2) {
    double ts = v0 / ((1 + 1 / k2) * mu * G), v1 = v0 / (1 + k2);
    f->max_events = 0;
    assert_int_equal(sf_run(f, QD_SIM_DOP853, 2 * ts, 0, 1e-11, false), QD_OK);
    one_switch(f, ts);
    /* the row at the switch, after it: rolling, the speed v1 */
    assert_true(f->nev >= 1);
    const double *row = f->ev_row[0];
    near(row[0], ts, 1e-12, "event row time");
    near(col(f, row, "x'"), v1, 1e-12, "speed when rolling starts");
    near(col(f, row, "x"), v0 * ts - 0.5 * mu * G * ts * ts, 1e-12, "distance at t*");
    near(col(f, f->last, "x'"), v1, 1e-12, "speed rolling on");
    assert_true(col(f, f->last, "dissipated") > 0);
    /* the kinetic energy lost, m v0^2/2 (1 - 1/(1 + k2)), all to friction */
    double m = 2;
    near(f->stats.friction_dissipated, 0.5 * m * v0 * v0 * (1 - 1 / (1 + k2)), 1e-12,
         "dissipated");
    assert_true(f->stats.energy_balance_error < 1e-8);
    /* the floor is at rest (a0 = 0): it does no work, and the columns stay */
    assert_true(f->stats.surface_work == 0.0);
    assert_true(sf_col(f, QD_SIM_DOP853, "surface_work") < 0);
}

static const char *const round_body =
    "coordinates x, phi\n"
    "parameters m = 2, a = 0.3, g = 9.81, mu = %g, k2 = %g\n"
    "T = m/2*x'^2 + k2*m*a^2/2*phi'^2\n"
    "constraint slip: x' - a*phi' = 0 friction mu normal m*g\n"
    "initial x' = %g\n";

static void sphere_constraint(void **state) {
    (void)state;
    sim_fix *f = load(round_body, 0.25, 0.4, 3.0);
    check_rolling_start(f, 3, 0.25, 0.4);
    /* the centre slid 12 v0^2/(49 mu g) before rolling */
    near(col(f, f->ev_row[0], "x"), 12 * 9.0 / (49 * 0.25 * G), 1e-12, "distance slid");
    sf_free(f);
}

static void cylinder_constraint(void **state) {
    (void)state;
    sim_fix *f = load(round_body, 0.1, 0.5, 2.0);
    check_rolling_start(f, 2, 0.1, 0.5);
    near(f->ev_t[0], 2.0 / (3 * 0.1 * G), 1e-12, "t = v0/(3 mu g)");
    sf_free(f);
}

/* N the multiplier of the floor constraint: m g (the sphere does not
 * leave the floor), so the same motion. */
static void sphere_normal_constraint(void **state) {
    (void)state;
    sim_fix *f = load("coordinates x, y, phi\n"
                      "parameters m = 2, a = 0.3, g = 9.81, mu = 0.25\n"
                      "T = m/2*(x'^2 + y'^2) + 2/5*m*a^2/2*phi'^2\n"
                      "V = m*g*y\n"
                      "constraint slip: x' - a*phi' = 0 friction mu normal floor\n"
                      "constraint floor: y = a\n"
                      "initial y = 0.3, x' = 3\n");
    check_rolling_start(f, 3, 0.25, 0.4);
    sf_free(f);
}

static void sphere_rolls(void **state) {
    (void)state;
    sim_fix *f = load("coordinates x, th\n"
                      "parameters m = 2, a = 0.3, g = 9.81, mu = 0.25\n"
                      "body ball mass m inertia sphere(m, a) at (x, 0, a) orientation "
                      "rot_y(th)\n"
                      "rolls ball on plane((0, 0, 1), (0, 0, 0)) as sphere(a) friction mu "
                      "normal m*g\n"
                      "initial x' = 3\n");
    assert_int_equal(qd_model_ncontacts(f->m), 1);
    assert_int_equal(qd_model_contact_kind(f->m, 0), QD_CONTACT_ROLLING);
    assert_string_equal(qd_model_contact_name(f->m, 0), "ball");
    check_rolling_start(f, 3, 0.25, 0.4);
    sf_free(f);
}

/* Rows of the billiard-ball run: the first, the one at the output grid
 * point half-way to the switch, and the switch's. */
typedef struct ball_rows {
    size_t ncols;
    double first[32], mid[32], sw[32], tmid;
    bool got_first, got_mid, got_sw;
} ball_rows;

static int ball_sink(void *data, int event, const double *row) {
    ball_rows *b = data;
    double *dst = !b->got_first ? b->first
                  : event >= 0 && !b->got_sw ? b->sw
                  : event < 0 && fabs(row[0] - b->tmid) < 1e-12 && !b->got_mid ? b->mid
                                                                               : NULL;
    if (dst) {
        memcpy(dst, row, b->ncols * sizeof *row);
        b->got_sw = b->got_sw || dst == b->sw;
        b->got_mid = b->got_mid || dst == b->mid;
        b->got_first = true;
    }
    return 0;
}

/* TC21: the ball with a slip S0 not along its velocity (spin theta');
 * both tangential directions are one contact.  S keeps its direction and
 * falls as S0 - (7/2) mu g t; the centre's velocity changes by mu g t
 * against S0, so rolling starts at t* = 2 |S0|/(7 mu g). */
static void billiard_ball(void **state) {
    (void)state;
    double mu = 0.3;
    sim_fix *f = load("coordinates x, y, phi, theta, psi\n"
                      "parameters m = 1, a = 0.2, g = 9.81, mu = %g\n"
                      "body ball mass m inertia sphere(m, a) at (x, y, a) orientation "
                      "euler(phi, theta, psi)\n"
                      "rolls ball on plane((0, 0, 1), (0, 0, 0)) as sphere(a) friction mu "
                      "normal m*g\n"
                      "initial theta = 1.2, x' = 2, y' = 0.5, theta' = 4, phi' = 3\n", mu);
    size_t con[2];
    assert_int_equal(qd_model_contact_constraints(f->m, 0, con), 2);
    ball_rows b = {.ncols = qd_sim_columns(f->s, QD_SIM_DOP853, NULL, 0)};
    assert_true(b.ncols <= 32);
    /* the initial slip: a run of one output row */
    qd_sim_opts o = {.method = QD_SIM_DOP853, .t0 = 0, .t_end = 1, .rtol = 1e-11,
                     .atol = 1e-13, .q0 = f->q0, .qd0 = f->qd0};
    b.tmid = -1;
    assert_int_equal(qd_sim_run(f->s, &o, ball_sink, &b, &f->stats, NULL), QD_OK);
    double S1 = col(f, b.first, "res_ball_roll1"), S2 = col(f, b.first, "res_ball_roll2");
    double S0 = hypot(S1, S2), ts = 2 * S0 / (7 * mu * G);
    assert_true(fabs(S1 * col(f, b.first, "y'") - S2 * col(f, b.first, "x'")) > 0.1);
    size_t n;
    const qd_sim_transition *tr = qd_sim_transitions(f->s, &n);
    assert_int_equal(n, 1);
    near(tr[0].t, ts, 1e-9, "t* = 2 |S0| / (7 mu g)");
    /* again with a row half-way: the slip there is S0/2, same direction */
    b = (ball_rows){.ncols = b.ncols, .tmid = ts / 2};
    o.dt = ts / 2;
    assert_int_equal(qd_sim_run(f->s, &o, ball_sink, &b, &f->stats, NULL), QD_OK);
    assert_true(b.got_mid && b.got_sw);
    near(col(f, b.mid, "res_ball_roll1"), S1 / 2, 1e-9, "slip 1 half-way");
    near(col(f, b.mid, "res_ball_roll2"), S2 / 2, 1e-9, "slip 2 half-way");
    /* (the 3-D trigonometry carries the integration error: 1e-8) */
    near(col(f, b.sw, "x'"), col(f, b.first, "x'") - mu * G * ts * S1 / S0, 1e-8, "x' at t*");
    near(col(f, b.sw, "y'"), col(f, b.first, "y'") - mu * G * ts * S2 / S0, 1e-8, "y' at t*");
    /* v . v_entry = 0 there: what is left is across, the drift of the
     * direction in the integration (1e-9 of S0) */
    if (!(col(f, b.sw, "slip_ball") < 1e-8 * S0))
        fail_msg("slip at the switch %g (t %g)", col(f, b.sw, "slip_ball"), b.sw[0]);
    assert_true(f->stats.energy_balance_error < 1e-8);
    sf_free(f);
}

/* A sphere set down at rest on an incline (gravity tilted by al, the
 * plane horizontal), both slip directions one contact: it rolls, x =
 * (5/7) g sin(al) t^2/2, iff tan al <= 7 mu/2; else it slides from rest
 * (the 2-D slip direction against the force it would need to roll),
 * x = g (sin al - mu cos al) t^2/2 (Byerly art. 9, exercise; reference
 * seed-byerly TC21). */
static void sphere_incline_3d(void **state) {
    (void)state;
    const double al = 0.5, mus[2] = {0.2, 0.1};
    for (int k = 0; k < 2; k++) {
        double mu = mus[k];
        sim_fix *f = load("coordinates x, y, phi, theta, psi\n"
                          "parameters m = 1, a = 0.2, g = 9.81, mu = %g, al = %g\n"
                          "body ball mass m inertia sphere(m, a) at (x, y, a) orientation "
                          "euler(phi, theta, psi)\n"
                          "rolls ball on plane((0, 0, 1), (0, 0, 0)) as sphere(a) friction "
                          "mu normal m*g*cos(al)\n"
                          "V = -m*g*sin(al)*x\n"
                          "initial theta = 1.2\n", mu, al);
        assert_int_equal(sf_run(f, QD_SIM_DOP853, 1, 0, 1e-11, false), QD_OK);
        bool rolls = tan(al) <= 3.5 * mu;
        double acc = rolls ? 5.0 / 7 * G * sin(al) : G * (sin(al) - mu * cos(al));
        near(col(f, f->last, "x"), acc / 2, 1e-9, rolls ? "rolling" : "sliding");
        assert_true(fabs(col(f, f->last, "y")) < 1e-9);
        assert_true(col(f, f->last, "mode_ball") == (rolls ? 0 : 1));
        assert_int_equal(f->stats.transitions, 0);
        assert_true(f->stats.energy_balance_error < 1e-8);
        sf_free(f);
    }
}

static const char *const block =
    "coordinates x\n"
    "parameters m = 3, g = 9.81, al = %.17g\n"
    "T = m/2*x'^2\n"
    "V = -m*g*sin(al)*x\n"
    "constraint grip: x' = 0 friction static %g kinetic %g normal m*g*cos(al)\n"
    "initial x' = %g\n";

static void block_sticks(void **state) {
    (void)state;
    double al = atan(0.45); /* tan al = 0.45 < mu_s = 0.5 */
    sim_fix *f = load(block, al, 0.5, 0.3, 0.0);
    assert_int_equal(sf_run(f, QD_SIM_DOP853, 2, 0, 1e-11, false), QD_OK);
    assert_int_equal(f->stats.transitions, 0);
    assert_true(fabs(col(f, f->last, "x")) < 1e-14);
    assert_true(col(f, f->last, "mode_grip") == 0);
    assert_true(col(f, f->last, "dissipated") == 0);
    sf_free(f);
}

static void block_slides(void **state) {
    (void)state;
    double al = atan(0.55), muk = 0.3, t = 1.5; /* tan al > mu_s = 0.5 */
    sim_fix *f = load(block, al, 0.5, muk, 0.0);
    assert_int_equal(sf_run(f, QD_SIM_DOP853, t, 0, 1e-11, false), QD_OK);
    double acc = G * (sin(al) - muk * cos(al));
    near(col(f, f->last, "x"), 0.5 * acc * t * t, 1e-12, "x = a t^2/2");
    near(col(f, f->last, "x'"), acc * t, 1e-12, "x' = a t");
    assert_true(col(f, f->last, "mode_grip") == 1);
    /* the work of friction, mu_k m g cos(al) x */
    near(f->stats.friction_dissipated, muk * 3 * G * cos(al) * 0.5 * acc * t * t, 1e-12,
         "dissipated");
    assert_true(f->stats.energy_balance_error < 1e-8);
    sf_free(f);
}

/* Pushed up the slope (x' = -v0 < 0) with mu_k < tan al < mu_s: decelerates
 * at g (sin al + mu_k cos al), stops, and static friction holds it. */
static void block_stops_and_sticks(void **state) {
    (void)state;
    double al = atan(0.4), muk = 0.3, v0 = 2;
    sim_fix *f = load(block, al, 0.5, muk, -v0);
    assert_int_equal(sf_run(f, QD_SIM_DOP853, 2, 0, 1e-11, false), QD_OK);
    double dec = G * (sin(al) + muk * cos(al)), ts = v0 / dec;
    one_switch(f, ts);
    near(col(f, f->last, "x"), -v0 * v0 / (2 * dec), 1e-12, "where it stops");
    assert_true(col(f, f->last, "x'") == 0);
    assert_true(f->stats.energy_balance_error < 1e-8);
    sf_free(f);
}

/* Same start with tan al > mu_s: it stops, then slides back down at
 * g (sin al - mu_k cos al); the switch at rest is slip -> slip, so no
 * transition is recorded but the direction turns. */
static void block_turns_back(void **state) {
    (void)state;
    double al = atan(0.6), muk = 0.3, v0 = 2, t = 1;
    sim_fix *f = load(block, al, 0.5, muk, -v0);
    assert_int_equal(sf_run(f, QD_SIM_DOP853, t, 0, 1e-11, false), QD_OK);
    double up = G * (sin(al) + muk * cos(al)), down = G * (sin(al) - muk * cos(al));
    double ts = v0 / up;
    assert_int_equal(f->stats.transitions, 0);
    near(col(f, f->last, "x'"), down * (t - ts), 1e-11, "sliding back");
    assert_true(f->stats.energy_balance_error < 1e-8);
    sf_free(f);
}

/* The stick-slip oscillator: a mass on a spring (k) dragged by a belt of
 * speed v (the constraint x' = v, a0 = -v: the belt's work is checked in
 * belt_energy_balance).  It sticks until k x = mu_s m g
 * (x_s), slips about x_k = mu_k m g/k with frequency w = sqrt(k/m) until
 * x' = v again at 2 x_k - x_s, where static friction holds it: the limit
 * cycle's slip lasts (pi + 2 atan2(v/w, x_s - x_k))/w, its stick
 * 2 (x_s - x_k)/v (Den Hartog, Mechanical Vibrations, sec. 8.2). */
static void belt_limit_cycle(void **state) {
    (void)state;
    double m = 1, k = 4, v = 0.5, mus = 0.4, muk = 0.25, w = 2;
    sim_fix *f = load("coordinates x\n"
                      "parameters m = 1, k = 4, g = 9.81, v = 0.5\n"
                      "T = m/2*x'^2\n"
                      "V = k/2*x^2\n"
                      "constraint belt: x' = v friction static 0.4 kinetic 0.25 normal m*g\n"
                      "initial x' = 0.5\n");
    assert_int_equal(sf_run(f, QD_SIM_DOP853, 12, 0, 1e-12, false), QD_OK);
    double xs = mus * m * G / k, xk = muk * m * G / k;
    double slip = (SF_PI + 2 * atan2(v / w, xs - xk)) / w, stick = 2 * (xs - xk) / v;
    size_t n;
    const qd_sim_transition *tr = qd_sim_transitions(f->s, &n);
    assert_int_equal(n, 6);
    double t = xs / v;
    for (size_t i = 0; i < n; i++) {
        assert_int_equal(tr[i].from, i % 2 ? QD_CONTACT_SLIP : QD_CONTACT_STICK);
        near(tr[i].t, t, 1e-10, "switch of the limit cycle");
        t += i % 2 ? stick : slip;
    }
    sf_free(f);
}

/* The belt's run on an output grid: every row's t, x, mode, E,
 * dissipated, surface_work. */
#define BELT_ROWS 4096
typedef struct belt_rows {
    int cx, cmode, cE, cdis, cwork;
    size_t n;
    double r[BELT_ROWS][6];
} belt_rows;

static int belt_sink(void *data, int event, const double *row) {
    belt_rows *b = data;
    (void)event;
    if (b->n < BELT_ROWS) {
        double *o = b->r[b->n++];
        o[0] = row[0], o[1] = row[b->cx], o[2] = row[b->cmode];
        o[3] = row[b->cE], o[4] = row[b->cdis], o[5] = row[b->cwork];
    }
    return 0;
}

/* The belt works on the block: while it sticks through the force holding
 * the spring, lambda = k x, at the belt's speed (power k x v: the spring's
 * force -k x is what the belt holds, so the work on the block is +k x v),
 * while it slips through the kinetic force mu_k m g (the block slower than
 * the belt), power mu_k m g v beyond the dissipated mu_k m g |x' - v|.  So
 * E + dissipated - surface_work = E0 (docs/design.md, "the energy balance
 * on a moving surface"); over a limit cycle the belt puts in
 * k ((x_k + D)^2 - (x_k - D)^2)/2 + mu_k m g v T_slip, D = x_s - x_k,
 * which friction takes out again (E returns).  Before the work was
 * integrated the balance reported here was 37.6 on examples/
 * friction_stick_slip.qd. */
static void belt_energy_balance(void **state) {
    (void)state;
    double m = 1, k = 4, v = 0.5, mus = 0.4, muk = 0.25, w = 2;
    sim_fix *f = load("coordinates x\n"
                      "parameters m = 1, k = 4, g = 9.81, v = 0.5\n"
                      "T = m/2*x'^2\n"
                      "V = k/2*x^2\n"
                      "constraint belt: x' = v friction static 0.4 kinetic 0.25 normal m*g\n"
                      "initial x' = 0.5\n");
    static belt_rows b;
    b.n = 0;
    b.cx = sf_col(f, QD_SIM_DOP853, "x");
    b.cmode = sf_col(f, QD_SIM_DOP853, "mode_belt");
    b.cE = sf_col(f, QD_SIM_DOP853, "energy");
    b.cdis = sf_col(f, QD_SIM_DOP853, "dissipated");
    b.cwork = sf_col(f, QD_SIM_DOP853, "surface_work");
    assert_true(b.cwork > b.cdis && b.cdis > 0);
    qd_sim_opts o = {.method = QD_SIM_DOP853, .t0 = 0, .t_end = 30, .dt = 0.01,
                     .rtol = 1e-12, .atol = 1e-14, .q0 = f->q0, .qd0 = f->qd0};
    assert_int_equal(qd_sim_run(f->s, &o, belt_sink, &b, &f->stats, f->last), QD_OK);
    double xs = mus * m * G / k, xk = muk * m * G / k, D = xs - xk;
    double slip = (SF_PI + 2 * atan2(v / w, D)) / w, stick = 2 * D / v;
    size_t ntr;
    const qd_sim_transition *tr = qd_sim_transitions(f->s, &ntr);
    assert_true(ntr >= 16); /* eight cycles and more */
    assert_true(f->stats.energy_balance_error < 1e-8);
    /* on every row, relative to the largest energy of the run */
    double E0 = f->stats.E0, scale = E0, worst = 0;
    for (size_t i = 0; i < b.n; i++)
        scale = fmax(scale, fabs(b.r[i][3]));
    for (size_t i = 0; i < b.n; i++)
        worst = fmax(worst, fabs(b.r[i][3] + b.r[i][4] - b.r[i][5] - E0) / scale);
    assert_true(worst < 1e-8);
    /* the belt's power between grid rows of one mode: x is linear in t while
     * it sticks, so the trapezoid of k x v is the integral exactly */
    size_t nstick = 0, nslip = 0;
    for (size_t i = 1; i < b.n; i++) {
        const double *a = b.r[i - 1], *c = b.r[i];
        double dt = c[0] - a[0], dW = c[5] - a[5];
        if (dt < 1e-3 || a[2] != c[2])
            continue; /* a switch inside the interval, or an event row */
        double P = c[2] ? muk * m * G * v : k * v * (a[1] + c[1]) / 2;
        near(dW / dt, P, 1e-8, c[2] ? "belt power while slipping" : "k x v while sticking");
        nstick += c[2] ? 0 : 1;
        nslip += c[2] ? 1 : 0;
    }
    assert_true(nstick > 100 && nslip > 100);
    /* a whole cycle, slip -> stick to slip -> stick: the work in closed form */
    double W1 = NAN, W3 = NAN;
    for (size_t i = 0; i < b.n; i++) {
        if (b.r[i][0] == tr[1].t)
            W1 = b.r[i][5];
        if (b.r[i][0] == tr[3].t)
            W3 = b.r[i][5];
    }
    near(tr[3].t - tr[1].t, stick + slip, 1e-10, "the limit cycle's period");
    near(W3 - W1, k * ((xk + D) * (xk + D) - (xk - D) * (xk - D)) / 2 + muk * m * G * v * slip,
         1e-9, "the belt's work over a cycle");
    near(col(f, f->last, "surface_work"), f->stats.surface_work, 1e-15, "stats = last row");
    sf_free(f);
}

/* A rheonomic holonomic constraint: a block sliding on the floor of a lift
 * that rises at c (floor: y = c t, a0 = dphi/dt = -c), the friction's normal
 * force the floor's multiplier, m g (no acceleration).  The floor lifts the
 * block, power -lambda a0 = m g c whether it slides or sticks, so
 * surface_work = m g c t (the potential energy gained), while friction takes
 * m v0^2/2 until it stops at v0/(mu g).  The friction row has no a0: the
 * work comes through the normal constraint alone. */
static void lift_floor_work(void **state) {
    (void)state;
    double m = 2, c = 0.7, mu = 0.3, v0 = 1.5, t = 1;
    sim_fix *f = load("coordinates x, y\n"
                      "parameters m = 2, g = 9.81, c = 0.7, mu = 0.3\n"
                      "particle m at (x, y, 0)\n"
                      "V = m*g*y\n"
                      "constraint floor: y = c*t\n"
                      "constraint slip: x' = 0 friction mu normal floor\n"
                      "initial x' = 1.5, y' = 0.7\n");
    assert_int_equal(sf_run(f, QD_SIM_DOP853, t, 0, 1e-12, false), QD_OK);
    one_switch(f, v0 / (mu * G));
    near(f->stats.friction_dissipated, m * v0 * v0 / 2, 1e-12, "the kinetic energy slid away");
    near(f->stats.surface_work, m * G * c * t, 1e-12, "m g c t");
    near(col(f, f->ev_row[0], "surface_work"), m * G * c * f->ev_t[0], 1e-12, "at the stop");
    assert_true(f->stats.energy_balance_error < 1e-8);
    sf_free(f);
}

/* Two contacts: block B (m) on block A (M) on the floor; A set moving at
 * v0, B at rest.  Both slip: B speeds up at mu2 g, A slows at
 * a = (mu2 m + mu1 (M + m)) g / M, until their speeds meet at
 * t1 = v0 / (mu2 g + a).  With mu1 <= mu2 they then move as one (B needs
 * the force m mu1 g <= m mu2 g) and stop at t1 + v1/(mu1 g); with mu1 >
 * mu2 B cannot follow A's deceleration and slides on ahead of it (a
 * slip -> slip reversal, no transition): A stops at t1 + v1 / a', a' =
 * (mu1 (M + m) - mu2 m) g / M, and stays (the floor holds it), B at
 * t1 + v1 / (mu2 g). */
static const char *const stacked =
    "coordinates xa, xb\n"
    "parameters M = 2, m = 1, g = 9.81, mu1 = %g, mu2 = %g\n"
    "T = M/2*xa'^2 + m/2*xb'^2\n"
    "constraint floor: xa' = 0 friction mu1 normal (M + m)*g\n"
    "constraint top: xb' - xa' = 0 friction mu2 normal m*g\n"
    "initial xa' = 3\n";

static void stacked_together(void **state) {
    (void)state;
    double M = 2, m = 1, mu1 = 0.1, mu2 = 0.3, v0 = 3;
    sim_fix *f = load(stacked, mu1, mu2);
    assert_int_equal(sf_run(f, QD_SIM_DOP853, 5, 0, 1e-11, false), QD_OK);
    double a = (mu2 * m + mu1 * (M + m)) * G / M, t1 = v0 / (mu2 * G + a), v1 = mu2 * G * t1;
    size_t n;
    const qd_sim_transition *tr = qd_sim_transitions(f->s, &n);
    assert_int_equal(n, 2);
    assert_int_equal(tr[0].contact, 1);
    near(tr[0].t, t1, 1e-12, "B sticks on A");
    assert_int_equal(tr[1].contact, 0);
    near(tr[1].t, t1 + v1 / (mu1 * G), 1e-12, "A stops");
    near(f->stats.friction_dissipated, M * v0 * v0 / 2, 1e-12, "all the energy");
    assert_true(f->stats.energy_balance_error < 1e-8);
    sf_free(f);
}

static void stacked_overtakes(void **state) {
    (void)state;
    double M = 2, m = 1, mu1 = 0.5, mu2 = 0.2, v0 = 3;
    sim_fix *f = load(stacked, mu1, mu2);
    assert_int_equal(sf_run(f, QD_SIM_DOP853, 5, 0, 1e-11, false), QD_OK);
    double a = (mu2 * m + mu1 * (M + m)) * G / M, t1 = v0 / (mu2 * G + a), v1 = mu2 * G * t1;
    double a2 = (mu1 * (M + m) - mu2 * m) * G / M;
    size_t n;
    const qd_sim_transition *tr = qd_sim_transitions(f->s, &n);
    assert_int_equal(n, 2);
    assert_int_equal(tr[0].contact, 0);
    near(tr[0].t, t1 + v1 / a2, 1e-12, "A stops");
    assert_int_equal(tr[1].contact, 1);
    near(tr[1].t, t1 + v1 / (mu2 * G), 1e-12, "B stops");
    near(f->stats.friction_dissipated, M * v0 * v0 / 2, 1e-12, "all the energy");
    assert_true(f->stats.energy_balance_error < 1e-8);
    sf_free(f);
}

/* Painleve: a rod of length 2l, its end A on the floor (bilateral), sliding
 * backwards at 1 rad with mu = 2: N (1 + 3 cos^2 - 3 mu sin cos) = m g has
 * no solution with the sign the law assumes. */
static void painleve_rod(void **state) {
    (void)state;
    sim_fix *f = load("coordinates x, y, th\n"
                      "parameters m = 1, l = 1, g = 9.81, mu = 2\n"
                      "T = m/2*(x'^2 + y'^2) + m*l^2/6*th'^2\n"
                      "V = m*g*y\n"
                      "constraint floor: y - l*sin(th) = 0\n"
                      "constraint slip: x' + l*sin(th)*th' = 0 friction mu normal floor\n"
                      "initial th = 1, y = sin(1), x' = -1\n");
    qd_status st = sf_run(f, QD_SIM_DOP853, 1, 0, 1e-10, false);
    assert_int_equal(st, QD_ERR_NUMERIC);
    assert_non_null(strstr(qd_ctx_message(f->ctx), "Painleve paradox at t = 0"));
    assert_non_null(strstr(qd_ctx_message(f->ctx), "no consistent stick/slip mode"));
    sf_free(f);
}

/* Sliding forwards the same rod has two consistent slips, with the
 * floor's multiplier of either sign (the floor is a bilateral constraint):
 * den = 1 + 3 cos^2 - 3 mu sin cos < 0 for one sign. */
static void painleve_rod_two_modes(void **state) {
    (void)state;
    sim_fix *f = load("coordinates x, y, th\n"
                      "parameters m = 1, l = 1, g = 9.81, mu = 2\n"
                      "T = m/2*(x'^2 + y'^2) + m*l^2/6*th'^2\n"
                      "V = m*g*y\n"
                      "constraint floor: y - l*sin(th) = 0\n"
                      "constraint slip: x' + l*sin(th)*th' = 0 friction mu normal floor\n"
                      "initial th = 1, y = sin(1), x' = 1\n");
    assert_int_equal(sf_run(f, QD_SIM_DOP853, 1, 0, 1e-10, false), QD_ERR_NUMERIC);
    const char *msg = qd_ctx_message(f->ctx);
    assert_non_null(strstr(msg, "Painleve paradox at t = 0: several consistent modes"));
    assert_non_null(strstr(msg, "lambda_floor > 0"));
    assert_non_null(strstr(msg, "lambda_floor < 0"));
    sf_free(f);
}

/* More than QD__FMAX = 12 contacts: refused, the choice tries 5^k sets. */
static void too_many_contacts(void **state) {
    (void)state;
    char text[4096];
    size_t k = (size_t)snprintf(text, sizeof text, "coordinates ");
    for (int i = 0; i < 13; i++)
        k += (size_t)snprintf(text + k, sizeof text - k, "%sx%d", i ? ", " : "", i);
    k += (size_t)snprintf(text + k, sizeof text - k, "\nT = (");
    for (int i = 0; i < 13; i++)
        k += (size_t)snprintf(text + k, sizeof text - k, "%sx%d'^2", i ? " + " : "", i);
    k += (size_t)snprintf(text + k, sizeof text - k, ")/2\n");
    for (int i = 0; i < 13; i++)
        k += (size_t)snprintf(text + k, sizeof text - k,
                              "constraint c%d: x%d' = 0 friction 0.1 normal 1\n", i, i);
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qd_model_parse(ctx, text, NULL);
    assert_non_null(m);
    assert_int_equal(qd_model_ncontacts(m), 13);
    qd_eom *e = qd_eom_derive(ctx, m);
    assert_non_null(e);
    assert_null(qd_sim_new(ctx, m, e));
    assert_non_null(strstr(qd_ctx_message(ctx), "13 friction contacts: at most 12"));
    qd_eom_free(e);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* The same rod with mu = 0.5 < 4/3 slides with a consistent N > 0. */
static void rod_small_mu(void **state) {
    (void)state;
    sim_fix *f = load("coordinates x, y, th\n"
                      "parameters m = 1, l = 1, g = 9.81, mu = 0.5\n"
                      "T = m/2*(x'^2 + y'^2) + m*l^2/6*th'^2\n"
                      "V = m*g*y\n"
                      "constraint floor: y - l*sin(th) = 0\n"
                      "constraint slip: x' + l*sin(th)*th' = 0 friction mu normal floor\n"
                      "initial th = 1, y = sin(1), x' = -1\n");
    assert_int_equal(sf_run(f, QD_SIM_DOP853, 0.2, 0, 1e-10, false), QD_OK);
    assert_true(f->stats.energy_balance_error < 1e-8);
    assert_true(f->stats.friction_dissipated > 0);
    sf_free(f);
}

/* A point on a rough incline of angle al in a vertical plane, the plane
 * written with a gradient of size 3 (|N| = |lambda| |grad S| must undo it):
 * from rest it slides down at g (sin al - mu cos al) when tan al > mu. */
static const char *const incline2d =
    "coordinates x, y\n"
    "parameters m = 2, g = 9.81, al = %.17g, mu = 0.3\n"
    "P = (x, y, 0)\n"
    "particle m at P\n"
    "V = m*g*y\n"
    "constraint plane: 3*y + 3*tan(al)*x = 0\n"
    "friction mu on P against plane\n";

static void point_on_incline(void **state) {
    (void)state;
    double al = 0.6, mu = 0.3, t = 1;
    sim_fix *f = load(incline2d, al);
    assert_int_equal(qd_model_contact_kind(f->m, 0), QD_CONTACT_POINT);
    assert_int_equal(sf_run(f, QD_SIM_DOP853, t, 0, 1e-11, false), QD_OK);
    double a = G * (sin(al) - mu * cos(al));
    near(col(f, f->last, "x"), 0.5 * a * cos(al) * t * t, 1e-12, "x = a cos(al) t^2/2");
    near(fabs(col(f, f->last, "slip_P")), a * t, 1e-12, "|slip| = a t");
    assert_true(f->stats.energy_balance_error < 1e-8);
    sf_free(f);
    f = load(incline2d, atan(0.25)); /* below the friction angle: stays */
    assert_int_equal(sf_run(f, QD_SIM_DOP853, t, 0, 1e-11, false), QD_OK);
    assert_true(fabs(col(f, f->last, "x")) < 1e-14 && col(f, f->last, "mode_P") == 0);
    sf_free(f);
}

/* The same in space (P = (x, y, z), both tangential directions one
 * contact), set moving down the line of greatest slope. */
static void point_on_plane_3d(void **state) {
    (void)state;
    double al = 0.6, mu = 0.3, t = 1, v0 = 0.5;
    sim_fix *f = load("coordinates x, y, z\n"
                      "parameters m = 2, g = 9.81, al = 0.6, mu = 0.3\n"
                      "P = (x, y, z)\n"
                      "particle m at P\n"
                      "V = m*g*z\n"
                      "constraint plane: z + tan(al)*x = 0\n"
                      "friction mu on P against plane\n"
                      "initial x' = %.17g, z' = %.17g\n", v0 * cos(al), -v0 * sin(al));
    size_t con[2];
    assert_int_equal(qd_model_contact_constraints(f->m, 0, con), 2);
    assert_int_equal(sf_run(f, QD_SIM_DOP853, t, 0, 1e-11, false), QD_OK);
    double a = G * (sin(al) - mu * cos(al)), sl = v0 * t + 0.5 * a * t * t;
    near(col(f, f->last, "x"), sl * cos(al), 1e-12, "x along the slope");
    assert_true(fabs(col(f, f->last, "y")) < 1e-14);
    near(col(f, f->last, "slip_P"), v0 + a * t, 1e-12, "|slip|");
    assert_true(f->stats.energy_balance_error < 1e-8);
    sf_free(f);
}

/* A particle in a rough spherical bowl (|grad S| = 2R): it comes to rest
 * where the slope's tangent, r/|z|, is within mu, having dissipated
 * exactly the energy it lost. */
static void point_in_bowl(void **state) {
    (void)state;
    double mu = 0.2;
    sim_fix *f = load("coordinates x, y, z\n"
                      "parameters m = 1, R = 1, g = 9.81, mu = 0.2\n"
                      "P = (x, y, z)\n"
                      "particle m at P\n"
                      "V = m*g*z\n"
                      "constraint bowl: x^2 + y^2 + z^2 = R^2\n"
                      "friction mu on P against bowl\n"
                      "initial z = -0.8, x = 0.6, y' = 1\n");
    assert_int_equal(sf_run(f, QD_SIM_DOP853, 5, 0, 1e-11, false), QD_OK);
    double x = col(f, f->last, "x"), y = col(f, f->last, "y"), z = col(f, f->last, "z");
    assert_true(col(f, f->last, "mode_P") == 0);
    assert_true(hypot(x, y) / fabs(z) <= mu);
    near(f->stats.friction_dissipated, f->stats.E0 - col(f, f->last, "energy"), 1e-9,
         "dissipated = E0 - E");
    assert_true(f->stats.energy_balance_error < 1e-8);
    sf_free(f);
}

/* qd_sim_run_with from 4 threads on one compiled system: the modes are
 * each run's own, so every run switches at the same instant and ends in
 * the same state, bit for bit, as a run alone. */
typedef struct job {
    const sim_fix *f;
    qd_sim_stats stats;
    double last[32];
    qd_status st;
} job;

static void *run_job(void *arg) {
    job *j = arg;
    qd_ctx *ctx = qd_ctx_new();
    qd_sim_opts o = {.method = QD_SIM_DOP853, .t0 = 0, .t_end = 12, .rtol = 1e-11,
                     .atol = 1e-13, .q0 = j->f->q0, .qd0 = j->f->qd0};
    j->st = qd_sim_run_with(ctx, j->f->s, &o, NULL, NULL, &j->stats, j->last);
    qd_ctx_free(ctx);
    return NULL;
}

static void threads_share_a_system(void **state) {
    (void)state;
    sim_fix *f = load("coordinates x\n"
                      "parameters m = 1, k = 4, g = 9.81, v = 0.5\n"
                      "T = m/2*x'^2\n"
                      "V = k/2*x^2\n"
                      "constraint belt: x' = v friction static 0.4 kinetic 0.25 normal m*g\n"
                      "initial x' = 0.5\n");
    assert_int_equal(qd_sim_compile(f->s), QD_OK);
    job alone = {.f = f};
    run_job(&alone);
    assert_int_equal(alone.st, QD_OK);
    assert_int_equal(alone.stats.transitions, 6);
    job jobs[4];
    pthread_t th[4];
    for (int i = 0; i < 4; i++) {
        jobs[i] = (job){.f = f};
        assert_int_equal(pthread_create(&th[i], NULL, run_job, &jobs[i]), 0);
    }
    for (int i = 0; i < 4; i++)
        pthread_join(th[i], NULL);
    size_t ncols = qd_sim_columns(f->s, QD_SIM_DOP853, NULL, 0);
    for (int i = 0; i < 4; i++) {
        assert_int_equal(jobs[i].st, QD_OK);
        assert_int_equal(jobs[i].stats.transitions, 6);
        assert_memory_equal(jobs[i].last, alone.last, ncols * sizeof *alone.last);
    }
    size_t n;
    qd_sim_transitions(f->s, &n); /* qd_sim_run's list: run_with leaves it */
    assert_int_equal(n, 0);
    sf_free(f);
}

static void expect_parse_error(const char *text, const char *msg, size_t line, size_t col) {
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, text, &d);
    assert_null(m);
    if (!strstr(d.message, msg))
        fail_msg("message '%s' lacks '%s'", d.message, msg);
    assert_int_equal(d.line, line);
    assert_int_equal(d.col, col);
    assert_true(d.hint[0] != '\0');
    qd_ctx_free(ctx);
}

static void errors(void **state) {
    (void)state;
    const char *head = "coordinates x, phi\nparameters m = 1, a = 0.1, g = 9.81, mu = 0.2\n"
                       "T = m/2*x'^2 + m*a^2/5*phi'^2\n";
    char text[512];
    snprintf(text, sizeof text, "%sconstraint slip: x - a*phi = 0 friction mu normal m*g\n",
             head);
    expect_parse_error(text, "friction needs a velocity constraint", 4, 32);
    snprintf(text, sizeof text, "%sconstraint slip: x' - a*phi' = 0 friction -0.3 normal m*g\n",
             head);
    expect_parse_error(text, "the friction coefficient is negative", 4, 43);
    snprintf(text, sizeof text,
             "%sconstraint slip: x' - a*phi' = 0 friction static 0.4 kinetic -mu normal m*g\n",
             head);
    expect_parse_error(text, "the friction coefficient is negative", 4, 62);
    snprintf(text, sizeof text, "%sconstraint slip: x' - a*phi' = 0 friction mu normal flor\n"
             "constraint floor: x = phi\n", head);
    expect_parse_error(text, "no constraint named 'flor'", 4, 53);
    snprintf(text, sizeof text, "%sconstraint slip: x' - a*phi' = 0 friction mu\n", head);
    expect_parse_error(text, "friction needs the normal force", 4, 34);
    snprintf(text, sizeof text, "%sconstraint c: x = a*phi\nfriction mu on Q against c\n", head);
    expect_parse_error(text, "'Q' is not a point", 5, 16);
    snprintf(text, sizeof text, "%sQ = (x, phi, 0)\nfriction mu on Q against d\n", head);
    expect_parse_error(text, "no constraint named 'd'", 5, 26);
}

static void symplectic_refused(void **state) {
    (void)state;
    sim_fix *f = load(round_body, 0.25, 0.4, 3.0);
    assert_int_equal(sf_run(f, QD_SIM_GL4, 1, 0.01, 0, false), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(f->ctx), "friction"));
    qd_ctx_clear_error(f->ctx);
    /* taylor's steps would run past the switches: a sliding ball that never
     * started to roll (dissipating negative energy) before it was refused */
    assert_int_equal(sf_run(f, QD_SIM_TAYLOR, 1, 0.01, 0, false), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(f->ctx), "friction"));
    sf_free(f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(sphere_constraint),    cmocka_unit_test(cylinder_constraint),
        cmocka_unit_test(sphere_normal_constraint), cmocka_unit_test(sphere_rolls),
        cmocka_unit_test(billiard_ball),        cmocka_unit_test(block_sticks),
        cmocka_unit_test(block_slides),         cmocka_unit_test(block_stops_and_sticks),
        cmocka_unit_test(block_turns_back),     cmocka_unit_test(painleve_rod),
        cmocka_unit_test(rod_small_mu),         cmocka_unit_test(errors),
        cmocka_unit_test(belt_limit_cycle),     cmocka_unit_test(belt_energy_balance),
        cmocka_unit_test(lift_floor_work),      cmocka_unit_test(stacked_together),
        cmocka_unit_test(stacked_overtakes),    cmocka_unit_test(point_on_incline),
        cmocka_unit_test(point_on_plane_3d),    cmocka_unit_test(point_in_bowl),
        cmocka_unit_test(threads_share_a_system), cmocka_unit_test(painleve_rod_two_modes),
        cmocka_unit_test(too_many_contacts),    cmocka_unit_test(sphere_incline_3d),
        cmocka_unit_test(symplectic_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
