/*
 * tests/linear/test_speeds_modes.c - linearization, stability and
 * equilibria of models in generalized speeds (src/linear/speeds_lin.c,
 * speeds_eq.c):
 *   the thin uniform disk rolling upright at spin rate Omega: the reduced
 *     system keeps theta alone (x, y, the heading and the spin angle are
 *     ignorable), the straight rolling is stationary, and it is stable iff
 *     Omega^2 > g/(3a).  The threshold is the classic one for a disk with
 *     I_axle = C, I_diam = A: Omega^2 > m g a A / (C (C + m a^2)), which
 *     is g/(3a) for C = m a^2/2, A = m a^2/4 (Neimark and Fufaev, Dynamics
 *     of Nonholonomic Systems, ch. III sec. 5; Routh, Advanced Rigid
 *     Dynamics, art. 244); the tilt then oscillates with
 *     s^2 = -(4/5)(3 Omega^2 - g/a), found by bisection on the verdict and
 *     compared with the formula, and the frequency at two spins;
 *   the same threshold from qd_speeds_modes_scan along the spin u3, and along
 *     g at a fixed spin (g = 3 a Omega^2), one transition each;
 *   the equilibria of the disk: theta = +-pi/2 with x, y, phi, psi free;
 *     with its height z a coordinate held by the contact z = a sin(theta)
 *     and the body components of w as speeds (tests/speeds' disk), the
 *     spin angle enters the equations at rest yet stays free: a family,
 *     flagged continuous, every sample upright at z = +-a;
 *   the double pendulum in the speeds u1 = th1', u2 = th1' + th2' (absolute
 *     angular velocity of the lower rod) has the equilibria of the same
 *     model in coordinates (qd_equilibria_find), and its modes the same
 *     frequencies (Goldstein ch. 6; the double pendulum of equal rods);
 *   errors: a rheonomic speed map refuses equilibria.
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
#include "util/check.h"

static const double PI = 3.14159265358979323846;

/* The disk of examples/rolling_disk_tilted.qd with its centre's height
 * built in, and speeds that close the reduced system: the tilt rate, the
 * vertical component of the angular velocity, the spin about the axle. */
static const char disk[] =
    "coordinates x, y, phi, theta, psi\n"
    "parameters m = 1.4, a = 0.35, g = 9.81\n"
    "body disk mass m inertia disk(m, a) at (x, y, a*sin(theta)) "
    "orientation euler(phi, theta, psi)\n"
    "V = m*g*a*sin(theta)\n"
    "rolls disk on plane((0, 0, 1), (0, 0, 0)) as disk(a)\n"
    "speeds u1 = theta', u2 = omega_space(disk).z, u3 = omega(disk).z\n";

typedef struct world {
    qd_ctx *ctx;
    qd_model *m;
    qd_speeds_eom *e;
} world;

static void open_world(world *w, const char *text) {
    w->ctx = qd_ctx_new();
    assert_non_null(w->ctx);
    w->m = qt_parse_ok(w->ctx, text);
    w->e = qd_speeds_derive(w->ctx, w->m, NULL);
    if (!w->e)
        fail_msg("qd_speeds_derive: %s", qd_ctx_message(w->ctx));
}

static void close_world(world *w) {
    qd_speeds_eom_free(w->e);
    qd_model_free(w->m);
    qd_ctx_free(w->ctx);
}

static size_t coord(const world *w, const char *name) {
    for (size_t j = 0; j < w->e->n; j++)
        if (!strcmp(qd_expr_name(w->e->q[j]), name))
            return j;
    fail_msg("no coordinate %s", name);
    return 0;
}

static double pnum(const qd_model *m, size_t i) {
    double x = 0;
    assert_int_equal(qd_model_param_number(m, i, &x), QD_OK);
    return x;
}

static double param(const world *w, const char *name) {
    for (size_t i = 0; i < qd_model_nparams(w->m); i++)
        if (!strcmp(qd_expr_name(qd_model_param(w->m, i)), name))
            return pnum(w->m, i);
    fail_msg("no parameter %s", name);
    return 0;
}

