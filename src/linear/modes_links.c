/*
 * src/linear/modes_links.c - what joins the particles of a mode picture
 * (qd_modes_picture's links, qdot/modes.h): springs from V, rods from
 * distances that do not change, and a pivot at the origin.
 *
 * Both are read off numbers the picture has already: the positions'
 * Jacobian at the equilibrium (a forward difference per coordinate) and
 * K0 = d2V/dq2.  A coordinate that moves one particle only is that
 * particle's own; a distance term k/2 (|ri - rj| - a)^2 in V couples the
 * own coordinates of i and j in K0, and nothing else of V does (a spring
 * to a wall or a potential of one particle stays in its own block).  A
 * rod is a distance that a step of any one coordinate leaves as it is (to
 * 1e-9, the step a thousandth of the configuration's size: a first-order
 * test would take |r2| of a pendulum hanging straight for a rod too, its
 * change being of second order): the links of a pendulum, |r1| about the
 * pivot and |r2 - r1|.  A spring to a wall: where each particle has a
 * coordinate of its own moving it along an axis alone (a chain, particles
 * in the plane), those together translate the whole configuration, which
 * springs between particles let be (K0 T = 0 on their coordinates); K0 T
 * not 0 on a particle's coordinate is a force from something fixed (k/2
 * x1^2, k/2 (x3 - L)^2 in V).
 */
#include "linear.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MULTI ((size_t)-1) /* a coordinate that moves several particles */
#define NONE ((size_t)-2)  /* one that moves none */

/* jac[(j*np + i)*3 + k]: d(position k of particle i)/dq_j.  The owner of
 * each coordinate: the one particle it moves, NONE or MULTI. */
static void owners(const double *jac, size_t n, size_t np, double tiny, size_t *owner) {
    for (size_t j = 0; j < n; j++) {
        owner[j] = NONE;
        for (size_t i = 0; i < np; i++) {
            const double *d = jac + (j * np + i) * 3;
            if (fabs(d[0]) + fabs(d[1]) + fabs(d[2]) > tiny)
                owner[j] = owner[j] == NONE ? i : MULTI;
        }
    }
}

/* K0 couples an own coordinate of a with one of b. */
static bool coupled(const double *K, size_t n, const size_t *owner, size_t a, size_t b,
                    double kmax) {
    for (size_t u = 0; u < n; u++)
        for (size_t v = 0; v < n; v++)
            if (owner[u] == a && owner[v] == b && fabs(K[u * n + v]) > 1e-9 * kmax)
                return true;
    return false;
}

/* |pos_a - pos_b| (b == np: the origin) */
static double distance(const double *pos, size_t np, size_t a, size_t b) {
    double d2 = 0;
    for (unsigned k = 0; k < 3; k++) {
        double d = pos[3 * a + k] - (b < np ? pos[3 * b + k] : 0);
        d2 += d * d;
    }
    return sqrt(d2);
}

/* The distance from a to b (b == np: the origin) is not zero, the step
 * of each coordinate (far) keeps it, and some coordinate moves a against b. */
static bool rigid(const double *rest, const double *jac, const double *far, size_t n, size_t np,
                  size_t a, size_t b, double size, double jmax) {
    double dist = distance(rest, np, a, b);
    if (!(dist > 1e-6 * size))
        return false;
    bool moves = false;
    for (size_t j = 0; j < n; j++) {
        const double *da = jac + (j * np + a) * 3, *db = b < np ? jac + (j * np + b) * 3 : NULL;
        if (fabs(distance(far + j * 3 * np, np, a, b) - dist) > 1e-9 * dist)
            return false;
        for (unsigned k = 0; k < 3; k++)
            moves |= fabs(da[k] - (db ? db[k] : 0)) > 1e-6 * jmax;
    }
    return moves;
}

static bool add_link(qd_modes_picture *pic, size_t a, size_t b, qd_modes_link kind) {
    if (pic->nlinks == QD_MODES_PLOT_MAXLINKS)
        return false;
    pic->links[pic->nlinks++] = (qd_modes_link_of){a, b, kind};
    return true;
}

