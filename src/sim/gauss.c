/*
 * src/sim/gauss.c - Gauss-Legendre collocation with s = 1, 2, 3 stages
 * (orders 2, 4, 6): implicit, symmetric and symplectic (Hairer, Lubich &
 * Wanner, Geometric Numerical Integration, sec. II.1.3 and VIII.6).
 *
 * The stage equations Z_i = h sum_j a_ij F(y + Z_j) are solved by fixed-point
 * iteration until the correction stops decreasing (round-off), from a start
 * extrapolated from the last step's collocation polynomial.  The update
 * y + h sum_i b_i F(y + Z_i) is added with compensated (Kahan) summation, so
 * that round-off does not drift the energy over millions of steps (GNI
 * sec. VIII.5).
 */
#include "simint.h"
#include "../base/mem.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MAX_ITER 60

typedef struct gl_tab {
    int s;
    double c[3], a[3][3], b[3];
} gl_tab;

typedef struct gl {
    const gl_tab *tab;
    double *Z, *Znew, *F, *yst, *comp, *w;  /* s*dim, s*dim, s*dim, dim, dim, s*dim */
    double hprev;
    bool have_prev;
} gl;

#define R3 1.7320508075688772935
#define R15 3.8729833462074168852

static const gl_tab gl1 = {1, {0.5}, {{0.5}}, {1}};
static const gl_tab gl2 = {2, {0.5 - R3 / 6, 0.5 + R3 / 6},
                           {{0.25, 0.25 - R3 / 6}, {0.25 + R3 / 6, 0.25}}, {0.5, 0.5}};
static const gl_tab gl3 = {3, {0.5 - R15 / 10, 0.5, 0.5 + R15 / 10},
                           {{5.0 / 36, 2.0 / 9 - R15 / 15, 5.0 / 36 - R15 / 30},
                            {5.0 / 36 + R15 / 24, 2.0 / 9, 5.0 / 36 - R15 / 24},
                            {5.0 / 36 + R15 / 30, 2.0 / 9 + R15 / 15, 5.0 / 36}},
                           {5.0 / 18, 4.0 / 9, 5.0 / 18}};

static qd_status init_tab(qd__sim_integ *it, const gl_tab *tab) {
    size_t d = it->dim, s = (size_t)tab->s;
    gl *g = qd__calloc(it->s->ctx, 1, sizeof *g);
    double *mem = qd__malloc(it->s->ctx, (4 * s * d + 2 * d + 1) * sizeof *mem);
    if (!g || !mem) {
        qd__free(g);
        qd__free(mem);
        return QD_ERR_NOMEM;
    }
    g->tab = tab;
    g->Z = mem;
    g->Znew = mem + s * d;
    g->F = mem + 2 * s * d;
    g->w = mem + 3 * s * d;
    g->yst = mem + 4 * s * d;
    g->comp = g->yst + d;
    memset(g->comp, 0, d * sizeof *g->comp);
    it->priv = g;
    return QD_OK;
}

static void gl_free(qd__sim_integ *it) {
    gl *g = it->priv;
    if (g)
        qd__free(g->Z);
    qd__free(g);
    it->priv = NULL;
}

/* Start values: the last step's collocation polynomial w(x) (w(0) = 0,
 * w(c_j) = Z_j) continued to the new stages, minus the step's increment. */
static void extrapolate(qd__sim_integ *it, gl *g, double h) {
    const gl_tab *T = g->tab;
    size_t d = it->dim, s = (size_t)T->s;
    if (!g->have_prev || g->hprev != h || it->y_changed) {
        memset(g->Z, 0, s * d * sizeof *g->Z);
        return;
    }
    for (size_t i = 0; i < s; i++) {
        double x = 1 + T->c[i];
        double l[3];
        for (size_t j = 0; j < s; j++) {
            l[j] = x / T->c[j];
            for (size_t k = 0; k < s; k++)
                if (k != j)
                    l[j] *= (x - T->c[k]) / (T->c[j] - T->c[k]);
        }
        for (size_t r = 0; r < d; r++) {
            double v = 0;
            for (size_t j = 0; j < s; j++)
                v += l[j] * g->Z[j * d + r];
            g->w[i * d + r] = v - (it->y[r] - it->yold[r]);
        }
    }
    memcpy(g->Z, g->w, s * d * sizeof *g->Z);
}

/* Solve the stage equations from (t0, y0) with the start in g->Z; g->F
 * holds F(y0 + Z_i) on return. */
