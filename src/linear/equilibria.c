/*
 * src/linear/equilibria.c - configurations of rest: exact where the
 * equations come apart one unknown at a time, numerical otherwise, each
 * classified by K = -dF/dq (qdot/equilibria.h has the method).
 */
#include "qdot/equilibria.h"

#include "base/ptrmap.h"
#include "linear.h"
#include "num/num.h"
#include "qdot/constrained.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const double PI = 3.14159265358979323846;

/* Exact solutions beyond this many are not enumerated (the numeric search
 * takes over). */
#define MAX_EXACT 256

const char *qd_eq_kind_name(qd_eq_kind k) {
    switch (k) {
    case QD_EQ_MINIMUM: return "minimum";
    case QD_EQ_MAXIMUM: return "maximum";
    case QD_EQ_SADDLE: return "saddle";
    default: return "degenerate";
    }
}

/* ---- which coordinates are angles ------------------------------------------ */

/* A coordinate is an angle when the equations are 2 pi-periodic in it:
 * it appears inside sin, cos or tan, and only there, each time as
 * k q + (terms free of q) with k a nonzero integer (d(arg)/dq = k).  Both
 * conditions matter: the box, the folding of roots into (-pi, pi] and the
 * merging of roots 2 pi apart are right only then.  A chain of pendulums
 * with springs on the angle differences, V = -g cos th_i + k/2 (th_{i+1} -
 * th_i)^2, is not periodic in any th_i: folded, its roots were listed with
 * residuals 2 pi k (issue 33). */
typedef struct angle_walk {
    qd_ctx *ctx;
    const qd_eom *e;
    bool *in_trig, *bare; /* per coordinate: inside a trig function; anywhere else */
    qd__ptrmap seen;
} angle_walk;

static void mark_angles(angle_walk *w, const qd_expr *x) {
    if (!x || qd__ptrmap_has(&w->seen, x))
        return;
    qd__ptrmap_put(&w->seen, x, (void *)x);
    const qd_eom *e = w->e;
    if (qd_expr_kind(x) == QD_FUNC &&
        (qd_expr_func(x) == QD_SIN || qd_expr_func(x) == QD_COS || qd_expr_func(x) == QD_TAN)) {
        const qd_expr *arg = qd_expr_arg(x, 0);
        for (size_t j = 0; j < e->n; j++)
            if (qd_has(arg, e->q[j])) {
                const qd_expr *k = qd_diff(w->ctx, arg, e->q[j]);
                w->in_trig[j] = true;
                if (!k || !qd_is_integer(k) || qd_is_zero(k))
                    w->bare[j] = true; /* sin(q^2), cos(q/2), sin(q*t): not 2 pi-periodic */
            }
        return;
    }
    for (size_t j = 0; j < e->n; j++)
        if (x == e->q[j])
            w->bare[j] = true;
    for (size_t i = 0; i < qd_expr_nargs(x); i++)
        mark_angles(w, qd_expr_arg(x, i));
}

qd_status qd_equilibria_default_box(qd_ctx *ctx, const qd_eom *e, const qd_model *m, bool *angle,
                                    double *lo, double *hi) {
    QD_ARGS_CTX(ctx, ctx && e && m && angle && lo && hi);
    bool *flags = qd__calloc(ctx, 2 * e->n + 1, sizeof *flags);
    if (!flags)
        return QD_ERR_NOMEM;
    angle_walk w = {ctx, e, flags, flags + e->n, QD_PTRMAP_AL(qd__ctx_allocator(ctx))};
    for (size_t j = 0; j < e->n; j++)
        mark_angles(&w, e->f[j]);
    mark_angles(&w, e->L);
    if (m) {
        mark_angles(&w, qd_model_kinetic(m));
        mark_angles(&w, qd_model_potential(m));
    }
    qd__ptrmap_free(&w.seen);
    for (size_t j = 0; j < e->n; j++)
        angle[j] = w.in_trig[j] && !w.bare[j];
    qd__free(flags);
    if (qd_ctx_status(ctx) == QD_ERR_NOMEM)
        return QD_ERR_NOMEM;
    for (size_t j = 0; lo && hi && j < e->n; j++) {
        lo[j] = angle[j] ? -PI : -10;
        hi[j] = angle[j] ? PI : 10;
    }
    return QD_OK;
}

/* ---- exact solutions ------------------------------------------------------- */

typedef struct exact {
    qd_ctx *ctx;
    size_t n;
    const qd_expr *const *q;
    const bool *angle;
    const qd_expr **val;        /* n: the current assignment */
    const qd_expr **sols;       /* nsol * n */
    size_t nsol;
    bool failed;                /* the equations do not come apart: go numeric */
    bool continuum;
    const qd_expr *z;           /* a scratch symbol */
} exact;

static bool value_of(qd_ctx *ctx, const qd_expr *x, double *v) {
    if (qd_eval(ctx, x, 0, NULL, NULL, v) != QD_OK) {
        qd__ctx_recover(ctx);
        return false;
    }
    return isfinite(*v);
}

/* The unknowns (unassigned coordinates) in x: how many, the last one. */
static size_t unknowns(const exact *x, const qd_expr *e, size_t *which) {
    size_t c = 0;
    for (size_t j = 0; j < x->n; j++)
        if (!x->val[j] && qd_has(e, x->q[j])) {
            c++;
            *which = j;
        }
    return c;
}