/* The coordinate of its own that moves particle i along axis e alone (to
 * 1e-6 of its step), or n for none. */
static size_t along(const double *jac, size_t n, size_t np, const size_t *owner, size_t i,
                    unsigned e) {
    for (size_t u = 0; u < n; u++) {
        const double *d = jac + (u * np + i) * 3;
        double rest = fabs(d[(e + 1) % 3]) + fabs(d[(e + 2) % 3]);
        if (owner[u] == i && fabs(d[e]) > 0 && rest <= 1e-6 * fabs(d[e]))
            return u;
    }
    return n;
}

/* The nearest two particles' distance at rest, or size for one. */
static double spacing(const qd_modes_picture *pic, double size) {
    double best = INFINITY;
    for (size_t a = 0; a < pic->np; a++)
        for (size_t b = a + 1; b < pic->np; b++) {
            double d = distance(pic->rest, pic->np, a, b);
            if (d > 1e-9 * size)
                best = fmin(best, d);
        }
    return isfinite(best) ? best : size;
}

/* Springs to walls along axis e: every particle moved along e by a
 * coordinate of its own (T, a rigid translation of the configuration), and
 * K0 T not 0 on particle a's coordinate: a is held by something fixed. */
static void walls_along(qd_modes_picture *pic, const double *jac, size_t n, const double *K,
                        double kmax, const size_t *owner, unsigned e, double size) {
    size_t np = pic->np, own[QD_MODES_PLOT_MAXP];
    double *T = calloc(n + 1, sizeof *T), mid = 0, tmax = 0;
    for (size_t i = 0; T && i < np; i++) {
        if ((own[i] = along(jac, n, np, owner, i, e)) == n) {
            free(T);
            return; /* a particle that cannot follow: no rigid translation */
        }
        T[own[i]] = 1 / jac[(own[i] * np + i) * 3 + e];
        tmax = fmax(tmax, fabs(T[own[i]]));
        mid += pic->rest[3 * i + e] / (double)np;
    }
    for (size_t a = 0; T && a < np && pic->nwalls < QD_MODES_PLOT_MAXWALLS; a++) {
        double f = 0;
        for (size_t v = 0; v < n; v++)
            f += K[own[a] * n + v] * T[v];
        if (!(fabs(f) > 1e-9 * kmax * tmax) || pic->nlinks == QD_MODES_PLOT_MAXLINKS)
            continue;
        double *w = pic->wall + 3 * pic->nwalls, side = pic->rest[3 * a + e] > mid ? 1 : -1;
        for (unsigned k = 0; k < 3; k++)
            w[k] = pic->rest[3 * a + k];
        w[e] += side * spacing(pic, size);
        pic->wall_axis[pic->nwalls] = e;
        pic->links[pic->nlinks++] = (qd_modes_link_of){a, np + 1 + pic->nwalls++,
                                                       QD_MODES_SPRING};
    }
    free(T);
}

static void cross(const double *u, const double *v, double *out) {
    out[0] = u[1] * v[2] - u[2] * v[1];
    out[1] = u[2] * v[0] - u[0] * v[2];
    out[2] = u[0] * v[1] - u[1] * v[0];
}

static double dist3(const double *u, const double *v) {
    return sqrt((u[0] - v[0]) * (u[0] - v[0]) + (u[1] - v[1]) * (u[1] - v[1]) +
                (u[2] - v[2]) * (u[2] - v[2]));
}

