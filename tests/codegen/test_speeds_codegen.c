/*
 * tests/codegen/test_speeds_codegen.c - the C of a model in generalized
 * speeds (qd_codegen_speeds_c), compiled with the system compiler and
 * loaded, against the library's own numbers (qd_speeds_eval) at random
 * states and parameter values, relative 1e-12:
 *   rhs: q' from the kinematics and u' from M_u u' = f_u solved in the
 *     generated code, for Euler's rigid body (Desloge ch. 68 Ex. 2; with
 *     w = omega(b) Euler's equations A w1' = (B - C) w2 w3 ... are also
 *     checked), the rolling disk (3 speeds for 5 coordinates and 2 rolling
 *     constraints) and the Chaplygin sleigh;
 *   mass and forcing: M_u u' = f_u holds at the rhs's u';
 *   the Jacobian equals central differences of the generated rhs (relative
 *     1e-6);
 *   the energy T + V is constant along the motion (dE/dt = grad E . y' = 0 by
 *     central differences): the rolling constraints do no work (Desloge
 *     ch. 49; examples/rolling_disk_tilted.qd);
 *   a prefix that is not a C identifier is refused.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "qdot/qdot.h"
#include "qdot/codegen.h"
#include "util/check.h"

#define NMAX 8

static char dir[256];

static int group_setup(void **state) {
    (void)state;
    snprintf(dir, sizeof dir, "/tmp/qdot-test-speeds-cg-XXXXXX");
    return mkdtemp(dir) ? 0 : -1;
}

static int group_teardown(void **state) {
    (void)state;
    char cmd[300];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    return system(cmd) == 0 ? 0 : -1;
}

static uint64_t rng = 0x2545f4914f6cdd1dULL;
static double uniform(double lo, double hi) {
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return lo + (hi - lo) * (double)(rng >> 11) / 9007199254740992.0;
}

static bool close_to(double a, double b, double tol) {
    return fabs(a - b) <= tol * (1 + fabs(a) + fabs(b));
}

typedef int (*rhs_fn)(double, const double *, const double *, double *);
typedef void (*mass_fn)(double, const double *, const double *, double *);
typedef void (*forcing_fn)(double, const double *, const double *, const double *, double *);
typedef double (*energy_fn)(double, const double *, const double *);
typedef void (*jac_fn)(double, const double *, const double *, double *);

typedef struct loaded {
    void *h;
    rhs_fn rhs;
    mass_fn mass;
    forcing_fn forcing;
    energy_fn energy;
    jac_fn jacobian;
} loaded;

static void write_file(const char *path, const qd_buf *b) {
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    assert_true(fputs(qd_buf_str(b), f) >= 0);
    assert_int_equal(fclose(f), 0);
}

static void *sym(void *h, const char *prefix, const char *name) {
    char full[128];
    snprintf(full, sizeof full, "%s_%s", prefix, name);
    void *p = dlsym(h, full);
    if (!p)
        fail_msg("no %s in the generated object", full);
    return p;
}

/* Generate, compile with -Wall -Werror (the generated code must be clean)
 * and load. */
static void generate(qd_ctx *ctx, const qd_model *m, const qd_speeds_eom *e, const char *prefix,
                     loaded *out) {
    qd_buf c = QD_BUF_INIT, h = QD_BUF_INIT;
    if (qd_codegen_speeds_c(ctx, m, e, prefix, &c, &h) != QD_OK)
        fail_msg("qd_codegen_speeds_c: %s", qd_ctx_message(ctx));
    char path[400], cmd[1400];
    snprintf(path, sizeof path, "%s/%s.c", dir, prefix);
    write_file(path, &c);
    snprintf(path, sizeof path, "%s/%s.h", dir, prefix);
    write_file(path, &h);
    qd_buf_free(&c);
    qd_buf_free(&h);
    const char *cc = getenv("CC");
    snprintf(cmd, sizeof cmd,
             "%s -std=c11 -Wall -Wextra -Werror -O2 -shared -fPIC -o '%s/%s.so' '%s/%s.c' -lm",
             cc && *cc ? cc : "cc", dir, prefix, dir, prefix);
    assert_int_equal(system(cmd), 0);
    snprintf(path, sizeof path, "%s/%s.so", dir, prefix);
    out->h = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (!out->h)
        fail_msg("dlopen: %s", dlerror());
    *(void **)&out->rhs = sym(out->h, prefix, "rhs");
    *(void **)&out->mass = sym(out->h, prefix, "mass");
    *(void **)&out->forcing = sym(out->h, prefix, "forcing");
    *(void **)&out->energy = sym(out->h, prefix, "energy");
    *(void **)&out->jacobian = sym(out->h, prefix, "jacobian");
}

static double pnum(const qd_model *m, size_t i) {
    double x = 0;
    assert_int_equal(qd_model_param_number(m, i, &x), QD_OK);
    return x;
}