/* The factors of e that may vanish: a product's factors, a power's base
 * (positive exponent); a negative power never vanishes. */
static size_t factors(const qd_expr *e, const qd_expr **out, size_t cap) {
    size_t nf = qd_expr_kind(e) == QD_MUL ? qd_expr_nargs(e) : 1, k = 0;
    for (size_t i = 0; i < nf && k < cap; i++) {
        const qd_expr *f = qd_expr_kind(e) == QD_MUL ? qd_expr_arg(e, i) : e;
        if (qd_expr_kind(f) == QD_POW) {
            const qd_expr *ex = qd_expr_arg(f, 1);
            if (qd_is_number(ex) && qd_number_sign(ex) < 0)
                continue;
            f = qd_expr_arg(f, 0);
        }
        out[k++] = f;
    }
    return k;
}

/* Add root r (exact) when it is real, folding angles into (-pi, pi]. */
static void push_root(exact *x, size_t u, const qd_expr *r, const qd_expr **roots, size_t *nr) {
    double v;
    if (!r || !value_of(x->ctx, r, &v) || *nr >= 16)
        return;
    if (x->angle[u]) {
        while (v > PI + 1e-12) {
            r = qd_simplify(x->ctx, qd_sub(x->ctx, r, qd_mul(x->ctx, qd_int(x->ctx, 2),
                                                             qd_const(x->ctx, QD_PI))));
            v -= 2 * PI;
        }
        while (v <= -PI + 1e-12) {
            r = qd_simplify(x->ctx, qd_add(x->ctx, r, qd_mul(x->ctx, qd_int(x->ctx, 2),
                                                             qd_const(x->ctx, QD_PI))));
            v += 2 * PI;
        }
    }
    for (size_t i = 0; i < *nr; i++) {
        double w;
        if (value_of(x->ctx, roots[i], &w) && fabs(w - v) <= 1e-12 * (1 + fabs(v)))
            return;
    }
    roots[(*nr)++] = r;
}

/* Roots of c2 z^2 + c1 z + c0 (numbers), exact. */
static size_t poly_roots(exact *x, const qd_expr *c0, const qd_expr *c1, const qd_expr *c2,
                         const qd_expr **z) {
    qd_ctx *ctx = x->ctx;
    double a, b, c;
    if (!value_of(ctx, c2, &a) || !value_of(ctx, c1, &b) || !value_of(ctx, c0, &c))
        return SIZE_MAX;
    if (a == 0 && b == 0)
        return c == 0 ? SIZE_MAX : 0;
    if (a == 0) {
        z[0] = qd_simplify(ctx, qd_neg(ctx, qd_div(ctx, c0, c1)));
        return 1;
    }
    double d = b * b - 4 * a * c;
    if (d < -1e-13 * (b * b + fabs(4 * a * c)))
        return 0;
    const qd_expr *disc = qd_simplify(ctx, qd_sub(ctx, qd_mul(ctx, c1, c1),
                                                  qd_mul(ctx, qd_int(ctx, 4), qd_mul(ctx, c2, c0))));
    const qd_expr *den = qd_mul(ctx, qd_int(ctx, 2), c2);
    if (fabs(d) <= 1e-13 * (b * b + fabs(4 * a * c))) {
        z[0] = qd_simplify(ctx, qd_div(ctx, qd_neg(ctx, c1), den));
        return 1;
    }
    const qd_expr *s = qd_sqrt(ctx, disc);
    z[0] = qd_simplify(ctx, qd_div(ctx, qd_sub(ctx, qd_neg(ctx, c1), s), den));
    z[1] = qd_simplify(ctx, qd_div(ctx, qd_add(ctx, qd_neg(ctx, c1), s), den));
    return 2;
}

/* f as a polynomial of degree <= 2 in the node s (u must not remain). */
static size_t roots_in(exact *x, const qd_expr *f, const qd_expr *s, const qd_expr *u,
                       const qd_expr **z) {
    qd_ctx *ctx = x->ctx;
    const qd_expr *g = qd_expand(ctx, qd_subs(ctx, f, 1, &s, &x->z));
    if (!g || qd_has(g, u))
        return SIZE_MAX;
    const qd_expr *c0 = qd_coeff(ctx, g, x->z, 0), *c1 = qd_coeff(ctx, g, x->z, 1),
                  *c2 = qd_coeff(ctx, g, x->z, 2);
    const qd_expr *back = qd_add_n(ctx, 3, (const qd_expr *[]){
        c0, qd_mul(ctx, c1, x->z), qd_mul(ctx, c2, qd_mul(ctx, x->z, x->z))});
    const qd_expr *diff = qd_expand(ctx, qd_sub(ctx, g, back));
    if (!diff || !qd_is_zero(diff) || qd_has(c0, x->z) || qd_has(c1, x->z) || qd_has(c2, x->z))
        return SIZE_MAX;
    return poly_roots(x, c0, c1, c2, z);
}