/* The disk upright (theta = pi/2) rolling straight at spin Omega. */
static void disk_state(const world *w, double Omega, const qd_expr **syms, double *vals,
                       size_t *k) {
    const qd_speeds_eom *e = w->e;
    *k = 0;
    for (size_t i = 0; i < qd_model_nparams(w->m); i++) {
        syms[*k] = qd_model_param(w->m, i);
        vals[(*k)++] = pnum(w->m, i);
    }
    syms[*k] = e->q[coord(w, "theta")];
    vals[(*k)++] = PI / 2;
    syms[*k] = e->q[coord(w, "phi")];
    vals[(*k)++] = 0.3;   /* the heading must not matter */
    for (size_t r = 0; r < e->m; r++) {
        syms[*k] = e->u[r];
        vals[(*k)++] = r == 2 ? Omega : 0;
    }
}

/* The verdict at spin Omega; the linearization checked to be about a
 * stationary point of the reduced system (theta, u1, u2, u3). */
static int disk_verdict(const world *w, double Omega, qd_modes_result *res) {
    const qd_expr *syms[16];
    double vals[16];
    size_t k;
    disk_state(w, Omega, syms, vals, &k);
    qd_speeds_linear lin;
    assert_int_equal(qd_speeds_linear_about(w->ctx, w->e, k, syms, vals, &lin), QD_OK);
    assert_int_equal(lin.nkept, 1);
    assert_int_equal(lin.kept[0], coord(w, "theta"));
    assert_true(lin.ignorable[coord(w, "x")] && lin.ignorable[coord(w, "y")] &&
                lin.ignorable[coord(w, "phi")] && lin.ignorable[coord(w, "psi")]);
    assert_int_equal(lin.dim, 4);
    for (size_t i = 0; i < lin.dim; i++)
        assert_true(fabs(lin.rate[i]) < 1e-12 * (1 + Omega * Omega));
    assert_int_equal(qd_speeds_modes_solve(w->ctx, &lin, res), QD_OK);
    qd_speeds_linear_free(&lin);
    return res->stable;
}

static void disk_threshold(void **state) {
    (void)state;
    world w;
    open_world(&w, disk);
    double g = param(&w, "g"), a = param(&w, "a"), Oc = sqrt(g / (3 * a));
    qd_modes_result res;
    /* either side of the threshold, and the tilt's frequency there */
    for (int side = -1; side <= 1; side += 2) {
        double Omega = Oc * (1 + 0.2 * side);
        int v = disk_verdict(&w, Omega, &res);
        double s2 = -0.8 * (3 * Omega * Omega - g / a);
        assert_int_equal(v, side > 0 ? 1 : 0);
        /* the largest |s|: the tilt's root, +-sqrt(s2) */
        double re = res.eig_re[0], im = 0;
        for (size_t i = 0; i < res.neig; i++)
            im = fmax(im, fabs(res.eig_im[i]));
        if (side > 0)
            assert_true(fabs(im * im + s2) < 1e-9 * fabs(s2));
        else
            assert_true(fabs(re * re - s2) < 1e-9 * fabs(s2));
        qd_modes_result_free(&res);
    }
    /* the threshold itself by bisection on the verdict */
    double lo = 0.5 * Oc, hi = 2 * Oc;
    while (hi - lo > 1e-10 * Oc) {
        double mid = (lo + hi) / 2;
        int v = disk_verdict(&w, mid, &res);
        qd_modes_result_free(&res);
        *(v == 1 ? &hi : &lo) = mid;
    }
    assert_true(fabs((lo + hi) / 2 - Oc) < 1e-7 * Oc);
    close_world(&w);
}

