/*
 * src/scatter/section.c - the deflection function chi(b) of one energy
 * read as a whole (Desloge ch. 60; seed-desloge-B.md C4 and pitfalls 5-6):
 * its kinks (where an orbit grazes a jump or the core), dchi/db, the
 * orbiting impact parameter, rainbows and glories, and the cross section
 * summed over every branch b that gives an angle.
 *
 * chi is smooth between kinks, so the grid is laid out interval by
 * interval between them and no refinement ever straddles one: a jump of
 * chi (the refracting sphere at b = a) is never taken for a root.
 */
#include "sct.h"

#include <math.h>
#include <stdlib.h>
#include "../base/mem.h"
#include "../base/args.h"

#define PI 3.14159265358979323846 /* M_PI is not C11 */
#define GRID 600
#define CROWD 40  /* points crowding towards each end of a piece */
#define MAX_KINKS (2 * QD_SCT_MAX_JUMPS + 4)

typedef struct sct_grid {
    size_t n;
    double *b, *chi;
    int *piece;  /* the interval between kinks the point lies in */
} sct_grid;

/* ---- kinks and orbiting ---------------------------------------------------- */

static void add_kink(double *k, size_t *n, double b) {
    if (b > 0 && isfinite(b) && *n < MAX_KINKS)
        k[(*n)++] = b;
}

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The circular orbits at energy E that are maxima of V_eff: E = V + r V'/2
 * with V' > 0 and V'' + 3 V'/r < 0, b^2 = r^3 V'/(2E) (g = g' = 0).  The
 * largest b is where chi -> -inf (orbiting). */
static bool orbit_point(qd_scatter *s, double E, double *rc, double *bc) {
    double L = qd__sct_scale(s, 0), best_b = 0, best_r = 0;
    for (size_t seg = 0; seg <= s->njump; seg++) {
        double lo = seg ? s->jump[seg - 1] : fmax(s->core, L * 1e-9);
        double hi = seg < s->njump ? s->jump[seg] : L * 1e4, v[4], h0 = NAN, r0 = lo;
        for (int i = 0; i <= 2000; i++) {
            double r = lo * pow(hi / lo, i / 2000.0);
            qd__sct_eval(s, r, lo, hi, v);
            double h = v[0] + r * v[1] / 2 - E;
            if (i && (h > 0) != (h0 > 0)) {
                double a = r0, c = r; /* bisection of E = V + r V'/2 */
                for (int it = 0; it < 100; it++) {
                    double m = 0.5 * (a + c), w[4];
                    qd__sct_eval(s, m, lo, hi, w);
                    if (((w[0] + m * w[1] / 2 - E) > 0) == (h0 > 0))
                        a = m;
                    else
                        c = m;
                }
                double m = 0.5 * (a + c), w[4];
                qd__sct_eval(s, m, lo, hi, w);
                double b2 = m * m * m * w[1] / (2 * E);
                if (w[1] > 0 && w[2] + 3 * w[1] / m < 0 && b2 > best_b * best_b)
                    best_b = sqrt(b2), best_r = m;
            }
            h0 = h, r0 = r;
        }
    }
    *rc = best_r, *bc = best_b;
    return best_b > 0;
}

/* The impact parameters where the kind of orbit changes: grazing each side
 * of a jump and the core (g = 0 there), and the orbiting one. */
static size_t kinks(qd_scatter *s, double E, double *k) {
    size_t n = 0;
    for (size_t i = 0; i < s->njump; i++) {
        double a = s->jump[i];
        for (int side = -1; side <= 1; side += 2) {
            double V = qd__sct_V(s, a, side < 0 ? 0 : a, side < 0 ? a : INFINITY);
            if (1 - V / E > 0)
                add_kink(k, &n, a * sqrt(1 - V / E));
        }
    }
    if (s->core > 0) {
        double V = qd__sct_V(s, s->core, s->core, s->njump ? s->jump[0] : INFINITY);
        if (1 - V / E > 0)
            add_kink(k, &n, s->core * sqrt(1 - V / E));
    }
    double rc, bc;
    if (orbit_point(s, E, &rc, &bc))
        add_kink(k, &n, bc);
    qsort(k, n, sizeof *k, cmp_double);
    return n;
}

