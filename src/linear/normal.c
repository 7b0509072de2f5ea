/*
 * src/linear/normal.c - what a caller reads off a solved modes result: the
 * normal coordinates of a state and the frequencies (qdot/modes.h).
 *
 * Allocations: none.
 */
#include "qdot/modes.h"
#include "../base/args.h"

#include <math.h>
#include <string.h>

/* Q_j = a_j^T M0 (q - q0), Q_j' = a_j^T M0 q': the shapes are M0-orthonormal,
 * so this inverts q = q0 + sum_j a_j Q_j (Goldstein ch. 6, the principal coordinates). */
qd_status qd_modes_normal_coords(const qd_linear *lin, const qd_modes_result *r,
                                 const double *q0, const double *q, const double *qd,
                                 double *Q, double *Qd) {
    QD_ARGS(QD_ERR_ARG, lin && r && q0 && q && qd && Q && Qd);
    size_t n = r->n;
    if (!r->conservative || !r->shapes || lin->n != n)
        return QD_ERR_ARG;
    memset(Q, 0, n * sizeof *Q);
    memset(Qd, 0, n * sizeof *Qd);
    for (size_t j = 0; j < n; j++)
        for (size_t i = 0; i < n; i++)
            for (size_t k = 0; k < n; k++) {
                double w = r->shapes[i * n + j] * lin->M[i * n + k];
                Q[j] += w * (q[k] - q0[k]);
                Qd[j] += w * qd[k];
            }
    return QD_OK;
}

static void sort_ascending(size_t n, double *w) {
    for (size_t a = 1; a < n; a++)
        for (size_t c = a; c > 0 && w[c] < w[c - 1]; c--) {
            double t = w[c];
            w[c] = w[c - 1];
            w[c - 1] = t;
        }
}

size_t qd_modes_frequencies(const qd_modes_result *r, double *w) {
    QD_ARGS(0, r && w);
    size_t nw = 0;
    if (r->conservative) {
        for (size_t k = 0; k < r->n; k++)
            if (r->omega2[k] >= 0)
                w[nw++] = sqrt(r->omega2[k]);
        return nw; /* omega2 is ascending already */
    }
    for (size_t k = 0; k < r->neig; k++)
        if (r->eig_im[k] > 0)
            w[nw++] = r->eig_im[k];
    sort_ascending(nw, w);
    return nw;
}
