/*
 * src/linear/steady_all.c - every steady motion for the given values
 * (qd_steady_find_all), and the size of a residual's terms.
 *
 * A steady motion solves the kept residuals f_k(x, w) = 0 with the given
 * momenta p_c(x, w) = P_c.  T is quadratic in the velocities, so at rest in
 * x the f_k are polynomials of degree <= 2 in the rates and the p_c linear
 * ones.  When a single unknown is left free once the given momenta have
 * fixed the other rates, the problem is one-dimensional along it:
 *   - a rate: each f_k is a quadratic in it, read off from three samples
 *     (a fourth checks the degree) and solved exactly: the heavy top's
 *     A phi'^2 cos th - C n phi' + M g h = 0 gives the slow and the fast
 *     precession (Goldstein 3rd ed. sec. 5.7; Britannica 1911 "Dynamics"
 *     sec. 5 (29)-(30), seed 004);
 *   - a coordinate: every sign change of each f_k over its range (an
 *     angle's period; else a grid about 0 and a geometric ladder out to
 *     1e12 and in to 1e-9 of the start's scale), bisected.
 * Each candidate is polished by the search of steady.c and kept only when
 * its relative residual is small, so poles and round-off zeros drop out.
 */
#include "steady.h"

#include "base/ptrmap.h"
#include "base/mem.h"
#include "../base/args.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static const double PI = 3.14159265358979323846;

/* Samples over the range of a free coordinate. */
#define SCAN_POINTS 400
/* A quadratic's coefficient is zero below this times the size of its row. */
#define COEFF_TOL 1e-10
/* A steady motion's rows vanish below this times the size of their terms. */
#define AT_SCALE_TOL 1e-8

/* ---- the size of a residual's terms ------------------------------------ */

typedef struct sizes {
    qd_ctx *ctx;
    const qd__steady_env *env;
    qd__ptrmap memo;       /* node -> 1 + index into val */
    double *val;
    size_t n, cap;
} sizes;

static double value(sizes *z, const qd_expr *x) {
    double v;
    if (qd_eval(z->ctx, x, z->env->n, z->env->syms, z->env->vals, &v) != QD_OK) {
        qd__ctx_recover(z->ctx);
        return NAN;
    }
    return fabs(v);
}

static double size_of(sizes *z, const qd_expr *x);

static double size_uncached(sizes *z, const qd_expr *x) {
    size_t n = qd_expr_nargs(x);
    double s;
    switch (qd_expr_kind(x)) {
    case QD_ADD:
        s = 0;
        for (size_t i = 0; i < n; i++)
            s += size_of(z, qd_expr_arg(x, i));
        return s;
    case QD_MUL:
        s = 1;
        for (size_t i = 0; i < n; i++)
            s *= size_of(z, qd_expr_arg(x, i));
        return s;
    case QD_POW: {
        const qd_expr *ex = qd_expr_arg(x, 1);
        /* a denominator that cancels makes the term large: its value counts */
        if (qd_is_number(ex) && qd_number_value(ex) > 0)
            return pow(size_of(z, qd_expr_arg(x, 0)), qd_number_value(ex));
        return value(z, x);
    }
    case QD_FUNC:
        if (qd_expr_func(x) == QD_SIN || qd_expr_func(x) == QD_COS)
            return 1;
        return value(z, x);
    default:
        return value(z, x);
    }
}

static double size_of(sizes *z, const qd_expr *x) {
    uintptr_t k = (uintptr_t)qd__ptrmap_get(&z->memo, x);
    if (k)
        return z->val[k - 1];
    double s = size_uncached(z, x);
    if (z->n == z->cap) {
        size_t cap = z->cap ? 2 * z->cap : 64;
        double *nv = qd__realloc(z->ctx, z->val, cap * sizeof *nv);
        if (!nv)
            return s;
        z->val = nv;
        z->cap = cap;
    }
    z->val[z->n++] = s;
    if (!qd__ptrmap_put(&z->memo, x, (void *)(uintptr_t)z->n))
        z->n--;
    return s;
}

double qd__lin_steady_magnitude(qd_ctx *ctx, const qd__steady_env *env, const qd_expr *x) {
    sizes z = {.ctx = ctx, .env = env, .memo = QD_PTRMAP_INIT};
    double s = x ? size_of(&z, x) : NAN;
    qd__ptrmap_free(&z.memo);
    qd__free(z.val);
    return s;
}

/* ---- angles ------------------------------------------------------------- */

static bool in_trig(const qd_expr *x, const qd_expr *q, qd__ptrmap *seen) {
    if (!x || qd__ptrmap_has(seen, x))
        return false;
    qd__ptrmap_put(seen, x, (void *)x);
    if (qd_expr_kind(x) == QD_FUNC && (qd_expr_func(x) == QD_SIN || qd_expr_func(x) == QD_COS ||
                                       qd_expr_func(x) == QD_TAN))
        return qd_has(qd_expr_arg(x, 0), q);
    for (size_t i = 0; i < qd_expr_nargs(x); i++)
        if (in_trig(qd_expr_arg(x, i), q, seen))
            return true;
    return false;
}

