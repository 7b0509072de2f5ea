/*
 * tests/linear/test_steady_given.c - a steady-motion problem stated by name
 * (qd_steady_derive_named, qd_steady_given_read, qd_stability_print):
 *
 *   - the conical pendulum (spherical pendulum, Byerly Art. 5 Ex. 3) held at
 *     theta0 = pi/3 (an expression): phi'^2 = g/(a cos theta0), both signs,
 *     and the momentum p_phi = m a^2 sin^2 theta0 phi';
 *   - the momentum given instead, "p_phi = 2*m": theta0 found from
 *     p^2 cos th = m^2 a^3 g sin^4 th (the same relation solved for theta);
 *   - the driven case "phi' = w" with w a parameter: held exactly, its
 *     expression kept for a scan;
 *   - errors located in their text with the field named: a misspelt
 *     coordinate (with "did you mean"), a misspelt parameter in a value, a
 *     guess of a held value, a rate without a prime, a momentum of a driven
 *     coordinate.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/stability.h"

#define QT_PI 3.14159265358979323846

#define SPHERICAL                                                                              \
    "coordinates theta, phi\nparameters m = 1.1, a = 0.9, g = 9.81, w = 4\n"                   \
    "r = a*(sin(theta)*cos(phi), sin(theta)*sin(phi), -cos(theta))\nparticle m at r\n"         \
    "V = m*g*r.z\n"

typedef struct fixture {
    qd_ctx *ctx;
    qd_model *m;
    qd_eom *e;
    qd_steady *s;
    qd_steady_given g;
    qd_steady_set set;
} fixture;

static void load(fixture *f, const char *names, bool driven) {
    f->ctx = qd_ctx_new();
    f->m = qd_model_parse(f->ctx, SPHERICAL, NULL);
    assert_non_null(f->m);
    f->e = qd_eom_derive(f->ctx, f->m);
    assert_non_null(f->e);
    f->s = qd_steady_derive_named(f->ctx, f->m, f->e, driven ? "driven" : "ignore", names,
                                  driven);
    assert_non_null(f->s);
}

static void done(fixture *f) {
    qd_steady_set_free(&f->set);
    qd_steady_given_free(&f->g);
    qd_steady_free(f->s);
    qd_eom_free(f->e);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
}

static qd_status find(fixture *f, const qd_steady_spec *spec) {
    qd_status st = qd_steady_given_read(f->ctx, f->s, f->m, spec, &f->g);
    if (st != QD_OK)
        return st;
    const qd_steady_given *g = &f->g;
    return qd_steady_find_all(f->ctx, f->s, g->nvals, g->syms, g->vals, g->xfix, g->wfix,
                              g->pfix, g->pguess, &g->start, &f->set);
}

static void conical_at(void **state) {
    (void)state;
    fixture f = {0};
    load(&f, "phi", false);
    qd_steady_spec spec = {.at = "theta = pi/3"};
    assert_int_equal(find(&f, &spec), QD_OK);
    double m = 1.1, a = 0.9, g = 9.81, th = QT_PI / 3, w = sqrt(g / (a * cos(th)));
    assert_true(f.g.xfix[0] && !f.g.wfix[0] && !f.g.pfix[0]);
    assert_int_equal(f.set.count, 2); /* it turns either way */
    for (size_t k = 0; k < 2; k++) {
        const qd_steady_point *p = &f.set.pts[k];
        assert_true(fabs(p->x[0] - th) < 1e-15);
        assert_true(fabs(fabs(p->w[0]) - w) < 1e-10 * w);
        assert_true(fabs(p->p[0] - m * a * a * sin(th) * sin(th) * p->w[0]) < 1e-10);
    }
    /* the held value's expression is kept (pi/3, exact) for a scan */
    assert_non_null(f.g.held[0]);
    assert_null(f.g.held[1]);
    /* printed: one analysis each; the report needs them all */
    qd_stability an[2];
    for (size_t k = 0; k < 2; k++)
        assert_int_equal(qd_stability_analyze(f.ctx, f.s, f.g.nvals, f.g.syms, f.g.vals,
                                              &f.set.pts[k], &an[k]), QD_OK);
    /* frequency^2 = (g/(a cos th0)) (1 + 3 cos^2 th0) (Byerly) */
    double f2 = g / (a * cos(th)) * (1 + 3 * cos(th) * cos(th));
    assert_true(an[0].nfreq == 1 && fabs(an[0].freq[0] * an[0].freq[0] - f2) < 1e-9 * f2);
    qd_buf b = QD_BUF_INIT;
    qd_stability_report rep = {f.s, &f.g, &f.set, an, "spherical"};
    assert_int_equal(qd_stability_print(f.ctx, &rep, true, &b), QD_OK);
    assert_non_null(strstr(qd_buf_str(&b), "\"mass_matrix\""));
    qd_buf_free(&b);
    for (size_t k = 0; k < 2; k++)
        qd_stability_free(&an[k]);
    done(&f);
}

