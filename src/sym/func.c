/*
 * src/sym/func.c - built-in and user-named functions.
 *
 * On construction: exact values at 0 and 1; sin, cos and tan of rational
 * multiples of pi reduced to the first quadrant, with exact values at
 * multiples of pi/6 and pi/4 (sin(pi/6) = 1/2, tan(pi/3) = sqrt(3)); whole
 * quarter turns taken out of a sum's pi term (sin(pi/2 - x) = cos(x),
 * sin(x + 2 pi) = sin(x)), as SymPy does on construction; a float argument
 * is evaluated; step of a number folds to 0, 1/2 or 1; odd functions take a leading minus sign out (sin(-x) =
 * -sin(x)) and even ones drop it (cos(b - a) = cos(a - b)), so that equal
 * values meet as one node; exp and log cancel; |x| = x for x known >= 0.
 */
#include "node.h"
#include "../base/args.h"
#include "sym_export.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *const names[QD_FUNC_COUNT] = {
    "sin", "cos", "tan", "asin", "acos", "atan", "atan2",
    "sinh", "cosh", "tanh", "exp", "log", "abs", "sign", "step",
};

const char *qd_func_name(qd_func f) { return (unsigned)f < QD_FUNC_COUNT ? names[f] : "?"; }

bool qd_func_from_name(const char *name, qd_func *out) {
    QD_ARGS(false, name && out);
    for (int i = 0; i < QD_FUNC_COUNT; i++)
        if (strcmp(names[i], name) == 0) {
            *out = (qd_func)i;
            return true;
        }
    return false;
}

static const qd_expr *call_node(qd_ctx *ctx, qd_func f, size_t n, const qd_expr *const *args) {
    qd_expr proto = {0};
    proto.kind = QD_FUNC;
    proto.tag = (uint8_t)f;
    return qd__intern(ctx, &proto, n, args);
}

static double eval1(qd_func f, double x) {
    switch (f) {
    case QD_SIN: return sin(x);
    case QD_COS: return cos(x);
    case QD_TAN: return tan(x);
    case QD_ASIN: return asin(x);
    case QD_ACOS: return acos(x);
    case QD_ATAN: return atan(x);
    case QD_SINH: return sinh(x);
    case QD_COSH: return cosh(x);
    case QD_TANH: return tanh(x);
    case QD_EXP: return exp(x);
    case QD_LOG: return log(x);
    case QD_ABS: return fabs(x);
    case QD_SIGN: return (x > 0) - (x < 0);
    case QD_STEP: return qd__step_value(x);
    default: return NAN;
    }
}

static bool is_odd(qd_func f) {
    return f == QD_SIN || f == QD_TAN || f == QD_ASIN || f == QD_ATAN || f == QD_SINH ||
           f == QD_TANH || f == QD_SIGN;
}

static bool is_even(qd_func f) { return f == QD_COS || f == QD_COSH || f == QD_ABS; }

/* ---- sin, cos and tan at rational multiples of pi ------------------------- */

static bool is_pi(const qd_expr *e) { return e->kind == QD_CONSTANT && e->tag == QD_PI; }

/* K = num/den when t is K*pi with K rational and small enough that the
 * reductions below cannot overflow a long. */
static bool pi_coeff(const qd_expr *t, long *num, long *den) {
    if (is_pi(t)) {
        *num = *den = 1;
        return true;
    }
    if (t->kind != QD_MUL || t->nargs != 2 || !is_pi(t->args[1]) ||
        !qd_rational_get(t->args[0], num, den))
        return false;
    return labs(*num) < (1L << 40) && *den < (1L << 20);
}

static long floor_div(long a, long b) { return a / b - (a % b != 0 && (a < 0) != (b < 0)); }

/* x^(1/2) * c: the surds in the exact values. */
static const qd_expr *surd(qd_ctx *ctx, long x, long cn, long cd) {
    return qd_mul(ctx, qd_rat(ctx, cn, cd), qd_sqrt(ctx, qd_int(ctx, x)));
}

/* f(r*pi) for r = n/d in [0, 1/2] in lowest terms: the exact values at
 * r = 0, 1/6, 1/4, 1/3, 1/2 (cos(r pi) = sin((1/2 - r) pi) runs the list
 * backwards), else the call itself; tan(pi/2) stays as it is. */
static const qd_expr *first_quadrant(qd_ctx *ctx, qd_func f, long n, long d) {
    static const long tan_x[4] = {0, 3, 1, 3}, tan_d[4] = {1, 3, 1, 1};
    int k = n == 0 ? 0 : d == 6 ? 1 : d == 4 ? 2 : d == 3 ? 3 : d == 2 ? 4 : -1;
    if (k >= 0 && f == QD_COS) {
        f = QD_SIN;
        k = 4 - k;
    }
    if (k >= 0 && f == QD_SIN) /* sqrt(k)/2: 0, 1/2, sqrt(2)/2, sqrt(3)/2, 1 */
        return surd(ctx, k, 1, 2);
    if (k >= 0 && k < 4 && f == QD_TAN)
        return k == 0 ? ctx->sym->zero : k == 2 ? ctx->sym->one : surd(ctx, tan_x[k], 1, tan_d[k]);
    const qd_expr *arg = qd_mul(ctx, qd_rat(ctx, n, d), qd_const(ctx, QD_PI));
    return arg ? call_node(ctx, f, 1, &arg) : NULL;
}

