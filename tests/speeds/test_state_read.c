/*
 * tests/speeds/test_state_read.c - a state of a model in generalized speeds
 * read from text (qd_speeds_state_read, qdot/speeds.h, what `qdot eom --at`
 * reads for a model with speeds), checked by the motion it gives:
 *
 *   a particle in the central field V = -k/r in polar coordinates with the
 *   speeds v = r' and the areal velocity A = r^2 theta'/2: at
 *   "r=2, v=0, A=1.5, k=1" (m = 1) the kinematics give r' = v = 0 and
 *   theta' = 2A/r^2 = 0.75, and the equations give Kepler's second law
 *   A' = 0 and the radial v' = r theta'^2 - k/(m r^2) = 0.875;
 *   a velocity named in the text is refused even at 0 (the velocities
 *   follow from the speeds), the caret under its name and the hint naming
 *   the speeds; a misspelt speed is the state reader's located error.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/speeds.h"
#include "util/check.h"

static const char AREAL[] = "coordinates r, theta\nparameters m = 1, k = 3\n"
                            "particle m at (r*cos(theta), r*sin(theta))\nV = -k/r\n"
                            "speeds v = r', A = r^2*theta'/2\n";

typedef struct fix {
    qd_ctx *ctx;
    qd_model *m;
    qd_speeds_eom *e;
    qd_state st;
} fix;

static void fix_open(fix *f) {
    memset(f, 0, sizeof *f);
    f->ctx = qd_ctx_new();
    assert_non_null(f->ctx);
    f->m = qt_parse_ok(f->ctx, AREAL);
    f->e = qd_speeds_derive(f->ctx, f->m, NULL);
    if (!f->e)
        fail_msg("qd_speeds_derive: %s", qd_ctx_message(f->ctx));
    assert_int_equal(f->e->n, 2);
    assert_int_equal(f->e->m, 2);
}

static void fix_close(fix *f) {
    qd_state_free(&f->st);
    qd_speeds_eom_free(f->e);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
}

static void test_kepler(void **state) {
    (void)state;
    fix f;
    fix_open(&f);
    assert_int_equal(qd_speeds_state_read(f.ctx, f.m, f.e, "r=2, v=0, A=1.5, k=1", &f.st), QD_OK);
    double qd[2], ud[2];
    assert_int_equal(qd_speeds_eval(f.ctx, f.e, f.st.n, f.st.syms, f.st.vals, qd, ud, NULL),
                     QD_OK);
    assert_true(fabs(qd[0]) < 1e-12);          /* r' = v */
    assert_true(fabs(qd[1] - 0.75) < 1e-12);   /* theta' = 2A/r^2 */
    /* the speeds in e's order: v' radial, A' = 0 (a central force) */
    size_t iv = strcmp(qd_expr_name(f.e->u[0]), "v") ? 1 : 0, iA = 1 - iv;
    assert_true(fabs(ud[iv] - 0.875) < 1e-12);
    assert_true(fabs(ud[iA]) < 1e-12);
    fix_close(&f);
}

static void test_velocity_refused(void **state) {
    (void)state;
    fix f;
    fix_open(&f);
    const char *text = "r=1, theta'=0, v=0.1";
    assert_int_equal(qd_speeds_state_read(f.ctx, f.m, f.e, text, &f.st), QD_ERR_ARG);
    const qd_diag *d = qd_ctx_diag(f.ctx);
    assert_true(d->located);
    assert_int_equal(d->offset, 5);
    assert_int_equal(d->length, strlen("theta'"));
    assert_non_null(strstr(d->message, "theta' is given"));
    assert_non_null(strstr(d->hint, "give the speeds"));
    qd_ctx_clear_error(f.ctx);
    qd_state_free(&f.st);
    /* an unknown name: located by the state reader */
    text = "r=1, vv=0.1";
    assert_int_equal(qd_speeds_state_read(f.ctx, f.m, f.e, text, &f.st), QD_ERR_ARG);
    assert_true(qd_ctx_diag(f.ctx)->located);
    assert_int_equal(qd_ctx_diag(f.ctx)->offset, 5);
    fix_close(&f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_kepler),
        cmocka_unit_test(test_velocity_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
