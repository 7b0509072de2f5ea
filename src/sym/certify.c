/*
 * src/sym/certify.c - certified zero tests by ball arithmetic (qdot/certify.h,
 * issue 33).  One walk of the DAG per point in FLINT's Arb: a value whose
 * ball excludes 0 is a witness that the expression is not identically 0.
 */
#include "node.h"
#include "qdot/certify.h"
#include "../base/args.h"

#include <arb.h>
#include <flint/fmpq.h>
#include <math.h>
#include <stdlib.h>

typedef struct aw {
    qd__ptrmap memo;  /* node -> index + 1 into vals */
    arb_struct *vals;
    size_t n, cap;
    slong prec;
    bool bad;        /* undefined here (NaN ball) or out of memory */
    bool unknown;    /* a user function or an unbound symbol: undecidable */
} aw;

static arb_struct *slot(aw *w, const qd_expr *e) {
    if (w->n == w->cap) {
        size_t cap = w->cap ? 2 * w->cap : 64;
        arb_struct *v = realloc(w->vals, cap * sizeof *v);
        if (!v) {
            w->bad = true;
            return NULL;
        }
        w->vals = v;
        w->cap = cap;
    }
    arb_struct *r = &w->vals[w->n];
    arb_init(r);
    w->n++;
    if (!qd__ptrmap_put(&w->memo, e, (void *)(uintptr_t)w->n))
        w->bad = true;
    return r;
}

/* The value of e, or NULL (w->bad or w->unknown set). */
static const arb_struct *aval(aw *w, const qd_expr *e);

static void set_number(arb_t r, const qd_expr *e, slong prec) {
    if (e->kind == QD_FLOAT) {
        arb_set_d(r, e->u.f);
        return;
    }
    fmpq_t q;
    fmpq_init(q);
    fmpq_set_mpq(q, e->u.q);
    arb_set_fmpq(r, q, prec);
    fmpq_clear(q);
}

static void apply_func(arb_t r, qd_func f, const arb_t a, const arb_t b, slong prec,
                       bool *bad) {
    switch (f) {
    case QD_SIN: arb_sin(r, a, prec); break;
    case QD_COS: arb_cos(r, a, prec); break;
    case QD_TAN: arb_tan(r, a, prec); break;
    case QD_ASIN: arb_asin(r, a, prec); break;
    case QD_ACOS: arb_acos(r, a, prec); break;
    case QD_ATAN: arb_atan(r, a, prec); break;
    case QD_ATAN2: arb_atan2(r, a, b, prec); break;
    case QD_SINH: arb_sinh(r, a, prec); break;
    case QD_COSH: arb_cosh(r, a, prec); break;
    case QD_TANH: arb_tanh(r, a, prec); break;
    case QD_EXP: arb_exp(r, a, prec); break;
    case QD_LOG:
        if (!arb_is_positive(a))
            *bad = true;
        else
            arb_log(r, a, prec);
        break;
    case QD_ABS: arb_abs(r, a); break;
    case QD_SIGN:
    case QD_STEP:
        if (arb_is_positive(a))
            arb_one(r);
        else if (arb_is_negative(a))
            f == QD_SIGN ? arb_set_si(r, -1) : arb_zero(r);
        else
            *bad = true;  /* at or too near the jump */
        break;
    default: *bad = true; break;
    }
}

static void apply_pow(arb_t r, const arb_t b, const qd_expr *ex, const arb_t e, slong prec,
                      bool *bad) {
    if (ex->kind == QD_RATIONAL && mpz_cmp_ui(mpq_denref(ex->u.q), 1) == 0) {
        fmpz_t k;
        fmpz_init(k);
        fmpz_set_mpz(k, mpq_numref(ex->u.q));
        if (fmpz_sgn(k) < 0 && arb_contains_zero(b))
            *bad = true;
        else
            arb_pow_fmpz(r, b, k, prec);
        fmpz_clear(k);
        return;
    }
    if (ex->kind == QD_RATIONAL && mpz_cmp_ui(mpq_denref(ex->u.q), 2) == 0 &&
        mpz_sgn(mpq_numref(ex->u.q)) > 0 && arb_is_nonnegative(b)) {
        arb_sqrt(r, b, prec); /* sqrt(0) is 0; then the integer power */
        fmpz_t k;
        fmpz_init(k);
        fmpz_set_mpz(k, mpq_numref(ex->u.q));
        arb_pow_fmpz(r, r, k, prec);
        fmpz_clear(k);
        return;
    }
    if (!arb_is_positive(b)) { /* a real power of a non-positive base: not here */
        *bad = true;
        return;
    }
    arb_pow(r, b, e, prec);
}