/* The centre c of the circle through A, B, C; false when they are on a line. */
static bool circumcentre(const double *A, const double *B, const double *C, double *c) {
    double a[3], b[3], axb[3], w[3], num[3];
    for (unsigned k = 0; k < 3; k++)
        a[k] = B[k] - A[k], b[k] = C[k] - A[k];
    cross(a, b, axb);
    double aa = a[0] * a[0] + a[1] * a[1] + a[2] * a[2], bb = b[0] * b[0] + b[1] * b[1] + b[2] * b[2];
    double d = axb[0] * axb[0] + axb[1] * axb[1] + axb[2] * axb[2];
    if (!(d > 1e-12 * aa * bb))
        return false;
    for (unsigned k = 0; k < 3; k++)
        w[k] = aa * b[k] - bb * a[k];
    cross(w, axb, num);
    for (unsigned k = 0; k < 3; k++)
        c[k] = A[k] + num[k] / (2 * d);
    return true;
}

/* Particle a swings about a fixed point other than the origin (the second
 * of two pendulums hung side by side): the centre of the circle its own
 * coordinate u moves it on (through q0 and q0 +- H), whose distance every
 * coordinate's steps keep (to 1e-7: the centre is found from points H
 * apart), checked at q0 + 2H too.  A pivot there, wall_axis 3. */
static void pivot_elsewhere(qd_modes_picture *pic, const double *jac, const double *far, size_t n,
                            const size_t *owner, size_t a, double size, double jmax) {
    size_t np = pic->np, stride = 3 * np * n;
    const double *ra = pic->rest + 3 * a;
    for (size_t u = 0; u < n; u++) {
        double c[3];
        if (owner[u] != a ||
            !circumcentre(ra, far + u * 3 * np + 3 * a, far + stride + u * 3 * np + 3 * a, c))
            continue;
        double R = dist3(ra, c), origin[3] = {0, 0, 0};
        bool kept = R > 1e-6 * size && R < 1e3 * size && dist3(c, origin) > 1e-6 * size;
        for (size_t v = 0; kept && v < n; v++) {
            const double *d = jac + (v * np + a) * 3;
            if (!(fabs(d[0]) + fabs(d[1]) + fabs(d[2]) > 1e-9 * jmax))
                continue;
            for (unsigned f = 0; f < 3; f++)
                kept &= fabs(dist3(far + f * stride + v * 3 * np + 3 * a, c) - R) <= 1e-7 * R;
        }
        if (kept && pic->nwalls < QD_MODES_PLOT_MAXWALLS && pic->nlinks < QD_MODES_PLOT_MAXLINKS) {
            memcpy(pic->wall + 3 * pic->nwalls, c, sizeof c);
            pic->wall_axis[pic->nwalls] = 3;
            pic->links[pic->nlinks++] = (qd_modes_link_of){a, np + 1 + pic->nwalls++,
                                                           QD_MODES_ROD};
        }
        return;
    }
}

void qd__lin_modes_links(qd_modes_picture *pic, const double *jac, const double *far, size_t n,
                         const double *K, const double *Kw, double size, size_t *owner) {
    size_t np = pic->np;
    double jmax = 0, kmax = 0;
    for (size_t k = 0; k < 3 * np * n; k++)
        jmax = fmax(jmax, fabs(jac[k]));
    for (size_t k = 0; K && k < n * n; k++)
        kmax = fmax(kmax, fabs(K[k]));
    if (!(jmax > 0))
        return;
    owners(jac, n, np, 1e-9 * jmax, owner);
    for (size_t a = 0; a < np; a++) {
        if (rigid(pic->rest, jac, far, n, np, a, np, size, jmax)) {
            pic->pivot = true;
            add_link(pic, np, a, QD_MODES_ROD);
        } else
            pivot_elsewhere(pic, jac, far, n, owner, a, size, jmax);
        for (size_t b = a + 1; b < np; b++) {
            if (rigid(pic->rest, jac, far, n, np, b, a, size, jmax))
                add_link(pic, a, b, QD_MODES_ROD);
            else if (K && kmax > 0 && coupled(K, n, owner, a, b, kmax))
                add_link(pic, a, b, QD_MODES_SPRING);
        }
    }
    for (unsigned e = 0; Kw && kmax > 0 && e < 3; e++)
        walls_along(pic, jac, n, Kw, kmax, owner, e, size);
}
