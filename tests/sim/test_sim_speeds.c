/*
 * tests/sim/test_sim_speeds.c - simulation in generalized speeds, y = (q, u)
 * (qd_sim_new_speeds; issue 15, seed-desloge-C.md ch. 67-70, C11-C13):
 *   - the rolling disk (examples/rolling_disk_tilted.qd with the body
 *     components of its angular velocity as speeds, Desloge ch. 64 / 69):
 *     the same q(t) as the multiplier form to 1e-10, the energy conserved,
 *     the rolling constraints kept to round-off with no multiplier;
 *   - the knife edge through the centre of mass: v and omega constant, the
 *     centre on the circle of radius v/omega (Neimark and Fufaev ch. II;
 *     seed T5) to 1e-10;
 *   - the Chaplygin sleigh (contact a distance b behind the centre of
 *     mass): m (v' - b w^2) = 0 and (J + m b^2) w' = -m b v w, whose
 *     solution is v = V tanh(c V t + a), |w| = sqrt(m / (J + m b^2)) V
 *     sech(c V t + a), theta by the Gudermannian, c = m b / (J + m b^2),
 *     V^2 = 2E/m (derived in the comment of test_sleigh), with dop853, gl4
 *     and bdf;
 *   - Euler's free rigid body (Desloge ch. 68 Ex. 2): energy and |L|
 *     conserved, and the same motion as Lagrange's equations in the Euler
 *     angles;
 *   - errors: verlet and impacts refused, naming what can.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/sim.h"
#include "qdot/speeds.h"

typedef struct spd {
    qd_ctx *ctx;
    qd_model *m;
    qd_speeds_eom *se;
    qd_sim *s;
    qd_eom *e;        /* the multiplier form, for comparisons */
    qd_sim *sl;
    double q0[8], qd0[8];
    double last[64], first[64];
    size_t rows, ncols;
    qd_sim_stats stats;
    /* per-row checks: the worst of each over the rows */
    double (*check)(const struct spd *f, const double *row);
    double worst;
    const void *data;
} spd;

static double number(qd_ctx *ctx, const qd_expr *v) {
    double x = 0;
    if (v)
        qd_eval(ctx, v, 0, NULL, NULL, &x);
    return x;
}

static spd *load(const char *text) {
    spd *f = calloc(1, sizeof *f);
    qd_diag d;
    f->ctx = qd_ctx_new();
    f->m = qd_model_parse(f->ctx, text, &d);
    if (!f->m)
        fail_msg("parse: %s", d.message);
    f->se = qd_speeds_derive(f->ctx, f->m, NULL);
    if (!f->se)
        fail_msg("derive: %s", qd_ctx_message(f->ctx));
    f->s = qd_sim_new_speeds(f->ctx, f->m, f->se);
    if (!f->s)
        fail_msg("sim: %s", qd_ctx_message(f->ctx));
    for (size_t i = 0; i < qd_model_ncoords(f->m) && i < 8; i++) {
        f->q0[i] = number(f->ctx, qd_model_initial(f->m, i, 0));
        f->qd0[i] = number(f->ctx, qd_model_initial(f->m, i, 1));
    }
    return f;
}

/* The same model's multiplier form (qd_eom_derive, qd_sim_new). */
static void load_lagrange(spd *f) {
    f->e = qd_eom_derive(f->ctx, f->m);
    if (!f->e)
        fail_msg("eom: %s", qd_ctx_message(f->ctx));
    f->sl = qd_sim_new(f->ctx, f->m, f->e);
    if (!f->sl)
        fail_msg("sim: %s", qd_ctx_message(f->ctx));
}

static void unload(spd *f) {
    qd_sim_free(f->s);
    qd_sim_free(f->sl);
    qd_speeds_eom_free(f->se);
    if (f->e)
        qd_eom_free(f->e);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
    free(f);
}

static int sink(void *data, int event, const double *row) {
    spd *f = data;
    (void)event;
    if (!f->rows++)
        memcpy(f->first, row, f->ncols * sizeof *row);
    if (f->check)
        f->worst = fmax(f->worst, f->check(f, row));
    return 0;
}