/* J against central differences of rhs, column by column. */
static void check_jacobian(const loaded *L, double t, const double *y, const double *par,
                           size_t d) {
    double J[4 * NMAX * NMAX], yp[2 * NMAX], ym[2 * NMAX], fp[2 * NMAX], fm[2 * NMAX];
    L->jacobian(t, y, par, J);
    for (size_t k = 0; k < d; k++) {
        double h = 1e-6 * (1 + fabs(y[k]));
        memcpy(yp, y, d * sizeof *yp);
        memcpy(ym, y, d * sizeof *ym);
        yp[k] += h;
        ym[k] -= h;
        assert_int_equal(L->rhs(t, yp, par, fp), 0);
        assert_int_equal(L->rhs(t, ym, par, fm), 0);
        for (size_t i = 0; i < d; i++) {
            double fd = (fp[i] - fm[i]) / (2 * h);
            if (!close_to(J[i * d + k], fd, 1e-6))
                fail_msg("J[%zu][%zu] = %.12g, differences %.12g", i, k, J[i * d + k], fd);
        }
    }
}

/* dE/dt along y' = rhs: (E(y + h y') - E(y - h y'))/(2h), against the
 * size of E's gradient along y'. */
static void check_energy(const loaded *L, double t, const double *y, const double *par,
                         size_t d) {
    double f[2 * NMAX], yp[2 * NMAX], ym[2 * NMAX], h = 1e-5;
    assert_int_equal(L->rhs(t, y, par, f), 0);
    for (size_t i = 0; i < d; i++) {
        yp[i] = y[i] + h * f[i];
        ym[i] = y[i] - h * f[i];
    }
    double Ep = L->energy(t, yp, par), Em = L->energy(t, ym, par);
    assert_true(isfinite(Ep) && isfinite(Em));
    double scale = 0;
    for (size_t i = 0; i < d; i++) {
        double yi[2 * NMAX];
        memcpy(yi, y, d * sizeof *yi);
        yi[i] += h * f[i];
        scale += fabs(L->energy(t, yi, par) - L->energy(t, y, par)) / h;
    }
    assert_true(fabs(Ep - Em) / (2 * h) <= 1e-6 * (1 + scale));
}

/* At random states: the generated rhs against qd_speeds_eval, and
 * M_u u' = f_u from the generated mass and forcing. */
static void compare(qd_ctx *ctx, const qd_model *m, const qd_speeds_eom *e, const loaded *L,
                    double qlo, double qhi) {
    size_t n = e->n, ns = e->m, np = qd_model_nparams(m);
    assert_true(n <= NMAX && ns <= NMAX && np <= 8);
    for (int trial = 0; trial < 20; trial++) {
        double y[2 * NMAX], par[8], dydt[2 * NMAX], qd[NMAX], ud[NMAX];
        double M[NMAX * NMAX], f[NMAX], vals[2 * NMAX + 9], t = uniform(0, 2);
        const qd_expr *syms[2 * NMAX + 9];
        size_t k = 0;
        for (size_t j = 0; j < n; j++) {
            y[j] = uniform(qlo, qhi);
            syms[k] = e->q[j];
            vals[k++] = y[j];
        }
        for (size_t r = 0; r < ns; r++) {
            y[n + r] = uniform(-2, 2);
            syms[k] = e->u[r];
            vals[k++] = y[n + r];
        }
        for (size_t i = 0; i < np; i++) {
            par[i] = pnum(m, i) * uniform(0.6, 1.4);
            syms[k] = qd_model_param(m, i);
            vals[k++] = par[i];
        }
        syms[k] = qd_time((qd_ctx *)ctx);
        vals[k++] = t;
        assert_int_equal(qd_speeds_eval(ctx, e, k, syms, vals, qd, ud, NULL), QD_OK);
        assert_int_equal(L->rhs(t, y, par, dydt), 0);
        for (size_t j = 0; j < n; j++)
            assert_true(close_to(dydt[j], qd[j], 1e-12));
        for (size_t r = 0; r < ns; r++)
            assert_true(close_to(dydt[n + r], ud[r], 1e-12));
        L->mass(t, y, par, M);
        L->forcing(t, y, y + n, par, f);
        for (size_t r = 0; r < ns; r++) {
            double lhs = 0, scale = fabs(f[r]);
            for (size_t s = 0; s < ns; s++) {
                lhs += M[r * ns + s] * ud[s];
                scale += fabs(M[r * ns + s] * ud[s]);
            }
            assert_true(fabs(lhs - f[r]) <= 1e-12 * (1 + scale));
        }
        check_jacobian(L, t, y, par, n + ns);
        check_energy(L, t, y, par, n + ns);
    }
}

