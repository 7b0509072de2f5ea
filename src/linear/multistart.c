/*
 * src/linear/multistart.c - every equilibrium in a box, numerically.
 *
 * Two kinds of starting points for the damped Newton solver:
 *   - a Halton sequence over the box (deterministic, evenly spread);
 *   - scans along each coordinate axis through the box centre: F_i sampled
 *     at 400 points, every sign change bracketed and bisected, then
 *     polished.  A sign change across a pole (F_i -> +-inf, e.g. at a
 *     primary of the restricted three-body problem) bisects onto the pole;
 *     its residual does not fall and it is dropped.  This finds the
 *     collinear Lagrange points robustly: one root in each interval
 *     between the poles (Desloge ch. 62; seed-desloge-B.md pitfall 8).
 * Roots closer than 1e-6 (relative) are one root; angles are compared
 * modulo 2 pi.
 */
#include "linear.h"
#include "../base/mem.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const double PI = 3.14159265358979323846;

void qd__lin_wrap_angles(size_t n, double *q, const bool *angle) {
    for (size_t j = 0; angle && j < n; j++)
        if (angle[j] && isfinite(q[j])) {
            double x = fmod(q[j], 2 * PI);
            if (x <= -PI)
                x += 2 * PI;
            else if (x > PI)
                x -= 2 * PI;
            if (fabs(x + PI) < 1e-12)
                x = PI;
            q[j] = x;
        }
}

bool qd__lin_roots_same(size_t n, const double *a, const double *b, const bool *angle) {
    double big = 1;
    for (size_t j = 0; j < n; j++)
        big = fmax(big, fmax(fabs(a[j]), fabs(b[j])));
    for (size_t j = 0; j < n; j++) {
        double d = fabs(a[j] - b[j]);
        if (angle && angle[j])
            d = fmin(d, fabs(2 * PI - d));
        if (d > 1e-6 * big)
            return false;
    }
    return true;
}

bool qd__lin_roots_add(qd_ctx *ctx, qd__roots *r, const double *q, double res, const bool *angle) {
    size_t n = r->n;
    for (size_t i = 0; i < r->count; i++)
        if (qd__lin_roots_same(n, r->q + i * n, q, angle)) {
            if (res < r->res[i]) {
                memcpy(r->q + i * n, q, n * sizeof *q);
                r->res[i] = res;
            }
            return true;
        }
    if (r->count == r->cap) {
        size_t cap = r->cap ? 2 * r->cap : 16;
        double *nq = qd__realloc(ctx, r->q, (cap * n + 1) * sizeof *nq);
        if (!nq)
            return false;
        r->q = nq;
        double *nr = qd__realloc(ctx, r->res, cap * sizeof *nr);
        if (!nr)
            return false;
        r->res = nr;
        r->cap = cap;
    }
    memcpy(r->q + r->count * n, q, n * sizeof *q);
    r->res[r->count++] = res;
    return true;
}

void qd__lin_roots_free(qd__roots *r) {
    qd__free(r->q);
    qd__free(r->res);
    r->q = r->res = NULL;
    r->count = r->cap = 0;
}

double qd__lin_halton(size_t i, unsigned base) {
    double f = 1, x = 0;
    for (size_t k = i; k; k /= base) {
        f /= base;
        x += f * (double)(k % base);
    }
    return x;
}

const unsigned qd__lin_halton_primes[16] = {2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53};

static bool polish(qd__lin *L, double *q, const bool *angle, double ftol, qd__roots *out) {
    double res;
    if (qd__lin_lm_solve(L, q, ftol, 200, &res)) {
        qd__lin_wrap_angles(L->n, q, angle);
        return qd__lin_roots_add(L->ctx, out, q, res, angle);
    }
    return true;
}

/* F_i along axis i through c, brackets bisected, then polished. */
static bool scan_axis(qd__lin *L, size_t i, const double *c, const double *lo, const double *hi,
                      const bool *angle, double ftol, double *q, qd__roots *out) {
    enum { N = 400 };
    size_t n = L->n;
    double prev = NAN, xprev = 0;
    memcpy(q, c, n * sizeof *q);
    for (int s = 0; s <= N; s++) {
        double x = lo[i] + (hi[i] - lo[i]) * s / N;
        q[i] = x;
        qd__lin_run(L, q);
        double f = qd__lin_F(L)[i];
        if (isfinite(f) && isfinite(prev) && ((f < 0) != (prev < 0) || f == 0)) {
            double a = xprev, b = x, fa = prev;
            for (int it = 0; it < 80 && f != 0; it++) {
                double m = (a + b) / 2;
                q[i] = m;
                qd__lin_run(L, q);
                double fm = qd__lin_F(L)[i];
                if (!isfinite(fm))
                    break;
                if ((fm < 0) == (fa < 0)) {
                    a = m;
                    fa = fm;
                } else {
                    b = m;
                }
            }
            q[i] = f == 0 ? x : (a + b) / 2;
            if (!polish(L, q, angle, ftol, out))
                return false;
            memcpy(q, c, n * sizeof *q);
        }
        prev = f;
        xprev = x;
    }
    return true;
}

/* Each axis scan and each start is a step of the progress reported to the
 * context (qd_ctx_set_progress): n + starts steps. */
static bool stop_asked(qd__lin *L, size_t done, size_t total) {
    if (!qd__ctx_progress(L->ctx, "equilibria: multistart", done, total))
        return false;
    qd_ctx_error(L->ctx, QD_ERR_ARG, "the search for equilibria was stopped after %zu of %zu "
                 "starts", done, total);
    return true;
}

qd_status qd__lin_multistart(qd__lin *L, const double *lo, const double *hi, const bool *angle,
                             size_t starts, double ftol, qd__roots *out) {
    size_t n = L->n, total = n + starts;
    double *q = qd__malloc(L->ctx, (n + 1) * sizeof *q), *c = qd__malloc(L->ctx, (n + 1) * sizeof *c);
    bool ok = q && c, stopped = false;
    for (size_t j = 0; ok && j < n; j++)
        c[j] = lo[j] <= 0 && hi[j] >= 0 ? 0 : (lo[j] + hi[j]) / 2;
    for (size_t i = 0; ok && !stopped && i < n; i++) {
        ok = scan_axis(L, i, c, lo, hi, angle, ftol, q, out);
        stopped = stop_asked(L, i + 1, total);
    }
    unsigned long long seed = 88172645463325252ULL;
    for (size_t s = 0; ok && !stopped && s < starts; s++) {
        for (size_t j = 0; j < n; j++) {
            double u;
            if (j < sizeof qd__lin_halton_primes / sizeof *qd__lin_halton_primes) {
                u = qd__lin_halton(s + 1, qd__lin_halton_primes[j]);
            } else {
                seed ^= seed << 13;
                seed ^= seed >> 7;
                seed ^= seed << 17;
                u = (double)(seed >> 11) / 9007199254740992.0;
            }
            q[j] = lo[j] + (hi[j] - lo[j]) * u;
        }
        ok = polish(L, q, angle, ftol, out);
        stopped = stop_asked(L, n + s + 1, total);
    }
    qd__free(q);
    qd__free(c);
    return !ok ? QD_ERR_NOMEM : stopped ? QD_ERR_ARG : QD_OK;
}