/* chi at b; NaN for an orbit that does not leave, and for one so close
 * to orbiting that its integral does not converge: such a grid point is
 * left out (the branches there wind without end anyway). */
static double chi_at(qd_ctx *ctx, qd_scatter *s, double E, double b, qd_status *st) {
    qd_scatter_path p;
    qd_status r = qd_scatter_deflect(ctx, s, E, b, &p);
    if (r == QD_ERR_NUMERIC && qd__ctx_recover(ctx))
        return NAN;
    if (r != QD_OK && *st == QD_OK)
        *st = r;
    return p.kind == QD_SCATTER_DEFLECTED || p.kind == QD_SCATTER_REFLECTED ? p.chi : NAN;
}

static double nearest_kink(const double *k, size_t n, double b) {
    double d = INFINITY;
    for (size_t i = 0; i < n; i++)
        d = fmin(d, fabs(k[i] - b));
    return d;
}

/* 5-point central differences, the stencil kept inside b's interval. */
static qd_status dchi(qd_ctx *ctx, qd_scatter *s, double E, double b, const double *k,
                      size_t nk, double *out) {
    double h = fmin(1e-3 * b, nearest_kink(k, nk, b) / 50);
    qd_status st = QD_OK;
    double f[4], off[4] = {-2, -1, 1, 2};
    for (int i = 0; i < 4; i++)
        f[i] = chi_at(ctx, s, E, b + off[i] * h, &st);
    *out = (f[0] - 8 * f[1] + 8 * f[2] - f[3]) / (12 * h);
    return st;
}

qd_status qd_scatter_dchi_db(qd_ctx *ctx, qd_scatter *s, double E, double b, double *out) {
    QD_ARGS_CTX(ctx, ctx && s && out);
    double k[MAX_KINKS];
    qd_scatter_path p;
    qd_status st = qd_scatter_deflect(ctx, s, E, b, &p);
    if (st != QD_OK)
        return st;
    if (!(b > 0)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "dchi/db is taken at b > 0, not at %g", b);
        return QD_ERR_ARG;
    }
    return dchi(ctx, s, E, b, k, kinks(s, E, k), out);
}

/* ---- the grid --------------------------------------------------------------- */

/* Where V falls below 1e-3 E for good: the length the angles live on. */
static double potential_reach(qd_scatter *s, double E) {
    double L = qd__sct_scale(s, 0);
    if (isfinite(s->range))
        return s->range;
    for (int i = 0; i <= 13 * 50; i++) {
        double r = L * 1e4 * pow(10.0, -i / 50.0), lo, hi;
        qd__sct_segment(s, r, +1, &lo, &hi);
        if (fabs(qd__sct_V(s, r, lo, hi)) > 1e-3 * E)
            return r;
    }
    return L;
}

static void grid_free(sct_grid *g) {
    qd__free(g->b);
    qd__free(g->chi);
    qd__free(g->piece);
}

/* The points of one piece (a, c) of the b axis: uniform, plus points
 * crowding geometrically towards both ends, where chi changes fastest (a
 * Coulomb tail near b = 0, a sphere's edge, an orbiting singularity); the
 * ends themselves stay out, a kink's value belongs to neither side. */
static size_t piece_points(double a, double c, size_t m, double *out) {
    size_t n = 0;
    for (size_t j = 0; j < m; j++)
        out[n++] = a + (c - a) * (j + 0.5) / m;
    for (size_t j = 0; j < CROWD; j++) {
        double d = (c - a) * pow(10.0, -7.0 + 6.0 * j / CROWD);
        out[n++] = a + d;
        out[n++] = c - d;
    }
    qsort(out, n, sizeof *out, cmp_double);
    return n;
}

