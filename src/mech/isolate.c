/*
 * src/mech/isolate.c - solve equations for unknowns that enter nonlinearly,
 * by isolating them (the relations of a generating function, Goldstein
 * ch. 9: p = dF1/dq for Q when F1 = m w q^2 cot(Q)/2).
 *
 * An unknown y that occurs once in e = 0 is isolated by undoing what is
 * done to it, outermost first: a sum loses its other terms, a product its
 * other factors, a power its exponent, a function is inverted (sin -> asin,
 * tan -> atan, exp -> log, ...).  One that occurs several times is first
 * reduced to one occurrence: the whole equation linear in y; or y only
 * inside copies of one subexpression g(y) (exp(p) twice), solved for
 * u = g(y) and then g(y) = u; or sin(y) and cos(y) only as a ratio
 * (cos(Q)/sin(Q)), solved for u = tan(y) after sin(y) -> u cos(y) cancels
 * cos(y).  Inverses are principal branches (asin and atan in [-pi/2, pi/2],
 * acos in [0, pi], the positive root, the real log), as a generating function's
 * map is meant near a point: Goldstein writes Q = atan(m w q / p).  A trig
 * function of an inverse one is then written without it
 * (sin(atan(u)) = u/sqrt(1 + u^2)), so that P = (p^2 + m^2 w^2 q^2)/(2 m w)
 * comes out without atan.
 *
 * Several equations: one with a single unknown is solved and substituted
 * into the rest, until all are solved; when every equation left has several,
 * one is solved for one of them (the others as parameters) and that is
 * substituted into the rest and into the solutions found before.
 */
#include "mech.h"
#include "base/mem.h"

#include <stdlib.h>

#define DEPTH 3 /* nested reductions (kernel within kernel) */

/* Occurrences of y in e as a tree, counted up to 2. */
static int occurrences(const qd_expr *e, const qd_expr *y) {
    if (e == y)
        return 1;
    int c = 0;
    for (size_t i = 0; i < qd_expr_nargs(e) && c < 2; i++)
        if (qd_has(qd_expr_arg(e, i), y))
            c += occurrences(qd_expr_arg(e, i), y);
    return c;
}

/* f(x) = r solved for x on the principal branch; NULL when f has no
 * inverse here. */
static const qd_expr *inverse(qd_ctx *ctx, qd_func f, const qd_expr *r) {
    const qd_expr *one = qd_int(ctx, 1), *half = qd_rat(ctx, 1, 2);
    switch (f) {
    case QD_SIN: return qd_fn(ctx, QD_ASIN, r);
    case QD_COS: return qd_fn(ctx, QD_ACOS, r);
    case QD_TAN: return qd_fn(ctx, QD_ATAN, r);
    case QD_ASIN: return qd_fn(ctx, QD_SIN, r);
    case QD_ACOS: return qd_fn(ctx, QD_COS, r);
    case QD_ATAN: return qd_fn(ctx, QD_TAN, r);
    case QD_EXP: return qd_fn(ctx, QD_LOG, r);
    case QD_LOG: return qd_fn(ctx, QD_EXP, r);
    case QD_SINH: /* asinh r = log(r + sqrt(r^2 + 1)) */
        return qd_fn(ctx, QD_LOG, qd_add(ctx, r, qd_sqrt(ctx, qd_add(ctx, qd_powi(ctx, r, 2), one))));
    case QD_COSH:
        return qd_fn(ctx, QD_LOG, qd_add(ctx, r, qd_sqrt(ctx, qd_sub(ctx, qd_powi(ctx, r, 2), one))));
    case QD_TANH:
        return qd_mul(ctx, half, qd_fn(ctx, QD_LOG, qd_div(ctx, qd_add(ctx, one, r),
                                                           qd_sub(ctx, one, r))));
    default: return NULL;
    }
}

/* b^x = r solved for b: r^(1/x), the positive root; an odd integer power
 * is inverted on the whole line, sign(r) |r|^(1/x), since r^(1/3) of a
 * negative r has no real value. */