static const arb_struct *aval(aw *w, const qd_expr *e) {
    if (w->bad || w->unknown)
        return NULL;
    uintptr_t k = (uintptr_t)qd__ptrmap_get(&w->memo, e);
    if (k)
        return &w->vals[k - 1];
    /* the arguments first: slot() may move vals */
    const arb_struct *a[2] = {NULL, NULL};
    switch ((qd_kind)e->kind) {
    case QD_SYMBOL:
        w->unknown = true;  /* every bound symbol is in the memo */
        return NULL;
    case QD_UFUNC:
    case QD_UDERIV:
        w->unknown = true;
        return NULL;
    case QD_ADD:
    case QD_MUL: {
        for (size_t i = 0; i < e->nargs; i++)
            if (!aval(w, e->args[i]))
                return NULL;
        arb_struct *r = slot(w, e);
        if (!r)
            return NULL;
        arb_set_si(r, e->kind == QD_ADD ? 0 : 1);
        for (size_t i = 0; i < e->nargs; i++) {
            const arb_struct *x = &w->vals[(uintptr_t)qd__ptrmap_get(&w->memo, e->args[i]) - 1];
            if (e->kind == QD_ADD)
                arb_add(r, r, x, w->prec);
            else
                arb_mul(r, r, x, w->prec);
        }
        if (!arb_is_finite(r))
            w->bad = true;
        return w->bad ? NULL : r;
    }
    default: break;
    }
    for (size_t i = 0; i < e->nargs && i < 2; i++)
        if (!aval(w, e->args[i]))
            return NULL;
    arb_struct *r = slot(w, e);
    if (!r)
        return NULL;
    for (size_t i = 0; i < e->nargs && i < 2; i++)
        a[i] = &w->vals[(uintptr_t)qd__ptrmap_get(&w->memo, e->args[i]) - 1];
    switch ((qd_kind)e->kind) {
    case QD_RATIONAL:
    case QD_FLOAT: set_number(r, e, w->prec); break;
    case QD_CONSTANT:
        if (e->tag == QD_PI)
            arb_const_pi(r, w->prec);
        else
            arb_const_e(r, w->prec);
        break;
    case QD_POW: apply_pow(r, a[0], e->args[1], a[1], w->prec, &w->bad); break;
    case QD_FUNC:
        apply_func(r, (qd_func)e->tag, a[0], e->nargs > 1 ? a[1] : a[0], w->prec, &w->bad);
        break;
    default: w->bad = true; break;
    }
    if (!w->bad && !arb_is_finite(r))
        w->bad = true;
    return w->bad ? NULL : r;
}

typedef enum { PT_BAD, PT_UNKNOWN, PT_ZERO, PT_NONZERO, PT_WIDE } pt_kind;

/* e at the point (syms[i] = at[i]) with prec bits. */
static pt_kind eval_at(qd_ctx *ctx, const qd_expr *e, size_t n, const qd_expr *const *syms,
                       const double *at, slong prec, double *mid, double *rad) {
    aw w = {QD_PTRMAP_AL(qd__ctx_allocator(ctx)), NULL, 0, 0, prec, false, false};
    for (size_t i = 0; i < n && !w.bad; i++) {
        arb_struct *r = slot(&w, syms[i]);
        if (r)
            arb_set_d(r, at[i]);
    }
    const arb_struct *v = aval(&w, e);
    pt_kind k = w.unknown ? PT_UNKNOWN : !v ? PT_BAD : PT_WIDE;
    if (v) {
        *mid = arf_get_d(arb_midref(v), ARF_RND_NEAR);
        *rad = mag_get_d(arb_radref(v));
        if (!arb_contains_zero(v))
            k = PT_NONZERO;
        else if (*rad < ldexp(1.0, -(int)(prec / 2)))
            k = PT_ZERO;
    }
    for (size_t i = 0; i < w.n; i++)
        arb_clear(&w.vals[i]);
    free(w.vals);
    qd__ptrmap_free(&w.memo);
    return k;
}

bool qd__ball_eval(qd_ctx *ctx, const qd_expr *e, size_t n, const qd_expr *const *syms,
                   const double *at, double *mid, double *rad) {
    pt_kind k = eval_at(ctx, e, n, syms, at, 128, mid, rad);
    return k != PT_BAD && k != PT_UNKNOWN && isfinite(*mid) && isfinite(*rad);
}

/* A point where the simplified form gave k (ZERO or NONZERO at prec bits):
 * the expression as given must be defined there too, or the point is
 * skipped (PT_BAD): simplifying may widen the domain (sqrt(a) sqrt(b) *
 * (|a| - a) vanishes wherever it is defined, a, b >= 0, but its merged
 * form sqrt(a b) (|a| - a) is 2.4 at a = b = -1).  A witness is the given
 * expression's own value, its ball excluding 0. */