/* Run s from 0 to t_end (u0 may be NULL: from f->qd0). */
static qd_status run(spd *f, qd_sim *s, qd_sim_method method, double t_end, double dt,
                     double rtol, const double *u0) {
    qd_sim_opts o = {.method = method, .t_end = t_end, .dt = dt, .rtol = rtol,
                     .atol = rtol > 0 ? rtol * 1e-2 : 0, .q0 = f->q0, .qd0 = f->qd0, .u0 = u0};
    f->rows = 0;
    f->worst = 0;
    f->ncols = qd_sim_columns(s, method, NULL, 0);
    qd_status st = qd_sim_run(s, &o, sink, f, &f->stats, f->last);
    if (st != QD_OK)
        fprintf(stderr, "run (%s): %s\n", qd_sim_method_name(method), qd_ctx_message(f->ctx));
    return st;
}

static int col(const qd_sim *s, const char *name) {
    const char *names[64];
    size_t k = qd_sim_columns(s, QD_SIM_DOP853, names, 64);
    for (size_t i = 0; i < k && i < 64; i++)
        if (!strcmp(names[i], name))
            return (int)i;
    fail_msg("no column %s", name);
    return -1;
}

/* ---- the rolling disk ------------------------------------------------------ */

static const char disk[] =
    "coordinates x, y, z, phi, theta, psi\n"
    "parameters m = 1.4, a = 0.35, g = 9.81\n"
    "body disk mass m inertia disk(m, a) at (x, y, z) orientation euler(phi, theta, psi)\n"
    "V = m*g*z\n"
    "rolls disk on plane((0, 0, 1), (0, 0, 0)) as disk(a)\n"
    "speeds w1 = omega(disk).x, w2 = omega(disk).y, w3 = omega(disk).z\n"
    "initial x = 0, y = 0, z = 0.3, phi = 0, theta = 1.0, psi = 0, phi' = 0.8, theta' = 0, "
    "psi' = 4\n";

/* Desloge ch. 64 / 69: the disk's motion with its 3 speeds (no multiplier)
 * is the motion of the multiplier form with 6 coordinates and 3
 * multipliers from the same (projected) initial state. */
static void test_disk_same_motion(void **state) {
    (void)state;
    spd *f = load(disk);
    load_lagrange(f);
    assert_int_equal(qd_sim_nspeeds(f->s), 3);
    assert_int_equal(run(f, f->s, QD_SIM_DOP853, 3, 0, 1e-13, NULL), QD_OK);
    double qs[6];
    memcpy(qs, f->last + 1, sizeof qs);
    qd_sim_stats st = f->stats;
    assert_int_equal(run(f, f->sl, QD_SIM_DOP853, 3, 0, 1e-13, NULL), QD_OK);
    for (int j = 0; j < 6; j++)
        if (fabs(qs[j] - f->last[1 + j]) > 1e-10)
            fail_msg("q%d: speeds %.17g, multipliers %.17g", j, qs[j], f->last[1 + j]);
    if (st.energy_error_max > 1e-10)
        fail_msg("energy error %.3g with speeds", st.energy_error_max);
    /* the rolling constraints hold for every u: only round-off is left */
    for (size_t k = 0; k < qd_sim_ncon(f->s); k++)
        if (qd_sim_constraint_error(f->s, k) > 1e-12)
            fail_msg("constraint %s: residual %.3g with speeds", f->se->con[k].name,
                     qd_sim_constraint_error(f->s, k));
    unload(f);
}

/* The columns: t, q, the speeds by name, q', energy, res_NAME. */
static void test_disk_columns(void **state) {
    (void)state;
    spd *f = load(disk);
    const char *names[32];
    size_t k = qd_sim_columns(f->s, QD_SIM_DOP853, names, 32);
    static const char *const want[] = {"t", "x", "y", "z", "phi", "theta", "psi", "w1", "w2",
                                       "w3", "x'", "y'", "z'", "phi'", "theta'", "psi'",
                                       "energy"};
    assert_int_equal(k, 17 + 3);
    for (size_t i = 0; i < 17; i++)
        assert_string_equal(names[i], want[i]);
    for (size_t i = 17; i < k; i++)
        assert_memory_equal(names[i], "res_disk_", 9);
    /* the speeds' columns are the definitions at the q' columns: the
     * initial u from q'0 read back through omega(disk) */
    assert_int_equal(run(f, f->s, QD_SIM_DOP853, 0.5, 0, 1e-12, NULL), QD_OK);
    const qd_expr *syms[13];
    double vals[13];
    for (size_t j = 0; j < 6; j++) {
        syms[j] = f->se->q[j];
        syms[6 + j] = f->se->qd[j];
        vals[j] = f->last[1 + j];
        vals[6 + j] = f->last[10 + j];
    }
    for (size_t r = 0; r < 3; r++) {
        double u = 0;
        assert_int_equal(qd_eval(f->ctx, f->se->def[r], 12, syms, vals, &u), QD_OK);
        if (fabs(u - f->last[7 + r]) > 1e-12)
            fail_msg("%s = %.17g from q', column %.17g", names[7 + r], u, f->last[7 + r]);
    }
    unload(f);
}