/* Is kept coordinate j an angle (inside a sin or cos of the equations)? */
static bool is_angle(const qd_steady *s, size_t j) {
    qd__ptrmap seen = QD_PTRMAP_INIT;
    bool a = false;
    for (size_t k = 0; !a && k < s->nkeep; k++)
        a = in_trig(s->res[k], s->keep[j], &seen);
    for (size_t c = 0; !a && c < s->ncyc; c++)
        a = in_trig(s->mom[c], s->keep[j], &seen);
    qd__ptrmap_free(&seen);
    return a;
}

static double wrap(double x) {
    x = fmod(x, 2 * PI);
    if (x <= -PI)
        x += 2 * PI;
    else if (x > PI)
        x -= 2 * PI;
    return fabs(x + PI) < 1e-12 ? PI : x;
}

/* ---- the one-dimensional problem ----------------------------------------- */

typedef struct line {
    qd__steady_search *S;
    size_t ifree;              /* the free unknown */
    bool rate;                 /* it is a rate (else a kept coordinate) */
    qd__steady_search sub;     /* the given momenta in the bound rates */
    double *usub, *F;
} line;

static bool unknown_is_rate(const qd__steady_search *S, size_t i) {
    return S->uslot[i] >= S->env.w && S->uslot[i] < S->env.w + S->s->ncyc;
}

/* The momentum rows of S as a square search in the bound unknowns (the rates
 * whose momentum is given): those rows' derivatives, S's environment. */
static qd_status sub_search(qd__steady_search *S, const bool *bound, qd__steady_search *sub) {
    size_t nk = S->s->nkeep, nb = S->neq - nk, b = 0;
    *sub = (qd__steady_search){.ctx = S->ctx, .s = S->s, .env = S->env, .nu = nb, .neq = nb,
                               .F = S->F + nk, .pgiven = S->pgiven + nk};
    sub->uslot = qd__calloc(S->ctx, nb + 1, sizeof *sub->uslot);
    sub->dF = qd__calloc(S->ctx, nb * nb + 1, sizeof *sub->dF);
    if (!sub->uslot || !sub->dF)
        return QD_ERR_NOMEM;
    for (size_t i = 0; i < S->nu; i++) {
        if (!bound[i])
            continue;
        if (b == nb)
            return QD_ERR_ARG;
        sub->uslot[b] = S->uslot[i];
        for (size_t r = 0; r < nb; r++)
            sub->dF[r * nb + b] = S->dF[(nk + r) * S->nu + i];
        b++;
    }
    return b == nb ? QD_OK : QD_ERR_ARG;
}

static void sub_free(qd__steady_search *sub) {
    qd__free(sub->uslot);
    qd__free(sub->dF);
}

/* u with the free unknown at t and the bound rates solving the given momenta;
 * the kept residuals there in L->F.  false where that fails (a singular
 * point, no solution). */
static bool on_line(line *L, double t, double *u) {
    qd__steady_search *S = L->S;
    u[L->ifree] = t;
    qd_status st = qd__lin_steady_residual(S, u, L->F, NULL);
    if (st == QD_OK && L->sub.nu) {
        for (size_t b = 0, i = 0; i < S->nu; i++)
            if (i != L->ifree)
                L->usub[b++] = u[i];
        st = qd__lin_steady_iterate(&L->sub, L->usub, NULL);
        for (size_t b = 0, i = 0; st == QD_OK && i < S->nu; i++)
            if (i != L->ifree)
                u[i] = L->usub[b++];
        if (st == QD_OK)
            st = qd__lin_steady_residual(S, u, L->F, NULL);
    }
    if (st != QD_OK)
        qd__ctx_recover(S->ctx);
    return st == QD_OK;
}

/* ---- the motions found ------------------------------------------------------ */

typedef struct found {
    size_t nu, count, cap;
    double *u, *res;
    const bool *angle;         /* nu: the unknown is an angle */
    const qd_expr **mcc;       /* ncyc: dp_c/dc', the cyclic coordinate's inertia */
    size_t nsingular;
} found;

/* Does a cyclic coordinate move nothing here (dp_c/dc' = 0: theta = 0 of
 * spherical coordinates, where phi' means nothing)?  The Routhian is not
 * defined there, and a "steady motion" is an artefact of the coordinates. */
static bool singular_here(qd__steady_search *S, const found *f) {
    for (size_t c = 0; c < S->s->ncyc; c++) {
        double v;
        if (qd__lin_steady_eval(S->ctx, &S->env, f->mcc[c], &v) != QD_OK) {
            qd__ctx_recover(S->ctx);
            return true;
        }
        double m = qd__lin_steady_magnitude(S->ctx, &S->env, f->mcc[c]);
        if (fabs(v) <= 1e-10 * (isfinite(m) ? m : 0))
            return true;
    }
    return false;
}

static bool same(const found *f, const double *a, const double *b) {
    for (size_t i = 0; i < f->nu; i++) {
        double d = fabs(a[i] - b[i]);
        if (f->angle[i])
            d = fmin(d, fabs(2 * PI - d));
        if (d > 1e-7 * fmax(1, fmax(fabs(a[i]), fabs(b[i]))))
            return false;
    }
    return true;
}

