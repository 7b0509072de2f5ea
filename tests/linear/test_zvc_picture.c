/*
 * tests/linear/test_zvc_picture.c - the zero-velocity picture of qdot/zvc.h
 * (issue 31): the box read from "x=A:B, y=C:D" (ends in the parameters, an
 * unknown coordinate located at its name), and for the isotropic
 * oscillator V = k (x^2 + y^2)/2 the curve W = h is the circle of radius
 * sqrt(2 h / k) around the one equilibrium, a minimum with W = 0 there.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/zvc.h"

static const char OSC2[] = "coordinates x, y\nparameters m = 1, k = 4\n"
                           "T = m/2*(x'^2 + y'^2)\nV = k/2*(x^2 + y^2)\n";

typedef struct fix {
    qd_ctx *ctx;
    qd_model *m;
    qd_eom *e;
} fix;

static fix load(void) {
    fix f = {qd_ctx_new(), NULL, NULL};
    qd_diag d;
    f.m = qd_model_parse(f.ctx, OSC2, &d);
    assert_non_null(f.m);
    f.e = qd_eom_derive(f.ctx, f.m);
    assert_non_null(f.e);
    return f;
}

static void unload(fix *f) {
    qd_eom_free(f->e);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
}

static void test_box_read(void **state) {
    (void)state;
    fix f = load();
    qd_zvc_box box = {0};
    assert_int_equal(qd_zvc_box_read(f.ctx, f.m, f.e, "y=-1:sqrt(k), x=-(1):2", &box), QD_OK);
    assert_int_equal(box.ix, 1);
    assert_int_equal(box.iy, 0);
    assert_true(box.lo[0] == -1 && box.hi[0] == 2 && box.lo[1] == -1 && box.hi[1] == 2);
    const char *bad = "x=-1:1, yy=0:1";
    assert_int_equal(qd_zvc_box_read(f.ctx, f.m, f.e, bad, &box), QD_ERR_ARG);
    const qd_diag *d = qd_ctx_diag(f.ctx);
    assert_true(d->located);
    assert_int_equal(d->offset, 8);
    assert_int_equal(d->length, 2);
    assert_non_null(strstr(d->message, "not an independent coordinate"));
    qd_ctx_clear_error(f.ctx);
    assert_int_equal(qd_zvc_box_read(f.ctx, f.m, f.e, "x=1:-1, y=0:1", &box), QD_ERR_ARG);
    qd_ctx_clear_error(f.ctx);
    assert_int_equal(qd_zvc_box_read(f.ctx, f.m, f.e, "x=0:1, x=0:1", &box), QD_ERR_ARG);
    qd_ctx_clear_error(f.ctx);
    assert_int_equal(qd_zvc_box_read(f.ctx, f.m, f.e, "x=0:1", &box), QD_ERR_ARG);
    qd_ctx_clear_error(f.ctx);
    assert_int_equal(qd_zvc_box_read(f.ctx, f.m, f.e, "x=0:zz, y=0:1", &box), QD_ERR_ARG);
    assert_int_equal(qd_ctx_diag(f.ctx)->offset, 4); /* at zz in the whole text */
    unload(&f);
}

static void test_circle(void **state) {
    (void)state;
    fix f = load();
    qd_zvc z;
    assert_int_equal(qd_zvc_derive(f.ctx, f.m, f.e, &z), QD_OK);
    qd_zvc_box box = {.nx = 200, .ny = 200};
    assert_int_equal(qd_zvc_box_read(f.ctx, f.m, f.e, "x=-2:2, y=-2:2", &box), QD_OK);
    const qd_expr *syms[2] = {qd_model_param(f.m, 0), qd_model_param(f.m, 1)};
    const double vals[2] = {1, 4};
    double h = 2; /* radius sqrt(2 h / k) = 1 */
    qd_zvc_picture p;
    assert_int_equal(qd_zvc_picture_make(f.ctx, f.m, f.e, &z, &box, 2, syms, vals, h, true, &p),
                     QD_OK);
    assert_int_equal(p.curves.count, 1);
    assert_true(p.curves.lines[0].closed);
    for (size_t i = 0; i < p.curves.lines[0].count; i++) {
        double x = p.curves.lines[0].x[i], y = p.curves.lines[0].y[i];
        assert_true(fabs(hypot(x, y) - 1) < 1e-3); /* linear interpolation on 0.02 cells */
    }
    assert_int_equal(p.eq.count, 1);
    assert_true(fabs(p.eq.pts[0].q[0]) < 1e-9 && fabs(p.eq.pts[0].q[1]) < 1e-9);
    assert_int_equal(p.eq.pts[0].kind, QD_EQ_MINIMUM);
    assert_true(fabs(p.eq_W[0]) < 1e-12);
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_zvc_json(f.ctx, f.e, &p, &b), QD_OK);
    assert_int_equal(qd_zvc_csv(f.ctx, f.e, &p, &b), QD_OK);
    assert_int_equal(qd_zvc_print(f.ctx, f.e, &p, &b), QD_OK);
    qd_buf_free(&b);
    qd_zvc_picture_free(&p);
    unload(&f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_box_read),
        cmocka_unit_test(test_circle),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