/* ---- the knife edge and the Chaplygin sleigh ------------------------------- */

/* The centre of mass (x, y), heading theta; the blade touches a distance b
 * behind it and cannot slide sideways: the contact's velocity normal to
 * the heading, -sin(theta) x' + cos(theta) y' - b theta', is 0. */
static const char sleigh_fmt[] =
    "coordinates x, y, theta\n"
    "parameters m = 2, J = 0.3, b = %s\n"
    "T = m/2*(x'^2 + y'^2) + J/2*theta'^2\n"
    "constraint knife: cos(theta)*y' - sin(theta)*x' = b*theta'\n"
    "speeds v = cos(theta)*x' + sin(theta)*y', w = theta'\n"
    "initial x = 0.2, y = -0.1, theta = 0.3\n";

static spd *sleigh(const char *b) {
    char text[sizeof sleigh_fmt + 32];
    snprintf(text, sizeof text, sleigh_fmt, b);
    return load(text);
}

/* The knife edge at its centre of mass: v and w constant, so the centre
 * goes round the circle of radius v/w about (x0 - R sin theta0,
 * y0 + R cos theta0). */
typedef struct circle {
    double xc, yc, R;
} circle;

static double off_circle(const spd *f, const double *row) {
    const circle *c = f->data;
    return fabs(hypot(row[1] - c->xc, row[2] - c->yc) - c->R);
}

static void test_knife_circle(void **state) {
    (void)state;
    spd *f = sleigh("0");
    double u0[2] = {0.7, 1.3}, R = 0.7 / 1.3;
    circle c = {0.2 - R * sin(0.3), -0.1 + R * cos(0.3), R};
    f->check = off_circle;
    f->data = &c;
    assert_int_equal(run(f, f->s, QD_SIM_DOP853, 10, 0.05, 1e-13, u0), QD_OK);
    assert_true(f->rows > 200);
    if (f->worst > 1e-10)
        fail_msg("off the circle by %.3g", f->worst);
    double th = 0.3 + 1.3 * 10;
    double want[5] = {c.xc + R * sin(th), c.yc - R * cos(th), th, 0.7, 1.3};
    for (int j = 0; j < 5; j++)
        if (fabs(f->last[1 + j] - want[j]) > 1e-10)
            fail_msg("component %d: %.17g, want %.17g", j, f->last[1 + j], want[j]);
    /* the blade's sideways velocity: round-off only */
    assert_true(qd_sim_constraint_error(f->s, 0) < 1e-13);
    unload(f);
}

/* The sleigh with b > 0.  Body axes at the centre of mass, velocity
 * (v, b w): its acceleration is (v' - b w^2, b w' + v w); the blade's
 * force F acts sideways at -b e1, so m (v' - b w^2) = 0,
 * m (b w' + v w) = F, J w' = -b F.  With E = m (v^2 + b^2 w^2)/2 + J w^2/2
 * constant, v' = c (V^2 - v^2): v = V tanh(s), s = c V t + atanh(v0/V),
 * and w^2 = m (V^2 - v^2)/(J + m b^2) gives w = w0 sech(s)/sech(s0); then
 * theta = theta0 + (w0 / (c V sech(s0))) (gd(s) - gd(s0)). */
typedef struct sleigh_sol {
    double c, V, s0, w0, th0;
} sleigh_sol;

static double gd(double s) { return 2 * atan(tanh(s / 2)); }