/* Is the polished u a steady motion at the scale of the equations' own
 * terms?  The search's residual also forgives |J| |u| (how far a step could
 * move it), which a runaway (r -> 0 with th' -> 1e31 on -k/r - beta/r^2)
 * makes huge: there p_th = m r^2 th' = 0.316 passed for the 2 given.  Here
 * every unknown is finite and each row's residual is judged against the
 * given momentum and the size of the row's terms only. */
static bool at_scale(qd__steady_search *S, const double *u) {
    double *F = qd__calloc(S->ctx, S->neq + 1, sizeof *F);
    bool ok = F != NULL;
    for (size_t i = 0; ok && i < S->nu; i++)
        ok = isfinite(u[i]);
    if (ok && qd__lin_steady_residual(S, u, F, NULL) != QD_OK) {
        qd__ctx_recover(S->ctx);
        ok = false;
    }
    for (size_t k = 0; ok && k < S->neq; k++) {
        double m = qd__lin_steady_magnitude(S->ctx, &S->env, S->F[k]);
        ok = isfinite(F[k]) && isfinite(m) && fabs(F[k]) <= AT_SCALE_TOL * (fabs(S->pgiven[k]) + m);
    }
    qd__free(F);
    return ok;
}

/* Polish u (a candidate) and keep it when it is a steady motion not seen yet. */
static qd_status polish_add(qd__steady_search *S, found *f, double *u) {
    double res = 0;
    qd_status st = qd__lin_steady_iterate(S, u, &res);
    if (st != QD_OK) {
        qd__ctx_recover(S->ctx);
        return st == QD_ERR_NOMEM ? st : QD_OK;
    }
    if (!at_scale(S, u))
        return qd__ctx_nomem(S->ctx) ? QD_ERR_NOMEM : QD_OK;
    if (singular_here(S, f)) {
        f->nsingular++;
        return QD_OK;
    }
    for (size_t i = 0; i < f->nu; i++)
        if (f->angle[i])
            u[i] = wrap(u[i]);
    for (size_t k = 0; k < f->count; k++)
        if (same(f, f->u + k * f->nu, u))
            return QD_OK;
    if (f->count == f->cap) {
        size_t cap = f->cap ? 2 * f->cap : 8;
        double *nu = qd__realloc(S->ctx, f->u, (cap * f->nu + 1) * sizeof *nu);
        if (!nu)
            return QD_ERR_NOMEM;
        f->u = nu;
        double *nr = qd__realloc(S->ctx, f->res, cap * sizeof *nr);
        if (!nr)
            return QD_ERR_NOMEM;
        f->res = nr;
        f->cap = cap;
    }
    memcpy(f->u + f->count * f->nu, u, f->nu * sizeof *u);
    f->res[f->count++] = res;
    return QD_OK;
}

/* ---- a free rate: the roots of quadratics ---------------------------------- */

/* Real roots of c2 t^2 + c1 t + c0 (coefficients already chopped to 0). */
static size_t quad_roots(const double c[3], double t[2]) {
    if (c[2] == 0) {
        if (c[1] == 0)
            return 0;
        t[0] = c[0] == 0 ? 0 : -c[0] / c[1];
        return 1;
    }
    double d = c[1] * c[1] - 4 * c[2] * c[0];
    double big = c[1] * c[1] + fabs(4 * c[2] * c[0]);
    if (d < -1e-12 * big)
        return 0;
    if (d <= 1e-12 * big) {  /* a double root: exactly 0 when c1 = c0 = 0 */
        t[0] = c[1] == 0 ? 0 : -c[1] / (2 * c[2]);
        return 1;
    }
    double q = -(c[1] + copysign(sqrt(d), c[1])) / 2;
    t[0] = q / c[2];
    t[1] = q != 0 ? c[0] / q : 0;
    return 2;
}

/* Each kept row as a quadratic in the free rate about 0 (samples at -h, 0,
 * h, checked at 2h): coefficients c (nkeep*3), 0 below COEFF_TOL of the
 * row's size.  1 when every row is identically zero, -1 when a row is not a
 * quadratic or a sample fails, else 0. */