static void conical_momentum(void **state) {
    (void)state;
    fixture f = {0};
    load(&f, "phi", false);
    qd_steady_spec spec = {.momenta = "p_phi = 2*m", .guess = "theta = 1"};
    assert_int_equal(find(&f, &spec), QD_OK);
    double m = 1.1, a = 0.9, g = 9.81, p = 2 * m;
    const qd_steady_point *pt = &f.set.pts[0];
    double th = pt->x[0], s = sin(th);
    assert_true(f.g.pfix[0] && pt->p[0] == p);
    assert_true(fabs(p * p * cos(th) - m * m * a * a * a * g * s * s * s * s) < 1e-9);
    done(&f);
}

static void driven_rate(void **state) {
    (void)state;
    fixture f = {0};
    load(&f, "phi' = w", true);
    qd_steady_spec spec = {.rates = "phi' = w", .rates_field = "driven", .guess = "theta=1"};
    assert_int_equal(find(&f, &spec), QD_OK);
    assert_true(f.g.wfix[0] && f.g.start.w[0] == 4);
    assert_non_null(f.g.held[1]); /* w: it follows a scan of w */
    /* driven at w = 4: cos th0 = g/(a w^2) */
    bool found = false;
    for (size_t k = 0; k < f.set.count; k++)
        found |= fabs(cos(f.set.pts[k].x[0]) - 9.81 / (0.9 * 16)) < 1e-10;
    assert_true(found);
    done(&f);
}

/* The error is QD_ERR_ARG, named by field, at [off, off + len) of its text. */
static void expect_error(const char *names, bool driven, const qd_steady_spec *spec,
                         const char *field, size_t off, size_t len, const char *message,
                         const char *hint) {
    fixture f = {0};
    load(&f, names, driven);
    assert_int_equal(qd_steady_given_read(f.ctx, f.s, f.m, spec, &f.g), QD_ERR_ARG);
    const qd_diag *d = qd_ctx_diag(f.ctx);
    if (strcmp(d->name, field) || !d->located || d->offset != off || d->length != len ||
        !strstr(d->message, message) || (hint && !strstr(d->hint, hint)))
        fail_msg("%s: '%s' at %zu+%zu (hint '%s'), wanted '%s' at %zu+%zu", d->name, d->message,
                 d->offset, d->length, d->hint, message, off, len);
    assert_null(f.g.xfix); /* zeroed on an error */
    done(&f);
}

static void errors(void **state) {
    (void)state;
    expect_error("phi", false, &(qd_steady_spec){.at = "theta=1, thet=2"}, "at", 9, 4,
                 "'thet' is not a coordinate", "did you mean 'theta'?");
    expect_error("phi", false, &(qd_steady_spec){.at = "theta = 2*pj"}, "at", 10, 2,
                 "unknown name 'pj'", "did you mean 'pi'?");
    expect_error("phi", false, &(qd_steady_spec){.rates = "phi' = 2",
                 .rates_field = "omega", .guess = "phi' = 3"}, "guess", 0, 4,
                 "is given: a guess cannot change it", NULL);
    expect_error("phi", false, &(qd_steady_spec){.rates = "phi = 2", .rates_field = "omega"},
                 "omega", 0, 3, "a rate is written with a prime", NULL);
    expect_error("phi", false, &(qd_steady_spec){.at = "phi = 2"}, "at", 0, 3,
                 "phi is cyclic here", NULL);
    expect_error("phi", true, &(qd_steady_spec){.momenta = "p_phi = 1"}, "momentum", 0, 9,
                 "momenta are given when they are free", NULL);
    /* the cyclic list itself */
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qd_model_parse(ctx, SPHERICAL, NULL);
    qd_eom *e = qd_eom_derive(ctx, m);
    assert_null(qd_steady_derive_named(ctx, m, e, "ignore", "phi, phi", false));
    assert_string_equal(qd_ctx_diag(ctx)->name, "ignore");
    assert_int_equal(qd_ctx_diag(ctx)->offset, 5);
    qd_eom_free(e);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(conical_at),
        cmocka_unit_test(conical_momentum),
        cmocka_unit_test(driven_rate),
        cmocka_unit_test(errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
