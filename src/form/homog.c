/*
 * src/form/homog.c - the degree of homogeneity of a function in chosen
 * variables (qd_homogeneity, qdot/form.h; Desloge App. 20: Euler's theorem
 * and its converse).
 *
 * The degree is (sum x_i df/dx_i) / f when that simplifies to something free
 * of x, confirmed by the zero test of sum x_i df/dx_i - n f.  Otherwise the
 * probe f(x) f(4x) - f(2x)^2, which vanishes for every homogeneous f, is
 * evaluated in ball arithmetic at points of f's domain: a certainly nonzero
 * value is the witness of "no".  Failing
 * both, log2(f(2x)/f(x)) at a point gives a rational guess that the zero
 * test may confirm; else the verdict is undecided, never guessed.
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include "qdot/form.h"
#include "base/args.h"
#include "base/mem.h"
#include "sym/node.h"

const char *qd_homog_verdict_name(qd_homog_verdict v) {
    switch (v) {
    case QD_HOMOG_YES: return "homogeneous";
    case QD_HOMOG_EVERY: return "every degree";
    case QD_HOMOG_NO: return "not homogeneous";
    case QD_HOMOG_UNDECIDED: break;
    }
    return "undecided";
}

/* f with every x_i replaced by c x_i. */
static const qd_expr *scaled(qd_ctx *ctx, const qd_expr *f, size_t n, const qd_expr *const *x,
                             long c) {
    const qd_expr **to = qd__malloc(ctx, n * sizeof *to);
    if (!to)
        return NULL;
    for (size_t i = 0; i < n; i++)
        to[i] = qd_mul(ctx, qd_int(ctx, c), x[i]);
    const qd_expr *r = qd_subs(ctx, f, n, x, to);
    qd__free(to);
    return r;
}

/* sum_i x_i df/dx_i (App. 20 eq. 2's right side), simplified. */
static const qd_expr *euler_sum(qd_ctx *ctx, const qd_expr *f, size_t n, const qd_expr *const *x) {
    const qd_expr *s = qd_int(ctx, 0);
    for (size_t i = 0; i < n; i++)
        s = qd_add(ctx, s, qd_mul(ctx, x[i], qd_diff(ctx, f, x[i])));
    return qd_simplify(ctx, s);
}

static bool free_of(const qd_expr *e, size_t n, const qd_expr *const *x) {
    for (size_t i = 0; i < n; i++)
        if (qd_has(e, x[i]))
            return false;
    return true;
}

/* The degree deg confirmed: sum x_i df/dx_i - deg f is zero (proven, or
 * verified numerically), and h says YES; h->test is that test either way. */
static qd_status confirm(qd_ctx *ctx, qd_homog *h, const qd_expr *deg) {
    qd_status st = qd_equal_test(ctx, h->euler, qd_mul(ctx, deg, h->f), &h->test);
    if (st == QD_OK && (h->test.kind == QD_ZERO_PROVEN || h->test.kind == QD_ZERO_NUMERIC)) {
        h->verdict = QD_HOMOG_YES;
        h->degree = deg;
    }
    return st;
}

/* log2(f(2x)/f(x)) at a point, as p/q with q <= 12 when one is within
 * 1e-9 of it; NULL when there is none (or no point to evaluate at). */
static const qd_expr *estimate(qd_ctx *ctx, const qd_expr *f, size_t n, const qd_expr *const *x) {
    const qd_expr *syms[QD_WITNESS_MAX], *f2 = scaled(ctx, f, n, x, 2);
    size_t ns = f2 ? qd_free_symbols(ctx, f, syms, QD_WITNESS_MAX) : 0;
    double vals[QD_WITNESS_MAX], a = 0, b = 0;
    if (!f2 || ns > QD_WITNESS_MAX)
        return NULL;
    for (size_t k = 0; k < ns; k++)
        vals[k] = (13.0 + 5.0 * (double)k) / 16.0;
    if (qd_eval(ctx, f, ns, syms, vals, &a) != QD_OK ||
        qd_eval(ctx, f2, ns, syms, vals, &b) != QD_OK || !(b / a > 0) || !isfinite(b / a)) {
        qd__ctx_recover(ctx); /* no point, no guess: not an error */
        return NULL;
    }
    double d = log2(b / a);
    for (long q = 1; q <= 12; q++) {
        double p = round(d * (double)q);
        if (fabs(p / (double)q - d) < 1e-9 * fmax(1.0, fabs(d)) && fabs(p) < 1e6)
            return qd_rat(ctx, (long)p, q);
    }
    return NULL;
}

/* The variables: symbols, none twice. */
static qd_status check_vars(qd_ctx *ctx, size_t n, const qd_expr *const *x) {
    if (!n) {
        qd_ctx_error(ctx, QD_ERR_ARG, "homogeneity: name the variables (none given)");
        return QD_ERR_ARG;
    }
    for (size_t i = 0; i < n; i++) {
        if (!x[i] || qd_expr_kind(x[i]) != QD_SYMBOL) {
            qd_ctx_error(ctx, QD_ERR_ARG, "homogeneity: variable %zu is not a symbol", i + 1);
            return QD_ERR_ARG;
        }
        for (size_t k = 0; k < i; k++)
            if (x[k] == x[i]) {
                qd_ctx_error(ctx, QD_ERR_ARG, "homogeneity: %s is named twice",
                             qd_expr_name(x[i]));
                return QD_ERR_ARG;
            }
    }
    return QD_OK;
}