static int row_quadratics(line *L, double *u, double h, double *c) {
    qd__steady_search *S = L->S;
    size_t nk = S->s->nkeep;
    const double ts[4] = {-h, 0, h, 2 * h};
    double *f = qd__calloc(S->ctx, 4 * nk + 1, sizeof *f), *scale = qd__calloc(S->ctx, nk + 1, sizeof *scale);
    int rc = f && scale ? 1 : -1;
    for (int p = 0; rc != -1 && p < 4; p++) {
        if (!on_line(L, ts[p], u)) {
            rc = -1;
            break;
        }
        for (size_t k = 0; k < nk; k++) {
            f[p * nk + k] = L->F[k];
            scale[k] = fmax(scale[k], qd__lin_steady_magnitude(S->ctx, &S->env, S->F[k]));
        }
    }
    for (size_t k = 0; rc != -1 && k < nk; k++) {
        double fm = f[k], f0 = f[nk + k], fp = f[2 * nk + k], f2 = f[3 * nk + k];
        double *ck = c + 3 * k, tol = COEFF_TOL * (isfinite(scale[k]) ? scale[k] : 0);
        ck[0] = f0;
        ck[1] = (fp - fm) / (2 * h);
        ck[2] = (fp + fm - 2 * f0) / (2 * h * h);
        if (fabs(ck[0] + 2 * h * ck[1] + 4 * h * h * ck[2] - f2) > 1e-7 * (scale[k] + fabs(f2)))
            rc = -1;
        for (int d = 0; d < 3; d++)
            if (fabs(ck[d]) * pow(h, d) <= tol)
                ck[d] = 0;
        if (ck[0] != 0 || ck[1] != 0 || ck[2] != 0)
            rc = rc == 1 ? 0 : rc;
    }
    qd__free(f);
    qd__free(scale);
    return rc;
}

static qd_status free_rate(line *L, found *f, double *u, const double *u0, bool *complete) {
    size_t nk = L->S->s->nkeep;
    double h = fmax(1, fabs(u0[L->ifree]));
    double *c = qd__calloc(L->S->ctx, 3 * nk + 1, sizeof *c);
    if (!c)
        return QD_ERR_NOMEM;
    memcpy(u, u0, L->S->nu * sizeof *u);
    int rc = row_quadratics(L, u, h, c);
    qd_status st = rc == -1 && qd__ctx_nomem(L->S->ctx) ? QD_ERR_NOMEM : QD_OK; /* not "no quadratic" */
    if (rc == 1) {
        const qd_steady *s = L->S->s;
        size_t cslot = L->S->uslot[L->ifree] - L->S->env.w;
        qd_ctx_error(L->S->ctx, QD_ERR_ARG,
                     "every value of %s is a steady motion here (the kept equations vanish "
                     "whatever it is): give %s or the momentum p_%s", qd_expr_name(s->cycd[cslot]),
                     qd_expr_name(s->cycd[cslot]), qd_expr_name(s->cyc[cslot]));
        st = QD_ERR_ARG;
    }
    for (size_t k = 0; rc == 0 && st == QD_OK && k < nk; k++) {
        double t[2];
        size_t nr = quad_roots(c + 3 * k, t);
        for (size_t r = 0; r < nr && st == QD_OK; r++)
            if (on_line(L, t[r], u))
                st = polish_add(L->S, f, u);
    }
    *complete = rc == 0;
    qd__free(c);
    return st;
}

/* ---- a free coordinate: sign changes over its range ---------------------- */

/* Bisect row k of the kept residuals on [a, b] (F_k of opposite signs at the
 * ends, fa the value at a), then polish. */
static qd_status bisect(line *L, found *f, double *u, size_t k, double a, double b, double fa) {
    for (int it = 0; it < 80 && b - a > 1e-15 * fmax(1, fabs(a)); it++) {
        double m = (a + b) / 2;
        if (!on_line(L, m, u))
            return QD_OK;
        if ((L->F[k] < 0) == (fa < 0)) {
            a = m;
            fa = L->F[k];
        } else {
            b = m;
        }
    }
    return on_line(L, (a + b) / 2, u) ? polish_add(L->S, f, u) : QD_OK;
}

/* Is kept residual k at round-off, against the size of its terms? */
static bool at_noise(line *L, size_t k) {
    double m = qd__lin_steady_magnitude(L->S->ctx, &L->S->env, L->S->F[k]);
    return fabs(L->F[k]) <= COEFF_TOL * (isfinite(m) ? m : 0);
}

static qd_status family(line *L) {
    const qd_expr *q = L->S->env.syms[L->S->uslot[L->ifree]];
    qd_ctx_error(L->S->ctx, QD_ERR_ARG,
                 "every value of %s is a steady motion here (the kept equations vanish "
                 "whatever it is): give %s with --at", qd_expr_name(q), qd_expr_name(q));
    return QD_ERR_ARG;
}

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The samples of a free coordinate: an angle's range (-pi, pi] on a grid half
 * a step off (a root at an end, th = pi, is crossed, not sampled); any other
 * coordinate on a grid of [-10 s, 10 s] about 0 (s = max(1, |start|)) and, on
 * each side, a geometric ladder from 1e-9 s to 1e12 s (issue 33: a circle at
 * r = 24.9 or r = 0.0089 on V = -k/r - beta/r^2 lies off the grid, and a root
 * next to the pole at 0 changes no sign between two grid points).  Sorted,
 * count in *n; NULL when out of memory. */
