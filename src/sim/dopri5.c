/*
 * src/sim/dopri5.c - the Dormand-Prince 5(4) pair (J. R. Dormand and
 * P. J. Prince, J. Comput. Appl. Math. 6 (1980) 19; Hairer, Norsett &
 * Wanner I, table II.5.2), step taken with the fifth-order result, and
 * Shampine's quartic dense output (Math. Comp. 46 (1986) 135).
 */
#include "simint.h"
#include "num/num.h"

#include <math.h>

/* The tables are num's (qd__num_dp5_*, shared with src/path; the step is
 * qd__num_dp5 through num's stage loop). */
#define E qd__num_dp5_e
#define P qd__num_dp5_p

static double err(const qd__sim_integ *it, const double *const *K, double h, const double *ynew) {
    double sum = 0;
    for (size_t i = 0; i < it->dim; i++) {
        double e = 0;
        for (int j = 0; j < 7; j++)
            e += E[j] * K[j][i];
        double sc = it->atol + it->rtol * fmax(fabs(it->y[i]), fabs(ynew[i]));
        e *= h / sc;
        sum += e * e;
    }
    return sqrt(sum / (double)it->dim);
}

static qd_status dense_prep(qd__sim_integ *it, double **K, double *coef) {
    size_t d = it->dim;
    for (size_t i = 0; i < d; i++)
        for (int k = 0; k < 4; k++) {
            double q = 0;
            for (int j = 0; j < 7; j++)
                q += K[j][i] * P[j][k];
            coef[k * d + i] = q;
        }
    return QD_OK;
}

static void dense_eval(const qd__sim_integ *it, const double *coef, double x, double *y) {
    size_t d = it->dim;
    double h = it->t - it->told;
    for (size_t i = 0; i < d; i++) {
        double acc = 0;
        for (int k = 3; k >= 0; k--)
            acc = (acc + coef[k * d + i]) * x;
        y[i] = it->yold[i] + h * acc;
    }
}

/* dopri5.f's defaults: fac1 = 0.2, fac2 = 10, safe = 0.9, beta = 0.04,
 * expo = 1/5 - 0.75 beta */
static const qd__sim_erk tab = {.rk = &qd__num_dp5, .order = 4, .nextra = 0, .ndense = 4,
                            .fac1 = 0.2, .fac2 = 10.0, .safe = 0.9, .beta = 0.04,
                            .expo = 0.2 - 0.75 * 0.04, .err = err, .dense_prep = dense_prep,
                            .dense_eval = dense_eval};

static qd_status init(qd__sim_integ *it) { return qd__sim_erk_init(it, &tab); }

const qd__sim_method qd__sim_dopri5 = {init, qd__sim_erk_step, qd__sim_erk_dense, qd__sim_erk_redo,
                               qd__sim_erk_free};
