/*
 * tests/scene/test_scene_choose.c - choosing what a picture draws and
 * sampling it (qdot/scene.h, issue 31):
 *
 *   - --draw's words: a kind takes every point of it, a name one point; a
 *     name that is no point, or nothing to draw, refused naming the field;
 *   - springs and traces by name, the origin allowed as a spring's end only;
 *   - the places as outputs of a run of the double pendulum: at the end of
 *     the run the output x2 = l1 sin(theta1) + l2 sin(theta2), y2 = -l1
 *     cos(theta1) - l2 cos(theta2) of the run's own final angles;
 *   - the frames: 60 a second plus the last (181 for 3 s, as the docs say),
 *     at most 3601; each frame the row nearest its time (never a blend),
 *     the energy as E - E(t0).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "qdot/scene.h"
#include "sim/sim_fixture.h"

static const char pendulum[] =
    "coordinates theta1, theta2\n"
    "parameters l1 = 1, l2 = 2\n"
    "x1 = l1*sin(theta1)\n"
    "y1 = -l1*cos(theta1)\n"
    "x2 = x1 + l2*sin(theta2)\n"
    "y2 = y1 - l2*cos(theta2)\n"
    "T = (x1'^2 + y1'^2 + x2'^2 + y2'^2)/2\n"
    "V = 9.81*(y1 + y2)\n"
    "initial theta1 = 1.2, theta2 = 0.3\n";

static void test_choose(void **state) {
    (void)state;
    sim_fix *f = sf_load(pendulum);
    qd_scene_point *p = NULL;
    size_t n = 0;
    const char *one[] = {"x2"}, *all[] = {"positions"}, *bad[] = {"x9"};
    assert_int_equal(qd_scene_choose(f->ctx, f->m, one, 1, &p, &n), QD_OK);
    assert_int_equal(n, 1);
    assert_string_equal(p[0].name, "x2,y2");
    qd_scene_points_free(p);
    assert_int_equal(qd_scene_choose(f->ctx, f->m, all, 1, &p, &n), QD_OK);
    assert_int_equal(n, 2);
    qd_scene_points_free(p);
    assert_int_equal(qd_scene_choose(f->ctx, f->m, NULL, 0, &p, &n), QD_OK); /* the default */
    assert_int_equal(n, 2);
    size_t at[2], ends[2];
    const char *orig[] = {"origin"}, *good[] = {"origin,x2"}, *nocomma[] = {"x1"},
               *twice[] = {"x1,y1"};
    assert_int_equal(qd_scene_pairs(f->ctx, p, n, good, 1, ends), QD_OK);
    assert_true(ends[0] == QD_SCENE_ORIGIN && ends[1] == 1);
    assert_int_equal(qd_scene_named(f->ctx, p, n, one, 1, at), QD_OK);
    assert_int_equal(at[0], 1);
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_scene_named(f->ctx, p, n, orig, 1, at), QD_ERR_ARG);
    assert_string_equal(qd_ctx_diag(f->ctx)->name, "trace");
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_scene_pairs(f->ctx, p, n, nocomma, 1, ends), QD_ERR_ARG);
    assert_string_equal(qd_ctx_diag(f->ctx)->name, "spring");
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_scene_pairs(f->ctx, p, n, twice, 1, ends), QD_ERR_ARG); /* one point */
    qd_scene_points_free(p);
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_scene_choose(f->ctx, f->m, bad, 1, &p, &n), QD_ERR_ARG);
    assert_string_equal(qd_ctx_diag(f->ctx)->name, "draw");
    assert_non_null(strstr(qd_ctx_message(f->ctx), "x1,y1; x2,y2"));
    assert_null(p);
    sf_free(f);
    /* a model given by T and V in its coordinates: nothing to draw */
    f = sf_load("coordinates x\nT = x'^2/2\nV = x^2/2\n");
    qd_ctx_clear_error(f->ctx);
    assert_int_equal(qd_scene_choose(f->ctx, f->m, NULL, 0, &p, &n), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(f->ctx), "nothing to draw"));
    sf_free(f);
}