#define LADDER_LO 1e-9
#define LADDER_HI 1e12
#define LADDER_RATIO 1.2
static double *coord_samples(qd_ctx *ctx, double g, bool angle, size_t *n) {
    double lo = angle ? -PI : -10 * fmax(1, g);
    double step = (angle ? 2 * PI : 20 * fmax(1, g)) / SCAN_POINTS;
    size_t rungs = angle ? 0 : (size_t)ceil(log(LADDER_HI / LADDER_LO) / log(LADDER_RATIO)) + 1;
    double *t = qd__calloc(ctx, SCAN_POINTS + 1 + 2 * rungs + 1, sizeof *t);
    if (!t)
        return NULL;
    size_t k = 0;
    for (size_t i = 0; i <= SCAN_POINTS; i++)
        t[k++] = lo + (i + 0.5) * step;
    for (size_t i = 0; i < rungs; i++) {
        double r = LADDER_LO * fmax(1, g) * pow(LADDER_RATIO, (double)i);
        t[k++] = r;
        t[k++] = -r;
    }
    qsort(t, k, sizeof *t, cmp_double);
    *n = k;
    return t;
}

static qd_status free_coord(line *L, found *f, double *u, const double *u0, bool angle,
                            bool *complete) {
    qd__steady_search *S = L->S;
    size_t nk = S->s->nkeep, nsamples = 0, nzero = 0, nt = 0;
    double *ts = coord_samples(L->S->ctx, fabs(u0[L->ifree]), angle, &nt);
    double *prev = qd__calloc(L->S->ctx, nk + 1, sizeof *prev), tp = 0;
    bool *pzero = qd__calloc(L->S->ctx, nk + 1, sizeof *pzero), *zero = qd__calloc(L->S->ctx, nk + 1, sizeof *zero);
    bool have = false;
    qd_status st = ts && prev && pzero && zero ? QD_OK : QD_ERR_NOMEM;
    memcpy(u, u0, S->nu * sizeof *u);
    for (size_t i = 0; st == QD_OK && i < nt; i++) {
        double t = ts[i];
        if (!on_line(L, t, u)) {
            have = false;
            continue;
        }
        bool all = true;
        for (size_t k = 0; k < nk; k++)
            all = (zero[k] = at_noise(L, k)) && all;
        nsamples++;
        nzero += all;
        /* a sign change between two values at round-off is noise, not a root */
        for (size_t k = 0; have && st == QD_OK && k < nk; k++)
            if ((prev[k] < 0) != (L->F[k] < 0) && !(pzero[k] && zero[k])) {
                st = bisect(L, f, u, k, tp, t, prev[k]);
                on_line(L, t, u);   /* L->F back to the sample at t */
            }
        memcpy(prev, L->F, nk * sizeof *prev);
        memcpy(pzero, zero, nk * sizeof *pzero);
        tp = t;
        have = true;
    }
    if (st == QD_OK && nsamples > 1 && nzero == nsamples)
        st = family(L);
    *complete = angle;
    qd__free(ts);
    qd__free(prev);
    qd__free(pzero);
    qd__free(zero);
    return st;
}

/* ---- assembly ---------------------------------------------------------------- */

/* Rates marked in pguess: solved from the momenta start->p at the start. */
static qd_status rates_from_momenta(qd_ctx *ctx, const qd_steady *s, size_t nvals,
                                    const qd_expr *const *syms, const double *vals,
                                    const bool *pguess, qd_steady_point *pt) {
    bool *xf = qd__calloc(ctx, s->nkeep + 1, sizeof *xf), *wf = qd__calloc(ctx, s->ncyc + 1, sizeof *wf);
    bool *all = qd__calloc(ctx, s->ncyc + 1, sizeof *all);
    qd__steady_search S = {.ctx = ctx, .s = s}, sub = {0};
    qd_status st = xf && wf && all ? QD_OK : QD_ERR_NOMEM;
    for (size_t j = 0; st == QD_OK && j < s->nkeep; j++)
        xf[j] = true;
    for (size_t c = 0; st == QD_OK && c < s->ncyc; c++)
        wf[c] = !pguess[c];
    if (st == QD_OK)
        st = qd__lin_steady_search_init(&S, xf, wf, pguess, pt, nvals, syms, vals);
    for (size_t i = 0; st == QD_OK && i < S.nu; i++)
        all[i] = true;
    if (st == QD_OK)
        st = sub_search(&S, all, &sub);
    double *u = st == QD_OK ? qd__calloc(ctx, S.nu + 1, sizeof *u) : NULL;
    for (size_t i = 0; u && i < S.nu; i++)
        u[i] = S.env.vals[S.uslot[i]];
    if (st == QD_OK)
        st = u ? qd__lin_steady_iterate(&sub, u, NULL) : QD_ERR_NOMEM;
    for (size_t c = 0, i = 0; st == QD_OK && c < s->ncyc; c++)
        if (pguess[c])
            pt->w[c] = u[i++];
    if (st != QD_OK && st != QD_ERR_NOMEM)
        qd_ctx_error(ctx, st, "the momenta given as the guess do not fix the rates at the "
                              "starting point: %s", qd_ctx_message(ctx));
    qd__free(u);
    sub_free(&sub);
    qd__lin_steady_search_free(&S);
    qd__free(xf);
    qd__free(wf);
    qd__free(all);
    return st;
}