static const qd_expr *inverse_trig(qd_ctx *ctx, qd_func f, const qd_expr *z, bool other) {
    /* the branches the kernel does not fold itself */
    long p, d;
    const qd_expr *pi = qd_const(ctx, QD_PI);
    if (qd_rational_get(z, &p, &d) && d == 1 && (p == 1 || p == -1)) {
        if (f == QD_ASIN)
            return qd_mul(ctx, qd_rat(ctx, p, 2), pi);
        return p == 1 ? qd_int(ctx, 0) : pi;
    }
    const qd_expr *r = qd_simplify(ctx, qd_fn(ctx, f, z));
    if (!other)
        return r;
    return f == QD_ASIN ? qd_simplify(ctx, qd_sub(ctx, pi, r)) : qd_simplify(ctx, qd_neg(ctx, r));
}

/* Roots of one factor in the unknown u; SIZE_MAX when it cannot be solved. */
static size_t factor_roots(exact *x, const qd_expr *f, size_t u, const qd_expr **roots) {
    qd_ctx *ctx = x->ctx;
    const qd_expr *q = x->q[u], *z[2];
    size_t nr = 0, k;
    /* sin(a q + b), cos(a q + b) with numbers a, b */
    if (qd_expr_kind(f) == QD_FUNC && (qd_expr_func(f) == QD_SIN || qd_expr_func(f) == QD_COS)) {
        const qd_expr *arg = qd_expr_arg(f, 0), *a = qd_simplify(ctx, qd_diff(ctx, arg, q));
        const qd_expr *zero = qd_int(ctx, 0);
        const qd_expr *b = qd_simplify(ctx, qd_subs(ctx, arg, 1, &q, &zero));
        double av, bv;
        if (a && b && !qd_has(a, q) && value_of(ctx, a, &av) && av != 0 && value_of(ctx, b, &bv)) {
            double off = qd_expr_func(f) == QD_COS ? 0.5 : 0;
            long k0 = (long)floor(((-PI) * fabs(av) + bv) / PI - off) - 1;
            long k1 = (long)ceil((PI * fabs(av) + bv) / PI - off) + 1;
            for (long kk = k0; kk <= k1 && k1 - k0 < 64; kk++) {
                const qd_expr *r = qd_div(ctx, qd_sub(ctx, qd_mul(ctx, qd_add(ctx, qd_int(ctx, kk),
                                          qd_rat(ctx, off == 0 ? 0 : 1, 2)), qd_const(ctx, QD_PI)), b), a);
                double v;
                r = qd_simplify(ctx, r);
                if (r && value_of(ctx, r, &v) && v > -PI + 1e-12 && v <= PI + 1e-12)
                    push_root(x, u, r, roots, &nr);
            }
            return nr;
        }
    }
    /* polynomial in q, in sin q or in cos q */
    if ((k = roots_in(x, f, q, q, z)) != SIZE_MAX) {
        for (size_t i = 0; i < k; i++)
            push_root(x, u, z[i], roots, &nr);
        return nr;
    }
    for (int trig = 0; trig < 2; trig++) {
        qd_func fn = trig ? QD_COS : QD_SIN, inv = trig ? QD_ACOS : QD_ASIN;
        if ((k = roots_in(x, f, qd_fn(ctx, fn, q), q, z)) == SIZE_MAX)
            continue;
        for (size_t i = 0; i < k; i++) {
            double v;
            if (!value_of(ctx, z[i], &v) || fabs(v) > 1 + 1e-14)
                continue;
            push_root(x, u, inverse_trig(ctx, inv, z[i], false), roots, &nr);
            push_root(x, u, inverse_trig(ctx, inv, z[i], true), roots, &nr);
        }
        return nr;
    }
    return SIZE_MAX;
}

static void record(exact *x) {
    if (x->nsol >= MAX_EXACT) {
        x->failed = true;
        return;
    }
    memcpy(x->sols + x->nsol * x->n, x->val, x->n * sizeof *x->val);
    x->nsol++;
}

static void solve_rec(exact *x, const qd_expr **eqs, size_t neq);

/* Try equation i: every factor in one unknown at most.  false when it does
 * not qualify. */
static bool branch_on(exact *x, const qd_expr **eqs, size_t neq, size_t i) {
    const qd_expr *fs[32], *roots[16];
    size_t nf = factors(eqs[i], fs, 32), var[32];
    for (size_t k = 0; k < nf; k++) {
        size_t u = SIZE_MAX, c = unknowns(x, fs[k], &u);
        if (c > 1)
            return false;
        var[k] = c ? u : SIZE_MAX;
    }
    const qd_expr **rest = qd__malloc(x->ctx, (neq + 1) * sizeof *rest);
    if (!rest) {
        x->failed = true;
        return true;
    }
    for (size_t k = 0; k < nf && !x->failed; k++) {
        if (var[k] == SIZE_MAX)
            continue;
        size_t u = var[k], nr = factor_roots(x, fs[k], u, roots);
        if (nr == SIZE_MAX) {
            x->failed = true;
            break;
        }
        for (size_t r = 0; r < nr && !x->failed; r++) {
            x->val[u] = roots[r];
            size_t m = 0;
            for (size_t j = 0; j < neq; j++)
                if (j != i)
                    rest[m++] = qd_simplify(x->ctx, qd_subs(x->ctx, eqs[j], 1, &x->q[u], &roots[r]));
            solve_rec(x, rest, m);
            x->val[u] = NULL;
        }
    }
    qd__free(rest);
    return true;
}

