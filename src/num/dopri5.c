/*
 * src/num/dopri5.c - the one copy of the Dormand-Prince 5(4) tables
 * (J. R. Dormand and P. J. Prince, J. Comput. Appl. Math. 6 (1980) 19;
 * Hairer, Norsett & Wanner I, table II.5.2) and Shampine's quartic dense
 * output (Math. Comp. 46 (1986) 135), for the simulation's method (src/sim)
 * and the Jacobi-field integration that locates kinetic foci (src/path).
 */
#include "num.h"

const double qd__num_dp5_c[7] = {0, 1.0 / 5, 3.0 / 10, 4.0 / 5, 8.0 / 9, 1, 1};

/* Row s: the stage s weights; row 6 is the fifth-order result (FSAL: stage 7
 * is the derivative there). */
const double qd__num_dp5_a[7][6] = {
    {0, 0, 0, 0, 0, 0},
    {1.0 / 5, 0, 0, 0, 0, 0},
    {3.0 / 40, 9.0 / 40, 0, 0, 0, 0},
    {44.0 / 45, -56.0 / 15, 32.0 / 9, 0, 0, 0},
    {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729, 0, 0},
    {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656, 0},
    {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84}};

/* Fifth- minus fourth-order weights, the last for the FSAL stage. */
const double qd__num_dp5_e[7] = {-71.0 / 57600, 0, 71.0 / 16695, -71.0 / 1920,
                                 17253.0 / 339200, -22.0 / 525, 1.0 / 40};

/* y(told + x h) = yold + h sum_k (sum_j K_j P[j][k]) x^(k+1) */
const double qd__num_dp5_p[7][4] = {
    {1, -8048581381.0 / 2820520608, 8663915743.0 / 2820520608, -12715105075.0 / 11282082432},
    {0, 0, 0, 0},
    {0, 131558114200.0 / 32700410799, -68118460800.0 / 10900136933,
     87487479700.0 / 32700410799},
    {0, -1754552775.0 / 470086768, 14199869525.0 / 1410260304, -10690763975.0 / 1880347072},
    {0, 127303824393.0 / 49829197408, -318862633887.0 / 49829197408,
     701980252875.0 / 199316789632},
    {0, -282668133.0 / 205662961, 2019193451.0 / 616988883, -1453857185.0 / 822651844},
    {0, 40617522.0 / 29380423, -110615467.0 / 29380423, 69997945.0 / 29380423}};

/* The fifth-order step (the pair's sim method takes it): rows 0-5 of a are
 * the stages' (6 columns, the stride), row 6 the weights, over 1. */
const qd__num_rk qd__num_dp5 = {6, qd__num_dp5_c, &qd__num_dp5_a[0][0], qd__num_dp5_a[6], 1};