/* chi on GRID points over (0, bmax], laid out between the kinks. */
static qd_status grid_make(qd_ctx *ctx, qd_scatter *s, double E, double bmax, const double *k,
                           size_t nk, sct_grid *g) {
    double edge[MAX_KINKS + 2];
    size_t ne = 0;
    g->n = 0;
    if (!(bmax > 0 && isfinite(bmax)))  /* range 0 (V = 0, no core): nothing is deflected */
        return QD_OK;
    edge[ne++] = 0;
    for (size_t i = 0; i < nk; i++)
        if (k[i] < bmax)
            edge[ne++] = k[i];
    edge[ne++] = bmax;
    size_t cap = GRID + (20 + 2 * CROWD) * ne;
    g->b = qd__malloc(ctx, cap * sizeof *g->b);
    g->chi = qd__malloc(ctx, cap * sizeof *g->chi);
    g->piece = qd__malloc(ctx, cap * sizeof *g->piece);
    g->n = 0;
    if (!g->b || !g->chi || !g->piece)
        return QD_ERR_NOMEM;
    qd_status st = QD_OK;
    for (size_t i = 0; i + 1 < ne && st == QD_OK; i++) {
        size_t m = 20 + (size_t)(GRID * (edge[i + 1] - edge[i]) / bmax);
        size_t np = piece_points(edge[i], edge[i + 1], m, g->b + g->n);
        for (size_t j = 0; j < np; j++) {
            g->chi[g->n] = chi_at(ctx, s, E, g->b[g->n], &st);
            g->piece[g->n++] = (int)i;
        }
    }
    return st;
}

/* ---- refinement ---------------------------------------------------------------- */

typedef double (*sct_target)(double chi, double arg);

static double t_cos(double chi, double theta) { return cos(chi) - cos(theta); }
static double t_sin(double chi, double unused) { (void)unused; return sin(chi); }

/* A root of target(chi(b)) in (a, c) where it changes sign: bisection. */
static double refine(qd_ctx *ctx, qd_scatter *s, double E, double a, double c, sct_target t,
                     double arg, qd_status *st) {
    double fa = t(chi_at(ctx, s, E, a, st), arg);
    for (int it = 0; it < 80; it++) {
        double m = 0.5 * (a + c), fm = t(chi_at(ctx, s, E, m, st), arg);
        if (m <= a || m >= c || *st != QD_OK)
            break;
        if ((fm > 0) == (fa > 0))
            a = m, fa = fm;
        else
            c = m;
    }
    return 0.5 * (a + c);
}

/* The extremum of chi in (a, c) (golden section), *bx its place. */
static double extremum(qd_ctx *ctx, qd_scatter *s, double E, double a, double c, double sgn,
                       double *bx, qd_status *st) {
    const double k = 0.3819660112501051;
    double x1 = a + k * (c - a), x2 = c - k * (c - a);
    double f1 = sgn * chi_at(ctx, s, E, x1, st), f2 = sgn * chi_at(ctx, s, E, x2, st);
    for (int it = 0; it < 80 && *st == QD_OK; it++) {
        if (f1 > f2)
            c = x2, x2 = x1, f2 = f1, x1 = a + k * (c - a), f1 = sgn * chi_at(ctx, s, E, x1, st);
        else
            a = x1, x1 = x2, f1 = f2, x2 = c - k * (c - a), f2 = sgn * chi_at(ctx, s, E, x2, st);
    }
    *bx = 0.5 * (x1 + x2);
    return sgn * fmax(f1, f2);
}

static bool same_piece(const sct_grid *g, size_t i) {
    return g->piece[i] == g->piece[i + 1] && isfinite(g->chi[i]) && isfinite(g->chi[i + 1]);
}

/* ---- features ------------------------------------------------------------------ */