static void disk_scan(void **state) {
    (void)state;
    world w;
    open_world(&w, disk);
    const qd_expr *syms[16];
    double vals[16], g = param(&w, "g"), a = param(&w, "a"), Omega = 6;
    size_t k;
    disk_state(&w, Omega, syms, vals, &k);
    qd_scan sc;
    qd_scan_opts o = {.steps = 20};
    const qd_expr *u3 = w.e->u[2], *gs = NULL;
    for (size_t i = 0; i < qd_model_nparams(w.m); i++)
        if (!strcmp(qd_expr_name(qd_model_param(w.m, i)), "g"))
            gs = qd_model_param(w.m, i);
    assert_int_equal(qd_speeds_modes_scan(w.ctx, w.e, k, syms, vals, u3, 1, 6, &o, &sc), QD_OK);
    assert_int_equal(sc.count, 21);
    assert_int_equal(sc.ntrans, 1);
    assert_int_equal(sc.trans[0].from, 0);
    assert_int_equal(sc.trans[0].to, 1);
    assert_true(fabs(sc.trans[0].value - sqrt(g / (3 * a))) < 1e-8 * sqrt(g / (3 * a)));
    qd_scan_free(&sc);
    assert_int_equal(qd_speeds_modes_scan(w.ctx, w.e, k, syms, vals, gs, 1, 50, &o, &sc), QD_OK);
    assert_int_equal(sc.ntrans, 1);
    assert_int_equal(sc.trans[0].from, 1);
    assert_int_equal(sc.trans[0].to, 0);
    assert_true(fabs(sc.trans[0].value - 3 * a * Omega * Omega) < 1e-8 * 3 * a * Omega * Omega);
    qd_scan_free(&sc);
    /* the time is no value of this state; a reversed range */
    assert_int_equal(qd_speeds_modes_scan(w.ctx, w.e, k, syms, vals, qd_time(w.ctx), 0, 1, &o,
                                          &sc),
                     QD_ERR_ARG);
    qd_scan_free(&sc);
    assert_int_equal(qd_speeds_modes_scan(w.ctx, w.e, k, syms, vals, u3, 6, 1, &o, &sc),
                     QD_ERR_ARG);
    qd_scan_free(&sc);
    close_world(&w);
}

static void disk_equilibria(void **state) {
    (void)state;
    world w;
    open_world(&w, disk);
    const qd_expr *syms[8];
    double vals[8];
    size_t k = qd_model_nparams(w.m);
    for (size_t i = 0; i < k; i++) {
        syms[i] = qd_model_param(w.m, i);
        vals[i] = pnum(w.m, i);
    }
    qd_speeds_equilibria eq;
    assert_int_equal(qd_speeds_equilibria_find(w.ctx, w.e, w.m, k, syms, vals, NULL, &eq), QD_OK);
    assert_int_equal(eq.nsolved, 1);
    assert_int_equal(eq.solved[0], coord(&w, "theta"));
    for (size_t j = 0; j < w.e->n; j++)
        assert_int_equal(eq.free_coord[j], j != coord(&w, "theta"));
    assert_int_equal(eq.eq.count, 2);
    assert_true(fabs(eq.eq.pts[0].q[0] + PI / 2) < 1e-12);
    assert_true(fabs(eq.eq.pts[1].q[0] - PI / 2) < 1e-12);
    qd_speeds_equilibria_free(&eq);
    close_world(&w);
}