static void solve_rec(exact *x, const qd_expr **eqs, size_t neq) {
    size_t live = 0, u;
    const qd_expr **keep = qd__malloc(x->ctx, (neq + 1) * sizeof *keep);
    if (!keep) {
        x->failed = true;
        return;
    }
    for (size_t i = 0; i < neq && !x->failed; i++) {
        if (!eqs[i]) {
            x->failed = true;
        } else if (unknowns(x, eqs[i], &u) == 0) {
            double v;
            if (!value_of(x->ctx, eqs[i], &v))
                x->failed = true;
            else if (fabs(v) > 1e-9) /* inconsistent: no root on this branch */
                live = SIZE_MAX;
        } else if (live != SIZE_MAX) {
            keep[live++] = eqs[i];
        }
        if (live == SIZE_MAX)
            break;
    }
    if (!x->failed && live != SIZE_MAX) {
        bool all = true;
        for (size_t j = 0; j < x->n; j++)
            all = all && x->val[j];
        if (live == 0) {
            if (all)
                record(x);
            else
                x->failed = x->continuum = true;
        } else {
            bool done = false;
            for (size_t i = 0; i < live && !done && !x->failed; i++)
                done = branch_on(x, keep, live, i);
            if (!done)
                x->failed = true;
        }
    }
    qd__free(keep);
}

/* The exact attempt: sols (nsol * n) or false. */
static bool solve_exact(qd_ctx *ctx, const qd_eom *e, const qd_model *m, const qd__lin *L,
                        const bool *angle, exact *x) {
    size_t n = e->n, np = qd_model_nparams(m);
    const qd_expr **from = qd__malloc(ctx, (np + 1) * sizeof *from), **to = qd__malloc(ctx, (np + 1) * sizeof *to);
    const qd_expr **eqs = qd__malloc(ctx, (n + 1) * sizeof *eqs);
    *x = (exact){.ctx = ctx, .n = n, .q = e->q, .angle = angle,
                 .val = qd__calloc(ctx, n + 1, sizeof *x->val),
                 .sols = qd__calloc(ctx, MAX_EXACT * n + 1, sizeof *x->sols),
                 .z = qd_symbol(ctx, "qd__eq_z")};
    bool ok = from && to && eqs && x->val && x->sols && x->z;
    for (size_t i = 0; ok && i < np; i++) {
        from[i] = qd_model_param(m, i);
        to[i] = qd_model_param_value(m, i);
        ok = to[i] != NULL;
    }
    for (size_t j = 0; ok && j < n; j++) {
        eqs[j] = qd_simplify(ctx, qd_subs(ctx, L->F[j], np, from, to));
        ok = eqs[j] && !qd_has(eqs[j], qd_time(ctx));
    }
    if (ok)
        solve_rec(x, eqs, n);
    /* a step that ran out of memory may leave another way to the same roots
       (cos q = 0 by the polynomial in cos q when sin/cos(a q + b) could not
       be read): the set found then is not to be trusted, nor the error
       cleared */
    ok = ok && !x->failed && qd_ctx_status(ctx) != QD_ERR_NOMEM;
    if (qd_ctx_status(ctx) != QD_OK && qd_ctx_status(ctx) != QD_ERR_NOMEM)
        qd__ctx_recover(ctx);
    qd__free(from);
    qd__free(to);
    qd__free(eqs);
    return ok;
}

/* ---- classification and assembly ------------------------------------------ */

/* kscale: the Hessian's size over the box (the median of the largest |dF/dq|
 * at spread points).  An eigenvalue below QD_LINEAR_ZERO_TOL of it is zero,
 * not a curvature: at a degenerate root the multistart polishes to, th ~ 1e-20
 * of (1 - cos th)^3, K ~ 1e-80 is no minimum's "1 positive" (issue 33). */
static qd_status classify(qd__lin *L, qd_equilibrium *p, double kscale) {
    size_t n = L->n;
    double *K = qd__malloc(L->ctx, (n * n + 1) * sizeof *K), *w = qd__malloc(L->ctx, (n + 1) * sizeof *w);
    if (!K || !w) {
        qd__free(K);
        qd__free(w);
        return QD_ERR_NOMEM;
    }
    qd__lin_run(L, p->q);
    const double *J = qd__lin_J(L);
    double big = 0, asym = 0;
    for (size_t i = 0; i < n * n; i++) {
        K[i] = -J[i];
        big = fmax(big, fabs(K[i]));
    }
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++)
            asym = fmax(asym, fabs(K[i * n + j] - K[j * n + i]));
    p->symmetric = asym <= 1e-9 * big;
    p->residual = 0;
    for (size_t j = 0; j < n; j++)
        p->residual = fmax(p->residual, fabs(qd__lin_F(L)[j]));
    bool ok = qd__lin_sym_eig(L->ctx, n, K, w, NULL);
    for (size_t j = 0; ok && j < n; j++)
        if (qd__lin_negligible(w[j], kscale))
            w[j] = 0;
    if (ok)
        qd__lin_eq_classify(n, w, p);
    qd__free(K);
    qd__free(w);
    /* qd__lin_sym_eig fails for want of memory as well as in LAPACK */
    return ok ? QD_OK : qd_ctx_status(L->ctx) == QD_ERR_NOMEM ? QD_ERR_NOMEM : QD_ERR_NUMERIC;
}