static void find_rainbows(qd_ctx *ctx, qd_scatter *s, double E, const sct_grid *g,
                          qd_scatter_features *f, qd_status *st) {
    for (size_t i = 1; i + 1 < g->n && f->nrainbow < QD_SCATTER_MAX_FEATURE; i++) {
        if (!same_piece(g, i - 1) || !same_piece(g, i))
            continue;
        double d0 = g->chi[i] - g->chi[i - 1], d1 = g->chi[i + 1] - g->chi[i];
        /* differences at round-off are the quadrature's noise in a far tail */
        double noise = 1e-12 * fmax(1, fabs(g->chi[i]));
        if (!(d0 * d1 < 0) || fabs(d0) < noise || fabs(d1) < noise)
            continue;
        double bx, cx = extremum(ctx, s, E, g->b[i - 1], g->b[i + 1], d0 > 0 ? 1 : -1, &bx, st);
        if (fabs(cx) < 1e-9)
            continue;
        f->rainbow_b[f->nrainbow] = bx;
        f->rainbow_theta[f->nrainbow++] = acos(cos(cx));
    }
}

static void find_glories(qd_ctx *ctx, qd_scatter *s, double E, const sct_grid *g,
                         qd_scatter_features *f, qd_status *st) {
    for (size_t i = 0; i + 1 < g->n && f->nglory < QD_SCATTER_MAX_FEATURE; i++) {
        double s0 = sin(g->chi[i]), s1 = sin(g->chi[i + 1]);
        /* a crossing at round-off size is noise in a far tail, not a glory */
        if (!same_piece(g, i) || !(s0 * s1 < 0) || fmax(fabs(s0), fabs(s1)) < 1e-9)
            continue;
        /* a crossing of a multiple of pi, not a jump of 2 pi in the folding */
        if (fabs(g->chi[i + 1] - g->chi[i]) > PI / 2)
            continue;
        double bx = refine(ctx, s, E, g->b[i], g->b[i + 1], t_sin, 0, st);
        f->glory_b[f->nglory] = bx;
        f->glory_theta[f->nglory++] = cos(g->chi[i]) > 0 ? 0 : PI;
    }
}

static double b_limit(qd_ctx *ctx, qd_scatter *s, double E, double theta, qd_status *st) {
    double bmax = fmax(3 * potential_reach(s, E), qd__sct_scale(s, 0));
    if (isfinite(s->range))
        return s->range * (1 + 1e-12);
    /* an infinite range: out to where |chi| has fallen well below theta */
    double L = qd__sct_scale(s, 0);
    while (bmax < 1e6 * L && fabs(chi_at(ctx, s, E, bmax, st)) > 0.5 * theta && *st == QD_OK)
        bmax *= 2;
    return bmax;
}

/* An absorbing core captures every b whose orbit reaches it: those below
 * b_c, b_c^2 = min over r >= core of r^2 (1 - V/E) (a barrier outside the
 * core, or the core itself: Desloge ch. 60 P5).  Found by bisection on the
 * deflection's own verdict (captured or not is monotone in b: the radial
 * g = 1 - V/E - b^2/r^2 falls as b grows), so it agrees with every orbit
 * shown; b_c <= core sqrt(1 - V(core)/E), the value at r = core. */
static qd_status absorbed_b(qd_ctx *ctx, qd_scatter *s, double E, qd_scatter_features *f) {
    double V = qd__sct_V(s, s->core, s->core, s->njump ? s->jump[0] : INFINITY);
    double lo = 0, hi = s->core * sqrt(fmax(0, 1 - V / E));
    qd_scatter_path p;
    qd_status st = qd_scatter_deflect(ctx, s, E, 0, &p);
    if (st != QD_OK || p.kind != QD_SCATTER_CAPTURED)
        return st; /* not even head-on: a wall or barrier keeps everything out */
    if ((st = qd_scatter_deflect(ctx, s, E, hi, &p)) == QD_OK && p.kind == QD_SCATTER_CAPTURED)
        lo = hi;
    for (int i = 0; i < 200 && st == QD_OK && hi - lo > 4e-16 * hi; i++) {
        double mid = (lo + hi) / 2;
        if ((st = qd_scatter_deflect(ctx, s, E, mid, &p)) == QD_OK)
            *(p.kind == QD_SCATTER_CAPTURED ? &lo : &hi) = mid;
    }
    f->capture = true;
    f->capture_b = lo;
    return st;
}

