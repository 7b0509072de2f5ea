/*
 * tests/mech/test_routh_ignore.c - the list of coordinates a reduction
 * ignores (qd_routh_ignore_read: `qdot routh --ignore`, `qdot orbit
 * --ignore`, Python's Model.routh).
 *
 * The heavy symmetric top in Euler angles has L = I1/2 (theta'^2 +
 * phi'^2 sin^2 theta) + I3/2 (psi' + phi' cos theta)^2 - M g l cos theta:
 * phi and psi are cyclic, theta is not (Goldstein sec. 5.7, Byerly Art. 20),
 * and it is the kinetic energy and the potential that hold theta.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <string.h>

#include "qdot/qdot.h"
#include "qdot/model.h"
#include "qdot/routh.h"

static const char *TOP =
    "coordinates theta, phi, psi\nparameters I1 = 2, I3 = 1, M = 1, g = 9.81, l = 1\n"
    "T = I1/2*(theta'^2 + phi'^2*sin(theta)^2) + I3/2*(psi' + phi'*cos(theta))^2\n"
    "V = M*g*l*cos(theta)\n";

typedef struct top {
    qd_ctx *ctx;
    qd_model *m;
    qd_eom *e;
} top;

static int setup(void **state) {
    static top t;
    qd_diag d;
    t.ctx = qd_ctx_new();
    t.m = qd_model_parse(t.ctx, TOP, &d);
    t.e = t.m ? qd_eom_derive(t.ctx, t.m) : NULL;
    *state = &t;
    return t.e ? 0 : -1;
}

static int teardown(void **state) {
    top *t = *state;
    qd_eom_free(t->e);
    qd_model_free(t->m);
    qd_ctx_free(t->ctx);
    return 0;
}

/* phi and psi, in the order given, are the top's cyclic coordinates. */
static void cyclic(void **state) {
    top *t = *state;
    const qd_expr *ign[3];
    size_t n = 9;
    const char *where = "x";
    assert_int_equal(qd_routh_ignore_read(t->ctx, t->m, t->e, " psi ,phi", ign, 3, &n, &where),
                     QD_OK);
    assert_int_equal(n, 2);
    assert_ptr_equal(ign[0], qd_model_coord(t->m, 2));
    assert_ptr_equal(ign[1], qd_model_coord(t->m, 1));
    assert_null(where);
}

/* theta is not cyclic: the statement that holds it is named. */
static void not_cyclic(void **state) {
    top *t = *state;
    const qd_expr *ign[3];
    size_t n;
    const char *where = NULL;
    qd_ctx_clear_error(t->ctx);
    assert_int_equal(qd_routh_ignore_read(t->ctx, t->m, t->e, "phi, theta", ign, 3, &n, &where),
                     QD_ERR_ARG);
    assert_non_null(where);
    assert_true(!strcmp(where, "T") || !strcmp(where, "V"));
    assert_non_null(strstr(qd_ctx_message(t->ctx), "theta cannot be ignored"));
    /* without the equations only the names are read */
    assert_int_equal(qd_routh_ignore_read(t->ctx, t->m, NULL, "phi, theta", ign, 3, &n, NULL),
                     QD_OK);
    assert_int_equal(n, 2);
}

/* Names that are not coordinates, twice, empty or too many are refused. */
static void refused(void **state) {
    top *t = *state;
    const qd_expr *ign[2];
    size_t n;
    const char *bad[][2] = {{"phy", "did you mean 'phi'"}, {"g", "parameter"},
                            {"phi, phi", "listed twice"}, {"phi,", "comma-separated"},
                            {"phi, psi, theta", "at most 2"}};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        qd_ctx_clear_error(t->ctx);
        assert_int_equal(qd_routh_ignore_read(t->ctx, t->m, NULL, bad[k][0], ign, 2, &n, NULL),
                         QD_ERR_ARG);
        if (!strstr(qd_ctx_message(t->ctx), bad[k][1]))
            fail_msg("'%s': %s", bad[k][0], qd_ctx_message(t->ctx));
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(cyclic),
        cmocka_unit_test(not_cyclic),
        cmocka_unit_test(refused),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
