/*
 * src/num/rk.c - one fixed step of an explicit Runge-Kutta method given by
 * its Butcher tableau, and the classical fourth-order tableau (Hairer,
 * Norsett & Wanner I, sec. II.1), for the shooting of src/path.  The
 * adaptive pairs with error control stay in src/sim (erk.c), whose
 * Dormand-Prince tables are num's too (dopri5.c).
 */
#include "num.h"

static const double rk4_c[4] = {0, 0.5, 0.5, 1};
static const double rk4_a[16] = {0, 0, 0, 0, 0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 1, 0};
static const double rk4_b[4] = {1, 2, 2, 1};

const qd__num_rk qd__num_rk4 = {4, rk4_c, rk4_a, rk4_b, 6};

bool qd__num_rk_step(const qd__num_rk *m, qd__num_ode_fn f, void *data, size_t n, double t,
                     double h, double *y, double *w) {
    size_t s = (size_t)m->stages;
    double *yt = w + s * n;
    for (size_t i = 0; i < s; i++) {
        double *ki = w + i * n;
        const double *ai = m->a + i * s;
        const double *arg = y;
        if (i > 0) {
            /* zero weights are skipped, so a non-finite stage never
             * meets a zero (0 + x is x: the classical sums are kept) */
            for (size_t j = 0; j < n; j++) {
                double sum = 0;
                for (size_t l = 0; l < i; l++)
                    if (ai[l] != 0)
                        sum += ai[l] * w[l * n + j];
                yt[j] = y[j] + h * sum;
            }
            arg = yt;
        }
        if (!f(data, t + m->c[i] * h, arg, ki))
            return false;
    }
    double hb = h / m->bden;
    for (size_t j = 0; j < n; j++) {
        double sum = 0;
        for (size_t i = 0; i < s; i++)
            if (m->b[i] != 0)
                sum += m->b[i] * w[i * n + j];
        y[j] += hb * sum;
    }
    return true;
}
