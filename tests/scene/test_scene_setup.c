/*
 * tests/scene/test_scene_setup.c - a picture set up as qdot animate takes
 * it (qd_scene_setup_new, qd_scene_setup_record), on the double pendulum
 * (Goldstein sec. 1.4: two rods l1, l2 from a fixed pivot):
 *
 *   - at every frame the rods keep their lengths, |P1| = l1 and |P2 - P1| =
 *     l2 (the positions are the model's own expressions of the run's
 *     angles), and the picture finds both rods, origin-P1 and P1-P2, and
 *     the plane of the motion (x, y);
 *   - a spring asked for comes first among the links, then the rods; the
 *     trace is the point named; named positions weigh 1;
 *   - the energy is kept (a conservative system): the frames' E - E(t0)
 *     below the run's tolerance;
 *   - a word naming no point refused with the option field it is in;
 *   - a progress callback that asks to stop (a Ctrl-C) ends the run after
 *     a whole row: the frames cover [0, the stop], the first row past it,
 *     and are still the motion (the rods keep their lengths).
 */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "qdot/qdot.h"
#include "qdot/scene.h"
#include "qdot/simsetup.h"

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

typedef struct fix {
    qd_ctx *ctx;
    qd_model *m;
    qd_sim_setup *set;
} fix;

static fix load(void) {
    fix f = {qd_ctx_new(), NULL, NULL};
    f.m = qd_model_parse(f.ctx, pendulum, NULL);
    assert_non_null(f.m);
    f.set = qd_sim_setup_new(f.ctx, f.m, false);
    assert_non_null(f.set);
    return f;
}

static void unload(fix *f) {
    qd_sim_setup_free(f->set);
    qd_model_free(f->m);
    qd_ctx_free(f->ctx);
}

static void test_double_pendulum(void **state) {
    (void)state;
    fix f = load();
    const char *traces[] = {"x2"}, *springs[] = {"origin,x2"};
    qd_scene_spec sp = {.traces = traces, .ntraces = 1, .springs = springs, .nsprings = 1,
                        .title = "pendulum"};
    qd_scene_setup *sc = qd_scene_setup_new(f.ctx, f.set, f.m, &sp);
    assert_non_null(sc);
    qd_sim_setup_opts so = {.t_end = "3", .rtol = "1e-10", .atol = "1e-12"};
    qd_sim_opts o;
    assert_int_equal(qd_sim_setup_options(f.set, &so, &o), QD_OK);
    qd_sim_stats st;
    assert_int_equal(qd_scene_setup_record(sc, &o, NULL, NULL, &st), QD_OK);
    assert_int_equal(qd_scene_setup_record(sc, &o, NULL, NULL, NULL), QD_ERR_ARG); /* once */
    const qd_scene *v = qd_scene_setup_scene(sc);
    assert_int_equal(v->npts, 2);
    assert_string_equal(v->model, "pendulum");
    assert_int_equal(v->fr->nframes, qd_scene_nframes(0, 3));
    assert_true(v->conservative);
    assert_non_null(v->fr->energy);
    for (size_t k = 0; k < v->fr->nframes; k++) {
        const double *p = v->fr->pos + 6 * k; /* P1 then P2, x y z each */
        assert_true(fabs(hypot(p[0], p[1]) - 1) < 1e-9);
        assert_true(fabs(hypot(p[3] - p[0], p[4] - p[1]) - 2) < 1e-9);
        assert_true(p[2] == 0 && p[5] == 0);
        assert_true(fabs(v->fr->energy[k]) < 1e-6);
    }
    assert_true(v->plane[0] == 0 && v->plane[1] == 1);
    assert_true(v->mass[0] == 1 && v->mass[1] == 1);
    assert_true(v->ntraces == 1 && v->traces[0] == 1);
    /* the spring, then the rods origin-P1 and P1-P2 (either order, either way round) */
    assert_int_equal(v->nlinks, 3);
    assert_true(v->links[0].spring && v->links[0].a == QD_SCENE_ORIGIN && v->links[0].b == 1);
    bool rod0 = false, rod1 = false;
    for (size_t j = 1; j < 3; j++) {
        const qd_scene_link *l = &v->links[j];
        assert_false(l->spring);
        rod0 |= (l->a == QD_SCENE_ORIGIN && l->b == 0) || (l->b == QD_SCENE_ORIGIN && l->a == 0);
        rod1 |= (l->a == 0 && l->b == 1) || (l->a == 1 && l->b == 0);
    }
    assert_true(rod0 && rod1);
    qd_scene_setup_free(sc);
    unload(&f);
}

typedef struct stopper {
    double at, last;
    int calls;
} stopper;

static int stop_at(void *data, double t) {
    stopper *s = data;
    s->calls++;
    s->last = t;
    return t >= s->at;
}

static void test_stopped_by_progress(void **state) {
    (void)state;
    fix f = load();
    qd_scene_spec sp = {.title = "pendulum"};
    qd_scene_setup *sc = qd_scene_setup_new(f.ctx, f.set, f.m, &sp);
    assert_non_null(sc);
    qd_sim_setup_opts so = {.t_end = "10", .rtol = "1e-10", .atol = "1e-12"};
    qd_sim_opts o;
    assert_int_equal(qd_sim_setup_options(f.set, &so, &o), QD_OK);
    stopper s = {.at = 1};
    assert_int_equal(qd_scene_setup_record(sc, &o, stop_at, &s, NULL), QD_OK);
    const qd_scene *v = qd_scene_setup_scene(sc);
    double t_last = v->fr->t[v->fr->nframes - 1];
    /* rows come at the frames' spacing: the stop is the first row at or past 1 */
    double frame = 10.0 / (double)(qd_scene_nframes(0, 10) - 1);
    assert_true(s.last >= 1 && s.last < 1 + frame + 1e-12);
    assert_true(t_last <= s.last + 1e-12 && t_last > 1 - frame);
    assert_true(v->fr->nframes > 2 && v->fr->nframes < qd_scene_nframes(0, 10));
    for (size_t k = 0; k < v->fr->nframes; k++) {
        const double *p = v->fr->pos + 6 * k;
        assert_true(fabs(hypot(p[0], p[1]) - 1) < 1e-9);
        assert_true(fabs(hypot(p[3] - p[0], p[4] - p[1]) - 2) < 1e-9);
    }
    qd_scene_setup_free(sc);
    unload(&f);
}

static void refused(const char *const *draws, const char *const *traces,
                    const char *const *springs, const char *field) {
    fix f = load();
    qd_scene_spec sp = {draws, draws != NULL, traces, traces != NULL, springs, springs != NULL,
                        NULL};
    assert_null(qd_scene_setup_new(f.ctx, f.set, f.m, &sp));
    assert_int_equal(qd_ctx_status(f.ctx), QD_ERR_ARG);
    assert_string_equal(qd_ctx_diag(f.ctx)->name, field);
    unload(&f);
}

static void test_refusals(void **state) {
    (void)state;
    const char *bad[] = {"x9"}, *nocomma[] = {"x1"};
    refused(bad, NULL, NULL, "draw");
    refused(NULL, bad, NULL, "trace");
    refused(NULL, NULL, nocomma, "spring");
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_double_pendulum),
        cmocka_unit_test(test_refusals),
        cmocka_unit_test(test_stopped_by_progress),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