static pt_kind in_domain(qd_ctx *ctx, const qd_expr *e, size_t n, const qd_expr *const *syms,
                         const double *at, pt_kind k, slong prec, double *mid, double *rad) {
    double m = 0, r = 0;
    pt_kind g = PT_WIDE;
    for (; prec <= 512 && g == PT_WIDE; prec *= 2)
        g = eval_at(ctx, e, n, syms, at, prec, &m, &r);
    if (g == PT_BAD || g == PT_UNKNOWN)
        return PT_BAD;
    if (k == PT_ZERO)
        return PT_ZERO;
    if (g != PT_NONZERO)
        return PT_BAD; /* the two forms disagree here: not a witness */
    *mid = m;
    *rad = r;
    return PT_NONZERO;
}

static uint64_t next_rand(uint64_t *s) {
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return *s >> 33;
}

const char *qd_zero_kind_name(qd_zero_kind k) {
    switch (k) {
    case QD_ZERO_PROVEN: return "proven";
    case QD_ZERO_NONZERO: return "nonzero";
    case QD_ZERO_NUMERIC: return "numeric";
    default: return "unknown";
    }
}

qd_status qd_zero_test(qd_ctx *ctx, const qd_expr *e, qd_zero_result *out) {
    QD_ARGS_CTX(ctx, ctx && e && out);
    *out = (qd_zero_result){QD_ZERO_UNKNOWN, NULL, {0}, 0, 128};
    const qd_expr *s = qd_is_zero(e) ? e : qd_simplify(ctx, e);
    if (!s)
        return qd_ctx_status(ctx);
    out->simplified = s;
    if (qd_is_zero(s)) {
        out->kind = QD_ZERO_PROVEN;
        return QD_OK;
    }
    if (qd__is_num(s) || s->kind == QD_CONSTANT) { /* a nonzero number */
        double m = 0, r = 0;
        if (eval_at(ctx, s, 0, NULL, NULL, 128, &m, &r) == PT_NONZERO) {
            out->kind = QD_ZERO_NONZERO;
            out->witness.value = m;
            out->witness.radius = r;
        }
        return QD_OK;
    }
    /* the points bind the symbols of e as given, so that each is checked to
     * lie in e's domain (below); s has no others */
    const qd_expr *syms[QD_WITNESS_MAX];
    size_t n = qd_free_symbols(ctx, e, syms, QD_WITNESS_MAX);
    const qd_expr *given = e;
    if (n > QD_WITNESS_MAX && qd_ctx_status(ctx) == QD_OK) {
        given = NULL; /* too many to bind: s's alone, e's domain not checked */
        n = qd_free_symbols(ctx, s, syms, QD_WITNESS_MAX);
    }
    if (n > QD_WITNESS_MAX || (n == 0 && qd_ctx_status(ctx) != QD_OK))
        return n > QD_WITNESS_MAX ? QD_OK : qd_ctx_status(ctx);
    uint64_t seed = 0x9e3779b97f4a7c15ULL;
    unsigned zero = 0;
    double at[QD_WITNESS_MAX];
    /* a point where the values are all positive first, then mixed signs */
    for (unsigned tries = 0; tries < 24 * QD_ZERO_POINTS && zero < QD_ZERO_POINTS; tries++) {
        for (size_t i = 0; i < n; i++) {
            double v = (double)(3 + next_rand(&seed) % 27) / 16.0;
            bool neg = tries >= 2 && !qd_symbol_is_positive(syms[i]) && (next_rand(&seed) & 1);
            at[i] = neg ? -v : v;
        }
        double m = 0, r = 0;
        pt_kind k = PT_WIDE;
        slong prec = 128;
        for (; prec <= 512 && k == PT_WIDE; prec *= 2)
            k = eval_at(ctx, s, n, syms, at, prec, &m, &r);
        if (k == PT_UNKNOWN)
            return QD_OK;
        if ((k == PT_NONZERO || k == PT_ZERO) && given && given != s)
            k = in_domain(ctx, given, n, syms, at, k, prec / 2, &m, &r);
        if (k == PT_NONZERO) {
            out->kind = QD_ZERO_NONZERO;
            out->bits = (unsigned)(prec / 2);
            out->witness.n = n;
            for (size_t i = 0; i < n; i++) {
                out->witness.sym[i] = syms[i];
                out->witness.at[i] = at[i];
            }
            out->witness.value = m;
            out->witness.radius = r;
            return QD_OK;
        }
        if (k == PT_ZERO)
            zero++;
    }
    if (zero >= QD_ZERO_POINTS) {
        out->kind = QD_ZERO_NUMERIC;
        out->points = zero;
    }
    return QD_OK;
}

qd_status qd_equal_test(qd_ctx *ctx, const qd_expr *e, const qd_expr *target,
                        qd_zero_result *out) {
    QD_ARGS_CTX(ctx, ctx && e && target && out);
    return qd_zero_test(ctx, qd_sub(ctx, e, target), out);
}