qd_status qd__lin_eq_box(qd_ctx *ctx, const qd_eom *e, const qd_model *m,
                     const qd_equilibria_opts *o, bool *angle, double *lo, double *hi) {
    size_t n = e->n;
    qd_equilibria_default_box(ctx, e, m, angle, lo, hi);
    if (o->lo && o->hi) {
        memcpy(lo, o->lo, n * sizeof *lo);
        memcpy(hi, o->hi, n * sizeof *hi);
    }
    for (size_t j = 0; j < n; j++) /* the samples are lo + (hi - lo) u: the width must be finite */
        if (!(lo[j] <= hi[j]) || !isfinite(hi[j] - lo[j])) {
            const char *name = qd_expr_name(e->q[j]);
            qd_ctx_error(ctx, QD_ERR_ARG, "the search box of %s, %g:%g, %s", name, lo[j], hi[j],
                         lo[j] <= hi[j] ? "is too wide: its width overflows a double"
                                        : "is empty or not a range of numbers");
            qd_ctx_error_about(ctx, QD_SUBJECT_COORD, j, name, QD_REASON_NONE, NULL);
            return QD_ERR_ARG;
        }
    return QD_OK;
}

void qd__lin_eq_classify(size_t n, const double *ev, qd_equilibrium *p) {
    double big = 0;
    for (size_t j = 0; j < n; j++)
        big = fmax(big, fabs(ev[j]));
    p->npos = p->nneg = p->nzero = 0;
    for (size_t j = 0; j < n; j++) {
        if (fabs(ev[j]) <= QD_MODES_ZERO_TOL * big || big == 0)
            p->nzero++;
        else if (ev[j] > 0)
            p->npos++;
        else
            p->nneg++;
    }
    p->kind = p->nzero ? QD_EQ_DEGENERATE
            : p->nneg == 0 ? QD_EQ_MINIMUM
            : p->npos == 0 ? QD_EQ_MAXIMUM : QD_EQ_SADDLE;
}

void qd_equilibria_free(qd_equilibria *r) {
    if (!r)
        return;
    for (size_t i = 0; i < r->count; i++) {
        qd__free(r->pts[i].q);
        qd__free(r->pts[i].exact);
    }
    qd__free(r->pts);
    memset(r, 0, sizeof *r);
}

static int by_q(size_t n, const qd_equilibrium *a, const qd_equilibrium *b) {
    for (size_t j = 0; j < n; j++) {
        double d = a->q[j] - b->q[j];
        if (fabs(d) > 1e-9 * (1 + fabs(a->q[j])))
            return d < 0 ? -1 : 1;
    }
    return 0;
}

/* Stable insertion sort by q: a few points, and qsort's comparison would
 * need n in a global, which two threads would share. */
static void sort_by_q(size_t n, qd_equilibrium *pts, size_t count) {
    for (size_t i = 1; i < count; i++) {
        qd_equilibrium x = pts[i];
        size_t k = i;
        for (; k > 0 && by_q(n, &pts[k - 1], &x) > 0; k--)
            pts[k] = pts[k - 1];
        pts[k] = x;
    }
}

/* Is the root q one of a family (not isolated)?  Decided from the solution
 * set, not from a singular Jacobian alone (V = x^4, (1 - cos th)^2 are
 * isolated): along a null direction v of J, Newton from q + h v is run to
 * convergence; an isolated root draws it back to q (however slowly, a
 * degenerate root), a family (a ring of relative equilibria) holds it on a
 * root about h away (h |v|_inf in the largest coordinate).  Both h = 1e-2 and 1e-3 (times 1 + |q|) must find a
 * neighbour, so a root that is flat to round-off at one radius only is not
 * a family.  A free particle (J = 0, F = 0 everywhere) is a family. */
static bool on_continuum(qd__lin *L, const double *q, double ftol) {
    size_t n = L->n;
    double *w = qd__malloc(L->ctx, (n + 1) * sizeof *w), *v = qd__malloc(L->ctx, (n * n + 1) * sizeof *v);
    double *JtJ = qd__malloc(L->ctx, (n * n + 1) * sizeof *JtJ), *t = qd__malloc(L->ctx, (n + 1) * sizeof *t);
    bool cont = false;
    if (w && v && JtJ && t) {
        qd__lin_run(L, q);
        const double *J = qd__lin_J(L);
        for (size_t i = 0; i < n; i++)
            for (size_t j = 0; j < n; j++) {
                double s = 0;
                for (size_t k = 0; k < n; k++)
                    s += J[k * n + i] * J[k * n + j];
                JtJ[i * n + j] = s;
            }
        /* the caller found K degenerate: its most nearly null direction */
        if (qd__lin_sym_eig(L->ctx, n, JtJ, w, v)) {
            double qmax = 0;
            for (size_t i = 0; i < n; i++)
                qmax = fmax(qmax, fabs(q[i]));
            /* the step's largest component: h/sqrt(n) along a ring's rotation, whose
               unit null vector is spread over every coordinate */
            double vmax = 0;
            for (size_t i = 0; i < n; i++)
                vmax = fmax(vmax, fabs(v[i]));
            cont = true;
            for (double rel = 1e-2; cont && rel >= 1e-3; rel /= 10) {
                double h = rel * (1 + qmax), d = 0, res;
                for (size_t i = 0; i < n; i++)   /* v's first column: w[0]'s vector */
                    t[i] = q[i] + h * v[i];
                qd__lin_lm_solve(L, t, 0, 200, &res);
                for (size_t i = 0; i < n; i++)
                    d = fmax(d, fabs(t[i] - q[i]));
                cont = res <= ftol && d >= 0.5 * h * vmax;
            }
        }
    }
    qd__free(w);
    qd__free(v);
    qd__free(JtJ);
    qd__free(t);
    return cont;
}