static const qd_expr *root(qd_ctx *ctx, const qd_expr *r, const qd_expr *x) {
    long num, den;
    const qd_expr *inv = qd_div(ctx, qd_int(ctx, 1), x);
    if (!qd_rational_get(x, &num, &den) || den != 1 || num % 2 == 0 || num == 1 || num == -1)
        return qd_pow(ctx, r, inv);
    return qd_mul(ctx, qd_fn(ctx, QD_SIGN, r), qd_pow(ctx, qd_fn(ctx, QD_ABS, r), inv));
}

/* The arguments of e other than the one containing y, combined by ADD or
 * MUL; *with gets the one containing y. */
static const qd_expr *others(qd_ctx *ctx, const qd_expr *e, const qd_expr *y,
                             const qd_expr **with) {
    bool sum = qd_expr_kind(e) == QD_ADD;
    const qd_expr *acc = qd_int(ctx, sum ? 0 : 1);
    for (size_t i = 0; i < qd_expr_nargs(e); i++) {
        const qd_expr *a = qd_expr_arg(e, i);
        if (qd_has(a, y))
            *with = a;
        else
            acc = sum ? qd_add(ctx, acc, a) : qd_mul(ctx, acc, a);
    }
    return acc;
}

/* lhs = rhs with y once in lhs, solved for y; NULL when some step has no
 * inverse. */
static const qd_expr *undo(qd_ctx *ctx, const qd_expr *lhs, const qd_expr *rhs,
                           const qd_expr *y) {
    while (lhs && rhs && lhs != y) {
        const qd_expr *inner = NULL, *rest;
        switch (qd_expr_kind(lhs)) {
        case QD_ADD:
            rest = others(ctx, lhs, y, &inner);
            rhs = qd_sub(ctx, rhs, rest);
            break;
        case QD_MUL:
            rest = others(ctx, lhs, y, &inner);
            rhs = qd_div(ctx, rhs, rest);
            break;
        case QD_POW: {
            const qd_expr *b = qd_expr_arg(lhs, 0), *x = qd_expr_arg(lhs, 1);
            if (qd_has(b, y) && qd_is_number(x)) {
                inner = b;
                rhs = root(ctx, rhs, x);
            } else if (qd_has(x, y) && !qd_has(b, y)) {
                inner = x;
                rhs = qd_div(ctx, qd_fn(ctx, QD_LOG, rhs), qd_fn(ctx, QD_LOG, b));
            }
            break;
        }
        case QD_FUNC:
            if (qd_expr_nargs(lhs) == 1) {
                inner = qd_expr_arg(lhs, 0);
                rhs = inverse(ctx, qd_expr_func(lhs), rhs);
            }
            break;
        default:
            break;
        }
        if (!inner)
            return NULL;
        lhs = inner;
    }
    return lhs && rhs ? qd_simplify(ctx, rhs) : NULL;
}

static const qd_expr *solve1(qd_ctx *ctx, const qd_expr *e, const qd_expr *y, int depth);

/* e linear in y: -b/a. */
static const qd_expr *linear(qd_ctx *ctx, const qd_expr *e, const qd_expr *y) {
    const qd_expr *a, *b;
    if (qd_linear_coeffs(ctx, qd_expand(ctx, e), 1, &y, &a, &b) != QD_OK) {
        qd__ctx_recover(ctx);
        return NULL;
    }
    a = qd_simplify(ctx, a);
    return a && !qd_is_zero(a) ? qd_simplify(ctx, qd_div(ctx, qd_neg(ctx, b), a)) : NULL;
}

/* The function and power nodes of e that contain y, into k (at most cap). */
static size_t kernels(const qd_expr *e, const qd_expr *y, const qd_expr **k, size_t nk,
                      size_t cap) {
    if (!qd_has(e, y) || e == y)
        return nk;
    qd_kind kind = qd_expr_kind(e);
    if (kind == QD_FUNC || kind == QD_POW) {
        size_t i = 0;
        while (i < nk && k[i] != e)
            i++;
        if (i == nk && nk < cap)
            k[nk++] = e;
    }
    for (size_t i = 0; i < qd_expr_nargs(e); i++)
        nk = kernels(qd_expr_arg(e, i), y, k, nk, cap);
    return nk;
}