/* f, f(2x), f(4x) and the symbols of f: what the probe is evaluated from. */
typedef struct trio {
    const qd_expr *f[3];
    size_t ns;
    const qd_expr *syms[QD_WITNESS_MAX];
} trio;

/* The probe f(x) f(4x) - f(2x)^2 at the point, from the three values in
 * ball arithmetic, each evaluated as written: a simplified probe may be
 * defined where f is not (sqrt(a) sqrt(b) made sqrt(a b)), and a witness
 * must be a point of f's domain.  1 when certainly not 0 (*val, *rad its
 * value and error bound, the doubles' rounding included), 0 when 0 is
 * within the bound, -1 where f, f(2x) or f(4x) is undefined. */
static int probe_at(qd_ctx *ctx, const trio *t, const double *at, double *val, double *rad) {
    double m[3], r[3];
    for (int i = 0; i < 3; i++) {
        if (!qd__ball_eval(ctx, t->f[i], t->ns, t->syms, at, &m[i], &r[i]))
            return -1;
        r[i] += DBL_EPSILON * fabs(m[i]);
    }
    *val = m[0] * m[2] - m[1] * m[1];
    *rad = fabs(m[0]) * r[2] + fabs(m[2]) * r[0] + r[0] * r[2] + 2 * fabs(m[1]) * r[1] +
           r[1] * r[1] + 4 * DBL_EPSILON * (fabs(m[0] * m[2]) + m[1] * m[1]);
    return fabs(*val) > *rad ? 1 : 0;
}

static uint64_t next_rand(uint64_t *s) {
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return *s >> 33;
}

/* The search for a witness, at points k/16 (3 <= k <= 29) as qd_zero_test
 * picks them, all positive first; a witness is a NO, QD_ZERO_POINTS points
 * where the probe is 0 within its bound a numeric zero. */
static void search(qd_ctx *ctx, qd_homog *h, const trio *t) {
    uint64_t seed = 0x9e3779b97f4a7c15ULL;
    unsigned zero = 0;
    double at[QD_WITNESS_MAX], val = 0, rad = 0;
    for (unsigned tries = 0; tries < 24 * QD_ZERO_POINTS && zero < QD_ZERO_POINTS; tries++) {
        for (size_t i = 0; i < t->ns; i++) {
            double v = (double)(3 + next_rand(&seed) % 27) / 16.0;
            bool neg = tries >= 2 && !qd_symbol_is_positive(t->syms[i]) && (next_rand(&seed) & 1);
            at[i] = neg ? -v : v;
        }
        int k = probe_at(ctx, t, at, &val, &rad);
        zero += k == 0;
        if (k > 0) {
            h->verdict = QD_HOMOG_NO;
            h->test = (qd_zero_result){QD_ZERO_NONZERO, h->probe, {t->ns, {0}, {0}, val, rad}, 0, 128};
            for (size_t i = 0; i < t->ns; i++) {
                h->test.witness.sym[i] = t->syms[i];
                h->test.witness.at[i] = at[i];
            }
            return;
        }
    }
    if (zero >= QD_ZERO_POINTS)
        h->test = (qd_zero_result){QD_ZERO_NUMERIC, h->probe, {0}, zero, 128};
}

/* Not free of x, or not confirmed: the probe's witness, else a guess.
 * f is the caller's, as written (its domain is the witness's). */
static qd_status probe(qd_ctx *ctx, qd_homog *h, const qd_expr *f, size_t n,
                       const qd_expr *const *x) {
    trio t = {{f, scaled(ctx, f, n, x, 2), scaled(ctx, f, n, x, 4)}, 0, {0}};
    h->probe = qd_sub(ctx, qd_mul(ctx, t.f[0], t.f[2]), qd_powi(ctx, t.f[1], 2));
    if (!h->probe)
        return qd_ctx_status(ctx);
    t.ns = qd_free_symbols(ctx, f, t.syms, QD_WITNESS_MAX);
    if (t.ns <= QD_WITNESS_MAX)
        search(ctx, h, &t);
    if (h->verdict == QD_HOMOG_NO || qd_ctx_status(ctx) != QD_OK)
        return qd_ctx_status(ctx);
    const qd_expr *d = estimate(ctx, h->f, n, x);
    if (!d)
        return qd_ctx_status(ctx);
    qd_zero_result before = h->test;
    qd_status st = confirm(ctx, h, d);
    if (st == QD_OK && h->verdict != QD_HOMOG_YES)
        h->test = before;
    return st;
}

qd_status qd_homogeneity(qd_ctx *ctx, const qd_expr *f, size_t n, const qd_expr *const *x,
                         qd_homog *out) {
    QD_ARGS_CTX(ctx, ctx && f && out && (x || !n));
    *out = (qd_homog){.verdict = QD_HOMOG_UNDECIDED};
    out->test.kind = QD_ZERO_UNKNOWN;
    qd_status st = check_vars(ctx, n, x);
    if (st != QD_OK)
        return st;
    if (!(out->f = qd_simplify(ctx, f)))
        return qd_ctx_status(ctx);
    if (qd_is_zero(out->f)) {
        out->verdict = QD_HOMOG_EVERY;
        out->euler = out->f;
        return QD_OK;
    }
    const qd_expr *r = NULL;
    if (!(out->euler = euler_sum(ctx, out->f, n, x)) ||
        !(r = qd_simplify(ctx, qd_div(ctx, out->euler, out->f))))
        return qd_ctx_status(ctx);
    if (free_of(r, n, x) && ((st = confirm(ctx, out, r)) != QD_OK || out->verdict == QD_HOMOG_YES))
        return st;
    return probe(ctx, out, f, n, x);
}