/* The structured search when one unknown is free. */
static qd_status structured(qd__steady_search *S, const bool *pfix, const bool *angle,
                            found *f, const double *u0, bool *complete) {
    size_t nfree = 0, ifree = 0;
    bool *bound = qd__calloc(S->ctx, S->nu + 1, sizeof *bound);
    if (!bound)
        return QD_ERR_NOMEM;
    for (size_t i = 0; i < S->nu; i++) {
        bound[i] = unknown_is_rate(S, i) && pfix[S->uslot[i] - S->env.w];
        if (!bound[i]) {
            nfree++;
            ifree = i;
        }
    }
    line L = {.S = S, .ifree = ifree, .rate = nfree == 1 && unknown_is_rate(S, ifree)};
    qd_status st = QD_OK;
    if (nfree == 1) {
        L.usub = qd__calloc(S->ctx, S->nu + 1, sizeof *L.usub);
        L.F = qd__calloc(S->ctx, S->neq + 1, sizeof *L.F);
        double *u = qd__calloc(S->ctx, S->nu + 1, sizeof *u);
        st = L.usub && L.F && u ? sub_search(S, bound, &L.sub) : QD_ERR_NOMEM;
        if (st == QD_OK)
            st = L.rate ? free_rate(&L, f, u, u0, complete)
                        : free_coord(&L, f, u, u0, angle[ifree], complete);
        sub_free(&L.sub);
        qd__free(L.usub);
        qd__free(L.F);
        qd__free(u);
    }
    qd__free(bound);
    return st;
}

/* What the motions are ordered by: how far each is from the start in the
 * values that were not given, a momentum guessed with --guess compared as a
 * momentum. */
typedef struct order_key {
    const qd_steady *s;
    const qd_steady_point *start;
    const bool *xfix, *wfix, *pfix, *pguess, *xangle;
} order_key;

static double dist(const order_key *o, const qd_steady_point *p) {
    double d = 0;
    for (size_t j = 0; j < o->s->nkeep; j++) {
        double e = o->xfix[j] ? 0 : fabs(p->x[j] - o->start->x[j]);
        if (o->xangle[j])
            e = fmin(e, fabs(2 * PI - e));
        d += e * e;
    }
    for (size_t c = 0; c < o->s->ncyc; c++) {
        double e = o->wfix[c] || o->pfix[c] ? 0
                 : o->pguess && o->pguess[c] ? p->p[c] - o->start->p[c]
                 : p->w[c] - o->start->w[c];
        d += e * e;
    }
    return d;
}

/* Nearest the start first (insertion sort: there are a few). */
static void by_distance(const order_key *o, qd_steady_set *out) {
    for (size_t k = 1; k < out->count; k++) {
        qd_steady_point p = out->pts[k];
        double r = out->residual[k], dk = dist(o, &p);
        size_t j = k;
        for (; j > 0 && dist(o, &out->pts[j - 1]) > dk; j--) {
            out->pts[j] = out->pts[j - 1];
            out->residual[j] = out->residual[j - 1];
        }
        out->pts[j] = p;
        out->residual[j] = r;
    }
}

static qd_status fill(qd__steady_search *S, const found *f, qd_steady_set *out) {
    const qd_steady *s = S->s;
    out->pts = qd__calloc(S->ctx, f->count + 1, sizeof *out->pts);
    out->residual = qd__calloc(S->ctx, f->count + 1, sizeof *out->residual);
    if (!out->pts || !out->residual)
        return QD_ERR_NOMEM;
    qd_status st = QD_OK;
    for (size_t k = 0; st == QD_OK && k < f->count; k++) {
        qd_steady_point *p = &out->pts[out->count++];
        p->x = qd__calloc(S->ctx, s->nkeep + 1, sizeof *p->x);
        p->w = qd__calloc(S->ctx, s->ncyc + 1, sizeof *p->w);
        p->p = qd__calloc(S->ctx, s->ncyc + 1, sizeof *p->p);
        if (!p->x || !p->w || !p->p) {
            st = QD_ERR_NOMEM;
            break;
        }
        const double *u = f->u + k * f->nu;
        out->residual[k] = f->res[k];
        for (size_t i = 0; i < S->nu; i++)
            S->env.vals[S->uslot[i]] = u[i];
        for (size_t j = 0; j < s->nkeep; j++)
            p->x[j] = S->env.vals[S->env.x + j];
        for (size_t c = 0; st == QD_OK && c < s->ncyc; c++) {
            p->w[c] = S->env.vals[S->env.w + c];
            st = qd__lin_steady_eval(S->ctx, &S->env, s->mom[c], &p->p[c]);
        }
    }
    return st;
}

void qd_steady_set_free(qd_steady_set *set) {
    if (!set)
        return;
    for (size_t k = 0; k < set->count; k++) {
        qd__free(set->pts[k].x);
        qd__free(set->pts[k].w);
        qd__free(set->pts[k].p);
    }
    qd__free(set->pts);
    qd__free(set->residual);
    memset(set, 0, sizeof *set);
}

/* The search from the start, last: its message is the one left when nothing
 * is found; a failure is no error once the structured search found some. */
