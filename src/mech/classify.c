/*
 * src/mech/classify.c - is a Pfaffian constraint integrable?
 *
 * Desloge, ch. 49 (and seed-desloge-A C6, pitfall 4): a constraint
 * sum_j a_j q'_j + a_0 = 0 is the 1-form w = sum_j a_j dq_j + a_0 dt on the
 * variables x = (q, t).  It is
 *   exact          when dw = 0 (d a_i/d x_j = d a_j/d x_i); then w = d phi and
 *                  phi(q, t) = const along the motion;
 *   integrable     when w ^ dw = 0: some factor mu makes mu w exact.  The
 *                  factor is searched among a few candidates (see
 *                  candidates()); when none fits, the constraint is still
 *                  integrable but its integral is not given (NULL);
 *   nonholonomic   otherwise.
 * Several forms are integrable together (Frobenius) when
 * dw_k ^ w_1 ^ ... ^ w_m = 0 for every k: two no-slip conditions of a rolling
 * disk can each be fine alone and fail together.
 *
 * Zero tests.  An expression is taken to be 0 when qd_simplify gives 0, or,
 * when it does not, when it vanishes (to 1e-8 relative to its terms) at every
 * one of several random points where it is defined, at least MIN_DEFINED of
 * them: a point where it clearly does not vanish is a counterexample and
 * wins over everything.  The points are tried first, because a counterexample
 * ends the test cheaply.  An expression that cannot be evaluated (a user
 * function, too few points in its domain) and does not simplify to 0 counts
 * as nonzero: calling an integrable constraint nonholonomic only keeps a
 * multiplier, the reverse would eliminate a coordinate wrongly.
 */
#include "mech.h"
#include "../base/mem.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#define NPOINTS 10
#define MIN_DEFINED 4
#define REL_TOL 1e-8

/* ---- zero tests --------------------------------------------------------- */