/* The exact branches may reach a root twice (1 - cos th = 0 and sin th = 0
 * both give th = 0 of (1 - cos th)^2), the multistart a degenerate one at
 * points round-off apart: each point once (qd__lin_roots_same: relative to the
 * coordinates' size, angles modulo 2 pi), the first kept. */
/* Do degenerate roots a and b found numerically lie on one plateau of
 * round-off, |F| <= ftol all the way between them?  The multistart stops
 * anywhere on it: (1 - cos th)^3, whose force is noise for |th| < 2e-4,
 * gave 26 "equilibria" between -0.0028 and 0.0028 (issue 33).  Two points of
 * a ring of equilibria are not: its chord leaves the ring. */
static bool one_plateau(qd__lin *L, const double *a, const double *b, const bool *angle,
                        double ftol, double *t) {
    size_t n = L->n;
    for (int s = 1; s < 8; s++) {
        for (size_t j = 0; j < n; j++) {
            double d = b[j] - a[j];
            if (angle[j] && fabs(d) > PI)
                d -= copysign(2 * PI, d);
            t[j] = a[j] + d * s / 8.0;
        }
        qd__lin_run(L, t);
        for (size_t j = 0; j < n; j++)
            if (!(fabs(qd__lin_F(L)[j]) <= ftol))
                return false;
    }
    return true;
}

/* The plateau's points merged into their mean (angles about the first one),
 * the best estimate of the root inside the round-off. */
static qd_status drop_duplicates(qd__lin *L, size_t n, const bool *angle, double ftol,
                                 double *t, qd_equilibria *out) {
    size_t kept = 0;
    double *sum = t ? qd__calloc(L->ctx, out->count * n + 1, sizeof *sum) : NULL;
    size_t *cnt = t ? qd__calloc(L->ctx, out->count + 1, sizeof *cnt) : NULL;
    if (t && (!sum || !cnt)) {
        qd__free(sum);
        qd__free(cnt);
        return QD_ERR_NOMEM;
    }
    for (size_t i = 0; i < out->count; i++) {
        bool dup = false, plateau = false;
        size_t k = 0;
        for (; k < kept && !dup; k++) {
            dup = qd__lin_roots_same(n, out->pts[k].q, out->pts[i].q, angle);
            if (!dup && t && !out->pts[k].exact && !out->pts[i].exact && out->pts[k].nzero &&
                out->pts[i].nzero)
                dup = plateau = one_plateau(L, out->pts[k].q, out->pts[i].q, angle, ftol, t);
            if (dup)
                break;
        }
        if (dup) {
            if (plateau && sum && cnt) {
                for (size_t j = 0; j < n; j++) {
                    double d = out->pts[i].q[j] - out->pts[k].q[j];
                    if (angle[j] && fabs(d) > PI)
                        d -= copysign(2 * PI, d);
                    sum[k * n + j] += d;
                }
                cnt[k]++;
            }
            qd__free(out->pts[i].q);
            qd__free(out->pts[i].exact);
        } else {
            out->pts[kept++] = out->pts[i];
        }
    }
    out->count = kept;
    for (size_t k = 0; sum && cnt && k < kept; k++)
        if (cnt[k]) {
            for (size_t j = 0; j < n; j++)
                out->pts[k].q[j] += sum[k * n + j] / (double)(cnt[k] + 1);
            qd__lin_wrap_angles(n, out->pts[k].q, angle);
        }
    qd__free(sum);
    qd__free(cnt);
    return QD_OK;
}

static qd_status assemble(qd_ctx *ctx, qd__lin *L, const qd__roots *roots, const exact *x,
                          const bool *angle, double ftol, double kscale, qd_equilibria *out) {
    size_t n = L->n, cnt = x ? x->nsol : roots->count;
    out->pts = qd__calloc(ctx, cnt + 1, sizeof *out->pts);
    if (!out->pts)
        return QD_ERR_NOMEM;
    for (size_t i = 0; i < cnt; i++) {
        qd_equilibrium *p = &out->pts[out->count++];
        p->q = qd__malloc(ctx, (n + 1) * sizeof *p->q);
        if (!p->q)
            return QD_ERR_NOMEM;
        if (x) {
            p->exact = qd__malloc(ctx, (n + 1) * sizeof *p->exact);
            if (!p->exact)
                return QD_ERR_NOMEM;
            for (size_t j = 0; j < n; j++) {
                p->exact[j] = x->sols[i * n + j];
                if (!value_of(ctx, p->exact[j], &p->q[j]))
                    return qd_ctx_status(ctx) == QD_ERR_NOMEM ? QD_ERR_NOMEM : QD_ERR_NUMERIC;
            }
        } else {
            double res;
            memcpy(p->q, roots->q + i * n, n * sizeof *p->q);
            /* on to the root itself (only improves): a regular one in a few steps, a
             * degenerate one (Newton gains a fixed factor a step) from the plateau
             * |F| < ftol where the multistart stopped, th = +-0.0028 of
             * (1 - cos th)^3, so that its copies merge below (issue 33) */
            qd__lin_lm_solve(L, p->q, 0, 200, &res);
            qd__lin_wrap_angles(n, p->q, angle);
            if (qd_ctx_status(ctx) == QD_ERR_NOMEM)
                return QD_ERR_NOMEM;
        }
        qd_status st = classify(L, p, kscale);
        if (st != QD_OK)
            return st;
        if (!out->continuum && p->nzero && on_continuum(L, p->q, ftol))
            out->continuum = true;
    }
    sort_by_q(n, out->pts, out->count);
    double *t = out->continuum ? NULL : qd__malloc(ctx, (n + 1) * sizeof *t);
    if (!out->continuum && !t)
        return QD_ERR_NOMEM;
    qd_status st = drop_duplicates(L, n, angle, ftol, t, out);
    qd__free(t);
    return st;
}