static void disk_body_speeds(void **state) {
    (void)state;
    world w;
    open_world(&w, "coordinates x, y, z, phi, theta, psi\n"
                   "parameters m = 1.4, a = 0.35, g = 9.81\n"
                   "body disk mass m inertia disk(m, a) at (x, y, z) "
                   "orientation euler(phi, theta, psi)\n"
                   "V = m*g*z\n"
                   "rolls disk on plane((0, 0, 1), (0, 0, 0)) as disk(a)\n"
                   "speeds w1 = omega(disk).x, w2 = omega(disk).y, w3 = omega(disk).z\n");
    const qd_expr *syms[4];
    double vals[4], a = param(&w, "a");
    size_t k = qd_model_nparams(w.m);
    for (size_t i = 0; i < k; i++) {
        syms[i] = qd_model_param(w.m, i);
        vals[i] = pnum(w.m, i);
    }
    qd_speeds_equilibria eq;
    assert_int_equal(qd_speeds_equilibria_find(w.ctx, w.e, w.m, k, syms, vals, NULL, &eq), QD_OK);
    assert_int_equal(eq.nsolved, 3);  /* z, theta, psi */
    assert_true(eq.free_coord[coord(&w, "x")] && eq.free_coord[coord(&w, "y")] &&
                eq.free_coord[coord(&w, "phi")]);
    assert_true(eq.eq.continuum);
    assert_true(eq.eq.count > 2);
    size_t jz = SIZE_MAX, jt = SIZE_MAX;
    for (size_t j = 0; j < eq.nsolved; j++) {
        if (eq.solved[j] == coord(&w, "z"))
            jz = j;
        if (eq.solved[j] == coord(&w, "theta"))
            jt = j;
    }
    assert_true(jz != SIZE_MAX && jt != SIZE_MAX);
    for (size_t i = 0; i < eq.eq.count; i++) {
        const double *q = eq.eq.pts[i].q;
        assert_true(fabs(fabs(q[jt]) - PI / 2) < 1e-9);
        assert_true(fabs(q[jz] - a * sin(q[jt])) < 1e-9);
    }
    qd_speeds_equilibria_free(&eq);
    close_world(&w);
}

/* ---- the double pendulum: speeds against coordinates ----------------------- */

static const char pendulum2[] =
    "coordinates th1, th2\n"
    "parameters m = 1.3, l = 0.7, g = 9.81\n"
    "particle m at (l*sin(th1), -l*cos(th1))\n"
    "particle m at (l*sin(th1) + l*sin(th1 + th2), -l*cos(th1) - l*cos(th1 + th2))\n"
    "V = -m*g*l*(2*cos(th1) + cos(th1 + th2))\n";

static void pendulum_equilibria(void **state) {
    (void)state;
    char text[1024];
    snprintf(text, sizeof text, "%sspeeds u1 = th1', u2 = th1' + th2'\n", pendulum2);
    world w;
    open_world(&w, text);
    qd_ctx *ctx = w.ctx;
    qd_model *plain = qt_parse_ok(ctx, pendulum2);
    qd_eom *e = qd_eom_derive(ctx, plain);
    assert_non_null(e);
    const qd_expr *syms[4], *psyms[4];
    double vals[4];
    size_t k = qd_model_nparams(w.m);
    for (size_t i = 0; i < k; i++) {
        syms[i] = qd_model_param(w.m, i);
        psyms[i] = qd_model_param(plain, i);
        vals[i] = pnum(w.m, i);
    }
    qd_speeds_equilibria se;
    qd_equilibria pe;
    assert_int_equal(qd_speeds_equilibria_find(ctx, w.e, w.m, k, syms, vals, NULL, &se), QD_OK);
    assert_int_equal(qd_equilibria_find(ctx, e, plain, k, psyms, vals, NULL, &pe), QD_OK);
    assert_int_equal(se.nsolved, 2);
    assert_int_equal(se.eq.count, pe.count);
    assert_int_equal(pe.count, 4);  /* (0, 0), (0, pi), (pi, 0), (pi, pi) */
    for (size_t i = 0; i < pe.count; i++)
        for (size_t j = 0; j < 2; j++)
            assert_true(fabs(se.eq.pts[i].q[j] - pe.pts[i].q[j]) < 1e-12);
    qd_speeds_equilibria_free(&se);
    qd_equilibria_free(&pe);
    qd_eom_free(e);
    qd_model_free(plain);
    close_world(&w);
}

/* About the lowest point the eigenvalues of the first-order system are
 * +-i w for the two normal-mode frequencies of the equal double pendulum:
 * w^2 = (2 +- sqrt 2) g/l (Goldstein ch. 6, the double pendulum). */