static uint64_t splitmix(uint64_t *s) {
    uint64_t z = (*s += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}

/* Point k: the first half positive (inside log and sqrt domains), the rest
 * of either sign, never near 0. */
static double coordinate(uint64_t *s, int k) {
    double u = (double)(splitmix(s) >> 11) / 9007199254740992.0;
    double v = 0.3 + 1.4 * u;
    if (k >= NPOINTS / 2 && (splitmix(s) & 1))
        v = -v;
    return v;
}

/* e at one point; false when it has no finite value there. */
static bool value_at(qd_ctx *ctx, const qd_expr *e, size_t ns, const qd_expr **syms,
                     const double *vals, double *out) {
    qd_status st = qd_eval(ctx, e, ns, syms, vals, out);
    if (st != QD_OK) {
        qd__ctx_recover(ctx);
        return false;
    }
    return isfinite(*out);
}

/* 1: vanishes at every defined point (enough of them); -1: a
 * counterexample; 0: undecided. */
static int numeric_zero(qd_ctx *ctx, const qd_expr *e, const qd_expr **syms, size_t ns) {
    double vals[64];
    uint64_t seed = qd_expr_hash(e);
    int defined = 0;
    if (ns > 64)
        return 0;
    for (int k = 0; k < NPOINTS; k++) {
        for (size_t i = 0; i < ns; i++)
            vals[i] = coordinate(&seed, k);
        double v, scale = 1, term;
        if (!value_at(ctx, e, ns, syms, vals, &v))
            continue;
        for (size_t i = 0; qd_expr_kind(e) == QD_ADD && i < qd_expr_nargs(e); i++)
            if (value_at(ctx, qd_expr_arg(e, i), ns, syms, vals, &term))
                scale = fmax(scale, fabs(term));
        if (fabs(v) > REL_TOL * scale)
            return -1;
        defined++;
    }
    return defined >= MIN_DEFINED ? 1 : 0;
}

/* *zero as the header comment defines it.  Never called with an error
 * already recorded in ctx (value_at clears the ones it causes). */
static qd_status vanishes(qd_ctx *ctx, const qd_expr *e, bool *zero) {
    *zero = false;
    if (!e)
        return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    if (qd_is_zero(e)) {
        *zero = true;
        return QD_OK;
    }
    size_t ns = qd_free_symbols(ctx, e, NULL, 0);
    const qd_expr **syms = qd__malloc(ctx, (ns ? ns : 1) * sizeof *syms);
    if (!syms || qd__ctx_nomem(ctx)) { /* 0 symbols may mean out of memory */
        qd__free(syms);
        return QD_ERR_NOMEM;
    }
    qd_free_symbols(ctx, e, syms, ns);
    if (qd__ctx_nomem(ctx)) {
        qd__free(syms);
        return QD_ERR_NOMEM;
    }
    int num = numeric_zero(ctx, e, syms, ns);
    qd__free(syms);
    if (num < 0)
        return QD_OK;
    const qd_expr *s = qd_simplify(ctx, e);
    if (!s)
        return qd_ctx_status(ctx);
    *zero = qd_is_zero(s) || num > 0;
    return QD_OK;
}

/* ---- forms -------------------------------------------------------------- */

/* The forms restricted to the variables that occur in them: a variable
 * absent from every coefficient and with no coefficient of its own adds
 * nothing to d w or to any wedge. */
typedef struct forms {
    qd_ctx *ctx;
    size_t nv, m;         /* variables, forms */
    const qd_expr **x;    /* nv variables */
    const qd_expr **w;    /* m * nv coefficients, row-major */
} forms;

static bool occurs(const qd_expr *const *w, size_t m, size_t stride, size_t i,
                   const qd_expr *xi, size_t nx) {
    for (size_t k = 0; k < m; k++) {
        if (!qd_is_zero(w[k * stride + i]))
            return true;
        for (size_t j = 0; j < nx; j++)
            if (qd_has(w[k * stride + j], xi))
                return true;
    }
    return false;
}

/* Build f from m constraints over x = (q, t); a NULL a0 is 0. */
static qd_status forms_init(forms *f, qd_ctx *ctx, size_t n, const qd_expr *const *q,
                            const qd_con *const *cs, size_t m) {
    size_t nx = n + 1;
    const qd_expr **all = qd__malloc(ctx, m * nx * sizeof *all), **xs = qd__malloc(ctx, nx * sizeof *xs);
    *f = (forms){ctx, 0, m, NULL, NULL};
    f->x = qd__malloc(ctx, nx * sizeof *f->x);
    f->w = qd__malloc(ctx, m * nx * sizeof *f->w);
    if (!all || !xs || !f->x || !f->w) {
        qd__free(all);
        qd__free(xs);
        return QD_ERR_NOMEM;
    }
    for (size_t j = 0; j < nx; j++)
        xs[j] = j < n ? q[j] : qd_time(ctx);
    for (size_t k = 0; k < m; k++)
        for (size_t j = 0; j < nx; j++)
            all[k * nx + j] = j < n ? cs[k]->a[j] : cs[k]->a0 ? cs[k]->a0 : qd_int(ctx, 0);
    for (size_t j = 0; j < nx; j++) {
        if (!occurs(all, m, nx, j, xs[j], nx))
            continue;
        for (size_t k = 0; k < m; k++)
            f->w[k * nx + f->nv] = all[k * nx + j];
        f->x[f->nv++] = xs[j];
    }
    for (size_t k = 0; k < m; k++) /* close the gaps: rows of stride nv */
        for (size_t j = 0; j < f->nv; j++)
            f->w[k * f->nv + j] = f->w[k * nx + j];
    qd__free(all);
    qd__free(xs);
    return QD_OK;
}

static void forms_free(forms *f) {
    qd__free(f->x);
    qd__free(f->w);
}

/* (d w)_ij = d w_j / d x_i - d w_i / d x_j for the row w. */
static const qd_expr *curl(const forms *f, const qd_expr *const *w, size_t i, size_t j) {
    return qd_sub(f->ctx, qd_diff(f->ctx, w[j], f->x[i]), qd_diff(f->ctx, w[i], f->x[j]));
}

/* Is the single row w (nv coefficients) exact? */
static qd_status exact(const forms *f, const qd_expr *const *w, bool *ok) {
    *ok = true;
    for (size_t i = 0; i < f->nv && *ok; i++)
        for (size_t j = i + 1; j < f->nv && *ok; j++) {
            qd_status st = vanishes(f->ctx, curl(f, w, i, j), ok);
            if (st != QD_OK)
                return st;
        }
    return QD_OK;
}

/* ---- Frobenius ------------------------------------------------------------ */

/* The m x m minor of the forms on the columns cols[0..m). */
static const qd_expr *minor(const forms *f, const size_t *cols, size_t m, size_t row) {
    qd_ctx *ctx = f->ctx;
    if (m == 0)
        return qd_int(ctx, 1);
    const qd_expr *sum = qd_int(ctx, 0);
    size_t rest[16];
    for (size_t c = 0; c < m; c++) {
        const qd_expr *a = f->w[row * f->nv + cols[c]];
        if (qd_is_zero(a))
            continue;
        for (size_t i = 0, r = 0; i < m; i++)
            if (i != c)
                rest[r++] = cols[i];
        const qd_expr *t = qd_mul(ctx, a, minor(f, rest, m - 1, row + 1));
        sum = c % 2 ? qd_sub(ctx, sum, t) : qd_add(ctx, sum, t);
    }
    return sum;
}

/* The component on the variables T[0..m+2) of dw_k ^ w_1 ^ ... ^ w_m:
 * the sum over pairs p < r of T of (dw_k)_{T_p T_r} times the minor on the
 * rest, signed by the permutation (T_p, T_r, rest) -> T, (-1)^(p + r - 1). */
static const qd_expr *wedge(const forms *f, size_t k, const size_t *T) {
    qd_ctx *ctx = f->ctx;
    size_t m = f->m, rest[16];
    const qd_expr *sum = qd_int(ctx, 0);
    for (size_t p = 0; p < m + 2; p++)
        for (size_t r = p + 1; r < m + 2; r++) {
            const qd_expr *d = curl(f, f->w + k * f->nv, T[p], T[r]);
            if (d && qd_is_zero(d))
                continue;
            for (size_t i = 0, s = 0; i < m + 2; i++)
                if (i != p && i != r)
                    rest[s++] = T[i];
            const qd_expr *t = qd_mul(ctx, d, minor(f, rest, m, 0));
            sum = (p + r) % 2 ? qd_add(ctx, sum, t) : qd_sub(ctx, sum, t);
        }
    return sum;
}

/* The next subset of size len of {0..n) in lexicographic order. */
static bool next_subset(size_t *T, size_t len, size_t n) {
    size_t i = len;
    while (i > 0 && T[i - 1] == n - len + i - 1)
        i--;
    if (i == 0)
        return false;
    T[i - 1]++;
    for (size_t j = i; j < len; j++)
        T[j] = T[j - 1] + 1;
    return true;
}

/* Every dw_k ^ w_1 ^ ... ^ w_m vanishes (vacuous with fewer than m + 2
 * variables). */
static qd_status involutive(const forms *f, bool *ok) {
    size_t len = f->m + 2, T[18];
    *ok = true;
    if (len > f->nv)
        return QD_OK;
    if (len > 18)
        return QD_ERR_TOOBIG;
    for (size_t i = 0; i < len; i++)
        T[i] = i;
    do {
        for (size_t k = 0; k < f->m && *ok; k++) {
            qd_status st = vanishes(f->ctx, wedge(f, k, T), ok);
            if (st != QD_OK)
                return st;
        }
    } while (*ok && next_subset(T, len, f->nv));
    return QD_OK;
}

/* ---- integrals ------------------------------------------------------------ */

/* phi with d phi = w, integrating the variables in the order start,
 * start + 1, ... (cyclically): integrate what d phi still lacks in x_k with
 * respect to x_k.  NULL, with no error left in ctx, when some step has no
 * closed form or the result does not check. */
static const qd_expr *potential_from(const forms *f, const qd_expr *const *w, size_t start) {
    qd_ctx *ctx = f->ctx;
    const qd_expr *phi = qd_int(ctx, 0);
    for (size_t i = 0; i < f->nv && phi; i++) {
        size_t k = (start + i) % f->nv;
        bool none;
        const qd_expr *r = qd_simplify(ctx, qd_sub(ctx, w[k], qd_diff(ctx, phi, f->x[k])));
        if (vanishes(ctx, r, &none) != QD_OK || none)
            continue;
        phi = qd_add(ctx, phi, qd_integrate(ctx, r, f->x[k]));
    }
    if (!phi) {
        if (qd_ctx_status(ctx) == QD_ERR_ARG)
            qd__ctx_recover(ctx);
        return NULL;
    }
    phi = qd_simplify(ctx, phi);
    for (size_t k = 0; k < f->nv && phi; k++) {
        bool ok;
        if (vanishes(ctx, qd_sub(ctx, qd_diff(ctx, phi, f->x[k]), w[k]), &ok) != QD_OK || !ok)
            phi = NULL;
    }
    return phi;
}

/* The potential of an exact w, or NULL: each variable is tried first in
 * turn, since (q2 + cos q1)^4 integrates in q2 but not in q1. */
static const qd_expr *potential(const forms *f, const qd_expr *const *w) {
    const qd_expr *phi = NULL;
    for (size_t start = 0; start < f->nv && !phi && qd_ctx_status(f->ctx) == QD_OK; start++)
        phi = potential_from(f, w, start);
    return phi;
}

/* ---- integrating factors -------------------------------------------------- */

typedef struct cands {
    const qd_expr *mu[256];
    size_t n;
} cands;

static void cand_add(cands *c, const qd_expr *mu) {
    if (!mu || qd_is_number(mu) || c->n == sizeof c->mu / sizeof c->mu[0])
        return;
    for (size_t i = 0; i < c->n; i++)
        if (c->mu[i] == mu)
            return;
    c->mu[c->n++] = mu;
}

/* The factors tried, simplest first: 1/a_j; x_j^p (p = -1, -2, 1, 2);
 * x_i^p x_j^r (p, r = +-1); 1/(x_i^2 + x_j^2); 1/a_j^2, 1/(a_i a_j), a_j.
 * They cover the textbook cases: x y' - y x' (1/x^2), y' + (y/x) x' (x),
 * the homogeneous forms (1/(x^2 + y^2)). */
static void candidates(const forms *f, const qd_expr *const *w, cands *c) {
    qd_ctx *ctx = f->ctx;
    size_t nv = f->nv;
    static const long pw[4] = {-1, -2, 1, 2};
    c->n = 0;
    for (size_t j = 0; j < nv; j++)
        if (!qd_is_zero(w[j]))
            cand_add(c, qd_powi(ctx, w[j], -1));
    for (int p = 0; p < 4; p++)
        for (size_t j = 0; j < nv; j++)
            cand_add(c, qd_powi(ctx, f->x[j], pw[p]));
    for (size_t i = 0; i < nv; i++)
        for (size_t j = i + 1; j < nv; j++) {
            for (int p = 0; p < 4; p++)
                cand_add(c, qd_mul(ctx, qd_powi(ctx, f->x[i], p % 2 ? 1 : -1),
                                   qd_powi(ctx, f->x[j], p / 2 ? 1 : -1)));
            cand_add(c, qd_powi(ctx, qd_add(ctx, qd_powi(ctx, f->x[i], 2),
                                            qd_powi(ctx, f->x[j], 2)), -1));
        }
    for (size_t i = 0; i < nv; i++) {
        if (qd_is_zero(w[i]))
            continue;
        cand_add(c, qd_powi(ctx, w[i], -2));
        cand_add(c, w[i]);
        for (size_t j = i + 1; j < nv; j++)
            if (!qd_is_zero(w[j]))
                cand_add(c, qd_powi(ctx, qd_mul(ctx, w[i], w[j]), -1));
    }
}

/* Try mu: *exact when mu w is exact, and then its potential (may be NULL). */
static qd_status try_factor(const forms *f, const qd_expr *mu, bool *ok, const qd_expr **phi) {
    const qd_expr *mw[64];
    *phi = NULL;
    for (size_t j = 0; j < f->nv; j++)
        mw[j] = qd_mul(f->ctx, mu, f->w[j]);
    qd_status st = exact(f, mw, ok);
    if (st == QD_OK && *ok)
        *phi = potential(f, mw);
    return st;
}

static bool has_log(const qd_expr *e) {
    if (qd_expr_kind(e) == QD_FUNC && qd_expr_func(e) == QD_LOG)
        return true;
    for (size_t i = 0; i < qd_expr_nargs(e); i++)
        if (has_log(qd_expr_arg(e, i)))
            return true;
    return false;
}

/* An integrable, not exact form: the first candidate factor that gives an
 * integral free of logarithms (x y, not log(x) + log(y)), else the first
 * that gives one, else the first that makes the form exact, else none. */
static qd_status search_factor(const forms *f, qd_con *c) {
    cands *cs = qd__malloc(f->ctx, sizeof *cs);
    qd_status st = QD_OK;
    if (!cs)
        return QD_ERR_NOMEM;
    candidates(f, f->w, cs);
    c->factor = c->integral = NULL;
    for (size_t i = 0; i < cs->n && st == QD_OK; i++) {
        bool ok;
        const qd_expr *phi;
        st = try_factor(f, cs->mu[i], &ok, &phi);
        if (st != QD_OK || !ok || (c->integral && !phi) || (c->factor && !phi))
            continue;
        if (!c->integral || !has_log(phi)) {
            c->factor = cs->mu[i];
            c->integral = phi;
        }
        if (phi && !has_log(phi))
            break;
    }
    qd__free(cs);
    return st;
}

/* ---- entry points --------------------------------------------------------- */

static bool has_velocity(size_t n, const qd_con *c) {
    for (size_t j = 0; j < n; j++)
        if (!qd_is_zero(c->a[j]))
            return true;
    return false;
}

static qd_status classify_form(const forms *f, qd_con *c) {
    bool ok;
    qd_status st = exact(f, f->w, &ok);
    if (st != QD_OK)
        return st;
    if (ok) {
        c->kind = QD_CON_INTEGRABLE;
        c->factor = qd_int(f->ctx, 1);
        c->integral = potential(f, f->w);
        return QD_OK;
    }
    if ((st = involutive(f, &ok)) != QD_OK)
        return st;
    if (!ok) {
        c->kind = QD_CON_NONHOLONOMIC;
        c->factor = c->integral = NULL;
        return QD_OK;
    }
    c->kind = QD_CON_INTEGRABLE;
    if (f->nv > 64) {
        c->factor = c->integral = NULL;
        return QD_OK;
    }
    return search_factor(f, c);
}

qd_status qd__mech_con_classify(qd_ctx *ctx, size_t n, const qd_expr *const *q, qd_con *c) {
    if (qd_ctx_status(ctx) != QD_OK)
        return qd_ctx_status(ctx);
    if (!has_velocity(n, c)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "constraint %s has no velocities: it is not Pfaffian",
                     c->name ? c->name : "");
        return QD_ERR_ARG;
    }
    const qd_con *one[1] = {c};
    forms f;
    qd_status st = forms_init(&f, ctx, n, q, one, 1);
    if (st == QD_OK)
        st = classify_form(&f, c);
    forms_free(&f);
    if (st == QD_ERR_NOMEM && qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, st, "out of memory classifying a constraint");
    return st != QD_OK && qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : st;
}