static void sleigh_at(const sleigh_sol *S, double t, double *v, double *w, double *th) {
    double s = S->c * S->V * t + S->s0;
    *v = S->V * tanh(s);
    *w = S->w0 * cosh(S->s0) / cosh(s);
    *th = S->th0 + S->w0 * cosh(S->s0) / (S->c * S->V) * (gd(s) - gd(S->s0));
}

static double off_sleigh(const spd *f, const double *row) {
    double v, w, th;
    sleigh_at(f->data, row[0], &v, &w, &th);
    return fmax(fabs(row[3] - th), fmax(fabs(row[4] - v), fabs(row[5] - w)));
}

static void test_sleigh(void **state) {
    (void)state;
    double m = 2, J = 0.3, b = 0.4, v0 = -0.3, w0 = 1.5;
    double E = m / 2 * (v0 * v0 + b * b * w0 * w0) + J / 2 * w0 * w0, V = sqrt(2 * E / m);
    sleigh_sol S = {m * b / (J + m * b * b), V, atanh(v0 / V), w0, 0.3};
    struct {
        qd_sim_method method;
        double dt, rtol, tol;
    } cases[] = {
        {QD_SIM_DOP853, 0.05, 1e-13, 1e-10},
        {QD_SIM_DOPRI5, 0.05, 1e-12, 1e-9},
        {QD_SIM_GL4, 0.005, 0, 1e-8},
        {QD_SIM_BDF, 0.05, 1e-10, 1e-6},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        spd *f = sleigh("0.4");
        double u0[2] = {v0, w0};
        f->check = off_sleigh;
        f->data = &S;
        assert_int_equal(run(f, f->s, cases[i].method, 8, cases[i].dt, cases[i].rtol, u0),
                         QD_OK);
        if (f->worst > cases[i].tol)
            fail_msg("%s: off the closed form by %.3g", qd_sim_method_name(cases[i].method),
                     f->worst);
        /* the speed tends to V, the turning stops (Chaplygin's sleigh
         * straightens out): v passed from -0.3 to near +V */
        assert_true(f->last[4] > 0.9 * V);
        if (cases[i].method != QD_SIM_BDF && f->stats.energy_error_max > 10 * cases[i].tol)
            fail_msg("%s: energy error %.3g", qd_sim_method_name(cases[i].method),
                     f->stats.energy_error_max);
        unload(f);
    }
}

/* u0 NULL: the speeds from q'0 by their definitions, after q'0 is moved
 * onto the blade's constraint (the projection); a q'0 already on it gives
 * the u0 it was made from. */
/* q'0 of the sleigh with speeds (v0, w0) at theta0 = 0.3 (on the blade's
 * constraint). */
static void sleigh_velocities(spd *f, double v0, double w0) {
    double th = 0.3, b = 0.4;
    f->qd0[0] = v0 * cos(th) - b * w0 * sin(th);
    f->qd0[1] = v0 * sin(th) + b * w0 * cos(th);
    f->qd0[2] = w0;
}

static void test_sleigh_from_velocities(void **state) {
    (void)state;
    spd *f = sleigh("0.4");
    sleigh_velocities(f, 0.6, -0.8);
    /* a speed named in an output stands for its definition */
    assert_int_equal(qd_sim_add_output(f->s, "vv", f->se->u[0]), QD_OK);
    assert_int_equal(run(f, f->s, QD_SIM_DOP853, 1, 0, 1e-12, NULL), QD_OK);
    int cv = col(f->s, "v"), cw = col(f->s, "w"), cvv = col(f->s, "vv");
    if (fabs(f->first[cv] - 0.6) > 1e-15 || fabs(f->first[cw] + 0.8) > 1e-15)
        fail_msg("u0 from q'0: %.17g, %.17g", f->first[cv], f->first[cw]);
    if (fabs(f->last[cvv] - f->last[cv]) > 1e-13)
        fail_msg("output v %.17g, column v %.17g", f->last[cvv], f->last[cv]);
    unload(f);
}

/* ---- Euler's free rigid body ----------------------------------------------- */