/* Halton's radical inverse of i in base b, in [0, 1). */
static double radical(size_t i, unsigned b) {
    double f = 1, r = 0;
    for (; i; i /= b) {
        f /= b;
        r += f * (double)(i % b);
    }
    return r;
}

#define SPREAD_STARTS 48  /* the fallback's starts (spread_starts) */

/* The start failed and nothing was found: starts spread (a Halton sequence)
 * over the box u0 +- 2 max(1, |u0|) in the unknowns, each polished and kept
 * as any other (issue 33: a rod with a sliding bead, Desloge A T21, started
 * at th = 0, where V_eff's p^2/sin^2 th is singular, and its steady cone at
 * th = pi/3, x = 4a/3 was "not found" without --guess).  QD_OK when one
 * converged; else the first start's error stands. */
static qd_status spread_starts(qd__steady_search *S, found *f, const double *u0, double *u) {
    static const unsigned primes[] = {2, 3, 5, 7, 11, 13, 17, 19};
    size_t nu = S->nu;
    if (nu == 0 || nu > sizeof primes / sizeof primes[0])
        return QD_ERR_NUMERIC;
    for (size_t k = 1; k <= SPREAD_STARTS; k++) {
        for (size_t i = 0; i < nu; i++)
            u[i] = u0[i] + 2 * fmax(1, fabs(u0[i])) * (2 * radical(k, primes[i]) - 1);
        double res = 0;
        qd_status st = qd__lin_steady_iterate(S, u, &res);
        if (st == QD_ERR_NOMEM)
            return st;
        qd__ctx_recover(S->ctx);
        if (st == QD_OK && (st = polish_add(S, f, u)) != QD_OK)
            return st;
    }
    return f->count ? QD_OK : QD_ERR_NUMERIC;
}

static qd_status from_start(qd__steady_search *S, found *f, const double *u0, double *u) {
    memcpy(u, u0, S->nu * sizeof *u);
    double res = 0;
    qd_status st = qd__lin_steady_iterate(S, u, &res);
    if ((st == QD_ERR_NUMERIC || st == QD_ERR_SINGULAR) && f->count == 0 && f->nsingular == 0) {
        qd_diag first = *qd_ctx_diag(S->ctx);  /* the start's own error, kept if none is found */
        qd__ctx_recover(S->ctx);
        qd_status sp = spread_starts(S, f, u0, u);
        if (sp == QD_ERR_NOMEM)
            return sp;
        if (sp != QD_OK)
            qd_ctx_error(S->ctx, st, "%s", first.message);
        else
            st = QD_ERR_NUMERIC; /* found: the branch below keeps what the spread found */
    }
    if (st == QD_OK || ((st == QD_ERR_NUMERIC || st == QD_ERR_SINGULAR) && f->count)) {
        qd__ctx_recover(S->ctx);
        st = st == QD_OK ? polish_add(S, f, u) : QD_OK;
    }
    if ((st == QD_OK || st == QD_ERR_NUMERIC) && f->count == 0 && f->nsingular) {
        qd__ctx_recover(S->ctx);
        qd_ctx_error(S->ctx, QD_ERR_SINGULAR, "the only steady motion%s found %s at a singular "
                     "point of the coordinates (a cyclic coordinate that moves nothing there): "
                     "choose coordinates regular there", f->nsingular > 1 ? "s" : "",
                     f->nsingular > 1 ? "are" : "is");
        st = QD_ERR_SINGULAR;
    }
    return st;
}

/* The unknowns' starting values and which are angles; each cyclic
 * coordinate's inertia dp_c/dc'. */
static qd_status prepare_found(qd__steady_search *S, found *f, double *u0, bool *angle) {
    const qd_steady *s = S->s;
    for (size_t i = 0; i < S->nu; i++) {
        u0[i] = S->env.vals[S->uslot[i]];
        angle[i] = !unknown_is_rate(S, i) && is_angle(s, S->uslot[i] - S->env.x);
    }
    *f = (found){.nu = S->nu, .angle = angle, .mcc = qd__calloc(S->ctx, s->ncyc + 1, sizeof *f->mcc)};
    if (!f->mcc)
        return QD_ERR_NOMEM;
    for (size_t c = 0; c < s->ncyc; c++)
        if (!(f->mcc[c] = qd_diff(S->ctx, s->mom[c], s->cycd[c])))
            return qd_ctx_status(S->ctx);
    return QD_OK;
}

/* out from the motions found, nearest the start first. */
static qd_status ordered(qd__steady_search *S, const found *f, const qd_steady_point *start,
                         const bool *xfix, const bool *wfix, const bool *pfix,
                         const bool *pguess, qd_steady_set *out) {
    const qd_steady *s = S->s;
    bool *xangle = qd__calloc(S->ctx, s->nkeep + 1, sizeof *xangle);
    if (!xangle)
        return QD_ERR_NOMEM;
    for (size_t j = 0; j < s->nkeep; j++)
        xangle[j] = is_angle(s, j);
    qd_status st = fill(S, f, out);
    if (st == QD_OK) {
        order_key o = {s, start, xfix, wfix, pfix, pguess, xangle};
        by_distance(&o, out);
    }
    out->nsingular = f->nsingular;
    qd__free(xangle);
    return st;
}

