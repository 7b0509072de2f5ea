/*
 * tests/mech/test_metric_read.c - a force read by its covariant components
 * (qd_metric_force_read, qdot/metric.h, what `qdot metric --force` reads),
 * checked against the geometry of polar coordinates (Desloge ch. 47):
 *
 *   a particle of mass 1 in the plane in (r, phi) has the metric
 *   g = diag(1, r^2), so h_r = 1, h_phi = |r|; the force with the physical
 *   components (F_r, F_phi) = (a, b) has the covariant ones G = (a, b r)
 *   (G_i = F . dx/dq_i), and reading "a, b*r" and projecting back
 *   (qd_metric_force: phys_i = G_i / h_i) gives (a, b) for r > 0, raising gives
 *   g^ij G_j = (a, b/r);
 *   the errors are located in the option's text: a third component under
 *   the extra component, too few under the whole text (QD_ERR_ARG, with a
 *   hint saying how many), a component that does not read under its place
 *   in the whole list, an unknown name under the name.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/metric.h"
#include "util/check.h"

static const char POLAR[] = "coordinates r, phi\nparameters a = 2, b = 3\n"
                            "particle 1 at (r*cos(phi), r*sin(phi))\n";

typedef struct fix {
    qd_ctx *ctx;
    qd_model *m;
    qd_metric *g;
} fix;

static void fix_open(fix *f) {
    f->ctx = qd_ctx_new();
    assert_non_null(f->ctx);
    f->m = qt_parse_ok(f->ctx, POLAR);
    f->g = qd_metric_new(f->ctx, f->m);
    if (!f->g)
        fail_msg("qd_metric_new: %s", qd_ctx_message(f->ctx));
    assert_int_equal(f->g->n, 2);
}

static void fix_close(fix *f) {
    qd_metric_free(f->g);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
}

static void test_polar(void **state) {
    (void)state;
    fix f;
    fix_open(&f);
    /* diag(1, r^2) */
    qt_assert_is(f.ctx, f.g->g[0], "1");
    qt_assert_is(f.ctx, f.g->g[1], "0");
    qt_assert_is(f.ctx, f.g->g[2], "0");
    qt_assert_is(f.ctx, f.g->g[3], "r^2");
    const qd_expr *G[2], *up[2], *phys[2];
    assert_int_equal(qd_metric_force_read(f.ctx, f.g, "a, b*r", G), QD_OK);
    qt_assert_is(f.ctx, G[0], "a");
    qt_assert_is(f.ctx, G[1], "b*r");
    assert_int_equal(qd_metric_force(f.ctx, f.g, G, up, phys, NULL), QD_OK);
    /* physical components: G_i / h_i with h = (1, sqrt(r^2) = |r|): b for r > 0 */
    qt_assert_is(f.ctx, phys[0], "a");
    qt_assert_is(f.ctx, phys[1], "b*r/abs(r)");
    qt_assert_is(f.ctx, up[0], "a");
    qt_assert_is(f.ctx, up[1], "b/r");
    /* brackets hold commas; a trailing comma ends the list */
    assert_int_equal(qd_metric_force_read(f.ctx, f.g, "atan2(r, 1), 0,", G), QD_OK);
    qt_assert_is(f.ctx, G[0], "atan2(r, 1)");
    qt_assert_is(f.ctx, G[1], "0");
    fix_close(&f);
}

/* The read of text fails with st, located at [off, off + len). */
static void located(fix *f, const char *text, qd_status st, size_t off, size_t len) {
    const qd_expr *G[2];
    assert_int_equal(qd_metric_force_read(f->ctx, f->g, text, G), st);
    const qd_diag *d = qd_ctx_diag(f->ctx);
    assert_true(d->located);
    assert_int_equal(d->offset, off);
    if (len)
        assert_int_equal(d->length, len);
    qd_ctx_clear_error(f->ctx);
}

static void test_errors(void **state) {
    (void)state;
    fix f;
    fix_open(&f);
    /* a third component: the caret under it */
    located(&f, "a, b*r, 1", QD_ERR_ARG, 8, 1);
    assert_int_equal(qd_metric_force_read(f.ctx, f.g, "a, b*r, 1", (const qd_expr *[2]){0}),
                     QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_diag(f.ctx)->message, "2 coordinates"));
    assert_non_null(strstr(qd_ctx_diag(f.ctx)->hint, "give 2 covariant components"));
    qd_ctx_clear_error(f.ctx);
    /* one component for two coordinates: the whole text */
    located(&f, "a*r", QD_ERR_ARG, 0, 3);
    /* a component that does not read: in the whole text, past the first */
    const qd_expr *G[2];
    assert_int_not_equal(qd_metric_force_read(f.ctx, f.g, "a, )", G), QD_OK);
    assert_true(qd_ctx_diag(f.ctx)->located);
    assert_true(qd_ctx_diag(f.ctx)->offset >= 3);
    qd_ctx_clear_error(f.ctx);
    /* an unknown name, under it */
    assert_int_not_equal(qd_metric_force_read(f.ctx, f.g, "a, zeta", G), QD_OK);
    assert_true(qd_ctx_diag(f.ctx)->located);
    assert_int_equal(qd_ctx_diag(f.ctx)->offset, 3);
    qd_ctx_clear_error(f.ctx);
    fix_close(&f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_polar),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