/* f(K*pi) reduced by periodicity and symmetry to +-g(r*pi), r in [0, 1/2]:
 * sin(pi + x) = -sin x, sin(pi - x) = sin x, cos(2 pi - x) = cos x,
 * cos(pi - x) = -cos x, tan(pi - x) = -tan x. */
static const qd_expr *pi_multiple(qd_ctx *ctx, qd_func f, long n, long d) {
    long period = f == QD_TAN ? d : 2 * d;
    n -= floor_div(n, period) * period; /* K mod 2 (tan: mod 1), now 0 <= n < period */
    bool neg = false;
    if (f == QD_SIN && n >= d)
        n -= d, neg = true;
    if (f == QD_COS && n > d)
        n = 2 * d - n;
    if (2 * n > d) {
        n = d - n;
        neg ^= f != QD_SIN;
    }
    const qd_expr *v = first_quadrant(ctx, f, n, d);
    return neg ? qd_neg(ctx, v) : v;
}

/* The term K*pi of a sum, when there is one (constants sort first, so it is
 * the first term after the number). */
static const qd_expr *pi_term(const qd_expr *s, long *num, long *den) {
    for (size_t i = 0; i < s->nargs && i < 2; i++)
        if (pi_coeff(s->args[i], num, den))
            return s->args[i];
    return NULL;
}

/* f(x + K*pi) with the whole quarter turns taken out of K (what is left is
 * in [0, pi/2)): sin(x + pi/2) = cos x, cos(x + pi) = -cos x,
 * tan(x + pi/2) = -1/tan x; NULL when there are none. */
static const qd_expr *peel_pi(qd_ctx *ctx, qd_func f, const qd_expr *s) {
    long n, d;
    const qd_expr *t = pi_term(s, &n, &d);
    long q = t ? floor_div(2 * n, d) : 0;
    if (q == 0)
        return NULL;
    const qd_expr *rest = qd_sub(ctx, s, qd_mul(ctx, qd_rat(ctx, q, 2), qd_const(ctx, QD_PI)));
    q = ((q % 4) + 4) % 4;
    if (f == QD_TAN) {
        const qd_expr *v = qd_fn(ctx, QD_TAN, rest);
        return q % 2 ? qd_neg(ctx, qd_pow(ctx, v, ctx->sym->minus_one)) : v;
    }
    /* sin(y + q pi/2) and cos(y + q pi/2) = sin(y + (q + 1) pi/2) */
    q = (q + (f == QD_COS)) % 4;
    const qd_expr *v = qd_fn(ctx, q % 2 ? QD_COS : QD_SIN, rest);
    return q >= 2 ? qd_neg(ctx, v) : v;
}

static bool is_circular(qd_func f) { return f == QD_SIN || f == QD_COS || f == QD_TAN; }

/* The exact value of f(a) when there is a simple one; *err for log(0). */
static const qd_expr *exact_value(qd_ctx *ctx, qd_func f, const qd_expr *a, bool *err) {
    if (qd_is_zero(a) && a->kind == QD_RATIONAL) {
        switch (f) {
        case QD_SIN: case QD_TAN: case QD_ASIN: case QD_ATAN: case QD_SINH:
        case QD_TANH: case QD_ABS: case QD_SIGN:
            return ctx->sym->zero;
        case QD_COS: case QD_COSH: case QD_EXP:
            return ctx->sym->one;
        case QD_STEP:
            return ctx->sym->half;
        case QD_ACOS:
            return qd_mul(ctx, ctx->sym->half, qd_const(ctx, QD_PI));
        case QD_LOG:
            qd_ctx_error(ctx, QD_ERR_DIVZERO, "log(0) is not a number");
            *err = true;
            return NULL;
        default:
            return NULL;
        }
    }
    if (a->kind == QD_RATIONAL) {
        if (f == QD_ABS)
            return qd_number_sign(a) < 0 ? qd_neg(ctx, a) : a;
        if (f == QD_SIGN)
            return qd_int(ctx, qd_number_sign(a));
        if (f == QD_STEP)
            return qd_rat(ctx, qd_number_sign(a) + 1, 2);
        if (qd_is_one(a) && (f == QD_LOG || f == QD_ACOS))
            return ctx->sym->zero;
        return NULL;
    }
    long num, den;
    if (is_circular(f) && pi_coeff(a, &num, &den))
        return pi_multiple(ctx, f, num, den);
    if (f == QD_LOG && a->kind == QD_CONSTANT && a->tag == QD_E)
        return ctx->sym->one;
    if (f == QD_LOG && a->kind == QD_FUNC && a->tag == QD_EXP)
        return a->args[0];
    if (f == QD_EXP && a->kind == QD_FUNC && a->tag == QD_LOG)
        return a->args[0];
    if (f == QD_ABS && qd__nonneg(a)) /* |x^2| = x^2, |1 + y^2| = 1 + y^2, |m| = m for m > 0 */
        return a;
    return NULL;
}

