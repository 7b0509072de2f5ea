/*
 * src/sim/dop853.c - the explicit Runge-Kutta pair DOP853 of Dormand and
 * Prince: order 8, error estimated with embedded formulas of orders 5 and 3,
 * and a dense output of order 7 from three extra stages (Hairer, Norsett &
 * Wanner, Solving ODEs I, sec. II.10): the formulas; the coefficients, from
 * Hairer's dop853.f, are src/num/dop853.c's.
 */
#include "simint.h"
#include "num/num.h"

#include <math.h>

/* The tables are num's (qd__num_dp8_*, with the stage loop that takes the
 * step). */
#define B qd__num_dp8_b
#define C qd__num_dp8_c
#define AX qd__num_dp8_ax
#define BHH qd__num_dp8_bhh
#define E5 qd__num_dp8_e5
#define D qd__num_dp8_d

/* The error of the fifth-order formula, scaled by the third-order one so
 * that it stays a valid estimate at large steps (Hairer's err, err2). */
static double err(const qd__sim_integ *it, const double *const *K, double h, const double *ynew) {
    double e5 = 0, e3 = 0;
    for (size_t i = 0; i < it->dim; i++) {
        double a5 = 0, a3 = 0;
        for (int j = 0; j < 12; j++) {
            a5 += E5[j] * K[j][i];
            a3 += (B[j] - BHH[j]) * K[j][i];
        }
        double sc = it->atol + it->rtol * fmax(fabs(it->y[i]), fabs(ynew[i]));
        e5 += (a5 / sc) * (a5 / sc);
        e3 += (a3 / sc) * (a3 / sc);
    }
    double den = e5 + 0.01 * e3;
    /* den is 0 only for a step with no error at all; NaN (a stage or ynew
     * not finite) must reject the step, not pass as error 0 (issue 30) */
    if (!(den > 0))
        return den == 0 ? 0 : NAN;
    return fabs(h) * e5 / sqrt(den * (double)it->dim);
}

/* coef: 7 rows of dim, F0..F6 of Hairer's contd8 */
static qd_status dense_prep(qd__sim_integ *it, double **K, double *coef) {
    size_t d = it->dim;
    double h = it->t - it->told, *ytmp = coef + 7 * d;
    for (int k = 0; k < 3; k++) {
        for (size_t i = 0; i < d; i++) {
            double acc = 0;
            for (int j = 0; j < 13 + k; j++)
                acc += AX[k][j] * K[j][i];
            ytmp[i] = it->yold[i] + h * acc;
        }
        qd_status st = qd__sim_rhs(it->s, it->form, it->told + C[13 + k] * h, ytmp, K[13 + k]);
        if (st != QD_OK)
            return st;
    }
    for (size_t i = 0; i < d; i++) {
        double dy = it->y[i] - it->yold[i];
        coef[i] = dy;
        coef[d + i] = h * K[0][i] - dy;
        coef[2 * d + i] = 2 * dy - h * (K[12][i] + K[0][i]);
        for (int r = 0; r < 4; r++) {
            double acc = 0;
            for (int j = 0; j < 16; j++)
                acc += D[r][j] * K[j][i];
            coef[(3 + (size_t)r) * d + i] = h * acc;
        }
    }
    return QD_OK;
}

static void dense_eval(const qd__sim_integ *it, const double *coef, double x, double *y) {
    size_t d = it->dim;
    for (size_t i = 0; i < d; i++) {
        double acc = 0;
        for (int r = 6; r >= 0; r--) {
            acc += coef[(size_t)r * d + i];
            acc *= (6 - r) % 2 == 0 ? x : 1 - x;
        }
        y[i] = it->yold[i] + acc;
    }
}

/* dop853.f's controller: fac1 = 0.333, fac2 = 6, safe = 0.9, expo = 1/8 -
 * 0.2 beta, with beta = 0.04, the largest dop853.f admits (its default is 0):
 * on the double pendulum at rtol 1e-12 it halves the rejected steps and
 * saves 3% of the evaluations (docs/parts/sim-design.md has the figures). */
#define BETA 0.04
static const qd__sim_erk tab = {.rk = &qd__num_dp8, .order = 7, .nextra = 3, .ndense = 8,
                            .fac1 = 0.333, .fac2 = 6.0, .safe = 0.9, .beta = BETA,
                            .expo = 1.0 / 8 - 0.2 * BETA, .err = err, .dense_prep = dense_prep,
                            .dense_eval = dense_eval};

static qd_status init(qd__sim_integ *it) { return qd__sim_erk_init(it, &tab); }

const qd__sim_method qd__sim_dop853 = {init, qd__sim_erk_step, qd__sim_erk_dense, qd__sim_erk_redo,
                               qd__sim_erk_free};
