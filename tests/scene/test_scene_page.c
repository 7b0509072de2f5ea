/*
 * tests/scene/test_scene_page.c - the scene of a picture put together
 * (qdot/scene.h, issue 31): the double pendulum of two particles, m1 = 2 on
 * a rod l1 = 1.5 from the pivot and m2 = 3 on a rod l2 = 0.7 from m1,
 * moving along a prescribed planar motion theta1(t), theta2(t):
 *
 *   - qd_scene_masses: the particles' masses m1, m2; a named position 1;
 *   - qd_scene_links: a spring asked for (the pivot to m2) first, then
 *     exactly two rods, pivot-m1 and m1-m2, with the lengths l1 and l2 at
 *     every frame; the drawing plane x-y (axes 0 and 1); a motion out of
 *     the plane (m2 lifted along z) is 3-D;
 *   - qd_scene_json: valid JSON whose points carry the masses, whose links
 *     are those, and whose frames are the positions l1 (sin, -cos)(theta1),
 *     ... at the frame times t[f] (to the 7 digits written);
 *   - qd_scene_record: a real run of the pendulum sampled at the frames
 *     keeps both rod lengths and the energy at every frame, and the frame
 *     times step by the frames' spacing; qd_scene_html puts that scene's
 *     JSON in the page in place of its marker.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/qdot.h"
#include "util/jsonwalk.h"

#define L1 1.5
#define L2 0.7
#define NF 40

static const char pendulum[] = "coordinates theta1, theta2\n"
                               "parameters m1 = 2, m2 = 3, l1 = 1.5, l2 = 0.7, g = 9.81\n"
                               "particle m1 at l1*(sin(theta1), -cos(theta1))\n"
                               "particle m2 at l1*(sin(theta1), -cos(theta1)) + "
                               "l2*(sin(theta2), -cos(theta2))\n"
                               "V = -m1*g*l1*cos(theta1) - m2*g*(l1*cos(theta1) + "
                               "l2*cos(theta2))\n";

static double th1(double t) {
    return 0.8 * cos(1.1 * t);
}
static double th2(double t) {
    return 1.3 * sin(0.7 * t) + 0.2;
}

/* The places at time t: m1 then m2, (x, y, z); lift moves m2 along z. */
static void place(double t, double lift, double *p) {
    p[0] = L1 * sin(th1(t));
    p[1] = -L1 * cos(th1(t));
    p[2] = 0;
    p[3] = p[0] + L2 * sin(th2(t));
    p[4] = p[1] - L2 * cos(th2(t));
    p[5] = lift * sin(t);
}

typedef struct fix {
    qd_ctx *ctx;
    qd_model *m;
    qd_scene_point *pts;
    size_t npts;
    double t[NF], pos[NF * 6];
} fix;

static void load(fix *f, double lift) {
    f->ctx = qd_ctx_new();
    f->m = qd_model_parse(f->ctx, pendulum, NULL);
    assert_non_null(f->m);
    assert_int_equal(qd_scene_points(f->ctx, f->m, 0, &f->pts, &f->npts), QD_OK);
    assert_int_equal(f->npts, 2);
    for (size_t k = 0; k < NF; k++) {
        f->t[k] = 0.25 * (double)k;
        place(f->t[k], lift, f->pos + 6 * k);
    }
}

static void unload(fix *f) {
    qd_scene_points_free(f->pts);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
}