static void test_outputs(void **state) {
    (void)state;
    sim_fix *f = sf_load(pendulum);
    qd_scene_point *p = NULL;
    size_t n = 0;
    assert_int_equal(qd_scene_choose(f->ctx, f->m, NULL, 0, &p, &n), QD_OK);
    assert_int_equal(qd_scene_noutputs(p, n), 6);
    assert_int_equal(qd_scene_add_outputs(f->ctx, f->s, f->m, p, n), QD_OK);
    assert_int_equal(qd_sim_compile(f->s), QD_OK);
    assert_int_equal(sf_run(f, QD_SIM_DOP853, 2, 0, 1e-10, false), QD_OK);
    int c = sf_col(f, QD_SIM_DOP853, "scene:x2,y2.x"), t1 = sf_col(f, QD_SIM_DOP853, "theta1"),
        t2 = sf_col(f, QD_SIM_DOP853, "theta2");
    assert_true(c > 0 && t1 > 0 && t2 > 0);
    double a = f->last[t1], b = f->last[t2];
    assert_true(fabs(f->last[c] - (sin(a) + 2 * sin(b))) < 1e-12);
    assert_true(fabs(f->last[c + 1] - (-cos(a) - 2 * cos(b))) < 1e-12);
    assert_true(f->last[c + 2] == 0);
    qd_scene_points_free(p);
    sf_free(f);
}

static void test_sample(void **state) {
    (void)state;
    assert_int_equal(qd_scene_nframes(0, 3), 181);
    assert_int_equal(qd_scene_nframes(0, 1000), QD_SCENE_MAX_FRAMES + 1);
    assert_int_equal(qd_scene_nframes(0, 0), 3);
    /* one point moving as x = t^2 on rows every 0.3 s (a fixed step), the
     * energy column 1 as 5 + t */
    qd_scene_point pt = {.name = "p1", .kind = QD_SCENE_PARTICLE};
    enum { NR = 11, W = 5 };
    double rows[NR * W];
    for (size_t k = 0; k < NR; k++) {
        double t = 0.3 * (double)k;
        double r[W] = {t, 5 + t, t * t, 0, 0};
        memcpy(rows + k * W, r, sizeof r);
    }
    qd_scene_frames fr;
    assert_int_equal(qd_scene_sample(NULL, &pt, 1, rows, NR, 1, 2, W, 0, 3, &fr), QD_OK);
    assert_int_equal(fr.nframes, 181);
    for (size_t f = 0; f < fr.nframes; f++) {
        double want = 3.0 * (double)f / 180.0, t = fr.t[f];
        double k = round(t / 0.3); /* a row's own time, never between two */
        assert_true(fabs(t - 0.3 * k) < 1e-12);
        assert_true(fabs(t - want) <= 0.15 + 1e-12);
        assert_true(fr.pos[3 * f] == t * t || fabs(fr.pos[3 * f] - t * t) < 1e-12);
        assert_true(fabs(fr.energy[f] - t) < 1e-12);
    }
    qd_scene_frames_free(&fr);
    /* no energy column: none in the frames */
    assert_int_equal(qd_scene_sample(NULL, &pt, 1, rows, NR, QD_SCENE_NONE, 2, W, 0, 3, &fr),
                     QD_OK);
    assert_null(fr.energy);
    qd_scene_frames_free(&fr);
    /* the outputs beyond the row: refused */
    assert_int_equal(qd_scene_sample(NULL, &pt, 1, rows, NR, 1, 3, W, 0, 3, &fr), QD_ERR_ARG);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_choose),
        cmocka_unit_test(test_outputs),
        cmocka_unit_test(test_sample),
    };
    return cmocka_run_group_tests(tests, 0, NULL);
}
