/*
 * tests/linear/test_speeds_print.c - what `qdot modes` and `qdot equilibria`
 * print for a model in generalized speeds (qd_speeds_modes_print,
 * qd_speeds_equilibria_print, qd_speeds_equilibria_choose):
 *   the thin uniform disk rolling upright at spin Omega (the disk of
 *     test_speeds_modes.c, after Neimark and Fufaev ch. III sec. 5 and
 *     Routh, Advanced Rigid Dynamics art. 244): stable iff
 *     Omega^2 > g/(3a), the tilt then oscillating with
 *     s^2 = -(4/5)(3 Omega^2 - g/a).  The JSON is read back: its largest
 *     |Im s| squared is (4/5)(3 Omega^2 - g/a) above the threshold and its
 *     largest Re s squared is -(4/5)(3 Omega^2 - g/a) below it, the verdicts
 *     are "stable" and "unstable", the reduced system keeps theta alone and
 *     "state" echoes the state; the text names the frequency;
 *   its equilibria: upright, theta = +-pi/2 exactly, with x, y, phi, psi
 *     free, in the JSON and the text; the state chosen when none is given
 *     is the first of them, at rest.
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

static const char disk[] =
    "coordinates x, y, phi, theta, psi\n"
    "parameters m = 1.4, a = 0.35, g = 9.81\n"
    "body disk mass m inertia disk(m, a) at (x, y, a*sin(theta)) "
    "orientation euler(phi, theta, psi)\n"
    "V = m*g*a*sin(theta)\n"
    "rolls disk on plane((0, 0, 1), (0, 0, 0)) as disk(a)\n"
    "speeds u1 = theta', u2 = omega_space(disk).z, u3 = omega(disk).z\n";

static const double G = 9.81, A = 0.35;

typedef struct world {
    qd_ctx *ctx;
    qd_model *m;
    qd_speeds_eom *e;
    qd_state st; /* q, q', t, the parameters, then the speeds */
} world;

static void open_world(world *w) {
    w->ctx = qd_ctx_new();
    assert_non_null(w->ctx);
    w->m = qt_parse_ok(w->ctx, disk);
    w->e = qd_speeds_derive(w->ctx, w->m, NULL);
    if (!w->e)
        fail_msg("qd_speeds_derive: %s", qd_ctx_message(w->ctx));
    assert_int_equal(qd_state_init(w->ctx, w->m, &w->st), QD_OK);
    assert_int_equal(qd_state_append(w->ctx, &w->st, w->e->m, w->e->u, NULL), QD_OK);
}

static void close_world(world *w) {
    qd_state_free(&w->st);
    qd_speeds_eom_free(w->e);
    qd_model_free(w->m);
    qd_ctx_free(w->ctx);
}

static char *take(qd_buf *b) {
    char *s = malloc(b->len + 1);
    assert_non_null(s);
    memcpy(s, qd_buf_str(b), b->len + 1);
    qd_buf_free(b);
    return s;
}

/* The modes about the state text ("theta=pi/2, u3=6") as JSON or text. */
static char *modes(world *w, const char *text, bool json) {
    assert_int_equal(qd_state_read(w->ctx, w->m, &w->st, text, NULL), QD_OK);
    qd_speeds_linear lin;
    qd_modes_result res;
    assert_int_equal(qd_speeds_linear_about(w->ctx, w->e, w->st.n, w->st.syms, w->st.vals, &lin),
                     QD_OK);
    assert_int_equal(qd_speeds_modes_solve(w->ctx, &lin, &res), QD_OK);
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_speeds_modes_print(w->ctx, w->e, w->st.n, w->st.syms, w->st.vals, &lin,
                                           &res, json, &b),
                     QD_OK);
    qd_modes_result_free(&res);
    qd_speeds_linear_free(&lin);
    return take(&b);
}

/* The [re, im] pairs of "eigenvalues": how many, the largest |re| and |im|. */
static size_t eigen_extremes(const char *json, double *re, double *im) {
    const char *key = "\"eigenvalues\": [";
    const char *p = strstr(json, key);
    assert_non_null(p);
    p += strlen(key);
    size_t n = 0;
    *re = *im = 0;
    while (*p == '[') {
        char *end;
        double x = strtod(p + 1, &end);
        assert_true(end > p + 1 && *end == ',');
        double y = strtod(end + 1, &end);
        assert_true(*end == ']');
        *re = fmax(*re, fabs(x));
        *im = fmax(*im, fabs(y));
        n++;
        p = end + 1;
        while (*p == ',' || *p == ' ' || *p == '\n')
            p++;
    }
    assert_true(*p == ']');
    return n;
}