static double dist(const double *a, const double *b) {
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

static void test_masses(void **state) {
    (void)state;
    fix f;
    load(&f, 0);
    const qd_expr *syms[2] = {qd_param(f.ctx, "m1"), qd_param(f.ctx, "m2")};
    double vals[2] = {2, 3}, mass[2];
    assert_int_equal(qd_scene_masses(f.ctx, f.pts, 2, 2, syms, vals, mass), QD_OK);
    assert_true(mass[0] == 2 && mass[1] == 3);
    qd_scene_point named = f.pts[0];
    named.kind = QD_SCENE_POSITION;
    named.mass = NULL;
    assert_int_equal(qd_scene_masses(f.ctx, &named, 1, 0, NULL, NULL, mass), QD_OK);
    assert_true(mass[0] == 1);
    unload(&f);
}

static void test_links(void **state) {
    (void)state;
    fix f;
    load(&f, 0);
    size_t spring[2] = {QD_SCENE_ORIGIN, 1};
    qd_scene_link *l = NULL;
    size_t n = 0;
    int plane[2];
    assert_int_equal(qd_scene_links(f.ctx, f.pos, NF, 2, spring, 1, &l, &n, plane), QD_OK);
    assert_int_equal(n, 3);
    assert_true(l[0].spring && l[0].a == QD_SCENE_ORIGIN && l[0].b == 1);
    assert_true(!l[1].spring && l[1].a == QD_SCENE_ORIGIN && l[1].b == 0);
    assert_true(!l[2].spring && l[2].a == 0 && l[2].b == 1);
    const double origin[3] = {0, 0, 0};
    for (size_t k = 0; k < NF; k++) {
        assert_true(fabs(dist(origin, f.pos + 6 * k) - L1) < 1e-12);
        assert_true(fabs(dist(f.pos + 6 * k, f.pos + 6 * k + 3) - L2) < 1e-12);
    }
    assert_true(plane[0] == 0 && plane[1] == 1);
    free(l);
    /* m2 lifted out of the plane: no rod m1-m2 any more, and 3-D */
    for (size_t k = 0; k < NF; k++)
        place(f.t[k], 0.5, f.pos + 6 * k);
    assert_int_equal(qd_scene_links(f.ctx, f.pos, NF, 2, NULL, 0, &l, &n, plane), QD_OK);
    assert_int_equal(n, 1);
    assert_true(l[0].a == QD_SCENE_ORIGIN && l[0].b == 0);
    assert_true(plane[0] == -1 && plane[1] == -1);
    free(l);
    /* a position not finite is refused */
    f.pos[7] = NAN;
    assert_int_equal(qd_scene_links(f.ctx, f.pos, NF, 2, NULL, 0, &l, &n, plane), QD_ERR_ARG);
    assert_null(l);
    unload(&f);
}

static void test_json(void **state) {
    (void)state;
    fix f;
    load(&f, 0);
    const qd_expr *syms[2] = {qd_param(f.ctx, "m1"), qd_param(f.ctx, "m2")};
    double vals[2] = {2, 3}, mass[2];
    assert_int_equal(qd_scene_masses(f.ctx, f.pts, 2, 2, syms, vals, mass), QD_OK);
    qd_scene_link *l = NULL;
    size_t n = 0, trace = 1;
    qd_scene sc = {.model = "double<pendulum>.qd", .method = "rk45", .pts = f.pts, .npts = 2,
                   .mass = mass, .traces = &trace, .ntraces = 1, .conservative = true,
                   .energy_error_max = 1e-9};
    assert_int_equal(qd_scene_links(f.ctx, f.pos, NF, 2, NULL, 0, &l, &n, sc.plane), QD_OK);
    sc.links = l;
    sc.nlinks = n;
    qd_scene_frames fr = {.nframes = NF, .nbodies = 0, .t = f.t, .pos = f.pos};
    sc.fr = &fr;
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_scene_json(&sc, &b), QD_OK);
    const char *j = qd_buf_str(&b);
    assert_true(qt_json_valid(j));
    assert_null(strchr(j, '<')); /* safe inside a <script> */
    const char *title = qt_json_get(j, "model"); /* '<' escaped as \u003c */
    assert_non_null(title);
    assert_int_equal(strncmp(title, "\"double\\u003cpendulum>.qd\"", 26), 0);
    const char *pts = qt_json_get(j, "points");
    assert_int_equal(qt_json_len(pts), 2);
    assert_true(qt_json_num(qt_json_get(qt_json_at(pts, 0), "mass")) == 2);
    assert_true(qt_json_num(qt_json_get(qt_json_at(pts, 1), "mass")) == 3);
    const char *links = qt_json_get(j, "links");
    assert_int_equal(qt_json_len(links), 2);
    assert_true(qt_json_num(qt_json_at(qt_json_at(links, 0), 0)) == -1); /* the pivot */
    assert_true(qt_json_num(qt_json_at(qt_json_at(links, 0), 1)) == 0);
    assert_true(qt_json_num(qt_json_at(qt_json_at(links, 1), 0)) == 0);
    assert_true(qt_json_num(qt_json_at(qt_json_at(links, 1), 1)) == 1);
    const char *plane = qt_json_get(j, "plane");
    assert_true(qt_json_num(qt_json_at(plane, 0)) == 0 && qt_json_num(qt_json_at(plane, 1)) == 1);
    assert_true(qt_json_num(qt_json_at(qt_json_get(j, "traces"), 0)) == 1);
    assert_null(qt_json_get(j, "energy_error")); /* the frames carry none */
    const char *t = qt_json_get(j, "t"), *pos = qt_json_get(j, "pos");
    assert_int_equal(qt_json_len(t), NF);
    assert_int_equal(qt_json_len(pos), NF * 6);
    for (size_t k = 0; k < NF; k++) {
        double tk = qt_json_num(qt_json_at(t, k)), p[6];
        place(tk, 0, p);
        for (size_t c = 0; c < 6; c++)
            assert_true(fabs(qt_json_num(qt_json_at(pos, 6 * k + c)) - p[c]) < 1e-6);
    }
    assert_int_equal(qt_json_len(qt_json_get(j, "rot")), 0);
    qd_buf_free(&b);
    free(l);
    unload(&f);
}