static const char euler_body[] =
    "coordinates phi, theta, psi\n"
    "parameters A = 1, B = 2, C = 3\n"
    "body b mass 1 inertia (A, B, C) at (0, 0, 0) orientation euler(phi, theta, psi)\n"
    "speeds w1 = omega(b).x, w2 = omega(b).y, w3 = omega(b).z\n"
    "initial phi = 0.1, theta = 1.0, psi = -0.4\n";

typedef struct body_ref {
    double E, L;
} body_ref;

/* |E - E0|/E0 and ||L| - |L0||/|L0| in the body axes, L = I w. */
static double off_body(const spd *f, const double *row) {
    const body_ref *r = f->data;
    const double *w = row + 4;
    double E = 0.5 * (w[0] * w[0] + 2 * w[1] * w[1] + 3 * w[2] * w[2]);
    double L = sqrt(w[0] * w[0] + 4 * w[1] * w[1] + 9 * w[2] * w[2]);
    return fmax(fabs(E - r->E) / r->E, fabs(L - r->L) / r->L);
}

static void test_euler_body(void **state) {
    (void)state;
    spd *f = load(euler_body);
    load_lagrange(f);
    /* mostly about the axis of largest inertia: theta stays near 1, away
     * from the Euler angles' singularity */
    double w[3] = {0.3, -0.2, 2.0};
    body_ref ref = {0.5 * (w[0] * w[0] + 2 * w[1] * w[1] + 3 * w[2] * w[2]),
                    sqrt(w[0] * w[0] + 4 * w[1] * w[1] + 9 * w[2] * w[2])};
    f->check = off_body;
    f->data = &ref;
    assert_int_equal(run(f, f->s, QD_SIM_DOP853, 20, 0.1, 1e-13, w), QD_OK);
    if (f->worst > 1e-10)
        fail_msg("energy or |L| drifts by %.3g", f->worst);
    if (fabs(f->stats.E0 - ref.E) > 1e-14)
        fail_msg("energy column h = %.17g, want %.17g", f->stats.E0, ref.E);
    /* the same motion from Lagrange's equations in the angles, from the
     * velocities the kinematics gave at t = 0 */
    double q[3];
    memcpy(q, f->last + 1, sizeof q);
    memcpy(f->qd0, f->first + 7, 3 * sizeof(double));
    f->check = NULL;
    assert_int_equal(run(f, f->sl, QD_SIM_DOP853, 20, 0.1, 1e-13, NULL), QD_OK);
    for (int j = 0; j < 3; j++)
        if (fabs(q[j] - f->last[1 + j]) > 1e-9)
            fail_msg("q%d: speeds %.17g, Lagrange %.17g", j, q[j], f->last[1 + j]);
    unload(f);
}

/* ---- errors ---------------------------------------------------------------- */

static void test_errors(void **state) {
    (void)state;
    spd *f = sleigh("0.4");
    double u0[2] = {0.5, 0.5};
    qd_sim_opts o = {.method = QD_SIM_VERLET, .t_end = 1, .dt = 0.01, .q0 = f->q0,
                     .qd0 = f->qd0, .u0 = u0};
    assert_int_equal(qd_sim_run(f->s, &o, NULL, NULL, NULL, NULL), QD_ERR_ARG);
    const char *msg = qd_ctx_message(f->ctx);
    assert_non_null(strstr(msg, "verlet"));
    assert_non_null(strstr(msg, "dop853"));
    assert_non_null(strstr(msg, "bdf"));
    unload(f);

    /* impacts: Newton's law is written for the velocities */
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    char text[1024];
    snprintf(text, sizeof text, sleigh_fmt, "0.4");
    strcat(text, "impact wall: 5 - x >= 0 restitution 1\n");
    qd_model *m = qd_model_parse(ctx, text, &d);
    assert_non_null(m);
    qd_speeds_eom *se = qd_speeds_derive(ctx, m, NULL);
    assert_non_null(se);
    assert_null(qd_sim_new_speeds(ctx, m, se));
    assert_int_equal(qd_ctx_status(ctx), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(ctx), "--no-speeds"));
    qd_speeds_eom_free(se);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_disk_same_motion),
        cmocka_unit_test(test_disk_columns),
        cmocka_unit_test(test_knife_circle),
        cmocka_unit_test(test_sleigh),
        cmocka_unit_test(test_sleigh_from_velocities),
        cmocka_unit_test(test_euler_body),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