static void pendulum_modes(void **state) {
    (void)state;
    char text[1024];
    snprintf(text, sizeof text, "%sspeeds u1 = th1', u2 = th1' + th2'\n", pendulum2);
    world w;
    open_world(&w, text);
    const qd_expr *syms[8];
    double vals[8];
    size_t k = qd_model_nparams(w.m);
    for (size_t i = 0; i < k; i++) {
        syms[i] = qd_model_param(w.m, i);
        vals[i] = pnum(w.m, i);
    }
    double gl = param(&w, "g") / param(&w, "l");
    qd_speeds_linear lin;
    qd_modes_result res;
    assert_int_equal(qd_speeds_linear_about(w.ctx, w.e, k, syms, vals, &lin), QD_OK);
    assert_int_equal(lin.nkept, 2);
    assert_int_equal(qd_speeds_modes_solve(w.ctx, &lin, &res), QD_OK);
    assert_int_equal(res.neig, 4);
    assert_int_equal(res.stable, 1);
    double want[2] = {(2 - sqrt(2)) * gl, (2 + sqrt(2)) * gl}, got[2] = {0, 0};
    size_t ng = 0;
    for (size_t i = 0; i < res.neig; i++) {
        assert_true(fabs(res.eig_re[i]) < 1e-9 * sqrt(want[1]));
        if (res.eig_im[i] > 0 && ng < 2)
            got[ng++] = res.eig_im[i] * res.eig_im[i];
    }
    assert_int_equal(ng, 2);
    if (got[0] > got[1]) {
        double t = got[0];
        got[0] = got[1];
        got[1] = t;
    }
    for (size_t j = 0; j < 2; j++)
        assert_true(fabs(got[j] - want[j]) < 1e-10 * want[j]);
    qd_modes_result_free(&res);
    qd_speeds_linear_free(&lin);
    close_world(&w);
}

/* ---- against the multiplier form ------------------------------------------- */

/* At rest in the multiplier form (qd_eom: M q'' = f + A^T lambda, A q'' = b)
 * q'' at q, every velocity 0: an equilibrium when it is 0. */
static double rest_accel(qd_ctx *ctx, const qd_model *m, const qd_eom *e, const double *q) {
    const qd_expr *syms[16];
    double vals[16], qdd[8], lambda[8];
    size_t k = 0;
    for (size_t j = 0; j < e->n; j++) {
        syms[k] = e->q[j];
        vals[k++] = q[j];
    }
    for (size_t i = 0; i < qd_model_nparams(m); i++) {
        syms[k] = qd_model_param(m, i);
        vals[k++] = pnum(m, i);
    }
    assert_int_equal(qd_eom_eval(ctx, e, k, syms, vals, NULL, NULL, qdd, lambda, NULL), QD_OK);
    double a = 0;
    for (size_t j = 0; j < e->n; j++)
        a = fmax(a, fabs(qdd[j]));
    return a;
}

/* The equilibria in speeds are points of rest of the multiplier form, and
 * the holonomic constraint puts them on the circle: the Cartesian pendulum
 * (examples/pendulum_cartesian.qd) hangs at (0, -l) and stands at (0, l),
 * the speed u = x y' - y x' (its angular momentum over m). */
