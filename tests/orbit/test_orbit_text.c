/*
 * tests/orbit/test_orbit_text.c - qd_orbit_solve_text (orbit.h): the state
 * of `qdot orbit` as text, with values in the parameters, against Kepler's
 * closed forms (Desloge ch. 58, reference seed-desloge-B.md C3): the circle
 * of radius a has theta'^2 = k/(m a^3), E = -k/(2 a), small radial
 * oscillations of period 2 pi sqrt(m a^3/k); an ellipse from its apocentre
 * r = a(1 + e) with the momentum h given turns at a(1 -+ e), e from
 * p = h^2/(m k) = a(1 - e^2).  Errors name the field and point into it.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "qdot/orbit.h"
#include "qdot/qdot.h"

#define PI 3.14159265358979323846

static const char kepler[] = "coordinates r, theta\nparameters m = 1.3, k = 4, r0 = 2\n"
                             "particle m at r*(cos(theta), sin(theta))\nV = -k/r\n"
                             "initial r = 1, theta' = 1.5\n";

typedef struct fix {
    qd_ctx *ctx;
    qd_model *m;
    qd_eom *e;
    qd_orbit *o;
    qd_orbit_result r;
} fix;

static void load(fix *f) {
    memset(f, 0, sizeof *f);
    f->ctx = qd_ctx_new();
    f->m = qd_model_parse(f->ctx, kepler, NULL);
    assert_non_null(f->m);
    f->e = qd_eom_derive(f->ctx, f->m);
    assert_non_null(f->e);
    const qd_expr *ign = qd_model_coord(f->m, 1);
    f->o = qd_orbit_derive(f->ctx, f->m, f->e, 1, &ign);
    assert_non_null(f->o);
}

static void unload(fix *f) {
    qd_orbit_result_free(&f->r);
    qd_orbit_free(f->o);
    qd_eom_free(f->e);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
}

static void near(double got, double want, double tol) {
    if (!(fabs(got - want) <= tol * (1 + fabs(want))))
        fail_msg("got %.17g, want %.17g (tol %g)", got, want, tol);
}

static void circle_in_parameters(void **state) {
    (void)state;
    fix f;
    load(&f);
    const qd_orbit_text t = {.at = "r=r0, theta'=sqrt(k/(m*r0^3))"};
    assert_int_equal(qd_orbit_solve_text(f.ctx, f.o, f.m, &t, &f.r), QD_OK);
    assert_int_equal(f.r.kind, QD_ORBIT_CIRCULAR);
    near(f.r.energy, -4.0 / (2 * 2), 1e-13);
    near(f.r.period, 2 * PI * sqrt(1.3 * 8 / 4), 1e-9);
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_orbit_render(f.ctx, f.o, &f.r, "kepler", true, true, &b), QD_OK);
    assert_int_equal(qd_orbit_render(f.ctx, f.o, &f.r, "kepler", true, false, &b), QD_OK);
    qd_buf_free(&b);
    unload(&f);
}

/* From r = 1 at rest radially, with h = p_theta given: p = h^2/(m k),
 * the turning points p/(1 + e) and p/(1 - e), one of them 1. */
static void ellipse_from_momentum(void **state) {
    (void)state;
    fix f;
    load(&f);
    const qd_orbit_text t = {.at = "r=1, r'=0", .momentum = "p_theta = sqrt(m*k*r0/4)"};
    assert_int_equal(qd_orbit_solve_text(f.ctx, f.o, f.m, &t, &f.r), QD_OK);
    double p = 0.5, e = 1 - p; /* apocentre 1 = p/(1 - e) */
    assert_int_equal(f.r.kind, QD_ORBIT_BOUND);
    assert_int_equal(f.r.nturn, 2);
    near(f.r.turn[0], p / (1 + e), 1e-12);
    near(f.r.turn[1], 1, 1e-12);
    qd_orbit_result_free(&f.r);
    /* E = -k/(2a) with a = 1 given as an energy in the parameters */
    const qd_orbit_text te = {.at = "r=1, r'=0", .energy = "-k/2"};
    assert_int_equal(qd_orbit_solve_text(f.ctx, f.o, f.m, &te, &f.r), QD_OK);
    near(f.r.period, 2 * PI * sqrt(1.3 / 4), 1e-9);
    unload(&f);
}

static void refused(fix *f, const qd_orbit_text *t, const char *field, size_t off) {
    qd_status st = qd_orbit_solve_text(f->ctx, f->o, f->m, t, &f->r);
    assert_true(st == QD_ERR_ARG || st == QD_ERR_PARSE); /* an unknown name in the energy */
    const qd_diag *d = qd_ctx_diag(f->ctx);
    assert_string_equal(d->name, field);
    assert_true(d->located);
    assert_int_equal(d->offset, off);
    qd_ctx_clear_error(f->ctx);
    qd_orbit_result_free(&f->r);
}

static void errors(void **state) {
    (void)state;
    fix f;
    load(&f);
    refused(&f, &(qd_orbit_text){.at = "r=1, thetaa'=2"}, "at", 5);
    assert_string_equal(qd_ctx_diag(f.ctx)->hint, ""); /* cleared */
    assert_int_equal(qd_orbit_solve_text(f.ctx, f.o, f.m, &(qd_orbit_text){.at = "thetta'=2"},
                                         &f.r), QD_ERR_ARG);
    assert_string_equal(qd_ctx_diag(f.ctx)->hint, "did you mean 'theta''?");
    qd_ctx_clear_error(f.ctx);
    qd_orbit_result_free(&f.r);
    refused(&f, &(qd_orbit_text){.at = "r=2*kk"}, "at", 4);
    refused(&f, &(qd_orbit_text){.at = "r=1, r=2"}, "at", 5);
    refused(&f, &(qd_orbit_text){.momentum = "p_r=1"}, "momentum", 0);
    refused(&f, &(qd_orbit_text){.energy = "E0"}, "energy", 0);
    unload(&f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(circle_in_parameters),
        cmocka_unit_test(ellipse_from_momentum),
        cmocka_unit_test(errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