/* Exact roots must also be roots numerically: each is checked. */
static bool exact_verified(qd_ctx *ctx, qd__lin *L, const exact *x, double ftol) {
    size_t n = L->n;
    double *q = qd__malloc(ctx, (n + 1) * sizeof *q);
    bool ok = q != NULL;
    for (size_t i = 0; ok && i < x->nsol; i++) {
        for (size_t j = 0; ok && j < n; j++)
            ok = value_of(ctx, x->sols[i * n + j], &q[j]);
        qd__lin_run(L, q);
        for (size_t j = 0; ok && j < n; j++)
            ok = fabs(qd__lin_F(L)[j]) <= ftol;
    }
    qd__free(q);
    return ok;
}

/* ---- affine equations: one solve, no search ------------------------------- */

/* Is F affine in q: no entry of J = dF/dq holds a coordinate?  Then F has
 * one root where J is regular (none or a continuum where it is not), and a
 * search of the box would only find it again from every start. */
static bool affine(const qd__lin *L) {
    size_t n = L->n;
    for (size_t k = 0; k < n * n; k++)
        for (size_t j = 0; j < n; j++)
            if (!L->J[k] || qd_has(L->J[k], L->q[j]))
                return false;
    return true;
}

/* The root of affine F: J q = -F(0) by rank-revealing elimination.  true
 * with it added to roots when J is regular at the force scale. */
static bool affine_root(qd__lin *L, double ftol, const bool *angle, qd__roots *roots) {
    size_t n = L->n;
    double *A = qd__malloc(L->ctx, (n * n + 1) * sizeof *A), *q = qd__calloc(L->ctx, n + 1, sizeof *q);
    size_t *pc = qd__malloc(L->ctx, (n + 1) * sizeof *pc);
    bool ok = false;
    if (A && q && pc) {
        qd__lin_run(L, q);
        memcpy(A, qd__lin_J(L), n * n * sizeof *A);
        for (size_t j = 0; j < n; j++)
            q[j] = -qd__lin_F(L)[j];
        if (qd__num_rank(n, A, q, 1e-12, pc, NULL, NULL) == n) {
            qd__lin_run(L, q);
            double res = 0;
            for (size_t j = 0; j < n; j++)
                res = fmax(res, fabs(qd__lin_F(L)[j]));
            ok = res <= ftol || qd__lin_lm_solve(L, q, ftol, 8, &res); /* polish round-off */
            if (ok) {
                qd__lin_wrap_angles(n, q, angle);
                ok = qd__lin_roots_add(L->ctx, roots, q, res, angle);
            }
        }
    }
    qd__free(A);
    qd__free(q);
    qd__free(pc);
    return ok;
}

/* Affine F = J q + b with a singular J (the rotation of a ring of springs,
 * the translations of a free molecule): its roots, when there are any, are
 * one affine family, and a single damped Newton run (Levenberg-Marquardt on
 * |F|^2, a convex quadratic here) from the box's centre c reaches a point of
 * it, as each of the multistart's 40 n + 40 starts would (a ring of 100
 * masses: 4,140 runs of O(n^3) steps, 72-109 s, issue 34).  false when the
 * run does not reach ftol (b outside J's range, or a slow run): the caller
 * then searches. */
static bool affine_family(qd__lin *L, const double *lo, const double *hi, double ftol,
                          const bool *angle, qd__roots *roots) {
    size_t n = L->n;
    double *q = qd__malloc(L->ctx, (n + 1) * sizeof *q), res;
    bool ok = q != NULL;
    for (size_t j = 0; ok && j < n; j++)
        q[j] = lo[j] <= 0 && hi[j] >= 0 ? 0 : (lo[j] + hi[j]) / 2;
    ok = ok && qd__lin_lm_solve(L, q, ftol, 200, &res);
    if (ok) {
        qd__lin_wrap_angles(n, q, angle);
        ok = qd__lin_roots_add(L->ctx, roots, q, res, angle);
    }
    qd__free(q);
    return ok;
}

static void sort9(double *v) {
    for (int a = 0; a < 9; a++)
        for (int b = a + 1; b < 9; b++)
            if (v[b] < v[a]) {
                double t = v[a];
                v[a] = v[b];
                v[b] = t;
            }
}