static void disk_modes_json(void **state) {
    (void)state;
    world w;
    open_world(&w);
    double Oc = sqrt(G / (3 * A));
    /* above the threshold: the tilt oscillates at s^2 = -(4/5)(3 W^2 - g/a) */
    double W = 1.5 * Oc, s2 = -0.8 * (3 * W * W - G / A), re, im;
    char state_text[96];
    snprintf(state_text, sizeof state_text, "theta=pi/2, phi=0.3, u1=0, u2=0, u3=%.17g", W);
    char *json = modes(&w, state_text, true);
    assert_int_equal(eigen_extremes(json, &re, &im), 4); /* y = (theta, u1, u2, u3) */
    assert_true(fabs(im * im + s2) < 1e-9 * fabs(s2));
    assert_true(re < 1e-9 * im);
    assert_non_null(strstr(json, "\"verdict\": \"stable\""));
    assert_non_null(strstr(json, "\"stable\": true"));
    assert_non_null(strstr(json, "\"kept\": [\"theta\"]"));
    assert_non_null(strstr(json, "\"ignorable\": [\"x\", \"y\", \"phi\", \"psi\"]"));
    const char *u3 = strstr(json, "\"u3\": ");
    assert_non_null(u3);
    assert_true(fabs(strtod(u3 + 6, NULL) - W) < 1e-15 * W);
    assert_true(fabs(strtod(strstr(json, "\"theta\": ") + 9, NULL) - PI / 2) < 1e-15);
    free(json);
    /* the text names the frequency sqrt(-s^2) */
    char *text = modes(&w, state_text, false);
    char freq[64];
    snprintf(freq, sizeof freq, "(frequency %.10g rad/s)", sqrt(-s2));
    assert_non_null(strstr(text, freq));
    assert_non_null(strstr(text, "reduced system: (theta, u1, u2, u3); ignorable, dropped: x, "
                                 "y, phi, psi\n"));
    free(text);
    /* below: the tilt falls, s = +-sqrt(s2) real */
    W = 0.8 * Oc;
    s2 = -0.8 * (3 * W * W - G / A);
    snprintf(state_text, sizeof state_text, "u3=%.17g", W);
    json = modes(&w, state_text, true);
    eigen_extremes(json, &re, &im);
    assert_true(fabs(re * re - s2) < 1e-9 * s2);
    assert_non_null(strstr(json, "\"verdict\": \"unstable\""));
    assert_non_null(strstr(json, "\"stable\": false"));
    free(json);
    close_world(&w);
}

static void disk_equilibria(void **state) {
    (void)state;
    world w;
    open_world(&w);
    qd_speeds_equilibria s;
    assert_int_equal(qd_speeds_equilibria_find(w.ctx, w.e, w.m, w.st.n, w.st.syms, w.st.vals,
                                               NULL, &s),
                     QD_OK);
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_speeds_equilibria_print(w.ctx, w.e, &s, true, &b), QD_OK);
    char *json = take(&b);
    assert_non_null(strstr(json, "\"free\": [\"x\", \"y\", \"phi\", \"psi\"]"));
    assert_non_null(strstr(json, "\"speeds\": [\"u1\", \"u2\", \"u3\"]"));
    /* the two upright positions, each theta = +-pi/2 */
    const char *p = json;
    int count = 0;
    double sum = 0;
    while ((p = strstr(p, "\"equilibrium\": {"))) {
        p = strstr(p, "\"theta\": ");
        assert_non_null(p);
        p += strlen("\"theta\": ");
        double th = strtod(p, NULL);
        assert_true(fabs(fabs(th) - PI / 2) < 1e-12);
        sum += th;
        count++;
    }
    assert_int_equal(count, 2);
    assert_true(fabs(sum) < 1e-12);
    free(json);
    b = (qd_buf)QD_BUF_INIT;
    assert_int_equal(qd_speeds_equilibria_print(w.ctx, w.e, &s, false, &b), QD_OK);
    char *text = take(&b);
    assert_true(!strncmp(text, "2 equilibria (", 14));
    assert_non_null(strstr(text, "free (any value: no equation at rest involves them): x, y, "
                                 "phi, psi\n"));
    free(text);

    /* no state given: the first equilibrium listed, at rest */
    size_t th = 3, u3 = w.st.n - 1; /* theta's slot; the last speed's */
    w.st.vals[th] = 0.1;
    w.st.vals[u3] = 5;
    w.st.vals[0] = 0.7; /* x: free, kept */
    bool found = false;
    assert_int_equal(qd_speeds_equilibria_choose(w.ctx, w.e, w.m, w.st.n, w.st.syms, w.st.vals,
                                                 &found),
                     QD_OK);
    assert_true(found);
    assert_true(w.st.syms[th] == w.e->q[3]);
    assert_true(fabs(w.st.vals[th] - s.eq.pts[0].q[0]) < 1e-15);
    assert_true(fabs(fabs(w.st.vals[th]) - PI / 2) < 1e-12);
    assert_true(w.st.vals[u3] == 0 && w.st.vals[0] == 0.7);
    qd_speeds_equilibria_free(&s);
    close_world(&w);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(disk_modes_json),
        cmocka_unit_test(disk_equilibria),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