static void run_model(const char *text, const char *prefix, double qlo, double qhi) {
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qt_parse_ok(ctx, text);
    qd_speeds_eom *e = qd_speeds_derive(ctx, m, NULL);
    if (!e)
        fail_msg("qd_speeds_derive: %s", qd_ctx_message(ctx));
    loaded L;
    generate(ctx, m, e, prefix, &L);
    compare(ctx, m, e, &L, qlo, qhi);
    dlclose(L.h);
    qd_speeds_eom_free(e);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

static const char euler_body[] =
    "coordinates phi, theta, psi\n"
    "parameters A = 1, B = 2, C = 3\n"
    "body b mass 1 inertia (A, B, C) at (0, 0, 0) orientation euler(phi, theta, psi)\n"
    "speeds w1 = omega(b).x, w2 = omega(b).y, w3 = omega(b).z\n";

static void euler(void **state) {
    (void)state;
    /* theta away from 0 and pi, where the Euler angles are singular */
    run_model(euler_body, "euler_body", 0.3, 2.8);
    /* Euler's equations from the generated rhs (Desloge ch. 68 Ex. 2):
       A w1' = (B - C) w2 w3, B w2' = (C - A) w3 w1, C w3' = (A - B) w1 w2 */
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qt_parse_ok(ctx, euler_body);
    qd_speeds_eom *e = qd_speeds_derive(ctx, m, NULL);
    assert_non_null(e);
    loaded L;
    generate(ctx, m, e, "euler_check", &L);
    double par[3] = {1.3, 2.1, 2.9}, y[6] = {0.2, 1.1, -0.4, 0.7, -1.3, 0.9}, d[6];
    assert_int_equal(L.rhs(0, y, par, d), 0);
    const double *w = y + 3, *wd = d + 3;
    assert_true(close_to(par[0] * wd[0], (par[1] - par[2]) * w[1] * w[2], 1e-13));
    assert_true(close_to(par[1] * wd[1], (par[2] - par[0]) * w[2] * w[0], 1e-13));
    assert_true(close_to(par[2] * wd[2], (par[0] - par[1]) * w[0] * w[1], 1e-13));
    dlclose(L.h);
    qd_speeds_eom_free(e);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

static void rolling_disk(void **state) {
    (void)state;
    run_model("coordinates x, y, phi, theta, psi\n"
              "parameters m = 1.4, a = 0.35, g = 9.81\n"
              "body disk mass m inertia disk(m, a) at (x, y, a*sin(theta)) "
              "orientation euler(phi, theta, psi)\n"
              "V = m*g*a*sin(theta)\n"
              "rolls disk on plane((0, 0, 1), (0, 0, 0)) as disk(a)\n"
              "speeds u1 = theta', u2 = omega_space(disk).z, u3 = omega(disk).z\n",
              "disk", 0.3, 2.8);
}

static void sleigh(void **state) {
    (void)state;
    run_model("coordinates x, y, th\n"
              "parameters m = 2, I = 0.3, b = 0.4\n"
              "T = m/2*(x'^2 + y'^2) + I/2*th'^2\n"
              "constraint blade: -x'*sin(th) + y'*cos(th) + b*th' = 0\n"
              "speeds v = x'*cos(th) + y'*sin(th), w = th'\n",
              "sleigh", -2, 2);
}

static void bad_prefix(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qt_parse_ok(ctx, euler_body);
    qd_speeds_eom *e = qd_speeds_derive(ctx, m, NULL);
    assert_non_null(e);
    qd_buf c = QD_BUF_INIT;
    assert_int_equal(qd_codegen_speeds_c(ctx, m, e, "1bad", &c, NULL), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(ctx), "not a C identifier"));
    qd_buf_free(&c);
    qd_speeds_eom_free(e);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* A user function has no C definition: refused by name, as for the
 * equations in coordinates (the one block writer, src/codegen/block.c),
 * not written as a call no compiler can link. */
static void user_function(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = qt_parse_ok(ctx, "coordinates x\nfunctions W\nT = x'^2/2\nV = W(x)\n"
                                   "speeds u = x'\n");
    qd_speeds_eom *e = qd_speeds_derive(ctx, m, NULL);
    assert_non_null(e);
    qd_buf c = QD_BUF_INIT, h = QD_BUF_INIT;
    assert_int_equal(qd_codegen_speeds_c(ctx, m, e, "uf", &c, &h), QD_ERR_ARG);
    assert_non_null(strstr(qd_ctx_message(ctx), "user function 'W' has no definition"));
    qd_buf_free(&c);
    qd_buf_free(&h);
    qd_speeds_eom_free(e);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(euler),
        cmocka_unit_test(rolling_disk),
        cmocka_unit_test(sleigh),
        cmocka_unit_test(bad_prefix),
        cmocka_unit_test(user_function),
    };
    return cmocka_run_group_tests(tests, group_setup, group_teardown);
}