/* y only inside copies of one g(y): u = g(y) first. */
static const qd_expr *by_kernel(qd_ctx *ctx, const qd_expr *e, const qd_expr *y, int depth) {
    const qd_expr *k[16];
    size_t nk = kernels(e, y, k, 0, 16);
    const qd_expr *u = qd_symbol(ctx, "qd__isolate_u");
    for (size_t i = 0; i < nk; i++) {
        const qd_expr *eu = qd_simplify(ctx, qd_subs(ctx, e, 1, &k[i], &u));
        if (!eu || qd_has(eu, y) || !qd_has(eu, u))
            continue;
        const qd_expr *ku = solve1(ctx, eu, u, depth + 1);
        const qd_expr *sol = ku ? undo(ctx, k[i], ku, y) : NULL;
        if (sol)
            return sol;
    }
    return NULL;
}

/* sin(y) and cos(y) only as a ratio: tan(y) = u. */
static const qd_expr *by_tangent(qd_ctx *ctx, const qd_expr *e, const qd_expr *y, int depth) {
    const qd_expr *u = qd_symbol(ctx, "qd__isolate_t");
    const qd_expr *from[2] = {qd_fn(ctx, QD_SIN, y), qd_fn(ctx, QD_TAN, y)};
    const qd_expr *to[2] = {qd_mul(ctx, u, qd_fn(ctx, QD_COS, y)), u};
    const qd_expr *eu = qd_simplify(ctx, qd_subs(ctx, e, 2, from, to));
    if (!eu || qd_has(eu, y) || !qd_has(eu, u))
        return NULL;
    const qd_expr *tu = solve1(ctx, eu, u, depth + 1);
    return tu ? qd_fn(ctx, QD_ATAN, tu) : NULL;
}

/* e = 0 solved for y; NULL when not found (ctx left clean). */
static const qd_expr *solve1(qd_ctx *ctx, const qd_expr *e, const qd_expr *y, int depth) {
    e = qd_simplify(ctx, e);
    if (!e || !qd_has(e, y) || depth > DEPTH)
        return NULL;
    const qd_expr *sol = linear(ctx, e, y);
    if (!sol && occurrences(e, y) == 1)
        sol = undo(ctx, e, qd_int(ctx, 0), y);
    if (!sol)
        sol = by_tangent(ctx, e, y, depth);
    if (!sol)
        sol = by_kernel(ctx, e, y, depth);
    if (!sol && qd_ctx_status(ctx) != QD_ERR_NOMEM)
        qd__ctx_recover(ctx);
    return sol;
}

/* ---- trig of inverse trig ----------------------------------------------------- */

/* f(g(u)) without g, for f in sin, cos, tan and g in asin, acos, atan. */
static const qd_expr *trig_of_inverse(qd_ctx *ctx, qd_func f, qd_func g, const qd_expr *u) {
    const qd_expr *one = qd_int(ctx, 1), *u2 = qd_powi(ctx, u, 2);
    const qd_expr *c = g == QD_ATAN ? qd_powi(ctx, qd_sqrt(ctx, qd_add(ctx, one, u2)), -1)
                                    : qd_sqrt(ctx, qd_sub(ctx, one, u2));
    /* (sin, cos) of the angle: atan (u c, c); asin (u, c); acos (c, u) */
    const qd_expr *s = g == QD_ATAN ? qd_mul(ctx, u, c) : g == QD_ASIN ? u : c;
    const qd_expr *k = g == QD_ATAN ? c : g == QD_ASIN ? c : u;
    return f == QD_SIN ? s : f == QD_COS ? k : qd_div(ctx, s, k);
}

static bool is_trig(const qd_expr *e, bool inverse_fn) {
    if (qd_expr_kind(e) != QD_FUNC || qd_expr_nargs(e) != 1)
        return false;
    qd_func f = qd_expr_func(e);
    return inverse_fn ? f == QD_ASIN || f == QD_ACOS || f == QD_ATAN
                      : f == QD_SIN || f == QD_COS || f == QD_TAN;
}