static int progress(void *data, double t) {
    double *last = data;
    assert_true(t >= *last); /* rows in time order */
    *last = t;
    return 0; /* go on */
}

static void test_record_html(void **state) {
    (void)state;
    fix f;
    load(&f, 0);
    qd_eom *e = qd_eom_derive(f.ctx, f.m);
    assert_non_null(e);
    qd_sim *s = qd_sim_new(f.ctx, f.m, e);
    assert_non_null(s);
    assert_int_equal(qd_scene_add_outputs(f.ctx, s, f.m, f.pts, f.npts), QD_OK);
    assert_int_equal(qd_sim_compile(s), QD_OK);
    double q0[2] = {0.5, -0.3}, qd0[2] = {0, 0}, last = -1;
    qd_sim_opts o = {.method = QD_SIM_DOP853, .t_end = 2, .rtol = 1e-11, .atol = 1e-13,
                     .q0 = q0, .qd0 = qd0};
    qd_scene_frames fr;
    qd_sim_stats st;
    assert_int_equal(qd_scene_record(f.ctx, s, &o, f.pts, f.npts, progress, &last, &fr, &st),
                     QD_OK);
    size_t nf = qd_scene_nframes(0, 2);
    assert_int_equal(fr.nframes, nf);
    assert_true(last == 2);
    assert_non_null(fr.energy);
    const double origin[3] = {0, 0, 0};
    for (size_t k = 0; k < nf; k++) {
        const double *p = fr.pos + 6 * k;
        assert_true(fabs(dist(origin, p) - L1) < 1e-9);
        assert_true(fabs(dist(p, p + 3) - L2) < 1e-9);
        assert_true(fabs(fr.energy[k]) < 1e-8);                 /* conserved */
        assert_true(fabs(fr.t[k] - 2.0 * (double)k / (double)(nf - 1)) < 1e-9); /* dense rows */
    }
    double mass[2] = {2, 3};
    qd_scene sc = {.model = "pendulum.qd", .method = "dop853", .pts = f.pts, .npts = 2,
                   .mass = mass, .fr = &fr, .plane = {0, 1}};
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_scene_html(&sc, &b), QD_OK);
    const char *page = qd_buf_str(&b);
    assert_int_equal(strncmp(page, "<!DOCTYPE html>", 15), 0);
    assert_null(strstr(page, "@QDOT_DATA@"));
    assert_non_null(strstr(page, "{\"model\":\"pendulum.qd\""));
    assert_non_null(strstr(page, "</html>"));
    qd_buf_free(&b);
    qd_scene_frames_free(&fr);
    qd_sim_free(s);
    qd_eom_free(e);
    unload(&f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_masses),
        cmocka_unit_test(test_links),
        cmocka_unit_test(test_json),
        cmocka_unit_test(test_record_html),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