qd_status qd_scatter_features_at(qd_ctx *ctx, qd_scatter *s, double E, qd_scatter_features *f) {
    QD_ARGS_CTX(ctx, ctx && s && f);
    *f = (qd_scatter_features){.E = E, .range = s->range};
    if (!(E > 0)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the energy must be positive (the particle comes in "
                     "from infinity), not %g", E);
        return QD_ERR_ARG;
    }
    f->total = isfinite(s->range) ? PI * s->range * s->range : INFINITY;
    qd_status st = QD_OK;
    f->orbiting = orbit_point(s, E, &f->orbit_r, &f->orbit_b);
    if (f->orbiting) {
        qd_scatter_path p;
        st = qd_scatter_deflect(ctx, s, E, f->orbit_b * (1 - 1e-6), &p);
        f->capture = p.kind == QD_SCATTER_CAPTURED;
        f->capture_b = f->capture ? f->orbit_b : 0;
    }
    if (st == QD_OK && s->absorbing && s->core > 0)
        st = absorbed_b(ctx, s, E, f);
    double k[MAX_KINKS];
    size_t nk = kinks(s, E, k);
    sct_grid g = {0};
    if (st == QD_OK)
        st = grid_make(ctx, s, E, b_limit(ctx, s, E, 0.05, &st), k, nk, &g);
    if (st == QD_OK)
        find_rainbows(ctx, s, E, &g, f, &st);
    if (st == QD_OK)
        find_glories(ctx, s, E, &g, f, &st);
    grid_free(&g);
    return st;
}

/* ---- the cross section ---------------------------------------------------------- */

static void add_branch(qd_scatter_section *out, double b, double chi, double d) {
    if (out->nbranch == QD_SCATTER_MAX_BRANCH) {
        out->truncated = true;
        return;
    }
    double sigma = b / (sin(out->theta) * fabs(d));
    out->branch[out->nbranch++] = (qd_scatter_branch){b, chi, d, sigma};
    out->sigma += sigma;
}

qd_status qd_scatter_section_at(qd_ctx *ctx, qd_scatter *s, double E, double theta,
                                qd_scatter_section *out) {
    QD_ARGS_CTX(ctx, ctx && s && out);
    *out = (qd_scatter_section){.E = E, .theta = theta};
    if (!(E > 0) || !(theta > 0 && theta < PI)) {
        qd_ctx_error(ctx, QD_ERR_ARG, !(E > 0) ? "the energy must be positive, not %g"
                     : "the angle must lie in (0, pi), not %g", !(E > 0) ? E : theta);
        return QD_ERR_ARG;
    }
    double k[MAX_KINKS];
    size_t nk = kinks(s, E, k);
    qd_status st = QD_OK;
    sct_grid g = {0};
    double bmax = b_limit(ctx, s, E, theta, &st);
    if (st == QD_OK)
        st = grid_make(ctx, s, E, bmax, k, nk, &g);
    for (size_t i = 0; i < g.n && st == QD_OK; i++) {
        double f0 = t_cos(g.chi[i], theta), b, d;
        if (f0 == 0) /* a grid point on the root itself */
            b = g.b[i];
        else if (i + 1 < g.n && same_piece(&g, i) && f0 * t_cos(g.chi[i + 1], theta) < 0)
            b = refine(ctx, s, E, g.b[i], g.b[i + 1], t_cos, theta, &st);
        else
            continue;
        double chi = chi_at(ctx, s, E, b, &st);
        if (st != QD_OK || !(fabs(acos(cos(chi)) - theta) < 1e-7))
            continue;
        st = dchi(ctx, s, E, b, k, nk, &d);
        if (st == QD_OK && d != 0)
            add_branch(out, b, chi, d);
    }
    grid_free(&g);
    return st;
}