const qd_expr *qd__mech_con_integral(qd_ctx *ctx, size_t n, const qd_expr *const *q,
                               const qd_con *c) {
    forms f;
    const qd_expr *phi = NULL;
    if (forms_init(&f, ctx, n, q, &c, 1) == QD_OK && f.nv > 0)
        phi = potential(&f, f.w);
    forms_free(&f);
    return phi;
}

qd_status qd__mech_con_frobenius(qd_ctx *ctx, size_t n, const qd_expr *const *q, qd_con *const *cs,
                            size_t m, bool *integrable) {
    *integrable = true;
    if (qd_ctx_status(ctx) != QD_OK)
        return qd_ctx_status(ctx);
    if (m > 16) {
        qd_ctx_error(ctx, QD_ERR_TOOBIG, "integrability of %zu constraints together: at most 16",
                     m);
        return QD_ERR_TOOBIG;
    }
    if (m == 0)
        return QD_OK;
    forms f;
    qd_status st = forms_init(&f, ctx, n, q, (const qd_con *const *)cs, m);
    if (st == QD_OK)
        st = involutive(&f, integrable);
    forms_free(&f);
    if (st == QD_ERR_NOMEM && qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, st, "out of memory testing constraints for integrability");
    return st != QD_OK && qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : st;
}