/* Only the roots in the box (Newton may leave it). */
static void keep_in_box(qd__roots *roots, size_t n, const double *lo, const double *hi) {
    size_t kept = 0;
    for (size_t i = 0; i < roots->count; i++) {
        bool in = true;
        for (size_t j = 0; j < n; j++) {
            double v = roots->q[i * n + j], pad = 1e-9 * (1 + fabs(v));
            if (fabs(v) < 1e-15)
                roots->q[i * n + j] = v = 0;
            in = in && v >= lo[j] - pad && v <= hi[j] + pad;
        }
        if (in) {
            memmove(roots->q + kept * n, roots->q + i * n, n * sizeof *roots->q);
            roots->res[kept++] = roots->res[i];
        }
    }
    roots->count = kept;
}

qd_status qd_equilibria_find(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t nvals,
                             const qd_expr *const *syms, const double *vals,
                             const qd_equilibria_opts *opts, qd_equilibria *out) {
    QD_ARGS_CTX(ctx, ctx && e && m && (nvals == 0 || syms) && (nvals == 0 || vals) && out);
    memset(out, 0, sizeof *out);
    qd_equilibria_opts o = opts ? *opts : (qd_equilibria_opts){0};
    if (e->ncon) /* on the constraint manifold (qdot/constrained.h) */
        return qd_constrained_equilibria_find(ctx, e, m, nvals, syms, vals, opts, out);
    size_t n = e->n;
    out->n = n;
    qd__lin L;
    qd_status st = qd__lin_init(ctx, e, &L);
    if (st != QD_OK)
        return st;
    qd__lin_bind(&L, nvals, syms, vals);
    bool *angle = qd__calloc(ctx, n + 1, sizeof *angle);
    double *lo = qd__malloc(ctx, (n + 1) * sizeof *lo), *hi = qd__malloc(ctx, (n + 1) * sizeof *hi);
    double *q = qd__malloc(ctx, (n + 1) * sizeof *q);
    qd__roots roots = {.n = n};
    exact x = {0};
    if (!angle || !lo || !hi || !q) {
        st = QD_ERR_NOMEM;
        goto done;
    }
    if ((st = qd__lin_eq_box(ctx, e, m, &o, angle, lo, hi)) != QD_OK)
        goto done;
    /* the force scale: the median of the scales at spread points */
    double scales[9], kscales[9];
    for (int s = 0; s < 9; s++) {
        for (size_t j = 0; j < n; j++)
            q[j] = lo[j] + (hi[j] - lo[j]) * (0.1 + 0.1 * ((s + 3 * (int)j) % 9));
        scales[s] = qd__lin_scale(&L, q);   /* runs L at q */
        kscales[s] = 0;
        for (size_t k = 0; k < n * n; k++)
            kscales[s] = fmax(kscales[s], fabs(qd__lin_J(&L)[k]));
    }
    sort9(scales);
    sort9(kscales);
    double fscale = isfinite(scales[4]) && scales[4] > 0 ? scales[4] : 1;
    double kscale = isfinite(kscales[4]) ? kscales[4] : 0;
    double ftol = 1e-11 * fscale;
    if (o.near) {
        memcpy(q, o.near, n * sizeof *q);
        double res;
        out->method = "newton";
        if (!qd__lin_lm_solve(&L, q, ftol, 500, &res)) {
            qd_ctx_error(ctx, QD_ERR_NUMERIC,
                         "no convergence: Newton's method from the guess stopped with residual "
                         "%.3g (force scale %.3g)", res, fscale);
            st = QD_ERR_NUMERIC;
            goto done;
        }
        qd__lin_wrap_angles(n, q, angle);
        if (!qd__lin_roots_add(ctx, &roots, q, res, angle))
            st = QD_ERR_NOMEM;
    } else if (!o.numeric_only && solve_exact(ctx, e, m, &L, angle, &x) &&
               exact_verified(ctx, &L, &x, 1e-8 * fscale)) {
        out->method = "exact";
        out->exact = true;
    } else {
        if (qd_ctx_status(ctx) == QD_ERR_NOMEM) {
            st = QD_ERR_NOMEM;
            goto done;
        }
        x.nsol = 0;
        bool lin = affine(&L);
        if (lin && (affine_root(&L, ftol, angle, &roots) ||
                    (qd_ctx_status(ctx) != QD_ERR_NOMEM &&
                     affine_family(&L, lo, hi, ftol, angle, &roots)))) {
            out->method = "linear";
        } else if (qd_ctx_status(ctx) == QD_ERR_NOMEM) {
            st = QD_ERR_NOMEM;
            goto done;
        } else if (o.no_search) {
            out->method = "none";
        } else {
            out->method = "multistart";
            size_t starts = o.starts ? o.starts : 40 * n + 40;
            st = qd__lin_multistart(&L, lo, hi, angle, starts, ftol, &roots);
        }
        keep_in_box(&roots, n, lo, hi);
    }
    if (st == QD_OK)
        st = assemble(ctx, &L, &roots, out->exact ? &x : NULL, angle, ftol, kscale, out);
done:
    if (st != QD_OK && qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, st, st == QD_ERR_NOMEM ? "out of memory finding equilibria"
                                                 : "finding equilibria failed");
    if (st != QD_OK)
        qd_equilibria_free(out);
    qd__free(x.val);
    qd__free(x.sols);
    qd__lin_roots_free(&roots);
    qd__free(angle);
    qd__free(lo);
    qd__free(hi);
    qd__free(q);
    qd__lin_free(&L);
    return st;
}