static qd_status solve_stages(qd__sim_integ *it, gl *g, double t0, const double *y0, double h) {
    const gl_tab *T = g->tab;
    size_t d = it->dim, s = (size_t)T->s;
    double prev = INFINITY, scale = 0;
    for (size_t r = 0; r < d; r++)
        scale = fmax(scale, fabs(y0[r]));
    scale = fmax(scale, 1e-300);
    for (int iter = 0; iter < MAX_ITER; iter++) {
        for (size_t i = 0; i < s; i++) {
            for (size_t r = 0; r < d; r++)
                g->yst[r] = y0[r] + g->Z[i * d + r];
            qd_status st = qd__sim_rhs(it->s, it->form, t0 + T->c[i] * h, g->yst, g->F + i * d);
            if (st != QD_OK)
                return st;
        }
        double delta = 0;
        for (size_t i = 0; i < s; i++)
            for (size_t r = 0; r < d; r++) {
                double z = 0;
                for (size_t j = 0; j < s; j++)
                    z += T->a[i][j] * g->F[j * d + r];
                z *= h;
                delta = fmax(delta, fabs(z - g->Z[i * d + r]));
                g->Z[i * d + r] = z;
            }
        if (!isfinite(delta))
            break;
        delta /= scale;
        /* converged to round-off: the correction vanished or stopped shrinking */
        if (delta == 0 || (delta >= prev && delta < 1e-10) || delta < 1e-17)
            return QD_OK;
        prev = delta;
    }
    qd__sim_stop(it->s, QD_STOP_NO_CONVERGENCE, t0, h);
    qd_ctx_error(it->s->ctx, QD_ERR_NUMERIC,
                 "no convergence of the Gauss-Legendre iteration (Newton non-convergence) at "
                 "t = %.17g with h = %.3g: take a smaller --dt", t0, h);
    return QD_ERR_NUMERIC;
}

static qd_status gl_step(qd__sim_integ *it) {
    gl *g = it->priv;
    const gl_tab *T = g->tab;
    size_t d = it->dim, s = (size_t)T->s;
    double h = it->h;
    extrapolate(it, g, h);
    if (it->y_changed)
        memset(g->comp, 0, d * sizeof *g->comp);
    it->y_changed = false;
    qd_status st = solve_stages(it, g, it->t, it->y, h);
    if (st != QD_OK)
        return st;
    it->told = it->t;
    memcpy(it->yold, it->y, d * sizeof *it->y);
    for (size_t r = 0; r < d; r++) {
        double inc = 0;
        for (size_t i = 0; i < s; i++)
            inc += T->b[i] * g->F[i * d + r];
        /* Kahan: comp carries what the last addition lost */
        double delta = h * inc + g->comp[r];
        double y1 = it->y[r] + delta;
        g->comp[r] = (it->y[r] - y1) + delta;
        it->y[r] = y1;
    }
    it->t = it->told + h;
    g->hprev = h;
    g->have_prev = true;
    return QD_OK;
}

static qd_status gl_redo(qd__sim_integ *it, double h, double *y) {
    gl *g = it->priv;
    const gl_tab *T = g->tab;
    size_t d = it->dim, s = (size_t)T->s;
    /* keep the step's stages for the next extrapolation */
    double *save = g->Znew;
    memcpy(save, g->Z, s * d * sizeof *save);
    memset(g->Z, 0, s * d * sizeof *g->Z);
    qd_status st = solve_stages(it, g, it->told, it->yold, h);
    for (size_t r = 0; st == QD_OK && r < d; r++) {
        double inc = 0;
        for (size_t i = 0; i < s; i++)
            inc += T->b[i] * g->F[i * d + r];
        y[r] = it->yold[r] + h * inc;
    }
    memcpy(g->Z, save, s * d * sizeof *save);
    return st;
}

static qd_status init1(qd__sim_integ *it) { return init_tab(it, &gl1); }
static qd_status init2(qd__sim_integ *it) { return init_tab(it, &gl2); }
static qd_status init3(qd__sim_integ *it) { return init_tab(it, &gl3); }

const qd__sim_method qd__sim_gauss2 = {init1, gl_step, NULL, gl_redo, gl_free};
const qd__sim_method qd__sim_gauss4 = {init2, gl_step, NULL, gl_redo, gl_free};
const qd__sim_method qd__sim_gauss6 = {init3, gl_step, NULL, gl_redo, gl_free};
