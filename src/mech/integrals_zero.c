/*
 * src/mech/integrals_zero.c - does an expression vanish along the motion?
 *
 * The simplifier is tried first on the expression with the solved
 * accelerations in it; when it does not reach 0 (it is not complete:
 * quotients of trigonometric polynomials defeat it), random states decide:
 * coordinates, velocities, t and parameters drawn at random, the
 * accelerations and multipliers computed there numerically from the
 * equations of motion (qd_eom_eval), and the expression evaluated.  One
 * state where it clearly does not vanish is a counterexample, kept as the
 * witness once ball arithmetic at that state excludes 0 (else no verdict);
 * otherwise it vanishes when it does so at MIN_DEFINED states or more.  The draws are
 * seeded by the expression's hash, so every run gives the same verdict.
 */
#include "integrals_priv.h"
#include "qdot/certify.h"
#include "../base/mem.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#define NPOINTS 12
#define MAX_TRIES 48
#define MIN_DEFINED 6
#define REL_TOL 1e-8

static uint64_t splitmix(uint64_t *z0) {
    uint64_t z = (*z0 += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}

static double uniform(uint64_t *seed) {
    return (double)(splitmix(seed) >> 11) / 9007199254740992.0;
}

/* The value of symbol x at try k.  A parameter with a nonzero value in the
 * model stays within 20% of it (a model's square roots are real for its
 * own parameters: sqrt(a^2 - x^2) in a bowl of radius a); any other symbol
 * is in [0.3, 1.7], of either sign in the second half of each round of
 * NPOINTS tries (the first half stays inside the domains of sqrt and log),
 * and shrunk by half each round, so that small states are tried when
 * large ones fall outside the domain. */
static double draw(const qd__intsys *s, const qd_expr *x, uint64_t *seed, int k) {
    for (size_t i = 0; s && i < qd_model_nparams(s->m); i++)
        if (qd_model_param(s->m, i) == x) {
            const qd_expr *v = qd_model_param_value(s->m, i);
            double p = v && qd_is_number(v) ? qd_number_value(v) : 0;
            if (p != 0)
                return p * (0.8 + 0.4 * uniform(seed));
        }
    double v = (0.3 + 1.4 * uniform(seed)) / (double)(1 << (k / NPOINTS));
    return k % NPOINTS >= NPOINTS / 2 && (splitmix(seed) & 1) ? -v : v;
}

static bool value(qd_ctx *ctx, const qd_expr *x, size_t ns, const qd_expr *const *syms,
                  const double *vals, double *out) {
    if (qd_eval(ctx, x, ns, syms, vals, out) != QD_OK) {
        qd__ctx_recover(ctx);
        return false;
    }
    return isfinite(*out);
}

/* |x| against the size of its terms: -1 undefined, 0 zero, 1 not zero. */
static int test_at(qd_ctx *ctx, const qd_expr *x, size_t ns, const qd_expr *const *syms,
                   const double *vals) {
    double v, term, scale = 1;
    if (!value(ctx, x, ns, syms, vals, &v))
        return -1;
    for (size_t i = 0; qd_expr_kind(x) == QD_ADD && i < qd_expr_nargs(x); i++)
        if (value(ctx, qd_expr_arg(x, i), ns, syms, vals, &term))
            scale = fmax(scale, fabs(term));
    return fabs(v) > REL_TOL * scale;
}

typedef struct points {
    size_t ns, nstate;      /* all symbols; those qd_eom_eval sees */
    const qd_expr **syms;   /* state symbols, other symbols of X, q'', lambda */
    double *vals;
} points;

static bool listed(const points *p, const qd_expr *x) {
    for (size_t i = 0; i < p->ns; i++)
        if (p->syms[i] == x)
            return true;
    return false;
}

static void add(points *p, const qd_expr *x) {
    if (!listed(p, x))
        p->syms[p->ns++] = x;
}

static bool is_motion_symbol(const qd__intsys *s, const qd_expr *x) {
    for (size_t j = 0; j < s->n; j++)
        if (x == s->e->qdd[j])
            return true;
    for (size_t k = 0; k < s->e->ncon; k++)
        if (x == s->e->con[k].lambda)
            return true;
    return false;
}

/* q, q', t, parameters, every other free symbol of X, then q'' and lambda. */
static qd_status points_init(qd_ctx *ctx, const qd__intsys *s, const qd_expr *X, points *p) {
    size_t nx = qd_free_symbols(ctx, X, NULL, 0), np = qd_model_nparams(s->m);
    size_t cap = 3 * s->n + 1 + np + nx + s->e->ncon;
    const qd_expr **xs = qd__malloc(ctx, (nx ? nx : 1) * sizeof *xs);
    p->syms = qd__malloc(ctx, cap * sizeof *p->syms);
    p->vals = qd__calloc(ctx, cap, sizeof *p->vals);
    p->ns = 0;
    if (!xs || !p->syms || !p->vals || qd__ctx_nomem(ctx)) { /* 0 symbols may mean out of memory */
        qd__free(xs);
        return QD_ERR_NOMEM;
    }
    qd_free_symbols(ctx, X, xs, nx);
    if (qd__ctx_nomem(ctx)) {
        qd__free(xs);
        return QD_ERR_NOMEM;
    }
    for (size_t j = 0; j < s->n; j++)
        add(p, s->e->q[j]);
    for (size_t j = 0; j < s->n; j++)
        add(p, s->e->qd[j]);
    add(p, qd_time(ctx));
    for (size_t i = 0; i < np; i++)
        add(p, qd_model_param(s->m, i));
    for (size_t i = 0; i < nx; i++)
        if (!is_motion_symbol(s, xs[i]))
            add(p, xs[i]);
    p->nstate = p->ns;
    for (size_t j = 0; j < s->n; j++)
        p->syms[p->ns++] = s->e->qdd[j];
    for (size_t k = 0; k < s->e->ncon; k++)
        p->syms[p->ns++] = s->e->con[k].lambda;
    qd__free(xs);
    return QD_OK;
}

/* 1 vanishes, -1 counterexample, 0 undecided. */
static int numeric_along(qd_ctx *ctx, const qd__intsys *s, const qd_expr *X, points *p) {
    uint64_t seed = qd_expr_hash(X);
    int defined = 0;
    size_t n = s->n;
    for (int k = 0; k < MAX_TRIES && defined < NPOINTS; k++) {
        for (size_t i = 0; i < p->nstate; i++)
            p->vals[i] = draw(s, p->syms[i], &seed, k);
        double *qdd = p->vals + p->nstate, *lam = qdd + n;
        if (qd_eom_eval(ctx, s->e, p->nstate, p->syms, p->vals, NULL, NULL, qdd,
                        s->e->ncon ? lam : NULL, NULL) != QD_OK) {
            qd__ctx_recover(ctx);
            continue;
        }
        int r = test_at(ctx, X, p->ns, p->syms, p->vals);
        if (r > 0)
            return -1;
        defined += r == 0;
    }
    return defined >= MIN_DEFINED;
}

static const qd_expr *solved(qd_ctx *ctx, const qd__intsys *s, const qd_expr *X) {
    const qd_eom *e = s->e;
    if (!s->solved)
        return X;
    size_t n = e->n, m = e->ncon;
    const qd_expr **from = qd__malloc(ctx, (n + m + 1) * sizeof *from);
    const qd_expr **to = qd__malloc(ctx, (n + m + 1) * sizeof *to);
    const qd_expr *r = NULL;
    if (from && to) {
        for (size_t j = 0; j < n; j++) {
            from[j] = e->qdd[j];
            to[j] = e->acc[j];
        }
        for (size_t k = 0; k < m; k++) {
            from[n + k] = e->con[k].lambda;
            to[n + k] = e->mult[k];
        }
        r = qd_subs(ctx, X, n + m, from, to);
    } else {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory testing an integral");
    }
    qd__free(from);
    qd__free(to);
    return r;
}

/* The counterexample state of p made a witness: X with every symbol at its
 * value (the accelerations and multipliers as the equations gave them)
 * evaluated in ball arithmetic; a "no" only when the ball excludes 0,
 * else no verdict (false). */
static bool certify_state(qd_ctx *ctx, const qd_expr *X, const points *p, qd_zero_result *z) {
    const qd_expr **to = qd__malloc(ctx, (p->ns + 1) * sizeof *to);
    bool ok = to != NULL;
    for (size_t i = 0; ok && i < p->ns; i++)
        ok = (to[i] = qd_float(ctx, p->vals[i])) != NULL;
    const qd_expr *at = ok ? qd_subs(ctx, X, p->ns, p->syms, to) : NULL;
    qd__free(to);
    qd_zero_result r;
    if (!at || qd_zero_test(ctx, at, &r) != QD_OK || r.kind != QD_ZERO_NONZERO) {
        qd__ctx_recover(ctx);
        return false;
    }
    *z = r;
    /* the point: the whole state (q, q', t, parameters), since the
     * accelerations in X depend on all of it */
    z->witness.n = 0;
    for (size_t i = 0; i < p->nstate && z->witness.n < QD_WITNESS_MAX; i++) {
        z->witness.sym[z->witness.n] = p->syms[i];
        z->witness.at[z->witness.n++] = p->vals[i];
    }
    return true;
}

qd_status qd__mech_int_zero(qd_ctx *ctx, const qd__intsys *s, const qd_expr *X,
                       const qd_expr **shown, bool *zero, bool *numeric, qd_zero_result *cert) {
    *zero = *numeric = false;
    qd_zero_result none;
    if (!cert)
        cert = &none;
    *cert = (qd_zero_result){.kind = QD_ZERO_UNKNOWN};
    *shown = X ? qd_simplify(ctx, solved(ctx, s, X)) : NULL;
    if (!*shown)
        return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    if (qd_is_zero(*shown)) {
        *zero = true;
        cert->kind = QD_ZERO_PROVEN;
        return QD_OK;
    }
    /* with the accelerations solved, *shown is explicit in q, q', t and the
     * parameters: the certified test (qdot/certify.h) decides it, a "no" only
     * with a point where its ball excludes 0 (issue 33); the sampling along
     * the motion below is left for what that cannot decide */
    if (s->solved) {
        qd_zero_result z;
        qd_status zs = qd_zero_test(ctx, *shown, &z);
        if (zs == QD_ERR_NOMEM)
            return zs;
        if (zs == QD_OK && z.kind != QD_ZERO_UNKNOWN) {
            *zero = z.kind != QD_ZERO_NONZERO;
            *numeric = z.kind == QD_ZERO_NUMERIC;
            *cert = z;
            return QD_OK;
        }
        qd__ctx_recover(ctx);
    }
    points p;
    qd_status st = points_init(ctx, s, X, &p);
    if (st == QD_OK) {
        int r = numeric_along(ctx, s, X, &p);
        /* a counterexample in doubles counts once certified at its state */
        if (r < 0 && !certify_state(ctx, X, &p, cert))
            r = 0;
        *zero = r > 0;
        *numeric = r >= 0; /* with *zero false: undecided */
        if (r > 0)
            *cert = (qd_zero_result){.kind = QD_ZERO_NUMERIC, .points = NPOINTS, .bits = 53};
    }
    qd__free(p.syms);
    qd__free(p.vals);
    return st;
}

qd_status qd__mech_int_identically_zero(qd_ctx *ctx, const qd__intsys *s, const qd_expr *X,
                                   bool *zero, bool *numeric) {
    *zero = *numeric = false;
    const qd_expr *x = X ? qd_simplify(ctx, X) : NULL;
    if (!x)
        return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    if (qd_is_zero(x)) {
        *zero = true;
        return QD_OK;
    }
    size_t ns = qd_free_symbols(ctx, X, NULL, 0);
    const qd_expr **syms = qd__malloc(ctx, (ns ? ns : 1) * sizeof *syms);
    double *vals = qd__malloc(ctx, (ns ? ns : 1) * sizeof *vals);
    if (syms)
        qd_free_symbols(ctx, X, syms, ns);
    if (!syms || !vals || qd__ctx_nomem(ctx)) { /* 0 symbols may mean out of memory */
        qd__free(syms);
        qd__free(vals);
        return QD_ERR_NOMEM;
    }
    uint64_t seed = qd_expr_hash(X);
    int defined = 0, r = 0;
    for (int k = 0; k < MAX_TRIES && r <= 0 && defined < NPOINTS; k++) {
        for (size_t i = 0; i < ns; i++)
            vals[i] = draw(s, syms[i], &seed, k);
        r = test_at(ctx, X, ns, syms, vals);
        defined += r == 0;
    }
    *zero = r <= 0 && defined >= MIN_DEFINED;
    *numeric = r <= 0; /* with *zero false: undecided */
    qd__free(syms);
    qd__free(vals);
    return QD_OK;
}
