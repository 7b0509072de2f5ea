/*
 * src/num/rk.c - the one stage loop of the explicit Runge-Kutta methods,
 * given by their Butcher tableaux, and the classical fourth-order tableau
 * (Hairer, Norsett & Wanner I, sec. II.1) for the shooting of src/path.
 * The adaptive pairs (src/sim/erk.c: step size control, error estimates,
 * dense output) step through it too, with their tables from dopri5.c and
 * dop853.c here.
 */
#include "num.h"

static const double rk4_c[4] = {0, 0.5, 0.5, 1};
static const double rk4_a[16] = {0, 0, 0, 0, 0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 1, 0};
static const double rk4_b[4] = {1, 2, 2, 1};

const qd__num_rk qd__num_rk4 = {4, rk4_c, rk4_a, rk4_b, 6};

bool qd__num_rk_stages(const qd__num_rk *m, qd__num_ode_fn f, void *data, size_t n, double t,
                       double h, const double *y0, double *y1, double *const *k, double *ytmp,
                       bool fsal) {
    size_t s = (size_t)m->stages;
    for (size_t i = fsal ? 1 : 0; i < s; i++) {
        const double *ai = m->a + i * s;
        const double *arg = y0;
        if (i > 0) {
            /* zero weights are skipped, so a non-finite stage never
             * meets a zero (0 + x is x: the classical sums are kept) */
            for (size_t j = 0; j < n; j++) {
                double sum = 0;
                for (size_t l = 0; l < i; l++)
                    if (ai[l] != 0)
                        sum += ai[l] * k[l][j];
                ytmp[j] = y0[j] + h * sum;
            }
            arg = ytmp;
        }
        if (!f(data, t + m->c[i] * h, arg, k[i]))
            return false;
    }
    double hb = h / m->bden;
    for (size_t j = 0; j < n; j++) {
        double sum = 0;
        for (size_t i = 0; i < s; i++)
            if (m->b[i] != 0)
                sum += m->b[i] * k[i][j];
        y1[j] = y0[j] + hb * sum;
    }
    return !fsal || f(data, t + h, y1, k[s]);
}

bool qd__num_rk_step(const qd__num_rk *m, qd__num_ode_fn f, void *data, size_t n, double t,
                     double h, double *y, double *w) {
    size_t s = (size_t)m->stages;
    double *k[QD__NUM_RK_MAX_STAGES];
    if (s > QD__NUM_RK_MAX_STAGES)
        return false;
    for (size_t i = 0; i < s; i++)
        k[i] = w + i * n;
    return qd__num_rk_stages(m, f, data, n, t, h, y, y, k, w + s * n, false);
}
