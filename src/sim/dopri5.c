/*
 * src/sim/dopri5.c - the Dormand-Prince 5(4) pair (J. R. Dormand and
 * P. J. Prince, J. Comput. Appl. Math. 6 (1980) 19; Hairer, Norsett &
 * Wanner I, table II.5.2), step taken with the fifth-order result, and
 * Shampine's quartic dense output (Math. Comp. 46 (1986) 135).
 */
#include "simint.h"

#include <math.h>

static const double C[6] = {0, 1.0 / 5, 3.0 / 10, 4.0 / 5, 8.0 / 9, 1};
static const double A[6 * 6] = {
    0, 0, 0, 0, 0, 0,
    1.0 / 5, 0, 0, 0, 0, 0,
    3.0 / 40, 9.0 / 40, 0, 0, 0, 0,
    44.0 / 45, -56.0 / 15, 32.0 / 9, 0, 0, 0,
    19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729, 0, 0,
    9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656, 0};
static const double B[6] = {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784,
                            11.0 / 84};
/* fifth- minus fourth-order weights, the last for the FSAL stage */
static const double E[7] = {-71.0 / 57600, 0, 71.0 / 16695, -71.0 / 1920, 17253.0 / 339200,
                            -22.0 / 525, 1.0 / 40};
/* y(told + x h) = yold + h sum_k (sum_j K_j P[j][k]) x^(k+1) */
static const double P[7][4] = {
    {1, -8048581381.0 / 2820520608, 8663915743.0 / 2820520608, -12715105075.0 / 11282082432},
    {0, 0, 0, 0},
    {0, 131558114200.0 / 32700410799, -68118460800.0 / 10900136933,
     87487479700.0 / 32700410799},
    {0, -1754552775.0 / 470086768, 14199869525.0 / 1410260304, -10690763975.0 / 1880347072},
    {0, 127303824393.0 / 49829197408, -318862633887.0 / 49829197408,
     701980252875.0 / 199316789632},
    {0, -282668133.0 / 205662961, 2019193451.0 / 616988883, -1453857185.0 / 822651844},
    {0, 40617522.0 / 29380423, -110615467.0 / 29380423, 69997945.0 / 29380423}};

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
static const qd__sim_erk tab = {.s = 6, .order = 4, .nextra = 0, .ndense = 4, .c = C, .a = A,
                            .b = B, .fac1 = 0.2, .fac2 = 10.0, .safe = 0.9, .beta = 0.04,
                            .expo = 0.2 - 0.75 * 0.04, .err = err, .dense_prep = dense_prep,
                            .dense_eval = dense_eval};

static qd_status init(qd__sim_integ *it) { return qd__sim_erk_init(it, &tab); }

const qd__sim_method qd__sim_dopri5 = {init, qd__sim_erk_step, qd__sim_erk_dense, qd__sim_erk_redo,
                               qd__sim_erk_free};