const qd_expr *qd_fn(qd_ctx *ctx, qd_func f, const qd_expr *a) {
    QD_ARGS(NULL, ctx && a);
    if (!a)
        return NULL;
    if (f == QD_ATAN2 || (unsigned)f >= QD_FUNC_COUNT) {
        qd_ctx_error(ctx, QD_ERR_ARG, "%s takes %s", qd_func_name(f),
                     f == QD_ATAN2 ? "two arguments" : "a known function");
        return NULL;
    }
    if (a->kind == QD_FLOAT)
        return qd_float(ctx, eval1(f, a->u.f));
    bool err = false;
    const qd_expr *v = exact_value(ctx, f, a, &err);
    if (v || err)
        return v;
    if (qd__has_minus(a) && (is_odd(f) || is_even(f))) {
        const qd_expr *r = qd_fn(ctx, f, qd_neg(ctx, a));
        return is_odd(f) ? qd_neg(ctx, r) : r;
    }
    if (a->kind == QD_ADD && is_circular(f) && (v = peel_pi(ctx, f, a)))
        return v;
    return call_node(ctx, f, 1, &a);
}

const qd_expr *qd_fn2(qd_ctx *ctx, qd_func f, const qd_expr *y, const qd_expr *x) {
    QD_ARGS(NULL, ctx && y && x);
    if (!y || !x)
        return NULL;
    if (f != QD_ATAN2) {
        qd_ctx_error(ctx, QD_ERR_ARG, "%s takes one argument", qd_func_name(f));
        return NULL;
    }
    if (qd__is_num(y) && qd__is_num(x) && (y->kind == QD_FLOAT || x->kind == QD_FLOAT))
        return qd_float(ctx, atan2(qd_number_value(y), qd_number_value(x)));
    if (qd_is_zero(y) && y->kind == QD_RATIONAL && qd__is_num(x) && qd_number_sign(x) > 0)
        return ctx->sym->zero;
    if (qd__has_minus(y)) /* atan2 is odd in y */
        return qd_neg(ctx, qd_fn2(ctx, f, qd_neg(ctx, y), x));
    const qd_expr *args[2] = {y, x};
    return call_node(ctx, f, 2, args);
}

/* ---- user-named functions ----------------------------------------------- */

static bool check_name(qd_ctx *ctx, const char *name) {
    qd_func f;
    if (!name || !*name) {
        qd_ctx_error(ctx, QD_ERR_ARG, "a function needs a name");
        return false;
    }
    if (qd_func_from_name(name, &f)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "'%s' is a built-in function", name);
        return false;
    }
    return true;
}

const qd_expr *qd_ufunc(qd_ctx *ctx, const char *name, size_t n, const qd_expr *const *args) {
    QD_ARGS(NULL, ctx && name);
    if (!check_name(ctx, name))
        return NULL;
    qd_expr proto = {0};
    proto.kind = QD_UFUNC;
    proto.u.fn.name = qd__intern_name(ctx, name);
    if (!proto.u.fn.name)
        return NULL;
    return qd__intern(ctx, &proto, n, args);
}

static int cmp_unsigned(const void *a, const void *b) {
    unsigned x = *(const unsigned *)a, y = *(const unsigned *)b;
    return (x > y) - (x < y);
}

const qd_expr *qd_uderiv(qd_ctx *ctx, const char *name, size_t nslots, const unsigned *slots,
                         size_t n, const qd_expr *const *args) {
    QD_ARGS(NULL, ctx && name && (nslots == 0 || slots) && (n == 0 || args));
    if (!check_name(ctx, name))
        return NULL;
    if (nslots == 0 || nslots > 64) {
        qd_ctx_error(ctx, QD_ERR_ARG, "a derivative of %s needs 1 to 64 slots", name);
        return NULL;
    }
    unsigned sorted[64];
    for (size_t i = 0; i < nslots; i++) {
        if (slots[i] >= n) {
            qd_ctx_error(ctx, QD_ERR_ARG, "%s has no argument %u", name, slots[i] + 1);
            return NULL;
        }
        sorted[i] = slots[i];
    }
    qsort(sorted, nslots, sizeof sorted[0], cmp_unsigned);
    qd_expr proto = {0};
    proto.kind = QD_UDERIV;
    proto.u.fn.name = qd__intern_name(ctx, name);
    proto.u.fn.slots = sorted;
    proto.u.fn.nslots = (uint32_t)nslots;
    if (!proto.u.fn.name)
        return NULL;
    return qd__intern(ctx, &proto, n, args);
}

const qd_expr *qd__atan2_written(qd_ctx *ctx, const qd_expr *y, const qd_expr *x) {
    if (y && x && y->kind == QD_RATIONAL && x->kind == QD_RATIONAL && qd_is_zero(y) && qd_is_zero(x)) {
        qd_ctx_error(ctx, QD_ERR_DIVZERO, "atan2(0, 0) has no value: the angle of the origin");
        return NULL;
    }
    return qd_fn2(ctx, QD_ATAN2, y, x);
}