static qd_steady_point copy_point(qd_ctx *ctx, const qd_steady *s, const qd_steady_point *from) {
    qd_steady_point p = {qd__calloc(ctx, s->nkeep + 1, sizeof *p.x), qd__calloc(ctx, s->ncyc + 1, sizeof *p.w),
                         qd__calloc(ctx, s->ncyc + 1, sizeof *p.p)};
    if (p.x && p.w && p.p) {
        memcpy(p.x, from->x, s->nkeep * sizeof *p.x);
        memcpy(p.w, from->w, s->ncyc * sizeof *p.w);
        memcpy(p.p, from->p, s->ncyc * sizeof *p.p);
    }
    return p;
}

/* Motions whose reduced equations cannot be linearized (qd_stability_analyze
 * says QD_ERR_SINGULAR: M0 singular, a term not defined there) are left out
 * and counted with the singular ones; when every one is, that error stands. */
static qd_status drop_unanalysable(qd_ctx *ctx, const qd_steady *s, size_t nvals,
                                   const qd_expr *const *syms, const double *vals,
                                   qd_steady_set *out) {
    size_t kept = 0, n = out->count;
    for (size_t k = 0; k < n; k++) {
        qd_stability an;
        qd_status st = qd_stability_analyze(ctx, s, nvals, syms, vals, &out->pts[k], &an);
        qd_stability_free(&an);
        if (st == QD_ERR_SINGULAR && (kept > 0 || k + 1 < n)) {
            qd_ctx_clear_error(ctx);
            qd__free(out->pts[k].x);
            qd__free(out->pts[k].w);
            qd__free(out->pts[k].p);
            out->nsingular++;
            continue;
        }
        if (st != QD_OK) {
            /* the set frees [0, count): the rest moves down after the kept */
            memmove(out->pts + kept, out->pts + k, (n - k) * sizeof *out->pts);
            out->count = kept + (n - k);
            return st;
        }
        out->pts[kept] = out->pts[k];
        out->residual[kept++] = out->residual[k];
    }
    out->count = kept;
    return QD_OK;
}

qd_status qd_steady_find_all(qd_ctx *ctx, const qd_steady *s, size_t nvals,
                             const qd_expr *const *syms, const double *vals, const bool *xfix,
                             const bool *wfix, const bool *pfix, const bool *pguess,
                             const qd_steady_point *start, qd_steady_set *out) {
    QD_ARGS_CTX(ctx, ctx && s && (nvals == 0 || syms) && (nvals == 0 || vals) && xfix && wfix && pfix && start && out);
    memset(out, 0, sizeof *out);
    bool had_nomem = qd__ctx_nomem(ctx);
    qd_steady_point pt = copy_point(ctx, s, start);
    qd__steady_search S = {.ctx = ctx, .s = s};
    found f = {0};
    double *u0 = NULL, *u = NULL;
    bool *angle = NULL, any_guess = false;
    qd_status st = pt.x && pt.w && pt.p ? QD_OK : QD_ERR_NOMEM;
    for (size_t c = 0; pguess && c < s->ncyc; c++)
        any_guess = any_guess || pguess[c];
    if (st == QD_OK && any_guess)
        st = rates_from_momenta(ctx, s, nvals, syms, vals, pguess, &pt);
    if (st == QD_OK)
        st = qd__lin_steady_search_init(&S, xfix, wfix, pfix, &pt, nvals, syms, vals);
    if (st == QD_OK) {
        u0 = qd__calloc(ctx, S.nu + 1, sizeof *u0);
        u = qd__calloc(ctx, S.nu + 1, sizeof *u);
        angle = qd__calloc(ctx, S.nu + 1, sizeof *angle);
        st = u0 && u && angle ? prepare_found(&S, &f, u0, angle) : QD_ERR_NOMEM;
    }
    if (st == QD_OK && S.nu)
        st = structured(&S, pfix, angle, &f, u0, &out->complete);
    if (st == QD_OK)
        st = from_start(&S, &f, u0, u);
    if (st == QD_OK)
        st = ordered(&S, &f, &pt, xfix, wfix, pfix, pguess, out);
    if (st == QD_OK)
        st = drop_unanalysable(ctx, s, nvals, syms, vals, out);
    if (st == QD_OK && !had_nomem && qd__ctx_nomem(ctx))
        st = QD_ERR_NOMEM; /* a search that ran out was taken for "none there" */
    if (st != QD_OK) {
        if (qd_ctx_status(ctx) == QD_OK)
            qd_ctx_error(ctx, st, "out of memory finding the steady motions");
        qd_steady_set_free(out);
    }
    qd__free(f.u);
    qd__free(f.res);
    qd__free(f.mcc);
    qd__free(u0);
    qd__free(u);
    qd__free(angle);
    qd__free(pt.x);
    qd__free(pt.w);
    qd__free(pt.p);
    qd__lin_steady_search_free(&S);
    return st;
}