static size_t collect(const qd_expr *e, const qd_expr **found, size_t n, size_t cap) {
    if (is_trig(e, false) && is_trig(qd_expr_arg(e, 0), true)) {
        for (size_t i = 0; i < n; i++)
            if (found[i] == e)
                return n;
        if (n < cap)
            found[n++] = e;
        return n;
    }
    for (size_t i = 0; i < qd_expr_nargs(e); i++)
        n = collect(qd_expr_arg(e, i), found, n, cap);
    return n;
}

const qd_expr *qd__mech_untrig(qd_ctx *ctx, const qd_expr *e) {
    const qd_expr *from[32], *to[32];
    if (!e)
        return NULL;
    size_t n = collect(e, from, 0, 32);
    if (n == 0)
        return e;
    for (size_t i = 0; i < n; i++) {
        const qd_expr *g = qd_expr_arg(from[i], 0);
        to[i] = trig_of_inverse(ctx, qd_expr_func(from[i]), qd_expr_func(g), qd_expr_arg(g, 0));
    }
    return qd_simplify(ctx, qd_subs(ctx, e, n, from, to));
}

/* ---- systems ------------------------------------------------------------------ */

/* The index of the single unsolved unknown of e, or n (none or several). */
static size_t single_unknown(const qd_expr *e, size_t n, const qd_expr *const *xs,
                             const bool *done) {
    size_t which = n;
    for (size_t j = 0; j < n; j++)
        if (!done[j] && qd_has(e, xs[j])) {
            if (which != n)
                return n;
            which = j;
        }
    return which;
}

qd_status qd__mech_isolate(qd_ctx *ctx, size_t n, const qd_expr *const *eq,
                           const qd_expr *const *xs, const qd_expr **sol, size_t *failed) {
    const qd_expr **e = qd__malloc(ctx, (2 * n + 1) * sizeof *e);
    bool *done = qd__calloc(ctx, 2 * n + 1, sizeof *done), *used = done + n;
    if (!e || !done) {
        qd__free(e);
        qd__free(done);
        return QD_ERR_NOMEM;
    }
    for (size_t i = 0; i < n; i++)
        e[i] = eq[i];
    size_t solved = 0;
    for (bool progress = true, coupled = false; solved < n && (progress || !coupled);) {
        /* coupled: no equation has one unknown left (the action-angle map,
         * Q = atan(m w q/p), P = H/w); one is then solved for one of its
         * unknowns, the others standing as parameters, and that solution is
         * put into the equations left and into the solutions so far */
        coupled = !progress;
        progress = false;
        for (size_t i = 0; i < n && !(coupled && progress); i++) {
            size_t j = used[i] ? n : single_unknown(e[i], n, xs, done);
            const qd_expr *s = j < n && !coupled ? solve1(ctx, e[i], xs[j], 0) : NULL;
            for (size_t k = 0; coupled && !used[i] && !s && k < n; k++)
                if (!done[k] && qd_has(e[i], xs[k]) && (s = solve1(ctx, e[i], xs[k], 0)))
                    j = k;
            if (!s)
                continue;
            sol[j] = s;
            done[j] = used[i] = progress = true;
            solved++;
            for (size_t k = 0; k < n; k++) {
                if (!used[k])
                    e[k] = qd_subs(ctx, e[k], 1, &xs[j], &s);
                if (done[k] && k != j && qd_has(sol[k], xs[j]))
                    sol[k] = qd_simplify(ctx, qd_subs(ctx, sol[k], 1, &xs[j], &s));
            }
        }
    }
    *failed = n;
    for (size_t i = 0; i < n && *failed == n; i++)
        if (!used[i])
            *failed = i;
    for (size_t j = 0; j < n && solved == n; j++)
        sol[j] = qd__mech_untrig(ctx, sol[j]);
    qd__free(e);
    qd__free(done);
    if (qd_ctx_status(ctx) != QD_OK)
        return qd_ctx_status(ctx);
    return solved == n ? QD_OK : QD_ERR_NONLINEAR;
}