static void cartesian_pendulum(void **state) {
    (void)state;
    static const char plain[] = "coordinates x, y\nparameters m = 0.6, l = 1.4, g = 9.81\n"
                                "particle m at (x, y)\nV = m*g*y\n"
                                "constraint rod: x^2 + y^2 = l^2\n";
    char text[512];
    snprintf(text, sizeof text, "%sspeeds u = x*y' - y*x'\n", plain);
    world w;
    open_world(&w, text);
    qd_model *pm = qt_parse_ok(w.ctx, plain);
    qd_eom *pe = qd_eom_derive(w.ctx, pm);
    assert_non_null(pe);
    const qd_expr *syms[4];
    double vals[4], l = param(&w, "l");
    size_t k = qd_model_nparams(w.m);
    for (size_t i = 0; i < k; i++) {
        syms[i] = qd_model_param(w.m, i);
        vals[i] = pnum(w.m, i);
    }
    qd_speeds_equilibria eq;
    assert_int_equal(qd_speeds_equilibria_find(w.ctx, w.e, w.m, k, syms, vals, NULL, &eq), QD_OK);
    assert_int_equal(eq.nsolved, 2);
    assert_int_equal(eq.eq.count, 2);
    for (size_t i = 0; i < 2; i++) {
        const double *q = eq.eq.pts[i].q;
        assert_true(fabs(q[0]) < 1e-12);
        assert_true(fabs(q[1] - (i ? l : -l)) < 1e-12);
        assert_true(rest_accel(w.ctx, pm, pe, q) < 1e-12);
    }
    /* and off them the multiplier form moves */
    double off[2] = {l * sin(0.4), -l * cos(0.4)};
    assert_true(rest_accel(w.ctx, pm, pe, off) > 1);
    qd_speeds_equilibria_free(&eq);
    qd_eom_free(pe);
    qd_model_free(pm);
    close_world(&w);
}

/* The disk: its upright equilibria, with any x, y, heading and spin angle,
 * are rest points of the multiplier form (rolling constraints kept with
 * their multipliers); a leaning disk is not. */
static void disk_multiplier_form(void **state) {
    (void)state;
    world w;
    open_world(&w, disk);
    char plain[1024];
    snprintf(plain, sizeof plain, "%s", disk);
    *strstr(plain, "speeds") = '\0';
    qd_model *pm = qt_parse_ok(w.ctx, plain);
    qd_eom *pe = qd_eom_derive(w.ctx, pm);
    assert_non_null(pe);
    assert_int_equal(pe->ncon, 2);
    const qd_expr *syms[4];
    double vals[4];
    size_t k = qd_model_nparams(w.m);
    for (size_t i = 0; i < k; i++) {
        syms[i] = qd_model_param(w.m, i);
        vals[i] = pnum(w.m, i);
    }
    qd_speeds_equilibria eq;
    assert_int_equal(qd_speeds_equilibria_find(w.ctx, w.e, w.m, k, syms, vals, NULL, &eq), QD_OK);
    assert_int_equal(eq.eq.count, 2);
    /* the free coordinates anywhere (the same order in both models) */
    double q[5] = {0.7, -1.1, 0.4, 0, 2.3};
    for (size_t i = 0; i < eq.eq.count; i++) {
        q[eq.solved[0]] = eq.eq.pts[i].q[0];
        assert_true(rest_accel(w.ctx, pm, pe, q) < 1e-12);
    }
    qd_speeds_equilibria_free(&eq);
    q[3] = 1.0;
    assert_true(rest_accel(w.ctx, pm, pe, q) > 1);
    qd_eom_free(pe);
    qd_model_free(pm);
    close_world(&w);
}

/* A speed with a term free of the velocities: rest is not u = 0. */
static void rheonomic_refused(void **state) {
    (void)state;
    world w;
    open_world(&w, "coordinates x\nparameters k = 2, c = 0.5\nparticle 1 at (x, 0)\n"
                   "V = k*x^2/2\nspeeds u = x' - c\n");
    qd_speeds_equilibria eq;
    assert_int_equal(qd_speeds_equilibria_find(w.ctx, w.e, w.m, 0, NULL, NULL, NULL, &eq),
                     QD_ERR_UNSUPPORTED);
    assert_non_null(strstr(qd_ctx_message(w.ctx), "free of the speeds"));
    close_world(&w);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(disk_threshold),
        cmocka_unit_test(disk_scan),
        cmocka_unit_test(disk_equilibria),
        cmocka_unit_test(disk_body_speeds),
        cmocka_unit_test(pendulum_equilibria),
        cmocka_unit_test(pendulum_modes),
        cmocka_unit_test(cartesian_pendulum),
        cmocka_unit_test(disk_multiplier_form),
        cmocka_unit_test(rheonomic_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
